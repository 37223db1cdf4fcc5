//! The press fit's interface layout ([`Zoned`]): sliding from both faces, holding between.

use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::kernel::regime::{Law, Regime};
use crate::problems::problem::Registered;
use crate::problems::zoned::Zoned;

impl<K: FitKind> Zoned for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    const EDGES: [[&'static str; 2]; 2] = [["a_C", "L-d_C"], ["a", "L-d"]];

    fn interface_length(model: &PressFitModel) -> f64 {
        model.fit.params().length
    }

    fn holding(model: &PressFitModel, law: Law) -> (Regime, [f64; 2]) {
        let state = model.fit.axis(K::LOAD).solve(law, model.force);
        (state.regime(), state.holding_zone())
    }
}
