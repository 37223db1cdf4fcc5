//! The 8-node serendipity quadrilateral (Q8) on rectangles, shared by the continuum solvers (the
//! plate's plane strain, the lap joint's plane stress): node layout, shape functions, 3 x 3 Gauss
//! rule, the elastic stiffness for a given constitutive matrix, and consistent edge loads.

/// Half-grid offsets of the Q8 nodes: corners counter-clockwise from (x-, y-), then midsides.
pub(crate) const Q8: [(usize, usize); 8] = [
    (0, 0),
    (2, 0),
    (2, 2),
    (0, 2),
    (1, 0),
    (2, 1),
    (1, 2),
    (0, 1),
];
/// Natural coordinates of the same nodes.
pub(crate) const Q8_NATURAL: [(f64, f64); 8] = [
    (-1.0, -1.0),
    (1.0, -1.0),
    (1.0, 1.0),
    (-1.0, 1.0),
    (0.0, -1.0),
    (1.0, 0.0),
    (0.0, 1.0),
    (-1.0, 0.0),
];
/// 3-point Gauss-Legendre rule on [-1, 1].
const GAUSS3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

/// Consistent nodal forces of a uniform traction on a quadratic edge, per unit traction and unit
/// edge length (end, midside, end): Simpson's weights, exact for the element's field.
pub(crate) const EDGE_WEIGHTS: [f64; 3] = [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0];

/// Constitutive matrix (sigma_x, sigma_y, tau_xy) = D (eps_x, eps_y, gamma_xy) (MPa).
pub(crate) type Elasticity = [[f64; 3]; 3];

/// Plane strain (eps_z = 0): the plate's slab, long in z.
pub(crate) fn plane_strain(modulus: f64, poisson: f64) -> Elasticity {
    let c = modulus / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    [
        [c * (1.0 - poisson), c * poisson, 0.0],
        [c * poisson, c * (1.0 - poisson), 0.0],
        [0.0, 0.0, c * (1.0 - 2.0 * poisson) / 2.0],
    ]
}

/// Plane stress (sigma_z = 0): a thin slice with free faces, whose axial modulus is E itself, as
/// the 1-D theories and the beam and lap decks take it.
pub(crate) fn plane_stress(modulus: f64, poisson: f64) -> Elasticity {
    let c = modulus / (1.0 - poisson * poisson);
    [
        [c, c * poisson, 0.0],
        [c * poisson, c, 0.0],
        [0.0, 0.0, c * (1.0 - poisson) / 2.0],
    ]
}

/// Q8 shape functions and their derivatives (d/dxi, d/deta) at (xi, eta).
pub(crate) fn q8(xi: f64, eta: f64) -> ([f64; 8], [[f64; 2]; 8]) {
    let mut n = [0.0; 8];
    let mut d = [[0.0; 2]; 8];
    for (k, &(a, b)) in Q8_NATURAL.iter().enumerate() {
        if a != 0.0 && b != 0.0 {
            n[k] = 0.25 * (1.0 + a * xi) * (1.0 + b * eta) * (a * xi + b * eta - 1.0);
            d[k][0] = 0.25 * a * (1.0 + b * eta) * (2.0 * a * xi + b * eta);
            d[k][1] = 0.25 * b * (1.0 + a * xi) * (a * xi + 2.0 * b * eta);
        } else if a == 0.0 {
            n[k] = 0.5 * (1.0 - xi * xi) * (1.0 + b * eta);
            d[k][0] = -xi * (1.0 + b * eta);
            d[k][1] = 0.5 * b * (1.0 - xi * xi);
        } else {
            n[k] = 0.5 * (1.0 + a * xi) * (1.0 - eta * eta);
            d[k][0] = 0.5 * a * (1.0 - eta * eta);
            d[k][1] = -eta * (1.0 + a * xi);
        }
    }
    (n, d)
}

/// Stiffness of a rectangular Q8 element, width * height, per unit depth, with the constitutive
/// matrix `d` (unknowns (u, v) of each node in [`Q8`] order).
pub(crate) fn q8_stiffness(width: f64, height: f64, d: &Elasticity) -> [[f64; 16]; 16] {
    let (jx, jy) = (2.0 / width, 2.0 / height);
    let det = width * height / 4.0;
    let mut k = [[0.0; 16]; 16];
    for &(xi, wx) in &GAUSS3 {
        for &(eta, wy) in &GAUSS3 {
            let (_, dn) = q8(xi, eta);
            let mut b = [[0.0; 16]; 3];
            for n in 0..8 {
                let (dx, dy) = (dn[n][0] * jx, dn[n][1] * jy);
                b[0][2 * n] = dx;
                b[1][2 * n + 1] = dy;
                b[2][2 * n] = dy;
                b[2][2 * n + 1] = dx;
            }
            let weight = wx * wy * det;
            for r in 0..16 {
                let db = [0, 1, 2].map(|i| (0..3).map(|j| d[i][j] * b[j][r]).sum::<f64>());
                for s in 0..16 {
                    k[s][r] += weight * (b[0][s] * db[0] + b[1][s] * db[1] + b[2][s] * db[2]);
                }
            }
        }
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shape_functions_interpolate_and_sum_to_one() {
        for (k, &(a, b)) in Q8_NATURAL.iter().enumerate() {
            let (n, _) = q8(a, b);
            for (m, value) in n.iter().enumerate() {
                assert!((value - if m == k { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        }
        let (n, d) = q8(0.3, -0.7);
        assert!((n.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        assert!(d.iter().map(|g| g[0]).sum::<f64>().abs() < 1e-14);
    }

    #[test]
    fn element_stiffness_has_three_rigid_modes() {
        for d in [plane_strain(1000.0, 0.3), plane_stress(1000.0, 0.3)] {
            let k = q8_stiffness(2.0, 0.5, &d);
            let nodes: Vec<(f64, f64)> = Q8_NATURAL.iter().map(|&(a, b)| (a, 0.25 * b)).collect();
            // Translations along x and y, and a small rotation about the element's centre.
            for mode in 0..3 {
                let u: Vec<f64> = nodes
                    .iter()
                    .flat_map(|&(x, y)| match mode {
                        0 => [1.0, 0.0],
                        1 => [0.0, 1.0],
                        _ => [-y, x],
                    })
                    .collect();
                for row in &k {
                    let f: f64 = row.iter().zip(&u).map(|(a, b)| a * b).sum();
                    assert!(f.abs() < 1e-9, "{f}");
                }
            }
        }
    }

    #[test]
    fn plane_stress_stretch_gives_young_s_modulus_and_poisson_contraction() {
        // A uniform stretch eps_x with sigma_y = 0: eps_y = -nu eps_x, sigma_x = E eps_x.
        let (e, nu) = (70_000.0, 0.3);
        let d = plane_stress(e, nu);
        let eps = [1e-3, -nu * 1e-3, 0.0];
        let sigma: Vec<f64> = d
            .iter()
            .map(|row| row.iter().zip(&eps).map(|(a, b)| a * b).sum())
            .collect();
        assert!((sigma[0] / (e * 1e-3) - 1.0).abs() < 1e-14);
        assert!(sigma[1].abs() < 1e-12);
        // Shear modulus E / (2 (1 + nu)).
        assert!((d[2][2] / (e / 2.6) - 1.0).abs() < 1e-14);
    }
}
