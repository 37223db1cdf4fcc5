//! The y axis of a chart in three modes: linear (as built), logarithmic (where a quantity spans
//! decades: u(L) vs K_T, D vs F_a) and relative to Coulomb (each curve as y / y_Coulomb - 1 in %,
//! where the regularized family separates clearly). A mode is a transformation of a built [`Plot`],
//! so the TUI, `microslip plot --y` and the figures show the same numbers.

use super::{Axis, Plot, PlotSeries, SeriesKind, SeriesRole, axis_bounds, cursor, log_axis, tick};
use crate::chart::view::AnyChart;
use crate::study::curves::Series;

/// How the y axis shows the data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum YMode {
    /// The values, on a linear axis.
    #[default]
    Linear,
    /// The values, on a logarithmic axis (decades).
    Log,
    /// Each curve over the Coulomb curve, minus 1, in %.
    Relative,
}

/// The decades a log axis shows at most below its top: smaller values (D near F_a = 0 falls like
/// F_a^3) would flatten everything else.
const LOG_DECADES: f64 = 6.0;

impl YMode {
    /// Every mode, in the order `y` cycles through them.
    pub const ALL: [YMode; 3] = [YMode::Linear, YMode::Log, YMode::Relative];

    /// The mode's key on the command line (`--y`).
    pub fn key(self) -> &'static str {
        match self {
            YMode::Linear => "linear",
            YMode::Log => "log",
            YMode::Relative => "relative",
        }
    }

    /// The mode's name, for the status line and axis titles.
    pub fn label(self) -> &'static str {
        match self {
            YMode::Linear => "linear",
            YMode::Log => "log",
            YMode::Relative => "relative to Coulomb",
        }
    }

    /// The mode a chart opens in: log where its quantity spans decades.
    pub fn default_for(chart: AnyChart) -> YMode {
        if chart.spans_decades() {
            YMode::Log
        } else {
            YMode::Linear
        }
    }

    /// Whether `plot` can be shown in this mode: log needs positive values and no negative ones
    /// (the loop has both signs), relative a Coulomb curve and another curve on its samples.
    pub fn applies_to(self, plot: &Plot) -> bool {
        if plot.y.log {
            return self == YMode::Linear;
        }
        let data = || {
            plot.series
                .iter()
                .filter(|s| s.kind() != SeriesKind::Cursor)
        };
        match self {
            YMode::Linear => true,
            YMode::Log => {
                let ys = || data().flat_map(|s| s.points.iter().map(|p| p.1));
                ys().any(|y| y > 0.0) && ys().all(|y| y >= 0.0)
            }
            // A Coulomb curve over increasing x (not the loop, whose branches return), nonzero
            // past its first point (the lap joint's Coulomb tau and slip vanish where it sticks:
            // a ratio to nothing would be drawn across the gap as if it were one).
            YMode::Relative => coulomb(plot).is_some_and(|c| {
                c.windows(2).all(|w| w[0].0 < w[1].0)
                    && c.iter().skip(1).all(|p| p.1 != 0.0)
                    && data().any(|s| {
                        s.kind() == SeriesKind::Line
                            && s.role != SeriesRole::Coulomb
                            && same_samples(&s.points, c)
                    })
            }),
        }
    }

    /// The next mode after this one that applies to `plot` (this one if none other does).
    pub fn next_for(self, plot: &Plot) -> YMode {
        let at = YMode::ALL.iter().position(|&m| m == self).unwrap_or(0);
        (1..=YMode::ALL.len())
            .map(|i| YMode::ALL[(at + i) % YMode::ALL.len()])
            .find(|m| m.applies_to(plot))
            .unwrap_or(self)
    }

    /// `plot` with its y axis in this mode; unchanged if the mode does not apply.
    pub fn apply(self, plot: Plot) -> Plot {
        if self == YMode::Linear || !self.applies_to(&plot) {
            return plot;
        }
        match self {
            YMode::Linear => plot,
            YMode::Log => to_log(plot),
            YMode::Relative => to_relative(plot),
        }
    }
}

