//! Pinned curves: exploring means comparing one state with another, so a pin keeps a set of
//! parameters and every chart of its model shows, next to the current curves, the pinned state's
//! main curve (the regularized law: `K_T`, `regularized`, `P_r/P`). A pin keeps parameters rather
//! than points so that it follows chart switches: on w(L) vs F, X vs F or tau(x) alike, the pinned
//! curve is the same quantity as the current one, built by the same code over the same x range.
//!
//! A pin is labelled by what differs from the current parameters (`mu 0.3->0.2`: 0.3 pinned,
//! 0.2 now), so the legend says what the comparison is about.

use super::{Plot, PlotSeries, SeriesRole, linear_axis, log_axis};
#[cfg(feature = "app")]
use super::{YMode, build};
#[cfg(feature = "app")]
use crate::chart::view::AnyChart;
#[cfg(feature = "app")]
use crate::chart::view::setting_label;
#[cfg(feature = "app")]
use crate::kernel::format::number;
#[cfg(feature = "app")]
use crate::problems::inputs::{Inputs, Model};

/// Pins kept at most: more curves than that cannot be told apart on a terminal chart.
#[cfg(feature = "app")]
pub(crate) const MAX_PINS: usize = 4;

/// Differences named in a label before the rest are counted (`+2`).
#[cfg(feature = "app")]
const NAMED_DIFFERENCES: usize = 2;

/// The regularized law's curve of `plot` (role [`SeriesRole::Current`]), the one a pin keeps
/// (None for tables).
pub(crate) fn main_series(plot: &Plot) -> Option<&PlotSeries> {
    plot.series.iter().find(|s| s.role == SeriesRole::Current)
}

/// What differs between a pin and the current parameters, pinned value first:
/// `mu 0.3->0.2 KT 600->1e3 +1`; `= current` when nothing does.
#[cfg(feature = "app")]
pub(crate) fn label(pinned: &Inputs, current: &Inputs) -> String {
    let mut differences: Vec<String> = pinned
        .kind()
        .params()
        .iter()
        .filter_map(|&param| {
            let (was, now) = (pinned.get(param)?, current.get(param)?);
            (was != now).then(|| format!("{} {}->{}", param.name(), number(was), number(now)))
        })
        .collect();
    // A setting that is no number (the beams' theory), where both have one and it differs.
    if let (Some((name, was)), Some((_, now))) = (setting_label(pinned), setting_label(current))
        && was != now
    {
        differences.push(format!("{name} {was}->{now}"));
    }
    match differences.len() {
        0 => "= current".to_string(),
        n if n <= NAMED_DIFFERENCES => differences.join(" "),
        n => format!(
            "{} +{}",
            differences[..NAMED_DIFFERENCES].join(" "),
            n - NAMED_DIFFERENCES
        ),
    }
}

/// A pinned series' name in CSV and figures: `pin 1: mu 0.6->0.3`.
#[cfg(feature = "app")]
pub(crate) fn series_name(number: u8, label: &str) -> String {
    format!("pin {number}: {label}")
}

/// The label of a pinned series' name (what follows `pin 1: `), for legends that show the number
/// as the series' own symbol.
#[cfg(feature = "app")]
pub(crate) fn label_of(name: &str) -> &str {
    name.split_once(": ").map_or(name, |(_, label)| label)
}

