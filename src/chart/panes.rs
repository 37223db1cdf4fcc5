//! What a problem shows beside its charts on the terminal screen, as text and numbers: the
//! parameter pane's title, the regime pane's lines (with what each means), the zone strip's
//! origin and shear, the K_T table's rows, the regime pane's own continuum solve, the setting a
//! key toggles, the measured curve `d` reads and what `f` fits. Each problem writes them in its
//! face folder (`src/problems/<name>/pane.rs`) as its [`PaneFace`]; the TUI reaches them only
//! through its erased face ([`erased`], in the application's table `report::face::faces`,
//! built from the registry), so that no screen file names a problem
//! and the drawing (`tui/ui/`) reads the text the view model built from these.
//!
//! Why here, in the chart layer: the faces sit above it and the TUI above them, so the trait
//! must live below the faces; the regime pane is the chart pane's companion (the same model,
//! described in words instead of curves), and this layer already turns a model into what a
//! screen shows.

use crate::fe::face::LoadedVariant;
use crate::fe::load::{AnyLoaded, Loaded};
use crate::fit::Measured;
use crate::kernel::format::{number, number_with};
use crate::kernel::validity::Validity;
use crate::measured::DataError;
use crate::problems::inputs::{Inputs, Model};
use crate::problems::{LoadDriven, ModelKind};
use crate::study::tolerance::{
    Threshold, ToleranceAnswer, ToleranceError, stiffness_for_tolerance,
};

/// One line of the regime pane: its text (a regime line has a label and a styled value) and what
/// it means, in words for someone who has not read the paper (`i`, and the spare height of tall
/// screens).
#[derive(Debug, Clone, PartialEq)]
pub struct SummaryLine {
    /// The text, or the label of a regime line.
    pub text: String,
    /// The regime, for regime lines.
    pub regime: Option<String>,
    /// What the line means (most are fixed words; a line whose meaning states its own numbers,
    /// as the beams' envelopes in both kinematics, owns it).
    pub meaning: std::borrow::Cow<'static, str>,
    /// When the pane is short of rows, lines are dropped in increasing order of this rank; 0: kept
    /// always. What is dropped can be read elsewhere (the ratio and one w(L) give the other).
    pub drop_rank: u8,
}

impl SummaryLine {
    /// A line of text, kept always.
    pub fn plain(text: String, meaning: impl Into<std::borrow::Cow<'static, str>>) -> SummaryLine {
        SummaryLine {
            text,
            regime: None,
            meaning: meaning.into(),
            drop_rank: 0,
        }
    }

    /// A regime line: `label` padded to the column the regimes start at, then `regime`.
    pub fn regime(
        label: &str,
        regime: String,
        meaning: impl Into<std::borrow::Cow<'static, str>>,
    ) -> SummaryLine {
        SummaryLine {
            text: format!("{label:<12}"),
            regime: Some(regime),
            meaning: meaning.into(),
            drop_rank: 0,
        }
    }

    /// The same line, dropped `rank`-th when rows are short.
    #[must_use]
    pub fn dropped(self, rank: u8) -> SummaryLine {
        SummaryLine {
            drop_rank: rank,
            ..self
        }
    }
}

/// What the regime pane's own continuum solve found (the plate's u(L) and edge pressure).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuumSummary {
    /// u(L), thickness mean (mm).
    pub end_displacement: f64,
    /// Contact pressure over P, mean over the last t_p / 10: the free-end peak at that resolution
    /// (the corner node's own value grows with refinement).
    pub edge_pressure: f64,
}

/// Where the regime pane's 2-D continuum solution (the plate's best answer for u(L)) stands: it
/// is solved on a worker, since it takes up to a tenth of a second.
#[derive(Debug, Clone, PartialEq)]
pub enum ContinuumState {
    /// Not asked for (a problem whose pane has none, or an app that does not solve it).
    Off,
    /// Asked for the current values, not there yet.
    Solving,
    /// Solved at the current values.
    Solved(ContinuumSummary),
    /// Why there is none (out of the solver's range, no convergence).
    Failed(String),
}

