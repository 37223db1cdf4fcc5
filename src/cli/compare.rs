//! `compare`: an FE code's results against the closed forms, with a verdict.

use super::*;

/// `microslip compare MODEL RESULT...`: the FE results of the problem `model` against its
/// closed forms, written once for every problem through its deck and compare faces.
pub(super) fn run_compare(
    out: &mut impl Write,
    model: ModelKind,
    results: &[PathBuf],
    deck: Option<&std::path::Path>,
    inputs: &InputArgs,
    format: CompareFormat,
) -> Result<(), CliError> {
    if deck.is_some() && results.len() > 1 {
        return Err(CliError::Flag {
            flag: "--deck",
            value: results.len() as f64,
            allowed: "--deck names the deck of one result file; give one result".to_string(),
        });
    }
    let source: Vec<String> = results.iter().map(|p| p.display().to_string()).collect();
    let compare = Compare {
        out,
        results,
        deck,
        inputs,
        format,
        source: &source.join(", "),
    };
    for_problem(model, compare)
}

/// The arguments of [`run_compare`], for [`for_problem`].
struct Compare<'a, W> {
    out: &'a mut W,
    results: &'a [PathBuf],
    deck: Option<&'a std::path::Path>,
    inputs: &'a InputArgs,
    format: CompareFormat,
    /// The result files, as the report names them.
    source: &'a str,
}

impl<W: Write> ForProblem for Compare<'_, W> {
    type Output = Result<(), CliError>;

    fn run<P: Faces>(self) -> Result<(), CliError> {
        let Compare {
            out,
            results,
            deck,
            inputs,
            format,
            source,
        } = self;
        if let Some(why) = P::ONE_RUN
            && results.len() != 1
        {
            return Err(CliError::Flag {
                flag: "RESULT",
                value: results.len() as f64,
                allowed: why.to_string(),
            });
        }
        let data_error = |e: LoadError| CliError::Data {
            path: e.path,
            reason: e.reason,
        };
        let command = model_command(P::KIND, "compare");
        let mut checked = Vec::with_capacity(results.len());
        for path in results {
            let loaded = fe::load::results::<P>(path, deck).map_err(data_error)?;
            if loaded.header.is_some() && checked.is_empty() {
                note_flags_the_deck_overrides(inputs, P::KIND);
            }
            let model = match &loaded.header {
                Some(header) => header.model()?.of::<P>().map_err(deck_of_other_model)?,
                // A CSV has no header: the parameters come from the flags; the FE forces are
                // compared, not the preset's F.
                None => load_problem::<P>(inputs, &command, Load::Unused)?.1,
            };
            let compared = P::compare(&model, &loaded.points, loaded.interface_mesh.as_ref());
            checked.push(P::checked(compared).map_err(|e| CliError::Data {
                path: path.display().to_string(),
                reason: e.to_string(),
            })?);
        }
        let mut checked = checked.into_iter();
        // clap requires a result file.
        let Some(first) = checked.next() else {
            return Err(CliError::Usage("compare needs a result file"));
        };
        let (report, rows) = P::compare_report(source, first, checked.collect());
        write_comparison(
            out,
            format,
            &P::compare_text(&report),
            &report,
            rows.into_iter(),
        )
    }
}

/// A comparison in the format asked for: its text, its report as JSON, or its rows as CSV.
pub(super) fn write_comparison<R: serde::Serialize + Default>(
    out: &mut impl Write,
    format: CompareFormat,
    text: &str,
    report: &impl serde::Serialize,
    rows: impl Iterator<Item = R>,
) -> Result<(), CliError> {
    match format {
        CompareFormat::Text => out.write_all(text.as_bytes())?,
        CompareFormat::Json => write_json(out, &report::point::to_json(report))?,
        CompareFormat::Csv => write_table(out, TableFormat::Csv, rows)?,
    }
    Ok(())
}
