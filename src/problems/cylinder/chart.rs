//! The Hertzian cylinder's charts as data (its [`ChartFace`]): s(a) vs Q, c/a vs Q/mu P for a
//! K_T family with Mindlin's, q(x) with Mindlin's, s(x), the hysteresis loop of s(a) for +-Q
//! and the dissipation per cycle D vs Q_a/mu P for a K_T family with Mindlin-Deresiewicz's. The
//! independent discretized solver's points (`n`) are [`super::overlay`]'s.

use super::closed_form::{Cylinder, TangentialLoad};
use super::cycle::CylinderCycle;
use super::params::CylinderParam;
use super::problem::CylinderProblem;
use crate::chart::load::loop_plot;
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, Plot, SeriesRole, cursor, line, linear_axis, max_y, samples};
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Param;
use crate::problems::load_driven::MasingCycle;
use crate::study::curves::{Samples, Spacing};
use crate::study::load::cycle_loop;
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
    /// The hysteresis loop of the edge slip s(a) for Q cycling between +Q and -Q, both laws.
    /// s(a), not the rigid shift delta: s(a) is defined whatever the bodies' size (delta of two
    /// half-planes only up to a term linear in Q, which shears the loop), it is what an FE
    /// code's s(a) is compared with and what `microslip cycle --format csv` writes. Its area is
    /// not D: D (in the title) is the area of the shift's loop.
    Loop,
    /// The dissipation per cycle D against the amplitude Q_a / mu P: Mindlin-Deresiewicz's
    /// (plain Coulomb) and the regularized law at K_T/10, K_T and 10 K_T.
    Dissipation,
}

impl ChartSet for CylinderChart {
    const ALL: &'static [Self] = &[
        CylinderChart::EdgeSlip,
        CylinderChart::Zone,
        CylinderChart::Shear,
        CylinderChart::Slip,
        CylinderChart::Loop,
        CylinderChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            CylinderChart::EdgeSlip => "s(a) vs Q",
            CylinderChart::Zone => "c/a vs Q/mu P",
            CylinderChart::Shear => "q(x) at Q",
            CylinderChart::Slip => "s(x) at Q",
            CylinderChart::Loop => "loop +-Q",
            CylinderChart::Dissipation => "D vs Q_a/mu P",
        }
    }

    fn key(self) -> &'static str {
        match self {
            CylinderChart::EdgeSlip => "sa-vs-q",
            CylinderChart::Zone => "c-vs-q",
            CylinderChart::Shear => "cylinder-q",
            CylinderChart::Slip => "cylinder-slip",
            CylinderChart::Loop => "cylinder-loop",
            CylinderChart::Dissipation => "cylinder-d-vs-qa",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            CylinderChart::EdgeSlip => Some(Param::Cylinder(CylinderParam::TangentialLoad)),
            CylinderChart::Zone
            | CylinderChart::Shear
            | CylinderChart::Slip
            | CylinderChart::Loop
            | CylinderChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        matches!(self, CylinderChart::EdgeSlip)
    }

    /// D: as Q_a^3 (Mindlin) and Q_a^4 (regularized) at small amplitudes, where the laws part.
    fn spans_decades(self) -> bool {
        matches!(self, CylinderChart::Dissipation)
    }
}

impl ChartFace for CylinderProblem {
    type Chart = CylinderChart;

    /// Not finite elements: point forces on a grid over the contact, a Jenkins element at each
    /// (`overlay.rs` in this folder).
    const NUMERIC_NAME: &'static str = "discretized solver";

    fn plot(
        model: &Self::Model,
        chart: CylinderChart,
        _f_data: f64,
        span: Option<f64>,
    ) -> Option<Plot> {
        cylinder_plot(&model.cylinder, model.load, chart, span)
    }

    /// The independent discretized solver's points (`overlay.rs` in this folder).
    fn numeric_points(
        model: &Self::Model,
        chart: CylinderChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        super::overlay::numeric_points(&model.cylinder, model.load, chart, density)
    }
}

/// The points of a curve whose every point is a regularized solve (the s(a), c/a and D curves,
/// and each branch of the loop): 41, not the charts' 200, so that a frame stays within the
/// TUI's budget; the curves are smooth.
const FEW: u64 = 41;

