//! The Hertzian cylinder on a flat under a tangential line load (issue 34): plane strain, the
//! cylinder and the flat of one material, pressed by a normal line load P and then pulled by a
//! tangential line load Q (both N per mm of the cylinder's length), under plain Coulomb
//! friction (Mindlin's closed form) and under the regularized law (q = K_T s up to mu p: the
//! semi-analytic solution). docs/theory.md, "The Hertzian cylinder (Cattaneo-Mindlin,
//! regularized)".

pub mod closed_form;
pub mod collocation;
pub mod cross_check;
pub mod cycle;
pub mod discretized;
pub mod params;
mod quadrature;
pub mod regularized;
