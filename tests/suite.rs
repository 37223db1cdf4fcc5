//! `microslip suite` through the real binary and real child processes, without CalculiX: each
//! test writes a shell script that plays the solver (run as `SCRIPT -i job` in the run's folder,
//! as ccx is), handing back real CalculiX results of the deck it was given
//! (`tests/data/suite/`, made by its `make.sh` from the decks the suite writes) and counting its
//! invocations in a file.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

mod common;
use common::{microslip, script};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/suite")
}

/// A stand-in solver in `dir`: it reads the mesh rung from the deck's header, notes `start
/// RUNG` in `dir/count`, runs `before` (shell), copies the `VARIANT-RUNG` results (`plain-RUNG`
/// where the variant has none for the rung), then notes `done RUNG`.
fn solver(dir: &Path, variant: &str, before: &str) -> PathBuf {
    let count = dir.join("count");
    let data = data();
    let body = format!(
        "job=\"$2\"\n\
         mesh=$(sed -n 's/.*microslip-deck: .* mesh=\\([a-z]*\\) .*/\\1/p' \"$job.inp\")\n\
         echo \"start $mesh\" >> '{count}'\n\
         {before}\n\
         v={variant}; [ -e '{data}/'\"$v-$mesh\".dat ] || v=plain\n\
         cp '{data}/'\"$v-$mesh\".dat \"$job.dat\"\n\
         v={variant}; [ -e '{data}/'\"$v-$mesh\".frd ] || v=plain\n\
         cp '{data}/'\"$v-$mesh\".frd \"$job.frd\"\n\
         echo \"done $mesh\" >> '{count}'\n",
        count = count.display(),
        data = data.display(),
    );
    script(dir, "fake-ccx", &body)
}

fn count_lines(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join("count"))
        .unwrap_or_default()
        .lines()
        .map(str::to_string)
        .collect()
}

fn times(lines: &[String], line: &str) -> usize {
    lines.iter().filter(|l| *l == line).count()
}

fn suite(args: &[&str], program: &Path) -> Output {
    microslip()
        .arg("suite")
        .args(args)
        .args(["--jobs", "1", "--ccx"])
        .arg(program)
        .output()
        .unwrap()
}

