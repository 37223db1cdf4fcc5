//! `cycle`: hysteresis loops under a cyclic load.

use super::*;
use crate::report::point::cycle::LoadTableError;

/// `microslip cycle`: any load-driven problem (the preset's) cycled, through its cycle face
/// ([`AnyReportFace::cycle`](crate::report::face::AnyReportFace::cycle)); a problem without a
/// load is refused.
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
    let no_cycle = || plate_has_no_cycle(inputs, "cycle");
    let face = report::face::report_face(model.kind())
        .cycle()
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
