//! `microslip suite`: cases x ladders -> runs -> scorecard.
//!
//! A **case** is a problem's parameters (a preset, with `--set`-style assignments) and a
//! **ladder**: its deck at the mesh rungs h, h/2, h/4 ([`DeckMesh`]) at the deck's own load
//! increment, and the finest rung again at half that increment ([`plan`]). Each rung is a
//! **run**: a deck in `<workdir>/<case>/<run>/`, the solver on it, and the run's judged
//! quantities in a result file ([`result`]) written atomically (a temporary file renamed) only
//! once the run is complete. The runs go through an executor, the local pool by default
//! ([`pool`]: at most `jobs` solver processes at once, each in its own process group, ended with
//! us) or a Slurm job array ([`slurm`]). The **scorecard** ([`score`]) extrapolates each case's quantities over its ladder
//! ([`crate::fe::ladder`]) and judges them against the problem's envelope plus the
//! extrapolation's uncertainty; [`html`] draws it as one page with each case's convergence plots.
//! [`run`] is the whole suite from its options to its scorecard, the one function the command
//! line and the Python face call.
//!
//! Why one work folder with a result file per run: a suite of many solver runs outlives a
//! terminal, a CI job's time limit or a node. Killed at any moment (SIGTERM, SIGKILL), it resumes
//! with `--resume`: a run whose result file exists is not run again, and a run without one is
//! run from scratch (its folder emptied), so no finished run is lost or run twice. A kept run is
//! judged again from its output ([`result::read_rejudged`]): a resume after an envelope was
//! recalibrated scores it by the new one. A new suite in
//! a folder that holds anything is refused, so nothing is ever clobbered.
//!
//! Everything here is generic over the registry: a case's problem comes from its preset, its deck
//! and its judgement from the problem's traits ([`crate::fe::face::Deck`],
//! [`crate::report::compare::CompareFace`]); no problem is named.

pub mod cases;
pub mod html;
pub mod pool;
pub mod result;
pub mod run;
pub mod score;
pub mod slurm;

use std::path::{Path, PathBuf};

use crate::fe::deck::DeckMesh;
use crate::problems::ModelKind;

/// How long a ladder is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ladder {
    /// h, h/2, h/4, and h/4 at half the increment: Richardson with an observed order.
    Full,
    /// h, h/2, and h/2 at half the increment: the quick check CI runs (two rungs: the finer
    /// answer, the last change as its uncertainty).
    Quick,
}

impl Ladder {
    /// The mesh rungs, coarsest first.
    pub fn meshes(self) -> &'static [DeckMesh] {
        match self {
            Ladder::Full => &DeckMesh::ALL,
            Ladder::Quick => &[DeckMesh::Coarse, DeckMesh::Fine],
        }
    }
}

/// One case to run: a problem's parameters and its ladder.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Its name: the folder of its runs, the scorecard's and JUnit's name for it.
    pub name: String,
    /// Its problem.
    pub kind: ModelKind,
    /// The preset it starts from (a bundled name, a user preset's, or a path).
    pub preset: String,
    /// `KEY=VALUE` assignments on top of the preset, as `--set` takes them.
    pub assignments: Vec<String>,
    /// The mesh rungs, coarsest first.
    pub meshes: Vec<DeckMesh>,
    /// The load steps of its decks, in the problem's load unit (`deck --loads`); `None`: the
    /// deck's own.
    pub loads: Option<Vec<f64>>,
    /// The largest uncertainty the case accepts on each converged quantity, a fraction; `None`:
    /// the envelope's bound alone limits it. A convergence requirement tighter than the
    /// envelope, for a case that holds a deck's own meshes and increments to account (CI holds
    /// the beams' and the lap joint's default decks to 0.3 %: a single `compare` of them is then
    /// within that of the converged answer).
    pub converged_within: Option<f64>,
}

/// One run of a case: a mesh rung at an increment.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    /// The case's index in the plan.
    pub case: usize,
    /// The run's name, its folder under the case's (`fine`, `fine-half-increment`).
    pub name: String,
    /// Its mesh.
    pub mesh: DeckMesh,
    /// The largest load change per increment given to its deck; `None`: the deck's own.
    pub increment: Option<f64>,
    /// Whether it is the half-increment run of the finest rung.
    pub half_increment: bool,
}

