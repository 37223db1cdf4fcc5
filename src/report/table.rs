//! Streaming a table (an iterator of serde rows) as CSV or as a JSON array: memory stays flat
//! however many rows a sweep asks for, and both formats come from the same row type.

use std::io::{self, Write};

use serde::Serialize;

use super::csv;

/// Formats of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TableFormat {
    /// CSV with a header line.
    Csv,
    /// JSON array of row objects.
    Json,
}

/// Writes `rows` as CSV (header from the row type) or as a JSON array with one object per line.
///
/// # Examples
/// ```
/// use microslip::problems::twin_beams::TwinBeamsProblem;
/// use microslip::problems::twin_beams::report::BeamRow;
/// use microslip::report::table::{TableFormat, write_table};
/// use microslip::study::curves::load_samples;
/// use microslip::study::load::force_sweep;
/// use microslip::{TwinBeams, TwinBeamsParams};
/// let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
/// let forces = load_samples::<TwinBeamsProblem>(0.0, 80.0, 2)?;
/// let rows = force_sweep::<TwinBeamsProblem>(beams, forces)?.map(|p| BeamRow::from(&p));
/// let mut csv = Vec::new();
/// write_table(&mut csv, TableFormat::Csv, rows)?;
/// let csv = String::from_utf8(csv)?;
/// assert!(csv.starts_with("F_N,w_coulomb_mm,w_regularized_mm,X_mm,"));
/// assert_eq!(csv.lines().count(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// The writer's error.
pub fn write_table<R: Serialize + Default>(
    out: &mut impl Write,
    format: TableFormat,
    rows: impl Iterator<Item = R>,
) -> io::Result<()> {
    write_table_headed(out, format, &R::default(), rows)
}

/// [`write_table`] for rows whose header depends on their values' problem (a cycle sweep's
/// `Fa_N` or `Qa_N_per_mm`): the CSV header is `header`'s field names.
///
/// # Errors
/// The writer's error.
pub fn write_table_headed<R: Serialize>(
    out: &mut impl Write,
    format: TableFormat,
    header: &R,
    rows: impl Iterator<Item = R>,
) -> io::Result<()> {
    match format {
        TableFormat::Csv => {
            csv::write_header(out, header)?;
            for row in rows {
                csv::write_row(out, &row)?;
            }
            Ok(())
        }
        TableFormat::Json => {
            out.write_all(b"[")?;
            for (i, row) in rows.enumerate() {
                out.write_all(if i == 0 { b"\n  " } else { b",\n  " })?;
                serde_json::to_writer(&mut *out, &row).map_err(io::Error::from)?;
            }
            out.write_all(b"\n]\n")
        }
    }
}

/// Writes `rows`, each a leading value and a row, as [`write_table`] does, with the leading value
/// in a first column named `column` (CSV) or a first key `column` (JSON): a sweep over any
/// parameter, whose rows are those of the model's usual sweep.
///
/// # Errors
/// The writer's error.
#[cfg(feature = "app")]
pub(crate) fn write_table_after<R: Serialize + Default>(
    out: &mut impl Write,
    format: TableFormat,
    column: &str,
    rows: impl Iterator<Item = (f64, R)>,
) -> io::Result<()> {
    match format {
        TableFormat::Csv => {
            csv::write_header_after(out, column, &R::default())?;
            for (value, row) in rows {
                csv::write_row_after(out, value, &row)?;
            }
            Ok(())
        }
        TableFormat::Json => {
            let key = serde_json::to_string(column).map_err(io::Error::from)?;
            out.write_all(b"[")?;
            for (i, (value, row)) in rows.enumerate() {
                out.write_all(if i == 0 { b"\n  " } else { b",\n  " })?;
                let object = serde_json::to_string(&row).map_err(io::Error::from)?;
                let rest = object.strip_prefix('{').unwrap_or(&object);
                let value = serde_json::to_string(&value).map_err(io::Error::from)?;
                let comma = if rest.starts_with('}') { "" } else { "," };
                write!(out, "{{{key}:{value}{comma}{rest}")?;
            }
            out.write_all(b"\n]\n")
        }
    }
}

