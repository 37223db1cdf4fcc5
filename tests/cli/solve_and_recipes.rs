//! `solve`, commands that do not use the force, the recipes of the guide.

use super::*;

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
    let compare = compare_report(&[
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
    let text = compare_report(&["compare", "plate", csv.to_str().unwrap()]);
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
