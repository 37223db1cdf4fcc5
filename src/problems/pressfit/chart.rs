//! The press fit's charts as data, pushed out or twisted: Delta vs F (theta vs T) with Coulomb
//! and the K_T family, the sliding zones from each face vs the load, tau(x), s(x), the loop and D
//! vs the amplitude, with the discretized solver's points and, for the push-out, the
//! axisymmetric continuum's points (the problem's [`ChartFace`]). The curves are the
//! shear lag's, shared with the lap joint
//! ([`crate::chart::shear_lag`]); this file gives the fit's words and numbers.

use std::marker::PhantomData;

use super::closed_form::PressFit;
use super::continuum::{PressFitContinuumMesh, solve_pressfit_continuum_path};
use super::discretized::PressFitFe;
use super::registered::problem::{FitKind, FitProblem, PressFitModel, PushOut, Twist};
use super::registered::profiles::slip_along;
use crate::chart::load::LoadLabels;
use crate::chart::shear_lag::{
    self, ShearLagCharts, ShearLagContinuumPoint, ShearLagFe, ShearLagView,
};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, OVERLAY_POINTS, Plot};
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Param;
use crate::problems::problem::Registered;
use crate::problems::profiled::LawProfiles;

/// The charts of one kind of fit, in the order the TUI cycles through them, each one of the
/// shear lag's six (`ShearLagView`): the response against the load for K_T/5, K_T, 5 K_T and
/// Coulomb; the sliding zones from the loaded face x = 0 and from the held face x = L against
/// the load, outside the outline of the holding zone, both laws; the interface shear tau(x) and
/// slip s(x) along the fit at the load; the hysteresis loop of a load cycling between +F and -F
/// (+T and -T); the dissipation per cycle D against the amplitude.
///
/// Why one type over the kind ([`FitKind`]) and not an enum per kind: the push-out's and the
/// torque's charts are the same curves of the same shear lag; only their titles and keys (which
/// must differ over the problems) are the kind's (`FitCharts::CHARTS`).
pub struct FitChart<K> {
    view: ShearLagView,
    kind: PhantomData<fn() -> K>,
}

/// The push-out's charts: Delta vs F, the zones vs F, tau(x), s(x), the loop, D vs F_a.
pub type PressFitChart = FitChart<PushOut>;

/// The shear lag's charts in [`FitCharts::CHARTS`]'s order.
const VIEWS: [ShearLagView; 6] = [
    ShearLagView::Response,
    ShearLagView::Zones,
    ShearLagView::Shear,
    ShearLagView::Slip,
    ShearLagView::Loop,
    ShearLagView::Dissipation,
];

impl<K> FitChart<K> {
    const fn of(view: ShearLagView) -> Self {
        FitChart {
            view,
            kind: PhantomData,
        }
    }

    /// Its place in [`VIEWS`].
    fn index(self) -> usize {
        VIEWS.iter().position(|&v| v == self.view).unwrap_or(0)
    }
}

// By hand, not derived: a derive would ask the kind to be `Clone`, `Hash`... itself.
impl<K> Clone for FitChart<K> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<K> Copy for FitChart<K> {}
impl<K> PartialEq for FitChart<K> {
    fn eq(&self, other: &Self) -> bool {
        self.view == other.view
    }
}
impl<K> Eq for FitChart<K> {}
impl<K> std::hash::Hash for FitChart<K> {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.view.hash(state);
    }
}
impl<K> std::fmt::Debug for FitChart<K> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "FitChart({:?})", self.view)
    }
}

/// What the charts of one kind of fit say and draw beside the shear lag's curves.
pub(crate) trait FitCharts: FitKind {
    /// Each chart's (title, key) in [`VIEWS`]' order; the keys are unique over every problem.
    const CHARTS: [(&'static str, &'static str); 6];
    /// Its load charts' words.
    const LABELS: LoadLabels;
    /// The continuum's states along the monotonic path through `loads`; empty where the kind has
    /// none.
    ///
    /// # Errors
    /// As the continuum's solver.
    fn continuum_path(
        fit: &PressFit,
        loads: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError>;
}

impl<K: FitCharts> ChartSet for FitChart<K> {
    const ALL: &'static [Self] = &[
        Self::of(ShearLagView::Response),
        Self::of(ShearLagView::Zones),
        Self::of(ShearLagView::Shear),
        Self::of(ShearLagView::Slip),
        Self::of(ShearLagView::Loop),
        Self::of(ShearLagView::Dissipation),
    ];

    fn title(self) -> &'static str {
        K::CHARTS[self.index()].0
    }

    fn key(self) -> &'static str {
        K::CHARTS[self.index()].1
    }

    fn x_param(self) -> Option<Param> {
        matches!(self.view, ShearLagView::Response | ShearLagView::Zones).then_some(K::LOAD_PARAM)
    }

    fn load_axis(self) -> bool {
        matches!(
            self.view,
            ShearLagView::Response | ShearLagView::Zones | ShearLagView::Dissipation
        )
    }

    fn spans_decades(self) -> bool {
        self.view == ShearLagView::Dissipation
    }
}

