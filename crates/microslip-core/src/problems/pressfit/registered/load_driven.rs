//! The press fit as a load-driven problem ([`LoadDriven`]): the push-out force F in [0, F_gross],
//! Delta its response, F_gross = mu p 2 pi r L its regime scale, the shear lag's Masing cycle.

use super::point::{FitPoint, fit_point};
use super::problem::{PressFitModel, PressFitProblem};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::Param;
use crate::problems::load_driven::LoadDriven;
use crate::problems::pressfit::closed_form::{CarriedLoad, PressFit};
use crate::problems::pressfit::cycle::FitCycle;
use crate::problems::pressfit::params::PressFitParam;

impl LoadDriven for PressFitProblem {
    type Structure = PressFit;
    type Force = CarriedLoad;
    type Cycle = FitCycle;
    type Point = FitPoint;

    const FORCE: Param = Param::PressFit(PressFitParam::Force);
    const STIFFNESS: Param = Param::PressFit(PressFitParam::Stiffness);

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
        fit.force(newtons)
    }

    fn clamped_force(fit: &PressFit, newtons: f64) -> CarriedLoad {
        fit.axial().clamped(newtons)
    }

    fn load_value(force: CarriedLoad) -> f64 {
        force.value()
    }

    fn force_scale(fit: &PressFit) -> f64 {
        fit.gross_slip_force()
    }

    fn regime_changes(fit: &PressFit) -> Vec<f64> {
        vec![fit.first_slip_force(), fit.second_slip_force()]
    }

    fn response(fit: &PressFit, law: Law, force: CarriedLoad) -> f64 {
        fit.axial().solve(law, force).response()
    }

    fn point(fit: &PressFit, force: CarriedLoad) -> FitPoint {
        fit_point(fit, force)
    }

    fn holding_zone(fit: &PressFit, law: Law, force: CarriedLoad) -> [f64; 2] {
        fit.axial().solve(law, force).holding_zone()
    }

    fn cycle(fit: &PressFit, law: Law, amplitude: CarriedLoad) -> FitCycle {
        FitCycle::new(fit.axial(), law, amplitude)
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
