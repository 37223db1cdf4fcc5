//! The lap joint under a force cycling between +F_a and -F_a: hysteresis loop of Delta, energy
//! dissipated per cycle, secant stiffness and equivalent viscous damping, for both laws.
//!
//! The branches follow Masing's rule, exact here for the reasons docs/theory.md (L9) gives (the
//! same as the beams' (C1)): the structure is linear, mu P does not change with the load, every
//! interface point's shear grows monotonically on first loading, and a point elastic at the turning
//! point stays elastic over the reversal. With Delta_v the virgin curve, extended as an odd
//! function:
//!
//! ```text
//! unloading from +F_a:  Delta(F) = Delta_a - 2 Delta_v((F_a - F) / 2)
//! reloading from -F_a:  Delta(F) = -Delta_a + 2 Delta_v((F_a + F) / 2)
//! ```

use crate::kernel::regime::Law;
use crate::kernel::shear_lag::ShearLagCycle;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
pub use crate::problems::load_driven::MasingCycle;

/// One cycle of amplitude F_a for one law: the shear lag's cycle ([`ShearLagCycle`], which the
/// press fit shares) of the joint's two bars.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapCycle(ShearLagCycle);

impl LapCycle {
    /// The cycle between +`amplitude` and -`amplitude` for `law`.
    pub fn new(joint: &LapJoint, law: Law, amplitude: JointForce) -> LapCycle {
        LapCycle(ShearLagCycle::new(
            joint.shear_lag(),
            law,
            1.0,
            amplitude.newtons(),
        ))
    }

    /// Peak displacement Delta_a = Delta_v(F_a) (mm).
    pub fn peak_displacement(&self) -> f64 {
        self.0.peak_response()
    }
}

impl MasingCycle for LapCycle {
    fn amplitude(&self) -> f64 {
        self.0.amplitude()
    }

    /// Where sliding starts on first loading (N): F_1 under the regularized law, 0 under plain
    /// Coulomb (both ends slide from the first newton, (L7)).
    fn onset(&self) -> f64 {
        self.0.onset()
    }

    /// The virgin curve Delta_v(F) (mm), odd in F; |F| beyond F_gross is taken at F_gross (the
    /// branches never ask for more than F_a).
    fn virgin(&self, force: f64) -> f64 {
        self.0.virgin(force)
    }

    /// Delta_a (mm), [`LapCycle::peak_displacement`].
    fn peak_response(&self) -> f64 {
        self.0.peak_response()
    }

    /// Energy dissipated per cycle (N mm), (L10): the friction work of the plastic slip at the
    /// turning point; zero while nothing slides.
    fn dissipation(&self) -> f64 {
        self.0.dissipation()
    }

    /// Peak elastic energy U = F_a Delta_a / 2 (N mm), the secant definition.
    fn peak_energy(&self) -> f64 {
        self.0.peak_energy()
    }

    /// Secant stiffness F_a / Delta_a (N/mm); at zero amplitude the initial slope: the elastic
    /// joint's under the regularized law, the bonded joint's under Coulomb (its slip grows as F^2).
    fn secant_stiffness(&self) -> f64 {
        self.0.secant_stiffness()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::lap::closed_form::LapParams;

    fn joint() -> LapJoint {
        LapJoint::new(LapParams::ALUMINIUM).unwrap()
    }

    /// The loop's area by quadrature of Masing's branches, int (unloading - reloading) dF: an
    /// independent route to D from (L10)'s friction work.
    fn loop_area(cycle: &LapCycle) -> f64 {
        let n = 4000;
        let fa = cycle.amplitude();
        let h = 2.0 * fa / n as f64;
        let gap = |f: f64| cycle.unloading(f) - cycle.reloading(f);
        // Simpson's rule over [-F_a, F_a].
        let mut sum = gap(-fa) + gap(fa);
        for i in 1..n {
            let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
            sum += weight * gap(-fa + i as f64 * h);
        }
        sum * h / 3.0
    }

    #[test]
    fn dissipation_from_friction_work_equals_the_loop_area() {
        let j = joint();
        for law in [Law::Coulomb, Law::Regularized] {
            for fraction in [0.2, 0.4, 0.45, 0.7, 0.95, 1.0] {
                let fa = j.force(fraction * j.gross_slip_force()).unwrap();
                let cycle = LapCycle::new(&j, law, fa);
                let (d, area) = (cycle.dissipation(), loop_area(&cycle));
                if fa.newtons() <= cycle.onset() {
                    assert_eq!(d, 0.0);
                    assert!(area.abs() < 1e-9, "{law:?} {fraction}: {area}");
                    continue;
                }
                assert!(d > 0.0, "{law:?} {fraction}");
                assert!(
                    ((d - area) / d).abs() < 1e-4,
                    "{law:?} {fraction}: {d} vs {area}"
                );
            }
        }
    }

    #[test]
    fn loops_close_are_point_symmetric_and_vanish_below_first_slip() {
        let j = joint();
        for law in [Law::Coulomb, Law::Regularized] {
            let cycle = LapCycle::new(&j, law, j.force(4000.0).unwrap());
            let peak = cycle.peak_displacement();
            assert!((cycle.unloading(4000.0) - peak).abs() < 1e-15);
            assert!((cycle.unloading(-4000.0) + peak).abs() < 1e-12 * peak);
            assert!((cycle.reloading(4000.0) - peak).abs() < 1e-12 * peak);
            for f in [-3000.0, -100.0, 0.0, 2500.0] {
                assert!((cycle.reloading(f) + cycle.unloading(-f)).abs() < 1e-15);
            }
        }
        let below = LapCycle::new(
            &j,
            Law::Regularized,
            j.force(0.99 * j.first_slip_force()).unwrap(),
        );
        assert_eq!(below.dissipation(), 0.0);
        assert_eq!(below.damping_ratio(), 0.0);
        assert!((below.unloading(100.0) - below.virgin(100.0)).abs() < 1e-15);
        // Zero amplitude: the initial slopes, the bonded one stiffer than the elastic one.
        let zero = j.force(0.0).unwrap();
        let bonded = LapCycle::new(&j, Law::Coulomb, zero).secant_stiffness();
        let elastic = LapCycle::new(&j, Law::Regularized, zero).secant_stiffness();
        assert!(bonded > elastic && elastic > 0.0 && bonded.is_finite());
    }
}
