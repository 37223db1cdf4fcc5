//! The real binary, as scripts use it: every subcommand, output contracts, every error case.

use assert_cmd::Command;

fn microslip() -> Command {
    let mut cmd = Command::cargo_bin("microslip").expect("binary built by cargo");
    // Keep user presets of the machine running the tests out of the way.
    cmd.env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
        .env_remove("HOME");
    cmd
}

fn stdout_of(args: &[&str]) -> String {
    let output = microslip().args(args).output().unwrap();
    assert!(
        output.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(output.stderr.is_empty());
    String::from_utf8(output.stdout).unwrap()
}

/// Runs a command that must fail: one line on stderr, nothing on stdout, exit code `code`.
fn failure(args: &[&str], code: i32) -> String {
    let output = microslip().args(args).output().unwrap();
    assert_eq!(output.status.code(), Some(code), "{args:?}");
    assert!(output.stdout.is_empty(), "{args:?} wrote to stdout");
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    stderr
}

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
             vs_continuum_within,vs_continuum_within_fraction"
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

/// Issue 25 (5): the weights the errors assume. The issue's curve (`sweep beam --from 0 --to 300
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
        text.contains("contact elements of 0.2 mm (L/100 unless --element-size"),
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

/// Fails when an output shows NaN, an infinity or "n/a" (as a word of text, a CSV field or a JSON
/// null, which is how serde_json writes a non-finite number).
fn assert_finite_output(args: &[&str], output: &str) {
    assert!(!output.contains("n/a"), "{args:?}: n/a in\n{output}");
    for token in output.split(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '.' | '_'))) {
        let word = token.to_ascii_lowercase();
        assert!(
            !matches!(word.as_str(), "nan" | "inf" | "infinity" | "null"),
            "{args:?}: {token} in\n{output}"
        );
    }
}

/// The rows of a CSV table, parsed as numbers where they are numbers.
fn csv_numbers(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').filter_map(|v| v.parse().ok()).collect())
        .collect()
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

#[test]
fn the_largest_accepted_values_print_every_row_with_finite_numbers() {
    let sweep = |args: &[&str], rows: usize| {
        let out = stdout_of(args);
        assert_finite_output(args, &out);
        let numbers = csv_numbers(&out);
        assert_eq!(numbers.len(), rows, "{args:?}:\n{out}");
        numbers
    };
    let beam = sweep(
        &[
            "sweep", "beam", "--from", "0", "--to", "1e12", "--points", "3",
        ],
        3,
    );
    // Coulomb w(L) = (F - mu P b h) L^3 / (2 E b h^3) at 1e12 N, hand-written.
    let w = (1e12 - 0.3 * 20.0 * 10.0) * 200.0_f64.powi(3) / (2.0 * 210_000.0 * 20.0 * 1e3);
    assert!((beam[2][1] / w - 1.0).abs() < 1e-13, "{beam:?}");
    let plate = sweep(
        &[
            "sweep",
            "plate",
            "--kt-from",
            "1e-6",
            "--kt-to",
            "1e12",
            "--points",
            "5",
        ],
        5,
    );
    assert_eq!((plate[0][0], plate[4][0]), (1e-6, 1e12));
    sweep(
        &[
            "cycle",
            "--amplitude",
            "1e12",
            "--format",
            "csv",
            "--points",
            "3",
        ],
        6,
    );
    for args in [
        &["beam", "--set", "F=1e12"][..],
        &["beam", "--set", "F=1e12", "--format", "json"],
        &["cycle", "--amplitude", "1e12"],
        &["cycle", "--amplitude", "1e12", "--format", "json"],
    ] {
        assert_finite_output(args, &stdout_of(args));
    }
}

#[test]
fn dissipation_at_the_largest_amplitude_matches_the_closed_form() {
    // Issue item 8: (C4) written out, D = 4 mu P L^3 (F_a - F_thre) / (E h^2), and the regularized D
    // short of it by 3 q / (k L)^2 (q = F_thre / (F_a - F_thre), k = 2 sqrt(K_T / (E h))).
    let args = [
        "sweep", "cycle", "--from", "1e10", "--to", "1e12", "--points", "2",
    ];
    let out = stdout_of(&args);
    assert_finite_output(&args, &out);
    for row in csv_numbers(&out) {
        let fa = row[0];
        let exact = 4.0 * 0.3 * 200.0_f64.powi(3) * (fa - 80.0) / (210_000.0 * 100.0);
        assert!((row[1] / exact - 1.0).abs() < 1e-13, "{row:?} vs {exact}");
        let kl = 2.0 * (600.0_f64 / 2.1e6).sqrt() * 200.0;
        let predicted = 3.0 * (80.0 / (fa - 80.0)) / (kl * kl);
        let shortfall = 1.0 - row[2] / row[1];
        assert!(
            (shortfall - predicted).abs() <= 1e-3 * predicted + 1e-15,
            "{row:?}: {shortfall} vs {predicted}"
        );
    }
}

#[test]
fn a_long_plate_keeps_its_coulomb_slip_zone() {
    // Issue item 8: u(L) of the Coulomb plate is kappa l^2 / 2 = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E)
    // whatever L once l < L; at the largest accepted L it reported stick and 0.
    let expected = 1.3 * 0.09 * 0.2 * 10.0 / (2.0 * 0.7 * 0.3 * 70_000.0);
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["plate", "--set", "L=1e6", "--format", "json"])).unwrap();
    assert_eq!(json["coulomb"]["regime"], "stick+macroslip");
    let u = json["coulomb"]["u_end_mm"].as_f64().unwrap();
    assert!((u / expected - 1.0).abs() < 1e-12, "{u}");
    assert_eq!(json["regularized"]["regime"], "microslip+macroslip");
}

#[test]
fn every_report_at_the_corners_of_the_domain_is_finite() {
    let beams: &[&[&str]] = &[
        &[
            "L=1e6", "b=1e-6", "h=1e-6", "E=1e-4", "P=1e4", "mu=10", "KT=1e12", "F=1e12",
        ],
        &[
            "L=1e-6", "b=1e6", "h=1e6", "E=1e7", "P=1e-6", "mu=1e-6", "KT=1e-6", "F=1e12",
        ],
        &[
            "L=1e-6", "b=1e-6", "h=1e-6", "E=1e-4", "P=1e-6", "mu=1e-6", "KT=1e-6", "F=0",
        ],
        &[
            "L=1e6", "b=1e6", "h=1e6", "E=1e7", "P=1e4", "mu=10", "KT=1e12", "F=1e12",
        ],
    ];
    for set in beams {
        let with_set = |command: &[&str]| {
            let mut args: Vec<&str> = command.to_vec();
            for assignment in *set {
                args.extend(["--set", assignment]);
            }
            args.iter().map(|s| s.to_string()).collect::<Vec<_>>()
        };
        for command in [
            &["beam"][..],
            &["beam", "--format", "json"],
            &["cycle", "--amplitude", "1e12"],
            &["cycle", "--amplitude", "1e12", "--format", "json"],
            &[
                "cycle",
                "--amplitude",
                "1e12",
                "--format",
                "csv",
                "--points",
                "5",
            ],
            &["kt"],
            &["kt", "--kn", "1e12", "--element-size", "1e-8"],
            &[
                "sweep", "beam", "--from", "0", "--to", "1e12", "--points", "5",
            ],
            &[
                "sweep", "cycle", "--from", "0", "--to", "1e12", "--points", "5",
            ],
        ] {
            let args = with_set(command);
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let out = stdout_of(&args);
            // The K_T table may hold JSON nulls for codes without a default; only the numbers
            // there are checked.
            if args[0] == "kt" && args.contains(&"json") {
                continue;
            }
            assert_finite_output(&args, &out);
        }
    }
    let plates: &[&[&str]] = &[
        &[
            "L=1e6",
            "tp=1e-6",
            "E=1e-4",
            "nu=0.4999999",
            "mu=10",
            "P=1e4",
            "KT=1e12",
        ],
        &[
            "L=1e-6", "tp=1e6", "E=1e7", "nu=0", "mu=1e-6", "P=1e-6", "KT=1e-6",
        ],
        &[
            "L=1e-6", "tp=1e6", "E=1e-4", "nu=0.3", "mu=1e-6", "P=1e-6", "KT=1e12",
        ],
    ];
    for set in plates {
        for command in [
            &["plate"][..],
            &["plate", "--format", "json"],
            &["kt", "--preset", "paper-plate"],
            &[
                "sweep",
                "plate",
                "--kt-from",
                "1e-6",
                "--kt-to",
                "1e12",
                "--points",
                "7",
            ],
        ] {
            let mut args: Vec<&str> = command.to_vec();
            for assignment in *set {
                args.extend(["--set", assignment]);
            }
            assert_finite_output(&args, &stdout_of(&args));
        }
    }
}

#[test]
fn kt_candidates_outside_the_domain_show_their_value_and_why() {
    // K_N = 1e-6 MPa/mm gives K_T of 5e-7 to 7e-7 from the measured ratios and eq. 4, below the
    // accepted 1e-6: shown, marked, not evaluated.
    let text = stdout_of(&["kt", "--kn", "1e-6"]);
    let low = text.lines().find(|l| l.starts_with("K_N x 0.5")).unwrap();
    assert!(
        low.contains("5e-7") && low.contains("K_T out of range"),
        "{low}"
    );
    assert!(
        text.contains("K_T out of range: not evaluated, K_T must be in [1e-6, 1e12] MPa/mm."),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["kt", "--kn", "1e-6", "--format", "json"])).unwrap();
    assert_eq!(
        json["candidates"][1]["not_evaluated"],
        "invalid KT = 5e-7: must be in [1e-6, 1e12] MPa/mm"
    );
}

