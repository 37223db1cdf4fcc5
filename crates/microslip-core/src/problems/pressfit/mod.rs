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
//! **The torque** is not a load choice of this problem but, when it comes, a sixth problem type in
//! this folder over [`closed_form::PressFit::torsion`] (keys with `T` for `F`, [`TORQUE_BOUND`],
//! response theta): a [`Description`](crate::problems::Description)'s load, its bound, its
//! response's symbol and the load's JSON key are constants the generic layers read without
//! asking a setting (`F_N`, `F_gross`, `Delta_mm`), so a setting cannot turn F into T; a type
//! can, with the same closed forms.

pub mod closed_form;
pub mod continuum;
pub mod cycle;
pub mod discretized;
pub mod lame;
pub mod params;
pub mod registered;
pub mod validity;
pub use registered::point;
pub use registered::problem::PressFitProblem;

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

/// The quantities a target can be set on, as the push-out names them (for its `Description`).
pub const QUANTITIES: [QuantityName; 7] = [
    QuantityName {
        quantity: Quantity::Response,
        name: "Delta",
        aliases: &["delta_x"],
        meaning: "push-out displacement of the shaft's loaded end relative to the hub's held \
                  face, regularized law",
        unit: "mm",
    },
    QuantityName {
        quantity: Quantity::SlideFromStart,
        name: "a",
        aliases: &[],
        meaning: "sliding zone from x = 0, the shaft's loaded face",
        unit: "mm",
    },
    QuantityName {
        quantity: Quantity::SlideFromEnd,
        name: "d",
        aliases: &[],
        meaning: "sliding zone from x = L, the hub's held face",
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
];

/// The value of `quantity` for the push-out of `fit` at `force` (see [`Quantity`]); `None` for a
/// quantity it has not (one microslip end: it has two sliding zones) or where it is not defined
/// or not finite. What the registered problem's `Problem::quantity` will return.
pub fn quantity(
    fit: &closed_form::PressFit,
    force: closed_form::CarriedLoad,
    quantity: Quantity,
) -> Option<f64> {
    use crate::kernel::regime::Law;
    use crate::problems::load_driven::MasingCycle;
    use crate::problems::quantity::ratio_to_coulomb;
    let regularized = fit.regularized(force);
    let cycle = || cycle::FitCycle::new(fit.axial(), Law::Regularized, force);
    let value = match quantity {
        Quantity::Response => regularized.response(),
        Quantity::SlideFromStart => regularized.slide_from_loaded_face(),
        Quantity::SlideFromEnd => regularized.slide_from_held_face(),
        Quantity::Ratio => ratio_to_coulomb(regularized.response(), fit.coulomb(force).response())?,
        Quantity::FirstMacroslipForce => fit.first_slip_force(),
        Quantity::Dissipation => cycle().dissipation(),
        Quantity::DampingRatio => cycle().damping_ratio(),
        Quantity::MicroEnd => return None,
    };
    value.is_finite().then_some(value)
}
