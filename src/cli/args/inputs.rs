//! Where the parameters come from (`--preset`, `--set`) and the problems' own settings that are
//! names (`--beam-theory`): one flag per [`AnyChoice`] of the registry, built from what the
//! setting declares (its key, its values, its help), so that this file names no setting and no
//! problem. A command for one problem shows only its own settings' flags (the others are
//! hidden, and refused with whose setting they are: [`hide_foreign_choices`]).

use super::*;
use crate::problems::choice::AnyChoice;
use clap::{Arg, ArgAction, ArgMatches, Args, FromArgMatches};

/// Where the parameters come from.
#[derive(Debug, Clone, Default)]
pub struct InputArgs {
    /// `--preset`: bundled or user preset name, or a path to a TOML file.
    pub preset: Option<String>,
    /// `--set KEY=VALUE`, in the order given.
    pub assignments: Vec<String>,
    /// The settings given as flags: each setting's key (`beam_theory`) and the text given, in
    /// the registry's order.
    pub choices: Vec<(&'static str, String)>,
}

/// The id of `--set`.
const SET: &str = "assignments";
/// The id of `--preset`.
const PRESET: &str = "preset";

/// Every setting of the registry's problems, each key once.
pub(in crate::cli) fn registered_choices() -> Vec<&'static dyn AnyChoice> {
    let mut all: Vec<&'static dyn AnyChoice> = Vec::new();
    for choice in ModelKind::ALL
        .iter()
        .flat_map(|kind| kind.problem().faces().choices)
    {
        if !all.iter().any(|c| c.key() == choice.key()) {
            all.push(*choice);
        }
    }
    all
}

/// A setting's flag: the key with `-` for `_` (`--beam-theory`).
pub(in crate::cli) fn choice_flag(choice: &dyn AnyChoice) -> String {
    choice.key().replace('_', "-")
}

/// The flag of one setting, from what it declares.
fn choice_arg(choice: &dyn AnyChoice) -> Arg {
    // The value's name is the key's last word (`beam_theory`: THEORY).
    let value_name = choice
        .key()
        .rsplit('_')
        .next()
        .unwrap_or(choice.key())
        .to_uppercase();
    Arg::new(choice.key())
        .long(choice_flag(choice))
        .value_name(value_name)
        .help(choice.help())
        .action(ArgAction::Set)
        .value_parser(clap::builder::PossibleValuesParser::new(choice.values()))
}

/// Hides the flags of the settings `kind` does not have: a command for one problem lists only
/// its own (a hidden flag is still parsed, and refused by name when given).
pub(in crate::cli) fn hide_foreign_choices(
    kind: ModelKind,
    command: clap::Command,
) -> clap::Command {
    let own = kind.problem().faces().choices;
    registered_choices()
        .into_iter()
        .filter(|c| !own.iter().any(|o| o.key() == c.key()))
        .fold(command, |command, c| {
            command.edit_arg(c.key(), |a| a.hide(true))
        })
}

impl Args for InputArgs {
    fn augment_args(command: clap::Command) -> clap::Command {
        let command = command
            .arg(
                Arg::new(PRESET)
                    .long("preset")
                    .value_name("P")
                    .help("Bundled or user preset name, or a path to a TOML file")
                    .action(ArgAction::Set),
            )
            // The help names each model's keys from the specs (`set_help`), half sizes marked.
            .arg(
                Arg::new(SET)
                    .long("set")
                    .value_name("KEY=VALUE")
                    .help(set_help())
                    .action(ArgAction::Append),
            );
        registered_choices()
            .into_iter()
            .fold(command, |command, choice| command.arg(choice_arg(choice)))
    }

    fn augment_args_for_update(command: clap::Command) -> clap::Command {
        Self::augment_args(command)
    }
}

impl FromArgMatches for InputArgs {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        Self::from_arg_matches_mut(&mut matches.clone())
    }

    fn from_arg_matches_mut(matches: &mut ArgMatches) -> Result<Self, clap::Error> {
        let text = |matches: &mut ArgMatches, id: &str| {
            matches
                .try_remove_one::<String>(id)
                .map_err(|e| clap::Error::raw(clap::error::ErrorKind::ArgumentConflict, e))
        };
        let preset = text(matches, PRESET)?;
        let assignments = matches
            .try_remove_many::<String>(SET)
            .map_err(|e| clap::Error::raw(clap::error::ErrorKind::ArgumentConflict, e))?
            .map(Iterator::collect)
            .unwrap_or_default();
        let mut choices = Vec::new();
        for choice in registered_choices() {
            if let Some(value) = text(matches, choice.key())? {
                choices.push((choice.key(), value));
            }
        }
        Ok(InputArgs {
            preset,
            assignments,
            choices,
        })
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }

    fn update_from_arg_matches_mut(&mut self, matches: &mut ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches_mut(matches)?;
        Ok(())
    }
}

impl InputArgs {
    /// The files these flags read, with the flag that names each: the preset's file, given as a
    /// path or as the name of a user preset (bundled presets are no files). A preset that does
    /// not resolve reads nothing: loading it reports why.
    pub(in crate::cli) fn read_files(&self) -> Vec<(&'static str, PathBuf)> {
        let Some(name) = &self.preset else {
            return Vec::new();
        };
        match preset::resolve(name).map(|p| p.source) {
            Ok(preset::PresetSource::File(path)) => vec![("--preset", path)],
            _ => Vec::new(),
        }
    }

    /// The parameter flags given, as a command line repeats them (`--preset P`, `--set K=V`, ...).
    pub(in crate::cli) fn flags(&self) -> Vec<String> {
        let mut given: Vec<String> = self
            .preset
            .iter()
            .map(|p| format!("--preset {p}"))
            .collect();
        given.extend(self.assignments.iter().map(|a| format!("--set {a}")));
        given.extend(
            self.choices
                .iter()
                .map(|(key, value)| format!("--{} {value}", key.replace('_', "-"))),
        );
        given
    }
}

/// The help of `--set`: every model's keys as the specs define them.
pub(in crate::cli) fn set_help() -> String {
    format!("Set a parameter, e.g. KT=120 ({})", ModelKind::key_docs())
}

// The flags of `check` (Command::Check); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Preset files (TOML), or preset names (bundled, or in the user preset folder).
    #[arg(required = true, value_name = "FILE|NAME")]
    pub(in crate::cli) files: Vec<PathBuf>,
}
