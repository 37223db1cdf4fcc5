//! The double-lap joint's interface layout ([`Zoned`]): sliding from both ends, [0, a] and
//! [L - d, L], sticking (Coulomb) or elastic (regularized) between; edges named `a_C`, `L-d_C`
//! (Coulomb) and `a`, `L-d` (regularized).

use crate::kernel::regime::{Law, Regime};
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::zoned::Zoned;

impl Zoned for LapJointProblem {
    const EDGES: [[&'static str; 2]; 2] = [["a_C", "L-d_C"], ["a", "L-d"]];

    fn interface_length(model: &LapModel) -> f64 {
        model.joint.params().length
    }

    fn holding(model: &LapModel, law: Law) -> (Regime, [f64; 2]) {
        let state = match law {
            Law::Coulomb => model.joint.coulomb(model.force),
            Law::Regularized => model.joint.regularized(model.force),
        };
        let length = model.joint.params().length;
        (
            state.regime(),
            [
                state.slide_at_inner_end(),
                length - state.slide_at_cover_ends(),
            ],
        )
    }
}
