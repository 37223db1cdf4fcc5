//! The press fit under a load cycling between +F_a and -F_a (or +T_a and -T_a): hysteresis loop,
//! energy dissipated per cycle, secant stiffness and equivalent viscous damping, both laws.
//!
//! The branches follow Masing's rule, exact here for the reasons docs/theory.md (L9) gives for
//! the lap joint, whose shear lag the fit shares (section 18, (S7)): linear members, a pressure p
//! that the load does not change (no Poisson coupling, (S2)), shear growing monotonically on first
//! loading. The loop's area is the kernel's friction work (L10).

use crate::kernel::regime::Law;
use crate::kernel::shear_lag::ShearLagCycle;
use crate::problems::load_driven::MasingCycle;
use crate::problems::pressfit::closed_form::{CarriedLoad, FitAxis};

/// One cycle of amplitude F_a (or T_a) for one law: the shear lag's cycle ([`ShearLagCycle`],
/// shared with the lap joint) of the axis's two members, with its arm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitCycle(ShearLagCycle);

impl FitCycle {
    /// The cycle between +`amplitude` and -`amplitude` of `axis` under `law`.
    pub fn new(axis: &FitAxis, law: Law, amplitude: CarriedLoad) -> FitCycle {
        FitCycle(axis.cycle(law, amplitude))
    }

    /// The peak response (mm or rad).
    pub fn peak_displacement(&self) -> f64 {
        self.0.peak_response()
    }
}

impl MasingCycle for FitCycle {
    fn amplitude(&self) -> f64 {
        self.0.amplitude()
    }

    /// F_1 (T_1) under the regularized law; 0 under Coulomb (both faces slide at once, (L7)).
    fn onset(&self) -> f64 {
        self.0.onset()
    }

    /// The virgin curve, odd in the load; beyond the gross load taken at it.
    fn virgin(&self, load: f64) -> f64 {
        self.0.virgin(load)
    }

    fn peak_response(&self) -> f64 {
        self.0.peak_response()
    }

    /// (L10) on the fit's interface, the same for the torque (T dtheta = N dDelta_eq).
    fn dissipation(&self) -> f64 {
        self.0.dissipation()
    }

    /// U = F_a Delta_a / 2 (N mm), the secant definition.
    fn peak_energy(&self) -> f64 {
        self.0.peak_energy()
    }

    /// F_a / Delta_a; at zero amplitude the bonded fit's slope (Coulomb) or the elastic one's.
    fn secant_stiffness(&self) -> f64 {
        self.0.secant_stiffness()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::pressfit::closed_form::PressFit;
    use crate::problems::pressfit::params::PressFitParams;

    /// The loop's area by Simpson's rule over Masing's branches: an independent route to D.
    fn loop_area(cycle: &FitCycle) -> f64 {
        let n = 4000;
        let fa = cycle.amplitude();
        let h = 2.0 * fa / n as f64;
        let gap = |f: f64| cycle.unloading(f) - cycle.reloading(f);
        let mut sum = gap(-fa) + gap(fa);
        for i in 1..n {
            let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
            sum += weight * gap(-fa + i as f64 * h);
        }
        sum * h / 3.0
    }

    #[test]
    fn dissipation_equals_the_loop_area_for_both_loads_and_laws() {
        let fit = PressFit::new(PressFitParams::CCX98).unwrap();
        for axis in [fit.axial(), fit.torsion()] {
            for law in [Law::Coulomb, Law::Regularized] {
                for fraction in [0.1, 0.5, 0.9, 1.0] {
                    let amplitude = axis.load(fraction * axis.gross_load()).unwrap();
                    let cycle = FitCycle::new(axis, law, amplitude);
                    let (d, area) = (cycle.dissipation(), loop_area(&cycle));
                    if amplitude.value() <= cycle.onset() {
                        assert_eq!(d, 0.0);
                        assert!(area.abs() < 1e-9 * cycle.peak_energy());
                        continue;
                    }
                    assert!(d > 0.0);
                    assert!(
                        ((d - area) / d).abs() < 1e-4,
                        "{law:?} {fraction}: {d} {area}"
                    );
                    // The loop closes on itself.
                    let peak = cycle.peak_displacement();
                    assert!((cycle.reloading(amplitude.value()) - peak).abs() < 1e-12 * peak);
                }
            }
        }
    }
}
