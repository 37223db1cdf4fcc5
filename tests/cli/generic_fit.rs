//! `microslip fit DATA.csv` without a subcommand: the problem from `--model` or the preset, and
//! the aliases `fit beam|lap` as the reference it must equal byte for byte.

use super::{failure, stdout_of};

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
        format!(
            "microslip: fit: preset 'paper-plate' is a plate preset, which has no load to fit a \
             curve against; fit takes a {} preset",
            super::loaded_problems(" or ")
        )
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

/// The bundled cylinder curve (tests/data/reports/inputs/fit-cylinder.csv: the steel pad's s(a)
/// at mu = 0.5, K_T = 30000 MPa/mm with 1 % scatter) fitted by `fit cylinder`: both back within
/// three of their reported standard errors, identified, and every load in N/mm (a line load).
#[test]
fn fit_cylinder_finds_the_truth_of_its_bundled_curve_in_n_per_mm() {
    let curve = "tests/data/reports/inputs/fit-cylinder.csv";
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["fit", "cylinder", curve, "--format", "json"])).unwrap();
    for (key, truth) in [("mu", 0.5), ("KT_MPa_per_mm", 30000.0)] {
        let (value, error) = (
            json[key]["value"].as_f64().unwrap(),
            json[key]["std_error"].as_f64().unwrap(),
        );
        assert!((value - truth).abs() < 3.0 * error, "{key}: {json}");
        assert_eq!(json[key]["status"], "identified", "{json}");
    }
    // Q_gross = mu P at the fitted mu; Q_1 = 0 (the edges slide at every load).
    let mu = json["mu"]["value"].as_f64().unwrap();
    let gross = json["Q_gross_N_per_mm"].as_f64().unwrap();
    assert!((gross / (1000.0 * mu) - 1.0).abs() < 1e-12, "{json}");
    assert_eq!(json["Q_1_N_per_mm"], 0.0, "{json}");
    assert_eq!(json["points_above_Q_1"], 18, "{json}");
    assert!(json.get("F_1_N").is_none(), "{json}");
    let text = stdout_of(&["fit", "cylinder", curve]);
    assert!(
        text.contains("Hertzian cylinder of preset cylinder-steel-pad")
            && text.contains("P = 1000 N/mm")
            && text.contains("at the fitted values: Q_gross = ")
            && text.contains(" N/mm, Q_1 = 0 N/mm: the interface slides somewhere at every load"),
        "{text}"
    );
    // The problem named before the data is --model, and the preset's problem.
    for generic in [
        &["fit", curve, "--model", "cylinder"][..],
        &["fit", curve, "--preset", "cylinder-steel-pad"][..],
    ] {
        super::same_bytes(generic, &["fit", "cylinder", curve], &["text", "json"]);
    }
}

/// A file headed for another problem is refused naming the columns the cylinder needs; a load
/// outside Q's domain names Q's column and unit; an unknown problem and one --model contradicts
/// are refused by name.
#[test]
fn fit_cylinder_refuses_another_problem_s_columns_naming_its_own() {
    let beam = "tests/data/reports/inputs/fit-beam.csv";
    let stderr = failure(&["fit", "cylinder", beam], 2);
    assert!(
        stderr.contains(
            "fit-beam.csv: line 1: missing column 'sa_mm' in the header (found: F_N, w_mm); \
             Q_N_per_mm and sa_mm are required"
        ),
        "{stderr}"
    );
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    };
    let forces = write("forces.csv", "F_N,sa_mm\n100,0.001\n200,0.002\n300,0.003\n");
    let stderr = failure(&["fit", "cylinder", &forces], 2);
    assert!(
        stderr.contains("line 1: missing column 'Q_N_per_mm' in the header (found: F_N, sa_mm)"),
        "{stderr}"
    );
    let negative = write("negative.csv", "Q_N_per_mm,sa_mm\n-1,0.001\n");
    let stderr = failure(&["fit", "cylinder", &negative], 2);
    assert!(
        stderr.contains("line 2: Q_N_per_mm = -1 is negative; loads must be in [0, 1e9] N/mm"),
        "{stderr}"
    );
    let stderr = failure(&["fit", "cylindre", beam], 2);
    assert!(stderr.contains("'cylindre' is not a problem"), "{stderr}");
    let stderr = failure(&["fit", "cylinder", beam, "--model", "lap"], 2);
    assert!(
        stderr.contains("fit cylinder and --model lap disagree"),
        "{stderr}"
    );
}

/// s(a) falling as Q grows, which no cylinder gives: refused as not the cylinder's curve.
#[test]
fn fit_cylinder_refuses_a_curve_that_is_not_a_cylinder_s() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("falling.csv");
    let rows: String = (1..=10)
        .map(|i| format!("{},{}\n", 40 * i, 0.01 / f64::from(i)))
        .collect();
    std::fs::write(&path, format!("Q_N_per_mm,sa_mm\n{rows}")).unwrap();
    let stderr = failure(&["fit", "cylinder", path.to_str().unwrap()], 2);
    assert!(
        stderr
            .starts_with("microslip: the curve is not a Hertzian cylinder's: the best fit (mu = ")
            && stderr.contains("of the variation of sa_mm against Q_N_per_mm"),
        "{stderr}"
    );
}
