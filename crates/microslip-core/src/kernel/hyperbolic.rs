//! Overflow-free, cancellation-free hyperbolic building blocks.
//!
//! The closed forms of every problem are made of `sinh`, `cosh` and their Taylor remainders evaluated at
//! `k x`, where `k` ranges over many decades (over the accepted domain `k L` runs from ~6e-16 to
//! ~2e17, docs/theory.md). Evaluated naively, `cosh(k L)` overflows above 710 and `cosh(k x) - 1 - (k x)^2 / 2`
//! loses every digit for small arguments. Every function here stays finite and accurate to a few ulps
//! for all non-negative finite arguments, which is what lets the models promise "no NaN, no overflow".

/// Below this argument the Taylor remainders are summed as series; above it they are evaluated
/// directly, where cancellation costs at most a few bits.
const SERIES_LIMIT: f64 = 1.0;

/// Sums `sum_{n >= 0} z^(2n) / (2n + first)!` — the common shape of every remainder series below.
/// With `z <= 1` the terms shrink by at least 1/((2n+first+1)(2n+first+2)), so 12 terms exceed f64
/// precision.
fn even_series(z: f64, first: u32) -> f64 {
    let z2 = z * z;
    let mut term = 1.0 / (1..=first).map(f64::from).product::<f64>();
    let mut sum = term;
    let mut n = f64::from(first);
    for _ in 0..12 {
        term *= z2 / ((n + 1.0) * (n + 2.0));
        n += 2.0;
        sum += term;
    }
    sum
}

/// `sinh(z) / z`, equal to 1 at z = 0.
pub(crate) fn sinhc(z: f64) -> f64 {
    if z.abs() < SERIES_LIMIT {
        even_series(z, 1)
    } else {
        z.sinh() / z
    }
}

/// `(cosh z - 1) / z^2`, equal to 1/2 at z = 0.
pub(crate) fn cosh_rem0(z: f64) -> f64 {
    if z.abs() < SERIES_LIMIT {
        even_series(z, 2)
    } else {
        (z.cosh() - 1.0) / (z * z)
    }
}

/// `(sinh z - z) / z^3`, equal to 1/6 at z = 0.
pub(crate) fn sinh_rem1(z: f64) -> f64 {
    if z.abs() < SERIES_LIMIT {
        even_series(z, 3)
    } else {
        (z.sinh() - z) / (z * z * z)
    }
}

/// `(cosh z - 1 - z^2/2) / z^4`, equal to 1/24 at z = 0.
pub(crate) fn cosh_rem2(z: f64) -> f64 {
    if z.abs() < SERIES_LIMIT {
        even_series(z, 4)
    } else {
        (z.cosh() - 1.0 - 0.5 * z * z) / (z * z * z * z)
    }
}

/// `(sinh z - z - z^3/6) / z^5`, equal to 1/120 at z = 0.
pub(crate) fn sinh_rem3(z: f64) -> f64 {
    if z.abs() < SERIES_LIMIT {
        even_series(z, 5)
    } else {
        (z.sinh() - z - z * z * z / 6.0) / z.powi(5)
    }
}

/// `1 / sinh(b)` for `b > 0`, without overflow for large `b`.
pub(crate) fn inv_sinh(b: f64) -> f64 {
    2.0 * (-b).exp() / -(-2.0 * b).exp_m1()
}

/// `sinh(a) / sinh(b)` for `0 <= a <= b`, `b > 0`: at most 1, finite for any `b`.
pub(crate) fn sinh_ratio(a: f64, b: f64) -> f64 {
    (a - b).exp() * (-2.0 * a).exp_m1() / (-2.0 * b).exp_m1()
}

/// `cosh(a) / sinh(b)` for `0 <= a <= b`, `b > 0`: finite for any `b`.
pub(crate) fn cosh_sinh_ratio(a: f64, b: f64) -> f64 {
    (a - b).exp() * (1.0 + (-2.0 * a).exp()) / -(-2.0 * b).exp_m1()
}

/// `sinh(a) / cosh(b)` for `0 <= a <= b`: below 1, finite for any `b`.
pub(crate) fn sinh_cosh_ratio(a: f64, b: f64) -> f64 {
    (a - b).exp() * -(-2.0 * a).exp_m1() / (1.0 + (-2.0 * b).exp())
}

/// `1 - 1/cosh(z)`, accurate for small `z` (where it is ~ z^2/2) and finite for large `z`.
pub(crate) fn one_minus_sech(z: f64) -> f64 {
    let e = (-z.abs()).exp();
    // 1 - sech z = (cosh z - 1)/cosh z = (1 - e)^2 / (1 + e^2) with e = exp(-|z|).
    let one_minus_e = -(-z.abs()).exp_m1();
    one_minus_e * one_minus_e / (1.0 + e * e)
}

/// `tanh(z) / z`, equal to 1 at z = 0: a length times it stays finite and exact for every z.
pub(crate) fn tanhc(z: f64) -> f64 {
    if z == 0.0 { 1.0 } else { z.tanh() / z }
}

/// `1 - tanh(z) / z`, accurate for small `z` (where it is ~ z^2/3 and the direct form cancels):
/// the series of tanh below 0.1, where seven terms exceed f64 precision; the direct form above,
/// where it loses at most three digits to cancellation at the switch.
pub(crate) fn one_minus_tanhc(z: f64) -> f64 {
    const TANH_SERIES: [f64; 7] = [
        1.0 / 3.0,
        -2.0 / 15.0,
        17.0 / 315.0,
        -62.0 / 2835.0,
        1382.0 / 155_925.0,
        -21_844.0 / 6_081_075.0,
        929_569.0 / 638_512_875.0,
    ];
    if z.abs() < 0.1 {
        let z2 = z * z;
        TANH_SERIES.iter().rev().fold(0.0, |sum, c| sum * z2 + c) * z2
    } else {
        1.0 - z.tanh() / z
    }
}

