//! [`ReportFace`]: what the generic reports need of a problem (the K_T table's columns, the
//! equation that shows its response never grows with K_T, its table in the paper report), as a
//! trait each problem's application folder implements (`src/problems/<name>/report.rs`), and its
//! erased side; [`for_problem`], the one typed dispatch from a kind to a problem's faces
//! ([`Faces`]) that the command line's handlers and the Python face's bodies run through
//! ([`ForProblem`]), generated from the registry; and [`faces`], the table of a problem's erased
//! faces ([`AppFaces`]: report, cycle, panes) built on it. Before them (issue 43, item 5) the
//! application and the Python face had 5 erased traits and 9 registry expansions; now 4 and 6:
//! the Python face's erased commands and the command line's dispatch are [`for_problem`], and
//! the panes' own expansion went into their erased face (`validation/dispatch_lines.py` counts
//! the whole).
//!
//! Why a trait: the K_T table, the tolerance answer and the paper report are written once for
//! every problem; a problem's columns and words are its own and live in its folder, so that a
//! new problem is its folder and its registry line, not an arm in each report.

use std::fmt::{Debug, Write as _};

use serde::Serialize;

#[cfg(feature = "app")]
use crate::chart::panes::{AnyPaneFace, PaneFace};
use crate::fe::face::Deck;
use crate::kernel::regime::Regime;
use crate::numeric::NumericError;
use crate::problems::ModelKind;
use crate::problems::pointwise::Pointwise;
use crate::problems::problem::Registered;
use crate::report::compare::CompareFace;
use crate::report::number;
use crate::report::point::cycle::AnyCycleFace;
use crate::study::curves::Answer;

/// The heading of a K_T table: what every problem's first line says.
#[derive(Debug, Clone, Copy)]
pub struct KtHeading<'a> {
    /// The preset's name, sanitized.
    pub preset: &'a str,
    /// The load case's force (N), `None` for a problem without a load.
    pub force: Option<f64>,
    /// mu P (MPa), formatted.
    pub friction_stress: &'a str,
    /// The contact elements' length (mm), formatted.
    pub element: &'a str,
}

/// One row of a K_T table, formatted, but the answer's own columns.
#[derive(Debug, Clone, Copy)]
pub struct KtRow<'a> {
    /// The candidate's source.
    pub source: &'a str,
    /// Its K_T, or `-`.
    pub kt: &'a str,
    /// Against the current K_T's answer, signed %.
    pub vs_current: &'a str,
    /// Against Coulomb's, signed %.
    pub vs_coulomb: &'a str,
    /// What the regime column says without an answer.
    pub unanswered: &'a str,
    /// How the candidate was obtained.
    pub basis: &'a str,
}

/// A column of a problem's K_T table between the candidate's K_T and the regime: one of the
/// answer's numbers, or a comparison every problem has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KtColumn {
    /// The answer's next number ([`ReportFace::kt_values`]), under `title`, right-aligned in
    /// `width` characters.
    Answer {
        /// The column's title, with its unit (`w(L) (mm)`).
        title: &'static str,
        /// Its width.
        width: usize,
    },
    /// Against the current K_T's response, signed %.
    VsCurrent,
    /// Against Coulomb's response, signed %.
    VsCoulomb,
}

/// A problem as the generic reports show it.
pub trait ReportFace: Pointwise + Registered {
    /// The equation of docs/theory.md that shows the problem's response never grows with K_T
    /// (`(T1)`), which the tolerance answer cites.
    const MONOTONE_IN_STIFFNESS: &'static str;

    /// What a K_T candidate does to the problem: the fields of the K_T table's JSON row beside
    /// the candidate's (flattened into it, so each problem names its own).
    type KtAnswer: Serialize + Debug + Clone;

    /// What the K_T table's heading calls the problem (`twin beams`); a problem with a load
    /// adds the force it is at.
    const KT_TITLE: &'static str;
    /// What the K_T table's heading calls the friction stress it gives in MPa: `mu P` where P is
    /// a pressure; the cylinder's P is a line load, so its stress is the peak `mu p0`.
    const FRICTION_STRESS: &'static str = "mu P";
    /// The K_T table's columns between K_T and the regime, in order.
    const KT_COLUMNS: &'static [KtColumn];
    /// The width of the regime column (its longest label).
    const KT_REGIME_WIDTH: usize;

