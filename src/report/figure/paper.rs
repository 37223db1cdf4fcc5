//! The paper's figures (`microslip figures`): what one is (a chart of a bundled preset, with its
//! caption), every problem's list gathered from its face folder, and the HTML index that shows
//! them with their data. The captions are the problems' own words, so they live in their folders.

use super::Format;
use crate::chart::YMode;
use crate::chart::view::AnyChart;

/// One figure of `microslip figures`: a chart of a bundled preset.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg(any(feature = "app", test))]
pub(crate) struct PaperFigure {
    /// File name without extension (`.svg` and `.csv` are written).
    pub stem: &'static str,
    /// The bundled preset charted.
    pub preset: &'static str,
    /// The chart, by its key (`w-vs-f`, as `microslip plot` names it): the chart layer names no
    /// problem's chart type, so the figure names the chart as a user does ([`PaperFigure::chart`]).
    pub chart_key: &'static str,
    /// With the project's finite-element points (the paper's comparison figures).
    pub finite_elements: bool,
    /// The y axis.
    pub y: YMode,
    /// What it shows, for the index page.
    pub caption: &'static str,
}

/// Every problem's figures for `microslip figures`, in the registry's order: each problem's
/// `PAPER_FIGURES`, in its face folder (`src/problems/<name>/figures.rs` or its `mod.rs`),
/// gathered from the registry line, so that no problem's caption lives here.
#[cfg(any(feature = "app", test))]
macro_rules! paper_figures {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        [$(crate::problems::$folder::PAPER_FIGURES),+]
    };
}

/// [`paper_figures!`] as one list: the paper's data sets' figures (with the finite-element
/// points of its comparison figures) and those this project adds, problem by problem.
#[cfg(any(feature = "app", test))]
pub(crate) static PAPER_FIGURES: std::sync::LazyLock<Vec<PaperFigure>> =
    std::sync::LazyLock::new(|| {
        let mut all: Vec<PaperFigure> = Vec::new();
        for figure in microslip_core::with_problems!(paper_figures)
            .into_iter()
            .flatten()
        {
            // A folder that two registry lines name lists its figures for both: once here.
            if all.iter().all(|seen| seen.stem != figure.stem) {
                all.push(*figure);
            }
        }
        all
    });

/// One figure of an index page: its files, its title and what it shows.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg(any(feature = "app", test))]
pub(crate) struct IndexEntry {
    /// File name without extension (`.svg` and `.csv` are written).
    pub stem: String,
    /// The chart's short title (the image's alt text).
    pub title: &'static str,
    /// What it shows.
    pub caption: String,
    /// The command that draws it alone.
    pub command: String,
}

#[cfg(any(feature = "app", test))]
impl PaperFigure {
    /// The chart [`PaperFigure::chart_key`] names. Every key of [`PAPER_FIGURES`] names a chart
    /// (a unit test reads them all), so the fallback, the first chart, is never drawn.
    pub(crate) fn chart(&self) -> AnyChart {
        AnyChart::parse(self.chart_key).unwrap_or(AnyChart::ALL[0])
    }

    /// This figure as an entry of the index page.
    pub(crate) fn entry(&self) -> IndexEntry {
        IndexEntry {
            stem: self.stem.to_string(),
            title: self.chart().title(),
            caption: format!("{} (preset <code>{}</code>", self.caption, self.preset),
            command: format!(
                "microslip plot {} --preset {}{} --y {}",
                self.chart().key(),
                self.preset,
                if self.finite_elements { " --fe" } else { "" },
                self.y.key()
            ),
        }
    }
}

/// A user's own bench, as `figures --preset/--set` draws it.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg(feature = "app")]
pub(crate) struct Bench {
    /// The preset's name as shown (`mine (modified by --set)`).
    pub preset: String,
    /// Its parameters ([`parameter_caption`]).
    pub values: String,
    /// The flags that chose it, as typed (`--preset mine --set KT=3e5`).
    pub flags: String,
    /// With the project's finite-element points.
    pub finite_elements: bool,
}

