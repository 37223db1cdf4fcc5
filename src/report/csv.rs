//! CSV from the serde row types of [`super::rows`]: the header is the row struct's field names and a
//! line is its values, so the CSV header, the column order and the JSON keys cannot drift apart.
//!
//! A small serde serializer rather than the `csv` crate's, for two reasons: floats are written in
//! their shortest round-trip form by `zmij` (already in the tree through serde_json, so CSV and JSON
//! print the same digits; `core::fmt` float formatting was 55 % of a million-row sweep), and a row
//! goes straight to the writer with no intermediate record.

use std::fmt::Display;
use std::io::{self, Write};

use serde::ser::{self, Impossible, Serialize, SerializeStruct, Serializer};

/// Why a row could not be written: the writer failed, or a row type holds a field CSV cannot show
/// (a nested struct, a sequence): a programming error that tests catch.
#[derive(Debug)]
struct Error(io::Error);

impl Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::error::Error for Error {}

impl ser::Error for Error {
    fn custom<T: Display>(msg: T) -> Self {
        Error(io::Error::other(msg.to_string()))
    }
}

impl From<io::Error> for Error {
    fn from(e: io::Error) -> Self {
        Error(e)
    }
}

fn unsupported(what: &str) -> Error {
    Error(io::Error::other(format!(
        "CSV rows hold numbers and labels only, not {what}"
    )))
}

/// Writes the header line of row type `R`: its field names, as serde names them.
///
/// # Errors
/// The writer's error, or an error for a row type with a nested field.
pub(crate) fn write_header<R: Serialize>(out: &mut impl Write, row: &R) -> io::Result<()> {
    row.serialize(Line {
        out,
        header: true,
        first: true,
    })
    .map_err(|e| e.0)?;
    out.write_all(b"\n")
}

/// Writes one row as a CSV line.
///
/// # Errors
/// The writer's error, or an error for a row type with a nested field.
pub(crate) fn write_row<R: Serialize>(out: &mut impl Write, row: &R) -> io::Result<()> {
    row.serialize(Line {
        out,
        header: false,
        first: true,
    })
    .map_err(|e| e.0)?;
    out.write_all(b"\n")
}

/// Writes the header line of row type `R` after a leading column named `first` (a sweep over a
/// parameter: the parameter's column, then the row's).
///
/// # Errors
/// As [`write_header`].
#[cfg(feature = "app")]
pub(crate) fn write_header_after<R: Serialize>(
    out: &mut impl Write,
    first: &str,
    row: &R,
) -> io::Result<()> {
    write_text(out, first)?;
    row.serialize(Line {
        out,
        header: true,
        first: false,
    })
    .map_err(|e| e.0)?;
    out.write_all(b"\n")
}

/// Writes one row after a leading number (the header of [`write_header_after`]).
///
/// # Errors
/// As [`write_row`].
#[cfg(feature = "app")]
pub(crate) fn write_row_after<R: Serialize>(
    out: &mut impl Write,
    first: f64,
    row: &R,
) -> io::Result<()> {
    Cell { out: &mut *out }.float(first).map_err(|e| e.0)?;
    row.serialize(Line {
        out,
        header: false,
        first: false,
    })
    .map_err(|e| e.0)?;
    out.write_all(b"\n")
}

/// The serializer methods both [`Line`] and [`Cell`] refuse: bytes, enums with data and every
/// compound value but a row's own struct (serde requires each to be spelled out).
macro_rules! refuse_compound_values {
    () => {
        fn serialize_bytes(self, _: &[u8]) -> Result<(), Error> {
            Err(unsupported("bytes"))
        }
        fn serialize_newtype_variant<T: ?Sized + Serialize>(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: &T,
        ) -> Result<(), Error> {
            Err(unsupported("an enum with data"))
        }
        fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Error> {
            Err(unsupported("a sequence"))
        }
        fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Error> {
            Err(unsupported("a tuple"))
        }
        fn serialize_tuple_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleStruct, Error> {
            Err(unsupported("a tuple"))
        }
        fn serialize_tuple_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleVariant, Error> {
            Err(unsupported("an enum with data"))
        }
        fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Error> {
            Err(unsupported("a map"))
        }
        fn serialize_struct_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeStructVariant, Error> {
            Err(unsupported("an enum with data"))
        }
    };
}

