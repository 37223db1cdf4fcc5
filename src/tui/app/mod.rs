//! The TUI's state and its mutators: [`App::update`] applies a key's action, [`App::receive`]
//! what came of an effect. No drawing, no terminal and no file here: what needs the disk or
//! takes long (export, save, load, the preset list, file-name completion, the fit) is returned
//! as an [`Effect`] for the event loop to perform (see [`super::effects`]), so every behaviour can
//! be tested by feeding actions and outcomes and looking at the state.

use std::path::PathBuf;

use super::action::Action;
use super::effects::{Effect, Outcome};
use super::keymap::Context;
use super::text_input::TextInput;
use super::theme::Theme;
use super::view::View;
use super::views::Views;
use super::workers::Lane;
use crate::chart::view::AnyChart;
use crate::chart::{self, NumericPoints, Plot, YMode};
use crate::fit::Measurement;
use crate::preset::{self, Listed, Preset};
use crate::problems::inputs::Inputs;
use crate::problems::{ByProblem, ModelKind, Param};

mod command_line;
mod data;
mod export;
mod fit;
mod normal;
mod pins;
mod presets;
mod recompute;
mod state;
mod text_entry;

/// A status-line message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    /// The text.
    pub text: String,
    /// True for errors (refused input, failed save).
    pub is_error: bool,
}

/// What has the keyboard.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    /// The main screen.
    Normal,
    /// Typing a value for the selected parameter.
    Editing {
        /// Text typed so far.
        input: TextInput,
    },
    /// The help overlay.
    Help,
    /// The preset picker.
    Presets {
        /// Bundled then user presets.
        entries: Vec<Listed>,
        /// Selected row.
        selected: usize,
    },
    /// Typing the name of a preset to save.
    SaveName {
        /// Text typed so far.
        input: TextInput,
    },
    /// Typing the one-line description of the preset being saved (prefilled; Enter keeps it).
    SaveDescription {
        /// The preset name, typed before.
        name: String,
        /// Text typed so far.
        input: TextInput,
    },
    /// The command line (`:`), typed on the status line.
    Command {
        /// Text typed so far.
        input: TextInput,
    },
    /// The last status message, whole, in an overlay (`M`).
    Message,
    /// Typing the path of a measurement file.
    DataPath {
        /// Text typed so far.
        input: TextInput,
    },
    /// Asking before overwriting a user preset.
    ConfirmOverwrite {
        /// The preset name.
        name: String,
        /// The description typed for it.
        description: String,
    },
    /// Asking before quitting with unsaved edits.
    ConfirmQuit {
        /// What would be lost, e.g. `beam (paper-beams)`.
        unsaved: String,
    },
    /// Asking before resetting edited parameters to the preset.
    ConfirmReset,
    /// Typing a target (`ratio=1.01`) to solve the selected parameter for.
    Target {
        /// Text typed so far.
        input: TextInput,
    },
    /// What one line of the regime pane means (`j`/`k` move through the lines).
    Explain {
        /// The line explained (0-based).
        line: usize,
    },
    /// A fit runs on a worker: Esc cancels it, other keys are ignored until it ends (its result is
    /// adopted into the parameters it started from, which must not change meanwhile).
    Fitting {
        /// The fit, as in [`Effect::Fit`].
        job: u64,
    },
    /// A file named with `d` is read on a worker (a million rows take seconds): Esc cancels, other
    /// keys are ignored until it is in, so that keys typed meanwhile never act on the main
    /// screen (an `m` switched the model while the file loaded in the loop).
    Loading {
        /// The file, as typed.
        path: String,
    },
}

impl Mode {
    /// The key-map context of this mode.
    pub fn context(&self) -> Context {
        match self {
            Mode::Normal => Context::Main,
            Mode::Editing { .. }
            | Mode::SaveName { .. }
            | Mode::SaveDescription { .. }
            | Mode::Command { .. }
            | Mode::DataPath { .. }
            | Mode::Target { .. } => Context::TextEntry,
            Mode::Help | Mode::Message => Context::Help,
            Mode::Explain { .. } => Context::Explain,
            Mode::Presets { .. } => Context::Presets,
            Mode::ConfirmOverwrite { .. } | Mode::ConfirmQuit { .. } | Mode::ConfirmReset => {
                Context::Confirm
            }
            Mode::Fitting { .. } | Mode::Loading { .. } => Context::Working,
        }
    }
}

