//! The terminal UI: the event loop. Everything else lives in [`action`] (what keys ask for),
//! [`app`] (state), [`effects`] (files and the fit, which the loop performs for the app),
//! [`keymap`] (keys), [`text_input`] (typed text), [`terminal`] (entering, leaving, suspending),
//! `signals` and [`ui`] (drawing).
//!
//! Over SSH (see docs/guide.md, "Limits"):
//! - The screen is redrawn only after a key, a paste or a resize; there is no frame rate.
//! - A reader thread (`reader`) turns terminal input into events. The loop applies every queued
//!   event, for up to [`BATCH`] at a time, then rebuilds the chart and draws once, so a storm of
//!   keys costs one chart and one frame per batch (a key's own work is the closed forms of the
//!   regime pane; a chart, the overlay and the continuum are asked for, not built, per key).
//! - Every slow job (the finite-element and continuum overlay, the plate's continuum, a fit, a
//!   file read with `d`, an export) runs on a worker thread ([`workers`]), which reports over the
//!   same channel as the reader: the loop never waits for it, the newest request wins and Esc
//!   cancels.
//! - Pastes arrive as text: bracketed paste, and a paste from a terminal that does not bracket
//!   it (`tmux paste-buffer` without `-p`), which comes as a burst of keys, is made one paste by
//!   the reader (at least `reader::PASTE_KEYS` text keys, none more than `reader::GAP` after
//!   the one before, and then all that follows until `reader::PASTE_QUIET` of quiet; one key
//!   held down stays keys). A paste types into the field being edited,
//!   or is ignored with a note on the main screen; it never runs keys. A 100 kB paste was
//!   100 000 commands (93 s on the beams) before.
//! - Quitting and signals never wait behind input: SIGTERM, SIGHUP and SIGINT are looked at
//!   between any two events and at least every [`TICK`], and so is Ctrl-C, which the reader
//!   flags as it arrives; a `q` or Esc typed while `reader::DEEP` or more keys wait to be
//!   applied drops them (the status line says how many) and acts next. Behind that, the
//!   `watchdog` restores the terminal and ends the process if the loop has not ended
//!   `watchdog::GRACE` after a signal or Ctrl-C, however long the event or frame it is in.
//!   Measured in tmux (debug build, 2 cores at load 8 to 10): `q`, Ctrl-C and SIGTERM after a
//!   100 kB paste 8 to 60 ms; `q` behind 20 000 queued keys 0.17 s (more than 30 s before);
//!   SIGTERM, SIGINT, SIGHUP and Ctrl-C while a key held the loop for 3 s (a build made to),
//!   0.10 to 0.16 s, terminal restored, exit 143, 130, 129 and 0.
//! - SIGTERM, SIGHUP and SIGINT restore the terminal and exit with 128 + the signal; Ctrl-C
//!   exits 0 (quit without asking); SIGTSTP and Ctrl-Z suspend (where a shell with job control
//!   can resume the program; see `signals`).
//! - A terminal that hung up (a dropped link, a killed pane) ends the program within a tick, even
//!   if no SIGHUP arrives.
//! - The mouse is not captured. A panic restores the terminal through ratatui's hook.

pub mod action;
pub mod app;
pub mod command;
pub mod effects;
pub mod keymap;
pub mod kt_table;
mod reader;
mod signals;
pub mod summary;
pub mod terminal;
pub mod text_input;
pub mod theme;
pub mod ui;
pub mod view;
pub mod views;
mod watchdog;
pub mod workers;

use std::io::{self, IsTerminal};
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{Event, KeyEventKind};

use app::{App, AppOptions};
use effects::Runner;
use reader::{Input, Keyboard};
use theme::{Charset, Theme};

use crate::preset::{self, PresetError};
use crate::problems::ModelKind;

/// How often the loop wakes up without input, to look for signals and a hung-up terminal (it
/// draws nothing then).
pub const TICK: Duration = Duration::from_millis(50);

/// Longest run of queued events applied before the screen is redrawn.
pub const BATCH: Duration = Duration::from_millis(30);

/// How the TUI ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    /// The user quit.
    Quit,
    /// A signal (its number) asked the program to end.
    Signal(i32),
    /// The terminal went away.
    HangUp,
}

impl Exit {
    /// The process exit code: 0, or 128 + the signal as shells report it (129 for a hang-up).
    pub fn code(self) -> u8 {
        match self {
            Exit::Quit => 0,
            Exit::Signal(n) => u8::try_from(128 + n).unwrap_or(255),
            Exit::HangUp => 129,
        }
    }
}

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