    /// The problem's part of `answer`; `None` for an answer of another problem (while
    /// [`Answer`] is an enum of every problem's answers).
    fn kt_answer(answer: &Answer) -> Option<Self::KtAnswer>;

    /// The answer's numbers, one per [`KtColumn::Answer`] in order, and its regime.
    fn kt_values(answer: &Self::KtAnswer) -> (Vec<f64>, Regime);

    /// The problem's table in the paper report (`microslip` alone), where the paper has one.
    fn paper_table() -> Option<String> {
        None
    }

    /// The report of one state (`microslip beam|plate|lap`): its text is [`Self::point_text`],
    /// its JSON the struct serialized.
    type PointReport: Serialize;

    /// The report of `model`, from the preset `preset`. `continuum` is the command's
    /// `--continuum`: a problem with a continuum solves it when asked, or when its closed forms
    /// are not expected to hold (and reports a failed solve in its output then); a problem
    /// without one is never asked.
    ///
    /// # Errors
    /// The continuum asked for (`continuum`) and not solved.
    fn point_report(
        preset: &str,
        model: &Self::Model,
        continuum: bool,
    ) -> Result<Self::PointReport, NumericError>;

    /// [`Self::PointReport`] as text.
    fn point_text(report: &Self::PointReport) -> String;

    /// One row of a sweep's table at one state (`sweep --vary`, the plate's K_T sweep).
    type SweepRow: Serialize + Default + for<'a> From<&'a Self::Point>;

    /// The problem's cycle and load tables, when it is load-driven ([`AnyCycleFace`]); `None`
    /// for a problem without a load (the plate).
    fn cycle() -> Option<&'static dyn AnyCycleFace> {
        None
    }
}

/// A [`ReportFace`] with its types erased.
pub trait AnyReportFace: Send + Sync {
    /// [`ReportFace::MONOTONE_IN_STIFFNESS`].
    fn monotone_in_stiffness(&self) -> &'static str;
    /// The K_T table's heading and column titles, each line ended.
    fn kt_heading(&self, heading: &KtHeading) -> String;
    /// One K_T table row without an answer: dashes in the problem's columns.
    fn kt_row_unanswered(&self, row: &KtRow) -> String;
    /// [`ReportFace::paper_table`].
    fn paper_table(&self) -> Option<String>;
    /// [`ReportFace::FRICTION_STRESS`]: the friction stress's symbol (`mu P`, `mu p0`).
    fn friction_stress(&self) -> &'static str;
}

/// `F = 100 N`: a problem's load by its own key and unit (the cylinder's is a line load,
/// `Q = 300 N/mm`), with its value already written.
pub(crate) fn load_words(load: crate::problems::Param, value: String) -> String {
    let spec = load.spec();
    format!("{} = {value} {}", spec.name, spec.unit)
}

/// The [`AnyReportFace`] of a [`ReportFace`] problem `P`.
struct ReportOf<P>(std::marker::PhantomData<P>);

impl<P: ReportFace> AnyReportFace for ReportOf<P> {
    fn monotone_in_stiffness(&self) -> &'static str {
        P::MONOTONE_IN_STIFFNESS
    }

    fn kt_heading(&self, heading: &KtHeading) -> String {
        let KtHeading {
            preset,
            force,
            friction_stress: mu_p,
            element,
        } = *heading;
        let at = match P::INFO.load {
            Some(load) => format!(
                " at {}",
                load_words(load, force.map_or_else(|| "-".to_string(), number))
            ),
            None => String::new(),
        };
        let mut out = format!(
            "K_T candidates for preset {preset}: {}{at}, {} = {mu_p} MPa, contact elements \
             {element} mm\n",
            P::KT_TITLE,
            P::FRICTION_STRESS
        );
        let _ = write!(out, "{:<16} {:>12}", "source", "K_T (MPa/mm)");
        for column in P::KT_COLUMNS {
            let (title, width) = match *column {
                KtColumn::Answer { title, width } => (title, width),
                KtColumn::VsCurrent => ("vs current", 10),
                KtColumn::VsCoulomb => ("vs Coulomb", 10),
            };
            let _ = write!(out, " {title:>width$}");
        }
        let _ = writeln!(
            out,
            "  {:<width$} basis",
            "regime",
            width = P::KT_REGIME_WIDTH
        );
        out
    }

    fn kt_row_unanswered(&self, row: &KtRow) -> String {
        kt_row::<P>(row, None)
    }

    fn friction_stress(&self) -> &'static str {
        P::FRICTION_STRESS
    }

    fn paper_table(&self) -> Option<String> {
        P::paper_table()
    }
}

