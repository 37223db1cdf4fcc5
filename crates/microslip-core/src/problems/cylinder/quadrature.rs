//! The numerical pieces of the cylinder's semi-analytic solution, none of them physics: Gauss-
//! Legendre rules, the exact integrals of Legendre polynomials against the logarithmic kernel
//! ln|y - t| (docs/theory.md (H12)), Lagrange interpolation on Gauss points, and a dense LU
//! solve with partial pivoting for the small collocation systems.

use std::sync::OnceLock;

/// Most Gauss points per element any mesh uses.
pub(crate) const MAX_POINTS: usize = 16;

/// Points of the rule that integrates the kernel over an element far from the point (|y| >=
/// [`FAR`]): ln|y - t| is analytic in the Bernstein ellipse of parameter y + sqrt(y^2 - 1) >=
/// 2.6, so 24 points leave an error below 2.6^-48 ~ 1e-20 of the integrand's size.
const FAR_POINTS: usize = 24;

/// From |y| = 4 on (ellipse parameter 7.9), 12 points integrate P_k(t) ln|y - t| to about
/// 7.9^-(24 - k): 5e-16 for the moments up to k = 7 that meshes of up to 8 points per element
/// use (higher moments take the 24-point rule). Most elements are that far from most points,
/// so this halves a kernel row's cost.
const FARTHER: f64 = 4.0;

/// Points of the rule beyond [`FARTHER`].
const FARTHER_POINTS: usize = 12;

/// From |y| = 1.5 on, the moments come from [`FAR_POINTS`]-point quadrature; below, from the
/// Legendre functions of the second kind, whose forward recurrence loses (y + sqrt(y^2 -
/// 1))^(2k) of relative accuracy outside [-1, 1]: at most 2.6^30 ~ 3e12 times 1e-16 at y = 1.5
/// and k = 15, a 3e-4 relative error on a moment of size 1e-9 of the leading one, far below
/// the 1e-12 the solver needs.
const FAR: f64 = 1.5;

/// An n-point Gauss-Legendre rule on [-1, 1]: (nodes, weights), nodes increasing.
pub(crate) fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    for i in 0..n {
        // Tricomi's initial guess, then Newton on P_n.
        let mut x = -(std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = legendre_and_derivative(n, x);
            let step = p / dp;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let (_, dp) = legendre_and_derivative(n, x);
        nodes[i] = x;
        weights[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
    (nodes, weights)
}

/// P_n(x) and P_n'(x).
fn legendre_and_derivative(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 1..n {
        let p2 = ((2 * k + 1) as f64 * x * p1 - k as f64 * p0) / (k + 1) as f64;
        p0 = p1;
        p1 = p2;
    }
    let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
    (p1, dp)
}

/// P_0(x) .. P_{n-1}(x) into `out`.
pub(crate) fn legendre_values(x: f64, out: &mut [f64]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    out[0] = 1.0;
    if n > 1 {
        out[1] = x;
    }
    for k in 1..n.saturating_sub(1) {
        out[k + 1] = ((2 * k + 1) as f64 * x * out[k] - k as f64 * out[k - 1]) / (k + 1) as f64;
    }
}

/// A far-field rule: its nodes, weights and the Legendre polynomials P_0 .. P_15 at each node
/// (`legendre[i * (MAX_POINTS + 1) + k]`).
struct FarRule {
    nodes: Vec<f64>,
    weights: Vec<f64>,
    legendre: Vec<f64>,
}

impl FarRule {
    fn new(points: usize) -> FarRule {
        let (nodes, weights) = gauss_legendre(points);
        let mut legendre = vec![0.0; points * (MAX_POINTS + 1)];
        for (i, &t) in nodes.iter().enumerate() {
            legendre_values(
                t,
                &mut legendre[i * (MAX_POINTS + 1)..(i + 1) * (MAX_POINTS + 1)],
            );
        }
        FarRule {
            nodes,
            weights,
            legendre,
        }
    }
}

/// The far-field rules ([`FAR_POINTS`], [`FARTHER_POINTS`]), computed once.
fn far_rules() -> &'static [FarRule; 2] {
    static RULES: OnceLock<[FarRule; 2]> = OnceLock::new();
    RULES.get_or_init(|| [FarRule::new(FAR_POINTS), FarRule::new(FARTHER_POINTS)])
}

/// x ln|x|, 0 at 0.
fn x_log_x(x: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x * x.abs().ln() }
}

