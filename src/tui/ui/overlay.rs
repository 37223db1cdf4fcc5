//! Pop-ups: the help (generated from the key map), the preset picker and the questions.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph};

use super::panes::pane;
use crate::preset::Listed;
use crate::report::sanitize;
use crate::tui::app::App;
use crate::tui::keymap::{BINDINGS, Context, GLOBAL_KEYS, context_title};
use crate::tui::summary::wrap_words;
use crate::tui::theme::Role;

/// A centred rectangle of at most `width` x `height` inside `area`.
fn centred(area: Rect, width: u16, height: u16) -> Rect {
    let [_, row, _] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Length(height.min(area.height)),
        Constraint::Fill(1),
    ])
    .areas(area);
    let [_, cell, _] = Layout::horizontal([
        Constraint::Fill(1),
        Constraint::Length(width.min(area.width)),
        Constraint::Fill(1),
    ])
    .areas(row);
    cell
}

fn help_lines(app: &App, contexts: &[Context]) -> Vec<Line<'static>> {
    let theme = app.theme();
    let mut lines = Vec::new();
    for &context in contexts {
        if !lines.is_empty() {
            lines.push(Line::from(""));
        }
        lines.push(Line::from(Span::styled(
            context_title(context),
            theme.style(Role::Title),
        )));
        for binding in BINDINGS.iter().filter(|b| b.context == context) {
            lines.push(Line::from(format!(
                " {:<13} {}",
                binding.label(),
                binding.description
            )));
        }
    }
    lines
}

/// What the symbols on screen mean, in the theme's own characters (each line fits a column of the
/// 78-column pop-up): the zone strip's, which the compact strip of a small screen explains only on
/// its border, and the chart marks, one per role on every chart.
fn symbol_lines(app: &App) -> Vec<Line<'static>> {
    use crate::chart::SeriesRole as R;
    use crate::tui::view::Zone;
    let theme = app.theme();
    let zone = |z| theme.zone_symbol(z);
    let marks = |roles: &[(R, &str)]| {
        let entries: Vec<String> = roles
            .iter()
            .map(|&(role, name)| format!("{} {name}", theme.series_symbol(role)))
            .collect();
        Line::from(format!("  {}", entries.join(" ")))
    };
    vec![
        Line::from(Span::styled("Symbols", theme.style(Role::Title))),
        Line::from(" Zones (C Coulomb, R regularized):"),
        Line::from(format!(
            "  {} stick {} microslip {} macroslip",
            zone(Zone::Stick),
            zone(Zone::Microslip),
            zone(Zone::Macroslip)
        )),
        Line::from(" Chart marks without colour:"),
        marks(&[
            (R::Coulomb, "Coulomb"),
            (R::Current, "K_T"),
            (R::Softer, "softer"),
            (R::Stiffer, "stiffer"),
        ]),
        marks(&[
            (R::Limit, "limit"),
            (R::FiniteElements, "FE"),
            (R::Continuum, "continuum"),
            (R::Measured, "measured"),
        ]),
        marks(&[
            (R::External, "external"),
            (R::Pin(1), "pin 1"),
            (R::Cursor, "cursor"),
        ]),
        Line::from("  marks in turn: curves share cells"),
    ]
}

/// The key map, straight from the binding table: the contexts one after the other, flowing down two
/// columns, on as many pages as the screen needs (`j`/`k` turn them).
pub fn draw_help(frame: &mut Frame, app: &App, area: Rect) {
    let popup = centred(area, 78, area.height.saturating_sub(2).max(10));
    frame.render_widget(Clear, popup);
    let block = pane(app, "Keys (Esc or ? closes)");
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let mut lines = help_lines(
        app,
        &[
            Context::Main,
            Context::TextEntry,
            Context::Presets,
            Context::Confirm,
            Context::Explain,
        ],
    );
    lines.push(Line::from(""));
    for (key, _, what) in GLOBAL_KEYS {
        lines.push(Line::from(format!(
            " Ctrl-{:<8} {what}",
            key.to_ascii_uppercase()
        )));
    }
    lines.push(Line::from(""));
    lines.extend(COMMAND_HELP.iter().map(|l| Line::from(*l)));
    lines.push(Line::from(""));
    lines.extend(TITLE_HELP.iter().map(|l| Line::from(*l)));
    lines.push(Line::from(""));
    lines.extend(symbol_lines(app));
    let rows = usize::from(inner.height.saturating_sub(1)).max(1);
    let columns: Vec<Vec<Line>> = lines.chunks(rows).map(<[Line]>::to_vec).collect();
    let pages = columns.len().div_ceil(2).max(1);
    let page = app.help_page().min(pages - 1);
    let [body, hint] = Layout::vertical([Constraint::Min(0), Constraint::Length(1)]).areas(inner);
    let [left, right] = Layout::horizontal([Constraint::Fill(1), Constraint::Fill(1)]).areas(body);
    for (i, column) in [left, right].into_iter().enumerate() {
        if let Some(lines) = columns.get(2 * page + i) {
            frame.render_widget(Paragraph::new(lines.clone()), column);
        }
    }
    if pages > 1 {
        frame.render_widget(
            Paragraph::new(Span::styled(
                format!(" page {}/{pages}: j next, k back", page + 1),
                app.theme().style(Role::Muted),
            )),
            hint,
        );
    }
}

