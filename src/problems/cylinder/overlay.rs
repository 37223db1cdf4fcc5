//! The points `n` draws on the cylinder's charts (`plot --fe`): its independent discretized
//! solver ([`CylinderFe`]: point forces on a uniform grid over the Hertz contact, a Jenkins
//! element at every node, the load in increments with every node's history; it never reads the
//! closed forms or the semi-analytic solution), at the current K_T, on every chart:
//!
//! - s(a) vs Q and c/a vs Q/mu P: one model loaded monotonically through the points' loads;
//! - q(x) and s(x): the nodes' shear and slip at the current Q;
//! - the loop: the model driven round +Q -> -Q -> +Q, its own histories, no Masing rule;
//! - D vs Q_a/mu P: one model per amplitude, its nodes' friction work over a whole cycle.
//!
//! A point whose increment does not converge is a gap (the legend says where, the TUI's status
//! why); a load the solver refuses (|Q| at mu P, where the contact's position is undetermined)
//! is an error, which the TUI shows.

use super::chart::CylinderChart;
use super::closed_form::{Cylinder, TangentialLoad};
use super::discretized::{CylinderFe, FeLoop, MAX_CELLS, MIN_CELLS};
use crate::chart::load::fe_loop;
use crate::chart::{NumericPoints, OVERLAY_POINTS, PointFailure};
use crate::kernel::format::number;
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
            Ok((x, fe.edge_slip()))
        }),
        CylinderChart::Zone => gaps(ratios, ratio("Q / mu P"), |r| {
            fe.load_to(r * gross, STEPS)?;
            Ok((r, fe.holding_half_width() / a))
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
        CylinderChart::Dissipation => gaps(ratios, ratio("Q_a / mu P"), |r| {
            let cycle = FeLoop::run(params, Law::Regularized, cells, r * gross, CYCLE_STEPS)?;
            Ok((r, cycle.friction_work))
        }),
    }
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
/// an increment that does not converge leaving a gap; the first other error, or the last failure
/// when no point was solved, is the answer.
fn gaps(
    xs: impl Iterator<Item = f64>,
    at: impl Fn(f64) -> String,
    mut solve: impl FnMut(f64) -> Result<(f64, f64), NumericError>,
) -> Result<Option<NumericPoints>, NumericError> {
    let mut points = Vec::with_capacity(OVERLAY_POINTS);
    let (mut failed, mut first, mut last) = (0, None, None);
    for x in xs {
        match solve(x) {
            Ok(point) => points.push(point),
            Err(e @ NumericError::NoConvergence { .. }) => {
                failed += 1;
                first.get_or_insert_with(|| PointFailure {
                    at: at(x),
                    why: e.to_string(),
                });
                last = Some(e);
            }
            Err(e) => return Err(e),
        }
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
