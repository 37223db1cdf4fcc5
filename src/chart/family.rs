//! Families: one chart's main curve at several values of one parameter (`microslip plot --family
//! P=0.5,1,2`), for the comparison figures of a report ("w(L) vs F for P = 0.5, 1 and 2 MPa").
//!
//! A pin compares a kept state with the current one; a family has no current member. Every member
//! has the same rank ([`SeriesRole::Family`]): each is named by its value with the parameter's unit
//! (`P = 0.5 MPa`), drawn alike, and no cursor or companion curve (K_T/5, K_T x 5) is added, since
//! those belong to one member. A series of the chart that is the same for every member (Coulomb
//! when the family varies K_T, the cursor at F when it varies P) may be added once (`--series`);
//! one that differs between members (Coulomb when P varies) is refused rather than drawn for one
//! member as if it held for all.
//!
//! Every member is computed over the whole x axis: on the beams' force charts the axis is the
//! widest any member needs (3 F_thre of the member with the largest threshold), so that every
//! member's regime change is on the chart, and each member is rebuilt over that range.

use thiserror::Error;

use super::pins::{Borrowed, add_borrowed, main_series};
use super::{Plot, SeriesRole, YMode, build, linear_axis, log_axis};
use crate::chart::view::AnyChart;
use crate::kernel::params::Compact;
use crate::problems::Param;
use crate::problems::inputs::{Inputs, Model};

/// Members of a family at most: more curves than that cannot be told apart in a figure (the
/// palette has seven colours, one kept for the reference).
#[cfg(feature = "app")]
pub(crate) const MAX_MEMBERS: usize = 6;

/// Why a family cannot be drawn.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FamilyError {
    /// A series asked for differs between members.
    #[error(
        "the {role} series differs between the members (it depends on {param}): draw it with \
         --pin, or one plot per value"
    )]
    Differs {
        /// The series' key (`coulomb`).
        role: &'static str,
        /// The varied parameter.
        param: Param,
    },
    /// The varied parameter is the one the chart runs along its x axis: every member would draw
    /// the same curve.
    #[error(
        "{param} is the x axis of chart {chart}: every member would draw the same curve; vary \
         another parameter"
    )]
    AlongTheAxis {
        /// The chart's key.
        chart: &'static str,
        /// The varied parameter.
        param: Param,
    },
    /// A series asked for is not on this chart.
    #[error("chart {chart} has no {role} series; it has: {present}")]
    Missing {
        /// The chart's key.
        chart: &'static str,
        /// The series' key.
        role: &'static str,
        /// The keys of the series it has, comma-separated.
        present: String,
    },
    /// The y mode does not apply to one member's chart.
    #[error("--y {mode}: the member {member} cannot show it")]
    Mode {
        /// The mode's key.
        mode: &'static str,
        /// The member's legend text.
        member: String,
    },
}

/// A member's legend text: `P = 0.5 MPa`, `mu = 0.2`.
pub(crate) fn member_name(param: Param, value: f64) -> String {
    format!("{param} = {}{}", Compact(value), param.unit_suffix())
}

