//! Where the press fit's 1-D theory stands (docs/theory.md section 18, (S9)): the sizes of what
//! it leaves out, computable from the inputs. The theory assumes Lamé's pressure p uniform over
//! L, untouched by the load, and each member's axial strain (or twist) uniform over its section.
//! Each assumption fails by an amount these numbers measure; none is calibrated yet (the
//! axisymmetric continuum that would calibrate them is issue 44's item 2), so the verdict is
//! [`Validity::NotCalibrated`] whatever they say.

use super::closed_form::{CarriedLoad, FitAxis, PressFit};
use crate::kernel::validity::Validity;

/// The sizes of what the 1-D theory leaves out, for one fit at one push-out force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitValidity {
    /// (ro - r) / L: the hub's end faces raise the contact pressure over a length of the order
    /// of its wall; the larger this, the less of L sees Lamé's uniform p.
    pub end_zone_over_length: f64,
    /// (1/lambda) / (thicker wall): the length over which the shear is handed on, over the
    /// depth it must diffuse through for the section's strain to be uniform; small values are
    /// where the shear-lag assumption is doubtful.
    pub decay_over_wall: f64,
    /// The largest Poisson change of the interference the load makes, over delta:
    /// max(nus F / (Es As), nuh F / (Eh Ah)) r / delta. The shaft's compression swells it and
    /// raises p at the loaded face, the hub's shrinks its bore less; the theory keeps p.
    pub poisson_coupling: f64,
    /// delta / r: the strain of the shrink fit, which linear elasticity needs small.
    pub interference_strain: f64,
    /// The verdict: not calibrated (module docs).
    pub validity: Validity,
}

impl PressFit {
    /// The sizes of what the theory leaves out at push-out `force` (S9).
    pub fn validity(&self, force: CarriedLoad) -> PressFitValidity {
        let p = self.params();
        let axis: &FitAxis = self.axial();
        let thicker = (p.fit_radius - p.bore_radius).max(p.outer_radius - p.fit_radius);
        let shaft = p.shaft_poisson * force.value() / (p.shaft_modulus * p.shaft_area());
        let hub = p.hub_poisson * force.value() / (p.hub_modulus * p.hub_area());
        PressFitValidity {
            end_zone_over_length: (p.outer_radius - p.fit_radius) / p.length,
            decay_over_wall: 1.0 / (axis.decay_rate() * thicker),
            poisson_coupling: shaft.max(hub) * p.fit_radius / p.interference,
            interference_strain: p.interference / p.fit_radius,
            validity: Validity::NotCalibrated,
        }
    }
}
