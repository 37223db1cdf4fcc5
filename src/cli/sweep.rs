//! `sweep`: tables over one parameter.

use super::*;
use crate::problems::problem::ParamKey;
use crate::report::face::faces;
use crate::report::point::cycle::LoadTableError;
use std::time::{Duration, Instant};

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
    // Rows paced: a cylinder row is a solve (issue 47).
    let mut out = Paced::new(out, values.len());
    let sweep = Sweep {
        out: &mut out,
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
    let mut out = Paced::new(out, amplitudes.len());
    match face.write_cycle_sweep(&mut out, *format, &model, amplitudes) {
        Some(Ok(())) => Ok(()),
        Some(Err(LoadTableError::Range(e))) => Err(force_range_error(e)),
        Some(Err(LoadTableError::Force(e))) => Err(CliError::Param(e)),
        Some(Err(LoadTableError::Output(e))) => Err(CliError::Output(e)),
        None => Err(no_cycle()),
    }
}

/// The writer of a table whose rows may come slowly (issue 47: a cylinder row is a solve, and
/// `--points` takes up to 1e8). Rows reach the reader at least every [`Paced::FLUSH`], so a reader
/// that left (`sweep ... | head -2`) is seen within that and the run stops with the next row,
/// not when the 64 KiB buffer fills; and once [`Paced::MEASURE`] has gone by, if the rows left
/// would take more than [`Paced::WORTH_SAYING`] at the pace so far, the estimate goes to stderr,
/// once.
pub(super) struct Paced<'a, W: Write> {
    inner: &'a mut W,
    /// Rows expected, and lines written so far (a row is one line in CSV and in JSON).
    expected: u64,
    lines: u64,
    started: Instant,
    flushed: Instant,
    writes: u32,
    /// Whether the estimate was decided (said or not needed).
    estimated: bool,
}

impl<'a, W: Write> Paced<'a, W> {
    const FLUSH: Duration = Duration::from_millis(100);
    const MEASURE: Duration = Duration::from_millis(500);
    const WORTH_SAYING: Duration = Duration::from_secs(3);

    pub(super) fn new(inner: &'a mut W, expected: u64) -> Paced<'a, W> {
        let now = Instant::now();
        Paced {
            inner,
            expected,
            lines: 0,
            started: now,
            flushed: now,
            writes: 0,
            estimated: false,
        }
    }

    /// After [`Paced::MEASURE`], with a row written: the time the rest will take at this pace.
    fn estimate(&mut self, now: Instant) {
        let elapsed = now - self.started;
        if elapsed < Self::MEASURE || self.lines < 2 {
            return;
        }
        self.estimated = true;
        // About one line a row (CSV's header, JSON's opening bracket).
        let rows = self.lines - 1;
        let per_row = elapsed.as_secs_f64() / rows as f64;
        let left = per_row * self.expected.saturating_sub(rows) as f64;
        if left > Self::WORTH_SAYING.as_secs_f64() {
            // Not `eprintln!`, which panics when stderr is gone.
            let _ = writeln!(
                io::stderr(),
                "microslip: {} rows at about {:.3} ms a row: about {} more (Ctrl-C stops)",
                self.expected,
                per_row * 1e3,
                duration_words(left)
            );
        }
    }
}

/// `seconds` as a person says it: "40 s", "12 min", "3.5 h", "2.1 days".
pub(super) fn duration_words(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 7200.0 {
        format!("{:.0} min", seconds / 60.0)
    } else if seconds < 172_800.0 {
        format!("{:.1} h", seconds / 3600.0)
    } else {
        format!("{:.1} days", seconds / 86_400.0)
    }
}

impl<W: Write> Write for Paced<'_, W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let written = self.inner.write(buf)?;
        if !self.estimated {
            self.lines += buf[..written].iter().filter(|&&b| b == b'\n').count() as u64;
        }
        // The clock read every 16 writes: a fast table's rows (a beam's, 0.6 us) pay nothing.
        self.writes = self.writes.wrapping_add(1);
        if self.writes.is_multiple_of(16) {
            let now = Instant::now();
            if now - self.flushed >= Self::FLUSH {
                self.inner.flush()?;
                self.flushed = now;
            }
            if !self.estimated {
                self.estimate(now);
            }
        }
        Ok(written)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}
