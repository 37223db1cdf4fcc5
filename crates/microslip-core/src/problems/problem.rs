//! A problem is a type: the [`Problem`] trait each problem's folder implements, its capability
//! traits ([`Continuum`] here, [`LoadDriven`](crate::problems::load_driven::LoadDriven) in its
//! own module), and [`AnyProblem`], the same problem with its types erased, which the
//! generic layers hold as `&'static dyn AnyProblem` (from [`ModelKind::problem`]) so that a
//! feature is written once for every problem instead of as a `match` with an arm per problem.
//!
//! The typed side ([`Problem`]) is what a numerical user and the physics call; the erased side
//! ([`AnyProblem`]) speaks in plain numbers (parameter values as `&[f64]`, indexed like
//! [`Description::params`]) and in the enums generated from the registry ([`Inputs`],
//! [`Model`]), which the bridges (`to_inputs`, `from_model`, ...) connect to each problem's
//! typed side.
//!
//! # Dispatch in one place
//! The registry's list becomes the erased side here, once: [`AnyProblem`] (every registered
//! problem, blanket impl) with [`AnyProblem::faces`], the problem's one table of capabilities
//! ([`ProblemFaces`], its [`Problem::FACES`]), instead of a typed method and an erased forward
//! per capability; and [`ModelKind::visit`], the one typed dispatch ([`Visit`]) for what a higher
//! layer writes generic over the problem (a study's series). The application does the same once
//! above its chart layer (`report::face::faces` and `for_problem`).
//!
//! Measured by `validation/dispatch_lines.py` (issue 43, item 5: erased traits and their
//! impls, adapters, hand-outs, tables, typed dispatch with its bodies, registry callbacks; code
//! lines of the three crates), before and after the table: 1402 -> 1305 lines of dispatch
//! (1233 -> 989 without the typed dispatch and its command bodies), erased traits 12 -> 9
//! (`AnyContinuum`, `AnyZoned` became fns of the table, the Python face's `AnyFace` runs
//! through the application's `for_problem`), `with_problems!` expansions in shipped code 15 ->
//! 11, `pub` items of this crate 766 -> 768.

use std::fmt::Debug;
use std::hash::Hash;

use thiserror::Error;

use crate::kernel::params::{ParamError, ParamSpec};
use crate::kernel::regime::Regime;
use crate::numeric::NumericError;
use crate::problems::choice::AnyChoice;
use crate::problems::cross_check::AnyCrossChecked;
use crate::problems::fittable::AnyFittable;
use crate::problems::inputs::{Inputs, InterfaceData, Model};
use crate::problems::load_driven::AnyLoadDriven;
use crate::problems::pointwise::Pointwise;
use crate::problems::profiled::Profiled;
use crate::problems::stiffness_answer::StiffnessAnswer;
use crate::problems::zoned::Layout;
use crate::problems::{Description, ModelKind, Param, Quantity, Solution, UnknownParam};

/// One parameter of one problem, typed (each folder's key enum, in its `params.rs`): what the
/// generated [`Param`] wraps, one variant per problem.
pub trait ParamKey: Debug + Clone + Copy + PartialEq + Eq + Hash + Send + Sync + 'static {
    /// Every key of the problem, in the order of its [`Description::params`].
    const KEYS: &'static [Self];

    /// Key, unit, meaning, domain and step.
    fn spec(self) -> ParamSpec;

    /// Its place in its problem's [`Description::params`].
    fn index(self) -> usize {
        Self::KEYS.iter().position(|&k| k == self).unwrap_or(0)
    }

    /// The key typed as `key` (`KT`), for the problem `model`.
    ///
    /// # Errors
    /// [`UnknownParam`] (with the allowed keys) when the problem has no such key.
    fn parse_key(key: &str, model: ModelKind) -> Result<Self, UnknownParam> {
        Self::KEYS
            .iter()
            .copied()
            .find(|k| k.spec().name == key)
            .ok_or_else(|| UnknownParam {
                key: key.to_string(),
                model,
            })
    }
}

