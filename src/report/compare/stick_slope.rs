//! The stick slope the FE code used ([`crate::fe::stick_slope`]) and the kinematics of its run
//! ([`crate::fe::kinematics`]) in a comparison's words: a section before the closing verdict, the
//! verdict itself turned to "does not agree" when the contact used another slope than the deck's,
//! and the JSON keys `stick_slope` and `kinematics` beside the report's own (issue 33, items 1
//! and 4). Additive: the problem's report is serialized as it was, these keys flattened beside.

use std::fmt::Write as _;

use serde::Serialize;

use super::percent;
use super::verdict::Summary;
use crate::fe::kinematics::Kinematics;
use crate::fe::peak_pressure::{LockedPressure, PeakPressure};
use crate::fe::stick_slope::{STICK_SLOPE_TOLERANCE, StepSlope, StickSlopeUsed, StickSlopeVerdict};
use crate::report::{number, number_with, sanitize};

/// What one result file says about its contact.
#[derive(Debug, Clone)]
pub struct RunEvidence {
    /// The result file.
    pub results: String,
    /// Its stick slope, why it was not read, or `None` where there was no interface output.
    pub stick_slope: Option<Result<StickSlopeUsed, String>>,
    /// The K_T the benchmark asks for (MPa/mm): the deck header's, or the model's for CSV.
    pub deck: f64,
    /// Its kinematics.
    pub kinematics: Kinematics,
    /// The FE step numbers that carry a load step's force, with the force (N): CalculiX's step
    /// n + 2 is load n (step 1 is the pressure alone); empty where the steps carry no force.
    pub step_forces: Vec<(usize, f64)>,
    /// The largest contact pressure of its interface output, where read.
    pub peak_pressure: Option<PeakPressure>,
    /// The interface's nominal pressure (MPa), which the peak is measured in.
    pub nominal_pressure: f64,
}

/// One step's slope in JSON.
#[derive(Debug, Clone, Serialize)]
pub struct StepSlopeReport {
    /// The FE code's step number.
    pub step: usize,
    /// Its end time.
    pub time: f64,
    /// The force of the load step, where the step carries one (N).
    #[serde(rename = "F_N")]
    pub force: Option<f64>,
    /// The median of CSHEAR / CSLIP over the sticking nodes (MPa/mm).
    #[serde(rename = "KT_used_MPa_per_mm")]
    pub used: f64,
    /// Its lower quartile over the sticking nodes (MPa/mm).
    #[serde(rename = "KT_used_q1_MPa_per_mm")]
    pub low: f64,
    /// Its upper quartile (MPa/mm).
    #[serde(rename = "KT_used_q3_MPa_per_mm")]
    pub high: f64,
    /// Nodes counted as sticking.
    pub sticking_nodes: usize,
    /// Nodes in contact.
    pub nodes_in_contact: usize,
}

/// One result file's stick slope in JSON.
#[derive(Debug, Clone, Serialize)]
pub struct RunSlopeReport {
    /// The result file.
    pub results: String,
    /// `agrees`, `does not agree`, `not judged`, `not read` (no interface output found),
    /// `not given` (a CSV without `--interface`).
    pub verdict: &'static str,
    /// The slope used at the headline step (MPa/mm).
    #[serde(rename = "KT_used_MPa_per_mm")]
    pub used: Option<f64>,
    /// The K_T the deck asks for (MPa/mm).
    #[serde(rename = "KT_deck_MPa_per_mm")]
    pub deck: f64,
    /// (used - deck) / deck, a fraction.
    pub diff_fraction: Option<f64>,
    /// The quartiles over the headline step's sticking nodes, as fractions of the median.
    pub spread_fraction: Option<[f64; 2]>,
    /// The headline step (the one with the most sticking nodes).
    pub step: Option<usize>,
    /// Its sticking nodes.
    pub sticking_nodes: Option<usize>,
    /// The stick slope on the deck's `*FRICTION` card where it differs from the header's K_T
    /// (a deck edited after it was written) (MPa/mm).
    #[serde(rename = "KT_friction_card_MPa_per_mm")]
    pub friction_card: Option<f64>,
    /// Every step with enough sticking nodes.
    pub steps: Vec<StepSlopeReport>,
    /// Why the slope was not read or not judged.
    pub reason: Option<String>,
    /// The verdict in words.
    pub text: String,
    /// The largest contact pressure of the output (MPa), where read.
    #[serde(rename = "peak_pressure_MPa")]
    pub peak_pressure: Option<f64>,
    /// Why the run is no judge when its contact locked (the peak beyond what a sound run of the
    /// problem reaches, [`crate::fe::face::Deck::LOCKED_PRESSURE`]); `None` otherwise.
    pub contact_locked: Option<String>,
}