/// `plot` named for a figure someone reads without the terminal beside it: the current curve and
/// each pin by their own values of the parameters the pins change (`K_T (mu = 0.3)`,
/// `pin 1: mu = 0.2`), with units, and without the K_T companions when pins are compared. The
/// terminal's legend says `mu 0.2->0.3` (pinned, then now), which on paper reads as a change from
/// 0.2 to 0.3 on one curve.
#[cfg(feature = "app")]
pub(crate) fn named_by_values(mut plot: Plot, current: &Inputs, pinned: &[(u8, Inputs)]) -> Plot {
    let changed: Vec<Option<crate::problems::Param>> = current
        .kind()
        .params()
        .iter()
        .filter(|&&param| {
            pinned
                .iter()
                .any(|(_, p)| p.get(param) != current.get(param))
        })
        .map(|&param| Some(param))
        .collect();
    let unchanged: Vec<Option<crate::problems::Param>> = current
        .kind()
        .params()
        .iter()
        .map(|&param| Some(param))
        .filter(|param| !changed.contains(param))
        .collect();
    let values = |inputs: &Inputs| super::family::parameter_text(inputs, &unchanged);
    // A comparison exports what was compared: the current curve, the pins and the references
    // (Coulomb, limits, points), not the K_T/5 and K_T*5 companions drawn around the current
    // one, which would sit unlabelled between the compared curves (issue 47 item 6).
    if !changed.is_empty() {
        plot.series
            .retain(|s| !matches!(s.role, SeriesRole::Softer | SeriesRole::Stiffer));
    }
    for series in &mut plot.series {
        let own = match series.role {
            SeriesRole::Current if !changed.is_empty() => {
                format!("{} ({})", series.name, values(current))
            }
            SeriesRole::Pin(n) => match pinned.iter().find(|(m, _)| *m == n) {
                // A pin that differs only in the beam theory keeps its label (`theory EB->Timo`).
                Some((_, inputs)) if !changed.is_empty() && inputs != current => {
                    format!("pin {n}: {}", values(inputs))
                }
                _ => continue,
            },
            _ => continue,
        };
        series.name = own;
    }
    plot
}

/// `plot` with each pin's main curve added as [`SeriesRole::Pin`] (its number and label), taken
/// from `pinned`: the same chart built at the pin's parameters, in the same y-axis mode. Points
/// beyond the x range are left out (a pin at another K_T has its own K_T range); the y range
/// grows to show every pinned curve.
#[cfg(feature = "app")]
pub(crate) fn add_pins(plot: Plot, pinned: &[(u8, String, &Plot)]) -> Plot {
    let curves: Vec<Borrowed> = pinned
        .iter()
        .filter_map(|(number, label, pinned_plot)| {
            Some(Borrowed {
                role: SeriesRole::Pin(*number),
                name: series_name(*number, label),
                series: main_series(pinned_plot)?,
                log: pinned_plot.y.log,
            })
        })
        .collect();
    add_borrowed(plot, &curves)
}

/// A curve taken from another chart of the same quantity (a pin's, a family member's): the role
/// and name it gets here, its points, and whether its chart's y axis was logarithmic.
pub(super) struct Borrowed<'a> {
    pub role: SeriesRole,
    pub name: String,
    pub series: &'a PlotSeries,
    pub log: bool,
}

/// `plot` with `curves` added: points beyond the x range left out, the y range grown to show
/// them all.
pub(super) fn add_borrowed(mut plot: Plot, curves: &[Borrowed]) -> Plot {
    let [x0, x1] = plot.x.bounds;
    let [mut lo, mut hi] = plot.y.bounds;
    for curve in curves {
        let in_range = curve
            .series
            .points
            .iter()
            .copied()
            .filter(|&(x, y)| x >= x0 && x <= x1 && y.is_finite());
        // On a log axis, a borrowed chart that could not go log itself (its curve is 0, D at a
        // friction that never slips, u(L) at nu = 0) still holds raw values: a 0 there would be
        // drawn as 10^0 = 1. Values a log axis cannot show are left out and the name says so.
        let (points, name) = if plot.y.log && !curve.log {
            let all: Vec<(f64, f64)> = in_range.collect();
            let shown: Vec<(f64, f64)> = all
                .iter()
                .filter(|p| p.1 > 0.0)
                .map(|&(x, y)| (x, y.log10()))
                .collect();
            let name = match all.len() - shown.len() {
                0 => curve.name.clone(),
                n if n == all.len() => format!("{} (0: not on a log axis)", curve.name),
                n => format!("{} ({n} values <= 0 left out)", curve.name),
            };
            (shown, name)
        } else {
            (in_range.collect(), curve.name.clone())
        };
        for &(_, y) in &points {
            lo = lo.min(y);
            hi = hi.max(y);
        }
        plot.series.push(PlotSeries {
            name,
            points,
            role: curve.role,
        });
    }
    if [lo, hi] != plot.y.bounds {
        // A little room where a curve widened the range, so that it does not run along the frame.
        let pad = 0.03 * (hi - lo);
        let [old_lo, old_hi] = plot.y.bounds;
        let lo = if lo < old_lo { lo - pad } else { lo };
        let hi = if hi > old_hi { hi + pad } else { hi };
        let title = plot.y.title.clone();
        plot.y = if plot.y.log {
            log_axis(title, lo, hi)
        } else {
            linear_axis(title, lo, hi)
        };
        super::ymode::stretch_cursors(&mut plot.series, plot.y.bounds);
    }
    plot
}

