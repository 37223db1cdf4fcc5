//! The Hertzian cylinder's charts as data (its [`ChartFace`]): s(a) vs Q, c/a vs Q/mu P for a
//! K_T family with Mindlin's, q(x) with Mindlin's, s(x).

use super::closed_form::{Cylinder, TangentialLoad};
use super::params::CylinderParam;
use super::problem::CylinderProblem;
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, Plot, SeriesRole, cursor, line, linear_axis, max_y, samples};
use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Param;
use crate::study::curves::{Samples, Spacing};
use crate::study::samples::Series;

/// The cylinder's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CylinderChart {
    /// The edge slip s(a) (the fretting slip amplitude) against Q, both laws.
    EdgeSlip,
    /// c / a against Q / mu P: Mindlin's sqrt(1 - Q/mu P) and the regularized law at K_T/10,
    /// K_T and 10 K_T.
    Zone,
    /// The shear traction q(x) over the contact at Q, both laws, under mu p(x).
    Shear,
    /// The slip s(x) over the contact at Q, both laws.
    Slip,
}

impl ChartSet for CylinderChart {
    const ALL: &'static [Self] = &[
        CylinderChart::EdgeSlip,
        CylinderChart::Zone,
        CylinderChart::Shear,
        CylinderChart::Slip,
    ];

    fn title(self) -> &'static str {
        match self {
            CylinderChart::EdgeSlip => "s(a) vs Q",
            CylinderChart::Zone => "c/a vs Q/mu P",
            CylinderChart::Shear => "q(x) at Q",
            CylinderChart::Slip => "s(x) at Q",
        }
    }

    fn key(self) -> &'static str {
        match self {
            CylinderChart::EdgeSlip => "sa-vs-q",
            CylinderChart::Zone => "c-vs-q",
            CylinderChart::Shear => "cylinder-q",
            CylinderChart::Slip => "cylinder-slip",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            CylinderChart::EdgeSlip => Some(Param::Cylinder(CylinderParam::TangentialLoad)),
            CylinderChart::Zone | CylinderChart::Shear | CylinderChart::Slip => None,
        }
    }

    fn load_axis(self) -> bool {
        matches!(self, CylinderChart::EdgeSlip)
    }

    fn spans_decades(self) -> bool {
        false
    }
}

impl ChartFace for CylinderProblem {
    type Chart = CylinderChart;

    fn plot(
        model: &Self::Model,
        chart: CylinderChart,
        _f_data: f64,
        span: Option<f64>,
    ) -> Option<Plot> {
        cylinder_plot(&model.cylinder, model.load, chart, span)
    }

    /// The cylinder's independent discretized solver is not drawn here yet: no points.
    fn numeric_points(
        _model: &Self::Model,
        _chart: CylinderChart,
        _density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        Ok(None)
    }
}

/// The points of a curve whose every point is a regularized solve (the s(a) and c/a curves):
/// 41, not the charts' 200, so that a frame stays within the TUI's budget; the curves are smooth.
fn few(from: f64, to: f64) -> Option<Samples> {
    Samples::new(from, to, 41, Spacing::Linear).ok()
}

/// A load of `cylinder` at `q` (N/mm), clamped to what it carries.
fn at(cylinder: &Cylinder, q: f64) -> TangentialLoad {
    cylinder.clamped_load(q)
}

