//! `kt`: K_T from K_N, the K_T the FE codes assume, and the K_T a tolerance asks for.

use super::*;
use clap::{Args, ValueEnum};

// The flags of `kt` (Command::Kt); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct KtArgs {
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
    /// Contact element length of your FE model (mm, in [1e-8, 1e6]), which the codes' default
    /// K_T scale with; default: a hundredth of the contact's length (L; 0.4 mm on lap-aluminium,
    /// 2 mm on paper-beams; the cylinder's is its half-width a).
    #[arg(long, value_name = "LE", allow_negative_numbers = true)]
    pub(in crate::cli) element_size: Option<f64>,
    /// Normal contact stiffness K_N (MPa/mm), for paper eq. 4 and the measured K_T/K_N range.
    #[arg(long, value_name = "KN", allow_negative_numbers = true)]
    pub(in crate::cli) kn: Option<f64>,
    /// Poisson ratio for eq. 4 with --kn (default: the plate's nu, else 0.3).
    #[arg(
        long,
        value_name = "NU",
        allow_negative_numbers = true,
        requires = "kn"
    )]
    pub(in crate::cli) nu: Option<f64>,
    /// Instead of the table: the smallest K_T for which the regularized w(L) (beams), u(L)
    /// (plate) or Delta (lap) is within T of Coulomb (1% or 0.01), and each FE code's setting
    /// for it.
    #[arg(long, value_name = "T", conflicts_with_all = ["kn", "nu"], allow_hyphen_values = true)]
    pub(in crate::cli) tolerance: Option<String>,
    /// With --tolerance: T of what. coulomb: of the Coulomb answer (K_T -> infinity);
    /// current: of the current K_T's answer (the K_T interval around it).
    #[arg(long, value_enum, value_name = "REF", default_value_t = ToleranceOf::Coulomb, requires = "tolerance")]
    pub(in crate::cli) of: ToleranceOf,
    /// With --tolerance, beams and lap: lowest force checked (N; default: the preset's F).
    #[arg(
        long,
        value_name = "A",
        allow_negative_numbers = true,
        requires = "tolerance"
    )]
    pub(in crate::cli) from: Option<f64>,
    /// With --tolerance, beams and lap: highest force checked (N; default: the preset's F).
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

/// What `kt --tolerance` is a tolerance of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ToleranceOf {
    /// Of the Coulomb answer (the K_T -> infinity limit): the smallest K_T within it.
    Coulomb,
    /// Of the current K_T's answer: the K_T interval around it.
    Current,
}
