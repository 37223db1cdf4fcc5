//! The command line (`:`): several values in one line, in the `--set` syntax of the CLI
//! (`KT=250 mu=0.2 F=90`), and the few commands a keyboard user reaches for by name (`preset
//! NAME`, `save NAME`, `export`, `help`, `drop`, `q`). Parsing and completion are pure: the app
//! applies what [`parse`] returns, and the only completion that needs the disk (preset names) is
//! asked for as an effect.

use crate::problems::ModelKind;

/// What a command line asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Command {
    /// `KEY=VALUE ...`: set every value at once, or none (one undo step).
    Set(Vec<String>),
    /// `preset NAME`: load a preset by name or path; without a name, open the picker.
    Preset(Option<String>),
    /// `save NAME`: save the parameters as a user preset (the description is asked for next);
    /// without a name, ask for it as `s` does.
    Save(Option<String>),
    /// `export`: write the chart as `x` does.
    Export,
    /// `drop`: forget loaded measurements and FE results, as `D` does.
    Drop,
    /// `help`: the help overlay.
    Help,
    /// `q`: quit, asking first about unsaved edits as `q` does.
    Quit,
}

/// The command words, as completion offers them and the error lists them.
pub const WORDS: [&str; 7] = ["preset", "save", "export", "drop", "help", "q", "quit"];

/// Reads a command line. Assignments may be separated by spaces or commas; a line that starts
/// with a word other than an assignment is a command.
///
/// # Errors
/// A message naming what was typed and what is accepted.
pub fn parse(text: &str) -> Result<Command, String> {
    let text = text.trim();
    let text = text.strip_prefix(':').unwrap_or(text).trim();
    let mut words = text.split_whitespace();
    let Some(first) = words.next() else {
        return Err(usage("an empty command"));
    };
    let rest: Vec<&str> = words.collect();
    let single = |command: Command| {
        if rest.is_empty() {
            Ok(command)
        } else {
            Err(format!(
                "{first} takes nothing after it (got '{}')",
                rest.join(" ")
            ))
        }
    };
    let name = |what: &str| match rest.as_slice() {
        [] => Ok(None),
        [name] => Ok(Some((*name).to_string())),
        _ => Err(format!(
            "{first} takes one {what} (got '{}'); names have no spaces",
            rest.join(" ")
        )),
    };
    match first {
        "preset" | "p" => name("preset name or path").map(Command::Preset),
        "save" | "s" | "w" => name("preset name").map(Command::Save),
        "export" | "x" => single(Command::Export),
        "drop" | "D" => single(Command::Drop),
        "help" | "h" | "?" => single(Command::Help),
        "q" | "quit" => single(Command::Quit),
        _ if first.contains('=') => {
            let assignments: Vec<String> = text
                .split(|c: char| c.is_whitespace() || c == ',')
                .filter(|a| !a.is_empty())
                .map(str::to_string)
                .collect();
            match assignments.iter().find(|a| !a.contains('=')) {
                Some(stray) => Err(format!(
                    "'{stray}' is not KEY=VALUE: a command line sets values (KT=250 mu=0.2) or \
                     is one command"
                )),
                None => Ok(Command::Set(assignments)),
            }
        }
        other => Err(usage(&format!("unknown command '{other}'"))),
    }
}

/// The error for a line that is not a command: what is accepted.
fn usage(what: &str) -> String {
    format!(
        "{what}: type KEY=VALUE ... (as --set), or preset NAME, save NAME, export, drop, help, q"
    )
}

/// The preset name being typed, when Tab on `text` completes one (the names live on disk, so the
/// app asks for them as an effect); None otherwise.
pub fn completes_preset(text: &str) -> Option<&str> {
    let text = text.trim_start();
    let rest = text
        .strip_prefix("preset ")
        .or_else(|| text.strip_prefix("p "))?;
    let rest = rest.trim_start();
    (!rest.contains(' ')).then_some(rest)
}

/// Tab in the command line, for everything but preset names: the word being typed (the last one)
/// completed among `kind`'s parameter keys (with `=`) and, as the first word, the command words.
/// Returns the completed text and the candidates that match (none: nothing starts so).
pub fn complete(text: &str, kind: ModelKind) -> (String, Vec<String>) {
    let start = text
        .rfind(|c: char| c.is_whitespace() || c == ',')
        .map_or(0, |i| i + 1);
    let (head, word) = text.split_at(start);
    if word.contains('=') {
        return (text.to_string(), Vec::new());
    }
    let mut candidates: Vec<String> = kind
        .params()
        .iter()
        .map(|p| format!("{}=", p.name()))
        .collect();
    if head.trim().is_empty() {
        candidates.extend(WORDS.iter().map(|w| format!("{w} ")));
    }
    let names: Vec<String> = candidates
        .into_iter()
        .filter(|c| c.starts_with(word))
        .collect();
    match common_prefix(&names) {
        Some(common) => (format!("{head}{common}"), names),
        None => (text.to_string(), names),
    }
}

/// The longest prefix common to all `names` (None when there are none).
pub fn common_prefix(names: &[String]) -> Option<String> {
    let first = names.first()?;
    Some(names.iter().fold(first.clone(), |common, name| {
        common
            .chars()
            .zip(name.chars())
            .take_while(|(a, b)| a == b)
            .map(|(a, _)| a)
            .collect()
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn assignments_by_spaces_or_commas_and_the_commands() {
        assert_eq!(
            parse("KT=250 mu=0.2,F=90"),
            Ok(Command::Set(vec![
                "KT=250".into(),
                "mu=0.2".into(),
                "F=90".into()
            ]))
        );
        assert_eq!(
            parse(":preset bench3"),
            Ok(Command::Preset(Some("bench3".into())))
        );
        assert_eq!(parse("preset"), Ok(Command::Preset(None)));
        assert_eq!(
            parse("save my-bench"),
            Ok(Command::Save(Some("my-bench".into())))
        );
        assert_eq!(parse("export"), Ok(Command::Export));
        assert_eq!(parse(" help "), Ok(Command::Help));
        assert_eq!(parse("q"), Ok(Command::Quit));
        assert_eq!(parse("drop"), Ok(Command::Drop));
    }

    #[test]
    fn refusals_name_what_was_typed() {
        assert!(parse("").unwrap_err().contains("empty command"));
        let unknown = parse("frobnicate").unwrap_err();
        assert!(unknown.contains("'frobnicate'") && unknown.contains("KEY=VALUE"));
        assert!(
            parse("KT=250 mu")
                .unwrap_err()
                .contains("'mu' is not KEY=VALUE")
        );
        assert!(parse("export now").unwrap_err().contains("'now'"));
        assert!(parse("preset a b").unwrap_err().contains("one preset name"));
    }

    #[test]
    fn tab_completes_keys_and_command_words() {
        let beam = ModelKind::Beam;
        assert_eq!(complete("K", beam).0, "KT=");
        assert_eq!(complete("KT=250 m", beam).0, "KT=250 mu=");
        assert_eq!(complete("ex", beam).0, "export ");
        // Commands only as the first word; nothing after a complete assignment.
        assert!(complete("KT=250 ex", beam).1.is_empty());
        assert_eq!(complete("KT=2", beam), ("KT=2".to_string(), Vec::new()));
        // The plate's keys on the plate.
        assert_eq!(complete("t", ModelKind::Plate).0, "tp=");
        // Several matches: the common prefix, all of them listed.
        let (text, names) = complete("", beam);
        assert_eq!(text, "");
        assert!(names.len() > 9);
        assert_eq!(completes_preset("preset pa"), Some("pa"));
        assert_eq!(completes_preset("KT=1"), None);
    }
}
