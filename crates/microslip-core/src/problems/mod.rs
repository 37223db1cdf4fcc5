//! The benchmark problems, one folder each, and the registry of them. A problem's folder holds
//! what is its own: parameters, closed forms, validity envelope, its independent discretized
//! solver. Everything here is built on [`crate::kernel`] and [`crate::numeric`], which know no
//! problem.
//!
//! A problem is a type that implements [`Problem`] (its [`Description`], its parameters, the
//! model they validate into, one solve's state) and the capabilities it has ([`Continuum`],
//! [`LoadDriven`]; a capability a problem lacks is a trait it does not implement, not a `match`
//! arm; the erased side finds each in one table, [`ProblemFaces`](problem::ProblemFaces), the
//! problem's [`Problem::FACES`], through [`AnyProblem::faces`]). The
//! registry, [`with_problems!`](crate::with_problems) below, holds one line per problem (`Beam =>
//! twin_beams::TwinBeamsProblem`) and generates from it [`ModelKind`] (with
//! [`ModelKind::problem`], the problem as `&'static dyn` [`AnyProblem`]: what a caller uses
//! instead of a `match` on the kind) and [`Param`] (a parameter of any problem, what presets,
//! `--set`, the parameter pane, sweeps and solving for a target iterate over). [`ByProblem`]
//! keeps one value per problem; [`Quantity`] and [`Solution`] name what every problem's solution
//! answers.
//!
//! [`Inputs`](inputs::Inputs) and [`Model`](inputs::Model), the values of any problem that the
//! application keeps (a preset's inputs, the TUI's current model), are enums generated from the
//! registry, a tuple variant per problem holding its [`Problem::Params`] and [`Problem::Model`];
//! every method on them goes through the problem's [`Problem`] impl, and a folder reaches them
//! only through the bridges `enum_bridges!(Variant)` writes into its impl (`to_inputs`,
//! `from_inputs`, `to_model`, `from_model`, or [`Model::of`](inputs::Model::of)).
//!
//! # Adding a problem
//! A fourth problem (the Hertzian cylinder, say) is, in this crate:
//! 1. **Its folder** `problems/cylinder/`, naming no other problem (`tests/layering.rs` checks it):
//!    - `params.rs`: the parameter key enum (`CylinderParam`, with `ALL` in display order and a
//!      `spec()` giving key, unit, meaning, domain, usual range and step; `FromStr` through
//!      [`ParamKey::parse_key`]) and the raw parameter struct with a `PAPER` (or bundled) data
//!      set and `value_mut`;
//!    - `closed_form.rs`: the validated model (a checked `new -> Result<_, ParamError>`) and
//!      one state per law, each implementing [`Solution`];
//!    - `validity.rs`: where the closed form holds; `discretized.rs`: the independent solver
//!      (never importing the closed forms: `tests/layering.rs`); `continuum.rs` if it has a
//!      2-D reference;
//!    - if it is driven by a load: `cycle.rs` (its Masing cycle, a
//!      [`load_driven::MasingCycle`]) and `load_driven.rs` (the problem type's [`LoadDriven`]
//!      impl, whose `Structure` is the model without its force); its `problem.rs` then writes
//!      `regime_scale` as `Some(force_scale)` and fills `load_driven:
//!      Some(&LoadDrivenOf::<Self>::NEW)` in its `FACES`, and every sweep, cycle, tolerance and
//!      load chart serves it; then also `fittable.rs` ([`fittable::Fittable`], its `fittable`
//!      slot), and the fit (the TUI's `f`, `microslip fit`) serves it;
//!    - if it has a setting that is a name, not a number (the beams' theory): `choice.rs`, an
//!      [`AnyChoice`](choice::AnyChoice) listed in the `choices` of its `FACES`, which presets and the
//!      command line read and write with no edit; a problem whose refusal of another's setting
//!      needs its own words ("the plate", not its title) writes `REFUSED_AS`;
//!    - what every problem writes, because the studies dispatch over the whole registry:
//!      `point.rs` (its row type and [`pointwise::Pointwise`]: the sweeps' rows, re-exported
//!      into `study::curves`), `profiles.rs` ([`profiled::Profiled`]: the shear along the
//!      interface), `stiffness_answer.rs` ([`stiffness_answer::StiffnessAnswer`]: the K_T
//!      comparison's row);
//!    - what it may write, each put in the slot of the same name of its `FACES`:
//!      `zoned.rs` ([`zoned::Zoned`]: the TUI's zone strip) and `cross_check.rs`
//!      ([`cross_check::CrossChecked`]: its closed forms against its discretized solver in
//!      `microslip verify`);
//!    - `mod.rs`: its `DESCRIPTION` (key, title, summary, paper preset, parameters through
//!      `param_list!`, quantities, load) and its `quantity` function;
//!    - `problem.rs`: the unit struct (`CylinderProblem`) implementing [`ParamKey`] for its key
//!      enum, [`Problem`] (and [`Continuum`] and the other capabilities it has, each handed to
//!      the erased side in its slot of [`Problem::FACES`], one table: `continuum:
//!      Some(continuum_response::<Self>)`, `..ProblemFaces::NONE` for the rest). Its `State` is
//!      [`problem::Laws`] of its two law states.
//! 2. **One registry line** in [`with_problems!`](crate::with_problems): `Cylinder => cylinder::CylinderProblem,`
//!    with its doc comment. [`ModelKind`], [`ModelKind::ALL`], [`ModelKind::problem`] and
//!    [`Param`] follow from it; [`ByProblem`] grows a slot.
//! 3. **Its bridges** to the generated [`Inputs`](inputs::Inputs) and
//!    [`Model`](inputs::Model): `enum_bridges!(Cylinder);` inside its `impl Problem`.
//! 4. **Its faces** in the application, `src/problems/cylinder/` (declared from the registry
//!    line; the application's `problems` module docs say why a problem has two folders), each
//!    the impl of a trait of the layer that shows it, or a type only that problem has:
//!    `chart.rs` (`chart::view::ChartFace`: its charts), `pane.rs` (`chart::panes::PaneFace`:
//!    the TUI's parameter title, regime pane, K_T table), `deck.rs` (`fe::face::Deck`: its
//!    CalculiX deck and the closed-form values its header expects), `fe_points.rs` (its FE
//!    point type, the reader of a CalculiX run's `.dat`, written on `fe::results::DatRead`, and
//!    of a CSV curve, on `fe::results::points_from_csv`), `compare.rs` (its comparison with the
//!    closed forms and `report::compare::CompareFace`; where that is a table of FE points judged
//!    against an envelope and the continuum, `report::compare::table::CompareTable` too: its
//!    compare row, row verdict, closing verdict and the text of its table), `report.rs`
//!    (`report::face::ReportFace`: its point report, its sweep and loop row types, K_T answer
//!    and paper table; and `report::point::cycle::CycleFace` if it is driven by a load, handed
//!    out by its `ReportFace::cycle`). `fe` and `report` name no problem (`tests/layering.rs`).
//!    The cylinder's reader is its `ccx_read.rs` and its comparison its `deck.rs` (its report
//!    has another shape than the table's). Every command, chart, report and TUI pane then
//!    serves it through code generated from the registry: the application's one typed dispatch
//!    (`report::face::for_problem`) and its table of erased faces (`report::face::faces`) need
//!    no line for it. A problem without a CalculiX deck (the twisted press fit: CAX elements
//!    carry no twist) still implements `Deck` (its CSV curve, its comparison) with
//!    `Deck::NO_DECK` saying why: `deck` and `bench` refuse with it, the suite leaves it out.
//!    Every generic title, heading, key and column takes the load's name and unit, the
//!    response's and the first-slip load's names from its [`Description`] (`T` in N mm, `T_Nmm`,
//!    `theta_rad`): a problem writes none of them outside its folders. Two problems of one
//!    structure share its two folders, each with its own registry line (the press fit pushed out
//!    and twisted, `pressfit::registered::problem::FitProblem<K>`: `face_folders!` declares a
//!    folder once, its presets are listed once).
//! 5. **Its presets**: `presets/<paper-preset>.toml` (named by [`Description::paper_preset`]),
//!    each listed with its `include_str!` in `BUNDLED_PRESETS` of its face folder's `mod.rs`
//!    (`src/problems/cylinder/mod.rs`); `preset::bundled` gathers every problem's from the
//!    registry, and a test fails on a preset file no problem bundles. Beside it,
//!    `PAPER_FIGURES`: the figures `microslip figures` draws of its presets (`&[]` for none;
//!    the twin beams' `figures.rs` shows the shape). Its Python class needs no line: `python/`
//!    builds one per registered problem.
//! 6. **Its tests**: its folder's unit tests (closed form against hand values and its
//!    discretized solver, validity edges), a `tests/<name>_properties.rs` of properties over
//!    random inputs; the registry tests in `problems/problem.rs` cover it without an edit once
//!    the typed cross-check there (`typed_answers`) gets its arm.
//! 7. **Its docs**: its section in `docs/theory.md` (the equations its closed forms implement,
//!    cited by number in its doc comments) and its line in the guide's list of problems.
//!
//! Nothing else: no file outside the problem's two folders and the registry names a problem's
//! types, folders or variants (the application's
//! `tests/layering.rs::only_a_problem_s_folders_and_the_registry_name_it` fails on a new one),
//! so a fourth problem costs its folders, its registry line, its presets, tests and docs.

