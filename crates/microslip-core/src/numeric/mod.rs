//! Problem-agnostic finite-element kernels: graded meshes, element ingredients, a banded Cholesky
//! solver, the Jenkins interface point with its return mapping, and load stepping with Newton
//! iterations. Each problem's own discretized solver (`problems::*::discretized`, the plate's
//! `continuum`) is built on them and never calls the closed forms: the project's own proof that
//! the analytical core is right (see `microslip verify` and `docs/theory.md`, "Numerical solver").

pub(crate) mod banded;
pub mod cancel;
pub(crate) mod condense;
pub mod elements;
mod error;
pub(crate) mod grid;
pub(crate) mod interface;
pub mod mesh;
pub(crate) mod newton;
pub(crate) mod q8;
pub mod two_bar;
pub(crate) mod two_body;

pub use error::NumericError;
pub use error::short;
pub(crate) use error::stiffness_advice;
pub use mesh::MeshDensity;
