//! Twin cantilever beams pressed together and bent by equal tip forces (paper section 2.1): the
//! parameters, the closed forms under both laws, cyclic loading, the validity envelope (V2) and the
//! independent finite-element solver. The closed forms and the discretized solver never import
//! each other (tests/layering.rs checks it), so that their agreement means something.

pub mod choice;
pub mod closed_form;
pub mod continuum;
pub mod cross_check;
pub mod cycle;
pub mod discretized;
pub mod fittable;
pub mod load_driven;
pub mod params;
pub mod point;
pub mod problem;
pub mod profiles;
pub mod stiffness_answer;
pub mod validity;
pub mod zoned;

pub use continuum::{
    BeamsContinuumMesh, ContinuumBeams, solve_beams_continuum, solve_beams_continuum_path,
};
pub use discretized::{InterfaceSample, TwinBeamsFe};
pub use problem::TwinBeamsProblem;

use crate::problems::quantity::ratio_to_coulomb;
use crate::problems::{Description, Param, Quantity, QuantityName, Solution};
use closed_form::{TipForce, TwinBeams};
use cycle::{BeamsCycle, Law, MasingCycle};
use params::BeamParam;

/// The twin beams as the generic layers see them.
pub(crate) const DESCRIPTION: Description = Description {
    key: "beam",
    title: "twin cantilever beams",
    summary: "Twin cantilever beams (paper section 2.1)",
    paper_preset: "paper-beams",
    params: &PARAMS,
    response_symbol: "w",
    load: Some(Param::Beam(BeamParam::Force)),
    regime_scale_name: "F_thre",
    load_bound: None,
    load_span: 3.0,
    quantities: &[
        QuantityName {
            quantity: Quantity::Response,
            name: "w(L)",
            aliases: &["w", "wL"],
            meaning: "tip deflection, regularized law",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::MicroEnd,
            name: "X",
            aliases: &["X_r", "Xr"],
            meaning: "end of the microslip zone X, from the clamp (L: no macroslip)",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::Ratio,
            name: "ratio",
            aliases: &[],
            meaning: "w(L) regularized / w(L) Coulomb",
            unit: "",
        },
        QuantityName {
            quantity: Quantity::FirstMacroslipForce,
            name: "F_1",
            aliases: &["F1"],
            meaning: "force at which macroslip first appears",
            unit: "N",
        },
        QuantityName {
            quantity: Quantity::Dissipation,
            name: "D",
            aliases: &[],
            meaning: "dissipation per cycle of amplitude F (regularized)",
            unit: "N mm",
        },
        QuantityName {
            quantity: Quantity::DampingRatio,
            name: "zeta",
            aliases: &[],
            meaning: "equivalent damping ratio at amplitude F (regularized)",
            unit: "",
        },
    ],
};

/// The value of `quantity` for `beams` at `force` (see [`Quantity`]); `None` where it is not
/// defined (the ratio at zero load) or not finite.
pub(crate) fn quantity(beams: &TwinBeams, force: TipForce, quantity: Quantity) -> Option<f64> {
    let value = match quantity {
        Quantity::Response => beams.regularized(force).response(),
        Quantity::MicroEnd => beams.regularized(force).zone_end(),
        Quantity::Ratio => ratio_to_coulomb(
            beams.regularized(force).response(),
            beams.coulomb(force).response(),
        )?,
        Quantity::FirstMacroslipForce => beams.first_macroslip_force(),
        Quantity::Dissipation => BeamsCycle::new(beams, Law::Regularized, force).dissipation(),
        Quantity::SlideFromStart | Quantity::SlideFromEnd => return None,
        Quantity::DampingRatio => BeamsCycle::new(beams, Law::Regularized, force).damping_ratio(),
    };
    value.is_finite().then_some(value)
}

/// Every parameter, in display order.
const PARAMS: [Param; BeamParam::ALL.len()] = param_list!(Param::Beam, BeamParam);
