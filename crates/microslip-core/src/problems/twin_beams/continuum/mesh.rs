//! The twin beams' mesh: both beams on the same structured Q8 grid along x, graded toward the
//! clamp as the CalculiX deck grades its own (`src/problems/twin_beams/deck.rs`), the lower beam
//! y in [-2h, 0] and the upper one y in [0, 2h] facing it at y = 0 (`numeric::two_body`).

use super::BeamsContinuumMesh;
use crate::numeric::grid::Q8Grid;
use crate::numeric::mesh::{graded_toward_end, graded_toward_end_count};
use crate::numeric::q8::plane_stress;
use crate::numeric::two_body::TwoBodyGrid;
use crate::problems::twin_beams::params::TwinBeamsParams;

/// Growth ratio of neighbouring elements along x (the deck's).
const GROWTH: f64 = 1.2;

/// Element sizes along x (mm), the deck's coarse mesh's whatever the layers (refining along x
/// moved w(L) by 1e-6 of itself on the paper's beams, refining through the height from 2 to 16
/// layers by 0.04 %): the finest 2h/80 at the clamp, where the clamped face meets the interface and the
/// stresses are singular; the coarsest 2h/5, and at most a quarter of the microslip boundary
/// layer 1/k = sqrt(E h / K_T) / 2, which a stiff interface shortens.
fn sizes(p: &TwinBeamsParams, _layers: usize) -> (f64, f64) {
    let height = 2.0 * p.half_height;
    let boundary_layer = 0.5 * (p.youngs_modulus * p.half_height / p.tangential_stiffness).sqrt();
    let finest = height / 80.0;
    let coarsest = (height / 5.0).min(0.25 * boundary_layer).max(finest);
    (finest, coarsest)
}

/// The element boundaries along x, from the clamp (x = 0) to the tip (x = L).
pub(super) fn beam_breaks(p: &TwinBeamsParams, layers: usize) -> Vec<f64> {
    let (finest, coarsest) = sizes(p, layers);
    let length = p.length;
    let from_clamp = graded_toward_end(0.0, length, finest, coarsest, GROWTH);
    let mut xs: Vec<f64> = from_clamp.iter().rev().map(|x| length - x).collect();
    xs[0] = 0.0;
    xs
}

/// The number of elements along x [`beam_breaks`] would make, without making them.
pub(super) fn elements_along(p: &TwinBeamsParams, layers: usize) -> f64 {
    let (finest, coarsest) = sizes(p, layers);
    graded_toward_end_count(0.0, p.length, finest, coarsest, GROWTH)
}

/// Both beams and their interface, with the clamp's held unknowns.
#[derive(Debug, Clone)]
pub(super) struct Grid {
    pub(super) two: TwoBodyGrid,
    /// u and v of every node at x = 0, in both beams.
    pub(super) fixed: Vec<usize>,
}

impl Grid {
    pub(super) fn new(p: &TwinBeamsParams, mesh: BeamsContinuumMesh) -> Grid {
        let layers = mesh.layers;
        let xs = beam_breaks(p, layers);
        let height = 2.0 * p.half_height;
        let through = |from: f64| -> Vec<f64> {
            (0..=layers)
                .map(|j| from + height * j as f64 / layers as f64)
                .collect()
        };
        let elasticity = plane_stress(p.youngs_modulus, p.poisson);
        let lower = Q8Grid::new(xs.clone(), through(-height), 0, elasticity);
        let upper = Q8Grid::new(xs, through(0.0), 0, elasticity);
        // The pair at the clamp is held (no slip there): the first shared column is no pair.
        let two = TwoBodyGrid::new(lower, upper, 1);
        let mut fixed = Vec::new();
        for body in [&two.lower, &two.upper] {
            for j in 0..body.rows() {
                fixed.extend(body.dof(0, j));
            }
        }
        Grid { two, fixed }
    }
}
