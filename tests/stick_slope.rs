//! The stick slope an FE code used (issue 33, item 1), read from recorded CalculiX 2.20 output: no
//! ccx needed (CI runs it for real in `validation/calculix/validate.py`, "Stick slope used").
//!
//! `tests/data/stick_slope/` holds excerpts of the `.frd` files ccx wrote for decks of `microslip
//! deck ccx` (the last `CONTACT` block of each step, every third slave node, lines copied as ccx
//! wrote them) and the plate's `.dat`: the paper's beams at F = 40 N and the plate at K_T = 1e4
//! MPa/mm, each as written and with its `*FRICTION` stick slope edited by hand to +10 % and
//! -10 %. The expected slopes are the ones the runs were given (600, 660, 540; 1e4, 1.1e4, 9e3
//! MPa/mm), not values this code printed.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

use microslip::fe::stick_slope::{
    Friction, StickSlopeUsed, StickSlopeVerdict, read_frd_contact, read_interface_csv,
};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/stick_slope")
        .join(name)
}

fn read(name: &str) -> String {
    std::fs::read_to_string(fixture(name)).unwrap()
}

/// The paper's beams: mu = 0.3, P = 1 MPa.
const BEAM_FRICTION: Friction = Friction {
    coefficient: 0.3,
    nominal_pressure: 1.0,
};

fn beams(frd: &str, deck: f64) -> StickSlopeUsed {
    let steps = read_frd_contact(frd.as_bytes()).unwrap();
    StickSlopeUsed::measure(&steps, BEAM_FRICTION, deck)
}

#[test]
fn the_paper_beams_contact_used_the_decks_stick_slope() {
    let used = beams(&read("paper-beams.frd"), 600.0);
    // Step 1 (the pressure alone) and step 2 (F = 40 N), each with its sticking nodes.
    assert_eq!(
        used.steps.iter().map(|s| s.step).collect::<Vec<_>>(),
        [1, 2]
    );
    let head = used.headline().unwrap();
    assert_eq!(head.step, 2);
    assert!(head.sticking >= 90, "{head:?}");
    assert!((head.used / 600.0 - 1.0).abs() < 1e-4, "{head:?}");
    let (low, high) = head.spread();
    assert!(low.abs() < 1e-4 && high.abs() < 1e-4, "{head:?}");
    assert_eq!(used.verdict(), StickSlopeVerdict::Agrees);
}

#[test]
fn an_edited_stick_slope_is_seen_within_two_percent() {
    for (file, given) in [
        ("paper-beams-plus10.frd", 660.0),
        ("paper-beams-minus10.frd", 540.0),
    ] {
        let used = beams(&read(file), 600.0);
        let head = used.headline().unwrap();
        assert!((head.used / given - 1.0).abs() < 0.02, "{file}: {head:?}");
        assert_eq!(used.verdict(), StickSlopeVerdict::DoesNotAgree, "{file}");
    }
}

/// The sign convention: CalculiX's CSHEAR points along CSLIP at a sticking node. Output whose
/// slips are read with the wrong sign gives a negative slope, which does not agree.
#[test]
fn a_slip_read_with_the_wrong_sign_does_not_agree() {
    let frd = read("paper-beams.frd");
    let flipped: String = frd
        .lines()
        .map(|line| {
            if line.starts_with(" -1") && line.len() >= 13 + 36 {
                // Negate CSLIP1 and CSLIP2 (columns 2 and 3) in place.
                let mut out = line[..25].to_string();
                for column in 1..3 {
                    let text = &line[13 + 12 * column..25 + 12 * column];
                    let value: f64 = text.trim().parse().unwrap();
                    out.push_str(&format!("{:12.5E}", -value));
                }
                out.push_str(&line[49..]);
                out
            } else {
                line.to_string()
            }
        })
        .map(|l| l + "\n")
        .collect();
    let used = beams(&flipped, 600.0);
    let head = used.headline().unwrap();
    assert!(head.used < 0.0, "{head:?}");
    assert_eq!(used.verdict(), StickSlopeVerdict::DoesNotAgree);
}

