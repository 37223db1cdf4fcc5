//! A structured grid of 8-node quadrilaterals (Q8) on rectangles, shared by the continuum solvers
//! (the plate's one body, the lap joint's two): element boundaries along x and y, the (u, v)
//! unknowns of each half-grid point (corners and midsides; element centres are no nodes), and each
//! element's unknowns and elastic stiffness.
//!
//! The half grid of `nx` x `ny` elements has 2 nx + 1 columns and 2 ny + 1 rows of points, stored
//! column by column; a caller numbers the unknowns (column by column keeps the stiffness banded)
//! and may share one between bodies (the lap joint's interface pairs share their normal unknown).

use super::q8::{
    AxisymmetricElasticity, EDGE_WEIGHTS, Elasticity, GAUSS3, Q8, q8, q8_axisymmetric_stiffness,
    q8_stiffness,
};

/// One body's Q8 mesh: element boundaries and the unknowns of its half-grid points.
#[derive(Debug, Clone)]
pub(crate) struct Q8Grid {
    /// Element boundaries along x (mm).
    pub(crate) xs: Vec<f64>,
    /// Element boundaries along y (mm).
    pub(crate) ys: Vec<f64>,
    /// The global half-grid column of the body's first column (0 for a lone body).
    pub(crate) first_column: usize,
    /// (u, v) unknowns of each half-grid point, column by column; `None` at element centres.
    dofs: Vec<Option<[usize; 2]>>,
    section: Section,
}

/// What a body's 2-D mesh stands for: a slice of unit depth (plane stress or strain), or a body
/// of revolution about the x axis, y its radius (the press fit's shaft and hub), whose forces are
/// the whole ring's.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Section {
    Plane(Elasticity),
    Axisymmetric(AxisymmetricElasticity),
}

impl From<Elasticity> for Section {
    fn from(elasticity: Elasticity) -> Section {
        Section::Plane(elasticity)
    }
}

impl Q8Grid {
    /// The grid over the boundaries `xs` x `ys` of a body of `elasticity`, its unknowns not
    /// numbered yet.
    pub(crate) fn new(
        xs: Vec<f64>,
        ys: Vec<f64>,
        first_column: usize,
        section: impl Into<Section>,
    ) -> Q8Grid {
        let points = (2 * xs.len() - 1) * (2 * ys.len() - 1);
        Q8Grid {
            xs,
            ys,
            first_column,
            dofs: vec![None; points],
            section: section.into(),
        }
    }

    /// Columns of half-grid points.
    pub(crate) fn columns(&self) -> usize {
        2 * self.xs.len() - 1
    }

    /// Rows of half-grid points.
    pub(crate) fn rows(&self) -> usize {
        2 * self.ys.len() - 1
    }

    /// Elements along x.
    pub(crate) fn elements_x(&self) -> usize {
        self.xs.len() - 1
    }

    /// Elements along y.
    pub(crate) fn elements_y(&self) -> usize {
        self.ys.len() - 1
    }

    /// Whether half-grid point (i, j) is a node: a corner or a midside, not an element centre.
    pub(crate) fn is_node(i: usize, j: usize) -> bool {
        i.is_multiple_of(2) || j.is_multiple_of(2)
    }

    /// Gives half-grid point (i, j) the unknowns `dofs`.
    pub(crate) fn set_dof(&mut self, i: usize, j: usize, dofs: [usize; 2]) {
        let rows = self.rows();
        self.dofs[i * rows + j] = Some(dofs);
    }

    /// Numbers the nodes column by column from `next`, two unknowns (u, v) each; returns the next
    /// free unknown. A lone body's numbering, which keeps its stiffness banded.
    pub(crate) fn number_by_columns(&mut self, mut next: usize) -> usize {
        for i in 0..self.columns() {
            for j in 0..self.rows() {
                if Q8Grid::is_node(i, j) {
                    self.set_dof(i, j, [next, next + 1]);
                    next += 2;
                }
            }
        }
        next
    }

    /// The (u, v) unknowns of node (i, j).
    ///
    /// # Panics
    /// At an element centre or a node not numbered yet: a caller's indexing mistake.
    pub(crate) fn dof(&self, i: usize, j: usize) -> [usize; 2] {
        self.dofs[i * self.rows() + j].expect("corner and midside points are nodes")
    }

