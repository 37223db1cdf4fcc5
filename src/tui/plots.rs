//! What each chart shows, as plain data (title, axes, series), built from [`crate::curves`]. The
//! drawing code turns a [`Plot`] into cells and never computes physics itself.

use crate::curves::{self, Samples, Series, Spacing};
use crate::fit::Measurement;
use crate::numeric::{MeshDensity, NumericError, PlateFe, TwinBeamsFe};
use crate::preset::{Model, ModelKind};
use crate::report::{number, number_with};
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// Points per analytic curve: two per column of a 100-column chart, enough for Braille resolution.
pub const SAMPLES: u64 = 200;

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
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// A curve.
    Line,
    /// Isolated markers (finite-element results).
    Points,
    /// The vertical cursor at the current value.
    Cursor,
}

/// One series.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSeries {
    /// Legend text.
    pub name: String,
    /// Points in plotted units.
    pub points: Series,
    /// Line, points or cursor.
    pub kind: SeriesKind,
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
    /// Text lines shown instead of a chart (the K_T comparison table).
    pub table: Option<Vec<String>>,
}

/// Finite-element results for the overlay, in the chart's plotted units.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericPoints {
    /// The points.
    pub points: Series,
}

/// The charts of each model, in the order `c` cycles through them.
pub fn chart_names(kind: ModelKind) -> &'static [&'static str] {
    match kind {
        ModelKind::Beam => &[
            "w(L) vs F",
            "X vs F",
            "tau(x) at F",
            "loop +-F",
            "D vs F_a",
            "K_T: codes vs physics",
        ],
        ModelKind::Plate => &[
            "u(L) vs K_T",
            "X_r vs mu",
            "P_r(x)/P",
            "K_T: codes vs physics",
        ],
    }
}

fn line(name: impl Into<String>, points: Series) -> PlotSeries {
    PlotSeries {
        name: name.into(),
        points,
        kind: SeriesKind::Line,
    }
}

fn cursor(x: f64, [y0, y1]: [f64; 2]) -> PlotSeries {
    PlotSeries {
        name: "current".into(),
        points: vec![(x, y0), (x, y1)],
        kind: SeriesKind::Cursor,
    }
}

fn linear_axis(title: impl Into<String>, lo: f64, hi: f64) -> Axis {
    let hi = if hi > lo { hi } else { lo + 1.0 };
    Axis {
        title: title.into(),
        bounds: [lo, hi],
        labels: [lo, 0.5 * (lo + hi), hi].iter().map(|&v| tick(v)).collect(),
    }
}

/// An axis in log10 units, labelled with the values themselves.
fn log_axis(title: impl Into<String>, lo: f64, hi: f64) -> Axis {
    let labels = [lo, 0.5 * (lo + hi), hi]
        .iter()
        .map(|&v| tick(10f64.powf(v)))
        .collect();
    Axis {
        title: title.into(),
        bounds: [lo, hi],
        labels,
    }
}

/// Tick labels: 3 significant digits keep the y axis narrow.
fn tick(value: f64) -> String {
    number_with(value, 3)
}

fn max_y<'a>(series: impl IntoIterator<Item = &'a Series>) -> f64 {
    series
        .into_iter()
        .flatten()
        .map(|p| p.1)
        .fold(0.0, f64::max)
}

/// The force range of the beam charts: up to 3 F_thre, or further to show the current F and the
/// largest measured force.
fn force_range(beams: &TwinBeams, force: TipForce, f_data: f64) -> f64 {
    (3.0 * beams.threshold_force())
        .max(1.25 * force.newtons())
        .max(1.05 * f_data)
}

fn samples(from: f64, to: f64, spacing: Spacing) -> Option<Samples> {
    Samples::new(from, to, SAMPLES, spacing, ("from", "to")).ok()
}

/// Index of the K_T table among each model's charts.
const BEAM_STIFFNESS_TABLE: usize = 5;
const PLATE_STIFFNESS_TABLE: usize = 3;
/// Index of the hysteresis-loop and dissipation charts of the twin beams.
const BEAM_LOOP: usize = 3;
const BEAM_DISSIPATION: usize = 4;

