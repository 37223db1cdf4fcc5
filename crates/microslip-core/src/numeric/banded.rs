//! Symmetric banded matrices and their Cholesky factorization.
//!
//! Both finite-element models number their unknowns along the interface, so every stiffness matrix
//! is symmetric with a narrow band (half-bandwidth 9 for the beams, 2 for the plate). A banded
//! Cholesky solve costs O(n b^2): a few hundred microseconds for the default meshes, with no
//! dependency on a linear-algebra crate.

/// Lower half of a symmetric n x n matrix with half-bandwidth `bandwidth`, stored row by row.
#[derive(Debug, Clone)]
pub(crate) struct SymmetricBand {
    n: usize,
    bandwidth: usize,
    values: Vec<f64>,
}

/// The matrix is not positive definite (a mechanism: a constraint is missing).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct NotPositiveDefinite {
    /// Row where factorization broke down.
    pub row: usize,
}

impl SymmetricBand {
    /// A zero matrix.
    pub(crate) fn zeros(n: usize, bandwidth: usize) -> Self {
        SymmetricBand {
            n,
            bandwidth,
            values: vec![0.0; n * (bandwidth + 1)],
        }
    }

    fn index(&self, i: usize, j: usize) -> usize {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        debug_assert!(i - j <= self.bandwidth, "entry ({i}, {j}) outside the band");
        i * (self.bandwidth + 1) + self.bandwidth - (i - j)
    }

    /// Entry (i, j) (tests read the assembled matrix through it).
    #[cfg(test)]
    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        let (hi, lo) = if i >= j { (i, j) } else { (j, i) };
        if hi - lo > self.bandwidth {
            0.0
        } else {
            self.values[self.index(i, j)]
        }
    }

    /// Adds `value` to entry (i, j) and, by symmetry, (j, i).
    pub(crate) fn add(&mut self, i: usize, j: usize, value: f64) {
        let k = self.index(i, j);
        self.values[k] += value;
    }

    /// Replaces row and column `i` by those of the identity (an essential boundary condition).
    pub(crate) fn fix(&mut self, i: usize) {
        for j in i.saturating_sub(self.bandwidth)..=(i + self.bandwidth).min(self.n - 1) {
            let k = self.index(i, j);
            self.values[k] = 0.0;
        }
        let k = self.index(i, i);
        self.values[k] = 1.0;
    }

    /// Plain matrix-vector product: the tests' yardstick for [`SymmetricBand::mul_accurate`].
    #[cfg(test)]
    pub(crate) fn mul(&self, x: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; self.n];
        for i in 0..self.n {
            for j in i.saturating_sub(self.bandwidth)..=i {
                let a = self.values[self.index(i, j)];
                y[i] += a * x[j];
                if i != j {
                    y[j] += a * x[i];
                }
            }
        }
        y
    }

    /// Matrix-vector product accurate to about one rounding of the exact result, whatever the
    /// cancellation: each product is split exactly with a fused multiply-add and the sums are
    /// compensated (Ogita, Rump & Oishi's Dot2). Newton's residual needs it: for a beam cut into
    /// n elements, K d cancels terms n^3 times larger than the result, and a plainly rounded residual
    /// would cap the solution's accuracy at cond(K) x 1e-16 ~ n^4 x 1e-16 instead of letting Newton
    /// refine it to full precision.
    pub(crate) fn mul_accurate(&self, x: &[f64]) -> Vec<f64> {
        let mut sum = vec![0.0; self.n];
        let mut compensation = vec![0.0; self.n];
        let mut accumulate = |row: usize, a: f64, b: f64| {
            let product = a * b;
            let product_error = a.mul_add(b, -product);
            let total = sum[row] + product;
            let z = total - sum[row];
            let sum_error = (sum[row] - (total - z)) + (product - z);
            sum[row] = total;
            compensation[row] += sum_error + product_error;
        };
        for i in 0..self.n {
            for j in i.saturating_sub(self.bandwidth)..=i {
                let a = self.values[self.index(i, j)];
                accumulate(i, a, x[j]);
                if i != j {
                    accumulate(j, a, x[i]);
                }
            }
        }
        sum.iter().zip(compensation).map(|(s, c)| s + c).collect()
    }

    /// Solves A x = b by Cholesky factorization (consumes the matrix).
    pub(crate) fn solve(self, b: &[f64]) -> Result<Vec<f64>, NotPositiveDefinite> {
        Ok(self.factor()?.solve(b))
    }

    /// The Cholesky factor L (A = L L^T), in place (consumes the matrix): for solving with many
    /// right-hand sides at the cost of one factorization.
    pub(crate) fn factor(mut self) -> Result<BandCholesky, NotPositiveDefinite> {
        // Entry (i, k), k in [i - bw, i], sits at (i + 1) bw + k: a row's entries are contiguous,
        // so the inner products run over slices (the same operations, in the same order, as
        // through `index`).
        let bw = self.bandwidth;
        for i in 0..self.n {
            let row_i = (i + 1) * bw;
            let start = i.saturating_sub(bw);
            for j in start..=i {
                let row_j = (j + 1) * bw;
                let mut sum = self.values[row_i + j];
                for (a, b) in self.values[row_i + start..row_i + j]
                    .iter()
                    .zip(&self.values[row_j + start..row_j + j])
                {
                    sum -= a * b;
                }
                if i == j {
                    if sum <= 0.0 || !sum.is_finite() {
                        return Err(NotPositiveDefinite { row: i });
                    }
                    self.values[row_i + j] = sum.sqrt();
                } else {
                    self.values[row_i + j] = sum / self.values[row_j + j];
                }
            }
        }
        Ok(BandCholesky(self))
    }
}

