//! How far the joint's 1-D shear-lag theory holds (L14): its expected difference from a
//! plane-stress continuum, as numbers. The theory assumes each plate's axial strain uniform
//! through its thickness and the contact pressure equal to P. A CalculiX grid of 22 joints (16 to
//! fit, 6 held out, 74 states; docs/theory.md (L14), `validation/calculix/lap/envelope/ENVELOPE.md`) found
//! three ways that fails, each with a size computable from the inputs:
//!
//! - the plates' through-thickness shear compliance, in series with the interface's: r, the
//!   change of the closed form's Delta when K_T is replaced by K_eff,
//!   1/K_eff = 1/K_T + t1/(6 G1) + t2/(3 G2) (L12);
//! - the clamping prestress of dissimilar plates: P alone stretches them by nu P/E1 and nu P/E2,
//!   and the mismatch locks in an interface shear before any F. q_p = min(m, 1) min(1, 1/(lambda
//!   L)), with m = nu K_T |1/E1 - 1/E2| tanh(lambda L/2) / (lambda mu) the slip the mismatch
//!   demands at an end over the saturation slip;
//! - the covers bending under the eccentric interface shear, so that the contact pressure is not
//!   P: beta = mu (t1/2 + t2) / L.
//!
//! The joint's keys have no Poisson ratio; the envelope, like the deck and the continuum solver,
//! takes nu = [`LAP_POISSON`] = 0.3.

use super::closed_form::{JointForce, LapJoint};
use super::params::LAP_POISSON;
use crate::kernel::validity::Validity;

/// The shear-lag theory's envelope for one joint at one force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapValidity {
    /// The decay length of the interface shear over the thicker plate, (1/lambda) / max(t1, t2):
    /// small values are where uniform strain through the thickness is doubtful.
    pub decay_over_thickness: f64,
    /// r = |Delta(K_eff) / Delta(K_T) - 1|: the plates' shear compliance.
    pub shear_compliance: f64,
    /// q_p: the clamping prestress of dissimilar plates (0 for equal moduli).
    pub clamping_prestress: f64,
    /// beta = mu (t1/2 + t2) / L: the covers' bending.
    pub cover_bending: f64,
    /// The bound on |Delta continuum / Delta closed form - 1|, a fraction; `None` where the
    /// calibration does not reach ([`LapValidity::outside_calibration`] says why).
    pub expected_error: Option<f64>,
    /// The level of that bound.
    pub validity: Validity,
    /// Which calibrated range the joint leaves, when it does: the first of
    /// [`LapValidity::out_of_range`].
    pub outside_calibration: Option<&'static str>,
    /// Every calibrated range the joint leaves.
    pub out_of_range: LapRangesLeft,
}

/// The bound's coefficients on (r, q_p, beta, 1), fitted by a linear programme to the 54
/// in-domain calibration states (each bound at or above its measured |error|) and rounded up:
/// `ENVELOPE.md`, section 7.
const COEFFICIENTS: [f64; 4] = [1.0, 2.0, 0.36, 0.013];
/// The margin over the fitted bound: the hold-out joints exceeded it by up to 2.5 % of itself
/// (an E2 = 3 E1 joint in a sliding state) and the shortest joint by 8 %; with the margin every
/// hold-out state is under it (largest ratio 0.82 in the domain). The margin was chosen after
/// seeing the hold-outs, so it is not independently tested (docs/theory.md (L14)).
const MARGIN: f64 = 1.25;