/// Writes one JSON document, pretty-printed, with a final newline.
///
/// Strings stay exact, and safe on a terminal: JSON escapes C0 controls anyway, and here DEL, the C1
/// controls and the bidirectional controls are written as `\uXXXX` escapes too (the same string for
/// any JSON reader, nothing for a terminal to obey).
///
/// # Errors
/// The writer's error.
pub fn write_json(out: &mut impl Write, value: &impl Serialize) -> io::Result<()> {
    let mut serializer = serde_json::Serializer::with_formatter(
        &mut *out,
        TerminalSafe(serde_json::ser::PrettyFormatter::new()),
    );
    value.serialize(&mut serializer).map_err(io::Error::from)?;
    writeln!(out)
}

/// A JSON formatter that escapes, in strings, what `serde_json` writes raw but a terminal may act
/// on; the layout is the wrapped formatter's.
struct TerminalSafe<F>(F);

/// Delegates formatter methods to the wrapped formatter.
macro_rules! delegate {
    ($($name:ident($($arg:ident: $ty:ty),*);)*) => {$(
        fn $name<W: ?Sized + Write>(&mut self, writer: &mut W $(, $arg: $ty)*) -> io::Result<()> {
            self.0.$name(writer $(, $arg)*)
        }
    )*};
}

impl<F: serde_json::ser::Formatter> serde_json::ser::Formatter for TerminalSafe<F> {
    delegate! {
        begin_array();
        end_array();
        begin_array_value(first: bool);
        end_array_value();
        begin_object();
        end_object();
        begin_object_key(first: bool);
        end_object_key();
        begin_object_value();
        end_object_value();
    }

    fn write_string_fragment<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        let mut start = 0;
        for (i, c) in fragment.char_indices() {
            if c.is_control() || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}') {
                writer.write_all(&fragment.as_bytes()[start..i])?;
                write!(writer, "\\u{:04x}", u32::from(c))?;
                start = i + c.len_utf8();
            }
        }
        writer.write_all(&fragment.as_bytes()[start..])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::rows::LoopRow;

    #[test]
    fn json_strings_are_exact_and_carry_no_raw_control_character() {
        let value = serde_json::json!({ "name": "a\u{1b}[2J\u{7f}\u{9b}\u{202e}z", "n": [1, 2] });
        let mut out = Vec::new();
        write_json(&mut out, &value).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(
            !text.chars().any(|c| c.is_control() && c != '\n'),
            "{text:?}"
        );
        assert!(
            text.contains(r#""a\u001b[2J\u007f\u009b\u202ez""#),
            "{text}"
        );
        let back: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(back, value);
        // The layout is serde_json's pretty one.
        let mut plain = serde_json::to_string_pretty(&serde_json::json!({ "n": [1, 2] })).unwrap();
        plain.push('\n');
        let mut ours = Vec::new();
        write_json(&mut ours, &serde_json::json!({ "n": [1, 2] })).unwrap();
        assert_eq!(String::from_utf8(ours).unwrap(), plain);
    }

    #[test]
    fn both_formats_carry_the_same_columns_in_the_same_order() {
        let rows = || {
            [1.0, 2.5].map(|force| LoopRow {
                branch: "unloading",
                force,
                w_coulomb_mm: force / 3.0,
                w_regularized_mm: 0.0,
            })
        };
        let mut csv = Vec::new();
        write_table(&mut csv, TableFormat::Csv, rows().into_iter()).unwrap();
        let mut json = Vec::new();
        write_table(&mut json, TableFormat::Json, rows().into_iter()).unwrap();
        let csv = String::from_utf8(csv).unwrap();
        let parsed: Vec<serde_json::Map<String, serde_json::Value>> =
            serde_json::from_slice(&json).unwrap();
        let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        let keys: Vec<&str> = parsed[0].keys().map(String::as_str).collect();
        let mut sorted = header.clone();
        sorted.sort_unstable();
        assert_eq!(keys, sorted, "same names (serde_json sorts its keys)");
        assert_eq!(csv.lines().count(), 3);
        assert_eq!(parsed[1]["F_N"], 2.5);
    }
}
