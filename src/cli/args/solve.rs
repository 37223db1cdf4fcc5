//! `solve`: the value of one parameter at which a quantity takes a target value.

use super::*;
use clap::Args;

// The flags of `solve` (Command::Solve); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct SolveArgs {
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub model: ModelKind,
    /// The parameter to solve for (beam: L b h E P mu KT F; plate: L tp E nu mu P KT; lap: L b
    /// t1 t2 E1 E2 P mu KT F).
    #[arg(long, value_name = "NAME")]
    pub vary: String,
    /// The target, QUANTITY=VALUE (e.g. ratio=1.01, w(L)=0.05, X_r=9.5).
    #[arg(long, value_name = "QUANTITY=VALUE")]
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