use std::fmt;
use std::str::FromStr;

use thiserror::Error;

use crate::kernel::params::{ParamSpec, Unit};
pub use load_driven::{AnyLoadDriven, LoadDriven};
pub use problem::{AnyProblem, Continuum, ParamKey, Problem};
pub use quantity::{Quantity, QuantityName, Solution};

/// The parameters of one problem as [`Param`]s, in the order of `$ty::ALL`: a const array, so
/// that a problem's [`Description`] is a constant.
macro_rules! param_list {
    ($variant:path, $ty:ty) => {{
        let mut all = [$variant(<$ty>::ALL[0]); <$ty>::ALL.len()];
        let mut i = 0;
        while i < all.len() {
            all[i] = $variant(<$ty>::ALL[i]);
            i += 1;
        }
        all
    }};
}

pub mod choice;
pub mod cross_check;
pub mod fittable;
/// The bridges of a problem's [`Problem`] impl to the enums [`inputs::Inputs`] and
/// [`inputs::Model`], which the registry generates with one variant per problem: a folder writes
/// `enum_bridges!(Variant);` inside its `impl Problem`, naming its own variant only (a wrong one
/// does not compile: the variant holds another problem's types).
macro_rules! enum_bridges {
    ($variant:ident) => {
        fn to_inputs(params: Self::Params) -> crate::problems::inputs::Inputs {
            crate::problems::inputs::Inputs::$variant(params)
        }

        fn from_inputs(inputs: &crate::problems::inputs::Inputs) -> Option<Self::Params> {
            match inputs {
                crate::problems::inputs::Inputs::$variant(params) => Some(*params),
                #[allow(unreachable_patterns)]
                _ => None,
            }
        }

        fn to_model(model: Self::Model) -> crate::problems::inputs::Model {
            crate::problems::inputs::Model::$variant(model)
        }

        fn from_model(model: &crate::problems::inputs::Model) -> Option<Self::Model> {
            match model {
                crate::problems::inputs::Model::$variant(model) => Some(*model),
                #[allow(unreachable_patterns)]
                _ => None,
            }
        }
    };
}

