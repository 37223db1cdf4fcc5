//! The sliding strips' share of the regularized cylinder's log potential (docs/theory.md (H11')):
//! the shear mu p on gamma < |t| < 1, written in the angle alpha = arccos t so that its load
//! and its potential are computed to full relative precision however narrow the strips are
//! (their width 1 - gamma falls as Q^2, below any mesh and below the rounding of gamma itself).

use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;

use super::quadrature::{gauss_legendre, legendre_values, log_moments};

/// Gauss points per piece of [`graded`].
const POINTS: usize = 16;

/// Each piece of [`graded`] is this times as long as the one before it, towards the singular
/// point: the point is then 0.22 of a piece's half-length beyond its end (a Bernstein ellipse of
/// 1.9), so 16 points integrate the log to about 1.9^-32 ~ 1e-9 of the piece's share.
const RATIO: f64 = 0.1;

fn rule() -> &'static (Vec<f64>, Vec<f64>) {
    static RULE: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    RULE.get_or_init(|| gauss_legendre(POINTS))
}

/// The load the two strips carry, over the whole contact's: (4 / pi) times integral_gamma^1
/// sqrt(1 - t^2) dt = (4 / pi) (theta / 2 - sin(2 theta) / 4), gamma = cos theta; by its series
/// where the closed form would cancel (2 theta - sin 2 theta for a small theta).
pub(crate) fn strip_area(theta: f64) -> f64 {
    let x = 2.0 * theta;
    let difference = if x < 0.5 {
        // x - sin x = x^3/3! - x^5/5! + ..., to below 1e-16 of the first term at x = 0.5.
        let mut term = x * x * x / 6.0;
        let mut sum = 0.0;
        for k in 0..8 {
            sum += term;
            let next = (2 * k + 4) as f64 * (2 * k + 5) as f64;
            term *= -x * x / next;
        }
        sum
    } else {
        x - x.sin()
    };
    difference / 4.0
}

/// E(t) = integral over gamma < |tau| < 1 of sqrt(1 - tau^2) ln|t - tau| dtau, at t = 1 -
/// `one_minus_t` in [0, 1], gamma = cos `theta`: in tau = cos alpha it is the integral over [0,
/// theta] of sin^2 alpha ln|cos^2 alpha - t^2| dalpha, and with t = cos beta the argument is
/// 2 |sin((alpha + beta) / 2) sin((beta - alpha) / 2)| (cos alpha + t), exact however close
/// alpha and beta come; the log's one singular point, alpha = beta, is a piece end that the
/// pieces are graded towards.
pub(crate) fn strip_potential(theta: f64, one_minus_t: f64) -> f64 {
    if theta <= 0.0 {
        return 0.0;
    }
    let one_minus_t = one_minus_t.clamp(0.0, 1.0);
    let t = 1.0 - one_minus_t;
    let beta = 2.0 * (0.5 * one_minus_t).sqrt().min(1.0).asin();
    let integrand = |alpha: f64| {
        let (s, _) = alpha.sin_cos();
        let product = 2.0
            * (0.5 * (alpha + beta)).sin().abs()
            * (0.5 * (beta - alpha)).sin().abs()
            * (alpha.cos() + t);
        if product > 0.0 {
            s * s * product.ln()
        } else {
            0.0
        }
    };
    let theta = theta.min(FRAC_PI_2);
    if beta >= theta {
        graded(0.0, theta, beta - theta, &integrand)
    } else {
        graded(0.0, beta, 0.0, &integrand) + graded_from_start(beta, theta, &integrand)
    }
}

/// The integral of `f` over [from, to], whose singular point lies `beyond` (>= 0) past `to`:
/// pieces shrinking by [`RATIO`] towards `to` until they are as short as that distance (or
/// 1e-16 of the interval, where what is left is below rounding).
fn graded(from: f64, to: f64, beyond: f64, f: &impl Fn(f64) -> f64) -> f64 {
    let length = to - from;
    if length <= 0.0 {
        return 0.0;
    }
    let floor = beyond.max(1e-16 * length);
    let (mut start, mut rest, mut sum) = (from, length, 0.0);
    while rest > floor {
        let piece = rest * (1.0 - RATIO);
        sum += gauss(start, start + piece, f);
        start += piece;
        rest -= piece;
    }
    sum + gauss(start, to, f)
}

/// [`graded`] with the singular point at `from`.
fn graded_from_start(from: f64, to: f64, f: &impl Fn(f64) -> f64) -> f64 {
    graded(-to, -from, 0.0, &|x: f64| f(-x))
}

/// `POINTS`-point Gauss-Legendre over [from, to].
fn gauss(from: f64, to: f64, f: &impl Fn(f64) -> f64) -> f64 {
    let (nodes, weights) = rule();
    let (mid, half) = (0.5 * (from + to), 0.5 * (to - from));
    half * nodes
        .iter()
        .zip(weights)
        .map(|(x, w)| w * f(mid + half * x))
        .sum::<f64>()
}

