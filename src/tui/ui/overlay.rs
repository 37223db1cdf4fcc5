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

/// The key map, in two columns, straight from the binding table.
pub fn draw_help(frame: &mut Frame, app: &App, area: Rect) {
    let popup = centred(area, 78, 22);
    frame.render_widget(Clear, popup);
    let block = pane(app, "Keys (Esc or ? closes)");
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [left, right] = Layout::horizontal([Constraint::Fill(1), Constraint::Fill(1)]).areas(inner);
    frame.render_widget(Paragraph::new(help_lines(app, &[Context::Main])), left);
    let mut right_lines = help_lines(
        app,
        &[Context::Presets, Context::TextEntry, Context::Confirm],
    );
    right_lines.push(Line::from(""));
    for (key, _, what) in GLOBAL_KEYS {
        right_lines.push(Line::from(format!(
            " Ctrl-{:<8} {what}",
            key.to_ascii_uppercase()
        )));
    }
    frame.render_widget(Paragraph::new(right_lines), right);
}

/// The preset list: bundled first, then the user's; invalid user files are listed with their problem,
/// and a user file named like a bundled preset (which wins) with a warning.
pub fn draw_presets(frame: &mut Frame, app: &App, area: Rect, entries: &[Listed], selected: usize) {
    let theme = app.theme();
    let height = (entries.len() as u16 + 4).clamp(6, area.height.saturating_sub(2));
    let popup = centred(area, 76, height);
    frame.render_widget(Clear, popup);
    let block = pane(app, "Presets (Enter load, s save, Esc close)");
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let visible = inner.height.saturating_sub(1) as usize;
    let first = selected.saturating_sub(visible.saturating_sub(1));
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
                Err(problem) => ("?", format!("INVALID: {}", sanitize(problem))),
            };
            let marker = if i == selected { ">" } else { " " };
            let text = format!(
                "{marker} {:<18} {:<5} {:<7} {description}",
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
    let popup = centred(area, 60, 5);
    frame.render_widget(Clear, popup);
    let block = pane(app, title);
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let lines = vec![
        Line::from(format!(" {}", sanitize(content))),
        Line::from(""),
        Line::from(Span::styled(
            format!(" {hint}"),
            app.theme().style(Role::Muted),
        )),
    ];
    frame.render_widget(Paragraph::new(lines), inner);
}