/// The closed hysteresis loop of a cycle: unloading from +F_a, then reloading from -F_a.
fn loop_series(cycle: &crate::model::cycle::Cycle) -> Series {
    let fa = cycle.amplitude();
    let n = SAMPLES as usize / 2;
    let down = (0..=n)
        .map(|i| fa - 2.0 * fa * i as f64 / n as f64)
        .map(|f| (f, cycle.unloading(f)));
    let up = (1..=n)
        .map(|i| -fa + 2.0 * fa * i as f64 / n as f64)
        .map(|f| (f, cycle.reloading(f)));
    down.chain(up).collect()
}

/// Contact elements assumed by the K_T table: L/100, a typical benchmark mesh (the command line's
/// `microslip kt --element-size` sets any other).
const TABLE_ELEMENTS_PER_LENGTH: f64 = 100.0;

/// The K_T comparison as a narrow table (fits the 44-column chart pane of an 80x24 screen).
fn stiffness_table(model: &Model) -> Plot {
    use crate::model::code_defaults::{CODE_DEFAULTS, Confirmation, DefaultRule};
    let data = model.interface();
    let (length, mu, pressure, modulus, kt) = (
        data.length,
        data.friction,
        data.pressure,
        data.modulus,
        data.stiffness,
    );
    let element = length / TABLE_ELEMENTS_PER_LENGTH;
    let rows = curves::stiffness_candidates(kt, mu, pressure, modulus, element, None);
    let short = |source: &str| {
        CODE_DEFAULTS
            .iter()
            .find(|c| c.code == source)
            .map_or(source.to_string(), |c| c.short.to_string())
    };
    let mut lines = vec![match model {
        Model::Beam { .. } => format!(
            "{:<10} {:>7} {:>7} {:>7} {:>8}",
            "source", "K_T", "F_1 N", "X mm", "w(L) mm"
        ),
        Model::Plate(_) => format!(
            "{:<10} {:>7} {:>9} {:>8}",
            "source", "K_T", "u(L) mm", "X_r mm"
        ),
    }];
    for row in &rows {
        let cells = match (model, row.kt) {
            (Model::Beam { beams, force }, Some(k)) => {
                curves::beam_answer(beams, *force, k).map(|(f_1, x, w, _)| {
                    format!(
                        "{:>7} {:>7} {:>7} {:>8}",
                        tick(k),
                        tick(f_1),
                        tick(x),
                        tick(w)
                    )
                })
            }
            (Model::Plate(plate), Some(k)) => curves::plate_answer(plate, k)
                .map(|(u, x, _)| format!("{:>7} {:>9} {:>8}", tick(k), tick(u), tick(x))),
            _ => None,
        };
        let cells = cells.unwrap_or_else(|| format!("{:>7}", "none"));
        lines.push(format!("{:<10} {cells}", short(&row.source)));
    }
    lines.push(String::new());
    lines.push(format!(
        "K_T MPa/mm; FE elements {} mm (L/100)",
        number(element)
    ));
    for code in CODE_DEFAULTS {
        let how = match (code.rule, code.confirmation) {
            (DefaultRule::UserSupplied, _) => "no default: user input",
            (_, Confirmation::Confirmed) => "default confirmed",
            (_, Confirmation::Indirect) => "seen in solver output only",
            (_, Confirmation::NotConfirmed) => "default NOT confirmed",
        };
        lines.push(format!("{}: {how}", code.short));
    }
    lines.push("Other sizes, K_N, eq. 4: microslip kt".into());
    Plot {
        title: "K_T that FE codes assume by default".into(),
        table: Some(lines),
        ..Plot::default()
    }
}

/// Builds chart `chart` of `model`, with finite-element points and measurements if given
/// (measurements show on the twin beams' w(L) vs F chart).
pub fn build(
    model: &Model,
    chart: usize,
    numeric: Option<&NumericPoints>,
    measured: Option<&[Measurement]>,
) -> Plot {
    let table = match model {
        Model::Beam { .. } => BEAM_STIFFNESS_TABLE,
        Model::Plate(_) => PLATE_STIFFNESS_TABLE,
    };
    if chart == table {
        return stiffness_table(model);
    }
    let measured = measured.filter(|_| matches!(model, Model::Beam { .. }) && chart == 0);
    let mut plot = match *model {
        Model::Beam { beams, force } => {
            let f_data = measured.and_then(|m| m.last()).map_or(0.0, |m| m.force);
            beam_plot(&beams, force, chart, f_data)
        }
        Model::Plate(plate) => plate_plot(&plate, chart),
    }
    .unwrap_or_default();
    if let Some(points) = measured {
        let points: Series = points.iter().map(|m| (m.force, m.deflection)).collect();
        let top = max_y([&points]) * 1.05;
        plot.y.bounds[1] = plot.y.bounds[1].max(top);
        plot.y = linear_axis(plot.y.title.clone(), plot.y.bounds[0], plot.y.bounds[1]);
        plot.series.push(PlotSeries {
            name: "measured".into(),
            points,
            kind: SeriesKind::Points,
        });
    }
    if let Some(numeric) = numeric {
        plot.series.push(PlotSeries {
            name: "finite elements".into(),
            points: numeric.points.clone(),
            kind: SeriesKind::Points,
        });
    }
    plot
}

