//! microslip: closed-form solutions of two friction benchmarks (Ligier & Bonhote, 2014) under the
//! plain and the regularized Coulomb law.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! Layout (the shape of `ARCHITECTURE.md`, with four additions, each for a reason):
//! - `model/` pure physics; beside the planned files, `cycle.rs` (cyclic loading is a closed form of
//!   the same model) and `code_defaults.rs` (the FE codes' default friction penalties are data about
//!   K_T, kept next to `stiffness.rs`).
//! - `numeric/` the independent FE solvers; `newton.rs` holds the load stepping both share.
//! - `fit/` identification of mu and K_T: an optimisation over the closed form, neither physics nor
//!   I/O, so a module of its own (it parses data text but never opens files).
//! - `verify.rs` the only place that calls both the closed forms and the FE solvers.
//! - `curves.rs`, `preset.rs`, `report/` (text, JSON, CSV), `cli.rs` and `tui/` as planned. Presets are
//!   parsed from a TOML table rather than serde structs so that every problem of a file can be
//!   reported with its line, not only the first.
//!
//! ```
//! use microslip::{TipForce, TwinBeams, TwinBeamsParams};
//! let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
//! let state = beams.regularized(TipForce::new(100.0)?);
//! assert_eq!(state.regime().label(), "microslip+macroslip");
//! # Ok::<(), microslip::ParamError>(())
//! ```

#[cfg(feature = "app")]
#[doc(hidden)]
pub mod cli;
pub mod curves;
pub mod fit;
pub mod model;
pub mod numeric;
pub mod preset;
pub mod report;
#[cfg(feature = "app")]
#[doc(hidden)]
pub mod tui;
pub mod verify;

pub use model::inputs::{Inputs, Model};
pub use model::params::{BeamParam, ModelKind, Param, ParamError, PlateParam, Unit};
pub use model::plate::{
    ContactPressure, CoulombPlate, PlateParams, RegularizedPlate, SqueezedPlate,
};
pub use model::regime::Regime;
pub use model::twin_beams::{CoulombBeams, RegularizedBeams, TipForce, TwinBeams, TwinBeamsParams};
