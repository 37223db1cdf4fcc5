//! `fit`: the generic fit (`--model`, or the preset's problem) and `fit PROBLEM DATA.csv` for
//! every problem of the registry that has a fit ([`ForKind`]`<`[`ProblemFitArgs`]`>`).

use super::*;
use clap::{Args, ValueEnum};

/// `fit`: the generic fit of any problem with a load, or `fit PROBLEM`.
pub type FitArgs = WithProblems<ForKind<ProblemFitArgs>, GenericFitArgs>;

/// The arguments of the generic `fit`: the problem comes from --model or the preset.
#[derive(Debug, Args)]
pub struct GenericFitArgs {
    // The help names each problem's columns from the registry (`fit_data_help`). Two values
    // are a word that is no problem's key and the data (`fit cylindre DATA.csv`): refused
    // with the problem it is a slip of.
    #[arg(
        value_name = "DATA.csv",
        required = true,
        num_args = 1..=2,
        help = fit_data_help()
    )]
    pub(in crate::cli) data: Vec<PathBuf>,
    // Its help names the default problem from the registry (`model_flag_help`).
    #[arg(long, value_parser = model_kind_parser(), help = model_flag_help(", one with a load to fit the curve against"))]
    pub(in crate::cli) model: Option<ModelKind>,
    #[command(flatten)]
    pub(in crate::cli) fit: FitFlags,
}

/// The flags every fit has, generic or per problem.
#[derive(Debug, Args)]
pub struct FitFlags {
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Hold a parameter at a value instead of fitting it: mu=0.3 or KT=600 (repeatable).
    #[arg(long = "fix", value_name = "KEY=VALUE")]
    pub(in crate::cli) fixed: Vec<String>,
    /// What the standard errors assume about the scatter of the response [default: relative;
    /// a sigma_mm column in the data gives each point's own, taken as known].
    #[arg(long, value_enum)]
    pub(in crate::cli) weights: Option<WeightsArg>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(in crate::cli) format: ReportFormat,
}

/// The load and response columns a fit of `kind` reads, as the registry's fit says them.
fn fit_columns(kind: ModelKind) -> Option<(&'static str, &'static str)> {
    let structure = crate::fit::Structure::of(&Inputs::paper(kind).validate().ok()?)?;
    Some((structure.load_column(), structure.response_column()))
}

/// The help of the generic fit's DATA.csv: the response column of every problem with a load,
/// as the registry lists them.
fn fit_data_help() -> String {
    let columns: Vec<String> = ModelKind::ALL
        .iter()
        .filter_map(|kind| {
            let (load, response) = fit_columns(*kind)?;
            Some(format!("{load},{response} ({kind})"))
        })
        .collect();
    format!(
        "Measurements: CSV with a header naming the problem's load and response columns, {}; \
         other columns are ignored. The problem may be named before it (`fit PROBLEM \
         DATA.csv`)",
        columns.join(" or ")
    )
}

// The flags of `fit PROBLEM`; its help is the problem's (`PerProblem::describe`).
#[derive(Debug, Args)]
pub struct ProblemFitArgs {
    /// Measurements: CSV with a header naming the load and the response columns.
    #[arg(value_name = "DATA.csv")]
    pub(in crate::cli) data: PathBuf,
    /// The problem, if given as well: it must be this one.
    #[arg(long, value_parser = model_kind_parser(), hide = true)]
    pub(in crate::cli) model: Option<ModelKind>,
    #[command(flatten)]
    pub(in crate::cli) fit: FitFlags,
}

impl PerProblem for ProblemFitArgs {
    fn offered(kind: ModelKind) -> bool {
        fit_columns(kind).is_some()
    }

    fn describe(kind: ModelKind, command: clap::Command) -> clap::Command {
        let Some((load, response)) = fit_columns(kind) else {
            return command;
        };
        let d = kind.description();
        let command = command
            .about(format!(
                "{}: fit mu and K_T to a measured curve (CSV with columns {load},{response}); \
                 the other parameters come from the preset (default {})",
                title(kind),
                d.paper_preset
            ))
            .edit_arg("data", |a| {
                a.help(format!(
                    "Measurements: CSV with a header naming {load} and {response} (other \
                     columns are ignored)"
                ))
            });
        hide_foreign_choices(kind, command)
    }
}

/// `fit --weights`: the scatter of the measured response that the standard errors assume.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum WeightsArg {
    /// The same at every point (a gauge whose error does not grow with the reading).
    Absolute,
    /// Proportional to the response (gain, calibration): the default.
    Relative,
}
