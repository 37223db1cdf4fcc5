//! The one place this binding names a problem. The application's reports and FE decks are still
//! one function per problem (`report::json::beam`, `plate`, `lap`, `fe::deck::beam_deck_on_path`,
//! ...) taking typed models, and the CLI commands that choose among them are private to its `app`
//! feature. Each function here is that command's body minus argument parsing and printing, and
//! says which file it mirrors; the tests compare every one with the CLI's output, so a drift
//! fails them. When issue 32 puts reports and decks behind the problem traits, each `match`
//! becomes one generic call and this file shrinks to nothing. Meanwhile a new problem needs an
//! arm here for `to_dict`, `cycle`, `kt_tolerance`, `fit`, `deck` and `compare` (construct,
//! solve, sweep, `fe_defaults` and `continuum` are generic, in `features`).

use std::path::Path;

use microslip::TipForce;
use microslip::fe::deck::{self, DeckMesh, LoadPath};
use microslip::fe::header::StickSlope;
use microslip::fe::{compare, lap_deck, load};
use microslip::fit::{self, Weights};
use microslip::kernel::params::{Compact, Domain, Unit};
use microslip::kernel::validity::Validity;
use microslip::problems::inputs::Model;
use microslip::problems::lap::LapJointProblem;
use microslip::problems::twin_beams::TwinBeamsProblem;
use microslip::problems::{ModelKind, lap, plate};
use microslip::report::compare::plate::PlateCompareReport;
use microslip::report::compare::{beam::BeamCompareReport, lap::LapCompareReport};
use microslip::report::json;
use microslip::report::point::tolerance::ToleranceReport;
use microslip::study::tolerance;
use serde_json::Value;

/// The model of `kind` at `values`, validated as the CLI validates it.
fn model(kind: ModelKind, values: &[f64]) -> Result<Model, String> {
    let inputs = kind
        .problem()
        .inputs_at(values)
        .map_err(|e| e.to_string())?;
    inputs.validate().map_err(|e| e.to_string())
}

/// The model without its load (a command that does not read F: cycle, fit, compare).
fn structure(kind: ModelKind, values: &[f64]) -> Result<Model, String> {
    let inputs = kind
        .problem()
        .inputs_at(values)
        .map_err(|e| e.to_string())?;
    inputs.validate_without_load().map_err(|e| e.to_string())
}

/// A report struct as the CLI's JSON value (`report::point::to_json`, which is crate-private).
fn to_json(report: &impl serde::Serialize) -> Value {
    serde_json::to_value(report).unwrap_or(Value::Null)
}

/// A value given for a flag of the CLI (`amplitude`, `F_from`), checked against `domain` with the
/// CLI's words (`src/cli/loading.rs`, `check_flag`).
pub fn check_flag(name: &str, value: f64, domain: Domain, unit: Unit) -> Result<f64, String> {
    domain
        .check("value", value, unit)
        .map_err(|e| format!("invalid {name} = {}: {}", Compact(value), e.allowed()))
}

/// `microslip beam|plate|lap --format json` (`src/cli/mod.rs`, `src/cli/point.rs`): the plate and
/// the joint add the continuum reference where their reduced theory does not hold.
pub fn point_report(kind: ModelKind, values: &[f64], name: &str) -> Result<Value, String> {
    Ok(match model(kind, values)? {
        Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, force }) => json::beam(name, &beams, force),
        Model::Plate(squeezed) => {
            let continuum = (squeezed.validity().validity != Validity::Holds).then(|| {
                plate::solve_plate_continuum(squeezed.params(), plate::ContinuumMesh::default())
            });
            json::plate(name, &squeezed, continuum.as_ref())
        }
        Model::Lap(microslip::problems::lap::problem::LapModel { joint, force }) => {
            let continuum = (joint.validity(force).validity != Validity::Holds).then(|| {
                lap::solve_lap_continuum(
                    joint.params(),
                    force.newtons(),
                    lap::LapContinuumMesh::default(),
                )
            });
            json::lap(name, &joint, force, continuum.as_ref())
        }
    })
}

/// `microslip cycle --amplitude A --format json` (`src/cli/cycle.rs`): the structure validated
/// without its load, the amplitude checked as the CLI checks `--amplitude`.
pub fn cycle_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    amplitude: f64,
) -> Result<Value, String> {
    let amplitude = check_flag("amplitude", amplitude, Domain::FORCE, Unit::Newton)?;
    let refused =
        |allowed: String| format!("invalid amplitude = {}: {allowed}", Compact(amplitude));
    match structure(kind, values)? {
        Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, .. }) => {
            let amplitude = TipForce::new(amplitude).map_err(|e| refused(e.allowed()))?;
            Ok(json::cycle(name, &beams, amplitude))
        }
        Model::Lap(microslip::problems::lap::problem::LapModel { joint, .. }) => {
            let amplitude = joint.force(amplitude).map_err(|e| refused(e.allowed()))?;
            Ok(json::lap_cycle(name, &joint, amplitude))
        }
        Model::Plate(_) => Err(format!(
            "the {kind} problem has no load to cycle (its pressure is fixed)"
        )),
    }
}

