//! `microslip compare plate`: one report type; its JSON is serde of it, its text a renderer of it.

use std::fmt::Write as _;

use serde::Serialize;

use super::continuum::{self, Check, ContinuumRow, ContinuumSummary};
use super::verdict::{self, PlateRowVerdict, Summary};
use super::{PlateCompareRow, UNDEFINED_NOTE, optional, percent, percent_or_na};
use crate::fe::compare::PlateCompared;
use crate::kernel::validity::Validity;
use crate::report::{number, sanitize};

/// The plate's comparison, one row per FE run.
#[derive(Debug, Clone, Serialize)]
pub struct PlateCompareReport {
    /// Always `plate`.
    pub model: &'static str,
    /// The FE results compared.
    pub results: String,
    pub rows: Vec<PlateRowReport>,
    /// The closing verdict.
    pub verdict: Summary,
    /// The FE response against the continuum at the deck's parameters, all rows together
    /// (`compare`, `bench`; absent where no row was checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumSummary>,
}

/// One run: the CSV row's columns and its verdict.
#[derive(Debug, Clone, Serialize)]
pub struct PlateRowReport {
    #[serde(flatten)]
    pub row: PlateCompareRow,
    /// (V1) at the run's K_T, for the text (the JSON has its label in `strip_theory`).
    #[serde(skip)]
    pub strip_validity: Validity,
    pub verdict: PlateRowVerdict,
    /// This row against the continuum (absent where it was not checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumRow>,
}

impl PlateCompareReport {
    /// The report of `rows` of the results named `source`.
    pub fn new(source: &str, rows: &[PlateCompared]) -> PlateCompareReport {
        let checks: Vec<(String, Check)> = rows
            .iter()
            .map(|r| {
                (
                    format!("K_T = {} MPa/mm", number(r.fe.stiffness)),
                    r.continuum,
                )
            })
            .collect();
        let mut verdict = verdict::plate_summary(rows);
        let (checked, continuum) = continuum::judged_rows("u(L)", &checks, &mut verdict);
        PlateCompareReport {
            model: "plate",
            results: source.to_string(),
            rows: rows
                .iter()
                .zip(checked)
                .map(|(r, continuum)| PlateRowReport {
                    row: PlateCompareRow::from(r),
                    strip_validity: r.strip_validity,
                    verdict: verdict::plate_row(r),
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
            "FE results ({}) vs the closed forms: squeezed plate\n\
             K_T in MPa/mm; u(L) in mm; FE: thickness mean (face: contact face, mid: mid-thickness);\n\
             closed form: strip theory, regularized law; X_r (mm) from the centre (FE: where K_T |slip|\n\
             = mu P); implied K_T (MPa/mm): the K_T whose closed-form u(L) equals the FE mean, given only\n\
             where the strip theory holds (docs/theory.md (V1)); elsewhere the difference is the strip\n\
             theory's, not the interface's.\n",
            sanitize(&self.results)
        );
        let _ = writeln!(
            out,
            "{:>10} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9}  {:>16}  regime (closed form / FE)",
            "K_T", "u FE", "u closed", "diff", "face", "mid", "X_r FE", "X_r", "implied K_T"
        );
        for PlateRowReport {
            row,
            strip_validity,
            ..
        } in &self.rows
        {
            let _ = writeln!(
                out,
                "{:>10} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9}  {:>16}  {} / {}",
                number(row.stiffness),
                number(row.u_fe_mm),
                number(row.u_mm),
                percent_or_na(row.diff),
                row.diff_contact_face.map_or("-".into(), percent),
                row.diff_mid_thickness.map_or("-".into(), percent),
                optional(row.micro_zone_end_fe),
                number(row.micro_zone_end),
                row.implied_stiffness.map_or_else(
                    || {
                        if *strip_validity == Validity::Holds {
                            "none".into()
                        } else {
                            format!("({})", strip_validity.label())
                        }
                    },
                    number
                ),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        if self.rows.iter().any(|r| r.row.diff.is_none()) {
            let _ = writeln!(out, "{UNDEFINED_NOTE}");
        }
        let zone = if self
            .rows
            .iter()
            .any(|r| r.verdict.zone_end_elements.is_some())
        {
            "X_r against the closed form's in elements of the deck's mesh along the contact face\n\
             (under one: within what the mesh resolves, the FE X_r being interpolated between nodes;\n\
             (V1) does not bound X_r)."
        } else {
            "X_r is not judged (the results carry no slip profile\nand no mesh)."
        };
        let _ = writeln!(
            out,
            "\nPer run: the thickness-mean u(L) against the strip theory's envelope (docs/theory.md\n\
             (V1)); {zone}"
        );
        for r in &self.rows {
            let _ = writeln!(out, "  {}", r.verdict.text);
        }
        if let Some(c) = &self.continuum {
            out.push_str(&continuum::section(c, "plane-strain continuum"));
        }
        let _ = writeln!(out, "\n{}", self.verdict.summary);
        out
    }
}