/// A benchmark problem: its description, its parameters, the model they validate into and the
/// state one solve gives. One folder implements it; the registry in `problems/mod.rs` lists it
/// once; everything else reaches it through this trait or [`AnyProblem`].
///
/// `State` is not `Serialize` yet: this crate has no serde dependency (the application writes
/// JSON from its own report structs). When the core takes serde, the bound is added here and
/// every problem's state derives it.
pub trait Problem: Send + Sync + Sized + 'static {
    /// What the generic layers know of the problem, as data: key, title, parameters (specs with
    /// units and domains), quantities, the load and its regime scale.
    const INFO: &'static Description;
    /// One parameter, typed: the payload of this problem's [`Param`] variant.
    type Key: ParamKey;
    /// The parameters as a user sets them, unvalidated: every value of [`Description::params`].
    type Params: Debug + Clone + Copy + PartialEq;
    /// The validated model: exists only when every parameter is accepted.
    type Model: Debug + Clone + Copy + PartialEq;
    /// One solve: both laws' solutions.
    type State: Debug + BothLaws;

    /// The bundled data set that opens the problem ([`Description::paper_preset`]).
    fn paper() -> Self::Params;

    /// The field that holds the parameter at `index` in [`Description::params`], `None` past the
    /// end: the one place a problem maps its parameter list onto its fields.
    fn slot(params: &mut Self::Params, index: usize) -> Option<&mut f64>;

    /// Validates `params` through the checked constructors.
    ///
    /// # Errors
    /// The first parameter outside its domain, in display order, with its value and range.
    fn model(params: &Self::Params) -> Result<Self::Model, ParamError>;

    /// As [`Problem::model`] for a command that does not use the load (a cycle's amplitude, a
    /// fit's own forces): the load is checked against its own domain only and the model is at
    /// zero load. The default checks the structure first, then the load.
    ///
    /// # Errors
    /// As [`Problem::model`], except a load the structure cannot carry.
    fn model_without_load(params: &Self::Params) -> Result<Self::Model, ParamError> {
        let Some(load) = Self::INFO.load.and_then(|l| Self::index_of(l)) else {
            return Self::model(params);
        };
        let mut unloaded = *params;
        let value = Self::value(params, load).unwrap_or(0.0);
        if let Some(slot) = Self::slot(&mut unloaded, load) {
            *slot = 0.0;
        }
        let model = Self::model(&unloaded)?;
        let spec = Self::INFO.params[load].spec();
        spec.domain.check(spec.name, value, spec.unit)?;
        Ok(model)
    }

    /// The parameters `model` was validated from.
    fn params(model: &Self::Model) -> Self::Params;

    /// Solves the model under both laws.
    fn solve(model: &Self::Model) -> Self::State;

    /// The value of `quantity` for this model; `None` where the problem has no such quantity or
    /// it is not defined here (see [`Quantity`]).
    fn quantity(model: &Self::Model, quantity: Quantity) -> Option<f64>;

    /// The load at which the regimes change, which the load parameter steps and spans charts in
    /// (F_thre, F_gross); `None` for a problem without a load ([`Description::load`]).
    fn regime_scale(model: &Self::Model) -> Option<f64>;

    /// The interface data the K_T comparisons need.
    fn interface(model: &Self::Model) -> InterfaceData;

    /// The values the parameter at `index` may take with every other input as in `model`: its
    /// domain by default; a problem whose inputs bound one another (the lap joint's F <=
    /// F_gross) narrows it.
    fn accepted_range(model: &Self::Model, index: usize) -> (f64, f64) {
        let _ = model;
        Self::INFO
            .params
            .get(index)
            .map_or((f64::NAN, f64::NAN), |p| {
                let domain = p.spec().domain;
                (domain.min(), domain.max())
            })
    }

    /// The accepted range of the parameter at `index` (domain `[min, max]`) when the load
    /// `load` must stay below a bound `gross` proportional to it (the lap joint's F_gross = 2 b mu
    /// P L in each of b, mu, P, L): the value at which the bound falls to the load, moved up past
    /// round-off until the model is accepted there (a few ulps at most), to `max`.
    fn range_above_proportional_bound(
        model: &Self::Model,
        index: usize,
        (min, max): (f64, f64),
        (load, gross): (f64, f64),
    ) -> (f64, f64) {
        let mut params = Self::params(model);
        let value = Self::value(&params, index).unwrap_or(min);
        let mut lowest = min.max(value * load / gross).min(max);
        for _ in 0..8 {
            if let Some(slot) = Self::slot(&mut params, index) {
                *slot = lowest;
            }
            if Self::model(&params).is_ok() {
                break;
            }
            lowest = lowest.next_up().min(max);
        }
        (lowest, max)
    }

    /// The accepted value of the parameter at `index` nearest to `outside`, on the way from the
    /// model's own (accepted) value, less 1e-9 of the way: bisection on acceptance, for bounds
    /// the other inputs set in no closed form (the press fit's F <= F_gross as its radii move).
    /// Assumes one boundary between the two values; `outside` itself when the model accepts it.
    fn accepted_toward(model: &Self::Model, index: usize, outside: f64) -> f64 {
        let mut params = Self::params(model);
        let Some(inside) = Self::value(&params, index) else {
            return outside;
        };
        let mut accepts = |value: f64| match Self::slot(&mut params, index) {
            Some(slot) => {
                *slot = value;
                Self::model(&params).is_ok()
            }
            None => false,
        };
        if accepts(outside) {
            return outside;
        }
        let (mut good, mut bad) = (inside, outside);
        for _ in 0..200 {
            let mid = 0.5 * (good + bad);
            if mid == good || mid == bad {
                break;
            }
            if accepts(mid) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        // A hair inside: samples spaced on a log scale come back to their ends within a few
        // ulps, which must not cross the boundary.
        let safe = good + 1e-9 * (inside - good);
        if accepts(safe) { safe } else { good }
    }

    /// The same model with the parameter `key` set to the accepted value nearest to `value`
    /// (its domain, then [`Problem::accepted_range`]): infallible, for sweeps and root finding
    /// whose range was checked; should the model refuse it all the same, `model` as it is.
    fn with_clamped(model: &Self::Model, key: Self::Key, value: f64) -> Self::Model {
        let index = key.index();
        let (lo, hi) = Self::accepted_range(model, index);
        let mut params = Self::params(model);
        let Some(slot) = Self::slot(&mut params, index) else {
            return *model;
        };
        *slot = key.spec().domain.clamp(value).clamp(lo, hi);
        Self::model(&params).unwrap_or(*model)
    }

    /// How a refusal names the problem when it is given another problem's setting (`beam_theory`
    /// for the plate: "... not the plate"), with why it has none in parentheses where that helps
    /// (a one-line flag refusal keeps the part before them). By default its title.
    const REFUSED_AS: &'static str = Self::INFO.title;

    /// Its capabilities, erased: the one table the generic layers find them in
    /// ([`ProblemFaces`]); none by default. A problem with a capability fills its slot from its
    /// typed impl (`load_driven: Some(&LoadDrivenOf::<Self>::NEW)`), so that the erased side finds
    /// it without specialisation and without a method per capability.
    const FACES: &'static ProblemFaces = &ProblemFaces::NONE;

    /// Bridge to the [`Inputs`] enum (generated from the registry; written by `enum_bridges!`).
    fn to_inputs(params: Self::Params) -> Inputs;
    /// Bridge from the [`Inputs`] enum: `None` for another problem's inputs.
    fn from_inputs(inputs: &Inputs) -> Option<Self::Params>;
    /// Bridge to the [`Model`] enum (generated from the registry; written by `enum_bridges!`).
    fn to_model(model: Self::Model) -> Model;
    /// Bridge from the [`Model`] enum: `None` for another problem's model.
    fn from_model(model: &Model) -> Option<Self::Model>;

    /// The place of `param` in [`Description::params`], `None` for another problem's parameter.
    fn index_of(param: Param) -> Option<usize> {
        Self::INFO.params.iter().position(|&p| p == param)
    }

    /// The value of the parameter at `index`.
    fn value(params: &Self::Params, index: usize) -> Option<f64> {
        let mut copy = *params;
        Self::slot(&mut copy, index).map(|v| *v)
    }

    /// Every value, in the order of [`Description::params`].
    fn values(params: &Self::Params) -> Vec<f64> {
        (0..Self::INFO.params.len())
            .filter_map(|i| Self::value(params, i))
            .collect()
    }

    /// The parameters with `values`, in the order of [`Description::params`].
    ///
    /// # Errors
    /// [`ProblemError::Count`] when there is not one value per parameter.
    fn from_values(values: &[f64]) -> Result<Self::Params, ProblemError> {
        let expected = Self::INFO.params.len();
        if values.len() != expected {
            return Err(ProblemError::Count {
                problem: Self::INFO.key,
                expected,
                got: values.len(),
            });
        }
        let mut params = Self::paper();
        for (i, &v) in values.iter().enumerate() {
            if let Some(slot) = Self::slot(&mut params, i) {
                *slot = v;
            }
        }
        Ok(params)
    }
}