/// What `kt --tolerance` measures the deviation from (`--of`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Of {
    /// The Coulomb answer (K_T -> infinity).
    Coulomb,
    /// The answer at the current K_T.
    Current,
}

/// `microslip kt --tolerance T [--of REF] [--from F] [--to F] --format json` (`src/cli/kt.rs`,
/// `run_kt_tolerance`): the K_T within `tol` (a fraction) of the reference over the forces
/// `[from, to]` (each the model's F when not given).
pub fn kt_tolerance_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    (tol, of): (f64, Of),
    [from, to]: [Option<f64>; 2],
    element: f64,
) -> Result<Value, String> {
    let range = |force: f64| -> Result<[f64; 2], String> {
        let range = [
            check_flag("F_from", from.unwrap_or(force), Domain::FORCE, Unit::Newton)?,
            check_flag("F_to", to.unwrap_or(force), Domain::FORCE, Unit::Newton)?,
        ];
        if range[0] > range[1] {
            return Err(format!(
                "invalid F_to = {}: must not be below F_from = {} N (the forces checked run from \
                 F_from up to F_to)",
                Compact(range[1]),
                Compact(range[0])
            ));
        }
        Ok(range)
    };
    let answer = match model(kind, values)? {
        Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, force }) => {
            let range = range(force.newtons())?;
            match of {
                Of::Coulomb => tolerance::stiffness_for_tolerance::<TwinBeamsProblem>(
                    &beams, range, tol, element,
                ),
                Of::Current => tolerance::stiffness_near_current::<TwinBeamsProblem>(
                    &beams, range, tol, element,
                ),
            }
        }
        Model::Lap(microslip::problems::lap::problem::LapModel { joint, force }) => {
            let range = range(force.newtons())?;
            let gross = joint.gross_slip_force();
            if range[1] > gross {
                let flag = if to.is_some() { "F_to" } else { "F_from" };
                return Err(format!(
                    "invalid {flag} = {}: must be at most F_gross = 2 b mu P L = {} N (the joint \
                     slides through beyond it)",
                    Compact(range[1]),
                    Compact(gross)
                ));
            }
            match of {
                Of::Coulomb => tolerance::stiffness_for_tolerance::<LapJointProblem>(
                    &joint, range, tol, element,
                ),
                Of::Current => tolerance::stiffness_near_current::<LapJointProblem>(
                    &joint, range, tol, element,
                ),
            }
        }
        Model::Plate(squeezed) => {
            if from.is_some() || to.is_some() {
                return Err(format!(
                    "the {kind} problem has no force: F_from and F_to do not apply"
                ));
            }
            match of {
                Of::Coulomb => tolerance::plate_stiffness_for_tolerance(&squeezed, tol, element),
                Of::Current => tolerance::plate_stiffness_near_current(&squeezed, tol, element),
            }
        }
    }
    .map_err(|e| e.to_string())?;
    Ok(to_json(&ToleranceReport::new(name, &answer)))
}

/// `microslip fit beam|lap DATA --format json` (`src/cli/fitting.rs`, `run_fit`) on `csv`, the
/// measured curve written as the CLI reads it (so the CLI's parser checks every value), `data`
/// what the report calls it.
pub fn fit_report(
    kind: ModelKind,
    values: &[f64],
    name: &str,
    (data, csv): (&str, &str),
    fixed: (Option<f64>, Option<f64>),
    weights: Option<&str>,
) -> Result<Value, String> {
    let (structure, measured) = match structure(kind, values)? {
        Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, .. }) => (
            fit::Structure::Beam(beams.params()),
            microslip::measured::parse_measured_with_progress(csv, &mut |_, _| {}),
        ),
        Model::Lap(microslip::problems::lap::problem::LapModel { joint, .. }) => (
            fit::Structure::Lap(joint.params()),
            microslip::measured::parse_measured_joint_with_progress(csv, &mut |_, _| {}),
        ),
        Model::Plate(_) => {
            return Err(format!(
                "the {kind} problem has no force-response curve to fit (the twin beams and the \
                 lap joint have)"
            ));
        }
    };
    let measured = measured.map_err(|e| format!("{data}: {e}"))?;
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
    let result = fit::fit_weighted(structure, &measured.points, fixed, weights, &mut |_| {})
        .map_err(|e| e.to_string())?;
    Ok(json::fit(data, name, &structure, &result))
}