/// The log moments I_k(y) = integral over [-1, 1] of P_k(t) ln|y - t| dt, k < `out.len()`
/// (H12): exact through the Legendre functions of the second kind near the interval
/// (I_0 = (y + 1) ln|y + 1| - (y - 1) ln|y - 1| - 2 and I_k = 2 (Q_{k+1}(y) - Q_{k-1}(y)) /
/// (2k + 1), by parts), by quadrature of the smooth integrand far from it.
pub(crate) fn log_moments(y: f64, out: &mut [f64]) {
    let n = out.len();
    if y.abs() >= FAR {
        let rules = far_rules();
        let rule = if y.abs() >= FARTHER && n <= 8 {
            &rules[1]
        } else {
            &rules[0]
        };
        out.fill(0.0);
        for (i, (&t, &w)) in rule.nodes.iter().zip(&rule.weights).enumerate() {
            let l = w * (y - t).abs().ln();
            let p = &rule.legendre[i * (MAX_POINTS + 1)..i * (MAX_POINTS + 1) + n];
            for (o, pk) in out.iter_mut().zip(p) {
                *o += l * pk;
            }
        }
        return;
    }
    out[0] = x_log_x(y + 1.0) - x_log_x(y - 1.0) - 2.0;
    if n == 1 {
        return;
    }
    if (y.abs() - 1.0).abs() == 0.0 {
        // At an end of the element, integral of P_k(t) ln(1 - t) = -2 / (k (k + 1)); the other
        // end by parity.
        for (k, o) in out.iter_mut().enumerate().skip(1) {
            let at_one = -2.0 / (k * (k + 1)) as f64;
            *o = if y > 0.0 || k % 2 == 0 {
                at_one
            } else {
                -at_one
            };
        }
        return;
    }
    // Q_0 .. Q_n by the forward recurrence (the principal value's on the cut).
    let mut q = [0.0; MAX_POINTS + 2];
    q[0] = 0.5 * ((1.0 + y) / (1.0 - y)).abs().ln();
    q[1] = y * q[0] - 1.0;
    for j in 1..n {
        q[j + 1] = ((2 * j + 1) as f64 * y * q[j] - j as f64 * q[j - 1]) / (j + 1) as f64;
    }
    for (k, o) in out.iter_mut().enumerate().skip(1) {
        *o = 2.0 * (q[k + 1] - q[k - 1]) / (2 * k + 1) as f64;
    }
}

/// The Lagrange basis on the Gauss `nodes` at `t` (barycentric form), into `out`.
pub(crate) fn lagrange_basis(nodes: &[f64], bary: &[f64], t: f64, out: &mut [f64]) {
    if let Some(j) = nodes.iter().position(|&x| x == t) {
        out.fill(0.0);
        out[j] = 1.0;
        return;
    }
    let mut sum = 0.0;
    for ((o, &x), &b) in out.iter_mut().zip(nodes).zip(bary) {
        *o = b / (t - x);
        sum += *o;
    }
    for o in out.iter_mut() {
        *o /= sum;
    }
}

/// The barycentric weights of `nodes`.
pub(crate) fn barycentric_weights(nodes: &[f64]) -> Vec<f64> {
    nodes
        .iter()
        .enumerate()
        .map(|(j, &xj)| {
            1.0 / nodes
                .iter()
                .enumerate()
                .filter(|&(k, _)| k != j)
                .map(|(_, &xk)| xj - xk)
                .product::<f64>()
        })
        .collect()
}

