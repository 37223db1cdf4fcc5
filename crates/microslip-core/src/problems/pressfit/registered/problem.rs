//! The press fit as a [`Problem`]: parameter values by index, the model, both laws' solutions and
//! the bound F <= F_gross its inputs put on one another.
//!
//! Written once over the load ([`FitKind`]): the push-out ([`PushOut`], [`PressFitProblem`](tyalias@PressFitProblem)) and
//! the torque ([`Twist`], [`PressFitTorqueProblem`](tyalias@PressFitTorqueProblem), over [`PressFit::torsion`]), two registry
//! lines (the folder's module docs say why two problems and not a setting). Each is both a type
//! (an alias of [`FitProblem`]) and its value, as a unit struct is, so the registry names it as it
//! names every problem.

use super::{DESCRIPTION, TORQUE_DESCRIPTION, TorqueParam};
use crate::kernel::params::{ParamError, ParamSpec};
use crate::numeric::NumericError;
use crate::problems::cross_check::CrossCheckedOf;
use crate::problems::fittable::FittableOf;
use crate::problems::inputs::InterfaceData;
use crate::problems::inputs::{Inputs, Model};
use crate::problems::load_driven::{LoadDriven, LoadDrivenOf};
use crate::problems::pressfit::closed_form::{CarriedLoad, FitState, PressFit};
use crate::problems::pressfit::continuum::{
    ContinuumPressFit, PressFitContinuumMesh, solve_pressfit_continuum,
};
use crate::problems::pressfit::params::{FitLoad, PressFitParam, PressFitParams};
use crate::problems::problem::{
    Continuum, ContinuumResponse, Laws, ParamKey, Problem, ProblemFaces, Registered,
    continuum_response,
};
use crate::problems::zoned::erased_layout;
use crate::problems::{Description, Param, Quantity};
use std::marker::PhantomData;

/// The registry's bridges of one kind of fit (what `enum_bridges!` writes): its variants of
/// `Inputs` and `Model`.
pub trait FitBridges {
    /// Always [`PressFitInputs`].
    type Params;
    /// Always [`PressFitModel`].
    type Model;
    /// Into the registry's inputs.
    fn to_inputs(params: Self::Params) -> crate::problems::inputs::Inputs;
    /// Out of them, when they are this kind's.
    fn from_inputs(inputs: &crate::problems::inputs::Inputs) -> Option<Self::Params>;
    /// Into the registry's model.
    fn to_model(model: Self::Model) -> crate::problems::inputs::Model;
    /// Out of it, when it is this kind's.
    fn from_model(model: &crate::problems::inputs::Model) -> Option<Self::Model>;
}

/// One way of loading the fit as a problem: its load, its keys and its words. Everything else
/// of the registered problem is written once over it.
pub trait FitKind:
    FitBridges<Params = PressFitInputs, Model = PressFitModel>
    + std::fmt::Debug
    + Clone
    + Copy
    + PartialEq
    + Eq
    + Send
    + Sync
    + 'static
{
    /// Which load.
    const LOAD: FitLoad;
    /// The description.
    const INFO: &'static Description;
    /// How a refusal names it.
    const REFUSED_AS: &'static str;
    /// Its key type (the generated `Param` wraps one per problem).
    type Key: ParamKey;
    /// The load's parameter.
    const LOAD_PARAM: Param;
    /// K_T's parameter.
    const STIFFNESS_PARAM: Param;
    /// The load of its paper preset (the #98 fit at half its gross load).
    const PAPER_LOAD: f64;
    /// The fit's parameter a key is.
    fn param(key: Self::Key) -> PressFitParam;
    /// The axisymmetric continuum's response, where the kind has one.
    const CONTINUUM: Option<ContinuumResponse>;
    /// `Fittable::LOAD_COLUMN`.
    const LOAD_COLUMN: &'static str;
    /// `Fittable::RESPONSE_COLUMN`.
    const RESPONSE_COLUMN: &'static str;
    /// `Fittable::FITTED`.
    const FITTED: &'static str;
    /// `Fittable::HELD`: the fit's own keys, r to delta.
    const HELD: &'static [Self::Key];
    /// `CrossChecked::COMPARED`.
    const COMPARED: &'static [&'static str];
}

/// The press fit under one kind of load, as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FitProblem<K>(PhantomData<K>);

