//! Charts. In colour with Unicode, ratatui's Chart draws Braille curves told apart by colour. Without
//! colour or with ASCII, curves must be told apart by their symbols: each series is then rendered
//! alone into a scratch buffer with one dot per cell, and its dots are copied into the frame with the
//! symbol of its role (`*` Coulomb, `x` the current K_T, `o` softer, `+` stiffer, ...; see
//! [`Theme::series_symbol`]). The legend line above the chart works in both modes.
//!
//! Where curves share a cell (on w(L) vs F at 80x24, Coulomb, K_T and K_T x 5 are one row of cells
//! everywhere), one symbol on top would hide the others; the cell instead shows the symbols of the
//! curves in it in turn along the line (`*x+*x+`), so that every curve is seen and the shared
//! stretch reads as shared (Coulomb's plateau on the `mu P` line reads `*-x*-x`). Layers still
//! rank above that: the cursor under everything, points on top. In colour, where Braille dots
//! cannot take turns, limit lines are drawn first so that Coulomb's colour shows on them.

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::{self, Marker};
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine, Points};
use ratatui::widgets::{Axis, Chart, Dataset, GraphType, Paragraph, Widget};

use super::panes::pane;
use crate::chart::{self as plots, Plot, PlotSeries, SeriesKind, SeriesRole, pins};
use crate::tui::app::App;
use crate::tui::theme::{Role, Theme};

/// The chart pane: title, legend, plot.
pub fn draw(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let shown = &app.view().chart;
    let plot = &shown.plot;
    let mut block = pane(app, &shown.title);
    if shown.table.is_none() {
        // The x axis's title on the pane's lower border, not on the chart's bottom row, where it
        // would hide a curve lying along y = 0 (u(L) under Coulomb on the plate's K_T axis).
        block = block.title_bottom(Line::from(format!(" {} ", plot.x.title)).right_aligned());
    }
    let inner = block.inner(area);
    frame.render_widget(block, area);
    if let Some((table_title, table)) = &shown.table {
        let mut lines = vec![Line::from(format!(" {table_title}")), Line::from("")];
        lines.extend(table.iter().map(|l| Line::from(format!(" {l}"))));
        frame.render_widget(Paragraph::new(lines), inner);
        return;
    }
    // Spaced out where one line holds it, compact otherwise; pins may need more lines.
    let width = usize::from(inner.width);
    let mut legend = legend_lines(plot, &theme, false, width);
    if legend.len() > 1 {
        legend = legend_lines(plot, &theme, true, width);
    }
    let legend_rows = legend.len().clamp(1, MAX_LEGEND_ROWS) as u16;
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
    frame.render_widget(Paragraph::new(legend), legend_area);
    if theme.symbol_mode() {
        draw_with_symbols(frame.buffer_mut(), plot, &theme, body);
    } else {
        let labels = pin_label_points(plot);
        chart(plot, &theme, colour_datasets(plot, &theme, &labels), body)
            .render(body, frame.buffer_mut());
        if !labels.is_empty() {
            label_pins(frame.buffer_mut(), &theme, body);
        }
    }
    place_x_ticks(frame.buffer_mut(), plot, &theme, body);
}

