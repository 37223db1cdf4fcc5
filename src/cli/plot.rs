//! `plot`: one chart as SVG, PNG, PDF or CSV, with pins and families.

use super::*;

pub(super) fn run_plot(out: &mut impl Write, args: &PlotArgs) -> Result<(), CliError> {
    let PlotArgs {
        chart,
        inputs,
        fe,
        y,
        pins,
        family,
        series,
        no_cursor,
        format,
        output,
    } = args;
    refuse_overwriting_an_input(output.as_deref(), &inputs.read_files())?;
    // Before any work: a file name that no format has is refused at once.
    let format = FigureFormat::choose(
        *format,
        output.as_deref(),
        "-o/--output",
        &[
            FigureFormat::Svg,
            FigureFormat::Png,
            FigureFormat::Pdf,
            FigureFormat::Csv,
        ],
        FigureFormat::Svg,
    )?;
    let command = format!("plot (a {} chart)", chart.kind());
    let (_, model) = load(inputs, chart.kind(), &command)?;
    let shown = shown_roles(series.as_deref(), *no_cursor)?;
    if let Some(spec) = family {
        if !pins.is_empty() {
            return Err(CliError::Invalid(format!(
                "--family {spec} and --pin: a family has no current curve to pin against; \
                 add the pinned values to the family instead"
            )));
        }
        if *fe {
            return Err(CliError::Invalid(format!(
                "--family {spec} and --fe: finite-element points are of one model; draw \
                 them with one plot per value"
            )));
        }
    }
    let plot = crate::chart::figure(&model, *chart, *fe, YMode::Linear)?;
    // Asked for points the chart has no counterpart of: refused, as a --y the chart cannot show
    // is, rather than drawn without them as if they were there.
    let numeric = [SeriesRole::FiniteElements, SeriesRole::Continuum];
    if *fe && !plot.series.iter().any(|s| numeric.contains(&s.role)) {
        return Err(CliError::Invalid(format!(
            "--fe: chart {} has no finite-element or discretized points of the project; draw \
             it without --fe",
            chart.key()
        )));
    }
    // The chart's own default falls back to linear where it cannot apply (u(L) = 0 at
    // nu = 0 on a log axis); a mode asked for with --y is refused instead.
    let mode = match y {
        Some(mode) => *mode,
        None => Some(YMode::default_for(*chart))
            .filter(|m| m.applies_to(&plot))
            .unwrap_or(YMode::Linear),
    };
    if !mode.applies_to(&plot) {
        return Err(CliError::Invalid(format!(
            "--y {}: chart {} cannot show it (log needs values > 0, none negative; relative needs a Coulomb curve over increasing x, nowhere zero past its start)",
            mode.label(),
            chart.key()
        )));
    }
    let plot = match family {
        Some(spec) => {
            let (param, members) = family_models(&model, spec)?;
            crate::chart::family::build_family(
                *chart,
                param,
                &members,
                mode,
                shown.as_deref().unwrap_or_default(),
            )
            .map_err(|e| CliError::Invalid(format!("--family {spec}: {e}")))?
        }
        None => {
            let mut plot = mode.apply(plot);
            if let Some(roles) = &shown {
                keep_roles(&mut plot, roles, chart.key())?;
            }
            if *no_cursor {
                plot.series.retain(|s| s.role != SeriesRole::Cursor);
            }
            let pinned = pinned_models(&model, pins)?;
            let plot = crate::chart::pins::with_pinned_models(plot, &model, *chart, &pinned, mode);
            // A figure names each curve by its own values (the terminal's `mu 0.2->0.3`
            // reads as a change on paper); CSV keeps its series names.
            let own: Vec<(u8, crate::Inputs)> =
                (1u8..).zip(pinned.iter().map(|m| m.inputs())).collect();
            let mut plot = match format.figure() {
                Some(_) => crate::chart::pins::named_by_values(plot, &model.inputs(), &own),
                None => plot,
            };
            plot.caption = Some(crate::chart::family::parameter_text(
                &model.inputs(),
                &[chart.x_param()],
            ));
            plot
        }
    };
    let bytes = match format.figure() {
        Some(figure_format) => figure::render(&plot, figure_format)?,
        None => chart_csv(&plot)?,
    };
    write_output(out, output.as_deref(), &bytes)?;
    Ok(())
}