// After `enum_bridges!`, which its `impl Problem` uses.
pub mod cylinder;
pub mod inputs;
pub mod lap;
pub mod load_driven;
pub mod plate;
pub mod pointwise;
pub mod pressfit;
pub mod problem;
pub mod profiled;
pub mod quantity;
pub mod stiffness;
pub mod stiffness_answer;
pub mod twin_beams;
pub mod zoned;

pub use lap::params::LapParam;
pub use plate::params::PlateParam;
pub use twin_beams::params::BeamParam;

/// What the generic layers (presets, deck headers, commands, the parameter pane, targets) know
/// of a problem, as data: a new problem writes one in its folder and hands it out as its
/// [`Problem::INFO`]; [`ModelKind::description`] reads it through the registry.
#[derive(Debug)]
pub struct Description {
    /// The key in presets (`model = "beam"`), commands and JSON.
    pub key: &'static str,
    /// The problem for people ("twin cantilever beams").
    pub title: &'static str,
    /// The problem and where it comes from, for `--help` ("Twin cantilever beams (paper
    /// section 2.1)").
    pub summary: &'static str,
    /// The bundled preset that opens it (the paper's data set).
    pub paper_preset: &'static str,
    /// Its parameters, in display order.
    pub params: &'static [Param],
    /// The quantities of its solution a target can be set on, in the order error messages list
    /// them.
    pub quantities: &'static [QuantityName],
    /// The response's letter in file names (`microslip-w-vs-mu.svg`).
    pub response_symbol: &'static str,
    /// The load the problem is driven by, when it has one (the beams' tip force F): it steps in
    /// fractions of the force where the regimes change, a force-response curve of it can be
    /// measured and fitted, and FE decks apply it in load steps. None for the plate, loaded by
    /// its pressure alone.
    pub load: Option<Param>,
    /// The name of [`crate::problems::inputs::Model::regime_scale`] as messages say it (`F_thre`);
    /// empty without a load.
    pub regime_scale_name: &'static str,
    /// The largest load the structure carries, when it has one (the lap joint's F_gross, the
    /// cylinder's Q_gross): every generic message that refuses a load beyond it says it through
    /// this ([`Description::bound_formula`]), so that none hard-codes one problem's formula.
    pub load_bound: Option<LoadBound>,
    /// How many regime scales the load axis of its charts spans by default: 3 F_thre for the
    /// beams (macroslip well past F_1), 1 F_gross for the lap joint (no state beyond it); 0
    /// without a load.
    pub load_span: f64,
}