fn beam_plot(beams: &TwinBeams, force: TipForce, chart: usize, f_data: f64) -> Option<Plot> {
    let p = beams.params();
    let f_max = force_range(beams, force, f_data);
    let forces = samples(0.0, f_max, Spacing::Linear)?;
    let kt = p.tangential_stiffness;
    let softer = beams.with_tangential_stiffness(kt / 5.0).ok()?;
    let stiffer = beams.with_tangential_stiffness(kt * 5.0).ok()?;
    let f = force.newtons();
    match chart {
        0 => {
            let (coulomb, regularized) = curves::beam_deflection_vs_force(beams, forces);
            let (_, soft) = curves::beam_deflection_vs_force(&softer, forces);
            let (_, stiff) = curves::beam_deflection_vs_force(&stiffer, forces);
            let top = 1.05 * max_y([&coulomb, &regularized, &soft, &stiff]);
            Some(Plot {
                table: None,
                title: format!("w(L) vs F, K_T = {} MPa/mm", number(kt)),
                x: linear_axis("F (N)", 0.0, f_max),
                y: linear_axis("w(L) (mm)", 0.0, top),
                // The current K_T last, so that it is drawn on top.
                series: vec![
                    line("Coulomb", coulomb),
                    line("K_T/5", soft),
                    line("K_T*5", stiff),
                    line("K_T", regularized),
                    cursor(f, [0.0, top]),
                ],
            })
        }
        1 => {
            let regularized = curves::beam_slip_boundary_vs_force(beams, forces);
            let soft = curves::beam_slip_boundary_vs_force(&softer, forces);
            let stiff = curves::beam_slip_boundary_vs_force(&stiffer, forces);
            Some(Plot {
                table: None,
                title: format!(
                    "X vs F, K_T = {} MPa/mm, F_1 = {} N",
                    number(kt),
                    number(beams.first_macroslip_force())
                ),
                x: linear_axis("F (N)", 0.0, f_max),
                y: linear_axis("X (mm)", 0.0, p.length),
                series: vec![
                    line("K_T/5", soft),
                    line("K_T*5", stiff),
                    line("K_T", regularized),
                    cursor(f, [0.0, p.length]),
                ],
            })
        }
        BEAM_LOOP => {
            use crate::model::cycle::{Cycle, Law};
            let (coulomb, regularized) = (
                Cycle::new(beams, Law::Coulomb, force),
                Cycle::new(beams, Law::Regularized, force),
            );
            let top = 1.05
                * coulomb
                    .peak_deflection()
                    .max(regularized.peak_deflection())
                    .max(f64::MIN_POSITIVE);
            let span = f.max(1e-9);
            Some(Plot {
                table: None,
                title: format!(
                    "+-{} N: D = {} (C), {} (reg.) N mm",
                    number(f),
                    number_with(coulomb.dissipation(), 3),
                    number_with(regularized.dissipation(), 3)
                ),
                x: linear_axis("F (N)", -span, span),
                y: linear_axis("w(L) (mm)", -top, top),
                series: vec![
                    line("Coulomb", loop_series(&coulomb)),
                    line("regularized", loop_series(&regularized)),
                ],
            })
        }
        BEAM_DISSIPATION => {
            let amplitudes = samples(0.0, f_max, Spacing::Linear)?;
            let (coulomb, regularized) = curves::dissipation_vs_amplitude(beams, amplitudes);
            let top = 1.05 * max_y([&coulomb, &regularized]).max(f64::MIN_POSITIVE);
            let zeta = curves::cycle_point(beams, force);
            Some(Plot {
                table: None,
                title: format!(
                    "D per cycle vs F_a; zeta at F: {} (C), {} (reg.)",
                    number_with(zeta.zeta_coulomb, 3),
                    number_with(zeta.zeta_regularized, 3)
                ),
                x: linear_axis("F_a (N)", 0.0, f_max),
                y: linear_axis("D (N mm)", 0.0, top),
                series: vec![
                    line("Coulomb", coulomb),
                    line("regularized", regularized),
                    cursor(f, [0.0, top]),
                ],
            })
        }
        _ => {
            let positions = samples(0.0, p.length, Spacing::Linear)?;
            let (coulomb, regularized) = curves::beam_shear_along(beams, force, positions);
            let top = 1.1 * max_y([&coulomb, &regularized]).max(beams.coulomb_stress());
            let mu_p = vec![
                (0.0, beams.coulomb_stress()),
                (p.length, beams.coulomb_stress()),
            ];
            Some(Plot {
                table: None,
                title: format!("tau(x) at F = {} N, K_T = {} MPa/mm", number(f), number(kt)),
                x: linear_axis("x (mm)", 0.0, p.length),
                y: linear_axis("tau (MPa)", 0.0, top),
                series: vec![
                    line("Coulomb", coulomb),
                    line("regularized", regularized),
                    line("mu P", mu_p),
                ],
            })
        }
    }
}

