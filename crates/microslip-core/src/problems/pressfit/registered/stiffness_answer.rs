//! What a K_T does to the press fit at its force ([`StiffnessAnswer`]).

use super::problem::{PressFitModel, PressFitProblem};
use crate::kernel::regime::Regime;
use crate::problems::stiffness_answer::StiffnessAnswer;

/// The fit at the model's force, with a candidate K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitAnswer {
    /// Force of first sliding F_1 (N).
    pub first_slip_force: f64,
    /// Sliding zones from the loaded and from the held face (mm).
    pub zones: (f64, f64),
    /// Delta (mm).
    pub displacement: f64,
    /// Regime.
    pub regime: Regime,
}

impl StiffnessAnswer for PressFitProblem {
    type Answer = FitAnswer;

    fn answer(model: &PressFitModel, kt: f64) -> Option<FitAnswer> {
        let fit = model.fit.with_tangential_stiffness(kt).ok()?;
        let state = fit.regularized(model.force);
        Some(FitAnswer {
            first_slip_force: fit.first_slip_force(),
            zones: (state.slide_from_loaded_face(), state.slide_from_held_face()),
            displacement: state.response(),
            regime: state.regime(),
        })
    }

    fn answer_response(answer: &FitAnswer) -> f64 {
        answer.displacement
    }

    fn coulomb_response(model: &PressFitModel) -> f64 {
        model.fit.coulomb(model.force).response()
    }
}
