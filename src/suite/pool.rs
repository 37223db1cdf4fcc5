//! The local executor: a bounded pool of solver processes. At most `jobs` runs at once (default:
//! the cores less one, at least one: the machine stays usable), each a thread that writes its
//! deck, runs the solver through [`crate::fe::run::run_ccx`] (its own process group, ended with
//! us: on a stop, an error, a panic or our death) and writes the run's result file.
//!
//! Why threads around blocking runs and not an async runtime: the solver is the work, a thread
//! per running solver costs nothing beside it, and `run_ccx` already polls its stop flag; a
//! stop (a signal to microslip) ends every running solver within one poll and starts no other.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use super::result::{self, RunResult};
use super::{JOB, RunSpec};
use crate::fe::run::{RunError, RunFiles, run_ccx};
use crate::problems::ModelKind;

/// The default number of solver processes at once: the cores less one, at least one.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .saturating_sub(1)
        .max(1)
}

/// How far a suite is, for its progress line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    /// Runs finished (by this process or an earlier one, resumed).
    pub done: usize,
    /// Runs whose solver is running.
    pub running: usize,
    /// Runs not started yet.
    pub queued: usize,
}

/// One run ready to go: its spec, its case's problem and name, its deck and its folder.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// The run.
    pub spec: RunSpec,
    /// Its case's name.
    pub case: String,
    /// Its case's problem.
    pub kind: ModelKind,
    /// The deck's text.
    pub deck: String,
    /// `<workdir>/<case>/<run>`.
    pub folder: PathBuf,
}

/// A run's outcome: its result, or why it has none.
pub type Outcome = Result<RunResult, RunFailure>;

/// Why a run gave no result.
#[derive(Debug, thiserror::Error)]
pub enum RunFailure {
    /// The solver could not run, failed, or was stopped.
    #[error(transparent)]
    Solver(#[from] RunError),
    /// Its results could not be read or judged, or its folder not written.
    #[error("{0}")]
    Judge(String),
}

/// Runs `runs` on at most `jobs` solver processes of `program` at once, in order of the list;
/// `stop` is asked between runs and while each solver runs (a signal: `Some(number)`).
/// `progress` is told of each run that finishes, with the counts after it (`done_before`: runs
/// complete before this call, counted as done). Returns each run's outcome, in the list's
/// order; `None` for a run never started (a stop came first).
pub fn run_all(
    program: &Path,
    runs: &[Prepared],
    jobs: usize,
    done_before: usize,
    stop: &(dyn Fn() -> Option<i32> + Sync),
    progress: &(dyn Fn(&Prepared, &Outcome, Counts) + Sync),
) -> Vec<Option<Outcome>> {
    let next = Mutex::new(0usize);
    let counts = Mutex::new(Counts {
        done: done_before,
        running: 0,
        queued: runs.len(),
    });
    let outcomes: Mutex<Vec<Option<Outcome>>> = Mutex::new(runs.iter().map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..jobs.max(1).min(runs.len().max(1)) {
            scope.spawn(|| {
                loop {
                    if stop().is_some() {
                        return;
                    }
                    let index = {
                        let mut next = next.lock().unwrap_or_else(|e| e.into_inner());
                        let index = *next;
                        *next += 1;
                        index
                    };
                    let Some(run) = runs.get(index) else { return };
                    {
                        let mut c = counts.lock().unwrap_or_else(|e| e.into_inner());
                        c.queued -= 1;
                        c.running += 1;
                    }
                    let outcome = execute(program, run, stop);
                    let now = {
                        let mut c = counts.lock().unwrap_or_else(|e| e.into_inner());
                        c.running -= 1;
                        if outcome.is_ok() {
                            c.done += 1;
                        }
                        *c
                    };
                    progress(run, &outcome, now);
                    outcomes.lock().unwrap_or_else(|e| e.into_inner())[index] = Some(outcome);
                }
            });
        }
    });
    outcomes.into_inner().unwrap_or_else(|e| e.into_inner())
}

