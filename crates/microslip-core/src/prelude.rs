//! What most numerical users need, in one `use microslip_core::prelude::*;`: the problems'
//! models and their checked constructors, the capability traits a generic study is written
//! over, the registry's handles, and the errors. Everything else stays one module path away.
//!
//! ```
//! use microslip_core::prelude::*;
//! let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
//! let w = beams.regularized(TipForce::new(100.0)?).tip_deflection(); // mm
//! assert!(w > 0.0);
//! // Every registered problem, with its parameters (key, unit, allowed range).
//! for kind in ModelKind::ALL {
//!     assert!(!kind.params().is_empty());
//! }
//! # Ok::<(), ParamError>(())
//! ```

pub use crate::kernel::params::{ParamError, Unit};
pub use crate::kernel::regime::Regime;
pub use crate::problems::inputs::{Inputs, Model};
pub use crate::problems::lap::closed_form::{JointForce, LapJoint, LapParams};
pub use crate::problems::load_driven::LoadDriven;
pub use crate::problems::plate::closed_form::{PlateParams, SqueezedPlate};
pub use crate::problems::twin_beams::closed_form::{TipForce, TwinBeams, TwinBeamsParams};
pub use crate::problems::{AnyProblem, Continuum, ModelKind, Param, Problem};
pub use crate::study::curves::{Samples, Spacing};
