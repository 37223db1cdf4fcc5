//! The double-lap joint as a [`Problem`] and a [`Continuum`]: the one place the generic layers'
//! view of it (parameter values by index, the model, both laws' solutions, the plane-strain
//! reference, the bound F <= F_gross its inputs put on one another) is mapped onto its own types.

use super::DESCRIPTION;
use super::closed_form::{JointForce, LapJoint, LapState};
use super::continuum::{ContinuumLap, LapContinuumMesh, solve_lap_continuum};
use super::params::{LapParam, LapParams};
use crate::kernel::params::{ParamError, ParamSpec};
use crate::numeric::NumericError;
use crate::problems::cross_check::CrossCheckedOf;
use crate::problems::fittable::FittableOf;
use crate::problems::inputs::InterfaceData;
use crate::problems::load_driven::{LoadDriven, LoadDrivenOf};
use crate::problems::problem::{
    Continuum, Laws, ParamKey, Problem, ProblemFaces, continuum_response,
};
use crate::problems::zoned::erased_layout;
use crate::problems::{Description, Quantity};

/// The clamped double-lap joint as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LapJointProblem;

/// The joint's parameters and the force through it F (N), unvalidated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapInputs {
    /// Structure and interface.
    pub structure: LapParams,
    /// Force through the joint (N).
    pub force: f64,
}

/// A validated joint at a force it carries (F <= F_gross).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapModel {
    /// The joint.
    pub joint: LapJoint,
    /// The force through it.
    pub force: JointForce,
}

impl ParamKey for LapParam {
    // `ALL` is the description's order (`param_list!`).
    const KEYS: &'static [LapParam] = &LapParam::ALL;

    fn spec(self) -> ParamSpec {
        LapParam::spec(self)
    }
}

impl Problem for LapJointProblem {
    const INFO: &'static Description = &DESCRIPTION;
    const REFUSED_AS: &'static str = "the lap joint (its plates are bars: no bending)";
    type Key = LapParam;
    type Params = LapInputs;
    type Model = LapModel;
    type State = Laws<LapState, LapState>;

    /// The bundled aluminium joint at F = 3000 N (both ends sliding).
    fn paper() -> LapInputs {
        LapInputs {
            structure: LapParams::ALUMINIUM,
            force: 3000.0,
        }
    }

    // The description lists the parameters in the order of `LapParam::ALL` (`param_list!`).
    fn slot(params: &mut LapInputs, index: usize) -> Option<&mut f64> {
        match *LapParam::ALL.get(index)? {
            LapParam::Force => Some(&mut params.force),
            param => params.structure.value_mut(param),
        }
    }

    fn model(params: &LapInputs) -> Result<LapModel, ParamError> {
        let joint = LapJoint::new(params.structure)?;
        Ok(LapModel {
            joint,
            force: joint.force(params.force)?,
        })
    }

    fn params(model: &LapModel) -> LapInputs {
        LapInputs {
            structure: model.joint.params(),
            force: model.force.newtons(),
        }
    }

    fn solve(model: &LapModel) -> Self::State {
        Laws {
            coulomb: model.joint.coulomb(model.force),
            regularized: model.joint.regularized(model.force),
        }
    }

    fn quantity(model: &LapModel, quantity: Quantity) -> Option<f64> {
        super::quantity(&model.joint, model.force, quantity)
    }

    /// F_gross, also the force's upper bound: the load-driven [`LoadDriven::force_scale`] of
    /// the joint.
    fn regime_scale(model: &LapModel) -> Option<f64> {
        Some(Self::force_scale(&model.joint))
    }

    /// The inner plate's modulus: the member every FE model of the joint meshes.
    fn interface(model: &LapModel) -> InterfaceData {
        let p = model.joint.params();
        InterfaceData {
            length: p.length,
            friction: p.friction,
            pressure: p.pressure,
            modulus: p.inner_modulus,
            stiffness: p.tangential_stiffness,
            poisson: None,
        }
    }

