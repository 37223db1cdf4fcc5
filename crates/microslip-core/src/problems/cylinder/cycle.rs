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

use std::f64::consts::PI;

use super::closed_form::{Cylinder, TangentialLoad};
use crate::kernel::regime::Law;
pub use crate::problems::load_driven::MasingCycle;

/// The first-loading shift of Mindlin's cylinder, normalized by 2 mu P / (pi E*) (HC8):
/// delta_v / (2 mu P / (pi E*)) = phi (ln 2 + 1/2) + (1 - phi) ln(1 - phi) / 2, phi = Q / (mu P),
/// odd in phi; 1/2 ln 2 + 1/4 + ... at |phi| = 1, where the whole contact slides. The log is
/// ln_1p(-phi): ln(1 - phi) of a rounded 1 - phi is 0 below phi ~ 1e-16, which left phi (ln 2 +
/// 1/2) where the shift is phi ln 2 (HC8a).
pub fn mindlin_shift_ratio(phi: f64) -> f64 {
    let x = phi.abs().min(1.0);
    let u = 1.0 - x;
    let curved = if u > 0.0 { 0.5 * u * (-x).ln_1p() } else { 0.0 };
    ((2.0_f64.ln() + 0.5) * x + curved).copysign(phi)
}

/// Below this amplitude (HC9) is summed as its series (HC9a): the closed form 1 - u^2 + 2 u ln u
/// cancels its O(phi) terms and keeps phi^3 / 3 only to 1e-16 / phi^3 of itself (wrong in every
/// digit below phi ~ 1e-5).
const DISSIPATION_SERIES_BELOW: f64 = 0.1;

/// Mindlin-Deresiewicz's dissipation per cycle of the cylinder, normalized by 2 (mu P)^2 / (pi
/// E*) (HC9): 1 - u^2 + 2 u ln u with u = 1 - Q_a / (mu P); phi_a^3 / 3 for small amplitudes, 1
/// at gross slip. Below `DISSIPATION_SERIES_BELOW` by its series (HC9a), 2 sum_{k >= 3}
/// phi^k / (k (k - 1)), whose terms are positive: full relative precision at any amplitude.
pub fn mindlin_dissipation_ratio(phi: f64) -> f64 {
    let x = phi.abs().min(1.0);
    if x < DISSIPATION_SERIES_BELOW {
        let mut power = x * x * x;
        let mut sum = 0.0;
        // Terms fall by at least 10 each: 17 of them reach 1e-17 of the first.
        for k in 3..20 {
            sum += power / (k * (k - 1)) as f64;
            power *= x;
        }
        return 2.0 * sum;
    }
    let u = 1.0 - x;
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
    let integral = amplitude * simpson(|t| virgin(t * amplitude), intervals);
    8.0 * (0.5 * amplitude * virgin(amplitude) - integral)
}

/// Composite Simpson's rule of `f` over [0, 1] on `intervals` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, intervals: usize) -> f64 {
    let n = intervals.max(2).next_multiple_of(2);
    let h = 1.0 / n as f64;
    let mut sum = f(0.0) + f(1.0);
    for i in 1..n {
        let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += weight * f(i as f64 * h);
    }
    sum * h / 3.0
}

/// int_from^to f(x) dx with x = from + (to - from) sin^4 theta, theta in [0, pi / 2], by Simpson's
/// rule on [`PROFILE_INTERVALS`] intervals: a log or a power 1/2 or 3/2 at either end (the log
/// kernel at 0, the square roots of p and of the stick shear, the slip's (x - c)^(3/2)) becomes
/// smooth in theta.
fn mapped(from: f64, to: f64, f: impl Fn(f64) -> f64) -> f64 {
    let width = to - from;
    simpson(
        |t| {
            let theta = 0.5 * PI * t;
            let (sin, cos) = theta.sin_cos();
            let jacobian = 0.5 * PI * width * 4.0 * sin.powi(3) * cos;
            if jacobian > 0.0 {
                f(from + width * sin.powi(4)) * jacobian
            } else {
                0.0
            }
        },
        PROFILE_INTERVALS,
    )
}

/// Intervals of the quadratures over one state's profiles, each split at the zone's edge c and
/// mapped so that the integrand is smooth on each piece: 200 (D to 1e-7, the shift to 1e-6 of
/// Mindlin's closed forms).
const PROFILE_INTERVALS: usize = 200;