    /// The (u, v) unknowns of every numbered node, column by column.
    #[cfg(test)]
    pub(crate) fn node_dofs(&self) -> impl Iterator<Item = [usize; 2]> + '_ {
        self.dofs.iter().flatten().copied()
    }

    /// The 16 unknowns of element (ex, ey): (u, v) of each Q8 node.
    pub(crate) fn element_dofs(&self, ex: usize, ey: usize) -> [usize; 16] {
        let mut dofs = [0; 16];
        for (k, &(a, b)) in Q8.iter().enumerate() {
            let [u, v] = self.dof(2 * ex + a, 2 * ey + b);
            dofs[2 * k] = u;
            dofs[2 * k + 1] = v;
        }
        dofs
    }

    /// The elastic stiffness of element (ex, ey), in the order of [`Q8Grid::element_dofs`].
    pub(crate) fn element_stiffness(&self, ex: usize, ey: usize) -> [[f64; 16]; 16] {
        let (width, height) = (self.xs[ex + 1] - self.xs[ex], self.ys[ey + 1] - self.ys[ey]);
        match &self.section {
            Section::Plane(d) => q8_stiffness(width, height, d),
            Section::Axisymmetric(d) => q8_axisymmetric_stiffness(width, self.ys[ey], height, d),
        }
    }

    /// The half-bandwidth of the stiffness: the widest spread of one element's unknowns.
    pub(crate) fn bandwidth(&self) -> usize {
        let mut bandwidth = 0;
        for ex in 0..self.elements_x() {
            for ey in 0..self.elements_y() {
                let dofs = self.element_dofs(ex, ey);
                let (lo, hi) = dofs
                    .iter()
                    .fold((usize::MAX, 0), |(lo, hi), &d| (lo.min(d), hi.max(d)));
                bandwidth = bandwidth.max(hi - lo);
            }
        }
        bandwidth
    }
}

/// Simpson weights of the half-grid points along a row of boundaries `breaks` (each element's
/// length times 1/6, 4/6, 1/6): a uniform traction's consistent nodal loads, and each point's
/// share of the edge.
pub(crate) fn edge_weights(breaks: &[f64]) -> Vec<f64> {
    let mut w = vec![0.0; 2 * breaks.len() - 1];
    for (e, pair) in breaks.windows(2).enumerate() {
        let length = pair[1] - pair[0];
        for (k, share) in EDGE_WEIGHTS.iter().enumerate() {
            w[2 * e + k] += share * length;
        }
    }
    w
}

/// The ring weights of the half-grid points along radial boundaries `breaks` (mm): the integral
/// of each point's quadratic shape function times 2 pi r over the edges (mm^2), a uniform axial
/// traction's consistent nodal loads per unit traction, and each point's share of the annulus
/// (they sum to pi (r_last^2 - r_first^2)).
pub(crate) fn ring_weights(breaks: &[f64]) -> Vec<f64> {
    let mut w = vec![0.0; 2 * breaks.len() - 1];
    for (e, pair) in breaks.windows(2).enumerate() {
        let height = pair[1] - pair[0];
        for &(eta, weight) in &GAUSS3 {
            // The shape functions of a quadratic edge are the Q8's along xi = -1.
            let (n, _) = q8(-1.0, eta);
            let r = pair[0] + 0.5 * (eta + 1.0) * height;
            let ring = weight * 0.5 * height * 2.0 * std::f64::consts::PI * r;
            // Nodes 0 (eta = -1), 7 (midside), 3 (eta = 1) of the edge xi = -1.
            for (k, node) in [0, 7, 3].into_iter().enumerate() {
                w[2 * e + k] += ring * n[node];
            }
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::q8::plane_strain;

    #[test]
    fn column_numbering_skips_element_centres_and_keeps_the_band_narrow() {
        // 2 x 1 elements: 5 columns of 3 points, the 2 centres are no nodes.
        let mut grid = Q8Grid::new(
            vec![0.0, 1.0, 3.0],
            vec![0.0, 2.0],
            0,
            plane_strain(1.0, 0.3),
        );
        assert_eq!(grid.number_by_columns(0), 2 * 13);
        assert_eq!(grid.dof(0, 0), [0, 1]);
        assert_eq!(grid.dof(1, 0), [6, 7]);
        assert_eq!(grid.dof(1, 2), [8, 9]);
        assert_eq!(grid.dof(4, 2), [24, 25]);
        // Element 1 runs from column 2 (unknowns 10..) to column 4 (..25).
        assert_eq!(grid.bandwidth(), 25 - 10);
        let weights = edge_weights(&grid.xs);
        let simpson = [1.0 / 6.0, 4.0 / 6.0, 3.0 / 6.0, 8.0 / 6.0, 2.0 / 6.0];
        assert_eq!(weights.len(), simpson.len());
        for (w, s) in weights.iter().zip(simpson) {
            assert!((w - s).abs() < 1e-15, "{weights:?}");
        }
    }

    #[test]
    fn ring_weights_integrate_the_annulus_and_its_first_moment() {
        let breaks = [0.0, 1.0, 2.5, 4.0];
        let w = ring_weights(&breaks);
        let area: f64 = w.iter().sum();
        assert!((area / (std::f64::consts::PI * 16.0) - 1.0).abs() < 1e-14);
        // Exact for a quadratic field: the integral of r over the annulus, 2 pi r^3/3.
        let nodes: Vec<f64> = (0..w.len())
            .map(|i| {
                if i % 2 == 0 {
                    breaks[i / 2]
                } else {
                    0.5 * (breaks[i / 2] + breaks[i / 2 + 1])
                }
            })
            .collect();
        let moment: f64 = w.iter().zip(&nodes).map(|(w, r)| w * r).sum();
        let exact = 2.0 * std::f64::consts::PI * 64.0 / 3.0;
        assert!((moment / exact - 1.0).abs() < 1e-14, "{moment} {exact}");
    }
}