/// Per-model state: inputs (always valid), the preset they came from and the selected row.
#[derive(Debug, Clone, PartialEq)]
struct ModelState {
    inputs: Inputs,
    preset: Preset,
    selected: usize,
    /// The parameter charted on the x axis (`v`), instead of the model's views.
    varied: Option<Param>,
    /// Parameters pinned with `g`, oldest first: their curves show on every chart of the model.
    pins: Vec<Pin>,
}

/// Parameters kept for comparison (`g`), with the number their curve is drawn with.
#[derive(Debug, Clone, PartialEq)]
struct Pin {
    number: u8,
    inputs: Inputs,
    /// The chart last built at these values, and what it was built for: a pin's chart does not
    /// change with the current parameters, so dragging a value rebuilds only the current curves.
    chart: Option<(PinnedChart, Plot)>,
}

/// What a pinned chart depends on besides the pin's values.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PinnedChart {
    views: Views,
    varied: Option<Param>,
    force_span: Option<f64>,
    y_mode: YMode,
}

/// The parameters of every problem and which is active: one step of the undo history.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Snapshot {
    inputs: ByProblem<Inputs>,
    kind: ModelKind,
}

/// Changes kept for `u` (the oldest are dropped beyond this).
pub const HISTORY: usize = 100;

/// Start-up choices.
#[derive(Debug, Clone)]
pub struct AppOptions {
    /// Colours and characters.
    pub theme: Theme,
    /// The preset to open (its model becomes the active one).
    pub preset: Preset,
    /// Where user presets are listed and saved (`None`: saving is refused with a message).
    pub user_dir: Option<PathBuf>,
    /// Measurements to show on the w(L) chart and fit (`--data`).
    pub data: Option<Measurements>,
    /// Solve the plate's 2-D continuum at the current values for the regime pane
    /// (`Effect::SolveContinuum`). The program does; tests that do not look at it leave it off,
    /// since a debug build takes about a second per solve.
    pub solve_continuum: bool,
}

/// Measurements loaded from a file.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurements {
    /// The file, as given.
    pub path: String,
    /// The points.
    pub points: Vec<Measurement>,
}

/// The whole TUI state.
#[derive(Debug, Clone)]
pub struct App {
    theme: Theme,
    /// Each problem's parameters, preset, selection and pins: `m` switches between them.
    states: ByProblem<ModelState>,
    kind: ModelKind,
    views: Views,
    mode: Mode,
    message: Option<Message>,
    show_numeric: bool,
    user_dir: Option<PathBuf>,
    quit: bool,
    /// What the screen shows, rebuilt after every action and outcome (the chart by
    /// [`App::recompute`]): the drawing reads it and nothing of the physics.
    view: View,
    numeric: Option<NumericPoints>,
    /// What the finite-element overlay (`n`) was last asked for (parameters and chart), and true
    /// while its answer is pending: `numeric` is that answer, never one for other values.
    overlay: Option<(Inputs, AnyChart, bool)>,
    /// True from `n` switching the overlay on until its answer comes, which the status explains
    /// (no points for this chart, unsolved points).
    overlay_toggled: bool,
    /// See [`App::defer_charts`].
    charts_deferred: bool,
    /// True when a change left the chart to be rebuilt ([`App::settle`]).
    chart_stale: bool,
    measurements: Option<Measurements>,
    /// The problem whose measured curve `measurements` is (the one `f` fits).
    measured_kind: ModelKind,
    /// Points of an external FE code loaded with `d` (a CalculiX .dat, or a plate CSV), and the
    /// parameters of the deck they came from.
    external: Option<(chart::ExternalPoints, Option<Inputs>)>,
    /// The number of the last fit started (see [`Mode::Fitting`]).
    jobs: u64,
    /// The effects asked for by the action or outcome being applied, handed to the caller of
    /// `update` or `receive` when it is done.
    asked: Vec<Effect>,
    undo: Vec<Snapshot>,
    redo: Vec<Snapshot>,
    /// The last target typed after `t`, offered again.
    last_target: String,
    /// The load range (N) of each problem's charts over its load (the beams' F), kept while
    /// parameters change so that the axes do not jump; `a` fits it to the current regime scale
    /// (F_thre) again. None for a problem without a load.
    force_span: ByProblem<Option<f64>>,
    help_page: usize,
    /// Where `x` writes the chart's SVG and CSV (the working directory unless set).
    export_dir: PathBuf,
    /// The y-axis modes chosen with `y`, by chart (None: the chart against a parameter of `v`);
    /// a chart not listed shows its default ([`YMode::default_for`]).
    y_modes: Vec<(Option<AnyChart>, YMode)>,
    /// See [`AppOptions::solve_continuum`].
    solve_continuum: bool,
    /// Why the force axis was just fitted again, added to the action's message when it is done.
    axis_note: Option<String>,
    /// The regime pane's continuum solution (the plate's), for the values it was solved at (the
    /// last asked for, with None until it comes).
    continuum: Option<(
        Inputs,
        Option<Result<super::effects::ContinuumSummary, String>>,
    )>,
}

