//! What each chart shows, as plain data (title, axes, series), built from [`crate::study::curves`]
//! and the problems' discretized solvers (the finite-element points). The TUI turns a [`Plot`] into
//! cells, the figure writer (`report::figure`, behind the feature `figures`) into SVG; neither
//! computes physics itself, so a curve on screen and in a figure are the same numbers. Its own
//! layer, below `report`: `report` formats (text, JSON, CSV, SVG) and computes nothing; which
//! charts exist is [`view`].

pub mod family;
pub(crate) mod load;
#[cfg(feature = "app")]
pub mod panes;
pub(crate) mod pins;
mod plot;
pub(crate) mod shear_lag;
pub mod vary;
pub mod view;
mod ymode;

pub use plot::{
    Axis, ExternalPoints, NumericPoints, Plot, PlotSeries, PointFailure, SeriesKind, SeriesRole,
};
pub(crate) use plot::{axis_bounds, cursor, line, linear_axis, log_axis, max_y, tick, unsolved};
pub use ymode::YMode;

use crate::chart::view::AnyChart;
use crate::fit::Measurement;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::inputs::Model;
use crate::study::curves::{Samples, Series, Spacing};

/// Points per analytic curve: two per column of a 100-column chart, enough for Braille resolution.
pub(crate) const SAMPLES: u64 = 200;

/// Elements of the finite-element overlay: its error (~1e-6) is far below a pixel.
const OVERLAY_ELEMENTS: usize = 100;

/// Number of finite-element points shown on a curve.
pub(crate) const OVERLAY_POINTS: usize = 8;

pub(crate) fn samples(from: f64, to: f64, spacing: Spacing) -> Option<Samples> {
    Samples::new(from, to, SAMPLES, spacing).ok()
}

/// Builds `chart` of `model` (a chart of the model's problem), with finite-element points,
/// measurements and an external code's points if given (measurements show on the chart of the
/// measured response against the load, w(L) or Delta vs F; external points on the chart of their
/// quantity).
pub fn build(
    model: &Model,
    chart: AnyChart,
    numeric: Option<&NumericPoints>,
    measured: Option<&[Measurement]>,
    external: Option<&ExternalPoints>,
    force_span: Option<f64>,
) -> Plot {
    let external = external.filter(|e| e.model == model.kind());
    let mut overlays: Vec<(SeriesRole, &str, Series)> = Vec::new();
    // Measurements (a force and a response) and an external code's points are of the
    // problem's response: they show on its first chart.
    if chart.is_response() {
        if let Some(points) = measured.filter(|_| chart.has_load()) {
            let series = points.iter().map(|m| (m.force, m.response)).collect();
            overlays.push((SeriesRole::Measured, "measured", series));
        }
        if let Some(e) = external {
            let series = e.points.iter().map(|&p| chart.external_point(p)).collect();
            overlays.push((SeriesRole::External, e.label.as_str(), series));
        }
    }
    let f_data = overlays
        .iter()
        .flat_map(|(_, _, s)| s.iter().map(|p| p.0))
        .fold(0.0, f64::max);
    // None for a model of another problem than the chart's.
    let plot = chart.plot_of(model, f_data, force_span);
    // Every range above lies in the accepted domain, so a chart is always built; should one not be,
    // an empty chart with valid axes is drawn rather than axes without extent.
    let mut plot = plot.unwrap_or_else(|| Plot {
        title: "no chart for these values".into(),
        x: linear_axis("- (-)", 0.0, 1.0),
        y: linear_axis("- (-)", 0.0, 1.0),
        ..Plot::default()
    });
    for (role, name, points) in overlays {
        let top = max_y([&points]) * 1.05;
        plot.y.bounds[1] = plot.y.bounds[1].max(top);
        plot.y = linear_axis(plot.y.title.clone(), plot.y.bounds[0], plot.y.bounds[1]);
        plot.series.push(PlotSeries {
            name: name.into(),
            points,
            role,
        });
    }
    if let Some(numeric) = numeric {
        // Where the first gap is; why is too long for a legend (the TUI's status says it).
        let solver = chart.numeric_name();
        let name = match (numeric.failed, &numeric.failure) {
            (0, _) => solver.to_string(),
            (n, Some(first)) => format!("{solver} ({}, from {})", unsolved(n), first.at),
            (n, None) => format!("{solver} ({})", unsolved(n)),
        };
        plot.series.push(PlotSeries {
            name,
            points: numeric.points.clone(),
            role: SeriesRole::FiniteElements,
        });
        if !numeric.continuum.is_empty() {
            plot.series.push(PlotSeries {
                name: "2-D continuum".into(),
                points: numeric.continuum.clone(),
                role: SeriesRole::Continuum,
            });
        }
    }
    plot
}

