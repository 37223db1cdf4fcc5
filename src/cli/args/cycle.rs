//! `cycle`: a problem with a load cycled between +FA and -FA, as the generic command (the
//! preset's problem, or `--model`) or `cycle PROBLEM` for every problem of the registry with a
//! cycle ([`ForKind`]`<`[`CycleFlags`]`>`).

use super::*;
use clap::Args;

/// `cycle`: the generic cycle, or `cycle PROBLEM`.
pub type CycleArgs = WithProblems<ForKind<CycleFlags>, GenericCycleArgs>;

/// The flags of the generic `cycle`: the problem comes from --model or the preset.
#[derive(Debug, Args)]
pub struct GenericCycleArgs {
    // Its help names the default problem from the registry (`model_flag_help`).
    #[arg(long, value_parser = model_kind_parser(), help = model_flag_help(", one with a load to cycle"))]
    pub(in crate::cli) model: Option<ModelKind>,
    #[command(flatten)]
    pub(in crate::cli) cycle: CycleFlags,
}

// The flags every cycle has, generic or per problem; the help of `cycle PROBLEM` is the
// problem's (`PerProblem::describe`).
#[derive(Debug, Args)]
pub struct CycleFlags {
    // An option required by clap, so that the generic flags parse when a problem's subcommand
    // holds them.
    /// Amplitude (in the load's unit: N, or N/mm for a line load).
    #[arg(
        long,
        value_name = "FA",
        allow_negative_numbers = true,
        required = true
    )]
    pub(in crate::cli) amplitude: Option<f64>,
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Points per branch of the loop (csv format).
    #[arg(long, value_name = "N", default_value_t = 101, value_parser = parse_count, allow_negative_numbers = true)]
    pub(in crate::cli) points: u64,
    /// Output format: text summary, JSON summary, or the loop as CSV.
    #[arg(long, value_enum, default_value_t = CycleFormat::Text)]
    pub(in crate::cli) format: CycleFormat,
}

impl PerProblem for CycleFlags {
    fn offered(kind: ModelKind) -> bool {
        crate::report::face::faces(kind).cycle.is_some()
    }

    fn describe(kind: ModelKind, command: clap::Command) -> clap::Command {
        let Some(load) = kind.description().load else {
            return command;
        };
        let (name, unit) = (load.name(), load.unit().symbol());
        let command = command
            .about(format!(
                "{} cycled between +FA and -FA (its load {name}, {unit}): loop, dissipation, \
                 damping",
                title(kind)
            ))
            .edit_arg("amplitude", |a| {
                a.help(format!("Amplitude of {name} ({unit})"))
            });
        hide_foreign_choices(kind, command)
    }
}
