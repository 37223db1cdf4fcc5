//! The press fit as a fittable problem ([`Fittable`]): Delta against the push-out force. The fit
//! carries no force beyond F_gross = mu p 2 pi r L, so the search keeps to the mu that carry
//! every measured force.

use super::problem::PressFitProblem;
use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;
use crate::problems::pressfit::closed_form::PressFit;
use crate::problems::pressfit::params::{PressFitParam, PressFitParams};

impl Fittable for PressFitProblem {
    const RESPONSE_COLUMN: &'static str = "Delta_mm";
    const FITTED: &'static str = "press fit";
    const HELD: &'static [PressFitParam] = PressFitParam::STRUCTURE;

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
        fit.first_slip_force()
    }

    /// F_gross / mu = p 2 pi r L.
    fn force_per_friction(fit: &PressFit) -> Option<f64> {
        Some(fit.gross_slip_force() / fit.params().friction)
    }
}