/// The 2-D continuum reference of a problem: the plane-strain finite-element solve that measures
/// where the problem's reduced theory (strip, shear lag, beams) stops holding: the plate, the
/// lap joint and the twin beams have one.
pub trait Continuum: Problem {
    /// The mesh controls (refinement), with the default the reports use.
    type Mesh: Debug + Clone + Default;
    /// The converged continuum solution.
    type Reference: Debug + Clone;

    /// Solves the continuum of `model` on `mesh`.
    ///
    /// # Errors
    /// [`NumericError`] for inputs the solver refuses or a solve that does not converge.
    fn solve_continuum(
        model: &Self::Model,
        mesh: Self::Mesh,
    ) -> Result<Self::Reference, NumericError>;

    /// The continuum's value of the problem's response ([`Quantity::Response`], mm): what the
    /// closed form's is compared with.
    fn continuum_response(reference: &Self::Reference) -> f64;
}

/// The [`Continuum`] of `P`, erased: the continuum's response for `model` (of `P`) on the
/// default mesh; `None` for another problem's model. What `P` puts in its
/// [`ProblemFaces::continuum`].
///
/// # Errors
/// As [`Continuum::solve_continuum`], inside the `Some`.
pub fn continuum_response<P: Continuum>(model: &Model) -> Option<Result<f64, NumericError>> {
    let model = P::from_model(model)?;
    Some(P::solve_continuum(&model, P::Mesh::default()).map(|r| P::continuum_response(&r)))
}