/// The stick slope section of a comparison in JSON (`stick_slope`).
#[derive(Debug, Clone, Serialize)]
pub struct StickSlopeReport {
    /// `agrees` when every file that has one agrees; `does not agree` when one does not; else
    /// `not judged` / `not read` / `not given`.
    pub verdict: &'static str,
    /// How far the used slope may be from the deck's and agree, a fraction.
    pub tolerance_fraction: f64,
    /// One per result file.
    pub runs: Vec<RunSlopeReport>,
}

/// The kinematics section in JSON (`kinematics`).
#[derive(Debug, Clone, Serialize)]
pub struct KinematicsReport {
    /// `nlgeom`, `linear`, `mixed`, `not stated`.
    pub kinematics: &'static str,
    /// The same in words.
    #[serde(skip)]
    pub words: &'static str,
    /// The kinematics of the closed form's envelope applied to the run (`nlgeom`, `linear`), or
    /// of the first calibrated one where none applies.
    pub envelope_calibrated_on: &'static str,
    /// Every kinematics the problem states an envelope for, the narrowest first.
    pub envelopes_calibrated_on: Vec<&'static str>,
    /// Whether the envelope was applied (false where the run's kinematics is another).
    pub envelope_applies: bool,
    /// In words.
    pub text: String,
}

/// The two sections a comparison gains, flattened beside its own keys.
#[derive(Debug, Clone, Serialize)]
pub struct WithContact<'a, R> {
    /// The problem's report, its keys unchanged.
    #[serde(flatten)]
    pub report: &'a R,
    /// The stick slope used.
    pub stick_slope: StickSlopeReport,
    /// The kinematics.
    pub kinematics: KinematicsReport,
}

/// The kinematics of several files: theirs when they share it, else mixed.
pub fn combined_kinematics(runs: &[RunEvidence]) -> Kinematics {
    let mut kinds = runs.iter().map(|r| r.kinematics);
    let Some(first) = kinds.next() else {
        return Kinematics::NotStated;
    };
    if kinds.all(|k| k == first) {
        first
    } else {
        Kinematics::Mixed
    }
}

/// The kinematics of the envelope (of those `calibrated` on, the narrowest first) a run of
/// `kinematics` is judged against: its own where the problem states one; for a run whose
/// kinematics is not stated (a CSV without `--kinematics`), the widest, which holds for every
/// kinematics calibrated (and the report says so); none for another (mixed steps, or a
/// kinematics the problem was not calibrated on).
pub fn applied_envelope(kinematics: Kinematics, calibrated: &[Kinematics]) -> Option<Kinematics> {
    if calibrated.contains(&kinematics) {
        Some(kinematics)
    } else if kinematics == Kinematics::NotStated {
        calibrated.last().copied()
    } else {
        None
    }
}

/// Whether an envelope applies to a run of `kinematics` ([`applied_envelope`]).
pub fn envelope_applies(kinematics: Kinematics, calibrated: &[Kinematics]) -> bool {
    applied_envelope(kinematics, calibrated).is_some()
}