/// The runs of `case` (index `index`): one per mesh rung at the deck's own increment, and the
/// finest rung at half of `increment` (the deck's default, [`crate::fe::face::Deck::default_increment`])
/// when the deck has increments and the ladder more than one rung.
pub fn plan(index: usize, case: &Case, increment: Option<f64>) -> Vec<RunSpec> {
    let mut runs: Vec<RunSpec> = case
        .meshes
        .iter()
        .map(|&mesh| RunSpec {
            case: index,
            name: mesh.name().to_string(),
            mesh,
            increment: None,
            half_increment: false,
        })
        .collect();
    if let (Some(&finest), Some(step), true) =
        (case.meshes.last(), increment, case.meshes.len() > 1)
    {
        runs.push(RunSpec {
            case: index,
            name: format!("{}-half-increment", finest.name()),
            mesh: finest,
            increment: Some(0.5 * step),
            half_increment: true,
        });
    }
    runs
}

/// The folder of a run: `<workdir>/<case>/<run>`.
pub fn run_folder(workdir: &Path, case: &str, run: &str) -> PathBuf {
    workdir.join(case).join(run)
}

/// The job name of every run's deck and results (`job.inp`, `job.dat`).
pub const JOB: &str = "job";

/// Why a work folder is refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum WorkdirError {
    /// A new suite in a folder that holds something.
    #[error(
        "--workdir {0}: the folder is not empty; a new suite is run in an empty or new folder \
         (give --resume to carry on the suite whose runs are there)"
    )]
    NotEmpty(String),
    /// Something other than a folder stands there, or it cannot be made or read.
    #[error("--workdir {path}: {reason}")]
    Unusable {
        /// The path.
        path: String,
        /// What is wrong.
        reason: String,
    },
}

/// Makes the work folder `workdir` (with its parents) when missing; refuses a folder that holds
/// anything unless `resume`, and anything that is not a folder.
///
/// # Errors
/// [`WorkdirError`].
pub fn claim_workdir(workdir: &Path, resume: bool) -> Result<(), WorkdirError> {
    let unusable = |reason: String| WorkdirError::Unusable {
        path: workdir.display().to_string(),
        reason,
    };
    match std::fs::metadata(workdir) {
        Ok(m) if !m.is_dir() => {
            return Err(unusable(format!(
                "{}, not a folder",
                crate::file::kind_of(&m)
            )));
        }
        Ok(_) => {
            let mut entries = std::fs::read_dir(workdir).map_err(|e| unusable(e.to_string()))?;
            if !resume && entries.next().is_some() {
                return Err(WorkdirError::NotEmpty(workdir.display().to_string()));
            }
        }
        Err(_) => {
            std::fs::create_dir_all(workdir)
                .map_err(|e| unusable(format!("cannot make the folder: {e}")))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(meshes: &[DeckMesh]) -> Case {
        Case {
            name: "c".to_string(),
            kind: ModelKind::ALL[0],
            preset: "p".to_string(),
            assignments: Vec::new(),
            meshes: meshes.to_vec(),
            loads: None,
            converged_within: None,
        }
    }

    #[test]
    fn a_ladder_is_its_rungs_and_the_finest_at_half_the_increment() {
        let runs = plan(3, &case(Ladder::Full.meshes()), Some(30.0));
        let names: Vec<&str> = runs.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["coarse", "fine", "finest", "finest-half-increment"]);
        assert_eq!(runs[3].increment, Some(15.0));
        assert_eq!(runs[3].mesh, DeckMesh::Finest);
        assert!(runs.iter().all(|r| r.case == 3));
        assert!(runs[..3].iter().all(|r| r.increment.is_none()));
        // A deck without increments has no increment pair; one rung is a single run.
        assert_eq!(plan(0, &case(Ladder::Quick.meshes()), None).len(), 2);
        assert_eq!(plan(0, &case(&[DeckMesh::Coarse]), Some(1.0)).len(), 1);
    }

    #[test]
    fn a_new_suite_needs_an_empty_folder() {
        let dir = tempfile::tempdir().unwrap();
        let workdir = dir.path().join("new");
        claim_workdir(&workdir, false).unwrap();
        claim_workdir(&workdir, false).unwrap();
        std::fs::write(workdir.join("x"), "").unwrap();
        assert!(matches!(
            claim_workdir(&workdir, false),
            Err(WorkdirError::NotEmpty(_))
        ));
        claim_workdir(&workdir, true).unwrap();
        assert!(matches!(
            claim_workdir(&workdir.join("x"), true),
            Err(WorkdirError::Unusable { .. })
        ));
    }
}