/// [`continuum_response`] of one problem, erased: its slot in [`ProblemFaces`].
pub type ContinuumResponse = fn(&Model) -> Option<Result<f64, NumericError>>;

/// **The erased faces of one problem**: every capability it has, as the generic layers reach
/// it from `&'static dyn` [`AnyProblem`] ([`AnyProblem::faces`]), in one table instead of a
/// method per capability on [`Problem`] and another on [`AnyProblem`]. A problem fills it once,
/// as its [`Problem::FACES`], from its typed impls; a slot left `None` (or empty) is a
/// capability it lacks, which answers "is this problem load-driven?" without a `match` on its
/// kind.
///
/// A capability whose erased side is one function is a plain `fn` here
/// ([`continuum_response`], [`zoned::erased_layout`](crate::problems::zoned::erased_layout)).
/// One with several methods keeps an erased trait beside its typed one ([`AnyLoadDriven`],
/// [`AnyFittable`], [`AnyCrossChecked`]): its methods take the [`Model`] enum and plain
/// numbers, which the typed trait cannot (its models and forces are the problem's own types),
/// and one `&'static dyn` carries all of them; each is implemented once, generically
/// (`LoadDrivenOf<P>`), never by a problem. [`AnyChoice`] has no typed side: a problem writes it
/// for each setting that is a name. What the table saved is counted in the module docs.
#[derive(Clone, Copy)]
pub struct ProblemFaces {
    /// Its 2-D continuum reference ([`Continuum`]), on the default mesh.
    pub continuum: Option<ContinuumResponse>,
    /// Its force axis ([`LoadDriven`](crate::problems::load_driven::LoadDriven)), where it is
    /// driven by a load.
    pub load_driven: Option<&'static dyn AnyLoadDriven>,
    /// Its fit of mu and K_T to a measured load-response curve
    /// ([`Fittable`](crate::problems::fittable::Fittable)): `None` answers "can `f` fit this
    /// problem?".
    pub fittable: Option<&'static dyn AnyFittable>,
    /// Its closed forms against its own discretized solver
    /// ([`CrossChecked`](crate::problems::cross_check::CrossChecked)): what `verify` runs.
    pub cross_checked: Option<&'static dyn AnyCrossChecked>,
    /// Its interface's layout under both laws ([`Zoned`](crate::problems::zoned::Zoned)),
    /// where it has one interface that holds over one stretch: what the zone strip draws.
    pub zoned: Option<fn(&Model) -> Option<Layout>>,
    /// Its settings that are names, not numbers ([`AnyChoice`]: the beams' theory), which
    /// presets and the command line set through the registry.
    pub choices: &'static [&'static dyn AnyChoice],
}

impl ProblemFaces {
    /// No capability: what a problem's table starts from (`..ProblemFaces::NONE`).
    pub const NONE: ProblemFaces = ProblemFaces {
        continuum: None,
        load_driven: None,
        fittable: None,
        cross_checked: None,
        zoned: None,
        choices: &[],
    };
}

impl Debug for ProblemFaces {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ProblemFaces")
            .field("continuum", &self.continuum.is_some())
            .field("load_driven", &self.load_driven.is_some())
            .field("fittable", &self.fittable.is_some())
            .field("cross_checked", &self.cross_checked.is_some())
            .field("zoned", &self.zoned.is_some())
            .field("choices", &self.choices.len())
            .finish()
    }
}

