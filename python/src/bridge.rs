//! The Python face's command bodies. Each public function here is a CLI command's body (the
//! CLI's is private to its `app` feature) minus argument parsing and printing, and says which
//! file it mirrors; the tests compare every one with the CLI's output, so a drift fails them.
//!
//! The bodies are written once for every problem, over the application's traits and generic
//! functions (`ReportFace::point_report`, its erased cycle face, `fe::face::written_deck`,
//! `fe::load::results::<P>`, `Deck::compare`, `fit::Structure::of`, `study::tolerance::*::<P>`),
//! and dispatched through [`face`], generated from the registry
//! (`microslip_core::with_problems!`): no problem is named here, and a new problem needs no line
//! in this crate.

use std::marker::PhantomData;
use std::path::Path;

use microslip::fe::deck::DeckMesh;
use microslip::fe::face::Deck;
use microslip::fe::face::DeckRequest;
use microslip::fe::header::StickSlope;
use microslip::fe::kinematics::Kinematics;
use microslip::fe::load;
use microslip::fit::{self, Weights};
use microslip::kernel::params::{Compact, Domain, Unit};
use microslip::numeric::cancel::checkpoint;
use microslip::problems::inputs::Model;
use microslip::problems::problem::Registered;
use microslip::problems::{ModelKind, Problem};
use microslip::report::compare::CompareFace;
use microslip::report::compare::run::{self as compare_run, ContactCompared};
use microslip::report::face::ReportFace;
use microslip::report::json;
use microslip::report::point::cycle::AnyCycleFace;
use microslip::report::point::tolerance::ToleranceReport;
use microslip::study::tolerance::{self, ToleranceAnswer};
use serde_json::Value;

/// The model of `kind` at `values`, validated as the CLI validates it: with its load, or
/// without it (`loaded` false: a command that does not read F, such as cycle, fit, compare).
fn model(kind: ModelKind, values: &[f64], loaded: bool) -> Result<Model, String> {
    let inputs = kind
        .problem()
        .inputs_at(values)
        .map_err(|e| e.to_string())?;
    if loaded {
        inputs.validate()
    } else {
        inputs.validate_without_load()
    }
    .map_err(|e| e.to_string())
}

/// `model` as the problem `P`'s typed model. Every caller holds a model of `P` (from
/// [`face`]`(P::KIND)`); the error says so should one not.
fn typed<P: Problem + Registered>(model: &Model) -> Result<P::Model, String> {
    model.of::<P>().map_err(|other| {
        format!(
            "internal error: a {other} model where a {} one was expected",
            P::KIND
        )
    })
}

/// A value given for a flag of the CLI (`amplitude`, `F_from`), checked against `domain` with the
/// CLI's words (`src/cli/loading.rs`, `check_flag`).
pub fn check_flag(name: &str, value: f64, domain: Domain, unit: Unit) -> Result<f64, String> {
    domain
        .check("value", value, unit)
        .map_err(|e| format!("invalid {name} = {}: {}", Compact(value), e.allowed()))
}

/// What `kt --tolerance` measures the deviation from (`--of`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Of {
    /// The Coulomb answer (K_T -> infinity).
    Coulomb,
    /// The answer at the current K_T.
    Current,
}

/// [`Face::tolerance`]'s load range, checked as `kt --tolerance --from/--to` checks it
/// (`src/cli/kt.rs`): each end the model's load when not given, in order, the upper one a load
/// the structure carries (refused in the problem's words beyond its bound).
fn load_range(
    kind: ModelKind,
    face: &dyn AnyCycleFace,
    model: &Model,
    [from, to]: [Option<f64>; 2],
) -> Result<[f64; 2], String> {
    let info = kind.description();
    let (name, unit) = info
        .load_words()
        .ok_or_else(|| format!("the {} has no load", info.title))?;
    let load = face
        .applied_force(model)
        .ok_or_else(|| format!("the {} has no load", info.title))?;
    let spec = info.load.map(|p| p.spec()).ok_or("no load")?;
    let (lower, upper) = (format!("{name}_from"), format!("{name}_to"));
    let range = [
        check_flag(&lower, from.unwrap_or(load), spec.domain, spec.unit)?,
        check_flag(&upper, to.unwrap_or(load), spec.domain, spec.unit)?,
    ];
    if range[0] > range[1] {
        return Err(format!(
            "invalid {upper} = {}: must not be below {lower} = {} {unit} (the loads checked run \
             from {lower} up to {upper})",
            Compact(range[1]),
            Compact(range[0])
        ));
    }
    if let Some(limit) = face.force_limit(model)
        && range[1] > limit
    {
        let flag = if to.is_some() { upper } else { lower };
        return Err(format!(
            "invalid {flag} = {}: {}",
            Compact(range[1]),
            info.beyond_bound(limit)
        ));
    }
    Ok(range)
}

