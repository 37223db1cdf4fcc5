//! The values of the formats and enums the commands take: the application's own (`--format`)
//! and clap's view of the library's (`TableFormat`, `YMode`, `DeckMesh`, `AnyChart`).

use super::*;
use clap::ValueEnum;

/// Formats of `cycle`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CycleFormat {
    /// Readable summary.
    Text,
    /// JSON summary.
    Json,
    /// The loop points, both laws, as CSV.
    Csv,
}

/// Formats of single-point reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReportFormat {
    /// Readable report.
    Text,
    /// JSON object with unit-suffixed names.
    Json,
}

/// Output formats of `compare`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CompareFormat {
    /// A table with the K_T the results imply.
    Text,
    /// One row per FE point.
    Csv,
    /// Rows and the implied K_T.
    Json,
}

/// Formats of `microslip plot`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FigureFormat {
    /// An SVG figure: axes with units, legend, the chart's curves and points.
    Svg,
    /// The same figure as a PNG image of 1600 x 1000 px.
    Png,
    /// The same figure as a one-page PDF (vector, font embedded).
    Pdf,
    /// The chart's points: series, x, y (with the axis titles).
    Csv,
}

impl FigureFormat {
    /// The figure format, or `None` for CSV.
    pub(in crate::cli) fn figure(self) -> Option<figure::Format> {
        match self {
            FigureFormat::Svg => Some(figure::Format::Svg),
            FigureFormat::Png => Some(figure::Format::Png),
            FigureFormat::Pdf => Some(figure::Format::Pdf),
            FigureFormat::Csv => None,
        }
    }

    /// The extension, also the name `--format` takes.
    pub(in crate::cli) fn extension(self) -> &'static str {
        self.figure().map_or("csv", figure::Format::extension)
    }

    /// The format of `output`'s extension and `--format`, which must agree: a file named `w.png`
    /// holds a PNG. No extension (or stdout) takes `--format`, else `default`. An extension no
    /// format has is refused, so a figure is never written under a name that lies about it.
    pub(in crate::cli) fn choose(
        format: Option<FigureFormat>,
        output: Option<&std::path::Path>,
        flag: &str,
        accepted: &[FigureFormat],
        default: FigureFormat,
    ) -> Result<FigureFormat, CliError> {
        let list = accepted
            .iter()
            .map(|f| format!(".{}", f.extension()))
            .collect::<Vec<_>>()
            .join(", ");
        let shown = || {
            report::sanitize(&output.map(|p| p.display().to_string()).unwrap_or_default())
                .into_owned()
        };
        let by_name = match output.and_then(|p| p.extension()) {
            None => None,
            Some(extension) => Some(
                accepted
                    .iter()
                    .copied()
                    .find(|f| extension.eq_ignore_ascii_case(f.extension()))
                    .ok_or_else(|| {
                        CliError::Invalid(format!(
                            "invalid {flag} = '{}': microslip writes {list} (the extension chooses the format)",
                            shown()
                        ))
                    })?,
            ),
        };
        match (format, by_name) {
            (Some(asked), _) if !accepted.contains(&asked) => Err(CliError::Invalid(format!(
                "invalid --format = {}: accepted here: {}",
                asked.extension(),
                list.replace('.', "")
            ))),
            (Some(asked), Some(named)) if asked != named => Err(CliError::Invalid(format!(
                "invalid --format = {} with {flag} = '{}': the file's extension says .{}; name the file .{} or leave out --format",
                asked.extension(),
                shown(),
                named.extension(),
                asked.extension()
            ))),
            (asked, named) => Ok(named.or(asked).unwrap_or(default)),
        }
    }
}

/// clap's view of a library enum: each value with the key users type and its help line. The
/// library's own types carry no clap derive (the library compiles without clap, and what a
/// command line accepts is this layer's business), so each lists its values here.
macro_rules! value_enum {
    ($ty:ty { $($variant:expr => ($key:expr, $help:expr)),+ $(,)? }) => {
        impl ValueEnum for $ty {
            fn value_variants<'a>() -> &'a [Self] {
                &[$($variant),+]
            }

            fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
                $(
                    if *self == $variant {
                        return Some(clap::builder::PossibleValue::new($key).help($help));
                    }
                )+
                None
            }
        }
    };
}

value_enum!(TableFormat {
    TableFormat::Csv => ("csv", "CSV with a header line"),
    TableFormat::Json => ("json", "JSON array of row objects"),
});

value_enum!(YMode {
    YMode::Linear => (YMode::Linear.key(), "The values, on a linear axis"),
    YMode::Log => (YMode::Log.key(), "The values, on a logarithmic axis (decades)"),
    YMode::Relative => (YMode::Relative.key(), "Each curve over the Coulomb curve, minus 1, in %"),
});

value_enum!(DeckMesh {
    DeckMesh::Coarse => (DeckMesh::Coarse.name(), "The default mesh of the problem's deck (the deck's own node and element lists give its size)"),
    DeckMesh::Fine => (DeckMesh::Fine.name(), "Every element size halved"),
    DeckMesh::Finest => (DeckMesh::Finest.name(), "Every element size a quarter of the coarse one (the third rung of a mesh ladder)"),
});

impl ValueEnum for AnyChart {
    fn value_variants<'a>() -> &'a [Self] {
        AnyChart::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let model = self.kind().name();
        Some(
            clap::builder::PossibleValue::new(self.key())
                .help(format!("{model}: {}", self.title())),
        )
    }
}
