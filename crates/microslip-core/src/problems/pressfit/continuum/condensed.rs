//! The press fit's bodies condensed onto its interface pairs (`numeric::two_body`): the first
//! load is the interference (a prescribed radial overlap), the driving one the push-out force,
//! the reading Delta.

use super::mesh::Grid;
use crate::numeric::NumericError;
use crate::numeric::grid::ring_weights;
use crate::numeric::q8::Q8;
use crate::numeric::two_body::Condensed;
use crate::problems::pressfit::params::PressFitParams;

/// The fit's bodies condensed, per unit of each load:
///
/// - the interference delta = 1 mm: the hub's interface nodes sit at u_r = v + delta where the
///   shaft's sit at v (they share v, the tie). With the hub's displacement T u + delta e (e
///   picks its interface u_r), its energy's gradient moves -K_hub e delta to the right-hand
///   side: that is the load vector, built from the hub's first row of elements. The contact
///   force (the hub's internal force at its interface u_r) is then row . u + (K_hub e)_i: the
///   hub's "own" share of the load at pair i is -(K_hub e)_i;
/// - F = 1 N as a uniform axial traction 1 / As on the shaft's face x = 0 (ring weights, exact
///   for the element's field), toward +x;
/// - Delta: the area mean of the shaft's u_x over its face x = 0 (the hub's face x = L, the
///   support, is held at u_x = 0).
pub(super) fn condense(grid: &Grid, p: &PressFitParams) -> Result<Condensed, NumericError> {
    let two = &grid.two;
    let hub = &two.upper;
    let mut overlap = vec![0.0; two.unknowns];
    for ex in 0..hub.elements_x() {
        let k = hub.element_stiffness(ex, 0);
        let dofs = hub.element_dofs(ex, 0);
        for (node, &(_, b)) in Q8.iter().enumerate() {
            if b != 0 {
                continue;
            }
            for s in 0..16 {
                overlap[dofs[s]] -= k[s][2 * node + 1];
            }
        }
    }
    let interference = |add: &mut dyn FnMut(usize, f64)| {
        for (dof, value) in overlap.iter().enumerate() {
            if *value != 0.0 {
                add(dof, *value);
            }
        }
    };
    let top = two.lower.rows() - 1;
    let radial = |i: usize| two.lower.dof(i, top)[1];
    let own_overlap = |i: usize| overlap[radial(i)];
    let face = ring_weights(&two.lower.ys);
    let area = p.shaft_area();
    let force = |add: &mut dyn FnMut(usize, f64)| {
        for (j, w) in face.iter().enumerate() {
            add(two.lower.dof(0, j)[0], w / area);
        }
    };
    let delta = |at: &dyn Fn(usize) -> f64| {
        face.iter()
            .enumerate()
            .map(|(j, w)| w * at(two.lower.dof(0, j)[0]))
            .sum::<f64>()
            / area
    };
    Condensed::new(
        two,
        p.tangential_stiffness * p.interface_width(),
        &grid.fixed,
        [&interference, &force],
        [&own_overlap, &|_| 0.0],
        &delta,
    )
}