#[cfg(feature = "app")]
impl Bench {
    /// The index entry of `chart` on the y axis `y`.
    pub(crate) fn entry(&self, chart: AnyChart, y: YMode) -> IndexEntry {
        IndexEntry {
            // A chart key that already names its problem (`lap-tau`) is not named twice.
            stem: {
                let model = chart.kind().name();
                match chart
                    .key()
                    .strip_prefix(model)
                    .and_then(|k| k.strip_prefix('-'))
                {
                    Some(rest) => format!("{model}-{rest}"),
                    None => format!("{model}-{}", chart.key()),
                }
            },
            title: chart.title(),
            caption: format!(
                "{} (preset <code>{}</code>: {}",
                chart.title(),
                html_text(&self.preset),
                html_text(&self.values)
            ),
            command: format!(
                "microslip plot {} {}{} --y {}",
                chart.key(),
                html_text(&self.flags),
                if self.finite_elements { " --fe" } else { "" },
                y.key()
            ),
        }
    }

    /// The introduction of its index page.
    pub(crate) fn intro(&self) -> String {
        format!(
            "Your bench, preset <code>{}</code>: {}. Units: mm, N, MPa; K_T in MPa/mm. Closed \
             forms under both laws{}. Made by <code>microslip figures {}</code>.",
            html_text(&self.preset),
            html_text(&self.values),
            if self.finite_elements {
                "; points are the project's own finite-element solutions"
            } else {
                ""
            },
            html_text(&self.flags)
        )
    }
}

/// Text for an HTML page: `&`, `<`, `>` and `"` escaped (preset names and paths are the user's).
#[cfg(feature = "app")]
fn html_text(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The introduction of the paper's index page.
#[cfg(any(feature = "app", test))]
pub(crate) const PAPER_INTRO: &str = "Ligier &amp; Bonhote (2014), regularized Coulomb friction: the paper's data sets, \
     both laws, closed forms; points are the project's own finite-element solutions. \
     Units: mm, N, MPa; K_T in MPa/mm. Made by <code>microslip figures</code>.";

/// The parameters of `inputs` as a caption says them: `L = 200 mm, b = 20 mm, ..., mu = 0.3`.
#[cfg(feature = "app")]
pub(crate) fn parameter_caption(inputs: &crate::Inputs) -> String {
    inputs
        .kind()
        .params()
        .iter()
        .filter_map(|&param| {
            let value = inputs.get(param)?;
            let unit = match param.unit() {
                crate::Unit::Dimensionless => String::new(),
                unit => format!(" {unit}"),
            };
            Some(format!(
                "{param} = {}{unit}",
                crate::kernel::params::Compact(value)
            ))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// An HTML page showing `entries` (files of `format` beside it) after `intro` (HTML), with their
/// captions, CSV data links and the command that draws each alone. A PDF is shown by the browser's
/// viewer (`<object>`), with a link where it has none.
#[cfg(any(feature = "app", test))]
pub(crate) fn index_html(intro: &str, entries: &[IndexEntry], format: Format) -> String {
    let mut page = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>microslip figures</title>\n<style>\n\
         body { font-family: sans-serif; max-width: 860px; margin: 2em auto; }\n\
         figure { margin: 0 0 2.5em 0; } img { width: 100%; border: 1px solid #ddd; }\n\
         </style>\n</head>\n<body>\n<h1>microslip figures</h1>\n",
    );
    page.push_str(&format!("<p>{intro}</p>\n"));
    for entry in entries {
        page.push_str(&format!(
            "<figure id=\"{stem}\">\n{image}\n\
             <figcaption>{caption}; \
             data: <a href=\"{stem}.csv\">{stem}.csv</a>; \
             <code>{command}</code>)</figcaption>\n</figure>\n",
            image = match format {
                Format::Pdf => format!(
                    "<object data=\"{stem}.pdf\" type=\"application/pdf\" width=\"100%\" \
                     height=\"540\"><a href=\"{stem}.pdf\">{title} (PDF)</a></object>",
                    stem = entry.stem,
                    title = entry.title
                ),
                Format::Svg | Format::Png => format!(
                    "<img src=\"{stem}.{format}\" alt=\"{title}\">",
                    stem = entry.stem,
                    title = entry.title
                ),
            },
            stem = entry.stem,
            caption = entry.caption,
            command = entry.command,
        ));
    }
    page.push_str("</body>\n</html>\n");
    page
}