/// The x tick labels between the two ends, each centred on the column of its own value.
///
/// ratatui's Chart lays middle labels out in equal slots of `width / labels` cells, which drifts
/// from their values as the chart widens (at 200 columns "60" sat where F is 73 N); so the chart
/// gets only the end labels (which it aligns to the axis ends, correctly) and these are written
/// here. Column `c` of the graph area holds the values `[c, c + 1) * span / width` (as ratatui's
/// canvas maps them); a label of `n` cells starts at `round(p - n / 2)`, so its centre is within half
/// a cell of its value's position `p`. A label that would touch another is left out.
fn place_x_ticks(buffer: &mut Buffer, plot: &Plot, theme: &Theme, area: Rect) {
    let Some(graph) = graph_area(buffer, area) else {
        return;
    };
    let row = graph.bottom() + 1;
    if row >= area.bottom() {
        return;
    }
    let ticks = plot.x.ticks(tick_count(area.width, 40));
    let last = ticks.len().saturating_sub(1);
    let style = theme.style(Role::Muted);
    for (i, label) in ticks.iter().enumerate().take(last).skip(1) {
        let cells = Span::raw(label.as_str()).width() as f64;
        let position = f64::from(graph.left()) + f64::from(graph.width) * i as f64 / last as f64;
        let start = (position - cells / 2.0).round();
        let end = start + cells;
        // One blank cell either side, inside the chart's area.
        if start < f64::from(area.left()) + 1.0 || end > f64::from(area.right()) - 1.0 {
            continue;
        }
        let (start, end) = (start as u16, end as u16);
        if (start - 1..=end).all(|x| buffer[(x, row)].symbol() == " ") {
            buffer.set_string(start, row, label, style);
        }
    }
}

/// Rows the legend may take (four pins and five curves on an 80-column screen need three).
const MAX_LEGEND_ROWS: usize = 3;

/// The legend: each curve's symbol (or a coloured bar) and name, then each pin's number and label,
/// then the cursor; packed into lines of `width` without splitting an entry. `compact` (for narrow
/// panes) drops the spaces between marks and names, so that the legend of an 80-column screen fits
/// on one line.
fn legend_lines<'a>(plot: &'a Plot, theme: &Theme, compact: bool, width: usize) -> Vec<Line<'a>> {
    let (gap, after) = if compact { ("", " ") } else { (" ", "  ") };
    let mut entries: Vec<Vec<Span>> = Vec::new();
    for series in plot
        .series
        .iter()
        .filter(|s| !matches!(s.kind(), SeriesKind::Cursor | SeriesKind::Pin(_)))
    {
        let mark = if theme.symbol_mode() {
            theme.series_symbol(series.role).to_string()
        } else {
            "--".to_string()
        };
        entries.push(vec![
            Span::styled(mark, theme.series_style(series.role)),
            Span::raw(format!("{gap}{}{after}", series.name)),
        ]);
    }
    for series in &plot.series {
        if let SeriesKind::Pin(_) = series.kind() {
            entries.push(vec![
                Span::styled(
                    theme.series_symbol(series.role),
                    theme.series_style(series.role),
                ),
                Span::raw(format!(" {}{after}", pins::label_of(&series.name))),
            ]);
        }
    }
    if plot.series.iter().any(|s| s.kind() == SeriesKind::Cursor) {
        entries.push(vec![Span::styled(
            format!("{} current", theme.cursor_symbol()),
            theme.style(Role::Cursor),
        )]);
    }
    let mut lines: Vec<Vec<Span>> = vec![vec![Span::raw(" ")]];
    let mut used = 1;
    for entry in entries {
        let size: usize = entry.iter().map(Span::width).sum();
        if used > 1 && used + size > width {
            lines.push(vec![Span::raw(" ")]);
            used = 1;
        }
        used += size;
        if let Some(line) = lines.last_mut() {
            line.extend(entry);
        }
    }
    lines.into_iter().map(Line::from).collect()
}

/// The series in drawing order: by layer ([`SeriesRole::layer`]: cursor, limit lines, curves,
/// points), pins first among the curves so that the live curves are drawn over them, the plot's
/// order otherwise.
fn drawing_order(plot: &Plot) -> Vec<(usize, &PlotSeries)> {
    let mut order: Vec<(usize, &PlotSeries)> = plot.series.iter().enumerate().collect();
    order.sort_by_key(|(_, s)| (s.role.layer(), !matches!(s.kind(), SeriesKind::Pin(_))));
    order
}

