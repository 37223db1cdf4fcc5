//! Every output format over the physics: text reports for people, JSON and CSV for scripts.
//!
//! Pure formatting (strings, or bytes into a writer the caller owns), so every format is testable
//! and the binary stays thin. All numbers come from [`crate::study::curves`] and the structured results of
//! [`crate::fit`] and [`crate::verify`], the same values the TUI shows. Nothing below this module
//! imports it (tests/layering.rs checks it); the number formatting that decks and reports share
//! lives in [`crate::kernel::format`] (re-exported here for the rest of the crate).
//!
//! Generic types only: what a problem's report, sweep row, compare row and verdicts hold is the
//! problem's own, in its folder (`src/problems/<name>/report.rs`, `compare.rs`), written on the
//! traits and the generic report types here ([`face::ReportFace`],
//! [`compare::CompareFace`], [`compare::table::TableReport`]); this module names no problem
//! (`tests/layering.rs`), so that a new problem's report is its folder.

pub mod compare;
pub(crate) mod csv;
pub mod face;
#[cfg(feature = "figures")]
pub mod figure;
pub mod json;
pub mod point;
pub mod presets;
pub mod rows;
pub mod table;
pub mod text;
pub mod verify;

use std::borrow::Cow;
use std::fmt::Write;

pub(crate) use crate::kernel::format::{number, number_with};

/// `n` and the noun, singular for one: "1 measurement", "3 measurements".
pub(crate) fn count_of(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// A user-supplied string (preset name or description, file path, a value or CSV header echoed in an
/// error) made safe for a terminal: control characters (C0, DEL, C1) and the invisible bidirectional
/// controls that reorder text are shown as escapes instead of acting on the terminal. Tab, line feed
/// and carriage return become `\t`, `\n` and `\r`, other ASCII controls `\xHH` (ESC is `\x1b`, so
/// an escape sequence is shown, not obeyed), the rest `\u{HHHH}`. Characters that take no
/// room on screen (zero-width spaces and joiners, the word joiner, the byte-order mark, the soft
/// hyphen, variation selectors) are escaped too: `--set KT=\u{200b}1000` is refused, and the
/// message must show why, not a `1000` that seems refused. Everything else, including any other
/// Unicode (no-break spaces, which show as spaces), is kept. The result is one line.
pub(crate) fn sanitize(text: &str) -> Cow<'_, str> {
    fn unsafe_char(c: char) -> bool {
        c.is_control()
            || matches!(
                c,
                '\u{202a}'..='\u{202e}'
                    | '\u{2066}'..='\u{2069}'
                    | '\u{00ad}'
                    | '\u{034f}'
                    | '\u{061c}'
                    | '\u{115f}'
                    | '\u{1160}'
                    | '\u{17b4}'
                    | '\u{17b5}'
                    | '\u{180b}'..='\u{180e}'
                    | '\u{200b}'..='\u{200f}'
                    | '\u{2060}'..='\u{2064}'
                    | '\u{206a}'..='\u{206f}'
                    | '\u{3164}'
                    | '\u{fe00}'..='\u{fe0f}'
                    | '\u{feff}'
                    | '\u{ffa0}'
                    | '\u{fff9}'..='\u{fffb}'
                    | '\u{e0000}'..='\u{e007f}'
            )
    }
    if !text.chars().any(unsafe_char) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        match c {
            '\t' => out.push_str("\\t"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            c if c.is_ascii_control() => {
                let _ = write!(out, "\\x{:02x}", u32::from(c));
            }
            c if unsafe_char(c) => {
                let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    Cow::Owned(out)
}

/// The report for the paper's data sets (what `microslip` prints for now): each problem's table
/// where the paper has one ([`ReportFace::paper_table`](face::ReportFace::paper_table)), in the
/// registry's order, a blank line between them.
pub fn paper_report() -> String {
    let tables: Vec<String> = crate::problems::ModelKind::ALL
        .iter()
        .filter_map(|&kind| face::faces(kind).report.paper_table())
        .collect();
    tables.join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_readable() {
        assert_eq!(number(80.0), "80");
        assert_eq!(number(80.185_677_6), "80.1857");
        assert_eq!(number(0.038_292_26), "0.0382923");
        assert_eq!(number(5e-4), "5e-4");
        assert_eq!(number(1e-3), "0.001");
        assert_eq!(number(7.959_183_67e-6), "7.95918e-6");
        assert_eq!(number(1e6), "1e6");
        assert_eq!(number(210_000.0), "210000");
        assert_eq!(number(-2.5), "-2.5");
        assert_eq!(number(0.0), "0");
        assert_eq!(number(f64::NAN), "n/a");
        assert_eq!(number_with(0.090_045_6, 3), "0.09");
        assert_eq!(number_with(4.843_42e-4, 3), "4.84e-4");
        assert_eq!(number_with(1e10, 3), "1e10");
        assert_eq!(number_with(240.0, 3), "240");
    }

    #[test]
    fn sanitize_shows_controls_as_escapes() {
        assert_eq!(sanitize("plain text, déjà vu"), "plain text, déjà vu");
        assert_eq!(
            sanitize("red \u{1b}[31malert\u{7}\nnext"),
            "red \\x1b[31malert\\x07\\nnext"
        );
        assert_eq!(sanitize("\u{9b}2J"), "\\u{9b}2J");
    }

    #[test]
    fn sanitize_leaves_no_control_character() {
        let nasty = "a\u{1b}]0;title\u{7}b\u{1b}[2Jc\u{0}d\u{7f}e\u{85}f\u{9b}31mg\u{202e}h\r\n\ti";
        let clean = sanitize(nasty);
        assert!(
            !clean
                .chars()
                .any(|c| c.is_control() || ('\u{202a}'..='\u{2069}').contains(&c)),
            "{clean:?}"
        );
        assert_eq!(
            clean,
            "a\\x1b]0;title\\x07b\\x1b[2Jc\\x00d\\x7fe\\u{85}f\\u{9b}31mg\\u{202e}h\\r\\n\\ti"
        );
        assert!(matches!(sanitize("paper-beams"), Cow::Borrowed(_)));
    }

    #[test]
    fn paper_report_names_both_models_units_and_regimes() {
        let text = paper_report();
        assert!(text.contains("Twin cantilever beams"));
        assert!(text.contains("Squeezed plate"));
        assert!(text.contains("F_thre = 80 N"));
        assert!(text.contains("microslip+macroslip"));
        assert!(text.contains("stick+macroslip"));
        assert!(!text.contains("NaN") && !text.contains("inf") && !text.contains("n/a"));
    }
}
