//! The double-lap joint at one force, for the reports and sweeps ([`Pointwise`]).

use crate::kernel::regime::Regime;
use crate::problems::lap::closed_form::{JointForce, LapJoint, LapState};
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::pointwise::Pointwise;

/// Everything the reports show about the joint at one force, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapPoint {
    /// Force through the joint F (N).
    pub force: f64,
    /// Coulomb joint displacement Delta (mm).
    pub delta_coulomb: f64,
    /// Regularized joint displacement Delta (mm).
    pub delta_regularized: f64,
    /// Coulomb sliding zones from x = 0 (a) and from x = L (d) (mm).
    pub zones_coulomb: (f64, f64),
    /// Regularized sliding zones a and d (mm).
    pub zones_regularized: (f64, f64),
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// The shear-lag envelope's bound on Delta's difference from a continuum (L14), a fraction;
    /// `None` where it is not calibrated.
    pub shear_lag_within: Option<f64>,
}

/// The joint at one force.
pub fn lap_point(joint: &LapJoint, force: JointForce) -> LapPoint {
    let (coulomb, regularized) = (joint.coulomb(force), joint.regularized(force));
    let zones = |s: &LapState| (s.slide_at_inner_end(), s.slide_at_cover_ends());
    LapPoint {
        force: force.newtons(),
        delta_coulomb: coulomb.joint_displacement(),
        delta_regularized: regularized.joint_displacement(),
        zones_coulomb: zones(&coulomb),
        zones_regularized: zones(&regularized),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        shear_lag_within: joint
            .validity_at(force, regularized.joint_displacement())
            .expected_error,
    }
}

impl Pointwise for LapJointProblem {
    type Point = LapPoint;

    fn point(model: &LapModel) -> LapPoint {
        lap_point(&model.joint, model.force)
    }
}