/// The commands of any problem, their types erased: one body each, written once over the
/// application's faces ([`FaceOf`]); no problem writes anything here.
trait AnyFace: Sync {
    fn point_report(&self, model: &Model, name: &str) -> Result<Value, String>;
    fn cycle_report(&self, model: &Model, name: &str, amplitude: f64) -> Result<Value, String>;
    fn tolerance(
        &self,
        model: &Model,
        question: (f64, Of),
        range: [Option<f64>; 2],
        element: f64,
    ) -> Result<ToleranceAnswer, String>;
    fn deck(&self, model: &Model, mesh: DeckMesh, loads: Option<&[f64]>) -> Result<String, String>;
    fn compare(
        &self,
        path: &Path,
        deck: Option<&Path>,
        structure: &dyn Fn() -> Result<Model, String>,
    ) -> Result<Value, String>;
}

/// The [`AnyFace`] of a [`Face`] problem `P`.
struct FaceOf<P>(PhantomData<P>);

impl<P: ReportFace + CompareFace + Deck> AnyFace for FaceOf<P> {
    /// `src/cli/point.rs`: the problem's point report, which adds its continuum reference where
    /// its reduced theory is not expected to hold.
    fn point_report(&self, model: &Model, name: &str) -> Result<Value, String> {
        let report =
            P::point_report(name, &typed::<P>(model)?, false).map_err(|e| e.to_string())?;
        Ok(json::of(&report))
    }

    /// `src/cli/cycle.rs`: the structure cycled at `amplitude` (checked as a load of it).
    fn cycle_report(&self, model: &Model, name: &str, amplitude: f64) -> Result<Value, String> {
        let face = <P as ReportFace>::cycle()
            .ok_or_else(|| format!("the {} problem has no load to cycle", P::KIND))?;
        match face.report(name, model, amplitude) {
            Some(Ok(report)) => Ok(json::of(&report)),
            Some(Err(e)) => Err(format!(
                "invalid amplitude = {}: {}",
                Compact(amplitude),
                e.allowed()
            )),
            None => Err(format!("no {} model to cycle", P::KIND)),
        }
    }

    /// `src/cli/kt.rs`: over the load range of a load-driven problem, at the one state of any
    /// other.
    fn tolerance(
        &self,
        model: &Model,
        (tol, of): (f64, Of),
        range: [Option<f64>; 2],
        element: f64,
    ) -> Result<ToleranceAnswer, String> {
        let current = of == Of::Current;
        let answer = match <P as ReportFace>::cycle() {
            Some(face) => {
                let range = load_range(P::KIND, face, model, range)?;
                face.tolerance(model, range, (tol, element), current)
            }
            None => {
                if range.iter().any(Option::is_some) {
                    return Err(format!(
                        "the {} has no load: a load range does not apply",
                        P::KIND.description().title
                    ));
                }
                let model = typed::<P>(model)?;
                Some(if current {
                    tolerance::state_stiffness_near_current::<P>(&model, tol, element)
                } else {
                    tolerance::state_stiffness_for_tolerance::<P>(&model, tol, element)
                })
            }
        };
        answer
            .ok_or_else(|| format!("no {} model to check", P::KIND))?
            .map_err(|e| e.to_string())
    }

