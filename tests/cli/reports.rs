//! Reports, sweeps, presets, `check`, input errors and help texts.

use super::*;

#[test]
fn report_prints_the_paper_data_sets() {
    let text = stdout_of(&["report"]);
    assert!(text.contains("Twin cantilever beams") && text.contains("Squeezed plate"));
}

#[test]
fn the_tui_refuses_to_start_without_a_terminal() {
    // Under `cargo test` stdout is a pipe: one clear line, exit 2, nothing on stdout.
    let stderr = failure(&[], 2);
    assert!(stderr.contains("needs an interactive terminal"), "{stderr}");
    let stderr = failure(&["--preset", "nope"], 2);
    assert!(stderr.contains("no preset named 'nope'"), "{stderr}");
}

#[test]
fn beam_report_text_and_json_agree() {
    let text = stdout_of(&["beam", "--set", "F=120"]);
    assert!(
        text.contains("At F = 120 N") && text.contains("8.81755 (microslip end X)"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["beam", "--set", "F=120", "--format", "json"])).unwrap();
    assert_eq!(json["inputs"]["F_N"], 120.0);
    assert_eq!(json["inputs"]["KT_MPa_per_mm"], 600.0);
    assert_eq!(json["regularized"]["regime"], "microslip+macroslip");
    // Independent FE reference (tests/data): X(K_T=600, F=120) = 8.817548418 mm.
    assert!((json["regularized"]["X_mm"].as_f64().unwrap() - 8.817_548_418).abs() < 1e-6);
    assert_eq!(json["F_thre_N"], 80.0);
}

#[test]
fn plate_report_text_and_json() {
    let text = stdout_of(&["plate"]);
    assert!(
        text.contains("X_r = 9.83832")
            && text.contains("flat Timoshenko plate")
            && text.contains("contact pressure (continuum FE): 0.944 to 1 P beyond t_p"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["plate", "--format", "json", "--set", "KT=1"])).unwrap();
    assert_eq!(json["regularized"]["regime"], "microslip");
    assert_eq!(json["regularized"]["Xr_mm"], 10.0);
    assert_eq!(json["coulomb"]["regime"], "stick+macroslip");
    // Deprecated, kept: the flat model's flag.
    assert_eq!(json["contact_pressure"]["constant_pressure_holds"], true);
    assert_eq!(json["contact_pressure"]["end_layer_ratio_applies"], false);
    assert!(
        json["contact_pressure"]["model"]
            .as_str()
            .unwrap()
            .contains("P7-P9")
    );
}

#[test]
fn soft_preset_is_the_paper_data_set_with_kt_over_5() {
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "beam",
        "--preset",
        "paper-beams-soft",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["inputs"]["KT_MPa_per_mm"], 120.0);
    // Header of the FE reference: F_1(K_T=120) = 88.5946673 N.
    assert!((json["F_1_N"].as_f64().unwrap() - 88.594_667_3).abs() < 1e-6);
}

#[test]
fn beam_sweep_csv_has_the_contract_header_and_round_trip_numbers() {
    let csv = stdout_of(&[
        "sweep", "beam", "--from", "0", "--to", "300", "--points", "16",
    ]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some(
            "F_N,w_coulomb_mm,w_regularized_mm,X_mm,regime_coulomb,regime_regularized,beam_theory,\
             vs_continuum_within,vs_continuum_within_fraction,vs_continuum_nlgeom_within_fraction,\
             vs_continuum_linear_within_fraction"
        )
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 16);
    assert_eq!(
        rows[0][..7],
        [
            "0.0",
            "0.0",
            "0.0",
            "200.0",
            "unloaded",
            "unloaded",
            "euler-bernoulli"
        ]
    );
    // Row 5 is F = 100 N: FE reference w(L) = 3.829225956399e-2 mm, X = 17.30949125 mm.
    let row: Vec<f64> = rows[5][..4].iter().map(|v| v.parse().unwrap()).collect();
    assert!((row[0] - 100.0).abs() < 1e-12);
    assert!((row[2] / 3.829_225_956_399e-2 - 1.0).abs() < 2e-9);
    assert!((row[3] - 17.309_491_25).abs() < 1e-6);
    assert_eq!(rows[5][4..6], ["macroslip", "microslip+macroslip"]);
}

