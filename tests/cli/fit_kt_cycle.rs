//! `verify`, `fit`, `kt` and `cycle`.

use super::*;

/// Issue 25 (5): the weights the errors assume. The curve (`sweep beam --from 0 --to 300
/// --points 61`, mu = 0.22, K_T = 300) with w alternately 1 % high and low: the default (relative)
/// weights see 1 % scatter, a sigma_mm column of 1 % of w is taken as known (chi^2/dof near 1),
/// and the column and `--weights` together are refused.
#[test]
fn fit_weights_say_what_the_errors_assume() {
    let sweep = stdout_of(&[
        "sweep", "beam", "--from", "0", "--to", "300", "--points", "61", "--set", "mu=0.22",
        "--set", "KT=300",
    ]);
    let (mut plain, mut with_sigma) = (
        String::from("F_N,w_mm\n"),
        String::from("F_N,w_mm,sigma_mm\n"),
    );
    for (i, line) in sweep.lines().skip(1).enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        let w: f64 = fields[2].parse().unwrap();
        let noisy = w * if i % 2 == 0 { 1.01 } else { 0.99 };
        plain.push_str(&format!("{},{noisy}\n", fields[0]));
        // w = 0 at F = 0 has no relative scatter; any small sigma says so.
        with_sigma.push_str(&format!("{},{noisy},{}\n", fields[0], (0.01 * w).max(1e-9)));
    }
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("plain.csv"), dir.path().join("sigma.csv"));
    std::fs::write(&a, plain).unwrap();
    std::fs::write(&b, with_sigma).unwrap();
    let (a, b) = (a.to_str().unwrap(), b.to_str().unwrap());
    let json = |args: &[&str]| -> serde_json::Value {
        let mut all = vec!["fit", "beam"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--format", "json"]);
        serde_json::from_str(&stdout_of(&all)).unwrap()
    };
    let relative = json(&[a]);
    assert_eq!(relative["weights"], "relative");
    let scatter = relative["scatter"].as_f64().unwrap();
    assert!((scatter - 0.01).abs() < 0.001, "{relative}");
    let rho = relative["mu_KT_correlation"].as_f64().unwrap();
    assert!(rho.abs() < 1.0, "{relative}");
    let absolute = json(&[a, "--weights", "absolute"]);
    assert_eq!(absolute["weights"], "absolute");
    let known = json(&[b]);
    assert_eq!(known["weights"], "sigma_mm");
    // sqrt(chi^2 / dof): residuals of about 1 % against sigmas of 1 %.
    let ratio = known["scatter"].as_f64().unwrap();
    assert!((ratio - 1.0).abs() < 0.1, "{known}");
    for fit in [&relative, &known] {
        let kt = &fit["KT_MPa_per_mm"];
        let (value, error) = (
            kt["value"].as_f64().unwrap(),
            kt["std_error"].as_f64().unwrap(),
        );
        assert!((value - 300.0).abs() < 3.0 * error, "{fit}");
    }
    let text = stdout_of(&["fit", "beam", b]);
    assert!(
        text.contains("errors assume the sigma_mm column, taken as known"),
        "{text}"
    );
    assert!(text.contains("correlation of mu and K_T = "), "{text}");
    let refused = failure(&["fit", "beam", b, "--weights", "relative"], 2);
    assert!(refused.contains("has a sigma_mm column"), "{refused}");
}

/// The capture of the default fit (tests/data/reports/fit-relative.*) is checked against the truth
/// its data were made with (mu = 0.4, K_T = 200, w rounded to 5 significant digits, so a relative
/// scatter of about 1e-5), not only against itself.
#[test]
fn the_default_fit_of_the_report_fixture_finds_its_truth() {
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "fit",
        "beam",
        "tests/data/reports/inputs/fit-beam.csv",
        "--format",
        "json",
    ]))
    .unwrap();
    for (key, truth) in [("mu", 0.4), ("KT_MPa_per_mm", 200.0)] {
        let (value, error) = (
            json[key]["value"].as_f64().unwrap(),
            json[key]["std_error"].as_f64().unwrap(),
        );
        assert!((value - truth).abs() < 3.0 * error, "{key}: {json}");
    }
    let scatter = json["scatter"].as_f64().unwrap();
    assert!(scatter > 1e-6 && scatter < 3e-5, "{json}");
}