/// The reader of a problem's measured load-response curve (`F_N,w_mm`, `F_N,Delta_mm`): what
/// `d` and `--data` read and `f` fits; `progress` is called every few ten thousand rows.
pub type CurveParser = fn(&str, &mut dyn FnMut(usize, usize)) -> Result<Measured, DataError>;

/// The regime pane's own continuum solve of a model `M` (see [`PaneFace::PANE_CONTINUUM`]): its
/// summary, or why there is none.
pub type PaneContinuum<M> = fn(&M) -> Result<ContinuumSummary, String>;

/// What the regime pane's ratio of the regularized response to Coulomb's means, for every
/// problem.
pub const RATIO_MEANING: &str =
    "regularized / Coulomb: 1.01 means 1 % more than under the plain Coulomb law";

/// What the regime pane's saturation slip means, for every problem.
pub const SATURATION_MEANING: &str = "mu P / K_T: the elastic slip at which the regularized law reaches the \
     Coulomb stress mu P";

/// What the regime pane's K_T in MPa/um means.
pub const KT_UM_MEANING: &str = "K_T in the unit some FE codes use: 1 MPa/um = 1000 MPa/mm";

/// The width of the K_T table's K_T column.
pub const KT_WIDTH: usize = 7;

/// The tolerance the K_T table answers for: 1 % of Coulomb (`microslip kt --tolerance` takes any).
pub const TABLE_TOLERANCE: f64 = 0.01;

/// How a problem shows on the terminal screen beside its charts (see the module docs).
pub trait PaneFace: LoadedVariant {
    /// What x = 0 of the zone strip is (`clamp`, `centre`, `inner end`).
    const STRIP_ORIGIN: &'static str;
    /// What the zone strip's sparkline rows show: the interface shear over the problem's
    /// [`crate::problems::inputs::InterfaceData`]'s `friction * pressure` (`tau(x) / mu P` where
    /// that pressure is the interface's uniform P; a problem whose pressure varies names its
    /// own shear and the pressure it is divided by).
    const STRIP_SHEAR: &'static str = "tau(x) / mu P";
    /// The regime pane's own continuum solve, where the pane shows one (the plate's: a tenth of
    /// a second, on a worker); None for a problem whose continuum is drawn by `n` only.
    const PANE_CONTINUUM: Option<PaneContinuum<Self::Model>> = None;
    /// The K_T table's columns after `source` and `K_T`: each head and width (with them, 44
    /// characters at most).
    const KT_COLUMNS: &'static [(&'static str, usize)];
    /// The parameter pane's title (`Twin beams, Euler-Bernoulli`).
    fn parameters_title(params: &Self::Params) -> String;

    /// The regime pane's title after "Regime (i), " (an envelope: "FE within 3.02 %") and what it
    /// means; None where the pane states it as one of its lines.
    fn title_line(model: &Self::Model) -> Option<SummaryLine> {
        let _ = model;
        None
    }

    /// The regime pane's lines; `continuum`: where its own continuum solve stands.
    fn summary_lines(model: &Self::Model, continuum: &ContinuumState) -> Vec<SummaryLine>;

    /// The K_T table's values for `model` at K_T = `kt` (MPa/mm), one per
    /// [`PaneFace::KT_COLUMNS`]; None where `kt` is not accepted.
    fn kt_values(model: &Self::Model, kt: f64) -> Option<Vec<f64>>;

    /// The K_T table's answer to "how stiff for Coulomb within 1 %" ([`TABLE_TOLERANCE`]), for
    /// contact elements of `element` mm; `within`: `within 1 % of Coulomb: K_T`.
    fn kt_tolerance_lines(model: &Self::Model, within: &str, element: f64) -> Vec<String>;

    /// Toggles the problem's setting that is no number (the beams' theory) and says what it is
    /// now; None where the problem has none.
    fn toggle_setting(params: &mut Self::Params) -> Option<&'static str> {
        let _ = params;
        None
    }

    /// An FE point on the axes of the problem's first chart, as read: (load or K_T, response).
    fn fe_xy(point: &Self::FePoint) -> (f64, f64);

    /// One line for the status after `d` loads FE results: `loaded` against the closed forms of
    /// `model`, the verdict first (the line is cut at the screen's width); `code`: the FE code's
    /// name (`CalculiX`).
    ///
    /// # Errors
    /// Why the points cannot be compared with `model`, as the status line says it.
    fn fe_brief(
        model: &Self::Model,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String>;

    /// True where the FE runs of decks at `a` and at `b` are points of one curve, which add up
    /// as they are loaded (the plate's runs of one deck at several K_T); false by default: a new
    /// run replaces the previous points.
    fn same_curve(a: &Self::Params, b: &Self::Params) -> bool {
        let _ = (a, b);
        false
    }
}

