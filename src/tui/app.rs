//! The TUI's state and its mutators: [`App::update`] applies a key's action, [`App::receive`]
//! what came of an effect. No drawing, no terminal and no file here: what needs the disk or
//! takes long (export, save, load, the preset list, file-name completion, the fit) is returned
//! as an [`Effect`] for the event loop to perform (see [`super::effects`]), so every behaviour can
//! be tested by feeding actions and outcomes and looking at the state.

use std::path::PathBuf;

use super::action::Action;
use super::effects::{Effect, ExportError, Outcome};
use super::keymap::Context;
use super::kt_table;
use super::text_input::TextInput;
use super::theme::Theme;
use super::views::{View, Views};
use crate::PlateParams;
use crate::chart::view::AnyChart;
use crate::chart::{self, NumericPoints, Plot, YMode, pins};
use crate::fit::Measurement;
use crate::kernel::params::Compact;
use crate::preset::{self, Listed, Preset, PresetSource, SaveError};
use crate::problems::inputs::{Inputs, Model};
use crate::problems::twin_beams::closed_form::BeamTheory;
use crate::problems::{BeamParam, ByProblem, ModelKind, Param};
use crate::report::{number, number_with};

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
            Mode::Fitting { .. } => Context::Working,
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
    plot: Plot,
    /// The K_T table (title and lines) when the view is the table; `plot` is empty then.
    table: Option<(&'static str, Vec<String>)>,
    numeric: Option<NumericPoints>,
    measurements: Option<Measurements>,
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
    /// The plate's continuum solution, for the values it was solved at (the last asked for, with
    /// None until it comes).
    continuum: Option<(
        PlateParams,
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
            plot: Plot::default(),
            table: None,
            numeric: None,
            measurements: options.data,
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
        app
    }

    /// The load axis of each problem's charts that run along its load: 3 times its regime scale
    /// (3 F_thre for the beams); none for a problem without a load.
    fn fit_axes(&mut self) {
        for kind in ModelKind::ALL {
            let span = kind.description().load_span;
            self.force_span[kind] = self.regime_scale_of(kind).map(|s| span * s);
        }
    }

    /// `kind`'s regime scale at its current values (F_thre for the beams), where it has one.
    fn regime_scale_of(&self, kind: ModelKind) -> Option<f64> {
        self.states[kind].inputs.validate().ok()?.regime_scale()
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

    /// Where `x` writes the exported chart (default: the working directory).
    pub fn set_export_dir(&mut self, dir: PathBuf) {
        self.export_dir = dir;
    }

    /// The file name (without extension) of the chart shown: `microslip-w-vs-f`, or after `v`
    /// `microslip-w-vs-mu`.
    fn export_stem(&self) -> String {
        let chart = match (self.varied(), self.kind) {
            (Some(param), kind) => {
                let response = kind.description().response_symbol;
                let name = param.to_string().to_ascii_lowercase();
                let name: String = name
                    .chars()
                    .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
                    .collect();
                format!("{response}-vs-{name}")
            }
            (None, kind) => self.views.of(kind).key().to_string(),
        };
        format!("microslip-{chart}")
    }

    /// `x`: asks to write the chart shown as an SVG figure and its points as CSV, under the first
    /// free name (`-2`, `-3`, ... appended); never replaces a file ([`Effect::ExportChart`]).
    fn export_chart(&mut self) {
        use crate::report::figure;
        use crate::report::table::{TableFormat, write_table};
        if self.table.is_some() {
            return self.error("x exports charts; this is a table (microslip kt prints it)");
        }
        // A figure is read away from the screen: the parameters in a caption (as `plot` writes
        // them, less the x axis's), each curve named by its own values.
        let current = self.inputs();
        let pinned: Vec<(u8, crate::Inputs)> = self
            .state()
            .pins
            .iter()
            .map(|pin| (pin.number, pin.inputs))
            .collect();
        let mut plot = pins::named_by_values(self.plot.clone(), &current, &pinned);
        let x_param = match self.varied() {
            Some(param) => Some(param),
            None => self.views.of(self.kind).chart().and_then(AnyChart::x_param),
        };
        plot.caption = Some(crate::chart::family::parameter_text(&current, &[x_param]));
        let svg = match figure::svg(&plot) {
            Ok(svg) => svg,
            Err(e) => return self.error(e.to_string()),
        };
        let mut csv = Vec::new();
        let rows = crate::report::rows::chart_rows(&self.plot);
        if let Err(e) = write_table(&mut csv, TableFormat::Csv, rows) {
            return self.error(format!("export failed: {e}"));
        }
        self.asked.push(Effect::ExportChart {
            dir: self.export_dir.clone(),
            stem: self.export_stem(),
            svg,
            csv,
        });
    }

    /// What `x` wrote, or why nothing.
    fn exported(&mut self, result: Result<PathBuf, ExportError>) {
        match result {
            Ok(svg) => self.info(format!(
                "chart exported: {} (+ .png, .pdf, .csv data)",
                svg.display()
            )),
            Err(ExportError::Failed { path, reason }) => {
                self.error(format!("cannot export to {}: {reason}", path.display()))
            }
            Err(ExportError::AllTaken { stem }) => self.error(format!(
                "export: {stem}-2 to -{} all exist; move some away",
                super::effects::MAX_EXPORT_NUMBER
            )),
        }
    }

    /// The parameter charted on the x axis, if `v` chose one.
    pub fn varied(&self) -> Option<Param> {
        self.state().varied
    }

    /// True when `param` differs from the loaded preset's value.
    pub fn is_edited(&self, param: Param) -> bool {
        self.state().inputs.get(param) != self.state().preset.inputs.get(param)
    }

    /// The page of the help shown (the drawing clamps it to the pages there are).
    pub fn help_page(&self) -> usize {
        self.help_page
    }

    /// How many changes `u` can undo and `Ctrl-R` redo.
    pub fn history(&self) -> (usize, usize) {
        (self.undo.len(), self.redo.len())
    }

    fn state(&self) -> &ModelState {
        &self.states[self.kind]
    }

    fn state_mut(&mut self) -> &mut ModelState {
        self.state_of_mut(self.kind)
    }

    fn state_of_mut(&mut self, kind: ModelKind) -> &mut ModelState {
        &mut self.states[kind]
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

    /// The models whose parameters differ from their loaded preset, as `beam (paper-beams)`.
    fn unsaved(&self) -> Vec<String> {
        self.states
            .iter()
            .filter(|(_, state)| state.inputs != state.preset.inputs)
            .map(|(kind, state)| format!("{kind} ({})", state.preset.name))
            .collect()
    }

    /// Index of the selected parameter.
    pub fn selected(&self) -> usize {
        self.state().selected
    }

    /// The selected parameter.
    pub fn selected_param(&self) -> Param {
        self.kind.params()[self.state().selected]
    }

    /// The views shown for each model.
    pub fn views(&self) -> Views {
        self.views
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

    /// The table shown in the chart pane in place of a chart (title and lines), if the view is
    /// one.
    pub fn table(&self) -> Option<&(&'static str, Vec<String>)> {
        self.table.as_ref()
    }

    /// Says why Ctrl-Z did nothing: the kernel discards a stop in a process group that no
    /// job-control shell leads (`ssh host microslip`, `sh -c`), since nothing could resume it.
    pub fn suspend_ignored(&mut self) {
        self.error("Not suspended: no job-control shell here could resume microslip (q quits)");
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

    /// What the regime pane shows of the plate's continuum solution.
    pub fn continuum(&self) -> crate::tui::summary::ContinuumState {
        use crate::tui::summary::ContinuumState;
        // Only the plate has a continuum solver of its own.
        let current = match self.model() {
            Some(Model::Plate(plate)) if self.solve_continuum => plate.params(),
            Some(Model::Plate(_) | Model::Beam { .. } | Model::Lap { .. }) | None => {
                return ContinuumState::Off;
            }
        };
        match &self.continuum {
            Some((params, Some(Ok(solved)))) if *params == current => {
                ContinuumState::Solved(*solved)
            }
            Some((params, Some(Err(e)))) if *params == current => ContinuumState::Failed(e.clone()),
            _ => ContinuumState::Solving,
        }
    }

    /// The lines of the regime pane.
    pub fn summary_lines(&self) -> Vec<crate::tui::summary::SummaryLine> {
        self.model().map_or_else(Vec::new, |m| {
            crate::tui::summary::summary_lines(&m, &self.continuum())
        })
    }

    /// The lines `i` walks through: the regime pane's title where it states an envelope, then
    /// its lines.
    pub fn explained_lines(&self) -> Vec<crate::tui::summary::SummaryLine> {
        self.model().map_or_else(Vec::new, |m| {
            crate::tui::summary::explained_lines(&m, &self.continuum())
        })
    }

    /// Asks for the plate's continuum at the current values when it is shown and not asked yet.
    fn ask_continuum(&mut self) {
        let plate = match self.model() {
            Some(Model::Plate(plate)) => plate,
            Some(Model::Beam { .. } | Model::Lap { .. }) | None => return,
        };
        let params = plate.params();
        if !self.solve_continuum || self.continuum.as_ref().is_some_and(|(p, _)| *p == params) {
            return;
        }
        self.continuum = Some((params, None));
        self.asked.push(Effect::SolveContinuum { params });
    }

    /// A problem's load axis (the beams' F), kept while values change so that the curves can be
    /// compared, is fitted again (`load_span` times the regime scale: 3 F_thre, 1 F_gross) when
    /// the regime scale leaves it or is squeezed into its first twelfth (a geometry, mu or P
    /// changed by a large factor); the status says so for the problem shown. K_T does not move F_thre: dragging it never rescales.
    fn follow_threshold(&mut self) {
        for kind in ModelKind::ALL {
            let (Some(span), Some(threshold)) = (self.force_span[kind], self.regime_scale_of(kind))
            else {
                continue;
            };
            if threshold <= span && threshold >= span / 12.0 {
                continue;
            }
            let wanted = kind.description().load_span * threshold;
            self.force_span[kind] = Some(wanted);
            let load = kind.description().load;
            let unit = load.map(Param::unit_suffix).unwrap_or_default();
            let note = format!(
                "{} axis rescaled to 0-{}{unit}: {} = {}{unit} {} the old 0-{}{unit}",
                load.map_or("", |p| p.name()),
                number(wanted),
                kind.description().regime_scale_name,
                number(threshold),
                if threshold > span {
                    "is beyond"
                } else {
                    "was squeezed into the start of"
                },
                number(span)
            );
            if self.kind == kind {
                self.axis_note = Some(note);
            }
        }
    }

    /// Rebuilds the chart (and the finite-element points when shown) after any change.
    fn recompute(&mut self) {
        self.follow_threshold();
        self.ask_continuum();
        let Some(model) = self.model() else { return };
        match (self.show_numeric, self.views.of(self.kind).chart()) {
            (true, Some(shown)) => match chart::numeric_points(&model, shown) {
                Ok(points) => self.numeric = points,
                Err(e) => {
                    self.numeric = None;
                    self.error(format!("finite elements failed: {e}"));
                }
            },
            _ => self.numeric = None,
        }
        let y_mode = self.y_mode();
        let Some(plot) = self.linear_plot(&model) else {
            // The view is the K_T table: text in the chart pane.
            self.table = Some(kt_table::stiffness_table(&model));
            self.plot = Plot::default();
            return;
        };
        self.table = None;
        let plot = y_mode.apply(plot);
        if self.state().pins.is_empty() {
            self.plot = plot;
            return;
        }
        // Each pin: the same chart at its values, in the same y mode, without the overlays, over
        // the shown chart's x range (the current F or measured points may have widened it beyond
        // the kept force span: a pin built over that span alone would stop short of the axis).
        let span = Some(plot.x.bounds[1]);
        let key = PinnedChart {
            views: self.views,
            varied: self.state().varied,
            force_span: span,
            y_mode,
        };
        for i in 0..self.state().pins.len() {
            let pin = &self.state().pins[i];
            if pin.chart.as_ref().is_some_and(|(k, _)| *k == key) {
                continue;
            }
            let built = pin
                .inputs
                .validate()
                .ok()
                .and_then(|m| self.chart_of(&m, None, None, None, span))
                .map(|plot| (key, y_mode.apply(plot)));
            self.state_mut().pins[i].chart = built;
        }
        let current = self.inputs();
        let pinned: Vec<(u8, String, &Plot)> = self
            .state()
            .pins
            .iter()
            .filter_map(|pin| {
                let (_, plot) = pin.chart.as_ref()?;
                Some((pin.number, pins::label(&pin.inputs, &current), plot))
            })
            .collect();
        self.plot = pins::add_pins(plot, &pinned);
    }

    /// The chart shown, with its y axis linear; None where the view is a table.
    fn linear_plot(&self, model: &Model) -> Option<Plot> {
        let measured = self.measurements.as_ref().map(|m| m.points.as_slice());
        let external = self.external.as_ref().map(|(points, _)| points);
        self.chart_of(
            model,
            self.numeric.as_ref(),
            measured,
            external,
            self.force_span[model.kind()],
        )
    }

    /// The chart shown (the view's, or the one against the parameter of `v`) for `model`; None
    /// where the view is a table (the v chart takes its place too).
    fn chart_of(
        &self,
        model: &Model,
        numeric: Option<&NumericPoints>,
        measured: Option<&[Measurement]>,
        external: Option<&chart::ExternalPoints>,
        force_span: Option<f64>,
    ) -> Option<Plot> {
        if let Some(param) = self.state().varied {
            return Some(chart::vary::build(model, param));
        }
        let shown = self.views.of(model.kind()).chart()?;
        Some(chart::build(
            model, shown, numeric, measured, external, force_span,
        ))
    }

    /// `g`: keeps the current parameters as a pin (the oldest goes beyond [`pins::MAX_PINS`]).
    fn pin(&mut self) {
        if self.y_key().is_none() {
            return self.error("g: a table has no curves to pin; pins show on every chart (c)");
        }
        if self.model().is_none() {
            return self.error("g: the parameters are not valid, nothing to pin");
        }
        let inputs = self.inputs();
        let kind = self.kind;
        let state = self.state_mut();
        if let Some(pin) = state.pins.iter().find(|p| p.inputs == inputs) {
            let number = pin.number;
            return self.info(format!("these values are pin {number} already"));
        }
        let dropped = if state.pins.len() >= pins::MAX_PINS {
            Some(state.pins.remove(0).number)
        } else {
            None
        };
        let number = (1..=pins::MAX_PINS as u8)
            .find(|n| state.pins.iter().all(|p| p.number != *n))
            .unwrap_or(1);
        state.pins.push(Pin {
            number,
            inputs,
            chart: None,
        });
        self.recompute();
        let replaced = dropped.map_or(String::new(), |n| {
            format!(
                " (replaces pin {n}, the oldest: at most {})",
                pins::MAX_PINS
            )
        });
        self.info(format!(
            "pin {number}{replaced}: drawn as {number}s on every {kind} chart; change a value to \
             compare, G clears"
        ));
    }

    /// `G`: removes every pin of the active model.
    fn clear_pins(&mut self) {
        let count = std::mem::take(&mut self.state_mut().pins).len();
        if count == 0 {
            return self.info("no pins to clear (g pins the curves)");
        }
        self.recompute();
        self.info(format!("{count} pin(s) cleared"));
    }

    /// Which chart the y-axis mode belongs to: the view's chart, None for the chart of `v`;
    /// tables have none (outer None).
    fn y_key(&self) -> Option<Option<AnyChart>> {
        if self.varied().is_some() {
            return Some(None);
        }
        self.views.of(self.kind).chart().map(Some)
    }

    /// The y-axis mode of the chart shown.
    pub fn y_mode(&self) -> YMode {
        let Some(key) = self.y_key() else {
            return YMode::Linear;
        };
        self.y_modes
            .iter()
            .find(|(k, _)| *k == key)
            .map_or_else(|| key.map_or(YMode::Linear, YMode::default_for), |m| m.1)
    }

    /// `y`: the next y-axis mode the chart can show.
    fn cycle_y_axis(&mut self) {
        let (Some(key), Some(model)) = (self.y_key(), self.model()) else {
            return self.error("y: a table has no y axis");
        };
        let Some(plot) = self.linear_plot(&model) else {
            return self.error("y: a table has no y axis");
        };
        let current = self.y_mode();
        let next = current.next_for(&plot);
        if next == current {
            return self.info(format!("y axis: only {} for this chart", current.label()));
        }
        self.y_modes.retain(|(k, _)| *k != key);
        self.y_modes.push((key, next));
        self.recompute();
        self.info(format!("y axis: {} (y: next mode)", next.label()));
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
            Outcome::Measurements { path, result } => {
                self.measurements_read(path, result);
                self.recompute();
            }
            Outcome::FeResults { path, result } => {
                match result {
                    Ok(loaded) => self.fe_results_read(&path, &loaded),
                    Err(reason) => self.error(reason),
                }
                self.recompute();
            }
            Outcome::Continuum { params, result } => {
                if self.continuum.as_ref().is_some_and(|(p, _)| *p == params) {
                    self.continuum = Some((params, Some(result)));
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
        }
    }

    /// Undoes (`redo` false) or redoes the last change of any problem's parameters.
    fn travel(&mut self, redo: bool) {
        let now = self.snapshot();
        let (from, to) = if redo {
            (&mut self.redo, &mut self.undo)
        } else {
            (&mut self.undo, &mut self.redo)
        };
        let Some(snapshot) = from.pop() else {
            let what = if redo { "redo" } else { "undo" };
            return self.info(format!("nothing to {what}"));
        };
        let left = from.len();
        to.push(now);
        self.restore(snapshot);
        self.recompute();
        let (done, key) = if redo {
            ("redone", "Ctrl-R")
        } else {
            ("undone", "u")
        };
        self.info(format!("{done}; {left} more with {key}"));
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
                let count = self.explained_lines().len().max(1);
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
        }
    }

    /// `t`: the value of the selected parameter at which a quantity takes the typed target; one
    /// certified root is adopted (u undoes it), anything else is said.
    fn solve_target(&mut self, text: &str) {
        use crate::study::target::{Target, solve_for_target};
        let (Some(model), param) = (self.model(), self.selected_param()) else {
            return;
        };
        self.last_target = text.to_string();
        let target = match Target::parse(text, self.kind) {
            Ok(target) => target,
            Err(e) => return self.error(e.to_string()),
        };
        let name = target.quantity.name(self.kind);
        let unit = |u: &str| {
            if u.is_empty() {
                String::new()
            } else {
                format!(" {u}")
            }
        };
        let punit = param.unit_suffix();
        match solve_for_target(&model, param, target, None) {
            Ok(solved) => match solved.roots.as_slice() {
                [root] if root.plateau => self.info(format!(
                    "{name} = {}{} for every {param} from {} to {}{punit}; nothing changed",
                    number(if root.within_rounding {
                        target.value
                    } else {
                        root.achieved
                    }),
                    if root.within_rounding {
                        " to within rounding (a limit, not a root)"
                    } else {
                        ""
                    },
                    number(root.bracket.0),
                    number(root.bracket.1)
                )),
                [root] if root.certified => {
                    self.set_value(param, root.value);
                    if self.message.is_none() {
                        self.info(format!(
                            "{param} = {}{punit} gives {name} = {}{} (certified root; u undoes)",
                            number(root.value),
                            number(root.achieved),
                            unit(target.quantity.unit(self.kind))
                        ));
                    }
                }
                roots => {
                    let values: Vec<String> = roots.iter().map(|r| number(r.value)).collect();
                    self.info(format!(
                        "{} of {param} give {name} = {}: {}{punit}; nothing changed \
                         (microslip solve --from/--to narrows the search)",
                        crate::report::count_of(roots.len(), "value"),
                        number(target.value),
                        values.join(", ")
                    ));
                }
            },
            Err(e) => self.error(e.to_string()),
        }
    }

    /// Pasted text (bracketed paste): typed into the field being edited, up to the first line
    /// break (a paste never runs keys); elsewhere it is ignored with a note. Returns true when the
    /// screen changed.
    pub fn paste(&mut self, text: &str) -> bool {
        let line = text.split(['\n', '\r']).next().unwrap_or("");
        let input = match &mut self.mode {
            Mode::Editing { input }
            | Mode::SaveName { input }
            | Mode::SaveDescription { input, .. }
            | Mode::Command { input }
            | Mode::DataPath { input } => input,
            Mode::Normal => {
                self.info("paste ignored: press Enter to type a value, then paste");
                return true;
            }
            _ => return false,
        };
        // All or nothing: a paste longer than the input takes is refused whole (as the user guide
        // says), never cut, so that a value is never entered half pasted.
        let mut trial = input.clone();
        let complete = line
            .chars()
            .filter(|c| !c.is_control())
            .all(|c| trial.push(c));
        if complete {
            *input = trial;
        }
        if !complete {
            self.error(format!(
                "paste refused: {} characters, more than the {} an input takes; nothing was pasted",
                line.chars().filter(|c| !c.is_control()).count(),
                super::text_input::MAX_CHARS
            ));
        } else if line.len() < text.trim_end_matches(['\n', '\r']).len() {
            self.info("pasted the first line only; Enter accepts it");
        }
        true
    }

    /// One key in a text-entry mode: edits stay in the mode (rebuilt by `mode`), Esc leaves it with
    /// the note `cancelled`, Enter returns the trimmed text for the caller to act on.
    fn edit(
        &mut self,
        mut input: TextInput,
        action: Action,
        mode: impl FnOnce(TextInput) -> Mode,
        cancelled: &'static str,
    ) -> Option<String> {
        match action {
            Action::Input(c) if !input.push(c) => {
                self.error(format!(
                    "input is limited to {} characters",
                    super::text_input::MAX_CHARS
                ));
            }
            Action::Input(_) => {}
            Action::Backspace => input.pop(),
            Action::Delete => input.delete(),
            Action::CursorLeft => input.move_by(-1),
            Action::CursorRight => input.move_by(1),
            Action::CursorHome => input.jump(false),
            Action::CursorEnd => input.jump(true),
            Action::ClearToStart => input.clear_to_start(),
            Action::DeleteWord => input.delete_word(),
            Action::Complete => self.asked.push(Effect::CompletePath {
                text: input.as_str().to_string(),
            }),
            Action::Commit => return Some(input.trimmed().to_string()),
            Action::Cancel => {
                self.info(cancelled);
                return None;
            }
            _ => {}
        }
        self.mode = mode(input);
        None
    }

    /// Tab's completion: applied if the prompt still holds the text completed; the status line
    /// lists the names that match.
    fn completed(&mut self, text: &str, completed: &str, names: &[String]) {
        let input = match &mut self.mode {
            Mode::Editing { input }
            | Mode::SaveName { input }
            | Mode::SaveDescription { input, .. }
            | Mode::DataPath { input }
            | Mode::Target { input } => input,
            Mode::Command { input } => {
                if input.as_str() == text {
                    input.set(completed);
                    self.completions(names, "no key, command or preset starts so");
                }
                return;
            }
            _ => return,
        };
        if input.as_str() != text {
            return;
        }
        input.set(completed);
        self.completions(names, "no file name starts so");
    }

    /// What Tab found, on the status line: nothing, the one match (no message), or the matches.
    fn completions(&mut self, names: &[String], none: &str) {
        match names.len() {
            0 => self.info(none),
            1 => self.message = None,
            n => self.info(format!(
                "{n} matches: {}",
                names.iter().take(8).cloned().collect::<Vec<_>>().join("  ")
            )),
        }
    }

    fn update_normal(&mut self, action: Action) {
        let rows = self.kind.params().len();
        match action {
            // The selection stops at the ends: a key held too long does not land on another row.
            Action::Next => self.state_mut().selected = (self.state().selected + 1).min(rows - 1),
            Action::Previous => self.state_mut().selected = self.state().selected.saturating_sub(1),
            Action::Increase => self.step(true, false),
            Action::Decrease => self.step(false, false),
            Action::IncreaseCoarse => self.step(true, true),
            Action::DecreaseCoarse => self.step(false, true),
            Action::StartEdit => {
                self.message = None;
                let value = self.inputs().get(self.selected_param()).unwrap_or(0.0);
                self.mode = Mode::Editing {
                    input: TextInput::prefilled(&Compact(value).to_string()),
                };
            }
            Action::Undo => self.travel(false),
            Action::Redo => self.travel(true),
            Action::ExportChart => self.export_chart(),
            Action::Pin => self.pin(),
            Action::ClearPins => self.clear_pins(),
            Action::CycleYAxis => self.cycle_y_axis(),
            Action::Vary => {
                let param = self.selected_param();
                let state = self.state_mut();
                state.varied = if state.varied == Some(param) {
                    None
                } else {
                    Some(param)
                };
                self.message = None;
                self.recompute();
            }
            Action::SolveTarget => {
                self.message = None;
                self.mode = Mode::Target {
                    input: TextInput::prefilled(&self.last_target),
                };
            }
            Action::Explain => self.mode = Mode::Explain { line: 0 },
            Action::FitAxes => {
                self.fit_axes();
                self.info("axes fitted to the data");
                self.recompute();
            }
            Action::SwitchModel => {
                self.kind = self.kind.next();
                self.message = None;
                self.recompute();
            }
            Action::NextChart | Action::PreviousChart => {
                let forward = action == Action::NextChart;
                // From a chart against a parameter, c goes back to the view it came from.
                if self.state_mut().varied.take().is_none() {
                    self.views = self.views.turn(self.kind, forward);
                }
                self.recompute();
            }
            Action::ToggleNumeric => {
                self.show_numeric = !self.show_numeric;
                self.recompute();
                if self.show_numeric && self.numeric.is_none() && self.message.is_none() {
                    self.info("no finite-element points for this chart (D vs F_a, P_r/P, X_r vs mu and the table have none)");
                }
                // The legend says where the first gap is; the status says why.
                if let Some(words) = self
                    .numeric
                    .as_ref()
                    .filter(|_| self.show_numeric)
                    .and_then(NumericPoints::failure_words)
                {
                    self.info(format!("finite elements: {words}"));
                }
            }
            Action::ToggleBeamTheory => match &mut self.state_mut().inputs {
                Inputs::Beam { structure, .. } => {
                    structure.theory = structure.theory.other();
                    let text = match structure.theory {
                        BeamTheory::EulerBernoulli => {
                            "beam theory: Euler-Bernoulli (the paper's; no shear deflection)"
                        }
                        BeamTheory::Timoshenko => {
                            "beam theory: Timoshenko (adds each beam's shear deflection \
                             F x / (kappa G b 2h), nu from the nu row)"
                        }
                    };
                    self.info(text);
                    self.recompute();
                }
                Inputs::Plate(_) | Inputs::Lap { .. } => {
                    self.error("the beam theory is a twin-beam setting: press m for the beams")
                }
            },
            Action::ToggleHelp => {
                self.help_page = 0;
                self.mode = Mode::Help;
            }
            Action::RequestQuit => {
                let unsaved = self.unsaved();
                if unsaved.is_empty() {
                    self.quit = true;
                } else {
                    self.message = None;
                    self.mode = Mode::ConfirmQuit {
                        unsaved: unsaved.join(", "),
                    };
                }
            }
            Action::OpenPresets => self.open_presets(),
            Action::SavePreset => {
                self.mode = Mode::SaveName {
                    input: TextInput::default(),
                }
            }
            Action::LoadData => {
                let path = self.measurements.as_ref().map_or("", |m| m.path.as_str());
                self.mode = Mode::DataPath {
                    input: TextInput::prefilled(path),
                };
            }
            Action::Fit => self.fit(),
            Action::CommandLine => {
                self.message = None;
                self.mode = Mode::Command {
                    input: TextInput::default(),
                };
            }
            Action::DropData => self.drop_data(),
            Action::ShowMessage => {
                if self.message.is_some() {
                    self.mode = Mode::Message;
                } else {
                    self.info("no message to show");
                }
            }
            Action::Reset => {
                if self.modified() {
                    self.message = None;
                    self.mode = Mode::ConfirmReset;
                } else {
                    self.info(format!(
                        "no edits: the values are preset {}",
                        self.preset_name()
                    ));
                }
            }
            Action::Input(_)
            | Action::Backspace
            | Action::Delete
            | Action::CursorLeft
            | Action::CursorRight
            | Action::CursorHome
            | Action::CursorEnd
            | Action::ClearToStart
            | Action::DeleteWord
            | Action::Complete
            | Action::Commit
            | Action::Cancel
            | Action::Yes
            | Action::Suspend
            | Action::Quit => {}
        }
    }

    /// Asks to read what `d` names: a CalculiX `.dat` (FE results, of the model its deck is), a
    /// plate CSV `KT_MPa_per_mm,u_mm` on the plate, a lap CSV `F_N,Delta_mm` on the lap joint
    /// (FE results: the TUI fits only the beams), else a measurement CSV `F_N,w_mm` for the fit.
    fn load_data(&mut self, path: String) {
        let is_dat = std::path::Path::new(&path)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("dat"));
        // A CSV is a measured force-deflection curve to fit for the beams, FE results (K_T, u(L))
        // for the plate, (F, Delta) for the lap joint.
        let measurements = match self.kind {
            ModelKind::Beam => !is_dat,
            ModelKind::Plate | ModelKind::Lap => false,
        };
        self.asked.push(if !measurements {
            Effect::ReadFeResults {
                path,
                kind: self.kind,
            }
        } else {
            Effect::ReadMeasurements { path }
        });
    }

    /// Measurements read for the fit; problems go to the status line and keep the previous data.
    fn measurements_read(&mut self, path: String, result: Result<Vec<Measurement>, String>) {
        match result {
            Ok(points) => {
                self.info(format!(
                    "loaded {} from {path}; f fits mu and K_T",
                    crate::report::count_of(points.len(), "measurement")
                ));
                self.measurements = Some(Measurements { path, points });
            }
            Err(reason) => self.error(format!("{path}: {reason}")),
        }
    }

    /// FE results: shown on the w(L) or u(L) chart, labelled with the code's name; a deck's
    /// parameters become the model's (the points mean nothing against others), and the status line
    /// gives the comparison `microslip compare` prints.
    fn fe_results_read(&mut self, path: &str, loaded: &crate::fe::load::AnyLoaded) {
        use crate::fe::load::AnyLoaded;
        let (model, header, points, code) = match loaded {
            AnyLoaded::Beam(l) => (
                ModelKind::Beam,
                l.header.as_ref(),
                l.points.iter().map(|p| (p.force, p.deflection)).collect(),
                l.header.as_ref().map_or("FE (CSV)", |_| "CalculiX"),
            ),
            AnyLoaded::Plate(l) => (
                ModelKind::Plate,
                l.header.as_ref(),
                l.points
                    .iter()
                    .map(|p| (p.stiffness, p.end_displacement))
                    .collect::<Vec<_>>(),
                l.header.as_ref().map_or("FE (CSV)", |_| "CalculiX"),
            ),
            AnyLoaded::Lap(l) => (
                ModelKind::Lap,
                l.header.as_ref(),
                l.points
                    .iter()
                    .map(|p| (p.force, p.joint_displacement))
                    .collect(),
                l.header.as_ref().map_or("FE (CSV)", |_| "CalculiX"),
            ),
        };
        let origin = header.map(|h| h.inputs);
        // Measurements were taken on the values the deck now replaces: they go (the help's rule).
        let mut dropped = String::new();
        if let Some(inputs) = origin {
            self.kind = model;
            self.state_mut().inputs = inputs;
            if let Some(m) = self.measurements.take() {
                dropped = format!(
                    "; dropped {} ({}): they were for the previous values",
                    crate::report::count_of(m.points.len(), "measurement"),
                    m.path
                );
            }
        }
        // Plate runs of the same deck but for K_T add up to a curve; anything else replaces.
        let same_plate = |previous: &Option<Inputs>| match (previous, origin) {
            (Some(Inputs::Plate(a)), Some(Inputs::Plate(b))) => {
                PlateParams {
                    tangential_stiffness: b.tangential_stiffness,
                    ..*a
                } == b
            }
            // A CSV's points (no deck), or a run of the beams: they replace.
            (
                None | Some(Inputs::Beam { .. } | Inputs::Plate(_) | Inputs::Lap { .. }),
                None | Some(Inputs::Beam { .. } | Inputs::Lap { .. }),
            )
            | (None | Some(Inputs::Beam { .. } | Inputs::Lap { .. }), Some(Inputs::Plate(_))) => {
                false
            }
        };
        let mut points: Vec<(f64, f64)> = points;
        if let Some((previous, previous_origin)) = &self.external
            && model == ModelKind::Plate
            && previous.model == model
            && same_plate(previous_origin)
        {
            points.extend(previous.points.iter().copied());
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            points.dedup_by(|a, b| a.0 == b.0);
        }
        let Some(current) = self.model() else {
            return self.error(format!("{path}: the deck's parameters are not valid"));
        };
        let summary = match (loaded, current) {
            (AnyLoaded::Beam(l), Model::Beam { beams, .. }) => {
                let comparison =
                    crate::fe::compare::compare_beams(&beams, &l.points, l.interface_mesh.as_ref());
                super::brief::beam_summary(code, &comparison)
            }
            (AnyLoaded::Plate(l), Model::Plate(plate)) => {
                let rows =
                    crate::fe::compare::compare_plate(&plate, &l.points, l.interface_mesh.as_ref());
                rows.first()
                    .map(|row| super::brief::plate_summary(code, row))
                    .unwrap_or_default()
            }
            (AnyLoaded::Lap(l), Model::Lap { joint, .. }) => {
                match crate::fe::compare::compare_lap(&joint, &l.points, l.interface_mesh.as_ref())
                {
                    Ok(rows) => super::brief::lap_summary(code, &rows),
                    Err(e) => return self.error(format!("{path}: {e}")),
                }
            }
            (AnyLoaded::Beam(_), Model::Plate(_) | Model::Lap { .. })
            | (AnyLoaded::Plate(_), Model::Beam { .. } | Model::Lap { .. })
            | (AnyLoaded::Lap(_), Model::Beam { .. } | Model::Plate(_)) => {
                format!("{path}: FE results of another problem: press m")
            }
        };
        let adopted = if origin.is_some() {
            " (deck parameters adopted)"
        } else {
            ""
        };
        self.info(format!("{path}{adopted}: {summary}{dropped}"));
        self.external = Some((
            chart::ExternalPoints {
                label: code.to_string(),
                model,
                points,
            },
            origin,
        ));
        // The external points are of the problem's response: its first chart.
        self.views = self.views.with(model, View::first(model));
    }

    /// `f`: asks to fit mu and K_T of the twin beams to the measurements ([`Effect::Fit`]), in
    /// [`Mode::Fitting`] until the result comes (or Esc cancels).
    fn fit(&mut self) {
        if self.kind == ModelKind::Lap {
            return self.error(
                "the terminal UI fits the twin beams; for the lap joint run `microslip fit lap \
                 DATA.csv` (columns F_N,Delta_mm)",
            );
        }
        let Some(measurements) = &self.measurements else {
            return self.error("no measurements: press d to load a CSV with columns F_N,w_mm");
        };
        // The fit identifies mu and K_T from a force-deflection curve: the beams'.
        let beams = match self.model() {
            Some(Model::Beam { beams, .. }) => beams,
            Some(Model::Plate(_) | Model::Lap { .. }) => {
                return self.error("fitting needs the twin-beam model: press m");
            }
            None => return self.error("the parameters are not valid: nothing to fit"),
        };
        self.jobs += 1;
        self.asked.push(Effect::Fit {
            job: self.jobs,
            structure: beams.params(),
            points: measurements.points.clone(),
        });
        self.mode = Mode::Fitting { job: self.jobs };
    }

    /// A fit's result: adopts each estimate the data determine (identified or weakly) and says
    /// what it did.
    fn fitted(&mut self, fitted: Result<crate::fit::FitResult, crate::fit::FitError>) {
        match fitted {
            Ok(result) => {
                let mut inputs = self.state().inputs;
                let mut text = Vec::new();
                for (param, estimate) in [
                    (BeamParam::Friction, &result.mu),
                    (BeamParam::Stiffness, &result.kt),
                ] {
                    let error = estimate
                        .std_error
                        .map_or(String::new(), |e| format!(" +- {}", number_with(e, 2)));
                    text.push(format!(
                        "{param} = {}{error} ({})",
                        number(estimate.value),
                        estimate.status.label()
                    ));
                    if matches!(
                        estimate.status,
                        crate::fit::Status::Identified | crate::fit::Status::Weak
                    ) {
                        let _ = inputs.set(Param::Beam(param), estimate.value);
                    }
                }
                if inputs.validate().is_ok() {
                    self.state_mut().inputs = inputs;
                }
                self.recompute();
                self.info(format!(
                    "fit: {}; RMS {} mm",
                    text.join(", "),
                    number_with(result.rms, 3)
                ));
            }
            Err(e) => self.error(format!("fit failed: {e}")),
        }
    }

    /// Moves the selected parameter by its fine or coarse step; the result is validated like typed
    /// input.
    fn step(&mut self, up: bool, coarse: bool) {
        let param = self.selected_param();
        let Some(value) = self.inputs().get(param) else {
            return;
        };
        // The force steps in fractions of its regime scale (F_thre, F_gross).
        let scale = self.regime_scale_of(self.kind).unwrap_or(1.0);
        // A step stops at the edge of the accepted domain rather than being refused there.
        // The lap joint's F stops at F_gross, and L, b, P, mu where F_gross falls to F.
        let spec = param.spec();
        let (lo, hi) = self
            .model()
            .map_or((spec.domain.min(), spec.domain.max()), |m| {
                m.accepted_range(param)
            });
        let stepped = spec.domain.clamp(spec.scale.step(value, up, coarse, scale));
        let next = stepped.clamp(lo, hi);
        if next == value && stepped != value {
            // Held by the other values, not by its own domain: say so rather than do nothing.
            return self.info(format!(
                "{param} stops at {}{}: F must not exceed F_gross = 2 b mu P L",
                number(value),
                param.unit_suffix()
            ));
        }
        self.set_value(param, next);
    }

    /// Sets a parameter if the model accepts it; otherwise refuses with the model's message and keeps
    /// the previous value.
    fn set_value(&mut self, param: Param, value: f64) {
        let mut candidate = self.state().inputs;
        if let Err(e) = candidate.set(param, value) {
            self.error(e.to_string());
            return;
        }
        match candidate.validate() {
            Ok(_) => {
                self.state_mut().inputs = candidate;
                self.message = None;
                if let Some(warning) = param.unusual(value) {
                    self.error(format!("accepted, but {warning}; u undoes"));
                }
                self.recompute();
            }
            Err(e) => self.error(format!("{e}; kept {}", self.current_value(param))),
        }
    }

    /// The parameter's current value, as the status line shows it.
    fn current_value(&self, param: Param) -> String {
        number(self.inputs().get(param).unwrap_or(0.0))
    }

    /// Enter in the value field: parse, then set like a step.
    fn commit_value(&mut self, text: &str) {
        let param = self.selected_param();
        match crate::preset::parse_value(param, text) {
            Ok(value) => self.set_value(param, value),
            Err(e) => self.error(format!("{e}; kept {}", self.current_value(param))),
        }
    }

    /// `p`: asks for the presets; the picker opens with them ([`Outcome::Presets`]).
    fn open_presets(&mut self) {
        self.asked.push(Effect::ListPresets {
            user_dir: self.user_dir.clone(),
        });
    }

    fn update_presets(&mut self, entries: Vec<Listed>, selected: usize, action: Action) {
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
                Some(Ok(preset)) => self.adopt_preset(preset.clone()),
                Some(Err(problem)) => {
                    self.error(format!("cannot load {}: {problem}", entries[selected].name));
                    self.mode = Mode::Presets { entries, selected };
                }
                None => {}
            },
            Action::SavePreset => {
                self.mode = Mode::SaveName {
                    input: TextInput::default(),
                }
            }
            Action::Cancel => {}
            _ => self.mode = Mode::Presets { entries, selected },
        }
    }

    /// A preset loaded (picked, or named after `:preset`): its model becomes the active one, with
    /// its values. Loaded data go: measurements and FE results belong to the bench they were
    /// loaded for (the rule the help states).
    fn adopt_preset(&mut self, preset: Preset) {
        self.kind = preset.inputs.kind();
        let state = self.state_mut();
        state.inputs = preset.inputs;
        state.preset = preset;
        let dropped = self.forget_data();
        self.fit_axes();
        self.recompute();
        let dropped = if dropped.is_empty() {
            String::new()
        } else {
            format!("; dropped {dropped} (they were for the previous values; d loads again)")
        };
        self.info(format!("loaded preset {}{dropped}", self.preset_name()));
    }

    /// Forgets the measurements and FE results; says what went, as `25 measurements and the
    /// CalculiX points` (empty when nothing was loaded).
    fn forget_data(&mut self) -> String {
        let measured = self.measurements.take().map(|m| {
            format!(
                "{} ({})",
                crate::report::count_of(m.points.len(), "measurement"),
                m.path
            )
        });
        let external = self
            .external
            .take()
            .map(|(points, _)| format!("the {} points", points.label));
        [measured, external]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join(" and ")
    }

    /// `D`: drops the loaded measurements and FE results.
    fn drop_data(&mut self) {
        let dropped = self.forget_data();
        if dropped.is_empty() {
            return self.info("no loaded data to drop (d loads measurements or FE results)");
        }
        self.recompute();
        self.info(format!("dropped {dropped}; d loads again"));
    }

    /// After the name of `s`: asks for the preset's description, prefilled with the loaded
    /// preset's own when the name is the one it was loaded from, else with the default one.
    fn ask_description(&mut self, name: String) {
        if self.user_dir.is_none() {
            return self.error(SaveError::NoDirectory.to_string());
        }
        // The name first: refused after the description, it would throw the description away.
        if let Err(e) = preset::check_name(&name) {
            return self.error(e.to_string());
        }
        let preset = &self.state().preset;
        let description = if preset.name == name && !preset.description.is_empty() {
            preset.description.clone()
        } else {
            self.default_description()
        };
        self.mode = Mode::SaveDescription {
            name,
            input: TextInput::prefilled(&description),
        };
    }

    /// The description of a preset saved without one.
    fn default_description(&self) -> String {
        format!(
            "Saved from the microslip TUI ({} model, from {})",
            self.kind,
            self.preset_name()
        )
    }

    /// Tab in the command line: keys and command words at once, preset names through the disk.
    fn complete_command(&mut self, input: TextInput) {
        let text = input.as_str().to_string();
        self.mode = Mode::Command { input };
        if let Some(prefix) = super::command::completes_preset(&text) {
            self.asked.push(Effect::CompletePreset {
                prefix: prefix.to_string(),
                text,
                user_dir: self.user_dir.clone(),
            });
            return;
        }
        let (completed, names) = super::command::complete(&text, self.kind);
        self.completed(&text, &completed, &names);
    }

    /// Enter in the command line.
    fn run_command(&mut self, text: &str) {
        use super::command::{Command, parse};
        match parse(text) {
            Err(e) => self.error(e),
            Ok(Command::Set(assignments)) => self.set_values(&assignments),
            Ok(Command::Preset(None)) => self.open_presets(),
            Ok(Command::Preset(Some(name))) => self.asked.push(Effect::LoadPreset {
                name,
                user_dir: self.user_dir.clone(),
            }),
            Ok(Command::Save(None)) => {
                self.mode = Mode::SaveName {
                    input: TextInput::default(),
                }
            }
            Ok(Command::Save(Some(name))) => self.ask_description(name),
            Ok(Command::Export) => self.export_chart(),
            Ok(Command::Drop) => self.drop_data(),
            Ok(Command::Help) => {
                self.help_page = 0;
                self.mode = Mode::Help;
            }
            Ok(Command::Quit) => self.update_normal(Action::RequestQuit),
        }
    }

    /// `:KT=250 mu=0.2`: every value set, or none (the first refusal is said, as `--set` says
    /// it); one undo step.
    fn set_values(&mut self, assignments: &[String]) {
        let mut candidate = self.state().inputs;
        for assignment in assignments {
            if let Err(e) = preset::apply_assignment(&mut candidate, assignment) {
                return self.error(format!("{assignment}: {e}; nothing changed"));
            }
        }
        if let Err(e) = candidate.validate() {
            return self.error(format!("{e}; nothing changed"));
        }
        let warnings: Vec<String> = self
            .kind
            .params()
            .iter()
            .filter(|&&p| candidate.get(p) != self.inputs().get(p))
            .filter_map(|&p| p.unusual(candidate.get(p)?))
            .collect();
        let changed = self
            .kind
            .params()
            .iter()
            .filter(|&&p| candidate.get(p) != self.inputs().get(p))
            .map(|&p| {
                let value = number(candidate.get(p).unwrap_or(0.0));
                format!("{p} = {value}{}", p.unit_suffix())
            })
            .collect::<Vec<_>>();
        self.state_mut().inputs = candidate;
        self.recompute();
        if changed.is_empty() {
            return self.info("those are the values already; nothing changed");
        }
        if warnings.is_empty() {
            self.info(format!("set {} (u undoes)", changed.join(", ")));
        } else {
            self.error(format!(
                "set {}, but {} (u undoes)",
                changed.join(", "),
                warnings.join("; ")
            ));
        }
    }

    /// Asks to save the parameters as the user preset `name` (replacing one only if `overwrite`).
    fn save(&mut self, name: String, description: String, overwrite: bool) {
        let Some(dir) = self.user_dir.clone() else {
            self.error(SaveError::NoDirectory.to_string());
            return;
        };
        let inputs = self.inputs();
        self.asked.push(Effect::SavePreset {
            dir,
            name,
            text: preset::to_toml(&inputs, &description),
            description,
            inputs,
            overwrite,
        });
    }

    /// A preset saved: the model now comes from it. One of that name exists: asks before
    /// replacing it.
    fn saved(
        &mut self,
        name: String,
        description: String,
        inputs: Inputs,
        result: Result<PathBuf, SaveError>,
    ) {
        match result {
            Ok(path) => {
                self.info(format!("saved {}", path.display()));
                self.state_of_mut(inputs.kind()).preset = Preset {
                    name,
                    description,
                    inputs,
                    source: PresetSource::File(path),
                };
            }
            Err(SaveError::Exists(name)) => {
                self.message = None;
                self.mode = Mode::ConfirmOverwrite { name, description };
            }
            Err(e) => self.error(e.to_string()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::theme::Charset;

    const L: Param = Param::Beam(BeamParam::Length);
    const B: Param = Param::Beam(BeamParam::Width);
    const MU: Param = Param::Beam(BeamParam::Friction);
    const KT: Param = Param::Beam(BeamParam::Stiffness);
    const F: Param = Param::Beam(BeamParam::Force);

    fn app_with_dir(dir: Option<PathBuf>) -> App {
        App::new(AppOptions {
            theme: Theme {
                charset: Charset::Unicode,
                color: true,
            },
            preset: preset::resolve("paper-beams").unwrap(),
            user_dir: dir,
            data: None,
            solve_continuum: false,
        })
    }

    fn app() -> App {
        app_with_dir(None)
    }

    /// 25 deflections of the paper's beams with mu = 0.35 and K_T = 250 MPa/mm, 12 N to 300 N.
    fn measured() -> Vec<Measurement> {
        let beams = crate::TwinBeams::new(crate::TwinBeamsParams {
            friction: 0.35,
            tangential_stiffness: 250.0,
            ..crate::TwinBeamsParams::PAPER
        })
        .unwrap();
        (1..=25)
            .map(|i| {
                let force = 12.0 * f64::from(i);
                let deflection = beams
                    .regularized(crate::TipForce::new(force).unwrap())
                    .tip_deflection();
                Measurement {
                    force,
                    response: deflection,
                }
            })
            .collect()
    }

    /// A key, and what it asks for done at once (files read and written, the fit run).
    fn press(app: &mut App, action: Action) {
        crate::tui::effects::update_blocking(app, action);
    }

    /// Selects the row of `name` with j/k.
    fn select(app: &mut App, name: &str) {
        for _ in 0..10 {
            app.update(Action::Previous);
        }
        while app.selected_param().name() != name {
            app.update(Action::Next);
        }
    }

    fn typed(app: &mut App, text: &str) {
        for c in text.chars() {
            app.update(Action::Input(c));
        }
    }

    /// The pinned series of the chart shown: (number, name).
    fn pinned(app: &App) -> Vec<(u8, String)> {
        app.plot()
            .series
            .iter()
            .filter_map(|s| match s.kind() {
                chart::SeriesKind::Pin(n) => Some((n, s.name.clone())),
                _ => None,
            })
            .collect()
    }

    fn set_typed(app: &mut App, name: &str, value: &str) {
        select(app, name);
        app.update(Action::StartEdit);
        typed(app, value);
        app.update(Action::Commit);
    }

    /// A pin kept at F = 100 N, then F raised to 252 N: the force axis grows to 1.25 F = 315 N
    /// and the pinned curve runs to its end (it stopped at 240 N, 3 F_thre, before).
    #[test]
    fn a_pinned_curve_spans_the_whole_force_axis() {
        let mut app = app();
        app.update(Action::Pin);
        set_typed(&mut app, "F", "252");
        let plot = app.plot();
        assert_eq!(plot.x.bounds[1], 315.0);
        let pin = plot
            .series
            .iter()
            .find(|s| s.kind() == chart::SeriesKind::Pin(1));
        let last = pin.and_then(|s| s.points.last()).expect("a pinned curve");
        assert_eq!(last.0, 315.0);
    }

    #[test]
    fn pins_keep_values_follow_the_charts_and_are_named_by_what_differs() {
        let mut app = app();
        app.update(Action::Pin);
        assert_eq!(pinned(&app), [(1, "pin 1: = current".to_string())]);
        set_typed(&mut app, "mu", "0.2");
        assert_eq!(pinned(&app), [(1, "pin 1: mu 0.3->0.2".to_string())]);
        // The same values twice: one pin.
        app.update(Action::Pin);
        app.update(Action::Pin);
        assert_eq!(pinned(&app).len(), 2);
        assert!(app.message().unwrap().text.contains("pin 2 already"));
        // Every chart of the model shows them, the table refuses to pin, the plate has its own.
        for _ in 0..4 {
            app.update(Action::NextChart);
            assert_eq!(pinned(&app).len(), 2, "{}", app.plot().title);
        }
        app.update(Action::NextChart);
        assert!(app.table().is_some());
        app.update(Action::Pin);
        assert!(app.message().unwrap().is_error);
        app.update(Action::NextChart);
        app.update(Action::SwitchModel);
        assert!(pinned(&app).is_empty());
        app.update(Action::SwitchModel);
        assert_eq!(app.kind(), ModelKind::Lap);
        assert!(pinned(&app).is_empty());
        app.update(Action::SwitchModel);
        assert_eq!(pinned(&app).len(), 2);
        // A fifth pin replaces the oldest, and its number is free again.
        for mu in ["0.25", "0.35"] {
            set_typed(&mut app, "mu", mu);
            app.update(Action::Pin);
        }
        let numbers: Vec<u8> = pinned(&app).iter().map(|p| p.0).collect();
        assert_eq!(numbers, [1, 2, 3, 4]);
        set_typed(&mut app, "mu", "0.4");
        app.update(Action::Pin);
        assert!(app.message().unwrap().text.contains("replaces pin 1"));
        set_typed(&mut app, "mu", "0.5");
        let names: Vec<String> = pinned(&app).into_iter().map(|p| p.1).collect();
        assert_eq!(
            names,
            [
                "pin 2: mu 0.2->0.5",
                "pin 3: mu 0.25->0.5",
                "pin 4: mu 0.35->0.5",
                "pin 1: mu 0.4->0.5",
            ]
        );
        app.update(Action::ClearPins);
        assert!(pinned(&app).is_empty());
        assert!(app.message().unwrap().text.contains("4 pin(s) cleared"));
    }

    #[test]
    fn arrows_select_and_step_parameters() {
        let mut app = app();
        assert_eq!(app.selected_param().name(), "L");
        // The selection does not wrap from the first row to the last, nor back.
        app.update(Action::Previous);
        assert_eq!(app.selected_param().name(), "L");
        select(&mut app, "F");
        app.update(Action::Next);
        assert_eq!(app.selected_param().name(), "F");
        app.update(Action::Increase);
        // F steps by 1 % of F_thre = 0.8 N.
        assert!((app.inputs().get(F).unwrap() - 100.8).abs() < 1e-9);
        select(&mut app, "b");
        app.update(Action::IncreaseCoarse);
        assert!((app.inputs().get(B).unwrap() - 25.0).abs() < 1e-9);
        assert!(app.modified());
        assert!(app.is_edited(B) && !app.is_edited(L));
        // Reset asks first; no keeps the edits, yes resets, u undoes the reset.
        app.update(Action::Reset);
        assert_eq!(app.mode(), &Mode::ConfirmReset);
        app.update(Action::Cancel);
        assert!(app.modified());
        app.update(Action::Reset);
        app.update(Action::Yes);
        assert!(!app.modified());
        app.update(Action::Undo);
        assert!((app.inputs().get(B).unwrap() - 25.0).abs() < 1e-9);
    }

    #[test]
    fn steps_stop_at_the_edge_of_the_domain() {
        let mut app = app();
        select(&mut app, "KT");
        let max = BeamParam::Stiffness.spec().domain.max();
        for _ in 0..200 {
            app.update(Action::IncreaseCoarse);
        }
        assert_eq!(app.inputs().get(KT), Some(max));
        // 1e12 MPa/mm is accepted, with a warning: far outside the usual range.
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("far outside the usual range"),
            "{:?}",
            app.message()
        );
    }

    #[test]
    fn force_steps_stop_at_zero() {
        let mut app = app();
        select(&mut app, "F");
        for _ in 0..20 {
            app.update(Action::DecreaseCoarse);
        }
        assert_eq!(app.inputs().get(F), Some(0.0));
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
        assert_eq!(app.inputs().get(L), Some(200.0));
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
        assert_eq!(app.inputs().get(L), Some(350.0));
        app.update(Action::StartEdit);
        typed(&mut app, "1");
        app.update(Action::Cancel);
        assert_eq!(app.inputs().get(L), Some(350.0));
    }

    #[test]
    fn undo_and_redo_walk_a_bounded_history_of_both_models() {
        let mut app = app();
        app.update(Action::Undo);
        assert_eq!(app.message().unwrap().text, "nothing to undo");
        app.update(Action::IncreaseCoarse); // L 250
        app.update(Action::SwitchModel);
        app.update(Action::IncreaseCoarse); // plate L 12.5
        app.update(Action::SwitchModel); // the lap joint, unchanged
        app.update(Action::SwitchModel);
        app.update(Action::IncreaseCoarse); // L 312.5
        assert_eq!(app.history(), (3, 0));
        app.update(Action::Undo);
        assert_eq!(app.inputs().get(L), Some(250.0));
        // Undoing the plate's change shows the plate.
        app.update(Action::Undo);
        assert_eq!(app.kind(), ModelKind::Plate);
        assert_eq!(
            app.inputs()
                .get(Param::Plate(crate::PlateParam::HalfLength)),
            Some(10.0)
        );
        app.update(Action::Undo);
        assert_eq!(app.kind(), ModelKind::Beam);
        assert_eq!(app.inputs().get(L), Some(200.0));
        app.update(Action::Redo);
        app.update(Action::Redo);
        assert_eq!(app.kind(), ModelKind::Beam);
        assert_eq!(app.inputs().get(L), Some(250.0));
        // A new change forgets what could be redone.
        app.update(Action::Increase);
        assert_eq!(app.history(), (3, 0));
        for _ in 0..2 * HISTORY {
            app.update(Action::Increase);
        }
        assert_eq!(app.history().0, HISTORY);
    }

    #[test]
    fn typing_replaces_the_prefilled_value_and_unusual_values_warn() {
        let mut app = app();
        select(&mut app, "mu");
        app.update(Action::StartEdit);
        let Mode::Editing { input } = app.mode() else {
            panic!()
        };
        assert_eq!(input.shown(), "[0.3]");
        typed(&mut app, "4.5");
        app.update(Action::Commit);
        assert_eq!(app.inputs().get(MU), Some(4.5));
        let message = app.message().unwrap();
        assert!(message.is_error && message.text.contains("mu = 4.5 is far outside"));
        // Outside the domain: refused, as before.
        app.update(Action::StartEdit);
        typed(&mut app, "450");
        app.update(Action::Commit);
        assert_eq!(app.inputs().get(MU), Some(4.5));
        app.update(Action::Undo);
        assert_eq!(app.inputs().get(MU), Some(0.3));
    }

    #[test]
    fn v_charts_the_response_against_the_selected_row_and_t_solves_it() {
        let mut app = app();
        select(&mut app, "mu");
        app.update(Action::Vary);
        assert_eq!(app.varied(), Some(MU));
        assert!(app.plot().title.starts_with("w(L) vs mu"));
        app.update(Action::NextChart);
        assert_eq!(app.varied(), None);
        assert_eq!(
            app.views().of(ModelKind::Beam).position(ModelKind::Beam).0,
            1
        );
        // t on K_T with the offered target ratio=1.01: the smallest K_T within 1 % of Coulomb.
        select(&mut app, "KT");
        app.update(Action::SolveTarget);
        app.update(Action::Commit);
        let kt = app.inputs().get(KT).unwrap();
        assert!((kt - 423.12).abs() < 0.01, "{kt} {:?}", app.message());
        assert!(app.message().unwrap().text.contains("certified root"));
        app.update(Action::Undo);
        assert_eq!(app.inputs().get(KT), Some(600.0));
        // No root: said, nothing changed.
        app.update(Action::SolveTarget);
        typed(&mut app, "ratio=0.5");
        app.update(Action::Commit);
        assert!(app.message().unwrap().is_error);
        assert_eq!(app.inputs().get(KT), Some(600.0));
    }

    #[test]
    fn the_force_axis_stays_when_mu_changes_until_a_fits_it() {
        let mut app = app();
        let before = app.plot().x.bounds;
        select(&mut app, "mu");
        app.update(Action::DecreaseCoarse);
        assert_eq!(app.plot().x.bounds, before, "the x range jumped");
        app.update(Action::FitAxes);
        // 3 F_thre of mu = 0.3 / 1.25: 192 N instead of 240 N.
        assert!(
            (app.plot().x.bounds[1] - 192.0).abs() < 1e-9,
            "{:?}",
            app.plot().x
        );
    }

    #[test]
    fn i_walks_through_the_lines_of_the_regime_pane() {
        let mut app = app();
        app.update(Action::Explain);
        assert_eq!(app.mode(), &Mode::Explain { line: 0 });
        for _ in 0..50 {
            app.update(Action::Next);
        }
        let count = app.explained_lines().len();
        assert_eq!(app.summary_lines().len() + 1, count, "the title first");
        assert_eq!(app.mode(), &Mode::Explain { line: count - 1 });
        app.update(Action::Cancel);
        assert_eq!(app.mode(), &Mode::Normal);
    }

    /// The lap joint's F stops at F_gross and its mu where F_gross falls to F, and says why.
    #[test]
    fn lap_steps_stop_where_the_joint_would_slide_through() {
        let mut app = app();
        app.update(Action::SwitchModel);
        app.update(Action::SwitchModel);
        assert_eq!(app.kind(), ModelKind::Lap);
        let force = Param::Lap(crate::problems::LapParam::Force);
        let mu = Param::Lap(crate::problems::LapParam::Friction);
        while app.selected_param() != force {
            app.update(Action::Next);
        }
        for _ in 0..20 {
            app.update(Action::IncreaseCoarse);
        }
        assert_eq!(app.inputs().get(force), Some(6000.0));
        assert!(app.message().unwrap().text.starts_with("F stops at 6000 N"));
        while app.selected_param() != mu {
            app.update(Action::Previous);
        }
        for _ in 0..20 {
            app.update(Action::DecreaseCoarse);
        }
        let lowest = app.inputs().get(mu).unwrap();
        assert!((lowest - 0.3).abs() < 1e-12, "{lowest}");
        assert!(app.message().unwrap().text.starts_with("mu stops at 0.3"));
        assert!(app.model().is_some());
    }

    #[test]
    fn switching_model_keeps_each_models_edits() {
        let mut app = app();
        app.update(Action::IncreaseCoarse);
        app.update(Action::SwitchModel);
        assert_eq!(app.kind(), ModelKind::Plate);
        assert_eq!(app.preset_name(), "paper-plate");
        assert_eq!(app.selected_param().name(), "L");
        app.update(Action::SwitchModel);
        assert_eq!(app.kind(), ModelKind::Lap);
        assert_eq!(app.preset_name(), "lap-aluminium");
        app.update(Action::SwitchModel);
        assert_eq!(app.inputs().get(L), Some(250.0));
    }

    #[test]
    fn charts_cycle_both_ways() {
        let mut app = app();
        app.update(Action::PreviousChart);
        let (position, count) = app.views().of(ModelKind::Beam).position(ModelKind::Beam);
        assert_eq!(position, count);
        assert!(count > 1);
        app.update(Action::NextChart);
        assert_eq!(
            app.views().of(ModelKind::Beam).position(ModelKind::Beam).0,
            1
        );
    }

    #[test]
    fn a_paste_longer_than_an_input_takes_is_refused_whole() {
        let mut app = app();
        select(&mut app, "F");
        app.update(Action::StartEdit);
        assert!(app.paste("12"));
        assert!(app.paste(&"9".repeat(5000)));
        let message = app.message().unwrap().text.clone();
        assert!(
            message.starts_with("paste refused: 5000 characters"),
            "{message}"
        );
        app.update(Action::Commit);
        assert_eq!(
            app.inputs().get(F),
            Some(12.0),
            "the earlier text, untouched"
        );
    }

    #[test]
    fn pastes_are_text_up_to_the_first_line_break_and_never_keys() {
        let mut app = app();
        select(&mut app, "F");
        app.update(Action::StartEdit);
        assert!(app.paste("150\nq\n"));
        assert!(!app.should_quit());
        app.update(Action::Commit);
        assert_eq!(app.inputs().get(F), Some(150.0));
        assert!(app.paste("q"));
        assert!(!app.should_quit());
        assert!(app.message().unwrap().text.starts_with("paste ignored"));
    }

    #[test]
    fn quitting_with_unsaved_edits_asks_first() {
        let mut app = app();
        app.update(Action::RequestQuit);
        assert!(app.should_quit(), "nothing edited: quits at once");
        let mut app = app_with_dir(None);
        app.update(Action::Increase);
        app.update(Action::SwitchModel);
        app.update(Action::RequestQuit);
        let Mode::ConfirmQuit { unsaved } = app.mode().clone() else {
            panic!("no question: {:?}", app.mode())
        };
        assert_eq!(unsaved, "beam (paper-beams)");
        app.update(Action::Cancel);
        assert!(!app.should_quit());
        app.update(Action::RequestQuit);
        app.update(Action::Yes);
        assert!(app.should_quit());
        // Ctrl-C never asks.
        let mut app = app_with_dir(None);
        app.update(Action::Increase);
        app.update(Action::Quit);
        assert!(app.should_quit());
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
    fn a_refused_preset_name_is_refused_before_the_description_is_asked() {
        let dir = tempfile::tempdir().unwrap();
        for via_command in [true, false] {
            let mut app = app_with_dir(Some(dir.path().to_path_buf()));
            if via_command {
                press(&mut app, Action::CommandLine);
                typed(&mut app, "save ../x");
            } else {
                press(&mut app, Action::SavePreset);
                typed(&mut app, "paper-beams");
            }
            press(&mut app, Action::Commit);
            assert!(
                !matches!(app.mode(), Mode::SaveDescription { .. }),
                "{:?}",
                app.mode()
            );
            let message = app.message().unwrap();
            assert!(message.is_error, "{}", message.text);
        }
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
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
        press(&mut app, Action::OpenPresets);
        let Mode::Presets { entries, .. } = app.mode().clone() else {
            panic!("picker not open")
        };
        let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "paper-beams",
                "paper-beams-soft",
                "paper-plate",
                "lap-aluminium",
                "broken"
            ]
        );
        press(&mut app, Action::Next);
        press(&mut app, Action::Commit);
        assert_eq!(app.preset_name(), "paper-beams-soft");
        assert_eq!(app.inputs().get(KT), Some(120.0));
        // Invalid user file: refused with its problem, picker stays open.
        press(&mut app, Action::OpenPresets);
        for _ in 0..3 {
            press(&mut app, Action::Next);
        }
        press(&mut app, Action::Commit);
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("cannot load broken: line 2: invalid KT = -1")
        );
        press(&mut app, Action::Cancel);
        // Save, then save again under the same name: asked first; "no" keeps the file.
        // Save: the name, then the description (prefilled; typing replaces it).
        press(&mut app, Action::SavePreset);
        typed(&mut app, "bench");
        press(&mut app, Action::Commit);
        let Mode::SaveDescription { input, .. } = app.mode() else {
            panic!("{:?}", app.mode())
        };
        assert_eq!(
            input.as_str(),
            "Saved from the microslip TUI (beam model, from paper-beams-soft)"
        );
        typed(&mut app, "soft joint, \"rig 2\"");
        press(&mut app, Action::Commit);
        let path = dir.path().join("bench.toml");
        let saved = std::fs::read_to_string(&path).unwrap();
        assert!(saved.contains("KT = 120.0"));
        let read = crate::preset::store::load(&path).unwrap();
        assert_eq!(read.description, "soft joint, \"rig 2\"");
        assert_eq!(app.state().preset.description, read.description);
        // Saved again under its own name, the description offered is its own.
        press(&mut app, Action::IncreaseCoarse);
        press(&mut app, Action::SavePreset);
        typed(&mut app, "bench");
        press(&mut app, Action::Commit);
        assert!(
            matches!(app.mode(), Mode::SaveDescription { input, .. } if input.as_str() == read.description)
        );
        press(&mut app, Action::Commit);
        assert!(matches!(app.mode(), Mode::ConfirmOverwrite { .. }));
        press(&mut app, Action::Cancel);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), saved);
        press(&mut app, Action::SavePreset);
        typed(&mut app, "bench");
        press(&mut app, Action::Commit);
        press(&mut app, Action::Commit);
        press(&mut app, Action::Yes);
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
        let mut csv = String::from("F_N,w_mm\n");
        for m in measured() {
            csv.push_str(&format!("{},{}\n", m.force, m.response));
        }
        let path = dir.path().join("m.csv");
        std::fs::write(&path, csv).unwrap();
        let mut app = app();
        press(&mut app, Action::Fit);
        assert!(app.message().unwrap().text.starts_with("no measurements"));
        press(&mut app, Action::LoadData);
        typed(&mut app, path.to_str().unwrap());
        press(&mut app, Action::Commit);
        assert_eq!(app.measurements().unwrap().points.len(), 25);
        assert!(app.plot().series.iter().any(|s| s.name == "measured"));
        press(&mut app, Action::Fit);
        assert!(
            (app.inputs().get(MU).unwrap() / 0.35 - 1.0).abs() < 1e-6,
            "{:?}",
            app.message()
        );
        assert!((app.inputs().get(KT).unwrap() / 250.0 - 1.0).abs() < 1e-6);
        assert!(
            app.message().unwrap().text.starts_with("fit: mu = 0.35"),
            "{:?}",
            app.message()
        );
        // A bad file is refused with its line; the loaded data stay.
        std::fs::write(dir.path().join("bad.csv"), "F_N,w_mm\n1,x\n").unwrap();
        press(&mut app, Action::LoadData);
        for _ in 0..200 {
            press(&mut app, Action::Backspace);
        }
        typed(&mut app, dir.path().join("bad.csv").to_str().unwrap());
        press(&mut app, Action::Commit);
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

    /// The exported figure is read without the terminal: a parameter caption, each curve named by
    /// its own values with units (not `mu 0.3->0.2`, which reads as a change), and pin 1 not in
    /// Coulomb's black dashes.
    #[test]
    fn x_exports_a_figure_with_a_caption_and_curves_named_by_their_own_values() {
        let dir = tempfile::tempdir().unwrap();
        let mut app = app();
        app.set_export_dir(dir.path().to_path_buf());
        app.update(Action::Pin);
        set_typed(&mut app, "mu", "0.2");
        set_typed(&mut app, "KT", "1000");
        press(&mut app, Action::ExportChart);
        let file = |extension: &str| dir.path().join(format!("microslip-w-vs-f.{extension}"));
        assert!(
            std::fs::read(file("png"))
                .unwrap()
                .starts_with(b"\x89PNG\r\n\x1a\n")
        );
        assert!(std::fs::read(file("pdf")).unwrap().starts_with(b"%PDF-"));
        let svg = std::fs::read_to_string(file("svg")).unwrap();
        for text in [
            "L = 200 mm, b = 20 mm",
            // F is the x axis: not in the caption.
            "P = 1 MPa, mu = 0.2, KT = 1000 MPa/mm\n</text>",
            "K_T (mu = 0.2, KT = 1000 MPa/mm)",
            "pin 1: mu = 0.3, KT = 600 MPa/mm",
        ] {
            assert!(svg.contains(text), "{text}\n{svg}");
        }
        assert!(!svg.contains("-&gt;") && !svg.contains("->"), "{svg}");
        // Coulomb is black with even dashes; pin 1 is neither (purple, dash-dot).
        let curves: Vec<&str> = svg.lines().filter(|l| l.starts_with("<polyline")).collect();
        let with = |dashes: &str| {
            curves
                .iter()
                .find(|l| l.contains(&format!("stroke-dasharray=\"{dashes}\"")))
                .copied()
                .unwrap_or_else(|| panic!("a curve dashed {dashes}\n{svg}"))
        };
        assert!(with("7 4").contains("stroke=\"#000000\""));
        assert!(with("10 4 2 4").contains("stroke=\"#7570B3\""));
        // The CSV keeps its series names.
        let csv = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.csv")).unwrap();
        assert!(csv.contains("\npin 1: mu 0.3->0.2 KT 600->1000,"), "{csv}");
    }

    #[test]
    fn x_exports_the_chart_as_svg_and_csv_without_replacing_files() {
        let dir = tempfile::tempdir().unwrap();
        let mut app = app();
        app.set_export_dir(dir.path().to_path_buf());
        press(&mut app, Action::ExportChart);
        let message = app.message().unwrap();
        assert!(!message.is_error, "{}", message.text);
        assert!(
            message.text.contains("microslip-w-vs-f.svg"),
            "{}",
            message.text
        );
        let svg = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.svg")).unwrap();
        assert!(svg.contains(&app.plot().title));
        let csv = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.csv")).unwrap();
        assert!(
            csv.starts_with("series,x_axis,x,y_axis,y\nCoulomb,F (N),0"),
            "{csv}"
        );
        // Again: a new name, the first files untouched.
        press(&mut app, Action::ExportChart);
        assert!(dir.path().join("microslip-w-vs-f-2.svg").exists());
        // After v, the file says what is charted; a table is refused with a reason.
        press(&mut app, Action::Vary);
        press(&mut app, Action::ExportChart);
        assert!(dir.path().join("microslip-w-vs-l.csv").exists());
        press(&mut app, Action::Vary);
        press(&mut app, Action::PreviousChart);
        press(&mut app, Action::ExportChart);
        assert!(app.message().unwrap().is_error);
        // Three exports of four files each (SVG, PNG, PDF, CSV).
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 12);
    }

    #[test]
    fn keys_that_need_files_return_effects_and_touch_nothing() {
        let dir = tempfile::tempdir().unwrap();
        // Neither folder exists: the keys alone must not fail, create or read anything.
        let missing = dir.path().join("missing");
        let mut app = app_with_dir(Some(missing.join("presets")));
        app.set_export_dir(missing.join("charts"));
        let effects = app.update(Action::ExportChart);
        let [
            Effect::ExportChart {
                dir,
                stem,
                svg,
                csv,
            },
        ] = effects.as_slice()
        else {
            panic!("{effects:?}")
        };
        assert_eq!(dir, &missing.join("charts"));
        assert_eq!(stem, "microslip-w-vs-f");
        assert!(svg.contains(&app.plot().title));
        assert!(csv.starts_with(b"series,x_axis,x,y_axis,y\n"));
        app.update(Action::SavePreset);
        typed(&mut app, "bench");
        app.update(Action::Commit);
        let effects = app.update(Action::Commit);
        assert!(
            matches!(
                effects.as_slice(),
                [Effect::SavePreset { dir, name, text, overwrite: false, .. }]
                    if *dir == missing.join("presets") && name == "bench" && text.contains("KT = 600.0")
            ),
            "{effects:?}"
        );
        assert_eq!(
            app.update(Action::OpenPresets),
            [Effect::ListPresets {
                user_dir: Some(missing.join("presets"))
            }]
        );
        assert_eq!(app.mode(), &Mode::Normal, "the picker opens with the list");
        let path = missing.join("m.csv").display().to_string();
        app.update(Action::LoadData);
        typed(&mut app, &path);
        assert_eq!(
            app.update(Action::Complete),
            [Effect::CompletePath { text: path.clone() }]
        );
        assert_eq!(
            app.update(Action::Commit),
            [Effect::ReadMeasurements { path: path.clone() }]
        );
        app.update(Action::LoadData);
        typed(&mut app, &format!("{path}.dat"));
        assert_eq!(
            app.update(Action::Commit),
            [Effect::ReadFeResults {
                path: format!("{path}.dat"),
                kind: ModelKind::Beam
            }]
        );
        // Nothing said, nothing loaded, nothing changed, nothing on the disk.
        assert_eq!(app.message(), None);
        assert_eq!(app.measurements(), None);
        assert_eq!(app.history(), (0, 0));
        assert!(!missing.exists());
    }

    #[test]
    fn f_asks_for_a_fit_that_esc_cancels_leaving_the_parameters_as_they_were() {
        let mut app = app();
        app.measurements = Some(Measurements {
            path: "m.csv".into(),
            points: measured(),
        });
        let before = app.inputs();
        let effects = app.update(Action::Fit);
        let [fit @ Effect::Fit { job, points, .. }] = effects.as_slice() else {
            panic!("{effects:?}")
        };
        let job = *job;
        assert_eq!(points, &measured());
        assert_eq!(app.mode(), &Mode::Fitting { job });
        assert_eq!(app.mode().context(), Context::Working);
        let grid = |done| Outcome::FitProgress {
            job,
            progress: crate::fit::Progress::Bracket {
                done,
                total: 784,
                points: 25,
            },
        };
        app.receive(grid(392));
        assert_eq!(
            app.message().unwrap().text,
            "fitting: grid search for a start on 25 measurements, 50% (Esc cancels)"
        );
        // Meanwhile other keys do nothing: the result is for these parameters.
        for action in [
            Action::Increase,
            Action::SwitchModel,
            Action::Fit,
            Action::RequestQuit,
        ] {
            assert!(app.update(action).is_empty());
        }
        assert_eq!((app.inputs(), app.kind()), (before, ModelKind::Beam));
        assert!(!app.should_quit());
        assert_eq!(app.update(Action::Cancel), [Effect::CancelFit { job }]);
        assert_eq!(app.mode(), &Mode::Normal);
        let cancelled = app.message().cloned();
        assert_eq!(
            cancelled.as_ref().unwrap().text,
            "fit cancelled; the parameters are unchanged"
        );
        // Its progress and result, should they still come, change nothing.
        let late = crate::tui::effects::perform_blocking(fit.clone()).unwrap();
        assert!(matches!(late, Outcome::Fitted { result: Ok(_), .. }));
        app.receive(grid(784));
        assert!(app.receive(late).is_empty());
        assert_eq!(app.inputs(), before);
        assert_eq!(app.message().cloned(), cancelled);
        assert_eq!(app.history(), (0, 0));
        // The next fit is another job; its result is adopted, and u undoes it.
        let effects = app.update(Action::Fit);
        let [next @ Effect::Fit { job: second, .. }] = effects.as_slice() else {
            panic!("{effects:?}")
        };
        assert_ne!(*second, job);
        let result = crate::tui::effects::perform_blocking(next.clone()).unwrap();
        app.receive(result);
        assert!((app.inputs().get(MU).unwrap() / 0.35 - 1.0).abs() < 1e-6);
        assert_eq!(app.mode(), &Mode::Normal);
        app.update(Action::Undo);
        assert_eq!(app.inputs(), before);
    }

    /// Types `text` on the command line and runs it (files read at once).
    fn command(app: &mut App, text: &str) {
        press(app, Action::CommandLine);
        typed(app, text);
        press(app, Action::Commit);
    }

    #[test]
    fn the_command_line_sets_several_values_at_once_and_u_undoes_them_together() {
        let mut app = app();
        command(&mut app, "KT=250 mu=0.2,F=90");
        assert_eq!(
            (
                app.inputs().get(KT),
                app.inputs().get(MU),
                app.inputs().get(F)
            ),
            (Some(250.0), Some(0.2), Some(90.0))
        );
        let said = &app.message().unwrap().text;
        assert!(
            said.contains("KT = 250 MPa/mm")
                && said.contains("mu = 0.2")
                && said.contains("F = 90 N"),
            "{said}"
        );
        assert_eq!(app.history(), (1, 0));
        press(&mut app, Action::Undo);
        assert_eq!(app.inputs(), preset::paper(ModelKind::Beam).inputs);
    }

    #[test]
    fn the_command_line_refuses_as_set_does_and_changes_nothing() {
        let mut app = app();
        let before = app.inputs();
        for (typed_line, said) in [
            ("KT=250 mu=abc", "mu=abc"),
            ("KT=250 mu=-1", "mu"),
            ("KT=250 tp=1", "unknown key 'tp' for the beam model"),
            ("KT=250 mu", "'mu' is not KEY=VALUE"),
            ("frobnicate", "unknown command 'frobnicate'"),
        ] {
            command(&mut app, typed_line);
            let message = app.message().unwrap();
            assert!(message.is_error, "{typed_line}: {message:?}");
            assert!(
                message.text.contains(said),
                "{typed_line}: {}",
                message.text
            );
            assert_eq!(app.inputs(), before, "{typed_line}");
            assert_eq!(app.mode(), &Mode::Normal);
        }
        assert_eq!(app.history(), (0, 0));
    }

    #[test]
    fn the_command_line_loads_presets_by_name_and_completes_keys_and_names() {
        let mut app = app();
        press(&mut app, Action::CommandLine);
        typed(&mut app, "K");
        press(&mut app, Action::Complete);
        assert!(matches!(app.mode(), Mode::Command { input } if input.as_str() == "KT="));
        press(&mut app, Action::Cancel);
        press(&mut app, Action::CommandLine);
        typed(&mut app, "preset paper-p");
        press(&mut app, Action::Complete);
        assert!(
            matches!(app.mode(), Mode::Command { input } if input.as_str() == "preset paper-plate")
        );
        press(&mut app, Action::Commit);
        assert_eq!(app.kind(), ModelKind::Plate);
        assert_eq!(app.preset_name(), "paper-plate");
        command(&mut app, "preset no-such");
        let message = app.message().unwrap();
        assert!(message.is_error && message.text.contains("no preset named 'no-such'"));
        assert!(message.text.contains("p lists them"), "{}", message.text);
        command(&mut app, "help");
        assert_eq!(app.mode(), &Mode::Help);
    }

    #[test]
    fn loaded_data_go_with_d_and_with_another_preset() {
        let mut app = app();
        press(&mut app, Action::DropData);
        assert!(app.message().unwrap().text.starts_with("no loaded data"));
        let data = Measurements {
            path: "m.csv".into(),
            points: measured(),
        };
        app.measurements = Some(data.clone());
        press(&mut app, Action::DropData);
        assert_eq!(app.measurements(), None);
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("dropped 25 measurements (m.csv)"),
            "{:?}",
            app.message()
        );
        // Another preset: the data belonged to the previous bench.
        app.measurements = Some(data);
        command(&mut app, "preset paper-beams-soft");
        assert_eq!(app.measurements(), None);
        assert!(
            app.message()
                .unwrap()
                .text
                .contains("dropped 25 measurements")
        );
    }

    #[test]
    fn a_deck_s_values_adopted_drop_the_measurements_taken_at_other_values() {
        let mut app = app();
        app.measurements = Some(Measurements {
            path: "m.csv".into(),
            points: measured(),
        });
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/calculix/paper-beams.dat"
        );
        press(&mut app, Action::LoadData);
        typed(&mut app, path);
        press(&mut app, Action::Commit);
        assert_eq!(app.measurements(), None);
        let said = &app.message().unwrap().text;
        assert!(
            said.contains("deck parameters adopted") && said.contains("dropped 25"),
            "{said}"
        );
    }

    #[test]
    fn the_plate_s_continuum_u_is_solved_for_the_values_shown_and_a_late_answer_is_ignored() {
        use crate::tui::summary::ContinuumState;
        let mut app = App::new(AppOptions {
            theme: Theme {
                charset: Charset::Unicode,
                color: true,
            },
            preset: preset::resolve("paper-plate").unwrap(),
            user_dir: None,
            data: None,
            solve_continuum: true,
        });
        let asked = app.take_asked();
        let [Effect::SolveContinuum { params }] = asked.as_slice() else {
            panic!("{asked:?}")
        };
        assert_eq!(*params, crate::PlateParams::PAPER);
        assert_eq!(app.continuum(), ContinuumState::Solving);
        // A value changes before the answer comes: the answer is for values no longer shown.
        let stale = crate::tui::effects::perform_blocking(asked[0].clone()).unwrap();
        select(&mut app, "mu");
        let effects = app.update(Action::IncreaseCoarse);
        assert!(matches!(
            effects.as_slice(),
            [Effect::SolveContinuum { .. }]
        ));
        app.receive(stale);
        assert_eq!(app.continuum(), ContinuumState::Solving);
        for effect in effects {
            let outcome = crate::tui::effects::perform_blocking(effect).unwrap();
            app.receive(outcome);
        }
        let Some(Model::Plate(plate)) = app.model() else {
            panic!()
        };
        let expected = crate::problems::plate::solve_plate_continuum(
            plate.params(),
            crate::problems::plate::ContinuumMesh::default(),
        )
        .unwrap();
        assert_eq!(
            app.continuum(),
            ContinuumState::Solved(crate::tui::effects::ContinuumSummary {
                end_displacement: expected.end_displacement_mean,
                edge_pressure: expected.edge_pressure_ratio,
            })
        );
        assert!(
            app.summary_lines()
                .iter()
                .any(|l| l.text.starts_with("contact P 2-D: ") && l.text.ends_with(" P at end")),
            "the continuum's edge pressure replaces the flat model's line"
        );
        let line = app
            .summary_lines()
            .into_iter()
            .find(|l| l.text.starts_with("u(L) 2-D FE"))
            .unwrap();
        assert!(line.text.contains(" mm ("), "{}", line.text);
        // The beams have none.
        press(&mut app, Action::SwitchModel);
        assert_eq!(app.continuum(), ContinuumState::Off);
    }

    #[test]
    fn the_force_axis_follows_f_thre_when_it_leaves_the_axis_and_says_so() {
        let mut app = app();
        let right = |app: &App| app.plot().x.bounds[1];
        assert!(
            (right(&app) - 240.0).abs() < 1e-9,
            "3 F_thre of the paper's beams"
        );
        // K_T does not move F_thre: the axis stays while it is dragged.
        select(&mut app, "KT");
        for _ in 0..5 {
            press(&mut app, Action::DecreaseCoarse);
        }
        assert!((right(&app) - 240.0).abs() < 1e-9);
        // P x 8: F_thre = 640 N, beyond the axis: fitted again, and said.
        command(&mut app, "P=8");
        let threshold = match app.model() {
            Some(Model::Beam { beams, .. }) => beams.threshold_force(),
            _ => panic!(),
        };
        assert!((threshold - 640.0).abs() < 1e-9);
        assert!(
            (right(&app) - 3.0 * threshold).abs() < 1e-9,
            "{}",
            right(&app)
        );
        let said = &app.message().unwrap().text;
        assert!(
            said.contains("set P = 8 MPa") && said.contains("F axis rescaled to 0-1920 N"),
            "{said}"
        );
        // Down by 40: F_thre = 16 N, squeezed into the start of 0-1920 N (F lowered too: the
        // axis always reaches 1.25 F to show the current force).
        command(&mut app, "P=0.2 F=10");
        assert!((right(&app) - 48.0).abs() < 1e-9, "{}", right(&app));
        assert!(app.message().unwrap().text.contains("squeezed"));
        // A factor inside the band keeps the axis (and says nothing of it).
        command(&mut app, "P=0.3");
        assert!((right(&app) - 48.0).abs() < 1e-9);
        assert!(!app.message().unwrap().text.contains("rescaled"));
    }
}
