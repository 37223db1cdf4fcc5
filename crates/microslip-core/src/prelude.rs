//! What most numerical users need, in one `use microslip_core::prelude::*;`: the problems'
//! models and their checked constructors, the capability traits a generic study is written
//! over, the registry's handles, and the errors. Everything else stays one module path away.
//!
//! The per-problem part is generated from the registry ([`crate::with_problems`]): each
//! registered problem's type (`TwinBeamsProblem`, ...) and everything public in its folder's
//! `closed_form` and `params` modules (its model, its checked force and parameter types, its law states), so
//! that a new problem is in the prelude by its registry line and this file names none.
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
pub use crate::problems::load_driven::LoadDriven;
pub use crate::problems::{AnyProblem, Continuum, ModelKind, Param, Problem};
pub use crate::study::curves::{Samples, Spacing};

/// Re-exports every registered problem's type and its closed forms (module docs).
macro_rules! problem_exports {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        $(
            pub use crate::problems::$folder::$problem;
            // A folder that two registry lines name is re-exported twice: the same items.
            #[allow(unused_imports)]
            pub use crate::problems::$folder::closed_form::*;
            #[allow(unused_imports)]
            pub use crate::problems::$folder::params::*;
        )+
    };
}

crate::with_problems!(problem_exports);
