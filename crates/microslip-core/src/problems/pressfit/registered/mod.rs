//! The press fit as the registry's generic layers see it: the trait impls that name the types the
//! registry generates (`Param::PressFit`, `Inputs::PressFit`, `Model::PressFit`). Each impl is a
//! delegation to the typed press fit of the folder above.

pub mod cross_check;
pub mod fittable;
pub mod load_driven;
pub mod point;
pub mod problem;
pub mod profiles;
pub mod stiffness_answer;
pub mod zoned;

use super::params::PressFitParam;
use super::{PUSH_OUT_BOUND, QUANTITIES};
use crate::problems::{Description, Param};

/// Every parameter of the push-out as a [`Param`], in display order (the torque, `T`, belongs to
/// the torsion's problem, to come: the folder's module docs).
const PARAMS: [Param; PressFitParam::PUSH_OUT.len()] = {
    let keys = PressFitParam::PUSH_OUT;
    let mut all = [Param::PressFit(keys[0]); PressFitParam::PUSH_OUT.len()];
    let mut i = 0;
    while i < all.len() {
        all[i] = Param::PressFit(keys[i]);
        i += 1;
    }
    all
};

/// The press fit pushed out, as the generic layers see it.
pub(crate) const DESCRIPTION: Description = Description {
    key: "pressfit",
    title: "press fit",
    summary: "Press fit pushed out of its hub (shear lag, docs/theory.md section 18)",
    paper_preset: "pressfit-ccx98",
    params: &PARAMS,
    response_symbol: "Delta",
    load: Some(Param::PressFit(PressFitParam::Force)),
    regime_scale_name: "F_gross",
    load_bound: Some(PUSH_OUT_BOUND),
    load_span: 1.0,
    quantities: &QUANTITIES,
};
