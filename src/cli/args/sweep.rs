//! `sweep`: the generic sweep (`--model`, or the preset's problem), `sweep PROBLEM` for every
//! problem of the registry ([`ForKind`]`<`[`ProblemSweepArgs`]`>`) and `sweep cycle`.

use super::*;
use clap::{Arg, Args, Subcommand};

/// A generic command of any problem (its own flags, when no subcommand is given) or one of its
/// per-problem subcommands ([`ForKind`], one per problem of the registry, with the flags that
/// problem takes: `sweep PROBLEM`, `fit PROBLEM`). A subcommand and the generic flags exclude
/// each other, so a subcommand's `--help` shows its own flags only.
#[derive(Debug, Args)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    subcommand_value_name = "PROBLEM",
    subcommand_help_heading = "Problems (one each, with its own flags)"
)]
pub struct WithProblems<A: Subcommand, G: Args> {
    #[command(subcommand)]
    pub(in crate::cli) command: Option<A>,
    #[command(flatten)]
    pub(in crate::cli) generic: G,
}

/// `sweep`: the generic sweep, `sweep PROBLEM` or `sweep cycle`.
pub type SweepArgs = WithProblems<SweepCommand, GenericSweepArgs>;

/// The flags of the generic `sweep`: the problem comes from --model or the preset.
#[derive(Debug, Args)]
pub struct GenericSweepArgs {
    // Its help names the default problem from the registry (`model_flag_help`).
    #[arg(long, value_parser = model_kind_parser(), help = model_flag_help(""))]
    pub(in crate::cli) model: Option<ModelKind>,
    // The help lists each problem's keys from the registry (`vary_help`).
    #[arg(long, value_name = "NAME", help = vary_help())]
    pub(in crate::cli) vary: Option<String>,
    /// First value of the varied parameter (in its unit: F in N, K_T in MPa/mm, ...).
    #[arg(long, value_name = "A", allow_negative_numbers = true, required = true)]
    pub(in crate::cli) from: Option<f64>,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true, required = true)]
    pub(in crate::cli) to: Option<f64>,
    /// Number of rows, both ends included (2 to 100000000; default 11, or 1 when --from = --to).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub(in crate::cli) points: Option<u64>,
    #[command(flatten)]
    pub(in crate::cli) spacing: SpacingArgs,
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub(in crate::cli) format: TableFormat,
}

/// The help of the generic sweep's `--vary`: every problem's keys, as the registry lists them.
fn vary_help() -> String {
    per_problem_help("The parameter to vary", |kind| {
        kind.params().iter().map(|p| p.name()).collect()
    }) + ". Default: the problem's load F, else KT. Columns: the parameter's then those of the \
         default's sweep; for the default, that sweep's own"
}

/// Rows of a generic `sweep` without --points: the ends and nine steps between, so a range of
/// round ends gives round values (0.1 to 0.5: steps of 0.04).
pub(in crate::cli) const DEFAULT_SWEEP_POINTS: u64 = 11;

/// Sweep subcommands: one per problem, and the cycle sweep.
#[derive(Debug, Subcommand)]
pub enum SweepCommand {
    /// One per problem of the registry.
    #[command(flatten)]
    Problem(ForKind<ProblemSweepArgs>),
    /// Any problem with a load (the preset's, or --model's) cycled at amplitudes from F0 to F1
    /// (in the load's unit): dissipation and damping per cycle.
    Cycle(CycleSweepArgs),
}

// The flags of `sweep PROBLEM`; its help is the problem's (`PerProblem::describe`). A problem
// without a load sweeps K_T by default and also takes `--kt-from A --kt-to B`.
#[derive(Debug, Args)]
pub struct ProblemSweepArgs {
    /// The parameter to vary.
    #[arg(long, value_name = "NAME")]
    pub(in crate::cli) vary: Option<String>,
    /// First value of the varied parameter.
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub(in crate::cli) from: Option<f64>,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true)]
    pub(in crate::cli) to: Option<f64>,
    /// Number of rows, both ends included (2 to 100000000; 1 when both ends are equal).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub(in crate::cli) points: u64,
    #[command(flatten)]
    pub(in crate::cli) spacing: SpacingArgs,
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub(in crate::cli) format: TableFormat,
}