#[test]
fn plate_sweep_is_logarithmic_unless_linear() {
    let csv = stdout_of(&[
        "sweep",
        "plate",
        "--kt-from",
        "1",
        "--kt-to",
        "1e4",
        "--points",
        "5",
    ]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some(
            "KT_MPa_per_mm,u_coulomb_mm,u_regularized_mm,Xs_mm,Xr_mm,regime_coulomb,regime_regularized,\
             strip_theory"
        )
    );
    let kts: Vec<f64> = lines
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(kts.len(), 5);
    for (kt, expected) in kts.iter().zip([1.0, 10.0, 100.0, 1000.0, 10000.0]) {
        assert!((kt / expected - 1.0).abs() < 1e-12, "{kts:?}");
    }
    let csv = stdout_of(&[
        "sweep",
        "plate",
        "--kt-from",
        "1",
        "--kt-to",
        "9",
        "--points",
        "3",
        "--linear",
    ]);
    let kts: Vec<&str> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(kts, ["1.0", "5.0", "9.0"]);
}

#[test]
fn sweeps_in_json_parse_with_one_object_per_point() {
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "sweep", "beam", "--from", "10", "--to", "200", "--points", "7", "--format", "json",
    ]))
    .unwrap();
    let rows = json.as_array().unwrap();
    assert_eq!(rows.len(), 7);
    assert_eq!(rows[6]["F_N"], 200.0);
    assert!(rows[6].get("w_regularized_mm").is_some() && rows[6].get("X_mm").is_some());
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "sweep",
        "plate",
        "--kt-from",
        "1e6",
        "--kt-to",
        "1e7",
        "--points",
        "2",
        "--format",
        "json",
    ]))
    .unwrap();
    // FD reference: X_r(K_T=1e7) = 9.75350893955 mm.
    assert!((json[1]["Xr_mm"].as_f64().unwrap() - 9.753_508_939_55).abs() < 1e-8);
}

#[test]
fn presets_lists_bundled_and_user_presets() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("microslip").join("presets");
    std::fs::create_dir_all(&presets).unwrap();
    std::fs::write(
        presets.join("bench-a.toml"),
        "description = \"my bench\"\nmodel = \"beam\"\nKT = 300\n",
    )
    .unwrap();
    std::fs::write(presets.join("broken.toml"), "model = \"beam\"\nKT = -3\n").unwrap();
    let output = microslip()
        .env("XDG_CONFIG_HOME", dir.path())
        .arg("presets")
        .output()
        .unwrap();
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    for needle in [
        "paper-beams ",
        "paper-beams-soft",
        "paper-plate",
        "bench-a",
        "my bench",
        "broken",
        "INVALID",
    ] {
        assert!(text.contains(needle), "missing {needle} in\n{text}");
    }
    // A user preset is usable by name.
    let output = microslip()
        .env("XDG_CONFIG_HOME", dir.path())
        .args(["beam", "--preset", "bench-a", "--format", "json"])
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["inputs"]["KT_MPa_per_mm"], 300.0);
    assert_eq!(json["preset"], "bench-a");
}

#[test]
fn check_reports_every_problem_and_fails() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, "model = \"beam\"\nKt = 5\nL = -1\nmu = \"high\"\n").unwrap();
    let good = dir.path().join("good.toml");
    std::fs::write(&good, "model = \"plate\"\ndescription = \"ok\"\n").unwrap();
    let output = microslip()
        .arg("check")
        .arg(&good)
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(text.contains("good.toml: ok (plate preset: ok)"), "{text}");
    assert!(
        text.contains("bad.toml: line 2: unknown key 'Kt'"),
        "{text}"
    );
    assert!(text.contains("bad.toml: line 3: invalid L = -1"), "{text}");
    assert!(
        text.contains("bad.toml: line 4: invalid value '\"high\"' for mu"),
        "{text}"
    );
    let output = microslip().arg("check").arg(&good).output().unwrap();
    assert!(output.status.success());
}

