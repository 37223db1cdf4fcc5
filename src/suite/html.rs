//! The scorecard as one self-contained HTML page (`suite --html FILE`): the summary table (each
//! case's quantities with their converged values, uncertainties, observed orders, the stick slope
//! used against the deck's, the tolerance and the verdict) and each case's convergence plots,
//! one per quantity: its difference from the reference on each mesh rung against the element size
//! h (the finest rung at half the increment too), the extrapolated answer at h = 0 with its
//! uncertainty band, the reference line and the tolerance band around it.
//!
//! Why written here and not with `report::figure` (plotters): that module is behind the `figures`
//! feature, which the library without the app (and the Python wheel built on it) does not compile,
//! and a plot of three points and four bands needs no more than a few SVG elements. The page has no
//! script, no external style sheet, font or image, so it opens offline, from a CI artifact, in a
//! mail; its markup is well-formed XML (every element closed, every user text escaped), so XML
//! tools read it too.

use std::fmt::Write as _;

use super::score::{CaseScore, QuantityScore, xml};
use crate::fe::deck::DeckMesh;
use crate::fe::ladder::Verdict;
use crate::report::number;

/// The plot's size and its margins (SVG px).
const SIZE: (f64, f64) = (420.0, 260.0);
const WIDTH: f64 = SIZE.0;
const HEIGHT: f64 = SIZE.1;
const LEFT: f64 = 64.0;
const RIGHT: f64 = 16.0;
const TOP: f64 = 28.0;
const BOTTOM: f64 = 40.0;

const STYLE: &str = "body{font-family:sans-serif;margin:1.5em;color:#222}\
table{border-collapse:collapse;font-size:0.9em}\
th,td{border:1px solid #bbb;padding:0.25em 0.5em;text-align:left;vertical-align:top}\
th{background:#eee}td.n{text-align:right;font-variant-numeric:tabular-nums}\
.agrees{background:#d9f2d9}.does-not-agree{background:#f7d4d4}\
.not-converged{background:#fbe8c8}.not-judged{background:#e8e8e8}\
figure{display:inline-block;margin:0.5em 1em 0.5em 0}figcaption{font-size:0.85em;max-width:420px}\
p.why{max-width:60em}";

/// What the plots' marks are, once for the page.
const LEGEND: &str = "<p>Each plot: a quantity's difference from the reference (%) against the element \
size in the contact zone (h: the coarse mesh's). <span style=\"color:#c03020\">\u{25cf}</span> the \
runs on the mesh ladder, <span style=\"color:#7a2a9a\">\u{25b3}</span> the finest mesh at half the \
load increment, <span style=\"color:#3c5ac8\">\u{25a0}</span> the converged (extrapolated) answer at \
h = 0 with its uncertainty as a bar and a blue band; the green line is the reference, the darker green \
band the reference's own accuracy (the bound), the lighter one the tolerance (bound + uncertainty).</p>\n";

/// The page for the scorecard `cases`; `title` heads it (the command that made it).
pub fn page(cases: &[CaseScore], title: &str) -> String {
    let agree = cases
        .iter()
        .filter(|c| c.verdict == Verdict::Agrees)
        .count();
    let mut out = String::new();
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <title>{t}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n<h1>{t}</h1>\n\
         <p>{agree} of {n} cases agree{exit}.</p>\n",
        t = xml(title),
        n = cases.len(),
        exit = if agree == cases.len() {
            ""
        } else {
            " (exit code 1)"
        },
    );
    summary(&mut out, cases);
    out.push_str(LEGEND);
    for (index, case) in cases.iter().enumerate() {
        case_section(&mut out, index, case);
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// The CSS class of a verdict.
fn class(verdict: Verdict) -> &'static str {
    match verdict {
        Verdict::Agrees => "agrees",
        Verdict::DoesNotAgree => "does-not-agree",
        Verdict::NotConverged => "not-converged",
        Verdict::NotJudged => "not-judged",
    }
}

fn percent(x: f64) -> String {
    format!("{:+.3} %", 100.0 * x)
}

