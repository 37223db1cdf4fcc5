//! `sweep`: tables over one parameter.

use super::*;
use crate::problems::problem::ParamKey;
use crate::report::face::faces;
use crate::report::point::cycle::LoadTableError;

/// `microslip sweep ...`: the generic sweep, a problem's (`sweep PROBLEM`) or `sweep cycle`.
pub(super) fn run_sweep(out: &mut impl Write, args: &SweepArgs) -> Result<(), CliError> {
    match &args.command {
        None => run_generic_sweep(out, &args.generic),
        Some(SweepCommand::Problem(problem)) => run_problem_sweep(out, problem),
        Some(SweepCommand::Cycle(args)) => run_cycle_sweep(out, args),
    }
}

/// `microslip sweep [--model M] [--preset P] [--vary NAME] --from A --to B`: the problem comes
/// from --model or the preset; the same tables, bytes and refusals as the alias of that problem
/// (both end in [`write_sweep`]).
fn run_generic_sweep(out: &mut impl Write, args: &GenericSweepArgs) -> Result<(), CliError> {
    let (name, preset) = resolve_generic(&args.inputs, args.model)?;
    let kind = preset.inputs.kind();
    let param = match (&args.vary, default_vary(kind)) {
        (Some(key), _) => kind.param(key)?,
        (None, Some(param)) => param,
        (None, None) => {
            return Err(CliError::Invalid(format!(
                "the {kind} problem has no load and no K_T to sweep by default: give --vary \
                 (allowed: {})",
                kind.params()
                    .iter()
                    .map(|p| p.name())
                    .collect::<Vec<_>>()
                    .join(" ")
            )));
        }
    };
    // clap requires both ends without a subcommand.
    let (Some(from), Some(to)) = (args.from, args.to) else {
        return Err(CliError::Usage("sweep needs --from A --to B"));
    };
    let points = match args.points {
        Some(points) => points,
        None if from == to => 1,
        None => DEFAULT_SWEEP_POINTS,
    };
    let values = Samples::of_param(param, from, to, points, args.spacing.spacing(param))
        .map_err(force_range_error)?;
    let (_, model) = apply_and_validate(&args.inputs, name, preset, Load::Used)?;
    write_sweep(out, model, param, values, args.format, force_range_error)
}

/// The rows of `model` over `param` at `values`, as every sweep command writes them: for the
/// problem's [`default_vary`] parameter its own table (the F sweep, the plate's K_T sweep), for
/// any other the parameter's column first, then the same columns. The one place a sweep meets
/// each problem's row type (its [`ReportFace`](crate::report::face::ReportFace)); `range_error`
/// names the command's flags in a refusal.
fn write_sweep(
    out: &mut impl Write,
    model: Model,
    param: Param,
    values: Samples,
    format: TableFormat,
    range_error: impl Fn(RangeError) -> CliError,
) -> Result<(), CliError> {
    let sweep = Sweep {
        out,
        model,
        param,
        values,
        format,
        range_error,
    };
    for_problem(model.kind(), sweep)
}

/// The arguments of [`write_sweep`], for [`for_problem`].
struct Sweep<'a, W, E> {
    out: &'a mut W,
    model: Model,
    param: Param,
    values: Samples,
    format: TableFormat,
    range_error: E,
}

impl<W: Write, E: Fn(RangeError) -> CliError> ForProblem for Sweep<'_, W, E> {
    type Output = Result<(), CliError>;

    fn run<P: Faces>(self) -> Result<(), CliError> {
        let Sweep {
            out,
            model,
            param,
            values,
            format,
            range_error,
        } = self;
        let own_table = Some(param) == default_vary(model.kind());
        let key = P::index_of(param).and_then(|i| <P::Key as ParamKey>::KEYS.get(i).copied());
        // `param` is parsed with the model's own kind by every caller.
        let (Some(typed), Some(key)) = (P::from_model(&model), key) else {
            return Err(CliError::Invalid(format!(
                "{param} is not a parameter of the {} problem",
                model.kind()
            )));
        };
        // A load-driven problem's own table is its F sweep, over the forces its structure
        // carries; any other table is the problem's rows at each value of the parameter.
        if own_table && let Some(face) = P::cycle() {
            let written = face.write_force_sweep(out, format, &model, values);
            return match written {
                Some(Ok(())) => Ok(()),
                Some(Err(LoadTableError::Range(e))) => Err(range_error(e)),
                Some(Err(LoadTableError::Force(e))) => Err(CliError::Param(e)),
                Some(Err(LoadTableError::Output(e))) => Err(CliError::Output(e)),
                None => Err(CliError::Invalid(format!(
                    "{param} is not a parameter of the {} problem",
                    model.kind()
                ))),
            };
        }
        let rows = curves::param_sweep::<P>(typed, key, values).map_err(range_error)?;
        if own_table {
            write_table(out, format, rows.map(|(_, r)| P::SweepRow::from(&r)))?;
        } else {
            write_varied(
                out,
                format,
                param,
                rows.map(|(v, r)| (v, P::SweepRow::from(&r))),
            )?;
        }
        Ok(())
    }
}