/// The continuum solution a point report shows: solved when `asked` (the command's
/// `--continuum`) or when the closed forms are not expected to hold (`holds` false), and none
/// otherwise. Only a solve that was asked for fails the report; an automatic one that fails is
/// reported as failed in the output.
///
/// # Errors
/// The solve's error, when it was asked for.
pub fn point_continuum<T>(
    asked: bool,
    holds: bool,
    solve: impl FnOnce() -> Result<T, NumericError>,
) -> Result<Option<Result<T, NumericError>>, NumericError> {
    let solved = (asked || !holds).then(solve);
    match solved {
        Some(Err(e)) if asked => Err(e),
        solved => Ok(solved),
    }
}

/// One row of `P`'s K_T table, ended: the answer's columns, or dashes without one.
pub(crate) fn kt_row<P: ReportFace>(row: &KtRow, answer: Option<&P::KtAnswer>) -> String {
    let values = answer.map(P::kt_values);
    let mut out = format!("{:<16} {:>12}", row.source, row.kt);
    let mut numbers = values
        .iter()
        .flat_map(|(numbers, _)| numbers.iter().copied());
    for column in P::KT_COLUMNS {
        let (text, width) = match (*column, &values) {
            (KtColumn::Answer { width, .. }, Some(_)) => (
                numbers.next().map_or_else(|| "-".to_string(), number),
                width,
            ),
            (KtColumn::VsCurrent, Some(_)) => (row.vs_current.to_string(), 10),
            (KtColumn::VsCoulomb, Some(_)) => (row.vs_coulomb.to_string(), 10),
            (KtColumn::Answer { width, .. }, None) => ("-".to_string(), width),
            (KtColumn::VsCurrent | KtColumn::VsCoulomb, None) => ("-".to_string(), 10),
        };
        let _ = write!(out, " {text:>width$}");
    }
    let regime = values
        .as_ref()
        .map_or(row.unanswered, |(_, regime)| regime.label());
    let _ = writeln!(
        out,
        "  {regime:<width$} {}",
        row.basis,
        width = P::KT_REGIME_WIDTH
    );
    out
}

/// Everything a command may ask of any problem, typed: its reports ([`ReportFace`]), its FE deck
/// ([`Deck`]), its comparison ([`CompareFace`]) and its screen panes ([`PaneFace`]). What only
/// some problems have is reached through an erased, optional capability of these
/// ([`ReportFace::cycle`]), never by naming the problems that have it. The panes exist with the
/// terminal only (the feature `app`; the Python face builds without it).
#[cfg(feature = "app")]
pub trait Faces: ReportFace + Deck + CompareFace + PaneFace {}

#[cfg(feature = "app")]
impl<P: ReportFace + Deck + CompareFace + PaneFace> Faces for P {}

/// As with the feature `app`, without the panes.
#[cfg(not(feature = "app"))]
pub trait Faces: ReportFace + Deck + CompareFace {}

#[cfg(not(feature = "app"))]
impl<P: ReportFace + Deck + CompareFace> Faces for P {}

/// A command's body for one problem `P`, given its arguments as `self`: written once, generic
/// over the problem's type, and run for the problem of a [`ModelKind`] by [`for_problem`] (the
/// command line's handlers and the Python face's bodies alike).
pub trait ForProblem {
    /// What the command gives back.
    type Output;

