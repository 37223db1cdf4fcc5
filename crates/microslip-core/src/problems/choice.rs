//! A problem's settings that are names, not numbers (the twin beams' beam theory): the
//! capability that lets presets read and write them and the command line set them without a
//! `match` on the problem. A problem with such a setting implements [`AnyChoice`] for it in its
//! folder and lists it in the `choices` of its [`Problem::FACES`](crate::problems::Problem::FACES); a
//! problem without one writes nothing (the default is none).

use thiserror::Error;

use crate::problems::inputs::Inputs;

/// One setting of one problem that takes a name among a few (`beam_theory = "timoshenko"`),
/// erased so that a preset or a flag reaches it through the registry: its key, what a written
/// preset says of it, and reading and setting it in [`Inputs`] of its problem.
pub trait AnyChoice: Send + Sync {
    /// Its key in presets (`beam_theory`); the command line's flag is the key with `-` for `_`
    /// (`--beam-theory`).
    fn key(&self) -> &'static str;
    /// What a written preset says of it after its value (the names it takes, which is the
    /// paper's).
    fn comment(&self) -> &'static str;
    /// The problem it belongs to as a refusal names it ("the twin beams"): "KEY applies to
    /// OWNER, not ...".
    fn owner(&self) -> &'static str;
    /// The names it takes, as a flag lists them (`euler-bernoulli`, `timoshenko`).
    fn values(&self) -> &'static [&'static str];
    /// What it sets and its default, as the flag's help says it: the setting declares its own
    /// option, so a command line builds the flag from it without naming the problem.
    fn help(&self) -> &'static str;
    /// Its value in `inputs`, as presets write it; `None` for another problem's inputs.
    fn get(&self, inputs: &Inputs) -> Option<&'static str>;
    /// Sets it in `inputs` from `text` as a user typed it; `None` (nothing set) for another
    /// problem's inputs.
    ///
    /// # Errors
    /// [`ChoiceError`] when `text` names none of its values.
    fn set(&self, inputs: &mut Inputs, text: &str) -> Option<Result<(), ChoiceError>>;
}

/// A name a setting does not take: the text given and the names it takes.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("invalid {what} '{text}': must be {}", quoted(allowed))]
pub struct ChoiceError {
    /// The setting as people say it (`beam theory`).
    pub what: &'static str,
    /// The text given.
    pub text: String,
    /// The names accepted.
    pub allowed: &'static [&'static str],
}

/// `"a"`, `"a" or "b"`, `"a", "b" or "c"`: the names as messages list them.
fn quoted(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    match quoted.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_names_are_listed_as_messages_list_them() {
        let error = ChoiceError {
            what: "beam theory",
            text: "x".to_string(),
            allowed: &["euler-bernoulli", "timoshenko"],
        };
        assert_eq!(
            error.to_string(),
            "invalid beam theory 'x': must be \"euler-bernoulli\" or \"timoshenko\""
        );
        assert_eq!(quoted(&["a", "b", "c"]), "\"a\", \"b\" or \"c\"");
    }
}
