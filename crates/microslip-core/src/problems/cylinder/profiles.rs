//! The cylinder's profiles across the contact ([`Profiled`]): the shear q(x) and the slip s(x),
//! x from the centre (both are even in x).

use super::problem::{CylinderModel, CylinderProblem};
use crate::problems::profiled::{LawProfiles, Profiled, both_along};

impl Profiled for CylinderProblem {
    /// q(x) (MPa): Mindlin's (H7) and the regularized law's.
    fn shear_along(model: &CylinderModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        let (coulomb, regularized) = (
            model.cylinder.coulomb(model.load),
            model.cylinder.regularized(model.load),
        );
        both_along(
            positions,
            |x| coulomb.shear_at(x),
            |x| regularized.shear_at(x),
        )
    }
}

/// Slip s(x) (mm) at each of `positions` (mm from the centre): (Mindlin, regularized).
pub fn slip_along(model: &CylinderModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
    let (coulomb, regularized) = (
        model.cylinder.coulomb(model.load),
        model.cylinder.regularized(model.load),
    );
    both_along(
        positions,
        |x| coulomb.slip_at(x),
        |x| regularized.slip_at(x),
    )
}

/// The Hertz pressure p(x) and the friction limit mu p(x) (MPa) at each of `positions`: the
/// envelope the shear profiles are drawn against.
pub fn friction_limit_along(
    model: &CylinderModel,
    positions: impl Iterator<Item = f64>,
) -> Vec<(f64, f64)> {
    let mu = model.cylinder.params().friction;
    positions
        .map(|x| (x, mu * model.cylinder.pressure_at(x)))
        .collect()
}