/// A [`PaneFace`] with its types erased, for the TUI, which holds models as [`Model`] and
/// [`Inputs`]: each method answers for a model of its own problem and gives nothing (an empty
/// text or list, None) for another's, which the TUI never asks (it asks the face of the
/// model's own kind, `report::face::faces(kind).pane`).
pub trait AnyPaneFace: Send + Sync {
    /// See [`PaneFace::STRIP_ORIGIN`].
    fn strip_origin(&self) -> &'static str;
    /// See [`PaneFace::STRIP_SHEAR`].
    fn strip_shear(&self) -> &'static str;
    /// True where the regime pane solves a continuum of its own ([`PaneFace::PANE_CONTINUUM`]).
    fn has_pane_continuum(&self) -> bool;
    /// The regime pane's continuum at `model`, where it has one.
    fn pane_continuum(&self, model: &Model) -> Option<Result<ContinuumSummary, String>>;
    /// See [`PaneFace::parameters_title`].
    fn parameters_title(&self, inputs: &Inputs) -> String;
    /// See [`PaneFace::title_line`].
    fn title_line(&self, model: &Model) -> Option<SummaryLine>;
    /// See [`PaneFace::summary_lines`].
    fn summary_lines(&self, model: &Model, continuum: &ContinuumState) -> Vec<SummaryLine>;
    /// The K_T table's column heads after `source`: `K_T`, then [`PaneFace::KT_COLUMNS`].
    fn kt_header(&self) -> String;
    /// The K_T table's cells for `model` at K_T = `kt`, aligned under [`AnyPaneFace::kt_header`]
    /// ([`PaneFace::kt_values`]); None where `kt` is not accepted.
    fn kt_cells(&self, model: &Model, kt: f64) -> Option<String>;
    /// See [`PaneFace::kt_tolerance_lines`].
    fn kt_tolerance_lines(&self, model: &Model, within: &str, element: f64) -> Vec<String>;
    /// See [`PaneFace::toggle_setting`].
    fn toggle_setting(&self, inputs: &mut Inputs) -> Option<&'static str>;
    /// See [`PaneFace::same_curve`]; false where either is of another problem.
    fn same_curve(&self, a: &Inputs, b: &Inputs) -> bool;
    /// The points of `loaded` on the axes of the problem's first chart ([`PaneFace::fe_xy`]);
    /// none for another problem's.
    fn fe_points(&self, loaded: &AnyLoaded) -> Vec<(f64, f64)>;
    /// The status line's brief of `loaded` against `model` ([`PaneFace::fe_brief`]); None
    /// where either is of another problem.
    fn fe_brief(
        &self,
        loaded: &AnyLoaded,
        model: &Model,
        code: &str,
    ) -> Option<Result<String, String>>;

    /// `loaded` as the TUI shows it ([`FeRead`]), read by the face of its own problem.
    fn fe_read(&self, loaded: &AnyLoaded) -> FeRead {
        FeRead {
            kind: loaded.kind(),
            origin: loaded.header().map(|h| h.inputs),
            points: self.fe_points(loaded),
            code: loaded.header().map_or("FE (CSV)", |_| "CalculiX"),
        }
    }
}

/// The [`AnyPaneFace`] of a [`PaneFace`] problem `P`.
struct PaneOf<P>(std::marker::PhantomData<P>);

