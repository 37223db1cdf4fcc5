//! The Hertzian cylinder as a [`Problem`]: the one place the generic layers' view of it
//! (parameter values by index, the model, both laws' solutions, the bound Q <= mu P its inputs
//! put on one another) is mapped onto its own types.

use std::str::FromStr;

use super::closed_form::{Cylinder, CylinderParams, MindlinState, TangentialLoad};
use super::description::DESCRIPTION;
use super::params::CylinderParam;
use super::regularized::RegularizedState;
use crate::kernel::params::ParamError;
use crate::problems::cross_check::CrossCheckedOf;
use crate::problems::fittable::FittableOf;
use crate::problems::inputs::InterfaceData;
use crate::problems::load_driven::LoadDrivenOf;
use crate::problems::problem::{Laws, ParamKey, Problem, ProblemFaces};
use crate::problems::zoned::erased_layout;
use crate::problems::{Description, ModelKind, Quantity, UnknownParam};

/// The Hertzian cylinder on a flat as a type: see [`Problem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CylinderProblem;

/// The contact's parameters and the tangential line load Q (N/mm), unvalidated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderInputs {
    /// The cylinder, the flat and their interface.
    pub structure: CylinderParams,
    /// Tangential line load Q (N/mm, per mm of the cylinder's length).
    pub load: f64,
}

/// A validated contact at a tangential load it carries (Q <= mu P).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderModel {
    /// The contact.
    pub cylinder: Cylinder,
    /// The tangential line load on it.
    pub load: TangentialLoad,
}

impl FromStr for CylinderParam {
    type Err = UnknownParam;

    fn from_str(key: &str) -> Result<Self, Self::Err> {
        <CylinderParam as ParamKey>::parse_key(key, ModelKind::Cylinder)
    }
}

impl Problem for CylinderProblem {
    const INFO: &'static Description = &DESCRIPTION;
    const REFUSED_AS: &'static str =
        "the cylinder (two elastic half-planes in contact: no bending)";
    type Key = CylinderParam;
    type Params = CylinderInputs;
    type Model = CylinderModel;
    type State = Laws<MindlinState, RegularizedState>;

    /// The bundled steel pad at Q = mu P / 2 = 300 N/mm.
    fn paper() -> CylinderInputs {
        CylinderInputs {
            structure: CylinderParams::STEEL_PAD,
            load: 300.0,
        }
    }

    // The description lists the parameters in the order of `CylinderParam::ALL`.
    fn slot(params: &mut CylinderInputs, index: usize) -> Option<&mut f64> {
        match *CylinderParam::ALL.get(index)? {
            CylinderParam::TangentialLoad => Some(&mut params.load),
            param => params.structure.value_mut(param),
        }
    }

    fn model(params: &CylinderInputs) -> Result<CylinderModel, ParamError> {
        let cylinder = Cylinder::new(params.structure)?;
        Ok(CylinderModel {
            cylinder,
            load: cylinder.load(params.load)?,
        })
    }

    fn params(model: &CylinderModel) -> CylinderInputs {
        CylinderInputs {
            structure: model.cylinder.params(),
            load: model.load.newtons_per_mm(),
        }
    }

    fn solve(model: &CylinderModel) -> Self::State {
        Laws {
            coulomb: model.cylinder.coulomb(model.load),
            regularized: model.cylinder.regularized(model.load),
        }
    }

    fn quantity(model: &CylinderModel, quantity: Quantity) -> Option<f64> {
        super::description::quantity(model, quantity)
    }

    /// The gross-slip load mu P (N/mm), also Q's upper bound.
    fn regime_scale(model: &CylinderModel) -> Option<f64> {
        Some(model.cylinder.gross_slip_load())
    }

    /// The contact's half-width a as its length, its peak pressure p0 as its pressure (what an
    /// FE code's slip tolerance meets where it matters, at the centre), E and nu of both bodies.
    fn interface(model: &CylinderModel) -> InterfaceData {
        let p = model.cylinder.params();
        InterfaceData {
            length: model.cylinder.half_width(),
            friction: p.friction,
            pressure: model.cylinder.peak_pressure(),
            modulus: p.modulus,
            stiffness: p.tangential_stiffness,
            poisson: Some(p.poisson),
        }
    }