/// `microslip deck ccx MODEL [--mesh fine] [--loads ...]` (`src/cli/decks.rs`, `build_deck`) at
/// the model's stick slope: the deck's text.
pub fn deck_text(
    kind: ModelKind,
    values: &[f64],
    mesh: DeckMesh,
    loads: Option<&[f64]>,
) -> Result<String, String> {
    let slope = StickSlope::Model;
    let path = LoadPath { force_step: None };
    let increasing = |forces: &[f64]| match forces.windows(2).find(|w| w[0] >= w[1]) {
        Some(w) => Err(format!(
            "invalid loads = {}: the loads must increase from one step to the next",
            Compact(w[1])
        )),
        None => Ok(()),
    };
    match model(kind, values)? {
        Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, .. }) => {
            let loads: Vec<TipForce> = match loads {
                // The CLI's default: multiples of F_thre spanning microslip and macroslip.
                None => [0.5, 0.75, 1.0, 1.25, 1.875, 2.5]
                    .map(|m| TipForce::clamped(m * beams.threshold_force()))
                    .to_vec(),
                Some(forces) => {
                    increasing(forces)?;
                    forces
                        .iter()
                        .map(|&f| check_flag("loads", f, Domain::FORCE, Unit::Newton))
                        .map(|f| f.map(TipForce::clamped))
                        .collect::<Result<_, _>>()?
                }
            };
            deck::beam_deck_on_path(&beams, &loads, mesh, slope, path)
        }
        Model::Lap(microslip::problems::lap::problem::LapModel { joint, .. }) => {
            let loads: Vec<_> = match loads {
                // The CLI's default at the model's slope: one force in each regime.
                None => {
                    let (f1, f2, gross) = (
                        joint.first_slip_force(),
                        joint.second_slip_force(),
                        joint.gross_slip_force(),
                    );
                    let mut forces =
                        vec![0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.9 * gross];
                    forces.dedup_by(|a, b| *a <= *b);
                    forces.into_iter().map(|f| joint.clamped_force(f)).collect()
                }
                Some(forces) => {
                    increasing(forces)?;
                    forces
                        .iter()
                        .map(|&f| {
                            joint.force(f).map_err(|e| {
                                format!("invalid loads = {}: {}", Compact(f), e.allowed())
                            })
                        })
                        .collect::<Result<_, _>>()?
                }
            };
            lap_deck::lap_deck(&joint, &loads, mesh, slope, path)
        }
        Model::Plate(squeezed) => {
            if loads.is_some() {
                return Err(
                    "loads are the tip forces of a beam deck or the joint's; the plate \
                            deck applies its pressure P in one step"
                        .to_string(),
                );
            }
            deck::plate_deck(&squeezed, mesh, slope)
        }
    }
    .map_err(|e| e.to_string())
}

/// `microslip compare MODEL RESULT [--deck INP] --format json` (`src/cli/compare.rs`) for one
/// result file: a CalculiX `.dat` (its deck's header gives the parameters) or a CSV (compared at
/// `values`).
pub fn compare_report(
    kind: ModelKind,
    values: &[f64],
    path: &Path,
    deck: Option<&Path>,
) -> Result<Value, String> {
    let source = path.display().to_string();
    let data_error = |e: load::LoadError| format!("{}: {}", e.path, e.reason);
    let of_header = |header: &Option<microslip::fe::header::DeckHeader>| -> Result<Model, String> {
        match header {
            Some(header) => {
                let model = header.model().map_err(|e| e.to_string())?;
                if model.kind() != kind {
                    return Err(format!(
                        "the deck's header describes the {} problem, not the one compared",
                        model.kind()
                    ));
                }
                Ok(model)
            }
            None => structure(kind, values),
        }
    };
    match kind {
        ModelKind::Beam => {
            let loaded = load::beam_results(path, deck).map_err(data_error)?;
            let Model::Beam(microslip::problems::twin_beams::problem::BeamsModel { beams, .. }) = of_header(&loaded.header)? else {
                return Err(format!("{source}: not a twin-beam result"));
            };
            let compared =
                compare::compare_beams(&beams, &loaded.points, loaded.interface_mesh.as_ref());
            Ok(to_json(&BeamCompareReport::new(&source, &compared)))
        }
        ModelKind::Plate => {
            let loaded = load::plate_results(path, deck).map_err(data_error)?;
            let squeezed = match &loaded.header {
                Some(_) => of_header(&loaded.header)?,
                // A plate CSV is compared at the model as given, with its load.
                None => model(kind, values)?,
            };
            let Model::Plate(squeezed) = squeezed else {
                return Err(format!("{source}: not a plate result"));
            };
            let rows =
                compare::compare_plate(&squeezed, &loaded.points, loaded.interface_mesh.as_ref());
            Ok(to_json(&PlateCompareReport::new(&source, &rows)))
        }
        ModelKind::Lap => {
            let loaded = load::lap_results(path, deck).map_err(data_error)?;
            let Model::Lap(microslip::problems::lap::problem::LapModel { joint, .. }) = of_header(&loaded.header)? else {
                return Err(format!("{source}: not a lap-joint result"));
            };
            let rows = compare::compare_lap(&joint, &loaded.points, loaded.interface_mesh.as_ref())
                .map_err(|e| format!("{source}: {e}"))?;
            Ok(to_json(&LapCompareReport::new(&source, &rows)))
        }
    }
}