/// Both laws' solutions of one solve, as code written for any problem reads them.
pub trait BothLaws {
    /// The solution under plain Coulomb friction.
    fn coulomb(&self) -> &dyn Solution;
    /// The solution under the regularized law.
    fn regularized(&self) -> &dyn Solution;
}

/// One solve under both laws: the `State` of every problem so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Laws<C, R> {
    /// Plain Coulomb.
    pub coulomb: C,
    /// The regularized law.
    pub regularized: R,
}

impl<C: Solution, R: Solution> BothLaws for Laws<C, R> {
    fn coulomb(&self) -> &dyn Solution {
        &self.coulomb
    }

    fn regularized(&self) -> &dyn Solution {
        &self.regularized
    }
}

/// One law's answer in plain numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawAnswer {
    /// The response (mm) ([`Solution::response`]).
    pub response: f64,
    /// The regime.
    pub regime: Regime,
    /// Where the zone this law is about ends (mm) ([`Solution::zone_end`]).
    pub zone_end: f64,
}

impl LawAnswer {
    fn of(solution: &dyn Solution) -> LawAnswer {
        LawAnswer {
            response: solution.response(),
            regime: solution.regime(),
            zone_end: solution.zone_end(),
        }
    }
}

/// The few numbers of one solve the generic layers need, for any problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Answers {
    /// Under plain Coulomb.
    pub coulomb: LawAnswer,
    /// Under the regularized law.
    pub regularized: LawAnswer,
}

/// Why parameter values given as numbers were refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ProblemError {
    /// Not one value per parameter.
    #[error("the {problem} problem takes {expected} parameter values, got {got}")]
    Count {
        /// The problem's key.
        problem: &'static str,
        /// How many it has ([`Description::params`]).
        expected: usize,
        /// How many were given.
        got: usize,
    },
    /// A value outside its domain.
    #[error(transparent)]
    Param(#[from] ParamError),
}

/// A [`Problem`]'s line in the registry: written by the registry ([`crate::with_problems`]), never by hand, so that a
/// problem is an [`AnyProblem`] exactly when it is listed.
pub trait Registered {
    /// Its variant of [`ModelKind`].
    const KIND: ModelKind;
}

/// What every registered problem writes, because the studies dispatch over the whole registry
/// (the checklist in `problems/mod.rs`): the bound a [`Visit`] may use.
pub trait Listed: Registered + Pointwise + Profiled + StiffnessAnswer {}

impl<P: Registered + Pointwise + Profiled + StiffnessAnswer> Listed for P {}

/// Code written once, generic over a problem's type, run for the problem of a [`ModelKind`] by
/// [`ModelKind::visit`]: the core's one typed dispatch, generated from the registry, for what
/// cannot be an erased face of [`ProblemFaces`] because it speaks a higher layer's types (a
/// study's samples and series).
pub trait Visit {
    /// What it gives back.
    type Output;

    /// Runs it for the problem `P`.
    fn run<P: Listed>(self) -> Self::Output;
}

/// A [`Problem`] with its types erased (object safe): parameter values as `&[f64]` indexed like
/// [`Description::params`], answers as plain numbers, and the bridges to the enums the
/// application still matches on. Every registered [`Problem`] is one (blanket impl); the registry hands them
/// out as `&'static dyn AnyProblem`.
///
/// # Examples
/// Code written once for every problem, with no `match` on the kind:
/// ```
/// use microslip_core::problems::ModelKind;
/// for kind in ModelKind::ALL {
///     let problem = kind.problem();
///     let mut values = problem.paper_values();
///     let answers = problem.answers(&values)?;
///     // Every bundled data set is loaded: the regularized response is positive.
///     assert!(answers.regularized.response > 0.0, "{kind}");
///     // Values are indexed like the description's parameters; a bad one is refused by name.
///     values[0] = -1.0;
///     let refused = problem.answers(&values).unwrap_err().to_string();
///     assert!(refused.starts_with(&format!("invalid {} = -1", kind.params()[0])));
/// }
/// # Ok::<(), microslip_core::problems::problem::ProblemError>(())
/// ```
pub trait AnyProblem: Send + Sync {
    /// What the generic layers know of the problem.
    fn info(&self) -> &'static Description;
    /// The problem in the registry.
    fn kind(&self) -> ModelKind;
    /// The values of the bundled data set, in the order of [`Description::params`].
    fn paper_values(&self) -> Vec<f64>;
    /// Validates `values`.
    ///
    /// # Errors
    /// [`ProblemError`]: a wrong count or the first value outside its domain.
    fn check(&self, values: &[f64]) -> Result<(), ProblemError>;
    /// Solves the problem at `values` under both laws.
    ///
    /// # Errors
    /// As [`AnyProblem::check`].
    fn answers(&self, values: &[f64]) -> Result<Answers, ProblemError>;
    /// The value of `quantity` at `values` (`Ok(None)` where it is not defined).
    ///
    /// # Errors
    /// As [`AnyProblem::check`].
    fn quantity_at(&self, values: &[f64], quantity: Quantity) -> Result<Option<f64>, ProblemError>;
    /// [`Problem::REFUSED_AS`].
    fn refused_as(&self) -> &'static str;
    /// Its capabilities ([`Problem::FACES`]): the one table the erased side finds them in.
    fn faces(&self) -> &'static ProblemFaces;

