//! The clamped double-lap joint under a force F (docs/theory.md section 9, (L1)-(L9)).
//!
//! An inner plate (t1, E1) between two identical covers (t2, E2 each), width b, overlap L, clamped
//! at pressure P on both interfaces. x = 0 is the inner plate's free end inside the overlap (the
//! covers carry the whole force there), x = L the covers' free ends (the inner plate carries it).
//! Each plate is a bar with uniform axial strain through its thickness (the shear-lag
//! assumption), so the interface slip s = u_inner - u_cover obeys s'' = 2 c tau with
//! c = 1/k1 + 1/K2, k1 = E1 t1, K2 = 2 E2 t2 (L1).
//!
//! Every regime of both laws is one shape: a sliding zone of length `a` from x = 0 and one of
//! length `d` from x = L (either may be empty), where tau = mu P and the slip is a parabola, and
//! between them a zone that sticks (Coulomb) or deforms elastically (regularized law) with slopes
//! `p` at its start and `q` at its end (s'(a) = -p, s'(L - d) = q).

pub use super::params::LapParams;
use crate::kernel::hyperbolic::{cosh_sinh_ratio, one_minus_tanhc, sech, tanhc};
use crate::kernel::params::{Domain, ParamError};
use crate::kernel::regime::{Law, Regime, Zone};
use crate::kernel::solve::{find_root_in_bracket, find_root_newton};
use crate::problems::Solution;
use crate::problems::lap::params::LapParam;

/// A validated double-lap joint with its load-independent constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapJoint {
    params: LapParams,
    /// k1 = E1 t1 (N/mm): the inner plate's axial stiffness per unit width.
    k1: f64,
    /// K2 = 2 E2 t2 (N/mm): both covers' axial stiffness per unit width.
    k2: f64,
    /// c = 1/k1 + 1/K2 (mm/N).
    c: f64,
    /// lambda = sqrt(2 c K_T) (1/mm): inverse length of the elastic slip's decay (L2).
    lambda: f64,
    /// F_1 and F_2 (N), (L3) and (L4'): load-independent, so solved once here rather than at
    /// every force (F_2 is a root).
    slip_forces: (f64, f64),
    /// The elastic length at F_2 (mm): with L at F_1, where (L4)'s root starts from.
    second_elastic: f64,
}

/// A validated force through the joint, 0 <= F <= F_gross (N).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct JointForce(f64);

impl JointForce {
    /// The force in N.
    pub fn newtons(self) -> f64 {
        self.0
    }
}

/// Where sliding starts as the force grows (L2): the end where the more compliant member carries
/// the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FirstSlip {
    /// x = 0, the inner plate's free end: the covers are more compliant (k1 > K2).
    InnerEnd,
    /// x = L, the covers' free ends: the inner plate is more compliant (k1 < K2).
    CoverEnds,
    /// Both ends at once: a balanced joint (k1 = K2).
    BothEnds,
}

impl FirstSlip {
    /// Where, in words, for reports.
    pub fn label(self) -> &'static str {
        match self {
            FirstSlip::InnerEnd => "x = 0 (inner plate's end)",
            FirstSlip::CoverEnds => "x = L (covers' ends)",
            FirstSlip::BothEnds => "both ends at once (balanced joint)",
        }
    }

    /// The key in JSON and CSV.
    pub fn key(self) -> &'static str {
        match self {
            FirstSlip::InnerEnd => "x=0",
            FirstSlip::CoverEnds => "x=L",
            FirstSlip::BothEnds => "both",
        }
    }
}

