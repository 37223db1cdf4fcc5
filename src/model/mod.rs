//! Pure physics: parameter types with checked constructors, closed-form solutions, root finding.
//! No terminal, file or network I/O here, so every function is a plain, testable computation.

pub mod code_defaults;
pub mod cycle;
mod hyperbolic;
pub mod inputs;
pub mod params;
pub mod plate;
pub mod regime;
pub(crate) mod solve;
pub mod stiffness;
pub mod target;
pub mod tolerance;
pub mod twin_beams;
pub mod validity;
