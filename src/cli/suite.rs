//! `microslip suite`: the cases' decks written as `deck` writes them, run on the local pool,
//! scored ([`crate::suite`] holds the engine; this file reads the flags, writes the decks through
//! the same door as `deck` and `bench`, and maps the outcome to the exit-code table).

use super::*;
use crate::suite::pool::{self, Counts, Prepared, RunFailure};
use crate::suite::{self as engine, Case, Ladder, result, score};

/// `microslip suite`.
pub(super) fn run_suite(out: &mut impl Write, args: &SuiteArgs) -> Result<(), CliError> {
    if let Some(folder) = &args.run_one {
        return run_one(folder, &args.ccx);
    }
    let ladder = if args.quick {
        Ladder::Quick
    } else {
        Ladder::Full
    };
    let cases = engine::cases::resolve(args.cases.as_deref(), ladder)
        .map_err(|e| CliError::Invalid(e.to_string()))?;
    // Every deck before anything runs: a refused case costs no solver time.
    let workdir = match &args.workdir {
        Some(dir) => dir.clone(),
        None => fe::run::fresh_folder(&std::env::temp_dir(), "suite")?,
    };
    let mut plans = Vec::with_capacity(cases.len());
    for (index, case) in cases.iter().enumerate() {
        plans.push(prepared_runs(index, case, &workdir)?);
    }
    let program = fe::run::resolve_program(&args.ccx)?;
    engine::claim_workdir(&workdir, args.resume).map_err(|e| CliError::Invalid(e.to_string()))?;
    let all: Vec<&Prepared> = plans.iter().flatten().collect();
    // A run is complete when its result file reads back and its deck is the one this suite
    // writes (a case changed since, by its preset or its file, is run again).
    let done_before: Vec<Option<result::RunResult>> = all
        .iter()
        .map(|run| {
            let deck = std::fs::read(run.folder.join(format!("{}.inp", engine::JOB)));
            result::read(&run.folder).filter(|_| deck.is_ok_and(|d| d == run.deck.as_bytes()))
        })
        .collect();
    let pending: Vec<Prepared> = all
        .iter()
        .zip(&done_before)
        .filter(|(_, done)| done.is_none())
        .map(|(run, _)| (*run).clone())
        .collect();
    let jobs = args
        .jobs
        .map_or_else(pool::default_jobs, usize::from)
        .min(pending.len().max(1));
    eprintln!(
        "microslip suite: {} runs in {} cases, {} complete already, {} to run, {jobs} at a \
         time, in {}",
        all.len(),
        cases.len(),
        all.len() - pending.len(),
        pending.len(),
        workdir.display()
    );
    let stop = StopSignals::install()?;
    let started = Instant::now();
    let ended = std::sync::atomic::AtomicUsize::new(0);
    let progress = |run: &Prepared, outcome: &Result<result::RunResult, RunFailure>, c: Counts| {
        let what = match outcome {
            Ok(r) => format!("done in {:.0} s ({})", r.solver_seconds, r.verdict),
            Err(e) => format!("failed: {}", report::sanitize(&e.to_string())),
        };
        let elapsed = started.elapsed().as_secs_f64();
        let ended = ended.fetch_add(1, std::sync::atomic::Ordering::SeqCst) + 1;
        // At the pace so far: the finer rungs, run last, cost more, so this is a lower bound.
        let left = elapsed / ended as f64 * (c.running + c.queued) as f64;
        eprintln!(
            "microslip suite: {}/{} {what}; {} done, {} running, {} queued, {elapsed:.0} s, at \
             least {left:.0} s left",
            run.case, run.spec.name, c.done, c.running, c.queued,
        );
    };
    let outcomes = match args.executor {
        Executor::Local => pool::run_all(
            &program,
            &pending,
            jobs,
            all.len() - pending.len(),
            &|| stop.received(),
            &progress,
        ),
        Executor::Slurm => on_slurm(&pending, jobs, &workdir, &program, &stop)?,
    };
    if let Some(signal) = stop.received() {
        return Err(fe::run::RunError::Stopped {
            signal,
            folder: workdir.display().to_string(),
        }
        .into());
    }
    // Each run's outcome, in plan order: complete before, or run now.
    let mut fresh = pending.iter().zip(outcomes);
    let mut first_failure = None;
    let mut by_run = Vec::with_capacity(all.len());
    for (run, before) in all.iter().zip(done_before) {
        let outcome = match before {
            Some(done) => Ok(done),
            None => match fresh.next() {
                Some((_, Some(Ok(done)))) => Ok(done),
                Some((_, Some(Err(e)))) => {
                    let words = e.to_string();
                    if let (None, RunFailure::Solver(e)) = (&first_failure, e) {
                        first_failure = Some(e);
                    }
                    Err(words)
                }
                _ => Err("not run".to_string()),
            },
        };
        by_run.push((run.spec.case, outcome));
    }
    let scores: Vec<score::CaseScore> = cases
        .iter()
        .enumerate()
        .map(|(index, case)| {
            let specs: Vec<engine::RunSpec> = plans[index].iter().map(|p| p.spec.clone()).collect();
            let outcomes: Vec<Result<result::RunResult, String>> = by_run
                .iter()
                .filter(|(c, _)| *c == index)
                .map(|(_, o)| o.clone())
                .collect();
            score::case_score(case, &specs, &outcomes)
        })
        .collect();
    match args.format {
        SuiteFormat::Text => out.write_all(score::text(&scores).as_bytes())?,
        SuiteFormat::Json => write_json(out, &report::point::to_json(&scores))?,
    }
    out.flush()?;
    if let Some(path) = &args.junit {
        write_scorecard(
            path,
            &score::junit(&scores, started.elapsed().as_secs_f64()),
        )?;
    }
    if let Some(path) = &args.html {
        let title = format!("microslip suite: {} cases", scores.len());
        write_scorecard(path, &engine::html::page(&scores, &title))?;
    }
    eprintln!(
        "microslip suite: the runs' folders and result files are in {}",
        workdir.display()
    );
    if let Some(failure) = first_failure {
        return Err(failure.into());
    }
    let failing = scores
        .iter()
        .filter(|s| s.verdict != crate::fe::ladder::Verdict::Agrees)
        .count();
    if failing > 0 {
        return Err(CliError::Disagrees(format!(
            "{failing} of {} cases do not agree, are not converged or not judged",
            scores.len()
        )));
    }
    Ok(())
}

