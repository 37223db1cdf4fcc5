//! The preset picker (`p`) and saving (`s`, its name and description, the overwrite question).

use std::path::PathBuf;

use super::{App, Mode};
use crate::preset::{self, Listed, Preset, PresetSource, SaveError};
use crate::problems::inputs::Inputs;
use crate::tui::action::Action;
use crate::tui::effects::Effect;
use crate::tui::text_input::TextInput;

impl App {
    /// `p`: asks for the presets; the picker opens with them ([`Outcome::Presets`](crate::tui::effects::Outcome::Presets)).
    pub(super) fn open_presets(&mut self) {
        self.asked.push(Effect::ListPresets {
            user_dir: self.user_dir.clone(),
        });
    }
    pub(super) fn update_presets(&mut self, entries: Vec<Listed>, selected: usize, action: Action) {
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
    pub(super) fn adopt_preset(&mut self, preset: Preset) {
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
    /// After the name of `s`: asks for the preset's description, prefilled with the loaded
    /// preset's own when the name is the one it was loaded from, else with the default one.
    pub(super) fn ask_description(&mut self, name: String) {
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
    pub(super) fn default_description(&self) -> String {
        format!(
            "Saved from the microslip TUI ({} model, from {})",
            self.kind,
            self.preset_name()
        )
    }
    /// Asks to save the parameters as the user preset `name` (replacing one only if `overwrite`).
    pub(super) fn save(&mut self, name: String, description: String, overwrite: bool) {
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
    pub(super) fn saved(
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
