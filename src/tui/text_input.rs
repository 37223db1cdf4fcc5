//! [`TextInput`]: the one line of text being typed, shared by every text-entry mode (a value, a
//! preset name, a file path), so that they all edit, limit and show text the same way.

/// Longest text accepted: far more than any number, name or path needs, small enough that a stray
/// paste cannot make the line unbounded.
pub const MAX_CHARS: usize = 4096;

/// Text typed so far.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TextInput {
    text: String,
}

impl TextInput {
    /// Starts with `text` (e.g. the previous file path), cut to [`MAX_CHARS`].
    pub fn new(text: &str) -> TextInput {
        TextInput {
            text: text.chars().take(MAX_CHARS).collect(),
        }
    }

    /// Appends a character; returns false (and changes nothing) when the text is full.
    pub fn push(&mut self, c: char) -> bool {
        if self.text.chars().count() >= MAX_CHARS {
            return false;
        }
        self.text.push(c);
        true
    }

    /// Deletes the last character.
    pub fn pop(&mut self) {
        self.text.pop();
    }

    /// The text, without surrounding spaces.
    pub fn trimmed(&self) -> &str {
        self.text.trim()
    }

    /// The text as typed.
    pub fn as_str(&self) -> &str {
        &self.text
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
}
