//! `compare`: an FE code's results against the closed forms, with a verdict.

use super::*;
use crate::fe::kinematics::Kinematics;
use crate::fe::stick_slope::{self, Friction, StickSlopeUsed};
use crate::report::compare::run as compare_run;
use crate::report::compare::stick_slope::RunEvidence;

/// What `compare` is told about a CSV result's contact: its interface profile and kinematics (a
/// `.dat` says both itself, through its `.frd` and its deck).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct ContactArgs<'a> {
    /// The interface profile (`--interface`).
    pub(super) interface: Option<&'a std::path::Path>,
    /// The kinematics (`--kinematics`).
    pub(super) kinematics: Option<Kinematics>,
}

/// `microslip compare MODEL RESULT...`: the FE results of the problem `model` against its
/// closed forms, written once for every problem through its deck and compare faces.
pub(super) fn run_compare(
    out: &mut impl Write,
    model: ModelKind,
    results: &[PathBuf],
    deck: Option<&std::path::Path>,
    inputs: &InputArgs,
    contact: ContactArgs<'_>,
    format: CompareFormat,
) -> Result<(), CliError> {
    if contact.interface.is_some() && results.len() > 1 {
        return Err(CliError::Flag {
            flag: "--interface",
            value: results.len() as f64,
            allowed: "--interface names the interface profile of one CSV result; give one result"
                .to_string(),
        });
    }
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
        contact,
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
    contact: ContactArgs<'a>,
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
            contact,
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
        let mut evidence = Vec::with_capacity(results.len());
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
            say_the_estimate::<P>(&model, &loaded);
            let mut compared = P::compare(&model, &loaded.points, loaded.interface_mesh.as_ref());
            let run = run_evidence::<P>(path, deck, &loaded, &model, contact)?;
            compare_run::judged_for::<P>(&run, &model, &mut compared);
            evidence.push(run);
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
        let mut compared =
            compare_run::ContactCompared::<P>::new(source, (first, checked.collect()), &evidence);
        let rows = std::mem::take(&mut compared.rows);
        write_comparison(
            out,
            format,
            &compared.text(),
            &compared.with_contact(),
            rows.into_iter(),
        )?;
        // A script (an FE code's CI) reads the verdict from the exit code: 0 only when it agrees.
        let summary = P::summary_mut(&mut compared.report);
        if summary.agrees {
            Ok(())
        } else {
            Err(CliError::Disagrees(summary.short.clone()))
        }
    }
}

/// What the result at `path` says about its contact: the stick slope its `.frd` (CalculiX) or
/// its `--interface` profile (CSV) shows, against the K_T of `model`, and its kinematics.
fn run_evidence<P: Faces>(
    path: &std::path::Path,
    deck: Option<&std::path::Path>,
    loaded: &fe::load::Loaded<P::FePoint>,
    model: &P::Model,
    contact: ContactArgs<'_>,
) -> Result<RunEvidence, CliError> {
    let interface_data = P::interface(model);
    let (kinematics, stick_slope, peak_pressure) = match (&loaded.header, contact) {
        (
            Some(_),
            ContactArgs {
                interface: Some(_), ..
            },
        ) => {
            return Err(CliError::Usage(
                "--interface is for CSV results: a .dat's stick slope is read from the run's .frd",
            ));
        }
        (
            Some(header),
            ContactArgs {
                kinematics: said, ..
            },
        ) => {
            let read = fe::load::ccx_contact(path, deck, header).map_err(|e| CliError::Data {
                path: e.path,
                reason: e.reason,
            })?;
            if let Some(said) = said.filter(|k| *k != read.kinematics) {
                eprintln!(
                    "microslip: note: --kinematics {} not used: the deck says {}",
                    said.label(),
                    read.kinematics.words()
                );
            }
            (read.kinematics, Some(read.stick_slope), read.peak_pressure)
        }
        (
            None,
            ContactArgs {
                interface,
                kinematics,
            },
        ) => {
            let stick_slope = interface
                .map(|file| csv_stick_slope(file, &interface_data))
                .transpose()?;
            (
                kinematics.unwrap_or(Kinematics::NotStated),
                stick_slope.map(Ok),
                None,
            )
        }
    };
    Ok(compare_run::run_evidence(
        path,
        loaded.header.as_ref(),
        &interface_data,
        kinematics,
        stick_slope,
        peak_pressure,
    ))
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

/// The stick slope of the interface profile `file` (CSV) against the model's K_T, with its mu and
/// nominal pressure.
fn csv_stick_slope(
    file: &std::path::Path,
    interface: &crate::problems::inputs::InterfaceData,
) -> Result<StickSlopeUsed, CliError> {
    let fail = |reason: String| CliError::Data {
        path: file.display().to_string(),
        reason,
    };
    let text = crate::file::read_capped(
        file,
        fe::load::MAX_RESULT_SIZE,
        "an interface profile",
        crate::file::Kinds::RegularOnly,
    )
    .map_err(|e| fail(e.to_string()))?;
    let steps = stick_slope::read_interface_csv(&text).map_err(|e| fail(e.to_string()))?;
    let friction = Friction {
        coefficient: interface.friction,
        nominal_pressure: interface.pressure,
    };
    Ok(StickSlopeUsed::measure(
        &steps,
        friction,
        interface.stiffness,
    ))
}

/// A comparison that will take more than a few seconds says so on stderr first, with its
/// estimate (issue 47 item 2: a cylinder row is a solve, and a CSV of a million rows is
/// accepted): the first 64 points are compared alone and timed (an over-estimate, by about 2 on
/// the cylinder, whose later rows start from their neighbours' solutions); not `eprintln!`, which
/// panics when stderr is gone.
fn say_the_estimate<P: Faces>(model: &P::Model, loaded: &fe::load::Loaded<P::FePoint>) {
    const PROBE: usize = 64;
    const WORTH_SAYING: f64 = 3.0;
    let points = &loaded.points;
    if points.len() <= 4 * PROBE {
        return;
    }
    let started = std::time::Instant::now();
    let _ = P::compare(model, &points[..PROBE], None);
    let per_point = started.elapsed().as_secs_f64() / PROBE as f64;
    let total = per_point * points.len() as f64;
    if total > WORTH_SAYING {
        let _ = writeln!(
            std::io::stderr(),
            "microslip: comparing {} points at about {:.3} ms a point: about {} (Ctrl-C stops)",
            points.len(),
            per_point * 1e3,
            super::sweep::duration_words(total)
        );
    }
}