fn unsigned_percent(x: f64) -> String {
    format!("{:.3} %", 100.0 * x)
}

/// The summary table: a row per quantity of each case (one row for a case without any).
fn summary(out: &mut String, cases: &[CaseScore]) {
    out.push_str(
        "<h2>Summary</h2>\n<table>\n<tr><th>case</th><th>problem</th><th>quantity</th>\
         <th>converged value</th><th>uncertainty</th><th>observed order</th>\
         <th>stick slope used / deck's (MPa/mm)</th><th>tolerance</th><th>verdict</th></tr>\n",
    );
    for (index, case) in cases.iter().enumerate() {
        let slope = case.stick_slope.as_ref().map_or_else(
            || "-".to_string(),
            |s| {
                format!(
                    "{} / {} ({}, {})",
                    s.used.map_or_else(|| "-".to_string(), number),
                    number(s.deck),
                    s.diff_fraction.map_or_else(|| "-".to_string(), percent),
                    s.verdict
                )
            },
        );
        let name = format!(
            "<a href=\"#case-{index}\">{}</a>{}",
            xml(&case.case),
            case.label
                .map_or_else(String::new, |l| format!("<br/>({})", xml(l)))
        );
        if case.quantities.is_empty() {
            let _ = writeln!(
                out,
                "<tr class=\"{c}\"><td>{name}</td><td>{m}</td><td colspan=\"6\">{why}</td>\
                 <td>{v}</td></tr>",
                c = class(case.verdict),
                m = xml(case.model),
                why = xml(&case.reason),
                v = case.verdict.label(),
            );
            continue;
        }
        for q in &case.quantities {
            let e = &q.extrapolation;
            let (value, uncertainty) = match &q.value {
                Some(v) => (
                    format!(
                        "{} {} ({})",
                        number(v.estimate),
                        xml(&v.unit),
                        percent(e.estimate)
                    ),
                    v.uncertainty.map_or_else(
                        || "-".to_string(),
                        |u| format!("{} {}", number(u), xml(&v.unit)),
                    ),
                ),
                None => (
                    percent(e.estimate),
                    e.uncertainty
                        .map_or_else(|| "-".to_string(), unsigned_percent),
                ),
            };
            let _ = writeln!(
                out,
                "<tr class=\"{c}\"><td>{name}</td><td>{m}</td><td>{q}</td><td class=\"n\">{value}</td>\
                 <td class=\"n\">{uncertainty}</td><td class=\"n\">{order}</td><td>{slope}</td>\
                 <td class=\"n\">{tol}</td><td>{v}</td></tr>",
                c = class(q.verdict),
                m = xml(case.model),
                q = xml(&q.name),
                order = e
                    .order
                    .map_or_else(|| "-".to_string(), |p| format!("{p:.2}")),
                slope = xml(&slope),
                tol = q
                    .tolerance_fraction
                    .map_or_else(|| "no bound".to_string(), unsigned_percent),
                v = q.verdict.label(),
            );
        }
    }
    out.push_str("</table>\n");
}

/// A case's heading, verdict, reason and plots.
fn case_section(out: &mut String, index: usize, case: &CaseScore) {
    let _ = write!(
        out,
        "<h2 id=\"case-{index}\">{name} <span class=\"{c}\">{v}</span></h2>\n\
         <p>{model}, preset {preset}{set}</p>\n<p class=\"why\">{why}</p>\n",
        name = xml(&case.case),
        c = class(case.verdict),
        v = case.verdict.label(),
        model = xml(case.model),
        preset = xml(&case.preset),
        set = if case.set.is_empty() {
            String::new()
        } else {
            format!(", set {}", xml(&case.set.join(" ")))
        },
        why = xml(&case.reason),
    );
    // Each run: the single-run verdict `compare` gives it (or why it has none), its solver time.
    out.push_str("<table>\n<tr><th>run</th><th>the run alone</th><th>solver (s)</th></tr>\n");
    for run in &case.runs {
        let (said, seconds) = match (&run.result, &run.error) {
            (Some(r), _) => (r.verdict.as_str(), format!("{:.1}", r.solver_seconds)),
            (None, Some(e)) => (e.as_str(), "-".to_string()),
            (None, None) => ("not run", "-".to_string()),
        };
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{}</td><td class=\"n\">{seconds}</td></tr>",
            xml(&run.run),
            xml(said)
        );
    }
    out.push_str("</table>\n");
    let sizes = mesh_sizes(case);
    for q in &case.quantities {
        let _ = write!(
            out,
            "<figure>\n{}<figcaption>{}</figcaption>\n</figure>\n",
            plot(q, &sizes),
            xml(&super::score::quantity_line(q))
        );
    }
}