/// The push-out: F (N), Delta (mm).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PushOut;

/// The press fit pushed out, as a type: see [`Problem`].
pub type PressFitProblem = FitProblem<PushOut>;

/// The press fit pushed out, as a value (what the registry hands out).
#[allow(non_upper_case_globals)]
pub const PressFitProblem: PressFitProblem = FitProblem(PhantomData);

/// The torque: T (N mm), theta (rad).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Twist;

/// The press fit twisted, as a type: see [`Problem`].
pub type PressFitTorqueProblem = FitProblem<Twist>;

/// The press fit twisted, as a value (what the registry hands out).
#[allow(non_upper_case_globals)]
pub const PressFitTorqueProblem: PressFitTorqueProblem = FitProblem(PhantomData);

impl FitBridges for PushOut {
    type Params = PressFitInputs;
    type Model = PressFitModel;
    enum_bridges!(PressFit);
}

impl FitBridges for Twist {
    type Params = PressFitInputs;
    type Model = PressFitModel;
    enum_bridges!(PressFitTorque);
}

/// No continuum: the axisymmetric continuum ([`solve_pressfit_continuum`]) is the push-out's; a
/// torsional continuum is left.
impl FitKind for Twist {
    const LOAD: FitLoad = FitLoad::Torque;
    const INFO: &'static Description = &TORQUE_DESCRIPTION;
    const REFUSED_AS: &'static str = "the twisted press fit";
    type Key = TorqueParam;
    const LOAD_PARAM: Param = Param::PressFitTorque(TorqueParam(PressFitParam::Torque));
    const STIFFNESS_PARAM: Param = Param::PressFitTorque(TorqueParam(PressFitParam::Stiffness));
    /// Half T_gross = 27 420 N mm (F_gross 1371 N times r = 20 mm).
    const PAPER_LOAD: f64 = 13_710.0;
    fn param(key: TorqueParam) -> PressFitParam {
        key.0
    }
    const CONTINUUM: Option<ContinuumResponse> = None;
    const LOAD_COLUMN: &'static str = "T_Nmm";
    const RESPONSE_COLUMN: &'static str = "theta_rad";
    const FITTED: &'static str = "twisted press fit";
    const HELD: &'static [TorqueParam] = TorqueParam::STRUCTURE;
    const COMPARED: &'static [&'static str] =
        &["pressfit-torque theta (rad)", "pressfit-torque zones (/L)"];
}

impl FitKind for PushOut {
    const LOAD: FitLoad = FitLoad::Axial;
    const INFO: &'static Description = &DESCRIPTION;
    const REFUSED_AS: &'static str = "the press fit";
    type Key = PressFitParam;
    const LOAD_PARAM: Param = Param::PressFit(PressFitParam::Force);
    const STIFFNESS_PARAM: Param = Param::PressFit(PressFitParam::Stiffness);
    const PAPER_LOAD: f64 = 685.5;
    fn param(key: PressFitParam) -> PressFitParam {
        key
    }
    const CONTINUUM: Option<ContinuumResponse> = Some(continuum_response::<PressFitProblem>);
    const LOAD_COLUMN: &'static str = "F_N";
    const RESPONSE_COLUMN: &'static str = "Delta_mm";
    const FITTED: &'static str = "press fit";
    const HELD: &'static [PressFitParam] = PressFitParam::STRUCTURE;
    const COMPARED: &'static [&'static str] = &["pressfit Delta (mm)", "pressfit zones (/L)"];
}

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

