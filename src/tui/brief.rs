//! The TUI's one-line texts about FE comparisons: the status line after `d` loads FE results.
//! Sized for the screen, so they live with it; the full reports are `report::compare`'s (each
//! problem's validity words for the regime pane are its face's, `src/problems/<name>/pane.rs`).

use crate::fe::compare::{BeamComparison, LapCompared, PlateCompared};
use crate::kernel::format::number;
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