/// Each mesh rung's element size as a fraction of the coarse mesh's (1, 1/2, 1/4), in the order
/// of the case's runs at the deck's own increment.
fn mesh_sizes(case: &CaseScore) -> Vec<f64> {
    case.runs
        .iter()
        .filter_map(|r| r.result.as_ref())
        .filter(|r| r.increment.is_none())
        .filter_map(|r| DeckMesh::from_name(&r.mesh))
        .map(|m| 1.0 / m.refinement() as f64)
        .collect()
}

/// The plot's frame: data to pixels.
struct Frame {
    x: [f64; 2],
    y: [f64; 2],
}

impl Frame {
    fn px(&self, x: f64) -> f64 {
        LEFT + (x - self.x[0]) / (self.x[1] - self.x[0]) * (WIDTH - LEFT - RIGHT)
    }

    fn py(&self, y: f64) -> f64 {
        HEIGHT - BOTTOM - (y - self.y[0]) / (self.y[1] - self.y[0]) * (HEIGHT - TOP - BOTTOM)
    }

    /// A band from `lo` to `hi` across the plot, clipped to it.
    fn band(&self, out: &mut String, lo: f64, hi: f64, fill: &str) {
        let (top, bottom) = (self.py(hi.min(self.y[1])), self.py(lo.max(self.y[0])));
        if bottom > top {
            let _ = writeln!(
                out,
                "<rect x=\"{LEFT:.1}\" y=\"{top:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{fill}\"/>",
                WIDTH - LEFT - RIGHT,
                bottom - top
            );
        }
    }

    fn hline(&self, out: &mut String, y: f64, stroke: &str, dash: &str) {
        let _ = writeln!(
            out,
            "<line x1=\"{LEFT:.1}\" y1=\"{py:.1}\" x2=\"{:.1}\" y2=\"{py:.1}\" stroke=\"{stroke}\" \
             stroke-width=\"1.5\"{dash}/>",
            WIDTH - RIGHT,
            py = self.py(y),
        );
    }
}

