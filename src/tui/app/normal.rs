//! The main screen: selection, steps, typed values, undo and redo, `v`, `t` and the other keys
//! that act at once.

use super::{App, Mode};
use crate::kernel::params::Compact;
use crate::problems::Param;
use crate::report::face::faces;
use crate::report::number;
use crate::tui::action::Action;
use crate::tui::text_input::TextInput;

impl App {
    pub(super) fn update_normal(&mut self, action: Action) {
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
                // The status explains the points once they are in (on a worker: seconds).
                self.overlay_toggled = self.show_numeric;
                self.recompute();
                if !self.overlay.is_some_and(|(.., pending)| pending) {
                    self.overlay_toggled = false;
                    self.explain_overlay();
                }
            }
            Action::ToggleSetting => {
                let kind = self.kind;
                let toggled = faces(kind)
                    .pane
                    .toggle_setting(&mut self.state_mut().inputs);
                match toggled {
                    Some(text) => {
                        self.info(text);
                        self.recompute();
                    }
                    None => {
                        // Which problems have a setting `b` toggles, from the registry.
                        let owners: Vec<String> = crate::problems::ModelKind::ALL
                            .into_iter()
                            .flat_map(|k| {
                                k.problem().faces().choices.iter().map(move |c| {
                                    format!("{} of the {}", c.key(), k.description().title)
                                })
                            })
                            .collect();
                        self.error(format!(
                            "the {} has no setting to toggle (the settings: {}; press m)",
                            kind.description().title,
                            owners.join(", ")
                        ))
                    }
                }
            }
            Action::ToggleHelp => {
                self.help_page = 0;
                self.mode = Mode::Help;
            }
            // Esc (and q) first stop a pending overlay solve: one more quits.
            Action::RequestQuit if self.cancel_overlay() => {}
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

    /// Undoes (`redo` false) or redoes the last change of any problem's parameters.
    pub(super) fn travel(&mut self, redo: bool) {
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

    /// Moves the selected parameter by its fine or coarse step; the result is validated like typed
    /// input.
    pub(super) fn step(&mut self, up: bool, coarse: bool) {
        let param = self.selected_param();
        let Some(value) = self.inputs().get(param) else {
            return;
        };
        // The force steps in fractions of its regime scale (F_thre, F_gross).
        let scale = self.regime_scale_of(self.kind).unwrap_or(1.0);
        // A step stops at the edge of the accepted domain rather than being refused there.
        // A bounded load stops at its bound (the lap joint's F at F_gross), and the parameters
        // of the bound where it falls to the load.
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
            let info = self.kind.description();
            let load = info.load_words().map_or("the load", |(name, _)| name);
            return self.info(format!(
                "{param} stops at {}{}: {load} must not exceed {}",
                number(value),
                param.unit_suffix(),
                info.bound_formula().unwrap_or_default()
            ));
        }
        self.set_value(param, next);
    }

    /// Sets a parameter if the model accepts it; otherwise refuses with the model's message and keeps
    /// the previous value.
    pub(super) fn set_value(&mut self, param: Param, value: f64) {
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
    pub(super) fn current_value(&self, param: Param) -> String {
        number(self.inputs().get(param).unwrap_or(0.0))
    }

    /// Enter in the value field: parse, then set like a step.
    pub(super) fn commit_value(&mut self, text: &str) {
        let param = self.selected_param();
        match crate::preset::parse_value(param, text) {
            Ok(value) => self.set_value(param, value),
            Err(e) => self.error(format!("{e}; kept {}", self.current_value(param))),
        }
    }

    /// `t`: the value of the selected parameter at which a quantity takes the typed target; one
    /// certified root is adopted (u undoes it), anything else is said.
    pub(super) fn solve_target(&mut self, text: &str) {
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
}
