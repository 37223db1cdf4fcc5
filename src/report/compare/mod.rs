//! `microslip compare`: FE results beside the closed forms, as text, CSV or JSON. The numbers come
//! from each problem's comparison and the verdicts from [`crate::fe::verdict`]; this folder only
//! words and lays them out, for every problem alike: [`CompareFace`] (what `compare` and `bench`
//! need of a problem), [`table::TableReport`] (the one report of a comparison that is a table of
//! FE points: JSON is serde of it, text a renderer of it, and the CSV is its rows' columns
//! without the verdict), the verdicts in words ([`verdict`]), the continuum's section
//! ([`continuum`]) and the stick slope the FE code used ([`stick_slope`]).
//!
//! Each problem's rows, row verdicts and closing verdict are its own, in its folder
//! (`src/problems/<name>/compare.rs`; the cylinder's `deck.rs`): this folder names no problem.

pub mod continuum;
pub mod run;
pub mod stick_slope;
pub mod table;
pub mod verdict;

use serde::Serialize;

use super::number;
use crate::fe::face::Deck;
use crate::kernel::params::ParamError;

/// A problem's comparison as `compare` and `bench` report it: how many result files one report
/// takes, how one file's comparison is checked, and the report and CSV rows of them all. Each
/// problem's application folder implements it (`src/problems/<name>/compare.rs`; the
/// cylinder's `deck.rs`), so that the command is written once for every problem with a deck.
pub trait CompareFace: Deck {
    /// Why a comparison takes one result file, when it does (the beams': all the load steps of
    /// one run, fitted together); `None` when the rows of several files are put together.
    const ONE_RUN: Option<&'static str>;
    /// One file's comparison, checked.
    type Checked;
    /// The CSV row of a comparison.
    type CompareRow: Serialize + Default;
    /// The report of a comparison: its JSON is serde of it, its text [`Self::compare_text`].
    type CompareReport: Serialize;

    /// `compared`, checked.
    ///
    /// # Errors
    /// A point the closed forms cannot be evaluated at (a force the structure does not carry).
    fn checked(compared: Self::Compared) -> Result<Self::Checked, ParamError>;

    /// The report of the comparisons of the files `source` names, `first` and then `more` (empty
    /// when [`Self::ONE_RUN`]), and its CSV rows.
    fn compare_report(
        source: &str,
        first: Self::Checked,
        more: Vec<Self::Checked>,
    ) -> (Self::CompareReport, Vec<Self::CompareRow>);

    /// The report as text.
    fn compare_text(report: &Self::CompareReport) -> String;

    /// The report's closing verdict, which the stick slope the FE code used may turn
    /// ([`stick_slope::add_to_summary`]).
    fn summary_mut(report: &mut Self::CompareReport) -> &mut verdict::Summary;

    /// The differences from the closed form that the report judges, each with its bound, as a
    /// ladder of runs extrapolates them (`microslip suite`, [`crate::fe::ladder`]): one per
    /// judged quantity and load step, named so that the same quantity of another run of the
    /// ladder has the same name. A [`table::TableReport`] gives its rows'
    /// ([`table::TableReport::ladder_quantities`]).
    fn ladder_quantities(report: &Self::CompareReport) -> Vec<crate::fe::ladder::LadderQuantity>;
}

/// A relative difference in percent: two decimals, or the exponent form beyond 1e5 % (a number of
/// 200 digits helps nobody), "n/a" where it is undefined (a closed form of 0).
pub(crate) fn percent(x: f64) -> String {
    let p = 100.0 * x;
    if p.abs() < 1e5 {
        format!("{p:+.2} %")
    } else {
        format!("{p:+.2e} %")
    }
}

pub(crate) fn percent_or_na(x: Option<f64>) -> String {
    x.map_or_else(|| "n/a".to_string(), percent)
}

/// The range of the defined `values` as "a to b %", or the one value; "n/a" when none is.
/// Compact: it goes on the status line.
#[cfg(feature = "app")]
pub(crate) fn percent_range(values: impl Iterator<Item = Option<f64>>) -> String {
    let (lo, hi) = values
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        "n/a".to_string()
    } else if lo == hi {
        percent(lo)
    } else {
        format!("{:+.2} to {}", 100.0 * lo, percent(hi))
    }
}

/// The note under a table with an undefined relative difference.
pub(crate) const UNDEFINED_NOTE: &str = "n/a: the closed form is 0 there, so a relative difference is \
undefined; compare the values themselves.";

/// An optional value, or "-" where there is none.
pub(crate) fn optional(x: Option<f64>) -> String {
    x.map_or_else(|| "-".to_string(), number)
}