#[test]
fn input_errors_are_one_line_name_the_field_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let malformed = dir.path().join("malformed.toml");
    std::fs::write(&malformed, "model = \"beam\"\nL = = 3\n").unwrap();
    let malformed = malformed.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["beam", "--set", "Kt=5"],
            "unknown key 'Kt' for the beam model (allowed: L b h E nu P mu KT F)",
        ),
        (
            &["beam", "--set", "KT=abc"],
            "invalid value 'abc' for KT: not a finite number",
        ),
        (
            &["beam", "--set", "KT=-5"],
            "invalid KT = -5: must be > 0 and finite (MPa/mm)",
        ),
        (
            &["plate", "--set", "nu=0.5"],
            "invalid nu = 0.5: must be in [0, 0.5)",
        ),
        (&["beam", "--set", "F=NaN"], "invalid value 'NaN' for F"),
        (&["beam", "--preset", "nope"], "no preset named 'nope'"),
        (
            &["beam", "--preset", "/nonexistent/x.toml"],
            "cannot read /nonexistent/x.toml",
        ),
        (&["beam", "--preset", malformed], "line 2, column 5"),
        (&["plate", "--preset", "paper-beams"], "is a beam preset"),
        (
            &[
                "sweep", "beam", "--from", "10", "--to", "5", "--points", "3",
            ],
            "--from = 10 is above --to = 5",
        ),
        (
            &["sweep", "beam", "--from", "0", "--to", "5", "--points", "1"],
            "invalid --points = 1",
        ),
        (
            &[
                "sweep",
                "beam",
                "--from",
                "0",
                "--to",
                "5",
                "--points",
                "1000000000",
            ],
            "invalid --points = 1000000000",
        ),
        (
            &[
                "sweep", "beam", "--from", "-1", "--to", "5", "--points", "3",
            ],
            "invalid --from = -1",
        ),
        (
            &[
                "sweep",
                "plate",
                "--kt-from",
                "0",
                "--kt-to",
                "5",
                "--points",
                "3",
            ],
            "invalid --kt-from = 0",
        ),
        (
            &[
                "sweep", "beam", "--from", "abc", "--to", "5", "--points", "3",
            ],
            "invalid value 'abc' for '--from",
        ),
        (&["sweep", "beam", "--from", "0", "--to", "5"], "--points"),
        (&["bogus"], "unrecognized subcommand 'bogus'"),
    ];
    for (args, expected) in cases {
        let stderr = failure(args, 2);
        assert!(stderr.starts_with("microslip: "), "{args:?}: {stderr}");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
    }
}

#[test]
fn help_texts_are_stable() {
    insta::assert_snapshot!("help", stdout_of(&["--help"]));
    insta::assert_snapshot!("help_sweep_beam", stdout_of(&["sweep", "beam", "--help"]));
    insta::assert_snapshot!("help_sweep_plate", stdout_of(&["sweep", "plate", "--help"]));
    insta::assert_snapshot!("help_beam", stdout_of(&["beam", "--help"]));
}

#[test]
fn verify_prints_a_table_and_fails_above_tolerance() {
    let text = stdout_of(&["verify", "--quick"]);
    for needle in [
        "beam w(L) (mm)",
        "beam X (mm)",
        "plate u(L) (mm)",
        "plate X_r (mm)",
        "lap Delta (mm)",
        "lap a, d (/L)",
        "ok",
    ] {
        assert!(text.contains(needle), "missing {needle} in\n{text}");
    }
    assert!(!text.contains("FAIL"));
    let output = microslip()
        .args(["verify", "--quick", "--tolerance", "1e-12"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8(output.stdout).unwrap().contains("FAIL"));
    let stderr = failure(&["verify", "--elements", "5"], 2);
    assert!(stderr.contains("invalid --elements = 5"), "{stderr}");
}

#[test]
fn fit_recovers_mu_and_kt_from_a_measured_curve() {
    // Measurements made by the tool itself with mu = 0.4, K_T = 200 MPa/mm (noise-free).
    let sweep = stdout_of(&[
        "sweep", "beam", "--from", "5", "--to", "300", "--points", "30", "--set", "mu=0.4",
        "--set", "KT=200",
    ]);
    let mut csv = String::from("F_N,ignored,w_mm\n");
    for line in sweep.lines().skip(1) {
        let fields: Vec<&str> = line.split(',').collect();
        csv.push_str(&format!("{},x,{}\n", fields[0], fields[2]));
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bench.csv");
    std::fs::write(&path, csv).unwrap();
    let path = path.to_str().unwrap();
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["fit", "beam", path, "--format", "json"])).unwrap();
    assert!(
        (json["mu"]["value"].as_f64().unwrap() / 0.4 - 1.0).abs() < 1e-6,
        "{json}"
    );
    assert!(
        (json["KT_MPa_per_mm"]["value"].as_f64().unwrap() / 200.0 - 1.0).abs() < 1e-6,
        "{json}"
    );
    assert_eq!(json["mu"]["status"], "identified");
    let text = stdout_of(&["fit", "beam", path, "--fix", "KT=200"]);
    assert!(text.contains("K_T = 200 MPa/mm: fixed"), "{text}");
    assert!(text.contains("mu  = 0.4"), "{text}");
}
