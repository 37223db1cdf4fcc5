//! The Hertzian cylinder on a flat under a tangential load (issue 34): plane strain, the
//! cylinder and the flat of one material, pressed by a normal line load P and then pulled by a
//! tangential line load Q (both N per mm of the cylinder's length), under plain Coulomb
//! friction (Mindlin's closed form, [`closed_form`]) and under the regularized law (q = K_T s up
//! to mu p: the semi-analytic solution, [`regularized`]). docs/theory.md, "The Hertzian
//! cylinder (Cattaneo-Mindlin, regularized)".

pub mod closed_form;
pub mod collocation;
pub mod continued;
pub mod cross_check;
pub mod cycle;
pub mod discretized;
pub mod elastic;
pub mod params;
mod quadrature;
pub mod regularized;
mod strips;
#[cfg(test)]
mod tests;
pub mod validity;

// ---- REGISTRY: the modules below name what the registry generates for the cylinder (its
// `Param::Cylinder` and `ModelKind::Cylinder` variants, its `Inputs`/`Model` bridges through
// `enum_bridges!(Cylinder)` in `problem.rs`, the `Registered` bound of `Zoned`). They compile
// once `with_problems!` in `problems/mod.rs` lists `Cylinder => cylinder::CylinderProblem`,
// which the application's faces must come with: uncomment them with that line.
// REGISTRY-BEGIN
pub mod description;
pub mod fittable;
pub mod load_driven;
pub mod point;
pub mod problem;
pub mod profiles;
pub mod stiffness_answer;
pub mod zoned;
pub use problem::CylinderProblem;
// REGISTRY-END

pub use closed_form::{Cylinder, CylinderParams, MindlinState, TangentialLoad};
pub use params::CylinderParam;
pub use regularized::RegularizedState;