/// The calibrated ranges, each with what a joint outside it is told. `lambda L` and `beta`:
/// the corner beyond both (the envelope grid's C02, a thick cover on a short joint, lambda L
/// 0.29, beta 0.5) has no converged CalculiX answer: re-measured on mesh and load-step ladders
/// (docs/theory.md, "(L14) on converged ladders"), its Delta at 0.9 F_gross spreads from +51 to
/// +270 % over the shear lag with the covers lifting off at x = 0 (the envelope study's coarse
/// +236 % and +68 % are two points of that spread), +3.6 to +5.6 % at 0.5 F_gross, and the
/// continuum is 0.8 to 4.9 % below every rung even there.
const MIN_LAMBDA_L: f64 = 1.4;
const MAX_BETA: f64 = 0.30;
const LAMBDA_T1: (f64, f64) = (0.09, 4.65);
const LAMBDA_SHEAR_DEPTH: (f64, f64) = (0.12, 6.7);
const COVER_OVER_INNER_THICKNESS: (f64, f64) = (0.3, 2.0);
const COVER_OVER_INNER_MODULUS: (f64, f64) = (1.0, 3.0);
const COVERS_OVER_INNER_STIFFNESS: (f64, f64) = (0.3, 6.0);
/// Largest E2 t2 / (E1 t1) calibrated for dissimilar plates (E2 != E1). The grid measured stiff
/// dissimilar covers at low friction and soft interfaces only (ratio 6 at mu 0.3, K_T 1e3; 3.75
/// at mu 0.45; 4.5 at mu 0.2); against the continuum (which agrees with CalculiX within 0.3 %,
/// and at this corner within 0.06 % of its converged ladders, issue 45), ratios 4.5 and 6 at
/// mu 0.45-0.6 and K_T 1e4 exceed the bound by up to 1.34x at 0.5 F_gross and 1.2x at 0.85-0.9
/// F_gross (issue 33), while ratio 3 stays under it (docs/theory.md, "The verdict against the
/// continuum"). CalculiX on the fine mesh and at half the increment confirms issue 33's joints
/// A and B to 0.06 points (+15.9 to +28.4 % off the shear lag; docs/theory.md, "(L14) on
/// converged ladders").
const MAX_DISSIMILAR_STIFFNESS_RATIO: f64 = 3.0;
const LENGTH_OVER_T1: (f64, f64) = (3.0, 30.0);
const FRICTION: (f64, f64) = (0.1, 0.6);
/// The highest load level of the grid: 0.9 F_gross.
const MAX_LOAD_FRACTION: f64 = 0.9;

/// Relative slack on each range's ends, so that a joint on a grid node is inside.
const SLACK: f64 = 1e-9;

fn within((lo, hi): (f64, f64), x: f64) -> bool {
    x >= lo * (1.0 - SLACK) && x <= hi * (1.0 + SLACK)
}

impl LapJoint {
    /// Where the shear-lag theory stands for this joint at `force` (L14): the bound
    /// 1.25 (r + 2.0 q_p + 0.36 beta + 0.013) on Delta's difference from a continuum, inside
    /// the calibrated ranges.
    pub fn validity(&self, force: JointForce) -> LapValidity {
        self.validity_at(force, self.regularized(force).joint_displacement())
    }

    /// [`LapJoint::validity`] given the regularized Delta at `force` (sweeps have it already).
    pub fn validity_at(&self, force: JointForce, delta: f64) -> LapValidity {
        let p = self.params();
        let lambda = self.decay_rate();
        let shear_modulus = |e: f64| e / (2.0 * (1.0 + LAP_POISSON));
        let shear_compliance = p.inner_thickness / (6.0 * shear_modulus(p.inner_modulus))
            + p.cover_thickness / (3.0 * shear_modulus(p.cover_modulus));
        let k_eff = 1.0 / (1.0 / p.tangential_stiffness + shear_compliance);
        let r = match self.with_tangential_stiffness(k_eff) {
            Ok(softer) if delta > 0.0 => {
                (softer.regularized(force).joint_displacement() / delta - 1.0).abs()
            }
            // At F = 0 both Deltas vanish: r is its limit as F -> 0+. Below first slip each
            // joint is linear in F (every interface point elastic, (L2)), so the ratio of the
            // two Deltas is the same at every force up to the smaller F_1: take it at half of
            // that (issue 36: r = 0 here made the bound jump at zero load).
            Ok(softer) => {
                let linear = 0.5 * self.first_slip_force().min(softer.first_slip_force());
                let stiff = self.regularized(self.clamped_force(linear));
                let soft = softer.regularized(softer.clamped_force(linear));
                let stiff = stiff.joint_displacement();
                if stiff > 0.0 {
                    (soft.joint_displacement() / stiff - 1.0).abs()
                } else {
                    0.0
                }
            }
            // K_eff is in range whenever K_T is.
            Err(_) => 0.0,
        };
        let lambda_l = lambda * p.length;
        let mismatch = LAP_POISSON
            * p.tangential_stiffness
            * (1.0 / p.inner_modulus - 1.0 / p.cover_modulus).abs()
            * (0.5 * lambda_l).tanh()
            / (lambda * p.friction);
        let q_p = mismatch.min(1.0) * (1.0 / lambda_l).min(1.0);
        let beta = p.friction * (0.5 * p.inner_thickness + p.cover_thickness) / p.length;
        let stiffness_ratio =
            p.cover_modulus * p.cover_thickness / (p.inner_modulus * p.inner_thickness);
        let dissimilar = (p.cover_modulus / p.inner_modulus - 1.0).abs() > SLACK;
        let checks = [
            lambda_l >= MIN_LAMBDA_L * (1.0 - SLACK),
            beta <= MAX_BETA * (1.0 + SLACK),
            within(LAMBDA_T1, lambda * p.inner_thickness),
            within(
                LAMBDA_SHEAR_DEPTH,
                lambda * (0.5 * p.inner_thickness + p.cover_thickness),
            ),
            within(COVERS_OVER_INNER_STIFFNESS, stiffness_ratio),
            !dissimilar || stiffness_ratio <= MAX_DISSIMILAR_STIFFNESS_RATIO * (1.0 + SLACK),
            within(LENGTH_OVER_T1, p.length / p.inner_thickness),
            within(FRICTION, p.friction),
            within(
                COVER_OVER_INNER_THICKNESS,
                p.cover_thickness / p.inner_thickness,
            ),
            within(COVER_OVER_INNER_MODULUS, p.cover_modulus / p.inner_modulus),
            force.newtons() <= MAX_LOAD_FRACTION * self.gross_slip_force() * (1.0 + SLACK),
        ];
        let out_of_range = LapRangesLeft(
            checks
                .iter()
                .enumerate()
                .filter(|(_, inside)| !**inside)
                .fold(0, |bits, (i, _)| bits | (1 << i)),
        );
        let outside_calibration = out_of_range.names().first().copied();
        let [c_r, c_p, c_b, c_0] = COEFFICIENTS;
        let expected_error = outside_calibration
            .is_none()
            .then_some(MARGIN * (c_r * r + c_p * q_p + c_b * beta + c_0));
        LapValidity {
            decay_over_thickness: 1.0 / (lambda * p.inner_thickness.max(p.cover_thickness)),
            shear_compliance: r,
            clamping_prestress: q_p,
            cover_bending: beta,
            expected_error,
            validity: expected_error.map_or(Validity::NotCalibrated, Validity::of_error),
            outside_calibration,
            out_of_range,
        }
    }
}