impl LapJoint {
    /// Validates every input against its domain ([`LapParam::spec`]).
    ///
    /// # Errors
    /// The first input out of its domain, in display order.
    ///
    /// # Examples
    /// ```
    /// use microslip_core::problems::lap::closed_form::{LapJoint, LapParams};
    /// let joint = LapJoint::new(LapParams::ALUMINIUM)?;
    /// assert_eq!(joint.gross_slip_force(), 6000.0); // 2 b mu P L, N
    /// let state = joint.regularized(joint.force(3000.0)?);
    /// assert!(state.joint_displacement() > 0.0);
    /// assert_eq!(
    ///     joint.force(7000.0).unwrap_err().to_string(),
    ///     "invalid F = 7000: must be in [0, 6000] N (F_gross = 2 b mu P L: \
    ///      the joint slides through beyond it)"
    /// );
    /// # Ok::<(), microslip_core::ParamError>(())
    /// ```
    pub fn new(params: LapParams) -> Result<Self, ParamError> {
        params.check()?;
        let k1 = params.inner_stiffness();
        let k2 = params.covers_stiffness();
        let c = 1.0 / k1 + 1.0 / k2;
        let lambda = (2.0 * c * params.tangential_stiffness).sqrt();
        let mut joint = LapJoint {
            params,
            k1,
            k2,
            c,
            lambda,
            slip_forces: (0.0, 0.0),
            second_elastic: 0.0,
        };
        let (second, elastic) = joint.solve_second_slip_force();
        joint.slip_forces = (joint.solve_first_slip_force(), second);
        joint.second_elastic = elastic;
        Ok(joint)
    }

    /// The inputs this joint was built from.
    pub fn params(&self) -> LapParams {
        self.params
    }

    /// The same joint with another K_T (MPa/mm); validated like [`LapJoint::new`].
    ///
    /// # Errors
    /// [`ParamError`] when `kt` is outside the K_T domain.
    pub fn with_tangential_stiffness(&self, kt: f64) -> Result<Self, ParamError> {
        LapJoint::new(LapParams {
            tangential_stiffness: kt,
            ..self.params
        })
    }

    /// Accepts a force through this joint: in the force domain and at most F_gross, beyond which
    /// no static state exists (the joint slides through, (L6)).
    ///
    /// # Errors
    /// [`ParamError`] naming F, its value and the range [0, F_gross].
    pub fn force(&self, newtons: f64) -> Result<JointForce, ParamError> {
        let newtons = LapParam::Force.check(newtons)?;
        let gross = self.gross_slip_force();
        if newtons > gross {
            let spec = LapParam::Force.spec();
            return Err(ParamError {
                field: spec.name,
                value: newtons,
                domain: Domain::NonNegative { max: gross },
                unit: spec.unit,
                reason: None,
            }
            .because("F_gross = 2 b mu P L: the joint slides through beyond it"));
        }
        Ok(JointForce(newtons))
    }

    /// The accepted force nearest to `newtons` (N): 0 for negative values and NaN, F_gross above
    /// it.
    pub fn clamped_force(&self, newtons: f64) -> JointForce {
        let newtons = if newtons.is_nan() { 0.0 } else { newtons };
        JointForce(newtons.clamp(0.0, self.gross_slip_force()))
    }

    /// The K_T (MPa/mm) at which this joint's regularized Delta at `force` equals
    /// `joint_displacement` (mm), all else as in this joint: what an FE result of Delta says about
    /// the stiffness its code really used. Delta falls with K_T at every force (L11), from large
    /// values at the softest accepted K_T to nearly Coulomb's at the stiffest, so there is at most
    /// one answer; `None` when no K_T in the accepted domain gives it.
    pub fn stiffness_for_joint_displacement(
        &self,
        force: JointForce,
        joint_displacement: f64,
    ) -> Option<f64> {
        // K_T = min e^k, k in [0, ln(max / min)]: the root finder's bracket starts at 0.
        let min = Domain::STIFFNESS.min();
        let at = |k: f64| {
            self.with_tangential_stiffness(min * k.exp())
                .map(|j| j.regularized(force).joint_displacement())
        };
        let span = (Domain::STIFFNESS.max() / min).ln();
        let (soft, stiff) = (at(0.0).ok()?, at(span).ok()?);
        if !(joint_displacement > 0.0 && (stiff..=soft).contains(&joint_displacement)) {
            return None;
        }
        // Relative misfit, so that the root finder sees numbers near 1 whatever the scale.
        let k = find_root_in_bracket(
            |k| at(k).map_or(f64::NAN, |d| d / joint_displacement - 1.0),
            0.0,
            span,
        );
        Some(min * k.exp())
    }

    /// lambda = sqrt(2 c K_T) (1/mm), (L2): 1/lambda is the length over which the elastic slip
    /// decays from a loaded end.
    pub fn decay_rate(&self) -> f64 {
        self.lambda
    }

