//! `fit`: mu and K_T from a measured curve, with progress on stderr.

use super::*;

/// `--fix` values: (mu, K_T), keyed as `kind` keys them. Only those two are fitted, so only
/// they can be held: each is told by its spec (the friction coefficient's domain, a stiffness's
/// unit), the vocabulary every problem shares, not by a problem's key type.
pub(super) fn parse_fixed(
    kind: ModelKind,
    fixed: &[String],
) -> Result<(Option<f64>, Option<f64>), CliError> {
    let (mut mu, mut kt) = (None, None);
    for text in fixed {
        let bad = || CliError::Fix(text.clone());
        let (key, value) = text.split_once('=').ok_or_else(bad)?;
        let value = parse_number(value.trim()).ok_or_else(bad)?;
        let param = kind.param(key.trim()).map_err(|_| bad())?;
        if param.spec().domain == Domain::FRICTION {
            mu = Some(value);
        } else if param.is_stiffness() {
            kt = Some(value);
        } else {
            return Err(bad());
        }
    }
    Ok((mu, kt))
}

/// `microslip fit ...`: the generic fit, or a problem's (`fit PROBLEM DATA.csv`).
pub(super) fn run_fit_command(out: &mut impl Write, args: &FitArgs) -> Result<(), CliError> {
    match &args.command {
        None => run_generic_fit(out, &args.generic),
        Some(problem) => {
            let kind = problem.kind;
            match problem.args.model {
                Some(model) if model != kind => Err(CliError::Invalid(format!(
                    "fit {kind} and --model {model} disagree: name one problem"
                ))),
                _ => run_fit(out, kind, &problem.args.data, &problem.args.fit),
            }
        }
    }
}

/// `microslip fit DATA.csv [--model M] [--preset P] ...`: the problem comes from --model or the
/// preset, and must have a load; the same report, bytes and refusals as `fit PROBLEM`.
fn run_generic_fit(out: &mut impl Write, args: &GenericFitArgs) -> Result<(), CliError> {
    // clap requires the data without a subcommand; a word before it is no problem's key (a
    // problem's key is its subcommand).
    let data = match args.data.as_slice() {
        [data] => data,
        [word, _] => return Err(not_a_problem(&word.to_string_lossy())),
        _ => return Err(CliError::Usage("fit needs DATA.csv")),
    };
    refuse_a_problem_as_data(data)?;
    let (name, preset) = resolve_generic(&args.fit.inputs, args.model)?;
    let kind = preset.inputs.kind();
    if kind.description().load.is_none() {
        return Err(CliError::Invalid(format!(
            "fit: preset '{name}' is a {kind} preset, which has no load to fit a curve against; \
             fit takes a {} preset",
            fitted_problems().join(" or ")
        )));
    }
    run_fit(out, kind, data, &args.fit)
}

/// The problems `fit` takes, by key.
fn fitted_problems() -> Vec<&'static str> {
    ModelKind::ALL
        .iter()
        .filter(|k| k.description().load.is_some())
        .map(|k| k.name())
        .collect()
}

/// `fit WORD` where WORD is no file and names a problem without a fit (`fit plate`) or is a
/// slip of a problem's key (`fit lapp`): said so, rather than "cannot read WORD".
fn refuse_a_problem_as_data(data: &std::path::Path) -> Result<(), CliError> {
    if data.exists() {
        return Ok(());
    }
    let word = data.to_string_lossy();
    if let Ok(kind) = word.parse::<ModelKind>() {
        return Err(CliError::Invalid(format!(
            "fit {kind}: the {kind} problem has no load to fit a curve against; fit takes {} \
             (`fit PROBLEM DATA.csv`)",
            fitted_problems().join(", ")
        )));
    }
    match closest_problem(&word) {
        Some(_) => Err(not_a_problem(&word)),
        None => Ok(()),
    }
}

/// `fit WORD DATA.csv` where WORD is no problem's key: said so, with the key it is a slip of.
fn not_a_problem(word: &str) -> CliError {
    let suggestion = closest_problem(word)
        .map(|kind| format!("; did you mean 'fit {kind} DATA.csv'?"))
        .unwrap_or_default();
    CliError::Invalid(format!(
        "fit {word}: '{word}' is not a problem with a fit ({}){suggestion}",
        fitted_problems().join(", ")
    ))
}