/// The points at which [`StripRule`] integrates the smooth part of the strips' integrand.
const RULE_POINTS: usize = 16;

/// A singular point of the strips' integrand is subtracted and integrated exactly when it lies
/// within this many half-lengths of [0, theta]'s centre (where the log moments are exact, not
/// quadrature); beyond, the 16-point rule sees it through a Bernstein ellipse of at least 1.5 +
/// sqrt 1.25 = 2.6, an error below 2.6^-32 ~ 5e-14 of the integrand's size.
const SUBTRACT_WITHIN: f64 = 1.5;

/// (2k + 1) / 2 w_j P_k(x_j) of the [`RULE_POINTS`]-point rule (`[j][k]`): the Legendre
/// coefficients of the interpolant through the rule's points.
fn rule_transform() -> &'static [[f64; RULE_POINTS]; RULE_POINTS] {
    static TRANSFORM: OnceLock<[[f64; RULE_POINTS]; RULE_POINTS]> = OnceLock::new();
    TRANSFORM.get_or_init(|| {
        let (nodes, weights) = rule();
        let mut table = [[0.0; RULE_POINTS]; RULE_POINTS];
        for (row, (&x, &w)) in table.iter_mut().zip(nodes.iter().zip(weights)) {
            legendre_values(x, row);
            for (k, value) in row.iter_mut().enumerate() {
                *value *= (2 * k + 1) as f64 / 2.0 * w;
            }
        }
        table
    })
}

/// [`strip_potential`] for one theta at many t, by product integration (issue 47: the graded
/// pieces cost a thousand evaluations a row near the zone's edge, where the log's singular
/// point nears theta). In tau = cos alpha, t = cos beta, the integrand is sin^2 alpha
/// ln|sin(beta - alpha) sin(beta + alpha)| (cos^2 alpha - t^2 = sin(beta - alpha) sin(beta +
/// alpha)), whose only singular points near [0, pi / 2] are alpha = beta, -beta and pi - beta. Each that lies
/// near [0, theta] is split off as sin^2 alpha ln|alpha - s|, integrated exactly against the
/// Legendre expansion of sin^2 alpha (the log moments of (H12)); what is left is analytic and
/// integrated by one 16-point Gauss rule. One rule serves every row of a collocation system (its
/// points, sines and expansion depend on theta only).
pub(crate) struct StripRule {
    theta: f64,
    mid: f64,
    half: f64,
    /// The rule's points alpha_j on [0, theta], their sines and cosines, and the weights times
    /// sin^2 alpha_j.
    alpha: [f64; RULE_POINTS],
    sin: [f64; RULE_POINTS],
    cos: [f64; RULE_POINTS],
    weighted: [f64; RULE_POINTS],
    /// The Legendre coefficients of sin^2 alpha on [0, theta].
    legendre: [f64; RULE_POINTS],
}

impl StripRule {
    /// The rule on [0, min(theta, pi / 2)].
    pub(crate) fn new(theta: f64) -> StripRule {
        let theta = theta.clamp(0.0, FRAC_PI_2);
        let (nodes, weights) = rule();
        let (mid, half) = (0.5 * theta, 0.5 * theta);
        let mut out = StripRule {
            theta,
            mid,
            half,
            alpha: [0.0; RULE_POINTS],
            sin: [0.0; RULE_POINTS],
            cos: [0.0; RULE_POINTS],
            weighted: [0.0; RULE_POINTS],
            legendre: [0.0; RULE_POINTS],
        };
        let mut squares = [0.0; RULE_POINTS];
        for j in 0..RULE_POINTS {
            let alpha = mid + half * nodes[j];
            let (s, c) = (alpha.sin(), alpha.cos());
            out.alpha[j] = alpha;
            out.sin[j] = s;
            out.cos[j] = c;
            squares[j] = s * s;
            out.weighted[j] = half * weights[j] * s * s;
        }
        for (row, square) in rule_transform().iter().zip(squares) {
            for (c, t) in out.legendre.iter_mut().zip(row) {
                *c += t * square;
            }
        }
        out
    }