/// The columns are found by their names: a block whose names say another order is read in that
/// order, so that reading the shear from the pressure's column is impossible without the output
/// saying so; and a block without a column is refused, naming it.
#[test]
fn a_wrong_column_does_not_pass() {
    let frd = read("paper-beams.frd");
    // Name CPRESS where CSHEAR1 is and the other way round: the values are now read as a
    // pressure of ~0.15 MPa and a shear of ~1 MPa, and no node sticks at 0.3 x 0.15 MPa.
    let swapped = frd
        .replace(" -5  CPRESS ", " -5  XXXXXX ")
        .replace(" -5  CSHEAR1", " -5  CPRESS ")
        .replace(" -5  XXXXXX ", " -5  CSHEAR1");
    let used = beams(&swapped, 600.0);
    assert_ne!(used.verdict(), StickSlopeVerdict::Agrees, "{used:?}");
    let missing = frd.replace(" -5  CSLIP2 ", " -5  OTHER  ");
    let error = read_frd_contact(missing.as_bytes())
        .unwrap_err()
        .to_string();
    assert!(error.contains("without CSLIP2"), "{error}");
}

#[test]
fn an_interface_csv_gives_the_slope_of_any_code() {
    // A profile with 5 sticking nodes at 600 MPa/mm and 2 at the limit mu P = 0.3 MPa.
    let csv = "x_mm,slip_mm,shear_MPa\n0,1e-5,6e-3\n10,2e-5,1.2e-2\n20,4e-5,2.4e-2\n\
               30,1e-4,6e-2\n40,2e-4,1.2e-1\n50,8e-4,0.3\n60,1.6e-3,0.3\n";
    let steps = read_interface_csv(csv).unwrap();
    let used = StickSlopeUsed::measure(&steps, BEAM_FRICTION, 600.0);
    let head = used.headline().unwrap();
    assert_eq!(head.sticking, 5);
    assert!((head.used / 600.0 - 1.0).abs() < 1e-12);
    assert_eq!(used.verdict(), StickSlopeVerdict::Agrees);
}

/// The plate's deck (the one `deck ccx plate --set KT=1e4` writes, kept as a fixture), with its
/// `*FRICTION` stick slope times `factor`, in a fresh folder with the recorded `.dat` and `.frd`.
fn plate_run(factor: f64, results: &str) -> (tempfile::TempDir, PathBuf) {
    let deck = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/calculix/plate-kt1e4.inp"),
    )
    .unwrap();
    let edited = deck.replacen(
        "*FRICTION\n0.3, 10000.0\n",
        &format!("*FRICTION\n0.3, {:?}\n", 10000.0 * factor),
        1,
    );
    assert_ne!(
        edited == deck,
        factor != 1.0,
        "the deck's *FRICTION card moved"
    );
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("run.inp"), edited).unwrap();
    for extension in ["dat", "frd"] {
        std::fs::copy(
            fixture(&format!("{results}.{extension}")),
            dir.path().join(format!("run.{extension}")),
        )
        .unwrap();
    }
    let dat = dir.path().join("run.dat");
    (dir, dat)
}

/// `microslip ARGS...`, run.
fn microslip<I: AsRef<std::ffi::OsStr>>(args: impl IntoIterator<Item = I>) -> std::process::Output {
    Command::cargo_bin("microslip")
        .unwrap()
        .args(args)
        .output()
        .unwrap()
}

