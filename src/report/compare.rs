//! `microslip compare`: FE results beside the closed forms, as text, CSV or JSON. The numbers come
//! from [`crate::fe::compare`]; this file only words and lays them out.

use std::fmt::Write as _;

use serde::Serialize;
use serde_json::Value;

use super::{number, number_with, sanitize};
use crate::fe::compare::{BeamCompared, BeamComparison, PlateCompared};
use crate::kernel::params::Compact;

/// One row of `microslip compare beam`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct BeamCompareRow {
    /// Tip force on each beam (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// FE w(L) (mm).
    pub w_fe_mm: f64,
    /// Closed form, Euler-Bernoulli (the paper's) (mm).
    pub w_euler_mm: f64,
    /// (FE - Euler-Bernoulli) / Euler-Bernoulli; empty (null) at F = 0, where it is undefined.
    pub diff_euler: Option<f64>,
    /// Closed form plus the shear deflection (mm).
    pub w_shear_corrected_mm: f64,
    /// (FE - shear corrected) / shear corrected; empty (null) at F = 0.
    pub diff_shear_corrected: Option<f64>,
    /// The stated bound on that difference (V2), a fraction.
    pub shear_corrected_within: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows (empty without one).
    pub regime_fe: Option<&'static str>,
    /// Closed-form start of the macroslip zone X (mm).
    #[serde(rename = "X_mm")]
    pub macroslip_start: f64,
    /// FE X (mm), from K_T |slip| = mu P (empty without a slip profile).
    #[serde(rename = "X_fe_mm")]
    pub macroslip_start_fe: Option<f64>,
}

impl From<&BeamCompared> for BeamCompareRow {
    fn from(r: &BeamCompared) -> Self {
        BeamCompareRow {
            force: r.fe.force,
            w_fe_mm: r.fe.deflection,
            w_euler_mm: r.euler,
            diff_euler: r.difference_euler(),
            w_shear_corrected_mm: r.shear_corrected,
            diff_shear_corrected: r.difference_shear_corrected(),
            shear_corrected_within: r.shear_corrected_within,
            regime: r.regime.label(),
            regime_fe: r.fe.interface.map(|i| i.regime.label()),
            macroslip_start: r.macroslip_start,
            macroslip_start_fe: r.fe.interface.map(|i| i.macroslip_start),
        }
    }
}

/// One row of `microslip compare plate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PlateCompareRow {
    /// The run's stick slope K_T (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub stiffness: f64,
    /// FE u(L) (mm): thickness mean for CalculiX, the given value for CSV.
    pub u_fe_mm: f64,
    /// FE u(L) at the contact face (mm).
    pub u_fe_contact_face_mm: Option<f64>,
    /// FE u(L) at mid-thickness (mm).
    pub u_fe_mid_thickness_mm: Option<f64>,
    /// Strip theory, regularized law (mm).
    pub u_mm: f64,
    /// (FE - closed form) / closed form; empty (null) where the closed form is 0 (nu = 0).
    pub diff: Option<f64>,
    /// The same at the contact face.
    pub diff_contact_face: Option<f64>,
    /// The same at mid-thickness.
    pub diff_mid_thickness: Option<f64>,
    /// Strip theory, plain Coulomb law (mm).
    pub u_coulomb_mm: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows.
    pub regime_fe: Option<&'static str>,
    /// Closed-form X_r (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_zone_end: f64,
    /// FE X_r (mm), from K_T |slip| = mu P.
    #[serde(rename = "Xr_fe_mm")]
    pub micro_zone_end_fe: Option<f64>,
    /// The K_T whose closed-form u(L) equals the FE value (MPa/mm).
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// (V1) for the thickness mean at the run's K_T; the implied K_T is given only where it holds.
    pub strip_theory: &'static str,
}

