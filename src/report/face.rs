//! [`ReportFace`]: what the generic reports need of a problem (the K_T table's columns, the
//! equation that shows its response never grows with K_T, its table in the paper report), as a
//! trait each problem's application folder implements (`src/problems/<name>/report.rs`), and its
//! erased side ([`report_face`]) generated from the registry.
//!
//! Why a trait: the K_T table, the tolerance answer and the paper report are written once for
//! every problem; a problem's columns and words are its own and live in its folder, so that a
//! new problem is its folder and its registry line, not an arm in each report.

use std::fmt::Debug;

use serde::Serialize;

use crate::problems::problem::Registered;
use crate::problems::{ModelKind, Problem};
use crate::study::curves::Answer;

/// The heading of a K_T table: what every problem's first lines say.
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

/// A problem as the generic reports show it.
pub trait ReportFace: Problem + Registered {
    /// The equation of docs/theory.md that shows the problem's response never grows with K_T
    /// (`(T1)`), which the tolerance answer cites.
    const MONOTONE_IN_STIFFNESS: &'static str;

    /// What a K_T candidate does to the problem: the fields of the K_T table's JSON row beside
    /// the candidate's (flattened into it, so each problem names its own).
    type KtAnswer: Serialize + Debug + Clone;

    /// The problem's part of `answer`; `None` for an answer of another problem.
    fn kt_answer(answer: &Answer) -> Option<Self::KtAnswer>;

    /// The K_T table's heading and column titles, each line ended.
    fn kt_heading(heading: &KtHeading) -> String;

    /// One K_T table row, ended: the answer's columns, or dashes where there is none.
    fn kt_row(row: &KtRow, answer: Option<&Self::KtAnswer>) -> String;

    /// The problem's table in the paper report (`microslip` alone), where the paper has one.
    fn paper_table() -> Option<String> {
        None
    }
}

/// A [`ReportFace`] with its types erased.
pub trait AnyReportFace: Send + Sync {
    /// [`ReportFace::MONOTONE_IN_STIFFNESS`].
    fn monotone_in_stiffness(&self) -> &'static str;
    /// [`ReportFace::kt_heading`].
    fn kt_heading(&self, heading: &KtHeading) -> String;
    /// [`ReportFace::kt_row`] without an answer.
    fn kt_row_unanswered(&self, row: &KtRow) -> String;
    /// [`ReportFace::paper_table`].
    fn paper_table(&self) -> Option<String>;
}

/// The [`AnyReportFace`] of a [`ReportFace`] problem `P`.
struct ReportOf<P>(std::marker::PhantomData<P>);

impl<P: ReportFace> AnyReportFace for ReportOf<P> {
    fn monotone_in_stiffness(&self) -> &'static str {
        P::MONOTONE_IN_STIFFNESS
    }

    fn kt_heading(&self, heading: &KtHeading) -> String {
        P::kt_heading(heading)
    }

    fn kt_row_unanswered(&self, row: &KtRow) -> String {
        P::kt_row(row, None)
    }

    fn paper_table(&self) -> Option<String> {
        P::paper_table()
    }
}

/// Writes [`report_face`] from the registry.
macro_rules! report_faces {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// The [`ReportFace`] of the problem `kind`, erased.
        pub fn report_face(kind: ModelKind) -> &'static dyn AnyReportFace {
            match kind {
                $(ModelKind::$variant => &ReportOf::<crate::problems::$folder::$problem>(
                    std::marker::PhantomData,
                )),+
            }
        }
    };
}

microslip_core::with_problems!(report_faces);