/// The K_T range of the plate's displacement chart: four decades either side of K_T (log10 units).
fn stiffness_range(kt: f64) -> (f64, f64) {
    let centre = kt.log10();
    (centre - 4.0, centre + 4.0)
}

fn plate_plot(plate: &SqueezedPlate, chart: usize) -> Option<Plot> {
    let p = plate.params();
    let kt = p.tangential_stiffness;
    match chart {
        0 => {
            let (lo, hi) = stiffness_range(kt);
            let stiffnesses = samples(10f64.powf(lo), 10f64.powf(hi), Spacing::Logarithmic)?;
            let (coulomb, regularized) =
                curves::plate_end_displacement_vs_stiffness(plate, stiffnesses);
            let to_log = |s: Series| {
                s.into_iter()
                    .map(|(k, u)| (k.log10(), u))
                    .collect::<Series>()
            };
            let (coulomb, regularized) = (to_log(coulomb), to_log(regularized));
            let top = 1.05 * max_y([&coulomb, &regularized]);
            Some(Plot {
                table: None,
                title: "u(L) vs K_T (log scale)".into(),
                x: log_axis("K_T (MPa/mm, log)", lo, hi),
                y: linear_axis("u(L) (mm)", 0.0, top),
                series: vec![
                    line("Coulomb", coulomb),
                    line("regularized", regularized),
                    cursor(kt.log10(), [0.0, top]),
                ],
            })
        }
        1 => {
            let mu = p.friction;
            let (lo, hi) = (mu / 5.0, (mu * 5.0).min(5.0).max(mu * 1.5));
            let frictions = samples(lo, hi, Spacing::Linear)?;
            let mut series = Vec::new();
            for (label, factor) in [("K_T/10", 0.1), ("K_T*10", 10.0), ("K_T", 1.0)] {
                let other = plate.with_tangential_stiffness(kt * factor).ok()?;
                series.push(line(
                    label,
                    curves::plate_slip_boundary_vs_friction(&other, frictions),
                ));
            }
            // Zoom on the band the curves use: X_r stays near L over most of the range.
            let bottom = series
                .iter()
                .flat_map(|s| &s.points)
                .map(|q| q.1)
                .fold(p.half_length, f64::min);
            let bottom = (bottom - 0.05 * (p.half_length - bottom)).max(0.0);
            series.push(cursor(mu, [bottom, p.half_length]));
            Some(Plot {
                table: None,
                title: format!("X_r vs mu, K_T = {} MPa/mm", number(kt)),
                x: linear_axis("mu (-)", lo, hi),
                y: linear_axis("X_r (mm)", bottom, p.half_length),
                series,
            })
        }
        _ => {
            let positions = samples(0.0, p.half_length, Spacing::Linear)?;
            let ratio = curves::plate_contact_pressure_along(plate, positions);
            let (low, high) = ratio.iter().fold((1.0_f64, 1.0_f64), |(lo, hi), &(_, r)| {
                (lo.min(r), hi.max(r))
            });
            let pad = 0.05 * (high - low).max(0.01);
            let flag = if plate.contact_pressure().constant_pressure_holds() {
                "holds"
            } else {
                "FAILS"
            };
            Some(Plot {
                table: None,
                title: format!("P_r(x)/P; constant-P assumption {flag}"),
                x: linear_axis("x (mm)", 0.0, p.half_length),
                y: linear_axis("P_r/P (-)", low - pad, high + pad),
                series: vec![
                    line("P_r/P", ratio),
                    line("P_r = P", vec![(0.0, 1.0), (p.half_length, 1.0)]),
                ],
            })
        }
    }
}

