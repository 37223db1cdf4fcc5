//! A thin plate squeezed on a rigid plane (paper section 2.2): the parameters, the strip theory's
//! closed forms under both laws, its validity envelope (V1), the independent 1-D finite-element
//! solver and the 2-D plane-strain continuum that measures where the strip theory fails. The closed
//! forms and the discretized solvers never import each other (tests/layering.rs checks it).

pub mod closed_form;
pub mod continuum;
pub mod cross_check;
pub mod discretized;
pub mod params;
pub mod point;
pub mod problem;
pub mod profiles;
pub mod stiffness_answer;
pub mod validity;
pub mod zoned;

pub use continuum::{ContinuumMesh, ContinuumPlate, solve_plate_continuum};
pub use discretized::PlateFe;
pub use problem::SqueezedPlateProblem;

use crate::problems::quantity::ratio_to_coulomb;
use crate::problems::{Description, Param, Quantity, QuantityName, Solution};
use closed_form::SqueezedPlate;
use params::PlateParam;

/// The squeezed plate as the generic layers see it.
pub(crate) const DESCRIPTION: Description = Description {
    key: "plate",
    title: "squeezed plate",
    summary: "Squeezed plate (paper section 2.2)",
    paper_preset: "paper-plate",
    params: &PARAMS,
    response_symbol: "u",
    load: None,
    regime_scale_name: "",
    load_bound: None,
    load_span: 0.0,
    quantities: &[
        QuantityName {
            quantity: Quantity::Response,
            name: "u(L)",
            aliases: &["u", "uL"],
            meaning: "end displacement, regularized law",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::MicroEnd,
            name: "X_r",
            aliases: &["X", "Xr"],
            meaning: "end of the microslip zone X_r, from the centre (L: no macroslip)",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::Ratio,
            name: "ratio",
            aliases: &[],
            meaning: "u(L) regularized / u(L) Coulomb",
            unit: "",
        },
    ],
};

/// The value of `quantity` for `plate` (see [`Quantity`]); `None` for a quantity the plate has
/// not (it carries no force), where it is not defined (the ratio where nothing slides) or not
/// finite.
pub(crate) fn quantity(plate: &SqueezedPlate, quantity: Quantity) -> Option<f64> {
    let value = match quantity {
        Quantity::Response => plate.regularized().response(),
        Quantity::MicroEnd => plate.regularized().zone_end(),
        Quantity::Ratio => {
            ratio_to_coulomb(plate.regularized().response(), plate.coulomb().response())?
        }
        Quantity::FirstMacroslipForce
        | Quantity::Dissipation
        | Quantity::DampingRatio
        | Quantity::SlideFromStart
        | Quantity::SlideFromEnd => {
            return None;
        }
    };
    value.is_finite().then_some(value)
}

/// Every parameter, in display order.
const PARAMS: [Param; PlateParam::ALL.len()] = param_list!(Param::Plate, PlateParam);
