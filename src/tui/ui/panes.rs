//! The parameter list, the regime summary and the status line.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};

use crate::report::sanitize;
use crate::tui::app::{App, Mode};
use crate::tui::summary::wrap_words;
use crate::tui::theme::Role;
use crate::tui::ui::strip::{self, StripSize};

/// A bordered pane with a title.
pub fn pane<'a>(app: &App, title: &'a str) -> Block<'a> {
    let theme = app.theme();
    Block::default()
        .borders(Borders::ALL)
        .border_set(theme.border_set())
        .title(Span::styled(format!(" {title} "), theme.style(Role::Title)))
}

/// Every input of the active model with its unit; the selected row is marked by `>` as well as by
/// colour, so it shows without colour too. While typing, the row shows the text being typed.
pub fn draw_parameters(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let view = app.view();
    let lines: Vec<Line> = view
        .rows
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let selected = i == app.selected();
            let shown = match app.mode() {
                // What is typed, invisible characters escaped (a zero-width space shows).
                Mode::Editing { input } if selected => sanitize(&input.shown()).into_owned(),
                _ => row.value.clone(),
            };
            // `*`: edited, differs from the loaded preset (shown without colour too).
            let text = format!(
                "{}{}{:<3} {:>11} {:<7}",
                if selected { ">" } else { " " },
                if row.edited { "*" } else { " " },
                row.name,
                shown,
                row.unit
            );
            let style = if selected {
                theme.style(Role::Selected)
            } else {
                ratatui::style::Style::default()
            };
            Line::from(Span::styled(text, style))
        })
        .collect();
    frame.render_widget(
        Paragraph::new(lines).block(pane(app, &view.parameters_title)),
        area,
    );
}

