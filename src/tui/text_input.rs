//! [`TextInput`]: the one line of text being typed, shared by every text-entry mode (a value, a
//! preset name, a file path, a target), so that they all edit, limit and show text the same way:
//! like a shell line (cursor, Home/End, Ctrl-U, Ctrl-W), and a pre-filled value is selected, so
//! typing replaces it while the arrows keep it for editing.

/// Longest text accepted: far more than any number, name or path needs, small enough that a stray
/// paste cannot make the line unbounded.
pub const MAX_CHARS: usize = 4096;

/// Text typed so far, the cursor (a character index) and whether the whole text is selected.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TextInput {
    text: String,
    cursor: usize,
    selected: bool,
}

impl TextInput {
    /// Starts with `text` (e.g. the previous file path), cut to [`MAX_CHARS`], cursor at the end.
    pub fn new(text: &str) -> TextInput {
        let text: String = text.chars().take(MAX_CHARS).collect();
        TextInput {
            cursor: text.chars().count(),
            text,
            selected: false,
        }
    }

    /// Starts with `text` selected: the first typed character replaces it, an arrow key keeps it.
    pub fn prefilled(text: &str) -> TextInput {
        TextInput {
            selected: !text.is_empty(),
            ..TextInput::new(text)
        }
    }

    fn byte(&self, index: usize) -> usize {
        self.text
            .char_indices()
            .nth(index)
            .map_or(self.text.len(), |(i, _)| i)
    }

    fn take_selection(&mut self) -> bool {
        if self.selected {
            self.text.clear();
            self.cursor = 0;
            self.selected = false;
            true
        } else {
            false
        }
    }

    /// Inserts a character at the cursor (replacing a selection); returns false (and changes
    /// nothing) when the text is full.
    pub fn push(&mut self, c: char) -> bool {
        if !self.selected && self.text.chars().count() >= MAX_CHARS {
            return false;
        }
        self.take_selection();
        let at = self.byte(self.cursor);
        self.text.insert(at, c);
        self.cursor += 1;
        true
    }

    /// Deletes the character before the cursor (or the selection).
    pub fn pop(&mut self) {
        if self.take_selection() || self.cursor == 0 {
            return;
        }
        self.cursor -= 1;
        let at = self.byte(self.cursor);
        self.text.remove(at);
    }

    /// Deletes the character under the cursor (or the selection).
    pub fn delete(&mut self) {
        if self.take_selection() || self.cursor >= self.text.chars().count() {
            return;
        }
        let at = self.byte(self.cursor);
        self.text.remove(at);
    }

    /// Moves the cursor one character left (`-1`) or right (`1`), keeping the text.
    pub fn move_by(&mut self, step: isize) {
        self.selected = false;
        let len = self.text.chars().count();
        self.cursor = self.cursor.saturating_add_signed(step).min(len);
    }

    /// Cursor to the start (`false`) or the end (`true`).
    pub fn jump(&mut self, end: bool) {
        self.selected = false;
        self.cursor = if end { self.text.chars().count() } else { 0 };
    }

    /// Deletes from the start to the cursor (Ctrl-U).
    pub fn clear_to_start(&mut self) {
        if self.take_selection() {
            return;
        }
        let at = self.byte(self.cursor);
        self.text.replace_range(..at, "");
        self.cursor = 0;
    }

    /// Deletes the word before the cursor and the spaces after it (Ctrl-W); a word ends at a
    /// space or a `/`, as in a shell.
    pub fn delete_word(&mut self) {
        if self.take_selection() {
            return;
        }
        let chars: Vec<char> = self.text.chars().collect();
        let mut start = self.cursor;
        while start > 0 && chars[start - 1] == ' ' {
            start -= 1;
        }
        if start > 0 && chars[start - 1] == '/' {
            start -= 1;
        }
        while start > 0 && !matches!(chars[start - 1], ' ' | '/') {
            start -= 1;
        }
        let (from, to) = (self.byte(start), self.byte(self.cursor));
        self.text.replace_range(from..to, "");
        self.cursor = start;
    }

    /// Replaces the whole text (a completion), cursor at the end.
    pub fn set(&mut self, text: &str) {
        *self = TextInput::new(text);
    }

    /// The text, without surrounding spaces.
    pub fn trimmed(&self) -> &str {
        self.text.trim()
    }

    /// The text as typed.
    pub fn as_str(&self) -> &str {
        &self.text
    }

