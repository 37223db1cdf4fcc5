//! What each chart shows, as plain data (title, axes, series), built from [`crate::study::curves`]
//! and the problems' discretized solvers (the finite-element points). The TUI turns a [`Plot`] into
//! cells, the figure writer (`report::figure`, behind the feature `figures`) into SVG; neither
//! computes physics itself, so a curve on screen and in a figure are the same numbers. Its own
//! layer, below `report`: `report` formats (text, JSON, CSV, SVG) and computes nothing; which
//! charts exist is [`view`].

pub mod family;
mod lap;
mod load;
pub(crate) mod pins;
pub mod vary;
pub mod view;
mod ymode;

pub use ymode::YMode;

use crate::chart::view::{AnyChart, BeamChart, LapChart, PlateChart};
use crate::fit::Measurement;
use crate::kernel::format::{number, number_with};
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::inputs::Model;
use crate::problems::plate::{ContinuumMesh, PlateFe, solve_plate_continuum};
use crate::problems::twin_beams::TwinBeamsFe;
use crate::problems::twin_beams::load_driven::TwinBeamsLoad;
use crate::problems::{ModelKind, PlateParam};
use crate::study::curves::{self, Samples, Series, Spacing};
use crate::{SqueezedPlate, TipForce, TwinBeams};
use load::{LoadLabels, companions, dissipation_chart, fe_loop, loop_chart, response_plot};

/// Points per analytic curve: two per column of a 100-column chart, enough for Braille resolution.
pub(crate) const SAMPLES: u64 = 200;

/// What the twin beams' load charts call their quantities: the loop is one beam's, D both's.
const BEAM_LABELS: LoadLabels = LoadLabels {
    response: "w(L)",
    response_axis: "w(L) (mm)",
    loop_title: ("1 beam ", "D(2)"),
    dissipation_axis: "D, 2 beams (N mm)",
};

/// Elements of the finite-element overlay: its error (~1e-6) is far below a pixel.
const OVERLAY_ELEMENTS: usize = 100;

/// Number of finite-element points shown on a curve.
const OVERLAY_POINTS: usize = 8;

/// One axis.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Axis {
    /// Title with unit.
    pub title: String,
    /// [min, max] in plotted units.
    pub bounds: [f64; 2],
    /// Tick labels, evenly spaced from min to max.
    pub labels: Vec<String>,
    /// True when the plotted units are log10 of the values (the labels show the values).
    pub log: bool,
}

impl Axis {
    /// The value a plotted coordinate stands for: `10^v` on a log axis, `v` itself otherwise.
    pub fn value(&self, plotted: f64) -> f64 {
        if self.log {
            10f64.powf(plotted)
        } else {
            plotted
        }
    }

    /// `count` tick labels evenly spaced from min to max (at least the axis's own three): large
    /// charts get more ticks.
    #[cfg(feature = "app")]
    pub(crate) fn ticks(&self, count: usize) -> Vec<String> {
        if count <= self.labels.len() {
            return self.labels.clone();
        }
        let [lo, hi] = self.bounds;
        (0..count)
            .map(|i| {
                let v = lo + (hi - lo) * i as f64 / (count - 1) as f64;
                tick(self.value(v))
            })
            .collect()
    }
}

/// How a series is drawn: derived from its [`SeriesRole`], never set apart from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// A curve.
    Line,
    /// Isolated markers (finite-element results, measurements).
    Points,
    /// The vertical cursor at the current value.
    Cursor,
    /// A pinned curve (its number, 1 to 4, `pins::MAX_PINS`): the same quantity at parameters
    /// kept for comparison.
    Pin(u8),
}

/// What a series stands for, set where the series is built. The drawing layers choose colour,
/// marker, line style and draw order from the role alone, never from the series' position or
/// name, so that one role looks the same on every chart (the K_T curve is `x` in ASCII on w(L)
/// vs F, X vs F and tau(x) alike) and a legend text can change without changing a style.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SeriesRole {
    /// The regularized law at the current parameters: `K_T`, `regularized`, `P_r/P`. The curve a
    /// pin or a family member keeps.
    Current,
    /// The plain Coulomb law: the reference the others are compared with.
    Coulomb,
    /// The regularized law at a softer interface (`K_T/5` on the beams, `K_T/10` on the plate).
    Softer,
    /// The regularized law at a stiffer interface (`K_T*5`, `K_T*10`).
    Stiffer,
    /// A limit or reference line that is not a law: `mu P` under tau(x), `P_r = P`.
    Limit,
    /// The project's finite-element points.
    FiniteElements,
    /// The plate's 2-D plane-strain continuum points.
    Continuum,
    /// Points of a measured curve (`d` in the TUI).
    Measured,
    /// Points of an external FE code (a CalculiX .dat, any CSV).
    External,
    /// The vertical line at the current value.
    Cursor,
    /// A pinned curve, by its number (1 to 4, `pins::MAX_PINS`).
    Pin(u8),
    /// A member of a family (`plot --family`), by its position (1 to 6, `family::MAX_MEMBERS`):
    /// every member has the same rank, none is the current one.
    Family(u8),
}

