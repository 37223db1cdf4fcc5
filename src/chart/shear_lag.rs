//! The charts of a problem of two members in shear lag through one interface (the lap joint, the
//! press fit), written once: the response against the load with Coulomb and the K_T family, the
//! sliding zones from each end against the load, the shear and the slip along the interface, the
//! loop and D against the amplitude; with the problem's discretized points (the two-bar solver,
//! which never calls the closed forms) and, where it has one, its continuum's.
//!
//! Why a layer of its own: both problems are the same shear lag (`kernel::shear_lag`,
//! `numeric::two_bar`) in other words and other members, so their charts are the same curves;
//! each problem gives only its words and its numbers ([`ShearLagCharts`]), and its chart enum
//! (whose keys must differ) maps onto [`ShearLagView`].

use crate::chart::load::{
    LoadLabels, dissipation_chart, fe_loop, load_words, loop_chart, profile_plot, response_plot,
};
use crate::chart::{NumericPoints, Plot, SeriesRole, cursor, line, linear_axis, samples};
use crate::kernel::format::number_with;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::load_driven::LoadDriven;
use crate::problems::profiled::{LawProfiles, Profiled};
use crate::study::curves;
use crate::study::curves::Spacing;

/// The six charts of a shear-lag problem, whatever the problem calls them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum ShearLagView {
    /// The response (Delta) against the load, for K_T/5, K_T, 5 K_T and Coulomb.
    Response,
    /// The sliding zones from each end against the load, both laws.
    Zones,
    /// Interface shear along the interface at the load.
    Shear,
    /// Interface slip along the interface at the load.
    Slip,
    /// The hysteresis loop of the response for a load cycling between +F and -F.
    Loop,
    /// Dissipation per cycle against the amplitude.
    Dissipation,
}

/// One continuum state along a load path, in the charts' terms.
#[derive(Debug, Clone, Default)]
pub(crate) struct ShearLagContinuumPoint {
    /// The load (N).
    pub force: f64,
    /// The response (mm).
    pub response: f64,
    /// The sliding zones from the loaded end (x = 0) and from x = L (mm).
    pub zones: (f64, f64),
    /// Shear along the interface (x mm, MPa).
    pub shear: Vec<(f64, f64)>,
    /// Slip along the interface (x mm, mm).
    pub slip: Vec<(f64, f64)>,
}

/// The problem's discretized solver, as the charts drive it.
pub(crate) trait ShearLagFe {
    /// Loads monotonically to `force` (N) in `steps` increments.
    ///
    /// # Errors
    /// A load the solver cannot resolve.
    fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError>;
    /// The response (mm).
    fn response(&self) -> f64;
    /// The sliding zones from x = 0 and from x = L (mm).
    fn zones(&self) -> (f64, f64);
    /// Shear at `x` (MPa).
    fn shear_at(&self, x: f64) -> f64;
    /// Slip at `x` (mm).
    fn slip_at(&self, x: f64) -> f64;
}

/// A shear-lag problem's words and numbers for its charts.
pub(crate) trait ShearLagCharts: LoadDriven + Profiled {
    /// Its load charts' words.
    const LABELS: LoadLabels;
    /// Its discretized solver.
    type Fe: ShearLagFe;