#[cfg(target_os = "linux")]
#[test]
fn endless_inputs_stop_at_the_cap_with_bounded_memory() {
    // A preset is a regular file: `check` and `--preset` refuse a device without reading it.
    let output = microslip().args(["check", "/dev/zero"]).output().unwrap();
    assert_eq!(output.status.code(), Some(1));
    let text = String::from_utf8(output.stdout).unwrap();
    assert_eq!(
        text,
        "/dev/zero: cannot read /dev/zero: a character device, not a regular file\n"
    );
    let stderr = failure(&["beam", "--preset", "/dev/zero"], 2);
    assert!(
        stderr.contains("cannot read /dev/zero: a character device, not a regular file"),
        "{stderr}"
    );
    // `fit` reads at most 256 MiB, here under a 1 GiB address-space limit: unbounded reading
    // would abort on a failed allocation instead of exiting 2 with the limit.
    let output = std::process::Command::new("sh")
        .args([
            "-c",
            "ulimit -v 1048576 && exec \"$0\" \"$@\"",
            env!("CARGO_BIN_EXE_microslip"),
            "fit",
            "beam",
            "/dev/zero",
        ])
        .env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
        .output()
        .unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert_eq!(
        stderr,
        "microslip: /dev/zero: file is larger than the 256 MiB limit for a measurement file\n"
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_fed_forever_is_refused_at_the_cap() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("endless.csv");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    // The writer must be there before microslip opens the FIFO (a FIFO with no writer reads as
    // empty): a reader held by the test lets the writer open at once, and the writer says when
    // it has. Dropping that reader once microslip is done makes the writer's next write fail.
    use std::os::unix::fs::OpenOptionsExt;
    let held = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(&fifo)
        .unwrap();
    let writer_path = fifo.clone();
    let (opened, is_open) = std::sync::mpsc::channel();
    // Writes until the readers go away (then the write fails and the thread ends).
    let writer = std::thread::spawn(move || {
        use std::io::Write;
        let mut pipe = std::fs::OpenOptions::new()
            .write(true)
            .open(writer_path)
            .unwrap();
        opened.send(()).unwrap();
        let line = b"# a comment that never ends\n".repeat(1000);
        while pipe.write_all(&line).is_ok() {}
    });
    is_open.recv().unwrap();
    let stderr = failure(&["fit", "beam", fifo.to_str().unwrap()], 2);
    assert!(
        stderr.ends_with(": file is larger than the 256 MiB limit for a measurement file\n"),
        "{stderr}"
    );
    drop(held);
    writer.join().unwrap();
}

#[test]
fn oversized_files_are_refused_by_size_without_reading_them() {
    let dir = tempfile::tempdir().unwrap();
    // Sparse files: the size is enough to refuse them.
    let preset = dir.path().join("big.toml");
    std::fs::File::create(&preset)
        .unwrap()
        .set_len(64 * 1024 + 1)
        .unwrap();
    let data = dir.path().join("big.csv");
    std::fs::File::create(&data)
        .unwrap()
        .set_len((256 << 20) + 1)
        .unwrap();
    let stderr = failure(&["beam", "--preset", preset.to_str().unwrap()], 2);
    assert!(stderr.contains("larger than the 64 KiB limit"), "{stderr}");
    let stderr = failure(&["fit", "beam", data.to_str().unwrap()], 2);
    assert!(
        stderr.ends_with("big.csv: file is larger than the 256 MiB limit for a measurement file\n"),
        "{stderr}"
    );
}

/// True when `text` holds a control character other than a line feed, or a bidirectional control.
fn has_raw_control(text: &str) -> bool {
    text.chars()
        .any(|c| (c.is_control() && c != '\n') || ('\u{202a}'..='\u{202e}').contains(&c))
}

#[test]
fn control_characters_from_users_never_reach_the_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("microslip").join("presets");
    std::fs::create_dir_all(&presets).unwrap();
    let evil = "model = \"beam\"\ndescription = \"bell \\u0007 clear \\u001b[2J\\nfake \\u009b31m \\u202e\"\n";
    std::fs::write(presets.join("evil\u{1b}[31m.toml"), evil).unwrap();
    let run = |args: &[&str]| {
        microslip()
            .env("XDG_CONFIG_HOME", dir.path())
            .args(args)
            .output()
            .unwrap()
    };
    // The listing.
    let output = run(&["presets"]);
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(!has_raw_control(&text), "{text:?}");
    assert!(
        text.contains("evil\\x1b[31m")
            && text.contains("bell \\x07 clear \\x1b[2J\\nfake \\u{9b}31m \\u{202e}"),
        "{text}"
    );
    // check: the description and the path.
    let file = presets.join("evil\u{1b}[31m.toml");
    let output = microslip().arg("check").arg(&file).output().unwrap();
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(!has_raw_control(&text), "{text:?}");
    assert!(
        text.contains("evil\\x1b[31m.toml: ok (beam preset: bell \\x07"),
        "{text}"
    );
    // check: a key quoted in a problem.
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, "model = \"beam\"\n\"K\\u001b]0;owned\\u0007\" = 5\n").unwrap();
    let output = microslip().arg("check").arg(&bad).output().unwrap();
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(!has_raw_control(&text), "{text:?}");
    assert!(text.contains("unknown key 'K\\x1b]0;owned\\x07'"), "{text}");
    // Reports name the preset; JSON escapes what a terminal would obey.
    let name = "evil\u{1b}[31m";
    let output = run(&["beam", "--preset", name]);
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        output.status.success() && !has_raw_control(&text),
        "{text:?}"
    );
    assert!(text.contains("preset evil\\x1b[31m"), "{text}");
    let output = run(&["beam", "--preset", name, "--format", "json"]);
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(!has_raw_control(&text), "{text:?}");
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(json["preset"], name);
    // Errors echo names, paths, values and CSV headers: one sanitized line.
    for (args, expected) in [
        (
            vec!["beam", "--preset", "nope\u{1b}[2J"],
            "no preset named 'nope\\x1b[2J'",
        ),
        (
            vec!["beam", "--set", "KT=\u{7}\u{1b}[5m"],
            "invalid value '\\x07\\x1b[5m' for KT",
        ),
        (vec!["bogus\u{7}\u{9b}x"], "unrecognized subcommand 'bogus"),
        (
            vec!["beam", "--preset", "/nonexistent/\u{9b}x.toml"],
            "cannot read /nonexistent/\\u{9b}x.toml",
        ),
    ] {
        let stderr = failure(&args, 2);
        assert!(!has_raw_control(&stderr), "{stderr:?}");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
    }
    let csv = dir.path().join("header.csv");
    std::fs::write(&csv, "F_N,\u{1b}[31mw\n1,2\n").unwrap();
    let stderr = failure(&["fit", "beam", csv.to_str().unwrap()], 2);
    assert!(!has_raw_control(&stderr), "{stderr:?}");
    assert!(stderr.contains("(found: F_N, \\x1b[31mw)"), "{stderr}");
}

#[cfg(target_os = "linux")]
#[test]
fn help_and_version_on_a_full_disk_fail_with_a_message() {
    let to_full_disk = |arg: &str| {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        std::process::Command::new(env!("CARGO_BIN_EXE_microslip"))
            .arg(arg)
            .env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
            .stdout(full)
            .output()
            .unwrap()
    };
    for flag in ["--help", "--version", "-h", "-V"] {
        let output = to_full_disk(flag);
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(output.status.code(), Some(1), "{flag}: {stderr}");
        assert!(
            stderr.starts_with("microslip: cannot write output: No space left on device"),
            "{flag}: {stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    // Other output to a full disk fails the same way.
    let output = to_full_disk("report");
    assert_eq!(output.status.code(), Some(1));
    assert!(
        String::from_utf8(output.stderr)
            .unwrap()
            .contains("No space left on device")
    );
}

#[test]
fn huge_and_tiny_values_are_echoed_as_typed() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("neg.csv");
    std::fs::write(&data, "F_N,w_mm\n-1e308,0.1\n").unwrap();
    let unordered = dir.path().join("unordered.csv");
    // (Forces above 1e12 N are now outside the domain: the order check is shown within it.)
    std::fs::write(&unordered, "F_N,w_mm\n1e12,0.1\n2.5e-7,0.2\n").unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["beam", "--set", "L=-1e308"],
            "invalid L = -1e308: must be > 0 and finite (mm)",
        ),
        (
            &["cycle", "--amplitude", "-1e308"],
            "invalid --amplitude = -1e308: must be >= 0 and finite (N)",
        ),
        (
            // (`=`: clap takes `-1e-300` alone for a flag; a negative exponent is not a number to it.)
            &["kt", "--element-size=-1e-300"],
            "invalid --element-size = -1e-300",
        ),
        (
            &[
                "sweep", "beam", "--from", "1e12", "--to", "2.5e-7", "--points", "3",
            ],
            // (1e308 is now refused first, as outside the force domain, echoed as "1e308" too.)
            "--from = 1e12 is above --to = 2.5e-7",
        ),
        (
            &[
                "sweep", "beam", "--from", "-1e308", "--to", "5", "--points", "3",
            ],
            "invalid --from = -1e308",
        ),
        (
            &["fit", "beam", data.to_str().unwrap()],
            "line 2: F_N = -1e308 is negative",
        ),
        (
            &["fit", "beam", unordered.to_str().unwrap()],
            "line 3: F_N = 2.5e-7 is not above the previous 1e12",
        ),
    ];
    for (args, expected) in cases {
        let stderr = failure(args, 2);
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        assert!(stderr.len() < 200, "{args:?}: {stderr}");
    }
}

#[test]
fn check_says_a_numeric_description_must_be_a_string() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("numeric.toml");
    std::fs::write(&file, "model = \"beam\"\ndescription = 42\n").unwrap();
    let output = microslip().arg("check").arg(&file).output().unwrap();
    assert_eq!(output.status.code(), Some(1));
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        text.contains(
            "numeric.toml: line 2: invalid value '42' for description: must be a string, in double quotes"
        ),
        "{text}"
    );
    assert!(!text.contains("finite number"), "{text}");
}

#[test]
fn a_preset_of_the_other_model_names_the_command_that_was_run() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("d.csv");
    std::fs::write(&data, "F_N,w_mm\n1,0.001\n2,0.002\n3,0.003\n").unwrap();
    let data = data.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["beam", "--preset", "paper-plate"], "`microslip beam`"),
        (&["plate", "--preset", "paper-beams"], "`microslip plate`"),
        (
            &["fit", "beam", data, "--preset", "paper-plate"],
            "`microslip fit beam`",
        ),
        (
            &["cycle", "--amplitude", "100", "--preset", "paper-plate"],
            "`microslip cycle`",
        ),
        (
            &[
                "sweep",
                "beam",
                "--from",
                "0",
                "--to",
                "1",
                "--points",
                "2",
                "--preset",
                "paper-plate",
            ],
            "`microslip sweep beam`",
        ),
        (
            &[
                "sweep",
                "cycle",
                "--from",
                "0",
                "--to",
                "1",
                "--points",
                "2",
                "--preset",
                "paper-plate",
            ],
            "`microslip sweep cycle`",
        ),
        (
            &[
                "sweep",
                "plate",
                "--kt-from",
                "1",
                "--kt-to",
                "2",
                "--points",
                "2",
                "--preset",
                "paper-beams",
            ],
            "`microslip sweep plate`",
        ),
    ];
    for (args, command) in cases {
        let stderr = failure(args, 2);
        let wanted = if command.contains("plate") {
            "plate"
        } else if command.contains("cycle") {
            "beam or lap"
        } else {
            "beam"
        };
        let expected = format!("{command} needs a {wanted} preset");
        assert!(stderr.contains(&expected), "{args:?}: {stderr}");
    }
}

