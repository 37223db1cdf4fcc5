//! The figures' tests: every chart draws a deterministic SVG with its title, axes, legend and
//! series where the plot puts them, and the paper's figures and their index show what they say.

use super::paper::*;
use super::svg::*;
use super::{Format, SIZE};
use crate::chart::view::AnyChart;
use crate::chart::{Plot, SeriesKind};
use crate::problems::inputs::Inputs;
use crate::problems::plate::PlateChart;
use crate::problems::twin_beams::BeamChart;

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
    for f in PAPER_FIGURES.iter() {
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
        // Its preset is of the problem whose chart it draws (each problem lists its own).
        let preset = crate::preset::resolve(f.preset).unwrap();
        assert_eq!(preset.inputs.kind(), f.chart().kind(), "{}", f.stem);
        // Every figure names a chart by its key (the fallback of `chart()` is never drawn).
        assert!(AnyChart::parse(f.chart_key).is_some(), "{}", f.chart_key);
    }
    let stems: std::collections::HashSet<_> = PAPER_FIGURES.iter().map(|f| f.stem).collect();
    assert_eq!(stems.len(), PAPER_FIGURES.len());
}

/// The legend's box holds its labels as the built-in font draws them: plotters sizes the box by
/// its own estimate of the text, narrower than DejaVu Sans (issue 47: "KT = 100000 MPa/mm" ran
/// past the box's right edge in `plot sa-vs-q --family KT=1e4,1e5,1e6`). No dark (text) pixel of
/// the PNG may stand within 4 px of the box's right edge or beyond it, level with the box.
#[test]
fn the_legend_box_holds_its_labels_as_drawn() {
    use crate::chart::{SeriesRole, line, linear_axis};
    let names = ["KT = 10000 MPa/mm", "KT = 100000 MPa/mm", "KT = 1e6 MPa/mm"];
    let plot = Plot {
        caption: None,
        title: "legend".to_string(),
        x: linear_axis("Q (N/mm)", 0.0, 10.0),
        y: linear_axis("s(a) (mm)", 0.0, 10.0),
        // Curves in the lower right, so the legend goes to the upper left, away from them.
        series: names
            .iter()
            .zip(1u8..)
            .map(|(name, i)| {
                let y = f64::from(i);
                line(SeriesRole::Family(i), *name, vec![(6.0, y), (10.0, y)])
            })
            .collect(),
    };
    let svg = svg(&plot).unwrap();
    let all = elements(&svg);
    let frame = all
        .iter()
        .find(|e| e.name == "rect" && e.get("fill") == Some("none"))
        .expect("a legend frame");
    let frame = Area::around(frame.points());
    let png = super::png_from_svg(&svg).unwrap();
    let pixmap = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
    let scale = f64::from(super::PNG_SCALE);
    let px = |v: f64| (v * scale).round() as u32;
    let dark = |x: u32, y: u32| {
        pixmap
            .pixel(x, y)
            .is_some_and(|p| p.red() < 110 && p.green() < 110 && p.blue() < 110)
    };
    // From 4 px inside the box's right edge (the text keeps that room; the grey edge is not
    // dark) to well beyond it.
    let (right, top, bottom) = (px(frame.right - 4.0), px(frame.top), px(frame.bottom));
    let outside: usize = (right..right + 60)
        .flat_map(|x| (top..bottom).map(move |y| (x, y)))
        .filter(|&(x, y)| dark(x, y))
        .count();
    assert_eq!(outside, 0, "text right of the legend box {frame:?}");
}

/// A caption wider than the figure (the press fit's twelve parameters, 190 characters) wraps at
/// its commas into rows that fit; a short one stays one row, unchanged.
#[test]
fn a_long_caption_wraps_at_its_commas() {
    let long = "r = 20 mm, ri = 10 mm, ro = 30 mm, L = 17.7332 mm, Es = 210000 MPa, nus = 0.3, \
                Eh = 210000 MPa, nuh = 0.3, delta = 0.0025 mm, mu = 0.1, KT = 10000 MPa/mm";
    let rows = super::svg::caption_rows(long);
    assert!(rows.len() >= 2, "{rows:?}");
    assert!(rows.iter().all(|r| r.len() <= 100), "{rows:?}");
    assert_eq!(rows.join(" "), long);
    assert!(rows.iter().all(|r| !r.ends_with(' ')), "{rows:?}");
    assert_eq!(
        super::svg::caption_rows("L = 200 mm, mu = 0.3"),
        ["L = 200 mm, mu = 0.3"]
    );
}