/// A scorecard file a user named (`--junit`, `--html`), replaced atomically.
fn write_scorecard(path: &std::path::Path, text: &str) -> Result<(), CliError> {
    crate::file::write_atomic(path, text.as_bytes(), true).map_err(|e| CliError::Data {
        path: path.display().to_string(),
        reason: e.to_string(),
    })
}

/// `pending` as one Slurm job array of at most `jobs` tasks at once, followed to its end; each
/// run's outcome is its result file, or the task's failure with where its output is.
fn on_slurm(
    pending: &[Prepared],
    jobs: usize,
    workdir: &std::path::Path,
    program: &std::path::Path,
    stop: &StopSignals,
) -> Result<Vec<Option<pool::Outcome>>, CliError> {
    if pending.is_empty() {
        return Ok(Vec::new());
    }
    let slurm_error = |e: engine::slurm::SlurmError| CliError::Invalid(format!("slurm: {e}"));
    let microslip = std::env::current_exe()?;
    let job =
        engine::slurm::submit(pending, jobs, workdir, &microslip, program).map_err(slurm_error)?;
    eprintln!(
        "microslip suite: Slurm job array {job}: {} tasks, at most {jobs} at once",
        pending.len()
    );
    let started = Instant::now();
    engine::slurm::wait(&job, &|| stop.received(), &mut |left| {
        let done = pending
            .iter()
            .filter(|r| result::read(&r.folder).is_some())
            .count();
        eprintln!(
            "microslip suite: Slurm job {job}: {done} done, {left} queued or running, {:.0} s",
            started.elapsed().as_secs_f64()
        );
    })
    .map_err(slurm_error)?;
    let outputs = engine::slurm::folder(workdir);
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

/// `suite --run-one FOLDER`: the prepared run in the folder to its result file.
fn run_one(folder: &std::path::Path, ccx: &str) -> Result<(), CliError> {
    let program = fe::run::resolve_program(ccx)?;
    let stop = StopSignals::install()?;
    match pool::run_prepared(&program, folder, &|| stop.received()) {
        Ok(_) => Ok(()),
        Err(RunFailure::Solver(e)) => Err(e.into()),
        Err(RunFailure::Judge(why)) => Err(CliError::Invalid(why)),
    }
}

/// The runs of `case` (index `index`) with their decks, written as `deck ccx` writes them.
fn prepared_runs(
    index: usize,
    case: &Case,
    workdir: &std::path::Path,
) -> Result<Vec<Prepared>, CliError> {
    let inputs = InputArgs {
        preset: Some(case.preset.clone()),
        assignments: case.assignments.clone(),
        choices: Vec::new(),
    };
    let command = format!("suite (case {})", case.name);
    let (_, model) = load(&inputs, case.kind, &command)?;
    let increment = for_problem(case.kind, DefaultIncrement { model: &model });
    engine::plan(index, case, increment)
        .into_iter()
        .map(|spec| {
            let deck = DeckArgs {
                inputs: inputs.clone(),
                mesh: spec.mesh,
                loads: None,
                near_coulomb: false,
                increment: spec.increment,
            };
            let text = build_deck(case.kind, &deck, &command)?;
            Ok(Prepared {
                folder: engine::run_folder(workdir, &case.name, &spec.name),
                spec,
                case: case.name.clone(),
                kind: case.kind,
                deck: text,
            })
        })
        .collect()
}

/// The problem's [`Deck::default_increment`](crate::fe::face::Deck::default_increment) at a
/// model, for [`for_problem`].
struct DefaultIncrement<'a> {
    model: &'a Model,
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

    /// Each bundled case's ladder: the deck's own increment is what `default_increment` says
    /// (the deck written with it is the deck written without it, byte for byte), its half is a
    /// deck of its own, and each mesh rung is a finer deck than the one before.
    #[test]
    fn every_problem_s_ladder_is_written_as_its_rungs_say() {
        let dir = tempfile::tempdir().unwrap();
        for case in engine::cases::resolve(None, Ladder::Full).unwrap() {
            let runs = prepared_runs(0, &case, dir.path()).unwrap();
            let sizes: Vec<usize> = runs
                .iter()
                .filter(|r| !r.spec.half_increment)
                .map(|r| r.deck.len())
                .collect();
            assert_eq!(sizes.len(), 3, "{}", case.name);
            assert!(
                sizes.windows(2).all(|w| w[0] < w[1]),
                "{}: {sizes:?}",
                case.name
            );
            let inputs = InputArgs {
                preset: Some(case.preset.clone()),
                ..InputArgs::default()
            };
            let (_, model) = load(&inputs, case.kind, "test").unwrap();
            let Some(step) = for_problem(case.kind, DefaultIncrement { model: &model }) else {
                assert!(runs.iter().all(|r| !r.spec.half_increment), "{}", case.name);
                continue;
            };
            let deck = |increment| {
                let args = DeckArgs {
                    inputs: inputs.clone(),
                    mesh: DeckMesh::Finest,
                    loads: None,
                    near_coulomb: false,
                    increment,
                };
                build_deck(case.kind, &args, "test").unwrap()
            };
            assert_eq!(deck(Some(step)), deck(None), "{}", case.name);
            let half = runs.iter().find(|r| r.spec.half_increment).unwrap();
            assert_eq!(half.deck, deck(Some(0.5 * step)));
            assert_ne!(half.deck, deck(None), "{}", case.name);
        }
    }
}
