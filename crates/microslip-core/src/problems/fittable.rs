//! The fittable capability: a load-driven problem whose measured load-response curve identifies
//! its interface, mu and K_T (docs/theory.md section 3b; the beams' identification is the
//! paper's section 2.1.3, the joint's Delta against F is (L11)). The fit itself (least squares
//! on the regularized closed form, `crate::fit`) is written once over [`AnyFittable`]; a problem
//! is fitted by implementing [`Fittable`] in its folder and handing out
//! `FittableOf::<Self>::NEW` in the `fittable` slot of its [`Problem::FACES`](crate::problems::Problem::FACES), with
//! no code outside its folder.
//!
//! What the fit needs of a problem, besides [`LoadDriven`]: the structure at a trial (mu, K_T),
//! the force F_1 above which mu shows in the curve, and, for a structure that carries a bounded
//! force (the joint's F_gross = 2 b mu P L grows with mu), how that bound scales with mu, so that
//! the search keeps to the mu that carry every measured force.

use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::inputs::Model;
use crate::problems::load_driven::LoadDriven;
use crate::problems::{Param, ParamKey};

/// A load-driven problem whose measured curve u(F) identifies mu and K_T (module docs).
pub trait Fittable: LoadDriven {
    /// The header of the load column in a measurement file: the load parameter's key and unit
    /// ([`LoadDriven::FORCE`]), `F_N` for a force (the default), `Q_N_per_mm` for the
    /// cylinder's line load, as the problem's own sweep table heads it, so that a sweep loads
    /// as a measurement.
    const LOAD_COLUMN: &'static str = "F_N";
    /// The header of the response column in a measurement file (`w_mm`, `Delta_mm`).
    const RESPONSE_COLUMN: &'static str;
    /// What the fit's report calls the structure (`twin beams`).
    const FITTED: &'static str;
    /// The parameters the fit holds and its report lists (geometry, moduli, P), in that order:
    /// all but mu, K_T, F and what the closed form does not use.
    const HELD: &'static [Self::Key];

    /// The structure's own interface (mu, K_T): what a fit holds when told to fix one.
    fn interface_of(structure: &Self::Structure) -> (f64, f64);
    /// The same structure with mu = `mu` and K_T = `kt`, all else equal, through its checked
    /// constructor.
    ///
    /// # Errors
    /// [`ParamError`] for a mu or K_T outside its domain.
    fn with_interface(
        structure: &Self::Structure,
        mu: f64,
        kt: f64,
    ) -> Result<Self::Structure, ParamError>;
    /// F_1 (N): above it the regularized interface slides somewhere, and mu shows in the curve.
    fn first_macroslip_force(structure: &Self::Structure) -> f64;
    /// The largest force the structure carries per unit mu (N), where it is bounded (the
    /// joint's F_gross / mu = 2 b P L); `None` (the default) for a structure that carries every
    /// force of the force's domain (the beams, in macroslip past F_thre).
    fn force_per_friction(_structure: &Self::Structure) -> Option<f64> {
        None
    }
}

/// A [`Fittable`] structure at one trial (mu, K_T), erased: what the least squares evaluate.
pub trait FitCurve {
    /// The regularized response u(F) (mm) at `newtons`; `None` for a force the structure does
    /// not carry.
    fn response(&self, newtons: f64) -> Option<f64>;
    /// Accepts `newtons` as a force the structure carries ([`LoadDriven::force`]).
    ///
    /// # Errors
    /// As [`LoadDriven::force`].
    fn carries(&self, newtons: f64) -> Result<(), ParamError>;
    /// (the regime scale, F_1) (N): F_thre and F_1 of the beams, F_gross and F_1 of the joint.
    fn regime_forces(&self) -> (f64, f64);
}

/// The [`FitCurve`] of a [`Fittable`] problem `P`: its structure at the trial values.
struct CurveOf<P: Fittable>(P::Structure);

impl<P: Fittable> FitCurve for CurveOf<P> {
    fn response(&self, newtons: f64) -> Option<f64> {
        let force = P::force(&self.0, newtons).ok()?;
        Some(P::response(&self.0, Law::Regularized, force))
    }

    fn carries(&self, newtons: f64) -> Result<(), ParamError> {
        P::force(&self.0, newtons).map(|_| ())
    }

    fn regime_forces(&self) -> (f64, f64) {
        (P::force_scale(&self.0), P::first_macroslip_force(&self.0))
    }
}

