//! What every problem's comparison of FE results with its closed forms is written with: the
//! relative difference of one value, and an FE zone end against the closed form's in elements of
//! the FE mesh.
//!
//! What a problem compares (the beams' w(L) under both beam theories and the K_T a fit of it
//! implies, the plate's u(L) and the K_T it implies per run, the lap joint's Delta and its two
//! sliding zones, the cylinder's c and s(a)) is the problem's own, in its folder
//! (`src/problems/<name>/compare.rs`, the cylinder's `deck.rs`), so that this layer names no
//! problem and a new problem's comparison is its folder.

use super::results::FeInterface;
use super::verdict::{InterfaceMesh, MeshDifference};

/// (FE - closed form) / closed form, or `None` where the closed form is 0 (no load, or a plate
/// with nu = 0 that nothing squeezes sideways): a relative difference is undefined there, and
/// dividing printed "-inf %" and "NaN %".
pub(crate) fn relative_difference(fe: f64, closed: f64) -> Option<f64> {
    (closed != 0.0).then(|| fe / closed - 1.0)
}

/// The FE zone end against the closed form's on `mesh`, when there are both.
pub(crate) fn on_mesh(
    mesh: Option<&InterfaceMesh>,
    fe: Option<FeInterface>,
    closed: f64,
) -> Option<MeshDifference> {
    Some(MeshDifference::on(mesh?, fe?.macroslip_start, closed))
}
