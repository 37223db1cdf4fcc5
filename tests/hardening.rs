//! What a hostile user found accepted, ignored or worded wrongly (issue 21, "Smaller, each seen"),
//! through the real binary: each case failed before its fix.

mod binary;
use binary::run;

/// A refusal: exit 2, one line on stderr, which is returned.
fn refused(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {out}{err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    err
}

#[test]
fn flags_that_were_accepted_and_ignored_are_refused_with_the_reason() {
    let err = refused(&["kt", "--nu", "0.6"]);
    assert!(err.contains("--kn"), "{err}");
    let err = refused(&["deck", "ccx", "plate", "--loads", "10,20"]);
    assert!(
        err.contains("--loads are the tip forces of a beam deck"),
        "{err}"
    );
    let err = refused(&["kt", "--tolerance", "1%", "--from", "300", "--to", "0"]);
    assert!(
        err.contains("invalid --to = 0: must not be below --from = 300 N"),
        "{err}"
    );
    let err = refused(&["plot", "w-vs-f", "--pin", "mu=0.2,mu=0.3"]);
    assert!(err.contains("mu is given twice"), "{err}");
}

#[test]
fn measured_curves_with_a_repeated_column_or_the_other_sign_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let twice = dir.path().join("twice.csv");
    std::fs::write(
        &twice,
        "F_N,w_mm,w_mm\n40,0.01,0.02\n80,0.02,0.03\n120,0.03,0.05\n",
    )
    .unwrap();
    let err = refused(&["fit", "beam", twice.to_str().unwrap()]);
    assert!(
        err.contains("column 'w_mm' appears more than once"),
        "{err}"
    );
    let negative = dir.path().join("negative.csv");
    std::fs::write(&negative, "F_N,w_mm\n40,-0.01\n80,-0.02\n120,-0.05\n").unwrap();
    let err = refused(&["fit", "beam", negative.to_str().unwrap()]);
    assert!(err.contains("flip the sign of the column"), "{err}");
}

#[test]
fn counts_take_the_readmes_notation_and_negative_values_reach_their_range_check() {
    let (code, out, err) = run(&[
        "sweep", "beam", "--from", "0", "--to", "1", "--points", "1e1",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 11, "a header and 10 rows");
    for args in [
        [
            "sweep", "beam", "--from", "0", "--to", "1", "--points", "-1",
        ],
        [
            "sweep", "beam", "--from", "0", "--to", "1", "--points", "2.5",
        ],
    ] {
        let err = refused(&args);
        assert!(
            err.contains("must be a whole number such as 101 or 1e8"),
            "{err}"
        );
    }
    let err = refused(&["kt", "--tolerance", "-1%"]);
    assert!(err.contains("invalid --tolerance '-1%'"), "{err}");
    // A loop's points per branch: no "or 1 when  = " with empty names.
    let err = refused(&["cycle", "--amplitude", "100", "--points", "0"]);
    assert_eq!(
        err,
        "microslip: invalid --points = 0: must be an integer in [2, 100000000]\n"
    );
}

#[test]
fn messages_say_units_and_plain_numbers() {
    // No root is an answer (exit 1), not a usage error.
    let (code, _, err) = run(&["solve", "beam", "--vary", "KT", "--target", "w=5"]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "microslip: no KT in [1e-6, 1e12] MPa/mm gives w(L) = 5 mm: over that range w(L) goes \
         from 0.0952381 mm to 0.0380952 mm (min 0.0380952 mm, max 0.0952381 mm)\n"
    );
    let (_, out, _) = run(&["beam", "--set", "F=-0", "--format", "json"]);
    assert!(!out.contains("-0.0"), "{out}");
    let (_, out, _) = run(&["beam", "--beam-theory", "timoshenko"]);
    assert!(out.contains("(modified by --beam-theory)"), "{out}");
    let err = refused(&["beam", "--set", "F=1e400"]);
    assert!(!err.contains("inf"), "{err}");
}

#[test]
fn a_held_value_is_said_once_and_one_measurement_is_singular() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("w.csv");
    std::fs::write(
        &data,
        "F_N,w_mm\n40,0.0114\n60,0.0171\n80,0.0229\n100,0.0383\n150,0.082\n200,0.132\n",
    )
    .unwrap();
    let (code, out, err) = run(&["fit", "beam", data.to_str().unwrap(), "--fix", "mu=0.3"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("mu  = 0.3: fixed\n"), "{out}");
}

/// Inside the accepted domain the FE solvers used to fail after 12 step cuts, with no chart and
/// no table; now each is refused at once with what to change.
#[test]
fn fe_solvers_refuse_what_they_cannot_solve_and_say_what_to_change() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("w.svg");
    for set in ["KT=1e12", "E=1e-4"] {
        let (code, _, err) = run(&[
            "plot",
            "w-vs-f",
            "--fe",
            "--set",
            set,
            "-o",
            svg.to_str().unwrap(),
        ]);
        // Refused input (issue 36, item 19: it exited 1, the code of "no answer").
        assert_eq!(code, 2, "{set}: {err}");
        assert!(err.contains("lower K_T to at most"), "{set}: {err}");
    }
    let err = refused(&["verify", "--quick", "--elements", "10"]);
    assert!(err.contains("must be an integer in [25, 800]"), "{err}");
    // The coarsest accepted mesh solves every case: a table (exit 1 when a quantity is above the
    // tolerance at so coarse a mesh, which the table says), never a solver failure.
    let (code, out, err) = run(&["verify", "--quick", "--elements", "25"]);
    assert!(code <= 1 && out.contains("worst rel. error"), "{out}{err}");
}

