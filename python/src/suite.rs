//! `microslip.suite(...)`: `microslip suite` (`src/cli/suite.rs`) as a call that returns its
//! scorecard as data. The suite itself is the application's ([`microslip::suite::run::run`], the
//! one the command line runs), so the decks, the resume rule and the verdicts are the CLI's; here
//! only the door differs: keywords instead of flags, the exit status as data (`exit_code`, each
//! case's `verdict`), a `ValueError` for what the CLI refuses with exit 2, and Ctrl-C as the
//! rest of the wheel has it ([`interruptible`]): the running solvers are ended (each in its own
//! process group, as the CLI ends them on a signal) and `KeyboardInterrupt` is raised; a call
//! with the same `workdir` and `resume=True` carries on.

use std::path::PathBuf;
use std::sync::atomic::Ordering;

use microslip::suite::Ladder;
use microslip::suite::run::{self, Executor, Options, SuiteError};
use pyo3::prelude::*;
use serde_json::{Value, json};

use crate::errors::value_error;
use crate::features::report;
use crate::interrupt::interruptible;

/// The signal number a Ctrl-C stands for (SIGINT), as the CLI's stop reports it.
const SIGINT: i32 = 2;

/// The native half of `microslip.suite` (the Python half turns paths and lists into these
/// strings): runs the suite and returns its scorecard as a `microslip.Report`.
#[pyfunction]
#[pyo3(signature = (cases, quick, executor, jobs, workdir, resume, junit, html, ccx, microslip, progress))]
#[allow(clippy::too_many_arguments)]
pub fn suite<'py>(
    py: Python<'py>,
    cases: Option<String>,
    quick: bool,
    executor: &str,
    jobs: Option<usize>,
    workdir: Option<PathBuf>,
    resume: bool,
    junit: Option<PathBuf>,
    html: Option<PathBuf>,
    ccx: String,
    microslip: Option<PathBuf>,
    progress: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let executor = match executor {
        "local" => Executor::Local,
        "slurm" => Executor::Slurm,
        other => {
            return Err(value_error(format!(
                "invalid executor = {other:?}: must be \"local\" or \"slurm\""
            )));
        }
    };
    if jobs.is_some_and(|j| !(1..=256).contains(&j)) {
        return Err(value_error(format!(
            "invalid jobs = {}: must be in [1, 256]",
            jobs.unwrap_or_default()
        )));
    }
    if resume && workdir.is_none() {
        return Err(value_error(
            "resume=True needs the workdir of the suite to carry on",
        ));
    }
    let options = Options {
        cases,
        ladder: if quick { Ladder::Quick } else { Ladder::Full },
        executor,
        jobs,
        workdir,
        resume,
        ccx,
        microslip,
    };
    let ran = interruptible(py, |cancel| {
        let stop = || cancel.load(Ordering::SeqCst).then_some(SIGINT);
        let say = |line: &str| {
            if progress {
                eprintln!("{line}");
            }
        };
        let scorecard = run::run(&options, &stop, &say)?;
        let write = |path: &Option<PathBuf>, text: String| -> Result<(), SuiteError> {
            match path {
                Some(path) => microslip::file::write_atomic(path, text.as_bytes(), true)
                    .map_err(|e| SuiteError::Refused(format!("{}: {e}", path.display()))),
                None => Ok(()),
            }
        };
        write(&junit, scorecard.junit())?;
        write(&html, scorecard.html())?;
        Ok::<Value, SuiteError>(json!({
            "exit_code": scorecard.exit_code(),
            "agrees": scorecard.exit_code() == 0,
            "failing": scorecard.failing(),
            "solver_failure": scorecard.solver_failure.as_ref().map(|e| e.to_string()),
            "workdir": scorecard.workdir.display().to_string(),
            "seconds": scorecard.seconds,
            "cases": scorecard.json(),
        }))
    })?;
    match ran {
        Ok(value) => report(py, &value),
        // A stop without Ctrl-C cannot happen (only `interruptible` sets the flag); said as
        // what it would be.
        Err(SuiteError::Solver(e)) => Err(value_error(e)),
        Err(SuiteError::Refused(why)) => Err(value_error(why)),
    }
}
