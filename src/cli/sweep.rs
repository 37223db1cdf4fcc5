//! `sweep`: tables over one parameter.

use super::*;

/// `microslip sweep lap`: over F (rows of the F sweep) or any other parameter.
pub(super) fn run_lap_sweep(out: &mut impl Write, args: &LapSweepArgs) -> Result<(), CliError> {
    use crate::study::lap::lap_param_sweep;
    let varied: LapParam = args.vary.as_deref().unwrap_or("F").parse()?;
    let param = Param::Lap(varied);
    let values = Samples::of_param(
        param,
        args.from,
        args.to,
        args.points,
        args.spacing.spacing(param),
    )
    .map_err(force_range_error)?;
    let (_, joint, force) = load_lap(&args.inputs, "sweep lap")?;
    if varied == LapParam::Force {
        let rows =
            load::force_sweep::<LapJointProblem>(joint, values).map_err(force_range_error)?;
        write_table(out, args.format, rows.map(|r| LapRow::from(&r)))?;
    } else {
        let rows = lap_param_sweep(joint, force, varied, values).map_err(force_range_error)?;
        write_varied(
            out,
            args.format,
            param,
            rows.map(|(v, r)| (v, LapRow::from(&r))),
        )?;
    }
    Ok(())
}

pub(super) fn run_beam_sweep(out: &mut impl Write, args: &BeamSweepArgs) -> Result<(), CliError> {
    let BeamSweepArgs {
        vary,
        from,
        to,
        points,
        spacing,
        inputs,
        format,
    } = args;
    let varied: BeamParam = vary.as_deref().unwrap_or("F").parse()?;
    let param = Param::Beam(varied);
    let values = Samples::of_param(param, *from, *to, *points, spacing.spacing(param))
        .map_err(force_range_error)?;
    let (_, beams, force) = load_beams(inputs, "sweep beam")?;
    if varied == BeamParam::Force {
        let rows =
            load::force_sweep::<TwinBeamsProblem>(beams, values).map_err(force_range_error)?;
        write_table(out, *format, rows.map(|r| BeamRow::from(&r)))?;
    } else {
        let rows =
            curves::beam_param_sweep(beams, force, varied, values).map_err(force_range_error)?;
        write_varied(
            out,
            *format,
            param,
            rows.map(|(v, r)| (v, BeamRow::from(&r))),
        )?;
    }
    Ok(())
}

pub(super) fn run_plate_sweep(out: &mut impl Write, args: &PlateSweepArgs) -> Result<(), CliError> {
    let PlateSweepArgs {
        kt_from,
        kt_to,
        vary,
        from,
        to,
        points,
        spacing,
        inputs,
        format,
    } = args;
    let (varied, lo, hi, flags) = match (kt_from, kt_to, from, to) {
        (Some(a), Some(b), None, None) => (
            PlateParam::Stiffness,
            *a,
            *b,
            ["--kt-from", "--kt-to", "--points"],
        ),
        (None, None, Some(a), Some(b)) => (
            vary.as_deref().unwrap_or("KT").parse()?,
            *a,
            *b,
            ["--from", "--to", "--points"],
        ),
        _ => {
            return Err(CliError::Usage(
                "sweep plate needs --kt-from A --kt-to B, or [--vary NAME] --from A --to B",
            ));
        }
    };
    let param = Param::Plate(varied);
    let range_error = |error| CliError::Range { error, flags };
    let values =
        Samples::of_param(param, lo, hi, *points, spacing.spacing(param)).map_err(range_error)?;
    let (_, plate) = load_plate(inputs, "sweep plate")?;
    if varied == PlateParam::Stiffness {
        let rows = curves::plate_kt_sweep(plate, values).map_err(range_error)?;
        write_table(out, *format, rows.map(|r| PlateRow::from(&r)))?;
    } else {
        let rows = curves::plate_param_sweep(plate, varied, values).map_err(range_error)?;
        write_varied(
            out,
            *format,
            param,
            rows.map(|(v, r)| (v, PlateRow::from(&r))),
        )?;
    }
    Ok(())
}

pub(super) fn run_cycle_sweep(out: &mut impl Write, args: &CycleSweepArgs) -> Result<(), CliError> {
    let CycleSweepArgs {
        from,
        to,
        points,
        inputs,
        format,
    } = args;
    let amplitudes = curves::force_samples(*from, *to, *points).map_err(force_range_error)?;
    match load_any_structure(inputs, ModelKind::Beam)?.1 {
        Model::Beam { beams, .. } => {
            let rows = load::cycle_sweep::<TwinBeamsProblem>(beams, amplitudes)
                .map_err(force_range_error)?;
            write_table(out, *format, rows.map(|r| CycleRow::from(&r)))?;
        }
        Model::Lap { joint, .. } => {
            let rows = load::cycle_sweep::<LapJointProblem>(joint, amplitudes)
                .map_err(force_range_error)?;
            write_table(out, *format, rows.map(|r| CycleRow::from(&r)))?;
        }
        Model::Plate(_) => return Err(plate_has_no_cycle(inputs, "sweep cycle")),
    }
    Ok(())
}