/// The chart `chart` of `model` (a model of the chart's kind) as a figure shows it: the TUI's
/// series, with the finite-element points where asked and the chart has them, the y axis in mode
/// `y` where it applies.
///
/// # Errors
/// The finite-element solver's, when `finite_elements` is asked and it fails.
pub fn figure(
    model: &Model,
    chart: AnyChart,
    finite_elements: bool,
    y: YMode,
) -> Result<Plot, NumericError> {
    let numeric = if finite_elements {
        numeric_points(model, chart)?
    } else {
        None
    };
    Ok(y.apply(build(model, chart, numeric.as_ref(), None, None, None)))
}

/// Finite-element points for chart `chart`, where the chart has a finite-element counterpart.
pub fn numeric_points(
    model: &Model,
    chart: AnyChart,
) -> Result<Option<NumericPoints>, NumericError> {
    chart.numeric_points_of(model, MeshDensity::with_elements(OVERLAY_ELEMENTS))
}

/// The chart tests' fixtures, for the tests of the layers that draw charts.
#[cfg(all(test, feature = "app"))]
pub(crate) use tests::{corner_models, every_chart};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TipForce;
    use crate::problems::inputs::Inputs;
    use crate::problems::plate::PlateChart;
    use crate::problems::twin_beams::BeamChart;
    use crate::problems::{ModelKind, PlateParam};

    /// Every chart of `kind`, in the order the `c` key reaches them.
    pub(crate) fn every_chart(kind: ModelKind) -> Vec<AnyChart> {
        AnyChart::of(kind).collect()
    }

    fn model(kind: ModelKind) -> Model {
        Inputs::paper(kind).validate().unwrap()
    }

    #[test]
    fn every_chart_has_titles_units_bounds_and_finite_points() {
        for kind in [ModelKind::Beam, ModelKind::Plate] {
            for shown in every_chart(kind) {
                let chart = shown.title();
                let plot = build(&model(kind), shown, None, None, None, None);
                assert!(!plot.title.is_empty());
                assert!(
                    plot.x.title.contains('(') && plot.y.title.contains('('),
                    "{kind} {chart}: units"
                );
                assert!(plot.x.bounds[0] < plot.x.bounds[1] && plot.y.bounds[0] < plot.y.bounds[1]);
                assert!(!plot.series.is_empty());
                for s in &plot.series {
                    assert!(
                        s.points.iter().all(|(x, y)| x.is_finite() && y.is_finite()),
                        "{kind} {chart} {}",
                        s.name
                    );
                }
            }
        }
    }

    /// Axes finite and strictly increasing, every point finite and on the chart.
    fn check_plot(plot: &Plot, what: &str) {
        for axis in [&plot.x, &plot.y] {
            let [lo, hi] = axis.bounds;
            assert!(
                lo.is_finite() && hi.is_finite() && lo < hi,
                "{what}: {} {:?}",
                axis.title,
                axis.bounds
            );
            assert!(axis.labels.iter().all(|l| !l.contains("n/a")), "{what}");
        }
        assert!(!plot.series.is_empty(), "{what}");
        for s in &plot.series {
            for &(x, y) in &s.points {
                let inside = |v: f64, [lo, hi]: [f64; 2]| {
                    v.is_finite() && v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo)
                };
                assert!(
                    inside(x, plot.x.bounds) && inside(y, plot.y.bounds),
                    "{what} {}: ({x}, {y}) outside {:?} x {:?}",
                    s.name,
                    plot.x.bounds,
                    plot.y.bounds
                );
            }
        }
    }

    /// Every corner of each model's domain (the beam force at 0, at the largest accepted force
    /// or at F_thre, in turn), with a name for messages. nu (half-open domain, and only in the
    /// beams' shear deflection) keeps its value there.
    pub(crate) fn corner_models() -> Vec<(String, Model)> {
        use crate::problems::BeamParam;
        let mut models = Vec::new();
        let beam_params: Vec<BeamParam> = BeamParam::ALL
            .into_iter()
            .filter(|p| !matches!(p, BeamParam::Force | BeamParam::Poisson))
            .collect();
        for mask in 0..1_u32 << beam_params.len() {
            let mut inputs = Inputs::paper(ModelKind::Beam);
            for (i, param) in beam_params.iter().enumerate() {
                let domain = param.spec().domain;
                let value = if mask & (1 << i) == 0 {
                    domain.min()
                } else {
                    domain.max()
                };
                inputs.set(crate::Param::Beam(*param), value).unwrap();
            }
            let Ok(Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. })) =
                inputs.validate()
            else {
                panic!("corner {mask} refused");
            };
            let force = match mask % 3 {
                0 => 0.0,
                1 => BeamParam::Force.spec().domain.max(),
                _ => TipForce::clamped(beams.threshold_force()).newtons(),
            };
            inputs
                .set(crate::Param::Beam(BeamParam::Force), force)
                .unwrap();
            models.push((
                format!("beam corner {mask} F={force}"),
                inputs.validate().unwrap(),
            ));
        }
        let plate_params = crate::PlateParam::ALL;
        for mask in 0..1_u32 << 7 {
            let mut inputs = Inputs::paper(ModelKind::Plate);
            for (i, param) in plate_params.iter().enumerate() {
                let domain = param.spec().domain;
                let value = if mask & (1 << i) == 0 {
                    domain.min()
                } else {
                    domain.clamp(domain.max())
                };
                inputs.set(crate::Param::Plate(*param), value).unwrap();
            }
            models.push((format!("plate corner {mask}"), inputs.validate().unwrap()));
        }
        models
    }

    #[test]
    fn every_chart_at_every_corner_of_the_domain_has_valid_axes() {
        for (what, model) in corner_models() {
            for chart in every_chart(model.kind()) {
                let plot = build(&model, chart, None, None, None, None);
                check_plot(&plot, &format!("{what} {chart:?}"));
            }
        }
    }

    #[test]
    fn flat_and_huge_ranges_still_give_increasing_axes() {
        assert_eq!(axis_bounds(0.0, 0.0), [0.0, 1.0]);
        let [lo, hi] = axis_bounds(1e17, 1e17);
        assert!(lo < hi && hi - lo >= 1e8);
        let [lo, hi] = axis_bounds(1e-300, 1e-300);
        assert!(lo < hi);
        assert_eq!(axis_bounds(2.0, 5.0), [2.0, 5.0]);
        let [lo, hi] = axis_bounds(f64::NAN, f64::INFINITY);
        assert!(lo.is_finite() && hi.is_finite() && lo < hi);
    }

    /// Issue 36 (12): a point of the overlay that did not converge is a gap, and the legend says
    /// where and why, not only how many.
    #[test]
    fn the_overlay_says_why_a_point_did_not_converge() {
        // K_T up to 1e4 times 1e7 MPa/mm: the top points are beyond the 1-D solver's resolution.
        let mut inputs = Inputs::paper(ModelKind::Plate);
        let kt = crate::problems::Param::Plate(PlateParam::Stiffness);
        inputs.set(kt, 1e7).unwrap();
        let model = inputs.validate().unwrap();
        let chart = AnyChart::Plate(PlateChart::Displacement);
        let numeric = numeric_points(&model, chart).unwrap().unwrap();
        assert!(numeric.failed > 0);
        let words = numeric.failure_words().unwrap();
        assert!(
            words.contains("not solved; the first, at K_T = 1e10 MPa/mm: the saturation slip"),
            "{words}"
        );
        let plot = build(&model, chart, Some(&numeric), None, None, None);
        assert!(
            plot.series.iter().any(|s| s
                .name
                .ends_with("points not solved, from K_T = 1e10 MPa/mm)")),
            "{:?}",
            plot.series.iter().map(|s| &s.name).collect::<Vec<_>>()
        );
    }

    #[test]
    fn finite_element_points_sit_on_the_analytic_curve() {
        let m = model(ModelKind::Beam);
        let numeric = numeric_points(&m, AnyChart::Beam(BeamChart::Deflection))
            .unwrap()
            .unwrap();
        let Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. }) = m else {
            unreachable!()
        };
        for (f, w) in numeric.points {
            let exact = beams
                .regularized(TipForce::new(f).unwrap())
                .tip_deflection();
            assert!((w / exact - 1.0).abs() < 1e-4, "F={f}");
        }
        assert!(
            numeric_points(
                &model(ModelKind::Plate),
                AnyChart::Plate(PlateChart::ContactPressure)
            )
            .unwrap()
            .is_none()
        );
    }
}
