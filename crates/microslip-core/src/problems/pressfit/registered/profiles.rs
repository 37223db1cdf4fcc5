//! The press fit's profiles along the interface ([`Profiled`]), and its slip.

use super::problem::{PressFitModel, PressFitProblem};
use crate::problems::pressfit::closed_form::FitState;
use crate::problems::profiled::{LawProfiles, Profiled};

impl Profiled for PressFitProblem {
    /// On the shaft, from its loaded face.
    fn shear_along(model: &PressFitModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        along(model, positions, FitState::shear_at)
    }
}

/// Interface slip s(x) = u_shaft - u_hub (mm) at each of `positions`: (Coulomb, regularized).
pub fn slip_along(model: &PressFitModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
    along(model, positions, FitState::slip_at)
}

fn along(
    model: &PressFitModel,
    positions: impl Iterator<Item = f64>,
    at: fn(&FitState, f64) -> f64,
) -> LawProfiles {
    let (coulomb, regularized) = (
        model.fit.coulomb(model.force),
        model.fit.regularized(model.force),
    );
    positions
        .map(|x| ((x, at(&coulomb, x)), (x, at(&regularized, x))))
        .unzip()
}
