//! `microslip sweep` without a subcommand: the problem from `--model` or the preset, and the
//! aliases `sweep beam|plate|lap` as the reference it must equal byte for byte.

use super::{failure, stdout_of};

/// The generic sweep and its alias print the same bytes (CSV and JSON).
fn same_as_alias(generic: &[&str], alias: &[&str]) {
    super::same_bytes(generic, alias, &["csv", "json"]);
}

#[test]
fn the_generic_sweep_equals_each_alias() {
    // Beams over F: the default parameter, the default problem and preset.
    same_as_alias(
        &["sweep", "--from", "0", "--to", "300", "--points", "7"],
        &[
            "sweep", "beam", "--from", "0", "--to", "300", "--points", "7",
        ],
    );
    same_as_alias(
        &[
            "sweep",
            "--model",
            "beam",
            "--preset",
            "paper-beams-soft",
            "--set",
            "mu=0.3",
            "--from",
            "10",
            "--to",
            "200",
            "--points",
            "5",
        ],
        &[
            "sweep",
            "beam",
            "--preset",
            "paper-beams-soft",
            "--set",
            "mu=0.3",
            "--from",
            "10",
            "--to",
            "200",
            "--points",
            "5",
        ],
    );
    // Plate over K_T: its default parameter (the plate has no load), logarithmic by default.
    same_as_alias(
        &[
            "sweep", "--model", "plate", "--from", "100", "--to", "1e6", "--points", "5",
        ],
        &[
            "sweep",
            "plate",
            "--kt-from",
            "100",
            "--kt-to",
            "1e6",
            "--points",
            "5",
        ],
    );
    // Lap over F, the problem from the preset alone.
    same_as_alias(
        &[
            "sweep",
            "--preset",
            "lap-aluminium",
            "--from",
            "0",
            "--to",
            "6000",
            "--points",
            "7",
        ],
        &[
            "sweep", "lap", "--from", "0", "--to", "6000", "--points", "7",
        ],
    );
    // Parameters other than the default: the parameter's column first.
    same_as_alias(
        &[
            "sweep",
            "--preset",
            "lap-aluminium",
            "--vary",
            "KT",
            "--from",
            "100",
            "--to",
            "1000",
            "--points",
            "5",
        ],
        &[
            "sweep", "lap", "--vary", "KT", "--from", "100", "--to", "1000", "--points", "5",
        ],
    );
    same_as_alias(
        &[
            "sweep", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "9", "--linear",
        ],
        &[
            "sweep", "beam", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "9",
            "--linear",
        ],
    );
    same_as_alias(
        &[
            "sweep", "--model", "plate", "--vary", "mu", "--from", "0.1", "--to", "0.5",
            "--points", "3",
        ],
        &[
            "sweep", "plate", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "3",
        ],
    );
}

#[test]
fn without_points_the_generic_sweep_has_eleven_rows_or_one() {
    let csv = stdout_of(&[
        "sweep", "--model", "plate", "--vary", "mu", "--from", "0.1", "--to", "0.5",
    ]);
    // A header and the rows 0.1, 0.14, ..., 0.5.
    assert_eq!(csv.lines().count(), 1 + 11, "{csv}");
    assert!(csv.lines().nth(1).unwrap().starts_with("0.1,"), "{csv}");
    assert!(csv.lines().last().unwrap().starts_with("0.5,"), "{csv}");
    let one = stdout_of(&["sweep", "--model", "lap", "--from", "100", "--to", "100"]);
    assert_eq!(one.lines().count(), 2, "{one}");
    assert!(one.lines().nth(1).unwrap().starts_with("100.0,"), "{one}");
}

#[test]
fn a_model_the_preset_contradicts_is_refused_naming_both() {
    let refused = failure(
        &[
            "sweep",
            "--model",
            "plate",
            "--preset",
            "paper-beams",
            "--from",
            "1",
            "--to",
            "2",
        ],
        2,
    );
    for named in ["--model plate", "--preset paper-beams", "beam preset"] {
        assert!(refused.contains(named), "{named}: {refused}");
    }
}

#[test]
fn an_unknown_parameter_is_refused_with_the_problem_s_keys() {
    let refused = failure(
        &[
            "sweep", "--model", "plate", "--vary", "h", "--from", "1", "--to", "2",
        ],
        2,
    );
    assert!(refused.contains("--vary"), "{refused}");
    assert!(refused.contains("'h'"), "{refused}");
    assert!(refused.contains("L tp E nu mu P KT"), "{refused}");
    // The lap preset's keys, when the problem comes from the preset.
    let lap = failure(
        &[
            "sweep",
            "--preset",
            "lap-aluminium",
            "--vary",
            "h",
            "--from",
            "1",
            "--to",
            "2",
        ],
        2,
    );
    assert!(lap.contains("L b t1 t2 E1 E2 P mu KT F"), "{lap}");
}

#[test]
fn the_generic_sweep_refuses_what_the_alias_refuses_in_the_same_words() {
    for (generic, alias) in [
        (
            &[
                "sweep", "--model", "lap", "--from", "0", "--to", "7000", "--points", "3",
            ][..],
            &[
                "sweep", "lap", "--from", "0", "--to", "7000", "--points", "3",
            ][..],
        ),
        (
            &["sweep", "--from", "10", "--to", "5", "--points", "1"][..],
            &[
                "sweep", "beam", "--from", "10", "--to", "5", "--points", "1",
            ][..],
        ),
    ] {
        assert_eq!(failure(generic, 2), failure(alias, 2), "{generic:?}");
    }
    // A subcommand and the generic flags are one or the other.
    failure(&["sweep", "--from", "1", "--to", "2", "beam"], 2);
}

/// A cylinder sweep's rows continue from each other inside the sweep (issue 47), and only there:
/// the same command twice prints the same bytes, and its row at Q = 295 N/mm is the point report
/// at that load (a plain, cold solve) to 1e-9.
#[test]
fn a_cylinder_sweep_is_deterministic_and_the_cold_solve_to_1e_9() {
    let sweep = [
        "sweep", "--model", "cylinder", "--from", "0", "--to", "590", "--points", "41",
    ];
    let table = stdout_of(&sweep);
    assert_eq!(stdout_of(&sweep), table);
    let mut lines = table.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let row: Vec<&str> = lines.nth(20).unwrap().split(',').collect();
    assert_eq!(row[column("Q_N_per_mm")], "295.0");
    let point: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "cylinder", "--set", "Q=295", "--format", "json",
    ]))
    .unwrap();
    for (name, json) in [("sa_mm", "sa_mm"), ("s0_mm", "s0_mm"), ("c_mm", "c_mm")] {
        let swept: f64 = row[column(name)].parse().unwrap();
        let cold = point["regularized"][json].as_f64().unwrap();
        assert!(
            (swept - cold).abs() <= 1e-9 * cold,
            "{name}: {swept} vs {cold}"
        );
    }
}