/// Serializer methods of one argument that [`Line`] refuses: a line is a struct, not a value.
macro_rules! refuse_bare_values {
    ($($method:ident: $type:ty),* $(,)?) => {
        $(fn $method(self, _: $type) -> Result<(), Error> {
            Err(unsupported("a bare value"))
        })*
    };
}

/// Serializes one struct as one line: its field names (`header`) or its values.
struct Line<'a, W: Write> {
    out: &'a mut W,
    header: bool,
    first: bool,
}

impl<W: Write> Line<'_, W> {
    fn separator(&mut self) -> io::Result<()> {
        if self.first {
            self.first = false;
            Ok(())
        } else {
            self.out.write_all(b",")
        }
    }
}

/// Writes a text cell, quoted when it holds a separator, a quote or a line break (RFC 4180).
fn write_text(out: &mut impl Write, text: &str) -> io::Result<()> {
    if text.contains([',', '"', '\n', '\r']) {
        write!(out, "\"{}\"", text.replace('"', "\"\""))
    } else {
        out.write_all(text.as_bytes())
    }
}

impl<W: Write> SerializeStruct for Line<'_, W> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        self.separator()?;
        if self.header {
            write_text(self.out, key)?;
            Ok(())
        } else {
            value.serialize(Cell { out: self.out })
        }
    }

    fn end(self) -> Result<(), Error> {
        Ok(())
    }
}

impl<'a, W: Write> Serializer for Line<'a, W> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Impossible<(), Error>;
    type SerializeTuple = Impossible<(), Error>;
    type SerializeTupleStruct = Impossible<(), Error>;
    type SerializeTupleVariant = Impossible<(), Error>;
    type SerializeMap = Impossible<(), Error>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), Error>;

    refuse_compound_values!();

    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, Error> {
        Ok(self)
    }

    refuse_bare_values!(
        serialize_bool: bool,
        serialize_i8: i8,
        serialize_i16: i16,
        serialize_i32: i32,
        serialize_i64: i64,
        serialize_u8: u8,
        serialize_u16: u16,
        serialize_u32: u32,
        serialize_u64: u64,
        serialize_f32: f32,
        serialize_f64: f64,
        serialize_char: char,
        serialize_str: &str,
        serialize_unit_struct: &'static str,
    );
    fn serialize_none(self) -> Result<(), Error> {
        Err(unsupported("a bare value"))
    }
    fn serialize_some<T: ?Sized + Serialize>(self, _: &T) -> Result<(), Error> {
        Err(unsupported("a bare value"))
    }
    fn serialize_unit(self) -> Result<(), Error> {
        Err(unsupported("a bare value"))
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Error> {
        Err(unsupported("a bare value"))
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: &T,
    ) -> Result<(), Error> {
        Err(unsupported("a bare value"))
    }
}

/// Serializer methods of [`Cell`] that write a value as `Display` shows it (integers, booleans).
macro_rules! write_displayed {
    ($($method:ident: $type:ty),* $(,)?) => {
        $(fn $method(self, x: $type) -> Result<(), Error> {
            self.integer(x)
        })*
    };
}

/// Serializes one field value as one cell.
struct Cell<'a, W: Write> {
    out: &'a mut W,
}

impl<W: Write> Cell<'_, W> {
    fn float(self, x: f64) -> Result<(), Error> {
        let mut buffer = zmij::Buffer::new();
        self.out.write_all(buffer.format(x).as_bytes())?;
        Ok(())
    }

    fn integer(self, x: impl Display) -> Result<(), Error> {
        write!(self.out, "{x}")?;
        Ok(())
    }
}