    /// `src/cli/decks.rs`: the problem's own deck writer at the model's stick slope, `loads`
    /// checked there (increasing, each accepted) or the problem's defaults.
    fn deck(&self, model: &Model, mesh: DeckMesh, loads: Option<&[f64]>) -> Result<String, String> {
        let request = DeckRequest {
            loads,
            mesh,
            slope: StickSlope::Model,
            increment: None,
        };
        microslip::fe::face::written_deck::<P>(&typed::<P>(model)?, &request)
            .map_err(|e| e.to_string())
    }

    /// `src/cli/compare.rs` for one result file of `P`: a CalculiX `.dat`, whose deck's header
    /// gives the model and whose `.frd` and deck the stick slope used and the kinematics, or a
    /// CSV, compared at `structure` (the parameters given), its kinematics not stated; the
    /// report with the same sections as the command's ([`ContactCompared`]).
    fn compare(
        &self,
        path: &Path,
        deck: Option<&Path>,
        structure: &dyn Fn() -> Result<Model, String>,
    ) -> Result<Value, String> {
        let source = path.display().to_string();
        let failed = |e: load::LoadError| format!("{}: {}", e.path, e.reason);
        let loaded = load::results::<P>(path, deck).map_err(failed)?;
        let model = match &loaded.header {
            Some(header) => header.model().map_err(|e| e.to_string())?,
            None => structure()?,
        };
        let model = model.of::<P>().map_err(|other| {
            format!(
                "the deck's header describes the {other} problem, not the {} compared",
                P::KIND
            )
        })?;
        let mut compared = P::compare(&model, &loaded.points, loaded.interface_mesh.as_ref());
        let (kinematics, stick_slope) = match &loaded.header {
            Some(header) => {
                let read = load::ccx_contact(path, deck, header).map_err(failed)?;
                (read.kinematics, Some(read.stick_slope))
            }
            None => (Kinematics::NotStated, None),
        };
        let run = compare_run::run_evidence(
            path,
            loaded.header.as_ref(),
            P::interface(&model).stiffness,
            kinematics,
            stick_slope,
        );
        compare_run::judged_for::<P>(&run, &model, &mut compared);
        let checked = P::checked(compared).map_err(|e| format!("{source}: {e}"))?;
        let report = ContactCompared::<P>::new(&source, (checked, Vec::new()), &[run]);
        Ok(json::of(&report.with_contact()))
    }
}

/// Writes [`face`] from the registry: one arm per problem, none by hand.
macro_rules! faces {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// The commands of the problem `kind`.
        fn face(kind: ModelKind) -> &'static dyn AnyFace {
            match kind {
                $(ModelKind::$variant => &FaceOf::<microslip::problems::$folder::$problem>(
                    PhantomData,
                )),+
            }
        }
    };
}

microslip_core::with_problems!(faces);

/// `microslip beam|plate|lap --format json` (`src/cli/point.rs`): the plate and the joint add
/// the continuum reference where their reduced theory does not hold.
pub fn point_report(kind: ModelKind, values: &[f64], name: &str) -> Result<Value, String> {
    face(kind).point_report(&model(kind, values, true)?, name)
}

/// `microslip cycle --amplitude A --format json` (`src/cli/cycle.rs`): the structure validated
/// without its load, the amplitude checked as the CLI checks `--amplitude`.
pub fn cycle_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    amplitude: f64,
) -> Result<Value, String> {
    let amplitude = match kind.description().load {
        Some(load) => {
            let spec = load.spec();
            check_flag("amplitude", amplitude, spec.domain, spec.unit)?
        }
        None => amplitude,
    };
    face(kind).cycle_report(&model(kind, values, false)?, name, amplitude)
}

/// `microslip kt --tolerance T [--of REF] [--from F] [--to F] --format json` (`src/cli/kt.rs`,
/// `run_kt_tolerance`): the K_T within `tol` (a fraction) of the reference over the forces
/// `[from, to]` (each the model's F when not given).
pub fn kt_tolerance_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    question: (f64, Of),
    range: [Option<f64>; 2],
    element: f64,
) -> Result<Value, String> {
    let answer = face(kind).tolerance(&model(kind, values, true)?, question, range, element)?;
    Ok(json::of(&ToleranceReport::new(name, &answer)))
}

