//! What a K_T does to the double-lap joint at its force ([`StiffnessAnswer`]).

use crate::kernel::regime::Regime;
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::stiffness_answer::StiffnessAnswer;

/// The lap joint at the model's force, with a candidate K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapAnswer {
    /// Force of first sliding F_1 (N).
    pub first_slip_force: f64,
    /// Sliding zones a (from x = 0) and d (from x = L) (mm).
    pub zones: (f64, f64),
    /// Joint displacement Delta (mm).
    pub joint_displacement: f64,
    /// Regime.
    pub regime: Regime,
}

impl StiffnessAnswer for LapJointProblem {
    type Answer = LapAnswer;

    fn answer(model: &LapModel, kt: f64) -> Option<LapAnswer> {
        let joint = model.joint.with_tangential_stiffness(kt).ok()?;
        let state = joint.regularized(model.force);
        Some(LapAnswer {
            first_slip_force: joint.first_slip_force(),
            zones: (state.slide_at_inner_end(), state.slide_at_cover_ends()),
            joint_displacement: state.joint_displacement(),
            regime: state.regime(),
        })
    }

    fn answer_response(answer: &LapAnswer) -> f64 {
        answer.joint_displacement
    }

    fn coulomb_response(model: &LapModel) -> f64 {
        model.joint.coulomb(model.force).joint_displacement()
    }
}