impl<'a, W: Write> Serializer for Cell<'a, W> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Impossible<(), Error>;
    type SerializeTuple = Impossible<(), Error>;
    type SerializeTupleStruct = Impossible<(), Error>;
    type SerializeTupleVariant = Impossible<(), Error>;
    type SerializeMap = Impossible<(), Error>;
    type SerializeStruct = Impossible<(), Error>;
    type SerializeStructVariant = Impossible<(), Error>;

    refuse_compound_values!();

    fn serialize_f64(self, x: f64) -> Result<(), Error> {
        self.float(x)
    }
    fn serialize_f32(self, x: f32) -> Result<(), Error> {
        self.float(f64::from(x))
    }
    fn serialize_str(self, text: &str) -> Result<(), Error> {
        write_text(self.out, text)?;
        Ok(())
    }
    write_displayed!(
        serialize_bool: bool,
        serialize_i8: i8,
        serialize_i16: i16,
        serialize_i32: i32,
        serialize_i64: i64,
        serialize_u8: u8,
        serialize_u16: u16,
        serialize_u32: u32,
        serialize_u64: u64,
    );
    fn serialize_char(self, x: char) -> Result<(), Error> {
        self.serialize_str(x.encode_utf8(&mut [0; 4]))
    }
    /// An absent value is an empty cell.
    fn serialize_none(self) -> Result<(), Error> {
        Ok(())
    }
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<(), Error> {
        value.serialize(self)
    }
    /// A unit enum variant (a label) is its name.
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<(), Error> {
        self.serialize_str(variant)
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Error> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Error> {
        Ok(())
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self::SerializeStruct, Error> {
        Err(unsupported("a nested struct"))
    }
}

/// What the tests of a table's columns read.
#[cfg(test)]
pub(crate) mod test_support {
    /// The CSV header of the row type `R`, as `write_header` writes it.
    pub(crate) fn header<R: serde::Serialize + Default>() -> String {
        let mut out = Vec::new();
        super::write_header(&mut out, &R::default()).unwrap();
        String::from_utf8(out).unwrap().trim_end().to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Serialize;

    #[derive(Serialize)]
    struct Row {
        #[serde(rename = "F_N")]
        force: f64,
        label: &'static str,
        count: u64,
    }

    fn line(row: &Row, header: bool) -> String {
        let mut out = Vec::new();
        if header {
            write_header(&mut out, row).unwrap();
        } else {
            write_row(&mut out, row).unwrap();
        }
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn the_header_is_the_field_names_and_a_line_the_values() {
        let row = Row {
            force: 0.1 + 0.2,
            label: "micro+macro",
            count: 7,
        };
        assert_eq!(line(&row, true), "F_N,label,count\n");
        let text = line(&row, false);
        let fields: Vec<&str> = text.trim_end().split(',').collect();
        assert_eq!(fields[0].parse::<f64>().unwrap(), 0.1 + 0.2);
        assert_eq!(&fields[1..], ["micro+macro", "7"]);
    }

    #[test]
    fn floats_round_trip_and_text_is_quoted_when_it_must_be() {
        for x in [0.0, 1.0, 5e-324, 1e300, 1.0 / 3.0, -2.5e-8, 123_456_789.123] {
            let text = line(
                &Row {
                    force: x,
                    label: "",
                    count: 0,
                },
                false,
            );
            let cell = text.split(',').next().unwrap();
            assert_eq!(cell.parse::<f64>().unwrap(), x, "{text}");
        }
        let text = line(
            &Row {
                force: 1.0,
                label: "a,\"b\"",
                count: 0,
            },
            false,
        );
        assert_eq!(text, "1.0,\"a,\"\"b\"\"\",0\n");
    }

    #[test]
    fn nested_values_are_refused_not_flattened() {
        #[derive(Serialize)]
        struct Nested {
            inner: Vec<f64>,
        }
        let mut out = Vec::new();
        assert!(write_row(&mut out, &Nested { inner: vec![1.0] }).is_err());
    }
}
