//! The squeezed plate's profiles along the half-plate ([`Profiled`]), and its contact pressure.

use crate::problems::plate::closed_form::SqueezedPlate;
use crate::problems::plate::problem::SqueezedPlateProblem;
use crate::problems::profiled::{LawProfiles, Profiled, both_along};

impl Profiled for SqueezedPlateProblem {
    fn shear_along(plate: &SqueezedPlate, positions: impl Iterator<Item = f64>) -> LawProfiles {
        let (coulomb, regularized) = (plate.coulomb(), plate.regularized());
        both_along(
            positions,
            |x| coulomb.shear_stress(x),
            |x| regularized.shear_stress(x),
        )
    }
}

/// Contact pressure ratio P_r / P at each of `positions` along the half-plate.
pub fn contact_pressure_along(
    plate: &SqueezedPlate,
    positions: impl Iterator<Item = f64>,
) -> Vec<(f64, f64)> {
    let pressure = plate.contact_pressure();
    positions.map(|x| (x, pressure.ratio(x))).collect()
}
