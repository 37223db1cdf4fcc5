//! The points `n` draws on the cylinder's charts (`plot --fe`): its independent discretized
//! solver ([`CylinderFe`]: point forces on a uniform grid over the Hertz contact, a Jenkins
//! element at every node, the load in increments with every node's history; it never reads the
//! closed forms or the semi-analytic solution), at the current K_T, on every chart:
//!
//! - s(a) vs Q and c/a vs Q/mu P: one model loaded monotonically through the points' loads;
//! - q(x) and s(x): the nodes' shear and slip at the current Q;
//! - the loop: the model driven round +Q -> -Q -> +Q, its own histories, no Masing rule;
//! - D vs Q_a/mu P: one model per amplitude, on [`D_REFINEMENT`] times the cells, its nodes'
//!   friction work over a whole cycle after first loading.
//!
//! A point whose increment does not converge is a gap (the legend says where, the TUI's status
//! why), and so is a D point whose slide layers the grid does not resolve: the regularized law
//! slides over a layer at each edge whose width goes as (Q_a / mu P)^2 (docs/theory.md (HC9)),
//! and a uniform grid with fewer than [`MIN_SLIDING_CELLS`] cells in it misses most of the work
//! done there (measured at K_T = 1e4 and 1e5 MPa/mm: 0 instead of D with under one cell, +32 %
//! with 1.6 cells, 3 % with 4, 0.4 % to 0.8 % with 6.5 to 8). A load the solver refuses (|Q| at
//! mu P, where the contact's position is undetermined) is an error, which the TUI shows.

use super::chart::CylinderChart;
use super::closed_form::{Cylinder, TangentialLoad};
use super::discretized::{CylinderFe, MAX_CELLS, MIN_CELLS};
use crate::chart::load::fe_loop;
use crate::chart::{NumericPoints, OVERLAY_POINTS, PointFailure};
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::numeric::{MeshDensity, NumericError};

/// The highest load of the curves against Q (as Q / mu P): the charts' own end, below gross
/// slip, where the solver stops.
const TOP_RATIO: f64 = 0.98;

/// Increments per point of a monotone curve and per eighth of a loop's branch.
const STEPS: usize = 2;

/// Increments per branch of each cycle of the D points; D (the nodes' friction work) does not
/// depend on them (the discretized solver's tests).
const CYCLE_STEPS: usize = 4;

/// Points of q(x) and s(x) at most: about one per two columns of an 80-column chart.
const PROFILE_POINTS: usize = 40;

/// How many times the overlay's cells the D points are solved on: the slide layers are thin
/// (400 cells by default: some 30 ms per cycle).
const D_REFINEMENT: usize = 4;

/// Fewest cells of the grid inside each edge's slide layer (a - c on first loading, as the
/// discretized solver itself finds it) for a D point to be drawn (module docs).
const MIN_SLIDING_CELLS: f64 = 5.0;

