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

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use thiserror::Error;

use super::number_with;
#[cfg(any(feature = "app", test))]
use crate::chart::YMode;
#[cfg(any(feature = "app", test))]
use crate::chart::view::{AnyChart, BeamChart, PlateChart};
use crate::chart::{Plot, PlotSeries, SeriesKind, SeriesRole};

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

    /// The format an extension names (any letter case), if it is one.
    pub fn from_extension(extension: &str) -> Option<Format> {
        Format::ALL
            .into_iter()
            .find(|f| f.extension().eq_ignore_ascii_case(extension))
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
pub(crate) const FONT: &[u8] = include_bytes!("fonts/DejaVuSans-subset.ttf");

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

/// Okabe-Ito colours (distinguishable with colour-vision deficiency): the laws' curves by role,
/// family members by position.
const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(120, 120, 120),
];

/// Colours of pinned curves (drawn dash-dotted), by pin number: set apart from [`PALETTE`] and from
/// Coulomb's black (a dark grey pin 1 was taken for Coulomb on paper).
const PIN_PALETTE: [RGBColor; 4] = [
    RGBColor(117, 112, 179),
    RGBColor(231, 41, 138),
    RGBColor(166, 118, 29),
    RGBColor(102, 166, 30),
];

/// The grey of the cursor and of limit lines.
const GREY: RGBColor = RGBColor(150, 150, 150);

/// How a series of a role looks in a figure: one look per role on every chart, Coulomb always
/// black (the reference the others are compared with); a family member by its position.
#[derive(Debug, Clone, Copy)]
struct Look {
    colour: RGBColor,
    width: u32,
    /// SVG dash pattern (`stroke-dasharray`), solid if none.
    dashes: Option<&'static str>,
    /// The marker of a points series.
    marker: Marker,
}

/// The marker of a points series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Marker {
    /// A line, not points.
    None,
    /// An open circle: the finite-element points.
    Circle,
    /// An open square: the plate's continuum points.
    Square,
    /// An open triangle: measured and external points.
    Triangle,
}

fn look(role: SeriesRole) -> Look {
    let nth =
        |palette: &[RGBColor], n: u8| palette[usize::from(n.saturating_sub(1)) % palette.len()];
    let line = |colour| Look {
        colour,
        width: 2,
        dashes: None,
        marker: Marker::None,
    };
    let points = |colour, marker| Look {
        marker,
        ..line(colour)
    };
    match role {
        // Drawn over the other curves and dashed: where a regularized curve lies on it (K_T x 5
        // on w(L) vs F everywhere), both are seen.
        SeriesRole::Coulomb => Look {
            dashes: Some("7 4"),
            ..line(BLACK)
        },
        SeriesRole::Current => line(PALETTE[0]),
        SeriesRole::Softer => line(PALETTE[1]),
        SeriesRole::Stiffer => line(PALETTE[2]),
        // Dotted: apart from Coulomb's dashes where both lie on mu P.
        SeriesRole::Limit => Look {
            dashes: Some("2 3"),
            ..line(PALETTE[6])
        },
        SeriesRole::Cursor => Look {
            width: 1,
            dashes: Some("6 4"),
            ..line(GREY)
        },
        SeriesRole::FiniteElements => points(PALETTE[3], Marker::Circle),
        SeriesRole::Continuum => points(PALETTE[5], Marker::Square),
        SeriesRole::Measured => points(PALETTE[4], Marker::Triangle),
        SeriesRole::External => points(PALETTE[6], Marker::Triangle),
        // Dash-dot: neither Coulomb's even dashes nor the limit's dots.
        SeriesRole::Pin(n) => Look {
            dashes: Some("10 4 2 4"),
            ..line(nth(&PIN_PALETTE, n))
        },
        SeriesRole::Family(n) => line(nth(&PALETTE, n)),
    }
}

