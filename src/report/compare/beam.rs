//! `microslip compare beam`: one report type; its JSON is serde of it, its text a renderer of it.

use std::fmt::Write as _;

use serde::Serialize;

use super::continuum::{self, Check, ContinuumRow, ContinuumSummary};
use super::verdict::{self, BeamRowVerdict, Summary};
use super::{BeamCompareRow, UNDEFINED_NOTE, optional, percent_or_na};
use crate::fe::compare::BeamComparison;
use crate::kernel::params::Compact;
use crate::report::{number, sanitize};

/// The beams' comparison.
#[derive(Debug, Clone, Serialize)]
pub struct BeamCompareReport {
    /// Always `beam`.
    pub model: &'static str,
    /// The FE results compared.
    pub results: String,
    /// The K_T the closed forms use: the deck's stick slope (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub stiffness: f64,
    /// The Poisson ratio of the shear deflection.
    pub nu: f64,
    pub rows: Vec<BeamRowReport>,
    pub implied: ImpliedReport,
    /// The closing verdict.
    pub verdict: Summary,
    /// w(L) against the beams' plane-stress continuum at the deck's parameters (absent where no
    /// row was checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumSummary>,
}

/// One row: the CSV row's columns and its verdict.
#[derive(Debug, Clone, Serialize)]
pub struct BeamRowReport {
    #[serde(flatten)]
    pub row: BeamCompareRow,
    pub verdict: BeamRowVerdict,
    /// This row against the continuum (absent where it was not checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumRow>,
}

/// What the FE points imply: the fit's values, or why there are none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum ImpliedReport {
    /// The fit of mu and K_T to w(L) less the shear deflection.
    Fit {
        #[serde(rename = "KT_MPa_per_mm")]
        stiffness: f64,
        #[serde(rename = "KT_status")]
        stiffness_status: &'static str,
        /// The fit's standard error of K_T, when it has one.
        #[serde(rename = "KT_std_error_MPa_per_mm")]
        stiffness_std_error: Option<f64>,
        mu: f64,
        mu_status: &'static str,
        rms_mm: f64,
        /// Loaded points less fitted parameters: at 0 the fit passes through every point and
        /// its error is unknown (the RMS is 0 by construction).
        degrees_of_freedom: usize,
    },
    /// Why no fit ran.
    Error { error: String },
}

impl BeamCompareReport {
    /// The report of `comparison` of the results named `source`.
    pub fn new(source: &str, comparison: &BeamComparison) -> BeamCompareReport {
        let implied = match &comparison.implied {
            Ok(fit) => ImpliedReport::Fit {
                stiffness: fit.kt.value,
                stiffness_status: fit.kt.status.label(),
                stiffness_std_error: fit.kt.std_error,
                mu: fit.mu.value,
                mu_status: fit.mu.status.label(),
                rms_mm: fit.rms,
                degrees_of_freedom: fit.degrees_of_freedom,
            },
            Err(e) => ImpliedReport::Error {
                error: e.to_string(),
            },
        };
        let label = |force: f64| format!("F = {} N", number(force));
        let checks: Vec<(String, Check)> = comparison
            .rows
            .iter()
            .map(|r| (label(r.fe.force), r.continuum))
            .collect();
        let mut verdict = verdict::beam_summary(comparison);
        let (checked, continuum) = continuum::judged_rows("w(L)", &checks, &mut verdict);
        BeamCompareReport {
            model: "beam",
            results: source.to_string(),
            stiffness: comparison.stiffness,
            nu: comparison.poisson,
            rows: comparison
                .rows
                .iter()
                .zip(checked)
                .map(|(r, continuum)| BeamRowReport {
                    row: BeamCompareRow::from(r),
                    verdict: verdict::beam_row(r),
                    continuum,
                })
                .collect(),
            implied,
            verdict,
            continuum,
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FE results ({}) vs the closed forms: twin beams, K_T = {} MPa/mm\n\
             w(L) in mm; E-B: Euler-Bernoulli (the paper's closed form); +shear: plus each beam's shear\n\
             deflection F L / (kappa G b 2h), kappa = 5/6, G = E / (2 (1 + nu)), nu = {}; X (mm): start of\n\
             the macroslip zone, from the clamp (FE: where K_T |slip| = mu P).\n",
            sanitize(&self.results),
            number(self.stiffness),
            Compact(self.nu)
        );
        let _ = writeln!(
            out,
            "{:>8} {:>11} {:>11} {:>9} {:>11} {:>9}  {:>9} {:>9}  regime (closed form / FE)",
            "F (N)", "w FE", "w E-B", "diff", "w +shear", "diff", "X FE", "X"
        );
        for BeamRowReport { row, .. } in &self.rows {
            let _ = writeln!(
                out,
                "{:>8} {:>11} {:>11} {:>9} {:>11} {:>9}  {:>9} {:>9}  {} / {}",
                number(row.force),
                number(row.w_fe_mm),
                number(row.w_euler_mm),
                percent_or_na(row.diff_euler),
                number(row.w_shear_corrected_mm),
                percent_or_na(row.diff_shear_corrected),
                optional(row.macroslip_start_fe),
                number(row.macroslip_start),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        if self.rows.iter().any(|r| r.row.diff_euler.is_none()) {
            let _ = writeln!(out, "{UNDEFINED_NOTE}");
        }
        if self
            .rows
            .iter()
            .any(|r| r.verdict.zone_end_elements.is_some())
        {
            let _ = writeln!(
                out,
                "\nPer load step: w(L) +shear against its envelope (docs/theory.md (V2)); X against the\n\
                 closed form's in elements of the deck's mesh along the interface (under one: within what\n\
                 the mesh resolves, the FE X being interpolated between nodes)."
            );
        } else {
            let _ = writeln!(
                out,
                "\nPer load step: w(L) +shear against its envelope (docs/theory.md (V2)); X is not judged\n\
                 (the results carry no slip profile and no mesh)."
            );
        }
        for r in &self.rows {
            let _ = writeln!(out, "  {}", r.verdict.text);
        }
        out.push('\n');
        match &self.implied {
            ImpliedReport::Fit {
                stiffness,
                stiffness_status,
                stiffness_std_error,
                mu,
                mu_status,
                rms_mm,
                degrees_of_freedom,
            } => {
                let exact = if *degrees_of_freedom == 0 {
                    " (0 by construction: no degree of freedom left)"
                } else {
                    ""
                };
                let error =
                    stiffness_std_error.map_or_else(String::new, |e| format!(" +- {}", number(e)));
                let _ = writeln!(
                    out,
                    "What the FE points imply (fit of mu and K_T to w(L) less the shear deflection):\n  \
                     K_T = {}{error} MPa/mm ({stiffness_status}; the closed forms used {}), mu = {} \
                     ({mu_status}), RMS {} mm{exact}",
                    number(*stiffness),
                    number(self.stiffness),
                    number(*mu),
                    number(*rms_mm)
                );
            }
            ImpliedReport::Error { error } => {
                let _ = writeln!(out, "No K_T implied: {error}");
            }
        }
        if let Some(c) = &self.continuum {
            out.push_str(&continuum::section(c, "plane-stress continuum (BC1)"));
        }
        let _ = writeln!(out, "\n{}", self.verdict.summary);
        out
    }
}