    /// [`Inputs`] of this problem at `values`.
    ///
    /// # Errors
    /// [`ProblemError::Count`].
    fn inputs_at(&self, values: &[f64]) -> Result<Inputs, ProblemError>;
    /// The paper's [`Inputs`] of this problem.
    fn paper_inputs(&self) -> Inputs;
    /// The value of `param` in `inputs`; `None` for another problem's parameter or inputs.
    fn get(&self, inputs: &Inputs, param: Param) -> Option<f64>;
    /// Sets `param` in `inputs`; false (nothing set) for another problem's parameter or inputs.
    fn set(&self, inputs: &mut Inputs, param: Param, value: f64) -> bool;
    /// Validates `inputs`; `None` for another problem's inputs.
    fn validate(&self, inputs: &Inputs) -> Option<Result<Model, ParamError>>;
    /// As [`AnyProblem::validate`] through [`Problem::model_without_load`].
    fn validate_without_load(&self, inputs: &Inputs) -> Option<Result<Model, ParamError>>;
    /// The inputs `model` was validated from; `None` for another problem's model.
    fn model_inputs(&self, model: &Model) -> Option<Inputs>;
    /// [`Problem::quantity`] of `model`; `None` also for another problem's model.
    fn model_quantity(&self, model: &Model, quantity: Quantity) -> Option<f64>;
    /// [`Problem::regime_scale`] of `model`; `None` also for another problem's model.
    fn model_regime_scale(&self, model: &Model) -> Option<f64>;
    /// [`Problem::interface`] of `model`; `None` for another problem's model.
    fn model_interface(&self, model: &Model) -> Option<InterfaceData>;
    /// [`Problem::accepted_range`] of `param` in `model`; `None` for another problem's model or
    /// parameter.
    fn model_accepted_range(&self, model: &Model, param: Param) -> Option<(f64, f64)>;
}

impl<P: Problem + Registered> AnyProblem for P {
    fn info(&self) -> &'static Description {
        P::INFO
    }

    fn kind(&self) -> ModelKind {
        P::KIND
    }

    fn paper_values(&self) -> Vec<f64> {
        P::values(&P::paper())
    }

    fn check(&self, values: &[f64]) -> Result<(), ProblemError> {
        P::model(&P::from_values(values)?)?;
        Ok(())
    }

    fn answers(&self, values: &[f64]) -> Result<Answers, ProblemError> {
        let state = P::solve(&P::model(&P::from_values(values)?)?);
        Ok(Answers {
            coulomb: LawAnswer::of(state.coulomb()),
            regularized: LawAnswer::of(state.regularized()),
        })
    }

    fn quantity_at(&self, values: &[f64], quantity: Quantity) -> Result<Option<f64>, ProblemError> {
        Ok(P::quantity(&P::model(&P::from_values(values)?)?, quantity))
    }

    fn refused_as(&self) -> &'static str {
        P::REFUSED_AS
    }

    fn faces(&self) -> &'static ProblemFaces {
        P::FACES
    }

    fn inputs_at(&self, values: &[f64]) -> Result<Inputs, ProblemError> {
        Ok(P::to_inputs(P::from_values(values)?))
    }

    fn paper_inputs(&self) -> Inputs {
        P::to_inputs(P::paper())
    }

    fn get(&self, inputs: &Inputs, param: Param) -> Option<f64> {
        P::value(&P::from_inputs(inputs)?, P::index_of(param)?)
    }

    fn set(&self, inputs: &mut Inputs, param: Param, value: f64) -> bool {
        let (Some(mut params), Some(index)) = (P::from_inputs(inputs), P::index_of(param)) else {
            return false;
        };
        let Some(slot) = P::slot(&mut params, index) else {
            return false;
        };
        *slot = value;
        *inputs = P::to_inputs(params);
        true
    }

    fn validate(&self, inputs: &Inputs) -> Option<Result<Model, ParamError>> {
        Some(P::model(&P::from_inputs(inputs)?).map(P::to_model))
    }

    fn validate_without_load(&self, inputs: &Inputs) -> Option<Result<Model, ParamError>> {
        Some(P::model_without_load(&P::from_inputs(inputs)?).map(P::to_model))
    }

    fn model_inputs(&self, model: &Model) -> Option<Inputs> {
        Some(P::to_inputs(P::params(&P::from_model(model)?)))
    }

    fn model_quantity(&self, model: &Model, quantity: Quantity) -> Option<f64> {
        P::quantity(&P::from_model(model)?, quantity)
    }

    fn model_regime_scale(&self, model: &Model) -> Option<f64> {
        P::regime_scale(&P::from_model(model)?)
    }

    fn model_interface(&self, model: &Model) -> Option<InterfaceData> {
        Some(P::interface(&P::from_model(model)?))
    }

    fn model_accepted_range(&self, model: &Model, param: Param) -> Option<(f64, f64)> {
        Some(P::accepted_range(
            &P::from_model(model)?,
            P::index_of(param)?,
        ))
    }
}

