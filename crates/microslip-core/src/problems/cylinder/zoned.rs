//! The cylinder's interface layout ([`Zoned`]), from the centre to the contact's edge: the
//! stick zone (Coulomb) or the microslip zone (regularized) [0, c], sliding from c to a; edges
//! named `c_C` (Mindlin's) and `c`.

use super::problem::{CylinderModel, CylinderProblem};
use crate::kernel::regime::{Law, Regime};
use crate::problems::zoned::Zoned;

impl Zoned for CylinderProblem {
    const EDGES: [[&'static str; 2]; 2] = [["", "c_C"], ["", "c"]];

    /// The half-width a: the strip runs from the centre to the edge (the layout is even in x).
    fn interface_length(model: &CylinderModel) -> f64 {
        model.cylinder.half_width()
    }

    fn holding(model: &CylinderModel, law: Law) -> (Regime, [f64; 2]) {
        match law {
            Law::Coulomb => {
                let state = model.cylinder.coulomb(model.load);
                (state.regime(), [0.0, state.stick_half_width()])
            }
            Law::Regularized => {
                let state = model.cylinder.regularized(model.load);
                (state.regime(), [0.0, state.micro_half_width()])
            }
        }
    }
}