impl SeriesRole {
    /// The roles a chart's own series have (not pins or family members), in the order `--series`
    /// lists them.
    pub const CHART_ROLES: [SeriesRole; 10] = [
        SeriesRole::Current,
        SeriesRole::Coulomb,
        SeriesRole::Softer,
        SeriesRole::Stiffer,
        SeriesRole::Limit,
        SeriesRole::FiniteElements,
        SeriesRole::Continuum,
        SeriesRole::Measured,
        SeriesRole::External,
        SeriesRole::Cursor,
    ];

    /// How the role is drawn.
    pub fn kind(self) -> SeriesKind {
        match self {
            SeriesRole::Current
            | SeriesRole::Coulomb
            | SeriesRole::Softer
            | SeriesRole::Stiffer
            | SeriesRole::Limit
            | SeriesRole::Family(_) => SeriesKind::Line,
            SeriesRole::FiniteElements
            | SeriesRole::Continuum
            | SeriesRole::Measured
            | SeriesRole::External => SeriesKind::Points,
            SeriesRole::Cursor => SeriesKind::Cursor,
            SeriesRole::Pin(n) => SeriesKind::Pin(n),
        }
    }

    /// The role's key on the command line (`plot --series`); pins and family members have none
    /// (they are asked for with `--pin` and `--family`).
    pub fn key(self) -> Option<&'static str> {
        Some(match self {
            SeriesRole::Current => "current",
            SeriesRole::Coulomb => "coulomb",
            SeriesRole::Softer => "softer",
            SeriesRole::Stiffer => "stiffer",
            SeriesRole::Limit => "limit",
            SeriesRole::FiniteElements => "fe",
            SeriesRole::Continuum => "continuum",
            SeriesRole::Measured => "measured",
            SeriesRole::External => "external",
            SeriesRole::Cursor => "cursor",
            SeriesRole::Pin(_) | SeriesRole::Family(_) => return None,
        })
    }

    /// The chart role of `key` (`--series`).
    pub fn from_key(key: &str) -> Option<SeriesRole> {
        Self::CHART_ROLES.into_iter().find(|r| r.key() == Some(key))
    }

    /// Draw order, lowest first: the cursor under everything, then limit lines (so that a curve
    /// lying on `mu P` shows over it), then curves, then points on top (few and sparse, they
    /// would vanish under a curve).
    #[cfg(feature = "figures")]
    pub(crate) fn layer(self) -> u8 {
        match self.kind() {
            SeriesKind::Cursor => 0,
            _ if self == SeriesRole::Limit => 1,
            SeriesKind::Line | SeriesKind::Pin(_) => 2,
            SeriesKind::Points => 3,
        }
    }
}

/// One series.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSeries {
    /// Legend text.
    pub name: String,
    /// Points in plotted units.
    pub points: Series,
    /// What the series stands for (which sets how it is drawn).
    pub role: SeriesRole,
}

impl PlotSeries {
    /// How the series is drawn.
    pub fn kind(&self) -> SeriesKind {
        self.role.kind()
    }
}

/// A chart, ready to draw.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Plot {
    /// Title.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Curves, points and the cursor.
    pub series: Vec<PlotSeries>,
    /// What the title leaves out, under it in a figure: the parameters a family or a comparison
    /// holds fixed (`L = 200 mm, b = 20 mm, ...`). The TUI shows them in its parameter pane.
    pub caption: Option<String>,
}

/// Finite-element results for the overlay, in the chart's plotted units.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericPoints {
    /// The points.
    pub points: Series,
    /// The plate's plane-strain continuum solution at the same K_T (u(L) thickness mean), where
    /// it converged: where the strip theory and the continuum part ways. Empty elsewhere.
    pub continuum: Series,
    /// Sample points whose solve did not converge (left as gaps; the legend says how many).
    pub failed: usize,
    /// Where the first of them failed and why: the legend says where, the TUI's status why, so a
    /// gap is not a mystery.
    pub failure: Option<PointFailure>,
}

/// The first overlay point that was not solved.
#[derive(Debug, Clone, PartialEq)]
pub struct PointFailure {
    /// Where, with its unit: "F = 120 N", "K_T = 1e10 MPa/mm".
    pub at: String,
    /// The solver's reason (a [`NumericError`]'s message).
    pub why: String,
}

