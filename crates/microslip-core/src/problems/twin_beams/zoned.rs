//! The twin beams' interface layout ([`Zoned`]): from the clamp, stick up to X_s (Coulomb) or
//! microslip up to X (regularized), macroslip beyond.

use crate::kernel::regime::{Law, Regime};
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};
use crate::problems::zoned::Zoned;

impl Zoned for TwinBeamsProblem {
    const EDGES: [[&'static str; 2]; 2] = [["", "X_s"], ["", "X"]];

    fn interface_length(model: &BeamsModel) -> f64 {
        model.beams.params().length
    }

    fn holding(model: &BeamsModel, law: Law) -> (Regime, [f64; 2]) {
        match law {
            Law::Coulomb => {
                let state = model.beams.coulomb(model.force);
                (state.regime(), [0.0, state.stick_end()])
            }
            Law::Regularized => {
                let state = model.beams.regularized(model.force);
                (state.regime(), [0.0, state.micro_zone_end()])
            }
        }
    }
}
