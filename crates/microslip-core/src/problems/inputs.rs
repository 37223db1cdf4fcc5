//! The inputs of any problem as users set them ([`Inputs`], unvalidated, addressed by typed
//! [`Param`]s) and the validated models the physics accepts ([`Model`]). Presets, `--set` and the
//! TUI all edit an [`Inputs`] and validate it through the checked constructors.

use crate::kernel::params::ParamError;
use crate::problems::{ModelKind, Param, Problem, Quantity, UnknownParam};

/// Writes [`Inputs`] and [`Model`] from the registry: one tuple variant per problem, holding
/// its [`Problem::Params`] and [`Problem::Model`], so that no file lists the problems again and
/// a variant cannot hold another problem's type.
macro_rules! any_inputs_and_model {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// Unvalidated inputs of one problem, as read from a preset, flags or key presses: its
        /// [`Problem::Params`], in the variant the registry gives it.
        ///
        /// # Examples
        /// ```
        /// use microslip_core::problems::inputs::Inputs;
        /// use microslip_core::problems::{BeamParam, ModelKind, Param};
        /// let mut inputs = Inputs::paper(ModelKind::Beam);
        /// inputs.set(Param::Beam(BeamParam::Stiffness), 120.0)?;
        /// assert!(inputs.validate().is_ok());
        /// inputs.set(Param::Beam(BeamParam::Length), -1.0)?;
        /// assert_eq!(
        ///     inputs.validate().unwrap_err().to_string(),
        ///     "invalid L = -1: must be > 0 and finite (mm)"
        /// );
        /// # Ok::<(), microslip_core::problems::UnknownParam>(())
        /// ```
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum Inputs {
            $($(#[$doc])* $variant(<crate::problems::$folder::$problem as Problem>::Params)),+
        }

        /// Validated inputs, what the physics accepts: one problem's [`Problem::Model`].
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum Model {
            $($(#[$doc])* $variant(<crate::problems::$folder::$problem as Problem>::Model)),+
        }

        impl Inputs {
            /// Which problem these inputs are for.
            pub fn kind(&self) -> ModelKind {
                match self {
                    $(Inputs::$variant(_) => ModelKind::$variant),+
                }
            }
        }

        impl Model {
            /// Which problem this model is of.
            pub fn kind(&self) -> ModelKind {
                match self {
                    $(Model::$variant(_) => ModelKind::$variant),+
                }
            }
        }
    };
}

crate::with_problems!(any_inputs_and_model);

/// The interface data common to every problem: what the K_T comparisons need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceData {
    /// Length L (beam length or plate half-length) (mm).
    pub length: f64,
    /// Friction coefficient (-).
    pub friction: f64,
    /// Contact pressure (MPa).
    pub pressure: f64,
    /// Young's modulus (MPa).
    pub modulus: f64,
    /// Tangential stiffness (MPa/mm).
    pub stiffness: f64,
    /// Poisson ratio, where the model has one.
    pub poisson: Option<f64>,
}

impl Model {
    /// This model as problem `P`'s, typed, when it is `P`'s: how a caller that asked for one
    /// problem gets its model, without a match that could only fail by a bug; otherwise the
    /// problem it is of.
    pub fn of<P: Problem>(self) -> Result<P::Model, ModelKind> {
        P::from_model(&self).ok_or(self.kind())
    }

    /// The inputs this model was validated from.
    pub fn inputs(&self) -> Inputs {
        // Every model is its own problem's: the registry's bridge always answers.
        self.kind().problem().model_inputs(self).unwrap_or_else(|| {
            debug_assert!(false, "a {} model its problem does not read", self.kind());
            Inputs::paper(self.kind())
        })
    }

    /// The same model with `param` set to the accepted value nearest to `value` (see
    /// [`crate::kernel::params::Domain::clamp`] and [`Model::accepted_range`]): infallible, for sweeps and root finding whose range was
    /// checked. A parameter of another problem leaves the model as it is.
    pub fn with_clamped(&self, param: Param, value: f64) -> Model {
        let mut inputs = self.inputs();
        let (lo, hi) = self.accepted_range(param);
        if inputs
            .set(param, param.spec().domain.clamp(value).clamp(lo, hi))
            .is_err()
        {
            return *self;
        }
        // Every other value came from this (valid) model and the new one is in its domain, so
        // validation succeeds; should it not, the model stays as it is rather than panicking.
        inputs.validate().unwrap_or(*self)
    }

    /// This model at zero load (the plate has none): for what does not depend on the load, so
    /// that the load's own limit (the lap joint's F <= F_gross) cannot constrain it.
    pub fn unloaded(&self) -> Model {
        let Some(load) = self.kind().description().load else {
            return *self;
        };
        let mut inputs = self.inputs();
        if inputs.set(load, 0.0).is_err() {
            return *self;
        }
        // Zero is in every load's domain and within what any structure carries.
        inputs.validate().unwrap_or(*self)
    }

    /// The value of `quantity` for this model, computed by its problem; `None` where the problem
    /// has no such quantity or it is not defined here (see [`crate::problems::Quantity`]).
    pub fn quantity(&self, quantity: Quantity) -> Option<f64> {
        self.kind().problem().model_quantity(self, quantity)
    }

    /// The load at which the regimes change, the scale the problem's load parameter steps and
    /// spans charts in: F_thre for the beams, F_gross for the lap joint (also its force's upper
    /// bound); None for a problem without a load parameter
    /// ([`crate::problems::Description::load`]).
    pub fn regime_scale(&self) -> Option<f64> {
        self.kind().problem().model_regime_scale(self)
    }

    /// The values `param` may take with every other input as in this model: its domain, and for
    /// the lap joint also F <= F_gross = 2 b mu P L, which bounds F from above and L, b, P and mu
    /// from below (F_gross is proportional to each of them). What a chart or sweep over `param`
    /// keeps inside, so that every point of it has a state. A parameter of another problem gets
    /// its domain.
    pub fn accepted_range(&self, param: Param) -> (f64, f64) {
        self.kind()
            .problem()
            .model_accepted_range(self, param)
            .unwrap_or_else(|| {
                let domain = param.spec().domain;
                (domain.min(), domain.max())
            })
    }

    /// The model's interface data.
    pub fn interface(&self) -> InterfaceData {
        let problem = self.kind().problem();
        problem.model_interface(self).unwrap_or_else(|| {
            debug_assert!(false, "a {} model its problem does not read", self.kind());
            InterfaceData {
                length: f64::NAN,
                friction: f64::NAN,
                pressure: f64::NAN,
                modulus: f64::NAN,
                stiffness: f64::NAN,
                poisson: None,
            }
        })
    }
}

impl Inputs {
    /// The paper's data set for `kind` (beams at F = 100 N), the bundled aluminium joint at F =
    /// 3000 N for the lap joint (both ends sliding): each problem's [`Problem::paper`].
    ///
    /// [`Problem::paper`]: crate::problems::Problem::paper
    pub fn paper(kind: ModelKind) -> Inputs {
        kind.problem().paper_inputs()
    }

    /// The value of a parameter, or `None` for a parameter of another problem.
    pub fn get(&self, param: Param) -> Option<f64> {
        self.kind().problem().get(self, param)
    }

    /// Sets one parameter without validating its range (see [`Inputs::validate`]).
    ///
    /// # Errors
    /// [`UnknownParam`] when `param` belongs to another problem.
    pub fn set(&mut self, param: Param, value: f64) -> Result<(), UnknownParam> {
        let model = self.kind();
        if model.problem().set(self, param, value) {
            Ok(())
        } else {
            Err(UnknownParam {
                key: param.name().to_string(),
                model,
            })
        }
    }

    /// Validates through the model's checked constructors.
    ///
    /// # Errors
    /// The first out-of-range parameter, in display order.
    pub fn validate(&self) -> Result<Model, ParamError> {
        self.kind()
            .problem()
            .validate(self)
            .unwrap_or_else(|| Err(self.foreign()))
    }

    /// As [`Inputs::validate`] for a command that does not use the load (a cycle's amplitude,
    /// a fit's or a comparison's own forces): the load is checked against its own domain only,
    /// not against what the structure carries (the lap joint's F_gross), and the model returned
    /// is unloaded ([`Model::unloaded`]), so a value the command never reads cannot refuse it.
    ///
    /// # Errors
    /// As [`Inputs::validate`], except the lap joint's F above F_gross.
    pub fn validate_without_load(&self) -> Result<Model, ParamError> {
        self.kind()
            .problem()
            .validate_without_load(self)
            .unwrap_or_else(|| Err(self.foreign()))
    }

    /// What [`Inputs::validate`] says should the registry's bridge not read these inputs, which
    /// would be a bug in a problem's `from_inputs`: an error rather than a panic in a user's
    /// session.
    fn foreign(&self) -> ParamError {
        debug_assert!(false, "{} inputs their problem does not read", self.kind());
        let first = self.kind().params()[0].spec();
        ParamError {
            field: first.name,
            value: f64::NAN,
            domain: first.domain,
            unit: first.unit,
            reason: None,
        }
    }

    /// Every out-of-range parameter, not only the first: each one is checked on its own against
    /// its domain, so one bad value cannot hide another.
    pub fn all_param_errors(&self) -> Vec<ParamError> {
        self.kind()
            .params()
            .iter()
            .filter_map(|&param| {
                let value = self.get(param)?;
                let spec = param.spec();
                spec.domain.check(spec.name, value, spec.unit).err()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What each problem's description says of it agrees with its code: it names its response,
    /// its names and aliases are unique, every quantity it lists is computed (finite, on the
    /// paper's data), and it has a load exactly where its model has a regime scale.
    #[test]
    fn every_description_agrees_with_its_problem() {
        use crate::problems::Quantity;
        for kind in ModelKind::ALL {
            let d = kind.description();
            assert_eq!(d.key, kind.name());
            assert!(
                d.quantities
                    .iter()
                    .any(|q| q.quantity == Quantity::Response),
                "{kind}: no response"
            );
            let mut spellings: Vec<&str> = d
                .quantities
                .iter()
                .flat_map(|q| std::iter::once(q.name).chain(q.aliases.iter().copied()))
                .collect();
            let count = spellings.len();
            spellings.sort_unstable();
            spellings.dedup();
            assert_eq!(spellings.len(), count, "{kind}: a name or alias twice");
            let model = Inputs::paper(kind).validate().unwrap();
            for q in d.quantities {
                let value = model.quantity(q.quantity);
                assert!(value.is_some_and(f64::is_finite), "{kind}: {}", q.name);
            }
            assert_eq!(d.load.is_some(), model.regime_scale().is_some(), "{kind}");
            assert_eq!(d.load.is_some(), !d.regime_scale_name.is_empty(), "{kind}");
            if let Some(load) = d.load {
                assert_eq!(load.model(), kind);
            }
        }
    }

    #[test]
    fn every_parameter_has_its_own_slot() {
        for kind in ModelKind::ALL {
            let mut inputs = Inputs::paper(kind);
            for (i, &param) in kind.params().iter().enumerate() {
                inputs.set(param, 1000.0 + i as f64).unwrap();
            }
            for (i, &param) in kind.params().iter().enumerate() {
                assert_eq!(inputs.get(param), Some(1000.0 + i as f64), "{param}");
            }
            let other = kind.next().params()[0];
            assert_eq!(inputs.get(other), None);
            assert!(inputs.set(other, 1.0).is_err());
        }
    }

    #[test]
    fn all_errors_are_listed_and_agree_with_the_constructors() {
        let mut inputs = Inputs::paper(ModelKind::Plate);
        inputs
            .set(Param::Plate(crate::problems::PlateParam::Poisson), 0.5)
            .unwrap();
        inputs
            .set(
                Param::Plate(crate::problems::PlateParam::Stiffness),
                f64::NAN,
            )
            .unwrap();
        let errors = inputs.all_param_errors();
        assert_eq!(
            errors.iter().map(|e| e.field).collect::<Vec<_>>(),
            ["nu", "KT"]
        );
        assert_eq!(inputs.validate().unwrap_err(), errors[0]);
        assert!(Inputs::paper(ModelKind::Beam).all_param_errors().is_empty());
    }
}