    /// The line as shown: a selection in brackets (`[600]`, typing replaces it), otherwise the
    /// text with the cursor: `_` at the end, `|` before the character it stands on.
    pub fn shown(&self) -> String {
        if self.selected {
            return format!("[{}]", self.text);
        }
        let at = self.byte(self.cursor);
        if at == self.text.len() {
            format!("{}_", self.text)
        } else {
            format!("{}|{}", &self.text[..at], &self.text[at..])
        }
    }
}

/// Completes the file name at the end of `text` from the folder it names (the working folder
/// without one): the one match (a folder with `/`), or the longest prefix common to all matches.
/// Returns the completed text and the matching names (none when nothing matches).
pub fn complete_path(text: &str) -> (String, Vec<String>) {
    let (dir, prefix) = match text.rfind('/') {
        Some(i) => (&text[..=i], &text[i + 1..]),
        None => ("", text),
    };
    let folder = if dir.is_empty() { "." } else { dir };
    let Ok(entries) = std::fs::read_dir(folder) else {
        return (text.to_string(), Vec::new());
    };
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .filter_map(|e| {
            let name = e.file_name().into_string().ok()?;
            if !name.starts_with(prefix) || (name.starts_with('.') && !prefix.starts_with('.')) {
                return None;
            }
            let is_dir = e.file_type().is_ok_and(|t| t.is_dir());
            Some(if is_dir { format!("{name}/") } else { name })
        })
        .collect();
    names.sort();
    match super::command::common_prefix(&names) {
        Some(common) => (format!("{dir}{common}"), names),
        None => (text.to_string(), names),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typing_editing_and_the_limit() {
        let mut input = TextInput::new(" 1e3");
        assert!(input.push('x'));
        input.pop();
        assert_eq!((input.as_str(), input.trimmed()), (" 1e3", "1e3"));
        let mut full = TextInput::new(&"9".repeat(MAX_CHARS + 10));
        assert_eq!(full.as_str().len(), MAX_CHARS);
        assert!(!full.push('1'));
        assert_eq!(full.as_str().len(), MAX_CHARS);
        // 32 characters and more are kept: nothing is cut silently at a field width.
        let mut value = TextInput::default();
        for c in "1.0000000000000000000000000000000e3".chars() {
            assert!(value.push(c));
        }
        assert_eq!(value.trimmed().parse::<f64>(), Ok(1000.0));
    }

    #[test]
    fn a_prefilled_value_is_replaced_by_typing_and_kept_by_the_arrows() {
        let mut input = TextInput::prefilled("600");
        assert_eq!(input.shown(), "[600]");
        input.push('4');
        assert_eq!(input.as_str(), "4");
        let mut input = TextInput::prefilled("600");
        input.move_by(-1);
        input.push('5');
        assert_eq!((input.as_str(), input.shown().as_str()), ("6050", "605|0"));
        input.jump(false);
        input.delete();
        assert_eq!(input.as_str(), "050");
        input.jump(true);
        input.pop();
        assert_eq!(input.as_str(), "05");
    }

    #[test]
    fn ctrl_u_and_ctrl_w_delete_like_a_shell() {
        let mut input = TextInput::new("data/run 1.csv");
        input.delete_word();
        assert_eq!(input.as_str(), "data/run ");
        input.delete_word();
        assert_eq!(input.as_str(), "data/");
        input.delete_word();
        assert_eq!(input.as_str(), "");
        let mut input = TextInput::new("abc def");
        input.move_by(-3);
        input.clear_to_start();
        assert_eq!(input.as_str(), "def");
        // Multi-byte characters move by characters.
        let mut input = TextInput::new("µm");
        input.move_by(-1);
        input.pop();
        assert_eq!(input.as_str(), "m");
    }

    #[test]
    fn tab_completes_a_unique_name_and_the_common_prefix() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["sweep-mu.csv", "sweep-kt.csv", "other.dat"] {
            std::fs::write(dir.path().join(name), "").unwrap();
        }
        std::fs::create_dir(dir.path().join("runs")).unwrap();
        let base = format!("{}/", dir.path().display());
        let (text, names) = complete_path(&format!("{base}sw"));
        assert_eq!(text, format!("{base}sweep-"));
        assert_eq!(names.len(), 2);
        assert_eq!(
            complete_path(&format!("{base}o")).0,
            format!("{base}other.dat")
        );
        assert_eq!(complete_path(&format!("{base}r")).0, format!("{base}runs/"));
        assert!(complete_path(&format!("{base}zz")).1.is_empty());
    }
}