impl NumericPoints {
    /// The unsolved points in words, where and why ("2 points not solved; the first, at K_T =
    /// 1e10 MPa/mm: the saturation slip ..."); None when every point was solved.
    pub fn failure_words(&self) -> Option<String> {
        let failure = self.failure.as_ref()?;
        Some(format!(
            "{}; the first, at {}: {}",
            unsolved(self.failed),
            failure.at,
            failure.why
        ))
    }
}

/// "1 point not solved", "3 points not solved".
fn unsolved(count: usize) -> String {
    match count {
        1 => "1 point not solved".to_string(),
        n => format!("{n} points not solved"),
    }
}

/// Points from an external FE code (or a CSV of any code), drawn on the chart of their quantity:
/// w(L) vs F for the beams, u(L) vs K_T for the plate.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalPoints {
    /// The code's name, the legend label ("CalculiX").
    pub label: String,
    /// The model the points are of.
    pub model: ModelKind,
    /// (F in N, w(L) in mm) for the beams, (K_T in MPa/mm, u(L) in mm) for the plate.
    pub points: Vec<(f64, f64)>,
}

/// A curve of `role`.
pub(crate) fn line(role: SeriesRole, name: impl Into<String>, points: Series) -> PlotSeries {
    PlotSeries {
        name: name.into(),
        points,
        role,
    }
}

pub(crate) fn cursor(x: f64, [y0, y1]: [f64; 2]) -> PlotSeries {
    PlotSeries {
        name: "current".into(),
        points: vec![(x, y0), (x, y1)],
        role: SeriesRole::Cursor,
    }
}

/// Finite, strictly increasing bounds from a data range that may be flat (or, defensively, not
/// finite): a range narrower than 1e-9 of its magnitude is widened to that, a flat range at 0 to
/// [0, 1]. `lo + 1` would not do: it equals `lo` above 2^53.
fn axis_bounds(lo: f64, hi: f64) -> [f64; 2] {
    let lo = if lo.is_finite() { lo } else { 0.0 };
    let hi = if hi.is_finite() { hi } else { lo };
    let magnitude = lo.abs().max(hi.abs());
    let least = if magnitude > 0.0 {
        1e-9 * magnitude
    } else {
        1.0
    };
    if hi - lo >= least {
        [lo, hi]
    } else {
        [lo, lo + least]
    }
}

pub(crate) fn linear_axis(title: impl Into<String>, lo: f64, hi: f64) -> Axis {
    let [lo, hi] = axis_bounds(lo, hi);
    Axis {
        title: title.into(),
        bounds: [lo, hi],
        labels: [lo, 0.5 * (lo + hi), hi].iter().map(|&v| tick(v)).collect(),
        log: false,
    }
}

/// An axis in log10 units, labelled with the values themselves.
pub(crate) fn log_axis(title: impl Into<String>, lo: f64, hi: f64) -> Axis {
    let labels = [lo, 0.5 * (lo + hi), hi]
        .iter()
        .map(|&v| tick(10f64.powf(v)))
        .collect();
    Axis {
        title: title.into(),
        bounds: [lo, hi],
        labels,
        log: true,
    }
}

/// Tick labels: 3 significant digits keep the y axis narrow.
fn tick(value: f64) -> String {
    number_with(value, 3)
}

pub(crate) fn max_y<'a>(series: impl IntoIterator<Item = &'a Series>) -> f64 {
    series
        .into_iter()
        .flatten()
        .map(|p| p.1)
        .fold(0.0, f64::max)
}

/// The force range of the beam charts: up to `span` (kept by the app while parameters change) or
/// 3 F_thre, or further to show the current F and the largest measured force, but never beyond the
/// largest accepted force (the sweeps refuse it).
fn force_range(beams: &TwinBeams, force: TipForce, f_data: f64, span: Option<f64>) -> f64 {
    let wanted = span
        .unwrap_or(3.0 * beams.threshold_force())
        .max(1.25 * force.newtons())
        .max(1.05 * f_data);
    TipForce::clamped(wanted).newtons()
}

pub(crate) fn samples(from: f64, to: f64, spacing: Spacing) -> Option<Samples> {
    Samples::new(from, to, SAMPLES, spacing).ok()
}