fn coulomb(plot: &Plot) -> Option<&Series> {
    plot.series
        .iter()
        .find(|s| s.role == SeriesRole::Coulomb)
        .map(|s| &s.points)
}

fn same_samples(a: &Series, b: &Series) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(p, q)| p.0 == q.0)
}

/// The quantity of a y axis title: `w(L)` of `w(L) (mm)`.
fn quantity(title: &str) -> &str {
    title.split(" (").next().unwrap_or(title)
}

/// Rebuilds the cursors (vertical lines) of `series` over the new y bounds.
pub(super) fn stretch_cursors(series: &mut [PlotSeries], bounds: [f64; 2]) {
    for s in series.iter_mut().filter(|s| s.kind() == SeriesKind::Cursor) {
        if let Some(&(x, _)) = s.points.first() {
            *s = cursor(x, bounds);
        }
    }
}

/// y range of the data series, with 5 % headroom above and below.
fn data_bounds(series: &[PlotSeries]) -> [f64; 2] {
    let (lo, hi) = series
        .iter()
        .filter(|s| s.kind() != SeriesKind::Cursor)
        .flat_map(|s| &s.points)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
    if !lo.is_finite() || !hi.is_finite() {
        return [0.0, 1.0];
    }
    let pad = 0.05 * (hi - lo);
    axis_bounds(lo - pad, hi + pad)
}

fn to_log(mut plot: Plot) -> Plot {
    let top = plot
        .series
        .iter()
        .filter(|s| s.kind() != SeriesKind::Cursor)
        .flat_map(|s| &s.points)
        .map(|p| p.1)
        .fold(0.0, f64::max);
    let floor = top.log10() - LOG_DECADES;
    for s in plot
        .series
        .iter_mut()
        .filter(|s| s.kind() != SeriesKind::Cursor)
    {
        s.points = s
            .points
            .iter()
            .filter(|p| p.1 > 0.0)
            .map(|&(x, y)| (x, y.log10()))
            .filter(|p| p.1 >= floor)
            .collect();
    }
    let bounds = data_bounds(&plot.series);
    let title = match plot.y.title.strip_suffix(')') {
        Some(open) => format!("{open}, log)"),
        None => format!("{} (log)", plot.y.title),
    };
    plot.y = log_axis(title, bounds[0], bounds[1]);
    stretch_cursors(&mut plot.series, plot.y.bounds);
    plot
}

/// `y` of the Coulomb curve at `x`, linearly interpolated (None outside it).
fn interpolate(curve: &Series, x: f64) -> Option<f64> {
    let i = curve.partition_point(|p| p.0 < x);
    match (curve.get(i.wrapping_sub(1)), curve.get(i)) {
        (_, Some(&(x1, y1))) if x1 == x => Some(y1),
        (Some(&(x0, y0)), Some(&(x1, y1))) => Some(y0 + (y1 - y0) * (x - x0) / (x1 - x0)),
        _ => None,
    }
}

