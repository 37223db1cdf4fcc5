//! The double-lap joint's charts as data: Delta vs F with Coulomb and the K_T family, the sliding
//! zones vs F, tau(x), s(x), the loop and D vs F_a, with their finite-element and continuum
//! points (the problem's [`ChartFace`]). Built from [`crate::study::lap`].

use super::LapJointProblem;
use super::closed_form::LapJoint;
use super::problem::LapModel;
use super::profiles::slip_along;
use super::{LapContinuumMesh, LapFe, solve_lap_continuum_path};
use crate::chart::load::LoadLabels;
use crate::chart::shear_lag::{
    self, ShearLagCharts, ShearLagContinuumPoint, ShearLagFe, ShearLagView,
};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, OVERLAY_POINTS, Plot};
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::profiled::LawProfiles;
use crate::problems::{LapParam, Param};

/// The double-lap joint's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LapChart {
    /// Joint displacement Delta against F, for K_T/5, K_T, 5 K_T and Coulomb.
    Displacement,
    /// The zones against F: the sliding zones [0, a] and [L - d, L] outside the outline of the
    /// middle zone, for both laws.
    Zones,
    /// Interface shear tau(x) along the overlap at F.
    Shear,
    /// Interface slip s(x) = u_inner - u_cover along the overlap at F.
    Slip,
    /// The hysteresis loop of Delta for a force cycling between +F and -F.
    Loop,
    /// Dissipation per cycle D against the amplitude F_a.
    Dissipation,
}

impl ChartSet for LapChart {
    const ALL: &'static [Self] = &[
        LapChart::Displacement,
        LapChart::Zones,
        LapChart::Shear,
        LapChart::Slip,
        LapChart::Loop,
        LapChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            LapChart::Displacement => "Delta vs F",
            LapChart::Slip => "s(x) at F",
            LapChart::Zones => "zones vs F",
            LapChart::Shear => "tau(x) at F",
            LapChart::Loop => "loop +-F",
            LapChart::Dissipation => "D vs F_a",
        }
    }

    fn key(self) -> &'static str {
        match self {
            LapChart::Displacement => "delta-vs-f",
            LapChart::Zones => "zones-vs-f",
            LapChart::Shear => "lap-tau",
            LapChart::Slip => "lap-slip",
            LapChart::Loop => "lap-loop",
            LapChart::Dissipation => "lap-d-vs-fa",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            LapChart::Displacement | LapChart::Zones => Some(Param::Lap(LapParam::Force)),
            LapChart::Shear | LapChart::Slip | LapChart::Loop | LapChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        match self {
            LapChart::Displacement | LapChart::Zones | LapChart::Dissipation => true,
            LapChart::Shear | LapChart::Slip | LapChart::Loop => false,
        }
    }

    fn spans_decades(self) -> bool {
        match self {
            LapChart::Dissipation => true,
            LapChart::Displacement
            | LapChart::Zones
            | LapChart::Shear
            | LapChart::Slip
            | LapChart::Loop => false,
        }
    }
}

impl ChartFace for LapJointProblem {
    type Chart = LapChart;

    fn plot(model: &Self::Model, chart: LapChart, _f_data: f64, span: Option<f64>) -> Option<Plot> {
        shear_lag::plot::<Self>(&model.joint, model.force, chart.view(), span)
    }

    fn numeric_points(
        model: &Self::Model,
        chart: LapChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        shear_lag::numeric_points::<Self>(
            &model.joint,
            model.force,
            chart.view(),
            density,
            OVERLAY_POINTS,
        )
    }
}

impl LapChart {
    /// The shear-lag chart this one is.
    fn view(self) -> ShearLagView {
        match self {
            LapChart::Displacement => ShearLagView::Response,
            LapChart::Zones => ShearLagView::Zones,
            LapChart::Shear => ShearLagView::Shear,
            LapChart::Slip => ShearLagView::Slip,
            LapChart::Loop => ShearLagView::Loop,
            LapChart::Dissipation => ShearLagView::Dissipation,
        }
    }
}

/// The joint's charts are the shear lag's ([`crate::chart::shear_lag`]): its words, its numbers,
/// its discretized solver (`LapFe`, which never calls the closed forms) and, beside them, the 2-D
/// plane-stress continuum ([`solve_lap_continuum_path`], (L13)): the answer without the
/// shear-lag theory's assumptions, where its envelope (L14) says they fail.
impl ShearLagCharts for LapJointProblem {
    const LABELS: LoadLabels = LoadLabels {
        response: "Delta",
        response_axis: "Delta (mm)",
        loop_title: ("", "D"),
        dissipation_axis: "D (N mm)",
    };
    type Fe = LapFe;

    fn length(joint: &LapJoint) -> f64 {
        joint.params().length
    }

    fn first_slip_force(joint: &LapJoint) -> f64 {
        joint.first_slip_force()
    }

    fn strength(joint: &LapJoint) -> (&'static str, f64) {
        ("mu P", joint.coulomb_stress())
    }

    fn saturation(joint: &LapJoint) -> (&'static str, f64) {
        ("mu P / K_T", joint.saturation_slip())
    }

    fn slip_along(model: &LapModel, positions: impl Iterator<Item = f64>) -> LawProfiles {
        slip_along(model, positions)
    }

    fn discretized(joint: &LapJoint, density: MeshDensity) -> LapFe {
        LapFe::new(joint.params(), density)
    }

    fn continuum_path(
        joint: &LapJoint,
        forces: &[f64],
    ) -> Result<Vec<ShearLagContinuumPoint>, NumericError> {
        let states = solve_lap_continuum_path(joint.params(), forces, LapContinuumMesh::default())?;
        Ok(states
            .into_iter()
            .map(|c| ShearLagContinuumPoint {
                force: c.force,
                response: c.delta,
                zones: (
                    c.nominal_zones.from_inner_end,
                    c.nominal_zones.from_cover_ends,
                ),
                shear: c.shear,
                slip: c.slip,
            })
            .collect())
    }
}

impl ShearLagFe for LapFe {
    fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError> {
        LapFe::load_to(self, force, steps)
    }

    fn response(&self) -> f64 {
        self.joint_displacement()
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
