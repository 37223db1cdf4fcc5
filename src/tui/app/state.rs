//! What the app holds, as the drawing and the event loop read it, and the active problem's
//! state for the other files of `app/` to change.

use super::{App, Measurements, Message, Mode, ModelState};
use crate::chart::Plot;
use crate::problems::inputs::{Inputs, Model};
use crate::problems::{ModelKind, Param};
use crate::tui::theme::Theme;
use crate::tui::views::Views;

impl App {
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
    pub(super) fn state(&self) -> &ModelState {
        &self.states[self.kind]
    }
    pub(super) fn state_mut(&mut self) -> &mut ModelState {
        self.state_of_mut(self.kind)
    }
    pub(super) fn state_of_mut(&mut self, kind: ModelKind) -> &mut ModelState {
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
    pub(super) fn unsaved(&self) -> Vec<String> {
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
}