    /// Coulomb stress mu P (MPa).
    pub fn coulomb_stress(&self) -> f64 {
        self.params.friction * self.params.pressure
    }

    /// Saturation slip mu P / K_T (mm).
    pub fn saturation_slip(&self) -> f64 {
        self.coulomb_stress() / self.params.tangential_stiffness
    }

    /// F_gross = 2 b mu P L (N), (L6).
    pub fn gross_slip_force(&self) -> f64 {
        self.params.gross_slip_force()
    }

    /// The bonded joint's compliance L / (b (k1 + K2)) (mm/N), (L6): both members strained alike,
    /// what remains of Delta / F when nothing slips.
    pub fn bonded_compliance(&self) -> f64 {
        self.params.length / (self.params.width * (self.k1 + self.k2))
    }

    /// Which end slides first (L2).
    pub fn first_slip(&self) -> FirstSlip {
        if self.k1 < self.k2 {
            FirstSlip::CoverEnds
        } else if self.k1 > self.k2 {
            FirstSlip::InnerEnd
        } else {
            FirstSlip::BothEnds
        }
    }

    /// (L3): the force F_1 at which sliding first appears, at [`LapJoint::first_slip`]:
    /// 2 c mu P b L tanhc(lambda L) / (1/k_s + sech(lambda L)/k_o), k_s the stiffness of the
    /// member loaded at the sliding end (the more compliant one).
    pub fn first_slip_force(&self) -> f64 {
        self.slip_forces.0
    }

    fn solve_first_slip_force(&self) -> f64 {
        let (soft, stiff) = (self.k1.min(self.k2), self.k1.max(self.k2));
        let z = self.lambda * self.params.length;
        2.0 * self.c * self.coulomb_stress() * self.params.width * self.params.length * tanhc(z)
            / (1.0 / soft + sech(z) / stiff)
    }

    /// (L4'): the force F_2 at which the other end starts sliding too (F_1 for a balanced joint):
    /// with the elastic zone l solving l + (l/2) tanhc(lambda l/2) (k_o - k_s)/k_s = L,
    /// F_2 = b k_o c mu P l tanhc(lambda l/2).
    pub fn second_slip_force(&self) -> f64 {
        self.slip_forces.1
    }

    /// F_2 (N) and the elastic length there (mm).
    fn solve_second_slip_force(&self) -> (f64, f64) {
        let (soft, stiff) = (self.k1.min(self.k2), self.k1.max(self.k2));
        let lambda = self.lambda;
        let length = self.params.length;
        let excess = (stiff - soft) / soft;
        let elastic = find_root_in_bracket(
            |l| l + 0.5 * l * tanhc(0.5 * lambda * l) * excess - length,
            0.0,
            length,
        );
        let force = self.params.width
            * stiff
            * self.c
            * self.coulomb_stress()
            * elastic
            * tanhc(0.5 * lambda * elastic);
        // F_2 <= F_gross = 2 b mu P L exactly (F_2 tends to it as one member's stiffness or
        // lambda L tends to 0), but the product above rounds: a member a hundred million times
        // the other's stiffness gave F_2 = 6000.000000000001 N over F_gross = 6000 N. A joint
        // whose second end slides after the whole interface does is no joint: clamp.
        (force.min(self.params.gross_slip_force()), elastic)
    }

    /// The slopes of the slip at the two ends that the force sets (L1), in units of 2 c mu P, so
    /// lengths: G0 = g0 / (2 c mu P) at x = 0 and GL = gL / (2 c mu P) at x = L, with
    /// G0 + GL = L F / F_gross.
    fn end_slope_lengths(&self, force: f64) -> (f64, f64) {
        let per_width = force / (self.params.width * 2.0 * self.c * self.coulomb_stress());
        (per_width / self.k2, per_width / self.k1)
    }

    /// Solution under plain Coulomb at `force` (L7): sliding zones a = G0 and d = GL, the rest
    /// sticks and carries no shear.
    pub fn coulomb(&self, force: JointForce) -> LapState {
        let (g0, gl) = self.end_slope_lengths(force.0);
        self.state(Law::Coulomb, force.0, g0, gl)
    }