#[test]
fn a_log_chart_that_cannot_be_log_falls_back_to_linear_unless_asked() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("u.svg");
    let (code, _, err) = run(&[
        "plot",
        "u-vs-kt",
        "--set",
        "nu=0",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let err = refused(&[
        "plot",
        "u-vs-kt",
        "--set",
        "nu=0",
        "--y",
        "log",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert!(err.contains("log needs values > 0"), "{err}");
}

#[cfg(unix)]
#[test]
fn a_folder_name_with_control_characters_is_shown_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let evil = dir.path().join("g\u{1b}]0;PWNED\u{7}");
    let (code, out, err) = run(&["figures", "--no-fe", "--out", evil.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.chars().any(|c| c.is_control() && c != '\n'), "{out:?}");
    assert!(out.contains("\\x1b]0;PWNED\\x07"), "{out}");
}

/// `check` takes names as `--preset` does (issue: `check bench3` said "cannot read bench3", and
/// `check paper-beams` warned about a file that does not exist).
#[test]
fn check_takes_preset_names_as_preset_does() {
    let (code, out, err) = run(&["check", "paper-beams", "paper-plate"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("paper-beams: ok (bundled beam preset"),
        "{out}"
    );
    assert!(
        out.contains("paper-plate: ok (bundled plate preset"),
        "{out}"
    );
    assert!(!out.contains("warning"), "{out}");
    let (code, out, err) = run(&["check", "no-such-preset-here"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.contains(
            "no-such-preset-here: no such file, and no preset of that name (bundled: paper-beams"
        ),
        "{out}"
    );
    assert!(err.contains("1 of the files checked has problems"), "{err}");
    // A user preset by name is the file in the user folder, checked like any file.
    let config = tempfile::tempdir().unwrap();
    let folder = config.path().join("microslip/presets");
    std::fs::create_dir_all(&folder).unwrap();
    std::fs::write(folder.join("mine.toml"), "model = \"beam\"\nKT = -1\n").unwrap();
    let output = assert_cmd::Command::cargo_bin("microslip")
        .unwrap()
        .env("XDG_CONFIG_HOME", config.path())
        .args(["check", "mine"])
        .output()
        .unwrap();
    let out = String::from_utf8(output.stdout).unwrap();
    assert_eq!(output.status.code(), Some(1), "{out}");
    assert!(
        out.contains("mine.toml") && out.contains("KT = -1"),
        "{out}"
    );
}