/// Opens the TUI on `preset` (default: the paper preset of the registry's first problem, the
/// twin beams).
pub fn run(
    charset: Charset,
    preset: Option<&str>,
    data: Option<std::path::PathBuf>,
) -> Result<Exit, TuiError> {
    let preset = preset::resolve(preset.unwrap_or(preset::default_name(ModelKind::ALL[0])))?;
    if !io::stdout().is_terminal() || !io::stdin().is_terminal() {
        return Err(TuiError::NotATerminal);
    }
    // A bad data file is refused before the screen changes, like a bad preset.
    let data = match data {
        Some(path) => {
            let shown = path.display().to_string();
            let text = crate::measured::read_text(&path, crate::file::Kinds::AnyReadable)
                .map_err(|e| TuiError::Data(format!("{shown}: {e}")))?;
            // The measured curve of the problem opened: F_N,Delta_mm on a lap joint's preset.
            let points = crate::measured::parse_measured_curve_of(
                preset.inputs.kind(),
                &text,
                &mut |_, _| {},
            )
            .map_err(|e| TuiError::Data(format!("{shown}: {e}")))?
            .points;
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
        solve_continuum: true,
    });
    // One chart per frame, not one per key of a batch (see `event_loop`).
    app.defer_charts();
    let signals = signals::Signals::install()?;
    let watchdog = watchdog::Watchdog::start()?;
    let mut terminal = terminal::enter()?;
    let (sender, inputs) = mpsc::channel();
    let keyboard = Arc::new(Keyboard::default());
    reader::spawn(sender.clone(), Arc::clone(&keyboard), watchdog.clone());
    let mut runner = Runner::new(sender);
    runner.start(&mut app);
    let ends = Ends {
        signals: &signals,
        keyboard: &keyboard,
        inputs: &inputs,
    };
    let result = event_loop(&mut terminal, &mut app, &mut runner, &ends);
    if !watchdog.disarm() {
        // The watchdog is restoring the terminal and ending the process.
        loop {
            std::thread::park();
        }
    }
    // A SIGHUP sent by hand leaves a live terminal to restore; a closed one reports POLLHUP.
    let hung_up = terminal::hung_up();
    let gone = hung_up || matches!(result, Ok(Exit::HangUp) | Err(_));
    if gone {
        // Nothing is left to restore, and ratatui's `Terminal` would, when dropped, report its
        // failure to show the cursor with `eprintln!`, which panics on the closed stderr; the
        // panic hook's own report then panicked again and the process died of SIGABRT (with a
        // core dump, 1.2 to 2 s) instead of exiting 129.
        // Whatever the loop was doing when the terminal went (a failed draw is an I/O error),
        // this is a hang-up: exit 129, with nothing printed to a stderr that is gone.
        std::mem::forget(terminal);
        return match result {
            Ok(Exit::Signal(signal)) => Ok(Exit::Signal(signal)),
            Err(e) if !hung_up => Err(TuiError::from(e)),
            _ => Ok(Exit::HangUp),
        };
    }
    if result.is_ok() {
        let _ = terminal.show_cursor();
    }
    terminal::leave();
    result.map_err(TuiError::from)
}

/// Applies one event, performing what it asks for; true when the screen must be redrawn. While
/// the terminal is `too_small` to draw the app, only the keys that quit act (and a paste types
/// nothing): the user sees none of what the others would do.
fn apply(app: &mut App, runner: &mut Runner<Input>, event: Event, too_small: bool) -> bool {
    match event {
        Event::Key(key) if key.kind == KeyEventKind::Press => {
            let action = keymap::action_for(app.mode().context(), key)
                .filter(|&action| !too_small || app.acts_when_too_small(action));
            match action {
                // Like the terminal's own Ctrl-Z: the loop acts on the SIGTSTP once this batch
                // is over.
                Some(action::Action::Suspend) => {
                    signals::request_suspend();
                    false
                }
                Some(action) => {
                    runner.update(app, action);
                    true
                }
                None => false,
            }
        }
        Event::Paste(_) if too_small => false,
        Event::Paste(text) => app.paste(&text),
        Event::Resize(..) => true,
        _ => false,
    }
}

/// Rebuilds what the keys applied since the last frame left stale, once, and draws.
fn draw(terminal: &mut DefaultTerminal, app: &mut App) -> io::Result<()> {
    app.settle();
    terminal.draw(|frame| ui::draw(frame, app))?;
    Ok(())
}

/// What the loop reads besides the app: the signals, the reader's out-of-band flags and the
/// channel of events and reports.
struct Ends<'a> {
    signals: &'a signals::Signals,
    keyboard: &'a Keyboard,
    inputs: &'a Receiver<Input>,
}

impl Ends<'_> {
    /// True when the loop must stop applying events and look at its ends: a signal or Ctrl-C.
    fn waiting(&self) -> bool {
        self.signals.waiting() || self.keyboard.interrupted()
    }
}

