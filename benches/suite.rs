//! The suite's wall time against the sum of its runs' times, on the local pool at 1 and 2 solver
//! processes (issue 45): `cargo bench --bench suite`. Results and machine: BENCHMARKS.md.
//!
//! No CalculiX here: the solver is a shell script that sleeps a fixed time and hands back real
//! CalculiX results of the deck it was given (`tests/data/suite/`, as the suite's tests do), so
//! what is measured is the pool (its scheduling, the decks written, each run's results read and
//! judged, the result files written atomically), not ccx. With a sleeping solver the sum of the
//! runs is what one process would take; the pool at `jobs` processes should take that sum over
//! `jobs`, plus its own overhead, which this prints per run.
//!
//! Not a divan bench: one sample is a whole suite of seconds, and the figures wanted are the
//! ratio and the overhead, printed as a table of the median of a few samples.

use std::path::{Path, PathBuf};
use std::time::Instant;

use microslip::suite::Ladder;
use microslip::suite::run::{Executor, Options, run};

/// The runs of the suite: cases x 2 rungs (coarse, fine).
const CASES: usize = 6;
/// How long the stand-in solver sleeps per run (s).
const SLEEP: f64 = 0.5;
/// Samples per pool size (the median is printed).
const SAMPLES: usize = 3;

fn solver(dir: &Path) -> PathBuf {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/suite");
    let body = format!(
        "#!/bin/sh\njob=\"$2\"\n\
         mesh=$(sed -n 's/.*microslip-deck: .* mesh=\\([a-z]*\\) .*/\\1/p' \"$job.inp\")\n\
         sleep {SLEEP}\n\
         cp '{data}/'\"plain-$mesh\".dat \"$job.dat\"\n\
         cp '{data}/'\"plain-$mesh\".frd \"$job.frd\"\n",
        data = data.display()
    );
    let path = dir.join("sleeping-ccx");
    std::fs::write(&path, body).expect("a temporary folder");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755))
            .expect("a temporary folder");
    }
    path
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let program = solver(dir.path());
    let cases = dir.path().join("cases.toml");
    let list: String = (0..CASES)
        .map(|i| {
            format!("[[case]]\nname = \"plate-{i}\"\npreset = \"plate-bench\"\nmeshes = [\"coarse\", \"fine\"]\n")
        })
        .collect();
    std::fs::write(&cases, list).expect("a temporary folder");
    println!(
        "suite of {} runs, a solver sleeping {SLEEP} s each; median of {SAMPLES} samples",
        2 * CASES
    );
    println!("jobs | sum of runs (s) | wall (s) | wall / sum | overhead per run (ms)");
    let mut sample = 0;
    for jobs in [1, 2] {
        let (mut walls, mut sums) = (Vec::new(), Vec::new());
        for _ in 0..SAMPLES {
            sample += 1;
            let options = Options {
                cases: Some(cases.display().to_string()),
                ladder: Ladder::Quick,
                executor: Executor::Local,
                jobs: Some(jobs),
                workdir: Some(dir.path().join(format!("work-{sample}"))),
                resume: false,
                ccx: program.display().to_string(),
                microslip: None,
            };
            let started = Instant::now();
            let card = run(&options, &|| None, &|_| {}).expect("the suite runs");
            let wall = started.elapsed().as_secs_f64();
            assert_eq!(card.exit_code(), 0, "every case agrees");
            let sum: f64 = card
                .cases
                .iter()
                .flat_map(|c| &c.runs)
                .filter_map(|r| r.result.as_ref())
                .map(|r| r.solver_seconds)
                .sum();
            walls.push(wall);
            sums.push(sum);
        }
        let (wall, sum) = (median(walls), median(sums));
        let runs = (2 * CASES) as f64;
        println!(
            "{jobs} | {sum:.2} | {wall:.2} | {:.3} | {:.0}",
            wall / sum,
            1e3 * (wall - sum / jobs as f64) / runs * jobs as f64
        );
    }
}
