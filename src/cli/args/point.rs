//! `microslip PROBLEM`: one state of a problem, one subcommand per problem of the registry
//! ([`ForKind`]`<`[`PointArgs`]`>`): a problem with a continuum reference declares
//! `--continuum` too, read with [`ForKind::flag`].

use super::*;
use clap::{Arg, ArgAction, Args};

/// The flags of one state's report, every problem's.
#[derive(Debug, Args)]
pub struct PointArgs {
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(in crate::cli) format: ReportFormat,
}

/// The id of `--continuum`, declared by the problems that have a continuum reference.
pub(in crate::cli) const CONTINUUM: &str = "continuum";

impl PerProblem for PointArgs {
    fn offered(_: ModelKind) -> bool {
        true
    }

    fn describe(kind: ModelKind, command: clap::Command) -> clap::Command {
        let d = kind.description();
        let command = command
            .about(format!(
                "{}: one state, both laws side by side, regimes",
                d.summary
            ))
            .long_about(format!(
                "{}: one state, both laws side by side, regimes.\n\n\
                 One state of the {}: every quantity under Coulomb's law and the regularized \
                 one, the regimes and where the closed forms hold. The parameters come from \
                 the preset (default {}) and --set:\n\n{}",
                d.summary,
                d.title,
                d.paper_preset,
                param_lines(kind)
            ))
            .edit_arg("assignments", |a| {
                a.help(format!(
                    "Set a parameter, e.g. KT=120 (keys: {})",
                    kind.params()
                        .iter()
                        .map(|p| p.name())
                        .collect::<Vec<_>>()
                        .join(" ")
                ))
            });
        let command = match kind.problem().faces().continuum {
            Some(_) => command.arg(
                Arg::new(CONTINUUM)
                    .long("continuum")
                    .action(ArgAction::SetTrue)
                    .help(format!(
                        "Also solve the 2-D continuum reference of the {} (seconds), which \
                         an FE code's answer is judged against; done anyway where the closed \
                         forms are not expected to hold",
                        d.title
                    )),
            ),
            None => command,
        };
        hide_foreign_choices(kind, command)
    }
}
