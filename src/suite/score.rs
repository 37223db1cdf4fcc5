//! The scorecard: each case's quantities extrapolated over its ladder and judged
//! ([`crate::fe::ladder`]), the stick slope its runs used, its verdict; as text, as JSON (one
//! object per case) and as JUnit XML (one testcase per case, a `<failure>` with the numbers, as
//! pytest writes it: what CI services read).

use std::fmt::Write as _;

use serde::Serialize;

use super::result::{RunResult, RunStickSlope};
use super::{Case, RunSpec};
use crate::fe::ladder::{self, Convergence, Extrapolation, Verdict};
use crate::report::sanitize;

/// One quantity of a case over its ladder.
#[derive(Debug, Clone, Serialize)]
pub struct QuantityScore {
    /// The quantity and its load step.
    pub name: String,
    /// Its difference from the closed form on each mesh rung, coarsest first (fractions).
    pub rungs_fraction: Vec<f64>,
    /// On the finest rung at half the increment.
    pub half_increment_fraction: Option<f64>,
    /// The extrapolated (converged) difference, its uncertainty, the observed order.
    #[serde(flatten)]
    pub extrapolation: Extrapolation,
    /// The quantity itself, where the problem states it: the converged value, its uncertainty,
    /// the closed form's, in `value_unit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<ConvergedValue>,
    /// The envelope's bound (the reference's measured accuracy), a fraction.
    pub bound_fraction: Option<f64>,
    /// The tolerance the estimate was judged with: bound + uncertainty.
    pub tolerance_fraction: Option<f64>,
    /// The largest uncertainty its case accepts ([`Case::converged_within`]), a fraction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub converged_within_fraction: Option<f64>,
    /// Its verdict.
    pub verdict: Verdict,
}

/// A converged difference as the quantity itself.
#[derive(Debug, Clone, Serialize)]
pub struct ConvergedValue {
    /// The converged value.
    pub estimate: f64,
    /// Its uncertainty.
    pub uncertainty: Option<f64>,
    /// The reference's value (the closed form's, or the problem's continuum's).
    pub closed_form: f64,
    /// Their unit.
    pub unit: String,
}

/// One case's score.
#[derive(Debug, Clone, Serialize)]
pub struct CaseScore {
    /// The case's name.
    pub case: String,
    /// Its problem's key.
    pub model: &'static str,
    /// Its preset and assignments.
    pub preset: String,
    /// Assignments on top of it.
    pub set: Vec<String>,
    /// The verdict: `agrees`, `does not agree`, `not converged`, `not judged`.
    pub verdict: Verdict,
    /// Why, in one line (the numbers).
    pub reason: String,
    /// "single run, not converged" for a ladder of one run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<&'static str>,
    /// Its quantities.
    pub quantities: Vec<QuantityScore>,
    /// The stick slope used on the finest rung.
    pub stick_slope: Option<RunStickSlope>,
    /// Its runs, in ladder order (`null`: not complete).
    pub runs: Vec<RunScore>,
}