/// Builds `chart` of `model` (a chart of the model's problem), with finite-element points,
/// measurements and an external code's points if given (measurements show on the twin beams' w(L)
/// vs F chart, external points on the chart of their quantity).
pub fn build(
    model: &Model,
    chart: AnyChart,
    numeric: Option<&NumericPoints>,
    measured: Option<&[Measurement]>,
    external: Option<&ExternalPoints>,
    force_span: Option<f64>,
) -> Plot {
    debug_assert_eq!(chart.kind(), model.kind(), "a chart of another problem");
    let external = external.filter(|e| e.model == model.kind());
    let mut overlays: Vec<(SeriesRole, &str, Series)> = Vec::new();
    let plot = match *model {
        Model::Beam { beams, force } => match chart {
            AnyChart::Plate(_) | AnyChart::Lap(_) => None,
            AnyChart::Beam(chart) => {
                if chart == BeamChart::Deflection {
                    if let Some(points) = measured {
                        let series = points.iter().map(|m| (m.force, m.deflection)).collect();
                        overlays.push((SeriesRole::Measured, "measured", series));
                    }
                    if let Some(e) = external {
                        overlays.push((SeriesRole::External, e.label.as_str(), e.points.clone()));
                    }
                }
                let f_data = overlays
                    .iter()
                    .flat_map(|(_, _, s)| s.iter().map(|p| p.0))
                    .fold(0.0, f64::max);
                beam_plot(&beams, force, chart, f_data, force_span)
            }
        },
        Model::Plate(plate) => match chart {
            AnyChart::Beam(_) | AnyChart::Lap(_) => None,
            AnyChart::Plate(chart) => {
                if let (PlateChart::Displacement, Some(e)) = (chart, external) {
                    // The chart's x axis is log10 K_T.
                    let series = e.points.iter().map(|&(k, u)| (k.log10(), u)).collect();
                    overlays.push((SeriesRole::External, e.label.as_str(), series));
                }
                plate_plot(&plate, chart)
            }
        },
        Model::Lap { joint, force } => match chart {
            AnyChart::Beam(_) | AnyChart::Plate(_) => None,
            AnyChart::Lap(chart) => {
                if let (LapChart::Displacement, Some(e)) = (chart, external) {
                    overlays.push((SeriesRole::External, e.label.as_str(), e.points.clone()));
                }
                lap::lap_plot(&joint, force, chart, force_span)
            }
        },
    };
    // Every range above lies in the accepted domain, so a chart is always built; should one not be,
    // an empty chart with valid axes is drawn rather than axes without extent.
    let mut plot = plot.unwrap_or_else(|| Plot {
        title: "no chart for these values".into(),
        x: linear_axis("- (-)", 0.0, 1.0),
        y: linear_axis("- (-)", 0.0, 1.0),
        ..Plot::default()
    });
    for (role, name, points) in overlays {
        let top = max_y([&points]) * 1.05;
        plot.y.bounds[1] = plot.y.bounds[1].max(top);
        plot.y = linear_axis(plot.y.title.clone(), plot.y.bounds[0], plot.y.bounds[1]);
        plot.series.push(PlotSeries {
            name: name.into(),
            points,
            role,
        });
    }
    if let Some(numeric) = numeric {
        // Where the first gap is; why is too long for a legend (the TUI's status says it).
        let name = match (numeric.failed, &numeric.failure) {
            (0, _) => "finite elements".to_string(),
            (n, Some(first)) => format!("finite elements ({}, from {})", unsolved(n), first.at),
            (n, None) => format!("finite elements ({})", unsolved(n)),
        };
        plot.series.push(PlotSeries {
            name,
            points: numeric.points.clone(),
            role: SeriesRole::FiniteElements,
        });
        if !numeric.continuum.is_empty() {
            plot.series.push(PlotSeries {
                name: "2-D continuum".into(),
                points: numeric.continuum.clone(),
                role: SeriesRole::Continuum,
            });
        }
    }
    plot
}

fn beam_plot(
    beams: &TwinBeams,
    force: TipForce,
    chart: BeamChart,
    f_data: f64,
    span: Option<f64>,
) -> Option<Plot> {
    let p = beams.params();
    let f_max = force_range(beams, force, f_data, span);
    let forces = samples(0.0, f_max, Spacing::Linear)?;
    let kt = p.tangential_stiffness;
    let companions = companions(kt, |k| beams.with_tangential_stiffness(k).ok());
    let f = force.newtons();
    match chart {
        BeamChart::Deflection => {
            response_plot::<TwinBeamsLoad>(beams, &BEAM_LABELS, forces, (f, f_max))
        }
        BeamChart::SlipBoundary => {
            let mut series = Vec::new();
            for (role, label, other) in &companions {
                series.push(line(
                    *role,
                    *label,
                    curves::beam_slip_boundary_vs_force(other, forces).ok()?,
                ));
            }
            series.push(line(
                SeriesRole::Current,
                "K_T",
                curves::beam_slip_boundary_vs_force(beams, forces).ok()?,
            ));
            series.push(cursor(f, [0.0, p.length]));
            Some(Plot {
                caption: None,
                title: format!(
                    "X vs F, K_T = {} MPa/mm, F_1 = {} N",
                    number(kt),
                    number(beams.first_macroslip_force())
                ),
                x: linear_axis("F (N)", 0.0, f_max),
                y: linear_axis("X (mm)", 0.0, p.length),
                series,
            })
        }
        BeamChart::Loop => loop_chart::<TwinBeamsLoad>(beams, &BEAM_LABELS, force),
        BeamChart::Dissipation => {
            let amplitudes = samples(0.0, f_max, Spacing::Linear)?;
            dissipation_chart::<TwinBeamsLoad>(beams, &BEAM_LABELS, force, amplitudes, f_max)
        }
        BeamChart::Shear => {
            let positions = samples(0.0, p.length, Spacing::Linear)?;
            let (coulomb, regularized) = curves::beam_shear_along(beams, force, positions);
            let top = 1.1 * max_y([&coulomb, &regularized]).max(beams.coulomb_stress());
            let mu_p = vec![
                (0.0, beams.coulomb_stress()),
                (p.length, beams.coulomb_stress()),
            ];
            Some(Plot {
                caption: None,
                title: format!("tau(x) at F = {} N, K_T = {} MPa/mm", number(f), number(kt)),
                x: linear_axis("x (mm)", 0.0, p.length),
                y: linear_axis("tau (MPa)", 0.0, top),
                series: vec![
                    line(SeriesRole::Coulomb, "Coulomb", coulomb),
                    line(SeriesRole::Current, "regularized", regularized),
                    line(SeriesRole::Limit, "mu P", mu_p),
                ],
            })
        }
    }
}

