//! What a chart is, as plain data: its axes, its series and their roles, the finite-element and
//! external points drawn over it, and the helpers that build them (a line, a cursor, an axis with
//! bounds that always increase).

use crate::kernel::format::number_with;
use crate::problems::ModelKind;
use crate::study::curves::Series;

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
    /// The solver's reason (a [`crate::numeric::NumericError`]'s message).
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
pub(crate) fn unsolved(count: usize) -> String {
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
pub(crate) fn axis_bounds(lo: f64, hi: f64) -> [f64; 2] {
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
pub(crate) fn tick(value: f64) -> String {
    number_with(value, 3)
}

pub(crate) fn max_y<'a>(series: impl IntoIterator<Item = &'a Series>) -> f64 {
    series
        .into_iter()
        .flatten()
        .map(|p| p.1)
        .fold(0.0, f64::max)
}
