//! `microslip suite`: the flags read, the suite run ([`crate::suite::run`] holds it, shared with
//! the Python face: the decks written as `deck` writes them, the runs on the local pool or Slurm,
//! the scores), the scorecard printed and its outcome mapped to the exit-code table.

use super::*;
use crate::suite::pool::{self, RunFailure};
use crate::suite::run::{self as suite_run, Options};
use crate::suite::{Ladder, score};

/// `microslip suite`.
pub(super) fn run_suite(out: &mut impl Write, args: &SuiteArgs) -> Result<(), CliError> {
    if let Some(folder) = &args.run_one {
        return run_one(folder, &args.ccx);
    }
    let options = Options {
        cases: args.cases.clone(),
        ladder: if args.quick {
            Ladder::Quick
        } else {
            Ladder::Full
        },
        executor: match args.executor {
            Executor::Local => suite_run::Executor::Local,
            Executor::Slurm => suite_run::Executor::Slurm,
        },
        jobs: args.jobs.map(usize::from),
        workdir: args.workdir.clone(),
        resume: args.resume,
        ccx: args.ccx.clone(),
        microslip: std::env::current_exe().ok(),
    };
    let stop = StopSignals::install()?;
    let scorecard = suite_run::run(&options, &|| stop.received(), &|line| eprintln!("{line}"))
        .map_err(|e| match e {
            suite_run::SuiteError::Refused(why) => CliError::Invalid(why),
            suite_run::SuiteError::Solver(e) => CliError::Solver(e),
        })?;
    let scores = &scorecard.cases;
    match args.format {
        SuiteFormat::Text => out.write_all(score::text(scores).as_bytes())?,
        SuiteFormat::Json => write_json(out, &scorecard.json())?,
    }
    out.flush()?;
    if let Some(path) = &args.junit {
        write_scorecard(path, &scorecard.junit())?;
    }
    if let Some(path) = &args.html {
        write_scorecard(path, &scorecard.html())?;
    }
    eprintln!(
        "microslip suite: the runs' folders and result files are in {}",
        scorecard.workdir.display()
    );
    let failing = scorecard.failing();
    if let Some(failure) = scorecard.solver_failure {
        return Err(failure.into());
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Each bundled case's ladder: the deck's own increment is what `default_increment` says
    /// (the deck written with it is the deck written without it, byte for byte), its half is a
    /// deck of its own, and each mesh rung is a finer deck than the one before.
    #[test]
    fn every_problem_s_ladder_is_written_as_its_rungs_say() {
        let dir = tempfile::tempdir().unwrap();
        for case in crate::suite::cases::resolve(None, Ladder::Full).unwrap() {
            let runs = suite_run::prepared_runs(0, &case, dir.path()).unwrap();
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
            let Some(step) = for_problem(case.kind, suite_run::DefaultIncrement { model: &model })
            else {
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