/// A suite killed (SIGKILL, the whole process group) while its second run's solver runs, then
/// resumed: the run that was complete is not run again, the one killed runs from scratch, the
/// last runs once; every run's solver finished exactly once in all, and the scorecard is the
/// converged one.
#[test]
fn a_killed_suite_resumes_and_runs_each_run_once() {
    let dir = tempfile::tempdir().unwrap();
    // The fine rung's first solve hangs until it is killed; it notes its process group (its
    // own pid: the solver leads a group of its own) so that the test ends its `sleep` too.
    let hang = format!(
        "if [ \"$mesh\" = fine ] && [ ! -e '{0}/hung' ]; then echo $$ > '{0}/hung.tmp'; \
         mv '{0}/hung.tmp' '{0}/hung'; sleep 60; fi",
        dir.path().display()
    );
    let program = solver(dir.path(), "plain", &hang);
    let workdir = dir.path().join("work");
    let mut child = {
        use std::os::unix::process::CommandExt;
        microslip()
            .args([
                "suite",
                "--cases",
                "plate-bench",
                "--jobs",
                "1",
                "--workdir",
            ])
            .arg(&workdir)
            .arg("--ccx")
            .arg(&program)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .process_group(0)
            .spawn()
            .unwrap()
    };
    let started = Instant::now();
    while !dir.path().join("hung").exists() {
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "never reached the fine rung"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    let group = format!("-{}", child.id());
    assert!(
        Command::new("kill")
            .args(["-KILL", "--", &group])
            .status()
            .unwrap()
            .success()
    );
    child.wait().unwrap();
    let before = count_lines(dir.path());
    assert_eq!(before, ["start coarse", "done coarse", "start fine"]);
    assert!(workdir.join("plate-bench/coarse/result.json").exists());
    assert!(!workdir.join("plate-bench/fine/result.json").exists());

    // A new suite in the folder is refused: nothing is clobbered.
    let refused = suite(
        &[
            "--cases",
            "plate-bench",
            "--workdir",
            workdir.to_str().unwrap(),
        ],
        &program,
    );
    assert_eq!(refused.status.code(), Some(2), "{refused:?}");
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--resume"));

    // The suite resumed in the same folder with the same solver, `extra` flags added.
    let resume = |extra: &[&str]| {
        let mut args = vec![
            "--cases",
            "plate-bench",
            "--resume",
            "--workdir",
            workdir.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        suite(&args, &program)
    };
    let resumed = resume(&["--format", "json"]);
    let stderr = String::from_utf8_lossy(&resumed.stderr);
    assert_eq!(resumed.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("3 runs in 1 cases, 1 complete already, 2 to run"),
        "{stderr}"
    );
    let all = count_lines(dir.path());
    for rung in ["coarse", "fine", "finest"] {
        assert_eq!(times(&all, &format!("done {rung}")), 1, "{all:?}");
    }
    assert_eq!(times(&all, "start coarse"), 1, "{all:?}");
    assert_eq!(times(&all, "start fine"), 2, "{all:?}");
    let scorecard: serde_json::Value = serde_json::from_slice(&resumed.stdout).unwrap();
    let case = &scorecard[0];
    assert_eq!(case["case"], "plate-bench");
    assert_eq!(case["verdict"], "agrees");
    assert_eq!(case["runs"].as_array().unwrap().len(), 3);
    let quantity = &case["quantities"][0];
    assert_eq!(quantity["rungs_fraction"].as_array().unwrap().len(), 3);
    assert!(
        quantity["estimate"].as_f64().unwrap().abs() < quantity["bound_fraction"].as_f64().unwrap()
    );
    assert!(quantity["uncertainty"].as_f64().is_some());
    assert_eq!(case["stick_slope"]["verdict"], "agrees");

    // Resumed again, nothing runs.
    let again = resume(&[]);
    assert_eq!(again.status.code(), Some(0));
    assert_eq!(count_lines(dir.path()), all);

    // A finished run's stored judgement from an older program (a bound since recalibrated, a
    // difference since corrected): resumed, it is judged again from its output, not run again.
    let stored = workdir.join("plate-bench/finest/result.json");
    let mut old: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stored).unwrap()).unwrap();
    for quantity in old["quantities"].as_array_mut().unwrap() {
        quantity["difference"] = serde_json::json!(0.5);
        quantity["bound"] = serde_json::json!(1e-9);
    }
    old["agrees"] = serde_json::json!(false);
    std::fs::write(&stored, serde_json::to_string(&old).unwrap()).unwrap();
    let rejudged = resume(&["--format", "json"]);
    assert_eq!(rejudged.status.code(), Some(0), "{rejudged:?}");
    assert_eq!(count_lines(dir.path()), all);
    let rescored: serde_json::Value = serde_json::from_slice(&rejudged.stdout).unwrap();
    assert_eq!(rescored[0]["quantities"], case["quantities"]);

    // A finished run whose output is gone cannot be judged again: it runs again.
    std::fs::remove_file(workdir.join("plate-bench/finest/job.dat")).unwrap();
    let lost = resume(&[]);
    assert_eq!(lost.status.code(), Some(0), "{lost:?}");
    let all = count_lines(dir.path());
    assert_eq!(times(&all, "done finest"), 2, "{all:?}");

    // A run whose deck is not the one the suite writes (its case changed since) is run again.
    let coarse_deck = workdir.join("plate-bench/coarse/job.inp");
    let mut deck = std::fs::read_to_string(&coarse_deck).unwrap();
    deck.push_str("** edited\n");
    std::fs::write(&coarse_deck, deck).unwrap();
    let changed = resume(&[]);
    assert_eq!(changed.status.code(), Some(0));
    let last = count_lines(dir.path());
    assert_eq!(&last[all.len()..], ["start coarse", "done coarse"]);
}

/// The quick ladder (coarse, fine) of one case `name` of the bench plate, run with the stand-in
/// solver's `variant`: its exit code, its scorecard's text, its JUnit XML and its HTML page.
fn quick_case(variant: &str, name: &str) -> (Option<i32>, String, String, String) {
    let dir = tempfile::tempdir().unwrap();
    let program = solver(dir.path(), variant, "");
    let cases = dir.path().join("cases.toml");
    std::fs::write(
        &cases,
        format!(
            "[[case]]\nname = \"{name}\"\npreset = \"plate-bench\"\nmeshes = [\"coarse\", \"fine\"]\n"
        ),
    )
    .unwrap();
    let junit = dir.path().join("suite.xml");
    let html = dir.path().join("suite.html");
    let out = suite(
        &[
            "--cases",
            cases.to_str().unwrap(),
            "--workdir",
            dir.path().join("work").to_str().unwrap(),
            "--junit",
            junit.to_str().unwrap(),
            "--html",
            html.to_str().unwrap(),
        ],
        &program,
    );
    let xml = std::fs::read_to_string(&junit).unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        xml,
        std::fs::read_to_string(&html).unwrap(),
    )
}

/// A solver that used a stick slope 10 % above the deck's fails its case: exit 1, and a JUnit
/// failure that names the case and the numbers.
#[test]
fn a_stick_slope_ten_percent_off_fails_the_suite_with_its_numbers() {
    let (code, stdout, xml, html) = quick_case("off", "stiff-contact");
    assert_eq!(code, Some(1), "{stdout}");
    assert!(
        stdout.contains("stiff-contact (plate, preset plate-bench): does not agree"),
        "{stdout}"
    );
    assert!(xml.contains("tests=\"1\" failures=\"1\""), "{xml}");
    assert!(
        xml.contains("<testcase classname=\"microslip.suite.plate\" name=\"stiff-contact\""),
        "{xml}"
    );
    assert!(
        xml.contains("<failure message=\"stiff-contact: does not agree\""),
        "{xml}"
    );
    assert!(
        xml.contains("a stick slope of 11000 MPa/mm, +10.000 % from the deck's 10000 MPa/mm"),
        "{xml}"
    );
    // The stiffer contact's u(L) below the closed form's at the deck's K_T, on both rungs.
    assert!(xml.contains("at K_T = 10000 MPa/mm: rungs -"), "{xml}");
    // The HTML page: the case, its verdict, the slope used against the deck's, its plot.
    assert!(
        html.contains("stiff-contact <span class=\"does-not-agree\">does not agree</span>"),
        "{html}"
    );
    assert!(
        html.contains("11000 / 10000 (+10.000 %, does not agree)"),
        "{html}"
    );
    assert_eq!(html.matches("<svg ").count(), 1, "{html}");
}

