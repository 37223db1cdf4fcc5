//! The Python face's command bodies. Each public function here is a CLI command's body (the
//! CLI's is private to its `app` feature) minus argument parsing and printing, and says which
//! file it mirrors; the tests compare every one with the CLI's output, so a drift fails them.
//!
//! The bodies are written once for every problem, over the application's traits and generic
//! functions (`ReportFace::point_report`, its erased cycle face, `fe::face::written_deck`,
//! `fe::load::results::<P>`, `Deck::compare`, `fit::Structure::of`, `study::tolerance::*::<P>`),
//! each a [`ForProblem`] run by the application's [`for_problem`] (the one the command line's
//! handlers run through, generated from the registry): no problem is named here, no `match` on
//! a kind is written here, and a new problem needs no line in this crate.

use std::path::Path;

use microslip::fe::deck::DeckMesh;
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
use microslip::report::compare::run::{self as compare_run, ContactCompared};
use microslip::report::face::{Faces, ForProblem, ReportFace, for_problem};
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
/// [`for_problem`] of its kind); the error says so should one not.
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

/// [`Tolerance`]'s load range, checked as `kt --tolerance --from/--to` checks it
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
    let load = kind
        .problem()
        .faces()
        .load_driven
        .and_then(|load_driven| load_driven.applied_force(model))
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

/// `src/cli/point.rs`: the problem's point report, which adds its continuum reference where its
/// reduced theory is not expected to hold.
/// The model and the preset's name.
struct PointReport<'a>(&'a Model, &'a str);

impl ForProblem for PointReport<'_> {
    type Output = Result<Value, String>;

    fn run<P: Faces>(self) -> Self::Output {
        let PointReport(model, name) = self;
        let report =
            P::point_report(name, &typed::<P>(model)?, false).map_err(|e| e.to_string())?;
        Ok(json::of(&report))
    }
}

/// `src/cli/cycle.rs`: the structure cycled at `amplitude` (checked as a load of it).
/// The model, the preset's name and the amplitude.
struct CycleReport<'a>(&'a Model, &'a str, f64);

impl ForProblem for CycleReport<'_> {
    type Output = Result<Value, String>;

    fn run<P: Faces>(self) -> Self::Output {
        let CycleReport(model, name, amplitude) = self;
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
}

/// `src/cli/kt.rs`: over the load range of a load-driven problem, at the one state of any
/// other.
/// The model, the question (tolerance, reference), the load range and the element length.
struct Tolerance<'a>(&'a Model, (f64, Of), [Option<f64>; 2], f64);

impl ForProblem for Tolerance<'_> {
    type Output = Result<ToleranceAnswer, String>;

    fn run<P: Faces>(self) -> Self::Output {
        let Tolerance(model, (tol, of), range, element) = self;
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
}

/// `src/cli/decks.rs`: the problem's own deck writer at the model's stick slope, `loads` checked
/// there (increasing, each accepted) or the problem's defaults.
/// The model, the mesh and the loads.
struct DeckText<'a>(&'a Model, DeckMesh, Option<&'a [f64]>);

impl ForProblem for DeckText<'_> {
    type Output = Result<String, String>;

    fn run<P: Faces>(self) -> Self::Output {
        let DeckText(model, mesh, loads) = self;
        let request = DeckRequest {
            loads,
            mesh,
            slope: StickSlope::Model,
            increment: None,
        };
        microslip::fe::face::written_deck::<P>(&typed::<P>(model)?, &request)
            .map_err(|e| e.to_string())
    }
}

/// `src/cli/compare.rs` for one result file of `P`: a CalculiX `.dat`, whose deck's header gives
/// the model and whose `.frd` and deck the stick slope used and the kinematics, or a CSV,
/// compared at `structure` (the parameters given), its kinematics not stated; the report with
/// the same sections as the command's ([`ContactCompared`]).
/// The result file, its deck, and the model of a CSV.
struct Compare<'a>(
    &'a Path,
    Option<&'a Path>,
    &'a dyn Fn() -> Result<Model, String>,
);

impl ForProblem for Compare<'_> {
    type Output = Result<Value, String>;

    fn run<P: Faces>(self) -> Self::Output {
        let Compare(path, deck, structure) = self;
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
        let (kinematics, stick_slope, peak_pressure) = match &loaded.header {
            Some(header) => {
                let read = load::ccx_contact(path, deck, header).map_err(failed)?;
                (read.kinematics, Some(read.stick_slope), read.peak_pressure)
            }
            None => (Kinematics::NotStated, None, None),
        };
        let run = compare_run::run_evidence(
            path,
            loaded.header.as_ref(),
            &P::interface(&model),
            kinematics,
            stick_slope,
            peak_pressure,
        );
        compare_run::judged_for::<P>(&run, &model, &mut compared);
        let checked = P::checked(compared).map_err(|e| format!("{source}: {e}"))?;
        let report = ContactCompared::<P>::new(&source, (checked, Vec::new()), &[run]);
        Ok(json::of(&report.with_contact()))
    }
}

/// `microslip beam|plate|lap --format json` (`src/cli/point.rs`): the plate and the joint add
/// the continuum reference where their reduced theory does not hold.
pub fn point_report(kind: ModelKind, values: &[f64], name: &str) -> Result<Value, String> {
    let model = model(kind, values, true)?;
    for_problem(kind, PointReport(&model, name))
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
    let model = model(kind, values, false)?;
    for_problem(kind, CycleReport(&model, name, amplitude))
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
    let model = model(kind, values, true)?;
    let answer = for_problem(kind, Tolerance(&model, question, range, element))?;
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
    let model = model(kind, values, true)?;
    for_problem(kind, DeckText(&model, mesh, loads))
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
    let structure = || model(kind, values, false);
    for_problem(kind, Compare(path, deck, &structure))
}