/// The plot as an SVG document of 800 x 500 px (`SIZE`).
///
/// # Errors
/// [`FigureError::Drawing`] if plotters fails.
pub fn svg(plot: &Plot) -> Result<String, FigureError> {
    let mut out = String::new();
    let decade = |[lo, hi]: [f64; 2]| (10f64.powf(lo)..10f64.powf(hi)).log_scale();
    let linear = |[lo, hi]: [f64; 2]| lo..hi;
    let (x, y) = (plot.x.bounds, plot.y.bounds);
    match (plot.x.log, plot.y.log) {
        (false, false) => draw(&mut out, plot, linear(x), linear(y)),
        (true, false) => draw(&mut out, plot, decade(x), linear(y)),
        (false, true) => draw(&mut out, plot, linear(x), decade(y)),
        (true, true) => draw(&mut out, plot, decade(x), decade(y)),
    }
    .map_err(|e| FigureError::Drawing(e.to_string()))?;
    Ok(out)
}

/// The corner of the plot area with the fewest points, for the legend.
fn emptiest_corner(plot: &Plot) -> SeriesLabelPosition {
    let [x0, x1] = plot.x.bounds;
    let [y0, y1] = plot.y.bounds;
    let corners = [
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    let crowd = |right: bool, top: bool| {
        plot.series
            .iter()
            .flat_map(|s| &s.points)
            .filter(|&&(x, y)| {
                let (u, v) = ((x - x0) / (x1 - x0), (y - y0) / (y1 - y0));
                (if right { u > 0.6 } else { u < 0.4 }) && (if top { v > 0.6 } else { v < 0.4 })
            })
            .count()
    };
    corners
        .into_iter()
        .min_by_key(|&(_, right, top)| crowd(right, top))
        .map_or(SeriesLabelPosition::UpperLeft, |c| c.0)
}

type DrawResult = Result<(), Box<dyn std::error::Error>>;

/// Height of the caption row under the plot (the parameters a comparison holds fixed).
const CAPTION_ROW: u32 = 24;

/// Stands where the series go while plotters draws, then is replaced by them (see [`draw`]).
const SERIES_HERE: &str = "microslip-series-go-here";

/// `#RRGGBB`, as plotters writes colours.
fn hex(colour: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", colour.0, colour.1, colour.2)
}

/// A pixel coordinate with two decimals (a hundredth of a pixel is below any display's
/// resolution).
fn px((x, y): (f64, f64)) -> String {
    format!("{x:.2},{y:.2}")
}

/// The series of `plot` as SVG elements, in drawing order (by [`SeriesRole::layer`]: cursor,
/// limit lines, curves with pins first and Coulomb last, points), at fractional pixel positions
/// given by `at`.
fn series_elements(plot: &Plot, at: &dyn Fn(f64, f64) -> (f64, f64)) -> String {
    let mut order: Vec<&PlotSeries> = plot.series.iter().collect();
    order.sort_by_key(|s| {
        (
            s.role.layer(),
            !matches!(s.kind(), SeriesKind::Pin(_)),
            s.role == SeriesRole::Coulomb,
        )
    });
    let mut out = String::new();
    for series in order {
        let look = look(series.role);
        let stroke = format!(
            "opacity=\"1\" stroke=\"{}\" stroke-width=\"{}\"{}",
            hex(look.colour),
            look.width,
            look.dashes
                .map(|d| format!(" stroke-dasharray=\"{d}\""))
                .unwrap_or_default()
        );
        let points = series.points.iter().map(|&(x, y)| at(x, y));
        match look.marker {
            Marker::None => {
                if series.points.len() < 2 {
                    continue;
                }
                let path: Vec<String> = points.map(px).collect();
                out.push_str(&format!(
                    "<polyline fill=\"none\" {stroke} points=\"{}\"/>\n",
                    path.join(" ")
                ));
            }
            Marker::Circle => {
                for (x, y) in points {
                    out.push_str(&format!(
                        "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"4\" fill=\"none\" {stroke}/>\n"
                    ));
                }
            }
            Marker::Square => {
                for (x, y) in points {
                    out.push_str(&format!(
                        "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"7\" height=\"7\" fill=\"white\" {stroke}/>\n",
                        x - 3.5,
                        y - 3.5
                    ));
                }
            }
            Marker::Triangle => {
                for (x, y) in points {
                    let corners = [(x, y - 4.5), (x - 4.0, y + 2.5), (x + 4.0, y + 2.5)];
                    let path: Vec<String> = corners.into_iter().map(px).collect();
                    out.push_str(&format!(
                        "<polygon fill=\"none\" {stroke} points=\"{}\"/>\n",
                        path.join(" ")
                    ));
                }
            }
        }
    }
    out
}

/// Draws the figure. Plotters' SVG backend rounds every coordinate to a whole pixel, which makes
/// a gently sloping curve a staircase; so plotters draws the frame, the axes, the title, the
/// caption and the legend, and the series are written here at fractional pixel positions, with
/// the same mapping as plotters' axes (the plot area's pixel range, first to last pixel, y
/// upwards). They replace a placeholder text drawn just before the legend, so that the legend
/// stays on top of the curves.
fn draw<X, Y>(out: &mut String, plot: &Plot, x_spec: X, y_spec: Y) -> DrawResult
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let area;
    {
        let root = SVGBackend::with_string(out, SIZE).into_drawing_area();
        root.fill(&WHITE)?;
        let body = match &plot.caption {
            Some(caption) => {
                let (body, foot) = root.split_vertically(SIZE.1 - CAPTION_ROW);
                let style = TextStyle::from(("sans-serif", 13))
                    .color(&RGBColor(60, 60, 60))
                    .pos(plotters::style::text_anchor::Pos::new(
                        plotters::style::text_anchor::HPos::Center,
                        plotters::style::text_anchor::VPos::Top,
                    ));
                foot.draw(&Text::new(
                    caption.as_str(),
                    ((SIZE.0 / 2) as i32, 2),
                    style,
                ))?;
                body
            }
            None => root.clone(),
        };
        let mut chart = ChartBuilder::on(&body)
            .caption(&plot.title, ("sans-serif", 20))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(72)
            .build_cartesian_2d(x_spec, y_spec)?;
        // Key points that miss 0 by a rounding error (6.9e-18 on a symmetric axis) are labelled 0.
        let tick =
            |span: f64| move |v: &f64| number_with(if v.abs() < 1e-9 * span { 0.0 } else { *v }, 3);
        let span = |a: &crate::chart::Axis| (a.value(a.bounds[1]) - a.value(a.bounds[0])).abs();
        let (x_tick, y_tick) = (tick(span(&plot.x)), tick(span(&plot.y)));
        chart
            .configure_mesh()
            .x_desc(plot.x.title.as_str())
            .y_desc(plot.y.title.as_str())
            .x_label_formatter(&x_tick)
            .y_label_formatter(&y_tick)
            .x_labels(7)
            .y_labels(7)
            .label_style(("sans-serif", 13))
            .axis_desc_style(("sans-serif", 15))
            .max_light_lines(0)
            .bold_line_style(RGBColor(225, 225, 225))
            .draw()?;
        area = chart.plotting_area().get_pixel_range();
        body.draw(&Text::new(SERIES_HERE, (0, 0), ("sans-serif", 1)))?;
        // The legend in the plot's order with the cursor last, each entry an empty series
        // carrying its label and mark.
        let mut entries: Vec<&PlotSeries> = plot.series.iter().collect();
        entries.sort_by_key(|s| s.kind() == SeriesKind::Cursor);
        for series in entries {
            // The legend mark: a line (two dashes for a dashed one) or the marker.
            let look = look(series.role);
            let style = ShapeStyle::from(&look.colour).stroke_width(look.width);
            let entry = chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
                .label(series.name.as_str());
            match (look.marker, look.dashes) {
                (Marker::Circle, _) => {
                    entry.legend(move |(x, y)| Circle::new((x + 10, y), 4, style));
                }
                (Marker::Square, _) => {
                    entry.legend(move |(x, y)| {
                        Rectangle::new([(x + 7, y - 3), (x + 14, y + 4)], style)
                    });
                }
                (Marker::Triangle, _) => {
                    entry.legend(move |(x, y)| {
                        PathElement::new(
                            [
                                (x + 10, y - 4),
                                (x + 6, y + 3),
                                (x + 14, y + 3),
                                (x + 10, y - 4),
                            ],
                            style,
                        )
                    });
                }
                // A dotted line (the limits) as dots, apart from the dashed ones.
                (Marker::None, Some(_)) if series.role == SeriesRole::Limit => {
                    entry.legend(move |(x, y)| {
                        let dot = |i: i32| PathElement::new([(4 * i, 0), (4 * i + 2, 0)], style);
                        EmptyElement::at((x, y)) + dot(0) + dot(1) + dot(2) + dot(3) + dot(4)
                    });
                }
                (Marker::None, Some(_)) => {
                    entry.legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new([(0, 0), (8, 0)], style)
                            + PathElement::new([(12, 0), (20, 0)], style)
                    });
                }
                (Marker::None, None) => {
                    entry.legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], style));
                }
            }
        }
        chart
            .configure_series_labels()
            .position(emptiest_corner(plot))
            .label_font(("sans-serif", 13))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .draw()?;
        root.present()?;
    }
    // The plot area's first and last pixels, as plotters maps its axes.
    let (left, right) = (f64::from(area.0.start), f64::from(area.0.end - 1));
    let (top, bottom) = (f64::from(area.1.start), f64::from(area.1.end - 1));
    let ([x0, x1], [y0, y1]) = (plot.x.bounds, plot.y.bounds);
    let at = |x: f64, y: f64| {
        (
            left + (x - x0) / (x1 - x0) * (right - left),
            bottom - (y - y0) / (y1 - y0) * (bottom - top),
        )
    };
    let series = series_elements(plot, &at);
    let marker = out
        .find(SERIES_HERE)
        .ok_or("the series placeholder is missing")?;
    let start = out[..marker]
        .rfind("<text")
        .ok_or("the placeholder is not a text")?;
    let end = marker
        + out[marker..]
            .find("</text>\n")
            .ok_or("the placeholder is not closed")?
        + "</text>\n".len();
    out.replace_range(start..end, &series);
    Ok(())
}

