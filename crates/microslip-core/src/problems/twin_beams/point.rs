//! The twin beams at one force, for the reports and sweeps ([`Pointwise`]).

use crate::kernel::regime::Regime;
use crate::problems::pointwise::Pointwise;
use crate::problems::twin_beams::closed_form::{TipForce, TwinBeams};
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};
use crate::problems::twin_beams::validity::BeamValidity;

/// Everything the reports show about the twin beams at one force, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamPoint {
    /// Tip force F (N).
    pub force: f64,
    /// Coulomb tip deflection (mm).
    pub w_coulomb: f64,
    /// Regularized tip deflection (mm).
    pub w_regularized: f64,
    /// End of the Coulomb stick zone (mm): L in stick, 0 once the interface slides.
    pub stick_end: f64,
    /// End of the microslip zone X (mm); L without macroslip.
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// Where the beam theory stands against continuum FE at this force (V2).
    pub validity: BeamValidity,
}

/// The twin beams at one force.
pub fn beam_point(beams: &TwinBeams, force: TipForce) -> BeamPoint {
    let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
    let w_regularized = regularized.tip_deflection();
    BeamPoint {
        force: force.newtons(),
        w_coulomb: coulomb.tip_deflection(),
        w_regularized,
        stick_end: coulomb.stick_end(),
        micro_end: regularized.micro_zone_end(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        validity: beams.validity_at(force, w_regularized),
    }
}

impl Pointwise for TwinBeamsProblem {
    type Point = BeamPoint;

    fn point(model: &BeamsModel) -> BeamPoint {
        beam_point(&model.beams, model.force)
    }
}
