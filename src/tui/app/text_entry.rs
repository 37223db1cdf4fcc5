//! The text-entry modes' shared keys: typing, editing, Tab completion and paste.

use super::{App, Mode};
use crate::tui::action::Action;
use crate::tui::effects::Effect;
use crate::tui::text_input::TextInput;

impl App {
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
                crate::tui::text_input::MAX_CHARS
            ));
        } else if line.len() < text.trim_end_matches(['\n', '\r']).len() {
            self.info("pasted the first line only; Enter accepts it");
        }
        true
    }
    /// One key in a text-entry mode: edits stay in the mode (rebuilt by `mode`), Esc leaves it with
    /// the note `cancelled`, Enter returns the trimmed text for the caller to act on.
    pub(super) fn edit(
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
                    crate::tui::text_input::MAX_CHARS
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
    pub(super) fn completed(&mut self, text: &str, completed: &str, names: &[String]) {
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
    pub(super) fn completions(&mut self, names: &[String], none: &str) {
        match names.len() {
            0 => self.info(none),
            1 => self.message = None,
            n => self.info(format!(
                "{n} matches: {}",
                names.iter().take(8).cloned().collect::<Vec<_>>().join("  ")
            )),
        }
    }
}