#[test]
fn bundled_names_win_and_a_user_file_of_that_name_gets_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("microslip").join("presets");
    std::fs::create_dir_all(&presets).unwrap();
    let file = presets.join("paper-beams.toml");
    std::fs::write(&file, "model = \"beam\"\ndescription = \"mine\"\nKT = 5\n").unwrap();
    let run = |args: &[&str]| {
        microslip()
            .env("XDG_CONFIG_HOME", dir.path())
            .args(args)
            .output()
            .unwrap()
    };
    // --preset NAME: the bundled one.
    let output = run(&["beam", "--preset", "paper-beams", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["inputs"]["KT_MPa_per_mm"], 600.0);
    // The listing warns.
    let text = String::from_utf8(run(&["presets"]).stdout).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("paper-beams ") && l.contains(" user "))
        .unwrap_or_else(|| panic!("no user row in\n{text}"));
    assert!(
        line.contains("WARNING: named like the bundled preset 'paper-beams', which wins"),
        "{line}"
    );
    // check: the file is valid (exit 0) but named like a bundled preset.
    let output = microslip().arg("check").arg(&file).output().unwrap();
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        text.contains("paper-beams.toml: ok (beam preset: mine)"),
        "{text}"
    );
    assert!(
        text.contains(
            "paper-beams.toml: warning: named like the bundled preset 'paper-beams', which wins"
        ),
        "{text}"
    );
    // By path it still loads.
    let output = run(&[
        "beam",
        "--preset",
        file.to_str().unwrap(),
        "--format",
        "json",
    ]);
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["inputs"]["KT_MPa_per_mm"], 5.0);
}

fn calculix_fixture(name: &str) -> String {
    format!("{}/tests/data/calculix/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn deck_writes_a_calculix_deck_with_a_readable_header() {
    let deck = stdout_of(&[
        "deck", "ccx", "beam", "--set", "KT=120", "--loads", "40,100",
    ]);
    let header: Vec<&str> = deck.lines().take(12).collect();
    assert!(header[0].starts_with("** microslip "), "{}", header[0]);
    assert!(
        header[1].contains("model=beam") && header[1].contains("KT=120.0 F=40.0,100.0"),
        "{}",
        header[1]
    );
    assert!(deck.contains("*FRICTION\n0.3, 120.0\n"));
    assert_eq!(deck.matches("*STEP").count(), 3, "pressure, then two loads");
    // Near-Coulomb: a stiff stick slope, and the default loads avoid F_thre itself.
    let stiff = stdout_of(&["deck", "ccx", "beam", "--near-coulomb"]);
    assert!(stiff.contains("*FRICTION\n0.3, 525000.0\n"), "25 E / h");
    assert!(stiff.contains("F=40.0,60.0,76.0,100.0,150.0,200.0"));
    // The same inputs give the same bytes; -o writes an ordinary file.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plate.inp");
    stdout_of(&["deck", "ccx", "plate", "-o", path.to_str().unwrap()]);
    let written = std::fs::read_to_string(&path).unwrap();
    assert_eq!(written, stdout_of(&["deck", "ccx", "plate"]));
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o777;
        assert_ne!(mode, 0o600, "not a private temporary file");
    }
}

/// `h = 1e-6` used to abort on a failed allocation (exit 134, a backtrace); `L = 1e6` wrote 574 MB.
#[test]
fn a_deck_too_large_for_ccx_is_refused_with_its_size_and_a_way_out() {
    for set in ["h=1e-6", "h=1e-3", "L=1e6"] {
        let stderr = failure(&["deck", "ccx", "beam", "--set", set], 2);
        assert!(
            stderr.contains("elements, more than the 20000")
                && stderr.contains("choose beams with L/h below about"),
            "{set}: {stderr}"
        );
    }
}

#[test]
fn deck_refuses_bad_loads_and_presets_of_the_other_model() {
    let stderr = failure(&["deck", "ccx", "beam", "--loads", "100,50"], 2);
    assert!(
        stderr.contains("invalid --loads = 50: the loads must increase"),
        "{stderr}"
    );
    let stderr = failure(&["deck", "ccx", "beam", "--loads", "-1"], 2);
    assert!(stderr.contains("invalid --loads = -1"), "{stderr}");
    let stderr = failure(&["deck", "ccx", "beam", "--set", "nu=0.5"], 2);
    assert!(stderr.contains("invalid nu = 0.5"), "{stderr}");
    let stderr = failure(&["plate", "--beam-theory", "timoshenko"], 2);
    assert!(
        stderr.contains("--beam-theory applies to the twin beams"),
        "{stderr}"
    );
    let stderr = failure(&["deck", "ccx", "plate", "--preset", "paper-beams"], 2);
    assert!(
        stderr.contains("`microslip deck ccx plate` needs a plate preset"),
        "{stderr}"
    );
}

#[test]
fn compare_reads_calculix_results_with_their_deck() {
    let text = stdout_of(&["compare", "beam", &calculix_fixture("paper-beams.dat")]);
    assert!(text.contains("K_T = 600 MPa/mm"), "{text}");
    assert!(text.contains("What the FE points imply"), "{text}");
    let csv = stdout_of(&[
        "compare",
        "beam",
        &calculix_fixture("paper-beams.dat"),
        "--format",
        "csv",
    ]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "F_N,w_fe_mm,w_euler_mm,diff_euler,w_shear_corrected_mm,diff_shear_corrected,\
         shear_corrected_within,regime,regime_fe,X_mm,X_fe_mm,diff_euler_fraction,\
         diff_shear_corrected_fraction,shear_corrected_within_fraction"
    );
    assert_eq!(lines.count(), 6);
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "compare",
        "plate",
        &calculix_fixture("plate-kt1e4.dat"),
        &calculix_fixture("paper-plate.dat"),
        "--format",
        "json",
    ]))
    .unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["KT_MPa_per_mm"], 1e4);
    assert_eq!(rows[1]["KT_MPa_per_mm"], 1e6);
}

#[test]
fn compare_reads_csv_from_any_code_with_the_parameters_given() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("abaqus.csv");
    std::fs::write(
        &csv,
        "# from another code\nF_N,w_mm\n40,0.0114\n100,0.039\n",
    )
    .unwrap();
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "compare",
        "beam",
        csv.to_str().unwrap(),
        "--set",
        "KT=120",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["KT_MPa_per_mm"], 120.0);
    assert_eq!(json["rows"].as_array().unwrap().len(), 2);
    // Two points are too few to fit mu and K_T: said, not hidden.
    assert!(json["implied"]["error"].is_string(), "{json}");
}

#[test]
fn compare_lap_reads_calculix_results_and_csv() {
    let dat = calculix_fixture("lap-aluminium.dat");
    let text = stdout_of(&["compare", "lap", &dat]);
    assert!(text.contains("clamped double-lap joint"), "{text}");
    assert!(text.contains("Verdict:"), "{text}");
    let csv = stdout_of(&["compare", "lap", &dat, "--format", "csv"]);
    assert!(csv.starts_with("F_N,Delta_fe_mm,Delta_mm,diff,"), "{csv}");
    assert_eq!(csv.lines().count(), 5, "{csv}");
    // A CSV from any code, at the bundled joint's parameters; a force beyond F_gross = 6000 N
    // has no static state and is refused, naming the file and the range.
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("abaqus.csv");
    std::fs::write(&points, "F_N,Delta_mm\n1000,0.0047\n3000,0.0143\n").unwrap();
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "compare",
        "lap",
        points.to_str().unwrap(),
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["rows"].as_array().unwrap().len(), 2, "{json}");
    assert!(json["rows"][0]["diff"].as_f64().unwrap() > 0.0, "{json}");
    std::fs::write(&points, "F_N,Delta_mm\n7000,0.05\n").unwrap();
    let stderr = failure(&["compare", "lap", points.to_str().unwrap()], 2);
    assert!(stderr.contains("abaqus.csv"), "{stderr}");
    assert!(stderr.contains("F = 7000"), "{stderr}");
    assert!(stderr.contains("[0, 6000] N"), "{stderr}");
}

/// `--set` beside a deck's results used to be ignored without a word.
#[test]
fn compare_says_which_flags_the_deck_overrides() {
    let output = microslip()
        .args([
            "compare",
            "beam",
            &calculix_fixture("paper-beams.dat"),
            "--set",
            "KT=120",
        ])
        .output()
        .unwrap();
    assert!(output.status.success());
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("microslip: note: --set KT=120 not used: the deck's header gives"),
        "{stderr}"
    );
    assert!(
        String::from_utf8(output.stdout)
            .unwrap()
            .contains("K_T = 600 MPa/mm")
    );
}

/// At F = 0 the closed form is 0: "-inf %" and "NaN %" used to be printed (text, CSV, JSON).
#[test]
fn compare_at_zero_load_says_the_relative_difference_is_undefined() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("fe.csv");
    std::fs::write(&csv, "F_N,w_mm\n0,0\n40,0.0114\n100,0.039\n").unwrap();
    let path = csv.to_str().unwrap();
    let text = stdout_of(&["compare", "beam", path]);
    for bad in ["inf", "NaN"] {
        assert!(!text.contains(bad), "{text}");
    }
    assert!(
        text.contains("n/a") && text.contains("relative difference is undefined"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["compare", "beam", path, "--format", "json"])).unwrap();
    assert!(json["rows"][0]["diff_euler"].is_null(), "{json}");
    assert!(json["rows"][1]["diff_euler"].is_f64(), "{json}");
    let csv = stdout_of(&["compare", "beam", path, "--format", "csv"]);
    let first = csv.lines().nth(1).unwrap();
    assert!(first.starts_with("0.0,0.0,0.0,,"), "{first}");
}

/// Issue 36 item 15: three FE rows, one at F = 0, fit two parameters through two points. It
/// used to print `K_T = 751.576 +- 2.6e-12 MPa/mm` and judge the deck's K_T by `z = -5.8e13`.
#[test]
fn compare_beam_without_a_degree_of_freedom_judges_nothing_by_the_fit_error() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("fe.csv");
    std::fs::write(&csv, "F_N,w_mm\n0,0\n50,0.0135317\n100,0.0382238\n").unwrap();
    let path = csv.to_str().unwrap();
    let text = stdout_of(&["compare", "beam", path]);
    assert!(!text.contains("+-") && !text.contains("z ="), "{text}");
    assert!(
        text.contains(
            "implied K_T not judged (uncertainty unknown: 2 loaded points = 2 parameters)"
        ),
        "{text}"
    );
    assert!(
        text.contains("RMS") && text.contains("0 by construction"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["compare", "beam", path, "--format", "json"])).unwrap();
    assert!(json["verdict"]["KT_z"].is_null(), "{json}");
    assert_eq!(json["verdict"]["KT"], "not judged: uncertainty unknown");
    assert!(
        json["implied"]["KT_std_error_MPa_per_mm"].is_null(),
        "{json}"
    );
    assert_eq!(json["implied"]["KT_status"], "uncertainty unknown");
    assert_eq!(json["implied"]["degrees_of_freedom"], 0);
}