/// The kinematics section.
pub fn kinematics_report(kinematics: Kinematics, calibrated: &[Kinematics]) -> KinematicsReport {
    let applied = applied_envelope(kinematics, calibrated);
    let on: Vec<&str> = calibrated.iter().map(|k| k.words()).collect();
    let on = on.join(" and ");
    let text = match applied {
        Some(envelope) if kinematics == Kinematics::NotStated => {
            let widest = if calibrated.len() > 1 {
                ", the widest, which holds in each"
            } else {
                ""
            };
            format!(
                "kinematics: not stated (give --kinematics nlgeom|linear); the envelope applied \
                 is the one calibrated on {} runs{widest}",
                envelope.words()
            )
        }
        Some(_) if calibrated.len() > 1 => format!(
            "kinematics: {}, judged against the envelope calibrated on such runs (the problem \
             states one for {on})",
            kinematics.words()
        ),
        Some(_) => format!(
            "kinematics: {}, as the envelope was calibrated on",
            kinematics.words()
        ),
        None => format!(
            "kinematics: {}; the envelope was calibrated on {on} runs only: not calibrated for \
             {}, so the closed form is not judged against it",
            kinematics.words(),
            kinematics.words()
        ),
    };
    let shown = applied.or(calibrated.first().copied());
    KinematicsReport {
        kinematics: kinematics.label(),
        words: kinematics.words(),
        envelope_calibrated_on: shown.map_or("none", Kinematics::label),
        envelopes_calibrated_on: calibrated.iter().map(|k| k.label()).collect(),
        envelope_applies: applied.is_some(),
        text,
    }
}

/// "step 2 (F = 40 N)" or "step 1 (time 1)".
fn step_words(step: &StepSlope, forces: &[(usize, f64)]) -> String {
    match forces.iter().find(|(s, _)| *s == step.step) {
        Some((_, f)) => format!("step {} (F = {} N)", step.step, number(*f)),
        None => format!("step {} (time {})", step.step, number(step.time)),
    }
}

/// One file's stick slope section, with its peak contact pressure judged against the problem's
/// `locked` limit ([`locked_words`]).
pub fn run_report(run: &RunEvidence, locked: Option<LockedPressure>) -> RunSlopeReport {
    let report = slope_report(run);
    RunSlopeReport {
        peak_pressure: run.peak_pressure.map(|p| p.pressure),
        contact_locked: locked.and_then(|limit| locked_words(run, limit)),
        ..report
    }
}

/// Why `run` is no judge when its peak contact pressure is beyond `limit`'s ratio to its nominal
/// pressure: the pressure, where, the limit, and the problem's advice.
pub fn locked_words(run: &RunEvidence, limit: LockedPressure) -> Option<String> {
    let peak = run.peak_pressure?;
    let ratio = peak.ratio(run.nominal_pressure)?;
    peak.locked(run.nominal_pressure, limit.ratio).then(|| {
        format!(
            "its contact locked: a contact pressure of {} MPa ({} times the interface's {} MPa) \
             at node {} in step {}, where a sound run of this problem stays under {} times: \
             the run is no judge ({})",
            number_with(peak.pressure, 4),
            number_with(ratio, 3),
            number(run.nominal_pressure),
            peak.node,
            peak.step,
            number(limit.ratio),
            limit.advice
        )
    })
}

