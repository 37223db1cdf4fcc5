//! The discretization of the regularized cylinder's integral equation (docs/theory.md (H10)-
//! (H13)): the microslip zone, scaled to u = x / c in [0, 1] (the shear is even), is cut into
//! elements graded geometrically towards its edge u = 1, where the solution has a boundary
//! layer and, as c approaches a, the Hertz pressure's square root nearly touches; on each
//! element the unknown is the polynomial through its Gauss points, and the logarithmic kernel
//! (symmetrized: ln|u - v| + ln|u + v|) is integrated against each basis polynomial exactly
//! (`quadrature::log_moments`).
//!
//! The kernel matrix depends on the mesh only, not on c nor on any input (c scales out, leaving
//! a constant that the rigid shift absorbs), so the default mesh's is computed once per process.

use std::sync::OnceLock;

use super::quadrature::{
    MAX_POINTS, barycentric_weights, gauss_legendre, lagrange_basis, legendre_values, log_moments,
};

/// The elements: a first one [0, 1 - ratio], then each next one `ratio` times as long as the
/// one before, `layers` of them, and a last one reaching u = 1; `points` Gauss points in each.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CollocationMesh {
    /// Length of each element over the one before it, towards the edge (0 < ratio < 1).
    pub ratio: f64,
    /// Graded elements after the first (the last one, touching u = 1, is of length
    /// ratio^layers).
    pub layers: usize,
    /// Gauss points per element (at most 16).
    pub points: usize,
}

impl CollocationMesh {
    /// The mesh every solve uses (docs/theory.md, the convergence table (H14)): its smallest
    /// element is 0.2^14 = 1.6e-10 of c, below the boundary layer of every K_T a / E* up to
    /// 1e8 and the edge zones of every Q / mu P above 1e-4.
    pub const DEFAULT: CollocationMesh = CollocationMesh {
        ratio: 0.2,
        layers: 14,
        points: 8,
    };

    /// The number of collocation unknowns.
    pub fn unknowns(&self) -> usize {
        (self.layers + 1) * self.points
    }

    /// The element ends, from 0 to 1.
    fn breaks(&self) -> Vec<f64> {
        let mut breaks = vec![0.0];
        for k in 1..=self.layers {
            breaks.push(1.0 - self.ratio.powi(k as i32));
        }
        breaks.push(1.0);
        breaks
    }
}

/// A mesh with its collocation points, quadrature weights and kernel matrix.
#[derive(Debug, Clone)]
pub struct Collocation {
    mesh: CollocationMesh,
    /// Element ends, from 0 to 1.
    breaks: Vec<f64>,
    /// The reference Gauss points and their barycentric weights.
    reference: Vec<f64>,
    bary: Vec<f64>,
    /// The Legendre coefficients of each reference Lagrange polynomial: `coefficients[j * n +
    /// k]` of P_k in l_j, (2k + 1) / 2 w_j P_k(t_j).
    coefficients: Vec<f64>,
    /// Collocation points u_i, element after element.
    pub(crate) nodes: Vec<f64>,
    /// Integration weights W_j on [0, 1]: the integral of the polynomial interpolant.
    pub(crate) weights: Vec<f64>,
    /// The kernel: `kernel[i * n + j]` is the integral over [0, 1] of l_j(v) (ln|u_i - v| +
    /// ln|u_i + v|) dv, with one row per collocation point and a last row at u = 1.
    pub(crate) kernel: Vec<f64>,
}