/// Issue 36 item 15: `fit` on a curve without a degree of freedom says its uncertainty is
/// unknown, and refuses a response column of zeros, naming the file and the column.
#[test]
fn fit_says_when_its_uncertainty_is_unknown_and_refuses_a_zero_column() {
    let dir = tempfile::tempdir().unwrap();
    let exact = dir.path().join("exact.csv");
    std::fs::write(&exact, "F_N,w_mm\n0,0\n50,0.0135317\n100,0.0382238\n").unwrap();
    let path = exact.to_str().unwrap();
    let text = stdout_of(&["fit", "beam", path]);
    assert!(
        !text.contains("+-") && !text.contains("identified"),
        "{text}"
    );
    assert!(
        text.contains("K_T = ")
            && text.contains("uncertainty unknown (2 loaded points = 2 parameters"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["fit", "beam", path, "--format", "json"])).unwrap();
    assert!(json["KT_MPa_per_mm"]["std_error"].is_null(), "{json}");
    assert!(json["scatter"].is_null(), "{json}");
    assert_eq!(json["degrees_of_freedom"], 0);
    for (kind, header) in [("lap", "F_N,Delta_mm"), ("beam", "F_N,w_mm")] {
        let zeros = dir.path().join(format!("zeros-{kind}.csv"));
        std::fs::write(&zeros, format!("{header}\n500,0\n1000,0\n1500,0\n2000,0\n")).unwrap();
        let stderr = failure(&["fit", kind, zeros.to_str().unwrap()], 2);
        let column = header.split(',').nth(1).unwrap();
        assert!(
            stderr.contains(&format!(
                "zeros-{kind}.csv: every {column} is 0 mm: nothing to fit"
            )),
            "{stderr}"
        );
    }
}

/// Issue 36 item 13: F_1 does not depend on F, so the preset's F = 3000 N (which needs
/// P >= 5 MPa to stay below F_gross) must not cut the search; it used to say "no P in [5, 10000]
/// MPa gives F_1 = 1000 N" although P = 4.96 MPa does.
#[test]
fn solve_for_a_load_independent_quantity_searches_the_whole_domain() {
    let args = [
        "solve",
        "lap",
        "--preset",
        "lap-aluminium",
        "--vary",
        "P",
        "--target",
        "F_1=1000",
        "--format",
        "json",
    ];
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&args)).unwrap();
    let roots = json["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 1, "{json}");
    let p = roots[0]["value"].as_f64().unwrap();
    assert!(p < 5.0 && (p - 4.96).abs() < 0.01, "{json}");
    assert!(json.get("range_cut").is_none(), "{json}");
    // The lap report at that P, at a force it carries, gives F_1 = 1000 N on its own.
    let p = format!("P={p}");
    let lap: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "lap",
        "--preset",
        "lap-aluminium",
        "--set",
        &p,
        "--set",
        "F=100",
        "--format",
        "json",
    ]))
    .unwrap();
    assert!(
        (lap["F_1_N"].as_f64().unwrap() - 1000.0).abs() < 1e-6,
        "{lap}"
    );
}

/// Issue 36 item 13: where the load does cut the range (Delta depends on F), the answer says by
/// what, found or not.
#[test]
fn solve_says_what_cut_its_range() {
    let base = ["solve", "lap", "--preset", "lap-aluminium", "--vary", "P"];
    let cut = "P >= 5 MPa only: below it the given F = 3000 N exceeds F_gross = 2 b mu P L";
    let found = stdout_of(&[&base[..], &["--target", "Delta=0.015"]].concat());
    assert!(found.contains(cut), "{found}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(
        &[&base[..], &["--target", "Delta=0.015", "--format", "json"]].concat(),
    ))
    .unwrap();
    assert_eq!(json["range_cut"]["least"], 5.0, "{json}");
    assert_eq!(json["range_cut"]["F_N"], 3000.0, "{json}");
    let refused = failure(&[&base[..], &["--target", "Delta=0.5"]].concat(), 1);
    assert!(
        refused.contains("no P in [5, 10000] MPa") && refused.contains(cut),
        "{refused}"
    );
}

/// Issue 36 item 13: Delta = 0 only at F = 0; it used to say "for every F in [0, 7.6e-319] N"
/// (forces whose Delta underflows).
#[test]
fn solve_reports_a_plateau_narrower_than_its_resolution_as_a_point() {
    let text = stdout_of(&["solve", "lap", "--vary", "F", "--target", "Delta=0"]);
    assert!(text.contains("Delta = 0 mm only at F = 0 N"), "{text}");
    assert!(!text.contains("for every F"), "{text}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "solve", "lap", "--vary", "F", "--target", "Delta=0", "--format", "json",
    ]))
    .unwrap();
    assert_eq!(
        json["roots"][0]["bracket"],
        serde_json::json!([0.0, 0.0]),
        "{json}"
    );
    assert_eq!(json["roots"][0]["value"], 0.0);
}

/// Issue 36 item 13: `cycle`, `sweep cycle`, `fit lap` and `compare lap` do not use the preset's
/// F, so an F above F_gross (here 3000 N at L = 1 mm or P = 1 MPa) must not refuse them; an F
/// outside its own domain still does.
#[test]
fn commands_that_do_not_use_the_force_are_not_refused_over_it() {
    let cycle = stdout_of(&[
        "cycle",
        "--preset",
        "lap-aluminium",
        "--set",
        "L=1",
        "--amplitude",
        "100",
    ]);
    assert!(cycle.contains("+100 N and -100 N"), "{cycle}");
    stdout_of(&[
        "sweep",
        "cycle",
        "--preset",
        "lap-aluminium",
        "--set",
        "L=1",
        "--from",
        "10",
        "--to",
        "100",
        "--points",
        "3",
    ]);
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("lap.csv");
    // Delta of lap-aluminium at P = 1 MPa (F_gross = 600 N), mu = 0.3, K_T = 1000 MPa/mm.
    std::fs::write(
        &csv,
        "F_N,Delta_mm\n100,4.5972e-4\n200,9.1944e-4\n300,0.00140117\n400,0.00194307\n500,0.00255895\n",
    )
    .unwrap();
    let path = csv.to_str().unwrap();
    let fit = stdout_of(&[
        "fit",
        "lap",
        path,
        "--preset",
        "lap-aluminium",
        "--set",
        "P=1",
    ]);
    assert!(fit.contains("P = 1 MPa"), "{fit}");
    let compare = stdout_of(&[
        "compare",
        "lap",
        path,
        "--preset",
        "lap-aluminium",
        "--set",
        "P=1",
    ]);
    assert!(compare.contains("+0.00 %"), "{compare}");
    let refused = failure(
        &[
            "fit",
            "lap",
            path,
            "--preset",
            "lap-aluminium",
            "--set",
            "F=-1",
        ],
        2,
    );
    assert!(refused.contains("invalid F = -1"), "{refused}");
}

/// `compare plate`'s text table stays in columns when the implied K_T is replaced by the reason
/// it is not given: the regime column starts at the same place on every row.
#[test]
fn compare_plate_keeps_its_columns_when_no_stiffness_is_implied() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("plate.csv");
    // K_T = 1e4: the strip theory holds (a number); 1e6 and 1e8: it does not (a reason).
    std::fs::write(&csv, "KT_MPa_per_mm,u_mm\n1e4,2e-4\n1e6,1e-5\n1e8,1e-5\n").unwrap();
    let text = stdout_of(&["compare", "plate", csv.to_str().unwrap()]);
    let header = text.lines().find(|l| l.contains("regime (")).unwrap();
    let column = header.find("regime (").unwrap();
    let rows: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.contains("regime ("))
        .skip(1)
        // The table ends at the blank line before the verdicts.
        .take_while(|l| !l.trim().is_empty())
        .collect();
    assert_eq!(rows.len(), 3, "{text}");
    assert!(
        rows.iter().any(|r| r.contains("(not calibrated)")),
        "{text}"
    );
    for row in rows {
        assert_eq!(&row[column - 2..column], "  ", "{text}");
        assert!(row[column..].starts_with("microslip"), "{text}");
    }
}
#[test]
fn compare_errors_name_the_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let dat = dir.path().join("run.dat");
    std::fs::copy(calculix_fixture("paper-beams.dat"), &dat).unwrap();
    let stderr = failure(&["compare", "beam", dat.to_str().unwrap()], 2);
    assert!(
        stderr.contains("run.inp: the deck that produced the .dat is needed"),
        "{stderr}"
    );
    let text = std::fs::read_to_string(calculix_fixture("paper-beams.dat")).unwrap();
    // Line 4 is the first displacement row: "node vx vy vz"; break its vx.
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let fields: Vec<&str> = lines[3].split_whitespace().collect();
    lines[3] = format!("{} 1.0x {} {}", fields[0], fields[2], fields[3]);
    std::fs::write(&dat, lines.join("\n")).unwrap();
    let deck = calculix_fixture("paper-beams.inp");
    let stderr = failure(
        &["compare", "beam", dat.to_str().unwrap(), "--deck", &deck],
        2,
    );
    assert!(
        stderr.contains("line 4: '1.0x' is not a finite number"),
        "{stderr}"
    );
    let missing = dir.path().join("typo.dat");
    let stderr = failure(&["compare", "beam", missing.to_str().unwrap()], 2);
    assert!(stderr.contains("typo.dat: No such file"), "{stderr}");
    let frd = dir.path().join("run.frd");
    std::fs::write(&frd, "").unwrap();
    let stderr = failure(&["compare", "beam", frd.to_str().unwrap()], 2);
    assert!(stderr.contains("give the .dat file"), "{stderr}");
    let stderr = failure(
        &["compare", "plate", &calculix_fixture("paper-beams.dat")],
        2,
    );
    assert!(
        stderr.contains("a beam deck; use `microslip compare beam`"),
        "{stderr}"
    );
    let csv = dir.path().join("bad.csv");
    std::fs::write(&csv, "KT_MPa_per_mm,u_mm\n1e4,abc\n").unwrap();
    let stderr = failure(&["compare", "plate", csv.to_str().unwrap()], 2);
    assert!(
        stderr.contains("line 2: 'abc' in column u_mm is not a finite number"),
        "{stderr}"
    );
}

