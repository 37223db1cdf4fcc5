//! The press fit at one force, for the reports and sweeps ([`Pointwise`]).

use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::kernel::regime::Regime;
use crate::problems::pointwise::Pointwise;
use crate::problems::pressfit::closed_form::{CarriedLoad, FitAxis, FitState};
use crate::problems::problem::Registered;

/// Everything the reports show about the fit at one push-out force, both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitPoint {
    /// Push-out force F (N).
    pub force: f64,
    /// Coulomb Delta (mm).
    pub delta_coulomb: f64,
    /// Regularized Delta (mm).
    pub delta_regularized: f64,
    /// Coulomb sliding zones from the loaded face and from the held face (mm).
    pub zones_coulomb: (f64, f64),
    /// Regularized sliding zones (mm).
    pub zones_regularized: (f64, f64),
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
}

/// The fit at one load of `axis`.
pub fn fit_point(axis: &FitAxis, force: CarriedLoad) -> FitPoint {
    let (coulomb, regularized) = (axis.coulomb(force), axis.regularized(force));
    let zones = |s: &FitState| (s.slide_from_loaded_face(), s.slide_from_held_face());
    FitPoint {
        force: force.value(),
        delta_coulomb: coulomb.response(),
        delta_regularized: regularized.response(),
        zones_coulomb: zones(&coulomb),
        zones_regularized: zones(&regularized),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
    }
}

impl<K: FitKind> Pointwise for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    type Point = FitPoint;

    fn point(model: &PressFitModel) -> FitPoint {
        fit_point(model.fit.axis(K::LOAD), model.force)
    }
}
