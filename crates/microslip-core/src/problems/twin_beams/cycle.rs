//! Twin beams under a tip force cycling between +F_a and -F_a: hysteresis loop, energy dissipated
//! per cycle, secant stiffness and equivalent viscous damping, for both friction laws.
//!
//! The return branches follow Masing's rule, which docs/theory.md (section 6) proves exact for this
//! system: the structure is linear, the interface strength mu P does not change with the load, the
//! virgin loading is monotonic at every interface point, and a point elastic at the turning point
//! stays elastic over the whole reversal. With w_v the virgin (first-loading) curve, extended as an
//! odd function:
//!
//! ```text
//! unloading from +F_a:  w(F) = w_a - 2 w_v((F_a - F) / 2)
//! reloading from -F_a:  w(F) = -w_a + 2 w_v((F_a + F) / 2)
//! ```

pub use crate::kernel::regime::Law;
pub use crate::problems::load_driven::MasingCycle;
use crate::problems::twin_beams::closed_form::{TipForce, TwinBeams};

/// One cycle of amplitude F_a for one law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamsCycle {
    beams: TwinBeams,
    law: Law,
    amplitude: f64,
    /// w_v(F_a) (mm).
    peak_deflection: f64,
    /// Compliance of the initial linear branch, w_v / F below the onset of sliding (mm/N).
    initial_compliance: f64,
    /// F_thre (Coulomb) or F_1 (regularized) (N).
    onset: f64,
    /// Length L - X of the macroslip zone at the turning point F_a (mm): L for Coulomb above
    /// F_thre, 0 below the onset.
    macroslip_length: f64,
}

impl BeamsCycle {
    /// The cycle between +`amplitude` and -`amplitude` for `law`.
    pub fn new(beams: &TwinBeams, law: Law, amplitude: TipForce) -> BeamsCycle {
        let onset = match law {
            Law::Coulomb => beams.threshold_force(),
            Law::Regularized => beams.first_macroslip_force(),
        };
        let macroslip_length = match law {
            Law::Coulomb if amplitude.newtons() > onset => beams.params().length,
            Law::Coulomb => 0.0,
            Law::Regularized => beams.regularized(amplitude).macroslip_length(),
        };
        let mut cycle = BeamsCycle {
            beams: *beams,
            law,
            amplitude: amplitude.newtons(),
            peak_deflection: 0.0,
            initial_compliance: 0.0,
            onset,
            macroslip_length,
        };
        // Below the onset the virgin curve is a straight line through the origin: its slope at any
        // load under the onset is the initial compliance. The onset may lie beyond the largest
        // accepted force (a soft interface): the probe stays below both.
        let probe = 0.5 * TipForce::clamped(onset).newtons();
        cycle.initial_compliance = cycle.virgin(probe) / probe;
        cycle.peak_deflection = cycle.virgin(cycle.amplitude);
        cycle
    }

    /// Peak deflection w_a = w_v(F_a) (mm).
    pub fn peak_deflection(&self) -> f64 {
        self.peak_deflection
    }
}

impl MasingCycle for BeamsCycle {
    fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Where sliding starts on first loading: F_thre (Coulomb) or F_1 (regularized) (N).
    fn onset(&self) -> f64 {
        self.onset
    }

    /// The virgin curve w_v(F) (mm), odd in F; |F| beyond the largest accepted force is taken at
    /// that force (the branches never ask for more than F_a).
    fn virgin(&self, force: f64) -> f64 {
        let f = TipForce::clamped(force.abs());
        let w = match self.law {
            Law::Coulomb => self.beams.coulomb(f).tip_deflection(),
            Law::Regularized => self.beams.regularized(f).tip_deflection(),
        };
        w.copysign(force)
    }

    /// w_a (mm), [`BeamsCycle::peak_deflection`].
    fn peak_response(&self) -> f64 {
        self.peak_deflection
    }

