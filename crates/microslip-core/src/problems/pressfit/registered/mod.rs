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
use super::{PUSH_OUT_BOUND, QUANTITIES, TORQUE_BOUND, TORQUE_QUANTITIES};
use crate::kernel::params::ParamSpec;
use crate::problems::problem::ParamKey;
use crate::problems::{Description, Param};

/// Every parameter of the push-out as a [`Param`], in display order (the torque, `T`, belongs to
/// the twisted fit's problem: the folder's module docs).
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

/// A key of the twisted fit: one of the fit's parameters, `T` for `F`
/// ([`PressFitParam::TORQUE_KEYS`]). A type of its own because the registry's `Param` wraps one
/// key type per problem, and a key type's [`ParamKey::KEYS`] are its problem's: `PressFitParam`'s
/// are the push-out's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TorqueParam(pub PressFitParam);

impl TorqueParam {
    /// The twisted fit's keys, in display order.
    pub const KEYS: [TorqueParam; 12] = {
        let keys = PressFitParam::TORQUE_KEYS;
        let mut all = [TorqueParam(PressFitParam::Torque); 12];
        let mut i = 0;
        while i < all.len() {
            all[i] = TorqueParam(keys[i]);
            i += 1;
        }
        all
    };

    /// Its own keys, r to delta (what a fit of mu and K_T holds: `Fittable::HELD`).
    pub const STRUCTURE: &'static [TorqueParam] = Self::KEYS.split_at(9).0;
}

impl ParamKey for TorqueParam {
    const KEYS: &'static [TorqueParam] = &TorqueParam::KEYS;

    fn spec(self) -> ParamSpec {
        self.0.spec()
    }
}

/// Every parameter of the twisted fit as a [`Param`], in display order.
const TORQUE_PARAMS: [Param; 12] = {
    let mut all = [Param::PressFitTorque(TorqueParam::KEYS[0]); 12];
    let mut i = 0;
    while i < all.len() {
        all[i] = Param::PressFitTorque(TorqueParam::KEYS[i]);
        i += 1;
    }
    all
};

/// The press fit twisted, as the generic layers see it.
pub(crate) const TORQUE_DESCRIPTION: Description = Description {
    key: "pressfit-torque",
    title: "press fit twisted",
    summary: "Press fit twisted in its hub (shear lag, docs/theory.md section 18, (S6))",
    paper_preset: "pressfit-ccx98-torque",
    params: &TORQUE_PARAMS,
    response_symbol: "theta",
    load: Some(Param::PressFitTorque(TorqueParam(PressFitParam::Torque))),
    regime_scale_name: "T_gross",
    load_bound: Some(TORQUE_BOUND),
    load_span: 1.0,
    quantities: &TORQUE_QUANTITIES,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::ModelKind;

    /// The torque's keys parse as their own, T among them and F not; their places are the
    /// torque's order, not the push-out's.
    #[test]
    fn the_torque_keys_parse_t_and_refuse_f() {
        let t = TorqueParam::parse_key("T", ModelKind::PressFit).unwrap();
        assert_eq!(t, TorqueParam(PressFitParam::Torque));
        assert_eq!(t.index(), 11);
        assert_eq!(TorqueParam(PressFitParam::Stiffness).index(), 10);
        assert!(TorqueParam::parse_key("F", ModelKind::PressFit).is_err());
        let held: Vec<&str> = TorqueParam::STRUCTURE
            .iter()
            .map(|k| k.spec().name)
            .collect();
        assert_eq!(
            held,
            ["r", "ri", "ro", "L", "Es", "nus", "Eh", "nuh", "delta"]
        );
    }
}
