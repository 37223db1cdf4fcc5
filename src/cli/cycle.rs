//! `cycle`: hysteresis loops under a cyclic load.

use super::*;
use crate::report::point::cycle::LoadTableError;

/// `microslip cycle ...`: the generic cycle (`--model`, or the preset's problem) or a
/// problem's (`cycle PROBLEM`), both through [`run_cycle`].
pub(super) fn run_cycle_command(out: &mut impl Write, args: &CycleArgs) -> Result<(), CliError> {
    match &args.command {
        None => run_cycle(out, args.generic.model, &args.generic.cycle),
        Some(problem) => run_cycle(out, Some(problem.kind), &problem.args),
    }
}

/// A cycle of the problem `model` names (else the preset's), through its cycle face
/// ([`AppFaces::cycle`](crate::report::face::AppFaces::cycle)); a problem without a
/// load is refused.
fn run_cycle(
    out: &mut impl Write,
    model: Option<ModelKind>,
    flags: &CycleFlags,
) -> Result<(), CliError> {
    let CycleFlags {
        amplitude,
        inputs,
        points,
        format,
    } = flags;
    let (points, format) = (*points, *format);
    // clap requires it.
    let Some(amplitude) = *amplitude else {
        return Err(CliError::Usage("cycle needs --amplitude FA"));
    };
    let amplitude = check_flag("--amplitude", amplitude, Domain::FORCE, Unit::Newton)?;
    let points_error = |error| CliError::Range {
        error,
        flags: ["", "", "--points"],
    };
    curves::check_points(points).map_err(points_error)?;
    // The amplitude is cycled, not the preset's F.
    let (name, preset) = resolve_generic(inputs, model)?;
    let (name, model) = apply_and_validate(inputs, name, preset, Load::Unused)?;
    let no_cycle = || no_load_to_cycle(inputs, model.kind(), "cycle");
    let face = report::face::faces(model.kind())
        .cycle
        .ok_or_else(no_cycle)?;
    let amplitude_error = |e: ParamError| CliError::Flag {
        flag: "--amplitude",
        value: amplitude,
        allowed: e.allowed(),
    };
    let report = || -> Result<_, CliError> {
        face.report(&name, &model, amplitude)
            .ok_or_else(no_cycle)?
            .map_err(amplitude_error)
    };
    match format {
        CycleFormat::Text => out.write_all(report()?.text().as_bytes())?,
        CycleFormat::Json => write_json(out, &json::of(&report()?))?,
        CycleFormat::Csv => face
            .write_loop(
                &mut super::sweep::Paced::new(out, points),
                TableFormat::Csv,
                &model,
                (amplitude, points),
            )
            .ok_or_else(no_cycle)?
            .map_err(|e| match e {
                LoadTableError::Force(e) => amplitude_error(e),
                LoadTableError::Range(e) => points_error(e),
                LoadTableError::Output(e) => CliError::Output(e),
            })?,
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