/// Every calibrated range a joint leaves (issue 33: a joint outside two was told of one), as
/// bits in the order the ranges are checked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LapRangesLeft(u16);

/// What a joint outside each calibrated range is told, in the order they are checked.
const RANGE_REASONS: [&str; 11] = [
    "lambda L below 1.4: an overlap shorter than 1.4 decay lengths, where no calibrated joint \
     was (one measured +10 %); with mu (t1/2 + t2) / L up to 0.3 the covers stay pressed on \
     (the continuum's contact pressure stays positive up to 0.9 F_gross) but it is far from P, \
     and the 1-D error grows with F",
    "mu (t1/2 + t2) / L above 0.3, where the covers bend: at 0.5 (a short joint with thick covers) \
     CalculiX's covers lift off at x = 0 and its Delta converges in neither mesh nor load path \
     (+51 to +270 % at 0.9 F_gross), and the continuum is 0.8 to 4.9 % below it from 0.05 to 0.5 F_gross",
    "lambda t1 outside 0.09 to 4.65",
    "lambda (t1/2 + t2) outside 0.12 to 6.7",
    "E2 t2 / (E1 t1) outside 0.3 to 6",
    "E2 t2 / (E1 t1) above 3 with E2 != E1: stiff dissimilar covers, measured outside the \
     bound against the continuum (issue 33)",
    "L/t1 outside 3 to 30",
    "mu outside 0.1 to 0.6",
    "t2/t1 outside 0.3 to 2",
    "E2/E1 outside 1 to 3",
    "F above 0.9 F_gross",
];

/// The index of the cover-bending range (mu (t1/2 + t2) / L at most 0.3) in [`RANGE_REASONS`].
const COVER_BENDING_RANGE: usize = 1;

impl LapRangesLeft {
    /// Whether the plane-stress continuum's agreement with CalculiX is unestablished here: mu
    /// (t1/2 + t2) / L above 0.3, where CalculiX's own Delta converged in neither mesh nor load
    /// path and stood 0.8 to 4.9 % above the continuum from 0.05 to 0.5 F_gross (the grid's
    /// C02, issue 45: docs/theory.md, "(L14) on converged ladders"). Elsewhere the continuum was
    /// within 0.001 to 0.3 % of CalculiX on every joint compared.
    pub fn continuum_unestablished(self) -> bool {
        self.0 & (1 << COVER_BENDING_RANGE) != 0
    }

