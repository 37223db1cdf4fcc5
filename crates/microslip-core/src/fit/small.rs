//! Fixed-size linear algebra for the fit's normal equations: at most two free parameters (mu
//! and K_T), so every system is a 2x2 (or 1x1) one, held in arrays on the stack rather than in
//! nested vectors, and solved in closed form (Cramer's rule).

/// Most free parameters of a fit: mu and K_T.
pub(super) const MAX_FREE: usize = 2;

/// A symmetric matrix over the free log-parameters (J^T W J): the first `n` rows and columns
/// are used, `n` the number of free parameters.
pub(super) type Matrix = [[f64; MAX_FREE]; MAX_FREE];

/// A vector over the free log-parameters: the first `n` entries are used.
pub(super) type Vector = [f64; MAX_FREE];

/// Solves the leading `n` x `n` (n <= 2) symmetric system a x = b; None when singular. The
/// entries of x beyond `n` are 0.
pub(super) fn solve(a: &Matrix, b: &Vector, n: usize) -> Option<Vector> {
    match n {
        1 => (a[0][0] > 0.0).then(|| [b[0] / a[0][0], 0.0]),
        2 => {
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            let scale = a[0][0].abs() * a[1][1].abs();
            (det.abs() > 1e-14 * scale && det != 0.0).then(|| {
                [
                    (b[0] * a[1][1] - b[1] * a[0][1]) / det,
                    (a[0][0] * b[1] - a[1][0] * b[0]) / det,
                ]
            })
        }
        _ => Some([0.0; MAX_FREE]),
    }
}

/// The normal matrix with its diagonal scaled by 1 + `damping` (Levenberg-Marquardt).
pub(super) fn damped(normal: &Matrix, damping: f64) -> Matrix {
    let mut damped = *normal;
    for (i, row) in damped.iter_mut().enumerate() {
        row[i] = row[i] * (1.0 + damping) + 1e-300;
    }
    damped
}

/// The decrease of the sum of squares that the linearized model predicts for moving by `delta`:
/// 2 delta . g - delta^T N delta, with g = -J^T r.
pub(super) fn predicted_decrease(normal: &Matrix, gradient: &Vector, delta: &[f64]) -> f64 {
    let mut decrease = 0.0;
    for (i, &di) in delta.iter().enumerate() {
        decrease += 2.0 * di * gradient[i];
        for (j, &dj) in delta.iter().enumerate() {
            decrease -= di * normal[i][j] * dj;
        }
    }
    decrease
}

/// The inverse of the leading `n` x `n` block of `normal` scaled by `variance`, as columns (the
/// covariance (J^T W J)^-1 sigma^2); None when singular.
pub(super) fn scaled_inverse(normal: &Matrix, n: usize, variance: f64) -> Option<Matrix> {
    let mut columns = [[0.0; MAX_FREE]; MAX_FREE];
    for (k, column) in columns.iter_mut().enumerate().take(n) {
        let mut unit = [0.0; MAX_FREE];
        unit[k] = 1.0;
        *column = solve(normal, &unit, n)?.map(|c| variance * c);
    }
    Some(columns)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_two_by_two_system_is_solved_and_inverted() {
        // [[4, 1], [1, 3]] x = [1, 2]: x = [1/11, 7/11].
        let a = [[4.0, 1.0], [1.0, 3.0]];
        let x = solve(&a, &[1.0, 2.0], 2).unwrap();
        assert!((x[0] - 1.0 / 11.0).abs() < 1e-15 && (x[1] - 7.0 / 11.0).abs() < 1e-15);
        // The inverse is [[3, -1], [-1, 4]] / 11, here times 2.
        let inverse = scaled_inverse(&a, 2, 2.0).unwrap();
        let expected = [[6.0 / 11.0, -2.0 / 11.0], [-2.0 / 11.0, 8.0 / 11.0]];
        for (row, want) in inverse.iter().zip(expected) {
            for (got, want) in row.iter().zip(want) {
                assert!((got - want).abs() < 1e-15, "{inverse:?}");
            }
        }
        // One free parameter uses the leading entry only.
        assert_eq!(
            solve(&[[2.0, 9.0], [9.0, 9.0]], &[1.0, 9.0], 1),
            Some([0.5, 0.0])
        );
        // Singular systems have no solution.
        assert_eq!(solve(&[[1.0, 2.0], [2.0, 4.0]], &[1.0, 1.0], 2), None);
        assert_eq!(solve(&[[0.0, 0.0], [0.0, 0.0]], &[1.0, 0.0], 1), None);
        // Damping scales the diagonal only.
        assert_eq!(damped(&a, 1.0)[0], [8.0, 1.0]);
        // 2 d.g - d N d at d = [1, 0]: 2 * 1 - 4.
        assert_eq!(predicted_decrease(&a, &[1.0, 0.0], &[1.0, 0.0]), -2.0);
    }
}
