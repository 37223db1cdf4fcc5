//! A whole suite, from its options to its scorecard: the cases resolved, every run's deck written
//! before anything runs (a refused case costs no solver time), the work folder claimed, the runs
//! already complete kept (`resume`), the others run on the executor, each case scored.
//!
//! Why here and not in the command line: the command line (`microslip suite`) and the Python face
//! (`microslip.suite(...)`) run the same suite, so the decks, the resume rule, the progress lines
//! and the verdicts cannot differ between them; each keeps only its own door (flags and exit codes;
//! keywords, exceptions and Ctrl-C). What stops a suite (a signal to the program, Ctrl-C in
//! Python) and where its progress goes are the caller's, as closures.

use std::path::{Path, PathBuf};
use std::time::Instant;

use super::pool::{self, Counts, Prepared, RunFailure};
use super::result::{self, RunResult};
use super::score::{self, CaseScore};
use super::{Case, Ladder, RunSpec};
use crate::fe::face::{DeckError, DeckRequest};
use crate::fe::header::StickSlope;
use crate::fe::ladder::Verdict;
use crate::fe::run::RunError;
use crate::problems::ModelKind;
use crate::problems::inputs::Model;
use crate::report::face::{Faces, ForProblem, for_problem};

/// Where the runs go.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Executor {
    /// A bounded pool of solver processes on this machine ([`pool`]).
    Local,
    /// One Slurm job array ([`super::slurm`]).
    Slurm,
}

/// What a suite runs and how: the command line's flags, the Python keywords.
#[derive(Debug, Clone)]
pub struct Options {
    /// `--cases`: names or a TOML file ([`super::cases::resolve`]); `None`: every bundled preset.
    pub cases: Option<String>,
    /// The ladder (`--quick`: [`Ladder::Quick`]).
    pub ladder: Ladder,
    /// The executor.
    pub executor: Executor,
    /// Solver processes at once; `None`: [`pool::default_jobs`].
    pub jobs: Option<usize>,
    /// The work folder; `None`: a new one in the system's temporary folder.
    pub workdir: Option<PathBuf>,
    /// Carry on the suite in `workdir`.
    pub resume: bool,
    /// The solver program (a name on the PATH, or a path).
    pub ccx: String,
    /// The microslip program a Slurm array task runs (`suite --run-one`); needed by
    /// [`Executor::Slurm`] only.
    pub microslip: Option<PathBuf>,
}

/// A suite's outcome: each case's score, where its runs are, how long it took.
#[derive(Debug)]
pub struct Scorecard {
    /// Each case's score, in the order of the cases.
    pub cases: Vec<CaseScore>,
    /// The work folder.
    pub workdir: PathBuf,
    /// The suite's wall time (s).
    pub seconds: f64,
    /// The first failure of a solver of the local pool (a program that crashed or wrote no
    /// results): its case is not converged, and the command line exits 3.
    pub solver_failure: Option<RunError>,
}

impl Scorecard {
    /// The cases that do not agree (do not agree, are not converged or judged nothing).
    pub fn failing(&self) -> usize {
        self.cases
            .iter()
            .filter(|c| c.verdict != Verdict::Agrees)
            .count()
    }

    /// The exit status of the table (docs/guide.md): 0 every case agrees, 1 one does not, 3 a
    /// solver of the local pool failed.
    pub fn exit_code(&self) -> u8 {
        match (&self.solver_failure, self.failing()) {
            (Some(_), _) => 3,
            (None, 0) => 0,
            (None, _) => 1,
        }
    }

    /// The scorecard as JSON (`--format json`): an array, one object per case.
    pub fn json(&self) -> serde_json::Value {
        crate::report::point::to_json(&self.cases)
    }

    /// The scorecard as JUnit XML ([`score::junit`]).
    pub fn junit(&self) -> String {
        score::junit(&self.cases, self.seconds)
    }

    /// The scorecard as its HTML page ([`super::html::page`]).
    pub fn html(&self) -> String {
        let title = format!("microslip suite: {} cases", self.cases.len());
        super::html::page(&self.cases, &title)
    }
}

