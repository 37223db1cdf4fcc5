//! The press fit's interface layout ([`Zoned`]): sliding from both faces, holding between.

use super::problem::{PressFitModel, PressFitProblem};
use crate::kernel::regime::{Law, Regime};
use crate::problems::zoned::Zoned;

impl Zoned for PressFitProblem {
    const EDGES: [[&'static str; 2]; 2] = [["a_C", "L-d_C"], ["a", "L-d"]];

    fn interface_length(model: &PressFitModel) -> f64 {
        model.fit.params().length
    }

    fn holding(model: &PressFitModel, law: Law) -> (Regime, [f64; 2]) {
        let state = model.fit.axial().solve(law, model.force);
        (state.regime(), state.holding_zone())
    }
}