/// The erased [`PaneFace`] of `P`: its slot in the application's table of erased faces
/// (`report::face::faces`).
pub fn erased<P: PaneFace>() -> &'static dyn AnyPaneFace {
    &PaneOf::<P>(std::marker::PhantomData)
}

impl<P: PaneFace> AnyPaneFace for PaneOf<P> {
    fn strip_origin(&self) -> &'static str {
        P::STRIP_ORIGIN
    }

    fn strip_shear(&self) -> &'static str {
        P::STRIP_SHEAR
    }

    fn has_pane_continuum(&self) -> bool {
        P::PANE_CONTINUUM.is_some()
    }

    fn pane_continuum(&self, model: &Model) -> Option<Result<ContinuumSummary, String>> {
        Some(P::PANE_CONTINUUM?(&P::from_model(model)?))
    }

    fn parameters_title(&self, inputs: &Inputs) -> String {
        P::from_inputs(inputs).map_or_else(String::new, |p| P::parameters_title(&p))
    }

    fn title_line(&self, model: &Model) -> Option<SummaryLine> {
        P::title_line(&P::from_model(model)?)
    }

    fn summary_lines(&self, model: &Model, continuum: &ContinuumState) -> Vec<SummaryLine> {
        P::from_model(model).map_or_else(Vec::new, |m| P::summary_lines(&m, continuum))
    }

    fn kt_header(&self) -> String {
        let heads = P::KT_COLUMNS
            .iter()
            .map(|&(head, width)| format!("{head:>width$}"));
        std::iter::once(format!("{:>KT_WIDTH$}", "K_T"))
            .chain(heads)
            .collect::<Vec<_>>()
            .join(" ")
    }

    fn kt_cells(&self, model: &Model, kt: f64) -> Option<String> {
        let values = P::kt_values(&P::from_model(model)?, kt)?;
        let cells = P::KT_COLUMNS
            .iter()
            .zip(values)
            .map(|(&(_, width), value)| format!("{:>width$}", cell(value, width)));
        Some(
            std::iter::once(format!("{:>KT_WIDTH$}", cell(kt, KT_WIDTH)))
                .chain(cells)
                .collect::<Vec<_>>()
                .join(" "),
        )
    }

    fn kt_tolerance_lines(&self, model: &Model, within: &str, element: f64) -> Vec<String> {
        P::from_model(model).map_or_else(Vec::new, |m| P::kt_tolerance_lines(&m, within, element))
    }

    fn toggle_setting(&self, inputs: &mut Inputs) -> Option<&'static str> {
        let mut params = P::from_inputs(inputs)?;
        let said = P::toggle_setting(&mut params)?;
        *inputs = P::to_inputs(params);
        Some(said)
    }

    fn same_curve(&self, a: &Inputs, b: &Inputs) -> bool {
        match (P::from_inputs(a), P::from_inputs(b)) {
            (Some(a), Some(b)) => P::same_curve(&a, &b),
            _ => false,
        }
    }

    fn fe_points(&self, loaded: &AnyLoaded) -> Vec<(f64, f64)> {
        P::loaded(loaded).map_or_else(Vec::new, |l| l.points.iter().map(P::fe_xy).collect())
    }

    fn fe_brief(
        &self,
        loaded: &AnyLoaded,
        model: &Model,
        code: &str,
    ) -> Option<Result<String, String>> {
        Some(P::fe_brief(
            &P::from_model(model)?,
            P::loaded(loaded)?,
            code,
        ))
    }
}

/// FE results as the TUI shows them: of which problem, from which deck's values, the points on
/// the problem's first chart, and the code's name.
#[derive(Debug, Clone, PartialEq)]
pub struct FeRead {
    /// The problem the results are of.
    pub kind: ModelKind,
    /// The values of the deck that produced them (CalculiX results); None for a CSV curve.
    pub origin: Option<Inputs>,
    /// The points, as read: (load or K_T, response) ([`PaneFace::fe_xy`]).
    pub points: Vec<(f64, f64)>,
    /// `CalculiX` for a run with its deck, `FE (CSV)` for a CSV curve.
    pub code: &'static str,
}

