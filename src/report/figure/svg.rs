//! The SVG drawing of a [`Plot`]: each series role's look, the axes (linear, or logarithmic with
//! decade ticks), the legend in the emptiest corner, and the series written as plain SVG paths.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

use super::{FigureError, SIZE};
use crate::chart::{Plot, PlotSeries, SeriesKind, SeriesRole};
use crate::report::number_with;

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

/// How long a legend's line mark is (px).
const SWATCH_LENGTH: i32 = 22;

/// The drawn stretches, [from, to] in px, of a line `length` long dashed as `dashes` (an SVG
/// `stroke-dasharray`: on, off, on, off, ...): the legend's mark of a dashed series.
fn swatch_segments(dashes: &str, length: i32) -> Vec<(i32, i32)> {
    let pattern: Vec<i32> = dashes
        .split([' ', ','])
        .filter_map(|d| d.trim().parse::<f64>().ok())
        .map(|d| d.round().max(1.0) as i32)
        .collect();
    if pattern.is_empty() {
        return vec![(0, length)];
    }
    let mut segments = Vec::new();
    let (mut at, mut i) = (0, 0);
    while at < length {
        let step = pattern[i % pattern.len()];
        if i % 2 == 0 {
            segments.push((at, (at + step).min(length)));
        }
        at += step;
        i += 1;
    }
    segments
}

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

/// Height of a caption row under the plot (the parameters a comparison holds fixed).
const CAPTION_ROW: u32 = 24;

/// The widest caption row, in characters of the caption's 13 px sans-serif (about 7 px each,
/// with a margin): a longer caption (the press fit's twelve parameters) wraps at its commas
/// rather than running off both sides of the figure.
const CAPTION_CHARS: usize = (SIZE.0 / 8) as usize;

/// `caption` in rows of at most [`CAPTION_CHARS`], broken after its commas (a part longer than
/// a row stays whole).
pub(super) fn caption_rows(caption: &str) -> Vec<String> {
    let mut rows: Vec<String> = Vec::new();
    for part in caption.split_inclusive(", ") {
        match rows.last_mut() {
            Some(row) if row.len() + part.trim_end().len() <= CAPTION_CHARS => row.push_str(part),
            _ => rows.push(part.to_string()),
        }
    }
    rows.iter().map(|r| r.trim_end().to_string()).collect()
}

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
                let rows = caption_rows(caption);
                let height =
                    CAPTION_ROW * rows.len().max(1) as u32 - 6 * (rows.len().max(1) - 1) as u32;
                let (body, foot) = root.split_vertically(SIZE.1 - height);
                let style = TextStyle::from(("sans-serif", 13))
                    .color(&RGBColor(60, 60, 60))
                    .pos(plotters::style::text_anchor::Pos::new(
                        plotters::style::text_anchor::HPos::Center,
                        plotters::style::text_anchor::VPos::Top,
                    ));
                for (i, row) in rows.iter().enumerate() {
                    foot.draw(&Text::new(
                        row.as_str(),
                        ((SIZE.0 / 2) as i32, 2 + 18 * i as i32),
                        style.clone(),
                    ))?;
                }
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
                // A dashed line as its own pattern (even dashes, dash-dot), so that the mark
                // matches the curve it names.
                (Marker::None, Some(dashes)) => {
                    // Three stretches at most over the mark's length (a shorter pattern repeats
                    // its last, drawn twice).
                    let segments = swatch_segments(dashes, SWATCH_LENGTH);
                    let stretch = move |k: usize| {
                        let (a, b) = segments
                            .get(k)
                            .or(segments.last())
                            .copied()
                            .unwrap_or((0, SWATCH_LENGTH));
                        PathElement::new([(a, 0), (b, 0)], style)
                    };
                    entry.legend(move |(x, y)| {
                        EmptyElement::at((x, y)) + stretch(0) + stretch(1) + stretch(2)
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
            // plotters sizes the box by its own estimate of the text, narrower than the built-in
            // DejaVu Sans that draws it (issue 47: a long label ran past the box): a wider
            // margin gives the text's end room.
            .margin(18)
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

#[cfg(test)]
mod swatch_tests {
    use super::swatch_segments;

    /// A legend's mark is drawn in its curve's own pattern: even dashes as dashes, a dash-dot
    /// (pin 1's `10 4 2 4`) as a dash and a dot, never the one for the other.
    #[test]
    fn a_legend_mark_follows_its_curve_s_dash_pattern() {
        assert_eq!(swatch_segments("7 4", 22), [(0, 7), (11, 18)]);
        assert_eq!(
            swatch_segments("10 4 2 4", 22),
            [(0, 10), (14, 16), (20, 22)]
        );
        assert_eq!(swatch_segments("", 22), [(0, 22)]);
        assert_ne!(swatch_segments("7 4", 22), swatch_segments("10 4 2 4", 22));
    }
}