    /// Energy dissipated per cycle by the whole system, both beams' tip forces (N mm), from the
    /// friction work of the plastic slip (docs/theory.md, (C3)):
    /// D = 4 mu P (F_a - F_thre) (L - X)^3 / (E h^2), with X the end of the microslip zone at F_a
    /// (X = 0 for Coulomb, which gives (C4)); zero while the cycle never reaches the onset of sliding.
    /// A product of positive factors: no cancellation at any amplitude.
    fn dissipation(&self) -> f64 {
        if self.amplitude <= self.onset {
            return 0.0;
        }
        dissipation_from_macroslip(&self.beams, self.amplitude, self.macroslip_length)
    }

    /// Peak elastic energy U = 1/2 (2 F_a) w_a of the two tip forces (N mm), the secant definition.
    fn peak_energy(&self) -> f64 {
        self.amplitude * self.peak_deflection
    }

    /// Secant stiffness F_a / w_a of one beam (N/mm); the initial stiffness at zero amplitude.
    fn secant_stiffness(&self) -> f64 {
        if self.peak_deflection > 0.0 {
            self.amplitude / self.peak_deflection
        } else {
            1.0 / self.initial_compliance
        }
    }
}

/// D = 4 b mu P int_0^L s_p dx (N mm): every point slides back and forth by twice its plastic slip
/// s_p at the turning point (Masing, (C1)), against mu P. In the macroslip zone, the last
/// `macroslip_length` a = L - X mm, (B10) gives s_p = 2 (tau_b - mu P)(a^2 - (L - x)^2) / (E h),
/// whose integral is (4/3)(tau_b - mu P) a^3 / (E h); with tau_b - mu P = 3 (F_a - F_thre) / (4 b h),
/// D = 4 mu P (F_a - F_thre) a^3 / (E h^2).
fn dissipation_from_macroslip(beams: &TwinBeams, amplitude: f64, macroslip_length: f64) -> f64 {
    let p = beams.params();
    let excess = amplitude - beams.threshold_force();
    let ratio = macroslip_length / p.half_height;
    4.0 * beams.coulomb_stress() * excess * ratio * ratio * macroslip_length / p.youngs_modulus
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TwinBeamsParams;

    fn paper() -> TwinBeams {
        TwinBeams::new(TwinBeamsParams::PAPER).unwrap()
    }

    #[test]
    fn coulomb_dissipation_matches_the_friction_work_derivation() {
        // (C5), derived from friction work: D = 4 mu P L^3 (F_a - F_thre) / (E h^2).
        let beams = paper();
        for fa in [90.0, 150.0, 400.0] {
            let cycle = BeamsCycle::new(&beams, Law::Coulomb, TipForce::new(fa).unwrap());
            let expected = 4.0 * 0.3 * 1.0 * 200.0_f64.powi(3) * (fa - 80.0) / (210_000.0 * 100.0);
            assert!(
                (cycle.dissipation() / expected - 1.0).abs() < 1e-12,
                "F_a={fa}"
            );
        }
        assert_eq!(
            BeamsCycle::new(&beams, Law::Coulomb, TipForce::new(79.0).unwrap()).dissipation(),
            0.0
        );
    }

    #[test]
    fn loops_close_and_are_symmetric() {
        let beams = paper();
        for law in [Law::Coulomb, Law::Regularized] {
            let cycle = BeamsCycle::new(&beams, law, TipForce::new(150.0).unwrap());
            let wa = cycle.peak_deflection();
            assert!((cycle.unloading(150.0) - wa).abs() < 1e-15);
            assert!((cycle.unloading(-150.0) + wa).abs() < 1e-12 * wa);
            assert!((cycle.reloading(150.0) - wa).abs() < 1e-12 * wa);
            // Point symmetry of the loop: reloading(F) = -unloading(-F).
            for f in [-100.0, -20.0, 0.0, 60.0] {
                assert!((cycle.reloading(f) + cycle.unloading(-f)).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn pure_microslip_dissipates_nothing() {
        let beams = paper();
        let cycle = BeamsCycle::new(
            &beams,
            Law::Regularized,
            TipForce::new(0.99 * beams.first_macroslip_force()).unwrap(),
        );
        assert_eq!(cycle.dissipation(), 0.0);
        assert_eq!(cycle.damping_ratio(), 0.0);
        // The loop degenerates into the line: unloading retraces loading.
        assert!((cycle.unloading(10.0) - cycle.virgin(10.0)).abs() < 1e-15);
    }
}