impl<K: FitCharts> ChartFace for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    type Chart = FitChart<K>;
    const NUMERIC_NAME: &'static str = "1-D finite elements";

    fn plot(
        model: &PressFitModel,
        chart: FitChart<K>,
        _f_data: f64,
        span: Option<f64>,
    ) -> Option<Plot> {
        shear_lag::plot::<Self>(&model.fit, model.force, chart.view, span)
    }

    fn numeric_points(
        model: &PressFitModel,
        chart: FitChart<K>,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        shear_lag::numeric_points::<Self>(
            &model.fit,
            model.force,
            chart.view,
            density,
            OVERLAY_POINTS,
        )
    }
}

/// The fit's numbers for the shear lag's charts, under either load. Its discretized solver is
/// [`PressFitFe`] (two bars of 1-D elements with Jenkins points between them, which never calls
/// the closed forms).
impl<K: FitCharts> ShearLagCharts for FitProblem<K>
where
    FitProblem<K>: Registered,
{
    const LABELS: LoadLabels = K::LABELS;
    type Fe = PressFitFe;

    fn length(fit: &PressFit) -> f64 {
        fit.params().length
    }

    fn first_slip_force(fit: &PressFit) -> f64 {
        fit.axis(K::LOAD).first_slip_load()
    }

    fn strength(fit: &PressFit) -> (&'static str, f64) {
        ("mu p", fit.params().friction * fit.contact_pressure())
    }

    fn saturation(fit: &PressFit) -> (&'static str, f64) {
        let p = fit.params();
        (
            "mu p / K_T",
            p.friction * fit.contact_pressure() / p.tangential_stiffness,
        )
    }

    fn slip_along(model: &PressFitModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        slip_along(model.fit.axis(K::LOAD), model.force, positions)
    }

    fn discretized(fit: &PressFit, density: MeshDensity) -> PressFitFe {
        PressFitFe::new(fit.params(), K::LOAD, density)
    }

    fn continuum_path(
        fit: &PressFit,
        loads: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError> {
        K::continuum_path(fit, loads)
    }
}

impl FitCharts for PushOut {
    const CHARTS: [(&'static str, &'static str); 6] = [
        ("Delta vs F", "fit-delta-vs-f"),
        ("zones vs F", "fit-zones-vs-f"),
        ("tau(x) at F", "fit-tau"),
        ("s(x) at F", "fit-slip"),
        ("loop +-F", "fit-loop"),
        ("D vs F_a", "fit-d-vs-fa"),
    ];
    const LABELS: LoadLabels = LoadLabels {
        response: "Delta",
        response_axis: "Delta (mm)",
        loop_title: ("", "D"),
        dissipation_axis: "D (N mm)",
    };

    /// The axisymmetric continuum ([`solve_pressfit_continuum_path`], docs/theory.md (S10)):
    /// shaft and hub as ring bodies, Lamé's p not assumed; its zones as the 1-D theory reads
    /// them (K_T |s| >= mu p).
    fn continuum_path(
        fit: &PressFit,
        forces: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError> {
        let states =
            solve_pressfit_continuum_path(fit.params(), forces, PressFitContinuumMesh::default())?;
        Ok(states
            .into_iter()
            .map(|c| ShearLagContinuumPoint {
                force: c.force,
                response: c.delta,
                zones: (
                    c.nominal_zones.from_loaded_face,
                    c.nominal_zones.from_held_face,
                ),
                shear: c.shear,
                slip: c.slip,
            })
            .collect())
    }
}

impl ShearLagFe for PressFitFe {
    fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError> {
        PressFitFe::load_to(self, force, steps)
    }

    fn response(&self) -> f64 {
        PressFitFe::response(self)
    }

    fn zones(&self) -> (f64, f64) {
        self.sliding_zones()
    }

    fn shear_at(&self, x: f64) -> f64 {
        (**self).shear_at(x)
    }

    fn slip_at(&self, x: f64) -> f64 {
        (**self).slip_at(x)
    }
}

/// The torque's charts: theta against T, the zones against T, the profiles at T, the loop
/// and D against T_a; the shear lag's numbers under the torque (no continuum: none is
/// torsional).
impl FitCharts for Twist {
    const CHARTS: [(&'static str, &'static str); 6] = [
        ("theta vs T", "fit-theta-vs-t"),
        ("zones vs T", "fit-zones-vs-t"),
        ("tau(x) at T", "fit-tau-torque"),
        ("s(x) at T", "fit-slip-torque"),
        ("loop +-T", "fit-loop-torque"),
        ("D vs T_a", "fit-d-vs-ta"),
    ];
    const LABELS: LoadLabels = LoadLabels {
        response: "theta",
        response_axis: "theta (rad)",
        loop_title: ("", "D"),
        dissipation_axis: "D (N mm)",
    };

    fn continuum_path(
        _fit: &PressFit,
        _torques: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError> {
        Ok(Vec::new())
    }
}