/// Braille datasets told apart by colour (the cursor in the muted style, points as blocks) in
/// [`drawing_order`], and last the places where each pin carries its number, as dots tagged with
/// `Color::Indexed(n)` for [`label_pins`] to replace (the series' own colours are named colours,
/// never indexed ones).
fn colour_datasets<'a>(
    plot: &'a Plot,
    theme: &Theme,
    labels: &'a [(u8, Vec<(f64, f64)>)],
) -> Vec<Dataset<'a>> {
    let curves = drawing_order(plot).into_iter().map(|(_, s)| {
        let (graph, style, marker) = match s.kind() {
            SeriesKind::Points => (
                GraphType::Scatter,
                theme.series_style(s.role),
                Marker::Block,
            ),
            SeriesKind::Cursor => (GraphType::Line, theme.style(Role::Cursor), Marker::Braille),
            SeriesKind::Line | SeriesKind::Pin(_) => {
                (GraphType::Line, theme.series_style(s.role), Marker::Braille)
            }
        };
        Dataset::default()
            .marker(marker)
            .graph_type(graph)
            .style(style)
            .data(&s.points)
    });
    let tags = labels.iter().map(|(n, points)| {
        Dataset::default()
            .marker(Marker::Dot)
            .graph_type(GraphType::Scatter)
            .style(Style::default().fg(Color::Indexed(*n)))
            .data(points)
    });
    curves.chain(tags).collect()
}

/// Where along the x range pin `n` carries its number in colour mode: two places, shifted per
/// pin so that the numbers of close curves do not land on one another.
fn label_fractions(n: u8) -> [f64; 2] {
    let shift = 0.07 * f64::from(n.saturating_sub(1));
    [0.3 + shift, 0.62 + shift]
}

/// The points of each pinned curve that carry its number in colour mode.
fn pin_label_points(plot: &Plot) -> Vec<(u8, Vec<(f64, f64)>)> {
    let [x0, x1] = plot.x.bounds;
    plot.series
        .iter()
        .filter_map(|s| match s.kind() {
            SeriesKind::Pin(n) if !s.points.is_empty() => {
                let nearest = |f: f64| {
                    let x = x0 + f * (x1 - x0);
                    s.points
                        .iter()
                        .copied()
                        .min_by(|a, b| (a.0 - x).abs().total_cmp(&(b.0 - x).abs()))
                };
                Some((
                    n,
                    label_fractions(n).into_iter().filter_map(nearest).collect(),
                ))
            }
            _ => None,
        })
        .collect()
}

/// Colour mode: each pinned curve (a Braille line in its colour) carries its number where
/// [`colour_datasets`] left a tagged dot, so that it is named on the chart as in the legend.
fn label_pins(buffer: &mut Buffer, theme: &Theme, area: Rect) {
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            let cell = &mut buffer[(x, y)];
            let Color::Indexed(n) = cell.fg else { continue };
            if cell.symbol() != symbols::DOT {
                continue;
            }
            let role = SeriesRole::Pin(n);
            let style = theme.series_style(role);
            cell.set_symbol(theme.series_symbol(role))
                .set_style(style.fg(style.fg.unwrap_or(Color::Reset)));
        }
    }
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
    let axis = |a: &'a plots::Axis, count: usize, titled: bool, ends_only: bool| {
        let mut labels = a.ticks(count);
        if ends_only && labels.len() > 2 {
            // The middle ones are placed by [`place_x_ticks`].
            labels.drain(1..labels.len() - 1);
        }
        Axis::default()
            .title(if titled { a.title.as_str() } else { "" })
            .bounds(a.bounds)
            .labels(labels.into_iter().map(Line::from).collect::<Vec<_>>())
            .style(theme.style(Role::Muted))
    };
    Chart::new(datasets)
        .x_axis(axis(&plot.x, tick_count(area.width, 40), false, true))
        .y_axis(axis(&plot.y, tick_count(area.height, 16), true, false))
        .legend_position(None)
}