/// The bound a problem's load cannot pass, in the problem's own words: the one descriptor every
/// generic message, prompt, fit and cycle table asks (issue 43), so that the lap joint's
/// "F_gross = 2 b mu P L" is never said of the cylinder, whose bound is "Q_gross = mu P".
#[derive(Debug)]
pub struct LoadBound {
    /// Its symbol: `F_gross`, `Q_gross`.
    pub symbol: &'static str,
    /// Its formula in the problem's parameters: `2 b mu P L`, `mu P`.
    pub formula: &'static str,
    /// What happens beyond it: `the joint slides through beyond it`.
    pub beyond: &'static str,
}

impl Description {
    /// The load's key and unit as people read them (`("Q", "N/mm")`), when the problem has one.
    pub fn load_words(&self) -> Option<(&'static str, &'static str)> {
        self.load.map(|load| {
            let spec = load.spec();
            (spec.name, spec.unit.symbol())
        })
    }

    /// The JSON key or CSV header of a value of the load (`F_N`, `Q_N_per_mm`), `infix` after
    /// its name (`a` gives the amplitude's `Fa_N`, `Qa_N_per_mm`); None without a load.
    pub fn load_key(&self, infix: &str) -> Option<String> {
        self.load.map(|load| {
            let spec = load.spec();
            format!("{}{infix}_{}", spec.name, spec.unit.key())
        })
    }

    /// The load's bound with its formula: `F_gross = 2 b mu P L`, `Q_gross = mu P`; None for a
    /// load without one (the beams') or a problem without a load (the plate).
    pub fn bound_formula(&self) -> Option<String> {
        self.load_bound
            .as_ref()
            .map(|bound| format!("{} = {}", bound.symbol, bound.formula))
    }

    /// The bound, its formula and what happens beyond it: `F_gross = 2 b mu P L: the joint
    /// slides through beyond it`.
    pub fn bound_sentence(&self) -> Option<String> {
        self.load_bound
            .as_ref()
            .map(|bound| format!("{} = {}: {}", bound.symbol, bound.formula, bound.beyond))
    }

    /// The refusal of a load beyond `limit`, the bound's value in the load's unit: "must be at
    /// most F_gross = 2 b mu P L = 6000 N (the joint slides through beyond it)".
    pub fn beyond_bound(&self, limit: f64) -> String {
        let unit = self.load_words().map_or("", |(_, unit)| unit);
        let value = crate::kernel::params::Compact(limit);
        match &self.load_bound {
            Some(b) => format!(
                "must be at most {} = {} = {value} {unit} ({})",
                b.symbol, b.formula, b.beyond
            ),
            None => format!("must be at most {value} {unit}"),
        }
    }

    /// "the given F = 300 N" in the problem's words (its load's name and unit; `value` in that
    /// unit): what a refusal of a bounded range names.
    pub fn load_value(&self, value: f64) -> String {
        match self.load_words() {
            Some((name, unit)) => {
                format!("{name} = {} {unit}", crate::kernel::params::Compact(value))
            }
            None => format!("{}", crate::kernel::params::Compact(value)),
        }
    }
}

