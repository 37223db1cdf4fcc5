//! Pure drawing: `draw(frame, &App)` reads the app's view model ([`App::view`], built where the
//! state changed) and its plain UI state (the mode, the text typed, the selection, the message)
//! and writes cells, nothing else: no file here names the physics (`tests/layering.rs` checks),
//! so a frame never solves. That makes every screen a snapshot test over ratatui's `TestBackend`.

mod chart;
mod overlay;
mod panes;
mod strip;

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Constraint, Layout, Rect};
use ratatui::widgets::{Paragraph, Wrap};

use super::app::{App, Mode};
use super::theme::{Charset, Role, ascii_fallback};

/// Smallest terminal the layout is designed for.
pub const MIN_WIDTH: u16 = 80;
/// Smallest terminal height.
pub const MIN_HEIGHT: u16 = 24;

/// True when a terminal of `width` x `height` cells is too small for the layout: the screen then
/// only says so, and only the keys that quit act (see [`App::acts_when_too_small`]).
pub fn is_too_small(width: u16, height: u16) -> bool {
    width < MIN_WIDTH || height < MIN_HEIGHT
}

/// The left column's width (parameters above the regime pane): wider from 120 columns.
fn left_width(width: u16) -> u16 {
    if width >= 120 { 44 } else { 34 }
}

/// The cells the regime pane's zone strip can have, one per width of the left column: the view
/// samples the interface shear for each, so that drawing never solves.
pub fn strip_cells() -> [usize; 2] {
    // The pane's borders take a column each side.
    [MIN_WIDTH, 120].map(|width| strip::cells(left_width(width) - 2))
}

/// Draws the whole screen.
pub fn draw(frame: &mut Frame, app: &App) {
    let area = frame.area();
    if is_too_small(area.width, area.height) {
        draw_too_small(frame, app, area);
    } else {
        // The status takes the rows its message needs (up to a few), out of the panes above it,
        // so that a long message never covers the chart's axes or the pane borders.
        let status_rows = panes::status_rows(app, area.width, area.height);
        let [main, status] =
            Layout::vertical([Constraint::Min(0), Constraint::Length(status_rows)]).areas(area);
        let left_width = left_width(area.width);
        let [left, right] =
            Layout::horizontal([Constraint::Length(left_width), Constraint::Min(0)]).areas(main);
        let parameter_rows = app.view().rows.len() as u16 + 2;
        let [parameters, summary] =
            Layout::vertical([Constraint::Length(parameter_rows), Constraint::Min(0)]).areas(left);
        panes::draw_parameters(frame, app, parameters);
        panes::draw_summary(frame, app, summary);
        chart::draw(frame, app, right);
        panes::draw_status(frame, app, status);
        match app.mode() {
            Mode::Help => overlay::draw_help(frame, app, area),
            Mode::Presets { entries, selected } => {
                overlay::draw_presets(frame, app, area, entries, *selected)
            }
            Mode::SaveName { input } => overlay::draw_prompt(
                frame,
                app,
                area,
                "Save preset",
                &format!("Name: {}", input.shown()),
                "letters, digits, - and _; Enter save, Esc cancel",
            ),
            Mode::DataPath { input } => overlay::draw_prompt(
                frame,
                app,
                area,
                "Load measurements or FE results",
                &format!("File: {}", input.shown()),
                "CSV of measurements or FE results (the columns `microslip fit` and `compare` \
                 read for this problem) or a CalculiX .dat; Tab completes, Enter load, Esc cancel",
            ),
            Mode::SaveDescription { name, input } => overlay::draw_prompt(
                frame,
                app,
                area,
                &format!("Save preset {name}"),
                &format!("Description: {}", input.shown()),
                "one line, shown in the preset list; Enter save, Esc cancel",
            ),
            Mode::Message => overlay::draw_message(frame, app, area),
            Mode::ConfirmOverwrite { name, .. } => overlay::draw_prompt(
                frame,
                app,
                area,
                "Overwrite?",
                &format!("Preset '{name}' exists. Overwrite it?"),
                "y overwrite, n or Esc keep the existing file",
            ),
            Mode::ConfirmQuit { unsaved } => overlay::draw_prompt(
                frame,
                app,
                area,
                "Quit?",
                &format!("Unsaved edits: {unsaved}. Quit anyway?"),
                "y quit, n or Esc stay (s saves as a preset)",
            ),
            Mode::ConfirmReset => overlay::draw_prompt(
                frame,
                app,
                area,
                "Reset?",
                &format!(
                    "Reset the edited values (*) to preset {}?",
                    app.view().preset
                ),
                "y reset (u undoes it), n or Esc keep the edits",
            ),
            Mode::Target { input } => overlay::draw_prompt(
                frame,
                app,
                area,
                "Solve for a target",
                &format!(
                    "{} such that {}",
                    app.view().rows.get(app.selected()).map_or("", |r| r.name),
                    input.shown()
                ),
                &format!(
                    "one of {}; Enter solve, Esc cancel",
                    app.view().target_quantities
                ),
            ),
            Mode::Explain { line } => overlay::draw_explanation(frame, app, area, *line),
            Mode::Normal
            | Mode::Editing { .. }
            | Mode::Command { .. }
            | Mode::Fitting { .. }
            | Mode::Loading { .. } => {}
        }
    }
    if app.theme().charset == Charset::Ascii {
        enforce_ascii(frame.buffer_mut());
    }
}

