//! Shared element ingredients of both finite-element models: Gauss points, quadratic Lagrange
//! functions and the quadratic bar's stiffness.

/// Gauss-Legendre points and weights on [0, 1]: 4 points, exact for polynomials of degree 7, so the
/// elastic interface terms (slip quadratic, stress times test function quartic) are integrated exactly.
pub(crate) const GAUSS: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_9, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// Quadratic Lagrange functions at local coordinate r in [0, 1], for (end 1, midside, end 2).
pub(crate) fn lagrange(r: f64) -> [f64; 3] {
    [
        (1.0 - r) * (1.0 - 2.0 * r),
        4.0 * r * (1.0 - r),
        r * (2.0 * r - 1.0),
    ]
}

/// Lower-triangle entries (i, j, value) of a quadratic bar's stiffness, (end 1, midside, end 2),
/// for axial rigidity `rigidity` (N) over length `length`: rigidity / (3 l) [7 -8 1; -8 16 -8; 1 -8 7].
pub(crate) fn quadratic_bar(rigidity: f64, length: f64) -> [(usize, usize, f64); 6] {
    let c = rigidity / (3.0 * length);
    [
        (0, 0, 7.0 * c),
        (1, 0, -8.0 * c),
        (1, 1, 16.0 * c),
        (2, 0, c),
        (2, 1, -8.0 * c),
        (2, 2, 7.0 * c),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_rule_integrates_degree_seven_exactly() {
        let integral: f64 = GAUSS.iter().map(|(r, w)| w * r.powi(7)).sum();
        assert!((integral - 1.0 / 8.0).abs() < 1e-15);
        let weights: f64 = GAUSS.iter().map(|(_, w)| w).sum();
        assert!((weights - 1.0).abs() < 1e-15);
    }

    #[test]
    fn lagrange_functions_interpolate_and_sum_to_one() {
        assert_eq!(lagrange(0.0), [1.0, 0.0, 0.0]);
        assert_eq!(lagrange(0.5), [0.0, 1.0, 0.0]);
        assert_eq!(lagrange(1.0), [0.0, 0.0, 1.0]);
        assert!((lagrange(0.3).iter().sum::<f64>() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn bar_stiffness_has_the_rigid_mode_in_its_kernel() {
        let mut rows = [0.0; 3];
        for (i, j, v) in quadratic_bar(2.0, 0.5) {
            rows[i] += v;
            if i != j {
                rows[j] += v;
            }
        }
        assert!(rows.iter().all(|r| r.abs() < 1e-12));
    }
}