/// Writes [`ModelKind`], its [`ModelKind::ALL`], [`ModelKind::description`],
/// [`ModelKind::problem`] and [`Param`] (with [`Param::spec`] and [`Param::model`]) from one list
/// of `Variant => folder::ProblemType`, so that the list of problems is spelled once: a variant
/// missing from `ALL` (which would index past [`ByProblem`]'s slots), without a description or
/// without a parameter type cannot be written.
macro_rules! problem_list {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// Which benchmark a parameter set describes.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum ModelKind {
            $($(#[$doc])* $variant),+
        }

        impl ModelKind {
            /// Every problem, in the order of the list (the order the TUI's `m` cycles through).
            pub const ALL: [ModelKind; [$(ModelKind::$variant),+].len()] =
                [$(ModelKind::$variant),+];

            /// The problem itself, its types erased: what a caller uses instead of a `match` on
            /// the kind.
            pub fn problem(self) -> &'static dyn AnyProblem {
                match self {
                    $(ModelKind::$variant => &$folder::$problem),+
                }
            }

            /// Runs `visit` for this problem, typed ([`problem::Visit`]).
            pub fn visit<V: problem::Visit>(self, visit: V) -> V::Output {
                match self {
                    $(ModelKind::$variant => visit.run::<$folder::$problem>()),+
                }
            }
        }

        $(impl problem::Registered for $folder::$problem {
            const KIND: ModelKind = ModelKind::$variant;
        })+

        /// A parameter of any problem: what the TUI's parameter pane and presets iterate over.
        /// One variant per problem, holding that problem's [`Problem::Key`].
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Param {
            $($(#[$doc])* $variant(<$folder::$problem as Problem>::Key)),+
        }

        impl Param {
            /// Key, unit, meaning, domain and step.
            pub fn spec(self) -> ParamSpec {
                match self {
                    $(Param::$variant(p) => ParamKey::spec(p)),+
                }
            }

            /// The model this parameter belongs to.
            pub fn model(self) -> ModelKind {
                match self {
                    $(Param::$variant(_) => ModelKind::$variant),+
                }
            }
        }
    };
}

/// **The registry**: the one list of problems, a line each (`Variant => folder::ItsType`), which
/// every per-problem type of both crates is generated from. It hands the list to the macro it is
/// given: `with_problems!(problem_list)` below writes [`ModelKind`] and [`Param`]; a layer above
/// the core (a chart, a report, a deck) writes its own dispatch over every problem the same way,
/// from the same list, so that no file but this one lists the problems and a new problem is one
/// line here. The callback receives `$($(#[doc])* Variant => folder::ProblemType),+`: the
/// folder is the problem's module in `problems` (in the core, and in the application, whose
/// `problems` re-exports the core's and adds each problem's faces), so both crates name the type
/// as `crate::problems::$folder::$problem` and the application declares its folders from it.
///
/// # Examples
/// ```
/// // Count the problems by their type, written once for every problem.
/// macro_rules! keys {
///     ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
///         [$(<microslip_core::problems::$folder::$problem as
///             microslip_core::problems::Problem>::INFO.key),+]
///     };
/// }
/// let keys = microslip_core::with_problems!(keys);
/// assert_eq!(keys.len(), microslip_core::problems::ModelKind::ALL.len());
/// assert_eq!(keys[0], "beam");
/// ```
#[macro_export]
macro_rules! with_problems {
    ($callback:ident) => {
        $callback! {
            /// Twin cantilever beams (paper section 2.1).
            Beam => twin_beams::TwinBeamsProblem,
            /// Squeezed plate (paper section 2.2).
            Plate => plate::SqueezedPlateProblem,
            /// Clamped double-lap joint (issue 24).
            Lap => lap::LapJointProblem,
            /// Hertzian cylinder on a flat under a tangential line load (issue 34).
            Cylinder => cylinder::CylinderProblem,
            /// Shrink-fitted hub on a shaft, pushed out by an axial force (issue 44).
            PressFit => pressfit::PressFitProblem,
            /// The same fit twisted by a torque (issue 44).
            PressFitTorque => pressfit::PressFitTorqueProblem,
        }
    };
}

with_problems!(problem_list);

impl ModelKind {
    /// How many problems there are.
    pub(crate) const COUNT: usize = Self::ALL.len();

    /// This problem's place in [`ModelKind::ALL`].
    pub(crate) fn index(self) -> usize {
        self as usize
    }

    /// What the generic layers know of the problem: its [`Description`], from its folder.
    pub fn description(self) -> &'static Description {
        self.problem().info()
    }

    /// The problem after this one in [`ModelKind::ALL`], the first after the last: what `m`
    /// switches to.
    pub fn next(self) -> ModelKind {
        Self::ALL[(self.index() + 1) % Self::COUNT]
    }

    /// The longest key of any problem (`cylinder`): the width a column of keys is padded to,
    /// so that a listing lines up whatever problems the registry holds.
    pub fn key_width() -> usize {
        Self::ALL.iter().map(|k| k.name().len()).max().unwrap_or(0)
    }

    /// The `model = "..."` value in preset files.
    pub fn name(self) -> &'static str {
        self.description().key
    }

    /// The parameters of this model, in display order.
    pub fn params(self) -> &'static [Param] {
        self.description().params
    }

    /// Parses a model key of this kind (`KT`, `nu`, ...).
    ///
    /// # Errors
    /// [`UnknownParam`] (with the allowed keys) when the model has no such key.
    pub fn param(self, key: &str) -> Result<Param, UnknownParam> {
        self.params()
            .iter()
            .copied()
            .find(|p| p.name() == key)
            .ok_or_else(|| UnknownParam {
                key: key.to_string(),
                model: self,
            })
    }

    /// Every problem's key, quoted, as error messages offer them: `"beam" or "plate"`.
    pub fn choices() -> String {
        let keys: Vec<String> = Self::ALL
            .iter()
            .map(|k| format!("\"{}\"", k.name()))
            .collect();
        match keys.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => String::new(),
        }
    }

    /// Every model's keys, as `--help` lists them: `beam: L b h E nu P mu KT F, where h is the
    /// half height (each beam is 2h high); plate: ...`. A key whose spec carries a note (a half size where the
    /// key alone reads as a whole one) is followed by its meaning, so a user reading the help
    /// does not type the beams' whole height for `h`.
    pub fn key_docs() -> String {
        Self::ALL
            .iter()
            .map(|&kind| {
                let noted: Vec<String> = kind
                    .params()
                    .iter()
                    .map(|p| p.spec())
                    .filter(|spec| !spec.note.is_empty())
                    .map(|spec| format!("{} is the {}", spec.name, spec.meaning))
                    .collect();
                if noted.is_empty() {
                    format!("{kind}: {}", kind.key_list())
                } else {
                    format!("{kind}: {}, where {}", kind.key_list(), noted.join(" and "))
                }
            })
            .collect::<Vec<_>>()
            .join("; ")
    }

    /// The keys, space separated, as error messages list them.
    pub(crate) fn key_list(self) -> String {
        self.params()
            .iter()
            .map(|p| p.name())
            .collect::<Vec<_>>()
            .join(" ")
    }
}

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

