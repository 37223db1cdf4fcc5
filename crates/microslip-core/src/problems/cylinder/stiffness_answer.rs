//! What a K_T does to the cylinder at its tangential load ([`StiffnessAnswer`]).

use super::problem::{CylinderModel, CylinderProblem};
use crate::kernel::regime::Regime;
use crate::problems::stiffness_answer::StiffnessAnswer;

/// The cylinder at the model's load, with a candidate K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderAnswer {
    /// K_T a / E* (-).
    pub stiffness_group: f64,
    /// Microslip zone half-width c (mm).
    pub zone: f64,
    /// Edge slip s(a) (mm).
    pub edge_slip: f64,
    /// Centre slip s(0) (mm).
    pub centre_slip: f64,
    /// Regime.
    pub regime: Regime,
}

impl StiffnessAnswer for CylinderProblem {
    type Answer = CylinderAnswer;

    fn answer(model: &CylinderModel, kt: f64) -> Option<CylinderAnswer> {
        let cylinder = model.cylinder.with_tangential_stiffness(kt).ok()?;
        let state = cylinder.regularized(model.load);
        Some(CylinderAnswer {
            stiffness_group: cylinder.stiffness_group(),
            zone: state.micro_half_width(),
            edge_slip: state.edge_slip(),
            centre_slip: state.centre_slip(),
            regime: state.regime(),
        })
    }

    /// The edge slip s(a) (mm).
    fn answer_response(answer: &CylinderAnswer) -> f64 {
        answer.edge_slip
    }

    /// Mindlin's s(a) (mm).
    fn coulomb_response(model: &CylinderModel) -> f64 {
        model.cylinder.coulomb(model.load).edge_slip()
    }
}