    /// Solution under the regularized law at `force`: all microslip up to F_1 (L2), one end
    /// sliding up to F_2 (L4), both beyond (L5), all sliding at F_gross (L6).
    pub fn regularized(&self, force: JointForce) -> LapState {
        let f = force.0;
        let (g0, gl) = self.end_slope_lengths(f);
        let length = self.params.length;
        let lambda = self.lambda;
        let (a, d) = if f <= self.first_slip_force() {
            (0.0, 0.0)
        } else if f < self.second_slip_force() {
            // (L4): the elastic length e from the end that still sticks; the sliding end's slope
            // length and the other's.
            let (sliding, other) = match self.first_slip() {
                FirstSlip::InnerEnd => (g0, gl),
                FirstSlip::CoverEnds | FirstSlip::BothEnds => (gl, g0),
            };
            // d/de [e (1 - tanhc(lambda e))] = tanh^2(lambda e); Newton from e interpolated
            // between L at F_1 and the elastic length at F_2, certified and bracketed (it falls
            // back to Brent's method on [0, L]).
            let (f1, f2) = self.slip_forces;
            let start = length + (self.second_elastic - length) * (f - f1) / (f2 - f1);
            let elastic = find_root_newton(
                |e| length - e * one_minus_tanhc(lambda * e) - sliding - other * sech(lambda * e),
                |e| {
                    let t = (lambda * e).tanh();
                    -t * t + other * lambda * sech(lambda * e) * t
                },
                start,
                0.0,
                length,
            );
            match self.first_slip() {
                FirstSlip::InnerEnd => (length - elastic, 0.0),
                FirstSlip::CoverEnds | FirstSlip::BothEnds => (0.0, length - elastic),
            }
        } else {
            // (L5): l (1 - tanhc(lambda l/2)) = L (1 - F/F_gross).
            let remaining = (length - g0 - gl).max(0.0);
            // phi(l) = l (1 - tanhc(lambda l/2)) grows with slope tanh^2(lambda l/2): like
            // lambda^2 l^3 / 12 for short zones, like l - 2/lambda for long ones; Newton starts
            // from the larger of the two estimates (phi is convex, so it then never overshoots
            // below the root) and is certified and bracketed.
            let start = (remaining + 2.0 / lambda)
                .max((12.0 * remaining / (lambda * lambda)).cbrt())
                .min(length);
            let elastic = find_root_newton(
                |l| l * one_minus_tanhc(0.5 * lambda * l) - remaining,
                |l| {
                    let t = (0.5 * lambda * l).tanh();
                    t * t
                },
                start,
                0.0,
                length,
            );
            let half_t = 0.5 * elastic * tanhc(0.5 * lambda * elastic);
            ((g0 - half_t).max(0.0), (gl - half_t).max(0.0))
        };
        self.state(Law::Regularized, f, g0, gl).with_zones(a, d)
    }

    /// The state with sliding zones set by `law` before [`LapState::with_zones`] (Coulomb's are
    /// final: a = G0, d = GL).
    fn state(&self, law: Law, force: f64, g0: f64, gl: f64) -> LapState {
        let state = LapState {
            joint: *self,
            law,
            force,
            g0,
            gl,
            a: 0.0,
            d: 0.0,
        };
        match law {
            Law::Coulomb => state.with_zones(g0, gl),
            Law::Regularized => state,
        }
    }
}

/// One law's solution at one force: the two sliding zones and what follows from them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapState {
    joint: LapJoint,
    law: Law,
    force: f64,
    /// End slope lengths G0 = g0/(2 c mu P), GL = gL/(2 c mu P) (mm).
    g0: f64,
    gl: f64,
    /// Sliding zone from x = 0 (mm).
    a: f64,
    /// Sliding zone from x = L (mm).
    d: f64,
}

impl LapState {
    fn with_zones(self, a: f64, d: f64) -> LapState {
        let length = self.joint.params.length;
        let a = a.clamp(0.0, length);
        LapState {
            a,
            d: d.clamp(0.0, length - a),
            ..self
        }
    }

    /// The law this state is solved under.
    pub fn law(&self) -> Law {
        self.law
    }

    /// The force through the joint (N).
    pub fn force(&self) -> f64 {
        self.force
    }

    /// Length a of the sliding zone from x = 0, the inner plate's end (mm).
    pub fn slide_at_inner_end(&self) -> f64 {
        self.a
    }

