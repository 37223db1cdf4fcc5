//! microslip: closed-form solutions of two friction benchmarks (Ligier & Bonhote, 2014) under the
//! plain and the regularized Coulomb law.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! ```
//! use microslip::{TipForce, TwinBeams, TwinBeamsParams};
//! let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
//! let state = beams.regularized(TipForce::new(100.0)?);
//! assert_eq!(state.regime().label(), "microslip+macroslip");
//! # Ok::<(), microslip::ParamError>(())
//! ```

pub mod cli;
pub mod curves;
pub mod fit;
pub mod model;
pub mod numeric;
pub mod preset;
pub mod report;
pub mod tui;
pub mod verify;

pub use model::plate::{
    ContactPressure, CoulombPlate, PlateParams, RegularizedPlate, SqueezedPlate,
};
pub use model::regime::Regime;
pub use model::twin_beams::{CoulombBeams, RegularizedBeams, TipForce, TwinBeams, TwinBeamsParams};
pub use model::validate::ParamError;
