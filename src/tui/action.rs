//! [`Action`]: what a key press (or, later, an event) asks the app to do. Its own module so that
//! the key map (which produces actions) and the app (which applies them) depend on it and not on
//! each other.

/// What a key press asks for (see the key map).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// Leave the program now (Ctrl-C, or yes to "quit anyway?").
    Quit,
    /// Leave the program, asking first when a model has unsaved edits (q, Esc).
    RequestQuit,
    /// Suspend like other full-screen programs (Ctrl-Z): the event loop restores the terminal and
    /// stops the process; `fg` resumes it. The app state does not change.
    Suspend,
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
    /// The problem's setting (a choice it declares, e.g. the beams' theory) to its next value.
    ToggleSetting,
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
    /// Undo the last parameter change.
    Undo,
    /// Redo the last undone change.
    Redo,
    /// Chart the response against the selected parameter (again: back to the views).
    Vary,
    /// Solve for a target on the selected parameter.
    SolveTarget,
    /// Explain the numbers of the regime pane.
    Explain,
    /// The chart's y axis: linear, log, relative to Coulomb (the modes the chart can show).
    CycleYAxis,
    /// Pin the current parameters: their main curve stays on every chart of the model, for
    /// comparison (at most four pins; a fifth replaces the oldest).
    Pin,
    /// Remove every pin of the model.
    ClearPins,
    /// Export the chart shown (SVG figure and its CSV data) to files in the export directory.
    ExportChart,
    /// Fit the chart's axes to the data (the force range of the beams' charts follows F_thre again).
    FitAxes,
    /// Open the command line (`:`): several values at once (`KT=250 mu=0.2`) or a command.
    CommandLine,
    /// Forget the loaded measurements and FE results.
    DropData,
    /// Show the last status message whole (it is cut on the status line when too long).
    ShowMessage,
    /// Text entry: cursor one character left.
    CursorLeft,
    /// Text entry: cursor one character right.
    CursorRight,
    /// Text entry: cursor to the start.
    CursorHome,
    /// Text entry: cursor to the end.
    CursorEnd,
    /// Text entry: delete the character under the cursor.
    Delete,
    /// Text entry: delete from the start to the cursor (Ctrl-U).
    ClearToStart,
    /// Text entry: delete the word before the cursor (Ctrl-W).
    DeleteWord,
    /// Text entry: complete a file name (Tab).
    Complete,
}
