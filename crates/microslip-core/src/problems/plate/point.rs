//! The squeezed plate as it is, for the reports and sweeps ([`Pointwise`]).

use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::problems::plate::closed_form::SqueezedPlate;
use crate::problems::plate::problem::SqueezedPlateProblem;
use crate::problems::pointwise::Pointwise;

/// Everything the reports show about the plate at one K_T, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlatePoint {
    /// K_T (MPa/mm).
    pub kt: f64,
    /// Coulomb end displacement (mm).
    pub u_coulomb: f64,
    /// Regularized end displacement (mm).
    pub u_regularized: f64,
    /// End of the Coulomb stick zone X_s (mm); 0 when all slides.
    pub stick_end: f64,
    /// End of the microslip zone X_r (mm); L without macroslip.
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// Where the strip theory stands against a plane-strain continuum (V1).
    pub strip_validity: Validity,
}

/// The plate as it is.
pub fn plate_point(plate: &SqueezedPlate) -> PlatePoint {
    let (coulomb, regularized) = (plate.coulomb(), plate.regularized());
    PlatePoint {
        kt: plate.params().tangential_stiffness,
        u_coulomb: coulomb.end_displacement(),
        u_regularized: regularized.end_displacement(),
        stick_end: coulomb.stick_end(),
        micro_end: regularized.micro_zone_end(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        strip_validity: plate.validity().validity,
    }
}

impl Pointwise for SqueezedPlateProblem {
    type Point = PlatePoint;

    fn point(plate: &SqueezedPlate) -> PlatePoint {
        plate_point(plate)
    }
}