/// `1 / cosh(z)`, zero rather than a division by infinity past cosh's overflow.
pub(crate) fn sech(z: f64) -> f64 {
    let e = (-z.abs()).exp();
    2.0 * e / (1.0 + e * e)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn remainders_match_their_definitions_where_cancellation_is_harmless() {
        // At z = 3 the direct formulas lose under two digits, so they are an independent check of the
        // series used below z = 1 only through continuity (next test).
        for &z in &[1.5_f64, 3.0, 10.0, 40.0] {
            assert!(rel(sinhc(z), z.sinh() / z) < 1e-15);
            assert!(rel(cosh_rem0(z), (z.cosh() - 1.0) / z.powi(2)) < 1e-15);
            assert!(rel(sinh_rem1(z), (z.sinh() - z) / z.powi(3)) < 1e-15);
            assert!(rel(cosh_rem2(z), (z.cosh() - 1.0 - z * z / 2.0) / z.powi(4)) < 1e-15);
            assert!(rel(sinh_rem3(z), (z.sinh() - z - z.powi(3) / 6.0) / z.powi(5)) < 1e-14);
        }
    }

    #[test]
    fn series_and_direct_forms_agree_at_the_switch() {
        let below = SERIES_LIMIT * (1.0 - 1e-12);
        let above = SERIES_LIMIT * (1.0 + 1e-12);
        for f in [sinhc, cosh_rem0, sinh_rem1, cosh_rem2, sinh_rem3] {
            assert!(
                rel(f(below), f(above)) < 1e-10,
                "{} vs {}",
                f(below),
                f(above)
            );
        }
    }

    #[test]
    fn remainders_have_their_taylor_limits_at_zero() {
        assert_eq!(sinhc(0.0), 1.0);
        assert_eq!(cosh_rem0(0.0), 0.5);
        assert!(rel(sinh_rem1(0.0), 1.0 / 6.0) < 1e-15);
        assert!(rel(cosh_rem2(0.0), 1.0 / 24.0) < 1e-15);
        assert!(rel(sinh_rem3(0.0), 1.0 / 120.0) < 1e-15);
        // Next Taylor term: cosh_rem2(z) = 1/24 + z^2/720 + O(z^4).
        let z = 1e-3;
        assert!(rel(cosh_rem2(z), 1.0 / 24.0 + z * z / 720.0) < 1e-12);
    }

    #[test]
    fn ratios_match_naive_forms_in_range_and_stay_finite_beyond() {
        for &(a, b) in &[
            (0.0, 0.5),
            (0.3, 0.5),
            (2.0, 5.0),
            (5.0, 5.0),
            (100.0, 300.0),
        ] {
            assert!(rel(sinh_ratio(a, b) + 1e-300, a.sinh() / b.sinh() + 1e-300) < 1e-13);
            assert!(rel(cosh_sinh_ratio(a, b), a.cosh() / b.sinh()) < 1e-13);
            assert!(rel(sinh_cosh_ratio(a, b) + 1e-300, a.sinh() / b.cosh() + 1e-300) < 1e-13);
            assert!(rel(inv_sinh(b), 1.0 / b.sinh()) < 1e-13);
        }
        // Far beyond cosh's overflow at 710: ratios of equal arguments are still exact.
        assert!(rel(sinh_ratio(5000.0, 5000.0), 1.0) < 1e-15);
        assert!(rel(cosh_sinh_ratio(5000.0, 5000.0), 1.0) < 1e-15);
        assert_eq!(inv_sinh(5000.0), 0.0);
        assert!(rel(inv_sinh(1e-9), 1e9) < 1e-12);
    }

    #[test]
    fn one_minus_sech_is_accurate_at_both_ends() {
        let z = 1e-5;
        assert!(rel(one_minus_sech(z), z * z / 2.0 - 5.0 * z.powi(4) / 24.0) < 1e-12);
        assert_eq!(one_minus_sech(800.0), 1.0);
        assert!(rel(one_minus_sech(2.0), 1.0 - 1.0 / 2f64.cosh()) < 1e-15);
    }

    #[test]
    fn tanh_helpers_are_accurate_at_both_ends_and_agree_at_the_switch() {
        assert_eq!(tanhc(0.0), 1.0);
        assert!(rel(tanhc(2.0), 2f64.tanh() / 2.0) < 1e-15);
        assert_eq!(tanhc(1e300), 1e-300);
        // Series: 1 - tanh(z)/z = z^2/3 - 2 z^4/15 + ...
        let z = 1e-4;
        assert!(rel(one_minus_tanhc(z), z * z / 3.0 - 2.0 * z.powi(4) / 15.0) < 1e-12);
        assert_eq!(one_minus_tanhc(0.0), 0.0);
        // Against the direct form where it loses little (z = 0.099 loses about 2.5 digits).
        assert!(rel(one_minus_tanhc(0.099), 1.0 - 0.099f64.tanh() / 0.099) < 1e-12);
        assert!(rel(one_minus_tanhc(0.1 - 1e-15), one_minus_tanhc(0.1)) < 1e-12);
        assert_eq!(one_minus_tanhc(1e300), 1.0);
        assert!(rel(sech(3.0), 1.0 / 3f64.cosh()) < 1e-15);
        assert_eq!(sech(0.0), 1.0);
        assert_eq!(sech(1e4), 0.0);
    }
}