/// The discretized solver's points for `chart` of `cylinder` at `load`, on `density`'s element
/// count as cells (within [`MIN_CELLS`], [`MAX_CELLS`]).
///
/// # Errors
/// The solver's: a load at mu P, or no point of a curve solved.
pub(super) fn numeric_points(
    cylinder: &Cylinder,
    load: TangentialLoad,
    chart: CylinderChart,
    density: MeshDensity,
) -> Result<Option<NumericPoints>, NumericError> {
    let params = cylinder.params();
    let cells = density.elements.clamp(MIN_CELLS, MAX_CELLS);
    let gross = cylinder.gross_slip_load();
    let a = cylinder.half_width();
    let q = load.newtons_per_mm();
    let ratios = (1..=OVERLAY_POINTS).map(|i| TOP_RATIO * i as f64 / OVERLAY_POINTS as f64);
    let mut fe = CylinderFe::new(params, Law::Regularized, cells)?;
    match chart {
        CylinderChart::EdgeSlip => gaps(ratios.map(|r| r * gross), per_mm("Q"), |x| {
            fe.load_to(x, STEPS)?;
            Ok(Point::Solved(x, fe.edge_slip()))
        }),
        CylinderChart::Zone => gaps(ratios, ratio("Q / mu P"), |r| {
            fe.load_to(r * gross, STEPS)?;
            Ok(Point::Solved(r, fe.holding_half_width() / a))
        }),
        CylinderChart::Shear | CylinderChart::Slip => {
            fe.load_to(q, 2 * STEPS)?;
            let profile = if chart == CylinderChart::Shear {
                fe.shear_profile()
            } else {
                fe.slip_profile()
            };
            let stride = profile.len().div_ceil(PROFILE_POINTS).max(1);
            Ok(Some(solved(profile.into_iter().step_by(stride).collect())))
        }
        CylinderChart::Loop => {
            fe.load_to(q, 2 * STEPS)?;
            let points = fe_loop(q, OVERLAY_POINTS, |x| {
                fe.load_to(x, STEPS)?;
                Ok(fe.edge_slip())
            })?;
            Ok(Some(solved(points)))
        }
        CylinderChart::Dissipation => {
            let fine = (D_REFINEMENT * cells).min(MAX_CELLS);
            let cell = 2.0 * a / fine as f64;
            gaps(ratios, ratio("Q_a / mu P"), |r| {
                let amplitude = r * gross;
                let mut fe = CylinderFe::new(params, Law::Regularized, fine)?;
                fe.load_to(amplitude, 2 * CYCLE_STEPS)?;
                let layer = a - fe.holding_half_width();
                if layer < MIN_SLIDING_CELLS * cell {
                    return Ok(Point::Gap(format!(
                        "the slide layer at each edge, {} mm, spans {} of the solver's {fine} \
                         cells, fewer than {MIN_SLIDING_CELLS}: D is not resolved",
                        number(layer),
                        number_with(layer / cell, 2)
                    )));
                }
                let first_loading = fe.friction_work();
                fe.load_to(-amplitude, 2 * CYCLE_STEPS)?;
                fe.load_to(amplitude, 2 * CYCLE_STEPS)?;
                Ok(Point::Solved(r, fe.friction_work() - first_loading))
            })
        }
    }
}

/// What one point of a curve came to: solved, or a gap and why.
enum Point {
    Solved(f64, f64),
    Gap(String),
}

/// Points every one of which was solved.
fn solved(points: Vec<(f64, f64)>) -> NumericPoints {
    NumericPoints {
        points,
        continuum: Vec::new(),
        failed: 0,
        failure: None,
    }
}

/// A load x in words, with its unit: `Q = 120 N/mm`.
fn per_mm(symbol: &'static str) -> impl Fn(f64) -> String {
    move |x| format!("{symbol} = {} N/mm", number(x))
}

/// A load ratio x in words: `Q / mu P = 0.49`.
fn ratio(symbol: &'static str) -> impl Fn(f64) -> String {
    move |x| format!("{symbol} = {}", number(x))
}

/// The points `solve` gives at each of `xs` (`at` names x in a failure's place, with its unit),
/// a gap where it says so or an increment does not converge; the first other error, or the last
/// failure to converge when no point was solved, is the answer.
fn gaps(
    xs: impl Iterator<Item = f64>,
    at: impl Fn(f64) -> String,
    mut solve: impl FnMut(f64) -> Result<Point, NumericError>,
) -> Result<Option<NumericPoints>, NumericError> {
    let mut points = Vec::with_capacity(OVERLAY_POINTS);
    let (mut failed, mut first, mut last) = (0, None, None);
    for x in xs {
        let why = match solve(x) {
            Ok(Point::Solved(x, y)) => {
                points.push((x, y));
                continue;
            }
            Ok(Point::Gap(why)) => why,
            Err(e @ NumericError::NoConvergence { .. }) => {
                let why = e.to_string();
                last = Some(e);
                why
            }
            Err(e) => return Err(e),
        };
        failed += 1;
        first.get_or_insert_with(|| PointFailure { at: at(x), why });
    }
    match last {
        Some(e) if points.is_empty() => Err(e),
        _ => Ok(Some(NumericPoints {
            points,
            continuum: Vec::new(),
            failed,
            failure: first,
        })),
    }
}

#[cfg(test)]
mod tests {
    use super::super::closed_form::CylinderParams;
    use super::super::problem::{CylinderModel, CylinderProblem};
    use super::*;
    use crate::chart::Plot;
    use crate::chart::view::ChartFace;

    /// The bundled steel pad (a = 0.7428 mm, E* = 115385 MPa, mu P = 600 N/mm) with K_T = `kt`
    /// MPa/mm (kappa = K_T a / E* = 0.0644, 0.644, 6.44 at 1e4, 1e5, 1e6), at Q = 300 N/mm.
    fn pad(kt: f64) -> CylinderModel {
        let cylinder = Cylinder::new(CylinderParams {
            tangential_stiffness: kt,
            ..CylinderParams::STEEL_PAD
        })
        .unwrap();
        let load = cylinder.load(300.0).unwrap();
        CylinderModel { cylinder, load }
    }