/// The checks every problem's `problem.rs` runs on itself (its tests call them with its own
/// typed path), so that a new problem gets them by calling them, and this file names none.
#[cfg(test)]
pub(crate) mod checks {
    use super::*;

    /// The typed side of `P` agrees with its description and the registry: one key per listed
    /// parameter, in the same order, each knowing its own place and parsing back; every slot is
    /// its own field; its erased self is its registry entry.
    pub(crate) fn registered<P: Problem + Registered>() {
        let info = P::INFO;
        let kind = P::KIND;
        assert_eq!(kind.description().key, info.key);
        assert!(ModelKind::ALL.contains(&kind));
        assert_eq!(kind.problem().kind(), kind);
        assert_eq!(kind.name().parse::<ModelKind>(), Ok(kind));
        assert_eq!(kind.problem().paper_inputs(), P::to_inputs(P::paper()));
        assert_eq!(
            <P::Key as ParamKey>::KEYS.len(),
            info.params.len(),
            "{kind}"
        );
        let keys = <P::Key as ParamKey>::KEYS.iter();
        for (i, (&key, &param)) in keys.zip(info.params).enumerate() {
            assert_eq!(key.spec(), param.spec(), "{kind}: {param}");
            assert_eq!(key.index(), i, "{kind}: {param}");
            assert_eq!(param.model(), kind, "{param}");
            assert_eq!(P::index_of(param), Some(i));
            assert_eq!(P::Key::parse_key(param.name(), kind), Ok(key));
        }
        let values: Vec<f64> = (0..info.params.len()).map(|i| 1000.0 + i as f64).collect();
        let params = P::from_values(&values).unwrap();
        assert_eq!(P::values(&params), values, "{kind}");
        assert!(P::slot(&mut P::paper(), info.params.len()).is_none());
    }

    /// Pseudo-random values (a fixed linear congruential sequence, so a failure repeats), each
    /// log-uniform over its parameter's usual range, nu uniform; the load, where there is one,
    /// uniform up to 1.2 regime scales (past F_gross for the lap joint one time in six: the
    /// refusals must agree too).
    fn random_points(kind: ModelKind, count: usize) -> Vec<Vec<f64>> {
        let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let load = kind
            .description()
            .load
            .and_then(|l| kind.params().iter().position(|&p| p == l));
        let draw = |next: &mut dyn FnMut() -> f64| -> Vec<f64> {
            kind.params()
                .iter()
                .map(|p| {
                    let (low, high) = p.usual_range();
                    let u = next();
                    if low > 0.0 {
                        (low.ln() + u * (high / low).ln()).exp()
                    } else {
                        low + u * (high - low)
                    }
                })
                .collect()
        };
        let structure = |values: &[f64]| {
            kind.problem()
                .inputs_at(values)
                .ok()
                .and_then(|inputs| inputs.validate_without_load().ok())
        };
        let mut points = Vec::new();
        for _ in 0..count {
            // Keys drawn each over its own usual range may break a bound between them (the press
            // fit's ri < r < ro): redraw the point, so that most points reach the closed forms;
            // refusals still come from the load drawn beyond the bound below.
            let mut values = draw(&mut next);
            for _ in 0..1000 {
                if structure(&values).is_some() {
                    break;
                }
                values = draw(&mut next);
            }
            let scale = structure(&values).and_then(|model| model.regime_scale());
            if let (Some(i), Some(scale)) = (load, scale) {
                values[i] = 1.2 * scale * next();
            }
            points.push(values);
        }
        points
    }

