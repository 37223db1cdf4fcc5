//! The TUI's state and its one mutator, [`App::update`]. No drawing and no terminal here: every
//! behaviour can be tested by feeding actions and looking at the state.

use std::path::PathBuf;

use super::keymap::Context;
use super::plots::{self, NumericPoints, Plot};
use super::theme::Theme;
use crate::fit::Measurement;
use crate::preset::{self, Inputs, Model, ModelKind, ParamKey, Preset, PresetSource, SaveError};

/// What a key press asks for (see the key map).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// Leave the program.
    Quit,
    /// Next row (parameter or preset).
    Next,
    /// Previous row.
    Previous,
    /// Increase the selected parameter by a fine step.
    Increase,
    /// Decrease it by a fine step.
    Decrease,
    /// Increase by a coarse step.
    IncreaseCoarse,
    /// Decrease by a coarse step.
    DecreaseCoarse,
    /// Start typing an exact value.
    StartEdit,
    /// A typed character.
    Input(char),
    /// Delete the last typed character.
    Backspace,
    /// Accept (typed value, preset choice, name).
    Commit,
    /// Back out of the current overlay or entry.
    Cancel,
    /// Answer yes.
    Yes,
    /// Twin beams <-> plate.
    SwitchModel,
    /// Next chart of the model.
    NextChart,
    /// Previous chart.
    PreviousChart,
    /// Finite-element points on or off.
    ToggleNumeric,
    /// Help overlay on or off.
    ToggleHelp,
    /// Open the preset picker.
    OpenPresets,
    /// Save the parameters as a user preset.
    SavePreset,
    /// Back to the loaded preset's values.
    Reset,
    /// Ask for a measurement file (F_N, w_mm).
    LoadData,
    /// Fit mu and K_T to the measurements and adopt the identifiable ones.
    Fit,
}

/// A status-line message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    /// The text.
    pub text: String,
    /// True for errors (refused input, failed save).
    pub is_error: bool,
}

/// One row of the preset picker.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetEntry {
    /// Name.
    pub name: String,
    /// `bundled` or `user`.
    pub origin: &'static str,
    /// The preset, or the first problem of an invalid file.
    pub preset: Result<Preset, String>,
}

/// What has the keyboard.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    /// The main screen.
    Normal,
    /// Typing a value for the selected parameter.
    Editing {
        /// Text typed so far.
        buffer: String,
    },
    /// The help overlay.
    Help,
    /// The preset picker.
    Presets {
        /// Bundled then user presets.
        entries: Vec<PresetEntry>,
        /// Selected row.
        selected: usize,
    },
    /// Typing the name of a preset to save.
    SaveName {
        /// Text typed so far.
        buffer: String,
    },
    /// Typing the path of a measurement file.
    DataPath {
        /// Text typed so far.
        buffer: String,
    },
    /// Asking before overwriting a user preset.
    ConfirmOverwrite {
        /// The preset name.
        name: String,
    },
}

impl Mode {
    /// The key-map context of this mode.
    pub fn context(&self) -> Context {
        match self {
            Mode::Normal => Context::Main,
            Mode::Editing { .. } | Mode::SaveName { .. } | Mode::DataPath { .. } => {
                Context::TextEntry
            }
            Mode::Help => Context::Help,
            Mode::Presets { .. } => Context::Presets,
            Mode::ConfirmOverwrite { .. } => Context::Confirm,
        }
    }
}

/// Per-model state: inputs (always valid), the preset they came from, selection and chart.
#[derive(Debug, Clone, PartialEq)]
struct ModelState {
    inputs: Inputs,
    preset: Preset,
    selected: usize,
    chart: usize,
}

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
    beam: ModelState,
    plate: ModelState,
    kind: ModelKind,
    mode: Mode,
    message: Option<Message>,
    show_numeric: bool,
    user_dir: Option<PathBuf>,
    quit: bool,
    plot: Plot,
    numeric: Option<NumericPoints>,
    measurements: Option<Measurements>,
}

/// Relative fine and coarse steps of multiplicative parameters.
const FINE_FACTOR: f64 = 1.02;
const COARSE_FACTOR: f64 = 1.25;