impl App {
    /// The app on `options.preset`; every other problem starts on its own bundled preset.
    pub fn new(options: AppOptions) -> App {
        let state = |preset: Preset| ModelState {
            inputs: preset.inputs,
            preset,
            selected: 0,
            varied: None,
            pins: Vec::new(),
        };
        let kind = options.preset.inputs.kind();
        let mut opening = Some(options.preset);
        let states = ByProblem::from_fn(|k| match opening.take_if(|p| p.inputs.kind() == k) {
            Some(preset) => state(preset),
            None => state(preset::paper(k)),
        });
        let mut app = App {
            theme: options.theme,
            states,
            kind,
            views: Views::default(),
            mode: Mode::Normal,
            message: None,
            show_numeric: false,
            user_dir: options.user_dir,
            quit: false,
            view: View::default(),
            numeric: None,
            overlay: None,
            overlay_toggled: false,
            charts_deferred: false,
            chart_stale: false,
            measurements: options.data,
            measured_kind: kind,
            external: None,
            jobs: 0,
            asked: Vec::new(),
            undo: Vec::new(),
            redo: Vec::new(),
            last_target: "ratio=1.01".to_string(),
            force_span: ByProblem::from_fn(|_| None),
            help_page: 0,
            export_dir: PathBuf::from("."),
            y_modes: Vec::new(),
            solve_continuum: options.solve_continuum,
            continuum: None,
            axis_note: None,
        };
        app.fit_axes();
        app.recompute();
        app.refresh_view();
        app
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            inputs: ByProblem::from_fn(|kind| self.states[kind].inputs),
            kind: self.kind,
        }
    }

    fn restore(&mut self, snapshot: Snapshot) {
        for (kind, inputs) in snapshot.inputs.iter() {
            self.states[kind].inputs = *inputs;
        }
        self.kind = snapshot.kind;
    }

    /// The effects asked for outside an action (by [`App::new`]: the continuum of a plate it
    /// opens on), for the loop to perform before the first key.
    pub fn take_asked(&mut self) -> Vec<Effect> {
        std::mem::take(&mut self.asked)
    }

    /// Says why Ctrl-Z did nothing: the kernel discards a stop in a process group that no
    /// job-control shell leads (`ssh host microslip`, `sh -c`), since nothing could resume it.
    pub fn suspend_ignored(&mut self) {
        self.error("Not suspended: no job-control shell here could resume microslip (q quits)");
    }

    /// Says that `count` keys waiting to be applied were dropped because a `q` or Esc was typed
    /// behind them (nothing when none were).
    pub fn keys_dropped(&mut self, count: usize) {
        if count > 0 {
            self.info(format!(
                "dropped {count} keys still waiting to be applied: q and Esc jump a queue of keys"
            ));
        }
    }

    fn info(&mut self, text: impl Into<String>) {
        self.message = Some(Message {
            text: text.into(),
            is_error: false,
        });
    }

    fn error(&mut self, text: impl Into<String>) {
        self.message = Some(Message {
            text: text.into(),
            is_error: true,
        });
    }

    /// Whether `action` may act while the terminal is too small to draw the app: only quitting
    /// (q, Esc, Ctrl-C), answering the quit question, and suspending. Anything else would act
    /// unseen: at 1x1, `x` exported a file nobody saw.
    pub fn acts_when_too_small(&self, action: Action) -> bool {
        matches!(action, Action::Quit | Action::RequestQuit | Action::Suspend)
            || matches!(self.mode, Mode::ConfirmQuit { .. })
    }

    /// Applies one action; returns what the caller must do for it (nothing, for most keys), whose
    /// outcomes go to [`App::receive`]. Touches no file and never waits.
    pub fn update(&mut self, action: Action) -> Vec<Effect> {
        match action {
            Action::Quit => {
                self.quit = true;
                return Vec::new();
            }
            // The event loop suspends the process; nothing in the state changes.
            Action::Suspend => return Vec::new(),
            _ => {}
        }
        let undoable = !matches!(action, Action::Undo | Action::Redo);
        self.applying(undoable, |app| app.dispatch(action))
    }

    /// Applies what came of an effect (a file read, a preset saved, a fit's progress or result);
    /// returns what must be done next, like [`App::update`]. A parameter change it makes (a fit
    /// adopted, a deck's parameters) is undone by `u` like a key's.
    pub fn receive(&mut self, outcome: Outcome) -> Vec<Effect> {
        self.applying(true, |app| app.outcome(outcome))
    }

    /// Runs `change`, records the parameters before it for `u` when it changed them (and
    /// `undoable`), and hands over the effects it asked for.
    fn applying(&mut self, undoable: bool, change: impl FnOnce(&mut App)) -> Vec<Effect> {
        let before = self.snapshot();
        change(self);
        if let Some(note) = self.axis_note.take() {
            match &mut self.message {
                Some(message) => message.text = format!("{}; {note}", message.text),
                None => self.info(note),
            }
        }
        self.refresh_view();
        let after = self.snapshot();
        let changed = before.inputs != after.inputs;
        if changed && undoable {
            self.undo.push(before);
            if self.undo.len() > HISTORY {
                self.undo.remove(0);
            }
            self.redo.clear();
        }
        std::mem::take(&mut self.asked)
    }

    /// Applies what came of an effect (see [`App::receive`]).
    fn outcome(&mut self, outcome: Outcome) {
        match outcome {
            Outcome::Exported(result) => self.exported(result),
            Outcome::Saved {
                name,
                description,
                inputs,
                result,
            } => self.saved(name, description, inputs, result),
            // A read cancelled with Esc comes too late: the user has moved on.
            Outcome::Measurements { path, kind, result } => {
                if self.mode != (Mode::Loading { path: path.clone() }) {
                    return;
                }
                self.mode = Mode::Normal;
                self.measurements_read(path, kind, result);
                self.recompute();
            }
            Outcome::FeResults { path, result } => {
                if self.mode != (Mode::Loading { path: path.clone() }) {
                    return;
                }
                self.mode = Mode::Normal;
                match result {
                    Ok(loaded) => self.fe_results_read(&path, &loaded),
                    Err(reason) => self.error(reason),
                }
                self.recompute();
            }
            Outcome::Continuum { inputs, result } => {
                if self.continuum.as_ref().is_some_and(|(p, _)| *p == inputs) {
                    self.continuum = Some((inputs, Some(result)));
                }
            }
            Outcome::Preset { name, result } => match result {
                Ok(preset) => self.adopt_preset(preset),
                Err(reason) => self.error(format!("cannot load preset {name}: {reason}")),
            },
            Outcome::Presets(entries) => {
                let selected = entries
                    .iter()
                    .position(|e| e.name == self.preset_name())
                    .unwrap_or(0);
                self.mode = Mode::Presets { entries, selected };
            }
            Outcome::Completed {
                text,
                completed,
                names,
            } => self.completed(&text, &completed, &names),
            Outcome::FitProgress { job, progress } => {
                if self.mode == (Mode::Fitting { job }) {
                    self.info(format!(
                        "{} (Esc cancels)",
                        crate::report::text::fit_progress(&progress)
                    ));
                }
            }
            Outcome::Fitted { job, result } => {
                // A cancelled fit's result comes too late: the user has moved on.
                if self.mode == (Mode::Fitting { job }) {
                    self.mode = Mode::Normal;
                    self.fitted(result);
                }
            }
            Outcome::Overlay {
                inputs,
                chart,
                result,
            } => self.overlay_solved(inputs, chart, result),
        }
    }

    fn dispatch(&mut self, action: Action) {
        match std::mem::replace(&mut self.mode, Mode::Normal) {
            Mode::Normal => self.update_normal(action),
            Mode::Editing { input } => {
                if let Some(text) = self.edit(
                    input,
                    action,
                    |input| Mode::Editing { input },
                    "edit cancelled",
                ) {
                    self.commit_value(&text);
                }
            }
            Mode::Help => match action {
                Action::ToggleHelp | Action::Cancel => {}
                Action::Next => {
                    self.help_page += 1;
                    self.mode = Mode::Help;
                }
                Action::Previous => {
                    self.help_page = self.help_page.saturating_sub(1);
                    self.mode = Mode::Help;
                }
                _ => self.mode = Mode::Help,
            },
            Mode::Presets { entries, selected } => self.update_presets(entries, selected, action),
            Mode::SaveName { input } => {
                if let Some(name) = self.edit(
                    input,
                    action,
                    |input| Mode::SaveName { input },
                    "save cancelled",
                ) {
                    self.ask_description(name);
                }
            }
            Mode::SaveDescription { name, input } => {
                let prompt = name.clone();
                if let Some(description) = self.edit(
                    input,
                    action,
                    |input| Mode::SaveDescription {
                        name: prompt,
                        input,
                    },
                    "save cancelled",
                ) {
                    let description = if description.is_empty() {
                        self.default_description()
                    } else {
                        description
                    };
                    self.save(name, description, false);
                }
            }
            Mode::Command { input } => {
                if action == Action::Complete {
                    self.complete_command(input);
                } else if let Some(text) = self.edit(
                    input,
                    action,
                    |input| Mode::Command { input },
                    "command cancelled",
                ) {
                    self.run_command(&text);
                }
            }
            Mode::Message => match action {
                Action::ToggleHelp | Action::Cancel | Action::ShowMessage => {}
                _ => self.mode = Mode::Message,
            },
            Mode::DataPath { input } => {
                if let Some(path) = self.edit(
                    input,
                    action,
                    |input| Mode::DataPath { input },
                    "loading cancelled",
                ) {
                    self.load_data(path);
                }
            }
            Mode::ConfirmOverwrite { name, description } => match action {
                Action::Yes => self.save(name, description, true),
                _ => self.info("save cancelled; the existing preset is unchanged"),
            },
            Mode::ConfirmQuit { unsaved } => match action {
                Action::Yes => self.quit = true,
                Action::Cancel => self.info("not quitting; s saves the parameters as a preset"),
                _ => self.mode = Mode::ConfirmQuit { unsaved },
            },
            Mode::ConfirmReset => match action {
                Action::Yes => {
                    let preset = self.state().preset.inputs;
                    self.state_mut().inputs = preset;
                    self.info(format!(
                        "reset to preset {}; u undoes the reset",
                        self.preset_name()
                    ));
                    self.recompute();
                }
                Action::Cancel => self.info("reset cancelled; the parameters are unchanged"),
                _ => self.mode = Mode::ConfirmReset,
            },
            Mode::Target { input } => {
                if let Some(text) = self.edit(
                    input,
                    action,
                    |input| Mode::Target { input },
                    "solve cancelled",
                ) {
                    self.solve_target(&text);
                }
            }
            Mode::Explain { line } => {
                let count = self
                    .view
                    .regime
                    .as_ref()
                    .map_or(0, |r| r.explained().count());
                let count = count.max(1);
                match action {
                    Action::Next => {
                        self.mode = Mode::Explain {
                            line: (line + 1).min(count - 1),
                        }
                    }
                    Action::Previous => {
                        self.mode = Mode::Explain {
                            line: line.saturating_sub(1),
                        }
                    }
                    Action::Cancel | Action::Explain => {}
                    _ => self.mode = Mode::Explain { line },
                }
            }
            Mode::Fitting { job } => match action {
                Action::Cancel => {
                    self.info("fit cancelled; the parameters are unchanged");
                    self.asked.push(Effect::CancelFit { job });
                }
                _ => self.mode = Mode::Fitting { job },
            },
            Mode::Loading { path } => match action {
                Action::Cancel => {
                    self.info(format!("loading {path} cancelled; nothing changed"));
                    self.asked.push(Effect::Cancel { lane: Lane::Read });
                }
                _ => self.mode = Mode::Loading { path },
            },
        }
    }
}

#[cfg(test)]
mod tests;