/// `compare plate DAT --format FORMAT`: its report, and whether it exited 0. It exits 0 when its
/// verdict agrees and 1 when not (issue 46, item 6: it exited 0 on "does not agree"), with the
/// short verdict on stderr; any other code fails the test.
fn compare(dat: &Path, format: &str) -> (String, bool) {
    let output = microslip([
        "compare".as_ref(),
        "plate".as_ref(),
        dat.as_os_str(),
        "--format".as_ref(),
        format.as_ref(),
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    match output.status.code() {
        Some(0) => assert!(stderr.is_empty(), "{stderr}"),
        Some(1) => assert!(stderr.starts_with("microslip: verdict: "), "{stderr}"),
        other => panic!("exit {other:?}: {stderr}"),
    }
    (
        String::from_utf8(output.stdout).unwrap(),
        output.status.success(),
    )
}

#[test]
fn compare_says_an_edited_deck_does_not_agree_and_names_the_slope_used() {
    for (factor, results, verdict) in [
        (1.0, "plate-kt1e4", "agrees"),
        (1.1, "plate-kt1e4-plus10", "does not agree"),
        (0.9, "plate-kt1e4-minus10", "does not agree"),
    ] {
        let (_dir, dat) = plate_run(factor, results);
        let (report, exit_0) = compare(&dat, "json");
        let json: Value = serde_json::from_str(&report).unwrap();
        assert_eq!(
            exit_0,
            factor == 1.0,
            "{factor}: the exit code is the verdict's"
        );
        let run = &json["stick_slope"]["runs"][0];
        let used = run["KT_used_MPa_per_mm"].as_f64().unwrap();
        assert!(
            (used / (1e4 * factor) - 1.0).abs() < 0.02,
            "{factor}: {used}"
        );
        assert_eq!(run["verdict"], verdict, "{factor}");
        assert_eq!(json["stick_slope"]["verdict"], verdict, "{factor}");
        assert_eq!(json["verdict"]["agrees"], factor == 1.0, "{factor}");
        assert_eq!(json["kinematics"]["kinematics"], "linear");
        let (text, text_exit_0) = compare(&dat, "text");
        assert_eq!(text_exit_0, exit_0);
        let closing = text.lines().last().unwrap();
        assert!(
            closing.starts_with(&format!("Verdict: {verdict}.")),
            "{factor}: {closing}"
        );
        assert!(closing.contains("kinematics: linear geometry"), "{closing}");
        if factor != 1.0 {
            assert!(
                text.contains("it was edited after microslip wrote it"),
                "{text}"
            );
        }
    }
}

/// Issue 48: the beams state an envelope per kinematics. A deck whose steps are linear geometry
/// is judged against (V2L), the linear-geometry envelope, wider beyond first slip than (V2), the
/// `NLGEOM` one its twin deck is judged against; each report names the one it applied.
#[test]
fn a_linear_geometry_beam_deck_is_judged_against_its_own_envelope() {
    let calculix = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/calculix");
    let deck = std::fs::read_to_string(calculix.join("paper-beams.inp")).unwrap();
    assert!(deck.contains("*STEP, NLGEOM, INC=1000"));
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in [
        ("nlgeom", deck.clone()),
        ("linear", deck.replace("*STEP, NLGEOM,", "*STEP,")),
    ] {
        std::fs::write(dir.path().join(format!("{name}.inp")), text).unwrap();
        std::fs::copy(
            calculix.join("paper-beams.dat"),
            dir.path().join(format!("{name}.dat")),
        )
        .unwrap();
    }
    let run = |name: &str, format: &str| {
        let dat = dir.path().join(format!("{name}.dat"));
        let output = microslip([
            "compare".as_ref(),
            "beam".as_ref(),
            dat.as_os_str(),
            "--format".as_ref(),
            format.as_ref(),
        ]);
        assert!(output.status.success());
        String::from_utf8(output.stdout).unwrap()
    };
    let nlgeom: Value = serde_json::from_str(&run("nlgeom", "json")).unwrap();
    assert_eq!(nlgeom["kinematics"]["kinematics"], "nlgeom");
    assert_eq!(nlgeom["kinematics"]["envelope_applies"], true);
    assert_eq!(nlgeom["kinematics"]["envelope_calibrated_on"], "nlgeom");
    assert_eq!(
        nlgeom["kinematics"]["envelopes_calibrated_on"],
        serde_json::json!(["nlgeom", "linear"])
    );
    assert_eq!(nlgeom["rows"][0]["verdict"]["envelope"], "within");
    let linear: Value = serde_json::from_str(&run("linear", "json")).unwrap();
    assert_eq!(linear["kinematics"]["kinematics"], "linear");
    assert_eq!(linear["kinematics"]["envelope_applies"], true);
    assert_eq!(linear["kinematics"]["envelope_calibrated_on"], "linear");
    let bound = |report: &Value, row: usize| {
        report["rows"][row]["shear_corrected_within_fraction"]
            .as_f64()
            .unwrap()
    };
    let rows = linear["rows"].as_array().unwrap();
    let mut wider = 0;
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row["verdict"]["envelope"], "within", "{row}");
        // The same in stick, wider where the closed form slides (the paper's loads reach
        // 2.5 F_thre).
        assert!(bound(&linear, i) >= bound(&nlgeom, i), "{row}");
        if bound(&linear, i) > 1.01 * bound(&nlgeom, i) {
            wider += 1;
        }
    }
    assert!(
        wider >= 1 && wider < rows.len(),
        "{wider} of {}",
        rows.len()
    );
    let text = run("linear", "text");
    assert!(
        text.contains("judged against the envelope calibrated on such runs"),
        "{text}"
    );
    let closing = text.lines().last().unwrap();
    assert!(
        closing.ends_with("kinematics: linear geometry."),
        "{closing}"
    );
}

