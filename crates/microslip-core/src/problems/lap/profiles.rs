//! The double-lap joint's profiles along the overlap ([`Profiled`]), and its slip.

use crate::problems::lap::closed_form::LapState;
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::profiled::{LawProfiles, Profiled};

impl Profiled for LapJointProblem {
    /// On the inner plate.
    fn shear_along(model: &LapModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        along(model, positions, LapState::shear_at)
    }
}

/// Interface slip s(x) = u_inner - u_cover (mm) at each of `positions` along the overlap:
/// (Coulomb, regularized).
pub fn slip_along(model: &LapModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
    along(model, positions, LapState::slip_at)
}

/// A profile `at` of both laws' states at the model's force, at `positions`.
fn along(
    model: &LapModel,
    positions: impl Iterator<Item = f64>,
    at: fn(&LapState, f64) -> f64,
) -> LawProfiles {
    let (coulomb, regularized) = (
        model.joint.coulomb(model.force),
        model.joint.regularized(model.force),
    );
    positions
        .map(|x| ((x, at(&coulomb, x)), (x, at(&regularized, x))))
        .unzip()
}
