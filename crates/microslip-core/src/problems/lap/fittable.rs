//! The double-lap joint as a fittable problem ([`Fittable`]): Delta against the force through
//! the joint (docs/theory.md (L11) and section 3b). The joint carries no force beyond F_gross =
//! 2 b mu P L, so the fit searches only the mu that carry every measured force.

use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;
use crate::problems::lap::closed_form::LapJoint;
use crate::problems::lap::params::{LapParam, LapParams};
use crate::problems::lap::problem::LapJointProblem;

impl Fittable for LapJointProblem {
    const RESPONSE_COLUMN: &'static str = "Delta_mm";
    const FITTED: &'static str = "double-lap joint";
    const HELD: &'static [LapParam] = &[
        LapParam::Length,
        LapParam::Width,
        LapParam::InnerThickness,
        LapParam::CoverThickness,
        LapParam::InnerModulus,
        LapParam::CoverModulus,
        LapParam::Pressure,
    ];

    fn interface_of(joint: &LapJoint) -> (f64, f64) {
        let p = joint.params();
        (p.friction, p.tangential_stiffness)
    }

    fn with_interface(joint: &LapJoint, mu: f64, kt: f64) -> Result<LapJoint, ParamError> {
        LapJoint::new(LapParams {
            friction: mu,
            tangential_stiffness: kt,
            ..joint.params()
        })
    }

    /// F_1, where the first end starts to slide (L2).
    fn first_macroslip_force(joint: &LapJoint) -> f64 {
        joint.first_slip_force()
    }

    /// F_gross / mu = 2 b P L: F_gross grows in proportion to mu.
    fn force_per_friction(joint: &LapJoint) -> Option<f64> {
        let p = joint.params();
        Some(p.gross_slip_force() / p.friction)
    }
}
