//! microslip: closed-form solutions of two friction benchmarks (Ligier & Bonhote, 2014) under the
//! plain and the regularized Coulomb law.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! # Layers
//! Data flows one way; no module imports one above it:
//!
//! ```text
//! preset (TOML) / --set / keys -> model::inputs::Inputs (typed model::params::Param)
//!   -> model (checked constructors, closed forms)   <- numeric (independent FE) <- verify
//!   -> curves (the only loops over parameters)      <- fit (identification)
//!   -> report (text, CSV, JSON; views)  -> cli | tui   (feature `app`)
//! ```
//!
//! - [`model`]: pure physics. Typed parameters ([`model::params`]: key, unit, domain, step), inputs
//!   and validated models ([`model::inputs`]), the closed forms, cyclic loading, K_T helpers, FE
//!   code defaults, solving any parameter for a target value of a quantity
//!   ([`model::target`]) and the smallest K_T within a tolerance of Coulomb
//!   ([`model::tolerance`]). No I/O.
//! - [`numeric`]: finite-element solvers that never call the closed forms.
//! - [`verify`]: the only place that calls both, returning the worst cases as data.
//! - [`curves`]: sweeps, the hysteresis loop and the K_T comparison, computed once for every output.
//! - [`fit`]: identification of mu and K_T, with structured evidence (no prose).
//! - [`preset`]: TOML parse and write, and the file store (atomic, no clobber).
//! - [`file`]: reading a file a user named, with a size cap (presets, measurements); below
//!   `preset` and `fit`, above nothing.
//! - [`report`]: every format, from one serde row per table; what views exist ([`report::view`]);
//!   the series of every chart ([`report::chart`], drawn by the TUI and by the SVG figures of
//!   `report::figure`, behind the feature `figures`, on by default through `app`).
//! - `cli` and `tui` (behind the default feature `app`, hidden from these docs): thin layers that
//!   parse flags or keys, call the library and hand the results to `report` or the screen. With
//!   `default-features = false` none of clap, ratatui, crossterm or signal-hook is compiled.
//!
//! Beside `ARCHITECTURE.md`'s plan: `model/` also holds `cycle.rs` (cyclic loading is a closed form
//! of the same model) and `code_defaults.rs` (FE codes' default friction penalties are data about
//! K_T); `verify.rs` sits at the top level because it is neither physics nor I/O; chart and table
//! enums live in `report::view` so that figure exports can name views the way the TUI does.
//!
//! # Example
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
pub mod fe;
pub mod file;
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