/// Finite-element points for chart `chart`, where the chart has a finite-element counterpart.
pub fn numeric_points(model: &Model, chart: usize) -> Result<Option<NumericPoints>, NumericError> {
    let density = MeshDensity::with_elements(OVERLAY_ELEMENTS);
    match *model {
        Model::Beam { beams, force } if chart <= 1 => {
            // One model loaded monotonically through the sample forces: one load step per point.
            let f_max = force_range(&beams, force, 0.0);
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            let mut points = Vec::with_capacity(OVERLAY_POINTS);
            for i in 1..=OVERLAY_POINTS {
                let f = f_max * i as f64 / OVERLAY_POINTS as f64;
                fe.load_to(f, 2)?;
                points.push((
                    f,
                    if chart == 0 {
                        fe.tip_deflection()
                    } else {
                        fe.micro_zone_end()
                    },
                ));
            }
            Ok(Some(NumericPoints { points }))
        }
        Model::Beam { beams, force } if chart == BEAM_LOOP => {
            // The FE model driven round the same cycle: its own slider histories, no Masing rule.
            let fa = force.newtons();
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(fa, 4)?;
            let mut points = Vec::with_capacity(2 * OVERLAY_POINTS);
            for (from, sign) in [(fa, -1.0), (-fa, 1.0)] {
                for i in 1..=OVERLAY_POINTS {
                    let f = from + sign * 2.0 * fa * i as f64 / OVERLAY_POINTS as f64;
                    fe.load_to(f, 2)?;
                    points.push((f, fe.tip_deflection()));
                }
            }
            Ok(Some(NumericPoints { points }))
        }
        Model::Beam { beams, force } if chart == 2 => {
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(force.newtons(), 4)?;
            let samples = fe.interface();
            let stride = (samples.len() / 40).max(1);
            Ok(Some(NumericPoints {
                points: samples
                    .iter()
                    .step_by(stride)
                    .map(|s| (s.x, s.stress))
                    .collect(),
            }))
        }
        Model::Plate(plate) if chart == 0 => {
            let p = plate.params();
            let (lo, hi) = stiffness_range(p.tangential_stiffness);
            let mut points = Vec::with_capacity(OVERLAY_POINTS + 1);
            for i in 0..=OVERLAY_POINTS {
                let log_kt = lo + (hi - lo) * i as f64 / OVERLAY_POINTS as f64;
                let params = crate::PlateParams {
                    tangential_stiffness: 10f64.powf(log_kt),
                    ..p
                };
                let mut fe = PlateFe::new(params, density);
                fe.load_to(p.pressure, 2)?;
                points.push((log_kt, fe.end_displacement()));
            }
            Ok(Some(NumericPoints { points }))
        }
        Model::Beam { .. } | Model::Plate(_) => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Inputs;

    fn model(kind: ModelKind) -> Model {
        Inputs::paper(kind).validate().unwrap()
    }

    #[test]
    fn every_chart_has_titles_units_bounds_and_finite_points() {
        for kind in [ModelKind::Beam, ModelKind::Plate] {
            for chart in 0..chart_names(kind).len() {
                let plot = build(&model(kind), chart, None, None);
                assert!(!plot.title.is_empty());
                if let Some(table) = &plot.table {
                    // The K_T table: every line fits the 44-column pane of an 80x24 screen, no NaN.
                    assert!(
                        table.iter().all(|l| l.len() <= 43 && !l.contains("NaN")),
                        "{table:#?}"
                    );
                    continue;
                }
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

    #[test]
    fn finite_element_points_sit_on_the_analytic_curve() {
        let m = model(ModelKind::Beam);
        let numeric = numeric_points(&m, 0).unwrap().unwrap();
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
            numeric_points(&model(ModelKind::Plate), 2)
                .unwrap()
                .is_none()
        );
    }
}
