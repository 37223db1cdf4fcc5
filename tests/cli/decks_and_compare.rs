//! Presets of the other model, FE decks, `compare`, and a fit's unknown uncertainty.

use super::*;

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
    let text = compare_report(&["compare", "beam", &calculix_fixture("paper-beams.dat")]);
    assert!(text.contains("K_T = 600 MPa/mm"), "{text}");
    assert!(text.contains("What the FE points imply"), "{text}");
    let csv = compare_report(&[
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
    let json: serde_json::Value = serde_json::from_str(&compare_report(&[
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
    let json: serde_json::Value = serde_json::from_str(&compare_report(&[
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
    let text = compare_report(&["compare", "lap", &dat]);
    assert!(text.contains("clamped double-lap joint"), "{text}");
    assert!(text.contains("Verdict:"), "{text}");
    let csv = compare_report(&["compare", "lap", &dat, "--format", "csv"]);
    assert!(csv.starts_with("F_N,Delta_fe_mm,Delta_mm,diff,"), "{csv}");
    assert_eq!(csv.lines().count(), 5, "{csv}");
    // A CSV from any code, at the bundled joint's parameters; a force beyond F_gross = 6000 N
    // has no static state and is refused, naming the file and the range.
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("abaqus.csv");
    std::fs::write(&points, "F_N,Delta_mm\n1000,0.0047\n3000,0.0143\n").unwrap();
    let json: serde_json::Value = serde_json::from_str(&compare_report(&[
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
    let text = compare_report(&["compare", "beam", path]);
    for bad in ["inf", "NaN"] {
        assert!(!text.contains(bad), "{text}");
    }
    assert!(
        text.contains("n/a") && text.contains("relative difference is undefined"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&compare_report(&[
        "compare", "beam", path, "--format", "json",
    ]))
    .unwrap();
    assert!(json["rows"][0]["diff_euler"].is_null(), "{json}");
    assert!(json["rows"][1]["diff_euler"].is_f64(), "{json}");
    let csv = compare_report(&["compare", "beam", path, "--format", "csv"]);
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
    let text = compare_report(&["compare", "beam", path]);
    // The fit's line (the continuum's own lines say their resolution in "+-").
    let fit_line = text
        .lines()
        .find(|l| l.trim_start().starts_with("K_T = "))
        .unwrap_or_default();
    assert!(
        fit_line.contains("uncertainty unknown") && !fit_line.contains("+-"),
        "{text}"
    );
    assert!(!text.contains("z ="), "{text}");
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
    let json: serde_json::Value = serde_json::from_str(&compare_report(&[
        "compare", "beam", path, "--format", "json",
    ]))
    .unwrap();
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