/// `microslip sweep PROBLEM`: over the problem's default parameter ([`default_vary`]: its load,
/// else K_T) or any other with `--vary`; a problem without a load also takes its K_T range as
/// `--kt-from A --kt-to B`.
fn run_problem_sweep(
    out: &mut impl Write,
    problem: &ForKind<ProblemSweepArgs>,
) -> Result<(), CliError> {
    let kind = problem.kind;
    let args = &problem.args;
    let command = model_command(kind, "sweep");
    let kt_range = (problem.value(args::KT_FROM), problem.value(args::KT_TO));
    let (param, lo, hi, flags) = match (kt_range, args.from, args.to) {
        ((Some(a), Some(b)), None, None) => (
            kind.params()
                .iter()
                .copied()
                .find(|p| p.is_stiffness())
                .ok_or_else(|| CliError::Invalid(format!("{command} has no K_T to sweep")))?,
            a,
            b,
            ["--kt-from", "--kt-to", "--points"],
        ),
        ((None, None), Some(a), Some(b)) => {
            let param = match (&args.vary, default_vary(kind)) {
                (Some(key), _) => kind.param(key)?,
                (None, Some(param)) => param,
                (None, None) => kind.param("")?,
            };
            (param, a, b, ["--from", "--to", "--points"])
        }
        // Only a problem without a load declares --kt-from (clap requires both ends of the
        // others).
        _ => {
            return Err(CliError::Invalid(format!(
                "{command} needs --kt-from A --kt-to B, or [--vary NAME] --from A --to B"
            )));
        }
    };
    let range_error = |error| CliError::Range { error, flags };
    let values = Samples::of_param(param, lo, hi, args.points, args.spacing.spacing(param))
        .map_err(range_error)?;
    let (_, model) = load(&args.inputs, kind, &command)?;
    write_sweep(out, model, param, values, args.format, range_error)
}

/// `microslip sweep cycle`: one cycle summary per amplitude, of any load-driven problem (the
/// preset's), through its cycle face; a problem without a load is refused.
fn run_cycle_sweep(out: &mut impl Write, args: &CycleSweepArgs) -> Result<(), CliError> {
    let CycleSweepArgs {
        from,
        to,
        points,
        inputs,
        format,
    } = args;
    // The amplitudes are checked before the preset is read, as the default problem's forces.
    let no_load = || {
        CliError::Invalid(format!(
            "sweep cycle: the {DEFAULT_PROBLEM} problem has no load to cycle"
        ))
    };
    let force = DEFAULT_PROBLEM.description().load.ok_or_else(no_load)?;
    let amplitudes = Samples::of_param(force, *from, *to, *points, Spacing::Linear)
        .map_err(force_range_error)?;
    let model = load_any_structure(inputs, DEFAULT_PROBLEM)?.1;
    let no_cycle = || no_load_to_cycle(inputs, model.kind(), "sweep cycle");
    let face = faces(model.kind()).cycle.ok_or_else(no_cycle)?;
    match face.write_cycle_sweep(out, *format, &model, amplitudes) {
        Some(Ok(())) => Ok(()),
        Some(Err(LoadTableError::Range(e))) => Err(force_range_error(e)),
        Some(Err(LoadTableError::Force(e))) => Err(CliError::Param(e)),
        Some(Err(LoadTableError::Output(e))) => Err(CliError::Output(e)),
        None => Err(no_cycle()),
    }
}