impl Collocation {
    /// The default mesh's, computed once.
    pub fn default_mesh() -> &'static Collocation {
        static DEFAULT: OnceLock<Collocation> = OnceLock::new();
        DEFAULT.get_or_init(|| Collocation::new(CollocationMesh::DEFAULT))
    }

    /// Builds the collocation of `mesh` (its points clamped to [1, 16], its ratio to (0, 1)).
    pub fn new(mesh: CollocationMesh) -> Collocation {
        let mesh = CollocationMesh {
            points: mesh.points.clamp(1, MAX_POINTS),
            ratio: mesh.ratio.clamp(1e-3, 0.999),
            layers: mesh.layers,
        };
        let n = mesh.points;
        let (reference, reference_weights) = gauss_legendre(n);
        let bary = barycentric_weights(&reference);
        let mut coefficients = vec![0.0; n * n];
        let mut p = [0.0; MAX_POINTS];
        for (j, (&t, &w)) in reference.iter().zip(&reference_weights).enumerate() {
            legendre_values(t, &mut p[..n]);
            for k in 0..n {
                coefficients[j * n + k] = (2 * k + 1) as f64 / 2.0 * w * p[k];
            }
        }
        let breaks = mesh.breaks();
        let mut nodes = Vec::new();
        let mut weights = Vec::new();
        for pair in breaks.windows(2) {
            let (mid, half) = (0.5 * (pair[0] + pair[1]), 0.5 * (pair[1] - pair[0]));
            for (&t, &w) in reference.iter().zip(&reference_weights) {
                nodes.push(mid + half * t);
                weights.push(half * w);
            }
        }
        let mut collocation = Collocation {
            mesh,
            breaks,
            reference,
            bary,
            coefficients,
            nodes,
            weights,
            kernel: Vec::new(),
        };
        let size = collocation.nodes.len();
        let mut kernel = vec![0.0; (size + 1) * size];
        for i in 0..=size {
            let u = collocation.nodes.get(i).copied().unwrap_or(1.0);
            collocation.kernel_row(u, &mut kernel[i * size..(i + 1) * size]);
        }
        collocation.kernel = kernel;
        collocation
    }

    /// The mesh.
    pub fn mesh(&self) -> CollocationMesh {
        self.mesh
    }

    /// The number of unknowns.
    pub fn size(&self) -> usize {
        self.nodes.len()
    }

    /// The kernel's row at any `u` >= 0 (inside the zone or beyond it): the integral over [0, 1]
    /// of l_j(v) (ln|u - v| + ln|u + v|) dv for every basis function j, into `row`.
    pub(crate) fn kernel_row(&self, u: f64, row: &mut [f64]) {
        let n = self.mesh.points;
        let mut minus = [0.0; MAX_POINTS];
        let mut plus = [0.0; MAX_POINTS];
        for (e, pair) in self.breaks.windows(2).enumerate() {
            let (mid, half) = (0.5 * (pair[0] + pair[1]), 0.5 * (pair[1] - pair[0]));
            log_moments((u - mid) / half, &mut minus[..n]);
            log_moments((-u - mid) / half, &mut plus[..n]);
            let log_half = 2.0 * half.ln();
            for j in 0..n {
                let c = &self.coefficients[j * n..(j + 1) * n];
                let moments: f64 = (0..n).map(|k| c[k] * (minus[k] + plus[k])).sum();
                // The constant ln(half) of both logs integrates l_j to its weight (c_j0 = w_j / 2).
                row[e * n + j] = half * (moments + log_half * 2.0 * c[0]);
            }
        }
    }

    /// The interpolant of the nodal `values` at `u` in [0, 1].
    pub(crate) fn interpolate(&self, values: &[f64], u: f64) -> f64 {
        let n = self.mesh.points;
        let u = u.clamp(0.0, 1.0);
        let e = self
            .breaks
            .windows(2)
            .position(|pair| u <= pair[1])
            .unwrap_or(self.breaks.len() - 2);
        let (mid, half) = (
            0.5 * (self.breaks[e] + self.breaks[e + 1]),
            0.5 * (self.breaks[e + 1] - self.breaks[e]),
        );
        let mut basis = [0.0; MAX_POINTS];
        lagrange_basis(
            &self.reference,
            &self.bary,
            (u - mid) / half,
            &mut basis[..n],
        );
        basis[..n]
            .iter()
            .zip(&values[e * n..(e + 1) * n])
            .map(|(b, v)| b * v)
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel applied to the half-ellipse sqrt(1 - v^2) gives the closed form of (H4):
    /// the integral over [-1, 1] of sqrt(1 - v^2) ln|u - v| dv = pi/2 (u^2 - 1/2 - ln 2) inside,
    /// and pi/2 (u^2 - u sqrt(u^2 - 1) - 1/2 - ln 2) + pi/2 ln(u + sqrt(u^2 - 1)) beyond: a
    /// check of the exact integrals on a function with the square-root edge the mesh is graded
    /// for. What is left is the interpolation's error: each element sees the edge at 1.5 of its
    /// half-lengths from its centre (ratio 0.2), a Bernstein ellipse of 2.62, so the error is
    /// about 2.62^(-2 * 8) = 2e-7 of the function's size.
    #[test]
    fn the_kernel_reproduces_the_half_ellipse_s_log_potential() {
        let colloc = Collocation::new(CollocationMesh::DEFAULT);
        let values: Vec<f64> = colloc.nodes.iter().map(|&v| (1.0 - v * v).sqrt()).collect();
        let closed = |u: f64| {
            let pi2 = std::f64::consts::FRAC_PI_2;
            if u <= 1.0 {
                pi2 * (u * u - 0.5 - 2f64.ln())
            } else {
                let r = (u * u - 1.0).sqrt();
                pi2 * (u * u - u * r - 0.5 - 2f64.ln()) + pi2 * (u + r).ln()
            }
        };
        let mut row = vec![0.0; colloc.size()];
        for u in [0.0, 0.3, 0.9, 0.999, 1.0, 1.001, 1.5, 4.0] {
            colloc.kernel_row(u, &mut row);
            let value: f64 = row.iter().zip(&values).map(|(k, v)| k * v).sum();
            assert!(
                (value - closed(u)).abs() < 1e-6,
                "{u}: {value} {}",
                closed(u)
            );
        }
        // The stored rows are the same function (the last at u = 1).
        let n = colloc.size();
        let last: f64 = (0..n).map(|j| colloc.kernel[n * n + j] * values[j]).sum();
        assert!((last - closed(1.0)).abs() < 1e-6);
        // The weights integrate it: pi / 4.
        let area: f64 = colloc.weights.iter().zip(&values).map(|(w, v)| w * v).sum();
        assert!((area - std::f64::consts::FRAC_PI_4).abs() < 1e-6);
        // The interpolant reproduces it between the nodes, pointwise to about 2.62^-8 = 5e-4 of
        // its size (an interpolation's error, not a quadrature's: its square root is not
        // taken), 1.5e-5 where it is worst, at u = 0 (the largest element's far end).
        for u in [0.0, 0.5, 0.95, 0.9999] {
            let exact = (1.0f64 - u * u).sqrt();
            let got = colloc.interpolate(&values, u);
            assert!((got - exact).abs() < 5e-5, "{u}: {got} {exact}");
        }
    }
}
