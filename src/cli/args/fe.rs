//! The FE commands: `deck`, `bench`, `compare` (each takes the problem by its registry key) and
//! `verify`.

use super::*;
use clap::{Args, ValueEnum};

// The flags of `verify` (Command::Verify); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct VerifyArgs {
    /// Run one geometry per model only (a smoke test).
    #[arg(long)]
    pub(in crate::cli) quick: bool,
    #[arg(
        long,
        value_name = "N",
        default_value_t = MeshDensity::default().elements,
        help = format!(
            "Elements per model ({} to {}; the smallest element shrinks in proportion)",
            MeshDensity::MIN_ELEMENTS,
            MeshDensity::MAX_ELEMENTS
        )
    )]
    pub(in crate::cli) elements: usize,
    /// Largest relative error accepted on w(L), X, u(L) and X_r.
    #[arg(long, value_name = "T", default_value_t = verify::DEFAULT_TOLERANCE)]
    pub(in crate::cli) tolerance: f64,
}

// The flags of `deck` (Command::Deck); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct DeckCommandArgs {
    /// The FE code (ccx: CalculiX 2.20; Abaqus reads the same keywords, see docs/guide.md).
    #[arg(value_enum)]
    pub(in crate::cli) code: FeCode,
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub(in crate::cli) model: ModelKind,
    #[command(flatten)]
    pub(in crate::cli) deck: DeckArgs,
    /// Write the deck to FILE instead of stdout (replaced atomically if it exists).
    #[arg(short = 'o', long, value_name = "FILE")]
    pub(in crate::cli) output: Option<PathBuf>,
}

// The flags of `bench` (Command::Bench); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// The FE code (ccx: CalculiX 2.20).
    #[arg(value_enum)]
    pub(in crate::cli) code: FeCode,
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub(in crate::cli) model: ModelKind,
    #[command(flatten)]
    pub(in crate::cli) deck: DeckArgs,
    /// Work folder (made if missing; refused if it holds the job's files already). Default:
    /// a new folder microslip-ccx-JOB-N in the system's temporary folder.
    #[arg(long, value_name = "DIR")]
    pub(in crate::cli) workdir: Option<PathBuf>,
    /// The ccx program to run: a name is looked up on the PATH, a path (`./ccx_2.20`) is
    /// taken from the current folder.
    #[arg(long, value_name = "PROGRAM", default_value = "ccx")]
    pub(in crate::cli) ccx: String,
    /// Output format of the comparison.
    #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
    pub(in crate::cli) format: CompareFormat,
}

// The flags of `suite` (Command::Suite); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct SuiteArgs {
    /// The cases: problem keys (each problem's bundled presets), preset names, or a TOML file
    /// of cases (docs/guide.md, "A verification suite"); default: every bundled preset.
    #[arg(long, value_name = "NAME,...|FILE.toml")]
    pub(in crate::cli) cases: Option<String>,
    /// A short ladder for CI: coarse and fine meshes, the fine one at half the increment too
    /// (default: coarse, fine, finest, the finest at half the increment too).
    #[arg(long)]
    pub(in crate::cli) quick: bool,
    /// Where the runs go.
    #[arg(long, value_enum, default_value_t = Executor::Local)]
    pub(in crate::cli) executor: Executor,
    /// Solver processes at once (default: the cores less one, at least 1); with Slurm, the
    /// array's throttle.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..=256))]
    pub(in crate::cli) jobs: Option<u16>,
    /// The work folder: `<DIR>/<case>/<run>/` per run. A new suite needs an empty or new
    /// folder; default: a new folder microslip-suite-N in the system's temporary folder.
    #[arg(long, value_name = "DIR")]
    pub(in crate::cli) workdir: Option<PathBuf>,
    /// Carry on the suite in --workdir: runs with a complete result file are kept, the others
    /// run from scratch.
    #[arg(long, requires = "workdir")]
    pub(in crate::cli) resume: bool,
    /// Also write the scorecard as JUnit XML to FILE (one testcase per case; replaced
    /// atomically if it exists).
    #[arg(long, value_name = "FILE")]
    pub(in crate::cli) junit: Option<PathBuf>,
    /// Also write the scorecard as one self-contained HTML page to FILE: the summary table and
    /// each case's convergence plots (replaced atomically if it exists).
    #[arg(long, value_name = "FILE")]
    pub(in crate::cli) html: Option<PathBuf>,
    /// The scorecard's format on stdout.
    #[arg(long, value_enum, default_value_t = SuiteFormat::Text)]
    pub(in crate::cli) format: SuiteFormat,
    /// The ccx program to run: a name is looked up on the PATH, a path is taken from the
    /// current folder.
    #[arg(long, value_name = "PROGRAM", default_value = "ccx")]
    pub(in crate::cli) ccx: String,
    /// Run the one prepared run in DIR to its result file (what a Slurm array task runs).
    #[arg(long, value_name = "DIR", hide = true)]
    pub(in crate::cli) run_one: Option<PathBuf>,
}

