//! `figures`: every chart drawn as SVG, PNG or PDF.

use super::*;

/// `microslip figures`: every figure of [`figure::PAPER_FIGURES`] in `format` and as CSV, then the
/// index.
pub(super) fn run_figures(
    out: &mut impl Write,
    dir: &std::path::Path,
    fe: bool,
    format: figure::Format,
    inputs: &InputArgs,
) -> Result<(), CliError> {
    let unwritable = |e: io::Error| CliError::Data {
        path: dir.display().to_string(),
        reason: e.to_string(),
    };
    let flags = inputs.flags();
    // Every model is loaded before the folder is made: a bad preset leaves nothing behind.
    let mut figures = Vec::new();
    let intro = if !flags.is_empty() {
        let (name, model) = load_any(inputs, DEFAULT_PROBLEM)?;
        let bench = figure::Bench {
            preset: name,
            values: figure::parameter_caption(&model.inputs()),
            flags: flags.join(" "),
            finite_elements: fe,
        };
        for chart in AnyChart::all().filter(|c| c.kind() == model.kind()) {
            let plot = crate::chart::figure(&model, chart, fe, YMode::Linear).map_err(|e| {
                CliError::Invalid(format!(
                    "the finite-element points of chart {}: {e} (--no-fe draws the figures \
                     without them)",
                    chart.key()
                ))
            })?;
            // Each chart's own default axis, where its data allow it (as `plot` chooses).
            let y = Some(YMode::default_for(chart))
                .filter(|m| m.applies_to(&plot))
                .unwrap_or(YMode::Linear);
            figures.push((y.apply(plot), bench.entry(chart, y)));
        }
        bench.intro()
    } else {
        for f in figure::PAPER_FIGURES.iter() {
            let inputs = InputArgs {
                preset: Some(f.preset.to_string()),
                ..InputArgs::default()
            };
            let (_, model) = load(&inputs, f.chart().kind(), "figures")?;
            let plot = crate::chart::figure(&model, f.chart(), fe && f.finite_elements, f.y)?;
            figures.push((plot, f.entry()));
        }
        figure::PAPER_INTRO.to_string()
    };
    std::fs::create_dir_all(dir).map_err(unwritable)?;
    for (plot, entry) in &figures {
        let file = dir.join(format!("{}.{format}", entry.stem));
        write_output(out, Some(&file), &figure::render(plot, format)?)?;
        write_output(
            out,
            Some(&dir.join(format!("{}.csv", entry.stem))),
            &chart_csv(plot)?,
        )?;
        // The folder is the user's text: control characters are shown escaped, never sent.
        let shown = file.display().to_string();
        writeln!(out, "{}  {}", report::sanitize(&shown), entry.title)?;
    }
    let entries: Vec<figure::IndexEntry> = figures.into_iter().map(|(_, e)| e).collect();
    let index = dir.join("index.html");
    write_output(
        out,
        Some(&index),
        figure::index_html(&intro, &entries, format).as_bytes(),
    )?;
    let shown = index.display().to_string();
    writeln!(out, "{}  open it in a browser", report::sanitize(&shown))?;
    Ok(())
}
