//! Problem-agnostic building blocks of the closed forms: typed parameters (units, domains, the
//! error that names a field), overflow-free hyperbolic functions, certified root finding, regimes
//! and validity verdicts, the shear lag of two bars coupled through one frictional interface
//! (the closed forms the lap joint and the press fit share), the FE codes' default friction
//! penalties (data about K_T), and the scope in which solves may continue along a family
//! ([`family`]). Nothing here knows a problem; every problem in [`crate::problems`] is built on
//! it. No I/O.

pub mod code_defaults;
pub mod family;
pub mod format;
pub(crate) mod hyperbolic;
pub mod params;
pub mod regime;
pub mod shear_lag;
pub(crate) mod solve;
pub mod validity;