#[test]
fn the_three_recipes_take_one_command_each() {
    // 1. Smallest K_T with w(L) within 1 % of Coulomb at F = 100 N.
    let text = stdout_of(&["solve", "beam", "--vary", "KT", "--target", "ratio=1.01"]);
    assert!(text.contains("\nKT = 423.1"), "{text}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "solve",
        "beam",
        "--vary",
        "KT",
        "--target",
        "ratio=1.01",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["roots"].as_array().unwrap().len(), 1);
    // 2. w(L) at F = 120 N for mu from 0.1 to 0.5: the varied column first, then the F sweep's.
    let csv = stdout_of(&[
        "sweep", "beam", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "9", "--set",
        "F=120",
    ]);
    assert!(
        csv.starts_with("mu,F_N,w_coulomb_mm,w_regularized_mm,X_mm,"),
        "{csv}"
    );
    assert_eq!(csv.lines().count(), 10);
    // A single point is allowed when both ends are equal.
    let one = stdout_of(&[
        "sweep", "beam", "--from", "120", "--to", "120", "--points", "1",
    ]);
    assert_eq!(one.lines().count(), 2);
    // 3. K_T at macroslip onset of the paper's plate: in the report, no solving.
    let plate = stdout_of(&["plate"]);
    assert!(
        plate.contains("K_T at macroslip onset = 188462 MPa/mm"),
        "{plate}"
    );
    // Problems are one line each: no root (exit 1), an unknown quantity or parameter (exit 2).
    assert!(
        failure(
            &["solve", "beam", "--vary", "mu", "--target", "ratio=0.5"],
            1
        )
        .contains("no mu in [1e-6, 10] gives ratio = 0.5")
    );
    assert!(
        failure(&["solve", "plate", "--vary", "KT", "--target", "w(L)=1"], 2)
            .contains("unknown quantity 'w(L)' for the plate model (allowed: u(L) X_r ratio)")
    );
    assert!(
        failure(
            &[
                "sweep", "beam", "--vary", "tp", "--from", "0", "--to", "1", "--points", "2"
            ],
            2
        )
        .contains("invalid --vary: unknown key 'tp' for the beam model")
    );
    assert!(failure(&["sweep", "plate", "--points", "3"], 2).contains("--kt-from"));
}

#[test]
fn plot_writes_an_svg_figure_or_its_data_and_refuses_the_other_models_preset() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("w.svg");
    let csv = dir.path().join("w.csv");
    for file in [&svg, &csv] {
        let path = file.to_str().unwrap();
        stdout_of(&["plot", "w-vs-f", "--set", "mu=0.2", "--fe", "-o", path]);
    }
    let svg = std::fs::read_to_string(svg).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("finite elements"));
    let csv = std::fs::read_to_string(csv).unwrap();
    assert!(csv.starts_with("series,x_axis,x,y_axis,y\n"));
    assert!(csv.contains("\nfinite elements,F (N),"), "{csv}");
    // The log axis of u(L) vs K_T is written as K_T values, not their logarithms.
    let data = stdout_of(&["plot", "u-vs-kt", "--format", "csv"]);
    let first = data.lines().nth(1).unwrap();
    assert!(
        first.starts_with("Coulomb,\"K_T (MPa/mm, log)\",100"),
        "{first}"
    );
    // The y modes: u(L) vs K_T opens on a log axis, w(L) vs F can be relative to Coulomb, the loop
    // (both signs) cannot be logarithmic.
    assert!(stdout_of(&["plot", "u-vs-kt"]).contains("u(L) (mm, log)"));
    let relative = stdout_of(&["plot", "w-vs-f", "--y", "relative", "--format", "csv"]);
    assert!(relative.contains("w(L) / Coulomb - 1 (%)"), "{relative}");
    let error = failure(&["plot", "loop", "--y", "log"], 2);
    assert!(error.contains("--y log"), "{error}");
    let error = failure(&["plot", "u-vs-kt", "--preset", "paper-beams"], 2);
    assert!(error.contains("plate"), "{error}");
    let error = failure(&["plot", "nope"], 2);
    assert!(error.contains("w-vs-f"), "{error}");
}

/// Pixels of `png` (RGBA) darker than mid-grey within the rows `rows` (PNG pixels).
fn dark_pixels(png: &resvg::tiny_skia::Pixmap, rows: std::ops::Range<u32>) -> usize {
    png.pixels()
        .chunks(png.width() as usize)
        .skip(rows.start as usize)
        .take((rows.end - rows.start) as usize)
        .flatten()
        .filter(|p| u32::from(p.red()) + u32::from(p.green()) + u32::from(p.blue()) < 3 * 100)
        .count()
}