/// Where `suite` runs its solver processes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Executor {
    /// A bounded pool of solver processes on this machine.
    Local,
    /// One Slurm job array (sbatch --array with --jobs tasks at once), followed with squeue;
    /// each task runs `microslip suite --run-one` on a run's folder, so --workdir must be on a
    /// file system the nodes share.
    Slurm,
}

/// The scorecard's formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SuiteFormat {
    /// Readable lines.
    Text,
    /// One JSON object per case, in an array.
    Json,
}

// The flags of `compare` (Command::Compare); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct CompareArgs {
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub(in crate::cli) model: ModelKind,
    // The help lists each problem's CSV columns from the registry (`results_help`).
    #[arg(required = true, value_name = "RESULT", help = results_help())]
    pub(in crate::cli) results: Vec<PathBuf>,
    /// The deck of a .dat result (default: the result's name with .inp).
    #[arg(long, value_name = "FILE")]
    pub(in crate::cli) deck: Option<PathBuf>,
    /// Parameters for CSV results (a .dat takes them from its deck).
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// The interface profile of a CSV result, from which the stick slope your FE code used is
    /// read: x_mm,slip_mm,shear_MPa (one load step) or step,x_mm,slip_mm,shear_MPa (a .dat
    /// reads it from the run's .frd).
    #[arg(long, value_name = "FILE")]
    pub(in crate::cli) interface: Option<PathBuf>,
    /// The kinematics of a CSV result's FE run, which the verdict names and a problem's
    /// envelope may depend on (each names the kinematics it holds for; a .dat's deck says it).
    #[arg(long, value_enum)]
    pub(in crate::cli) kinematics: Option<KinematicsArg>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
    pub(in crate::cli) format: CompareFormat,
}

/// The help of `compare`'s RESULT: each problem's CSV columns, from its deck face.
fn results_help() -> String {
    per_problem_help(
        "Result files: the .dat of a `microslip deck ccx` run (its deck JOB.inp beside it), or a \
         CSV from any FE code, with the problem's columns",
        |kind| vec![crate::fe::face::deck_face(kind).csv_columns()],
    ) + ". Several runs may be given, unless the problem compares one run only (it says why)"
}

/// What a deck is made of: the parameters, the mesh and the load path (`deck` and `bench`).
#[derive(Debug, Args)]
pub struct DeckArgs {
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Mesh density (fine halves every element size: run both to check convergence).
    #[arg(long, value_enum, default_value_t = DeckMesh::Coarse)]
    pub(in crate::cli) mesh: DeckMesh,
    /// The load steps, increasing, in the problem's load unit (default: the problem's own, in
    /// the deck's expected-values table); refused by a problem without a load.
    #[arg(
        long,
        value_name = "F0,F1,...",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    pub(in crate::cli) loads: Option<Vec<f64>>,
    /// Give the FE code the problem's stiff stick slope instead of K_T (its slip decays over a
    /// fraction of the members' thickness; the deck's header gives the value): plain Coulomb to
    /// within what the mesh resolves.
    #[arg(long)]
    pub(in crate::cli) near_coulomb: bool,
    /// Largest load change per increment (in the load's unit) in the load steps that end beyond
    /// first slip (friction is path-dependent once it saturates); default: the problem's, in
    /// the deck's step comments; refused by a problem whose deck has no such steps.
    #[arg(long, value_name = "N")]
    pub(in crate::cli) increment: Option<f64>,
}

/// External FE codes `deck` writes for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FeCode {
    /// CalculiX's solver, ccx (tested with 2.20).
    Ccx,
}

/// The kinematics of a CSV result's FE run (`compare --kinematics`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum KinematicsArg {
    /// Large rotations (NLGEOM in Abaqus and CalculiX).
    Nlgeom,
    /// Linear (small-displacement) geometry.
    Linear,
}

impl KinematicsArg {
    /// The kinematics it names.
    pub fn kinematics(self) -> crate::fe::kinematics::Kinematics {
        match self {
            KinematicsArg::Nlgeom => crate::fe::kinematics::Kinematics::Nlgeom,
            KinematicsArg::Linear => crate::fe::kinematics::Kinematics::Linear,
        }
    }
}