    /// Length d of the sliding zone from x = L, the covers' ends (mm).
    pub fn slide_at_cover_ends(&self) -> f64 {
        self.d
    }

    /// The zone between the sliding ones, [a, L - d]: elastic (regularized) or stuck (Coulomb).
    pub fn middle_zone(&self) -> (f64, f64) {
        (self.a, self.joint.params.length - self.d)
    }

    /// The slip at the ends of the sliding zones (mm): mu P / K_T under the regularized law, 0
    /// under Coulomb.
    fn zone_edge_slip(&self) -> f64 {
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => self.joint.saturation_slip(),
        }
    }

    /// The slopes p = -s'(a) and q = s'(L - d) of the slip at the middle zone's ends, in units
    /// of 2 c mu P (lengths): G0 - a and GL - d, since s' changes by 2 c mu P per mm of sliding
    /// zone (L5).
    fn middle_slope_lengths(&self) -> (f64, f64) {
        ((self.g0 - self.a).max(0.0), (self.gl - self.d).max(0.0))
    }

    /// The slip s(x) = u_inner - u_cover (mm) at `x` (clamped to [0, L]), (L4)-(L7): in a sliding
    /// zone edge + u (p + c mu P u) with u the distance into it from the middle zone; in the
    /// middle zone the elastic profile [q cosh(lambda (x - a)) + p cosh(lambda (L - d - x))] /
    /// (lambda sinh(lambda l)) (regularized), or 0 (Coulomb: it sticks).
    pub fn slip_at(&self, x: f64) -> f64 {
        let joint = &self.joint;
        let x = x.clamp(0.0, joint.params.length);
        let (start, end) = self.middle_zone();
        let two_c_mu_p = 2.0 * joint.c * joint.coulomb_stress();
        let (p, q) = self.middle_slope_lengths();
        let edge = self.zone_edge_slip();
        let parabola = |u: f64, slope: f64| edge + u * two_c_mu_p * (slope + 0.5 * u);
        if x < start {
            return parabola(start - x, p);
        }
        if x > end {
            // d - (L - x), not x - (L - d): a zone far shorter than the overlap would lose its
            // digits to L in the difference (exact at x = L).
            return parabola((self.d - (joint.params.length - x)).max(0.0), q);
        }
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => {
                let l = end - start;
                let lambda = joint.lambda;
                if l * lambda == 0.0 {
                    // F_gross, or the whole joint one point: the middle zone has shrunk to its
                    // edge value.
                    return edge;
                }
                two_c_mu_p
                    * (q * cosh_sinh_ratio(lambda * (x - start), lambda * l)
                        + p * cosh_sinh_ratio(lambda * (end - x), lambda * l))
                    / lambda
            }
        }
    }

    /// The interface shear tau(x) on the inner plate (MPa), positive resisting F: mu P in the
    /// sliding zones; K_T s in the elastic zone (regularized), 0 in the stick zone (Coulomb).
    pub fn shear_at(&self, x: f64) -> f64 {
        let mu_p = self.joint.coulomb_stress();
        let (start, end) = self.middle_zone();
        if x < start || x > end {
            return mu_p;
        }
        match self.law {
            Law::Coulomb => 0.0,
            Law::Regularized => {
                (self.joint.params.tangential_stiffness * self.slip_at(x)).min(mu_p)
            }
        }
    }

    /// The joint displacement Delta = u_inner(L) - u_cover(0) (mm), (L6):
    /// (1 - alpha) s(0) + alpha s(L) + F L / (b (k1 + K2)), alpha = K2 / (k1 + K2).
    pub fn joint_displacement(&self) -> f64 {
        let joint = &self.joint;
        let alpha = joint.k2 / (joint.k1 + joint.k2);
        (1.0 - alpha) * self.slip_at(0.0)
            + alpha * self.slip_at(joint.params.length)
            + self.force * joint.bonded_compliance()
    }

    /// The zones from x = 0 outward.
    pub fn regime(&self) -> Regime {
        if self.force == 0.0 {
            return Regime::UNLOADED;
        }
        let (start, end) = self.middle_zone();
        if end - start <= 0.0 {
            return Regime::MACROSLIP;
        }
        zones_regime(self.law, self.a, self.d, self.joint.params.length)
    }

    /// (L10): energy dissipated per cycle between +F and -F (N mm), from the friction work of
    /// Masing's loop: every point of a sliding zone slides back and forth by twice its plastic
    /// slip s_p at the turning point against mu P, on two interfaces of width b, so
    /// D = 8 b mu P sum over both zones of integral(s_p) = 8 b mu P sum (c mu P)(p u^2 + u^3/3)
    /// with u the zone's length and p its middle-zone slope length: a sum of positive terms.
    pub fn cycle_dissipation(&self) -> f64 {
        let joint = &self.joint;
        let mu_p = joint.coulomb_stress();
        let (p, q) = self.middle_slope_lengths();
        let zone = |u: f64, slope: f64| u * u * (slope + u / 3.0);
        8.0 * joint.params.width * mu_p * joint.c * mu_p * (zone(self.a, p) + zone(self.d, q))
    }
}