#[test]
fn plot_writes_png_and_pdf_by_the_extension_and_refuses_one_it_cannot_write() {
    let dir = tempfile::tempdir().unwrap();
    let file = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    for name in ["w.png", "W.PDF", "w.svg"] {
        stdout_of(&["plot", "w-vs-f", "--fe", "-o", &file(name)]);
    }
    let png = std::fs::read(file("w.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    let image = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
    assert_eq!((image.width(), image.height()), (1600, 1000));
    // The title (the top 80 px, text alone: the built-in font, not the system's), the axes and
    // curves (the rest) are drawn in dark ink on white.
    let title = dark_pixels(&image, 0..80);
    let body = dark_pixels(&image, 80..1000);
    assert!(title > 500, "{title} dark pixels in the title band");
    assert!(body > 5000, "{body} dark pixels under the title");
    assert!(
        image.pixels()[0].red() == 255,
        "the background is opaque white"
    );
    let pdf = std::fs::read(file("W.PDF")).unwrap();
    assert!(pdf.starts_with(b"%PDF-"), "not a PDF");
    assert!(
        pdf.windows(b"DejaVu".len()).any(|w| w == b"DejaVu"),
        "the PDF embeds its font"
    );
    assert!(
        std::fs::read_to_string(file("w.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    // `--format` on stdout; an extension that no format has, or one that contradicts --format,
    // is refused before anything is written.
    let output = microslip()
        .args(["plot", "w-vs-f", "--format", "png"])
        .output()
        .unwrap();
    assert!(output.status.success() && output.stdout.starts_with(b"\x89PNG"));
    let error = failure(&["plot", "w-vs-f", "-o", &file("w.jpg")], 2);
    assert!(
        error.contains("-o/--output") && error.contains("w.jpg") && error.contains(".png, .pdf"),
        "{error}"
    );
    let error = failure(
        &["plot", "w-vs-f", "--format", "pdf", "-o", &file("x.svg")],
        2,
    );
    assert!(
        error.contains("--format = pdf") && error.contains(".svg"),
        "{error}"
    );
    assert!(!dir.path().join("w.jpg").exists() && !dir.path().join("x.svg").exists());
}

#[test]
fn figures_writes_png_or_pdf_when_asked_and_refuses_csv() {
    let dir = tempfile::tempdir().unwrap();
    for (format, magic) in [("png", &b"\x89PNG"[..]), ("pdf", &b"%PDF-"[..])] {
        let out = dir.path().join(format);
        let args = [
            "figures",
            "--out",
            out.to_str().unwrap(),
            "--no-fe",
            "--format",
            format,
        ];
        stdout_of(&args);
        let index = std::fs::read_to_string(out.join("index.html")).unwrap();
        let file = out.join(format!("beam-w-vs-f.{format}"));
        assert!(
            index.contains(&format!("beam-w-vs-f.{format}\"")),
            "{index}"
        );
        assert!(std::fs::read(&file).unwrap().starts_with(magic), "{file:?}");
        assert!(!out.join("beam-w-vs-f.svg").exists());
    }
    let error = failure(&["figures", "--out", "x", "--format", "csv"], 2);
    assert!(
        error.contains("--format = csv") && error.contains("svg, png, pdf"),
        "{error}"
    );
}

#[test]
fn figures_writes_every_figure_its_data_and_an_index() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    let text = stdout_of(&["figures", "--out", out.to_str().unwrap(), "--no-fe"]);
    assert!(text.contains("index.html"));
    let index = std::fs::read_to_string(out.join("index.html")).unwrap();
    let figures: Vec<&str> = index
        .split("<img src=\"")
        .skip(1)
        .map(|s| s.split('"').next().unwrap())
        .collect();
    assert!(figures.len() >= 9, "{figures:?}");
    for svg in figures {
        let body = std::fs::read_to_string(out.join(svg)).unwrap();
        assert!(body.starts_with("<svg"), "{svg}");
        assert!(out.join(svg.replace(".svg", ".csv")).exists(), "{svg}");
    }
}

/// The smallest K_T (MPa/mm) at which the paper's beams' regularized w(L) is within `tolerance` of
/// Coulomb's at every force of 0 < F <= 300 N, from the closed forms of docs/theory.md.
///
/// The worst forces are those in stick, F <= F_thre = 4 mu b h P / 3 = 80 N < F_1, where both
/// deflections are linear in F ((T2); tests/kt_tolerance.rs checks it by brute force over 1000
/// forces). There (B6) gives tau = tau_b (1 - cosh k(L - x) / cosh kL), and (B11)
/// w(L) = F L^3 / (2 E b h^3) - 3 / (2 E h^2) int_0^L tau(x) (L x - x^2 / 2) dx. With y = L - x,
/// L x - x^2 / 2 = (L^2 - y^2) / 2, int_0^L cosh(ky) dy = sinh(kL) / k and
/// int_0^L y^2 cosh(ky) dy = L^2 sinh(kL) / k - 2 L cosh(kL) / k^2 + 2 sinh(kL) / k^3:
///
///     int_0^L (1 - cosh k(L - x) / cosh kL)(L x - x^2 / 2) dx = L^3/3 - L/k^2 + tanh(kL)/k^3,
///
/// so, with tau_b = 3 F / (4 b h), w(L) = F (L^3 + 9 L / k^2 - 9 tanh(kL) / k^3) / (8 E b h^3).
/// Coulomb's stick is w(L) = F L^3 / (8 E b h^3) (B3), hence
///
///     w / w_Coulomb - 1 = 9 / (kL)^2 (1 - tanh(kL) / (kL))
///
/// (9 / (kL)^2 for large kL, the limit of section 1), which falls as kL grows: bisected on kL,
/// then K_T = (kL)^2 E h / (4 L^2) from k = 2 sqrt(K_T / (E h)) (B5).
fn paper_beams_stiffness_within(tolerance: f64) -> f64 {
    // The paper's beams (preset paper-beams): L (mm), h half the height (mm), E (MPa).
    let (length, half_height, youngs) = (200.0, 10.0, 210_000.0);
    let deviation = |kl: f64| 9.0 / (kl * kl) * (1.0 - kl.tanh() / kl);
    let (mut low, mut high) = (1.0, 1e4);
    assert!(deviation(low) > tolerance && deviation(high) < tolerance);
    for _ in 0..100 {
        let mid = 0.5 * (low + high);
        if deviation(mid) > tolerance {
            low = mid;
        } else {
            high = mid;
        }
    }
    high * high * youngs * half_height / (4.0 * length * length)
}

/// The smallest K_T (MPa/mm) at which the paper's plate's regularized u(L) is within `tolerance`
/// of Coulomb's, from the closed forms of docs/theory.md.
///
/// Far into macroslip, where coth(alpha X_r) = 1 to double precision, (P6) gives
/// L - X_r = l - 1 / alpha, and (P2) from u(X_r) = mu P / K_T gives
///
///     u(L) = mu P / K_T + kappa (l (l - 1 / alpha) - (l - 1 / alpha)^2 / 2)
///          = mu P / K_T + kappa l^2 / 2 - kappa / (2 alpha^2) = u_Coulomb + mu P / (2 K_T),
///
/// since kappa / alpha^2 = mu P / K_T ((P2), (P4)) and u_Coulomb = kappa l^2 / 2 (P3); the limit
/// K_T -> infinity of section 2. So u / u_Coulomb - 1 = mu P / (2 K_T u_Coulomb), and the K_T
/// sought is mu P / (2 tolerance u_Coulomb), with
/// u_Coulomb = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E) (7.9591836735e-6 mm, the header of
/// tests/data/plate-paper-fd.csv). At 1 % that K_T is 1.88e7 MPa/mm: alpha = 35 /mm,
/// X_r = 9.74 mm, alpha X_r = 341, where coth is 1 to 1e-290.
fn paper_plate_stiffness_within(tolerance: f64) -> f64 {
    // The paper's plate (preset paper-plate): mu, P (MPa), E (MPa), nu, t_p (mm).
    let (mu, pressure, youngs, poisson, thickness) = (0.3, 10.0, 70_000.0, 0.3, 0.2);
    let coulomb = (1.0 + poisson) * poisson * poisson * thickness * pressure
        / (2.0 * (1.0 - poisson) * mu * youngs);
    mu * pressure / (2.0 * tolerance * coulomb)
}

#[test]
fn kt_tolerance_answers_with_the_stiffness_and_each_codes_setting() {
    let text = stdout_of(&["kt", "--tolerance", "1%"]);
    assert!(
        text.contains("within 1 % of Coulomb at F = 100 N"),
        "{text}"
    );
    assert!(text.contains("K_T >= 423.1 MPa/mm"), "{text}");
    assert!(text.contains("SLIP TOLERANCE <=") && text.contains("stick slope lambda >= 423"));
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "kt",
        "--tolerance",
        "0.01",
        "--from",
        "0",
        "--to",
        "300",
        "--format",
        "json",
    ]))
    .unwrap();
    let kt = json["KT_min_MPa_per_mm"].as_f64().unwrap();
    let expected = paper_beams_stiffness_within(0.01);
    assert!((kt / expected - 1.0).abs() < 1e-9, "{kt} vs {expected}");
    assert_eq!(json["force_range_N"], serde_json::json!([0.0, 300.0]));
    let plate = stdout_of(&["kt", "--tolerance", "1%", "--preset", "paper-plate"]);
    // Rounded to four significant digits, as the text shows K_T.
    let shown = format!("K_T >= {:.3e} MPa/mm", paper_plate_stiffness_within(0.01));
    assert!(plate.contains("u(L)") && plate.contains(&shown), "{plate}");
    for (args, says) in [
        (&["kt", "--tolerance", "0"][..], "--tolerance"),
        (&["kt", "--tolerance", "1%", "--from", "-3"], "--from"),
        (
            &["kt", "--tolerance", "1%", "--from", "0", "--to", "0"],
            "no positive force",
        ),
        (
            &[
                "kt",
                "--tolerance",
                "1%",
                "--preset",
                "paper-plate",
                "--to",
                "5",
            ],
            "plate",
        ),
    ] {
        let error = failure(args, 2);
        assert!(error.contains(says), "{args:?}: {error}");
    }
}

#[test]
fn plot_pins_draw_the_chart_at_other_values_over_the_same_range() {
    let data = stdout_of(&["plot", "w-vs-f", "--pin", "mu=0.2", "--format", "csv"]);
    let pinned: Vec<&str> = data
        .lines()
        .filter(|l| l.starts_with("pin 1: mu 0.2->0.3,"))
        .collect();
    assert_eq!(pinned.len(), 200, "{data}");
    // Over the current chart's force range (3 F_thre = 240 N at mu = 0.3, not 160 N at mu = 0.2),
    // and at 240 N the same w(L) as `microslip beam` at mu = 0.2.
    let last: Vec<&str> = pinned[199].split(',').collect();
    assert_eq!(last[2], "240.0");
    let point = stdout_of(&[
        "beam", "--set", "mu=0.2", "--set", "F=240", "--format", "json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&point).unwrap();
    let w = json["regularized"]["w_tip_mm"].as_f64().unwrap();
    let pinned_w: f64 = last[4].parse().unwrap();
    assert!((pinned_w - w).abs() <= 1e-12 * w, "{pinned_w} vs {w}");
    // Several values per pin, and the refusals name the pin.
    let two = stdout_of(&[
        "plot",
        "x-vs-f",
        "--pin",
        "mu=0.2,KT=1000",
        "--format",
        "csv",
    ]);
    assert!(two.contains("pin 1: mu 0.2->0.3 KT 1000->600,"), "{two}");
    let error = failure(&["plot", "w-vs-f", "--pin", "mu=-1"], 2);
    assert!(
        error.contains("--pin mu=-1") && error.contains("mu"),
        "{error}"
    );
    let five: Vec<&str> = ["mu=0.1", "mu=0.2", "mu=0.4", "mu=0.5", "mu=0.6"]
        .iter()
        .flat_map(|p| ["--pin", *p])
        .collect();
    let error = failure(&[&["plot", "w-vs-f"], five.as_slice()].concat(), 2);
    assert!(error.contains("at most 4"), "{error}");
}

#[test]
fn kt_says_what_its_tolerance_is_of_and_offers_the_other_reading() {
    let text = stdout_of(&["kt", "--tolerance", "1%"]);
    assert!(
        text.contains("1 % of the Coulomb answer") && text.contains("--of current"),
        "{text}"
    );
    let text = stdout_of(&["kt", "--tolerance", "0.1%", "--of", "current"]);
    assert!(
        text.contains("within 0.1 % of the current K_T's (600 MPa/mm)") && text.contains(" to "),
        "{text}"
    );
    let said = failure(&["kt", "--of", "current"], 2);
    assert!(said.contains("--tolerance"), "{said}");
    // The table says how far each candidate's w(L) is from the current K_T's.
    // Abaqus's default, 30 MPa/mm here, against the paper's 600, from the closed forms:
    let w = |kt: f64| {
        microslip::TwinBeams::new(microslip::TwinBeamsParams {
            tangential_stiffness: kt,
            ..microslip::TwinBeamsParams::PAPER
        })
        .unwrap()
        .regularized(microslip::TipForce::new(100.0).unwrap())
        .tip_deflection()
    };
    let expected = format!("+{:.1} %", 100.0 * (w(30.0) / w(600.0) - 1.0));
    let table = stdout_of(&["kt"]);
    let abaqus = table.lines().find(|l| l.starts_with("Abaqus")).unwrap();
    assert!(
        table.contains("vs current") && abaqus.contains(&expected),
        "{expected}: {table}"
    );
}

/// The series of a chart CSV: each name with its number of points and its largest x.
fn csv_series(data: &str) -> Vec<(String, usize, f64)> {
    let mut series: Vec<(String, usize, f64)> = Vec::new();
    for line in data.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let (name, x) = (cells[0].to_string(), cells[2].parse::<f64>().unwrap());
        match series.iter_mut().find(|s| s.0 == name) {
            Some(s) => {
                s.1 += 1;
                s.2 = s.2.max(x);
            }
            None => series.push((name, 1, x)),
        }
    }
    series
}

#[test]
fn plot_family_draws_one_curve_per_value_over_the_whole_force_axis() {
    let data = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2", "--format", "csv"]);
    assert!(data.starts_with("series,x_axis,x,y_axis,y\n"), "{data}");
    let series = csv_series(&data);
    let names: Vec<&str> = series.iter().map(|s| s.0.as_str()).collect();
    // Equal rank: no Coulomb, no K_T/5 or K_T*5, no cursor; the unit in every name.
    assert_eq!(names, ["P = 0.5 MPa", "P = 1 MPa", "P = 2 MPa"]);
    // Each member over the whole axis, which shows P = 2 MPa's regime change (F_thre = 160 N).
    for (name, points, last) in &series {
        assert_eq!((*points, *last), (200, 480.0), "{name}");
    }
    let svg = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2"]);
    for text in [
        "w(L) vs F, P = 0.5, 1, 2 MPa",
        "P = 0.5 MPa",
        "L = 200 mm, b = 20 mm, h = 10 mm, E = 210000 MPa, nu = 0.3, mu = 0.3, KT = 600 MPa/mm",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    assert!(!svg.contains(">\ncurrent\n<") && !svg.contains("K_T/5"));
    // A series the same for every member may be added once; one that differs is refused.
    let names = plotted_names(&[
        "w-vs-f",
        "--family",
        "KT=120,3000",
        "--series",
        "coulomb,current",
    ]);
    assert_eq!(names, ["Coulomb", "KT = 120 MPa/mm", "KT = 3000 MPa/mm"]);
    let error = failure(
        &[
            "plot", "w-vs-f", "--family", "P=0.5,2", "--series", "coulomb",
        ],
        2,
    );
    assert!(error.contains("differs between the members"), "{error}");
}

#[test]
fn plot_family_refusals_name_the_flag() {
    for (args, says) in [
        (
            &["--family", "P=0.5,-1"][..],
            "--family P=0.5,-1: invalid P = -1: must be > 0",
        ),
        (&["--family", "Q=1,2"], "--family Q=1,2: unknown key 'Q'"),
        (
            &["--family", "P=1,x"],
            "--family P=1,x: invalid value 'x' for P",
        ),
        (&["--family", "P"], "--family P: expected KEY=V1,V2"),
        (&["--family", "P=1,1"], "P = 1 is given twice"),
        (
            &["--family", "P=1,2,3,4,5,6,7"],
            "7 values given, at most 6",
        ),
        (&["--family", "P=1,2", "--pin", "mu=0.2"], "--pin"),
        (&["--family", "P=1,2", "--fe"], "--fe"),
    ] {
        let error = failure(&[&["plot", "w-vs-f"], args].concat(), 2);
        assert!(error.contains(says), "{args:?}: {error}");
    }
    // The same messages as --set gives, after the flag.
    let set = failure(&["plot", "w-vs-f", "--set", "P=-1"], 2);
    let family = failure(&["plot", "w-vs-f", "--family", "P=-1"], 2);
    let reason = set.trim_start_matches("microslip: ");
    assert!(family.ends_with(reason), "{family} vs {set}");
}

/// The names of the series `plot` writes as CSV with `args`.
fn plotted_names(args: &[&str]) -> Vec<String> {
    let data = stdout_of(&[&["plot"], args, &["--format", "csv"]].concat());
    csv_series(&data).into_iter().map(|s| s.0).collect()
}

#[test]
fn plot_series_and_no_cursor_choose_what_is_drawn() {
    let names = plotted_names(&["w-vs-f", "--series", "current,coulomb"]);
    assert_eq!(names, ["Coulomb", "K_T"]);
    let svg = stdout_of(&["plot", "w-vs-f", "--series", "current,coulomb"]);
    assert!(!svg.contains(">\ncurrent\n<") && !svg.contains("K_T*5"));
    let with_cursor = stdout_of(&["plot", "w-vs-f"]);
    assert!(with_cursor.contains(">\ncurrent\n<"));
    let without = stdout_of(&["plot", "w-vs-f", "--no-cursor"]);
    assert!(!without.contains(">\ncurrent\n<") && without.contains(">\nK_T/5\n<"));
    let error = failure(&["plot", "w-vs-f", "--series", "current,nope"], 2);
    assert!(
        error.contains(
            "unknown series 'nope' (allowed: current, coulomb, softer, stiffer, limit, fe, \
             continuum, measured, external, cursor)"
        ),
        "{error}"
    );
    let error = failure(&["plot", "w-vs-f", "--series", "limit"], 2);
    assert!(
        error.contains("chart w-vs-f has no limit series; it has: "),
        "{error}"
    );
    let error = failure(&["plot", "w-vs-f", "--series", "fe"], 2);
    assert!(error.contains("fe needs --fe"), "{error}");
    let error = failure(&["plot", "w-vs-f", "--series", "cursor", "--no-cursor"], 2);
    assert!(error.contains("--no-cursor"), "{error}");
    // The mu P line of tau(x) alone with Coulomb.
    let names = plotted_names(&["tau", "--series", "coulomb,limit"]);
    assert_eq!(names, ["Coulomb", "mu P"]);
}

/// Plotters rounds to whole pixels, which makes gentle slopes stairs; curves are written at
/// fractional pixels.
#[test]
fn plot_curves_are_drawn_at_fractional_pixels() {
    let svg = stdout_of(&["plot", "w-vs-f", "--family", "P=0.5,1,2"]);
    let curves: Vec<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.matches(',').count() > 100)
        .collect();
    assert_eq!(curves.len(), 3, "{svg}");
    for curve in curves {
        let points = curve.split("points=\"").nth(1).unwrap();
        let coordinates: Vec<f64> = points
            .trim_end_matches("\"/>")
            .split([' ', ','])
            .map(|c| c.parse().unwrap())
            .collect();
        let fractional = coordinates.iter().filter(|c| c.fract() != 0.0).count();
        assert!(fractional > coordinates.len() / 2, "{curve}");
    }
}

#[test]
fn a_family_along_the_chart_s_own_axis_is_refused() {
    for (args, param) in [
        (
            &["plot", "w-vs-f", "--family", "F=0,100"][..],
            "F is the x axis of chart w-vs-f",
        ),
        (
            &[
                "plot",
                "u-vs-kt",
                "--preset",
                "paper-plate",
                "--family",
                "KT=1e3,1e6",
            ][..],
            "KT is the x axis of chart u-vs-kt",
        ),
    ] {
        let said = failure(args, 2);
        assert!(said.contains(param), "{said}");
    }
}

/// Beyond the friction strain (V2) was measured at (mu P = 10 MPa on the paper's beams:
/// mu P L / (2 E h) = 10 x 200 / (2 x 210000 x 10) = 4.76e-4 > 1.2e-4), every output says "not
/// calibrated" instead of a bound, and `compare` does not judge the implied K_T by it.
#[test]
fn beams_beyond_the_calibrated_friction_strain_get_no_bound() {
    let set = ["--set", "mu=1", "--set", "P=10", "--set", "KT=3000"];
    let args = |command: &[&'static str]| -> Vec<&'static str> {
        command.iter().copied().chain(set).collect()
    };
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&args(&["beam", "--format", "json"]))).unwrap();
    let theory = &json["beam_theory"];
    assert_eq!(theory["validity"], "not calibrated", "{json}");
    assert!(theory.get("vs_continuum_within").is_none(), "{json}");
    let strain = theory["friction_strain"].as_f64().unwrap();
    assert!((strain / (10.0 * 200.0 / (2.0 * 210_000.0 * 10.0)) - 1.0).abs() < 1e-12);
    let text = stdout_of(&args(&["beam"]));
    assert!(
        text.contains("not calibrated") && text.contains("4.76e-4"),
        "{text}"
    );
    let csv = stdout_of(&args(&[
        "sweep", "beam", "--from", "0", "--to", "60000", "--points", "2",
    ]));
    assert!(
        csv.lines().nth(2).unwrap().ends_with(",euler-bernoulli,,"),
        "{csv}"
    );
    // Any FE points (these are made up): the implied K_T is not judged through (V2).
    let dir = tempfile::tempdir().unwrap();
    let fe = dir.path().join("fe.csv");
    std::fs::write(&fe, "F_N,w_mm\n20000,1.5\n30000,3.0\n40000,4.5\n").unwrap();
    let mut compare = vec!["compare", "beam", fe.to_str().unwrap()];
    compare.extend(set);
    let text = stdout_of(&compare);
    assert!(
        text.contains("implied K_T not judged (the beam theory's envelope is not calibrated"),
        "{text}"
    );
}

/// The lap joint from the command line (issue 24): every command that has it, and what it refuses
/// and why.
#[test]
fn the_lap_joint_from_the_command_line() {
    let text = stdout_of(&["lap"]);
    for needed in [
        "Clamped double-lap joint",
        "F_1        = 2015.89 N",
        "at x = L (covers' ends)",
        "macroslip+microslip+macroslip",
        "Delta within 3.4 % of a continuum (approximate)",
        "2-D continuum (plane stress, nu = 0.3",
    ] {
        assert!(text.contains(needed), "{needed}\n{text}");
    }
    // F beyond F_gross: refused with the bound and why, exit 2.
    let refused = failure(&["lap", "--set", "F=6001"], 2);
    assert!(
        refused.contains(
            "invalid F = 6001: must be in [0, 6000] N (F_gross = 2 b mu P L: the joint slides \
             through beyond it)"
        ),
        "{refused}"
    );
    // Sweeps over F (up to F_gross) and over any parameter, refusing an end with no state.
    let csv = stdout_of(&[
        "sweep", "lap", "--from", "0", "--to", "6000", "--points", "7",
    ]);
    assert!(
        csv.starts_with("F_N,Delta_coulomb_mm,Delta_regularized_mm,a_mm,d_mm,"),
        "{csv}"
    );
    assert_eq!(csv.lines().count(), 8);
    assert!(
        csv.lines()
            .next()
            .unwrap()
            .ends_with(",shear_lag_within,shear_lag_within_fraction"),
        "{csv}"
    );
    // At F_gross the envelope (calibrated up to 0.9 F_gross) gives no bound: an empty cell.
    assert!(
        csv.lines()
            .last()
            .unwrap()
            .ends_with("macroslip,macroslip,,"),
        "{csv}"
    );
    let beyond = failure(
        &[
            "sweep", "lap", "--from", "0", "--to", "7000", "--points", "3",
        ],
        2,
    );
    assert!(beyond.contains("F_gross"), "{beyond}");
    let varied = stdout_of(&[
        "sweep", "lap", "--vary", "KT", "--from", "100", "--to", "1e5", "--points", "4",
    ]);
    assert!(
        varied.starts_with("KT_MPa_per_mm,F_N,Delta_coulomb_mm"),
        "{varied}"
    );
    let low_mu = failure(
        &[
            "sweep", "lap", "--vary", "mu", "--from", "0.1", "--to", "0.5", "--points", "3",
        ],
        2,
    );
    assert!(low_mu.contains("at mu = 0.1, invalid F = 3000"), "{low_mu}");
    // Cycles of a lap preset; the loop's columns name Delta.
    let cycle = stdout_of(&["cycle", "--preset", "lap-aluminium", "--amplitude", "4000"]);
    assert!(cycle.contains("Double-lap joint, force cycling"), "{cycle}");
    let loop_csv = stdout_of(&[
        "cycle",
        "--preset",
        "lap-aluminium",
        "--amplitude",
        "4000",
        "--format",
        "csv",
        "--points",
        "3",
    ]);
    assert!(loop_csv.starts_with("branch,F_N,Delta_coulomb_mm,Delta_regularized_mm"));
    let too_big = failure(
        &["cycle", "--preset", "lap-aluminium", "--amplitude", "9000"],
        2,
    );
    assert!(
        too_big.contains("--amplitude = 9000") && too_big.contains("F_gross"),
        "{too_big}"
    );
    let sweep_cycle = stdout_of(&[
        "sweep",
        "cycle",
        "--from",
        "0",
        "--to",
        "6000",
        "--points",
        "4",
        "--preset",
        "lap-aluminium",
    ]);
    assert_eq!(sweep_cycle.lines().count(), 5, "{sweep_cycle}");
    // Solve searches only where F <= F_gross; kt --tolerance answers for Delta.
    let solved = stdout_of(&["solve", "lap", "--vary", "mu", "--target", "Delta=0.015"]);
    assert!(solved.contains("searched mu in [0.15, 10]"), "{solved}");
    let tolerance = stdout_of(&["kt", "--preset", "lap-aluminium", "--tolerance", "1%"]);
    assert!(tolerance.contains("(L11)"), "{tolerance}");
    assert!(failure(&["lap", "--beam-theory", "timoshenko"], 2).contains("not the lap joint"));
    // The deck is written, its header naming the command that reads its results.
    let deck = stdout_of(&["deck", "ccx", "lap", "--loads", "1000,3000"]);
    assert!(deck.contains("** microslip-deck: model=lap"), "{deck}");
    assert!(
        deck.contains("** Compare it:  microslip compare lap JOB.dat"),
        "{deck}"
    );
    let beyond = failure(&["deck", "ccx", "lap", "--loads", "1000,7000"], 2);
    assert!(
        beyond.contains("--loads = 7000") && beyond.contains("F_gross"),
        "{beyond}"
    );
    // A beam curve is not a lap curve: its columns are named.
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("r.csv");
    std::fs::write(&data, "F_N,w_mm\n1,0.001\n").unwrap();
    let compare = failure(&["compare", "lap", data.to_str().unwrap()], 2);
    assert!(compare.contains("Delta_mm"), "{compare}");
    let fit = failure(
        &[
            "fit",
            "beam",
            data.to_str().unwrap(),
            "--preset",
            "lap-aluminium",
        ],
        2,
    );
    assert!(fit.contains("needs a beam preset"), "{fit}");
    // fit lap: a sweep of a joint with mu 0.4, K_T 2500 gives both back.
    let measured = dir.path().join("joint.csv");
    std::fs::write(
        &measured,
        stdout_of(&[
            "sweep", "lap", "--from", "100", "--to", "5500", "--points", "30", "--set", "mu=0.4",
            "--set", "KT=2500",
        ]),
    )
    .unwrap();
    let fitted = stdout_of(&["fit", "lap", measured.to_str().unwrap()]);
    assert!(fitted.contains("  mu  = 0.4 +- "), "{fitted}");
    assert!(fitted.contains("F_gross = 8000 N"), "{fitted}");
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "fit",
        "lap",
        measured.to_str().unwrap(),
        "--format",
        "json",
    ]))
    .unwrap();
    assert!((json["KT_MPa_per_mm"]["value"].as_f64().unwrap() / 2500.0 - 1.0).abs() < 1e-9);
    assert!(json.get("F_thre_N").is_none() && json.get("F_gross_N").is_some());
    let too_low = failure(
        &["fit", "lap", measured.to_str().unwrap(), "--fix", "mu=0.05"],
        2,
    );
    assert!(too_low.contains("F_gross"), "{too_low}");
    // The plate has no load to cycle.
    let plate = failure(&["cycle", "--amplitude", "1", "--preset", "paper-plate"], 2);
    assert!(plate.contains("needs a beam or lap preset"), "{plate}");
}

