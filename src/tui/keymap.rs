//! Keys as data: one table maps key presses to actions per context, and the help overlay is printed
//! from the same table (labels included, generated from the bound keys), so the two cannot drift
//! apart.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::action::Action;

/// Where the user is; the same key means different things in different places.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Context {
    /// The main screen.
    Main,
    /// The preset picker.
    Presets,
    /// Typing text: a value, a preset name.
    TextEntry,
    /// A yes/no question.
    Confirm,
    /// The help overlay.
    Help,
    /// The explanation of the regime pane's lines.
    Explain,
    /// A fit runs: only Esc (and the global keys) mean anything.
    Working,
}

/// One line of the key map.
#[derive(Debug, Clone, Copy)]
pub struct Binding {
    /// Where it applies.
    pub context: Context,
    /// The keys (code, required modifiers).
    pub keys: &'static [(KeyCode, KeyModifiers)],
    /// What happens.
    pub action: Action,
    /// What the help says.
    pub description: &'static str,
}

const NONE: KeyModifiers = KeyModifiers::NONE;
const SHIFT: KeyModifiers = KeyModifiers::SHIFT;
const CTRL: KeyModifiers = KeyModifiers::CONTROL;

const fn bind(
    context: Context,
    keys: &'static [(KeyCode, KeyModifiers)],
    action: Action,
    description: &'static str,
) -> Binding {
    Binding {
        context,
        keys,
        action,
        description,
    }
}

/// How one key is written in the help: `j`, `L`, `Down`, `S-Right` (ASCII only, so the ASCII
/// charset can show it).
fn key_label(code: KeyCode, modifiers: KeyModifiers) -> String {
    let name = match code {
        KeyCode::Char(c) if modifiers.contains(KeyModifiers::CONTROL) => return format!("C-{c}"),
        KeyCode::Char(c) => return c.to_string(),
        KeyCode::Up => "Up",
        KeyCode::Down => "Down",
        KeyCode::Left => "Left",
        KeyCode::Right => "Right",
        KeyCode::Enter => "Enter",
        KeyCode::Esc => "Esc",
        KeyCode::Tab => "Tab",
        KeyCode::Backspace => "Backspace",
        KeyCode::Home => "Home",
        KeyCode::End => "End",
        KeyCode::Delete => "Del",
        other => return format!("{other:?}"),
    };
    if modifiers.contains(KeyModifiers::SHIFT) {
        format!("S-{name}")
    } else {
        name.to_string()
    }
}

impl Binding {
    /// The keys as the help writes them: each key once, a shifted letter and its lower case
    /// counted as one key (`y` for y and Y), joined by ` / `.
    pub fn label(&self) -> String {
        let mut labels: Vec<String> = Vec::new();
        for &(code, modifiers) in self.keys {
            let label = key_label(code, modifiers);
            if !labels
                .iter()
                .any(|l| l.eq_ignore_ascii_case(&label) && l.len() == 1)
            {
                labels.push(label);
            }
        }
        labels.join(" / ")
    }
}

