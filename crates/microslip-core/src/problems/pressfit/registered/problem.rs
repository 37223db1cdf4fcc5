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
        crate::problems::pressfit::quantity(model.fit.axial(), model.force, quantity)
    }

    fn regime_scale(model: &PressFitModel) -> Option<f64> {
        Some(Self::force_scale(&model.fit))
    }

    /// The domain, narrowed where the inputs bound one another: ri < r < ro (each radius between
    /// its neighbours), and F <= F_gross = mu p 2 pi r L, which bounds F from above and mu, delta
    /// and L from below (F_gross is proportional to each: p to delta). The radii and the moduli
    /// move F_gross too, not in proportion (p falls to 0 as either wall thins, and grows with
    /// each modulus): their bounds are found by bisection on the model's acceptance.
    fn accepted_range(model: &PressFitModel, index: usize) -> (f64, f64) {
        let Some(&param) = PressFitParam::PUSH_OUT.get(index) else {
            return (f64::NAN, f64::NAN);
        };
        let domain = param.spec().domain;
        let (min, max) = (domain.min(), domain.max());
        let p = model.fit.params();
        let gross = model.fit.gross_slip_force();
        match param {
            PressFitParam::Force => (min, max.min(gross)),
            PressFitParam::Friction | PressFitParam::Interference | PressFitParam::Length => {
                Self::range_above_proportional_bound(
                    model,
                    index,
                    (min, max),
                    (model.force.value(), gross),
                )
            }
            PressFitParam::FitRadius => (
                Self::accepted_toward(model, index, min.max(p.bore_radius)),
                Self::accepted_toward(model, index, max.min(p.outer_radius)),
            ),
            PressFitParam::BoreRadius => (
                min,
                Self::accepted_toward(model, index, max.min(p.fit_radius)),
            ),
            PressFitParam::OuterRadius => (
                Self::accepted_toward(model, index, min.max(p.fit_radius)),
                max,
            ),
            PressFitParam::ShaftModulus | PressFitParam::HubModulus => {
                (Self::accepted_toward(model, index, min), max)
            }
            _ => (min, max),
        }
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