/// Solves the `size` x `size` system `matrix` x = `rhs` in place (both overwritten) and splits
/// x into the collocation unknowns (left in `rhs`) and the last one, the rigid shift's constant
/// D, returned; `None` when the matrix is singular. The collocation systems of the cylinder all
/// end with that one constant.
pub(crate) fn solve_with_constant(
    matrix: &mut [f64],
    size: usize,
    rhs: &mut Vec<f64>,
) -> Option<f64> {
    let mut pivots = vec![0; size];
    if !lu_factor(matrix, size, &mut pivots) {
        return None;
    }
    lu_solve(matrix, size, &pivots, rhs);
    let constant = rhs.pop()?;
    Some(constant)
}

/// Solves the dense `n` x `n` system `a x = b` in place (row-major `a`, `b` becomes x) by LU
/// with partial pivoting, keeping the factors in `a` and the row order in `pivots` so that
/// [`lu_solve`] can reuse them; `false` when a pivot vanishes (a singular matrix).
pub(crate) fn lu_factor(a: &mut [f64], n: usize, pivots: &mut [usize]) -> bool {
    for k in 0..n {
        let (mut best, mut row) = (a[k * n + k].abs(), k);
        for i in k + 1..n {
            let v = a[i * n + k].abs();
            if v > best {
                best = v;
                row = i;
            }
        }
        if best == 0.0 || !best.is_finite() {
            return false;
        }
        pivots[k] = row;
        if row != k {
            for j in 0..n {
                a.swap(k * n + j, row * n + j);
            }
        }
        let pivot = a[k * n + k];
        for i in k + 1..n {
            let factor = a[i * n + k] / pivot;
            a[i * n + k] = factor;
            if factor != 0.0 {
                let (upper, lower) = a.split_at_mut(i * n);
                let source = &upper[k * n + k + 1..k * n + n];
                for (t, s) in lower[k + 1..n].iter_mut().zip(source) {
                    *t -= factor * s;
                }
            }
        }
    }
    true
}

/// Solves with the factors of [`lu_factor`]: `b` becomes x.
pub(crate) fn lu_solve(a: &[f64], n: usize, pivots: &[usize], b: &mut [f64]) {
    for (k, &row) in pivots.iter().enumerate().take(n) {
        b.swap(k, row);
    }
    for i in 0..n {
        b[i] -= dot(&a[i * n..i * n + i], &b[..i]);
    }
    for i in (0..n).rev() {
        let sum = b[i] - dot(&a[i * n + i + 1..i * n + n], &b[i + 1..n]);
        b[i] = sum / a[i * n + i];
    }
}