/// One file's stick slope section, its peak pressure not yet judged.
fn slope_report(run: &RunEvidence) -> RunSlopeReport {
    let empty = |verdict: &'static str, reason: Option<String>, text: String| RunSlopeReport {
        results: run.results.clone(),
        verdict,
        used: None,
        deck: run.deck,
        diff_fraction: None,
        spread_fraction: None,
        step: None,
        sticking_nodes: None,
        friction_card: None,
        steps: Vec::new(),
        reason,
        text,
        peak_pressure: None,
        contact_locked: None,
    };
    let used = match &run.stick_slope {
        None => {
            return empty(
                "not given",
                None,
                "stick slope used: not read (give the interface profile with --interface \
                 FILE.csv, x_mm,slip_mm,shear_MPa)"
                    .to_string(),
            );
        }
        Some(Err(reason)) => {
            return empty(
                "not read",
                Some(reason.clone()),
                format!("stick slope used: not read: {}", sanitize(reason)),
            );
        }
        Some(Ok(used)) => used,
    };
    let steps: Vec<StepSlopeReport> = used
        .steps
        .iter()
        .map(|s| StepSlopeReport {
            step: s.step,
            time: s.time,
            force: run
                .step_forces
                .iter()
                .find(|(n, _)| *n == s.step)
                .map(|(_, f)| *f),
            used: s.used,
            low: s.low,
            high: s.high,
            sticking_nodes: s.sticking,
            nodes_in_contact: s.in_contact,
        })
        .collect();
    let verdict = used.verdict();
    let Some(head) = used.headline() else {
        let reason = "no step has 3 nodes or more that stick (in contact, below the friction \
                      limit by 10 %, with a slip)";
        return RunSlopeReport {
            steps,
            friction_card: used.friction_card,
            ..empty(
                verdict.label(),
                Some(reason.to_string()),
                format!("stick slope used: not judged: {reason}"),
            )
        };
    };
    let diff = head.used / used.deck - 1.0;
    let (low, high) = head.spread();
    let mut text = format!(
        "stick slope used: {} MPa/mm ({} vs the deck's {} MPa/mm; spread {} to {} over {} \
         sticking nodes, {})",
        number_with(head.used, 5),
        percent(diff),
        number(used.deck),
        percent(low),
        percent(high),
        head.sticking,
        step_words(head, &run.step_forces)
    );
    let tolerance = format!("{} %", number(100.0 * STICK_SLOPE_TOLERANCE));
    let meaning = match verdict {
        StickSlopeVerdict::Agrees => {
            format!(": within {tolerance}, the contact used the deck's stick slope")
        }
        StickSlopeVerdict::DoesNotAgree => format!(
            ": beyond {tolerance}. Your contact used {} MPa/mm where the deck asked for {} \
             ({}): every comparison above is of a run with another K_T than the closed forms'",
            number_with(head.used, 4),
            number(used.deck),
            if diff > 0.0 { "stiffer" } else { "softer" }
        ),
        StickSlopeVerdict::NotJudged => {
            format!(": not judged, the sticking nodes' quartiles spread beyond {tolerance}")
        }
    };
    text.push_str(&meaning);
    if let Some(card) = used.friction_card {
        let _ = write!(
            text,
            " (the deck's *FRICTION card says {} MPa/mm: it was edited after microslip wrote it)",
            number(card)
        );
    }
    RunSlopeReport {
        results: run.results.clone(),
        verdict: verdict.label(),
        used: Some(head.used),
        deck: used.deck,
        diff_fraction: Some(diff),
        spread_fraction: Some([low, high]),
        step: Some(head.step),
        sticking_nodes: Some(head.sticking),
        friction_card: used.friction_card,
        steps,
        reason: None,
        text,
        peak_pressure: None,
        contact_locked: None,
    }
}

/// The stick slope section of all files, each one's peak contact pressure judged against the
/// problem's `locked` limit ([`crate::fe::face::Deck::LOCKED_PRESSURE`]).
pub fn stick_slope_report(
    runs: &[RunEvidence],
    locked: Option<LockedPressure>,
) -> StickSlopeReport {
    let runs: Vec<RunSlopeReport> = runs.iter().map(|r| run_report(r, locked)).collect();
    let order = [
        "does not agree",
        "not judged",
        "not read",
        "not given",
        "agrees",
    ];
    let verdict = order
        .into_iter()
        .find(|v| runs.iter().any(|r| r.verdict == *v))
        .unwrap_or("not given");
    StickSlopeReport {
        verdict,
        tolerance_fraction: STICK_SLOPE_TOLERANCE,
        runs,
    }
}

