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
//!
//! That shape is the shear lag of any two bars coupled through one interface, which the press fit
//! shares: it is solved once in [`crate::kernel::shear_lag`], and this file maps the joint onto it
//! (the inner plate is the bar loaded at x = L, the covers the bar held at x = 0, the width the
//! two faces' 2 b) and names its results in the joint's words.

pub use super::params::LapParams;
use crate::kernel::params::ParamError;
use crate::kernel::regime::{Law, Regime};
pub use crate::kernel::shear_lag::zones_regime;
use crate::kernel::shear_lag::{ShearLag, ShearLagState, SlipStart, TwoBars};
use crate::problems::Solution;
use crate::problems::lap::params::LapParam;

/// A validated double-lap joint with its load-independent constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapJoint {
    params: LapParams,
    /// The two bars of the shear lag: the inner plate (loaded at x = L) and both covers lumped
    /// (held at x = 0), per unit interface width, over the two faces' width 2 b.
    lag: ShearLag,
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
        // (L1) as two bars (kernel::shear_lag): per unit of the two faces' width 2 b, the inner
        // plate's rigidity b k1 is k1 / 2 and the covers' b K2 is K2 / 2. Halving and doubling
        // are exact, so every number is the one the per-width formulas of section 9 give.
        let lag = ShearLag::new(TwoBars {
            loaded: params.inner_stiffness() / 2.0,
            held: params.covers_stiffness() / 2.0,
            width: 2.0 * params.width,
            length: params.length,
            friction: params.friction,
            pressure: params.pressure,
            stiffness: params.tangential_stiffness,
        });
        Ok(LapJoint { params, lag })
    }

    /// The inputs this joint was built from.
    pub fn params(&self) -> LapParams {
        self.params
    }

    /// The shear lag of its two bars (the kernel's, [`ShearLag`]).
    pub(crate) fn shear_lag(&self) -> &ShearLag {
        &self.lag
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
            return Err(LapParam::Force.spec().above(
                newtons,
                gross,
                "F_gross = 2 b mu P L: the joint slides through beyond it",
            ));
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
        self.lag
            .stiffness_for_end_displacement(force.0, joint_displacement)
    }

    /// lambda = sqrt(2 c K_T) (1/mm), (L2): 1/lambda is the length over which the elastic slip
    /// decays from a loaded end.
    pub fn decay_rate(&self) -> f64 {
        self.lag.decay_rate()
    }

    /// Coulomb stress mu P (MPa).
    pub fn coulomb_stress(&self) -> f64 {
        self.lag.coulomb_stress()
    }

    /// Saturation slip mu P / K_T (mm).
    pub fn saturation_slip(&self) -> f64 {
        self.lag.saturation_slip()
    }

    /// F_gross = 2 b mu P L (N), (L6).
    pub fn gross_slip_force(&self) -> f64 {
        self.params.gross_slip_force()
    }

    /// The bonded joint's compliance L / (b (k1 + K2)) (mm/N), (L6): both members strained alike,
    /// what remains of Delta / F when nothing slips.
    pub fn bonded_compliance(&self) -> f64 {
        self.lag.bonded_compliance()
    }

    /// Which end slides first (L2).
    pub fn first_slip(&self) -> FirstSlip {
        match self.lag.slip_start() {
            SlipStart::End => FirstSlip::CoverEnds,
            SlipStart::Start => FirstSlip::InnerEnd,
            SlipStart::Both => FirstSlip::BothEnds,
        }
    }

    /// (L3): the force F_1 at which sliding first appears, at [`LapJoint::first_slip`]:
    /// 2 c mu P b L tanhc(lambda L) / (1/k_s + sech(lambda L)/k_o), k_s the stiffness of the
    /// member loaded at the sliding end (the more compliant one).
    pub fn first_slip_force(&self) -> f64 {
        self.lag.first_slip_force()
    }

    /// (L4'): the force F_2 at which the other end starts sliding too (F_1 for a balanced joint):
    /// with the elastic zone l solving l + (l/2) tanhc(lambda l/2) (k_o - k_s)/k_s = L,
    /// F_2 = b k_o c mu P l tanhc(lambda l/2).
    pub fn second_slip_force(&self) -> f64 {
        self.lag.second_slip_force()
    }

    /// Solution under plain Coulomb at `force` (L7): sliding zones a = G0 and d = GL, the rest
    /// sticks and carries no shear.
    pub fn coulomb(&self, force: JointForce) -> LapState {
        LapState(self.lag.coulomb(force.0))
    }

    /// Solution under the regularized law at `force`: all microslip up to F_1 (L2), one end
    /// sliding up to F_2 (L4), both beyond (L5), all sliding at F_gross (L6).
    pub fn regularized(&self, force: JointForce) -> LapState {
        LapState(self.lag.regularized(force.0))
    }
}

/// One law's solution at one force: the two sliding zones and what follows from them (the
/// shear lag's state, [`ShearLagState`], in the joint's words).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapState(ShearLagState);

impl LapState {
    /// The law this state is solved under.
    pub fn law(&self) -> Law {
        self.0.law()
    }

    /// The force through the joint (N).
    pub fn force(&self) -> f64 {
        self.0.force()
    }

    /// Length a of the sliding zone from x = 0, the inner plate's end (mm).
    pub fn slide_at_inner_end(&self) -> f64 {
        self.0.slide_from_start()
    }

    /// Length d of the sliding zone from x = L, the covers' ends (mm).
    pub fn slide_at_cover_ends(&self) -> f64 {
        self.0.slide_from_end()
    }

    /// The zone between the sliding ones, [a, L - d]: elastic (regularized) or stuck (Coulomb).
    pub fn middle_zone(&self) -> (f64, f64) {
        self.0.middle_zone()
    }

    /// The slip s(x) = u_inner - u_cover (mm) at `x` (clamped to [0, L]), (L4)-(L7): in a sliding
    /// zone edge + u (p + c mu P u) with u the distance into it from the middle zone; in the
    /// middle zone the elastic profile [q cosh(lambda (x - a)) + p cosh(lambda (L - d - x))] /
    /// (lambda sinh(lambda l)) (regularized), or 0 (Coulomb: it sticks).
    pub fn slip_at(&self, x: f64) -> f64 {
        self.0.slip_at(x)
    }

    /// The interface shear tau(x) on the inner plate (MPa), positive resisting F: mu P in the
    /// sliding zones; K_T s in the elastic zone (regularized), 0 in the stick zone (Coulomb).
    pub fn shear_at(&self, x: f64) -> f64 {
        self.0.shear_at(x)
    }

    /// The joint displacement Delta = u_inner(L) - u_cover(0) (mm), (L6):
    /// (1 - alpha) s(0) + alpha s(L) + F L / (b (k1 + K2)), alpha = K2 / (k1 + K2).
    pub fn joint_displacement(&self) -> f64 {
        self.0.end_displacement()
    }

    /// The zones from x = 0 outward.
    pub fn regime(&self) -> Regime {
        self.0.regime()
    }

    /// (L10): energy dissipated per cycle between +F and -F (N mm), from the friction work of
    /// Masing's loop: every point of a sliding zone slides back and forth by twice its plastic
    /// slip s_p at the turning point against mu P, on two interfaces of width b, so
    /// D = 8 b mu P sum over both zones of integral(s_p) = 8 b mu P sum (c mu P)(p u^2 + u^3/3)
    /// with u the zone's length and p its middle-zone slope length: a sum of positive terms.
    pub fn cycle_dissipation(&self) -> f64 {
        self.0.cycle_dissipation()
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
