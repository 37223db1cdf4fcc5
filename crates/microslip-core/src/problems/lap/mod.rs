//! The clamped double-lap joint (issue 24): an inner plate between two cover plates, clamped at a
//! pressure P and pulled by a force F: the parameters, the shear-lag closed forms under both
//! laws, cyclic loading and the independent discretized solver. The closed forms and the
//! discretized solver never import each other (tests/layering.rs checks it).

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
    ContinuumLap, LAP_POISSON, LapContinuumMesh, SlidingZones, solve_lap_continuum,
    solve_lap_continuum_path,
};
pub use discretized::LapFe;
pub use problem::LapJointProblem;
pub use validity::{LapRangesLeft, LapValidity};

use crate::kernel::regime::Law;
use crate::problems::quantity::ratio_to_coulomb;
use crate::problems::{Description, LoadBound, Param, Quantity, QuantityName, Solution};
use closed_form::{JointForce, LapJoint};
use cycle::{LapCycle, MasingCycle};
use params::LapParam;

/// The double-lap joint as the generic layers see it.
pub(crate) const DESCRIPTION: Description = Description {
    key: "lap",
    title: "clamped double-lap joint",
    summary: "Clamped double-lap joint (shear lag, docs/theory.md section 9)",
    paper_preset: "lap-aluminium",
    params: &PARAMS,
    response_symbol: "Delta",
    load: Some(Param::Lap(LapParam::Force)),
    regime_scale_name: "F_gross",
    load_bound: Some(LoadBound {
        symbol: "F_gross",
        formula: "2 b mu P L",
        beyond: "the joint slides through beyond it",
    }),
    load_span: 1.0,
    quantities: &[
        QuantityName {
            quantity: Quantity::Response,
            name: "Delta",
            aliases: &["D_L", "delta"],
            meaning: "joint displacement u_inner(L) - u_cover(0), regularized law",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::SlideFromStart,
            name: "a",
            aliases: &[],
            meaning: "sliding zone from x = 0, the inner plate's end",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::SlideFromEnd,
            name: "d",
            aliases: &[],
            meaning: "sliding zone from x = L, the covers' ends",
            unit: "mm",
        },
        QuantityName {
            quantity: Quantity::Ratio,
            name: "ratio",
            aliases: &[],
            meaning: "Delta regularized / Delta Coulomb",
            unit: "",
        },
        QuantityName {
            quantity: Quantity::FirstMacroslipForce,
            name: "F_1",
            aliases: &["F1"],
            meaning: "force at which sliding first appears",
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

/// The value of `quantity` for `joint` at `force` (see [`Quantity`]); `None` for a quantity the
/// joint has not (one microslip zone end: it has two sliding zones, `a` and `d`), where it is not
/// defined (the ratio at zero load) or not finite.
pub(crate) fn quantity(joint: &LapJoint, force: JointForce, quantity: Quantity) -> Option<f64> {
    let regularized = joint.regularized(force);
    let value = match quantity {
        Quantity::Response => regularized.response(),
        Quantity::SlideFromStart => regularized.slide_at_inner_end(),
        Quantity::SlideFromEnd => regularized.slide_at_cover_ends(),
        Quantity::Ratio => {
            ratio_to_coulomb(regularized.response(), joint.coulomb(force).response())?
        }
        Quantity::FirstMacroslipForce => joint.first_slip_force(),
        Quantity::Dissipation => LapCycle::new(joint, Law::Regularized, force).dissipation(),
        Quantity::DampingRatio => LapCycle::new(joint, Law::Regularized, force).damping_ratio(),
        Quantity::MicroEnd => return None,
    };
    value.is_finite().then_some(value)
}

/// Every parameter, in display order.
const PARAMS: [Param; LapParam::ALL.len()] = param_list!(Param::Lap, LapParam);