impl From<&PlateCompared> for PlateCompareRow {
    fn from(r: &PlateCompared) -> Self {
        let through = r.fe.through_thickness;
        let diffs = r.differences_through_thickness();
        PlateCompareRow {
            stiffness: r.fe.stiffness,
            u_fe_mm: r.fe.end_displacement,
            u_fe_contact_face_mm: through.map(|u| u[0]),
            u_fe_mid_thickness_mm: through.map(|u| u[1]),
            u_mm: r.closed,
            diff: r.difference(),
            diff_contact_face: diffs.map(|d| d[0]),
            diff_mid_thickness: diffs.map(|d| d[1]),
            u_coulomb_mm: r.coulomb,
            regime: r.regime.label(),
            regime_fe: r.fe_interface().map(|i| i.regime.label()),
            micro_zone_end: r.micro_zone_end,
            micro_zone_end_fe: r.fe_interface().map(|i| i.macroslip_start),
            implied_stiffness: r.implied_stiffness,
            strip_theory: r.strip_validity.label(),
        }
    }
}

/// A relative difference in percent: two decimals, or the exponent form beyond 1e5 % (a number of
/// 200 digits helps nobody), "n/a" where it is undefined (a closed form of 0).
fn percent(x: f64) -> String {
    let p = 100.0 * x;
    if p.abs() < 1e5 {
        format!("{p:+.2} %")
    } else {
        format!("{p:+.2e} %")
    }
}

fn percent_or_na(x: Option<f64>) -> String {
    x.map_or_else(|| "n/a".to_string(), percent)
}

/// The note under a table with an undefined relative difference.
const UNDEFINED_NOTE: &str = "n/a: the closed form is 0 there (no load, or nothing squeezes the \
plate sideways), so a relative difference is undefined; compare the values themselves.";

fn optional(x: Option<f64>) -> String {
    x.map_or_else(|| "-".to_string(), number)
}

/// The beams' comparison as text. `source` names the FE results; `stiffness` is the K_T the closed
/// forms use (the deck's stick slope).
pub fn beam_text(source: &str, stiffness: f64, comparison: &BeamComparison) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "FE results ({}) vs the closed forms: twin beams, K_T = {} MPa/mm\n\
         w(L) in mm; E-B: Euler-Bernoulli (the paper's closed form); +shear: plus each beam's shear\n\
         deflection F L / (kappa G b 2h), kappa = 5/6, G = E / (2 (1 + nu)), nu = {}; X (mm): start of\n\
         the macroslip zone, from the clamp (FE: where K_T |slip| = mu P).\n",
        sanitize(source),
        number(stiffness),
        Compact(comparison.poisson)
    );
    let _ = writeln!(
        out,
        "{:>8} {:>11} {:>11} {:>9} {:>11} {:>9}  {:>9} {:>9}  regime (closed form / FE)",
        "F (N)", "w FE", "w E-B", "diff", "w +shear", "diff", "X FE", "X"
    );
    for r in &comparison.rows {
        let row = BeamCompareRow::from(r);
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
    if comparison
        .rows
        .iter()
        .any(|r| r.difference_euler().is_none())
    {
        let _ = writeln!(out, "{UNDEFINED_NOTE}");
    }
    out.push('\n');
    match &comparison.implied {
        Ok(fit) => {
            let _ = writeln!(
                out,
                "What the FE points imply (fit of mu and K_T to w(L) less the shear deflection):\n  \
                 K_T = {} MPa/mm ({}; the closed forms used {}), mu = {} ({}), RMS {} mm",
                number(fit.kt.value),
                fit.kt.status.label(),
                number(stiffness),
                number(fit.mu.value),
                fit.mu.status.label(),
                number(fit.rms)
            );
        }
        Err(e) => {
            let _ = writeln!(out, "No K_T implied: {e}");
        }
    }
    out
}