/// A factored [`SymmetricBand`]: its lower Cholesky factor in the same storage.
#[derive(Debug, Clone)]
pub(crate) struct BandCholesky(SymmetricBand);

impl BandCholesky {
    /// Solves A x = b by forward and back substitution.
    pub(crate) fn solve(&self, b: &[f64]) -> Vec<f64> {
        let f = &self.0;
        let bw = f.bandwidth;
        let mut y = b.to_vec();
        for i in 0..f.n {
            let row = (i + 1) * bw;
            let start = i.saturating_sub(bw);
            let mut sum = y[i];
            for (a, x) in f.values[row + start..row + i].iter().zip(&y[start..i]) {
                sum -= a * x;
            }
            y[i] = sum / f.values[row + i];
        }
        for i in (0..f.n).rev() {
            let mut sum = y[i];
            let end = (i + bw).min(f.n - 1);
            for (k, x) in y.iter().enumerate().take(end + 1).skip(i + 1) {
                sum -= f.values[(k + 1) * bw + i] * x;
            }
            y[i] = sum / f.values[(i + 1) * bw + i];
        }
        y
    }

    /// Solves A X = B for `columns` right-hand sides at once, in place: `b` holds B row by row
    /// (entry (i, r) at `b[i * columns + r]`). The same operations as [`BandCholesky::solve`] per
    /// column, each factor entry read once for all of them.
    pub(crate) fn solve_many(&self, b: &mut [f64], columns: usize) {
        let f = &self.0;
        let bw = f.bandwidth;
        let n = f.n;
        debug_assert_eq!(b.len(), n * columns);
        for i in 0..n {
            for k in i.saturating_sub(bw)..i {
                let l = f.values[(i + 1) * bw + k];
                let (head, tail) = b.split_at_mut(i * columns);
                let source = &head[k * columns..(k + 1) * columns];
                for (y, x) in tail[..columns].iter_mut().zip(source) {
                    *y -= l * x;
                }
            }
            let d = f.values[(i + 1) * bw + i];
            for y in &mut b[i * columns..(i + 1) * columns] {
                *y /= d;
            }
        }
        for i in (0..n).rev() {
            for k in (i + 1)..=(i + bw).min(n - 1) {
                let l = f.values[(k + 1) * bw + i];
                let (head, tail) = b.split_at_mut(k * columns);
                let source = &tail[..columns];
                for (y, x) in head[i * columns..(i + 1) * columns].iter_mut().zip(source) {
                    *y -= l * x;
                }
            }
            let d = f.values[(i + 1) * bw + i];
            for y in &mut b[i * columns..(i + 1) * columns] {
                *y /= d;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn many_right_hand_sides_solve_as_one_each() {
        let n = 30;
        let mut a = SymmetricBand::zeros(n, 3);
        for i in 0..n {
            a.add(i, i, 10.0 + i as f64);
            for k in 1..=3.min(i) {
                a.add(i, i - k, 1.0 / (1.0 + k as f64));
            }
        }
        let factor = a.factor().unwrap();
        let columns = 4;
        let rhs: Vec<Vec<f64>> = (0..columns)
            .map(|r| {
                (0..n)
                    .map(|i| ((i * 7 + r * 3) % 11) as f64 - 5.0)
                    .collect()
            })
            .collect();
        let mut block = vec![0.0; n * columns];
        for (r, column) in rhs.iter().enumerate() {
            for (i, v) in column.iter().enumerate() {
                block[i * columns + r] = *v;
            }
        }
        factor.solve_many(&mut block, columns);
        for (r, column) in rhs.iter().enumerate() {
            let one = factor.solve(column);
            for i in 0..n {
                assert_eq!(block[i * columns + r], one[i]);
            }
        }
    }

    #[test]
    fn solves_a_tridiagonal_system_exactly() {
        // -x_{i-1} + 2 x_i - x_{i+1} = b with x = i^2 => b_i = -2 inside.
        let n = 50;
        let mut a = SymmetricBand::zeros(n, 1);
        for i in 0..n {
            a.add(i, i, 2.0);
            if i > 0 {
                a.add(i, i - 1, -1.0);
            }
        }
        let x: Vec<f64> = (0..n).map(|i| (i * i) as f64).collect();
        let b = a.mul(&x);
        assert_eq!(a.mul_accurate(&x), b);
        let solved = a.solve(&b).unwrap();
        for (s, e) in solved.iter().zip(&x) {
            assert!((s - e).abs() < 1e-8 * (1.0 + e.abs()), "{s} vs {e}");
        }
    }

    #[test]
    fn accurate_product_survives_cancellation() {
        // [1e16, 1; 1, 1e-16] x [1, -1e16]: the first row is 1e16 - 1e16 = 0 exactly; the second is
        // 1 - 1 = 0. With x = [1 + 2^-52, -1e16] the first row is 1e16 * 2^-52 = 2.22..., which the
        // plain product loses to rounding of 1e16 + 2.22 - 1e16.
        let mut a = SymmetricBand::zeros(2, 1);
        a.add(0, 0, 1e16);
        a.add(1, 0, 1.0);
        a.add(1, 1, 1e-16);
        let x = [1.0 + f64::EPSILON, -1e16];
        let exact = 1e16 * f64::EPSILON;
        assert!((a.mul_accurate(&x)[0] - exact).abs() < 1e-15 * exact);
        assert!((a.mul(&x)[0] - exact).abs() > 0.05 * exact);
    }

    #[test]
    fn fixed_rows_pin_their_unknown_and_indefinite_matrices_are_refused() {
        let mut a = SymmetricBand::zeros(3, 2);
        for i in 0..3 {
            a.add(i, i, 4.0);
        }
        a.add(1, 0, 1.0);
        a.add(2, 0, 1.0);
        a.fix(0);
        assert_eq!(a.get(0, 2), 0.0);
        let x = a.solve(&[0.0, 4.0, 8.0]).unwrap();
        assert_eq!(x, vec![0.0, 1.0, 2.0]);
        let mut singular = SymmetricBand::zeros(2, 1);
        singular.add(0, 0, 1.0);
        singular.add(1, 0, 1.0);
        singular.add(1, 1, 1.0);
        assert_eq!(
            singular.solve(&[1.0, 1.0]).unwrap_err(),
            NotPositiveDefinite { row: 1 }
        );
    }
}