fn to_relative(mut plot: Plot) -> Plot {
    let Some(reference) = coulomb(&plot).cloned() else {
        return plot;
    };
    // Where Coulomb's value is 0 (no load) the ratio means nothing: those points are left out.
    let least = reference.iter().map(|p| p.1.abs()).fold(0.0, f64::max) * 1e-12;
    for s in plot
        .series
        .iter_mut()
        .filter(|s| s.kind() != SeriesKind::Cursor)
    {
        // Curves on Coulomb's samples point by point, other points (FE) against its interpolant.
        let aligned = same_samples(&s.points, &reference);
        s.points = s
            .points
            .iter()
            .enumerate()
            .filter_map(|(i, &(x, y))| {
                let c = if aligned {
                    reference[i].1
                } else {
                    interpolate(&reference, x)?
                };
                (c.abs() > least).then(|| (x, 100.0 * (y / c - 1.0)))
            })
            .collect();
    }
    let bounds = data_bounds(&plot.series);
    let q = quantity(&plot.y.title);
    plot.y = Axis {
        title: format!("{q} / Coulomb - 1 (%)"),
        bounds,
        labels: [bounds[0], 0.5 * (bounds[0] + bounds[1]), bounds[1]]
            .iter()
            .map(|&v| tick(v))
            .collect(),
        log: false,
    };
    stretch_cursors(&mut plot.series, plot.y.bounds);
    plot
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::figure;
    use crate::problems::ModelKind;
    use crate::problems::inputs::{Inputs, Model};
    use crate::problems::plate::PlateChart;
    use crate::problems::twin_beams::BeamChart;
    use crate::{TipForce, TwinBeams};

    fn plot_of(chart: AnyChart) -> Plot {
        let model = Inputs::paper(chart.kind()).validate().unwrap();
        figure(&model, chart, false, YMode::Linear).unwrap()
    }

    #[test]
    fn relative_mode_shows_the_closed_form_ratio_in_percent() {
        let plot = YMode::Relative.apply(plot_of(AnyChart::Beam(BeamChart::Deflection)));
        assert_eq!(plot.y.title, "w(L) / Coulomb - 1 (%)");
        let kt = plot.series.iter().find(|s| s.name == "K_T").unwrap();
        let Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. }) =
            Inputs::paper(ModelKind::Beam).validate().unwrap()
        else {
            unreachable!()
        };
        let beams: TwinBeams = beams;
        for &(f, percent) in kt.points.iter().step_by(23) {
            let force = TipForce::new(f).unwrap();
            let exact = beams.regularized(force).tip_deflection()
                / beams.coulomb(force).tip_deflection()
                - 1.0;
            assert!((percent - 100.0 * exact).abs() < 1e-9, "F {f}");
        }
        // F = 0 is left out (0 / 0), Coulomb is the zero line, and K_T/5 lies above K_T.
        assert!(kt.points.iter().all(|p| p.0 > 0.0));
        let at = |name: &str| plot.series.iter().find(|s| s.name == name).unwrap().points[0].1;
        assert!(at("Coulomb").abs() < 1e-12 && at("K_T/5") > at("K_T") && at("K_T") > at("K_T*5"));
    }

    #[test]
    fn log_mode_spans_the_decades_and_says_so() {
        let linear = plot_of(AnyChart::Plate(PlateChart::Displacement));
        let plot = YMode::Log.apply(linear.clone());
        assert!(plot.y.log && plot.y.title == "u(L) (mm, log)");
        for (a, b) in linear.series.iter().zip(&plot.series) {
            if a.kind() == SeriesKind::Cursor {
                continue;
            }
            for (p, q) in a.points.iter().zip(&b.points) {
                assert!((10f64.powf(q.1) / p.1 - 1.0).abs() < 1e-12);
            }
        }
        // The default per chart: log for u(L) vs K_T and D vs F_a.
        assert_eq!(
            YMode::default_for(AnyChart::Plate(PlateChart::Displacement)),
            YMode::Log
        );
        assert_eq!(
            YMode::default_for(AnyChart::Beam(BeamChart::Deflection)),
            YMode::Linear
        );
    }

    #[test]
    fn modes_that_do_not_apply_are_skipped() {
        let cycle = plot_of(AnyChart::Beam(BeamChart::Loop));
        // Both signs: no log; branches that return: no ratio at one force.
        assert!(!YMode::Log.applies_to(&cycle) && !YMode::Relative.applies_to(&cycle));
        assert_eq!(YMode::Linear.next_for(&cycle), YMode::Linear);
        let x = plot_of(AnyChart::Beam(BeamChart::SlipBoundary));
        assert!(!YMode::Relative.applies_to(&x));
        assert_eq!(YMode::Log.apply(cycle.clone()), cycle);
    }
}