/// The beams' comparison as JSON.
pub fn beam_json(source: &str, stiffness: f64, comparison: &BeamComparison) -> Value {
    let rows: Vec<BeamCompareRow> = comparison.rows.iter().map(BeamCompareRow::from).collect();
    let implied = match &comparison.implied {
        Ok(fit) => serde_json::json!({
            "KT_MPa_per_mm": fit.kt.value,
            "KT_status": fit.kt.status.label(),
            "mu": fit.mu.value,
            "mu_status": fit.mu.status.label(),
            "rms_mm": fit.rms,
        }),
        Err(e) => serde_json::json!({ "error": e.to_string() }),
    };
    serde_json::json!({
        "model": "beam",
        "results": source,
        "KT_MPa_per_mm": stiffness,
        "nu": comparison.poisson,
        "rows": rows,
        "implied": implied,
    })
}

/// The plate's comparison as text.
pub fn plate_text(source: &str, rows: &[PlateCompared]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "FE results ({}) vs the closed forms: squeezed plate\n\
         K_T in MPa/mm; u(L) in mm; FE: thickness mean (face: contact face, mid: mid-thickness);\n\
         closed form: strip theory, regularized law; X_r (mm) from the centre (FE: where K_T |slip|\n\
         = mu P); implied K_T (MPa/mm): the K_T whose closed-form u(L) equals the FE mean, given only\n\
         where the strip theory holds (docs/theory.md (V1)); elsewhere the difference is the strip\n\
         theory's, not the interface's.\n",
        sanitize(source)
    );
    let _ = writeln!(
        out,
        "{:>10} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9}  {:>16}  regime (closed form / FE)",
        "K_T", "u FE", "u closed", "diff", "face", "mid", "X_r FE", "X_r", "implied K_T"
    );
    for r in rows {
        let row = PlateCompareRow::from(r);
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
                    if r.strip_validity == crate::kernel::validity::Validity::Holds {
                        "none".into()
                    } else {
                        format!("({})", r.strip_validity.label())
                    }
                },
                number
            ),
            row.regime,
            row.regime_fe.unwrap_or("-")
        );
    }
    if rows.iter().any(|r| r.difference().is_none()) {
        let _ = writeln!(out, "{UNDEFINED_NOTE}");
    }
    out
}

/// The plate's comparison as JSON.
pub fn plate_json(source: &str, rows: &[PlateCompared]) -> Value {
    let rows: Vec<PlateCompareRow> = rows.iter().map(PlateCompareRow::from).collect();
    serde_json::json!({
        "model": "plate",
        "results": source,
        "rows": rows,
    })
}

/// The range of the defined `values` as "a to b" in percent, or the one value; "n/a" when none is.
fn percent_range(values: impl Iterator<Item = Option<f64>>) -> String {
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
        format!("{} to {}", percent(lo), percent(hi))
    }
}

/// One line for the TUI's status: the beams' comparison in brief.
pub fn beam_summary(code: &str, comparison: &BeamComparison) -> String {
    let shear = percent_range(
        comparison
            .rows
            .iter()
            .map(|r| r.difference_shear_corrected()),
    );
    let euler = percent_range(comparison.rows.iter().map(|r| r.difference_euler()));
    let implied = match &comparison.implied {
        Ok(fit) if fit.kt.status == crate::fit::Status::Identified => {
            format!("; implied K_T {} MPa/mm", number_with(fit.kt.value, 4))
        }
        Ok(fit) => format!(
            "; implied K_T {} MPa/mm ({})",
            number_with(fit.kt.value, 4),
            fit.kt.status.label()
        ),
        Err(_) => String::new(),
    };
    format!(
        "{code}, {} points: w(L) {shear} from closed form + shear (Euler-Bernoulli alone {euler}){implied}",
        comparison.rows.len()
    )
}

/// One line for the TUI's status: one plate run in brief.
pub fn plate_summary(code: &str, row: &PlateCompared) -> String {
    let through = row
        .differences_through_thickness()
        .map_or(String::new(), |[face, mid]| {
            format!(
                "; contact face {}, mid-thickness {}",
                percent(face),
                percent(mid)
            )
        });
    format!(
        "{code} at K_T = {} MPa/mm: u(L) {} mm, strip theory {} mm ({}{through})",
        number(row.fe.stiffness),
        number(row.fe.end_displacement),
        number(row.closed),
        percent_or_na(row.difference())
    )
}
