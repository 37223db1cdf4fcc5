//! Independent discretized solvers that never call the closed forms: the project's own proof that
//! the analytical core is right (see `microslip verify` and `docs/theory.md`, "Numerical solver").

pub mod banded;
pub mod beams;
pub mod elements;
pub mod interface;
pub mod mesh;
mod newton;
pub mod plate;

pub use beams::{InterfaceSample, MeshDensity, NumericError, TwinBeamsFe};
pub use plate::PlateFe;