impl FromStr for ModelKind {
    type Err = UnknownModel;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        ModelKind::ALL
            .into_iter()
            .find(|k| k.name() == text)
            .ok_or_else(|| UnknownModel {
                text: text.to_string(),
            })
    }
}

/// A model key that names no problem: what parsing a [`ModelKind`] refuses, listing the keys.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("unknown model '{text}': must be {}", ModelKind::choices())]
pub struct UnknownModel {
    /// The key as written.
    pub text: String,
}

/// One value per problem, indexed by [`ModelKind`]: what a layer keeps for every problem at once
/// (the TUI's parameters, pins and chart of each problem, an undo snapshot of all of them) holds
/// it here rather than in a field per problem, so that a new problem adds no field and no match.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ByProblem<T>([T; ModelKind::COUNT]);

impl<T> ByProblem<T> {
    /// The value `make` gives each problem.
    pub fn from_fn(mut make: impl FnMut(ModelKind) -> T) -> ByProblem<T> {
        ByProblem(std::array::from_fn(|i| make(ModelKind::ALL[i])))
    }

    /// Each problem with its value, in the order of [`ModelKind::ALL`].
    pub fn iter(&self) -> impl Iterator<Item = (ModelKind, &T)> {
        ModelKind::ALL.into_iter().zip(self.0.iter())
    }
}

impl<T> std::ops::Index<ModelKind> for ByProblem<T> {
    type Output = T;

    fn index(&self, kind: ModelKind) -> &T {
        &self.0[kind.index()]
    }
}

impl<T> std::ops::IndexMut<ModelKind> for ByProblem<T> {
    fn index_mut(&mut self, kind: ModelKind) -> &mut T {
        &mut self.0[kind.index()]
    }
}

/// A key the model does not have.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("unknown key '{key}' for the {model} model (allowed: {})", model.key_list())]
pub struct UnknownParam {
    /// The key as written.
    pub key: String,
    /// The model.
    pub model: ModelKind,
}

