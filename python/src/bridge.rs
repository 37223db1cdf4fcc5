//! The one place this binding names a problem: the application's reports are still one function
//! per problem (`report::json::beam`, `plate`, `lap`, `cycle`, `lap_cycle`) taking typed models,
//! and the CLI's commands that pick among them are private to its `app` feature. Each function
//! here is the CLI command's body minus argument parsing and printing (`src/cli/point.rs`,
//! `src/cli/cycle.rs`), so the JSON is the CLI's byte for byte. When issue 32 puts the reports
//! behind the problem traits, each `match` below becomes one generic call and this file shrinks
//! to nothing; a new problem meanwhile needs an arm here for `to_dict()` and `cycle()` only
//! (construct, solve and sweep are generic).

use microslip::TipForce;
use microslip::kernel::params::{Domain, Unit};
use microslip::kernel::validity::Validity;
use microslip::problems::inputs::Model;
use microslip::problems::{ModelKind, lap, plate};
use microslip::report::json;
use serde_json::Value;

/// The model of `kind` at `values`, validated as the CLI validates it.
fn model(kind: ModelKind, values: &[f64]) -> Result<Model, String> {
    let inputs = kind
        .problem()
        .inputs_at(values)
        .map_err(|e| e.to_string())?;
    inputs.validate().map_err(|e| e.to_string())
}

/// `microslip beam|plate|lap --format json` (`src/cli/mod.rs`, `src/cli/point.rs`): the plate and
/// the joint add the continuum reference where their reduced theory does not hold.
pub fn point_report(kind: ModelKind, values: &[f64], name: &str) -> Result<Value, String> {
    Ok(match model(kind, values)? {
        Model::Beam { beams, force } => json::beam(name, &beams, force),
        Model::Plate(squeezed) => {
            let continuum = (squeezed.validity().validity != Validity::Holds).then(|| {
                plate::solve_plate_continuum(squeezed.params(), plate::ContinuumMesh::default())
            });
            json::plate(name, &squeezed, continuum.as_ref())
        }
        Model::Lap { joint, force } => {
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
    let refused = |allowed: String| format!("invalid amplitude = {amplitude}: {allowed}");
    let amplitude = Domain::FORCE
        .check("amplitude", amplitude, Unit::Newton)
        .map_err(|e| refused(e.allowed()))?;
    let inputs = kind
        .problem()
        .inputs_at(values)
        .map_err(|e| e.to_string())?;
    match inputs.validate_without_load().map_err(|e| e.to_string())? {
        Model::Beam { beams, .. } => {
            let amplitude = TipForce::new(amplitude).map_err(|e| refused(e.allowed()))?;
            Ok(json::cycle(name, &beams, amplitude))
        }
        Model::Lap { joint, .. } => {
            let amplitude = joint.force(amplitude).map_err(|e| refused(e.allowed()))?;
            Ok(json::lap_cycle(name, &joint, amplitude))
        }
        Model::Plate(_) => Err(format!(
            "the {kind} problem has no load to cycle (its pressure is fixed)"
        )),
    }
}