impl<K: FitKind> Problem for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    const INFO: &'static Description = K::INFO;
    const REFUSED_AS: &'static str = K::REFUSED_AS;
    type Key = K::Key;
    type Params = PressFitInputs;
    type Model = PressFitModel;
    type State = Laws<FitState, FitState>;

    /// The #98 fit at half its gross load.
    fn paper() -> PressFitInputs {
        PressFitInputs {
            structure: PressFitParams::CCX98,
            force: K::PAPER_LOAD,
        }
    }

    fn slot(params: &mut PressFitInputs, index: usize) -> Option<&mut f64> {
        match K::param(*<K::Key as ParamKey>::KEYS.get(index)?) {
            PressFitParam::Force | PressFitParam::Torque => Some(&mut params.force),
            param => params.structure.value_mut(param),
        }
    }

    fn model(params: &PressFitInputs) -> Result<PressFitModel, ParamError> {
        let fit = PressFit::new(params.structure)?;
        Ok(PressFitModel {
            fit,
            force: fit.axis(K::LOAD).load(params.force)?,
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
            coulomb: model.fit.axis(K::LOAD).coulomb(model.force),
            regularized: model.fit.axis(K::LOAD).regularized(model.force),
        }
    }

    fn quantity(model: &PressFitModel, quantity: Quantity) -> Option<f64> {
        crate::problems::pressfit::quantity(model.fit.axis(K::LOAD), model.force, quantity)
    }

    fn regime_scale(model: &PressFitModel) -> Option<f64> {
        Some(Self::force_scale(&model.fit))
    }

    /// The domain, narrowed where the inputs bound one another: ri < r < ro (each radius between
    /// its neighbours), and F <= F_gross = mu p 2 pi r L (T <= T_gross = F_gross r), which bounds
    /// the load from above and mu, delta and L from below (the gross load is proportional to
    /// each: p to delta). The radii and the moduli
    /// move F_gross too, not in proportion (p falls to 0 as either wall thins, and grows with
    /// each modulus): their bounds are found by bisection on the model's acceptance.
    fn accepted_range(model: &PressFitModel, index: usize) -> (f64, f64) {
        let Some(param) = <K::Key as ParamKey>::KEYS.get(index).map(|&k| K::param(k)) else {
            return (f64::NAN, f64::NAN);
        };
        let domain = param.spec().domain;
        let (min, max) = (domain.min(), domain.max());
        let p = model.fit.params();
        let gross = model.fit.axis(K::LOAD).gross_load();
        match param {
            PressFitParam::Force | PressFitParam::Torque => (min, max.min(gross)),
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
        continuum: K::CONTINUUM,
        load_driven: Some(&LoadDrivenOf::<Self>::NEW),
        fittable: Some(&FittableOf::<Self>::NEW),
        cross_checked: Some(&CrossCheckedOf::<Self>::NEW),
        zoned: Some(erased_layout::<Self>),
        ..ProblemFaces::NONE
    };

    fn to_inputs(params: PressFitInputs) -> Inputs {
        K::to_inputs(params)
    }

    fn from_inputs(inputs: &Inputs) -> Option<PressFitInputs> {
        K::from_inputs(inputs)
    }

    fn to_model(model: PressFitModel) -> Model {
        K::to_model(model)
    }

    fn from_model(model: &Model) -> Option<PressFitModel> {
        K::from_model(model)
    }
}

/// The axisymmetric continuum is the push-out's (a torsional continuum is left).
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
        for (kind, load, key) in [
            (ModelKind::PressFit, FitLoad::Axial, "F"),
            (ModelKind::PressFitTorque, FitLoad::Torque, "T"),
        ] {
            checks::erased_answers_as_typed(kind, |v| {
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
                let axis = fit.axis(load);
                let force = axis.load(v(key))?;
                let answers = checks::answers(&axis.coulomb(force), &axis.regularized(force));
                Ok((answers, Some(axis.gross_load())))
            });
        }
    }

    /// The twisted fit: registered, no continuum, its paper load half T_gross = mu p 2 pi r^2 L
    /// (by hand from Lame's p), its answers the torsion's.
    #[test]
    fn the_twisted_fit_is_registered_at_half_its_gross_torque() {
        checks::registered::<PressFitTorqueProblem>();
        assert!(PressFitTorqueProblem::FACES.continuum.is_none());
        let model = PressFitTorqueProblem::model(&PressFitTorqueProblem::paper()).unwrap();
        let p = model.fit.params();
        let gross = p.friction
            * model.fit.contact_pressure()
            * 2.0
            * std::f64::consts::PI
            * p.fit_radius.powi(2)
            * p.length;
        assert!((model.force.value() / gross - 0.5).abs() < 1e-4, "{gross}");
        let state = PressFitTorqueProblem::solve(&model);
        assert_eq!(
            state.regularized.response(),
            model.fit.torsion().regularized(model.force).response()
        );
        assert_eq!(
            PressFitTorqueProblem::regime_scale(&model),
            Some(model.fit.torsion().gross_load())
        );
    }
}