fn bundled_preset(kind: ModelKind) -> Preset {
    let name = match kind {
        ModelKind::Beam => "paper-beams",
        ModelKind::Plate => "paper-plate",
    };
    preset::resolve(name).unwrap_or_else(|_| Preset {
        name: name.to_string(),
        description: String::new(),
        inputs: Inputs::paper(kind),
        source: PresetSource::Bundled,
    })
}

impl App {
    /// The app on `options.preset`; the other model starts on its paper preset.
    pub fn new(options: AppOptions) -> App {
        let state = |preset: Preset| ModelState {
            inputs: preset.inputs,
            preset,
            selected: 0,
            chart: 0,
        };
        let kind = options.preset.inputs.kind();
        let (beam, plate) = match kind {
            ModelKind::Beam => (
                state(options.preset),
                state(bundled_preset(ModelKind::Plate)),
            ),
            ModelKind::Plate => (
                state(bundled_preset(ModelKind::Beam)),
                state(options.preset),
            ),
        };
        let mut app = App {
            theme: options.theme,
            beam,
            plate,
            kind,
            mode: Mode::Normal,
            message: None,
            show_numeric: false,
            user_dir: options.user_dir,
            quit: false,
            plot: Plot::default(),
            numeric: None,
            measurements: options.data,
        };
        app.recompute();
        app
    }

    fn state(&self) -> &ModelState {
        match self.kind {
            ModelKind::Beam => &self.beam,
            ModelKind::Plate => &self.plate,
        }
    }

    fn state_mut(&mut self) -> &mut ModelState {
        match self.kind {
            ModelKind::Beam => &mut self.beam,
            ModelKind::Plate => &mut self.plate,
        }
    }

    /// Colours and characters.
    pub fn theme(&self) -> Theme {
        self.theme
    }

    /// The active model.
    pub fn kind(&self) -> ModelKind {
        self.kind
    }

    /// The active model's inputs (always valid).
    pub fn inputs(&self) -> Inputs {
        self.state().inputs
    }

    /// The active model, validated.
    pub fn model(&self) -> Option<Model> {
        self.state().inputs.validate().ok()
    }

    /// Name of the preset the active model came from.
    pub fn preset_name(&self) -> &str {
        &self.state().preset.name
    }

    /// True when the parameters differ from the loaded preset.
    pub fn modified(&self) -> bool {
        self.state().inputs != self.state().preset.inputs
    }

    /// Index of the selected parameter.
    pub fn selected(&self) -> usize {
        self.state().selected
    }

    /// The selected parameter's key.
    pub fn selected_key(&self) -> ParamKey {
        self.kind.keys()[self.state().selected]
    }

    /// Index of the chart shown.
    pub fn chart(&self) -> usize {
        self.state().chart
    }

    /// What has the keyboard.
    pub fn mode(&self) -> &Mode {
        &self.mode
    }

    /// The status message.
    pub fn message(&self) -> Option<&Message> {
        self.message.as_ref()
    }

    /// True once the user asked to leave.
    pub fn should_quit(&self) -> bool {
        self.quit
    }

    /// True when finite-element points are shown.
    pub fn show_numeric(&self) -> bool {
        self.show_numeric
    }

    /// Loaded measurements, if any.
    pub fn measurements(&self) -> Option<&Measurements> {
        self.measurements.as_ref()
    }

