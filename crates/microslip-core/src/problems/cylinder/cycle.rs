//! The Hertzian cylinder under a tangential load cycling between +Q_a and -Q_a: the hysteresis
//! loop of the rigid shift delta, the energy dissipated per cycle, for plain Coulomb in closed
//! form (Mindlin-Deresiewicz, plane strain, docs/theory.md (HC8)-(HC9)) and for any law whose
//! first-loading curve is given, by Masing's rule (HC7), which holds for the regularized law too.
//!
//! With delta_v the first-loading curve, extended as an odd function:
//!
//! ```text
//! unloading from +Q_a:  delta(Q) = delta_a - 2 delta_v((Q_a - Q) / 2)
//! reloading from -Q_a:  delta(Q) = -delta_a + 2 delta_v((Q_a + Q) / 2)
//! D = 8 [Q_a delta_a / 2 - integral_0^Q_a delta_v dQ]                       (HC7)
//! ```
//!
//! delta is measured with the log kernel's distances against the contact half-width a (HC5): in
//! plane strain the shift of a half-plane is defined only up to a term C Q, C set by the bodies'
//! size. That term is single valued in Q and does no work over a closed cycle: the loop's area
//! and D do not depend on it; the peak energy and the secant stiffness do, and are given for this
//! convention.

pub use crate::problems::load_driven::MasingCycle;

/// The first-loading shift of Mindlin's cylinder, normalized by 2 mu P / (pi E*) (HC8):
/// delta_v / (2 mu P / (pi E*)) = phi (ln 2 + 1/2) + (1 - phi) ln(1 - phi) / 2, phi = Q / (mu P),
/// odd in phi; 1/2 ln 2 + 1/4 + ... at |phi| = 1, where the whole contact slides.
pub fn mindlin_shift_ratio(phi: f64) -> f64 {
    let x = phi.abs().min(1.0);
    let u = 1.0 - x;
    let curved = if u > 0.0 { 0.5 * u * u.ln() } else { 0.0 };
    ((2.0_f64.ln() + 0.5) * x + curved).copysign(phi)
}

/// Mindlin-Deresiewicz's dissipation per cycle of the cylinder, normalized by 2 (mu P)^2 / (pi
/// E*) (HC9): 1 - u^2 + 2 u ln u with u = 1 - Q_a / (mu P); phi_a^3 / 3 for small amplitudes, 1
/// at gross slip.
pub fn mindlin_dissipation_ratio(phi: f64) -> f64 {
    let u = 1.0 - phi.abs().min(1.0);
    let log = if u > 0.0 { 2.0 * u * u.ln() } else { 0.0 };
    1.0 - u * u + log
}

/// One cycle of Mindlin's cylinder (plain Coulomb) of amplitude Q_a: what it needs is mu P and
/// E* (the answer does not depend on R, (HC8)-(HC9)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MindlinCycle {
    /// mu P (N/mm).
    gross: f64,
    /// E* = E / (2 (1 - nu^2)) (MPa).
    contact_modulus: f64,
    /// Q_a (N/mm), within [0, mu P].
    amplitude: f64,
}

impl MindlinCycle {
    /// The cycle between +`amplitude` and -`amplitude` (N/mm, taken within [0, mu P]) of a
    /// contact of gross-slip load `gross` = mu P (N/mm) and contact modulus `contact_modulus` =
    /// E* (MPa), both positive.
    pub fn new(gross: f64, contact_modulus: f64, amplitude: f64) -> MindlinCycle {
        MindlinCycle {
            gross,
            contact_modulus,
            amplitude: amplitude.abs().min(gross),
        }
    }

    /// The shift scale 2 mu P / (pi E*) (mm) = mu p0 a / E* = mu a^2 / (2 R).
    pub fn shift_scale(&self) -> f64 {
        2.0 * self.gross / (std::f64::consts::PI * self.contact_modulus)
    }
}

impl MasingCycle for MindlinCycle {
    fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Slip starts at the contact edges with the first newton under plain Coulomb.
    fn onset(&self) -> f64 {
        0.0
    }

    /// delta_v(Q) (mm), (HC8).
    fn virgin(&self, force: f64) -> f64 {
        self.shift_scale() * mindlin_shift_ratio(force / self.gross)
    }

    fn peak_response(&self) -> f64 {
        self.virgin(self.amplitude)
    }

    /// (HC9): 2 (mu P)^2 / (pi E*) (1 - u^2 + 2 u ln u), N mm per mm of cylinder.
    fn dissipation(&self) -> f64 {
        self.gross * self.shift_scale() * mindlin_dissipation_ratio(self.amplitude / self.gross)
    }

