//! `microslip compare lap`: one report type; its JSON is serde of it, its text a renderer of it.

use std::fmt::Write as _;

use serde::Serialize;

use super::continuum::{self, Check, ContinuumRow, ContinuumSummary};
use super::verdict::{self, LapRowVerdict, Summary};
use super::{LapCompareRow, optional, percent_or_na};
use crate::fe::compare::LapCompared;
use crate::kernel::validity::Validity;
use crate::report::{number, sanitize};

/// The lap joint's comparison, one row per load step.
#[derive(Debug, Clone, Serialize)]
pub struct LapCompareReport {
    /// Always `lap`.
    pub model: &'static str,
    /// The FE results compared.
    pub results: String,
    pub rows: Vec<LapRowReport>,
    /// The closing verdict.
    pub verdict: Summary,
    /// The FE response against the continuum at the deck's parameters, all rows together
    /// (`compare`, `bench`; absent where no row was checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumSummary>,
}

/// One load step: the CSV row's columns and its verdict.
#[derive(Debug, Clone, Serialize)]
pub struct LapRowReport {
    #[serde(flatten)]
    pub row: LapCompareRow,
    /// (L14) at this force, for the text (the JSON has its label in `shear_lag`).
    #[serde(skip)]
    pub theory_validity: Validity,
    pub verdict: LapRowVerdict,
    /// This row against the continuum (absent where it was not checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumRow>,
}

impl LapCompareReport {
    /// The report of `rows` of the results named `source`.
    pub fn new(source: &str, rows: &[LapCompared]) -> LapCompareReport {
        let checks: Vec<(String, Check)> = rows
            .iter()
            .map(|r| (format!("F = {} N", number(r.fe.force)), r.continuum))
            .collect();
        let mut verdict = verdict::lap_summary(rows);
        let (checked, continuum) = continuum::judged_rows("Delta", &checks, &mut verdict);
        LapCompareReport {
            model: "lap",
            results: source.to_string(),
            rows: rows
                .iter()
                .zip(checked)
                .map(|(r, continuum)| LapRowReport {
                    row: LapCompareRow::from(r),
                    theory_validity: r.theory_validity,
                    verdict: verdict::lap_row(r),
                    continuum,
                })
                .collect(),
            verdict,
            continuum,
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FE results ({}) vs the closed forms: clamped double-lap joint\n\
             F in N; Delta = u_inner(L) - u_cover(0) in mm (FE: thickness means, zeroed after the\n\
             clamping step); closed form: shear lag, regularized law (docs/theory.md section 9);\n\
             a, d (mm): sliding zones from x = 0 and from x = L (FE: where K_T |slip| >= mu P);\n\
             implied K_T (MPa/mm): the K_T whose closed-form Delta equals the FE value, given only\n\
             where the shear-lag theory holds (docs/theory.md (L14)); elsewhere the difference is\n\
             the theory's, not the interface's.\n",
            sanitize(&self.results)
        );
        let _ = writeln!(
            out,
            "{:>8} {:>11} {:>11} {:>9} {:>7} {:>7} {:>7} {:>7}  {:>16}  regime (closed form / FE)",
            "F", "Delta FE", "Delta", "diff", "a FE", "a", "d FE", "d", "implied K_T"
        );
        for LapRowReport {
            row,
            theory_validity,
            ..
        } in &self.rows
        {
            let _ = writeln!(
                out,
                "{:>8} {:>11} {:>11} {:>9} {:>7} {:>7} {:>7} {:>7}  {:>16}  {} / {}",
                number(row.force),
                number(row.delta_fe),
                number(row.delta),
                percent_or_na(row.diff),
                optional(row.slide_from_start_fe),
                number(row.slide_from_start),
                optional(row.slide_from_end_fe),
                number(row.slide_from_end),
                row.implied_stiffness.map_or_else(
                    || {
                        if *theory_validity == Validity::Holds {
                            "none".into()
                        } else {
                            format!("({})", theory_validity.label())
                        }
                    },
                    number
                ),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        let zone = if self.rows.iter().any(|r| r.verdict.a_elements.is_some()) {
            "a and d against the closed form's in elements of the deck's mesh along the interface\n\
             (under one: within what the mesh resolves; (L14) does not bound them)."
        } else {
            "a and d are not judged (the results carry no slip profile and no mesh)."
        };
        let _ = writeln!(
            out,
            "\nPer load step: Delta against the shear-lag theory's envelope (docs/theory.md (L14));\n\
             {zone}"
        );
        for r in &self.rows {
            let _ = writeln!(out, "  {}", r.verdict.text);
        }
        if let Some(c) = &self.continuum {
            out.push_str(&continuum::section(c, "plane-stress continuum (L13)"));
        }
        let _ = writeln!(out, "\n{}", self.verdict.summary);
        out
    }
}
