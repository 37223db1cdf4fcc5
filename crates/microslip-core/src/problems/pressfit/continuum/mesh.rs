//! The press fit's axisymmetric mesh: shaft (r in [ri, r]) below, hub (r in [r, ro]) above, both
//! over x in [0, L] on structured Q8 ring grids (`numeric::grid`, `Section::Axisymmetric`) whose
//! interface pairs share their radial unknown (`numeric::two_body`), counted before it is built.

use super::PressFitContinuumMesh;
use crate::numeric::grid::{Q8Grid, Section};
use crate::numeric::mesh::{graded_toward_end, graded_toward_end_count};
use crate::numeric::q8::axisymmetric;
use crate::numeric::two_body::TwoBodyGrid;
use crate::problems::pressfit::params::PressFitParams;

/// Growth ratio of neighbouring elements along x.
const GROWTH: f64 = 1.15;

/// The sizes along x: finest at both faces (where the shear, the pressure's end peaks and the
/// corners are) two thirds of the thinner wall's layer or a quarter of the decay length 1/lambda,
/// coarsest 8 of that layer (the field is smooth away from the faces: a long thin-walled fit
/// needs no square elements there) or half the decay length.
struct Sizing {
    finest: f64,
    coarsest: f64,
}

fn sizing(p: &PressFitParams, layers: usize, decay: f64) -> Sizing {
    let layer = (p.fit_radius - p.bore_radius).min(p.outer_radius - p.fit_radius) / layers as f64;
    let finest = (2.0 / 3.0 * layer).min(0.25 * decay);
    Sizing {
        finest,
        coarsest: (8.0 * layer).min(0.5 * decay).max(finest),
    }
}

/// Element boundaries along x over [0, L], finest at both faces.
pub(super) fn axial_breaks(p: &PressFitParams, layers: usize, decay: f64) -> Vec<f64> {
    let Sizing { finest, coarsest } = sizing(p, layers, decay);
    let length = p.length;
    let right = graded_toward_end(0.5 * length, length, finest, coarsest, GROWTH);
    let mut breaks: Vec<f64> = right.iter().rev().map(|x| length - x).collect();
    breaks.pop();
    breaks.extend(&right);
    breaks
}

/// Both bodies and the interface (`numeric::two_body`): the shaft below, the hub above.
#[derive(Debug, Clone)]
pub(super) struct Grid {
    pub(super) two: TwoBodyGrid,
    /// Held unknowns: u_x of the hub's face x = L, u_r on the axis of a solid shaft.
    pub(super) fixed: Vec<usize>,
}

impl Grid {
    /// The interface pairs and elements the mesh would have, without building it.
    pub(super) fn counts(
        p: &PressFitParams,
        mesh: PressFitContinuumMesh,
        decay: f64,
    ) -> (usize, usize) {
        let Sizing { finest, coarsest } = sizing(p, mesh.layers, decay);
        let half = graded_toward_end_count(0.5 * p.length, p.length, finest, coarsest, GROWTH);
        let whole = |x: f64| {
            if x.is_finite() && x < usize::MAX as f64 {
                x as usize
            } else {
                usize::MAX
            }
        };
        // Two half lengths, two pairs per element and one more; both bodies `layers` deep.
        (
            whole(4.0 * half + 1.0),
            whole(4.0 * half * mesh.layers as f64),
        )
    }

    pub(super) fn new(p: &PressFitParams, mesh: PressFitContinuumMesh, decay: f64) -> Grid {
        let layers = mesh.layers;
        let xs = axial_breaks(p, layers, decay);
        let through = |from: f64, to: f64| -> Vec<f64> {
            (0..=layers)
                .map(|j| from + (to - from) * j as f64 / layers as f64)
                .collect()
        };
        let (ri, r, ro) = (p.bore_radius, p.fit_radius, p.outer_radius);
        let mut shaft_rs = through(ri, r);
        let mut hub_rs = through(r, ro);
        // The shared radius exactly r in both (the interpolation may round it).
        shaft_rs[layers] = r;
        hub_rs[0] = r;
        let shaft = Q8Grid::new(
            xs.clone(),
            shaft_rs,
            0,
            Section::Axisymmetric(axisymmetric(p.shaft_modulus, p.shaft_poisson)),
        );
        let hub = Q8Grid::new(
            xs,
            hub_rs,
            0,
            Section::Axisymmetric(axisymmetric(p.hub_modulus, p.hub_poisson)),
        );
        let two = TwoBodyGrid::new(shaft, hub, 0);
        let end = two.upper.columns() - 1;
        let mut fixed: Vec<usize> = (0..two.upper.rows())
            .filter(|&j| Q8Grid::is_node(end, j))
            .map(|j| two.upper.dof(end, j)[0])
            .collect();
        if ri == 0.0 {
            fixed.extend((0..two.lower.columns()).map(|i| two.lower.dof(i, 0)[1]));
        }
        Grid { two, fixed }
    }
}