/// The rigid shift delta (mm) of a state with shear `shear` (MPa, at x in mm, even in x), zone
/// edge `zone` = c (mm) and centre slip `centre_slip` (mm), with distances against a (HC2),
/// (HC5): delta = s(0) - (2 / (pi E*)) int q(xi) ln|xi / a| d xi. On [0, c] with xi = c sin^4
/// theta and on [c, a] ([`mapped`]), the log at 0, the kink at c and the square roots at c and a
/// all become smooth enough for Simpson's rule.
fn shift_of(cylinder: &Cylinder, zone: f64, centre_slip: f64, shear: impl Fn(f64) -> f64) -> f64 {
    let a = cylinder.half_width();
    let piece = |from: f64, to: f64| mapped(from, to, |xi| shear(xi) * (xi / a).ln());
    let half = piece(0.0, zone) + piece(zone, a);
    // Both halves of the even shear.
    centre_slip - 2.0 / (PI * cylinder.contact_modulus()) * 2.0 * half
}

/// One cycle of amplitude Q_a for one law, from the closed-form (Coulomb) or semi-analytic
/// (regularized) first-loading solution and Masing's rule (HC7): the branches of the edge slip
/// s(a) (the problem's response), the shift's loop ([`CylinderCycle::shift`], whose area is D),
/// D itself, and the peak energy and secant stiffness of the shift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderCycle {
    cylinder: Cylinder,
    law: Law,
    /// Q_a (N/mm).
    amplitude: f64,
}

impl CylinderCycle {
    /// The cycle between +`amplitude` and -`amplitude` under `law`.
    pub fn new(cylinder: &Cylinder, law: Law, amplitude: TangentialLoad) -> CylinderCycle {
        CylinderCycle {
            cylinder: *cylinder,
            law,
            amplitude: amplitude.newtons_per_mm(),
        }
    }

    fn mindlin(&self) -> MindlinCycle {
        MindlinCycle::new(
            self.cylinder.gross_slip_load(),
            self.cylinder.contact_modulus(),
            self.amplitude,
        )
    }

    /// The friction work of first loading to Q_a, W_1 = int mu p(x) s_p(x) dx over both slip
    /// zones (N mm per mm), s_p = s - mu p / K_T (s under Coulomb): a quarter of D (HC7 (iv)).
    /// Under Coulomb integrated on [c, a] with x = c + (a - c) sin^4 theta (smooth at both ends);
    /// under the regularized law in the angle x = a cos alpha over [0, theta] (HC9b), where mu p
    /// dx = mu p0 a sin^2 alpha dalpha: the strips are O(Q^2) wide, so [c, a] in x rounds to
    /// nothing below Q ~ 1e-8 mu P while D is still positive.
    pub fn first_loading_work(&self) -> f64 {
        let load = self.cylinder.clamped_load(self.amplitude);
        let params = self.cylinder.params();
        let a = self.cylinder.half_width();
        let one_side = match self.law {
            Law::Coulomb => {
                let state = self.cylinder.coulomb(load);
                mapped(state.stick_half_width(), a, |x| {
                    params.friction * self.cylinder.pressure_at(x) * state.slip_at(x).max(0.0)
                })
            }
            Law::Regularized => {
                let state = self.cylinder.regularized(load);
                let strength = params.friction * self.cylinder.peak_pressure();
                mapped(0.0, state.zone_angle(), |alpha| {
                    let sin = alpha.sin();
                    strength * a * sin * sin * state.strip_plastic_slip(alpha)
                })
            }
        };
        2.0 * one_side
    }

    /// The first-loading shift delta_v(Q) (mm), odd in Q, |Q| taken within [0, mu P].
    pub fn shift(&self, load: f64) -> f64 {
        let magnitude = match self.law {
            Law::Coulomb => self.mindlin().virgin(load.abs()),
            Law::Regularized => {
                let state = self
                    .cylinder
                    .regularized(self.cylinder.clamped_load(load.abs()));
                shift_of(
                    &self.cylinder,
                    state.micro_half_width(),
                    state.centre_slip(),
                    |x| state.shear_at(x),
                )
            }
        };
        magnitude.copysign(load)
    }
}

impl MasingCycle for CylinderCycle {
    fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// The contact edges slide from the first newton under both laws (p vanishes there).
    fn onset(&self) -> f64 {
        0.0
    }

    /// The edge slip on first loading s_v(a; Q) (mm), odd in Q: the problem's response (the
    /// fretting slip amplitude). Masing's rule holds for it as for every local quantity (HC7:
    /// the unloading state is the first-loading state doubled), so the generic branches are the
    /// edge slip's loop; its area is not D (the loop whose area is D is the shift's,
    /// [`CylinderCycle::shift`]).
    fn virgin(&self, force: f64) -> f64 {
        let load = self.cylinder.clamped_load(force.abs());
        let slip = match self.law {
            Law::Coulomb => self.cylinder.coulomb(load).edge_slip(),
            Law::Regularized => self.cylinder.regularized(load).edge_slip(),
        };
        slip.copysign(force)
    }

    fn peak_response(&self) -> f64 {
        self.virgin(self.amplitude)
    }