/// The whole key map. Ctrl-C is not listed per context: it always quits.
pub const BINDINGS: &[Binding] = &[
    bind(
        Context::Main,
        &[(KeyCode::Char('j'), NONE), (KeyCode::Down, NONE)],
        Action::Next,
        "next parameter",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('k'), NONE), (KeyCode::Up, NONE)],
        Action::Previous,
        "previous parameter",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('l'), NONE), (KeyCode::Right, NONE)],
        Action::Increase,
        "increase, fine step",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('h'), NONE), (KeyCode::Left, NONE)],
        Action::Decrease,
        "decrease, fine step",
    ),
    bind(
        Context::Main,
        &[
            (KeyCode::Char('L'), SHIFT),
            (KeyCode::Char('L'), NONE),
            (KeyCode::Right, SHIFT),
        ],
        Action::IncreaseCoarse,
        "increase, coarse step",
    ),
    bind(
        Context::Main,
        &[
            (KeyCode::Char('H'), SHIFT),
            (KeyCode::Char('H'), NONE),
            (KeyCode::Left, SHIFT),
        ],
        Action::DecreaseCoarse,
        "decrease, coarse step",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Enter, NONE), (KeyCode::Char('e'), NONE)],
        Action::StartEdit,
        "type an exact value",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('m'), NONE), (KeyCode::Tab, NONE)],
        Action::SwitchModel,
        "next problem",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('c'), NONE)],
        Action::NextChart,
        "next chart",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('C'), SHIFT), (KeyCode::Char('C'), NONE)],
        Action::PreviousChart,
        "previous chart",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('n'), NONE)],
        Action::ToggleNumeric,
        "toggle FE points",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('b'), NONE)],
        Action::ToggleSetting,
        "next setting (theory)",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('p'), NONE)],
        Action::OpenPresets,
        "load a preset",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('s'), NONE)],
        Action::SavePreset,
        "save as user preset",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('r'), NONE)],
        Action::Reset,
        "reset to the preset",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('d'), NONE)],
        Action::LoadData,
        "load data / FE results",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('f'), NONE)],
        Action::Fit,
        "fit mu, K_T to them",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('v'), NONE)],
        Action::Vary,
        "chart response vs row",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('t'), NONE)],
        Action::SolveTarget,
        "solve row for a target",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('i'), NONE)],
        Action::Explain,
        "explain the numbers",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('a'), NONE)],
        Action::FitAxes,
        "fit axes to the data",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('y'), NONE)],
        Action::CycleYAxis,
        "y axis lin/log/rel.",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('g'), NONE)],
        Action::Pin,
        "pin curves (up to 4)",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('G'), SHIFT), (KeyCode::Char('G'), NONE)],
        Action::ClearPins,
        "clear the pins",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char(':'), NONE), (KeyCode::Char(':'), SHIFT)],
        Action::CommandLine,
        "command line (KT=250)",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('D'), SHIFT), (KeyCode::Char('D'), NONE)],
        Action::DropData,
        "drop loaded data (d)",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('M'), SHIFT), (KeyCode::Char('M'), NONE)],
        Action::ShowMessage,
        "read the whole message",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('x'), NONE)],
        Action::ExportChart,
        "export chart SVG+CSV",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('u'), NONE)],
        Action::Undo,
        "undo a change",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('r'), CTRL)],
        Action::Redo,
        "redo",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('?'), NONE), (KeyCode::Char('?'), SHIFT)],
        Action::ToggleHelp,
        "this help",
    ),
    bind(
        Context::Main,
        &[(KeyCode::Char('q'), NONE), (KeyCode::Esc, NONE)],
        Action::RequestQuit,
        "quit",
    ),
    bind(
        Context::Presets,
        &[(KeyCode::Char('j'), NONE), (KeyCode::Down, NONE)],
        Action::Next,
        "next preset",
    ),
    bind(
        Context::Presets,
        &[(KeyCode::Char('k'), NONE), (KeyCode::Up, NONE)],
        Action::Previous,
        "previous preset",
    ),
    bind(
        Context::Presets,
        &[(KeyCode::Enter, NONE)],
        Action::Commit,
        "load selected preset",
    ),
    bind(
        Context::Presets,
        &[(KeyCode::Char('s'), NONE)],
        Action::SavePreset,
        "save as user preset",
    ),
    bind(
        Context::Presets,
        &[
            (KeyCode::Esc, NONE),
            (KeyCode::Char('q'), NONE),
            (KeyCode::Char('p'), NONE),
        ],
        Action::Cancel,
        "close the picker",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Enter, NONE)],
        Action::Commit,
        "accept",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Esc, NONE)],
        Action::Cancel,
        "cancel, keep old value",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Backspace, NONE)],
        Action::Backspace,
        "delete before cursor",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Delete, NONE)],
        Action::Delete,
        "delete under cursor",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Left, NONE)],
        Action::CursorLeft,
        "cursor left",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Right, NONE)],
        Action::CursorRight,
        "cursor right",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Home, NONE), (KeyCode::Char('a'), CTRL)],
        Action::CursorHome,
        "start of line",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::End, NONE), (KeyCode::Char('e'), CTRL)],
        Action::CursorEnd,
        "end of line",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Char('u'), CTRL)],
        Action::ClearToStart,
        "delete to start",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Char('w'), CTRL)],
        Action::DeleteWord,
        "delete word before",
    ),
    bind(
        Context::TextEntry,
        &[(KeyCode::Tab, NONE)],
        Action::Complete,
        "complete a name",
    ),
    bind(
        Context::Confirm,
        &[(KeyCode::Char('y'), NONE), (KeyCode::Char('Y'), SHIFT)],
        Action::Yes,
        "yes",
    ),
    bind(
        Context::Confirm,
        &[(KeyCode::Char('n'), NONE), (KeyCode::Esc, NONE)],
        Action::Cancel,
        "no",
    ),
    bind(
        Context::Help,
        &[(KeyCode::Char('j'), NONE), (KeyCode::Down, NONE)],
        Action::Next,
        "next page",
    ),
    bind(
        Context::Help,
        &[(KeyCode::Char('k'), NONE), (KeyCode::Up, NONE)],
        Action::Previous,
        "previous page",
    ),
    bind(
        Context::Help,
        &[
            (KeyCode::Esc, NONE),
            (KeyCode::Char('?'), NONE),
            (KeyCode::Char('?'), SHIFT),
            (KeyCode::Char('q'), NONE),
        ],
        Action::ToggleHelp,
        "close the help",
    ),
    bind(
        Context::Explain,
        &[(KeyCode::Char('j'), NONE), (KeyCode::Down, NONE)],
        Action::Next,
        "next line",
    ),
    bind(
        Context::Explain,
        &[(KeyCode::Char('k'), NONE), (KeyCode::Up, NONE)],
        Action::Previous,
        "previous line",
    ),
    bind(
        Context::Explain,
        &[
            (KeyCode::Esc, NONE),
            (KeyCode::Char('i'), NONE),
            (KeyCode::Char('q'), NONE),
        ],
        Action::Cancel,
        "close",
    ),
    bind(
        Context::Working,
        &[(KeyCode::Esc, NONE)],
        Action::Cancel,
        "cancel the fit",
    ),
];