/// The regime of each law and the numbers that define it, as plain text (readable without colour).
/// Where the pane has room for twice its lines (tall screens), each line is followed by what it
/// means.
pub fn draw_summary(frame: &mut Frame, app: &App, area: Rect) {
    let theme = app.theme();
    let Some(regime) = &app.view().regime else {
        let lines = vec![Line::from(" invalid parameters")];
        frame.render_widget(Paragraph::new(lines).block(pane(app, "Regime")), area);
        return;
    };
    let summary = &regime.lines;
    // The beams' and the lap joint's pane are full at 80x24: their envelope goes in the title,
    // which `i` explains first.
    let title_line = &regime.title_line;
    let title = |hidden: usize| {
        // `i` reaches the lines the pane leaves out: it says how many.
        let key = match hidden {
            0 => "i".to_string(),
            n => format!("i +{n}"),
        };
        title_line.as_ref().map_or_else(
            || match hidden {
                0 => "Regime (i explains)".to_string(),
                n => format!("Regime (i explains, +{n})"),
            },
            |t| format!("Regime ({key}), {}", t.text),
        )
    };
    let inner = pane(app, &title(0)).inner(area);
    let height = usize::from(inner.height);
    let width = usize::from(inner.width.saturating_sub(3)).max(10);
    let explained: usize = summary
        .iter()
        .map(|l| 1 + l.meaning.len().div_ceil(width))
        .sum();
    // Meanings under the lines with a strip that names the boundaries, where both fit; else the
    // largest strip the lines leave room for; at the smallest, the strip takes its rows from the
    // least needed lines instead (see `SummaryLine::drop_rank`).
    let fits = |rows: usize, size: StripSize| rows + size.rows() <= height;
    let (room, size) = [StripSize::WithShear, StripSize::Marked]
        .into_iter()
        .find(|&s| fits(explained, s))
        .map(|s| (true, s))
        .or_else(|| {
            StripSize::LARGEST_FIRST
                .into_iter()
                .find(|&s| fits(summary.len(), s))
                .map(|s| (false, s))
        })
        .unwrap_or((false, StripSize::Compact));
    let mut keep = vec![true; summary.len()];
    let mut ranks: Vec<(u8, usize)> = summary
        .iter()
        .enumerate()
        .filter(|(_, l)| l.drop_rank > 0)
        .map(|(i, l)| (l.drop_rank, i))
        .collect();
    ranks.sort();
    for (_, i) in ranks {
        if fits(keep.iter().filter(|&&k| k).count(), size) {
            break;
        }
        keep[i] = false;
    }
    // `i` counts the title first where it states an envelope.
    let highlighted = match app.mode() {
        Mode::Explain { line } => line.checked_sub(usize::from(title_line.is_some())),
        _ => None,
    };
    // Every line reachable on the smallest screen: while `i` walks the lines, a line the pane
    // left out (or cut at its bottom) is shown in a window of consecutive lines that ends on it.
    let rows = height.saturating_sub(size.rows());
    if let Some(h) = highlighted.filter(|&h| h < summary.len()) {
        let shown_before = keep[..h].iter().filter(|&&k| k).count();
        if !room && (!keep[h] || shown_before >= rows) {
            let start = (h + 1).saturating_sub(rows.max(1));
            for (i, k) in keep.iter_mut().enumerate() {
                *k = (start..start + rows).contains(&i);
            }
        }
    }
    // The lines out of sight: those left out, and those below the pane's last text row.
    let hidden = if room {
        0
    } else {
        summary.len() - keep.iter().filter(|&&k| k).count().min(rows)
    };
    // The count only where the title keeps its envelope whole (the beams' has no room for it).
    let counted = title(hidden);
    let title = if counted.chars().count() + 4 <= usize::from(area.width) {
        counted
    } else {
        title(0)
    };
    let mut block = pane(app, &title);
    if size == StripSize::Compact {
        // The compact strip has no legend row: its symbols are explained on the pane's border.
        block = block.title_bottom(strip::legend_of(&regime.strip, &theme));
    }
    frame.render_widget(block, area);
    let mut lines = Vec::new();
    for (i, line) in summary.iter().enumerate().filter(|(i, _)| keep[*i]) {
        let style = if highlighted == Some(i) {
            theme.style(Role::Selected)
        } else {
            Style::default()
        };
        let mut spans = vec![Span::styled(format!(" {}", line.text), style)];
        if let Some(regime) = &line.regime {
            spans.push(Span::styled(regime.clone(), theme.style(Role::Regime)));
        }
        lines.push(Line::from(spans));
        if room {
            for chunk in wrap_words(&line.meaning, width) {
                lines.push(Line::from(Span::styled(
                    format!("   {chunk}"),
                    theme.style(Role::Muted),
                )));
            }
        }
    }
    // Under the text, or at the bottom where the text is cut.
    let text_rows = lines.len().min(height.saturating_sub(size.rows()));
    lines.truncate(text_rows);
    lines.extend(strip::lines(&regime.strip, &theme, inner.width, size));
    frame.render_widget(Paragraph::new(lines), inner);
}

/// Model, preset (with `*` when modified), the last message, the command line or the typing
/// prompt, and the two keys everyone needs. A message too long for one row takes more rows (the
/// layout gives them, out of the panes above: see [`status_rows`]), wrapped at spaces; one longer
/// than [`STATUS_MAX_LINES`] rows ends in `... M reads all`.
pub fn draw_status(frame: &mut Frame, app: &App, area: Rect) {
    let line = status_line(app);
    let lines = wrap(
        &line,
        usize::from(area.width),
        usize::from(area.height.max(1)),
    );
    frame.render_widget(Paragraph::new(lines), area);
}

/// The rows the status needs at this terminal size: one, or as many as its message takes when
/// wrapped, up to [`STATUS_MAX_LINES`] (3 on a terminal of fewer than 30 rows, where the panes
/// need every row).
pub fn status_rows(app: &App, width: u16, height: u16) -> u16 {
    let most = if height < 30 {
        STATUS_MAX_LINES - 1
    } else {
        STATUS_MAX_LINES
    };
    let line = status_line(app);
    if line.width() <= usize::from(width) {
        return 1;
    }
    wrap(&line, usize::from(width), most).len() as u16
}

