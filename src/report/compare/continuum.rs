//! The verdict against the continuum ([`crate::fe::continuum_verdict`]) in words and JSON: one
//! line per row, one closing clause with the implied K_T and the case's resolution. Written once
//! for every problem: a report passes its rows' labels and verdicts, and its response's name.

use serde::Serialize;

use super::percent;
use crate::fe::continuum_verdict::{ContinuumVerdict, NotSolved};
use crate::report::number_with;

/// A row's continuum check as the compare faces hold it.
pub type Check = Option<Result<ContinuumVerdict, NotSolved>>;

/// The continuum part of a comparison report, the same for every problem: each row's
/// [`ContinuumRow`] in order (labelled as the report labels its rows) and their [`summary`],
/// whose clause joins the report's closing `verdict`.
pub fn judged_rows(
    response: &str,
    checks: &[(String, Check)],
    verdict: &mut super::verdict::Summary,
) -> (Vec<Option<ContinuumRow>>, Option<ContinuumSummary>) {
    let continuum = summary(response, checks);
    if let Some(c) = &continuum {
        super::verdict::with_continuum(verdict, c);
    }
    let rows = checks
        .iter()
        .map(|(label, check)| ContinuumRow::of(label, response, *check))
        .collect();
    (rows, continuum)
}

/// The resolution beyond which a report says in words that the response cannot tell the deck's
/// K_T from one that far off (a quarter: "could not tell 600 from 750").
const BLUNT_RESOLUTION: f64 = 0.25;

/// One row against the continuum, in JSON under the row's `continuum`.
#[derive(Debug, Clone, Serialize)]
pub struct ContinuumRow {
    /// Whether the continuum was solved at this row's parameters.
    pub solved: bool,
    /// The continuum's response at the deck's K_T (mm).
    pub response_mm: Option<f64>,
    /// (FE - continuum) / continuum, a fraction.
    pub diff_fraction: Option<f64>,
    /// The tolerance, a fraction (the allowance included).
    pub tolerance_fraction: Option<f64>,
    /// The part of the tolerance the run's kinematics adds (the beams' `NLGEOM`), a fraction.
    pub allowance_fraction: Option<f64>,
    /// Whether |diff| is within the tolerance.
    pub agrees: Option<bool>,
    /// d ln(response) / d ln K_T of the continuum at the deck's K_T.
    pub sensitivity: Option<f64>,
    /// The smallest relative K_T error this row can detect, tolerance / |sensitivity|.
    pub resolution_fraction: Option<f64>,
    /// The K_T whose continuum response equals the FE value (MPa/mm).
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied: Option<f64>,
    /// Its interval from the tolerance (MPa/mm).
    #[serde(rename = "KT_implied_low_MPa_per_mm")]
    pub implied_low: Option<f64>,
    #[serde(rename = "KT_implied_high_MPa_per_mm")]
    pub implied_high: Option<f64>,
    /// (implied - deck) / deck, a fraction.
    #[serde(rename = "KT_implied_diff_fraction")]
    pub implied_diff_fraction: Option<f64>,
    /// The row in words.
    pub text: String,
}

/// "1.23 %" (three significant figures).
fn bare(x: f64) -> String {
    format!("{} %", number_with(100.0 * x, 3))
}

fn stiffness(x: f64) -> String {
    number_with(x, 4)
}

