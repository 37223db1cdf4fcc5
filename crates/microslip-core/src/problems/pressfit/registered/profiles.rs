//! The press fit's profiles along the interface ([`Profiled`]), and its slip.

use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::problems::pressfit::closed_form::{CarriedLoad, FitAxis, FitState};
use crate::problems::problem::Registered;
use crate::problems::profiled::{LawProfiles, Profiled};

impl<K: FitKind> Profiled for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    /// On the shaft, from its loaded face.
    fn shear_along(model: &PressFitModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        along(
            model.fit.axis(K::LOAD),
            model.force,
            positions,
            FitState::shear_at,
        )
    }
}

/// Interface slip s(x) = u_shaft - u_hub (mm; circumferential, r (phi_shaft - phi_hub), for the
/// torque) along `axis` at `load`, at each of `positions`: (Coulomb, regularized).
pub fn slip_along(
    axis: &FitAxis,
    load: CarriedLoad,
    positions: impl Iterator<Item = f64>,
) -> LawProfiles {
    along(axis, load, positions, FitState::slip_at)
}

fn along(
    axis: &FitAxis,
    load: CarriedLoad,
    positions: impl Iterator<Item = f64>,
    at: fn(&FitState, f64) -> f64,
) -> LawProfiles {
    let (coulomb, regularized) = (axis.coulomb(load), axis.regularized(load));
    positions
        .map(|x| ((x, at(&coulomb, x)), (x, at(&regularized, x))))
        .unzip()
}
