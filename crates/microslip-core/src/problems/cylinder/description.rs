//! The cylinder as the generic layers see it: its [`Description`] and the quantities a target can
//! be set on. (In its own file rather than in `mod.rs` only because it names the registry's
//! `Param::Cylinder`, which exists once the registry lists the cylinder.)

use super::params::CylinderParam;
use super::problem::CylinderModel;
use crate::problems::quantity::ratio_to_coulomb;
use crate::problems::{Description, LoadBound, Param, Quantity, QuantityName, Solution};

/// The Hertzian cylinder as the generic layers see it.
pub(crate) const DESCRIPTION: Description = Description {
    key: "cylinder",
    title: "Hertzian cylinder on a flat",
    summary: "Hertzian cylinder on a flat under a tangential line load (Cattaneo-Mindlin, \
              regularized; docs/theory.md, the Hertzian cylinder)",
    paper_preset: "cylinder-steel-pad",
    params: &PARAMS,
    response_symbol: "sa",
    load: Some(Param::Cylinder(CylinderParam::TangentialLoad)),
    regime_scale_name: "Q_gross",
    load_bound: Some(LoadBound {
        symbol: "Q_gross",
        formula: "mu P",
        beyond: "the cylinder slides over the flat beyond it",
    }),
    load_span: 1.0,
    quantities: &[
        QuantityName {
            quantity: Quantity::Response,
            name: "s(a)",
            aliases: &["sa", "s_a"],
            meaning: "slip at the contact's edge (the fretting slip amplitude), regularized law",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::MicroEnd,
            name: "c",
            aliases: &[],
            meaning: "half-width of the microslip zone (q = K_T s < mu p), regularized law",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::Ratio,
            name: "ratio",
            aliases: &[],
            meaning: "s(a) regularized / s(a) Mindlin",
            unit: "",
        },
        // TODO(c1b): `D` (Quantity::Dissipation, "energy dissipated per cycle of amplitude Q",
        // N mm per mm) and `zeta` (Quantity::DampingRatio) once `cycle.rs` lands; their arms in
        // `quantity` below return None until then.
    ],
};

/// The value of `quantity` for `model` (see [`Quantity`]); `None` for a quantity the cylinder has
/// not (its sliding zones are at both edges, symmetric: no start or end zone; with a finite K_T
/// the edges slide from the first newton, so no first-macroslip load), where it is not defined
/// (the ratio at Q = 0) or not finite.
pub(crate) fn quantity(model: &CylinderModel, quantity: Quantity) -> Option<f64> {
    let value = match quantity {
        Quantity::Response => model.cylinder.regularized(model.load).response(),
        Quantity::MicroEnd => model.cylinder.regularized(model.load).zone_end(),
        Quantity::Ratio => ratio_to_coulomb(
            model.cylinder.regularized(model.load).response(),
            model.cylinder.coulomb(model.load).response(),
        )?,
        // TODO(c1b): the cycle's D and zeta at amplitude Q.
        Quantity::Dissipation | Quantity::DampingRatio => return None,
        Quantity::SlideFromStart | Quantity::SlideFromEnd | Quantity::FirstMacroslipForce => {
            return None;
        }
    };
    value.is_finite().then_some(value)
}

/// Every parameter, in display order.
const PARAMS: [Param; CylinderParam::ALL.len()] = param_list!(Param::Cylinder, CylinderParam);