/// What the regime pane's title states (for a problem with a continuum envelope), in words: `i`
/// says more.
const TITLE_HELP: [&str; 6] = [
    " Regime title \"FE within 3 %\":",
    "  how far continuum FE is expected",
    "  from the response at this load:",
    "  the theory's envelope (theory.md),",
    "  NL/lin: FE with NLGEOM / linear;",
    "  i explains it first",
];

/// The command line's words and the rule for loaded data, after the keys.
const COMMAND_HELP: [&str; 9] = [
    " Command line (:)",
    " KT=250 mu=0.2  set values (one u)",
    " preset NAME    load a preset",
    " save NAME      save (asks description)",
    " export  drop  help  q",
    " Loaded data (d) stay until D,",
    " until a preset is loaded, and",
    " measurements until a deck's values",
    " are adopted (d with a .dat).",
];

/// The preset list: bundled first, then the user's; invalid user files are listed with their problem,
/// and a user file named like a bundled preset (which wins) with a warning.
pub fn draw_presets(frame: &mut Frame, app: &App, area: Rect, entries: &[Listed], selected: usize) {
    let theme = app.theme();
    let height = (entries.len() as u16 + 4).clamp(6, area.height.saturating_sub(2));
    // 76 columns on an 80-column screen; wider where the screen is, so that descriptions show
    // beside the name and key columns (up to 120: a line longer than that is not read).
    let popup = centred(area, area.width.saturating_sub(4).clamp(76, 120), height);
    frame.render_widget(Clear, popup);
    let block = pane(app, "Presets (Enter load, s save, Esc close)");
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let visible = inner.height.saturating_sub(1) as usize;
    let first = selected.saturating_sub(visible.saturating_sub(1));
    // The model column as wide as the longest problem key listed, so every row lines up.
    let width = entries
        .iter()
        .filter_map(|e| e.preset.as_ref().ok())
        .map(|p| p.inputs.kind().name().len())
        .max()
        .unwrap_or(1);
    // The name column as wide as the longest name listed (18 at least), for the same reason.
    let names = entries
        .iter()
        .map(|e| sanitize(&e.name).chars().count())
        .max()
        .unwrap_or(0)
        .max(18);
    let mut lines: Vec<Line> = entries
        .iter()
        .enumerate()
        .skip(first)
        .take(visible)
        .map(|(i, entry)| {
            // Names and descriptions come from users' files: shown escaped, never obeyed.
            let (model, description) = match &entry.preset {
                Ok(p) => (
                    p.inputs.kind().name(),
                    sanitize(&p.description).into_owned(),
                ),
                // Short enough for the box; Enter on it shows the whole warning.
                Err(_) if entry.shadowed => ("?", "WARNING: shadowed by the bundled one".into()),
                Err(problem) => ("?", format!("INVALID: {}", sanitize(&problem.to_string()))),
            };
            let marker = if i == selected { ">" } else { " " };
            let text = format!(
                "{marker} {:<names$} {:<width$} {:<7} {description}",
                sanitize(&entry.name),
                model,
                entry.origin
            );
            let style = if i == selected {
                theme.style(Role::Selected)
            } else {
                ratatui::style::Style::default()
            };
            Line::from(Span::styled(text, style))
        })
        .collect();
    if entries.len() > visible {
        lines.push(Line::from(Span::styled(
            format!(" {}/{} presets", selected + 1, entries.len()),
            theme.style(Role::Muted),
        )));
    }
    frame.render_widget(Paragraph::new(lines), inner);
}