/// `base` (the chart of `chart` at `current`, in y mode `mode`) with the same chart at each of
/// `pinned` added as pins 1, 2, ...: what `microslip plot --pin` draws. The pins are built over
/// `base`'s force range (the beams' force axis would otherwise follow each pin's F_thre).
#[cfg(feature = "app")]
pub(crate) fn with_pinned_models(
    base: Plot,
    current: &Model,
    chart: AnyChart,
    pinned: &[Model],
    mode: YMode,
) -> Plot {
    let span = Some(base.x.bounds[1]);
    let plots: Vec<Plot> = pinned
        .iter()
        .map(|m| mode.apply(build(m, chart, None, None, None, span)))
        .collect();
    let now = current.inputs();
    let entries: Vec<(u8, String, &Plot)> = pinned
        .iter()
        .zip(&plots)
        .zip(1u8..)
        .map(|((m, plot), n)| (n, label(&m.inputs(), &now), plot))
        .collect();
    add_pins(base, &entries)
}

#[cfg(feature = "app")]
#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::{BeamParam, ModelKind, Param, PlateParam};

    use crate::chart::every_chart;

    #[test]
    fn every_chart_has_a_curve_to_pin() {
        for kind in ModelKind::ALL {
            let model = Inputs::paper(kind).validate().unwrap();
            for chart in every_chart(kind) {
                let plot = build(&model, chart, None, None, None, None);
                assert!(main_series(&plot).is_some(), "{}", plot.title);
            }
        }
    }

    /// A pinned chart whose curve is 0 everywhere (D at a friction that never slips; u(L) at
    /// nu = 0) used to be drawn at 10^0 = 1 on a log axis; values <= 0 are now left out and the
    /// legend says so.
    #[test]
    fn values_a_log_axis_cannot_show_are_left_out_and_said() {
        use crate::chart::view::AnyChart;
        use crate::problems::plate::PlateChart;
        use crate::problems::twin_beams::BeamChart;
        let cases = [
            (
                ModelKind::Beam,
                AnyChart::Beam(BeamChart::Dissipation),
                Param::Beam(BeamParam::Friction),
                10.0,
            ),
            (
                ModelKind::Plate,
                AnyChart::Plate(PlateChart::Displacement),
                Param::Plate(PlateParam::Poisson),
                0.0,
            ),
        ];
        for (kind, chart, param, value) in cases {
            let current = Inputs::paper(kind).validate().unwrap();
            let base = YMode::Log.apply(build(&current, chart, None, None, None, None));
            assert!(base.y.log, "{}", base.title);
            let mut pinned = Inputs::paper(kind);
            pinned.set(param, value).unwrap();
            let pinned = pinned.validate().unwrap();
            let plot = with_pinned_models(base, &current, chart, &[pinned], YMode::Log);
            let pin = plot.series.last().unwrap();
            assert_eq!(pin.role, SeriesRole::Pin(1));
            assert!(
                pin.points.is_empty(),
                "{}: {:?}",
                pin.name,
                &pin.points[..3.min(pin.points.len())]
            );
            assert!(pin.name.ends_with("(0: not on a log axis)"), "{}", pin.name);
        }
    }

    #[test]
    fn labels_name_what_differs_pinned_value_first() {
        let current = Inputs::paper(ModelKind::Beam);
        assert_eq!(label(&current, &current), "= current");
        let mut pinned = current;
        pinned.set(Param::Beam(BeamParam::Friction), 0.2).unwrap();
        assert_eq!(label(&pinned, &current), "mu 0.2->0.3");
        pinned
            .set(Param::Beam(BeamParam::Stiffness), 120.0)
            .unwrap();
        pinned.set(Param::Beam(BeamParam::Force), 50.0).unwrap();
        assert_eq!(label(&pinned, &current), "mu 0.2->0.3 KT 120->600 +1");
        let plate = Inputs::paper(ModelKind::Plate);
        let mut pinned = plate;
        pinned
            .set(Param::Plate(PlateParam::Thickness), 0.5)
            .unwrap();
        assert_eq!(label(&pinned, &plate), "tp 0.5->0.2");
    }

    /// The default chart (w(L) vs F) at `inputs` over 0..240 N (3 F_thre of the paper's beams):
    /// pins are built over the current chart's force range.
    fn build_at(inputs: &Inputs) -> Plot {
        let model = inputs.validate().unwrap();
        build(
            &model,
            AnyChart::Beam(crate::problems::twin_beams::BeamChart::Deflection),
            None,
            None,
            None,
            Some(240.0),
        )
    }

    #[test]
    fn a_pinned_curve_is_the_main_curve_of_the_same_chart_at_the_pinned_values() {
        let current = Inputs::paper(ModelKind::Beam);
        let mut pinned = current;
        pinned.set(Param::Beam(BeamParam::Friction), 0.6).unwrap();
        let plot = add_pins(
            build_at(&current),
            &[(1, label(&pinned, &current), &build_at(&pinned))],
        );
        let pin = plot.series.last().unwrap();
        assert_eq!(pin.role, SeriesRole::Pin(1));
        assert_eq!(pin.name, "pin 1: mu 0.6->0.3");
        assert_eq!(label_of(&pin.name), "mu 0.6->0.3");
        // Twice mu: twice F_thre, so at the top of the range the pinned beams deflect less.
        let alone = build_at(&pinned);
        assert_eq!(&pin.points, &main_series(&alone).unwrap().points);
        let current_top = main_series(&plot).unwrap().points.last().unwrap().1;
        assert!(pin.points.last().unwrap().1 < current_top);
    }

    #[test]
    fn the_y_range_grows_to_show_a_pin_and_points_beyond_the_x_range_are_left_out() {
        let current = Inputs::paper(ModelKind::Beam);
        let mut pinned = current;
        // A tenth of mu: the pinned beams slide early and deflect far more.
        pinned.set(Param::Beam(BeamParam::Friction), 0.03).unwrap();
        let before = build_at(&current);
        let pinned_plot = build_at(&pinned);
        let plot = add_pins(before.clone(), &[(2, "x".into(), &pinned_plot)]);
        let pin = plot.series.last().unwrap();
        assert_eq!(pin.points.last().unwrap().0, 240.0);
        let top = pin.points.iter().map(|p| p.1).fold(0.0, f64::max);
        assert!(top > before.y.bounds[1]);
        assert!(plot.y.bounds[1] >= top);
        assert!(pin.points.iter().all(|p| p.0 <= plot.x.bounds[1]));
        // The cursor spans the new range.
        let cursor = plot
            .series
            .iter()
            .find(|s| s.role == SeriesRole::Cursor)
            .unwrap();
        assert_eq!(cursor.points[1].1, plot.y.bounds[1]);
    }
}
