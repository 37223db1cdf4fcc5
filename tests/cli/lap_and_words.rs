//! The lap joint, the words every output uses, and outputs that never clobber an input.

use super::*;

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
    assert!(help.contains("lap: F_N,Delta_mm"), "{help}");
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

/// A value the user never typed, refused because a value set moved its range, is said to be
/// the preset's (issue 47): `--set P=1e-6` leaves the pad's Q = 300 N/mm beyond mu P.
#[test]
fn a_refused_preset_value_is_blamed_on_the_preset_not_the_user() {
    let stderr = failure(&["cylinder", "--set", "P=1e-6"], 2);
    assert!(
        stderr.contains("invalid Q = 300: must be in [0, 6e-7] N/mm")
            && stderr
                .contains("Q = 300 is the value of cylinder-steel-pad, not one given with --set")
            && stderr.contains("the values set (P) moved its range")
            && stderr.contains("--set Q=..."),
        "{stderr}"
    );
    // A value the user typed is refused as before, without the note.
    let stderr = failure(&["cylinder", "--set", "Q=900"], 2);
    assert!(!stderr.contains("not one given with --set"), "{stderr}");
}
