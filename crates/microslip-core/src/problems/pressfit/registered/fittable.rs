//! The press fit as a fittable problem ([`Fittable`]): Delta against the push-out force. The fit
//! carries no force beyond F_gross = mu p 2 pi r L, so the search keeps to the mu that carry
//! every measured force.

use super::problem::{FitKind, FitProblem};
use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;
use crate::problems::pressfit::closed_form::PressFit;
use crate::problems::pressfit::params::PressFitParams;
use crate::problems::problem::Registered;

impl<K: FitKind> Fittable for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    const LOAD_COLUMN: &'static str = K::LOAD_COLUMN;
    const RESPONSE_COLUMN: &'static str = K::RESPONSE_COLUMN;
    const FITTED: &'static str = K::FITTED;
    const HELD: &'static [K::Key] = K::HELD;

    fn interface_of(fit: &PressFit) -> (f64, f64) {
        let p = fit.params();
        (p.friction, p.tangential_stiffness)
    }

    fn with_interface(fit: &PressFit, mu: f64, kt: f64) -> Result<PressFit, ParamError> {
        PressFit::new(PressFitParams {
            friction: mu,
            tangential_stiffness: kt,
            ..fit.params()
        })
    }

    fn first_macroslip_force(fit: &PressFit) -> f64 {
        fit.axis(K::LOAD).first_slip_load()
    }

    /// F_gross / mu = p 2 pi r L (T_gross / mu = p 2 pi r^2 L).
    fn force_per_friction(fit: &PressFit) -> Option<f64> {
        Some(fit.axis(K::LOAD).gross_load() / fit.params().friction)
    }
}
