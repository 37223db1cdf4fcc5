//! The press fit's charts as data: Delta vs F with Coulomb and the K_T family, the sliding zones
//! from each face vs F, tau(x), s(x), the loop and D vs F_a, with the discretized solver's points
//! and the axisymmetric continuum's points (the problem's [`ChartFace`]). The curves are the
//! shear lag's, shared with the lap joint
//! ([`crate::chart::shear_lag`]); this file gives the fit's words and numbers.

use super::PressFitProblem;
use super::closed_form::PressFit;
use super::continuum::{PressFitContinuumMesh, solve_pressfit_continuum_path};
use super::discretized::PressFitFe;
use super::params::{FitLoad, PressFitParam};
use super::registered::problem::PressFitModel;
use super::registered::profiles::slip_along;
use crate::chart::load::LoadLabels;
use crate::chart::shear_lag::{
    self, ShearLagCharts, ShearLagContinuumPoint, ShearLagFe, ShearLagView, ZoneWords,
};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, OVERLAY_POINTS, Plot};
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Param;
use crate::problems::profiled::LawProfiles;

/// The press fit's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PressFitChart {
    /// Delta (the shaft's loaded end against the hub's held face) against F, for K_T/5, K_T,
    /// 5 K_T and Coulomb.
    Displacement,
    /// The sliding zones from the loaded face x = 0 and from the held face x = L against F,
    /// outside the outline of the holding zone, both laws.
    Zones,
    /// Interface shear tau(x) along the fit at F.
    Shear,
    /// Interface slip s(x) = u_shaft - u_hub along the fit at F.
    Slip,
    /// The hysteresis loop of Delta for a push cycling between +F and -F.
    Loop,
    /// Dissipation per cycle D against the amplitude F_a.
    Dissipation,
}

impl ChartSet for PressFitChart {
    const ALL: &'static [Self] = &[
        PressFitChart::Displacement,
        PressFitChart::Zones,
        PressFitChart::Shear,
        PressFitChart::Slip,
        PressFitChart::Loop,
        PressFitChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            PressFitChart::Displacement => "Delta vs F",
            PressFitChart::Zones => "zones vs F",
            PressFitChart::Shear => "tau(x) at F",
            PressFitChart::Slip => "s(x) at F",
            PressFitChart::Loop => "loop +-F",
            PressFitChart::Dissipation => "D vs F_a",
        }
    }

    fn key(self) -> &'static str {
        match self {
            PressFitChart::Displacement => "fit-delta-vs-f",
            PressFitChart::Zones => "fit-zones-vs-f",
            PressFitChart::Shear => "fit-tau",
            PressFitChart::Slip => "fit-slip",
            PressFitChart::Loop => "fit-loop",
            PressFitChart::Dissipation => "fit-d-vs-fa",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            PressFitChart::Displacement | PressFitChart::Zones => {
                Some(Param::PressFit(PressFitParam::Force))
            }
            PressFitChart::Shear
            | PressFitChart::Slip
            | PressFitChart::Loop
            | PressFitChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        match self {
            PressFitChart::Displacement | PressFitChart::Zones | PressFitChart::Dissipation => true,
            PressFitChart::Shear | PressFitChart::Slip | PressFitChart::Loop => false,
        }
    }

    fn spans_decades(self) -> bool {
        self == PressFitChart::Dissipation
    }
}

impl PressFitChart {
    /// The shear-lag chart this one is.
    fn view(self) -> ShearLagView {
        match self {
            PressFitChart::Displacement => ShearLagView::Response,
            PressFitChart::Zones => ShearLagView::Zones,
            PressFitChart::Shear => ShearLagView::Shear,
            PressFitChart::Slip => ShearLagView::Slip,
            PressFitChart::Loop => ShearLagView::Loop,
            PressFitChart::Dissipation => ShearLagView::Dissipation,
        }
    }
}

impl ChartFace for PressFitProblem {
    type Chart = PressFitChart;
    const NUMERIC_NAME: &'static str = "1-D finite elements";

    fn plot(
        model: &PressFitModel,
        chart: PressFitChart,
        _f_data: f64,
        span: Option<f64>,
    ) -> Option<Plot> {
        shear_lag::plot::<Self>(&model.fit, model.force, chart.view(), span)
    }

    fn numeric_points(
        model: &PressFitModel,
        chart: PressFitChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        shear_lag::numeric_points::<Self>(
            &model.fit,
            model.force,
            chart.view(),
            density,
            OVERLAY_POINTS,
        )
    }
}

/// The fit's words and numbers for the shear lag's charts. Its discretized solver is
/// [`PressFitFe`] (two bars of 1-D elements with Jenkins points between them, which never calls
/// the closed forms).
impl ShearLagCharts for PressFitProblem {
    const LABELS: LoadLabels = LoadLabels {
        response: "Delta",
        response_axis: "Delta (mm)",
        loop_title: ("", "D"),
        dissipation_axis: "D (N mm)",
    };
    const ZONES: ZoneWords = ZoneWords {
        series: "a, L-d",
        title: "zones: slide below a, above L-d; F_1 ",
        load_axis: "F (N)",
    };
    type Fe = PressFitFe;

    fn length(fit: &PressFit) -> f64 {
        fit.params().length
    }

    fn first_slip_force(fit: &PressFit) -> f64 {
        fit.first_slip_force()
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
        slip_along(model.fit.axial(), model.force, positions)
    }

    fn discretized(fit: &PressFit, density: MeshDensity) -> PressFitFe {
        PressFitFe::new(fit.params(), FitLoad::Axial, density)
    }

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