/// The reason the closing verdict gives for an envelope without a bound
/// ([`crate::report::compare::verdict`], `StiffnessMatch::ClosedFormNotCalibrated`).
const FRICTION_STRAIN_REASON: &str =
    "its friction strain mu P L / (2 E h) is beyond the measured range";

/// The closing verdict with the stick slope's: "does not agree" when the used slope is not the
/// deck's, whatever the closed forms said, the reason first; otherwise the verdict as it was,
/// with the stick slope's clause added.
pub fn add_to_summary(
    summary: &mut Summary,
    slope: &StickSlopeReport,
    kinematics: &KinematicsReport,
) {
    if !kinematics.envelope_applies {
        // The envelope was taken away for the run's kinematics, not for its friction strain,
        // which the closing verdict's K_T clause would otherwise give as the reason.
        summary.summary = summary.summary.replace(
            FRICTION_STRAIN_REASON,
            "the run is not of the kinematics it was calibrated on",
        );
    }
    let clause = match slope.verdict {
        "does not agree" => {
            let worst = slope
                .runs
                .iter()
                .filter(|r| r.verdict == "does not agree")
                .filter_map(|r| Some((r.used?, r.deck)))
                .next();
            match worst {
                Some((used, deck)) => format!(
                    "The contact used a stick slope of {} MPa/mm, {} from the deck's {} MPa/mm",
                    number_with(used, 4),
                    percent(used / deck - 1.0),
                    number(deck)
                ),
                None => "The contact used another stick slope than the deck's".to_string(),
            }
        }
        "agrees" => "stick slope used within 1 % of the deck's".to_string(),
        other => format!("stick slope used {other}"),
    };
    let clause = format!("{clause}; kinematics: {}", kinematics.words);
    if slope.verdict == "does not agree" {
        turn_to_disagree(summary, &clause, "stick slope; ");
    } else {
        summary.summary = match summary.summary.strip_suffix('.') {
            Some(start) => format!("{start}; {clause}."),
            None => format!("{}; {clause}", summary.summary),
        };
    }
    add_locked(summary, slope);
}

/// The closing verdict turned to "does not agree" when a run's contact locked: its differences
/// are not the FE code's answer to the benchmark, whatever they are.
fn add_locked(summary: &mut Summary, slope: &StickSlopeReport) {
    let Some((results, locked)) = slope
        .runs
        .iter()
        .find_map(|r| Some((&r.results, r.contact_locked.as_ref()?)))
    else {
        return;
    };
    let clause = format!("{}: {}", sanitize(results), sanitize(locked));
    turn_to_disagree(
        summary,
        &clause,
        "contact locked; the comparison otherwise: ",
    );
}

/// The closing verdict turned to "does not agree", `clause` (why) first and the verdict's own
/// reasons after it; its short form `short_why` then the short form it had.
fn turn_to_disagree(summary: &mut Summary, clause: &str, short_why: &str) {
    let body = summary
        .summary
        .strip_prefix("Verdict: ")
        .and_then(|rest| rest.split_once(". "))
        .map(|(_, body)| body.trim_end_matches('.').to_string());
    summary.agrees = false;
    summary.summary = match body {
        Some(body) => format!("Verdict: does not agree. {clause}; {body}."),
        None => format!("Verdict: does not agree. {clause}. {}", summary.summary),
    };
    summary.short = format!("does not agree ({short_why}{})", summary.short);
}

