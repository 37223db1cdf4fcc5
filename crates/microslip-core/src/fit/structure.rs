//! What is fitted: the structure of a fittable problem ([`Fittable`]), all but mu and K_T fixed,
//! and the same structure at a trial (mu, K_T).

use std::fmt;

use crate::kernel::params::ParamError;
use crate::problems::fittable::{self, AnyFittable, FitCurve, Fittable};
use crate::problems::inputs::Model;
use crate::problems::{ModelKind, Param};

/// What is fitted: the structure of a problem with a load-response curve ([`Fittable`]), held
/// as a [`Model`] of it (its force is not used: the fit's forces are the measured ones). Made by
/// [`Structure::of`] for any model (`None`: the problem has no curve to fit) or
/// [`Structure::typed`] from a typed structure.
#[derive(Clone, Copy)]
pub struct Structure {
    fittable: &'static dyn AnyFittable,
    model: Model,
}

impl fmt::Debug for Structure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Structure")
            .field("model", &self.model)
            .finish()
    }
}

impl PartialEq for Structure {
    /// The same structure: the capability follows from the model's problem.
    fn eq(&self, other: &Self) -> bool {
        self.model == other.model
    }
}

impl Structure {
    /// The structure of `model`, when its problem is fittable; `None` for a problem without a
    /// load-response curve (the plate): the one place that says which problems `f` fits.
    pub fn of(model: &Model) -> Option<Structure> {
        let fittable = model.kind().problem().faces().fittable?;
        Some(Structure {
            fittable,
            model: *model,
        })
    }

    /// The typed `structure` of the fittable problem `P`.
    pub fn typed<P: Fittable>(structure: &P::Structure) -> Structure {
        Structure {
            fittable: &fittable::FittableOf::<P>::NEW,
            model: fittable::unloaded::<P>(structure),
        }
    }

    /// The problem fitted.
    pub fn kind(&self) -> ModelKind {
        self.model.kind()
    }

    /// The model the structure is held as (at no particular force).
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// What the fit's report calls it (`twin beams`).
    pub fn fitted(&self) -> &'static str {
        self.fittable.fitted()
    }

    /// The parameters the fit holds, with their values, in the order its report lists them.
    pub fn held(&self) -> Vec<(Param, f64)> {
        let inputs = self.model.inputs();
        self.fittable
            .held()
            .into_iter()
            .filter_map(|p| Some((p, inputs.get(p)?)))
            .collect()
    }

    /// The header of its response column in a measurement file (`w_mm`).
    pub fn response_column(&self) -> &'static str {
        self.fittable.response_column()
    }

    /// The header of its load column in a measurement file (`F_N`, `Q_N_per_mm`).
    pub fn load_column(&self) -> &'static str {
        self.fittable.load_column()
    }

    /// Its load parameter (F, the cylinder's Q): name, unit and domain.
    pub fn load(&self) -> Param {
        self.fittable.load()
    }

    /// What bounds the load it carries, in the problem's words
    /// ([`Description::bound_sentence`](crate::problems::Description::bound_sentence)), for the
    /// refusal of a measured force no mu carries; empty for a structure without one.
    pub(super) fn bound(&self) -> String {
        self.kind()
            .description()
            .bound_sentence()
            .unwrap_or_default()
    }

    /// The structure at `mu`, `kt`; `None` where they (or the structure) are not accepted.
    pub(super) fn at(&self, mu: f64, kt: f64) -> Option<Box<dyn FitCurve>> {
        self.checked_at(mu, kt)?.ok()
    }

    /// The structure at `mu`, `kt`, or why it refuses them; `None` only for a structure whose
    /// model is not its capability's (not made by [`Structure::of`] or [`Structure::typed`]).
    pub(super) fn checked_at(
        &self,
        mu: f64,
        kt: f64,
    ) -> Option<Result<Box<dyn FitCurve>, ParamError>> {
        self.fittable.curve(&self.model, mu, kt)
    }

    /// The structure's own mu and K_T.
    pub(super) fn own(&self) -> (f64, f64) {
        self.fittable
            .interface(&self.model)
            .unwrap_or((f64::NAN, f64::NAN))
    }

    /// [`Fittable::force_per_friction`].
    pub(super) fn force_per_friction(&self) -> Option<f64> {
        self.fittable.force_per_friction(&self.model).flatten()
    }
}