/// One run from scratch: its folder emptied (a run without a result file left nothing to
/// keep), the deck written, the solver run, the output judged, the result file written.
fn execute(program: &Path, run: &Prepared, stop: &(dyn Fn() -> Option<i32> + Sync)) -> Outcome {
    let files = prepare(run)?;
    solve_and_judge(program, &files, &Task::of(run), stop)
}

/// What a run's folder holds besides its deck, for a solver started elsewhere (a Slurm array
/// task: `microslip suite --run-one FOLDER`): its problem and how it stands in its ladder.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Task {
    /// The problem's key.
    pub model: String,
    /// The run's name.
    pub run: String,
    /// Its mesh's name.
    pub mesh: String,
    /// The increment given to its deck.
    pub increment: Option<f64>,
}

/// The file of a run's [`Task`] in its folder.
pub const TASK_FILE: &str = "task.json";

impl Task {
    /// The task of `run`.
    pub fn of(run: &Prepared) -> Task {
        Task {
            model: run.kind.name().to_string(),
            run: run.spec.name.clone(),
            mesh: run.spec.mesh.name().to_string(),
            increment: run.spec.increment,
        }
    }
}

fn folder_error(folder: &Path) -> impl Fn(std::io::Error) -> RunFailure + '_ {
    move |e| RunFailure::Judge(format!("{}: {e}", folder.display()))
}

/// `run`'s folder emptied and made again, with its deck and its task file.
///
/// # Errors
/// The file system's.
pub fn prepare(run: &Prepared) -> Result<RunFiles, RunFailure> {
    let fail = folder_error(&run.folder);
    if run.folder.exists() {
        std::fs::remove_dir_all(&run.folder).map_err(&fail)?;
    }
    std::fs::create_dir_all(&run.folder).map_err(&fail)?;
    let files = RunFiles::new(&run.folder, JOB);
    let task =
        serde_json::to_string(&Task::of(run)).map_err(|e| RunFailure::Judge(e.to_string()))?;
    let task_path = run.folder.join(TASK_FILE);
    crate::file::write_new_files(&[
        (files.deck.as_path(), run.deck.as_bytes()),
        (task_path.as_path(), task.as_bytes()),
    ])
    .map_err(&fail)?;
    Ok(files)
}

/// The prepared run in `folder` ([`prepare`]) run to its result file: what a Slurm array task
/// does.
///
/// # Errors
/// Its task file unreadable, the solver's failure, or results that cannot be judged.
pub fn run_prepared(
    program: &Path,
    folder: &Path,
    stop: &(dyn Fn() -> Option<i32> + Sync),
) -> Outcome {
    let text = std::fs::read_to_string(folder.join(TASK_FILE)).map_err(folder_error(folder))?;
    let task: Task = serde_json::from_str(&text)
        .map_err(|e| RunFailure::Judge(format!("{}: {e}", folder.join(TASK_FILE).display())))?;
    solve_and_judge(program, &RunFiles::new(folder, JOB), &task, stop)
}

/// The solver on the deck of `files`, its output judged as the task's problem judges it, the
/// result file written.
fn solve_and_judge(
    program: &Path,
    files: &RunFiles,
    task: &Task,
    stop: &(dyn Fn() -> Option<i32> + Sync),
) -> Outcome {
    let kind: ModelKind = task
        .model
        .parse()
        .map_err(|e: crate::problems::UnknownModel| RunFailure::Judge(e.to_string()))?;
    let started = Instant::now();
    run_ccx(
        program,
        files,
        Duration::from_millis(100),
        &mut |_| {},
        &|| stop(),
    )?;
    let solver_seconds = started.elapsed().as_secs_f64();
    let judged = result::judge(kind, &files.results).map_err(RunFailure::Judge)?;
    let done = RunResult {
        run: task.run.clone(),
        mesh: task.mesh.clone(),
        increment: task.increment,
        quantities: judged.quantities,
        stick_slope: judged.stick_slope,
        agrees: judged.agrees,
        verdict: judged.verdict,
        contact_locked: judged.contact_locked,
        solver_seconds,
    };
    result::write(&files.folder, &done).map_err(folder_error(&files.folder))?;
    Ok(done)
}