/// Symbol mode: the axes, then each series rendered alone into a scratch buffer with one dot per
/// cell; each cell of the frame then shows a symbol of the highest layer present there (cursor,
/// lines, points), and where several series of that layer share it, each of them in turn along
/// the line (the `(x + y)`-th of them), so that a curve under another still shows.
fn draw_with_symbols(buffer: &mut Buffer, plot: &Plot, theme: &Theme, area: Rect) {
    chart(plot, theme, Vec::new(), area).render(area, buffer);
    // Where the chart put its axes' corner: the graph area is right of the y axis and above the
    // x axis (ratatui's layout). Each series is then painted alone on a canvas of that area, as
    // the chart itself paints its datasets, without laying the axes out again for every series.
    let Some(graph) = graph_area(buffer, area) else {
        return;
    };
    let width = usize::from(graph.width);
    // The series in each cell, in drawing order.
    let mut cells: Vec<Vec<&PlotSeries>> = vec![Vec::new(); width * usize::from(graph.height)];
    let tag = Color::Indexed(1);
    let mut scratch = Buffer::empty(graph);
    for (_, series) in drawing_order(plot) {
        let line = series.kind() != SeriesKind::Points;
        scratch.reset();
        Canvas::default()
            .x_bounds(plot.x.bounds)
            .y_bounds(plot.y.bounds)
            .marker(Marker::Dot)
            .paint(|ctx| {
                ctx.draw(&Points {
                    coords: &series.points,
                    color: tag,
                });
                if line {
                    for pair in series.points.windows(2) {
                        ctx.draw(&CanvasLine {
                            x1: pair[0].0,
                            y1: pair[0].1,
                            x2: pair[1].0,
                            y2: pair[1].1,
                            color: tag,
                        });
                    }
                }
            })
            .render(graph, &mut scratch);
        for y in graph.top()..graph.bottom() {
            for x in graph.left()..graph.right() {
                let cell = &scratch[(x, y)];
                if cell.symbol() == symbols::DOT && cell.fg == tag {
                    let at = usize::from(y - graph.top()) * width + usize::from(x - graph.left());
                    cells[at].push(series);
                }
            }
        }
    }
    let title_width = Span::raw(plot.y.title.as_str()).width();
    // Symbols take turns along the line by their cell's place in the chart body.
    let shift = usize::from(graph.left() - area.left());
    let area = graph;
    // Limit lines share the curves' layer here: under Coulomb's plateau (tau(x) past F_thre lies
    // on mu P from end to end) a limit line drawn under would vanish.
    let layer = |s: &PlotSeries| match s.kind() {
        SeriesKind::Cursor => 0,
        SeriesKind::Line | SeriesKind::Pin(_) => 1,
        SeriesKind::Points => 2,
    };
    for (at, here) in cells.iter().enumerate() {
        let Some(top) = here.iter().map(|s| layer(s)).max() else {
            continue;
        };
        let shown: Vec<&&PlotSeries> = here.iter().filter(|s| layer(s) == top).collect();
        let (x, y) = (at % width, at / width);
        let series = shown[(x + shift + y) % shown.len()];
        let style = match series.kind() {
            SeriesKind::Cursor => theme.style(Role::Cursor),
            _ => theme.series_style(series.role),
        };
        let position = (area.left() + x as u16, area.top() + y as u16);
        // The y axis title, which the chart writes over the graph area's first row, stays
        // readable.
        if y == 0 && x < title_width {
            continue;
        }
        buffer[position]
            .set_symbol(theme.series_symbol(series.role))
            .set_style(style.fg(style.fg.unwrap_or(Color::Reset)));
    }
}

/// The graph area of a chart drawn into `area` of `buffer`: right of its y axis, above its x axis,
/// found by the axes' corner; None when the chart had no room for axes.
fn graph_area(buffer: &Buffer, area: Rect) -> Option<Rect> {
    (area.top()..area.bottom())
        .rev()
        .find_map(|y| {
            (area.left()..area.right())
                .find(|&x| buffer[(x, y)].symbol() == symbols::line::BOTTOM_LEFT)
                .map(|x| Rect {
                    x: x + 1,
                    y: area.top(),
                    width: area.right().saturating_sub(x + 1),
                    height: y - area.top(),
                })
        })
        .filter(|graph| graph.width > 0 && graph.height > 0)
}