/// A table cell of at most `width` characters: 3 significant digits, fewer for the long exponent
/// forms of extreme values (`6.67e-17` becomes `6.7e-17`).
pub fn cell(value: f64, width: usize) -> String {
    (1..=3)
        .rev()
        .map(|digits| number_with(value, digits))
        .find(|text| text.len() <= width)
        .unwrap_or_else(|| number_with(value, 1))
}

/// A tolerance answer in a cell: `>= K_T`, `> K_T` where even the stiffest is not within, `-`
/// where there is no answer.
pub fn shown(answer: Result<ToleranceAnswer, ToleranceError>) -> String {
    match answer.map(|a| a.threshold) {
        Ok(Threshold::Stiffness(k) | Threshold::Everywhere(k)) => format!(">= {}", cell(k, 7)),
        Ok(Threshold::Nowhere { stiffness, .. }) => format!("> {}", cell(stiffness, 7)),
        Err(_) => "-".to_string(),
    }
}

/// [`PaneFace::kt_tolerance_lines`] of any load-driven problem at the force `f` (N): the
/// smallest K_T within the table's tolerance at F and at every F up to F; any K_T at F = 0,
/// where nothing slides.
pub fn load_tolerance_lines<P: LoadDriven>(
    structure: &P::Structure,
    f: f64,
    within: &str,
    element: f64,
) -> Vec<String> {
    let heading = format!("W{}", &within[1..]);
    let (load, _) = crate::chart::load::load_words::<P>();
    if f <= 0.0 {
        return vec![format!("{heading}: any, at {load} = 0")];
    }
    let within = |range| stiffness_for_tolerance::<P>(structure, range, TABLE_TOLERANCE, element);
    vec![
        format!("{heading} {} at {load},", shown(within([f, f]))),
        format!("  {} at all {load} up to {load}", shown(within([0.0, f]))),
    ]
}

/// A theory's envelope in a regime pane's title (about 20 characters), for the problems whose
/// pane is full at 80x24 (the lap joint, the press fit): "FE within 3.4 %" (the expected
/// difference of the response from the problem's continuum), "FE: >10 %, n solves" where the
/// theory is outside it, "FE: not calibrated" where no calibration reaches (`n` draws the
/// continuum in both cases).
pub fn envelope_title(validity: Validity, expected_error: Option<f64>) -> String {
    match (validity, expected_error) {
        (Validity::Holds | Validity::Approximate, Some(e)) => {
            format!("FE within {} %", number_with(100.0 * e, 2))
        }
        (Validity::Outside | Validity::MeasuredWrong, _) => {
            format!("FE: >{} %, n solves", 100.0 * Validity::APPROXIMATE)
        }
        (Validity::Holds | Validity::Approximate | Validity::NotCalibrated, _) => {
            "FE: not calibrated".to_string()
        }
    }
}

/// The ratio line's value: the regularized response over Coulomb's, or `none` where Coulomb's
/// is not positive (nothing loaded), where a ratio means nothing.
pub fn ratio_text(regularized: f64, coulomb: f64, none: &str) -> String {
    if coulomb > 0.0 {
        number(regularized / coulomb)
    } else {
        none.into()
    }
}

/// The regime pane's heading and both laws' regime words for a load-driven problem at `force`
/// (its symbol and unit `load`, as the problem's descriptor names them: `("F", "N")`), `what`
/// naming the force (`tip force`): at zero load nothing is loaded, whatever the law, so the pane
/// says so rather than "microslip".
pub fn load_regimes(
    force: f64,
    (load, unit): (&str, &str),
    what: &str,
    coulomb: impl FnOnce() -> String,
    regularized: impl FnOnce() -> String,
) -> (String, String, String) {
    if force == 0.0 {
        (
            "unloaded".to_string(),
            "unloaded".to_string(),
            format!("At {load} = 0 {unit}: no load, no slip"),
        )
    } else {
        (
            coulomb(),
            regularized(),
            format!("At {load} = {} {unit} ({what})", number(force)),
        )
    }
}
