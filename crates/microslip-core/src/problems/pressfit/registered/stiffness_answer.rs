//! What a K_T does to the press fit at its force ([`StiffnessAnswer`]).

use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::kernel::regime::Regime;
use crate::problems::problem::Registered;
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

impl<K: FitKind> StiffnessAnswer for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    type Answer = FitAnswer;

    fn answer(model: &PressFitModel, kt: f64) -> Option<FitAnswer> {
        let fit = model.fit.with_tangential_stiffness(kt).ok()?;
        let axis = fit.axis(K::LOAD);
        let state = axis.regularized(model.force);
        Some(FitAnswer {
            first_slip_force: axis.first_slip_load(),
            zones: (state.slide_from_loaded_face(), state.slide_from_held_face()),
            displacement: state.response(),
            regime: state.regime(),
        })
    }

    fn answer_response(answer: &FitAnswer) -> f64 {
        answer.displacement
    }

    fn coulomb_response(model: &PressFitModel) -> f64 {
        model.fit.axis(K::LOAD).coulomb(model.force).response()
    }
}