    /// D (N mm per mm): (HC9) under Coulomb, 4 W_1 under the regularized law (HC7).
    fn dissipation(&self) -> f64 {
        match self.law {
            Law::Coulomb => self.mindlin().dissipation(),
            Law::Regularized => 4.0 * self.first_loading_work(),
        }
    }

    /// Q_a delta_a / 2 (N mm per mm), the work of first loading through the rigid shift, with
    /// delta's convention (module docs): an energy, unlike Q_a s(a) / 2.
    fn peak_energy(&self) -> f64 {
        0.5 * self.amplitude * self.shift(self.amplitude)
    }

    /// Q_a / delta_a (N/mm per mm), the contact's secant tangential stiffness with delta's
    /// convention; at zero amplitude the slope at a probe of 1e-6 mu P.
    fn secant_stiffness(&self) -> f64 {
        let delta = self.shift(self.amplitude);
        if delta > 0.0 {
            return self.amplitude / delta;
        }
        let probe = 1e-6 * self.cylinder.gross_slip_load();
        probe / self.shift(probe)
    }
}

#[cfg(test)]
mod tests {
    use super::super::closed_form::CylinderParams;
    use super::*;

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

    /// (HC8a), (HC9a): at small amplitudes Mindlin's shift is phi ln 2 + phi^2 / 4 + ... and D
    /// is phi^3 / 3 + phi^4 / 6 + ..., to full relative precision down to phi = 1e-100 (the
    /// shift to 1e-300; D there is below the smallest double, 0 and never negative), and the
    /// series meets the closed form where both are accurate (phi = 0.1, 0.3). Before issue 46
    /// D at phi = 1e-6 was 5.5e-18 (not 3.3e-19) and the shift at phi = 1e-17 was phi (ln 2 +
    /// 1/2).
    #[test]
    fn small_amplitudes_keep_their_digits() {
        for phi in [1e-2_f64, 1e-6, 1e-17, 1e-100, 1e-300] {
            let d = mindlin_dissipation_ratio(phi);
            let shift = mindlin_shift_ratio(phi);
            let leading = phi * 2f64.ln() + phi * phi / 4.0;
            assert!(
                (shift / leading - 1.0).abs() < 1e-15 + phi * phi,
                "{phi}: {shift}"
            );
            if phi < 1e-103 {
                assert_eq!(d, 0.0);
                continue;
            }
            let series = phi.powi(3) / 3.0 * (1.0 + phi / 2.0);
            assert!((d / series - 1.0).abs() < 1e-5 + phi * phi, "{phi}: {d}");
        }
        // Either side of the switch, the closed form and the series agree.
        let closed = |phi: f64| {
            let u = 1.0 - phi;
            1.0 - u * u + 2.0 * u * u.ln()
        };
        let below = mindlin_dissipation_ratio(DISSIPATION_SERIES_BELOW * (1.0 - 1e-12));
        assert!(
            (below / closed(DISSIPATION_SERIES_BELOW) - 1.0).abs() < 1e-11,
            "{below}"
        );
        assert!((mindlin_dissipation_ratio(0.3) / closed(0.3) - 1.0).abs() < 1e-14);
    }

    fn pad(kt: f64) -> Cylinder {
        Cylinder::new(CylinderParams {
            tangential_stiffness: kt,
            ..CylinderParams::STEEL_PAD
        })
        .unwrap()
    }

    /// Two independent routes to Mindlin's loop meet: Masing's local form D = 4 W_1 (HC7 (iv))
    /// on the closed-form slip s(x) of the Mindlin state equals (HC9) to 1e-7, and the shift
    /// recovered from the closed-form shear by the log kernel (HC2) equals (HC8) to 1e-6 (both
    /// measured to 1e-9). Planted faults caught: D = 2 W_1; the kernel's factor 2 / (pi E*)
    /// written 1 / (pi E*) in `shift_of`.
    #[test]
    fn mindlin_s_loop_two_ways() {
        let cylinder = pad(1e5);
        for phi in [0.05, 0.5, 0.9] {
            let load = cylinder.load(phi * cylinder.gross_slip_load()).unwrap();
            let cycle = CylinderCycle::new(&cylinder, Law::Coulomb, load);
            let local = 4.0 * cycle.first_loading_work();
            let d = cycle.dissipation();
            assert!(((local - d) / d).abs() < 1e-7, "{phi}: {local} vs {d}");
            let state = cylinder.coulomb(load);
            let shift = shift_of(
                &cylinder,
                state.stick_half_width(),
                state.centre_slip(),
                |x| state.shear_at(x),
            );
            let closed = cycle.shift(load.newtons_per_mm());
            assert!(
                ((shift - closed) / closed).abs() < 1e-6,
                "{phi}: {shift} vs {closed}"
            );
            assert_eq!(cycle.peak_response(), state.edge_slip());
        }
    }