impl ContinuumRow {
    /// The row labelled `label` ("F = 1008 N") of a report whose response is `response`;
    /// `None` where the row was not checked.
    pub fn of(label: &str, response: &str, check: Check) -> Option<ContinuumRow> {
        let row = match check? {
            Err(NotSolved) => ContinuumRow {
                solved: false,
                response_mm: None,
                diff_fraction: None,
                tolerance_fraction: None,
                allowance_fraction: None,
                agrees: None,
                sensitivity: None,
                resolution_fraction: None,
                implied: None,
                implied_low: None,
                implied_high: None,
                implied_diff_fraction: None,
                text: format!("{label}: the continuum was not solved here: not judged"),
            },
            Ok(v) => {
                let verdict = if v.agrees() {
                    "agrees"
                } else {
                    "does not agree"
                };
                let tolerance = if v.allowance > 0.0 {
                    format!(
                        "{}: {} + {} for the run's kinematics",
                        bare(v.tolerance),
                        bare(v.tolerance - v.allowance),
                        bare(v.allowance)
                    )
                } else {
                    bare(v.tolerance)
                };
                let mut text = format!(
                    "{label}: {response} {} from the continuum's {} mm (tolerance {tolerance}): \
                     {verdict}",
                    percent(v.difference()),
                    number_with(v.continuum, 6),
                );
                match v.implied {
                    Some(k) => text.push_str(&format!(
                        "; implied K_T {} MPa/mm ({} to {}), {} from the deck's {}",
                        stiffness(k.value),
                        stiffness(k.low),
                        stiffness(k.high),
                        percent(k.value / v.deck_stiffness - 1.0),
                        stiffness(v.deck_stiffness)
                    )),
                    None => text.push_str("; no K_T gives this value"),
                }
                if let Some(r) = v.resolution() {
                    text.push_str(&format!("; resolution +-{}", bare(r)));
                }
                ContinuumRow {
                    solved: true,
                    response_mm: Some(v.continuum),
                    diff_fraction: Some(v.difference()),
                    tolerance_fraction: Some(v.tolerance),
                    allowance_fraction: Some(v.allowance),
                    agrees: Some(v.agrees()),
                    sensitivity: Some(v.sensitivity),
                    resolution_fraction: v.resolution(),
                    implied: v.implied.map(|k| k.value),
                    implied_low: v.implied.map(|k| k.low),
                    implied_high: v.implied.map(|k| k.high),
                    implied_diff_fraction: v.implied_difference(),
                    text,
                }
            }
        };
        Some(row)
    }
}

/// The rows together, in JSON as the report's `continuum`.
#[derive(Debug, Clone, Serialize)]
pub struct ContinuumSummary {
    /// Every judged row within the tolerance (null when none was judged).
    pub agrees: Option<bool>,
    /// The tolerance, a fraction (the smallest row's, where rows have their own).
    pub tolerance_fraction: Option<f64>,
    /// The deck's K_T (MPa/mm).
    #[serde(rename = "KT_deck_MPa_per_mm")]
    pub deck_stiffness: Option<f64>,
    /// The implied K_T of the sharpest row (the smallest resolution) (MPa/mm).
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied: Option<f64>,
    #[serde(rename = "KT_implied_low_MPa_per_mm")]
    pub implied_low: Option<f64>,
    #[serde(rename = "KT_implied_high_MPa_per_mm")]
    pub implied_high: Option<f64>,
    /// The smallest relative K_T error the case can detect (its sharpest row), a fraction.
    pub resolution_fraction: Option<f64>,
    /// The closing clause.
    pub text: String,
    /// The rows' lines, for the text.
    #[serde(skip)]
    pub lines: Vec<String>,
    /// Whether any row disagrees, for the closing verdict.
    #[serde(skip)]
    pub disagrees: bool,
}