    /// [`strip_potential`]`(theta, one_minus_t)`.
    pub(crate) fn potential(&self, one_minus_t: f64) -> f64 {
        if self.theta <= 0.0 {
            return 0.0;
        }
        let one_minus_t = one_minus_t.clamp(0.0, 1.0);
        let beta = 2.0 * (0.5 * one_minus_t).sqrt().min(1.0).asin();
        let (sb, cb) = (beta.sin(), beta.cos());
        // Each singular point s = beta, -beta, pi - beta near [0, theta], split off.
        let mut near = [false; 3];
        let mut exact = 0.0;
        let mut moments = [0.0; RULE_POINTS];
        for (k, s) in [beta, -beta, PI - beta].into_iter().enumerate() {
            let y = (s - self.mid) / self.half;
            if y.abs() < SUBTRACT_WITHIN {
                near[k] = true;
                // The integral of sin^2 alpha ln|alpha - s| = half (ln(half) 2 c_0 + sum c_k
                // I_k(y)).
                log_moments(y, &mut moments);
                let sum: f64 = self.legendre.iter().zip(&moments).map(|(c, m)| c * m).sum();
                exact += self.half * (2.0 * self.legendre[0] * self.half.ln() + sum);
            }
        }
        let mut smooth = 0.0;
        for j in 0..RULE_POINTS {
            let alpha = self.alpha[j];
            let difference = beta - alpha;
            // sin(beta - alpha) from the difference itself where the product formula would
            // cancel.
            let mut minus = if difference.abs() < 0.25 {
                difference.sin()
            } else {
                sb * self.cos[j] - cb * self.sin[j]
            };
            let mut plus = sb * self.cos[j] + cb * self.sin[j];
            // Each factor over its own singular point's, so that no product of small numbers
            // underflows (they are O(theta), and theta goes down to 1e-300).
            if near[0] {
                minus /= alpha - beta;
            }
            if near[1] {
                plus /= alpha + beta;
            }
            if near[2] {
                plus /= alpha - (PI - beta);
            }
            let product = minus * plus;
            let log = if product.is_normal() {
                product.abs().ln()
            } else {
                minus.abs().ln() + plus.abs().ln()
            };
            smooth += self.weighted[j] * log;
        }
        exact + smooth
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At theta = pi / 2 the strips are the whole half-ellipse, whose potential (H4) is
    /// (pi / 2) (t^2 - 1/2 - ln 2); at a small theta the strips are two narrow bands of width w =
    /// 1 - gamma and shear about sqrt(2 (1 - |tau|)), so E(t) -> (2 sqrt 2 / 3) w^(3/2) ln(1 -
    /// t^2) far from them (measured to 1e-10 and 1e-8). The area by its closed form, and its
    /// series against it where both are accurate.
    #[test]
    fn the_strips_potential_and_area_by_hand() {
        for t in [0.0, 0.3, 0.9, 1.0] {
            let exact = FRAC_PI_2 * (t * t - 0.5 - 2f64.ln());
            let got = strip_potential(FRAC_PI_2, 1.0 - t);
            assert!((got - exact).abs() < 1e-9, "{t}: {got} {exact}");
        }
        let theta = 1e-4_f64;
        let w = 1.0 - theta.cos();
        for t in [0.5_f64, 0.8] {
            let far = 2.0 * 2f64.sqrt() / 3.0 * w.powf(1.5) * (1.0 - t * t).ln();
            let got = strip_potential(theta, 1.0 - t);
            assert!((got / far - 1.0).abs() < 1e-6, "{t}: {got} {far}");
        }
        assert!((strip_area(FRAC_PI_2) - PI / 4.0).abs() < 1e-15);
        for theta in [0.2_f64, 0.249] {
            let closed = (2.0 * theta - (2.0 * theta).sin()) / 4.0;
            assert!((strip_area(theta) / closed - 1.0).abs() < 1e-12, "{theta}");
        }
        // Small angles: theta^3 / 3, never the 0 the closed form rounds to.
        assert!((strip_area(1e-9) / (1e-27 / 3.0) - 1.0).abs() < 1e-15);
    }

    /// The product-integration rule against the graded pieces, at every kind of row a solve
    /// and its fields ask for: the collocation rows (t <= gamma), inside the strips (t > gamma),
    /// the centre and the edge, from a tiny theta to nearly pi / 2. They agree to 5e-11 (at
    /// theta = pi / 2 - 1e-4, t near 0, where the graded pieces see the singular point pi - beta only
    /// through their grading towards beta), below the 1e-9 the solves are held to; what is left
    /// at a tiny theta and t = 0 is the graded sum's rounding (7e-44 where the potential is
    /// -theta^5 / 5 = -2e-46).
    #[test]
    fn the_product_rule_agrees_with_the_graded_pieces() {
        for theta in [1e-9, 1e-4, 0.05, 0.3, 0.8, 1.2, 1.5, FRAC_PI_2 - 1e-4] {
            let rule = StripRule::new(theta);
            let width = 1.0 - theta.cos();
            let mut ts: Vec<f64> = [0.0, 0.3, 0.9, 0.99, 0.999999, 1.0]
                .iter()
                .map(|u| (1.0 - u) + u * width)
                .collect();
            ts.extend([0.0, 0.3 * width, 0.999 * width, 1.0]);
            for one_minus_t in ts {
                let graded = strip_potential(theta, one_minus_t);
                let product = rule.potential(one_minus_t);
                // Plus the rounding of a log near 0 (1e-16) over the strips' area theta^3 / 3,
                // the size of both at t = 0 and a small theta.
                assert!(
                    (product - graded).abs() <= 1e-10 * graded.abs() + 1e-16 * theta.powi(3),
                    "theta {theta}, 1 - t {one_minus_t}: {product} {graded}"
                );
            }
        }
    }
}