    /// Bit-identical: both paths call the same closed forms, so any difference is a mapping bug.
    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits()
    }

    /// Both laws' answers from any problem's states, as the typed paths give them.
    pub(crate) fn answers(coulomb: &dyn Solution, regularized: &dyn Solution) -> Answers {
        Answers {
            coulomb: LawAnswer::of(coulomb),
            regularized: LawAnswer::of(regularized),
        }
    }

    /// `kind`'s erased problem and its [`Model`] enum answer exactly as `typed` (the problem's
    /// closed forms called by hand from the values, looked up by key name, with its regime
    /// scale) at the paper data and 40 random points: responses, zone ends, regimes, every
    /// quantity of its description, the regime scale and the values read back; and refuse
    /// exactly where `typed` refuses, with the same error.
    pub(crate) fn erased_answers_as_typed(
        kind: ModelKind,
        typed: impl Fn(&dyn Fn(&str) -> f64) -> Result<(Answers, Option<f64>), ParamError>,
    ) {
        let problem = kind.problem();
        let mut points = vec![problem.paper_values()];
        points.extend(random_points(kind, 40));
        let mut solved = 0;
        for values in &points {
            let by_name = |name: &str| {
                let i = kind.params().iter().position(|p| p.name() == name);
                values[i.unwrap_or_else(|| panic!("{kind} has no key {name}"))]
            };
            let erased = problem.answers(values);
            let model = problem.inputs_at(values).unwrap().validate();
            match (erased, typed(&by_name)) {
                (Ok(e), Ok((t, scale))) => {
                    solved += 1;
                    for (a, b) in [(e.coulomb, t.coulomb), (e.regularized, t.regularized)] {
                        assert!(same(a.response, b.response), "{kind} {values:?}");
                        assert!(same(a.zone_end, b.zone_end), "{kind} {values:?}");
                        assert_eq!(a.regime, b.regime, "{kind} {values:?}");
                    }
                    let model = model.unwrap();
                    assert_eq!(
                        model.regime_scale().map(f64::to_bits),
                        scale.map(f64::to_bits),
                        "{kind} {values:?}"
                    );
                    for q in kind.description().quantities {
                        let erased = problem.quantity_at(values, q.quantity).unwrap();
                        let through_enum = model.quantity(q.quantity);
                        assert_eq!(
                            erased.map(f64::to_bits),
                            through_enum.map(f64::to_bits),
                            "{kind} {}",
                            q.name
                        );
                    }
                    for (&param, &value) in kind.params().iter().zip(values) {
                        assert_eq!(model.inputs().get(param), Some(value), "{param}");
                    }
                }
                (Err(ProblemError::Param(e)), Err(t)) => {
                    assert_eq!(e, t, "{kind} {values:?}");
                    assert_eq!(model.unwrap_err(), t, "{kind} {values:?}");
                }
                (e, t) => panic!("{kind} {values:?}: erased {e:?}, typed {t:?}"),
            }
        }
        // Most random points are accepted (the lap joint's F <= F_gross refuses some).
        assert!(
            solved > points.len() / 2,
            "{kind}: {solved} of {}",
            points.len()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_registry_lists_every_problem_once() {
        let mut keys: Vec<&str> = ModelKind::ALL.iter().map(|k| k.name()).collect();
        for (i, kind) in ModelKind::ALL.into_iter().enumerate() {
            assert_eq!(kind.problem().kind(), kind);
            assert_eq!(kind as usize, i);
        }
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), ModelKind::ALL.len(), "two problems share a key");
    }

    #[test]
    fn an_unknown_model_says_the_keys_and_a_wrong_count_says_how_many() {
        let keys: Vec<String> = ModelKind::ALL
            .iter()
            .map(|k| format!("\"{}\"", k.name()))
            .collect();
        let (last, first) = keys.split_last().unwrap();
        assert_eq!(
            "beams".parse::<ModelKind>().unwrap_err().to_string(),
            format!(
                "unknown model 'beams': must be {} or {last}",
                first.join(", ")
            )
        );
        assert!(ModelKind::choices().ends_with(&format!(" or {}", keys[keys.len() - 1])));
        for kind in ModelKind::ALL {
            let count = kind.params().len();
            assert_eq!(
                kind.problem()
                    .answers(&vec![1.0; count + 1])
                    .unwrap_err()
                    .to_string(),
                format!(
                    "the {kind} problem takes {count} parameter values, got {}",
                    count + 1
                )
            );
        }
    }
}
