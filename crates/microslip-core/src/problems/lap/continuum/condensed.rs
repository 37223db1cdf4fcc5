//! The lap joint's elastic bodies condensed onto its interface pairs (`numeric::two_body`): the
//! joint's loads (P on the cover, F at the inner plate's end) and its reading (Delta).

use super::mesh::Grid;
use crate::numeric::NumericError;
use crate::numeric::grid::edge_weights;
use crate::numeric::two_body::Condensed;
use crate::problems::lap::params::LapParams;

/// The joint's bodies condensed: P = 1 MPa on the cover's outer face over the overlap, F = 1 N
/// as a uniform traction on the inner plate's end, and Delta: the thickness mean of u_x of the
/// inner plate at x = L minus that of the cover at x = 0.
pub(super) fn condense(grid: &Grid, p: &LapParams) -> Result<Condensed, NumericError> {
    let two = &grid.two;
    let cover_top = two.upper.rows() - 1;
    let end = two.lower.columns() - 1;
    let traction = 1.0 / (p.width * p.inner_thickness);
    let inner_end = 2 * grid.overlap_elements;
    let inner_mean = edge_weights(&two.lower.ys);
    let cover_mean = edge_weights(&two.upper.ys);
    let (h1, h2) = (0.5 * p.inner_thickness, p.cover_thickness);
    let pressure = |add: &mut dyn FnMut(usize, f64)| {
        for (i, w) in two.pair_weights.iter().enumerate() {
            let [_, v] = two.upper.dof(two.lower.first_column + i, cover_top);
            add(v, -w);
        }
    };
    let force = |add: &mut dyn FnMut(usize, f64)| {
        for (j, w) in inner_mean.iter().enumerate() {
            let [u, _] = two.lower.dof(end, j);
            add(u, traction * w);
        }
    };
    let delta = |at: &dyn Fn(usize) -> f64| {
        let inner: f64 = inner_mean
            .iter()
            .enumerate()
            .map(|(j, w)| w * at(two.lower.dof(inner_end, j)[0]))
            .sum();
        let cover: f64 = cover_mean
            .iter()
            .enumerate()
            .map(|(j, w)| w * at(two.upper.dof(two.lower.first_column, j)[0]))
            .sum();
        inner / h1 - cover / h2
    };
    Condensed::new(
        two,
        p.tangential_stiffness,
        &grid.fixed,
        [&pressure, &force],
        [&|_| 0.0, &|_| 0.0],
        &delta,
    )
}
