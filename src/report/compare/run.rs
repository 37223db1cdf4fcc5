//! One `compare`, written once for the command line and the Python face: the FE runs' evidence
//! about their contact (the stick slope they used, their kinematics), the envelope taken away for
//! a run of other kinematics, and the problem's report with the two sections it gains
//! ([`WithContact`](super::stick_slope::WithContact)). What differs between the callers (where the parameters of a CSV come from,
//! their error types, the notes on stderr) stays with them.

use std::path::Path;

use super::CompareFace;
use super::stick_slope::{self as contact, KinematicsReport, RunEvidence, StickSlopeReport};
use crate::fe::header::DeckHeader;
use crate::fe::kinematics::Kinematics;
use crate::fe::peak_pressure::PeakPressure;
use crate::fe::stick_slope::StickSlopeUsed;
use crate::problems::inputs::InterfaceData;

/// What one run says about its contact: `header` the deck's header of a CalculiX run (whose
/// force steps are numbered from it), `interface` the benchmark's (its K_T is the one asked for,
/// its pressure the nominal one), `kinematics`, `stick_slope` and `peak_pressure` as read (a
/// `.dat`'s `.frd` and deck) or told (a CSV's `--interface` and `--kinematics`).
pub fn run_evidence(
    path: &Path,
    header: Option<&DeckHeader>,
    interface: &InterfaceData,
    kinematics: Kinematics,
    stick_slope: Option<Result<StickSlopeUsed, String>>,
    peak_pressure: Option<PeakPressure>,
) -> RunEvidence {
    // CalculiX's step n + 2 carries load n (step 1 is the pressure alone).
    let step_forces = header
        .map(|h| {
            h.loads
                .iter()
                .enumerate()
                .map(|(n, f)| (n + 2, *f))
                .collect()
        })
        .unwrap_or_default();
    RunEvidence {
        results: path.display().to_string(),
        stick_slope,
        deck: interface.stiffness,
        kinematics,
        step_forces,
        peak_pressure,
        nominal_pressure: interface.pressure,
    }
}

/// `compared` (of `model`) judged for `run`'s kinematics: without its envelope when they are not
/// those the problem's envelope was calibrated on ([`contact::envelope_applies`]), and with the
/// allowance the problem states for them against its small-strain continuum
/// ([`Deck::judge_kinematics`](crate::fe::face::Deck::judge_kinematics)).
pub fn judged_for<P: CompareFace>(run: &RunEvidence, model: &P::Model, compared: &mut P::Compared) {
    if !contact::envelope_applies(run.kinematics, P::ENVELOPE_KINEMATICS) {
        P::without_envelope(compared);
    }
    P::judge_kinematics(compared, model, run.kinematics);
}

/// A problem's comparison report with what its runs say about their contact.
pub struct ContactCompared<P: CompareFace> {
    /// The problem's report, its verdict turned by the stick slope used.
    pub report: P::CompareReport,
    /// Its CSV rows.
    pub rows: Vec<P::CompareRow>,
    /// The stick slope the runs used.
    pub stick_slope: StickSlopeReport,
    /// Their kinematics, against the envelope's.
    pub kinematics: KinematicsReport,
}

impl<P: CompareFace> ContactCompared<P> {
    /// The report of the checked comparisons `first` and `more` of the runs `source` names, with
    /// the stick slope and kinematics of `runs` (one per file) and the verdict they turn.
    pub fn new(
        source: &str,
        (first, more): (P::Checked, Vec<P::Checked>),
        runs: &[RunEvidence],
    ) -> Self {
        let (mut report, rows) = P::compare_report(source, first, more);
        let stick_slope = contact::stick_slope_report(runs, P::LOCKED_PRESSURE);
        let kinematics =
            contact::kinematics_report(contact::combined_kinematics(runs), P::ENVELOPE_KINEMATICS);
        contact::add_to_summary(P::summary_mut(&mut report), &stick_slope, &kinematics);
        ContactCompared {
            report,
            rows,
            stick_slope,
            kinematics,
        }
    }

    /// What the JSON is made of: the report's keys and the two sections.
    pub fn with_contact(&self) -> contact::WithContact<'_, P::CompareReport> {
        contact::WithContact {
            report: &self.report,
            stick_slope: self.stick_slope.clone(),
            kinematics: self.kinematics.clone(),
        }
    }

    /// The report as text, with the two sections.
    pub fn text(&self) -> String {
        contact::insert_section(
            &P::compare_text(&self.report),
            &self.stick_slope,
            &self.kinematics,
        )
    }
}