impl Param {
    /// The key (`KT`).
    pub fn name(self) -> &'static str {
        self.spec().name
    }

    /// The unit.
    pub fn unit(self) -> Unit {
        self.spec().unit
    }

    /// The values engineers usually give this parameter (see [`ParamSpec::usual`]).
    pub fn usual_range(self) -> (f64, f64) {
        self.spec().usual
    }

    /// What follows a value of this parameter: ` MPa`, nothing for a dimensionless one.
    pub fn unit_suffix(self) -> String {
        match self.unit() {
            Unit::Dimensionless => String::new(),
            unit => format!(" {unit}"),
        }
    }

    /// A warning when an accepted `value` is outside [`Param::usual_range`], naming the range.
    pub fn unusual(self, value: f64) -> Option<String> {
        let (low, high) = self.usual_range();
        let unit = self.unit_suffix();
        (!(low..=high).contains(&value)).then(|| {
            format!(
                "{} = {}{unit} is far outside the usual range [{}, {}]{unit}: check the value",
                self.name(),
                crate::kernel::format::number(value),
                crate::kernel::params::Compact(low),
                crate::kernel::params::Compact(high)
            )
        })
    }

    /// True for the tangential stiffness K_T of any problem (shown in MPa/um as well): the one
    /// parameter in MPa/mm.
    pub fn is_stiffness(self) -> bool {
        self.unit() == Unit::MegapascalPerMillimetre
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::params::*;

    #[test]
    fn every_parameter_of_every_problem_has_a_usual_range_inside_its_domain() {
        for kind in ModelKind::ALL {
            for &param in kind.params() {
                let (low, high) = param.usual_range();
                let domain = param.spec().domain;
                assert!(
                    low.is_finite() && high.is_finite(),
                    "{param}: usual range not set"
                );
                assert!(low < high, "{param}");
                // Within the domain's bounds (an open bound, nu < 0.5, may be the range's end).
                assert!(low >= domain.min() && high <= domain.max(), "{param}");
            }
        }
        // Exactly K_T counts as a stiffness.
        let stiffnesses: Vec<Param> = ModelKind::ALL
            .iter()
            .flat_map(|k| k.params())
            .copied()
            .filter(|p| p.is_stiffness())
            .collect();
        let named_kt: Vec<Param> = ModelKind::ALL
            .iter()
            .flat_map(|k| k.params())
            .copied()
            .filter(|p| p.spec().name == "KT")
            .collect();
        assert_eq!(stiffnesses, named_kt);
        assert_eq!(stiffnesses.len(), ModelKind::COUNT);
    }

    #[test]
    fn errors_name_field_value_and_range() {
        let err = BeamParam::Length.check(-3.0).unwrap_err();
        assert_eq!(
            err.to_string(),
            "invalid L = -3: must be > 0 and finite (mm)"
        );
        // Huge and tiny values print as typed, not as hundreds of digits.
        assert_eq!(
            BeamParam::Length.check(-1e308).unwrap_err().to_string(),
            "invalid L = -1e308: must be > 0 and finite (mm)"
        );
        assert_eq!(
            BeamParam::Force.check(-1e-300).unwrap_err().to_string(),
            "invalid F = -1e-300: must be >= 0 and finite (N)"
        );
        assert_eq!(
            PlateParam::Poisson.check(0.5).unwrap_err().to_string(),
            "invalid nu = 0.5: must be in [0, 0.5) (dimensionless)"
        );
        assert!(BeamParam::Modulus.check(f64::NAN).is_err());
        assert!(BeamParam::Modulus.check(f64::INFINITY).is_err());
        assert!(BeamParam::Modulus.check(0.0).is_err());
        assert_eq!(BeamParam::Force.check(0.0), Ok(0.0));
        assert!(BeamParam::Force.check(-1e-300).is_err());
        assert_eq!(PlateParam::Poisson.check(0.0), Ok(0.0));
        assert!(PlateParam::Poisson.check(0.5).is_err());
        assert!(PlateParam::Poisson.check(-0.1).is_err());
        assert_eq!(
            PlateParam::Poisson.check(0.7).unwrap_err().to_string(),
            "invalid nu = 0.7: must be in [0, 0.5) (dimensionless)"
        );
        assert_eq!(
            BeamParam::Friction.check(-1.0).unwrap_err().to_string(),
            "invalid mu = -1: must be > 0 and finite (dimensionless)"
        );
    }

    #[test]
    fn every_domain_is_bounded_and_says_its_range_with_the_unit() {
        // Above the range, or positive below it: the range with the unit.
        assert_eq!(
            BeamParam::Force.check(1e307).unwrap_err().to_string(),
            "invalid F = 1e307: must be in [0, 1e12] N"
        );
        assert_eq!(
            PlateParam::HalfLength.check(1e-7).unwrap_err().to_string(),
            "invalid L = 1e-7: must be in [1e-6, 1e6] mm"
        );
        assert_eq!(
            BeamParam::Friction.check(11.0).unwrap_err().to_string(),
            "invalid mu = 11: must be in [1e-6, 10] (dimensionless)"
        );
        assert_eq!(
            BeamParam::Stiffness.check(2e12).unwrap_err().to_string(),
            "invalid KT = 2e12: must be in [1e-6, 1e12] MPa/mm"
        );
        // Zero, negative, NaN and infinities keep the sign rule.
        assert_eq!(
            BeamParam::Modulus.check(0.0).unwrap_err().to_string(),
            "invalid E = 0: must be > 0 and finite (MPa)"
        );
        assert_eq!(
            BeamParam::Pressure
                .check(f64::INFINITY)
                .unwrap_err()
                .to_string(),
            "invalid P = (a number beyond 1.8e308): must be in [1e-6, 10000] MPa"
        );
        assert_eq!(
            BeamParam::Force.check(f64::NAN).unwrap_err().to_string(),
            "invalid F = NaN: must be >= 0 and finite (N)"
        );
        // Both ends are accepted, the next f64 beyond them is not.
        for kind in ModelKind::ALL {
            for &param in kind.params() {
                let domain = param.spec().domain;
                let (min, max) = (domain.min(), domain.max());
                assert!(min.is_finite() && max.is_finite() && min < max, "{param}");
                assert!(domain.contains(min), "{param}");
                assert!(!domain.contains(min.next_down()), "{param}");
                assert_eq!(
                    domain.contains(max),
                    domain != Domain::PoissonRatio,
                    "{param}"
                );
                assert!(!domain.contains(max.next_up()), "{param}");
                for v in [f64::NAN, -1.0, 0.5 * min, 2.0 * max, 1e300] {
                    assert!(domain.contains(domain.clamp(v)), "{param} {v}");
                }
                assert_eq!(domain.clamp(min), min);
            }
        }
        assert_eq!(Domain::FORCE.clamp(2e12), 1e12);
        assert_eq!(
            Domain::LENGTH.describe(Unit::Millimetre),
            "must be in [1e-6, 1e6] mm"
        );
    }

    #[test]
    fn next_visits_every_problem_once_and_by_problem_indexes_them_all() {
        let mut kind = ModelKind::ALL[0];
        let mut seen = Vec::new();
        for _ in 0..ModelKind::COUNT {
            seen.push(kind);
            kind = kind.next();
        }
        assert_eq!(seen, ModelKind::ALL);
        assert_eq!(kind, ModelKind::ALL[0]);
        let mut names = ByProblem::from_fn(ModelKind::name);
        for kind in ModelKind::ALL {
            assert_eq!(names[kind], kind.name());
            assert_eq!(ModelKind::ALL[kind.index()], kind);
        }
        let changed = ModelKind::ALL[1];
        names[changed] = "changed";
        let listed: Vec<_> = names.iter().map(|(k, v)| (k, *v)).collect();
        let expected: Vec<_> = ModelKind::ALL
            .into_iter()
            .map(|k| (k, if k == changed { "changed" } else { k.name() }))
            .collect();
        assert_eq!(listed, expected);
    }

    #[test]
    fn keys_parse_back_to_their_parameter_and_typos_list_the_keys() {
        for kind in ModelKind::ALL {
            for &param in kind.params() {
                assert_eq!(kind.param(param.name()), Ok(param));
                assert_eq!(param.model(), kind);
            }
        }
        assert_eq!("KT".parse::<BeamParam>(), Ok(BeamParam::Stiffness));
        assert_eq!("nu".parse::<PlateParam>(), Ok(PlateParam::Poisson));
        assert_eq!(
            "Kt".parse::<BeamParam>().unwrap_err().to_string(),
            "unknown key 'Kt' for the beam model (allowed: L b h E nu P mu KT F)"
        );
        assert_eq!(
            ModelKind::Plate.param("F").unwrap_err().to_string(),
            "unknown key 'F' for the plate model (allowed: L tp E nu mu P KT)"
        );
    }

    #[test]
    fn steps_move_both_ways_and_respect_their_bounds() {
        let kt = BeamParam::Stiffness.spec().scale;
        assert!((kt.step(600.0, true, true, 0.0) / 600.0 - 10f64.powf(0.25)).abs() < 1e-12);
        assert!((kt.step(600.0, false, false, 0.0) - 600.0 / 1.02).abs() < 1e-12);
        let nu = PlateParam::Poisson.spec().scale;
        assert_eq!(nu.step(0.49, true, true, 0.0), 0.499);
        assert_eq!(nu.step(0.01, false, true, 0.0), 0.0);
        let force = BeamParam::Force.spec().scale;
        assert!((force.step(100.0, true, false, 80.0) - 100.8).abs() < 1e-12);
        assert_eq!(force.step(1.0, false, true, 80.0), 0.0);
        for kind in ModelKind::ALL {
            for &param in kind.params() {
                let spec = param.spec();
                assert!(
                    spec.domain
                        .contains(spec.scale.step(1e-3, false, true, 1.0))
                );
            }
        }
    }
}
