//! The double-lap joint's charts as data: Delta vs F with Coulomb and the K_T family, the sliding
//! zones vs F, tau(x), s(x), the loop and D vs F_a, with their finite-element and continuum
//! points (the problem's [`ChartFace`]). Built from [`crate::study::lap`].

use super::LapJointProblem;
use super::closed_form::{JointForce, LapJoint};
use super::problem::LapModel;
use super::profiles::slip_along;
use super::{LapContinuumMesh, LapFe, solve_lap_continuum_path};
use crate::chart::load::{
    LoadLabels, dissipation_chart, fe_loop, loop_chart, profile_plot, response_plot,
};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{
    NumericPoints, OVERLAY_POINTS, Plot, SeriesRole, cursor, line, linear_axis, samples,
};
use crate::kernel::format::number_with;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::{LapParam, Param};
use crate::study::curves;
use crate::study::curves::Spacing;

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
        lap_plot(&model.joint, model.force, chart, span)
    }

    fn numeric_points(
        model: &Self::Model,
        chart: LapChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        lap_numeric_points(&model.joint, model.force, chart, density, OVERLAY_POINTS)
    }
}

/// What the joint's load charts call its quantities.
const LAP_LABELS: LoadLabels = LoadLabels {
    response: "Delta",
    response_axis: "Delta (mm)",
    loop_title: ("", "D"),
    dissipation_axis: "D (N mm)",
};

/// The force axis: the whole range the joint carries, 0 to F_gross (N), or `span` when a family
/// asks for a wider one (never beyond F_gross: there is no state there).
fn force_range(joint: &LapJoint, span: Option<f64>) -> f64 {
    let gross = joint.gross_slip_force();
    span.map_or(gross, |s| s.min(gross)).max(f64::MIN_POSITIVE)
}

fn lap_plot(
    joint: &LapJoint,
    force: JointForce,
    chart: LapChart,
    span: Option<f64>,
) -> Option<Plot> {
    let p = joint.params();
    let f_max = force_range(joint, span);
    let forces = samples(0.0, f_max, Spacing::Linear)?;
    let kt = p.tangential_stiffness;
    let f = force.newtons();
    match chart {
        LapChart::Displacement => {
            response_plot::<LapJointProblem>(joint, &LAP_LABELS, forces, (f, f_max))
        }
        LapChart::Zones => {
            let (coulomb, regularized) =
                curves::zone_outline_vs_force::<LapJointProblem>(joint, forces).ok()?;
            let series = vec![
                line(SeriesRole::Coulomb, "Coulomb: a, L-d", coulomb),
                line(SeriesRole::Current, "regularized: a, L-d", regularized),
                cursor(f, [0.0, p.length]),
            ];
            Some(Plot {
                caption: None,
                // At most 41 characters (the title row of an 80x24 screen's chart pane).
                title: format!(
                    "zones: slide below a, above L-d; F_1 {} N",
                    number_with(joint.first_slip_force(), 4)
                ),
                x: linear_axis("F (N)", 0.0, f_max),
                y: linear_axis("x (mm)", 0.0, p.length),
                series,
            })
        }
        LapChart::Shear => {
            let positions = samples(0.0, p.length, Spacing::Linear)?;
            Some(profile_plot(
                ("tau(x)", "tau (MPa)"),
                (f, kt),
                p.length,
                curves::shear_along_of::<LapJointProblem>(
                    &LapModel {
                        joint: *joint,
                        force,
                    },
                    positions,
                ),
                ("mu P", joint.coulomb_stress()),
            ))
        }
        LapChart::Slip => {
            let positions = samples(0.0, p.length, Spacing::Linear)?;
            Some(profile_plot(
                ("s(x)", "s (mm)"),
                (f, kt),
                p.length,
                slip_along(
                    &LapModel {
                        joint: *joint,
                        force,
                    },
                    positions.values(),
                ),
                ("mu P / K_T", joint.saturation_slip()),
            ))
        }
        LapChart::Loop => loop_chart::<LapJointProblem>(joint, &LAP_LABELS, force),
        LapChart::Dissipation => {
            let amplitudes = samples(0.0, f_max, Spacing::Linear)?;
            dissipation_chart::<LapJointProblem>(joint, &LAP_LABELS, force, amplitudes, f_max)
        }
    }
}

/// The project's finite-element points for a lap chart: the discretized solver (`LapFe`, which
/// never calls the closed forms) loaded monotonically through the chart's forces, round the same
/// cycle as the loop, or to the current force for tau(x); None for D vs F_a (a closed-form
/// integral of the loop). Beside them, on Delta, the zones, tau(x) and s(x), the 2-D
/// plane-stress continuum ([`solve_lap_continuum_path`], (L13)): the answer without the
/// shear-lag theory's assumptions, where its envelope (L14) says they fail. Where the continuum
/// refuses the joint (an interface too stiff for it) its series is empty: a gap, not an error.
fn lap_numeric_points(
    joint: &LapJoint,
    force: JointForce,
    chart: LapChart,
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
    let points = |points: Vec<(f64, f64)>| with_continuum(points, Vec::new());
    let continuum_at = |forces: &[f64]| {
        solve_lap_continuum_path(joint.params(), forces, LapContinuumMesh::default())
    };
    let mut fe = LapFe::new(joint.params(), density);
    let length = joint.params().length;
    match chart {
        LapChart::Displacement | LapChart::Zones => {
            // Up to just below F_gross, where the solver (and the joint) stops.
            let top = 0.98 * force_range(joint, None);
            let forces: Vec<f64> = (1..=count).map(|i| top * i as f64 / count as f64).collect();
            let mut found = Vec::with_capacity(2 * count);
            for &f in &forces {
                fe.load_to(f, 2)?;
                if chart == LapChart::Displacement {
                    found.push((f, fe.joint_displacement()));
                } else {
                    let (a, d) = fe.sliding_zones();
                    found.extend([(f, a), (f, length - d)]);
                }
            }
            let continuum = continuum_at(&forces).map_or_else(
                |_| Vec::new(),
                |states| {
                    states
                        .iter()
                        .flat_map(|c| {
                            if chart == LapChart::Displacement {
                                vec![(c.force, c.delta)]
                            } else {
                                let zones = c.nominal_zones;
                                vec![
                                    (c.force, zones.from_inner_end),
                                    (c.force, length - zones.from_cover_ends),
                                ]
                            }
                        })
                        .collect()
                },
            );
            with_continuum(found, continuum)
        }
        LapChart::Shear | LapChart::Slip => {
            let at = force.newtons().min(0.98 * joint.gross_slip_force());
            fe.load_to(at, 4)?;
            let continuum = continuum_at(&[at]).map_or_else(
                |_| Vec::new(),
                |mut states| match states.pop() {
                    Some(state) if chart == LapChart::Shear => state.shear,
                    Some(state) => state.slip,
                    None => Vec::new(),
                },
            );
            with_continuum(
                (0..=40)
                    .map(|i| {
                        let x = length * f64::from(i) / 40.0;
                        let y = if chart == LapChart::Shear {
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
        LapChart::Loop => {
            // Its own slider histories round a real reversal, no Masing rule.
            let fa = force.newtons().min(0.98 * joint.gross_slip_force());
            fe.load_to(fa, 4)?;
            points(fe_loop(fa, count, |f| {
                fe.load_to(f, 2)?;
                Ok(fe.joint_displacement())
            })?)
        }
        LapChart::Dissipation => Ok(None),
    }
}