#[test]
fn fit_errors_name_the_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "F_N,w_mm\n10,0.01\n20,oops\n").unwrap();
    let bad = bad.to_str().unwrap();
    assert!(
        failure(&["fit", "beam", bad], 2)
            .contains("bad.csv: line 3: 'oops' in column w_mm is not a finite number")
    );
    assert!(
        failure(&["fit", "beam", "/nonexistent.csv"], 2).contains("/nonexistent.csv: No such file")
    );
    assert!(failure(&["fit", "beam", bad, "--fix", "nu=1"], 2).contains("invalid --fix 'nu=1'"));
}

#[test]
fn kt_compares_physical_and_code_default_stiffnesses() {
    let text = stdout_of(&["kt", "--element-size", "1", "--kn", "1000"]);
    // Abaqus: mu P / (0.005 x 1 mm) = 0.3 / 0.005 = 60 MPa/mm.
    assert!(
        text.lines()
            .any(|l| l.starts_with("Abaqus/Standard") && l.contains(" 60 ")),
        "{text}"
    );
    // Eq. 4 at nu = 0.3: 0.7 pi / 3.4 x 1000 = 646.798 MPa/mm.
    assert!(
        text.lines()
            .any(|l| l.starts_with("eq. 4") && l.contains("646.798")),
        "{text}"
    );
    assert!(text.contains("could NOT be confirmed"));
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "kt",
        "--preset",
        "paper-plate",
        "--element-size",
        "0.1",
        "--format",
        "json",
    ]))
    .unwrap();
    let rows = json["candidates"].as_array().unwrap();
    let abaqus = rows
        .iter()
        .find(|r| r["source"] == "Abaqus/Standard")
        .unwrap();
    // mu P = 3 MPa: 3 / (0.005 x 0.1) = 6000 MPa/mm.
    assert!((abaqus["KT_MPa_per_mm"].as_f64().unwrap() - 6000.0).abs() < 1e-9);
    assert!(abaqus["u_end_mm"].as_f64().unwrap() > 0.0);
    assert!(failure(&["kt", "--element-size", "-1"], 2).contains("invalid --element-size = -1"));
    assert!(failure(&["kt", "--kn", "5", "--nu", "0.5"], 2).contains("invalid --nu = 0.5"));
}

/// Issue 36 item 14: each candidate against Coulomb too, the figure users computed by hand
/// (lap-aluminium: Abaqus +8.2 %, Ansys +17.0 % of Coulomb's Delta), with the element size named.
#[test]
fn kt_shows_each_candidate_against_coulomb_and_the_element_size() {
    let args = ["kt", "--preset", "lap-aluminium", "--format", "json"];
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&args)).unwrap();
    let rows = json["candidates"].as_array().unwrap();
    let vs_coulomb = |source: &str| {
        rows.iter().find(|r| r["source"] == source).unwrap()["vs_coulomb_percent"]
            .as_f64()
            .unwrap()
    };
    assert!((vs_coulomb("Abaqus/Standard") - 8.2).abs() < 0.05, "{json}");
    assert!((vs_coulomb("Ansys MAPDL") - 17.0).abs() < 0.05, "{json}");
    // Every answered row against the Coulomb Delta that `lap` reports on its own.
    let lap: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "lap",
        "--preset",
        "lap-aluminium",
        "--format",
        "json",
    ]))
    .unwrap();
    let coulomb = lap["coulomb"]["Delta_mm"].as_f64().unwrap();
    for row in rows.iter().filter(|r| r["Delta_mm"].is_f64()) {
        let expected = 100.0 * (row["Delta_mm"].as_f64().unwrap() / coulomb - 1.0);
        let got = row["vs_coulomb_percent"].as_f64().unwrap();
        assert!((got - expected).abs() < 1e-9, "{row}");
        // The old key stays beside the new one.
        assert!(row["vs_current_percent"].is_f64(), "{row}");
    }
    assert_eq!(json["element_size_mm"], 0.4);
    let text = stdout_of(&["kt", "--preset", "lap-aluminium", "--element-size", "0.2"]);
    assert!(text.contains("vs current vs Coulomb"), "{text}");
    let abaqus = text.lines().find(|l| l.starts_with("Abaqus")).unwrap();
    // Half the elements, twice mu P / (0.005 x 0.2 mm) = 3000 MPa/mm.
    assert!(abaqus.contains(" 3000 "), "{abaqus}");
    assert!(
        text.contains(
            "contact elements of 0.2 mm (a hundredth of the contact's length unless --element-size"
        ),
        "{text}"
    );
    // Unloaded: nothing to be off by, nothing said.
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["kt", "--set", "F=0", "--format", "json"])).unwrap();
    assert!(
        json["candidates"][0].get("vs_coulomb_percent").is_none(),
        "{json}"
    );
}