/// Ticks at a round step, about five over `[lo, hi]`.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let raw = (hi - lo) / 5.0;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * magnitude)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * magnitude);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// One quantity's convergence plot: the differences in %, against h / h_coarse.
fn plot(q: &QuantityScore, sizes: &[f64]) -> String {
    let e = &q.extrapolation;
    let pct = |x: f64| 100.0 * x;
    let rungs: Vec<(f64, f64)> = sizes
        .iter()
        .zip(&q.rungs_fraction)
        .map(|(&h, &d)| (h, pct(d)))
        .collect();
    let finest_h = rungs.last().map_or(0.25, |r| r.0);
    let estimate = pct(e.estimate);
    let uncertainty = e.uncertainty.map(pct);
    let tolerance = q.tolerance_fraction.map(pct);
    let bound = q.bound_fraction.map(pct);
    let mut ys: Vec<f64> = rungs.iter().map(|r| r.1).collect();
    ys.push(0.0);
    ys.push(estimate);
    ys.extend(q.half_increment_fraction.map(pct));
    if let Some(u) = uncertainty {
        ys.extend([estimate - u, estimate + u]);
    }
    if let Some(t) = tolerance {
        ys.extend([-t, t]);
    }
    let ys: Vec<f64> = ys.into_iter().filter(|y| y.is_finite()).collect();
    let lo = ys.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let pad = ((hi - lo) * 0.1).max(1e-3);
    let frame = Frame {
        x: [-0.08, 1.08],
        y: [lo - pad, hi + pad],
    };
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{HEIGHT}\" \
         viewBox=\"0 0 {WIDTH} {HEIGHT}\" font-family=\"sans-serif\" font-size=\"11\" role=\"img\">\n\
         <title>{}</title>\n",
        xml(&q.name)
    );
    // Bands first (tolerance, then bound inside it, then the estimate's uncertainty), lines and
    // points over them.
    if let Some(t) = tolerance {
        frame.band(&mut out, -t, t, "#dcefdc");
    }
    if let Some(b) = bound {
        frame.band(&mut out, -b, b, "#c4e4c4");
    }
    if let Some(u) = uncertainty {
        frame.band(&mut out, estimate - u, estimate + u, "rgba(60,90,200,0.22)");
    }
    frame.hline(&mut out, 0.0, "#2a7a2a", "");
    frame.hline(&mut out, estimate, "#3c5ac8", " stroke-dasharray=\"5 3\"");
    // Axes, ticks and labels.
    let (x0, x1, y0, y1) = (LEFT, WIDTH - RIGHT, TOP, HEIGHT - BOTTOM);
    let _ = writeln!(
        out,
        "<rect x=\"{x0}\" y=\"{y0}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" stroke=\"#444\"/>",
        x1 - x0,
        y1 - y0
    );
    for t in ticks(frame.y[0], frame.y[1]) {
        let y = frame.py(t);
        let _ = writeln!(
            out,
            "<line x1=\"{x0}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"#444\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
            x0 - 4.0,
            x0 - 6.0,
            y + 4.0,
            number(t)
        );
    }
    for (h, label) in [(0.0, "0"), (0.25, "h/4"), (0.5, "h/2"), (1.0, "h")] {
        let x = frame.px(h);
        let _ = writeln!(
            out,
            "<line x1=\"{x:.1}\" y1=\"{y1:.1}\" x2=\"{x:.1}\" y2=\"{:.1}\" stroke=\"#444\"/>\
             <text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{label}</text>",
            y1 + 4.0,
            y1 + 16.0
        );
    }
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">element size in the contact zone \
         (h: the coarse mesh's)</text>\n<text x=\"12\" y=\"{:.1}\" text-anchor=\"middle\" \
         transform=\"rotate(-90 12 {:.1})\">difference from the reference (%)</text>\n\
         <text x=\"{x0}\" y=\"16\" font-weight=\"bold\">{}</text>",
        (x0 + x1) / 2.0,
        HEIGHT - 6.0,
        (y0 + y1) / 2.0,
        (y0 + y1) / 2.0,
        xml(&q.name)
    );
    // The runs, the half increment, the extrapolated answer with its error bar.
    for &(h, d) in &rungs {
        let _ = writeln!(
            out,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"#c03020\"><title>h x {h}: {}</title></circle>",
            frame.px(h),
            frame.py(d),
            percent(d / 100.0)
        );
    }
    if let Some(d) = q.half_increment_fraction.map(pct) {
        let (x, y) = (frame.px(finest_h), frame.py(d));
        let _ = writeln!(
            out,
            "<path d=\"M{:.1} {:.1}L{:.1} {:.1}L{:.1} {:.1}Z\" fill=\"none\" stroke=\"#7a2a9a\" \
             stroke-width=\"1.5\"><title>half increment: {}</title></path>",
            x,
            y - 6.0,
            x + 5.5,
            y + 4.0,
            x - 5.5,
            y + 4.0,
            percent(d / 100.0)
        );
    }
    let x = frame.px(0.0);
    if let Some(u) = uncertainty {
        let _ = writeln!(
            out,
            "<line x1=\"{x:.1}\" y1=\"{:.1}\" x2=\"{x:.1}\" y2=\"{:.1}\" stroke=\"#3c5ac8\" stroke-width=\"2\"/>",
            frame.py(estimate - u),
            frame.py(estimate + u)
        );
    }
    let _ = writeln!(
        out,
        "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"8\" height=\"8\" fill=\"#3c5ac8\"><title>converged: \
         {}</title></rect>",
        x - 4.0,
        frame.py(estimate) - 4.0,
        percent(estimate / 100.0)
    );
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::suite::score::tests::ladder;

    #[test]
    fn the_page_names_every_case_and_verdict_and_is_well_formed() {
        let good = ladder("<x&y>", [0.045, 0.015, 0.0075], 1.0);
        let coarse = ladder("coarse\"one'", [0.20, 0.02, 0.12], 1.0);
        let off = ladder("off", [0.045, 0.015, 0.0075], 1.1);
        let page = page(&[good, coarse, off], "microslip suite <&>");
        let options = roxmltree::ParsingOptions {
            allow_dtd: true,
            ..roxmltree::ParsingOptions::default()
        };
        let doc = roxmltree::Document::parse_with_options(&page, options)
            .unwrap_or_else(|e| panic!("{e}\n{page}"));
        // Every case named, escaped; the raw name nowhere.
        assert!(page.contains("&lt;x&amp;y&gt;"));
        assert!(!page.contains("<x&y>"));
        let headings: Vec<String> = doc
            .descendants()
            .filter(|n| n.has_tag_name("h2") && n.attribute("id").is_some())
            .map(|n| {
                n.descendants()
                    .filter(|t| t.is_text())
                    .filter_map(|t| t.text())
                    .collect()
            })
            .collect();
        assert_eq!(
            headings,
            [
                "<x&y> agrees",
                "coarse\"one' not converged",
                "off does not agree"
            ]
        );
        // One plot per quantity, each with its three runs, the converged point and its bar.
        let svgs: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("svg"))
            .collect();
        assert_eq!(svgs.len(), 3);
        for svg in &svgs {
            let circles = svg
                .descendants()
                .filter(|n| n.has_tag_name("circle"))
                .count();
            assert_eq!(circles, 3);
        }
        // The summary's rows: one per quantity, with its verdict.
        let summary = doc.descendants().find(|n| n.has_tag_name("table")).unwrap();
        let verdicts: Vec<String> = summary
            .children()
            .filter(|n| n.has_tag_name("tr"))
            .skip(1)
            .filter_map(|r| r.children().rfind(|c| c.has_tag_name("td")))
            .filter_map(|c| c.text().map(str::to_string))
            .collect();
        assert_eq!(verdicts, ["agrees", "not converged", "agrees"]);
        assert!(page.contains("1 of 3 cases agree (exit code 1)"));
        // The stick slope used against the deck's.
        assert!(
            page.contains("1100 / 1000 (+10.000 %, does not agree)"),
            "{page}"
        );
    }

    #[test]
    fn the_converged_point_sits_at_h_zero_at_its_estimate() {
        // 0.5 % + 4 % h^2: the converged point at 0.5 %, the coarse run at 4.5 %.
        let case = ladder("c", [0.045, 0.015, 0.0075], 1.0);
        let q = &case.quantities[0];
        let svg = plot(q, &mesh_sizes(&case));
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let number =
            |n: roxmltree::Node, a: &str| -> f64 { n.attribute(a).unwrap().parse().unwrap() };
        let circles: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("circle"))
            .collect();
        let marker = doc
            .descendants()
            .find(|n| n.has_tag_name("rect") && n.attribute("width") == Some("8"))
            .unwrap();
        // x: h = 1, 1/2, 1/4 left of each other, the converged point left of them all.
        let xs: Vec<f64> = circles.iter().map(|c| number(*c, "cx")).collect();
        assert!(xs[0] > xs[1] && xs[1] > xs[2] && xs[2] > number(marker, "x") + 4.0);
        // y: pixel distances in proportion to the values (4.5 - 1.5) : (1.5 - 0.5).
        let ys: Vec<f64> = circles.iter().map(|c| number(*c, "cy")).collect();
        let converged = number(marker, "y") + 4.0;
        let ratio = (ys[1] - ys[0]) / (converged - ys[1]);
        assert!((ratio - 3.0).abs() < 0.02, "{ratio}");
    }
}