fn draw_too_small(frame: &mut Frame, app: &App, area: Rect) {
    // Only quitting acts here (App::acts_when_too_small): say how, and the question it asks.
    let quit = if matches!(app.mode(), Mode::ConfirmQuit { .. }) {
        "Quit with unsaved edits? y quits, n or Esc stays."
    } else {
        "Enlarge the window, or press q (Ctrl-C) to quit."
    };
    let text = format!(
        "Terminal too small: {}x{}.\nmicroslip needs at least {MIN_WIDTH}x{MIN_HEIGHT}.\n{quit}",
        area.width, area.height
    );
    let paragraph = Paragraph::new(text)
        .style(app.theme().style(Role::Error))
        .alignment(Alignment::Center)
        .wrap(Wrap { trim: true });
    let [_, middle, _] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Length(4),
        Constraint::Fill(1),
    ])
    .areas(area);
    frame.render_widget(paragraph, middle);
}

/// The ASCII charset's guarantee: whatever a widget drew, only 7-bit characters reach the terminal.
fn enforce_ascii(buffer: &mut Buffer) {
    for cell in buffer.content.iter_mut() {
        if !cell.symbol().is_ascii() {
            cell.set_symbol(ascii_fallback(cell.symbol()));
        }
    }
}

#[cfg(test)]
mod tests {
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;

    use super::*;
    use crate::tui::app::AppOptions;
    use crate::tui::theme::Theme;

    /// The regime pane's shear rows are drawn from the view, which samples them for each width
    /// the left column can have: on a tall screen of either width the rows hold one bar per
    /// cell, not nothing.
    #[test]
    fn the_shear_rows_are_drawn_at_every_width_of_the_left_column() {
        let app = App::new(AppOptions {
            theme: Theme {
                charset: Charset::Ascii,
                color: false,
            },
            preset: crate::preset::resolve("paper-beams").unwrap(),
            user_dir: None,
            data: None,
            solve_continuum: false,
        });
        for width in [MIN_WIDTH, 100, 119, 120, 200] {
            let mut terminal = Terminal::new(TestBackend::new(width, 40)).unwrap();
            terminal.draw(|frame| draw(frame, &app)).unwrap();
            let screen = terminal.backend().to_string();
            let rows: Vec<&str> = screen.lines().collect();
            let heading = rows
                .iter()
                .position(|r| r.contains("tau(x) / mu P"))
                .unwrap_or_else(|| panic!("no shear rows at {width} columns:\n{screen}"));
            let cells = strip::cells(left_width(width) - 2);
            for row in &rows[heading + 1..heading + 3] {
                // The backend quotes each row; then the pane's border.
                let inside = usize::from(left_width(width) - 2);
                let left: String = row.chars().skip(2).take(inside).collect();
                let bars = left.trim_end().chars().count().saturating_sub(3);
                assert_eq!(bars, cells, "at {width} columns: {row}");
            }
        }
    }
}