/// Why a suite did not give a scorecard.
#[derive(Debug, thiserror::Error)]
pub enum SuiteError {
    /// Refused input: a case, a file, the work folder, a deck's parameters, Slurm unreachable.
    #[error("{0}")]
    Refused(String),
    /// The solver program cannot be run, or the suite was stopped ([`RunError::Stopped`]: a
    /// resumed suite carries on).
    #[error(transparent)]
    Solver(#[from] RunError),
}

/// Runs the suite `options` says. `stop` is asked between runs and while each solver runs (a
/// signal's number: the runs are ended and [`RunError::Stopped`] returned); `say` is given each
/// progress line (what the command line writes on stderr).
///
/// # Errors
/// [`SuiteError`]: refused input before anything runs, a solver program that cannot be run, a
/// stop.
pub fn run(
    options: &Options,
    stop: &(dyn Fn() -> Option<i32> + Sync),
    say: &(dyn Fn(&str) + Sync),
) -> Result<Scorecard, SuiteError> {
    let refused = |e: &dyn std::fmt::Display| SuiteError::Refused(e.to_string());
    let cases =
        super::cases::resolve(options.cases.as_deref(), options.ladder).map_err(|e| refused(&e))?;
    let workdir = match &options.workdir {
        Some(dir) => dir.clone(),
        None => crate::fe::run::fresh_folder(&std::env::temp_dir(), "suite")
            .map_err(|e| refused(&format!("a work folder in the temporary folder: {e}")))?,
    };
    let mut plans = Vec::with_capacity(cases.len());
    for (index, case) in cases.iter().enumerate() {
        plans.push(prepared_runs(index, case, &workdir)?);
    }
    let program = crate::fe::run::resolve_program(&options.ccx)?;
    super::claim_workdir(&workdir, options.resume).map_err(|e| refused(&e))?;
    let all: Vec<&Prepared> = plans.iter().flatten().collect();
    // A run is complete when its result file reads back and its deck is the one this suite
    // writes (a case changed since, by its preset or its file, is run again); its output is
    // judged again, so a finished run is scored by today's envelopes, not those it was run under.
    let done_before: Vec<Option<RunResult>> = all
        .iter()
        .map(|run| {
            let deck = std::fs::read(run.folder.join(format!("{}.inp", super::JOB)));
            deck.is_ok_and(|d| d == run.deck.as_bytes())
                .then(|| result::read_rejudged(run.kind, &run.folder))
                .flatten()
        })
        .collect();
    let pending: Vec<Prepared> = all
        .iter()
        .zip(&done_before)
        .filter(|(_, done)| done.is_none())
        .map(|(run, _)| (*run).clone())
        .collect();
    let jobs = options
        .jobs
        .unwrap_or_else(pool::default_jobs)
        .clamp(1, pending.len().max(1));
    say(&format!(
        "microslip suite: {} runs in {} cases, {} complete already, {} to run, {jobs} at a \
         time, in {}",
        all.len(),
        cases.len(),
        all.len() - pending.len(),
        pending.len(),
        workdir.display()
    ));
    let started = Instant::now();
    let outcomes = match options.executor {
        Executor::Local => on_pool(&program, &pending, jobs, all.len(), stop, say),
        Executor::Slurm => {
            let microslip = options.microslip.as_deref().ok_or_else(|| {
                refused(
                    &"the Slurm executor needs the microslip program, which each array task runs",
                )
            })?;
            on_slurm(&pending, jobs, &workdir, microslip, &program, stop, say)?
        }
    };
    if let Some(signal) = stop() {
        return Err(RunError::Stopped {
            signal,
            folder: workdir.display().to_string(),
        }
        .into());
    }
    // Each run's outcome, in plan order: complete before, or run now.
    let mut fresh = pending.iter().zip(outcomes);
    let mut solver_failure = None;
    let mut by_run = Vec::with_capacity(all.len());
    for (run, before) in all.iter().zip(done_before) {
        let outcome = match before {
            Some(done) => Ok(done),
            None => match fresh.next() {
                Some((_, Some(Ok(done)))) => Ok(done),
                Some((_, Some(Err(e)))) => {
                    let words = e.to_string();
                    if let (None, RunFailure::Solver(e)) = (&solver_failure, e) {
                        solver_failure = Some(e);
                    }
                    Err(words)
                }
                _ => Err("not run".to_string()),
            },
        };
        by_run.push((run.spec.case, outcome));
    }
    let scores = cases
        .iter()
        .enumerate()
        .map(|(index, case)| {
            let specs: Vec<RunSpec> = plans[index].iter().map(|p| p.spec.clone()).collect();
            let outcomes: Vec<Result<RunResult, String>> = by_run
                .iter()
                .filter(|(c, _)| *c == index)
                .map(|(_, o)| o.clone())
                .collect();
            score::case_score(case, &specs, &outcomes)
        })
        .collect();
    Ok(Scorecard {
        cases: scores,
        workdir,
        seconds: started.elapsed().as_secs_f64(),
        solver_failure,
    })
}

/// `pending` on the local pool, a progress line as each run ends.
fn on_pool(
    program: &Path,
    pending: &[Prepared],
    jobs: usize,
    total: usize,
    stop: &(dyn Fn() -> Option<i32> + Sync),
    say: &(dyn Fn(&str) + Sync),
) -> Vec<Option<pool::Outcome>> {
    let started = Instant::now();
    let ended = std::sync::atomic::AtomicUsize::new(0);
    let progress = |run: &Prepared, outcome: &pool::Outcome, c: Counts| {
        // The run's own verdict, as `compare` gives it for that run alone: the case's verdict
        // is the ladder's, and a rung may disagree alone (one mesh's implied K_T) while the
        // converged answer agrees.
        let what = match outcome {
            Ok(r) => format!(
                "done in {:.0} s (the run alone: {})",
                r.solver_seconds, r.verdict
            ),
            Err(e) => format!("failed: {}", crate::report::sanitize(&e.to_string())),
        };
        let elapsed = started.elapsed().as_secs_f64();
        let ended = ended.fetch_add(1, std::sync::atomic::Ordering::SeqCst) + 1;
        // At the pace so far: the finer rungs, run last, cost more, so this is a lower bound.
        let left = elapsed / ended as f64 * (c.running + c.queued) as f64;
        say(&format!(
            "microslip suite: {}/{} {what}; {} done, {} running, {} queued, {elapsed:.0} s, at \
             least {left:.0} s left",
            run.case, run.spec.name, c.done, c.running, c.queued,
        ));
    };
    pool::run_all(
        program,
        pending,
        jobs,
        total - pending.len(),
        stop,
        &progress,
    )
}

/// `pending` as one Slurm job array of at most `jobs` tasks at once, followed to its end; each
/// run's outcome is its result file, or the task's failure with where its output is.
fn on_slurm(
    pending: &[Prepared],
    jobs: usize,
    workdir: &Path,
    microslip: &Path,
    program: &Path,
    stop: &(dyn Fn() -> Option<i32> + Sync),
    say: &(dyn Fn(&str) + Sync),
) -> Result<Vec<Option<pool::Outcome>>, SuiteError> {
    if pending.is_empty() {
        return Ok(Vec::new());
    }
    let slurm_error = |e: super::slurm::SlurmError| SuiteError::Refused(format!("slurm: {e}"));
    let job =
        super::slurm::submit(pending, jobs, workdir, microslip, program).map_err(slurm_error)?;
    say(&format!(
        "microslip suite: Slurm job array {job}: {} tasks, at most {jobs} at once",
        pending.len()
    ));
    let started = Instant::now();
    super::slurm::wait(&job, &|| stop(), &mut |left| {
        let done = pending
            .iter()
            .filter(|r| result::read(&r.folder).is_some())
            .count();
        say(&format!(
            "microslip suite: Slurm job {job}: {done} done, {left} queued or running, {:.0} s",
            started.elapsed().as_secs_f64()
        ));
    })
    .map_err(slurm_error)?;
    let outputs = super::slurm::folder(workdir);
    Ok(pending
        .iter()
        .enumerate()
        .map(|(task, run)| {
            Some(result::read(&run.folder).ok_or_else(|| {
                RunFailure::Judge(format!(
                    "Slurm array task {job}_{task} left no result; its output is {}",
                    outputs.join(format!("task-{task}.out")).display()
                ))
            }))
        })
        .collect())
}

/// The model of `case`: its preset with its assignments, validated with its load.
///
/// # Errors
/// The preset cannot be read, an assignment or a value is refused.
pub fn case_model(case: &Case) -> Result<Model, SuiteError> {
    let refused = |e: &dyn std::fmt::Display| {
        SuiteError::Refused(format!("case {}: {e}", crate::report::sanitize(&case.name)))
    };
    let preset = crate::preset::resolve(&case.preset).map_err(|e| refused(&e))?;
    let mut inputs = preset.inputs;
    for assignment in &case.assignments {
        crate::preset::apply_assignment(&mut inputs, assignment).map_err(|e| refused(&e))?;
    }
    inputs.validate().map_err(|e| refused(&e))
}

/// The runs of `case` (index `index`) with their decks, written as `deck ccx` writes them at the
/// model's stick slope.
///
/// # Errors
/// The case's model or a deck refused.
pub fn prepared_runs(
    index: usize,
    case: &Case,
    workdir: &Path,
) -> Result<Vec<Prepared>, SuiteError> {
    let model = case_model(case)?;
    let increment = for_problem(case.kind, DefaultIncrement { model: &model });
    super::plan(index, case, increment)
        .into_iter()
        .map(|spec| {
            let request = DeckRequest {
                loads: case.loads.as_deref(),
                mesh: spec.mesh,
                slope: StickSlope::Model,
                increment: spec.increment,
            };
            let refused = |why: String| {
                SuiteError::Refused(format!(
                    "case {}, run {}: {why}",
                    crate::report::sanitize(&case.name),
                    spec.name
                ))
            };
            let deck = write_deck(case.kind, &model, &request)
                .ok_or_else(|| refused(format!("not a model of the {}", case.kind)))?
                .map_err(|e| refused(e.to_string()))?;
            Ok(Prepared {
                folder: super::run_folder(workdir, &case.name, &spec.name),
                spec,
                case: case.name.clone(),
                kind: case.kind,
                deck,
            })
        })
        .collect()
}

/// The deck of the problem `kind` at `model` as `request` asks (`None`: `model` is not one of
/// `kind`).
pub fn write_deck(
    kind: ModelKind,
    model: &Model,
    request: &DeckRequest<'_>,
) -> Option<Result<String, DeckError>> {
    for_problem(kind, WriteDeck { model, request })
}

/// [`write_deck`]'s body, for [`for_problem`].
struct WriteDeck<'a> {
    model: &'a Model,
    request: &'a DeckRequest<'a>,
}