/// The status as one line, before wrapping.
fn status_line(app: &App) -> Line<'static> {
    let theme = app.theme();
    let view = app.view();
    let marker = if view.modified { "*" } else { "" };
    let mut spans = vec![Span::styled(
        format!(" {} | {}{marker} ", view.kind, sanitize(&view.preset)),
        theme.style(Role::Title),
    )];
    match (app.mode(), app.message()) {
        (Mode::Command { input }, message) => {
            spans.push(Span::raw(format!(":{}", sanitize(&input.shown()))));
            let hint = match message {
                Some(message) => Span::styled(
                    format!("  {}", sanitize(&message.text)),
                    theme.style(if message.is_error {
                        Role::Error
                    } else {
                        Role::Info
                    }),
                ),
                None => Span::styled(
                    "  KEY=VALUE ... | preset NAME | save NAME | export | drop | help | q; Tab \
                     completes, Enter runs, Esc cancels",
                    theme.style(Role::Muted),
                ),
            };
            spans.push(hint);
        }
        (Mode::Editing { .. }, None) => {
            let prompt = view
                .rows
                .get(app.selected())
                .map_or("", |r| r.prompt.as_str());
            spans.push(Span::raw(format!(
                "| {prompt}: type a value (replaces), Enter accept, Esc cancel"
            )));
        }
        (_, Some(message)) => {
            let role = if message.is_error {
                Role::Error
            } else {
                Role::Info
            };
            // Messages quote paths, names and values users typed or files hold.
            spans.push(Span::styled(
                format!("| {}", sanitize(&message.text)),
                theme.style(role),
            ));
        }
        _ => spans.push(Span::styled("| ? help  q quit", theme.style(Role::Muted))),
    }
    Line::from(spans)
}

/// Most lines the status may take (the status row and the rows above it).
pub const STATUS_MAX_LINES: usize = 4;

/// What ends a status cut short.
const CUT: &str = "... M reads all";

/// `line` wrapped to `width` columns at spaces (a word longer than a line is broken), keeping each
/// character's style; at most `max_lines` lines, the last ending in `...` when text was left out.
fn wrap(line: &Line, width: usize, max_lines: usize) -> Vec<Line<'static>> {
    let width = width.max(4);
    let cells: Vec<(String, Style)> = line
        .spans
        .iter()
        .flat_map(|span| {
            let style = line.style.patch(span.style);
            span.content.chars().map(move |c| (c.to_string(), style))
        })
        .collect();
    let cell_width = |cell: &(String, Style)| Span::raw(cell.0.as_str()).width();
    // Greedy: words (runs of non-spaces, with the spaces before them) go on the current row while
    // they fit.
    let mut rows: Vec<Vec<(String, Style)>> = vec![Vec::new()];
    let mut used = 0;
    let mut i = 0;
    while i < cells.len() {
        let start = i;
        while i < cells.len() && cells[i].0 == " " {
            i += 1;
        }
        while i < cells.len() && cells[i].0 != " " {
            i += 1;
        }
        let word = &cells[start..i];
        let word_width: usize = word.iter().map(cell_width).sum();
        if used > 0 && used + word_width > width {
            rows.push(Vec::new());
            used = 0;
        }
        // A row made by wrapping does not start with the spaces between words.
        let skip = if used == 0 && rows.len() > 1 {
            word.iter().take_while(|c| c.0 == " ").count()
        } else {
            0
        };
        for cell in &word[skip..] {
            let w = cell_width(cell);
            if used + w > width {
                rows.push(Vec::new());
                used = 0;
            }
            if let Some(row) = rows.last_mut() {
                row.push(cell.clone());
            }
            used += w;
        }
    }
    if rows.len() > max_lines {
        rows.truncate(max_lines);
        if let Some(last) = rows.last_mut() {
            let style = last.last().map_or_else(Style::default, |c| c.1);
            let cut = if width > CUT.len() + 8 { CUT } else { "..." };
            while !last.is_empty() && last.iter().map(cell_width).sum::<usize>() + cut.len() > width
            {
                last.pop();
            }
            last.extend(cut.chars().map(|c| (c.to_string(), style)));
        }
    }
    rows.into_iter()
        .map(|row| {
            Line::from(
                row.into_iter()
                    .map(|(text, style)| Span::styled(text, style))
                    .collect::<Vec<_>>(),
            )
        })
        .collect()
}
