//! Independent discretized solvers that never call the closed forms: the project's own proof that
//! the analytical core is right (see `microslip verify` and `docs/theory.md`, "Numerical solver").

mod banded;
pub mod beams;
mod elements;
mod error;
mod interface;
pub(crate) mod mesh;
mod newton;
pub mod plate;
pub mod plate_continuum;

pub use beams::{InterfaceSample, TwinBeamsFe};
pub use error::NumericError;
pub use mesh::MeshDensity;
pub use plate::PlateFe;
pub use plate_continuum::{ContinuumMesh, ContinuumPlate, solve_plate_continuum};
