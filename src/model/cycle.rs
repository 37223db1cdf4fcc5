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

use super::twin_beams::{TipForce, TwinBeams};

/// Which friction law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// Plain Coulomb.
    Coulomb,
    /// Regularized Coulomb (tau = K_T slip up to mu P).
    Regularized,
}

/// Gauss-Legendre nodes and weights on [-1, 1], 16 points.
const GAUSS16: [(f64, f64); 8] = [
    (0.095_012_509_837_637_44, 0.189_450_610_455_068_5),
    (0.281_603_550_779_258_9, 0.182_603_415_044_923_6),
    (0.458_016_777_657_227_4, 0.169_156_519_395_002_5),
    (0.617_876_244_402_643_8, 0.149_595_988_816_576_7),
    (0.755_404_408_355_003, 0.124_628_971_255_533_9),
    (0.865_631_202_387_831_8, 0.095_158_511_682_492_8),
    (0.944_575_023_073_232_6, 0.062_253_523_938_647_9),
    (0.989_400_934_991_649_9, 0.027_152_459_411_754_1),
];

/// Panels of the quadrature of the excess deflection over [F_onset, F_a].
const PANELS: usize = 8;

/// One cycle of amplitude F_a for one law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    beams: TwinBeams,
    law: Law,
    amplitude: f64,
    /// w_v(F_a) (mm).
    peak_deflection: f64,
    /// Compliance of the initial linear branch, w_v / F below the onset of sliding (mm/N).
    initial_compliance: f64,
    /// F_thre (Coulomb) or F_1 (regularized) (N).
    onset: f64,
}

impl Cycle {
    /// The cycle between +`amplitude` and -`amplitude` for `law`.
    pub fn new(beams: &TwinBeams, law: Law, amplitude: TipForce) -> Cycle {
        let onset = match law {
            Law::Coulomb => beams.threshold_force(),
            Law::Regularized => beams.first_macroslip_force(),
        };
        let mut cycle = Cycle {
            beams: *beams,
            law,
            amplitude: amplitude.newtons(),
            peak_deflection: 0.0,
            initial_compliance: 0.0,
            onset,
        };
        // Below the onset the virgin curve is a straight line through the origin: its slope at any
        // load under the onset is the initial compliance.
        let probe = 0.5 * onset;
        cycle.initial_compliance = cycle.virgin(probe) / probe;
        cycle.peak_deflection = cycle.virgin(cycle.amplitude);
        cycle
    }

    /// The amplitude F_a (N).
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Where sliding starts on first loading: F_thre (Coulomb) or F_1 (regularized) (N).
    pub fn onset(&self) -> f64 {
        self.onset
    }

    /// The virgin curve w_v(F) (mm), odd in F.
    pub fn virgin(&self, force: f64) -> f64 {
        let Ok(f) = TipForce::new(force.abs()) else {
            return 0.0;
        };
        let w = match self.law {
            Law::Coulomb => self.beams.coulomb(f).tip_deflection(),
            Law::Regularized => self.beams.regularized(f).tip_deflection(),
        };
        w.copysign(force)
    }

    /// Peak deflection w_a = w_v(F_a) (mm).
    pub fn peak_deflection(&self) -> f64 {
        self.peak_deflection
    }

    /// Unloading branch from (F_a, w_a) down to -F_a (mm).
    pub fn unloading(&self, force: f64) -> f64 {
        self.peak_deflection - 2.0 * self.virgin(0.5 * (self.amplitude - force))
    }

    /// Reloading branch from (-F_a, -w_a) up to F_a (mm).
    pub fn reloading(&self, force: f64) -> f64 {
        -self.peak_deflection + 2.0 * self.virgin(0.5 * (self.amplitude + force))
    }

    /// Excess of the virgin curve over its initial straight line, w_v(F) - c F (mm), zero below the
    /// onset of sliding.
    fn excess(&self, force: f64) -> f64 {
        if force <= self.onset {
            0.0
        } else {
            self.virgin(force) - self.initial_compliance * force
        }
    }

    /// Integral of the excess over [onset, F_a] (N mm). Closed form for Coulomb (the excess is
    /// 3 c_s (F - F_thre)); for the regularized law Gauss-Legendre in u with F = F_1 + (F_a - F_1) u^2,
    /// which absorbs the square-root onset of macroslip at F_1.
    fn excess_integral(&self) -> f64 {
        let span = self.amplitude - self.onset;
        if span <= 0.0 {
            return 0.0;
        }
        if self.law == Law::Coulomb {
            return 1.5 * self.initial_compliance * span * span;
        }
        let mut sum = 0.0;
        for panel in 0..PANELS {
            let (a, b) = (
                panel as f64 / PANELS as f64,
                (panel + 1) as f64 / PANELS as f64,
            );
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for &(node, weight) in &GAUSS16 {
                for u in [mid - half * node, mid + half * node] {
                    let force = self.onset + span * u * u;
                    sum += weight * half * self.excess(force) * 2.0 * span * u;
                }
            }
        }
        sum
    }

    /// Energy dissipated per cycle by the whole system, both beams' tip forces (N mm):
    /// D = 2 x loop area = 16 [delta_a F_a / 2 - int_onset^F_a delta dF], delta the excess deflection
    /// (docs/theory.md, (C3)). Zero while the cycle never reaches the onset of sliding.
    pub fn dissipation(&self) -> f64 {
        if self.amplitude <= self.onset {
            return 0.0;
        }
        let peak_excess = self.excess(self.amplitude);
        (16.0 * (0.5 * peak_excess * self.amplitude - self.excess_integral())).max(0.0)
    }

    /// Peak elastic energy U = 1/2 (2 F_a) w_a of the two tip forces (N mm), the secant definition.
    pub fn peak_energy(&self) -> f64 {
        self.amplitude * self.peak_deflection
    }

    /// Equivalent viscous damping ratio D / (4 pi U) (-); 0 at zero amplitude.
    pub fn damping_ratio(&self) -> f64 {
        let u = self.peak_energy();
        if u > 0.0 {
            self.dissipation() / (4.0 * std::f64::consts::PI * u)
        } else {
            0.0
        }
    }

    /// Secant stiffness F_a / w_a of one beam (N/mm); the initial stiffness at zero amplitude.
    pub fn secant_stiffness(&self) -> f64 {
        if self.peak_deflection > 0.0 {
            self.amplitude / self.peak_deflection
        } else {
            1.0 / self.initial_compliance
        }
    }
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
            let cycle = Cycle::new(&beams, Law::Coulomb, TipForce::new(fa).unwrap());
            let expected = 4.0 * 0.3 * 1.0 * 200.0_f64.powi(3) * (fa - 80.0) / (210_000.0 * 100.0);
            assert!(
                (cycle.dissipation() / expected - 1.0).abs() < 1e-12,
                "F_a={fa}"
            );
        }
        assert_eq!(
            Cycle::new(&beams, Law::Coulomb, TipForce::new(79.0).unwrap()).dissipation(),
            0.0
        );
    }

    #[test]
    fn loops_close_and_are_symmetric() {
        let beams = paper();
        for law in [Law::Coulomb, Law::Regularized] {
            let cycle = Cycle::new(&beams, law, TipForce::new(150.0).unwrap());
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
        let cycle = Cycle::new(
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
