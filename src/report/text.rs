//! Readable single-point reports. Beam, plate, cycle, K_T candidates, fit and solve render their
//! [`super::point`] types (the same values their JSON serializes), `kt --tolerance` too
//! ([`super::point::tolerance`]); the progress lines are built here from the library's results.

use super::point::beam::BeamReport;
use super::point::cycle::{BeamCycleReport, LapCycleReport};
use super::point::fit::FitReport;
use super::point::lap::LapReport;
use super::point::plate::PlateReport;
use super::point::solve::SolveReport;
use super::point::stiffness::StiffnessReport;
use crate::numeric::NumericError;
use crate::problems::lap::ContinuumLap;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::plate::ContinuumPlate;
use crate::study::curves::StiffnessComparison;
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// Twin-beam report at one force.
pub fn beam(preset: &str, beams: &TwinBeams, force: TipForce) -> String {
    BeamReport::new(preset, beams, force).text()
}

/// Lap-joint report at one force.
pub fn lap(
    preset: &str,
    joint: &LapJoint,
    force: JointForce,
    continuum: Option<&Result<ContinuumLap, NumericError>>,
) -> String {
    LapReport::new(preset, joint, force, continuum).text()
}

/// One cycle of the lap joint, both laws.
pub fn lap_cycle(preset: &str, joint: &LapJoint, amplitude: JointForce) -> String {
    LapCycleReport::new(preset, joint, amplitude).text()
}

/// Squeezed-plate report.
pub fn plate(
    preset: &str,
    plate: &SqueezedPlate,
    continuum: Option<&Result<ContinuumPlate, NumericError>>,
) -> String {
    PlateReport::new(preset, plate, continuum).text()
}

/// Cyclic-loading report: both laws side by side.
pub fn cycle(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> String {
    BeamCycleReport::new(preset, beams, amplitude).text()
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
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

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

    #[test]
    fn beam_report_shows_units_thresholds_and_both_laws() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let text = beam("paper-beams", &beams, TipForce::new(100.0).unwrap());
        for needle in [
            "KT  = 600 MPa/mm",
            "(0.6 MPa/um)",
            "F_thre     = 80 N",
            "F_1        = 80.1857 N",
            "0.5 um",
            "17.3095 (microslip end X)",
            "microslip+macroslip",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
    }

    #[test]
    fn plate_report_shows_both_zone_ends_and_names_the_pressure_model() {
        let plate_model = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let text = plate("paper-plate", &plate_model, None);
        for needle in [
            "nu  = 0.3",
            "X_s = 9.71429",
            "X_r = 9.83832",
            "flat Timoshenko plate, friction saturated everywhere (P7-P9",
            // (L - X_r) / t_p = (10 - 9.83832) / 0.2: under one t_p, where the flat model's
            // end-layer mean was not measured right.
            "not here (slip zone 0.808 t_p)",
            "plane-strain continuum (--continuum)",
            "MEASURED WRONG here (V1c)",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
    }
}
