//! The squeezed plate as a [`Problem`] and a [`Continuum`]: the one place the generic layers'
//! view of it (parameter values by index, the model, both laws' solutions, the plane-strain
//! reference) is mapped onto its own types.

use super::DESCRIPTION;
use super::closed_form::{CoulombPlate, RegularizedPlate, SqueezedPlate};
use super::continuum::{ContinuumMesh, ContinuumPlate, solve_plate_continuum};
use super::params::{PlateParam, PlateParams};
use crate::kernel::params::{ParamError, ParamSpec};
use crate::numeric::NumericError;
use crate::problems::cross_check::CrossCheckedOf;
use crate::problems::inputs::InterfaceData;
use crate::problems::problem::{
    Continuum, Laws, ParamKey, Problem, ProblemFaces, continuum_response,
};
use crate::problems::zoned::erased_layout;
use crate::problems::{Description, Quantity};

/// The squeezed plate (paper section 2.2) as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SqueezedPlateProblem;

impl ParamKey for PlateParam {
    // `ALL` is the description's order (`param_list!`).
    const KEYS: &'static [PlateParam] = &PlateParam::ALL;

    fn spec(self) -> ParamSpec {
        PlateParam::spec(self)
    }
}

impl Problem for SqueezedPlateProblem {
    const INFO: &'static Description = &DESCRIPTION;
    const REFUSED_AS: &'static str = "the plate";
    type Key = PlateParam;
    type Params = PlateParams;
    type Model = SqueezedPlate;
    type State = Laws<CoulombPlate, RegularizedPlate>;

    fn paper() -> PlateParams {
        PlateParams::PAPER
    }

    // The description lists the parameters in the order of `PlateParam::ALL` (`param_list!`).
    fn slot(params: &mut PlateParams, index: usize) -> Option<&mut f64> {
        Some(params.value_mut(*PlateParam::ALL.get(index)?))
    }

    fn model(params: &PlateParams) -> Result<SqueezedPlate, ParamError> {
        SqueezedPlate::new(*params)
    }

    fn params(model: &SqueezedPlate) -> PlateParams {
        model.params()
    }

    fn solve(model: &SqueezedPlate) -> Self::State {
        Laws {
            coulomb: model.coulomb(),
            regularized: model.regularized(),
        }
    }

    fn quantity(model: &SqueezedPlate, quantity: Quantity) -> Option<f64> {
        super::quantity(model, quantity)
    }

    /// The plate is loaded by its pressure alone: no load, no regime scale.
    fn regime_scale(_: &SqueezedPlate) -> Option<f64> {
        None
    }

    fn interface(model: &SqueezedPlate) -> InterfaceData {
        let p = model.params();
        InterfaceData {
            length: p.half_length,
            friction: p.friction,
            pressure: p.pressure,
            modulus: p.youngs_modulus,
            stiffness: p.tangential_stiffness,
            poisson: Some(p.poisson),
        }
    }

    const FACES: &'static ProblemFaces = &ProblemFaces {
        continuum: Some(continuum_response::<SqueezedPlateProblem>),
        cross_checked: Some(&CrossCheckedOf::<SqueezedPlateProblem>::NEW),
        zoned: Some(erased_layout::<SqueezedPlateProblem>),
        ..ProblemFaces::NONE
    };

    enum_bridges!(Plate);
}

impl Continuum for SqueezedPlateProblem {
    type Mesh = ContinuumMesh;
    type Reference = ContinuumPlate;

    fn solve_continuum(
        model: &SqueezedPlate,
        mesh: ContinuumMesh,
    ) -> Result<ContinuumPlate, NumericError> {
        solve_plate_continuum(model.params(), mesh)
    }

    /// u(L) averaged through the thickness: what the strip theory's u stands for.
    fn continuum_response(reference: &ContinuumPlate) -> f64 {
        reference.end_displacement_mean
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::problem::checks;
    use crate::problems::{ModelKind, Problem};

    #[test]
    fn the_plate_is_registered_and_answers_the_same_erased_as_typed() {
        checks::registered::<SqueezedPlateProblem>();
        // The erased continuum is the typed one, on the default mesh.
        let model = crate::problems::inputs::Inputs::paper(ModelKind::Plate)
            .validate()
            .unwrap();
        let erased = SqueezedPlateProblem::FACES
            .continuum
            .and_then(|response| response(&model))
            .unwrap()
            .unwrap();
        let typed = solve_plate_continuum(PlateParams::PAPER, ContinuumMesh::default()).unwrap();
        assert_eq!(erased.to_bits(), typed.end_displacement_mean.to_bits());
        checks::erased_answers_as_typed(ModelKind::Plate, |v| {
            let plate = SqueezedPlate::new(PlateParams {
                half_length: v("L"),
                thickness: v("tp"),
                youngs_modulus: v("E"),
                poisson: v("nu"),
                friction: v("mu"),
                pressure: v("P"),
                tangential_stiffness: v("KT"),
            })?;
            Ok((
                checks::answers(&plate.coulomb(), &plate.regularized()),
                None,
            ))
        });
    }
}