/// The K_T range of the plate's displacement chart: four decades either side of K_T, within the
/// accepted stiffnesses (ends in MPa/mm).
fn stiffness_range(kt: f64) -> (f64, f64) {
    let domain = PlateParam::Stiffness.spec().domain;
    (domain.clamp(kt / 1e4), domain.clamp(kt * 1e4))
}

fn plate_plot(plate: &SqueezedPlate, chart: PlateChart) -> Option<Plot> {
    let p = plate.params();
    let kt = p.tangential_stiffness;
    match chart {
        PlateChart::Displacement => {
            let (from, to) = stiffness_range(kt);
            let stiffnesses = samples(from, to, Spacing::Logarithmic)?;
            let (coulomb, regularized) =
                curves::plate_end_displacement_vs_stiffness(plate, stiffnesses).ok()?;
            let to_log = |s: Series| {
                s.into_iter()
                    .map(|(k, u)| (k.log10(), u))
                    .collect::<Series>()
            };
            let (coulomb, regularized) = (to_log(coulomb), to_log(regularized));
            let top = 1.05 * max_y([&coulomb, &regularized]);
            let y = linear_axis("u(L) (mm)", 0.0, top);
            let cursor = cursor(kt.log10(), y.bounds);
            Some(Plot {
                caption: None,
                title: "u(L) vs K_T".into(),
                x: log_axis("K_T (MPa/mm, log)", from.log10(), to.log10()),
                y,
                series: vec![
                    line(SeriesRole::Coulomb, "Coulomb", coulomb),
                    line(SeriesRole::Current, "regularized", regularized),
                    cursor,
                ],
            })
        }
        PlateChart::SlipBoundary => {
            let mu = p.friction;
            // mu/5 to 5 (or 1.5 mu beyond 5), within the accepted friction coefficients.
            let domain = PlateParam::Friction.spec().domain;
            let (lo, hi) = (
                domain.clamp(mu / 5.0),
                domain.clamp((mu * 5.0).min(5.0).max(mu * 1.5)),
            );
            let frictions = samples(lo, hi, Spacing::Linear)?;
            let mut series = Vec::new();
            for (role, label, factor) in [
                (SeriesRole::Softer, "K_T/10", 0.1),
                (SeriesRole::Stiffer, "K_T*10", 10.0),
                (SeriesRole::Current, "K_T", 1.0),
            ] {
                // Companions only where their K_T is accepted.
                let Ok(other) = plate.with_tangential_stiffness(kt * factor) else {
                    continue;
                };
                series.push(line(
                    role,
                    label,
                    curves::plate_slip_boundary_vs_friction(&other, frictions).ok()?,
                ));
            }
            // Zoom on the band the curves use: X_r stays near L over most of the range.
            let bottom = series
                .iter()
                .flat_map(|s| &s.points)
                .map(|q| q.1)
                .fold(p.half_length, f64::min);
            let bottom = (bottom - 0.05 * (p.half_length - bottom)).max(0.0);
            let y = linear_axis("X_r (mm)", bottom, p.half_length);
            series.push(cursor(mu, y.bounds));
            Some(Plot {
                caption: None,
                title: format!("X_r vs mu, K_T = {} MPa/mm", number(kt)),
                x: linear_axis("mu (-)", lo, hi),
                y,
                series,
            })
        }
        PlateChart::ContactPressure => {
            let positions = samples(0.0, p.half_length, Spacing::Linear)?;
            let ratio = curves::plate_contact_pressure_along(plate, positions);
            let (low, high) = ratio.iter().fold((1.0_f64, 1.0_f64), |(lo, hi), &(_, r)| {
                (lo.min(r), hi.max(r))
            });
            let pad = 0.05 * (high - low).max(0.01);
            Some(Plot {
                caption: None,
                title: "P_r(x)/P: flat-plate model P7-P9 (not 2-D)".to_string(),
                x: linear_axis("x (mm)", 0.0, p.half_length),
                y: linear_axis("P_r/P (-)", low - pad, high + pad),
                series: vec![
                    line(SeriesRole::Current, "P_r/P", ratio),
                    line(
                        SeriesRole::Limit,
                        "P_r = P",
                        vec![(0.0, 1.0), (p.half_length, 1.0)],
                    ),
                ],
            })
        }
    }
}