fn event_loop(
    terminal: &mut DefaultTerminal,
    app: &mut App,
    runner: &mut Runner<Input>,
    ends: &Ends,
) -> io::Result<Exit> {
    draw(terminal, app)?;
    loop {
        // Ctrl-C, seen by the reader as it arrived: quit without asking, however many events
        // wait.
        if ends.keyboard.interrupted() {
            return Ok(Exit::Quit);
        }
        match ends.signals.take() {
            Some(signals::Request::Terminate(signal)) => return Ok(Exit::Signal(signal)),
            Some(signals::Request::Suspend) => {
                if terminal::suspend(terminal)? == signals::Suspended::Ignored {
                    app.suspend_ignored();
                }
                draw(terminal, app)?;
            }
            None => {}
        }
        if terminal::hung_up() {
            return Ok(Exit::HangUp);
        }
        let first = match ends.inputs.recv_timeout(TICK) {
            Ok(input) => input,
            Err(RecvTimeoutError::Timeout) => continue,
            Err(RecvTimeoutError::Disconnected) => return Ok(Exit::HangUp),
        };
        // Apply queued events for up to one batch, stopping early for a signal or Ctrl-C, and
        // skipping to a quit key typed behind a deep queue; then draw once.
        let started = Instant::now();
        let mut redraw = false;
        let mut next = Some(first);
        while let Some(input) = next {
            ends.keyboard.taken(&input);
            match input {
                Input::Terminal(Ok(event)) | Input::Urgent(event) => {
                    redraw |= apply(app, runner, event, too_small(terminal));
                }
                Input::Terminal(Err(_)) => return Ok(Exit::HangUp),
                Input::Work(report) => {
                    runner.deliver(app, *report);
                    redraw = true;
                }
            }
            if app.should_quit() {
                return Ok(Exit::Quit);
            }
            if ends.keyboard.urgent() {
                match skip_to_urgent(terminal, app, runner, ends) {
                    Ok(skipped) => redraw |= skipped,
                    Err(exit) => return Ok(exit),
                }
                if app.should_quit() {
                    return Ok(Exit::Quit);
                }
            }
            if ends.waiting() || started.elapsed() >= BATCH {
                break;
            }
            next = ends.inputs.try_recv().ok();
        }
        if redraw && !ends.waiting() {
            draw(terminal, app)?;
        }
    }
}

/// True when the terminal is, now, too small to draw the app (a resize may be in this batch).
fn too_small(terminal: &DefaultTerminal) -> bool {
    terminal
        .size()
        .is_ok_and(|size| ui::is_too_small(size.width, size.height))
}

/// A `q` or Esc was typed behind a deep queue ([`reader::DEEP`] keys): drops the keys and pastes
/// before it, says how many on the status line, and applies it. Workers' reports and resizes
/// on the way are taken as usual. True when the screen must be redrawn; the terminal's end
/// (a read error) as an error.
fn skip_to_urgent(
    terminal: &DefaultTerminal,
    app: &mut App,
    runner: &mut Runner<Input>,
    ends: &Ends,
) -> Result<bool, Exit> {
    let mut dropped = 0;
    let mut redraw = false;
    while let Ok(input) = ends.inputs.try_recv() {
        ends.keyboard.taken(&input);
        match input {
            Input::Terminal(Ok(Event::Key(key))) => {
                dropped += usize::from(key.kind == KeyEventKind::Press);
            }
            Input::Terminal(Ok(Event::Paste(_))) => dropped += 1,
            Input::Terminal(Ok(event)) => redraw |= apply(app, runner, event, too_small(terminal)),
            Input::Terminal(Err(_)) => return Err(Exit::HangUp),
            Input::Work(report) => {
                runner.deliver(app, *report);
                redraw = true;
            }
            Input::Urgent(event) => {
                app.keys_dropped(dropped);
                apply(app, runner, event, too_small(terminal));
                return Ok(true);
            }
        }
        if ends.waiting() {
            break;
        }
    }
    Ok(redraw)
}

#[cfg(test)]
mod tests {
    use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

    use super::*;

    fn app() -> App {
        App::new(AppOptions {
            theme: Theme {
                charset: Charset::Unicode,
                color: true,
            },
            preset: preset::resolve("paper-beams").unwrap(),
            user_dir: None,
            data: None,
            solve_continuum: false,
        })
    }

    fn key(c: char) -> Event {
        Event::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
    }

    /// Issue 36 (21): under "Terminal too small" only the keys that quit act: at 1x1, `x`
    /// exported a file nobody saw. The same keys act once the terminal is large enough.
    #[test]
    fn only_quitting_acts_while_the_terminal_is_too_small() {
        let (sender, _reports) = mpsc::channel::<Input>();
        let mut runner = Runner::new(sender);
        let mut app = app();
        let kind = app.kind();
        // `m` switches the model, `j` the row, `x` exports, `:` opens the command line.
        for c in ['m', 'j', 'L', 'x', ':', 's'] {
            apply(&mut app, &mut runner, key(c), true);
        }
        assert_eq!(app.kind(), kind);
        assert_eq!(app.selected(), 0);
        assert!(
            app.message().is_none(),
            "{:?}",
            app.message().map(|m| &m.text)
        );
        let inputs = app.inputs();
        assert!(inputs.kind().params().iter().all(|&p| !app.is_edited(p)));
        assert!(!apply(
            &mut app,
            &mut runner,
            Event::Paste("7".into()),
            true
        ));
        apply(&mut app, &mut runner, key('m'), false);
        assert_ne!(app.kind(), kind);
        // Quitting still works, and asks first where edits would be lost.
        apply(&mut app, &mut runner, key('q'), true);
        assert!(app.should_quit());
    }
}