    /// The domain, and F <= F_gross = 2 b mu P L, which bounds F from above and L, b, P and mu
    /// from below (F_gross is proportional to each of them).
    fn accepted_range(model: &LapModel, index: usize) -> (f64, f64) {
        let Some(&param) = LapParam::ALL.get(index) else {
            return (f64::NAN, f64::NAN);
        };
        let domain = param.spec().domain;
        let (min, max) = (domain.min(), domain.max());
        let gross = model.joint.gross_slip_force();
        match param {
            LapParam::Force => (min, max.min(gross)),
            LapParam::Length | LapParam::Width | LapParam::Pressure | LapParam::Friction => {
                Self::range_above_proportional_bound(
                    model,
                    index,
                    (min, max),
                    (model.force.newtons(), gross),
                )
            }
            _ => (min, max),
        }
    }

    const FACES: &'static ProblemFaces = &ProblemFaces {
        continuum: Some(continuum_response::<LapJointProblem>),
        load_driven: Some(&LoadDrivenOf::<LapJointProblem>::NEW),
        fittable: Some(&FittableOf::<LapJointProblem>::NEW),
        cross_checked: Some(&CrossCheckedOf::<LapJointProblem>::NEW),
        zoned: Some(erased_layout::<LapJointProblem>),
        ..ProblemFaces::NONE
    };

    enum_bridges!(Lap);
}

impl Continuum for LapJointProblem {
    type Mesh = LapContinuumMesh;
    type Reference = ContinuumLap;

    fn solve_continuum(
        model: &LapModel,
        mesh: LapContinuumMesh,
    ) -> Result<ContinuumLap, NumericError> {
        solve_lap_continuum(model.joint.params(), model.force.newtons(), mesh)
    }

    /// The joint displacement Delta from the clamped state: the closed form's.
    fn continuum_response(reference: &ContinuumLap) -> f64 {
        reference.delta
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::problem::checks;
    use crate::problems::{ModelKind, Param, Problem};

    #[test]
    fn the_joint_is_registered_and_answers_the_same_erased_as_typed() {
        checks::registered::<LapJointProblem>();
        // The erased continuum is the typed one, on the default mesh.
        let model = crate::problems::inputs::Inputs::paper(ModelKind::Lap)
            .validate()
            .unwrap();
        let erased = LapJointProblem::FACES
            .continuum
            .and_then(|response| response(&model))
            .unwrap()
            .unwrap();
        let mesh = LapContinuumMesh::default();
        let typed = solve_lap_continuum(LapParams::ALUMINIUM, 3000.0, mesh).unwrap();
        assert_eq!(erased.to_bits(), typed.delta.to_bits());
        checks::erased_answers_as_typed(ModelKind::Lap, |v| {
            let joint = LapJoint::new(LapParams {
                length: v("L"),
                width: v("b"),
                inner_thickness: v("t1"),
                cover_thickness: v("t2"),
                inner_modulus: v("E1"),
                cover_modulus: v("E2"),
                pressure: v("P"),
                friction: v("mu"),
                tangential_stiffness: v("KT"),
            })?;
            let force = joint.force(v("F"))?;
            let answers = checks::answers(&joint.coulomb(force), &joint.regularized(force));
            Ok((answers, Some(joint.gross_slip_force())))
        });
    }

    #[test]
    fn typed_clamping_agrees_with_the_enum_and_keeps_the_force_carried() {
        let model = crate::problems::inputs::Inputs::paper(ModelKind::Lap)
            .validate()
            .unwrap();
        let typed = LapJointProblem::from_model(&model).unwrap();
        let gross = typed.joint.gross_slip_force();
        for (key, value) in [
            (LapParam::Force, 10.0 * gross),
            (LapParam::Length, 1e-9),
            (LapParam::Friction, 0.05),
            (LapParam::Stiffness, -1.0),
        ] {
            let clamped = LapJointProblem::with_clamped(&typed, key, value);
            assert_eq!(
                LapJointProblem::to_model(clamped),
                model.with_clamped(Param::Lap(key), value),
                "{key}"
            );
        }
        // F far beyond F_gross is held at F_gross; L far below is held where F_gross = F.
        let held = LapJointProblem::with_clamped(&typed, LapParam::Force, 10.0 * gross);
        assert_eq!(held.force.newtons(), gross);
        let short = LapJointProblem::with_clamped(&typed, LapParam::Length, 1e-9);
        assert!(short.joint.gross_slip_force() >= typed.force.newtons());
        assert!(short.joint.params().length < typed.joint.params().length);
    }
}
