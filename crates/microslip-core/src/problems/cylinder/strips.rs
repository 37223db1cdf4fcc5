//! The sliding strips' share of the regularized cylinder's log potential (docs/theory.md (H11')):
//! the shear mu p on gamma < |t| < 1, written in the angle alpha = arccos t so that its load
//! and its potential are computed to full relative precision however narrow the strips are
//! (their width 1 - gamma falls as Q^2, below any mesh and below the rounding of gamma itself).

use std::f64::consts::FRAC_PI_2;
use std::sync::OnceLock;

use super::quadrature::gauss_legendre;

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

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

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
}