    /// Inside every calibrated range.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// What the joint is told, one reason per range it leaves, in the order checked.
    pub fn names(self) -> Vec<&'static str> {
        RANGE_REASONS
            .iter()
            .enumerate()
            .filter(|(i, _)| self.0 & (1 << i) != 0)
            .map(|(_, r)| *r)
            .collect()
    }

    /// The reasons in one line ("a; b").
    pub fn words(self) -> String {
        self.names().join("; ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::lap::params::LapParams;

    fn joint(change: impl Fn(&mut LapParams)) -> LapJoint {
        let mut p = LapParams::ALUMINIUM;
        change(&mut p);
        LapJoint::new(p).unwrap()
    }

    /// Steel covers (E2 = 210000 MPa) on the aluminium strap: [t1, t2, L, mu, K_T, P].
    fn steel_covers([t1, t2, length, friction, kt, pressure]: [f64; 6]) -> LapJoint {
        joint(|p| {
            p.cover_modulus = 210_000.0;
            p.inner_thickness = t1;
            p.cover_thickness = t2;
            p.length = length;
            p.friction = friction;
            p.tangential_stiffness = kt;
            p.pressure = pressure;
        })
    }

    #[test]
    fn the_bundled_joint_is_approximate_and_its_terms_are_the_calibrations() {
        // ENVELOPE.md's joint C05 (the bundled joint): r = 0.61 % at 2342 N, q_p = 0 (equal
        // moduli), beta = 0.3 x 3.5 / 40 = 0.02625.
        let j = joint(|_| {});
        let v = j.validity(j.force(2342.1342).unwrap());
        assert!((v.shear_compliance - 0.0061).abs() < 0.0002, "{v:?}");
        assert_eq!(v.clamping_prestress, 0.0);
        assert!((v.cover_bending - 0.02625).abs() < 1e-12);
        let bound = v.expected_error.unwrap();
        assert!(
            (bound - 1.25 * (v.shear_compliance + 0.36 * 0.02625 + 0.013)).abs() < 1e-12,
            "{bound}"
        );
        // CalculiX measured +1.18 % there: under the bound, which is above 2 %.
        assert!(bound > Validity::HOLDS, "{bound}");
        assert_eq!(v.validity, Validity::Approximate);
    }

    #[test]
    fn each_calibrated_range_is_enforced() {
        let at = |j: &LapJoint, f: f64| j.validity(j.force(f).unwrap());
        let bundled = joint(|_| {});
        assert!(at(&bundled, 5400.0).expected_error.is_some());
        assert_eq!(
            at(&bundled, 5500.0).outside_calibration,
            Some("F above 0.9 F_gross")
        );
        let short = joint(|p| p.length = 5.0);
        assert!(at(&short, 100.0).outside_calibration.is_some());
        let soft_covers = joint(|p| p.cover_modulus = 35_000.0);
        assert_eq!(
            at(&soft_covers, 1000.0).outside_calibration,
            Some("E2/E1 outside 1 to 3")
        );
        let stiff = joint(|p| p.tangential_stiffness = 1e7);
        assert_eq!(
            at(&stiff, 1000.0).validity,
            Validity::NotCalibrated,
            "lambda t1 = 39"
        );
    }

    /// Issue 33: stiff dissimilar covers at high friction (E2 = 3 E1, E2 t2 / (E1 t1) = 6, mu
    /// 0.55-0.6, beta near 0.3) were inside the ranges while the continuum measured Delta up to
    /// 1.17 times the bound off; they are now outside, and every range a joint leaves is named.
    #[test]
    fn stiff_dissimilar_covers_are_outside_and_every_range_left_is_named() {
        let corner = steel_covers([2.0, 4.0, 11.0, 0.6, 3000.0, 10.0]);
        let v = corner.validity(corner.force(0.9 * corner.gross_slip_force()).unwrap());
        assert_eq!(v.validity, Validity::NotCalibrated);
        assert!(
            v.out_of_range
                .words()
                .contains("E2 t2 / (E1 t1) above 3 with E2 != E1"),
            "{}",
            v.out_of_range.words()
        );
        // Ratio 3 (t2 = t1) stays calibrated.
        let at_three = joint(|p| {
            p.inner_thickness = 2.0;
            p.cover_thickness = 2.0;
            p.cover_modulus = 210_000.0;
        });
        assert!(
            at_three
                .validity(at_three.force(1000.0).unwrap())
                .out_of_range
                .is_empty()
        );
        // Soft covers (E2/E1 = 1/3): both the modulus ratio and the stiffness ratio are named.
        let soft = joint(|p| {
            p.cover_modulus = 70_000.0 / 3.0;
            p.cover_thickness = 1.0;
        });
        let names = soft
            .validity(soft.force(500.0).unwrap())
            .out_of_range
            .names();
        assert!(names.contains(&"E2/E1 outside 1 to 3"), "{names:?}");
        assert!(
            names.contains(&"E2 t2 / (E1 t1) outside 0.3 to 6"),
            "{names:?}"
        );
        // The short overlap is not said to lift off: neither CalculiX nor the continuum shows it.
        let short = joint(|p| p.length = 5.0);
        let words = short
            .validity(short.force(100.0).unwrap())
            .out_of_range
            .words();
        assert!(words.starts_with("lambda L below 1.4"), "{words}");
        assert!(!words.contains("lift off"), "{words}");
        // The short, thick-cover corner beyond both (the grid's C02, beta 0.5): CalculiX's covers
        // lift off there and its ladders do not converge (issue 45, item 5), which the joint is
        // told; the short overlap's "stay pressed on" is said of beta <= 0.3 only.
        let c02 = steel_covers([3.0, 6.0, 9.0, 0.6, 100.0, 50.0]);
        let words = c02
            .validity(c02.force(0.9 * c02.gross_slip_force()).unwrap())
            .out_of_range
            .words();
        assert!(words.starts_with("lambda L below 1.4"), "{words}");
        assert!(words.contains("with mu (t1/2 + t2) / L up to 0.3 the covers stay pressed on"));
        assert!(
            words.contains("covers lift off at x = 0")
                && words.contains("converges in neither mesh nor load path"),
            "{words}"
        );
        // There the continuum's accuracy is not established; at the short joint (beta <= 0.3)
        // and the bundled one it is.
        let left = |j: &LapJoint| j.validity(j.force(100.0).unwrap()).out_of_range;
        assert!(left(&c02).continuum_unestablished());
        assert!(!left(&short).continuum_unestablished());
        assert!(!left(&joint(|_| {})).continuum_unestablished());
    }

    #[test]
    fn dissimilar_plates_pay_for_the_clamping_prestress() {
        // Steel covers (E2 = 3 E1): m = nu K_T (1/E1 - 1/E2) tanh(lambda L / 2) / (lambda mu).
        let steel = joint(|p| p.cover_modulus = 210_000.0);
        let force = steel.force(1000.0).unwrap();
        let v = steel.validity(force);
        let p = steel.params();
        let lambda = steel.decay_rate();
        let m = 0.3
            * p.tangential_stiffness
            * (1.0 / 70_000.0 - 1.0 / 210_000.0)
            * (0.5 * lambda * p.length).tanh()
            / (lambda * p.friction);
        let expected = m.min(1.0) * (1.0 / (lambda * p.length)).min(1.0);
        assert!((v.clamping_prestress - expected).abs() < 1e-12);
        assert!(v.clamping_prestress > 0.0);
        let same = joint(|_| {}).validity(force);
        assert!(v.expected_error.unwrap() > same.expected_error.unwrap());
    }

    #[test]
    fn the_bound_at_zero_load_is_the_limit_of_its_neighbours() {
        // Issue 36: 0.0281 at F = 0 against 0.0363 at F = 1e-9 N. Below first slip both Deltas
        // are linear in F, so r (and the bound) is the same at every small force, and F = 0
        // must give that value. Steel covers too: q_p > 0 does not depend on F.
        for j in [joint(|_| {}), joint(|p| p.cover_modulus = 210_000.0)] {
            let at = |f: f64| j.validity(j.force(f).unwrap()).expected_error.unwrap();
            let zero = at(0.0);
            for f in [1e-9, 1e-6 * j.first_slip_force()] {
                assert!((at(f) / zero - 1.0).abs() < 1e-9, "{f}: {} {zero}", at(f));
            }
            assert!(j.validity(j.force(0.0).unwrap()).shear_compliance > 0.005);
        }
    }

    #[test]
    fn stiffer_interfaces_are_expected_further_off() {
        // r grows with K_T: the plates' shear compliance is a larger share of the interface's.
        let mut last = 0.0;
        for kt in [100.0, 1e3, 1e4, 1e5] {
            let j = joint(|p| p.tangential_stiffness = kt);
            let v = j.validity(j.force(500.0).unwrap());
            assert!(v.shear_compliance > last, "K_T {kt}: {v:?}");
            last = v.shear_compliance;
        }
    }
}