/// A ladder whose coarse rung is 25 % off and whose fine rung is not (a mesh far too coarse for
/// the case): the change between them is larger than the envelope's bound, so the case is not
/// converged, exit 1, and its JUnit failure gives the rungs.
#[test]
fn a_coarse_ladder_that_is_not_converged_fails_the_suite() {
    let (code, stdout, xml, html) = quick_case("far", "too-coarse");
    assert_eq!(code, Some(1), "{stdout}");
    assert!(
        stdout.contains("too-coarse (plate, preset plate-bench): not converged"),
        "{stdout}"
    );
    assert!(
        xml.contains("<failure message=\"too-coarse: not converged\""),
        "{xml}"
    );
    // u(L) 25 % above the fine rung's +1.49 %: 1.0149 x 1.25 - 1 = +26.86 %.
    assert!(xml.contains("rungs +26.86"), "{xml}");
    assert!(xml.contains("two meshes"), "{xml}");
    assert!(
        html.contains("too-coarse <span class=\"not-converged\">not converged</span>"),
        "{html}"
    );
}

/// `bench` follows `compare`'s exit rule: the same solver as above, which used a stick slope
/// 10 % off the deck's, gives "does not agree" and exit 1; the plain one agrees, exit 0.
#[test]
fn bench_exits_1_when_its_verdict_is_not_agrees() {
    let dir = tempfile::tempdir().unwrap();
    for (variant, code, verdict) in [
        ("off", 1, "Verdict: does not agree"),
        ("plain", 0, "Verdict: agrees"),
    ] {
        let variant_dir = dir.path().join(variant);
        std::fs::create_dir(&variant_dir).unwrap();
        let program = solver(&variant_dir, variant, "");
        let out = microslip()
            .args([
                "bench",
                "ccx",
                "plate",
                "--preset",
                "plate-bench",
                "--workdir",
            ])
            .arg(variant_dir.join("work"))
            .arg("--ccx")
            .arg(&program)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(code), "{variant}: {stdout}");
        assert!(stdout.contains(verdict), "{variant}: {stdout}");
    }
}

/// The Slurm executor on a real single-node Slurm (`.ci/run` starts one with `.ci/slurm-start`
/// and sets `MICROSLIP_SLURM_TEST=1`; elsewhere this test says so and returns): the bench
/// plate's ladder as one job array of at most 2 tasks at once, each task running its run to its
/// result file; then a solver that fails on the finest rung: exit 3, and the scorecard names the
/// run and the task's output.
#[test]
fn a_suite_runs_as_a_slurm_job_array() {
    if std::env::var_os("MICROSLIP_SLURM_TEST").is_none() {
        eprintln!("not run: MICROSLIP_SLURM_TEST is not set (.ci/run sets it with a Slurm up)");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let program = solver(dir.path(), "plain", "");
    let workdir = dir.path().join("work");
    let out = microslip()
        .args([
            "suite",
            "--executor",
            "slurm",
            "--jobs",
            "2",
            "--format",
            "json",
        ])
        .args(["--cases", "plate-bench", "--workdir"])
        .arg(&workdir)
        .arg("--ccx")
        .arg(&program)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("Slurm job array"), "{stderr}");
    let scorecard: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(scorecard[0]["verdict"], "agrees");
    assert_eq!(
        scorecard[0]["quantities"][0]["rungs_fraction"]
            .as_array()
            .unwrap()
            .len(),
        3
    );
    let all = count_lines(dir.path());
    for rung in ["coarse", "fine", "finest"] {
        assert_eq!(times(&all, &format!("done {rung}")), 1, "{all:?}");
    }

    let failing = script(
        dir.path(),
        "failing-ccx",
        "grep -q 'mesh=finest' \"$2.inp\" && exit 1\nexec \"$0.real\" \"$@\"",
    );
    std::fs::copy(&program, dir.path().join("failing-ccx.real")).unwrap();
    let out = microslip()
        .args([
            "suite",
            "--executor",
            "slurm",
            "--cases",
            "plate-bench",
            "--workdir",
        ])
        .arg(dir.path().join("work2"))
        .arg("--ccx")
        .arg(&failing)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(
        stdout.contains("plate-bench (plate, preset plate-bench): not converged"),
        "{stdout}"
    );
    assert!(stdout.contains("run finest: Slurm array task"), "{stdout}");
    assert!(stdout.contains("slurm/task-2.out"), "{stdout}");
}