/// `microslip fit DATA --format json` (`src/cli/fitting.rs`, `run_fit`) on the points `(load,
/// measured, sigma)`, written as the CSV the CLI reads (the problem's load and response columns,
/// `F_N,w_mm`, `Q_N_per_mm,sa_mm`, then `sigma_mm`) so that the CLI's parser checks every value,
/// `data` what the report calls it.
pub fn fit_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    (data, points): (&str, Points<'_>),
    fixed: (Option<f64>, Option<f64>),
    weights: Option<&str>,
) -> Result<Value, String> {
    let structure = fit::Structure::of(&model(kind, values, false)?).ok_or_else(|| {
        let fittable: Vec<_> = ModelKind::ALL
            .into_iter()
            .filter(|k| k.problem().faces().fittable.is_some())
            .map(|k| k.name())
            .collect();
        format!(
            "the {kind} problem has no force-response curve to fit (fit takes a {} problem)",
            fittable.join(" or ")
        )
    })?;
    let csv = measurement_csv(&structure, points);
    // Ctrl-C (`interrupt`) stops the parse and the fit at their progress ticks and at each
    // measurement the fit evaluates.
    let measured = microslip::measured::parse_measured_response_with_progress(
        &csv,
        &structure,
        &mut |_, _| checkpoint(),
    )
    .map_err(|e| format!("{data}: {e}"))?;
    let weights = match (measured.sigma.as_deref(), weights) {
        (Some(sigma), None) => Weights::Sigma(sigma),
        (Some(_), Some(_)) => {
            return Err(
                "sigma gives each point's own standard deviation; weights asks for \
                        another: give one"
                    .to_string(),
            );
        }
        (None, Some("absolute")) => Weights::Absolute,
        (None, Some("relative") | None) => Weights::default(),
        (None, Some(other)) => {
            return Err(format!(
                "invalid weights = {other:?}: must be \"relative\" or \"absolute\""
            ));
        }
    };
    let result = fit::fit_measured(structure, &measured.points, fixed, weights, &mut |_| {
        checkpoint()
    })
    .map_err(|e| e.to_string())?;
    Ok(json::fit(data, name, &structure, &result))
}

/// Measured points: the loads (in the load's unit), the responses (mm) and, when known, each
/// one's standard deviation (mm).
pub type Points<'a> = (&'a [f64], &'a [f64], Option<&'a [f64]>);

/// The points `(load, measured, sigma)` as the CSV the CLI's fit reads for `structure`: its
/// load and response columns, then `sigma_mm` when there are sigmas (one per point: checked by
/// the caller), every number written in full.
fn measurement_csv(structure: &fit::Structure, (loads, measured, sigma): Points<'_>) -> String {
    let mut csv = format!(
        "{},{}{}\n",
        structure.load_column(),
        structure.response_column(),
        if sigma.is_some() { ",sigma_mm" } else { "" }
    );
    for (i, (f, m)) in loads.iter().zip(measured).enumerate() {
        match sigma.and_then(|s| s.get(i)) {
            Some(s) => csv.push_str(&format!("{f:?},{m:?},{s:?}\n")),
            None => csv.push_str(&format!("{f:?},{m:?}\n")),
        }
    }
    csv
}

/// `microslip deck ccx MODEL [--mesh fine] [--loads ...]` (`src/cli/decks.rs`, `build_deck`) at
/// the model's stick slope: the deck's text.
pub fn deck_text(
    kind: ModelKind,
    values: &[f64],
    mesh: DeckMesh,
    loads: Option<&[f64]>,
) -> Result<String, String> {
    face(kind).deck(&model(kind, values, true)?, mesh, loads)
}

/// `microslip compare MODEL RESULT [--deck INP] --format json` (`src/cli/compare.rs`) for one
/// result file: a CalculiX `.dat` (its deck's header gives the parameters) or a CSV (compared at
/// `values`, without their load: the FE forces are compared; a problem without a load is its
/// whole model).
pub fn compare_report(
    kind: ModelKind,
    values: &[f64],
    path: &Path,
    deck: Option<&Path>,
) -> Result<Value, String> {
    face(kind).compare(path, deck, &|| model(kind, values, false))
}
