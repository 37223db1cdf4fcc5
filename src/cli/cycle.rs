//! `cycle`: hysteresis loops under a cyclic load.

use super::*;
use crate::TipForce;
use crate::problems::lap::LapJointProblem;
use crate::problems::twin_beams::TwinBeamsProblem;

pub(super) fn run_cycle(
    out: &mut impl Write,
    amplitude: f64,
    inputs: &InputArgs,
    points: u64,
    format: CycleFormat,
) -> Result<(), CliError> {
    let amplitude = check_flag("--amplitude", amplitude, Domain::FORCE, Unit::Newton)?;
    let points_error = |error| CliError::Range {
        error,
        flags: ["", "", "--points"],
    };
    curves::check_points(points).map_err(points_error)?;
    // The amplitude is cycled, not the preset's F.
    let (name, model) = load_any_structure(inputs, DEFAULT_PROBLEM)?;
    let beams = match model {
        Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. }) => beams,
        Model::Lap(crate::problems::lap::problem::LapModel { joint, .. }) => {
            let amplitude = joint.force(amplitude).map_err(|e| CliError::Flag {
                flag: "--amplitude",
                value: amplitude,
                allowed: e.allowed(),
            })?;
            match format {
                CycleFormat::Text => out.write_all(
                    text::cycle::<LapJointProblem>(&name, &joint, amplitude).as_bytes(),
                )?,
                CycleFormat::Json => write_json(
                    out,
                    &json::cycle::<LapJointProblem>(&name, &joint, amplitude),
                )?,
                CycleFormat::Csv => {
                    let points = load::cycle_loop::<LapJointProblem>(&joint, amplitude, points)
                        .map_err(points_error)?;
                    write_table(out, TableFormat::Csv, points.map(|p| LapLoopRow::from(&p)))?;
                }
            }
            return Ok(());
        }
        Model::Plate(_) => return Err(plate_has_no_cycle(inputs, "cycle")),
    };
    let amplitude = TipForce::new(amplitude)?;
    match format {
        CycleFormat::Text => {
            out.write_all(text::cycle::<TwinBeamsProblem>(&name, &beams, amplitude).as_bytes())?
        }
        CycleFormat::Json => write_json(
            out,
            &json::cycle::<TwinBeamsProblem>(&name, &beams, amplitude),
        )?,
        CycleFormat::Csv => {
            let points = load::cycle_loop::<TwinBeamsProblem>(&beams, amplitude, points)
                .map_err(points_error)?;
            write_table(out, TableFormat::Csv, points.map(|p| LoopRow::from(&p)))?;
        }
    }
    Ok(())
}

/// The contact element length of `--element-size`, default L/100.
pub(super) fn element_size(element: Option<f64>, model: &Model) -> Result<f64, CliError> {
    match element {
        Some(e) => check_flag("--element-size", e, Domain::ELEMENT_SIZE, Unit::Millimetre),
        None => Ok(model.interface().length / 100.0),
    }
}