/// The text section, put before the closing verdict line of `text`.
pub fn insert_section(
    text: &str,
    slope: &StickSlopeReport,
    kinematics: &KinematicsReport,
) -> String {
    let mut section = String::from(
        "Stick slope used by the FE code (CSHEAR / CSLIP over the nodes that stick: in contact, \
         |CSHEAR| below 0.9 mu CPRESS, slip not ~0; the median, with its quartiles as the spread):\n",
    );
    for run in &slope.runs {
        let _ = writeln!(section, "  {}", run.text);
        if let Some(locked) = &run.contact_locked {
            let _ = writeln!(section, "  contact: {}", sanitize(locked));
        }
        if run.steps.len() > 1 {
            let per_step: Vec<String> = run
                .steps
                .iter()
                .map(|s| format!("step {}: {}", s.step, number_with(s.used, 5)))
                .collect();
            let _ = writeln!(section, "    per step (MPa/mm): {}", per_step.join(", "));
        }
    }
    let _ = writeln!(section, "  {}\n", kinematics.text);
    match text.rfind("\nVerdict:") {
        Some(at) => format!("{}\n{section}{}", &text[..at], &text[at + 1..]),
        None => format!("{text}\n{section}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary(text: &str) -> Summary {
        Summary {
            agrees: true,
            summary: text.to_string(),
            stiffness: None,
            stiffness_z: None,
            short: "agrees (x)".to_string(),
        }
    }

    fn slope(verdict: &'static str, used: f64) -> StickSlopeReport {
        StickSlopeReport {
            verdict,
            tolerance_fraction: STICK_SLOPE_TOLERANCE,
            runs: vec![RunSlopeReport {
                results: "r.dat".into(),
                verdict,
                used: Some(used),
                deck: 600.0,
                diff_fraction: Some(used / 600.0 - 1.0),
                spread_fraction: Some([0.0, 0.0]),
                step: Some(2),
                sticking_nodes: Some(100),
                friction_card: None,
                steps: Vec::new(),
                reason: None,
                text: String::new(),
                peak_pressure: None,
                contact_locked: None,
            }],
        }
    }

    const LIMIT: LockedPressure = LockedPressure {
        ratio: 5.0,
        advice: "a corner locked",
    };

    fn evidence(peak: f64) -> RunEvidence {
        RunEvidence {
            results: "finest.dat".into(),
            stick_slope: None,
            deck: 600.0,
            kinematics: Kinematics::Linear,
            step_forces: Vec::new(),
            peak_pressure: Some(PeakPressure {
                pressure: peak,
                node: 2123,
                step: 2,
            }),
            nominal_pressure: 2.0,
        }
    }

    #[test]
    fn a_run_whose_contact_locked_is_no_judge_and_says_where() {
        // The beams' finest deck of docs/theory.md (BC4a): 267 MPa at the clamp under P = 2 MPa.
        let slope = stick_slope_report(&[evidence(267.0)], Some(LIMIT));
        let locked = slope.runs[0].contact_locked.as_deref().unwrap();
        assert!(
            locked.contains("267 MPa (134 times the interface's 2 MPa) at node 2123 in step 2"),
            "{locked}"
        );
        assert!(
            locked.ends_with("the run is no judge (a corner locked)"),
            "{locked}"
        );
        assert_eq!(slope.runs[0].peak_pressure, Some(267.0));
        let mut s =
            summary("Verdict: agrees. w(L) within the stated envelope on all 2 load steps.");
        add_to_summary(
            &mut s,
            &slope,
            &kinematics_report(Kinematics::Linear, &[Kinematics::Linear]),
        );
        assert!(!s.agrees);
        assert!(
            s.summary
                .starts_with("Verdict: does not agree. finest.dat: its contact locked"),
            "{}",
            s.summary
        );
        assert!(s.summary.ends_with("w(L) within the stated envelope on all 2 load steps; stick slope used not given; kinematics: linear geometry."), "{}", s.summary);
        assert!(s.short.starts_with("does not agree (contact locked;"));
        let text = insert_section(
            "rows\nVerdict: x",
            &slope,
            &kinematics_report(Kinematics::Linear, &[]),
        );
        assert!(text.contains("  contact: its contact locked"), "{text}");
        // A sound run (2.6 P, the largest of the converged ladders) and a problem that states
        // no limit are judged as before.
        let sound = stick_slope_report(&[evidence(5.2)], Some(LIMIT));
        assert_eq!(sound.runs[0].contact_locked, None);
        let unstated = stick_slope_report(&[evidence(267.0)], None);
        assert_eq!(unstated.runs[0].contact_locked, None);
        let mut s = summary("Verdict: agrees. fine.");
        add_to_summary(
            &mut s,
            &sound,
            &kinematics_report(Kinematics::Linear, &[Kinematics::Linear]),
        );
        assert!(s.agrees);
    }

    #[test]
    fn a_used_slope_beyond_the_tolerance_turns_the_verdict() {
        let mut s =
            summary("Verdict: agrees. w(L) within the stated envelope on all 2 load steps.");
        add_to_summary(
            &mut s,
            &slope("does not agree", 660.0),
            &kinematics_report(Kinematics::Nlgeom, &[Kinematics::Nlgeom]),
        );
        assert!(!s.agrees);
        assert_eq!(
            s.summary,
            "Verdict: does not agree. The contact used a stick slope of 660 MPa/mm, +10.00 % from \
             the deck's 600 MPa/mm; kinematics: NLGEOM (large rotations); w(L) within the stated \
             envelope on all 2 load steps."
        );
        let mut s =
            summary("Verdict: agrees. w(L) within the stated envelope on all 2 load steps.");
        add_to_summary(
            &mut s,
            &slope("agrees", 600.1),
            &kinematics_report(Kinematics::Linear, &[Kinematics::Linear]),
        );
        assert!(s.agrees);
        assert!(
            s.summary.starts_with("Verdict: agrees. w(L)"),
            "{}",
            s.summary
        );
        assert!(
            s.summary.ends_with("; kinematics: linear geometry."),
            "{}",
            s.summary
        );
    }

    #[test]
    fn the_section_goes_before_the_verdict() {
        let k = kinematics_report(Kinematics::Linear, &[Kinematics::Nlgeom]);
        assert!(!k.envelope_applies);
        assert!(
            k.text.contains("not calibrated for linear geometry"),
            "{}",
            k.text
        );
        let text = insert_section(
            "table\n\nVerdict: agrees. x.\n",
            &slope("agrees", 600.0),
            &k,
        );
        assert!(text.starts_with("table\n\nStick slope used"), "{text}");
        assert!(text.ends_with("\nVerdict: agrees. x.\n"), "{text}");
        assert!(envelope_applies(
            Kinematics::NotStated,
            &[Kinematics::Nlgeom]
        ));
    }

    /// A problem with an envelope per kinematics judges each run against its own; a run that
    /// does not say gets the widest (listed last); mixed steps get none.
    #[test]
    fn each_kinematics_gets_its_own_envelope_and_an_unstated_one_the_widest() {
        let both = [Kinematics::Nlgeom, Kinematics::Linear];
        assert_eq!(
            applied_envelope(Kinematics::Nlgeom, &both),
            Some(Kinematics::Nlgeom)
        );
        assert_eq!(
            applied_envelope(Kinematics::Linear, &both),
            Some(Kinematics::Linear)
        );
        assert_eq!(
            applied_envelope(Kinematics::NotStated, &both),
            Some(Kinematics::Linear)
        );
        assert_eq!(applied_envelope(Kinematics::Mixed, &both), None);
        let unstated = kinematics_report(Kinematics::NotStated, &both);
        assert!(unstated.text.contains("the widest"), "{}", unstated.text);
        assert_eq!(unstated.envelope_calibrated_on, "linear");
        let mixed = kinematics_report(Kinematics::Mixed, &both);
        assert!(
            mixed
                .text
                .contains("calibrated on NLGEOM (large rotations) and linear geometry runs only"),
            "{}",
            mixed.text
        );
    }
}