    /// The domain, and Q <= mu P, which bounds Q from above and P and mu from below; and
    /// Hertz's a < R, which bounds P from above (pi E* R / 4) and R and E from below.
    fn accepted_range(model: &CylinderModel, index: usize) -> (f64, f64) {
        let Some(&param) = CylinderParam::ALL.get(index) else {
            return (f64::NAN, f64::NAN);
        };
        let domain = param.spec().domain;
        let (min, max) = (domain.min(), domain.max());
        let gross = model.cylinder.gross_slip_load();
        match param {
            CylinderParam::TangentialLoad => (min, max.min(gross)),
            CylinderParam::NormalLoad => {
                let (lowest, _) = Self::range_above_proportional_bound(
                    model,
                    index,
                    (min, max),
                    (model.load.newtons_per_mm(), gross),
                );
                (lowest, Self::accepted_toward(model, index, max))
            }
            CylinderParam::Friction => Self::range_above_proportional_bound(
                model,
                index,
                (min, max),
                (model.load.newtons_per_mm(), gross),
            ),
            CylinderParam::Radius | CylinderParam::Modulus => {
                (Self::accepted_toward(model, index, min), max)
            }
            _ => (min, max),
        }
    }

    const FACES: &'static ProblemFaces = &ProblemFaces {
        load_driven: Some(&LoadDrivenOf::<CylinderProblem>::NEW),
        fittable: Some(&FittableOf::<CylinderProblem>::NEW),
        cross_checked: Some(&CrossCheckedOf::<CylinderProblem>::NEW),
        zoned: Some(erased_layout::<CylinderProblem>),
        ..ProblemFaces::NONE
    };

    enum_bridges!(Cylinder);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::Param;
    use crate::problems::problem::checks;

    #[test]
    fn the_cylinder_is_registered_and_answers_the_same_erased_as_typed() {
        checks::registered::<CylinderProblem>();
        checks::erased_answers_as_typed(ModelKind::Cylinder, |v| {
            let cylinder = Cylinder::new(CylinderParams {
                radius: v("R"),
                modulus: v("E"),
                poisson: v("nu"),
                normal_load: v("P"),
                friction: v("mu"),
                tangential_stiffness: v("KT"),
            })?;
            let load = cylinder.load(v("Q"))?;
            let answers = checks::answers(&cylinder.coulomb(load), &cylinder.regularized(load));
            Ok((answers, Some(cylinder.gross_slip_load())))
        });
    }

    #[test]
    fn typed_clamping_agrees_with_the_enum_and_keeps_the_load_carried() {
        let model = crate::problems::inputs::Inputs::paper(ModelKind::Cylinder)
            .validate()
            .unwrap();
        let typed = CylinderProblem::from_model(&model).unwrap();
        let gross = typed.cylinder.gross_slip_load();
        for (key, value) in [
            (CylinderParam::TangentialLoad, 10.0 * gross),
            (CylinderParam::NormalLoad, 1e-9),
            (CylinderParam::Friction, 0.05),
            (CylinderParam::Stiffness, -1.0),
        ] {
            let clamped = CylinderProblem::with_clamped(&typed, key, value);
            assert_eq!(
                CylinderProblem::to_model(clamped),
                model.with_clamped(Param::Cylinder(key), value),
                "{key}"
            );
        }
        // Q far beyond mu P is held at mu P; P far below is held where mu P = Q.
        let held = CylinderProblem::with_clamped(&typed, CylinderParam::TangentialLoad, 1e6);
        assert_eq!(held.load.newtons_per_mm(), gross);
        let light = CylinderProblem::with_clamped(&typed, CylinderParam::NormalLoad, 1e-9);
        assert!(light.cylinder.gross_slip_load() >= typed.load.newtons_per_mm());
        assert!(light.cylinder.params().normal_load < typed.cylinder.params().normal_load);
        assert_eq!(
            "Q".parse::<CylinderParam>(),
            Ok(CylinderParam::TangentialLoad)
        );
        assert!(
            "F".parse::<CylinderParam>()
                .unwrap_err()
                .to_string()
                .ends_with("(allowed: R E nu P mu KT Q)")
        );
    }

    /// The faces every problem writes read one solve: the zone strip's stretches, the point row,
    /// the profiles (even in x, mu p in the sliding zones), the K_T answer (the model's own K_T
    /// gives the model's state; s(a) falls to Mindlin's as K_T grows) and the quantities.
    #[test]
    fn every_face_reads_the_same_solve() {
        use crate::problems::pointwise::Pointwise;
        use crate::problems::profiled::Profiled;
        use crate::problems::stiffness_answer::StiffnessAnswer;
        let model = CylinderProblem::model(&CylinderProblem::paper()).unwrap();
        let state = CylinderProblem::solve(&model);
        let (mindlin, regularized) = (state.coulomb, state.regularized);
        let layout = crate::problems::zoned::layout::<CylinderProblem>(&model);
        assert_eq!(layout.length, model.cylinder.half_width());
        assert_eq!(layout.coulomb.holding, [0.0, mindlin.stick_half_width()]);
        assert_eq!(
            layout.regularized.holding,
            [0.0, regularized.micro_half_width()]
        );
        assert_eq!(layout.coulomb.regime.label(), "stick+macroslip");
        assert_eq!(layout.regularized.regime.label(), "microslip+macroslip");
        let point = CylinderProblem::point(&model);
        assert_eq!(point.edge_slip_regularized, regularized.edge_slip());
        assert_eq!(point.zone_coulomb, mindlin.stick_half_width());
        assert_eq!(point.regime_regularized, regularized.regime());
        let a = model.cylinder.half_width();
        let xs: Vec<f64> = (0..=20).map(|i| a * (i as f64 / 10.0 - 1.0)).collect();
        let (coulomb, regular) = CylinderProblem::shear_along(&model, xs.iter().copied());
        for (i, &x) in xs.iter().enumerate() {
            let mirror = xs.len() - 1 - i;
            assert!((regular[i].1 - regular[mirror].1).abs() < 1e-9, "{x}");
            assert!((coulomb[i].1 - coulomb[mirror].1).abs() < 1e-9, "{x}");
            if x.abs() > regularized.micro_half_width() {
                let limit = 0.6 * model.cylinder.pressure_at(x);
                assert!((regular[i].1 - limit).abs() < 1e-9, "{x}");
            }
        }
        let own = model.cylinder.params().tangential_stiffness;
        let answer = CylinderProblem::answer(&model, own).unwrap();
        assert_eq!(answer.edge_slip, regularized.edge_slip());
        assert_eq!(answer.zone, regularized.micro_half_width());
        let mindlin_slip = CylinderProblem::coulomb_response(&model);
        assert_eq!(mindlin_slip, mindlin.edge_slip());
        let mut last = f64::INFINITY;
        for kt in [1e3, 1e5, 1e7, 1e9, 1e11] {
            let slip = CylinderProblem::answer(&model, kt).unwrap().edge_slip;
            assert!(slip < last && slip > mindlin_slip, "{kt}");
            last = slip;
        }
        assert!(CylinderProblem::answer(&model, -1.0).is_none());
        let quantity = |q| CylinderProblem::quantity(&model, q).unwrap();
        assert_eq!(quantity(Quantity::Response), regularized.edge_slip());
        assert_eq!(quantity(Quantity::MicroEnd), regularized.micro_half_width());
        let ratio = regularized.edge_slip() / mindlin.edge_slip();
        assert_eq!(quantity(Quantity::Ratio), ratio);
        assert_eq!(
            CylinderProblem::quantity(&model, Quantity::SlideFromStart),
            None
        );
    }
}