#[test]
fn cycle_reports_and_sweeps() {
    let text = stdout_of(&["cycle", "--amplitude", "150"]);
    // Coulomb: D = 4 mu P L^3 (F_a - F_thre) / (E h^2) = 4 x 0.3 x 8e6 x 70 / (210000 x 100) = 32 N mm.
    assert!(
        text.lines()
            .any(|l| l.contains("D per cycle, both beams (N mm)") && l.contains(" 32 ")),
        "{text}"
    );
    let csv = stdout_of(&[
        "sweep", "cycle", "--from", "0", "--to", "300", "--points", "7",
    ]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("Fa_N,D_coulomb_Nmm,D_regularized_Nmm,zeta_coulomb,zeta_regularized")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 7);
    assert_eq!(rows[0][1..], [0.0, 0.0, 0.0, 0.0]);
    // F_a = 50 N is below F_thre and F_1: no dissipation in either law.
    assert_eq!((rows[1][1], rows[1][2]), (0.0, 0.0));
    assert!(rows[6][2] > 0.0 && rows[6][2] < rows[6][1]);
    let loop_csv = stdout_of(&[
        "cycle",
        "--amplitude",
        "150",
        "--format",
        "csv",
        "--points",
        "3",
    ]);
    assert!(
        loop_csv.starts_with("branch,F_N,w_coulomb_mm,w_regularized_mm\nunloading,150.0,"),
        "{loop_csv}"
    );
    // Coulomb residual deflection at F = 0 on unloading: w_a - 2 w_v(75) = 0.0857143 - 2 x 0.0178571 = 0.05.
    assert!(loop_csv.contains("unloading,0.0,0.05,"), "{loop_csv}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "cycle",
        "--amplitude",
        "100",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["coulomb"]["onset_N"], 80.0);
    assert!(failure(&["cycle", "--amplitude", "-5"], 2).contains("invalid --amplitude = -5"));
}

#[test]
fn values_beyond_the_domain_are_refused_with_the_range_and_unit() {
    // The reproductions of "Never hang, never spin, never print a wrong number", items 1, 7 and 8.
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "sweep", "beam", "--from", "0", "--to", "1e308", "--points", "3",
            ],
            "invalid --to = 1e308: must be in [0, 1e12] N",
        ),
        (
            &[
                "sweep",
                "plate",
                "--kt-from",
                "1e-320",
                "--kt-to",
                "1e308",
                "--points",
                "4",
            ],
            "invalid --kt-from = 1e-320: must be in [1e-6, 1e12] MPa/mm",
        ),
        (
            &[
                "sweep",
                "plate",
                "--kt-from",
                "1e-300",
                "--kt-to",
                "1e300",
                "--points",
                "5",
            ],
            "invalid --kt-from = 1e-300: must be in [1e-6, 1e12] MPa/mm",
        ),
        (
            &["cycle", "--amplitude", "1e307", "--format", "csv"],
            "invalid --amplitude = 1e307: must be in [0, 1e12] N",
        ),
        (
            &["beam", "--set", "F=1e305"],
            "invalid F = 1e305: must be in [0, 1e12] N",
        ),
        (
            &["beam", "--set", "F=1e307"],
            "invalid F = 1e307: must be in [0, 1e12] N",
        ),
        (
            &[
                "sweep", "cycle", "--from", "1e17", "--to", "1e17", "--points", "2",
            ],
            "invalid --from = 1e17: must be in [0, 1e12] N",
        ),
        (
            &["plate", "--set", "L=1e16"],
            "invalid L = 1e16: must be in [1e-6, 1e6] mm",
        ),
        (
            &["beam", "--set", "L=1e308"],
            "invalid L = 1e308: must be in [1e-6, 1e6] mm",
        ),
        (
            &["beam", "--set", "E=2.1e11"],
            "invalid E = 2.1e11: must be in [1e-4, 1e7] MPa",
        ),
        (
            &["plate", "--set", "mu=11"],
            "invalid mu = 11: must be in [1e-6, 10] (dimensionless)",
        ),
        (
            &["kt", "--element-size", "1e-9"],
            "invalid --element-size = 1e-9: must be in [1e-8, 1e6] mm",
        ),
        (
            &["kt", "--kn", "1e13"],
            "invalid --kn = 1e13: must be in [1e-6, 1e12] MPa/mm",
        ),
    ];
    for (args, expected) in cases {
        let stderr = failure(args, 2);
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
    }
}