/// The fit of `kind` to the measurements in `path`, with the fit's flags.
pub(super) fn run_fit(
    out: &mut impl Write,
    kind: ModelKind,
    path: &PathBuf,
    flags: &FitFlags,
) -> Result<(), CliError> {
    let FitFlags {
        inputs,
        fixed,
        weights,
        format,
    } = flags;
    let (weights, format) = (*weights, *format);
    let (fixed_mu, fixed_kt) = parse_fixed(kind, fixed)?;
    // The measured forces are fitted, not the preset's F.
    let (name, model) = load_for(inputs, kind, &model_command(kind, "fit"), Load::Unused)?;
    let structure = fit::Structure::of(&model)
        .ok_or_else(|| wrong_model(inputs, model.kind(), kind, &model_command(kind, "fit")))?;
    let data_error = |reason: String| CliError::Data {
        path: path.display().to_string(),
        reason,
    };
    let mut progress = ProgressLine::new(io::stderr(), io::stderr().is_terminal());
    let contents = crate::measured::read_text(path, crate::file::Kinds::AnyReadable)
        .map_err(|e| data_error(e.to_string()))?;
    let mut reading =
        |done, total| progress.update(Instant::now(), || text::reading_progress(done, total));
    // The columns are the fitted problem's own (`F_N,w_mm`, `Q_N_per_mm,sa_mm`).
    let data =
        crate::measured::parse_measured_response_with_progress(&contents, &structure, &mut reading);
    drop(contents);
    let crate::fit::Measured {
        points: data,
        sigma,
    } = match data {
        Ok(data) => data,
        Err(e) => {
            progress.finish();
            return Err(data_error(e.to_string()));
        }
    };
    let weights = match (sigma.as_deref(), weights) {
        (Some(sigma), None) => fit::Weights::Sigma(sigma),
        (Some(_), Some(chosen)) => {
            progress.finish();
            return Err(data_error(format!(
                "has a {} column, which gives each point's own standard deviation, and --weights {} \
                 asks for another; drop one",
                crate::measured::sigma_column(structure.response_column()),
                chosen
                    .to_possible_value()
                    .map_or_else(String::new, |v| v.get_name().to_string())
            )));
        }
        (None, Some(WeightsArg::Absolute)) => fit::Weights::Absolute,
        (None, Some(WeightsArg::Relative) | None) => fit::Weights::default(),
    };
    let result = fit::fit_measured(structure, &data, (fixed_mu, fixed_kt), weights, &mut |p| {
        progress.update(Instant::now(), || text::fit_progress(&p))
    });
    progress.finish();
    // A column of zeros is the file's fault: said with its path.
    let result = result.map_err(|e| match e {
        FitError::NothingToFit { .. } => data_error(e.to_string()),
        e => CliError::Fit(e),
    })?;
    match format {
        ReportFormat::Text => out.write_all(
            text::fit(&path.display().to_string(), &name, &structure, &result).as_bytes(),
        )?,
        ReportFormat::Json => write_json(
            out,
            &json::fit(&path.display().to_string(), &name, &structure, &result),
        )?,
    }
    Ok(())
}

/// A long fit's progress (reading, then fitting) on stderr: shown only when stderr is a terminal (scripts and pipes see
/// nothing) and once the command has run for [`ProgressLine::AFTER`]; one line rewritten in place
/// at most every [`ProgressLine::EVERY`], erased when the fit ends so that the report starts clean.
pub(super) struct ProgressLine<W: Write> {
    pub(super) out: W,
    pub(super) enabled: bool,
    pub(super) started: Instant,
    pub(super) last: Option<Instant>,
    pub(super) shown: bool,
}

impl<W: Write> ProgressLine<W> {
    /// Quiet for this long: short fits print nothing.
    const AFTER: Duration = Duration::from_secs(1);
    /// Fastest refresh.
    const EVERY: Duration = Duration::from_millis(100);

    pub(super) fn new(out: W, enabled: bool) -> Self {
        ProgressLine {
            out,
            enabled,
            started: Instant::now(),
            last: None,
            shown: false,
        }
    }

    /// Shows `message()` if it is time to; the message is only built then.
    pub(super) fn update(&mut self, now: Instant, message: impl FnOnce() -> String) {
        if !self.enabled
            || now.saturating_duration_since(self.started) < Self::AFTER
            || self
                .last
                .is_some_and(|last| now.saturating_duration_since(last) < Self::EVERY)
        {
            return;
        }
        self.last = Some(now);
        self.shown = true;
        // Carriage return and erase-line: the line is rewritten in place. A progress line is
        // best-effort: a failed write must not fail the fit.
        let _ = write!(self.out, "\r\x1b[2Kmicroslip: {}", message());
        let _ = self.out.flush();
    }

    pub(super) fn finish(&mut self) {
        if self.shown {
            let _ = write!(self.out, "\r\x1b[2K");
            let _ = self.out.flush();
        }
    }
}
