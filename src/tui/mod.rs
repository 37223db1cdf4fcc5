//! The terminal UI: terminal set-up and restore, and the event loop. Everything else lives in
//! [`action`] (what keys ask for), [`app`] (state), [`keymap`] (keys), [`plots`] (chart data),
//! [`text_input`] (typed text) and [`ui`] (drawing).
//!
//! Over SSH: the screen is redrawn only after a key or a resize (no frame rate; the 250 ms poll only
//! checks for SIGTERM/SIGHUP and draws nothing), queued keys are applied before a single redraw, the
//! mouse is not captured, and the terminal is restored on quit, on error, on panic (ratatui's hook)
//! and on SIGTERM or SIGHUP (a dropped SSH link).

pub mod action;
pub mod app;
pub mod keymap;
pub mod plots;
pub mod text_input;
pub mod theme;
pub mod ui;

use std::io::{self, IsTerminal};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{self, Event, KeyEventKind};

use app::{App, AppOptions};
use theme::{Charset, Theme};

use crate::model::params::ModelKind;
use crate::preset::{self, PresetError};

/// How often the loop wakes up to look for a termination signal (no redraw happens then).
const SIGNAL_POLL: Duration = Duration::from_millis(250);

/// Why the TUI could not run.
#[derive(Debug, thiserror::Error)]
pub enum TuiError {
    /// Standard output is not a terminal.
    #[error(
        "the terminal UI needs an interactive terminal; for a text report run `microslip report`, for scripts see `microslip --help`"
    )]
    NotATerminal,
    /// The `--data` file is unreadable or malformed.
    #[error("{0}")]
    Data(String),
    /// The start-up preset is unusable.
    #[error(transparent)]
    Preset(#[from] PresetError),
    /// The terminal failed.
    #[error("terminal error: {0}")]
    Io(#[from] io::Error),
}

/// Opens the TUI on `preset` (default: the paper's twin beams).
pub fn run(
    charset: Charset,
    preset: Option<&str>,
    data: Option<std::path::PathBuf>,
) -> Result<(), TuiError> {
    let preset = preset::resolve(preset.unwrap_or(preset::default_name(ModelKind::Beam)))?;
    if !io::stdout().is_terminal() || !io::stdin().is_terminal() {
        return Err(TuiError::NotATerminal);
    }
    // A bad data file is refused before the screen changes, like a bad preset.
    let data = match data {
        Some(path) => {
            let shown = path.display().to_string();
            let text = crate::fit::data::read_text(&path)
                .map_err(|e| TuiError::Data(format!("{shown}: {e}")))?;
            let points = crate::fit::data::parse(&text)
                .map_err(|e| TuiError::Data(format!("{shown}: {e}")))?;
            Some(app::Measurements {
                path: shown,
                points,
            })
        }
        None => None,
    };
    let mut app = App::new(AppOptions {
        theme: Theme::from_env(charset),
        preset,
        user_dir: preset::user_preset_dir(),
        data,
    });
    let terminate = Arc::new(AtomicBool::new(false));
    for signal in [signal_hook::consts::SIGTERM, signal_hook::consts::SIGHUP] {
        signal_hook::flag::register(signal, Arc::clone(&terminate))?;
    }
    let mut terminal = ratatui::try_init()?;
    let result = event_loop(&mut terminal, &mut app, &terminate);
    let _ = terminal.show_cursor();
    ratatui::restore();
    result.map_err(TuiError::from)
}

fn event_loop(
    terminal: &mut DefaultTerminal,
    app: &mut App,
    terminate: &AtomicBool,
) -> io::Result<()> {
    terminal.draw(|frame| ui::draw(frame, app))?;
    while !terminate.load(Ordering::Relaxed) {
        if !event::poll(SIGNAL_POLL)? {
            continue;
        }
        let mut redraw = false;
        // Apply every queued event, then draw once.
        loop {
            match event::read()? {
                Event::Key(key) if key.kind == KeyEventKind::Press => {
                    if let Some(action) = keymap::action_for(app.mode().context(), key) {
                        app.update(action);
                        redraw = true;
                    }
                    if app.should_quit() {
                        return Ok(());
                    }
                }
                Event::Resize(..) => redraw = true,
                _ => {}
            }
            if !event::poll(Duration::ZERO)? {
                break;
            }
        }
        if redraw {
            terminal.draw(|frame| ui::draw(frame, app))?;
        }
    }
    Ok(())
}