/// The regime of a loaded joint whose sliding zones from x = 0 and from x = L are `a` and `d` (mm)
/// over an overlap `length`: shared by the closed forms and the reader of FE slip profiles, so
/// that both name the same zones the same way.
pub fn zones_regime(law: Law, a: f64, d: f64, length: f64) -> Regime {
    if a + d >= length {
        return Regime::MACROSLIP;
    }
    let middle = match law {
        Law::Coulomb => Zone::Stick,
        Law::Regularized => Zone::Microslip,
    };
    match (a > 0.0, d > 0.0) {
        (true, true) => Regime::from_zones(&[Zone::Macroslip, middle, Zone::Macroslip]),
        (false, true) => Regime::from_zones(&[middle, Zone::Macroslip]),
        (true, false) => Regime::from_zones(&[Zone::Macroslip, middle]),
        (false, false) => Regime::from_zones(&[middle]),
    }
}

impl Solution for LapState {
    fn response(&self) -> f64 {
        self.joint_displacement()
    }

    fn regime(&self) -> Regime {
        LapState::regime(self)
    }

    /// The end of the middle (elastic or stuck) zone from x = 0, L - d.
    fn zone_end(&self) -> f64 {
        self.middle_zone().1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 36 (20): F_2 never above F_gross, where they are equal but for rounding (covers
    /// 1e-4 MPa against a 70 GPa inner plate, K_T = 1e-6 MPa/mm: F_2 was 6000.000000000001 N).
    #[test]
    fn the_second_slip_force_never_exceeds_the_gross_slip_force() {
        for (modulus, kt) in [(1e-4, 1e-6), (1e-4, 1e3), (1e7, 1e-6)] {
            let joint = LapJoint::new(LapParams {
                cover_modulus: modulus,
                tangential_stiffness: kt,
                ..LapParams::ALUMINIUM
            })
            .unwrap();
            assert!(
                joint.second_slip_force() <= joint.gross_slip_force(),
                "E2 {modulus} K_T {kt}: F_2 {} F_gross {}",
                joint.second_slip_force(),
                joint.gross_slip_force()
            );
            assert!(joint.first_slip_force() <= joint.gross_slip_force());
        }
    }

    /// The joints of the derivation's independent check (docs/theory.md section 9): b 20, L 40,
    /// P 10, mu 0.3, all E 70000 but `e2`; values computed by a separate Python implementation of
    /// (L2)-(L6) and confirmed by its discretized model to 1e-6 (/work/tmp/lapcheck, out_A-E).
    fn joint(t1: f64, t2: f64, e2: f64, kt: f64) -> LapJoint {
        LapJoint::new(LapParams {
            length: 40.0,
            width: 20.0,
            inner_thickness: t1,
            cover_thickness: t2,
            inner_modulus: 70_000.0,
            cover_modulus: e2,
            pressure: 10.0,
            friction: 0.3,
            tangential_stiffness: kt,
        })
        .unwrap()
    }

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn a_joint_displacement_gives_back_the_stiffness_that_made_it() {
        let soft = joint(3.0, 2.0, 70_000.0, 1000.0);
        for kt in [1.0, 100.0, 1e3, 1e4, 1e6] {
            let at = soft.with_tangential_stiffness(kt).unwrap();
            // Every regime: elastic, one end sliding, both ends, near gross slip.
            for newtons in [300.0, 1500.0, 3000.0, 4500.0, 4790.0] {
                let force = soft.force(newtons).unwrap();
                let delta = at.regularized(force).joint_displacement();
                let found = soft.stiffness_for_joint_displacement(force, delta).unwrap();
                assert!(
                    rel(found, kt) < 1e-6,
                    "K_T {kt}, F {newtons}: found {found}"
                );
            }
        }
        // Below Coulomb's Delta (stiffer than any interface) no K_T gives it.
        let force = soft.force(3000.0).unwrap();
        let coulomb = soft.coulomb(force).joint_displacement();
        assert_eq!(
            soft.stiffness_for_joint_displacement(force, 0.99 * coulomb),
            None
        );
        assert_eq!(soft.stiffness_for_joint_displacement(force, -1.0), None);
    }

    #[test]
    fn matches_the_independent_check_in_every_regime() {
        // (t1, t2, E2, K_T, F1, F2, [(F, a, d, Delta)]).
        type Row = (f64, f64, f64, f64);
        type Case = (f64, f64, f64, f64, f64, f64, &'static [Row]);
        let cases: [Case; 4] = [
            (
                4.0,
                2.0,
                70e3,
                1e3,
                1974.58,
                1974.577,
                &[
                    (987.2885, 0.0, 0.0, 0.00502603044),
                    (2400.0, 1.84896, 1.84896, 0.0122905843),
                    (4320.0, 11.62418, 11.62418, 0.0245003327),
                ],
            ),
            (
                4.0,
                3.0,
                70e3,
                1e3,
                1801.88,
                2638.772,
                &[
                    (900.938, 0.0, 0.0, 0.00388244665),
                    (2400.0, 0.0, 3.12696, 0.0104461674),
                    (2702.81, 0.237116, 4.7418, 0.0118846969),
                    (4320.0, 7.56029, 14.7603, 0.0209874706),
                ],
            ),
            (
                6.0,
                2.0,
                70e3,
                1e3,
                1801.88,
                2638.772,
                &[
                    (2400.0, 3.12696, 0.0, 0.0104461674),
                    (4320.0, 14.7603, 7.56029, 0.0209874706),
                ],
            ),
            // K2 = 2.8e8 N/mm as the check's E2 = 7e7, t2 = 2 (beyond the modulus domain).
            (
                4.0,
                20.0,
                7e6,
                1e3,
                1417.2,
                4800.0,
                &[
                    (708.599, 0.0, 0.0, 0.00150366104),
                    (2125.8, 0.0, 5.9474, 0.00488894785),
                    (4320.0, 0.0, 26.2714, 0.0158809616),
                ],
            ),
        ];
        for (t1, t2, e2, kt, f1, f2, rows) in cases {
            let j = joint(t1, t2, e2, kt);
            assert!(rel(j.first_slip_force(), f1) < 5e-6, "F1 {t1} {t2} {e2}");
            assert!(
                rel(j.second_slip_force(), f2) < 5e-6,
                "F2 {t1} {t2} {e2}: {}",
                j.second_slip_force()
            );
            for &(f, a, d, delta) in rows {
                let s = j.regularized(j.force(f).unwrap());
                assert!(
                    (s.slide_at_inner_end() - a).abs() < 1e-4,
                    "a at {f}: {}",
                    s.slide_at_inner_end()
                );
                assert!(
                    (s.slide_at_cover_ends() - d).abs() < 1e-4,
                    "d at {f}: {}",
                    s.slide_at_cover_ends()
                );
                // F printed to 7 digits where it was a fraction of F_1: Delta as close as F is.
                let tolerance = if f.fract() == 0.0 { 1e-8 } else { 5e-6 };
                assert!(
                    rel(s.joint_displacement(), delta) < tolerance,
                    "Delta at {f}: {}",
                    s.joint_displacement()
                );
            }
        }
        // Coulomb at K_T = 1e7 (case E): a, d and Delta of (L7).
        let j = joint(4.0, 3.0, 70e3, 1e7);
        let s = j.coulomb(j.force(27.49545).unwrap());
        assert!((s.slide_at_inner_end() - 0.0916515).abs() < 1e-7);
        assert!((s.slide_at_cover_ends() - 0.137477).abs() < 1e-6);
        assert!(rel(s.joint_displacement(), 7.88209405e-05) < 1e-6);
    }
}