    fn discretized(model: &CylinderModel, chart: CylinderChart) -> NumericPoints {
        numeric_points(
            &model.cylinder,
            model.load,
            chart,
            MeshDensity::with_elements(100),
        )
        .unwrap()
        .unwrap()
    }

    fn plot(model: &CylinderModel, chart: CylinderChart) -> Plot {
        <CylinderProblem as ChartFace>::plot(model, chart, 0.0, None).unwrap()
    }

    /// The drawn series `name` of `plot`.
    fn series<'a>(plot: &'a Plot, name: &str) -> &'a [(f64, f64)] {
        let found = plot.series.iter().find(|s| s.name == name);
        &found
            .unwrap_or_else(|| panic!("no {name} in {}", plot.title))
            .points
    }

    /// The drawn y at `x` of `points` (a sample of the curve sits at every discretized point's
    /// x: the overlay's loads are every fifth of the charts' 41).
    fn drawn_at(points: &[(f64, f64)], x: f64) -> f64 {
        let scale = points.iter().fold(1e-300_f64, |m, p| m.max(p.0.abs()));
        points
            .iter()
            .find(|p| (p.0 - x).abs() <= 1e-9 * scale)
            .unwrap_or_else(|| panic!("no sample at {x}"))
            .1
    }

    /// The largest |discretized - drawn| over `scale` of the points against the drawn curve.
    fn worst(found: &[(f64, f64)], curve: &[(f64, f64)], scale: f64) -> f64 {
        found
            .iter()
            .map(|&(x, y)| (y - drawn_at(curve, x)).abs() / scale)
            .fold(0.0, f64::max)
    }

    /// What `n` draws agrees with the drawn semi-analytic curves to the discretized solver's
    /// error on 100 cells, at three decades of K_T: s(a) vs Q within 1e-3 of the largest s(a)
    /// (measured 2e-4 to 5.4e-4), c/a within 5e-3 (1.0e-3 to 2.5e-3; the zone's edge moves
    /// within a cell), the loop of s(a) within 6e-3 of its peak (8e-4 to 3.4e-3: the solver's own
    /// histories round a real reversal, no Masing rule). Planted fault caught: the overlay's
    /// loop reading the centre slip s(0) instead of s(a).
    #[test]
    fn the_discretized_points_sit_on_the_drawn_curves() {
        for kt in [1e4, 1e5, 1e6] {
            let model = pad(kt);
            let edge = discretized(&model, CylinderChart::EdgeSlip).points;
            let drawn = plot(&model, CylinderChart::EdgeSlip);
            let top = drawn_at(series(&drawn, "regularized"), edge[edge.len() - 1].0);
            let error = worst(&edge, series(&drawn, "regularized"), top);
            assert!(error < 1e-3, "K_T {kt}: s(a) {error}");
            let zone = discretized(&model, CylinderChart::Zone).points;
            let error = worst(
                &zone,
                series(&plot(&model, CylinderChart::Zone), "K_T"),
                1.0,
            );
            assert!(error < 5e-3, "K_T {kt}: c/a {error}");
            let drawn = plot(&model, CylinderChart::Loop);
            let fe = discretized(&model, CylinderChart::Loop).points;
            let (unloading, reloading) = series(&drawn, "regularized").split_at(FEW_POINTS);
            let peak = unloading[0].1;
            let (fe_unloading, fe_reloading) = fe.split_at(OVERLAY_POINTS);
            let error =
                worst(fe_unloading, unloading, peak).max(worst(fe_reloading, reloading, peak));
            assert!(error < 6e-3, "K_T {kt}: loop {error}");
        }
    }

    /// The points of a chart's curves per branch of the loop (`chart.rs`'s FEW).
    const FEW_POINTS: usize = 41;

    /// q(x) and s(x) at Q: the solver's nodes against the semi-analytic state within 1.5e-2 of
    /// mu p0 (measured 8.1e-3, at the edge cells, where mu p(x) falls as a square root) and
    /// 1e-3 of s(a) (2.8e-4 to 5.5e-4).
    #[test]
    fn the_discretized_profiles_sit_on_the_semi_analytic_ones() {
        for kt in [1e4, 1e5, 1e6] {
            let model = pad(kt);
            let state = model.cylinder.regularized(model.load);
            let strength = 0.6 * model.cylinder.peak_pressure();
            let shear = discretized(&model, CylinderChart::Shear).points;
            assert!(shear.len() >= 30, "{}", shear.len());
            let error = shear
                .iter()
                .map(|&(x, q)| (q - state.shear_at(x)).abs() / strength)
                .fold(0.0, f64::max);
            assert!(error < 1.5e-2, "K_T {kt}: q {error}");
            let slip = discretized(&model, CylinderChart::Slip).points;
            let error = slip
                .iter()
                .map(|&(x, s)| (s - state.slip_at(x)).abs() / state.edge_slip())
                .fold(0.0, f64::max);
            assert!(error < 1e-3, "K_T {kt}: s {error}");
        }
    }

    /// One cycle +-`amplitude` (N/mm) of the discretized solver on 400 cells under `law`: its
    /// nodes' friction work after first loading (N mm per mm).
    fn cycle_work(model: &CylinderModel, law: Law, amplitude: f64) -> f64 {
        let mut fe = CylinderFe::new(model.cylinder.params(), law, 400).unwrap();
        fe.load_to(amplitude, 8).unwrap();
        let first = fe.friction_work();
        fe.load_to(-amplitude, 8).unwrap();
        fe.load_to(amplitude, 8).unwrap();
        fe.friction_work() - first
    }

    /// D vs Q_a / mu P at K_T = 1e5 MPa/mm draws K_T/10, K_T and K_T*10: the discretized solver
    /// at 1e4, 1e5 and 1e6 MPa/mm lands on each within 2.5 % (measured 1.2e-2 at the smallest
    /// drawn amplitude, below 5e-3 elsewhere), and on Mindlin-Deresiewicz's curve under plain
    /// Coulomb within 2e-3 (8e-4). An amplitude whose slide layers span fewer than 5 cells is a
    /// gap that says so, never a point off the curve. Planted faults caught: the K_T/10 curve
    /// drawn at K_T/5; D counted with first loading's work (+1/4); the resolution guard removed
    /// (0 or +32 % at the small amplitudes).
    #[test]
    fn the_dissipation_chart_is_the_discretized_solver_s() {
        let model = pad(1e5);
        let drawn = plot(&model, CylinderChart::Dissipation);
        for (kt, name) in [(1e4, "K_T/10"), (1e5, "K_T"), (1e6, "K_T*10")] {
            let fe = discretized(&pad(kt), CylinderChart::Dissipation);
            assert!(fe.points.len() >= 6, "K_T {kt}: {fe:?}");
            if let Some(failure) = &fe.failure {
                assert!(failure.why.contains("D is not resolved"), "{failure:?}");
            }
            let error = fe
                .points
                .iter()
                .map(|&(r, d)| (d / drawn_at(series(&drawn, name), r) - 1.0).abs())
                .fold(0.0, f64::max);
            assert!(error < 2.5e-2, "{name}: {error}");
        }
        let mindlin = series(&drawn, "Mindlin-Deresiewicz");
        for r in [0.1225, 0.49, 0.98] {
            let d = cycle_work(&model, Law::Coulomb, r * 600.0);
            let error = (d / drawn_at(mindlin, r) - 1.0).abs();
            assert!(error < 2e-3, "Mindlin at {r}: {error}");
        }
    }

    /// The loop's title gives D of both laws (the area of the rigid shift's loop, not of the
    /// s(a) loop drawn): the discretized solver's friction work over the same cycle, +-300 N/mm,
    /// within the title's 3 digits.
    #[test]
    fn the_loop_s_title_gives_the_dissipation_per_cycle() {
        let model = pad(1e5);
        let title = plot(&model, CylinderChart::Loop).title;
        let words: Vec<&str> = title.split(' ').collect();
        let after = |tag: &str| -> f64 {
            let at = words
                .iter()
                .position(|w| w.trim_end_matches(',') == tag)
                .unwrap();
            words[at - 1].parse().unwrap()
        };
        let (mindlin, regularized) = (after("M"), after("R"));
        for (shown, law) in [(mindlin, Law::Coulomb), (regularized, Law::Regularized)] {
            let d = cycle_work(&model, law, 300.0);
            assert!((shown / d - 1.0).abs() < 5e-3, "{title}: {law:?} {d}");
        }
        assert!(title.starts_with("+-300 N/mm; D ") && title.ends_with(" R N mm/mm"));
        assert!(title.len() <= 41, "{title}");
    }
}