/// One run in a case's score.
#[derive(Debug, Clone, Serialize)]
pub struct RunScore {
    /// The run's name.
    pub run: String,
    /// Its result, where complete.
    pub result: Option<RunResult>,
    /// Why it has none (a failed solver, unreadable output).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The score of `case` from its runs (`specs`) and their outcomes (`Err`: why none).
pub fn case_score(
    case: &Case,
    specs: &[RunSpec],
    outcomes: &[Result<RunResult, String>],
) -> CaseScore {
    let runs: Vec<RunScore> = specs
        .iter()
        .zip(outcomes)
        .map(|(spec, outcome)| RunScore {
            run: spec.name.clone(),
            result: outcome.as_ref().ok().cloned(),
            error: outcome.as_ref().err().cloned(),
        })
        .collect();
    let mesh_results: Vec<&RunResult> = specs
        .iter()
        .zip(outcomes)
        .filter(|(spec, _)| !spec.half_increment)
        .filter_map(|(_, o)| o.as_ref().ok())
        .collect();
    let half: Option<&RunResult> = specs
        .iter()
        .zip(outcomes)
        .find(|(spec, _)| spec.half_increment)
        .and_then(|(_, o)| o.as_ref().ok());
    let mut score = CaseScore {
        case: case.name.clone(),
        model: case.kind.name(),
        preset: case.preset.clone(),
        set: case.assignments.clone(),
        verdict: Verdict::NotConverged,
        reason: String::new(),
        label: (specs.len() == 1).then_some(Convergence::SingleRun.words()),
        quantities: Vec::new(),
        stick_slope: mesh_results.last().and_then(|r| r.stick_slope.clone()),
        runs,
    };
    if let Some(failed) = score.runs.iter().find(|r| r.result.is_none()) {
        score.reason = format!(
            "run {} gave no result: {}",
            failed.run,
            failed.error.as_deref().unwrap_or("not run")
        );
        return score;
    }
    let Some(finest) = mesh_results.last() else {
        score.reason = "no run".to_string();
        return score;
    };
    for q in &finest.quantities {
        let value = |r: &RunResult| {
            r.quantities
                .iter()
                .find(|o| o.name == q.name)
                .map(|o| o.difference)
        };
        let rungs: Option<Vec<f64>> = mesh_results.iter().map(|r| value(r)).collect();
        let Some(rungs) = rungs else { continue };
        let half_value = half.and_then(value);
        let Some(extrapolation) = ladder::extrapolate(&rungs, half_value) else {
            continue;
        };
        let verdict = match (
            ladder::judge(&extrapolation, q.bound),
            case.converged_within,
        ) {
            // Within the envelope, but not converged as tightly as the case asks (a single run
            // shows no convergence at all).
            (Verdict::Agrees, Some(within))
                if extrapolation.uncertainty.is_none_or(|u| u > within) =>
            {
                Verdict::NotConverged
            }
            (verdict, _) => verdict,
        };
        let value = q.value.as_ref().map(|v| ConvergedValue {
            estimate: v.at(extrapolation.estimate),
            uncertainty: extrapolation.uncertainty.map(|u| u * v.scale.abs()),
            closed_form: v.closed_form,
            unit: v.unit.clone(),
        });
        score.quantities.push(QuantityScore {
            value,
            name: q.name.clone(),
            rungs_fraction: rungs,
            half_increment_fraction: half_value,
            tolerance_fraction: q
                .bound
                .map(|b| b + extrapolation.uncertainty.unwrap_or(0.0)),
            extrapolation,
            bound_fraction: q.bound,
            converged_within_fraction: case.converged_within,
            verdict,
        });
    }
    let judged = score
        .quantities
        .iter()
        .filter(|q| q.verdict != Verdict::NotJudged);
    let worst = judged.clone().max_by_key(|q| q.verdict);
    (score.verdict, score.reason) = match worst {
        None => (
            Verdict::NotJudged,
            "no quantity with a calibrated bound: nothing judged".to_string(),
        ),
        Some(q) => (q.verdict, quantity_line(q)),
    };
    let locked = score
        .runs
        .iter()
        .filter_map(|r| r.result.as_ref())
        .find_map(|r| Some((r.run.clone(), r.contact_locked.clone()?)));
    if let Some((run, locked)) = locked {
        // The run is not the FE code's answer: its rung cannot make a converged ladder.
        score.verdict = Verdict::NotConverged;
        score.reason = format!("run {run}: {locked}; {}", score.reason);
    }
    let off = score
        .runs
        .iter()
        .filter_map(|r| r.result.as_ref())
        .find_map(|r| {
            r.stick_slope
                .as_ref()
                .filter(|s| s.verdict == "does not agree")
                .map(|s| (r.run.clone(), s.clone()))
        });
    if let Some((run, slope)) = off {
        score.verdict = Verdict::DoesNotAgree;
        score.reason = format!(
            "run {run}: the solver used a stick slope of {} MPa/mm, {} from the deck's {} \
             MPa/mm; {}",
            slope
                .used
                .map_or_else(|| "?".to_string(), crate::report::number),
            slope.diff_fraction.map_or_else(|| "?".to_string(), percent),
            crate::report::number(slope.deck),
            score.reason
        );
    }
    score
}

fn percent(x: f64) -> String {
    format!("{:+.3} %", 100.0 * x)
}

/// One quantity's numbers in a line.
pub fn quantity_line(q: &QuantityScore) -> String {
    let rungs: Vec<String> = q.rungs_fraction.iter().map(|&r| percent(r)).collect();
    let mut line = format!("{}: rungs {}", q.name, rungs.join(", "));
    if let Some(h) = q.half_increment_fraction {
        let _ = write!(line, " (half increment {})", percent(h));
    }
    let e = &q.extrapolation;
    let _ = write!(line, "; converged {}", percent(e.estimate));
    if let Some(u) = e.uncertainty {
        let _ = write!(line, " +- {}", percent(u).trim_start_matches('+'));
    }
    if let Some(p) = e.order {
        let _ = write!(line, ", observed order {p:.2}");
    }
    if let Some(v) = &q.value {
        let _ = write!(
            line,
            " = {}{} {} (reference {})",
            crate::report::number(v.estimate),
            v.uncertainty
                .map_or_else(String::new, |u| format!(" +- {}", crate::report::number(u))),
            v.unit,
            crate::report::number(v.closed_form)
        );
    }
    let _ = write!(line, " ({})", e.convergence.words());
    match (q.bound_fraction, q.tolerance_fraction) {
        (Some(b), Some(t)) => {
            let _ = write!(
                line,
                "; tolerance {} = bound {} + uncertainty",
                percent(t).trim_start_matches('+'),
                percent(b).trim_start_matches('+')
            );
        }
        _ => line.push_str("; no bound calibrated"),
    }
    if let Some(within) = q.converged_within_fraction {
        let _ = write!(
            line,
            "; the case asks an uncertainty of at most {}",
            percent(within).trim_start_matches('+')
        );
    }
    let _ = write!(line, ": {}", q.verdict.label());
    line
}

/// The scorecard as text.
pub fn text(cases: &[CaseScore]) -> String {
    let mut out = String::new();
    for c in cases {
        let _ = writeln!(
            out,
            "{} ({}, preset {}{}): {}{}",
            sanitize(&c.case),
            c.model,
            sanitize(&c.preset),
            if c.set.is_empty() {
                String::new()
            } else {
                format!(" {}", sanitize(&c.set.join(" ")))
            },
            c.verdict.label(),
            c.label.map_or_else(String::new, |l| format!(" ({l})"))
        );
        for q in &c.quantities {
            let _ = writeln!(out, "  {}", quantity_line(q));
        }
        if let Some(s) = &c.stick_slope {
            let _ = writeln!(
                out,
                "  stick slope used (finest rung): {} MPa/mm, deck {} MPa/mm ({}): {}",
                s.used
                    .map_or_else(|| "-".to_string(), crate::report::number),
                crate::report::number(s.deck),
                s.diff_fraction.map_or_else(|| "-".to_string(), percent),
                s.verdict
            );
        }
        for r in c.runs.iter().filter(|r| r.error.is_some()) {
            let _ = writeln!(
                out,
                "  run {}: {}",
                r.run,
                sanitize(r.error.as_deref().unwrap_or_default())
            );
        }
        if c.verdict != Verdict::Agrees {
            let _ = writeln!(out, "  why: {}", sanitize(&c.reason));
        }
    }
    let agree = cases
        .iter()
        .filter(|c| c.verdict == Verdict::Agrees)
        .count();
    let _ = writeln!(
        out,
        "\nSuite: {agree} of {} cases agree{}",
        cases.len(),
        if agree == cases.len() {
            ""
        } else {
            " (exit code 1)"
        }
    );
    out
}

/// The scorecard as JUnit XML: one testcase per case, `<failure>` with the numbers where it does
/// not agree.
pub fn junit(cases: &[CaseScore], seconds: f64) -> String {
    let failures = cases
        .iter()
        .filter(|c| c.verdict != Verdict::Agrees)
        .count();
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite \
         name=\"microslip suite\" tests=\"{}\" failures=\"{failures}\" errors=\"0\" \
         time=\"{seconds:.3}\">\n",
        cases.len()
    );
    for c in cases {
        let time: f64 = c
            .runs
            .iter()
            .filter_map(|r| r.result.as_ref())
            .map(|r| r.solver_seconds)
            .sum();
        let _ = write!(
            out,
            "    <testcase classname=\"microslip.suite.{}\" name=\"{}\" time=\"{time:.3}\"",
            xml(c.model),
            xml(&c.case)
        );
        if c.verdict == Verdict::Agrees {
            out.push_str("/>\n");
            continue;
        }
        let mut body: Vec<String> = c.quantities.iter().map(quantity_line).collect();
        body.push(format!("why: {}", c.reason));
        let _ = write!(
            out,
            ">\n      <failure message=\"{}: {}\" type=\"{}\">{}</failure>\n    </testcase>\n",
            xml(&c.case),
            xml(c.verdict.label()),
            xml(c.verdict.label()),
            xml(&body.join("\n"))
        );
    }
    out.push_str("  </testsuite>\n</testsuites>\n");
    out
}

