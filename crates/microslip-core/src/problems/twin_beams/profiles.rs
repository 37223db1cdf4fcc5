//! The twin beams' profiles along the interface ([`Profiled`]).

use crate::problems::profiled::{LawProfiles, Profiled, both_along};
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};

impl Profiled for TwinBeamsProblem {
    fn shear_along(model: &BeamsModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        let (coulomb, regularized) = (
            model.beams.coulomb(model.force),
            model.beams.regularized(model.force),
        );
        both_along(
            positions,
            |x| coulomb.shear_stress(x),
            |x| regularized.shear_stress(x),
        )
    }
}
