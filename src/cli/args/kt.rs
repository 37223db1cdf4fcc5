//! `kt`: K_T from K_N, the K_T the FE codes assume, and the K_T a tolerance asks for.

use super::*;
use clap::{Args, ValueEnum};

// The flags of `kt` (Command::Kt); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct KtArgs {
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Contact element length of your FE model (mm, in [1e-8, 1e6]), which the codes' default
    /// K_T scale with; default: a hundredth of the contact's length along the slip (the
    /// problem's, e.g. its L or a contact's half-width; the table states the value used).
    #[arg(long, value_name = "LE", allow_negative_numbers = true)]
    pub(in crate::cli) element_size: Option<f64>,
    /// Normal contact stiffness K_N (MPa/mm), for paper eq. 4 and the measured K_T/K_N range.
    #[arg(long, value_name = "KN", allow_negative_numbers = true)]
    pub(in crate::cli) kn: Option<f64>,
    /// Poisson ratio for eq. 4 with --kn (default: the problem's nu where it has one, else 0.3).
    #[arg(
        long,
        value_name = "NU",
        allow_negative_numbers = true,
        requires = "kn"
    )]
    pub(in crate::cli) nu: Option<f64>,
    // The help names each problem's response from the registry (`tolerance_help`).
    #[arg(
        long,
        value_name = "T",
        conflicts_with_all = ["kn", "nu"],
        allow_hyphen_values = true,
        help = tolerance_help()
    )]
    pub(in crate::cli) tolerance: Option<String>,
    /// With --tolerance: T of what. coulomb: of the Coulomb answer (K_T -> infinity);
    /// current: of the current K_T's answer (the K_T interval around it).
    #[arg(long, value_enum, value_name = "REF", default_value_t = ToleranceOf::Coulomb, requires = "tolerance")]
    pub(in crate::cli) of: ToleranceOf,
    /// With --tolerance, a problem with a load: the lowest load checked (in the load's unit;
    /// default: the preset's load).
    #[arg(
        long,
        value_name = "A",
        allow_negative_numbers = true,
        requires = "tolerance"
    )]
    pub(in crate::cli) from: Option<f64>,
    /// With --tolerance, a problem with a load: the highest load checked (in the load's unit;
    /// default: the preset's load).
    #[arg(
        long,
        value_name = "B",
        allow_negative_numbers = true,
        requires = "tolerance"
    )]
    pub(in crate::cli) to: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(in crate::cli) format: ReportFormat,
}

/// The help of `kt --tolerance`: each problem's response from the registry.
fn tolerance_help() -> String {
    let responses: Vec<String> = ModelKind::ALL
        .iter()
        .map(|kind| {
            format!(
                "{kind}: {}",
                crate::problems::Quantity::Response.name(*kind)
            )
        })
        .collect();
    format!(
        "Instead of the table: the smallest K_T for which the regularized response ({}) is \
         within T of Coulomb (1% or 0.01), and each FE code's setting for it",
        responses.join("; ")
    )
}

/// What `kt --tolerance` is a tolerance of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ToleranceOf {
    /// Of the Coulomb answer (the K_T -> infinity limit): the smallest K_T within it.
    Coulomb,
    /// Of the current K_T's answer: the K_T interval around it.
    Current,
}
