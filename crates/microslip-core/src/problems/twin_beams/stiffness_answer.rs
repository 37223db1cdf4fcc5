//! What a K_T does to the twin beams at their force ([`StiffnessAnswer`]).

use crate::kernel::regime::Regime;
use crate::problems::stiffness_answer::StiffnessAnswer;
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};

/// The twin beams at the model's force, with a candidate K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamAnswer {
    /// First-macroslip force F_1 (N).
    pub first_macroslip_force: f64,
    /// End of the microslip zone X (mm).
    pub micro_end: f64,
    /// Tip deflection w(L) (mm).
    pub tip_deflection: f64,
    /// Regime.
    pub regime: Regime,
}

impl StiffnessAnswer for TwinBeamsProblem {
    type Answer = BeamAnswer;

    fn answer(model: &BeamsModel, kt: f64) -> Option<BeamAnswer> {
        let beams = model.beams.with_tangential_stiffness(kt).ok()?;
        let state = beams.regularized(model.force);
        Some(BeamAnswer {
            first_macroslip_force: beams.first_macroslip_force(),
            micro_end: state.micro_zone_end(),
            tip_deflection: state.tip_deflection(),
            regime: state.regime(),
        })
    }

    fn answer_response(answer: &BeamAnswer) -> f64 {
        answer.tip_deflection
    }

    fn coulomb_response(model: &BeamsModel) -> f64 {
        model.beams.coulomb(model.force).tip_deflection()
    }
}