    /// The chart to draw, computed when the state last changed.
    pub fn plot(&self) -> &Plot {
        &self.plot
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

    /// Rebuilds the chart (and the finite-element points when shown) after any change.
    fn recompute(&mut self) {
        let Some(model) = self.model() else { return };
        let chart = self.state().chart;
        if self.show_numeric {
            match plots::numeric_points(&model, chart) {
                Ok(points) => self.numeric = points,
                Err(e) => {
                    self.numeric = None;
                    self.error(format!("finite elements failed: {e}"));
                }
            }
        } else {
            self.numeric = None;
        }
        let measured = self.measurements.as_ref().map(|m| m.points.as_slice());
        self.plot = plots::build(&model, chart, self.numeric.as_ref(), measured);
    }

    /// Applies one action.
    pub fn update(&mut self, action: Action) {
        if action == Action::Quit {
            self.quit = true;
            return;
        }
        match std::mem::replace(&mut self.mode, Mode::Normal) {
            Mode::Normal => self.update_normal(action),
            Mode::Editing { buffer } => self.update_editing(buffer, action),
            Mode::Help => {
                if action != Action::ToggleHelp && action != Action::Cancel {
                    self.mode = Mode::Help;
                }
            }
            Mode::Presets { entries, selected } => self.update_presets(entries, selected, action),
            Mode::SaveName { buffer } => self.update_save_name(buffer, action),
            Mode::DataPath { buffer } => match action {
                Action::Input(c) if buffer.len() < 4096 => {
                    self.mode = Mode::DataPath {
                        buffer: buffer + &c.to_string(),
                    }
                }
                Action::Backspace => {
                    let mut buffer = buffer;
                    buffer.pop();
                    self.mode = Mode::DataPath { buffer };
                }
                Action::Commit => {
                    self.load_data(buffer.trim());
                    self.recompute();
                }
                Action::Cancel => self.info("loading cancelled"),
                _ => self.mode = Mode::DataPath { buffer },
            },
            Mode::ConfirmOverwrite { name } => match action {
                Action::Yes => self.save(&name, true),
                _ => self.info("save cancelled; the existing preset is unchanged"),
            },
        }
    }

    fn update_normal(&mut self, action: Action) {
        let rows = self.kind.keys().len();
        match action {
            Action::Next => self.state_mut().selected = (self.state().selected + 1) % rows,
            Action::Previous => {
                self.state_mut().selected = (self.state().selected + rows - 1) % rows
            }
            Action::Increase => self.step(1.0, false),
            Action::Decrease => self.step(-1.0, false),
            Action::IncreaseCoarse => self.step(1.0, true),
            Action::DecreaseCoarse => self.step(-1.0, true),
            Action::StartEdit => {
                self.message = None;
                self.mode = Mode::Editing {
                    buffer: String::new(),
                };
            }
            Action::SwitchModel => {
                self.kind = match self.kind {
                    ModelKind::Beam => ModelKind::Plate,
                    ModelKind::Plate => ModelKind::Beam,
                };
                self.message = None;
                self.recompute();
            }
            Action::NextChart | Action::PreviousChart => {
                let charts = plots::chart_names(self.kind).len();
                let chart = self.state().chart;
                self.state_mut().chart = if action == Action::NextChart {
                    (chart + 1) % charts
                } else {
                    (chart + charts - 1) % charts
                };
                self.recompute();
            }
            Action::ToggleNumeric => {
                self.show_numeric = !self.show_numeric;
                self.recompute();
                if self.show_numeric && self.numeric.is_none() && self.message.is_none() {
                    self.info("no finite-element points for this chart (they show on w(L), X and u(L) charts)");
                }
            }
            Action::ToggleHelp => self.mode = Mode::Help,
            Action::OpenPresets => self.open_presets(),
            Action::SavePreset => {
                self.mode = Mode::SaveName {
                    buffer: String::new(),
                }
            }
            Action::LoadData => {
                let buffer = self
                    .measurements
                    .as_ref()
                    .map(|m| m.path.clone())
                    .unwrap_or_default();
                self.mode = Mode::DataPath { buffer };
            }
            Action::Fit => self.fit(),
            Action::Reset => {
                let preset = self.state().preset.inputs;
                self.state_mut().inputs = preset;
                self.info(format!("reset to preset {}", self.preset_name()));
                self.recompute();
            }
            _ => {}
        }
    }

    /// Reads a measurement file; problems go to the status line and keep the previous data.
    fn load_data(&mut self, path: &str) {
        let points = std::fs::read_to_string(path)
            .map_err(|e| e.to_string())
            .and_then(|text| crate::fit::data::parse(&text).map_err(|e| e.to_string()));
        match points {
            Ok(points) => {
                self.info(format!(
                    "loaded {} measurements from {path}; f fits mu and K_T",
                    points.len()
                ));
                self.measurements = Some(Measurements {
                    path: path.to_string(),
                    points,
                });
            }
            Err(reason) => self.error(format!("{path}: {reason}")),
        }
    }

    /// Fits mu and K_T of the twin beams to the measurements; adopts each estimate the data
    /// determine (identified or weakly) and says what it did.
    fn fit(&mut self) {
        let (Some(measurements), Some(Model::Beam { beams, .. })) =
            (self.measurements.clone(), self.model())
        else {
            self.error(if self.measurements.is_none() {
                "no measurements: press d to load a CSV with columns F_N,w_mm"
            } else {
                "fitting needs the twin-beam model: press m"
            });
            return;
        };
        match crate::fit::fit_twin_beams(beams.params(), &measurements.points, None, None) {
            Ok(result) => {
                let mut adopted = Vec::new();
                let mut text = Vec::new();
                for (key, estimate) in [("mu", &result.mu), ("KT", &result.kt)] {
                    let error = estimate.std_error.map_or(String::new(), |e| {
                        format!(" +- {}", crate::report::number_with(e, 2))
                    });
                    text.push(format!(
                        "{key} = {}{error} ({})",
                        crate::report::number(estimate.value),
                        estimate.status.label()
                    ));
                    if matches!(
                        estimate.status,
                        crate::fit::Status::Identified | crate::fit::Status::Weak
                    ) {
                        adopted.push((key, estimate.value));
                    }
                }
                let mut inputs = self.state().inputs;
                for (key, value) in &adopted {
                    let _ = inputs.set(key, *value);
                }
                if inputs.validate().is_ok() {
                    self.state_mut().inputs = inputs;
                }
                self.recompute();
                self.info(format!(
                    "fit: {}; RMS {} mm",
                    text.join(", "),
                    crate::report::number_with(result.rms, 3)
                ));
            }
            Err(e) => self.error(format!("fit failed: {e}")),
        }
    }

    /// Moves the selected parameter by a fine or coarse step; the result is validated like typed input.
    fn step(&mut self, direction: f64, coarse: bool) {
        let key = self.selected_key();
        let inputs = self.state().inputs;
        let Some(value) = inputs.get(key.name) else {
            return;
        };
        let next = match key.name {
            "nu" => (value + direction * if coarse { 0.05 } else { 0.005 }).clamp(0.0, 0.499),
            "F" => {
                // Additive, in steps of the Coulomb threshold, so that F can reach and leave 0.
                let threshold = match self.model() {
                    Some(Model::Beam { beams, .. }) => beams.threshold_force(),
                    _ => 1.0,
                };
                (value + direction * threshold * if coarse { 0.1 } else { 0.01 }).max(0.0)
            }
            _ => {
                let factor = match (key.name, coarse) {
                    ("KT", true) => 10f64.powf(0.25),
                    (_, true) => COARSE_FACTOR,
                    (_, false) => FINE_FACTOR,
                };
                if direction > 0.0 {
                    value * factor
                } else {
                    value / factor
                }
            }
        };
        self.set_value(key, next);
    }

    /// Sets a parameter if the model accepts it; otherwise refuses with the model's message and keeps
    /// the previous value.
    fn set_value(&mut self, key: ParamKey, value: f64) {
        let mut candidate = self.state().inputs;
        if let Err(e) = candidate.set(key.name, value) {
            self.error(e.to_string());
            return;
        }
        match candidate.validate() {
            Ok(_) => {
                self.state_mut().inputs = candidate;
                self.message = None;
                self.recompute();
            }
            Err(e) => self.error(format!(
                "{e}; kept {}",
                crate::report::number(self.inputs().get(key.name).unwrap_or(0.0))
            )),
        }
    }

    fn update_editing(&mut self, mut buffer: String, action: Action) {
        match action {
            Action::Input(c) if buffer.len() < 32 => {
                buffer.push(c);
                self.mode = Mode::Editing { buffer };
            }
            Action::Backspace => {
                buffer.pop();
                self.mode = Mode::Editing { buffer };
            }
            Action::Commit => {
                let key = self.selected_key();
                match preset::parse_number(buffer.trim()) {
                    Some(value) => self.set_value(key, value),
                    None => self.error(format!(
                        "invalid value '{}' for {}: not a finite number; kept {}",
                        buffer.trim(),
                        key.name,
                        crate::report::number(self.inputs().get(key.name).unwrap_or(0.0))
                    )),
                }
            }
            Action::Cancel => self.info("edit cancelled"),
            _ => self.mode = Mode::Editing { buffer },
        }
    }

    fn open_presets(&mut self) {
        let mut entries: Vec<PresetEntry> = preset::bundled()
            .into_iter()
            .map(|p| PresetEntry {
                name: p.name.clone(),
                origin: "bundled",
                preset: Ok(p),
            })
            .collect();
        if let Some(dir) = &self.user_dir
            && let Ok(read) = std::fs::read_dir(dir)
        {
            let mut paths: Vec<PathBuf> = read
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|e| e == "toml"))
                .collect();
            paths.sort();
            for path in paths {
                let name = path
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                let preset = Preset::load(&path).map_err(|problems| problems[0].to_string());
                entries.push(PresetEntry {
                    name,
                    origin: "user",
                    preset,
                });
            }
        }
        let selected = entries
            .iter()
            .position(|e| e.name == self.preset_name())
            .unwrap_or(0);
        self.mode = Mode::Presets { entries, selected };
    }

    fn update_presets(&mut self, entries: Vec<PresetEntry>, selected: usize, action: Action) {
        let count = entries.len().max(1);
        match action {
            Action::Next => {
                self.mode = Mode::Presets {
                    entries,
                    selected: (selected + 1) % count,
                }
            }
            Action::Previous => {
                self.mode = Mode::Presets {
                    entries,
                    selected: (selected + count - 1) % count,
                }
            }
            Action::Commit => match entries.get(selected).map(|e| &e.preset) {
                Some(Ok(preset)) => {
                    let preset = preset.clone();
                    self.kind = preset.inputs.kind();
                    let state = self.state_mut();
                    state.inputs = preset.inputs;
                    state.preset = preset;
                    self.info(format!("loaded preset {}", self.preset_name()));
                    self.recompute();
                }
                Some(Err(problem)) => {
                    self.error(format!("cannot load {}: {problem}", entries[selected].name));
                    self.mode = Mode::Presets { entries, selected };
                }
                None => {}
            },
            Action::SavePreset => {
                self.mode = Mode::SaveName {
                    buffer: String::new(),
                }
            }
            Action::Cancel => {}
            _ => self.mode = Mode::Presets { entries, selected },
        }
    }

    fn update_save_name(&mut self, mut buffer: String, action: Action) {
        match action {
            Action::Input(c) if buffer.len() < 64 => {
                buffer.push(c);
                self.mode = Mode::SaveName { buffer };
            }
            Action::Backspace => {
                buffer.pop();
                self.mode = Mode::SaveName { buffer };
            }
            Action::Commit => self.save(buffer.trim(), false),
            Action::Cancel => self.info("save cancelled"),
            _ => self.mode = Mode::SaveName { buffer },
        }
    }

    fn save(&mut self, name: &str, overwrite: bool) {
        let Some(dir) = self.user_dir.clone() else {
            self.error(SaveError::NoDirectory.to_string());
            return;
        };
        let description = format!("Saved from the microslip TUI ({} model)", self.kind);
        let text = preset::to_toml(&self.inputs(), &description);
        match preset::save_atomic(&dir, name, &text, overwrite) {
            Ok(path) => {
                let preset = Preset {
                    name: name.to_string(),
                    description,
                    inputs: self.inputs(),
                    source: PresetSource::File(path.clone()),
                };
                self.state_mut().preset = preset;
                self.info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(name)) => {
                self.message = None;
                self.mode = Mode::ConfirmOverwrite { name };
            }
            Err(e) => self.error(e.to_string()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::theme::Charset;

    fn app_with_dir(dir: Option<PathBuf>) -> App {
        App::new(AppOptions {
            theme: Theme {
                charset: Charset::Unicode,
                color: true,
            },
            preset: preset::resolve("paper-beams").unwrap(),
            user_dir: dir,
            data: None,
        })
    }

    fn app() -> App {
        app_with_dir(None)
    }

    fn typed(app: &mut App, text: &str) {
        for c in text.chars() {
            app.update(Action::Input(c));
        }
    }

    #[test]
    fn arrows_select_and_step_parameters() {
        let mut app = app();
        assert_eq!(app.selected_key().name, "L");
        app.update(Action::Previous);
        assert_eq!(app.selected_key().name, "F");
        app.update(Action::Increase);
        // F steps by 1 % of F_thre = 0.8 N.
        assert!((app.inputs().get("F").unwrap() - 100.8).abs() < 1e-9);
        app.update(Action::Next);
        app.update(Action::Next);
        assert_eq!(app.selected_key().name, "b");
        app.update(Action::IncreaseCoarse);
        assert!((app.inputs().get("b").unwrap() - 25.0).abs() < 1e-9);
        assert!(app.modified());
        app.update(Action::Reset);
        assert!(!app.modified());
    }

    #[test]
    fn force_steps_stop_at_zero() {
        let mut app = app();
        app.update(Action::Previous);
        for _ in 0..20 {
            app.update(Action::DecreaseCoarse);
        }
        assert_eq!(app.inputs().get("F"), Some(0.0));
        assert!(app.message().is_none());
    }

    #[test]
    fn typed_values_are_validated_and_bad_ones_keep_the_old_value() {
        let mut app = app();
        app.update(Action::StartEdit);
        typed(&mut app, "-5");
        app.update(Action::Commit);
        let message = app.message().unwrap();
        assert!(message.is_error);
        assert_eq!(
            message.text,
            "invalid L = -5: must be > 0 and finite (mm); kept 200"
        );
        assert_eq!(app.inputs().get("L"), Some(200.0));
        assert_eq!(app.mode(), &Mode::Normal);
        app.update(Action::StartEdit);
        typed(&mut app, "abc");
        app.update(Action::Commit);
        assert!(
            app.message()
                .unwrap()
                .text
                .starts_with("invalid value 'abc' for L: not a finite number")
        );
        app.update(Action::StartEdit);
        typed(&mut app, "3x");
        app.update(Action::Backspace);
        typed(&mut app, "50");
        app.update(Action::Commit);
        assert_eq!(app.inputs().get("L"), Some(350.0));
        app.update(Action::StartEdit);
        typed(&mut app, "1");
        app.update(Action::Cancel);
        assert_eq!(app.inputs().get("L"), Some(350.0));
    }

    #[test]
    fn switching_model_keeps_each_models_edits() {
        let mut app = app();
        app.update(Action::IncreaseCoarse);
        app.update(Action::SwitchModel);
        assert_eq!(app.kind(), ModelKind::Plate);
        assert_eq!(app.preset_name(), "paper-plate");
        assert_eq!(app.selected_key().name, "L");
        app.update(Action::SwitchModel);
        assert_eq!(app.inputs().get("L"), Some(250.0));
    }

    #[test]
    fn charts_cycle_both_ways() {
        let mut app = app();
        app.update(Action::PreviousChart);
        assert_eq!(app.chart(), plots::chart_names(ModelKind::Beam).len() - 1);
        app.update(Action::NextChart);
        assert_eq!(app.chart(), 0);
    }

    #[test]
    fn help_and_quit() {
        let mut app = app();
        app.update(Action::ToggleHelp);
        assert_eq!(app.mode(), &Mode::Help);
        app.update(Action::Next);
        assert_eq!(app.mode(), &Mode::Help);
        app.update(Action::ToggleHelp);
        assert_eq!(app.mode(), &Mode::Normal);
        app.update(Action::Quit);
        assert!(app.should_quit());
    }

    #[test]
    fn presets_load_and_save_without_clobbering() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("broken.toml"),
            "model = \"beam\"\nKT = -1\n",
        )
        .unwrap();
        let mut app = app_with_dir(Some(dir.path().to_path_buf()));
        app.update(Action::OpenPresets);
        let Mode::Presets { entries, .. } = app.mode().clone() else {
            panic!("picker not open")
        };
        let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(
            names,
            ["paper-beams", "paper-beams-soft", "paper-plate", "broken"]
        );
        app.update(Action::Next);
        app.update(Action::Commit);
        assert_eq!(app.preset_name(), "paper-beams-soft");
        assert_eq!(app.inputs().get("KT"), Some(120.0));
        // Invalid user file: refused with its problem, picker stays open.
        app.update(Action::OpenPresets);
        for _ in 0..2 {
            app.update(Action::Next);
        }
        app.update(Action::Commit);
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("cannot load broken: line 2: invalid KT = -1")
        );
        app.update(Action::Cancel);
        // Save, then save again under the same name: asked first; "no" keeps the file.
        app.update(Action::SavePreset);
        typed(&mut app, "bench");
        app.update(Action::Commit);
        let path = dir.path().join("bench.toml");
        let saved = std::fs::read_to_string(&path).unwrap();
        assert!(saved.contains("KT = 120.0"));
        app.update(Action::IncreaseCoarse);
        app.update(Action::SavePreset);
        typed(&mut app, "bench");
        app.update(Action::Commit);
        assert!(matches!(app.mode(), Mode::ConfirmOverwrite { .. }));
        app.update(Action::Cancel);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), saved);
        app.update(Action::SavePreset);
        typed(&mut app, "bench");
        app.update(Action::Commit);
        app.update(Action::Yes);
        assert!(
            std::fs::read_to_string(&path)
                .unwrap()
                .contains("L = 250.0")
        );
        assert!(app.message().unwrap().text.starts_with("saved "));
    }

    #[test]
    fn measurements_load_fit_and_set_the_parameters() {
        let dir = tempfile::tempdir().unwrap();
        let beams = crate::TwinBeams::new(crate::TwinBeamsParams {
            friction: 0.35,
            tangential_stiffness: 250.0,
            ..crate::TwinBeamsParams::PAPER
        })
        .unwrap();
        let mut csv = String::from("F_N,w_mm\n");
        for i in 1..=25 {
            let f = 12.0 * f64::from(i);
            csv.push_str(&format!(
                "{f},{}\n",
                beams
                    .regularized(crate::TipForce::new(f).unwrap())
                    .tip_deflection()
            ));
        }
        let path = dir.path().join("m.csv");
        std::fs::write(&path, csv).unwrap();
        let mut app = app();
        app.update(Action::Fit);
        assert!(app.message().unwrap().text.starts_with("no measurements"));
        app.update(Action::LoadData);
        typed(&mut app, path.to_str().unwrap());
        app.update(Action::Commit);
        assert_eq!(app.measurements().unwrap().points.len(), 25);
        assert!(app.plot().series.iter().any(|s| s.name == "measured"));
        app.update(Action::Fit);
        assert!(
            (app.inputs().get("mu").unwrap() / 0.35 - 1.0).abs() < 1e-6,
            "{:?}",
            app.message()
        );
        assert!((app.inputs().get("KT").unwrap() / 250.0 - 1.0).abs() < 1e-6);
        assert!(
            app.message().unwrap().text.starts_with("fit: mu = 0.35"),
            "{:?}",
            app.message()
        );
        // A bad file is refused with its line; the loaded data stay.
        std::fs::write(dir.path().join("bad.csv"), "F_N,w_mm\n1,x\n").unwrap();
        app.update(Action::LoadData);
        for _ in 0..200 {
            app.update(Action::Backspace);
        }
        typed(&mut app, dir.path().join("bad.csv").to_str().unwrap());
        app.update(Action::Commit);
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("line 2: 'x' in column w_mm")
        );
        assert_eq!(app.measurements().unwrap().points.len(), 25);
    }

    #[test]
    fn saving_without_a_directory_is_refused_clearly() {
        let mut app = app();
        app.update(Action::SavePreset);
        typed(&mut app, "x");
        app.update(Action::Commit);
        assert_eq!(
            app.message().unwrap().text,
            "no user preset directory: set XDG_CONFIG_HOME or HOME"
        );
    }
}
