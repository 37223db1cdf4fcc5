//! The TUI's one-line texts about FE comparisons and validity: the status line after `d` loads
//! FE results, and the plate's strip-theory verdict in the regime pane (30 characters). Sized
//! for the screen, so they live with it; the full reports are `report::compare`'s.

use crate::fe::compare::{BeamComparison, LapCompared, PlateCompared};
use crate::kernel::format::{number, number_with};
use crate::kernel::validity::Validity;
use crate::problems::lap::LapValidity;
use crate::problems::plate::validity::PlateValidity;
use crate::report::compare::{percent, percent_or_na, verdict};

/// The range of the defined `values` as "a to b %", or the one value; "n/a" when none is.
/// Compact: it goes on the status line.
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
        format!("{:+.2} to {}", 100.0 * lo, percent(hi))
    }
}

/// One line for the TUI's status: the beams' comparison in brief, the verdict first (the line is
/// cut at the screen's width).
pub fn beam_summary(code: &str, comparison: &BeamComparison) -> String {
    let shear = percent_range(
        comparison
            .rows
            .iter()
            .map(|r| r.difference_shear_corrected()),
    );
    let euler = percent_range(comparison.rows.iter().map(|r| r.difference_euler()));
    format!(
        "{code}, {} points: {}; w(L) {shear} vs Timoshenko (E-B {euler})",
        comparison.rows.len(),
        verdict::beam_summary(comparison).short
    )
}

/// One line for the TUI's status: one plate run in brief, the verdict first.
pub fn plate_summary(code: &str, row: &PlateCompared) -> String {
    let through = row
        .differences_through_thickness()
        .map_or(String::new(), |[face, mid]| {
            format!("; face {}, mid {}", percent(face), percent(mid))
        });
    format!(
        "{code} at K_T = {} MPa/mm: {}; u(L) {} mm, strip theory {} mm ({}{through})",
        number(row.fe.stiffness),
        verdict::plate_summary(std::slice::from_ref(row)).short,
        number(row.fe.end_displacement),
        number(row.closed),
        percent_or_na(row.difference())
    )
}

/// One line for the TUI's status: the lap joint's comparison in brief, the verdict first.
pub fn lap_summary(code: &str, rows: &[LapCompared]) -> String {
    format!(
        "{code}, {} points: {}; Delta {} vs shear lag",
        rows.len(),
        verdict::lap_summary(rows).short,
        percent_range(rows.iter().map(LapCompared::difference))
    )
}

/// The shear-lag theory's envelope in the lap joint's regime-pane title (about 20 characters), as
/// the beams' title gives theirs: "FE within 3.4 %" (the expected difference of Delta from a
/// plane-stress continuum, (L14)), "FE: >10 %, n solves" where the theory is outside it, "FE: not
/// calibrated" where no calibration reaches (`n` draws the continuum in both cases).
pub fn lap_validity_title(v: &LapValidity) -> String {
    match (v.validity, v.expected_error) {
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

/// The strip theory's validity in a few words (TUI regime pane, one line of 30 characters), for
/// the thickness-mean u(L): "mean holds (~1.6 %)", "mean approx. (~5.2 %)", "mean OUTSIDE",
/// "not calibrated". The number is the expected difference from a plane-strain continuum, (V1).
pub fn strip_validity_short(v: &PlateValidity) -> String {
    let e = v.expected_error();
    match v.validity {
        Validity::Holds => format!("mean holds (~{} %)", percent_of(e)),
        Validity::Approximate => format!("mean approx. (~{} %)", percent_of(e)),
        Validity::Outside => format!("mean OUTSIDE (>{} %)", 100.0 * Validity::APPROXIMATE),
        Validity::NotCalibrated => "not calibrated".to_string(),
        Validity::MeasuredWrong => format!(
            "mean WRONG (>{} %)",
            v.measured_at_least
                .map_or_else(|| "-".to_string(), |e| number_with(100.0 * e, 2))
        ),
    }
}

fn percent_of(error: Option<f64>) -> String {
    error.map_or_else(|| "-".to_string(), |e| number_with(100.0 * e, 2))
}