/// The [`Fittable`] capability of a problem, erased: what the fit, written once, asks of the
/// structure it holds as a [`Model`] of the problem (at any force: the fit uses the measured
/// ones). Every method that takes a model answers `None` for another problem's model.
pub trait AnyFittable: Send + Sync {
    /// [`Fittable::RESPONSE_COLUMN`].
    fn response_column(&self) -> &'static str;
    /// [`Fittable::LOAD_COLUMN`].
    fn load_column(&self) -> &'static str;
    /// The load parameter ([`LoadDriven::FORCE`]): its name, unit and domain.
    fn load(&self) -> Param;
    /// [`Fittable::FITTED`].
    fn fitted(&self) -> &'static str;
    /// [`Fittable::HELD`], as parameters of any problem.
    fn held(&self) -> Vec<Param>;
    /// The structure's own (mu, K_T) ([`Fittable::interface_of`]).
    fn interface(&self, model: &Model) -> Option<(f64, f64)>;
    /// The structure of `model` at (`mu`, `kt`) ([`Fittable::with_interface`]).
    fn curve(
        &self,
        model: &Model,
        mu: f64,
        kt: f64,
    ) -> Option<Result<Box<dyn FitCurve>, ParamError>>;
    /// [`Fittable::force_per_friction`] of `model`'s structure; `None` for another problem's
    /// model, `Some(None)` where the structure carries every force.
    fn force_per_friction(&self, model: &Model) -> Option<Option<f64>>;
}

/// The [`AnyFittable`] of a [`Fittable`] problem `P`: what its
/// [`Problem::FACES`](crate::problems::Problem::FACES) holds.
#[derive(Debug)]
pub struct FittableOf<P>(std::marker::PhantomData<P>);

impl<P> FittableOf<P> {
    /// The erased fittable capability of `P`.
    pub const NEW: FittableOf<P> = FittableOf(std::marker::PhantomData);
}

impl<P: Fittable> AnyFittable for FittableOf<P> {
    fn response_column(&self) -> &'static str {
        P::RESPONSE_COLUMN
    }

    fn load_column(&self) -> &'static str {
        P::LOAD_COLUMN
    }

    fn load(&self) -> Param {
        P::FORCE
    }

    fn fitted(&self) -> &'static str {
        P::FITTED
    }

    fn held(&self) -> Vec<Param> {
        P::HELD
            .iter()
            .filter_map(|key| P::INFO.params.get(ParamKey::index(*key)).copied())
            .collect()
    }

    fn interface(&self, model: &Model) -> Option<(f64, f64)> {
        Some(P::interface_of(&P::structure(&P::from_model(model)?)))
    }

    fn curve(
        &self,
        model: &Model,
        mu: f64,
        kt: f64,
    ) -> Option<Result<Box<dyn FitCurve>, ParamError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some(
            P::with_interface(&structure, mu, kt)
                .map(|at| Box::new(CurveOf::<P>(at)) as Box<dyn FitCurve>),
        )
    }

    fn force_per_friction(&self, model: &Model) -> Option<Option<f64>> {
        Some(P::force_per_friction(&P::structure(&P::from_model(model)?)))
    }
}

/// The model of `P` at its structure `structure` and no load: how a typed structure becomes the
/// [`Model`] the erased side holds.
pub fn unloaded<P: Fittable>(structure: &P::Structure) -> Model {
    P::to_model(P::at_force(structure, P::clamped_force(structure, 0.0)))
}

#[cfg(test)]
mod tests {
    use crate::problems::ModelKind;
    use crate::problems::inputs::Inputs;

    /// Exactly the load-driven problems are fittable, each names its own parameters, and another
    /// problem's model gets `None`.
    #[test]
    fn the_load_driven_problems_are_fittable_and_refuse_another_s_model() {
        for kind in ModelKind::ALL {
            let problem = kind.problem();
            assert_eq!(
                problem.faces().fittable.is_some(),
                problem.faces().load_driven.is_some(),
                "{kind}"
            );
            let Some(fittable) = problem.faces().fittable else {
                continue;
            };
            assert!(fittable.held().iter().all(|p| p.model() == kind));
            // The load column is the load parameter's key and unit, as its sweep heads it (a unit
            // of two symbols joined: `T_Nmm`, as the cycle's `D_Nmm`).
            let load = fittable.load();
            assert_eq!(Some(load), kind.description().load, "{kind}");
            assert_eq!(
                fittable.load_column(),
                format!("{}_{}", load.name(), load.unit().key()),
                "{kind}"
            );
            let model = Inputs::paper(kind).validate().unwrap();
            let (mu, kt) = fittable.interface(&model).unwrap();
            let curve = fittable.curve(&model, mu, kt).unwrap().unwrap();
            let (scale, first) = curve.regime_forces();
            // F_1 is 0 where the interface slides somewhere from the first newton (the
            // cylinder's edges, p -> 0 there).
            assert!(first >= 0.0 && scale > 0.0, "{kind}");
            let probe = if first > 0.0 {
                0.5 * first
            } else {
                0.5 * scale
            };
            assert!(curve.response(probe).unwrap() > 0.0, "{kind}");
            for other in ModelKind::ALL.into_iter().filter(|&o| o != kind) {
                let theirs = Inputs::paper(other).validate().unwrap();
                assert!(fittable.interface(&theirs).is_none());
                assert!(fittable.curve(&theirs, mu, kt).is_none());
            }
        }
    }
}
