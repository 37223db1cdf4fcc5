//! One comparison report for every problem whose comparison is a table of FE points, each judged
//! against the closed form's envelope and the continuum: [`TableReport`]. Its JSON is serde of
//! it, its CSV the rows' [`CompareTable::CsvRow`] columns without the verdict, its text
//! [`TableReport::text`]: the problem's title and table ([`CompareTable::table_text`]), one
//! verdict line per row, the problem's own closing section if it has one, the continuum's
//! section and the closing verdict.
//!
//! Why a trait: the twin beams', the plate's and the lap joint's reports were three copies of
//! this frame around their own columns and words; what differs is the problem's (its columns,
//! its row verdict's keys, the keys it adds around the rows) and lives in its folder
//! (`src/problems/<name>/compare.rs`). The cylinder's report has another shape (no row verdicts,
//! no continuum, `source` for `results`): it keeps its own, which JSON users already read.

use std::fmt::Debug;
use std::fmt::Write as _;

use serde::Serialize;

use super::continuum::{self, Check, ContinuumRow, ContinuumSummary};
use super::verdict::{RowVerdict, Summary};
use crate::fe::continuum_verdict::ContinuumJudged;

/// A problem's comparison as a table of FE points, each against the closed forms.
pub trait CompareTable: ContinuumJudged + Sized {
    /// One FE point beside the closed forms.
    type Compared;
    /// Its CSV row (the table's columns, without the verdict).
    type CsvRow: Serialize + Clone + Debug + for<'a> From<&'a Self::Compared>;
    /// The zone ends of its row verdict, under the problem's keys.
    type Zones: Serialize + Clone + Debug;
    /// What the text needs of a row beside its columns (not in the JSON): `()` for most.
    type Note: Clone + Copy + Debug;
    /// The keys the report holds between `results` and `rows`: `()` for most.
    type Head: Serialize + Clone + Debug;
    /// The keys the report holds between `rows` and `verdict`: `()` for most.
    type Tail: Serialize + Clone + Debug;
    /// The continuum the text's section names ("plane-stress continuum (BC1)").
    const CONTINUUM: &'static str;

    /// How the row is named where the continuum judges it ("F = 40 N").
    fn label(row: &Self::Compared) -> String;
    /// The row against the continuum (`None`: not checked).
    fn check(row: &Self::Compared) -> Check;
    /// The row's [`Self::Note`].
    fn note(row: &Self::Compared) -> Self::Note;
    /// The row's verdict.
    fn verdict(row: &Self::Compared) -> RowVerdict<Self::Zones>;
    /// The text before the rows' verdict lines: the title, the table and what the verdicts
    /// judge.
    fn table_text(report: &TableReport<Self>) -> String;
    /// The text after the rows' verdict lines (the beams': what the FE points imply); empty for
    /// most.
    fn tail_text(_report: &TableReport<Self>) -> String {
        String::new()
    }
}

/// One problem's comparison report.
#[derive(Debug, Clone, Serialize)]
#[serde(bound = "")]
pub struct TableReport<P: CompareTable> {
    /// The problem's key (`beam`).
    pub model: &'static str,
    /// The FE results compared.
    pub results: String,
    /// The problem's keys before the rows.
    #[serde(flatten)]
    pub head: P::Head,
    pub rows: Vec<TableRow<P>>,
    /// The problem's keys after the rows.
    #[serde(flatten)]
    pub tail: P::Tail,
    /// The closing verdict.
    pub verdict: Summary,
    /// The FE response against the continuum at the deck's parameters, all rows together
    /// (`compare`, `bench`; absent where no row was checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumSummary>,
}

/// One row: the CSV row's columns and its verdict.
#[derive(Debug, Clone, Serialize)]
#[serde(bound = "")]
pub struct TableRow<P: CompareTable> {
    #[serde(flatten)]
    pub row: P::CsvRow,
    /// What the text needs beside the columns.
    #[serde(skip)]
    pub note: P::Note,
    pub verdict: RowVerdict<P::Zones>,
    /// This row against the continuum (absent where it was not checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumRow>,
}

impl<P: CompareTable> TableReport<P> {
    /// The report of `rows` of the results named `source`, with the problem's `head` and `tail`
    /// keys and its closing `verdict` (which the continuum's verdict joins).
    pub fn new(
        source: &str,
        rows: &[P::Compared],
        (head, tail): (P::Head, P::Tail),
        mut verdict: Summary,
    ) -> TableReport<P> {
        let checks: Vec<(String, Check)> =
            rows.iter().map(|r| (P::label(r), P::check(r))).collect();
        let (checked, continuum) = continuum::judged_rows(P::RESPONSE, &checks, &mut verdict);
        TableReport {
            model: P::INFO.key,
            results: source.to_string(),
            head,
            rows: rows
                .iter()
                .zip(checked)
                .map(|(r, continuum)| TableRow {
                    row: P::CsvRow::from(r),
                    note: P::note(r),
                    verdict: P::verdict(r),
                    continuum,
                })
                .collect(),
            tail,
            verdict,
            continuum,
        }
    }

    /// Each row's judged difference, as a ladder of runs extrapolates it
    /// ([`CompareFace::ladder_quantities`](super::CompareFace::ladder_quantities)).
    pub fn ladder_quantities(&self) -> Vec<crate::fe::ladder::LadderQuantity> {
        self.rows
            .iter()
            .filter_map(|r| r.verdict.quantity.clone())
            .collect()
    }

    /// The CSV rows.
    pub fn csv_rows(&self) -> Vec<P::CsvRow> {
        self.rows.iter().map(|r| r.row.clone()).collect()
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = P::table_text(self);
        for r in &self.rows {
            let _ = writeln!(out, "  {}", r.verdict.text);
        }
        out.push_str(&P::tail_text(self));
        if let Some(c) = &self.continuum {
            out.push_str(&continuum::section(c, P::CONTINUUM));
        }
        let _ = writeln!(out, "\n{}", self.verdict.summary);
        out
    }
}
