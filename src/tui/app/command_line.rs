//! The command line (`:`): several values at once, presets by name, save, export, help, quit.

use super::{App, Mode};
use crate::preset;
use crate::report::number;
use crate::tui::action::Action;
use crate::tui::effects::Effect;
use crate::tui::text_input::TextInput;

impl App {
    /// Tab in the command line: keys and command words at once, preset names through the disk.
    pub(super) fn complete_command(&mut self, input: TextInput) {
        let text = input.as_str().to_string();
        self.mode = Mode::Command { input };
        if let Some(prefix) = crate::tui::command::completes_preset(&text) {
            self.asked.push(Effect::CompletePreset {
                prefix: prefix.to_string(),
                text,
                user_dir: self.user_dir.clone(),
            });
            return;
        }
        let (completed, names) = crate::tui::command::complete(&text, self.kind);
        self.completed(&text, &completed, &names);
    }
    /// Enter in the command line.
    pub(super) fn run_command(&mut self, text: &str) {
        use crate::tui::command::{Command, parse};
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
    pub(super) fn set_values(&mut self, assignments: &[String]) {
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
}