/// Any FE code: a CSV result with its interface profile (`--interface`) and its kinematics
/// (`--kinematics`), which a CSV cannot say itself.
#[test]
fn a_csv_result_takes_its_interface_profile_and_kinematics_from_flags() {
    let dir = tempfile::tempdir().unwrap();
    let profile = dir.path().join("interface.csv");
    // The paper's beams (mu P = 0.3 MPa): 5 nodes sticking at 660 MPa/mm, 2 at the limit.
    std::fs::write(
        &profile,
        "x_mm,slip_mm,shear_MPa\n0,1e-5,6.6e-3\n10,2e-5,1.32e-2\n20,4e-5,2.64e-2\n\
         30,1e-4,6.6e-2\n40,2e-4,1.32e-1\n50,8e-4,0.3\n60,1.6e-3,0.3\n",
    )
    .unwrap();
    let results =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/reports/inputs/compare-beam.csv");
    let output = microslip([
        "compare".as_ref(),
        "beam".as_ref(),
        results.as_os_str(),
        "--interface".as_ref(),
        profile.as_os_str(),
        "--kinematics".as_ref(),
        "linear".as_ref(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    // The verdict does not agree: exit 1, the report on stdout all the same.
    assert_eq!(
        output.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let json: Value = serde_json::from_slice(&output.stdout).unwrap();
    let run = &json["stick_slope"]["runs"][0];
    let used = run["KT_used_MPa_per_mm"].as_f64().unwrap();
    assert!((used / 660.0 - 1.0).abs() < 1e-9, "{used}");
    assert_eq!(run["verdict"], "does not agree");
    assert_eq!(json["verdict"]["agrees"], false);
    assert_eq!(json["kinematics"]["kinematics"], "linear");
    // The beams state a linear-geometry envelope too (V2L, issue 48).
    assert_eq!(json["kinematics"]["envelope_applies"], true);
    assert_eq!(json["kinematics"]["envelope_calibrated_on"], "linear");
    // A .dat says both itself: --interface is refused there.
    let dat = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/calculix/paper-beams.dat");
    let refused = microslip([
        "compare".as_ref(),
        "beam".as_ref(),
        dat.as_os_str(),
        "--interface".as_ref(),
        profile.as_os_str(),
    ]);
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--interface is for CSV results"));
}

/// The beams' continuum is small-strain: a run said to be `NLGEOM` (or not said) is judged with
/// the measured allowance on top of the 0.25 % tolerance (docs/theory.md (BC4a)), a linear one
/// without; the JSON says the allowance per row, and it is larger beyond first slip.
#[test]
fn the_beams_continuum_verdict_allows_for_nlgeom_and_not_for_linear_geometry() {
    let results =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/reports/inputs/compare-beam.csv");
    let allowances = |kinematics: Option<&str>| -> Vec<f64> {
        let mut args: Vec<&std::ffi::OsStr> = vec![
            "compare".as_ref(),
            "beam".as_ref(),
            results.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
        ];
        if let Some(k) = kinematics {
            args.push("--kinematics".as_ref());
            args.push(k.as_ref());
        }
        let output = microslip(args);
        let json: Value = serde_json::from_slice(&output.stdout).unwrap();
        // Exit 0 exactly when the verdict agrees (issue 46, item 6).
        assert_eq!(
            output.status.code(),
            Some(if json["verdict"]["agrees"] == true {
                0
            } else {
                1
            }),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        json["rows"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|r| r["continuum"].is_object())
            .map(|r| {
                let c = &r["continuum"];
                let (tolerance, allowance) = (
                    c["tolerance_fraction"].as_f64().unwrap(),
                    c["allowance_fraction"].as_f64().unwrap(),
                );
                assert!((tolerance - 0.0025 - allowance).abs() < 1e-15, "{c}");
                allowance
            })
            .collect()
    };
    let linear = allowances(Some("linear"));
    assert!(linear.iter().all(|a| *a == 0.0), "{linear:?}");
    let nlgeom = allowances(Some("nlgeom"));
    assert_eq!(allowances(None), nlgeom);
    // The paper's beams: (P/E)(L/h)^2 (0.06 + tanh(kL)/kL) = 0.0396 % in stick.
    assert!((nlgeom[0] - 3.96e-4).abs() < 1e-6, "{nlgeom:?}");
    assert!(nlgeom.last().unwrap() > &nlgeom[0], "{nlgeom:?}");
}

/// A run whose contact locked (issue 45): the beams' finest deck can press its clamp corner shut
/// (267 MPa under P = 1 to 2 MPa, docs/theory.md (BC4a)), and its w(L) then reads like any other
/// run's. The recorded paper run peaks at 1.47 MPa (P = 1 MPa); one node of its `.frd` pressed to
/// 267 MPa makes `compare` say "does not agree" (exit 1) naming the node; 4.9 MPa does not.
#[test]
fn compare_says_a_run_whose_contact_locked_is_no_judge() {
    let calculix = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/calculix");
    let frd = read("paper-beams.frd");
    let sound = " -1      1176-3.85403E-07 1.61369E-05 6.02452E-20 8.09347E-01";
    assert_eq!(frd.matches(sound).count(), 1);
    for (pressure, locked) in [
        (None, false),
        (Some(" 4.90000E+00"), false),
        (Some(" 2.67000E+02"), true),
    ] {
        let dir = tempfile::tempdir().unwrap();
        for extension in ["inp", "dat"] {
            std::fs::copy(
                calculix.join(format!("paper-beams.{extension}")),
                dir.path().join(format!("run.{extension}")),
            )
            .unwrap();
        }
        let edited = match pressure {
            None => frd.clone(),
            Some(p) => frd.replace(sound, &format!("{}{p}", &sound[..sound.len() - 12])),
        };
        std::fs::write(dir.path().join("run.frd"), edited).unwrap();
        let dat = dir.path().join("run.dat");
        let run = |format: &str| {
            microslip([
                "compare".as_ref(),
                "beam".as_ref(),
                dat.as_os_str(),
                "--format".as_ref(),
                format.as_ref(),
            ])
        };
        let output = run("json");
        assert_eq!(
            output.status.code(),
            Some(if locked { 1 } else { 0 }),
            "{pressure:?}"
        );
        let json: Value = serde_json::from_slice(&output.stdout).unwrap();
        let slope = &json["stick_slope"]["runs"][0];
        let peak = slope["peak_pressure_MPa"].as_f64().unwrap();
        let expected = pressure.map_or(1.47229, |p| p.trim().parse().unwrap());
        assert!((peak - expected).abs() < 1e-9, "{peak}");
        assert_eq!(slope["contact_locked"].is_string(), locked, "{slope}");
        if locked {
            assert_eq!(json["verdict"]["agrees"], false, "{}", json["verdict"]);
            let text = String::from_utf8(run("text").stdout).unwrap();
            assert!(
                text.contains(
                    "contact: its contact locked: a contact pressure of 267 MPa (267 times the \
                     interface's 1 MPa) at node 1176"
                ),
                "{text}"
            );
            assert!(
                text.lines()
                    .last()
                    .unwrap()
                    .starts_with("Verdict: does not agree.")
            );
        }
    }
}