/// `text` escaped for XML text and double-quoted attributes, control characters (which XML 1.0 cannot hold)
/// as `?`.
pub(super) fn xml(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '&' => "&amp;".to_string(),
            '<' => "&lt;".to_string(),
            '>' => "&gt;".to_string(),
            '"' => "&quot;".to_string(),
            '\n' | '\t' => c.to_string(),
            c if c.is_control() => "?".to_string(),
            c => c.to_string(),
        })
        .collect()
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::fe::deck::DeckMesh;
    use crate::fe::ladder::LadderQuantity;
    use crate::problems::ModelKind;

    fn result(run: &str, difference: f64, slope: f64) -> Result<RunResult, String> {
        Ok(RunResult {
            run: run.to_string(),
            mesh: run.to_string(),
            increment: None,
            quantities: vec![LadderQuantity {
                name: "u at F = 1 N".to_string(),
                difference,
                bound: Some(0.015),
                value: None,
            }],
            stick_slope: Some(RunStickSlope {
                verdict: if (slope - 1.0).abs() < 0.01 {
                    "agrees"
                } else {
                    "does not agree"
                }
                .to_string(),
                used: Some(1000.0 * slope),
                deck: 1000.0,
                diff_fraction: Some(slope - 1.0),
            }),
            agrees: true,
            verdict: "agrees".to_string(),
            contact_locked: None,
            solver_seconds: 1.0,
        })
    }

    fn quick_case() -> Case {
        Case {
            name: "c".to_string(),
            kind: ModelKind::ALL[0],
            preset: "p".to_string(),
            assignments: Vec::new(),
            meshes: vec![DeckMesh::Coarse, DeckMesh::Fine],
            loads: None,
            converged_within: None,
        }
    }

    /// A case of the full ladder named `name` whose one quantity is `values` on its rungs, run
    /// at `slope` times the deck's stick slope.
    pub(in crate::suite) fn ladder(name: &str, values: [f64; 3], slope: f64) -> CaseScore {
        let case = Case {
            name: name.to_string(),
            kind: ModelKind::ALL[0],
            preset: "p".to_string(),
            assignments: Vec::new(),
            meshes: DeckMesh::ALL.to_vec(),
            loads: None,
            converged_within: None,
        };
        let specs = super::super::plan(0, &case, None);
        let outcomes: Vec<_> = specs
            .iter()
            .zip(values)
            .map(|(s, v)| result(&s.name, v, slope))
            .collect();
        case_score(&case, &specs, &outcomes)
    }

    #[test]
    fn a_converging_ladder_agrees_and_one_off_a_power_law_is_not_converged() {
        // 0.5 % + 4 % h^2: converged 0.5 %, within 1.5 %.
        let good = ladder("a<b", [0.045, 0.015, 0.0075], 1.0);
        assert_eq!(good.verdict, Verdict::Agrees, "{}", good.reason);
        let q = &good.quantities[0];
        assert!((q.extrapolation.estimate - 0.005).abs() < 1e-12);
        let coarse = ladder("a<b", [0.20, 0.02, 0.12], 1.0);
        assert_eq!(coarse.verdict, Verdict::NotConverged);
        let xml = junit(&[good, coarse], 3.0);
        assert!(xml.contains("tests=\"2\" failures=\"1\""), "{xml}");
        assert!(xml.contains("name=\"a&lt;b\""), "{xml}");
        assert!(
            xml.contains("rungs +20.000 %, +2.000 %, +12.000 %"),
            "{xml}"
        );
    }

    #[test]
    fn a_quantity_with_its_value_is_given_back_in_its_unit() {
        let q = LadderQuantity {
            name: "s(a)".to_string(),
            difference: 0.02,
            bound: Some(0.04),
            value: Some(crate::fe::ladder::ValueScale {
                closed_form: 2.0,
                scale: 2.0,
                unit: "mm".to_string(),
            }),
        };
        let mut runs = vec![result("coarse", 0.03, 1.0), result("fine", 0.02, 1.0)];
        for (r, d) in runs.iter_mut().zip([0.03, 0.02]) {
            let r = r.as_mut().unwrap();
            r.quantities = vec![LadderQuantity {
                difference: d,
                ..q.clone()
            }];
        }
        let case = quick_case();
        let score = case_score(&case, &super::super::plan(0, &case, None), &runs);
        let v = score.quantities[0].value.as_ref().unwrap();
        // 2 mm (1 + 2 %) = 2.04 mm, +- 1 % of 2 mm.
        assert!((v.estimate - 2.04).abs() < 1e-12 && (v.uncertainty.unwrap() - 0.02).abs() < 1e-12);
        assert!(quantity_line(&score.quantities[0]).contains("= 2.04 +- 0.02 mm (reference 2)"));
    }

    #[test]
    fn a_stick_slope_off_the_deck_s_does_not_agree_with_its_numbers() {
        let off = ladder("a<b", [0.045, 0.015, 0.0075], 1.1);
        assert_eq!(off.verdict, Verdict::DoesNotAgree);
        assert!(
            off.reason.contains("1100 MPa/mm, +10.000 %"),
            "{}",
            off.reason
        );
        let text = text(&[off]);
        assert!(text.contains("0 of 1 cases agree (exit code 1)"), "{text}");
    }

    #[test]
    fn a_rung_whose_contact_locked_leaves_the_case_not_converged_naming_it() {
        // A ladder that would agree (0.5 % + 4 % h^2), but its finest run's contact locked.
        let case = quick_case();
        let specs = super::super::plan(0, &case, None);
        let mut outcomes = vec![result("coarse", 0.010, 1.0), result("fine", 0.006, 1.0)];
        assert_eq!(
            case_score(&case, &specs, &outcomes).verdict,
            Verdict::Agrees
        );
        let locked = "its contact locked: a contact pressure of 267 MPa at node 2123";
        outcomes[1].as_mut().unwrap().contact_locked = Some(locked.to_string());
        let score = case_score(&case, &specs, &outcomes);
        assert_eq!(score.verdict, Verdict::NotConverged);
        assert!(
            score
                .reason
                .starts_with(&format!("run {}: {locked}; ", specs[1].name)),
            "{}",
            score.reason
        );
        // A stick slope off the deck's is still the worse finding.
        outcomes[0] = result("coarse", 0.010, 1.1);
        assert_eq!(
            case_score(&case, &specs, &outcomes).verdict,
            Verdict::DoesNotAgree
        );
    }

    #[test]
    fn a_case_that_asks_a_tighter_convergence_than_its_envelope_is_held_to_it() {
        // Coarse 1.0 %, fine 0.6 %: converged 0.6 % +- 0.4 %, inside the bound of 1.5 %.
        let mut case = quick_case();
        let specs = super::super::plan(0, &case, None);
        let outcomes = vec![result("coarse", 0.010, 1.0), result("fine", 0.006, 1.0)];
        assert_eq!(
            case_score(&case, &specs, &outcomes).verdict,
            Verdict::Agrees
        );
        case.converged_within = Some(0.005);
        assert_eq!(
            case_score(&case, &specs, &outcomes).verdict,
            Verdict::Agrees
        );
        case.converged_within = Some(0.003);
        let held = case_score(&case, &specs, &outcomes);
        assert_eq!(held.verdict, Verdict::NotConverged);
        assert!(
            held.reason.contains("+- 0.400 %")
                && held
                    .reason
                    .contains("asks an uncertainty of at most 0.300 %: not converged"),
            "{}",
            held.reason
        );
        // A single run shows no convergence: a case that asks for some is not converged.
        let single = Case {
            meshes: vec![DeckMesh::Coarse],
            ..case
        };
        let specs = super::super::plan(0, &single, None);
        let score = case_score(&single, &specs, &[result("coarse", 0.001, 1.0)]);
        assert_eq!(score.verdict, Verdict::NotConverged);
        // Outside the envelope stays "does not agree", whatever the convergence.
        let far = vec![result("coarse", 0.050, 1.0), result("fine", 0.040, 1.0)];
        let specs = super::super::plan(0, &quick_case(), None);
        let case = Case {
            converged_within: Some(0.003),
            ..quick_case()
        };
        assert_eq!(
            case_score(&case, &specs, &far).verdict,
            Verdict::DoesNotAgree
        );
    }

    #[test]
    fn a_run_without_a_result_leaves_the_case_not_converged() {
        let case = quick_case();
        let specs = super::super::plan(0, &case, None);
        let outcomes = vec![result("coarse", 0.01, 1.0), Err("ccx failed".to_string())];
        let score = case_score(&case, &specs, &outcomes);
        assert_eq!(score.verdict, Verdict::NotConverged);
        assert!(score.reason.contains("run fine gave no result: ccx failed"));
    }
}
