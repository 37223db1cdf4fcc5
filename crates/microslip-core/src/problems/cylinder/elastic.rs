//! The regularized cylinder at loads too small for the nonlinear solve to resolve: the elastic
//! asymptote of docs/theory.md (H17)-(H20).
//!
//! As Q -> 0 the sliding zones at the edges shrink as Q^2 while the shear grows as Q, so to
//! leading order the whole contact obeys q = K_T s: the problem is linear and every field is Q
//! times a shape that depends on kappa = K_T a / E* alone. [`elastic_shape`] solves that linear
//! problem once per kappa, with the shear itself as the unknown (nonzero at the contact's edge),
//! so no O(1) number is subtracted from another to give an O(Q) one: the cancellation that makes
//! the deficit form of (H11) lose Q below the load its mesh resolves does not arise.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use super::collocation::Collocation;
use super::quadrature::solve_with_constant;

/// The linear problem's solution for Q / (mu P) = 1 (H17): phi = q / (mu p0) per unit load ratio.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticShape {
    /// kappa = K_T a / E*.
    pub kappa: f64,
    /// The constant D of (H17) per unit load ratio.
    pub shift: f64,
    /// phi / (Q / mu P) at the collocation points u_i = x / a.
    pub shape: Vec<f64>,
}

/// Below this kappa the shear is read from the potential (Nystrom), above it from the nodal
/// polynomial: the same switch as the nonlinear solution's, for the same reason
/// ([`super::regularized::NYSTROM_BELOW`]).
use super::regularized::NYSTROM_BELOW;

impl ElasticShape {
    /// S(t) / (Q / mu P), S = s E* / (mu p0 a), at t = x / a in [-1, 1] (H18): phi / kappa, the
    /// law itself (no part of the contact slides at this order).
    pub fn slip(&self, collocation: &Collocation, t: f64) -> f64 {
        self.shear(collocation, t) / self.kappa
    }

    /// phi(t) / (Q / mu P) at t = x / a in [-1, 1]: where the interface is compliant, kappa
    /// times the log potential (2 / pi)(D + integral phi ln|t - tau|) (Nystrom: the integral
    /// smooths the nodal values' error); where it is stiff, the nodal polynomial, because there
    /// D and the integral are O(1) and cancel to leave O(1 / kappa).
    pub fn shear(&self, collocation: &Collocation, t: f64) -> f64 {
        let t = t.abs().min(1.0);
        if self.kappa < NYSTROM_BELOW {
            let mut row = vec![0.0; collocation.size()];
            collocation.kernel_row(t, &mut row);
            let potential: f64 = row.iter().zip(&self.shape).map(|(k, f)| k * f).sum();
            self.kappa * (2.0 / PI) * (self.shift + potential)
        } else {
            collocation.interpolate(&self.shape, t)
        }
    }
}

/// Solves the linear problem (H17) on `collocation`'s mesh, scaled to the whole contact (c = a):
/// epsilon phi - integral_{-1}^{1} phi(tau) ln|t - tau| dtau = D on |t| < 1, with epsilon = pi /
/// (2 kappa) and the integral of phi equal to pi / 2 (Q = mu P); `None` when the matrix is
/// singular (never met).
pub fn elastic_shape(collocation: &Collocation, kappa: f64) -> Option<ElasticShape> {
    let n = collocation.size();
    let size = n + 1;
    let epsilon = FRAC_PI_2 / kappa;
    let mut matrix = vec![0.0; size * size];
    let mut rhs = vec![0.0; size];
    for i in 0..n {
        let row = &collocation.kernel[i * n..(i + 1) * n];
        for (j, k) in row.iter().enumerate() {
            matrix[i * size + j] = -k;
        }
        matrix[i * size + i] += epsilon;
        matrix[i * size + n] = -1.0;
    }
    // The load: the integral over [0, 1] is half of pi / 2.
    for (j, w) in collocation.weights.iter().enumerate() {
        matrix[n * size + j] = *w;
    }
    rhs[n] = FRAC_PI_4;
    let shift = solve_with_constant(&mut matrix, size, &mut rhs)?;
    Some(ElasticShape {
        kappa,
        shift,
        shape: rhs,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::cylinder::regularized::solve_normalized;

    #[test]
    #[ignore]
    fn measure_handover() {
        let colloc = Collocation::default_mesh();
        for kappa in [1e-6, 1e-2, 0.644, 10.0, 1e3, 1e6, 1e8, 1e10, 1e12] {
            let shape = elastic_shape(colloc, kappa).unwrap();
            let (e1, e0, f1) = (
                shape.slip(colloc, 1.0),
                shape.slip(colloc, 0.0),
                shape.shear(colloc, 1.0),
            );
            println!("kappa {kappa:e}: S(1)/L {e1:.6e} S(0)/L {e0:.6e} phi(1)/L {f1:.6e}");
            for lr in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9] {
                let s = solve_normalized(colloc, kappa, lr);
                let sa = s.edge_slip(colloc) / lr;
                let s0 = s.slip(colloc, 0.0) / lr;
                let lin_w = (lr * f1).powi(2) / 2.0;
                println!(
                    "  L {lr:e}: S(1)/L {sa:.6e} ({:+.2e}) S(0)/L {s0:.6e} ({:+.2e}) 1-c {:.3e} lin {:.3e}",
                    sa / e1 - 1.0,
                    s0 / e0 - 1.0,
                    1.0 - s.zone,
                    lin_w
                );
            }
        }
    }
}