fn few(from: f64, to: f64) -> Option<Samples> {
    Samples::new(from, to, FEW, Spacing::Linear).ok()
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
                title: format!("c/a, K_T = {} MPa/mm x {FAMILY_WORDS}", number(kt)),
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
        CylinderChart::Loop => Some(edge_slip_loop(cylinder, load)),
        CylinderChart::Dissipation => dissipation_vs_amplitude(cylinder, load),
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

/// How the K_T family of the c/a and D charts is named in their titles.
const FAMILY_WORDS: &str = "1/10, 1, 10";

/// The hysteresis loop of the edge slip s(a) at the current Q (the amplitude), both laws, by
/// Masing's rule on each law's first loading ([`CylinderCycle`]); the title gives D of both, the
/// area of the rigid shift's loop (at most 41 characters, an 80x24 chart pane's title row; M(indlin)
/// and R(egularized)).
fn edge_slip_loop(cylinder: &Cylinder, load: TangentialLoad) -> Plot {
    let q = load.newtons_per_mm();
    let (mindlin, regularized) = (
        CylinderCycle::new(cylinder, Law::Coulomb, load),
        CylinderCycle::new(cylinder, Law::Regularized, load),
    );
    let title = format!(
        "+-{} N/mm; D {} M, {} R N mm/mm",
        number_with(q, 4),
        number_with(mindlin.dissipation(), 3),
        number_with(regularized.dissipation(), 3)
    );
    // FEW is within cycle_loop's accepted range: no loop is refused.
    let loops = cycle_loop::<CylinderProblem>(cylinder, load, FEW)
        .into_iter()
        .flatten();
    let mut plot = loop_plot(
        title,
        loops,
        mindlin.peak_response().max(regularized.peak_response()),
        (q, "Q (N/mm)"),
        "s(a) (mm)",
    );
    for series in &mut plot.series {
        if series.role == SeriesRole::Coulomb {
            series.name = "Mindlin".into();
        }
    }
    plot
}

/// D per cycle (N mm per mm) against Q_a / mu P from 0 to 0.98: Mindlin-Deresiewicz's closed form
/// and the regularized law at K_T/10, K_T and 10 K_T (4 W_1 on the semi-analytic first loading),
/// the cursor at the current Q / mu P.
fn dissipation_vs_amplitude(cylinder: &Cylinder, load: TangentialLoad) -> Option<Plot> {
    let gross = cylinder.gross_slip_load();
    let kt = cylinder.params().tangential_stiffness;
    let ratios = few(0.0, 0.98)?;
    let curve = |c: &Cylinder, law: Law| -> Series {
        ratios
            .values()
            .map(|r| {
                let amplitude = at(c, r * gross);
                (r, CylinderCycle::new(c, law, amplitude).dissipation())
            })
            .collect()
    };
    let family = |factor: f64| -> Series {
        cylinder
            .with_tangential_stiffness(kt * factor)
            .map_or_else(|_| Vec::new(), |c| curve(&c, Law::Regularized))
    };
    let mut series = vec![
        line(
            SeriesRole::Coulomb,
            "Mindlin-Deresiewicz",
            curve(cylinder, Law::Coulomb),
        ),
        line(SeriesRole::Softer, "K_T/10", family(0.1)),
        line(
            SeriesRole::Current,
            "K_T",
            curve(cylinder, Law::Regularized),
        ),
        line(SeriesRole::Stiffer, "K_T*10", family(10.0)),
    ];
    let top = 1.05 * max_y(series.iter().map(|s| &s.points)).max(f64::MIN_POSITIVE);
    series.push(cursor(load.newtons_per_mm() / gross, [0.0, top]));
    Some(Plot {
        caption: None,
        title: format!("D, K_T = {} MPa/mm x {FAMILY_WORDS}", number(kt)),
        x: linear_axis("Q_a / mu P (-)", 0.0, 1.0),
        y: linear_axis("D (N mm per mm)", 0.0, top),
        series,
    })
}

#[cfg(test)]
mod tests {
    use super::super::closed_form::CylinderParams;
    use super::*;
    use crate::chart::view::ChartFace;

    /// The loop and D vs Q_a / mu P at the corners of K_T's domain and at Q = 0, mu P / 2 and
    /// mu P (the whole contact sliding): finite points on increasing axes, both laws drawn, the
    /// loop closed on itself (each branch ends where the other starts).
    #[test]
    fn the_loop_and_d_at_the_corners_have_finite_points_on_valid_axes() {
        let domain = CylinderParam::Stiffness.spec().domain;
        for kt in [domain.min(), 1e5, domain.max()] {
            let cylinder = Cylinder::new(CylinderParams {
                tangential_stiffness: kt,
                ..CylinderParams::STEEL_PAD
            })
            .unwrap();
            for q in [0.0, 300.0, 600.0] {
                let model = super::super::problem::CylinderModel {
                    cylinder,
                    load: cylinder.load(q).unwrap(),
                };
                for chart in [CylinderChart::Loop, CylinderChart::Dissipation] {
                    let plot =
                        <CylinderProblem as ChartFace>::plot(&model, chart, 0.0, None).unwrap();
                    let what = format!("K_T {kt} Q {q} {chart:?}");
                    for axis in [&plot.x, &plot.y] {
                        let [lo, hi] = axis.bounds;
                        assert!(lo.is_finite() && hi.is_finite() && lo < hi, "{what}");
                    }
                    for s in &plot.series {
                        assert!(
                            s.points.iter().all(|p| p.0.is_finite() && p.1.is_finite()),
                            "{what} {}",
                            s.name
                        );
                    }
                    let drawn = |name: &str| {
                        plot.series
                            .iter()
                            .find(|s| s.name == name)
                            .is_some_and(|s| !s.points.is_empty())
                    };
                    assert!(drawn("regularized") || drawn("K_T"), "{what}");
                    assert!(drawn("Mindlin") || drawn("Mindlin-Deresiewicz"), "{what}");
                    if chart == CylinderChart::Loop {
                        for s in &plot.series {
                            let (unloading, reloading) = s.points.split_at(FEW as usize);
                            assert_eq!(unloading.last(), reloading.first(), "{what}");
                            assert_eq!(unloading.first(), reloading.last(), "{what}");
                        }
                    }
                }
            }
        }
    }
}
