//! One state of a problem: `beam`, `plate` and `lap` reports (text or JSON).

use super::*;
use crate::problems::lap::LapJointProblem;
use crate::problems::plate::SqueezedPlateProblem;
use crate::problems::twin_beams::TwinBeamsProblem;

/// `beam`: the twin beams at their tip force.
pub(super) fn run_beam_point(out: &mut impl Write, args: &PointArgs) -> Result<(), CliError> {
    let (name, model) = load_problem::<TwinBeamsProblem>(&args.inputs, "beam", Load::Used)?;
    match args.format {
        ReportFormat::Text => out.write_all(
            crate::problems::twin_beams::report::BeamReport::new(&name, &model.beams, model.force)
                .text()
                .as_bytes(),
        )?,
        ReportFormat::Json => write_json(
            out,
            &json::of(&crate::problems::twin_beams::report::BeamReport::new(
                &name,
                &model.beams,
                model.force,
            )),
        )?,
    }
    Ok(())
}

pub(super) fn run_plate_point(out: &mut impl Write, args: &PlatePointArgs) -> Result<(), CliError> {
    let PlatePointArgs {
        point: args,
        continuum,
    } = args;
    let (name, plate) = load_problem::<SqueezedPlateProblem>(&args.inputs, "plate", Load::Used)?;
    let solved = (*continuum
        || plate.validity().validity != crate::kernel::validity::Validity::Holds)
        .then(|| {
            crate::problems::plate::solve_plate_continuum(
                plate.params(),
                crate::problems::plate::ContinuumMesh::default(),
            )
        });
    if *continuum && let Some(Err(e)) = &solved {
        return Err(CliError::Numeric(e.clone()));
    }
    match args.format {
        ReportFormat::Text => out.write_all(
            crate::problems::plate::report::PlateReport::new(&name, &plate, solved.as_ref())
                .text()
                .as_bytes(),
        )?,
        ReportFormat::Json => write_json(
            out,
            &json::of(&crate::problems::plate::report::PlateReport::new(
                &name,
                &plate,
                solved.as_ref(),
            )),
        )?,
    }
    Ok(())
}

pub(super) fn run_lap_point(out: &mut impl Write, args: &LapPointArgs) -> Result<(), CliError> {
    let LapPointArgs {
        point: args,
        continuum,
    } = args;
    let (name, model) = load_problem::<LapJointProblem>(&args.inputs, "lap", Load::Used)?;
    let (joint, force) = (model.joint, model.force);
    let solved = (*continuum
        || joint.validity(force).validity != crate::kernel::validity::Validity::Holds)
        .then(|| {
            crate::problems::lap::solve_lap_continuum(
                joint.params(),
                force.newtons(),
                crate::problems::lap::LapContinuumMesh::default(),
            )
        });
    // An answer asked for with --continuum that could not be given is an error (nothing on
    // stdout; exit 2 for inputs it refuses, 1 for a failed solve: `CliError::exit_code`);
    // the automatic one is reported as failed in the output.
    if *continuum && let Some(Err(e)) = &solved {
        return Err(CliError::Numeric(e.clone()));
    }
    match args.format {
        ReportFormat::Text => out.write_all(
            crate::problems::lap::report::LapReport::new(&name, &joint, force, solved.as_ref())
                .text()
                .as_bytes(),
        )?,
        ReportFormat::Json => write_json(
            out,
            &json::of(&crate::problems::lap::report::LapReport::new(
                &name,
                &joint,
                force,
                solved.as_ref(),
            )),
        )?,
    }
    Ok(())
}