/// One figure of `microslip figures`: a chart of a bundled preset.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg(any(feature = "app", test))]
pub(crate) struct PaperFigure {
    /// File name without extension (`.svg` and `.csv` are written).
    pub stem: &'static str,
    /// The bundled preset charted.
    pub preset: &'static str,
    /// The chart.
    pub chart: AnyChart,
    /// With the project's finite-element points (the paper's comparison figures).
    pub finite_elements: bool,
    /// The y axis.
    pub y: YMode,
    /// What it shows, for the index page.
    pub caption: &'static str,
}

/// The paper's figures (its two data sets, with the finite-element points of its comparison
/// figures), then the cyclic loading this project adds.
#[cfg(any(feature = "app", test))]
pub(crate) const PAPER_FIGURES: &[PaperFigure] = &[
    PaperFigure {
        stem: "beam-w-vs-f",
        preset: "paper-beams",
        chart: AnyChart::Beam(BeamChart::Deflection),
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T = 600 MPa/mm: tip deflection w(L) against the tip force F, \
                  Coulomb and regularized (K_T/5, K_T, K_T x 5), finite-element points at K_T",
    },
    PaperFigure {
        stem: "beam-w-vs-f-relative",
        preset: "paper-beams",
        chart: AnyChart::Beam(BeamChart::Deflection),
        y: YMode::Relative,
        finite_elements: true,
        caption: "Twin beams: the same curves as w(L) / w(L)_Coulomb - 1 in %, where the K_T \
                  family separates: constant in stick, falling once Coulomb slides",
    },
    PaperFigure {
        stem: "beam-soft-w-vs-f",
        preset: "paper-beams-soft",
        chart: AnyChart::Beam(BeamChart::Deflection),
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T/5 = 120 MPa/mm: w(L) against F, finite-element points at \
                  120 MPa/mm",
    },
    PaperFigure {
        stem: "beam-x-vs-f",
        preset: "paper-beams",
        chart: AnyChart::Beam(BeamChart::SlipBoundary),
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams: end X of the microslip zone (from the clamp) against F, \
                  finite-element points at K_T",
    },
    PaperFigure {
        stem: "beam-soft-x-vs-f",
        preset: "paper-beams-soft",
        chart: AnyChart::Beam(BeamChart::SlipBoundary),
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T/5: X against F, finite-element points at 120 MPa/mm",
    },
    PaperFigure {
        stem: "plate-u-vs-kt",
        preset: "paper-plate",
        chart: AnyChart::Plate(PlateChart::Displacement),
        y: YMode::Log,
        finite_elements: true,
        caption: "Squeezed plate: end displacement u(L) against K_T, Coulomb and regularized, \
                  finite-element points and the 2-D plane-strain continuum",
    },
    PaperFigure {
        stem: "plate-xr-vs-mu",
        preset: "paper-plate",
        chart: AnyChart::Plate(PlateChart::SlipBoundary),
        y: YMode::Linear,
        finite_elements: false,
        caption: "Squeezed plate: end X_r of the microslip zone against mu, for K_T/10, K_T, \
                  K_T x 10",
    },
    PaperFigure {
        stem: "plate-pressure",
        preset: "paper-plate",
        chart: AnyChart::Plate(PlateChart::ContactPressure),
        y: YMode::Linear,
        finite_elements: false,
        caption: "Squeezed plate: contact pressure P_r(x)/P along the half-plate of the paper's \
                  flat-plate model (P7-P9, friction saturated everywhere); the plane-strain \
                  continuum's is flat away from the free end (docs/theory.md (P12))",
    },
    PaperFigure {
        stem: "beam-loop",
        preset: "paper-beams",
        chart: AnyChart::Beam(BeamChart::Loop),
        y: YMode::Linear,
        finite_elements: true,
        caption: "One beam cycled between +F and -F (F = 100 N): the hysteresis loop, both laws, \
                  finite-element points of the same cycle",
    },
    PaperFigure {
        stem: "beam-d-vs-fa",
        preset: "paper-beams",
        chart: AnyChart::Beam(BeamChart::Dissipation),
        y: YMode::Log,
        finite_elements: false,
        caption: "Twin beams: dissipation per cycle D (both beams) against the amplitude F_a",
    },
];

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
    /// This figure as an entry of the index page.
    pub(crate) fn entry(&self) -> IndexEntry {
        IndexEntry {
            stem: self.stem.to_string(),
            title: self.chart.title(),
            caption: format!("{} (preset <code>{}</code>", self.caption, self.preset),
            command: format!(
                "microslip plot {} --preset {}{} --y {}",
                self.chart.key(),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::inputs::Inputs;

    fn paper_figure(chart: AnyChart, fe: bool) -> Plot {
        let model = Inputs::paper(chart.kind()).validate().unwrap();
        crate::chart::figure(&model, chart, fe, crate::chart::YMode::Linear).unwrap()
    }

    #[test]
    fn every_chart_draws_a_deterministic_svg_with_its_title_axes_and_legend() {
        for chart in AnyChart::all() {
            let plot = paper_figure(chart, false);
            let first = svg(&plot).unwrap();
            assert_eq!(first, svg(&plot).unwrap(), "{}", chart.key());
            assert!(first.starts_with("<svg") && first.trim_end().ends_with("</svg>"));
            let escaped = |t: &str| t.replace('&', "&amp;").replace('<', "&lt;");
            for text in [&plot.title, &plot.x.title, &plot.y.title] {
                assert!(first.contains(&escaped(text)), "{}: {text}", chart.key());
            }
            for s in &plot.series {
                assert!(
                    first.contains(&escaped(&s.name)),
                    "{}: {}",
                    chart.key(),
                    s.name
                );
            }
            assert!(
                !first.contains("NaN") && !first.contains("inf"),
                "{}",
                chart.key()
            );
        }
    }

    #[test]
    fn log_axes_get_decade_ticks_and_symmetric_axes_a_clean_zero() {
        let plate = svg(&paper_figure(
            AnyChart::Plate(PlateChart::Displacement),
            false,
        ))
        .unwrap();
        for decade in ["100", "1e6", "1e10"] {
            assert!(plate.contains(&format!("\n{decade}\n</text>")), "{decade}");
        }
        let cycle = svg(&paper_figure(AnyChart::Beam(BeamChart::Loop), false)).unwrap();
        assert!(!cycle.contains("e-18") && cycle.contains("\n0\n</text>"));
    }

    /// One element of an SVG as plotters writes it (one element a line, a `<text>`'s content on
    /// the lines before its `</text>`): name, attributes, text.
    #[derive(Debug)]
    struct Element {
        name: String,
        attributes: Vec<(String, String)>,
        text: String,
    }

    impl Element {
        fn get(&self, key: &str) -> Option<&str> {
            let found = self.attributes.iter().find(|(k, _)| k == key);
            found.map(|(_, v)| v.as_str())
        }

        fn number(&self, key: &str) -> f64 {
            let value = self
                .get(key)
                .unwrap_or_else(|| panic!("no {key} in {self:?}"));
            value
                .parse()
                .unwrap_or_else(|_| panic!("{key} = {value:?}"))
        }

        /// Where the element is drawn: a polyline's points, a circle's centre, a text's anchor,
        /// a line's or a rectangle's corners.
        fn points(&self) -> Vec<(f64, f64)> {
            let pair = |x: &str, y: &str| (self.number(x), self.number(y));
            match self.name.as_str() {
                "polyline" => self
                    .get("points")
                    .unwrap_or_default()
                    .split_whitespace()
                    .map(|p| {
                        let (x, y) = p.split_once(',').expect("x,y");
                        (x.parse().expect("x"), y.parse().expect("y"))
                    })
                    .collect(),
                "circle" => vec![pair("cx", "cy")],
                "text" => vec![pair("x", "y")],
                "line" => vec![pair("x1", "y1"), pair("x2", "y2")],
                "rect" => {
                    let (x, y) = pair("x", "y");
                    vec![
                        (x, y),
                        (x + self.number("width"), y + self.number("height")),
                    ]
                }
                _ => Vec::new(),
            }
        }

        /// What a series' legend mark shares with the series: shape and stroke.
        fn look(&self) -> (&str, Option<&str>, Option<&str>) {
            (&self.name, self.get("stroke"), self.get("stroke-width"))
        }
    }

    fn elements(svg: &str) -> Vec<Element> {
        let opening = svg
            .split('<')
            .skip(1)
            .filter(|chunk| !chunk.starts_with('/'));
        opening
            .map(|chunk| {
                let (head, text) = chunk.split_once('>').expect("a closed tag");
                let head = head.trim_end_matches('/');
                let (name, rest) = head.split_once(' ').unwrap_or((head, ""));
                // key="value" pairs: the odd pieces between quotes are the values.
                let pieces: Vec<&str> = rest.split('"').collect();
                let attributes = pieces
                    .chunks_exact(2)
                    .map(|kv| {
                        (
                            kv[0].trim().trim_end_matches('=').to_string(),
                            kv[1].to_string(),
                        )
                    })
                    .collect();
                Element {
                    name: name.to_string(),
                    attributes,
                    text: text.trim().to_string(),
                }
            })
            .collect()
    }

    /// What a reader of a figure looks for.
    struct Expected {
        title: &'static str,
        x_title: &'static str,
        y_title: &'static str,
        /// Legend entries, top to bottom.
        legend: &'static [&'static str],
        /// Curves: polylines of more than two points.
        curves: usize,
        /// Markers: finite-element points.
        markers: usize,
        /// Decades on the x axis, linear otherwise.
        x_log: bool,
        /// The current value, where the cursor (the legend's `current`) stands.
        cursor_x: f64,
    }

    /// Ticks of an axis, (value, position in pixels): at least three, at positions affine in the
    /// value (in its log10, and at powers of ten, on a log axis) to a pixel (plotters draws at
    /// whole pixels). Returns the position of a value.
    fn axis(mut ticks: Vec<(f64, f64)>, log: bool) -> impl Fn(f64) -> f64 {
        assert!(ticks.len() >= 3, "{ticks:?}");
        ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
        let scale = move |v: f64| if log { v.log10() } else { v };
        if log {
            for &(v, _) in &ticks {
                let decade = v > 0.0 && (v.log10() - v.log10().round()).abs() < 1e-12;
                assert!(decade, "{v} on a log axis");
            }
        }
        let ((v0, p0), (v1, p1)) = (ticks[0], ticks[ticks.len() - 1]);
        let (v0, v1) = (scale(v0), scale(v1));
        let position = move |v: f64| p0 + (scale(v) - v0) / (v1 - v0) * (p1 - p0);
        for &(v, p) in &ticks {
            assert!(
                (position(v) - p).abs() <= 1.0,
                "tick {v} at {p} in {ticks:?}"
            );
        }
        position
    }

    /// A box of the figure, in pixels.
    #[derive(Debug, Clone, Copy)]
    struct Area {
        left: f64,
        right: f64,
        top: f64,
        bottom: f64,
    }

    impl Area {
        /// The smallest box around `points`.
        fn around(points: impl IntoIterator<Item = (f64, f64)>) -> Area {
            let empty = Area {
                left: f64::INFINITY,
                right: f64::NEG_INFINITY,
                top: f64::INFINITY,
                bottom: f64::NEG_INFINITY,
            };
            points.into_iter().fold(empty, |a, (x, y)| Area {
                left: a.left.min(x),
                right: a.right.max(x),
                top: a.top.min(y),
                bottom: a.bottom.max(y),
            })
        }

        fn contains(&self, (x, y): (f64, f64)) -> bool {
            (self.left..=self.right).contains(&x) && (self.top..=self.bottom).contains(&y)
        }
    }

    fn names<'a>(texts: &[&'a Element]) -> Vec<&'a str> {
        texts.iter().map(|t| t.text.as_str()).collect()
    }

    /// The texts beside an axis: its ticks, as (value, `coordinate`), and its title, the one text
    /// that is not a number.
    fn side<'a>(
        texts: Vec<&'a Element>,
        title: &str,
        coordinate: &str,
    ) -> (&'a Element, Vec<(f64, f64)>) {
        let (ticks, titles): (Vec<&Element>, Vec<&Element>) = texts
            .into_iter()
            .partition(|t| t.text.parse::<f64>().is_ok());
        assert_eq!(names(&titles), [title]);
        let ticks = ticks
            .iter()
            .map(|t| (t.text.parse().unwrap(), t.number(coordinate)));
        (titles[0], ticks.collect())
    }

    /// How far, in pixels, a point may be from where the axes put its value: plotters rounds the
    /// point and the ticks the axes are read from down to whole pixels (the paper figures' points
    /// are within 0.995 pixels).
    const READING: f64 = 2.0;

    /// The texts around the plot area: the title above it, each axis' title and ticks beside it,
    /// the y axis' title turned to read along the axis. Returns where each axis puts a value.
    fn assert_title_and_axes(
        texts: &[&Element],
        area: Area,
        expected: &Expected,
    ) -> [impl Fn(f64) -> f64; 2] {
        let placed = |test: &dyn Fn((f64, f64)) -> bool| -> Vec<&Element> {
            let found = texts.iter().copied().filter(|t| test(t.points()[0]));
            found.collect()
        };
        assert_eq!(names(&placed(&|(_, y)| y < area.top)), [expected.title]);
        let (x_title, x_ticks) = side(placed(&|(_, y)| y > area.bottom), expected.x_title, "x");
        let (y_title, y_ticks) = side(placed(&|(x, _)| x < area.left), expected.y_title, "y");
        assert!(x_title.get("transform").is_none());
        let turned = y_title.get("transform");
        assert!(
            turned.is_some_and(|t| t.starts_with("rotate(270")),
            "{y_title:?}"
        );
        [axis(x_ticks, expected.x_log), axis(y_ticks, false)]
    }

    /// The legend: a framed box in the plot area, its entries in order, each with a mark beside it
    /// and a series drawn like the mark (same shape and stroke) outside the box: each point of the
    /// plot's series of that name where the axes put it (to [`READING`]), and the cursor at the
    /// expected value.
    fn assert_legend_and_series(
        all: &[Element],
        area: Area,
        expected: &Expected,
        plot: &Plot,
        at: &dyn Fn(f64, f64) -> (f64, f64),
    ) {
        let frame = all
            .iter()
            .find(|e| e.name == "rect" && e.get("fill") == Some("none"));
        let frame = Area::around(frame.expect("a legend frame").points());
        let framed =
            area.contains((frame.left, frame.top)) && area.contains((frame.right, frame.bottom));
        assert!(framed, "{frame:?}");
        let legend: Vec<&Element> = all
            .iter()
            .filter(|e| e.name == "text" && area.contains(e.points()[0]))
            .collect();
        assert_eq!(names(&legend), expected.legend);
        let drawn = all
            .iter()
            .filter(|e| matches!(e.name.as_str(), "polyline" | "circle"));
        let (marks, series): (Vec<&Element>, Vec<&Element>) =
            drawn.partition(|e| e.points().into_iter().all(|p| frame.contains(p)));
        let (mut curves, mut markers) = (0, 0);
        for entry in legend {
            let distance = |e: &&Element| (e.points()[0].1 - entry.number("y")).abs();
            let mark = marks
                .iter()
                .min_by(|a, b| distance(a).total_cmp(&distance(b)));
            let mark = mark.expect("a legend mark");
            let own: Vec<&&Element> = series.iter().filter(|e| e.look() == mark.look()).collect();
            curves += own.iter().filter(|e| e.points().len() > 2).count();
            markers += own.iter().filter(|e| e.name == "circle").count();
            let points: Vec<(f64, f64)> = own.iter().flat_map(|e| e.points()).collect();
            assert!(
                !points.is_empty(),
                "{}: nothing drawn like its mark",
                entry.text
            );
            assert!(points.iter().all(|&p| area.contains(p)), "{}", entry.text);
            let data = plot.series.iter().find(|s| s.name == entry.text);
            let data = data.expect("a series of the plot");
            if data.kind() == SeriesKind::Cursor {
                let x = at(expected.cursor_x, 0.0).0;
                assert!(
                    points.iter().all(|p| (p.0 - x).abs() <= READING),
                    "{points:?}"
                );
                continue;
            }
            let values = data.points.iter();
            let wanted = values.map(|&(x, y)| at(plot.x.value(x), plot.y.value(y)));
            let wanted: Vec<(f64, f64)> = wanted.collect();
            assert_eq!(points.len(), wanted.len(), "{}", entry.text);
            for (p, w) in points.iter().zip(&wanted) {
                let near = (p.0 - w.0).abs() <= READING && (p.1 - w.1).abs() <= READING;
                assert!(near, "{}: {p:?} drawn for {w:?}", entry.text);
            }
        }
        assert_eq!((curves, markers), (expected.curves, expected.markers));
    }

    /// The figure of `plot` as its reader sees it: every coordinate finite, the plot area (the box
    /// its grid lines span) filling most of the figure, the texts around it, and the legend and
    /// the series in it.
    fn assert_figure(plot: &Plot, expected: &Expected) {
        let all = elements(&svg(plot).unwrap());
        for e in &all {
            let finite = e
                .points()
                .iter()
                .all(|p| p.0.is_finite() && p.1.is_finite());
            assert!(finite, "{e:?}");
        }
        let grid = all.iter().filter(|e| e.name == "line");
        let area = Area::around(grid.flat_map(Element::points));
        let (width, height) = (f64::from(SIZE.0), f64::from(SIZE.1));
        let fills = area.right - area.left > 0.75 * width && area.bottom - area.top > 0.7 * height;
        assert!(fills, "{area:?}");
        let texts: Vec<&Element> = all.iter().filter(|e| e.name == "text").collect();
        let [x, y] = assert_title_and_axes(&texts, area, expected);
        assert_legend_and_series(&all, area, expected, plot, &|u, v| (x(u), y(v)));
    }

    /// What the reader of two paper figures must find: a linear one with finite-element points
    /// and a log one.
    #[test]
    fn paper_figures_show_their_title_axes_legend_and_series() {
        assert_figure(
            &paper_figure(AnyChart::Beam(BeamChart::Deflection), true),
            &Expected {
                title: "w(L) vs F, K_T = 600 MPa/mm",
                x_title: "F (N)",
                y_title: "w(L) (mm)",
                legend: &[
                    "Coulomb",
                    "K_T/5",
                    "K_T*5",
                    "K_T",
                    "finite elements",
                    "current",
                ],
                curves: 4,
                markers: 8,
                x_log: false,
                cursor_x: 100.0,
            },
        );
        assert_figure(
            &paper_figure(AnyChart::Plate(PlateChart::Displacement), false),
            &Expected {
                title: "u(L) vs K_T",
                x_title: "K_T (MPa/mm, log)",
                y_title: "u(L) (mm)",
                legend: &["Coulomb", "regularized", "current"],
                curves: 2,
                markers: 0,
                x_log: true,
                cursor_x: 1e6,
            },
        );
    }

    #[test]
    fn the_index_shows_every_figure_with_its_data() {
        let entries: Vec<IndexEntry> = PAPER_FIGURES.iter().map(PaperFigure::entry).collect();
        let page = index_html(PAPER_INTRO, &entries, Format::Svg);
        for f in PAPER_FIGURES {
            assert!(
                page.contains(&format!("src=\"{}.svg\"", f.stem)),
                "{}",
                f.stem
            );
            assert!(
                page.contains(&format!("href=\"{}.csv\"", f.stem)),
                "{}",
                f.stem
            );
            assert!(crate::preset::resolve(f.preset).is_ok(), "{}", f.preset);
        }
        let stems: std::collections::HashSet<_> = PAPER_FIGURES.iter().map(|f| f.stem).collect();
        assert_eq!(stems.len(), PAPER_FIGURES.len());
    }
}
