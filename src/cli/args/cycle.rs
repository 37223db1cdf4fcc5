//! `cycle`: a problem with a load cycled between +FA and -FA.

use super::*;
use clap::Args;

// The flags of `cycle` (Command::Cycle); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct CycleArgs {
    /// Amplitude (in the load's unit: N, or N/mm for a line load).
    #[arg(long, value_name = "FA", allow_negative_numbers = true)]
    pub(in crate::cli) amplitude: f64,
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Points per branch of the loop (csv format).
    #[arg(long, value_name = "N", default_value_t = 101, value_parser = parse_count, allow_negative_numbers = true)]
    pub(in crate::cli) points: u64,
    /// Output format: text summary, JSON summary, or the loop as CSV.
    #[arg(long, value_enum, default_value_t = CycleFormat::Text)]
    pub(in crate::cli) format: CycleFormat,
}