/// The parameters of `inputs` as a caption says them, `except` those (the varied one, the one the
/// x axis runs along): `L = 200 mm, b = 20 mm, ..., mu = 0.3`.
pub(crate) fn parameter_text(inputs: &Inputs, except: &[Option<Param>]) -> String {
    inputs
        .kind()
        .params()
        .iter()
        .filter(|&&param| !except.contains(&Some(param)))
        .filter_map(|&param| {
            let value = inputs.get(param)?;
            Some(format!(
                "{param} = {}{}",
                Compact(value),
                param.unit_suffix()
            ))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The title of a family of `chart` over `param` at `values`: `w(L) vs F, P = 0.5, 1, 2 MPa`.
pub(crate) fn title(chart: AnyChart, param: Param, values: &[f64]) -> String {
    let values: Vec<String> = values.iter().map(|&v| Compact(v).to_string()).collect();
    format!(
        "{}, {param} = {}{}",
        chart.title(),
        values.join(", "),
        param.unit_suffix()
    )
}

/// Whether a chart's x axis is the problem's load, which a family widens to its widest member.
fn force_axis(chart: AnyChart) -> bool {
    chart.load_axis()
}

/// The chart `chart` of each of `members` (models of `param` at `values`, the rest equal) in y
/// mode `mode`: one [`SeriesRole::Family`] curve per member, named by `member_name`, plus the
/// series of `shared` roles that every member has alike (added once, from the first member). The
/// title names the values, [`Plot::caption`] the parameters held fixed.
///
/// # Errors
/// [`FamilyError::Mode`] when `mode` cannot show a member; [`FamilyError::Missing`] for a shared
/// role the chart does not have; [`FamilyError::Differs`] for one that is not the same for every
/// member.
pub fn build_family(
    chart: AnyChart,
    param: Param,
    members: &[(f64, Model)],
    mode: YMode,
    shared: &[SeriesRole],
) -> Result<Plot, FamilyError> {
    if chart.x_param() == Some(param) {
        return Err(FamilyError::AlongTheAxis {
            chart: chart.key(),
            param,
        });
    }
    let linear = |model: &Model, span: Option<f64>| build(model, chart, None, None, None, span);
    // The widest force axis any member needs, then every member over it.
    let span = force_axis(chart)
        .then(|| {
            members
                .iter()
                .map(|(_, m)| linear(m, None).x.bounds[1])
                .fold(0.0, f64::max)
        })
        .filter(|s| *s > 0.0);
    let mut plots = Vec::with_capacity(members.len());
    for (value, model) in members {
        let plot = linear(model, span);
        if !mode.applies_to(&plot) {
            return Err(FamilyError::Mode {
                mode: mode.key(),
                member: member_name(param, *value),
            });
        }
        plots.push(mode.apply(plot));
    }
    let Some(first) = plots.first() else {
        return Ok(Plot::default());
    };
    let mut base = Plot {
        title: title(
            chart,
            param,
            &members.iter().map(|m| m.0).collect::<Vec<_>>(),
        ),
        caption: members
            .first()
            .map(|(_, m)| parameter_text(&m.inputs(), &[Some(param), chart.x_param()])),
        x: first.x.clone(),
        y: first.y.clone(),
        series: Vec::new(),
    };
    // The union of the members' axes (their x ranges differ where the chart's range follows the
    // varied parameter: X_r vs mu over mu, u(L) vs K_T over K_T).
    let union = |get: fn(&Plot) -> [f64; 2]| {
        plots
            .iter()
            .map(get)
            .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], [a, b]| {
                [lo.min(a), hi.max(b)]
            })
    };
    let [x0, x1] = union(|p| p.x.bounds);
    let axis = |a: &super::Axis, lo, hi| {
        if a.log {
            log_axis(a.title.clone(), lo, hi)
        } else {
            linear_axis(a.title.clone(), lo, hi)
        }
    };
    base.x = axis(&first.x, x0, x1);
    for &role in shared.iter().filter(|&&r| r != SeriesRole::Current) {
        let key = role.key().unwrap_or("?");
        let of = |p: &Plot| p.series.iter().find(|s| s.role == role).cloned();
        let Some(series) = of(first) else {
            let present: Vec<&str> = first.series.iter().filter_map(|s| s.role.key()).collect();
            return Err(FamilyError::Missing {
                chart: chart.key(),
                role: key,
                present: present.join(", "),
            });
        };
        // The cursor's ends follow each member's y axis; only where it stands matters.
        let close = |u: f64, v: f64| (u - v).abs() <= 1e-12 * u.abs().max(v.abs());
        let alike = |other: Option<super::PlotSeries>| {
            other.is_some_and(|o| match role {
                SeriesRole::Cursor => o
                    .points
                    .first()
                    .zip(series.points.first())
                    .is_some_and(|(a, b)| close(a.0, b.0)),
                _ => {
                    o.points.len() == series.points.len()
                        && o.points
                            .iter()
                            .zip(&series.points)
                            .all(|(a, b)| close(a.0, b.0) && close(a.1, b.1))
                }
            })
        };
        if !plots[1..].iter().all(|p| alike(of(p))) {
            return Err(FamilyError::Differs { role: key, param });
        }
        base.series.push(series);
    }
    // The y axis from what is drawn (the members' own axes also hold their companions: K_T/5
    // would set the top of a K_T family's relative chart), 5 % headroom, from 0 where the
    // members' axes start there.
    let drawn = plots
        .iter()
        .filter_map(main_series)
        .chain(&base.series)
        .filter(|s| s.role != SeriesRole::Cursor)
        .flat_map(|s| s.points.iter().map(|p| p.1));
    let (lo, hi) = drawn.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
        (lo.min(y), hi.max(y))
    });
    if lo.is_finite() && hi.is_finite() {
        let pad = 0.05 * (hi - lo);
        let from_zero = !first.y.log && plots.iter().all(|p| p.y.bounds[0] == 0.0) && lo >= 0.0;
        let lo = if from_zero { 0.0 } else { lo - pad };
        base.y = axis(&first.y, lo, hi + pad);
    }
    super::ymode::stretch_cursors(&mut base.series, base.y.bounds);
    let curves: Vec<Borrowed> = members
        .iter()
        .zip(&plots)
        .zip(1u8..)
        .filter_map(|(((value, _), plot), n)| {
            Some(Borrowed {
                role: SeriesRole::Family(n),
                name: member_name(param, *value),
                series: main_series(plot)?,
                log: plot.y.log,
            })
        })
        .collect();
    Ok(add_borrowed(base, &curves))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::plate::PlateChart;
    use crate::problems::twin_beams::BeamChart;
    use crate::problems::{BeamParam, ModelKind, PlateParam};

    fn members(kind: ModelKind, param: Param, values: &[f64]) -> Vec<(f64, Model)> {
        values
            .iter()
            .map(|&v| {
                let mut inputs = Inputs::paper(kind);
                inputs.set(param, v).unwrap();
                (v, inputs.validate().unwrap())
            })
            .collect()
    }

    const P: Param = Param::Beam(BeamParam::Pressure);
    const W_VS_F: AnyChart = AnyChart::Beam(BeamChart::Deflection);

    #[test]
    fn one_curve_per_value_named_with_its_unit_spanning_the_widest_force_axis() {
        let plot = build_family(
            W_VS_F,
            P,
            &members(ModelKind::Beam, P, &[0.5, 1.0, 2.0]),
            YMode::Linear,
            &[],
        )
        .unwrap();
        let names: Vec<&str> = plot.series.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["P = 0.5 MPa", "P = 1 MPa", "P = 2 MPa"]);
        let roles: Vec<SeriesRole> = plot.series.iter().map(|s| s.role).collect();
        assert_eq!(roles, [1, 2, 3].map(SeriesRole::Family));
        assert_eq!(plot.title, "w(L) vs F, P = 0.5, 1, 2 MPa");
        let caption = plot.caption.as_deref().unwrap();
        assert!(
            caption.contains("KT = 600 MPa/mm") && !caption.contains("P = "),
            "{caption}"
        );
        // F runs along the x axis: its value would say nothing.
        assert!(!caption.contains("F = "), "{caption}");
        // P = 2 MPa: F_thre = 160 N, so the axis runs to 480 N and every curve reaches it.
        assert_eq!(plot.x.bounds[1], 480.0);
        // The y axis from the members drawn, not their companions: 5 % above the highest.
        let top = plot
            .series
            .iter()
            .flat_map(|s| &s.points)
            .map(|p| p.1)
            .fold(0.0, f64::max);
        assert!(
            (plot.y.bounds[1] / top - 1.05).abs() < 1e-9,
            "{:?} {top}",
            plot.y.bounds
        );
        assert_eq!(plot.y.bounds[0], 0.0);
        for s in &plot.series {
            assert_eq!(s.points.first().unwrap().0, 0.0, "{}", s.name);
            assert_eq!(s.points.last().unwrap().0, 480.0, "{}", s.name);
            assert!(
                s.points.iter().all(|p| p.1 <= plot.y.bounds[1]),
                "{}",
                s.name
            );
        }
    }

    #[test]
    fn a_shared_series_is_added_once_and_one_that_differs_is_refused() {
        let kt = Param::Beam(BeamParam::Stiffness);
        let stiffnesses = members(ModelKind::Beam, kt, &[120.0, 600.0, 3000.0]);
        let plot = build_family(
            W_VS_F,
            kt,
            &stiffnesses,
            YMode::Linear,
            &[SeriesRole::Coulomb, SeriesRole::Cursor],
        )
        .unwrap();
        let roles: Vec<SeriesRole> = plot.series.iter().map(|s| s.role).collect();
        assert_eq!(roles[..2], [SeriesRole::Coulomb, SeriesRole::Cursor]);
        assert_eq!(roles.len(), 5);
        let pressures = members(ModelKind::Beam, P, &[0.5, 2.0]);
        let refused = build_family(W_VS_F, P, &pressures, YMode::Linear, &[SeriesRole::Coulomb]);
        assert_eq!(
            refused.unwrap_err(),
            FamilyError::Differs {
                role: "coulomb",
                param: P
            }
        );
        let missing = build_family(W_VS_F, P, &pressures, YMode::Linear, &[SeriesRole::Limit]);
        assert!(
            missing
                .unwrap_err()
                .to_string()
                .contains("has no limit series; it has: coulomb, softer, stiffer, current, cursor")
        );
    }

    #[test]
    fn a_family_along_the_chart_s_own_axis_is_refused_and_another_is_drawn() {
        // mu is the x axis of X_r vs mu: every member would draw the same X_r(mu).
        let mu = Param::Plate(PlateParam::Friction);
        let along = build_family(
            AnyChart::Plate(PlateChart::SlipBoundary),
            mu,
            &members(ModelKind::Plate, mu, &[0.1, 0.3]),
            YMode::Linear,
            &[],
        );
        assert!(matches!(along, Err(FamilyError::AlongTheAxis { .. })));
        // t_p is not (P would be, in effect: the plate's problem is homogeneous in P, X_r does
        // not move): two curves over the same mu axis, each its own.
        let tp = Param::Plate(PlateParam::Thickness);
        let plot = build_family(
            AnyChart::Plate(PlateChart::SlipBoundary),
            tp,
            &members(ModelKind::Plate, tp, &[0.1, 0.4]),
            YMode::Linear,
            &[],
        )
        .unwrap();
        assert_eq!(plot.series.len(), 2);
        assert_ne!(plot.series[0].points, plot.series[1].points);
    }
}
