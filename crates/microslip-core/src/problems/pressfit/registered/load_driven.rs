//! The press fit as a load-driven problem ([`LoadDriven`]): the push-out force F in [0, F_gross],
//! Delta its response, F_gross = mu p 2 pi r L its regime scale, the shear lag's Masing cycle
//! (or the torque T in [0, T_gross], theta its response: the kind's axis).

use super::point::{FitPoint, fit_point};
use super::problem::{FitKind, FitProblem, PressFitModel};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::Param;
use crate::problems::load_driven::LoadDriven;
use crate::problems::pressfit::closed_form::{CarriedLoad, PressFit};
use crate::problems::pressfit::cycle::FitCycle;
use crate::problems::problem::Registered;

impl<K: FitKind> LoadDriven for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    type Structure = PressFit;
    type Force = CarriedLoad;
    type Cycle = FitCycle;
    type Point = FitPoint;

    const FORCE: Param = K::LOAD_PARAM;
    const STIFFNESS: Param = K::STIFFNESS_PARAM;

    fn structure(model: &PressFitModel) -> PressFit {
        model.fit
    }

    fn applied_force(model: &PressFitModel) -> CarriedLoad {
        model.force
    }

    fn at_force(fit: &PressFit, force: CarriedLoad) -> PressFitModel {
        PressFitModel { fit: *fit, force }
    }

    fn force(fit: &PressFit, newtons: f64) -> Result<CarriedLoad, ParamError> {
        fit.axis(K::LOAD).load(newtons)
    }

    fn clamped_force(fit: &PressFit, newtons: f64) -> CarriedLoad {
        fit.axis(K::LOAD).clamped(newtons)
    }

    fn load_value(force: CarriedLoad) -> f64 {
        force.value()
    }

    fn force_scale(fit: &PressFit) -> f64 {
        fit.axis(K::LOAD).gross_load()
    }

    fn regime_changes(fit: &PressFit) -> Vec<f64> {
        let axis = fit.axis(K::LOAD);
        vec![axis.first_slip_load(), axis.second_slip_load()]
    }

    fn response(fit: &PressFit, law: Law, force: CarriedLoad) -> f64 {
        fit.axis(K::LOAD).solve(law, force).response()
    }

    fn point(fit: &PressFit, force: CarriedLoad) -> FitPoint {
        fit_point(fit.axis(K::LOAD), force)
    }

    fn holding_zone(fit: &PressFit, law: Law, force: CarriedLoad) -> [f64; 2] {
        fit.axis(K::LOAD).solve(law, force).holding_zone()
    }

    fn cycle(fit: &PressFit, law: Law, amplitude: CarriedLoad) -> FitCycle {
        FitCycle::new(fit.axis(K::LOAD), law, amplitude)
    }

    fn tangential_stiffness(fit: &PressFit) -> f64 {
        fit.params().tangential_stiffness
    }

    fn with_tangential_stiffness(fit: &PressFit, kt: f64) -> Result<PressFit, ParamError> {
        fit.with_tangential_stiffness(kt)
    }

    fn interface_strength(fit: &PressFit) -> f64 {
        fit.params().friction * fit.contact_pressure()
    }

    /// The shaft's Es.
    fn modulus(fit: &PressFit) -> f64 {
        fit.params().shaft_modulus
    }

    /// As the lap joint's: the limit F -> 0, where the regularized fit is elastic and Coulomb's
    /// bonded, is the range's largest deviation.
    fn deviation_probes(_fit: &PressFit, [from, to]: [f64; 2]) -> Vec<f64> {
        if from == 0.0 {
            vec![1e-9 * to]
        } else {
            Vec::new()
        }
    }
}