/// The rows `(label, check)` of a report about `response` together; `None` where no row was
/// checked (the TUI's pane, a report of rows not compared by `compare`).
pub fn summary(response: &str, rows: &[(String, Check)]) -> Option<ContinuumSummary> {
    if rows.iter().all(|(_, c)| c.is_none()) {
        return None;
    }
    let lines: Vec<String> = rows
        .iter()
        .filter_map(|(label, c)| ContinuumRow::of(label, response, *c).map(|r| r.text))
        .collect();
    let judged: Vec<(&String, ContinuumVerdict)> = rows
        .iter()
        .filter_map(|(label, c)| Some((label, (*c)?.ok()?)))
        .collect();
    let Some(first) = judged.first().map(|(_, v)| *v) else {
        return Some(ContinuumSummary {
            agrees: None,
            tolerance_fraction: None,
            deck_stiffness: None,
            implied: None,
            implied_low: None,
            implied_high: None,
            resolution_fraction: None,
            text: format!("{response} not judged against the continuum (not solved)"),
            lines,
            disagrees: false,
        });
    };
    let outside: Vec<&str> = judged
        .iter()
        .filter(|(_, v)| !v.agrees())
        .map(|(l, _)| l.as_str())
        .collect();
    // Rows may have their own tolerance (an allowance that grows with the load: the beams'
    // NLGEOM beyond first slip): then the range is said.
    let (low, high) = judged
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), (_, v)| {
            (lo.min(v.tolerance), hi.max(v.tolerance))
        });
    let tolerance = if bare(low) == bare(high) {
        bare(low)
    } else {
        format!("the tolerance ({} to {})", bare(low), bare(high))
    };
    let mut clauses = vec![if outside.is_empty() {
        format!(
            "{response} within {tolerance} of the continuum on all {} judged",
            judged.len()
        )
    } else {
        format!(
            "{response} more than {tolerance} from the continuum at {}",
            outside.join(", ")
        )
    }];
    // The sharpest row: the smallest resolution.
    let sharpest = judged
        .iter()
        .filter_map(|(l, v)| Some((*l, *v, v.resolution()?)))
        .min_by(|a, b| a.2.total_cmp(&b.2));
    let bluntest = judged
        .iter()
        .filter_map(|(l, v)| Some((*l, *v, v.resolution()?)))
        .max_by(|a, b| a.2.total_cmp(&b.2));
    if let Some((label, v, _)) = sharpest
        && let Some(k) = v.implied
    {
        clauses.push(format!(
            "implied K_T {} MPa/mm ({} to {}) at {label}, {} from the deck's {} MPa/mm",
            stiffness(k.value),
            stiffness(k.low),
            stiffness(k.high),
            percent(k.value / v.deck_stiffness - 1.0),
            stiffness(v.deck_stiffness)
        ));
    }
    match sharpest {
        Some((label, _, r)) => clauses.push(format!(
            "this case tells K_T within +-{} (at {label})",
            bare(r)
        )),
        None => clauses.push(format!("{response} does not depend on K_T here")),
    }
    if let Some((label, v, r)) = bluntest
        && r >= BLUNT_RESOLUTION
    {
        clauses.push(format!(
            "{response} alone at {label} could not tell {} from {} MPa/mm",
            stiffness(v.deck_stiffness),
            stiffness(v.deck_stiffness * (1.0 + r))
        ));
    }
    let implied = sharpest.and_then(|(_, v, _)| v.implied);
    Some(ContinuumSummary {
        agrees: Some(outside.is_empty()),
        tolerance_fraction: Some(low),
        deck_stiffness: Some(first.deck_stiffness),
        implied: implied.map(|k| k.value),
        implied_low: implied.map(|k| k.low),
        implied_high: implied.map(|k| k.high),
        resolution_fraction: sharpest.map(|(_, _, r)| r),
        text: clauses.join("; "),
        lines,
        disagrees: !outside.is_empty(),
    })
}

/// The report's text section: the rows' lines and the closing clause.
pub fn section(summary: &ContinuumSummary, what: &str) -> String {
    let mut out = format!(
        "\nAgainst the {what} at the deck's parameters, each row's K_T and load (docs/theory.md,\n\
         \"The verdict against the continuum\"; resolution: the smallest K_T error the row can\n\
         detect, tolerance / |d ln response / d ln K_T|):\n"
    );
    for line in &summary.lines {
        out.push_str(&format!("  {line}\n"));
    }
    out.push_str(&format!("  {}.\n", summary.text));
    out
}