fn cylinder_plot(
    cylinder: &Cylinder,
    load: TangentialLoad,
    chart: CylinderChart,
    span: Option<f64>,
) -> Option<Plot> {
    let p = cylinder.params();
    let gross = cylinder.gross_slip_load();
    let q = load.newtons_per_mm();
    let a = cylinder.half_width();
    let kt = p.tangential_stiffness;
    match chart {
        CylinderChart::EdgeSlip => {
            // Up to just below gross slip, where the edge slip grows without bound.
            let top = span.map_or(gross, |s| s.min(gross)) * 0.98;
            let loads = few(0.0, top.max(f64::MIN_POSITIVE))?;
            let (mindlin, regularized): (Series, Series) = loads
                .values()
                .map(|x| {
                    let l = at(cylinder, x);
                    (
                        (x, cylinder.coulomb(l).edge_slip()),
                        (x, cylinder.regularized(l).edge_slip()),
                    )
                })
                .unzip();
            let y_top = 1.05 * max_y([&mindlin, &regularized]).max(f64::MIN_POSITIVE);
            Some(Plot {
                caption: None,
                title: format!("s(a): edge slip, K_T = {} MPa/mm", number(kt)),
                x: linear_axis("Q (N/mm)", 0.0, top),
                y: linear_axis("s(a) (mm)", 0.0, y_top),
                series: vec![
                    line(SeriesRole::Coulomb, "Mindlin", mindlin),
                    line(SeriesRole::Current, "regularized", regularized),
                    cursor(q, [0.0, y_top]),
                ],
            })
        }
        CylinderChart::Zone => {
            let ratios = few(0.0, 0.98)?;
            let family = |kt: f64| -> Vec<(f64, f64)> {
                let Ok(c) = cylinder.with_tangential_stiffness(kt) else {
                    return Vec::new();
                };
                ratios
                    .values()
                    .map(|r| (r, c.regularized(at(&c, r * gross)).micro_half_width() / a))
                    .collect()
            };
            let mindlin: Vec<(f64, f64)> = ratios
                .values()
                .map(|r| {
                    (
                        r,
                        cylinder.coulomb(at(cylinder, r * gross)).stick_half_width() / a,
                    )
                })
                .collect();
            Some(Plot {
                caption: None,
                title: format!("c/a, K_T = {} MPa/mm x 1/10, 1, 10", number(kt)),
                x: linear_axis("Q / mu P (-)", 0.0, 1.0),
                y: linear_axis("c / a (-)", 0.0, 1.05),
                series: vec![
                    line(SeriesRole::Coulomb, "Mindlin", mindlin),
                    line(SeriesRole::Softer, "K_T/10", family(kt / 10.0)),
                    line(SeriesRole::Current, "K_T", family(kt)),
                    line(SeriesRole::Stiffer, "K_T*10", family(kt * 10.0)),
                    cursor(q / gross, [0.0, 1.05]),
                ],
            })
        }
        CylinderChart::Shear | CylinderChart::Slip => {
            let xs = samples(-a, a, Spacing::Linear)?;
            let (mindlin, regularized) = (cylinder.coulomb(load), cylinder.regularized(load));
            let shear = chart == CylinderChart::Shear;
            let (coulomb, current): (Series, Series) = xs
                .values()
                .map(|x| {
                    if shear {
                        ((x, mindlin.shear_at(x)), (x, regularized.shear_at(x)))
                    } else {
                        ((x, mindlin.slip_at(x)), (x, regularized.slip_at(x)))
                    }
                })
                .unzip();
            let mut series = vec![
                line(SeriesRole::Coulomb, "Mindlin", coulomb),
                line(SeriesRole::Current, "regularized", current),
            ];
            if shear {
                let limit: Vec<(f64, f64)> = xs
                    .values()
                    .map(|x| (x, p.friction * cylinder.pressure_at(x)))
                    .collect();
                series.push(line(SeriesRole::Limit, "mu p(x)", limit));
            }
            let top = 1.1
                * series
                    .iter()
                    .map(|s| max_y([&s.points]))
                    .fold(0.0, f64::max);
            let (symbol, unit) = if shear {
                ("q(x)", "q (MPa)")
            } else {
                ("s(x)", "s (mm)")
            };
            Some(Plot {
                caption: None,
                title: format!("{symbol} at Q = {} N/mm", number(q)),
                x: linear_axis("x (mm)", -a, a),
                y: linear_axis(unit, 0.0, top.max(f64::MIN_POSITIVE)),
                series,
            })
        }
    }
}
