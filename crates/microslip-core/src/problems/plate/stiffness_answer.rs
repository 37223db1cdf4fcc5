//! What a K_T does to the squeezed plate ([`StiffnessAnswer`]).

use crate::kernel::regime::Regime;
use crate::problems::plate::closed_form::SqueezedPlate;
use crate::problems::plate::problem::SqueezedPlateProblem;
use crate::problems::stiffness_answer::StiffnessAnswer;

/// The plate with a candidate K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateAnswer {
    /// End displacement u(L) (mm).
    pub end_displacement: f64,
    /// End of the microslip zone X_r (mm).
    pub micro_end: f64,
    /// Regime.
    pub regime: Regime,
}

impl StiffnessAnswer for SqueezedPlateProblem {
    type Answer = PlateAnswer;

    fn answer(plate: &SqueezedPlate, kt: f64) -> Option<PlateAnswer> {
        let state = plate.with_tangential_stiffness(kt).ok()?.regularized();
        Some(PlateAnswer {
            end_displacement: state.end_displacement(),
            micro_end: state.micro_zone_end(),
            regime: state.regime(),
        })
    }

    fn answer_response(answer: &PlateAnswer) -> f64 {
        answer.end_displacement
    }

    fn coulomb_response(plate: &SqueezedPlate) -> f64 {
        plate.coulomb().end_displacement()
    }
}
