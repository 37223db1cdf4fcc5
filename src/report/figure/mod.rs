//! Figures of the charts: the same [`Plot`] the terminal draws (series, axes, legend, finite-
//! element points), drawn by plotters' SVG backend. Text is written as `<text>` elements in a generic
//! `sans-serif` family; the output depends on the plot alone (no date, no random identifier), so
//! equal inputs give byte-identical files.
//!
//! PNG and PDF are that same SVG rendered (resvg for PNG, svg2pdf for PDF, both on one usvg tree), so
//! the three formats cannot disagree. Their text uses a font built into the binary (`FONT`), not
//! the system's: a figure looks the same on a server with no fonts installed.
//!
//! A log axis of the plot (plotted in log10 units) becomes a real logarithmic axis here, with
//! ticks at decades.
//!
//! Here: the formats and their rendering; the drawing is [`svg`]'s (its own file), the paper's
//! figures and their index `paper`'s.

use thiserror::Error;

use crate::chart::Plot;

#[cfg(any(feature = "app", test))]
mod paper;
mod svg;
#[cfg(test)]
mod tests;

#[cfg(feature = "app")]
pub(crate) use paper::{Bench, parameter_caption};
#[cfg(any(feature = "app", test))]
pub(crate) use paper::{IndexEntry, PAPER_FIGURES, PAPER_INTRO, PaperFigure, index_html};
pub use svg::svg;

/// Width and height of a figure, in SVG pixels (a 16:10 frame that prints well at 16 cm).
pub(crate) const SIZE: (u32, u32) = (800, 500);

/// Why a figure could not be drawn.
#[derive(Debug, Error)]
pub enum FigureError {
    /// The drawing backend failed (a programming error: the SVG goes to a string).
    #[error("drawing the figure failed: {0}")]
    Drawing(String),
    /// The SVG could not be rendered to PNG or PDF (a programming error: the SVG is our own).
    #[error("rendering the figure as {format} failed: {reason}")]
    Render {
        /// The format asked for.
        format: Format,
        /// What failed.
        reason: String,
    },
}

/// The file formats a figure can be written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Vector, for the web and for editing (the index page shows it).
    Svg,
    /// Raster at twice `SIZE` (1600 x 1000 px), for slides, mail and word processors.
    Png,
    /// Vector, with the font embedded, for papers and printing.
    Pdf,
}

impl Format {
    /// Every format, in the order help texts list them.
    pub const ALL: [Format; 3] = [Format::Svg, Format::Png, Format::Pdf];

    /// The file extension (without the dot), also the name `--format` takes.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
            Format::Pdf => "pdf",
        }
    }
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.extension())
    }
}

/// The font of PNG and PDF text: DejaVu Sans cut to Latin-1, Greek, punctuation, arrows and math
/// operators (70 kB; Bitstream Vera license, `fonts/LICENSE-DejaVu.txt`). Built in because a
/// machine without fonts (a CI runner, a container) would otherwise render every label blank.
pub(crate) const FONT: &[u8] = include_bytes!("../fonts/DejaVuSans-subset.ttf");

/// How many PNG pixels per SVG pixel: 2 keeps 13 px labels sharp on slides and when printed.
pub(crate) const PNG_SCALE: u32 = 2;

/// The SVG parsed with [`FONT`] as its only font (the generic `sans-serif` resolves to it).
fn svg_tree(svg: &str, format: Format) -> Result<resvg::usvg::Tree, FigureError> {
    let mut options = resvg::usvg::Options::default();
    let fonts = options.fontdb_mut();
    fonts.load_font_data(FONT.to_vec());
    fonts.set_sans_serif_family("DejaVu Sans");
    resvg::usvg::Tree::from_str(svg, &options).map_err(|e| FigureError::Render {
        format,
        reason: e.to_string(),
    })
}

/// An SVG document (as [`svg`] writes it) as a PNG of `PNG_SCALE` times its size.
///
/// # Errors
/// [`FigureError::Render`] if the SVG cannot be parsed or encoded.
pub fn png_from_svg(svg: &str) -> Result<Vec<u8>, FigureError> {
    let failed = |reason: String| FigureError::Render {
        format: Format::Png,
        reason,
    };
    let tree = svg_tree(svg, Format::Png)?;
    let size = tree.size().to_int_size();
    let (width, height) = (size.width() * PNG_SCALE, size.height() * PNG_SCALE);
    let mut pixmap = resvg::tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| failed(format!("no {width} x {height} px image")))?;
    // Opaque white under the figure: a transparent PNG shows black text on a dark viewer as
    // nothing.
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let scale = PNG_SCALE as f32;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap.encode_png().map_err(|e| failed(e.to_string()))
}

/// An SVG document (as [`svg`] writes it) as a one-page PDF of its size (1 SVG px = 0.75 pt),
/// its text as text in the embedded `FONT`.
///
/// # Errors
/// [`FigureError::Render`] if the SVG cannot be parsed or converted.
pub fn pdf_from_svg(svg: &str) -> Result<Vec<u8>, FigureError> {
    let tree = svg_tree(svg, Format::Pdf)?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        svg2pdf::PageOptions::default(),
    )
    .map_err(|e| FigureError::Render {
        format: Format::Pdf,
        reason: e.to_string(),
    })
}

/// The plot as a file of `format`: the SVG of [`svg`], rendered for PNG and PDF.
///
/// # Errors
/// [`FigureError`] if drawing or rendering fails.
pub fn render(plot: &Plot, format: Format) -> Result<Vec<u8>, FigureError> {
    let svg = svg(plot)?;
    match format {
        Format::Svg => Ok(svg.into_bytes()),
        Format::Png => png_from_svg(&svg),
        Format::Pdf => pdf_from_svg(&svg),
    }
}
