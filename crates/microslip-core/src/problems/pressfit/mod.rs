//! The press fit (issue 44): a shaft shrunk into a hub, pushed out by an axial force F on its end
//! face (the hub held on its far face) or twisted by a torque T, under the regularized law or
//! plain Coulomb. The parameters, Lamé's contact pressure, the closed forms (the shear lag of two
//! bars coupled through one interface, shared with the lap joint through
//! [`crate::kernel::shear_lag`]), the Masing cycle, where the 1-D theory's assumptions stand
//! (measured against the axisymmetric continuum, `continuum.rs`), and the independent
//! discretized solver. docs/theory.md section 18 derives all of it.
//!
//! Registered (`PressFit => pressfit::PressFitProblem` in [`crate::with_problems!`]): the trait
//! impls that name the registry's generated types (`Problem`, `LoadDriven`, `Fittable`, `Zoned`,
//! `StiffnessAnswer`, `CrossChecked`, `Pointwise`, `Profiled`) are in `registered/`, each a
//! delegation to the typed fit of this folder.
//!
//! **The torque** is not a load choice of this problem but a sixth problem type in this folder,
//! `PressFitTorque => pressfit::PressFitTorqueProblem` in [`crate::with_problems!`], over
//! [`closed_form::PressFit::torsion`] (keys with `T` for `F`, [`TORQUE_BOUND`], response theta):
//! a [`Description`](crate::problems::Description)'s load, its bound, its response's symbol and
//! the load's JSON key are constants the generic layers read without asking a setting (`F_N`,
//! `F_gross`, `Delta_mm`), so a setting cannot turn F into T; a type can, with the same closed
//! forms. Its keys are [`params::PressFitParam::TORQUE_KEYS`] as their own key type
//! ([`TorqueParam`]), its quantities [`TORQUE_QUANTITIES`] and their values [`quantity`] (over
//! either [`closed_form::FitAxis`]); the registered impls are written once over the kind of load
//! (`registered::problem::FitKind`: `PushOut`, `Twist`). The twisted fit has no continuum (the
//! axisymmetric one is the push-out's; a torsional one is left), so its theory is "not
//! calibrated" wherever it is shown, and no CalculiX deck (CAX elements carry no twist).
//!
//! **Its response is the twist theta in rad**, not the circumferential slip r theta in mm: theta
//! is what a torsion test measures (the angle between the shaft's end and the hub's held face),
//! what (S6) solves for and what [`discretized::PressFitFe`] answers; r theta would be a number
//! no rig reads, tied to one radius of the section. The generic layers print a response's unit
//! only through the problem's words: [`Quantity::Response`]'s unit is its [`QuantityName`]'s
//! (`rad` in [`TORQUE_QUANTITIES`]), a fit's response column is its `Fittable::RESPONSE_COLUMN`
//! (`theta_rad`), the cycle's JSON keys are its face's `CycleWords` (`peak_key` and `keys`: a
//! torque's `Ta_Nmm`, `theta_peak_rad`, `secant_stiffness_Nmm_per_rad`; `D_Nmm` stays, as
//! T dtheta is N mm) and the loop and sweep CSV rows are its face's own `LoopRow` and `LoadRow`
//! types. The fixed `_mm` columns of the application's `report/rows.rs` are the beams' rows.

pub mod closed_form;
pub mod continuum;
pub mod cycle;
pub mod discretized;
pub mod lame;
pub mod params;
pub mod registered;
pub mod validity;
pub use registered::TorqueParam;
pub use registered::point;
pub use registered::problem::{PressFitProblem, PressFitTorqueProblem};

#[cfg(test)]
mod tests;

use crate::problems::{LoadBound, Quantity, QuantityName};

/// The push-out's bound in the problem's words, for its `Description` (issue 43's descriptor).
pub const PUSH_OUT_BOUND: LoadBound = LoadBound {
    symbol: "F_gross",
    formula: "mu p 2 pi r L",
    beyond: "the shaft slides out beyond it",
};

/// The torque's bound in the problem's words.
pub const TORQUE_BOUND: LoadBound = LoadBound {
    symbol: "T_gross",
    formula: "mu p 2 pi r^2 L",
    beyond: "the shaft turns in the hub beyond it",
};

