//! The twin beams as a [`Problem`] and a [`Continuum`]: the one place the generic layers' view
//! of them (parameter values by index, the model, both laws' solutions, the plane-stress
//! reference) is mapped onto their own types.

use super::DESCRIPTION;
use super::closed_form::{CoulombBeams, RegularizedBeams, TipForce, TwinBeams};
use super::continuum::{BeamsContinuumMesh, ContinuumBeams, solve_beams_continuum};
use super::params::{BeamParam, TwinBeamsParams};
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

/// The twin cantilever beams (paper section 2.1) as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TwinBeamsProblem;

/// The beams' parameters and the tip force F (N), unvalidated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamsInputs {
    /// Structure and interface.
    pub structure: TwinBeamsParams,
    /// Tip force on each beam (N).
    pub force: f64,
}

/// Validated beams at a tip force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamsModel {
    /// The beams.
    pub beams: TwinBeams,
    /// The tip force.
    pub force: TipForce,
}

impl ParamKey for BeamParam {
    // `ALL` is the description's order (`param_list!`).
    const KEYS: &'static [BeamParam] = &BeamParam::ALL;

    fn spec(self) -> ParamSpec {
        BeamParam::spec(self)
    }
}

impl Problem for TwinBeamsProblem {
    const INFO: &'static Description = &DESCRIPTION;
    type Key = BeamParam;
    type Params = BeamsInputs;
    type Model = BeamsModel;
    type State = Laws<CoulombBeams, RegularizedBeams>;

    /// The paper's beams at F = 100 N.
    fn paper() -> BeamsInputs {
        BeamsInputs {
            structure: TwinBeamsParams::PAPER,
            force: 100.0,
        }
    }

    // The description lists the parameters in the order of `BeamParam::ALL` (`param_list!`).
    fn slot(params: &mut BeamsInputs, index: usize) -> Option<&mut f64> {
        match *BeamParam::ALL.get(index)? {
            BeamParam::Force => Some(&mut params.force),
            param => params.structure.value_mut(param),
        }
    }

    fn model(params: &BeamsInputs) -> Result<BeamsModel, ParamError> {
        Ok(BeamsModel {
            beams: TwinBeams::new(params.structure)?,
            force: TipForce::new(params.force)?,
        })
    }

    /// The force is checked first, as the beams always did.
    fn model_without_load(params: &BeamsInputs) -> Result<BeamsModel, ParamError> {
        TipForce::new(params.force)?;
        Ok(BeamsModel {
            beams: TwinBeams::new(params.structure)?,
            force: TipForce::clamped(0.0),
        })
    }

    fn params(model: &BeamsModel) -> BeamsInputs {
        BeamsInputs {
            structure: model.beams.params(),
            force: model.force.newtons(),
        }
    }

    fn solve(model: &BeamsModel) -> Self::State {
        Laws {
            coulomb: model.beams.coulomb(model.force),
            regularized: model.beams.regularized(model.force),
        }
    }

    fn quantity(model: &BeamsModel, quantity: Quantity) -> Option<f64> {
        super::quantity(&model.beams, model.force, quantity)
    }

    /// F_thre: the load-driven [`LoadDriven::force_scale`] of the beams.
    fn regime_scale(model: &BeamsModel) -> Option<f64> {
        Some(Self::force_scale(&model.beams))
    }

    fn interface(model: &BeamsModel) -> InterfaceData {
        let p = model.beams.params();
        InterfaceData {
            length: p.length,
            friction: p.friction,
            pressure: p.pressure,
            modulus: p.youngs_modulus,
            stiffness: p.tangential_stiffness,
            poisson: None,
        }
    }

    const FACES: &'static ProblemFaces = &ProblemFaces {
        continuum: Some(continuum_response::<TwinBeamsProblem>),
        load_driven: Some(&LoadDrivenOf::<TwinBeamsProblem>::NEW),
        fittable: Some(&FittableOf::<TwinBeamsProblem>::NEW),
        cross_checked: Some(&CrossCheckedOf::<TwinBeamsProblem>::NEW),
        zoned: Some(erased_layout::<TwinBeamsProblem>),
        // The beam theory ([`super::choice::TheoryChoice`]).
        choices: &[&super::choice::TheoryChoice],
    };

    enum_bridges!(Beam);
}

impl Continuum for TwinBeamsProblem {
    type Mesh = BeamsContinuumMesh;
    type Reference = ContinuumBeams;

    /// The same beams whatever their beam theory (the continuum has none).
    fn solve_continuum(
        model: &BeamsModel,
        mesh: BeamsContinuumMesh,
    ) -> Result<ContinuumBeams, NumericError> {
        solve_beams_continuum(model.beams.params(), model.force.newtons(), mesh)
    }

    /// The tip deflection w(L): the closed form's and the deck's.
    fn continuum_response(reference: &ContinuumBeams) -> f64 {
        reference.tip_deflection
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::problem::checks;
    use crate::problems::{ModelKind, Problem};

    #[test]
    fn the_beams_are_registered_and_answer_the_same_erased_as_typed() {
        checks::registered::<TwinBeamsProblem>();
        // The erased continuum is the typed one, on the default mesh.
        let model = crate::problems::inputs::Inputs::paper(ModelKind::Beam)
            .validate()
            .unwrap();
        let erased = TwinBeamsProblem::FACES
            .continuum
            .and_then(|response| response(&model))
            .unwrap()
            .unwrap();
        let typed =
            solve_beams_continuum(TwinBeamsParams::PAPER, 100.0, BeamsContinuumMesh::default())
                .unwrap();
        assert_eq!(erased.to_bits(), typed.tip_deflection.to_bits());
        checks::erased_answers_as_typed(ModelKind::Beam, |v| {
            let beams = TwinBeams::new(TwinBeamsParams {
                length: v("L"),
                width: v("b"),
                half_height: v("h"),
                youngs_modulus: v("E"),
                pressure: v("P"),
                friction: v("mu"),
                tangential_stiffness: v("KT"),
                poisson: v("nu"),
                ..TwinBeamsParams::PAPER
            })?;
            let force = TipForce::new(v("F"))?;
            let answers = checks::answers(&beams.coulomb(force), &beams.regularized(force));
            Ok((answers, Some(beams.threshold_force())))
        });
    }
}