/// Keys that mean the same everywhere, as the help lists them: (key, action, what happens).
pub const GLOBAL_KEYS: [(char, Action, &str); 2] = [
    ('c', Action::Quit, "quit, without asking"),
    ('z', Action::Suspend, "suspend (fg resumes)"),
];

/// The action for a key press in a context, if any. Ctrl-C quits and Ctrl-Z suspends everywhere;
/// in text entry, any other printable character is typed.
pub fn action_for(context: Context, key: KeyEvent) -> Option<Action> {
    if key.modifiers.contains(KeyModifiers::CONTROL)
        && let KeyCode::Char(c) = key.code
        && let Some(&(_, action, _)) = GLOBAL_KEYS
            .iter()
            .find(|(k, _, _)| k.eq_ignore_ascii_case(&c))
    {
        return Some(action);
    }
    let found = BINDINGS
        .iter()
        .filter(|b| b.context == context)
        .find(|b| {
            b.keys
                .iter()
                .any(|&(code, modifiers)| code == key.code && key.modifiers == modifiers)
        })
        .map(|b| b.action);
    match (found, context, key.code) {
        (Some(action), _, _) => Some(action),
        (None, Context::TextEntry, KeyCode::Char(c))
            if !key.modifiers.contains(KeyModifiers::CONTROL) =>
        {
            Some(Action::Input(c))
        }
        _ => None,
    }
}

/// Heading of each context in the help overlay.
pub fn context_title(context: Context) -> &'static str {
    match context {
        Context::Main => "Main screen",
        Context::Presets => "Preset picker",
        Context::TextEntry => "Typing a value or a name",
        Context::Confirm => "Yes/no questions",
        Context::Help => "This help",
        Context::Explain => "Explaining the numbers",
        Context::Working => "While a fit or a file read runs",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(code: KeyCode, modifiers: KeyModifiers) -> KeyEvent {
        KeyEvent::new(code, modifiers)
    }

    #[test]
    fn ctrl_c_quits_everywhere() {
        for context in [
            Context::Main,
            Context::Presets,
            Context::TextEntry,
            Context::Confirm,
            Context::Help,
            Context::Working,
        ] {
            assert_eq!(
                action_for(context, key(KeyCode::Char('c'), KeyModifiers::CONTROL)),
                Some(Action::Quit)
            );
        }
    }

    #[test]
    fn ctrl_z_suspends_everywhere_and_q_asks_before_quitting() {
        assert_eq!(
            action_for(
                Context::TextEntry,
                key(KeyCode::Char('z'), KeyModifiers::CONTROL)
            ),
            Some(Action::Suspend)
        );
        assert_eq!(
            action_for(Context::Main, key(KeyCode::Char('q'), NONE)),
            Some(Action::RequestQuit)
        );
    }

    #[test]
    fn keys_mean_what_the_table_says() {
        assert_eq!(
            action_for(Context::Main, key(KeyCode::Char('j'), NONE)),
            Some(Action::Next)
        );
        assert_eq!(
            action_for(Context::Main, key(KeyCode::Right, SHIFT)),
            Some(Action::IncreaseCoarse)
        );
        assert_eq!(
            action_for(Context::Main, key(KeyCode::Char('L'), SHIFT)),
            Some(Action::IncreaseCoarse)
        );
        assert_eq!(
            action_for(Context::TextEntry, key(KeyCode::Char('7'), NONE)),
            Some(Action::Input('7'))
        );
        assert_eq!(
            action_for(Context::TextEntry, key(KeyCode::Char('q'), NONE)),
            Some(Action::Input('q'))
        );
        assert_eq!(
            action_for(Context::Main, key(KeyCode::Char('z'), NONE)),
            None
        );
        // While a fit runs, Esc cancels it and q does not quit.
        assert_eq!(
            action_for(Context::Working, key(KeyCode::Esc, NONE)),
            Some(Action::Cancel)
        );
        assert_eq!(
            action_for(Context::Working, key(KeyCode::Char('q'), NONE)),
            None
        );
    }

    #[test]
    fn help_fits_two_columns_of_an_80_column_screen() {
        assert!(
            BINDINGS
                .iter()
                .all(|b| b.label().len() <= 13 && b.description.len() <= 22)
        );
    }

    #[test]
    fn no_key_is_bound_twice_in_one_context_and_labels_are_ascii() {
        for (i, a) in BINDINGS.iter().enumerate() {
            assert!(a.label().is_ascii() && a.description.is_ascii());
            for b in &BINDINGS[i + 1..] {
                if a.context == b.context {
                    assert!(
                        a.keys.iter().all(|k| !b.keys.contains(k)),
                        "{} / {}",
                        a.label(),
                        b.label()
                    );
                }
            }
        }
    }
}