/// The dot product of `a` and `b` in four interleaved sums: the compiler keeps a strict order
/// of additions, so one running sum is one add per cycle at best; four run side by side (issue
/// 47: the substitutions and the refinement's residuals are most of a continued solve). Not the
/// sequential sum's rounding, which no caller depends on.
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut sums = [0.0; 4];
    let (a4, b4) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (a4.remainder(), b4.remainder());
    for (x, y) in a4.zip(b4) {
        for k in 0..4 {
            sums[k] += x[k] * y[k];
        }
    }
    let tail: f64 = ra.iter().zip(rb).map(|(x, y)| x * y).sum();
    (sums[0] + sums[1]) + (sums[2] + sums[3]) + tail
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_of_degree_2n_minus_1() {
        for n in [1, 2, 5, 8, 16, 24] {
            let (x, w) = gauss_legendre(n);
            for degree in 0..2 * n {
                let numeric: f64 = x
                    .iter()
                    .zip(&w)
                    .map(|(x, w)| w * x.powi(degree as i32))
                    .sum();
                let exact = if degree % 2 == 1 {
                    0.0
                } else {
                    2.0 / (degree + 1) as f64
                };
                assert!((numeric - exact).abs() < 1e-14, "{n} {degree}");
            }
        }
    }

    /// The log moments, three ways: by hand (I_0 at 0 is -2, I_1(y) at 0 is 0 by parity, I_1 at
    /// the end is -1), against the far-field quadrature where the two methods meet (|y| = 1.5,
    /// the near side's formulas evaluated there), and against a graded quadrature of the
    /// singular integrand split at y inside the interval.
    #[test]
    fn log_moments_agree_with_hand_values_quadrature_and_across_the_switch() {
        let mut m = [0.0; 10];
        log_moments(0.0, &mut m);
        assert!((m[0] + 2.0).abs() < 1e-15);
        assert!(m[1].abs() < 1e-15);
        log_moments(1.0, &mut m);
        assert!((m[1] + 1.0).abs() < 1e-15);
        assert!((m[0] - (2.0 * 2f64.ln() - 2.0)).abs() < 1e-15);
        let mut near = [0.0; 12];
        let mut far = [0.0; 12];
        // Both far rules agree where they meet, for the eight moments the farther one serves.
        let (mut inner, mut outer) = ([0.0; 8], [0.0; 8]);
        log_moments(FARTHER, &mut outer);
        log_moments(FARTHER.next_down(), &mut inner);
        for k in 0..8 {
            assert!(
                (inner[k] - outer[k]).abs() < 1e-14,
                "{k}: {} {}",
                inner[k],
                outer[k]
            );
        }
        for y in [1.5f64, -1.5] {
            log_moments(y, &mut far);
            // The near-side formulas, evaluated at the switch by moving it a hair.
            log_moments(y - y.signum() * 1e-13, &mut near);
            for k in 0..12 {
                assert!(
                    (near[k] - far[k]).abs() < 1e-11,
                    "{y} {k}: {} {}",
                    near[k],
                    far[k]
                );
            }
        }
        // Inside: split the integral at y, each half with t = y + (end - y) s^6 (which smooths
        // the log singularity to s^5 ln s), 200-point Gauss.
        let (x, w) = gauss_legendre(200);
        for y in [0.3, -0.77, 0.999] {
            log_moments(y, &mut m);
            for (k, mk) in m.iter().enumerate() {
                let mut sum = 0.0;
                let mut p = [0.0; 10];
                for (end, length) in [(1.0, 1.0 - y), (-1.0, 1.0 + y)] {
                    let length: f64 = length;
                    for (&xi, &wi) in x.iter().zip(&w) {
                        let s = 0.5 * (xi + 1.0);
                        let t = y + (end - y) * s.powi(6);
                        legendre_values(t, &mut p);
                        let jacobian = 6.0 * s.powi(5) * length.abs();
                        let log = length.abs().ln() + 6.0 * s.ln();
                        sum += 0.5 * wi * jacobian * p[k] * log;
                    }
                }
                assert!((sum - mk).abs() < 1e-12, "{y} {k}: {sum} {mk}");
            }
        }
    }

    #[test]
    fn lu_solves_a_system_that_needs_pivoting() {
        let mut a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 2.0, 1.0, 3.0];
        let mut b = vec![3.0, 3.0, 6.0];
        let mut p = [0; 3];
        assert!(lu_factor(&mut a, 3, &mut p));
        lu_solve(&a, 3, &p, &mut b);
        for (x, e) in b.iter().zip([1.0, 1.0, 1.0]) {
            assert!((x - e).abs() < 1e-14);
        }
        let mut singular = vec![1.0, 2.0, 2.0, 4.0];
        assert!(!lu_factor(&mut singular, 2, &mut [0; 2]));
    }

    #[test]
    fn lagrange_basis_reproduces_polynomials() {
        let (x, _) = gauss_legendre(6);
        let bary = barycentric_weights(&x);
        let mut l = [0.0; 6];
        for t in [-1.0, -0.3, 0.0, 0.77, 1.0] {
            lagrange_basis(&x, &bary, t, &mut l);
            let value: f64 = l.iter().zip(&x).map(|(l, x)| l * x.powi(5)).sum();
            assert!((value - t.powi(5)).abs() < 1e-13);
        }
    }
}