    /// The interface's length L (mm).
    fn length(structure: &Self::Structure) -> f64;
    /// F_1 (N).
    fn first_slip_force(structure: &Self::Structure) -> f64;
    /// The friction stress's name and value (MPa): the shear chart's limit line.
    fn strength(structure: &Self::Structure) -> (&'static str, f64);
    /// The saturation slip's name and value (mm): the slip chart's limit line.
    fn saturation(structure: &Self::Structure) -> (&'static str, f64);
    /// Slip along the interface at each of `positions`: (Coulomb, regularized).
    fn slip_along(model: &Self::Model, positions: impl Iterator<Item = f64>) -> LawProfiles;
    /// The discretized solver of `structure` at `density`.
    fn discretized(structure: &Self::Structure, density: MeshDensity) -> Self::Fe;
    /// The continuum's states along the monotonic path through `forces`; empty where the problem
    /// has none, an error where it refuses the structure (a gap on the chart, not an error).
    ///
    /// # Errors
    /// As the continuum's solver.
    fn continuum_path(
        structure: &Self::Structure,
        forces: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError>;
}

/// The name of the load where sliding first appears (`F_1`, the twisted fit's `T_1`), from the
/// problem's quantities.
fn first_slip_name<P: ShearLagCharts>() -> &'static str {
    P::INFO
        .quantities
        .iter()
        .find(|q| q.quantity == crate::problems::Quantity::FirstMacroslipForce)
        .map_or("F_1", |q| q.name)
}

/// The load axis: the whole range the structure carries, 0 to the gross-slip load, or `span`
/// when a family asks for a wider one (never beyond it: there is no state there).
fn force_range<P: LoadDriven>(structure: &P::Structure, span: Option<f64>) -> f64 {
    let gross = P::force_scale(structure);
    span.map_or(gross, |s| s.min(gross)).max(f64::MIN_POSITIVE)
}

/// The chart `view` of `structure` at `force`.
pub(crate) fn plot<P: ShearLagCharts>(
    structure: &P::Structure,
    force: P::Force,
    view: ShearLagView,
    span: Option<f64>,
) -> Option<Plot> {
    let f_max = force_range::<P>(structure, span);
    let forces = samples(0.0, f_max, Spacing::Linear)?;
    let kt = P::tangential_stiffness(structure);
    let f = P::load_value(force);
    let length = P::length(structure);
    let model = P::at_force(structure, force);
    match view {
        ShearLagView::Response => response_plot::<P>(structure, &P::LABELS, forces, (f, f_max)),
        ShearLagView::Zones => {
            let (coulomb, regularized) =
                curves::zone_outline_vs_force::<P>(structure, forces).ok()?;
            let (load, unit) = load_words::<P>();
            let series = vec![
                line(SeriesRole::Coulomb, "Coulomb: a, L-d", coulomb),
                line(SeriesRole::Current, "regularized: a, L-d", regularized),
                cursor(f, [0.0, length]),
            ];
            Some(Plot {
                caption: None,
                // At most 41 characters (the title row of an 80x24 screen's chart pane).
                title: format!(
                    "zones: slide below a, above L-d; {} {} {unit}",
                    first_slip_name::<P>(),
                    number_with(P::first_slip_force(structure), 4),
                ),
                x: linear_axis(format!("{load} ({unit})"), 0.0, f_max),
                y: linear_axis("x (mm)", 0.0, length),
                series,
            })
        }
        ShearLagView::Shear => {
            let positions = samples(0.0, length, Spacing::Linear)?;
            Some(profile_plot(
                ("tau(x)", "tau (MPa)"),
                (f, kt),
                load_words::<P>(),
                length,
                curves::shear_along_of::<P>(&model, positions),
                P::strength(structure),
            ))
        }
        ShearLagView::Slip => {
            let positions = samples(0.0, length, Spacing::Linear)?;
            Some(profile_plot(
                ("s(x)", "s (mm)"),
                (f, kt),
                load_words::<P>(),
                length,
                P::slip_along(&model, positions.values()),
                P::saturation(structure),
            ))
        }
        ShearLagView::Loop => loop_chart::<P>(structure, &P::LABELS, force),
        ShearLagView::Dissipation => {
            let amplitudes = samples(0.0, f_max, Spacing::Linear)?;
            dissipation_chart::<P>(structure, &P::LABELS, force, amplitudes, f_max)
        }
    }
}

/// The project's finite-element points for the chart `view`: the discretized solver loaded
/// monotonically through the chart's forces, round the same cycle as the loop, or to the current
/// force for the profiles; None for D against the amplitude (a closed-form integral of the loop).
/// Beside them, on the response, the zones and the profiles, the problem's continuum: the answer
/// without the shear-lag theory's assumptions. Where the continuum refuses the structure its
/// series is empty: a gap, not an error.
pub(crate) fn numeric_points<P: ShearLagCharts>(
    structure: &P::Structure,
    force: P::Force,
    view: ShearLagView,
    density: MeshDensity,
    count: usize,
) -> Result<Option<NumericPoints>, NumericError> {
    let with_continuum = |points: Vec<(f64, f64)>, continuum: Vec<(f64, f64)>| {
        Ok(Some(NumericPoints {
            points,
            continuum,
            failed: 0,
            failure: None,
        }))
    };
    let mut fe = P::discretized(structure, density);
    let length = P::length(structure);
    let gross = P::force_scale(structure);
    match view {
        ShearLagView::Response | ShearLagView::Zones => {
            // Up to just below the gross-slip load, where the solver (and the structure) stops.
            let top = 0.98 * force_range::<P>(structure, None);
            let forces: Vec<f64> = (1..=count).map(|i| top * i as f64 / count as f64).collect();
            let mut found = Vec::with_capacity(2 * count);
            for &f in &forces {
                fe.load_to(f, 2)?;
                if view == ShearLagView::Response {
                    found.push((f, fe.response()));
                } else {
                    let (a, d) = fe.zones();
                    found.extend([(f, a), (f, length - d)]);
                }
            }
            let continuum = P::continuum_path(structure, &forces).map_or_else(
                |_| Vec::new(),
                |states| {
                    states
                        .iter()
                        .flat_map(|c| {
                            if view == ShearLagView::Response {
                                vec![(c.force, c.response)]
                            } else {
                                vec![(c.force, c.zones.0), (c.force, length - c.zones.1)]
                            }
                        })
                        .collect()
                },
            );
            with_continuum(found, continuum)
        }
        ShearLagView::Shear | ShearLagView::Slip => {
            let at = P::load_value(force).min(0.98 * gross);
            fe.load_to(at, 4)?;
            let continuum = P::continuum_path(structure, &[at]).map_or_else(
                |_| Vec::new(),
                |mut states| match states.pop() {
                    Some(state) if view == ShearLagView::Shear => state.shear,
                    Some(state) => state.slip,
                    None => Vec::new(),
                },
            );
            with_continuum(
                (0..=40)
                    .map(|i| {
                        let x = length * f64::from(i) / 40.0;
                        let y = if view == ShearLagView::Shear {
                            fe.shear_at(x)
                        } else {
                            fe.slip_at(x)
                        };
                        (x, y)
                    })
                    .collect(),
                continuum,
            )
        }
        ShearLagView::Loop => {
            // Its own slider histories round a real reversal, no Masing rule.
            let fa = P::load_value(force).min(0.98 * gross);
            fe.load_to(fa, 4)?;
            with_continuum(
                fe_loop(fa, count, |f| {
                    fe.load_to(f, 2)?;
                    Ok(fe.response())
                })?,
                Vec::new(),
            )
        }
        ShearLagView::Dissipation => Ok(None),
    }
}
