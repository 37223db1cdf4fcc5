//! microslip-core: the physics of microslip, for a numerical user who wants the answers without
//! the terminal application. Friction benchmarks (the problems of the registry,
//! [`with_problems!`]: the two of Ligier & Bonhote, 2014, and the ones added since) under the
//! plain and the regularized Coulomb law: an interface first deforms elastically (shear stress = K_T times the
//! microslip) and slides once the stress reaches mu times the pressure.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! This crate has no terminal, no file format and no command line in it: its normal
//! dependencies are `roots` (certified root finding) and `thiserror` (typed errors). Reading
//! files, writing reports, FE decks and the user interfaces live in the `microslip` application
//! above it.
//!
//! # Layers
//! Data flows one way, lowest first (the application's `tests/layering.rs` checks it):
//!
//! ```text
//! kernel <- numeric <- problems <- study, fit, verify
//! ```
//!
//! - [`kernel`]: what no problem owns: typed parameters (units, domains, the error that names a
//!   field, its value and its range), number formatting, overflow-free hyperbolic functions,
//!   certified root finding, regimes, validity verdicts, and the FE codes' default friction
//!   penalties (data about K_T).
//! - [`numeric`]: problem-agnostic finite-element kernels (meshes, elements, banded Cholesky, the
//!   Jenkins interface point, Newton with load stepping).
//! - [`problems`]: one folder per benchmark with its parameters, closed forms, validity envelope
//!   and independent discretized solver; the closed forms and the discretized solvers never
//!   import each other, so their agreement proves something.
//! - [`study`]: sweeps, families and loops over any parameter, solving for a target value, the
//!   smallest K_T within a tolerance of Coulomb.
//! - [`fit`]: identification of mu and K_T from measured points, with structured evidence.
//! - [`verify`]: the only place that calls both the closed forms and the discretized solvers,
//!   returning the worst cases as data.
//!
//! # Example
//! ```
//! use microslip_core::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};
//! let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
//! let state = beams.regularized(TipForce::new(100.0)?);
//! assert_eq!(state.regime().label(), "microslip+macroslip");
//! // The paper's plate at K_T = 1e6 MPa/mm has both zones (paper section 2.2.3).
//! let plate = SqueezedPlate::new(PlateParams::PAPER)?;
//! let squeezed = plate.regularized();
//! assert_eq!(squeezed.regime().label(), "microslip+macroslip");
//! assert!(squeezed.micro_zone_end() < 10.0 && squeezed.end_displacement() > 0.0);
//! # Ok::<(), microslip_core::ParamError>(())
//! ```

pub mod fit;
pub mod kernel;
pub mod numeric;
pub mod prelude;
pub mod problems;
pub mod study;
pub mod verify;

/// The prelude at the crate root too (`microslip_core::TwinBeams`): every registered problem's
/// type, parameter keys and closed forms, generated from the registry, with the generic handles
/// and errors; the crate root names no problem itself.
pub use prelude::*;