/// What differs between the push-out's quantities and the torque's: the response's and the
/// first slip's names and units, and the words for the load.
struct LoadWords {
    response: (
        &'static str,
        &'static [&'static str],
        &'static str,
        &'static str,
    ),
    ratio: &'static str,
    first_slip: (
        &'static str,
        &'static [&'static str],
        &'static str,
        &'static str,
    ),
    at_amplitude: [&'static str; 2],
}

/// The seven quantities of either load, in one order: the sliding zones, the dissipation (N mm
/// for both: T dtheta is N mm as F dDelta) and the damping ratio in the same words.
const fn quantities(words: LoadWords) -> [QuantityName; 7] {
    type Words = (
        &'static str,
        &'static [&'static str],
        &'static str,
        &'static str,
    );
    const fn named(quantity: Quantity, (name, aliases, meaning, unit): Words) -> QuantityName {
        QuantityName {
            quantity,
            name,
            aliases,
            meaning,
            unit,
        }
    }
    [
        named(Quantity::Response, words.response),
        named(
            Quantity::SlideFromStart,
            (
                "a",
                &[],
                "sliding zone from x = 0, the shaft's loaded face",
                "mm",
            ),
        ),
        named(
            Quantity::SlideFromEnd,
            (
                "d",
                &[],
                "sliding zone from x = L, the hub's held face",
                "mm",
            ),
        ),
        named(Quantity::Ratio, ("ratio", &[], words.ratio, "")),
        named(Quantity::FirstMacroslipForce, words.first_slip),
        named(
            Quantity::Dissipation,
            ("D", &[], words.at_amplitude[0], "N mm"),
        ),
        named(
            Quantity::DampingRatio,
            ("zeta", &[], words.at_amplitude[1], ""),
        ),
    ]
}

/// The quantities a target can be set on, as the push-out names them (for its `Description`).
pub const QUANTITIES: [QuantityName; 7] = quantities(LoadWords {
    response: (
        "Delta",
        &["delta_x"],
        "push-out displacement of the shaft's loaded end relative to the hub's held face, \
         regularized law",
        "mm",
    ),
    ratio: "Delta regularized / Delta Coulomb",
    first_slip: ("F_1", &["F1"], "force at which sliding first appears", "N"),
    at_amplitude: [
        "dissipation per cycle of amplitude F (regularized)",
        "equivalent damping ratio at amplitude F (regularized)",
    ],
});

/// The quantities as the twisted fit names them (for its `Description`): the response
/// is the twist theta in rad (the module docs say why), the onset T_1 in N mm.
pub const TORQUE_QUANTITIES: [QuantityName; 7] = quantities(LoadWords {
    response: (
        "theta",
        &[],
        "twist of the shaft's loaded end relative to the hub's held face, regularized law",
        "rad",
    ),
    ratio: "theta regularized / theta Coulomb",
    first_slip: (
        "T_1",
        &["T1"],
        "torque at which sliding first appears",
        "N mm",
    ),
    at_amplitude: [
        "dissipation per cycle of amplitude T (regularized)",
        "equivalent damping ratio at amplitude T (regularized)",
    ],
});

/// The value of `quantity` for the fit loaded along `axis` (the push-out's
/// [`closed_form::PressFit::axial`] or the torque's [`closed_form::PressFit::torsion`]) at
/// `load` (see [`Quantity`]); `None` for a quantity it has not (one microslip end: it has two
/// sliding zones) or where it is not defined or not finite. What a registered problem's
/// `Problem::quantity` returns.
pub fn quantity(
    axis: &closed_form::FitAxis,
    load: closed_form::CarriedLoad,
    quantity: Quantity,
) -> Option<f64> {
    use crate::kernel::regime::Law;
    use crate::problems::load_driven::MasingCycle;
    use crate::problems::quantity::ratio_to_coulomb;
    let regularized = axis.regularized(load);
    let cycle = || cycle::FitCycle::new(axis, Law::Regularized, load);
    let value = match quantity {
        Quantity::Response => regularized.response(),
        Quantity::SlideFromStart => regularized.slide_from_loaded_face(),
        Quantity::SlideFromEnd => regularized.slide_from_held_face(),
        Quantity::Ratio => ratio_to_coulomb(regularized.response(), axis.coulomb(load).response())?,
        Quantity::FirstMacroslipForce => axis.first_slip_load(),
        Quantity::Dissipation => cycle().dissipation(),
        Quantity::DampingRatio => cycle().damping_ratio(),
        Quantity::MicroEnd => return None,
    };
    value.is_finite().then_some(value)
}