impl ForProblem for WriteDeck<'_> {
    type Output = Option<Result<String, DeckError>>;

    fn run<P: Faces>(self) -> Self::Output {
        Some(crate::fe::face::written_deck::<P>(
            &P::from_model(self.model)?,
            self.request,
        ))
    }
}

/// The problem's [`Deck::default_increment`](crate::fe::face::Deck::default_increment) at a
/// model, for [`for_problem`].
pub struct DefaultIncrement<'a> {
    /// The model.
    pub model: &'a Model,
}

impl ForProblem for DefaultIncrement<'_> {
    type Output = Option<f64>;

    fn run<P: Faces>(self) -> Option<f64> {
        P::default_increment(&P::from_model(self.model)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CI's list of cases (validation/calculix/suite.toml) resolves, every run's deck is written,
    /// and a case's own loads reach its decks.
    #[test]
    fn the_ci_case_list_resolves_and_writes_its_decks() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/validation/calculix/suite.toml"
        );
        let cases = super::super::cases::resolve(Some(path), Ladder::Quick).unwrap();
        assert!(cases.len() >= 3, "{cases:?}");
        let dir = tempfile::tempdir().unwrap();
        let mut with_loads = 0;
        for (index, case) in cases.iter().enumerate() {
            let runs = prepared_runs(index, case, dir.path()).unwrap();
            assert!(runs.len() >= 2, "{}", case.name);
            if case.loads.is_some() {
                with_loads += 1;
                let own = Case {
                    loads: None,
                    ..case.clone()
                };
                let default = prepared_runs(index, &own, dir.path()).unwrap();
                assert_ne!(runs[0].deck, default[0].deck, "{}", case.name);
            }
        }
        assert!(with_loads > 0);
    }
}
