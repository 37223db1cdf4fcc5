//! [`NumericError`]: why a finite-element solve failed. Its own module so that the models
//! (`beams`, `plate`) and the shared Newton driver all use it without importing one another.

use thiserror::Error;

/// Why a numerical solve failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum NumericError {
    /// Newton did not converge even with small load steps.
    #[error("Newton iterations did not converge at load {load} after {cuts} step cuts")]
    NoConvergence {
        /// The load level that failed.
        load: f64,
        /// How many times the step was halved.
        cuts: u32,
    },
    /// The stiffness matrix is singular (should not happen with a clamped model).
    #[error("singular stiffness matrix at row {0}")]
    Singular(usize),
    /// A load that is not a finite number.
    #[error("invalid load {0}: must be finite")]
    BadLoad(f64),
    /// Inputs the solver does not handle (the message says which and why).
    #[error("{0}")]
    OutOfRange(String),
    /// A solve that was attempted and failed (the message says where and why).
    #[error("{0}")]
    Unsolved(String),
}

/// The advice of a refusal whose cure is a softer interface: "lower K_T to at most X MPa/mm" (or
/// `other`, e.g. "raise E") where X is a K_T the door accepts; where even the least accepted K_T
/// is too stiff, that no accepted K_T works (and `other`, the only cure left). Advising a value the
/// door then refuses sends users in a circle.
pub(crate) fn stiffness_advice(largest: f64, other: Option<&str>) -> String {
    let least = crate::kernel::params::Domain::STIFFNESS.min();
    if largest >= least {
        let other = other.map_or(String::new(), |o| format!(" or {o}"));
        return format!("lower K_T to at most {} MPa/mm{other}", short(largest));
    }
    let other = other.map_or(String::new(), |o| format!(": {o}"));
    format!(
        "no accepted K_T is small enough (this needs at most {} MPa/mm, the least accepted is {} \
         MPa/mm){other}",
        short(largest),
        short(least)
    )
}

/// A number in a message, to four significant digits ("1.714", "1.75e10", "5.385e-7").
pub fn short(x: f64) -> String {
    crate::kernel::params::significant(x, 4)
}