    /// The regularized law's D (4 W_1 on the semi-analytic solution): D > 0, increasing in Q_a,
    /// and vanishing as Q_a^4 (the edge layers of width ~ phi^2, (HC9)'s last paragraph): the
    /// local exponent between 0.01 and 0.02 mu P is 4 within 0.01 (measured 4.000) at kappa =
    /// 0.64, where Coulomb's is 3. Planted fault caught: W_1 done against mu p0 instead of mu
    /// p(x) (the edge layers' shear ~ phi lost: the exponent falls to 3).
    #[test]
    fn regularized_dissipation_vanishes_as_the_fourth_power() {
        let cylinder = pad(1e5);
        let d = |phi: f64| {
            let load = cylinder.load(phi * cylinder.gross_slip_load()).unwrap();
            CylinderCycle::new(&cylinder, Law::Regularized, load).dissipation()
        };
        let (small, double, large) = (d(0.01), d(0.02), d(0.6));
        assert!(0.0 < small && small < double && double < large);
        let exponent = (double / small).log2();
        assert!((exponent - 4.0).abs() < 0.01, "{exponent}");
        // The edge layers' width goes as phi^2 (measured exponent 1.999).
        let width = |phi: f64| {
            let load = cylinder.load(phi * cylinder.gross_slip_load()).unwrap();
            cylinder.regularized(load).edge_slide_width()
        };
        let growth = (width(0.02) / width(0.01)).log2();
        assert!((growth - 2.0).abs() < 0.01, "{growth}");
    }

    /// (HC9b): at small amplitudes the regularized D comes from the sliding strips alone (the
    /// elastic rest dissipates nothing): with s_p = (sin theta - sin alpha) mu p0 / K_T across a
    /// strip at leading order, D -> (2/3) (mu p0 a)^2 theta^4 / (E* kappa), theta = arccos(c / a),
    /// a fourth power of Q_a. Checked to 1e-3 at Q_a = 1e-4 and 1e-9 mu P at kappa = 0.64 and 64,
    /// with D > 0, the damping ratio finite, and the secant stiffness Q_a / delta_a the same at
    /// both (the contact is linear there). Before issue 46, D was 0 below 1e-8 mu P, the damping
    /// ratio reached 1e263, and the secant stiffness fell a hundredfold.
    #[test]
    fn the_regularized_cycle_at_small_amplitudes() {
        for kt in [1e5, 1e7] {
            let cylinder = pad(kt);
            let gross = cylinder.gross_slip_load();
            let strength = cylinder.params().friction * cylinder.peak_pressure();
            let kappa = cylinder.stiffness_group();
            let mut secant = Vec::new();
            for phi in [1e-4, 1e-9] {
                let load = cylinder.load(phi * gross).unwrap();
                let cycle = CylinderCycle::new(&cylinder, Law::Regularized, load);
                let theta = cylinder.regularized(load).zone_angle();
                let leading =
                    2.0 / 3.0 * (strength * cylinder.half_width()).powi(2) * theta.powi(4)
                        / (cylinder.contact_modulus() * kappa);
                let d = cycle.dissipation();
                assert!(
                    d > 0.0 && (d / leading - 1.0).abs() < 1e-3,
                    "{kt} {phi}: {d} {leading}"
                );
                let zeta = cycle.damping_ratio();
                assert!(zeta.is_finite() && zeta > 0.0, "{kt} {phi}: {zeta}");
                secant.push(cycle.secant_stiffness());
            }
            assert!(
                (secant[1] / secant[0] - 1.0).abs() < 1e-6,
                "{kt}: {secant:?}"
            );
        }
    }

    /// K_T -> infinity: the regularized cycle is Mindlin-Deresiewicz's (D and delta_a within
    /// 1e-5 at K_T = 1e12 MPa/mm).
    #[test]
    fn the_regularized_cycle_tends_to_mindlin_deresiewicz() {
        let cylinder = pad(1e12);
        let load = cylinder.load(0.6 * cylinder.gross_slip_load()).unwrap();
        let regularized = CylinderCycle::new(&cylinder, Law::Regularized, load);
        let coulomb = CylinderCycle::new(&cylinder, Law::Coulomb, load);
        let close = |x: f64, y: f64| ((x - y) / y).abs() < 1e-5;
        assert!(close(regularized.dissipation(), coulomb.dissipation()));
        assert!(close(regularized.peak_response(), coulomb.peak_response()));
        let q = load.newtons_per_mm();
        assert!(close(regularized.shift(q), coulomb.shift(q)));
        assert!(close(regularized.peak_energy(), coulomb.peak_energy()));
    }
}
