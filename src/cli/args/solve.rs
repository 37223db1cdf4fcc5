//! `solve`: the value of one parameter at which a quantity takes a target value.

use super::*;
use clap::Args;

// The flags of `solve` (Command::Solve); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct SolveArgs {
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub model: ModelKind,
    // The help lists each problem's keys from the registry (`per_problem_help`).
    #[arg(long, value_name = "NAME", help = per_problem_help(
        "The parameter to solve for",
        |kind| kind.params().iter().map(|p| p.name()).collect(),
    ))]
    pub vary: String,
    // The help lists each problem's quantities from the registry (`per_problem_help`).
    #[arg(long, value_name = "QUANTITY=VALUE", help = per_problem_help(
        "The target, QUANTITY=VALUE (e.g. ratio=1.01)",
        |kind| kind.description().quantities.iter().map(|q| q.name).collect(),
    ))]
    pub target: String,
    /// Lowest value of the parameter searched (default: its smallest accepted value).
    #[arg(long, value_name = "A", allow_negative_numbers = true, requires = "to")]
    pub from: Option<f64>,
    /// Highest value searched (default: its largest accepted value).
    #[arg(
        long,
        value_name = "B",
        allow_negative_numbers = true,
        requires = "from"
    )]
    pub to: Option<f64>,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub format: ReportFormat,
}
