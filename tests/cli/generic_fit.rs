//! `microslip fit DATA.csv` without a subcommand: the problem from `--model` or the preset, and
//! the aliases `fit beam|lap` as the reference it must equal byte for byte.

use super::failure;

/// A lap joint's measured Delta vs F: the bundled joint's regularized curve (`sweep lap`), 1 %
/// off up and down, for a fit with a scatter.
const LAP_CURVE: &str = "F_N,Delta_mm\n500,0.0023216\n1000,0.0045512\n1500,0.0069648\n\
                         2000,0.0091025\n2500,0.0116589\n";

#[test]
fn the_generic_fit_equals_each_alias() {
    let dir = tempfile::tempdir().unwrap();
    let lap = dir.path().join("lap.csv");
    std::fs::write(&lap, LAP_CURVE).unwrap();
    let lap = lap.to_str().unwrap();
    let beam = "tests/data/reports/inputs/fit-beam.csv";
    let pairs: [(&[&str], &[&str]); 4] = [
        // The default problem and preset.
        (&["fit", beam], &["fit", "beam", beam]),
        (&["fit", beam, "--model", "beam"], &["fit", "beam", beam]),
        // The problem from the preset, and from --model with its default preset.
        (
            &["fit", lap, "--preset", "lap-aluminium"],
            &["fit", "lap", lap],
        ),
        (
            &["fit", "--model", "lap", lap, "--fix", "mu=0.3"],
            &["fit", "lap", lap, "--fix", "mu=0.3"],
        ),
    ];
    for (generic, alias) in pairs {
        super::same_bytes(generic, alias, &["text", "json"]);
    }
}

#[test]
fn the_generic_fit_refuses_a_problem_without_a_load_and_a_model_its_preset_contradicts() {
    let beam = "tests/data/reports/inputs/fit-beam.csv";
    let stderr = failure(&["fit", beam, "--preset", "paper-plate"], 2);
    assert_eq!(
        stderr.trim(),
        "microslip: fit: preset 'paper-plate' is a plate preset, which has no load to fit a \
         curve against; fit takes a beam or lap or cylinder preset"
    );
    let stderr = failure(
        &["fit", beam, "--model", "lap", "--preset", "paper-beams"],
        2,
    );
    assert!(
        stderr.contains("--model lap and --preset paper-beams disagree"),
        "{stderr}"
    );
    // The alias keeps its own refusal.
    let stderr = failure(&["fit", "beam", beam, "--preset", "lap-aluminium"], 2);
    assert!(
        stderr.contains("`microslip fit beam` needs a beam preset"),
        "{stderr}"
    );
}
