//! The chart of `v`: the response (w(L) of the beams, u(L) of the plate, Delta of the lap joint)
//! against the selected
//! parameter, both laws, with the cursor at the current value. Numbers from
//! [`crate::study::curves::response_vs_param`]; axes and series from [`super`].

use super::{Plot, SeriesRole, cursor, line, linear_axis, log_axis, max_y, samples};
use crate::kernel::params::Scale;
use crate::problems::inputs::Model;
use crate::problems::{Param, Quantity};
use crate::study::curves::{Spacing, response_vs_param};

/// The range charted for `param` around its current `value`: the step's natural span (a decade
/// each way for multiplicative parameters, 0 to 3 F_thre or 1.25 F for the force, the whole range
/// of nu or of the press fit's bore), inside the range the other inputs accept; and whether the
/// axis is logarithmic.
fn range(model: &Model, param: Param, value: f64) -> (f64, f64, bool) {
    let spec = param.spec();
    // The domain, narrowed where the other inputs bound this one (the lap joint's F <= F_gross).
    let (min, max) = model.accepted_range(param);
    let clamp = |v: f64| v.clamp(min, max);
    match spec.scale {
        Scale::Factor { .. } => (clamp(value / 10.0), clamp(value * 10.0), true),
        Scale::Add { min, max, .. } => (clamp(min), clamp(max), false),
        Scale::FractionOfScale { .. } => {
            // Only a problem's load steps in fractions of a scale: its regime scale.
            let scale = model.regime_scale().unwrap_or(value);
            let hi = clamp((3.0 * scale).max(1.25 * value));
            (min, if hi > min { hi } else { 1.0 }, false)
        }
    }
}

/// w(L) or u(L) against `param`, Coulomb and regularized, cursor at the current value.
pub fn build(model: &Model, param: Param) -> Plot {
    let response = Quantity::Response.name(model.kind());
    let law = format!("{response} ({})", Quantity::Response.unit(model.kind()));
    let value = model.inputs().get(param).unwrap_or(f64::NAN);
    let (lo, hi, log) = range(model, param, value);
    let spacing = if log {
        Spacing::Logarithmic
    } else {
        Spacing::Linear
    };
    let unit = match param.unit().symbol() {
        "-" => String::new(),
        u => format!(" ({u})"),
    };
    let title = format!("{response} vs {param}, others fixed (v: back)");
    let curves = samples(lo, hi, spacing).and_then(|s| response_vs_param(model, param, s).ok());
    let Some((coulomb, regularized)) = curves else {
        return Plot {
            title: format!("{response} vs {param}: no range to chart"),
            x: linear_axis("-", 0.0, 1.0),
            y: linear_axis("-", 0.0, 1.0),
            ..Plot::default()
        };
    };
    let y_top = max_y([&coulomb, &regularized]) * 1.05;
    let to_x = |x: f64| if log { x.log10() } else { x };
    let plotted = |series: Vec<(f64, f64)>| series.into_iter().map(|(x, y)| (to_x(x), y)).collect();
    let x_title = format!("{param}{unit}");
    let x = if log {
        log_axis(x_title, lo.log10(), hi.log10())
    } else {
        linear_axis(x_title, lo, hi)
    };
    let y = linear_axis(law, 0.0, y_top);
    let mut series = vec![
        line(SeriesRole::Coulomb, "Coulomb", plotted(coulomb)),
        line(SeriesRole::Current, "regularized", plotted(regularized)),
    ];
    if value.is_finite() {
        series.push(cursor(to_x(value), y.bounds));
    }
    Plot {
        title,
        x,
        y,
        series,
        caption: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::inputs::Inputs;
    use crate::problems::{BeamParam, ModelKind};

    #[test]
    fn every_parameter_of_both_models_charts_with_finite_points() {
        for kind in ModelKind::ALL {
            let model = Inputs::paper(kind).validate().unwrap();
            for &param in kind.params() {
                let plot = build(&model, param);
                assert_eq!(plot.series.len(), 3, "{param}: {}", plot.title);
                assert!(plot.x.bounds[0] < plot.x.bounds[1], "{param}");
                for s in &plot.series {
                    assert!(
                        s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite()),
                        "{param}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_chart_of_mu_at_120_n_agrees_with_the_model() {
        // Task 2 of issue 16, as the chart shows it.
        let mut inputs = Inputs::paper(ModelKind::Beam);
        inputs.set(Param::Beam(BeamParam::Force), 120.0).unwrap();
        let model = inputs.validate().unwrap();
        let plot = build(&model, Param::Beam(BeamParam::Friction));
        let regularized = &plot.series[1].points;
        for &(x, w) in regularized.iter().step_by(37) {
            let mu = 10f64.powf(x);
            let direct = model.with_clamped(Param::Beam(BeamParam::Friction), mu);
            let Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, force }) =
                direct
            else {
                panic!()
            };
            let expected = beams.regularized(force).tip_deflection();
            assert!((w / expected - 1.0).abs() < 1e-9, "mu {mu}");
        }
    }
}