    /// Q_a delta_a / 2 (N mm per mm), with delta's convention (module docs).
    fn peak_energy(&self) -> f64 {
        0.5 * self.amplitude * self.peak_response()
    }

    /// Q_a / delta_a (N/mm per mm), with delta's convention (module docs); at zero amplitude
    /// the bonded contact's mu P / (scale ln 2).
    fn secant_stiffness(&self) -> f64 {
        let delta = self.peak_response();
        if delta > 0.0 {
            self.amplitude / delta
        } else {
            self.gross / (self.shift_scale() * 2.0_f64.ln())
        }
    }
}

/// D from a first-loading curve by Masing's rule (HC7): 8 [Q_a delta_v(Q_a) / 2 - integral_0^Q_a
/// delta_v dQ], the integral by Simpson's rule on `intervals` (even) intervals. `virgin` gives
/// delta_v (mm) at a load (N/mm); the result is N mm per mm. A term of delta_v linear in Q (the
/// log kernel's undetermined constant) cancels exactly.
pub fn masing_dissipation(virgin: impl Fn(f64) -> f64, amplitude: f64, intervals: usize) -> f64 {
    let n = intervals.max(2).next_multiple_of(2);
    let h = amplitude / n as f64;
    let mut sum = virgin(0.0) + virgin(amplitude);
    for i in 1..n {
        let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += weight * virgin(i as f64 * h);
    }
    8.0 * (0.5 * amplitude * virgin(amplitude) - sum * h / 3.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// (HC8) against a direct quadrature of delta = -(2 / pi) integral q(xi) ln|xi| d xi with
    /// Mindlin's traction q = sqrt(1 - xi^2) - sqrt(k - xi^2) (the stick condition at x = 0),
    /// midpoint rule on a fine grid: the closed form's ln 2 + 1/2 and its (1 - phi) ln(1 - phi) /
    /// 2. Planted fault caught: ln 2 + 1/2 written ln 2 (5e-1 off).
    #[test]
    fn the_shift_is_the_log_kernel_of_mindlin_s_traction() {
        for phi in [0.1, 0.5, 0.9] {
            let k: f64 = 1.0 - phi;
            let n = 400_000;
            let h = 1.0 / n as f64;
            let integral: f64 = (0..n)
                .map(|i| {
                    let x = (i as f64 + 0.5) * h;
                    let q = (1.0 - x * x).sqrt() - (k - x * x).max(0.0).sqrt();
                    2.0 * q * x.ln() * h
                })
                .sum();
            let direct = -2.0 / PI * integral;
            let closed = mindlin_shift_ratio(phi);
            assert!(
                (direct - closed).abs() < 1e-5 * closed,
                "{phi}: {direct} vs {closed}"
            );
        }
        assert_eq!(mindlin_shift_ratio(-0.5), -mindlin_shift_ratio(0.5));
    }

    /// (HC9) is Masing's (HC7) applied to (HC8), by quadrature; phi^3 / 3 for small amplitudes
    /// (D -> 0 as Q_a^3, the Coulomb power), 1 at gross slip; D > 0 and increasing.
    #[test]
    fn dissipation_is_masing_s_rule_on_the_shift() {
        let cycle = |phi: f64| MindlinCycle::new(500.0, 1e5, 500.0 * phi);
        let mut last = 0.0;
        for phi in [0.01, 0.1, 0.3, 0.6, 0.9, 0.999] {
            let c = cycle(phi);
            let masing = masing_dissipation(|q| c.virgin(q), c.amplitude(), 20_000);
            let d = c.dissipation();
            assert!(((masing - d) / d).abs() < 1e-6, "{phi}: {masing} vs {d}");
            assert!(d > last, "{phi}");
            last = d;
        }
        let small = mindlin_dissipation_ratio(1e-3);
        assert!((small / (1e-9 / 3.0) - 1.0).abs() < 2e-3, "{small}");
        assert_eq!(mindlin_dissipation_ratio(1.0), 1.0);
        // A linear term added to the virgin curve (the kernel's constant) changes nothing.
        let c = cycle(0.6);
        let shifted = masing_dissipation(|q| c.virgin(q) + 3.0 * q, c.amplitude(), 20_000);
        assert!(((shifted - c.dissipation()) / c.dissipation()).abs() < 1e-6);
        // The loop closes and the branches meet the peaks.
        assert!((c.unloading(c.amplitude()) - c.peak_response()).abs() < 1e-15);
        assert!((c.reloading(c.amplitude()) - c.peak_response()).abs() < 1e-15);
        assert!((c.unloading(-c.amplitude()) + c.peak_response()).abs() < 1e-15);
    }
}