/// Issue 36 (10): a ratio has one name in every output, its unit in the name, beside the old
/// name (kept one release); the lap report gives D and zeta as the TUI and `cycle` do.
#[test]
fn ratios_have_one_name_with_their_unit_in_every_output() {
    let json =
        |args: &[&str]| -> serde_json::Value { serde_json::from_str(&stdout_of(args)).unwrap() };
    let lap = json(&["lap", "--preset", "lap-aluminium", "--format", "json"]);
    let bound = &lap["shear_lag"]["shear_lag_within_fraction"];
    assert!(bound.as_f64().is_some(), "{lap}");
    assert_eq!(bound, &lap["shear_lag"]["expected_error"]);
    // The same bound in the sweep's CSV at the same force, under the same name.
    let csv = stdout_of(&[
        "sweep",
        "lap",
        "--preset",
        "lap-aluminium",
        "--from",
        "3000",
        "--to",
        "3000",
        "--points",
        "1",
    ]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| {
        let i = header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name}: {csv}"));
        row[i].parse::<f64>().unwrap()
    };
    assert_eq!(column("shear_lag_within_fraction"), bound.as_f64().unwrap());
    assert_eq!(column("shear_lag_within"), bound.as_f64().unwrap());
    // D and zeta: those of `cycle` at amplitude F, for both laws.
    let cycle = json(&[
        "cycle",
        "--preset",
        "lap-aluminium",
        "--amplitude",
        "3000",
        "--format",
        "json",
    ]);
    for law in ["coulomb", "regularized"] {
        for key in ["D_Nmm", "zeta"] {
            let value = lap[law][key]
                .as_f64()
                .unwrap_or_else(|| panic!("{law}.{key}: {lap}"));
            let expected = cycle[law][key].as_f64().unwrap();
            assert!(
                (value - expected).abs() <= 1e-12 * expected.abs(),
                "{law}.{key}"
            );
        }
    }
    let beam = json(&["beam", "--format", "json"]);
    assert_eq!(
        beam["beam_theory"]["vs_continuum_within_fraction"],
        beam["beam_theory"]["vs_continuum_within"]
    );
}

