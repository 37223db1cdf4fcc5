//! The command line as clap parses it, one file per command family: the top-level commands
//! here, each family's flags in its own file. A command that is run for one problem reaches it
//! the same way everywhere: by the problem's registry key, either as a subcommand generated
//! from the registry ([`ForKind`]: `microslip cylinder`, `sweep lap`, `fit beam`) or as a value
//! the registry's parser reads (`solve cylinder`, `deck ccx plate`, `--model lap`). No file
//! here lists the problems.

use super::*;
use clap::Subcommand;

mod cycle;
mod fe;
mod fit;
mod formats;
mod inputs;
mod kt;
mod plot;
mod point;
mod problem;
mod solve;
mod sweep;

pub use cycle::*;
pub use fe::*;
pub use fit::*;
pub use formats::*;
pub use inputs::*;
pub use kt::*;
pub use plot::*;
pub use point::*;
pub use problem::*;
pub use solve::*;
pub use sweep::*;

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Report of the paper's data sets, as text.
    Report,
    /// One subcommand per problem of the registry (`microslip PROBLEM`): its help from the
    /// problem's description, its options those the problem declares.
    #[command(flatten)]
    Problem(ForKind<PointArgs>),
    /// Tables over a parameter range, as CSV or JSON.
    Sweep(SweepArgs),
    /// The value of one parameter at which a quantity takes a target value (a certified root).
    ///
    /// The quantities are the problem's (--target lists each problem's; ratio: regularized
    /// over Coulomb, e.g. ratio=1.01 for "within 1 % of Coulomb"). The parameter's whole
    /// accepted range is searched unless --from/--to narrow it; every root is listed, and none
    /// is an error.
    Solve(SolveArgs),
    /// K_T from K_N and the K_T that FE codes assume, with what each does to the answer.
    ///
    /// Each answer is given against the current K_T's and against Coulomb's (`vs current`,
    /// `vs Coulomb`, in %).
    Kt(KtArgs),
    /// Any problem with a load (the preset's, or --model's) cycled between +FA and -FA: loop,
    /// dissipation, damping.
    Cycle(CycleArgs),
    /// Identify mu and K_T from a measured curve (the problem's response against its load).
    Fit(FitArgs),
    /// List bundled and user presets with their descriptions.
    Presets,
    /// Cross-check the closed forms against the finite-element solvers; exit 1 above tolerance.
    Verify(VerifyArgs),
    /// Write a CalculiX input deck for these parameters (see docs/guide.md).
    Deck(DeckCommandArgs),
    /// Benchmark CalculiX in one command: write the deck, run ccx on it (progress on stderr, its
    /// files and log kept in a work folder) and print the comparison with the closed forms.
    ///
    /// When stderr is not a terminal, one progress line per increment ccx starts. Exit 3 when
    /// ccx is not found, fails or writes no results (the last lines of its log follow); on
    /// SIGTERM, SIGINT or SIGHUP, ccx and what it started are ended first, then exit 128 + the
    /// signal.
    Bench(BenchArgs),
    /// Compare FE results with the closed forms, point by point, and the K_T they imply.
    Compare(CompareArgs),
    /// Run a verification suite: each case's deck on a ladder of meshes (h, h/2, h/4) and two
    /// increments, the answers extrapolated to converged ones (Richardson) and judged against
    /// the closed forms; a scorecard as text, JSON or JUnit XML.
    ///
    /// Runs on a local pool of solver processes (--executor local) or as one Slurm job array
    /// (--executor slurm). Exit 0 only when every case agrees, 1 when one does not agree, is not
    /// converged or is not judged, 2 for refused input, 3 when a solver failed, 128 + N on signal
    /// N (the solvers are ended first; --resume carries on).
    Suite(SuiteArgs),
    /// Draw a chart of the terminal UI as an SVG figure, or write its data as CSV.
    Plot(PlotArgs),
    /// Regenerate the paper's figures, the cycle loop and D vs F_a: SVG + CSV each, and an
    /// index.html that shows them all; with --preset or --set, every chart of that bench instead,
    /// its values in each caption.
    Figures(FiguresArgs),
    /// Validate presets (files, or names as --preset takes them); report every problem; exit 1 if
    /// any.
    Check(CheckArgs),
}