/// The ids of `--kt-from` and `--kt-to`, declared by the problems without a load.
pub(in crate::cli) const KT_FROM: &str = "kt_from";
/// See [`KT_FROM`].
pub(in crate::cli) const KT_TO: &str = "kt_to";

/// The parameter a sweep of `kind` varies unless `--vary` names another: the problem's load
/// (F) when it has one, else K_T, the parameter every problem has and the one the plate's
/// results depend on most. Its table is the problem's own sweep table, without a column
/// repeating the varied value.
pub(in crate::cli) fn default_vary(kind: ModelKind) -> Option<Param> {
    kind.description()
        .load
        .or_else(|| kind.params().iter().copied().find(|p| p.is_stiffness()))
}

impl PerProblem for ProblemSweepArgs {
    fn offered(kind: ModelKind) -> bool {
        default_vary(kind).is_some()
    }

    fn describe(kind: ModelKind, command: clap::Command) -> clap::Command {
        let title = title(kind);
        let keys = kind
            .params()
            .iter()
            .map(|p| p.name())
            .collect::<Vec<_>>()
            .join(" ");
        let Some(default) = default_vary(kind) else {
            return command;
        };
        let unit = default.unit().symbol();
        let name = default.name();
        let command = command
            .edit_arg("vary", |a| {
                a.help(format!(
                    "The parameter to vary: {keys} (default {name}). Columns: the parameter's \
                     then those of the {name} sweep; for {name}, the {name} sweep's own"
                ))
            })
            .edit_arg("from", |a| {
                a.help(format!(
                    "First value of the varied parameter (in its unit; {name}: {unit})"
                ))
            });
        let command = if kind.description().load.is_some() {
            command
                .about(format!(
                    "{title} over a range of its load {name} ({unit}), linearly spaced \
                     (replaces the preset's {name}), or of any parameter with --vary"
                ))
                .edit_arg("from", |a| a.required(true))
                .edit_arg("to", |a| a.required(true))
        } else {
            command
                .about(format!(
                    "{title} over a range of {name} ({unit}), logarithmically spaced unless \
                     --linear, or of any parameter with --vary NAME --from A --to B"
                ))
                .arg(
                    Arg::new(KT_FROM)
                        .long("kt-from")
                        .value_name("A")
                        .allow_negative_numbers(true)
                        .value_parser(clap::value_parser!(f64))
                        .conflicts_with_all(["vary", "from"])
                        .help(format!("First {name} ({unit})")),
                )
                .arg(
                    Arg::new(KT_TO)
                        .long("kt-to")
                        .value_name("B")
                        .allow_negative_numbers(true)
                        .value_parser(clap::value_parser!(f64))
                        .conflicts_with_all(["vary", "to"])
                        .help(format!("Last {name} ({unit})")),
                )
        };
        hide_foreign_choices(kind, command)
    }
}

/// How sweep values are spaced; the default is logarithmic for K_T, linear for the others.
#[derive(Debug, Args)]
pub struct SpacingArgs {
    /// Space the values linearly.
    #[arg(long, conflicts_with = "log")]
    pub(in crate::cli) linear: bool,
    /// Space the values logarithmically (both ends > 0).
    #[arg(long)]
    pub(in crate::cli) log: bool,
}

impl SpacingArgs {
    /// The spacing asked for, or the parameter's default.
    pub(in crate::cli) fn spacing(&self, param: Param) -> Spacing {
        if self.linear {
            Spacing::Linear
        } else if self.log || param.is_stiffness() {
            Spacing::Logarithmic
        } else {
            Spacing::Linear
        }
    }
}

// The flags of `sweep cycle` (SweepCommand::Cycle); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct CycleSweepArgs {
    /// First amplitude (in the load's unit: N, or N/mm for a line load).
    #[arg(long, value_name = "F0", allow_negative_numbers = true)]
    pub(in crate::cli) from: f64,
    /// Last amplitude.
    #[arg(long, value_name = "F1", allow_negative_numbers = true)]
    pub(in crate::cli) to: f64,
    /// Number of rows, both ends included (2 to 100000000).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub(in crate::cli) points: u64,
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub(in crate::cli) format: TableFormat,
}