/// Issue 36 (12): "modified by --set" only where a value differs from the preset's.
#[test]
fn a_set_that_repeats_the_presets_value_does_not_modify_it() {
    let same = stdout_of(&["lap", "--set", "F=3000"]);
    assert!(!same.contains("modified"), "{same}");
    let other = stdout_of(&["lap", "--set", "F=3001"]);
    assert!(other.contains("(modified by --set)"), "{other}");
    let json = stdout_of(&[
        "beam",
        "--beam-theory",
        "euler-bernoulli",
        "--format",
        "json",
    ]);
    assert!(json.contains("\"preset\": \"paper-beams\""), "{json}");
}

/// Issue 36 (12): the words users read: no issue numbers in help, no flag offered where it does
/// nothing, the lap CSV columns named, and the beam-theory note only for the beams.
#[test]
fn help_and_notes_say_only_what_applies() {
    let commands: &[&[&str]] = &[
        &[],
        &["beam"],
        &["plate"],
        &["lap"],
        &["sweep", "beam"],
        &["sweep", "plate"],
        &["sweep", "lap"],
        &["solve"],
        &["kt"],
        &["cycle"],
        &["fit"],
        &["deck", "ccx"],
        &["bench", "ccx"],
        &["compare"],
        &["plot"],
        &["figures"],
        &["check"],
        &["verify"],
    ];
    for command in commands {
        let help = stdout_of(&[*command, &["--help"][..]].concat());
        assert!(
            !help.to_lowercase().contains("issue"),
            "{command:?}: {help}"
        );
    }
    for command in [
        &["plate"][..],
        &["lap"],
        &["sweep", "plate"],
        &["sweep", "lap"],
    ] {
        let help = stdout_of(&[command, &["--help"][..]].concat());
        assert!(!help.contains("--beam-theory"), "{command:?}: {help}");
    }
    let stderr = failure(
        &[
            "sweep",
            "lap",
            "--from",
            "0",
            "--to",
            "1",
            "--points",
            "2",
            "--beam-theory",
            "timoshenko",
        ],
        2,
    );
    assert!(
        stderr.contains("--beam-theory applies to the twin beams"),
        "{stderr}"
    );
    let help = stdout_of(&["compare", "--help"]);
    assert!(help.contains("F_N,Delta_mm (lap)"), "{help}");
    let note = |model: &str, dat: &str| {
        let output = microslip()
            .args(["compare", model, dat, "--set", "KT=500"])
            .output()
            .unwrap();
        assert!(output.status.success(), "{model}");
        String::from_utf8(output.stderr).unwrap()
    };
    let lap = note("lap", "tests/data/calculix/lap-aluminium.dat");
    assert!(
        lap.contains("not used") && !lap.contains("beam theor"),
        "{lap}"
    );
    let beam = note("beam", "tests/data/calculix/paper-beams.dat");
    assert!(beam.contains("compare shows both beam theories"), "{beam}");
}

/// Issue 36 (20): a refusal keeps what the user needs: the range for a value that is no number,
/// the text typed for one that rounds to 0, invisible characters escaped.
#[test]
fn refusals_keep_the_range_the_text_typed_and_show_invisible_characters() {
    for text in ["nan", "", "abc"] {
        let stderr = failure(&["beam", "--set", &format!("KT={text}")], 2);
        assert!(
            stderr.contains(&format!(
                "invalid value '{text}' for KT: not a finite number; must be in [1e-6, 1e12] MPa/mm"
            )),
            "{stderr}"
        );
    }
    let stderr = failure(&["beam", "--set", "KT=1e-400"], 2);
    assert!(
        stderr.contains("invalid KT = 1e-400: must be in [1e-6, 1e12] MPa/mm"),
        "{stderr}"
    );
    let stderr = failure(&["beam", "--set", "KT=\u{200b}1000"], 2);
    assert!(stderr.contains("'\\u{200b}1000'"), "{stderr}");
    // Where 0 is accepted, a number that rounds to it is 0.
    let text = stdout_of(&["beam", "--set", "F=1e-400"]);
    assert!(text.contains("At F = 0 N"), "{text}");
}

/// Issue 36 (16): a command never writes over a file it reads: `-o` naming the preset, however
/// spelt (another relative form, an absolute path, a link, a user preset by name), is refused
/// before anything is written, and the preset is intact.
#[test]
fn output_never_overwrites_the_preset_the_command_reads() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("microslip").join("presets");
    std::fs::create_dir_all(&presets).unwrap();
    let text = std::fs::read_to_string("presets/lap-aluminium.toml").unwrap();
    let preset = dir.path().join("p.toml");
    std::fs::write(&preset, &text).unwrap();
    std::fs::write(presets.join("mine.toml"), &text).unwrap();
    let link = dir.path().join("link.toml");
    std::os::unix::fs::symlink(&preset, &link).unwrap();
    let p = preset.to_str().unwrap();
    let dotted = format!("{}/./p.toml", dir.path().display());
    let mine = presets.join("mine.toml");
    let cases: [Vec<&str>; 5] = [
        vec!["deck", "ccx", "lap", "--preset", p, "-o", &dotted],
        vec!["plot", "delta-vs-f", "--preset", p, "-o", p],
        vec![
            "plot",
            "delta-vs-f",
            "--preset",
            link.to_str().unwrap(),
            "-o",
            p,
        ],
        vec![
            "deck",
            "ccx",
            "lap",
            "--preset",
            p,
            "-o",
            link.to_str().unwrap(),
        ],
        vec![
            "deck",
            "ccx",
            "lap",
            "--preset",
            "mine",
            "-o",
            mine.to_str().unwrap(),
        ],
    ];
    for args in cases {
        let output = microslip()
            .env("XDG_CONFIG_HOME", dir.path())
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(
            stderr.contains("that is the file this command reads (--preset"),
            "{args:?}: {stderr}"
        );
        assert_eq!(std::fs::read_to_string(&preset).unwrap(), text, "{args:?}");
        assert_eq!(std::fs::read_to_string(&mine).unwrap(), text, "{args:?}");
    }
    // Another file is written as before.
    let other = dir.path().join("deck.inp");
    let output = microslip()
        .args([
            "deck",
            "ccx",
            "lap",
            "--preset",
            p,
            "-o",
            other.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(output.status.success());
    assert!(
        std::fs::read_to_string(&other)
            .unwrap()
            .contains("*HEADING")
    );
}

/// Issue 36: the lap continuum asked for with --continuum either answers with a finite, checked
/// Delta or exits non-zero with the reason on one line (2 for inputs it refuses at the door, as
/// every refusal; 1 for a solve that failed); the automatic one says it failed.
#[test]
fn the_lap_continuum_answers_or_says_why_not() {
    // mu = 2 at F = 20 kN: the contact forces' fixed point contracted too slowly (failed after
    // 60 iterations); it is solved now, within the envelope-free distance of the shear lag that
    // cover bending gives (beta = 0.175).
    let text = stdout_of(&["lap", "--continuum", "--set", "mu=2", "--set", "F=20000"]);
    let line = text
        .lines()
        .find(|l| l.contains("vs shear lag"))
        .expect("the continuum's Delta");
    let percent: f64 = line
        .split('(')
        .nth(1)
        .and_then(|r| r.split(" %").next())
        .and_then(|v| v.trim_start_matches('+').parse().ok())
        .expect("a percentage");
    assert!((0.0..10.0).contains(&percent), "{line}");
    // A friction so low that P alone slides the whole interface: refused with mu's least value.
    for force in ["F=1", "F=0"] {
        let error = failure(
            &["lap", "--continuum", "--set", "mu=1e-4", "--set", force],
            2,
        );
        assert!(
            error.contains("mu = 0.0001 is too small")
                && error.contains("mu must be at least 0.000166"),
            "{error}"
        );
    }
    // An overlap far shorter than the plates are thick: refused with L's least value.
    let error = failure(
        &["lap", "--continuum", "--set", "L=1e-6", "--set", "F=1e-4"],
        2,
    );
    assert!(
        error.contains("L = 1e-6 mm is too short") && error.contains("at least 0.0015 mm"),
        "{error}"
    );
    // Not asked for: the report is written (exit 0) and says the continuum failed.
    let text = stdout_of(&["lap", "--set", "L=1e-6", "--set", "F=1e-4"]);
    assert!(text.contains("2-D continuum (L13): FAILED"), "{text}");
}

// The generic `sweep` (issue 32): its own file, so that this one does not grow further.
#[path = "cli/generic_sweep.rs"]
mod generic_sweep;