    /// Runs the command for the problem `P`.
    fn run<P: Faces>(self) -> Self::Output;
}

/// **The erased faces of one problem in the application**, in one table: what the reports, the
/// TUI and the command line ask of a problem they hold as a [`ModelKind`], instead of a function
/// per face. Built by [`faces`] from the problem's typed faces through [`for_problem`], so that
/// the registry's list is turned into the application's erased faces in one place.
///
/// Each face keeps an erased trait beside its typed one ([`AnyReportFace`], [`AnyCycleFace`],
/// `chart::panes::AnyPaneFace` with the `app` feature): its methods take the
/// [`Model`](crate::problems::inputs::Model) and [`Inputs`](crate::problems::inputs::Inputs) enums and plain numbers where the typed trait
/// takes the problem's own types, and each is implemented once, generically (`ReportOf<P>`),
/// never by a problem. The deck's erased face (`fe::face::deck_face`) is not in the table: the
/// `fe` layer, below this one, reads its headers and results with it (`tests/layering.rs`), and
/// nothing above asks for it.
#[derive(Clone, Copy)]
pub struct AppFaces {
    /// Its K_T table, tolerance words and paper table.
    pub report: &'static dyn AnyReportFace,
    /// Its cycle and load tables, where it is load-driven ([`ReportFace::cycle`]): `None`
    /// answers "does this command apply to it?" without a `match` on its kind.
    pub cycle: Option<&'static dyn AnyCycleFace>,
    /// Its panes on the terminal screen.
    #[cfg(feature = "app")]
    pub pane: &'static dyn AnyPaneFace,
}

/// The erased faces of the problem `kind`.
pub fn faces(kind: ModelKind) -> AppFaces {
    for_problem(kind, Erase)
}

/// [`faces`]'s body: the erased faces of `P`.
struct Erase;

impl ForProblem for Erase {
    type Output = AppFaces;

    fn run<P: Faces>(self) -> AppFaces {
        AppFaces {
            report: &ReportOf::<P>(std::marker::PhantomData),
            cycle: P::cycle(),
            #[cfg(feature = "app")]
            pane: crate::chart::panes::erased::<P>(),
        }
    }
}

/// Writes [`for_problem`] from the registry: the application's one `match` from a kind to a
/// problem's type above the chart layer, one arm per problem, none by hand. The layers below
/// keep their own (`fe::face::deck_face` and `AnyLoaded`, `chart::view::AnyChart`): a layer
/// cannot reach this one (`tests/layering.rs`), and each generates the enum of its layer's
/// per-problem values from the same list.
macro_rules! typed_dispatch {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// Runs `command` for the problem `kind`, typed.
        pub fn for_problem<C: ForProblem>(kind: ModelKind, command: C) -> C::Output {
            match kind {
                $(ModelKind::$variant => command.run::<crate::problems::$folder::$problem>()),+
            }
        }
    };
}

microslip_core::with_problems!(typed_dispatch);

#[cfg(test)]
mod tests {
    use super::*;

    /// Each problem's K_T table lines up: a row without an answer, given the titles' words, is
    /// the title line itself; and every problem cites an equation.
    #[test]
    fn every_problem_s_kt_table_lines_up() {
        for kind in ModelKind::ALL {
            let face = faces(kind).report;
            assert!(face.monotone_in_stiffness().starts_with('('), "{kind}");
            let heading = face.kt_heading(&KtHeading {
                preset: "p",
                force: Some(1.0),
                friction_stress: "1",
                element: "1",
            });
            let titles = heading.lines().nth(1).unwrap_or_default();
            let row = face.kt_row_unanswered(&KtRow {
                source: "source",
                kt: "K_T (MPa/mm)",
                vs_current: "-",
                vs_coulomb: "-",
                unanswered: "regime",
                basis: "basis",
            });
            let words = titles.split_whitespace().count();
            assert!(words > 4, "{kind}: {titles}");
            assert_eq!(
                titles.len(),
                row.trim_end().len(),
                "{kind}:\n{titles}\n{row}"
            );
        }
    }
}
