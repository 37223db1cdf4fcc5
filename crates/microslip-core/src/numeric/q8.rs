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
pub(crate) const GAUSS3: [(f64, f64); 3] = [
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
    integrate(width, height, d, |_, dn, _| {
        let mut b = [[0.0; 16]; 3];
        for n in 0..8 {
            let (dx, dy) = (dn[n][0], dn[n][1]);
            b[0][2 * n] = dx;
            b[1][2 * n + 1] = dy;
            b[2][2 * n] = dy;
            b[2][2 * n + 1] = dx;
        }
        (1.0, b)
    })
}

/// Isotropic elasticity of a body of revolution: (sigma_x, sigma_r, sigma_theta, tau_xr) = D
/// (eps_x, eps_r, eps_theta, gamma_xr) (MPa), x the axis and r the radius.
pub(crate) type AxisymmetricElasticity = [[f64; 4]; 4];

/// The 3-D isotropic law in the axisymmetric strains (the hoop strain is a true strain, u_r/r).
pub(crate) fn axisymmetric(modulus: f64, poisson: f64) -> AxisymmetricElasticity {
    let c = modulus / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    let (a, b) = (c * (1.0 - poisson), c * poisson);
    [
        [a, b, b, 0.0],
        [b, a, b, 0.0],
        [b, b, a, 0.0],
        [0.0, 0.0, 0.0, c * (1.0 - 2.0 * poisson) / 2.0],
    ]
}

/// Stiffness of an axisymmetric Q8 ring element over x in a `width`, r in [r0, r0 + height]
/// (unknowns (u_x, u_r) of each node in [`Q8`] order), integrated over the whole ring (weight
/// 2 pi r): its forces are the ring's total, in N. The hoop strain u_r / r is evaluated at the
/// Gauss points, which never lie on the axis, so an element touching it (r0 = 0) is finite; the
/// caller holds u_r = 0 on the axis.
pub(crate) fn q8_axisymmetric_stiffness(
    width: f64,
    r0: f64,
    height: f64,
    d: &AxisymmetricElasticity,
) -> [[f64; 16]; 16] {
    integrate(width, height, d, |n, dn, eta| {
        let r = r0 + 0.5 * (eta + 1.0) * height;
        let mut b = [[0.0; 16]; 4];
        for k in 0..8 {
            let (dx, dr) = (dn[k][0], dn[k][1]);
            b[0][2 * k] = dx;
            b[1][2 * k + 1] = dr;
            b[2][2 * k + 1] = n[k] / r;
            b[3][2 * k] = dr;
            b[3][2 * k + 1] = dx;
        }
        (2.0 * std::f64::consts::PI * r, b)
    })
}

/// The 3 x 3 Gauss integral of B^T D B over a rectangle, `strains(n, dn, eta)` giving the
/// weight factor (1 per unit depth, 2 pi r for a ring) and B from the shape functions and their
/// x and y derivatives at a point.
fn integrate<const S: usize>(
    width: f64,
    height: f64,
    d: &[[f64; S]; S],
    strains: impl Fn(&[f64; 8], &[[f64; 2]; 8], f64) -> (f64, [[f64; 16]; S]),
) -> [[f64; 16]; 16] {
    let (jx, jy) = (2.0 / width, 2.0 / height);
    let det = width * height / 4.0;
    let mut k = [[0.0; 16]; 16];
    for &(xi, wx) in &GAUSS3 {
        for &(eta, wy) in &GAUSS3 {
            let (n, dn) = q8(xi, eta);
            let physical = dn.map(|g| [g[0] * jx, g[1] * jy]);
            let (factor, b) = strains(&n, &physical, eta);
            let weight = wx * wy * det * factor;
            for r in 0..16 {
                let db: [f64; S] =
                    std::array::from_fn(|i| (0..S).map(|j| d[i][j] * b[j][r]).sum::<f64>());
                for s in 0..16 {
                    k[s][r] += weight * (0..S).map(|i| b[i][s] * db[i]).sum::<f64>();
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

    #[test]
    fn the_ring_element_has_the_axial_rigid_mode_and_the_energy_of_a_uniform_strain() {
        let (e, nu) = (210_000.0, 0.3);
        let d = axisymmetric(e, nu);
        for (r0, height) in [(0.0, 1.5), (10.0, 2.0), (100.0, 0.5)] {
            let width = 0.7;
            let k = q8_axisymmetric_stiffness(width, r0, height, &d);
            let nodes: Vec<(f64, f64)> = Q8_NATURAL
                .iter()
                .map(|&(a, b)| (0.5 * (a + 1.0) * width, r0 + 0.5 * (b + 1.0) * height))
                .collect();
            // An axial translation strains nothing; a radial one stretches the hoop.
            let axial: Vec<f64> = nodes.iter().flat_map(|_| [1.0, 0.0]).collect();
            for row in &k {
                let f: f64 = row.iter().zip(&axial).map(|(a, b)| a * b).sum();
                assert!(f.abs() < 1e-6, "{f}");
            }
            // u = a x + g r, v = b r: eps = (a, b, b, g) everywhere (the hoop strain b r / r;
            // a v growing with x would strain the hoop unevenly), energy 1/2 eps.D.eps times
            // the ring's volume pi ((r0 + h)^2 - r0^2) w.
            let (a, b, g) = (1e-3, -4e-4, 2e-4);
            let u: Vec<f64> = nodes
                .iter()
                .flat_map(|&(x, r)| [a * x + g * r, b * r])
                .collect();
            let energy: f64 = (0..16)
                .map(|i| u[i] * (0..16).map(|j| k[i][j] * u[j]).sum::<f64>())
                .sum::<f64>()
                / 2.0;
            let eps = [a, b, b, g];
            let density: f64 = (0..4)
                .map(|i| eps[i] * (0..4).map(|j| d[i][j] * eps[j]).sum::<f64>())
                .sum::<f64>()
                / 2.0;
            let volume = std::f64::consts::PI * ((r0 + height).powi(2) - r0 * r0) * width;
            assert!(
                (energy / (density * volume) - 1.0).abs() < 1e-10,
                "{energy} {}",
                density * volume
            );
        }
    }
}
