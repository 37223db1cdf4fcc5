//! The press fit as a [`Problem`]: parameter values by index, the model, both laws' solutions and
//! the bound F <= F_gross its inputs put on one another.

use super::DESCRIPTION;
use crate::kernel::params::{ParamError, ParamSpec};
use crate::numeric::NumericError;
use crate::problems::cross_check::CrossCheckedOf;
use crate::problems::fittable::FittableOf;
use crate::problems::inputs::InterfaceData;
use crate::problems::load_driven::{LoadDriven, LoadDrivenOf};
use crate::problems::pressfit::closed_form::{CarriedLoad, FitState, PressFit};
use crate::problems::pressfit::continuum::{
    ContinuumPressFit, PressFitContinuumMesh, solve_pressfit_continuum,
};
use crate::problems::pressfit::params::{PressFitParam, PressFitParams};
use crate::problems::problem::{
    Continuum, Laws, ParamKey, Problem, ProblemFaces, continuum_response,
};
use crate::problems::zoned::erased_layout;
use crate::problems::{Description, Quantity};

/// The press fit pushed out, as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PressFitProblem;

/// The fit's parameters and the push-out force F (N), unvalidated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitInputs {
    /// Members and interface.
    pub structure: PressFitParams,
    /// Push-out force (N).
    pub force: f64,
}

/// A validated fit at a force it carries (F <= F_gross).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitModel {
    /// The fit.
    pub fit: PressFit,
    /// The force on it.
    pub force: CarriedLoad,
}

impl ParamKey for PressFitParam {
    const KEYS: &'static [PressFitParam] = PressFitParam::PUSH_OUT;

    fn spec(self) -> ParamSpec {
        PressFitParam::spec(self)
    }
}

impl Problem for PressFitProblem {
    const INFO: &'static Description = &DESCRIPTION;
    const REFUSED_AS: &'static str = "the press fit";
    type Key = PressFitParam;
    type Params = PressFitInputs;
    type Model = PressFitModel;
    type State = Laws<FitState, FitState>;

    /// The #98 fit at half its F_gross.
    fn paper() -> PressFitInputs {
        PressFitInputs {
            structure: PressFitParams::CCX98,
            force: 685.5,
        }
    }

    fn slot(params: &mut PressFitInputs, index: usize) -> Option<&mut f64> {
        match *PressFitParam::PUSH_OUT.get(index)? {
            PressFitParam::Force => Some(&mut params.force),
            param => params.structure.value_mut(param),
        }
    }

    fn model(params: &PressFitInputs) -> Result<PressFitModel, ParamError> {
        let fit = PressFit::new(params.structure)?;
        Ok(PressFitModel {
            fit,
            force: fit.force(params.force)?,
        })
    }

    fn params(model: &PressFitModel) -> PressFitInputs {
        PressFitInputs {
            structure: model.fit.params(),
            force: model.force.value(),
        }
    }

    fn solve(model: &PressFitModel) -> Self::State {
        Laws {
            coulomb: model.fit.coulomb(model.force),
            regularized: model.fit.regularized(model.force),
        }
    }

    fn quantity(model: &PressFitModel, quantity: Quantity) -> Option<f64> {
        crate::problems::pressfit::quantity(&model.fit, model.force, quantity)
    }

    fn regime_scale(model: &PressFitModel) -> Option<f64> {
        Some(Self::force_scale(&model.fit))
    }

    /// The shaft's modulus: the member every FE model of the fit meshes.
    fn interface(model: &PressFitModel) -> InterfaceData {
        let p = model.fit.params();
        InterfaceData {
            length: p.length,
            friction: p.friction,
            pressure: model.fit.contact_pressure(),
            modulus: p.shaft_modulus,
            stiffness: p.tangential_stiffness,
            poisson: Some(p.shaft_poisson),
        }
    }

    const FACES: &'static ProblemFaces = &ProblemFaces {
        continuum: Some(continuum_response::<PressFitProblem>),
        load_driven: Some(&LoadDrivenOf::<PressFitProblem>::NEW),
        fittable: Some(&FittableOf::<PressFitProblem>::NEW),
        cross_checked: Some(&CrossCheckedOf::<PressFitProblem>::NEW),
        zoned: Some(erased_layout::<PressFitProblem>),
        ..ProblemFaces::NONE
    };

    enum_bridges!(PressFit);
}

impl Continuum for PressFitProblem {
    type Mesh = PressFitContinuumMesh;
    type Reference = ContinuumPressFit;

    fn solve_continuum(
        model: &PressFitModel,
        mesh: PressFitContinuumMesh,
    ) -> Result<ContinuumPressFit, NumericError> {
        solve_pressfit_continuum(model.fit.params(), model.force.value(), mesh)
    }

    /// Delta from the fitted state: the closed form's.
    fn continuum_response(reference: &ContinuumPressFit) -> f64 {
        reference.delta
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::ModelKind;
    use crate::problems::problem::checks;

    #[test]
    fn the_fit_is_registered_and_answers_the_same_erased_as_typed() {
        checks::registered::<PressFitProblem>();
        // The erased continuum is the typed one, on the default mesh.
        let model = crate::problems::inputs::Inputs::paper(ModelKind::PressFit)
            .validate()
            .unwrap();
        let erased = PressFitProblem::FACES
            .continuum
            .and_then(|response| response(&model))
            .unwrap()
            .unwrap();
        let typed = solve_pressfit_continuum(
            PressFitParams::CCX98,
            685.5,
            PressFitContinuumMesh::default(),
        )
        .unwrap();
        assert_eq!(erased.to_bits(), typed.delta.to_bits());
        checks::erased_answers_as_typed(ModelKind::PressFit, |v| {
            let fit = PressFit::new(PressFitParams {
                fit_radius: v("r"),
                bore_radius: v("ri"),
                outer_radius: v("ro"),
                length: v("L"),
                shaft_modulus: v("Es"),
                shaft_poisson: v("nus"),
                hub_modulus: v("Eh"),
                hub_poisson: v("nuh"),
                interference: v("delta"),
                friction: v("mu"),
                tangential_stiffness: v("KT"),
            })?;
            let force = fit.force(v("F"))?;
            let answers = checks::answers(&fit.coulomb(force), &fit.regularized(force));
            Ok((answers, Some(fit.gross_slip_force())))
        });
    }
}
