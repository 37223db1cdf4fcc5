//! Charts. In colour with Unicode, ratatui's Chart draws Braille curves told apart by colour. Without
//! colour or with ASCII, curves must be told apart by their symbols: each series is then rendered
//! alone into a scratch buffer with one dot per cell, and its dots are copied into the frame with the
//! series' own symbol (`*`, `o`, `+`, ...). The legend line above the chart works in both modes.

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::{self, Marker};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Chart, Dataset, GraphType, Paragraph, Widget, Wrap};

use super::panes::pane;
use crate::report::chart::{self as plots, Plot, PlotSeries, SeriesKind};
use crate::tui::app::App;
use crate::tui::theme::{Role, Theme};

/// The chart pane: title, legend, plot.
pub fn draw(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let plot = app.plot();
    let (name, position, count) = app.views().describe(app.kind());
    let title = match app.varied() {
        Some(param) => format!("vs {param} (v or c: back to {name})"),
        None => format!("{name} ({position}/{count}, c cycles)"),
    };
    let mut block = pane(app, &title);
    if plot.table.is_none() {
        // The x axis's title on the pane's lower border, not on the chart's bottom row, where it
        // would hide a curve lying along y = 0 (u(L) under Coulomb on the plate's K_T axis).
        block = block.title_bottom(Line::from(format!(" {} ", plot.x.title)).right_aligned());
    }
    let inner = block.inner(area);
    frame.render_widget(block, area);
    if let Some(table) = &plot.table {
        let mut lines = vec![Line::from(format!(" {}", plot.title)), Line::from("")];
        lines.extend(table.iter().map(|l| Line::from(format!(" {l}"))));
        frame.render_widget(Paragraph::new(lines), inner);
        return;
    }
    let mut legend = legend_line(plot, &theme, false);
    if legend.width() as u16 > inner.width {
        legend = legend_line(plot, &theme, true);
    }
    let legend_rows = if legend.width() as u16 > inner.width {
        2
    } else {
        1
    };
    let [heading, legend_area, body] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Length(legend_rows),
        Constraint::Min(0),
    ])
    .areas(inner);
    frame.render_widget(
        Paragraph::new(Line::from(format!(" {}", plot.title))),
        heading,
    );
    frame.render_widget(
        Paragraph::new(legend).wrap(Wrap { trim: false }),
        legend_area,
    );
    if theme.symbol_mode() {
        draw_with_symbols(frame.buffer_mut(), plot, &theme, body);
    } else {
        chart(plot, &theme, colour_datasets(plot, &theme), body).render(body, frame.buffer_mut());
    }
}

/// The legend: each curve's symbol (or a coloured bar) and name.
/// The legend; `compact` (for narrow panes) drops the spaces between marks and names, so that the
/// legend of an 80-column screen fits on one line.
fn legend_line<'a>(plot: &'a Plot, theme: &Theme, compact: bool) -> Line<'a> {
    let (gap, after) = if compact { ("", " ") } else { (" ", "  ") };
    let mut spans = vec![Span::raw(" ")];
    for (i, series) in plot
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| s.kind != SeriesKind::Cursor)
    {
        let mark = if theme.symbol_mode() {
            theme.series_symbol(i).to_string()
        } else {
            "--".to_string()
        };
        spans.push(Span::styled(mark, theme.series_style(i)));
        spans.push(Span::raw(format!("{gap}{}{after}", series.name)));
    }
    if plot.series.iter().any(|s| s.kind == SeriesKind::Cursor) {
        spans.push(Span::styled(
            format!("{} current", theme.cursor_symbol()),
            theme.style(Role::Cursor),
        ));
    }
    Line::from(spans)
}

/// Braille datasets told apart by colour (the cursor in the muted style, finite-element points as
/// blocks).
fn colour_datasets<'a>(plot: &'a Plot, theme: &Theme) -> Vec<Dataset<'a>> {
    plot.series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (graph, style, marker) = match s.kind {
                SeriesKind::Line => (GraphType::Line, theme.series_style(i), Marker::Braille),
                SeriesKind::Points => (GraphType::Scatter, theme.series_style(i), Marker::Block),
                SeriesKind::Cursor => (GraphType::Line, theme.style(Role::Cursor), Marker::Braille),
            };
            Dataset::default()
                .marker(marker)
                .graph_type(graph)
                .style(style)
                .data(&s.points)
        })
        .collect()
}

/// Tick labels along an axis `cells` long: three on small charts, five or seven on large ones
/// (at 200x60 the chart is about 150 columns by 50 rows).
fn tick_count(cells: u16, per_tick: u16) -> usize {
    match cells / per_tick {
        0..=2 => 3,
        3..=5 => 5,
        _ => 7,
    }
}

/// A ratatui Chart of `datasets` with the plot's axes (more ticks on larger `area`s) and no
/// built-in legend.
fn chart<'a>(plot: &'a Plot, theme: &Theme, datasets: Vec<Dataset<'a>>, area: Rect) -> Chart<'a> {
    let axis = |a: &'a plots::Axis, count: usize, titled: bool| {
        Axis::default()
            .title(if titled { a.title.as_str() } else { "" })
            .bounds(a.bounds)
            .labels(
                a.ticks(count)
                    .into_iter()
                    .map(Line::from)
                    .collect::<Vec<_>>(),
            )
            .style(theme.style(Role::Muted))
    };
    Chart::new(datasets)
        .x_axis(axis(&plot.x, tick_count(area.width, 40), false))
        .y_axis(axis(&plot.y, tick_count(area.height, 16), true))
        .legend_position(None)
}

/// Symbol mode: one Chart render with one dot per cell, each series tagged by an indexed colour, then
/// one pass that turns each tagged dot into its series' symbol and real style. The cursor is drawn
/// first so that curves stay on top of it.
fn draw_with_symbols(buffer: &mut Buffer, plot: &Plot, theme: &Theme, area: Rect) {
    let mut order: Vec<(usize, &PlotSeries)> = plot.series.iter().enumerate().collect();
    order.sort_by_key(|(_, s)| s.kind != SeriesKind::Cursor);
    let tag = |i: usize| Style::default().fg(Color::Indexed(i as u8));
    let datasets = order
        .iter()
        .map(|&(i, s)| {
            let graph = if s.kind == SeriesKind::Points {
                GraphType::Scatter
            } else {
                GraphType::Line
            };
            Dataset::default()
                .marker(Marker::Dot)
                .graph_type(graph)
                .style(tag(i))
                .data(&s.points)
        })
        .collect();
    chart(plot, theme, datasets, area).render(area, buffer);
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            let cell = &mut buffer[(x, y)];
            if cell.symbol() != symbols::DOT {
                continue;
            }
            let Color::Indexed(i) = cell.fg else { continue };
            let i = usize::from(i);
            let (symbol, style) = match plot.series.get(i).map(|s| s.kind) {
                Some(SeriesKind::Cursor) => (theme.cursor_symbol(), theme.style(Role::Cursor)),
                _ => (theme.series_symbol(i), theme.series_style(i)),
            };
            cell.set_symbol(symbol)
                .set_style(style.fg(style.fg.unwrap_or(Color::Reset)));
        }
    }
}