/// The chart `chart` of `model` (a model of the chart's kind) as a figure shows it: the TUI's
/// series, with the finite-element points where asked and the chart has them, the y axis in mode
/// `y` where it applies.
///
/// # Errors
/// The finite-element solver's, when `finite_elements` is asked and it fails.
pub fn figure(
    model: &Model,
    chart: AnyChart,
    finite_elements: bool,
    y: YMode,
) -> Result<Plot, NumericError> {
    let numeric = if finite_elements {
        numeric_points(model, chart)?
    } else {
        None
    };
    Ok(y.apply(build(model, chart, numeric.as_ref(), None, None, None)))
}

/// Finite-element points for chart `chart`, where the chart has a finite-element counterpart.
pub fn numeric_points(
    model: &Model,
    chart: AnyChart,
) -> Result<Option<NumericPoints>, NumericError> {
    let density = MeshDensity::with_elements(OVERLAY_ELEMENTS);
    match (*model, chart) {
        (
            Model::Beam { beams, force },
            AnyChart::Beam(chart @ (BeamChart::Deflection | BeamChart::SlipBoundary)),
        ) => {
            // One model loaded monotonically through the sample forces: one load step per point.
            let f_max = force_range(&beams, force, 0.0, None);
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            let mut points = Vec::with_capacity(OVERLAY_POINTS);
            let (mut failed, mut failure) = (0, None);
            let mut first_failure = None;
            for i in 1..=OVERLAY_POINTS {
                let f = f_max * i as f64 / OVERLAY_POINTS as f64;
                // A very stiff interface can make Newton cycle at one load (the whole interface
                // on the yield limit to round-off): that point is a gap, the model stays at the
                // last converged load and the next point goes on from there.
                match fe.load_to(f, 2) {
                    Ok(()) => {}
                    Err(e @ NumericError::NoConvergence { .. }) => {
                        failed += 1;
                        first_failure.get_or_insert_with(|| PointFailure {
                            at: format!("F = {} N", number(f)),
                            why: e.to_string(),
                        });
                        failure = Some(e);
                        continue;
                    }
                    Err(e) => return Err(e),
                }
                points.push((
                    f,
                    if chart == BeamChart::Deflection {
                        fe.tip_deflection()
                    } else {
                        fe.micro_zone_end()
                    },
                ));
            }
            match failure {
                Some(e) if points.is_empty() => Err(e),
                _ => Ok(Some(NumericPoints {
                    points,
                    continuum: Vec::new(),
                    failed,
                    failure: first_failure,
                })),
            }
        }
        (Model::Beam { beams, force }, AnyChart::Beam(BeamChart::Loop)) => {
            // The FE model driven round the same cycle: its own slider histories, no Masing rule.
            let fa = force.newtons();
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(fa, 4)?;
            let points = fe_loop(fa, OVERLAY_POINTS, |f| {
                fe.load_to(f, 2)?;
                Ok(fe.tip_deflection())
            })?;
            Ok(Some(NumericPoints {
                points,
                continuum: Vec::new(),
                failed: 0,
                failure: None,
            }))
        }
        (Model::Beam { beams, force }, AnyChart::Beam(BeamChart::Shear)) => {
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(force.newtons(), 4)?;
            let samples = fe.interface();
            let stride = (samples.len() / 40).max(1);
            Ok(Some(NumericPoints {
                continuum: Vec::new(),
                failed: 0,
                failure: None,
                points: samples
                    .iter()
                    .step_by(stride)
                    .map(|s| (s.x, s.stress))
                    .collect(),
            }))
        }
        (Model::Plate(plate), AnyChart::Plate(PlateChart::Displacement)) => {
            let p = plate.params();
            let (from, to) = stiffness_range(p.tangential_stiffness);
            let (lo, hi) = (from.log10(), to.log10());
            let mut points = Vec::with_capacity(OVERLAY_POINTS + 1);
            let mut continuum = Vec::with_capacity(OVERLAY_POINTS + 1);
            let (mut failure, mut first_failure) = (None, None);
            for i in 0..=OVERLAY_POINTS {
                let log_kt = lo + (hi - lo) * i as f64 / OVERLAY_POINTS as f64;
                let params = crate::PlateParams {
                    tangential_stiffness: PlateParam::Stiffness
                        .spec()
                        .domain
                        .clamp(10f64.powf(log_kt)),
                    ..p
                };
                // A solve that fails at an extreme K_T (the 1-D solver at 1e10 MPa/mm, the
                // continuum beyond its stiffness limit) leaves a gap, not an error; only a chart
                // without any point reports the failure.
                let mut fe = PlateFe::new(params, density);
                match fe.load_to(p.pressure, 2) {
                    Ok(()) => points.push((log_kt, fe.end_displacement())),
                    Err(e) => {
                        first_failure.get_or_insert_with(|| PointFailure {
                            at: format!("K_T = {} MPa/mm", number(params.tangential_stiffness)),
                            why: e.to_string(),
                        });
                        failure = Some(e);
                    }
                }
                if let Ok(solution) = solve_plate_continuum(params, ContinuumMesh::default()) {
                    continuum.push((log_kt, solution.end_displacement_mean));
                }
            }
            match failure {
                Some(e) if points.is_empty() => Err(e),
                _ => Ok(Some(NumericPoints {
                    failed: OVERLAY_POINTS + 1 - points.len(),
                    failure: first_failure,
                    points,
                    continuum,
                })),
            }
        }
        // No finite-element counterpart: dissipation (a closed-form integral of the loop), the
        // contact pressure, X_r vs mu; and a chart of another problem.
        (Model::Beam { .. }, AnyChart::Beam(BeamChart::Dissipation))
        | (
            Model::Plate(_),
            AnyChart::Plate(PlateChart::SlipBoundary | PlateChart::ContactPressure),
        )
        | (Model::Beam { .. }, AnyChart::Plate(_) | AnyChart::Lap(_))
        | (Model::Plate(_), AnyChart::Beam(_) | AnyChart::Lap(_))
        | (Model::Lap { .. }, AnyChart::Beam(_) | AnyChart::Plate(_)) => Ok(None),
        (Model::Lap { joint, force }, AnyChart::Lap(chart)) => {
            lap::lap_numeric_points(&joint, force, chart, density, OVERLAY_POINTS)
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::problems::inputs::Inputs;

    /// Every chart of `kind`, in the order the `c` key reaches them.
    pub(crate) fn every_chart(kind: ModelKind) -> Vec<AnyChart> {
        AnyChart::all().filter(|c| c.kind() == kind).collect()
    }

    fn model(kind: ModelKind) -> Model {
        Inputs::paper(kind).validate().unwrap()
    }

    #[test]
    fn every_chart_has_titles_units_bounds_and_finite_points() {
        for kind in [ModelKind::Beam, ModelKind::Plate] {
            for shown in every_chart(kind) {
                let chart = shown.title();
                let plot = build(&model(kind), shown, None, None, None, None);
                assert!(!plot.title.is_empty());
                assert!(
                    plot.x.title.contains('(') && plot.y.title.contains('('),
                    "{kind} {chart}: units"
                );
                assert!(plot.x.bounds[0] < plot.x.bounds[1] && plot.y.bounds[0] < plot.y.bounds[1]);
                assert!(!plot.series.is_empty());
                for s in &plot.series {
                    assert!(
                        s.points.iter().all(|(x, y)| x.is_finite() && y.is_finite()),
                        "{kind} {chart} {}",
                        s.name
                    );
                }
            }
        }
    }

    /// Axes finite and strictly increasing, every point finite and on the chart.
    fn check_plot(plot: &Plot, what: &str) {
        for axis in [&plot.x, &plot.y] {
            let [lo, hi] = axis.bounds;
            assert!(
                lo.is_finite() && hi.is_finite() && lo < hi,
                "{what}: {} {:?}",
                axis.title,
                axis.bounds
            );
            assert!(axis.labels.iter().all(|l| !l.contains("n/a")), "{what}");
        }
        assert!(!plot.series.is_empty(), "{what}");
        for s in &plot.series {
            for &(x, y) in &s.points {
                let inside = |v: f64, [lo, hi]: [f64; 2]| {
                    v.is_finite() && v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo)
                };
                assert!(
                    inside(x, plot.x.bounds) && inside(y, plot.y.bounds),
                    "{what} {}: ({x}, {y}) outside {:?} x {:?}",
                    s.name,
                    plot.x.bounds,
                    plot.y.bounds
                );
            }
        }
    }

    /// Every corner of each model's domain (the beam force at 0, at the largest accepted force
    /// or at F_thre, in turn), with a name for messages. nu (half-open domain, and only in the
    /// beams' shear deflection) keeps its value there.
    pub(crate) fn corner_models() -> Vec<(String, Model)> {
        use crate::problems::BeamParam;
        let mut models = Vec::new();
        let beam_params: Vec<BeamParam> = BeamParam::ALL
            .into_iter()
            .filter(|p| !matches!(p, BeamParam::Force | BeamParam::Poisson))
            .collect();
        for mask in 0..1_u32 << beam_params.len() {
            let mut inputs = Inputs::paper(ModelKind::Beam);
            for (i, param) in beam_params.iter().enumerate() {
                let domain = param.spec().domain;
                let value = if mask & (1 << i) == 0 {
                    domain.min()
                } else {
                    domain.max()
                };
                inputs.set(crate::Param::Beam(*param), value).unwrap();
            }
            let Ok(Model::Beam { beams, .. }) = inputs.validate() else {
                panic!("corner {mask} refused");
            };
            let force = match mask % 3 {
                0 => 0.0,
                1 => BeamParam::Force.spec().domain.max(),
                _ => TipForce::clamped(beams.threshold_force()).newtons(),
            };
            inputs
                .set(crate::Param::Beam(BeamParam::Force), force)
                .unwrap();
            models.push((
                format!("beam corner {mask} F={force}"),
                inputs.validate().unwrap(),
            ));
        }
        let plate_params = crate::PlateParam::ALL;
        for mask in 0..1_u32 << 7 {
            let mut inputs = Inputs::paper(ModelKind::Plate);
            for (i, param) in plate_params.iter().enumerate() {
                let domain = param.spec().domain;
                let value = if mask & (1 << i) == 0 {
                    domain.min()
                } else {
                    domain.clamp(domain.max())
                };
                inputs.set(crate::Param::Plate(*param), value).unwrap();
            }
            models.push((format!("plate corner {mask}"), inputs.validate().unwrap()));
        }
        models
    }

    #[test]
    fn every_chart_at_every_corner_of_the_domain_has_valid_axes() {
        for (what, model) in corner_models() {
            for chart in every_chart(model.kind()) {
                let plot = build(&model, chart, None, None, None, None);
                check_plot(&plot, &format!("{what} {chart:?}"));
            }
        }
    }

    #[test]
    fn flat_and_huge_ranges_still_give_increasing_axes() {
        assert_eq!(axis_bounds(0.0, 0.0), [0.0, 1.0]);
        let [lo, hi] = axis_bounds(1e17, 1e17);
        assert!(lo < hi && hi - lo >= 1e8);
        let [lo, hi] = axis_bounds(1e-300, 1e-300);
        assert!(lo < hi);
        assert_eq!(axis_bounds(2.0, 5.0), [2.0, 5.0]);
        let [lo, hi] = axis_bounds(f64::NAN, f64::INFINITY);
        assert!(lo.is_finite() && hi.is_finite() && lo < hi);
    }

    /// Issue 36 (12): a point of the overlay that did not converge is a gap, and the legend says
    /// where and why, not only how many.
    #[test]
    fn the_overlay_says_why_a_point_did_not_converge() {
        // K_T up to 1e4 times 1e7 MPa/mm: the top points are beyond the 1-D solver's resolution.
        let mut inputs = Inputs::paper(ModelKind::Plate);
        let kt = crate::problems::Param::Plate(PlateParam::Stiffness);
        inputs.set(kt, 1e7).unwrap();
        let model = inputs.validate().unwrap();
        let chart = AnyChart::Plate(PlateChart::Displacement);
        let numeric = numeric_points(&model, chart).unwrap().unwrap();
        assert!(numeric.failed > 0);
        let words = numeric.failure_words().unwrap();
        assert!(
            words.contains("not solved; the first, at K_T = 1e10 MPa/mm: the saturation slip"),
            "{words}"
        );
        let plot = build(&model, chart, Some(&numeric), None, None, None);
        assert!(
            plot.series.iter().any(|s| s
                .name
                .ends_with("points not solved, from K_T = 1e10 MPa/mm)")),
            "{:?}",
            plot.series.iter().map(|s| &s.name).collect::<Vec<_>>()
        );
    }

    #[test]
    fn finite_element_points_sit_on_the_analytic_curve() {
        let m = model(ModelKind::Beam);
        let numeric = numeric_points(&m, AnyChart::Beam(BeamChart::Deflection))
            .unwrap()
            .unwrap();
        let Model::Beam { beams, .. } = m else {
            unreachable!()
        };
        for (f, w) in numeric.points {
            let exact = beams
                .regularized(TipForce::new(f).unwrap())
                .tip_deflection();
            assert!((w / exact - 1.0).abs() < 1e-4, "F={f}");
        }
        assert!(
            numeric_points(
                &model(ModelKind::Plate),
                AnyChart::Plate(PlateChart::ContactPressure)
            )
            .unwrap()
            .is_none()
        );
    }
}