/// A small box with a title, one line of content and a hint.
pub fn draw_prompt(
    frame: &mut Frame,
    app: &App,
    area: Rect,
    title: &str,
    content: &str,
    hint: &str,
) {
    // A long hint wraps onto more lines (the box grows) rather than being cut; so does a long
    // typed text (a path, a description), cut into rows of the box's width, its last rows shown
    // (where the cursor usually is) when it is longer than the screen allows.
    let hint_lines = wrap_words(hint, 56);
    let content: Vec<char> = sanitize(content).chars().collect();
    let room = usize::from(area.height.saturating_sub(6)).saturating_sub(hint_lines.len());
    let content_rows: Vec<String> = content.chunks(57).map(|c| c.iter().collect()).collect();
    let skip = content_rows.len().saturating_sub(room.max(1));
    let content_rows = &content_rows[skip..];
    let height = 3 + content_rows.len().max(1) + hint_lines.len().max(1);
    let popup = centred(area, 60, height as u16);
    frame.render_widget(Clear, popup);
    let block = pane(app, title);
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let mut lines: Vec<Line> = content_rows
        .iter()
        .map(|row| Line::from(format!(" {row}")))
        .collect();
    lines.push(Line::from(""));
    lines.extend(hint_lines.into_iter().map(|h| {
        Line::from(Span::styled(
            format!(" {h}"),
            app.theme().style(Role::Muted),
        ))
    }));
    frame.render_widget(Paragraph::new(lines), inner);
}

/// The last status message, whole (`M`), wrapped in a box over the chart.
pub fn draw_message(frame: &mut Frame, app: &App, area: Rect) {
    let Some(message) = app.message() else { return };
    let width = area.width.saturating_sub(4).min(100);
    let mut body: Vec<Line> = message
        .text
        .split('\n')
        .flat_map(|paragraph| wrap_words(&sanitize(paragraph), usize::from(width) - 4))
        .map(|l| Line::from(format!(" {l}")))
        .collect();
    let room = usize::from(area.height.saturating_sub(6));
    body.truncate(room.max(1));
    body.push(Line::from(""));
    body.push(Line::from(Span::styled(
        " Esc closes",
        app.theme().style(Role::Muted),
    )));
    let popup = centred(area, width, body.len() as u16 + 2);
    frame.render_widget(Clear, popup);
    let role = if message.is_error {
        Role::Error
    } else {
        Role::Info
    };
    let block = pane(app, "Message");
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    frame.render_widget(Paragraph::new(body).style(app.theme().style(role)), inner);
}

/// What one line of the regime pane means, in a box over the bottom of the chart; the line itself
/// is highlighted in the pane.
pub fn draw_explanation(frame: &mut Frame, app: &App, area: Rect, line: usize) {
    let Some(regime) = &app.view().regime else {
        return;
    };
    let lines: Vec<_> = regime.explained().collect();
    let Some(chosen) = lines.get(line.min(lines.len().saturating_sub(1))) else {
        return;
    };
    let width = area.width.saturating_sub(36).clamp(40, 80);
    let text = wrap_words(&chosen.meaning, usize::from(width) - 4);
    let height = text.len() as u16 + 4;
    let popup = Rect {
        x: area.x + area.width.saturating_sub(width + 1),
        y: area.y + area.height.saturating_sub(height + 1),
        width,
        height: height.min(area.height),
    };
    frame.render_widget(Clear, popup);
    let title = format!(
        "{}{}",
        chosen.text.trim_end(),
        chosen
            .regime
            .as_deref()
            .map_or(String::new(), |r| format!(" {r}"))
    );
    let block = pane(app, &title);
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let mut body: Vec<Line> = text
        .into_iter()
        .map(|l| Line::from(format!(" {l}")))
        .collect();
    body.push(Line::from(""));
    body.push(Line::from(Span::styled(
        format!(
            " line {}/{}: j/k other lines, Esc closes",
            line + 1,
            lines.len()
        ),
        app.theme().style(Role::Muted),
    )));
    frame.render_widget(Paragraph::new(body), inner);
}
