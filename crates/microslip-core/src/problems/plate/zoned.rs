//! The squeezed plate's interface layout ([`Zoned`]): from the centre, stick up to X_s (Coulomb)
//! or microslip up to X_r (regularized), macroslip beyond.

use crate::kernel::regime::{Law, Regime};
use crate::problems::plate::closed_form::SqueezedPlate;
use crate::problems::plate::problem::SqueezedPlateProblem;
use crate::problems::zoned::Zoned;

impl Zoned for SqueezedPlateProblem {
    const EDGES: [[&'static str; 2]; 2] = [["", "X_s"], ["", "X_r"]];

    fn interface_length(plate: &SqueezedPlate) -> f64 {
        plate.params().half_length
    }

    fn holding(plate: &SqueezedPlate, law: Law) -> (Regime, [f64; 2]) {
        match law {
            Law::Coulomb => {
                let state = plate.coulomb();
                (state.regime(), [0.0, state.stick_end()])
            }
            Law::Regularized => {
                let state = plate.regularized();
                (state.regime(), [0.0, state.micro_zone_end()])
            }
        }
    }
}
