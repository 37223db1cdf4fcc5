//! `compare`: an FE code's results against the closed forms, with a verdict.

use super::*;
use crate::problems::lap::LapJointProblem;
use crate::problems::plate::SqueezedPlateProblem;
use crate::problems::twin_beams::TwinBeamsProblem;

pub(super) fn run_compare(
    out: &mut impl Write,
    model: ModelKind,
    results: &[PathBuf],
    deck: Option<&std::path::Path>,
    inputs: &InputArgs,
    format: CompareFormat,
) -> Result<(), CliError> {
    let data_error = |e: LoadError| CliError::Data {
        path: e.path,
        reason: e.reason,
    };
    if deck.is_some() && results.len() > 1 {
        return Err(CliError::Flag {
            flag: "--deck",
            value: results.len() as f64,
            allowed: "--deck names the deck of one result file; give one result".to_string(),
        });
    }
    let source: Vec<String> = results.iter().map(|p| p.display().to_string()).collect();
    let source = source.join(", ");
    match model {
        ModelKind::Lap => {
            let mut rows = Vec::new();
            for path in results {
                let loaded = fe::load::results::<crate::problems::lap::LapJointProblem>(path, deck)
                    .map_err(data_error)?;
                if loaded.header.is_some() && rows.is_empty() {
                    note_flags_the_deck_overrides(inputs, model);
                }
                let joint = match &loaded.header {
                    Some(header) => {
                        header
                            .model()?
                            .of::<LapJointProblem>()
                            .map_err(deck_of_other_model)?
                            .joint
                    }
                    // The FE forces are compared, not the preset's F.
                    None => {
                        load_problem::<LapJointProblem>(inputs, "compare lap", Load::Unused)?
                            .1
                            .joint
                    }
                };
                let compared = crate::problems::lap::deck::compare_lap(
                    &joint,
                    &loaded.points,
                    loaded.interface_mesh.as_ref(),
                )
                .map_err(|e| CliError::Data {
                    path: path.display().to_string(),
                    reason: e.to_string(),
                })?;
                rows.extend(compared);
            }
            let report = report::compare::lap::LapCompareReport::new(&source, &rows);
            let csv = rows.iter().map(report::compare::LapCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
        ModelKind::Beam => {
            let [path] = results else {
                return Err(CliError::Flag {
                    flag: "RESULT",
                    value: results.len() as f64,
                    allowed: "compare beam takes one result file (all load steps of one run)"
                        .to_string(),
                });
            };
            let loaded =
                fe::load::results::<crate::problems::twin_beams::TwinBeamsProblem>(path, deck)
                    .map_err(data_error)?;
            if loaded.header.is_some() {
                note_flags_the_deck_overrides(inputs, model);
            }
            let beams = match &loaded.header {
                Some(header) => {
                    header
                        .model()?
                        .of::<TwinBeamsProblem>()
                        .map_err(deck_of_other_model)?
                        .beams
                }
                // A CSV has no header: the parameters come from the flags.
                None => {
                    load_problem::<TwinBeamsProblem>(inputs, "compare beam", Load::Unused)?
                        .1
                        .beams
                }
            };
            let comparison = crate::problems::twin_beams::deck::compare_beams(
                &beams,
                &loaded.points,
                loaded.interface_mesh.as_ref(),
            );
            let report = report::compare::beam::BeamCompareReport::new(&source, &comparison);
            let csv = comparison
                .rows
                .iter()
                .map(report::compare::BeamCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
        ModelKind::Plate => {
            let mut rows = Vec::new();
            for path in results {
                let loaded =
                    fe::load::results::<crate::problems::plate::SqueezedPlateProblem>(path, deck)
                        .map_err(data_error)?;
                if loaded.header.is_some() && rows.is_empty() {
                    note_flags_the_deck_overrides(inputs, model);
                }
                let plate = match &loaded.header {
                    Some(header) => header
                        .model()?
                        .of::<SqueezedPlateProblem>()
                        .map_err(deck_of_other_model)?,
                    None => {
                        load_problem::<SqueezedPlateProblem>(inputs, "compare plate", Load::Used)?.1
                    }
                };
                rows.extend(crate::problems::plate::deck::compare_plate(
                    &plate,
                    &loaded.points,
                    loaded.interface_mesh.as_ref(),
                ));
            }
            let report = report::compare::plate::PlateCompareReport::new(&source, &rows);
            let csv = rows.iter().map(report::compare::PlateCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
    }
    Ok(())
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
