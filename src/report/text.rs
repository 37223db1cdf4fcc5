//! Readable single-point reports. Cycle, K_T candidates, fit and solve render their
//! [`super::point`] types (the same values their JSON serializes), `kt --tolerance` too
//! ([`super::point::tolerance`]); a problem's own point report (the beams at a force, the plate,
//! the lap joint) is its folder's (`src/problems/<name>/report.rs`), with its `text()`. The
//! progress lines are built here from the library's results.

use super::point::cycle::{CycleFace, CycleReport};
use super::point::fit::FitReport;
use super::point::solve::SolveReport;
use super::point::stiffness::StiffnessReport;
use crate::study::curves::StiffnessComparison;

/// Cyclic-loading report of any load-driven problem: both laws side by side.
pub fn cycle<P: CycleFace>(preset: &str, structure: &P::Structure, amplitude: P::Force) -> String {
    CycleReport::new::<P>(preset, structure, amplitude).text()
}

pub use super::point::fit::evidence;

/// Fit report: estimates with standard errors and a plain verdict on identifiability.
pub fn fit(
    data: &str,
    preset: &str,
    structure: &crate::fit::Structure,
    result: &crate::fit::FitResult,
) -> String {
    FitReport::new(data, preset, structure, result).text()
}

/// One line on how far reading a measurement file got, for a progress display.
#[cfg(feature = "app")]
pub(crate) fn reading_progress(done: usize, total: usize) -> String {
    format!(
        "reading the measurements, {}%",
        (done as f64 / total.max(1) as f64 * 100.0) as u32
    )
}

/// One line on how far a running ccx got, from its log: "ccx: 12 s, load step 3 of 5 (41 %)".
pub fn ccx_progress(progress: &crate::fe::run::Progress) -> String {
    let elapsed = progress.elapsed.as_secs_f64();
    match progress.total_time {
        Some(done) if progress.steps > 0 => {
            let steps = progress.steps as f64;
            let done = done.clamp(0.0, steps);
            // The increment being solved ends at `done`, inside step ceil(done).
            let step = (done.ceil() as usize).clamp(1, progress.steps);
            format!(
                "ccx: {elapsed:.0} s, load step {step} of {} ({:.0} %)",
                progress.steps,
                100.0 * done / steps
            )
        }
        _ => format!("ccx: {elapsed:.0} s, setting up"),
    }
}

/// One line on how far a running fit got, for a progress display.
#[cfg(feature = "app")]
pub(crate) fn fit_progress(progress: &crate::fit::Progress) -> String {
    use crate::fit::{Pass, Progress};
    let percent = |done: usize, total: usize| 100 * done / total.max(1);
    match *progress {
        Progress::Bracket {
            done,
            total,
            points,
        } => format!(
            "fitting: grid search for a start on {points} measurements, {}%",
            percent(done, total)
        ),
        Progress::Refine {
            iteration,
            points,
            pass,
            done,
        } => format!(
            "fitting: refining on {points} measurements, iteration {iteration}: {} {}%",
            match pass {
                Pass::Residuals => "residuals",
                Pass::Derivatives => "derivatives",
                Pass::Step => "trying a step",
            },
            percent(done, points)
        ),
    }
}

/// The K_T comparison: each candidate and what it does to the answer.
pub fn stiffness_table(preset: &str, comparison: &StiffnessComparison) -> String {
    StiffnessReport::new(preset, comparison).text()
}

/// The answer of `microslip solve`: every root found, or why there is none.
pub fn solved(
    preset: &str,
    kind: crate::ModelKind,
    solved: &crate::study::target::Solved,
) -> String {
    SolveReport::new(preset, kind, solved).text()
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_fit_evidence_has_its_words() {
        use crate::fit::Evidence;
        let cases = [
            (Evidence::HeldFixed, "held fixed"),
            (
                Evidence::StandardError { relative: 0.0123 },
                "relative standard error 1.23 %",
            ),
            (
                Evidence::AtSearchBound,
                "the best fit sits at the edge of the search range",
            ),
            (Evidence::NoDependence, "the data do not depend on it"),
            (
                Evidence::NoDataAboveFirstMacroslip {
                    first_macroslip_force: 80.5,
                    mu_at_least: 0.25,
                },
                "no measurement above F_1 = 80.5 N: below F_1 the deflection does not depend on mu; the data only show mu >= 0.25",
            ),
            (
                Evidence::FewPointsAboveFirstMacroslip {
                    relative: 0.001,
                    points: 1,
                },
                "relative standard error 0.10 %; only 1 measurement above F_1",
            ),
        ];
        for (evidence, words) in cases {
            assert_eq!(super::evidence(&evidence), words);
        }
    }
}
