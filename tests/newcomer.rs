//! What a newcomer stumbled on (issue 25), through the real binary. `microslip bench ccx`: one
//! command from parameters to a comparison, tested here without CalculiX (it is never required by
//! `cargo test`): a missing ccx, a failing one and a work folder that holds a job's files; CI runs
//! the real ccx through it (.ci/run). `figures` for the user's own bench.

mod binary;
use binary::run;

#[test]
fn a_missing_ccx_says_how_to_install_it_and_how_to_do_without() {
    let dir = tempfile::tempdir().unwrap();
    let work = dir.path().join("work");
    let work = work.to_str().unwrap();
    let (code, out, err) = run(&[
        "bench",
        "ccx",
        "plate",
        "--workdir",
        work,
        "--ccx",
        "microslip-test-no-such-ccx",
    ]);
    // The external solver's own code (issue 36, item 19: it was 2, a usage error's).
    assert_eq!(code, 3, "{err}");
    assert!(out.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("`microslip-test-no-such-ccx` was not found"),
        "{err}"
    );
    assert!(err.contains("apt-get install calculix-ccx"), "{err}");
    assert!(err.contains("microslip compare"), "{err}");
    // The deck stays for a run by hand.
    let deck = std::fs::read_to_string(dir.path().join("work/plate.inp")).unwrap();
    assert!(deck.contains("squeezed plate"));
}

#[test]
fn a_failing_ccx_gives_its_exit_and_the_tail_of_its_log() {
    let dir = tempfile::tempdir().unwrap();
    let work = dir.path().join("work");
    // `false` stands for a ccx that fails without results.
    let (code, out, err) = run(&[
        "bench",
        "ccx",
        "beam",
        "--workdir",
        work.to_str().unwrap(),
        "--ccx",
        "false",
    ]);
    assert_eq!(code, 3, "{err}");
    assert!(out.is_empty());
    assert!(err.contains("ccx failed (exit status: 1)"), "{err}");
    assert!(err.contains("beam.log"), "{err}");
    assert!(work.join("beam.log").is_file());
}

#[test]
fn a_work_folder_that_holds_the_jobs_files_is_refused_and_left_alone() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("beam.dat"), "a user's results").unwrap();
    let (code, out, err) = run(&[
        "bench",
        "ccx",
        "beam",
        "--workdir",
        dir.path().to_str().unwrap(),
        "--ccx",
        "false",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(err.contains("beam.dat exists"), "{err}");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("beam.dat")).unwrap(),
        "a user's results"
    );
    assert!(!dir.path().join("beam.inp").exists());
}

#[test]
fn a_bench_refuses_what_deck_refuses_before_writing_anything() {
    let dir = tempfile::tempdir().unwrap();
    let work = dir.path().join("work");
    let (code, _, err) = run(&[
        "bench",
        "ccx",
        "plate",
        "--loads",
        "1,2",
        "--workdir",
        work.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--loads are the tip forces of a beam deck"),
        "{err}"
    );
    assert!(!work.exists());
}

#[test]
fn progress_counts_load_steps_from_ccx_total_time() {
    use microslip::fe::run::Progress;
    use microslip::report::text::ccx_progress;
    use std::time::Duration;
    let at = |total_time| Progress {
        elapsed: Duration::from_secs(12),
        steps: 4,
        total_time,
        increments: 0,
    };
    assert_eq!(ccx_progress(&at(None)), "ccx: 12 s, setting up");
    // Every step of the decks lasts 1: total time 1 ends step 1, 2.5 is half of step 3.
    assert_eq!(
        ccx_progress(&at(Some(1.0))),
        "ccx: 12 s, load step 1 of 4 (25 %)"
    );
    assert_eq!(
        ccx_progress(&at(Some(2.5))),
        "ccx: 12 s, load step 3 of 4 (62 %)"
    );
    assert_eq!(
        ccx_progress(&at(Some(9.0))),
        "ccx: 12 s, load step 4 of 4 (100 %)"
    );
}

/// `figures` for the user's own bench (issue: it only knew the paper): every chart of the
/// preset's problem, the values in each caption, the command that redraws each.
#[test]
fn figures_draw_every_chart_of_your_bench_with_its_values_in_the_captions() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    let (code, stdout, err) = run(&[
        "figures",
        "--out",
        out.to_str().unwrap(),
        "--no-fe",
        "--preset",
        "paper-plate",
        "--set",
        "KT=3e5",
    ]);
    assert_eq!(code, 0, "{err}");
    for stem in ["plate-u-vs-kt", "plate-xr-vs-mu", "plate-pressure"] {
        let svg = std::fs::read_to_string(out.join(format!("{stem}.svg"))).unwrap();
        assert!(svg.starts_with("<svg"), "{stem}");
        assert!(out.join(format!("{stem}.csv")).is_file(), "{stem}");
        assert!(stdout.contains(&format!("{stem}.svg")), "{stdout}");
    }
    let page = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert_eq!(page.matches("<figure ").count(), 3, "{page}");
    assert_eq!(page.matches("KT = 300000 MPa/mm").count(), 4, "{page}");
    assert!(page.contains("L = 10 mm, tp = 0.2 mm"), "{page}");
    assert!(
        page.contains(
            "<code>microslip plot u-vs-kt --preset paper-plate --set KT=3e5 --y log</code>"
        ),
        "{page}"
    );
    // A bad value is refused before anything is written.
    let refused = dir.path().join("refused");
    let (code, _, err) = run(&[
        "figures",
        "--out",
        refused.to_str().unwrap(),
        "--preset",
        "paper-plate",
        "--set",
        "KT=-1",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(!refused.exists());
}

/// `--beam-theory` alone chooses a bench too: the figures are the paper beams' under Timoshenko,
/// not the paper's set without a word.
#[test]
fn figures_with_only_a_beam_theory_draw_that_bench() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    let (code, _, err) = run(&[
        "figures",
        "--out",
        out.to_str().unwrap(),
        "--no-fe",
        "--beam-theory",
        "timoshenko",
    ]);
    assert_eq!(code, 0, "{err}");
    let page = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        page.contains("microslip figures --beam-theory timoshenko"),
        "{page}"
    );
    assert!(out.join("beam-w-vs-f.svg").is_file());
    assert!(!out.join("plate-u-vs-kt.svg").exists());
}

/// `sweep cylinder`: every problem of the registry is a subcommand of `sweep` (issue 43, item
/// 3; it used to be pointed to `--model`), writing what `sweep --model cylinder` writes; a word
/// that is no problem is refused with the problem it is a slip of.
#[test]
fn a_problem_given_as_a_subcommand_is_its_sweep() {
    let (code, out, err) = run(&[
        "sweep", "cylinder", "--from", "0", "--to", "100", "--points", "11",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Q_N_per_mm,"), "{out}");
    let (code, _, err) = run(&["sweep", "cylindre"]);
    assert_eq!(code, 2, "{err}");
    assert!(!err.contains("--model"), "{err}");
    assert!(
        err.contains("did you mean") && err.contains("'cylinder'"),
        "{err}"
    );
    let (code, generic, err) = run(&["sweep", "--model", "cylinder", "--from", "0", "--to", "100"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(generic, out);
}
