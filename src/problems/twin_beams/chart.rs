//! The twin beams' charts as data: w(L) vs F with Coulomb and the K_T family, X vs F, the loop,
//! D vs F_a and tau(x), and their finite-element points (the problem's [`ChartFace`]). The load
//! charts are written once in the chart layer's `load`; this file gives the beams' words and
//! their own charts.

use super::TwinBeamsFe;
use super::TwinBeamsProblem;
use super::closed_form::BeamTheory;
use super::continuum::{BeamsContinuumMesh, solve_beams_continuum_path};
use super::problem::BeamsModel;
use crate::chart::load::{
    LoadLabels, companions, dissipation_chart, fe_loop, load_words, loop_chart, profile_plot,
    response_plot,
};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{
    NumericPoints, OVERLAY_POINTS, Plot, PointFailure, SeriesRole, cursor, line, linear_axis,
    samples,
};
use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::{BeamParam, Param};
use crate::study::curves::{self, Spacing};
use crate::{TipForce, TwinBeams};

/// The twin beams' charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BeamChart {
    /// Tip deflection w(L) against the tip force F, for K_T/5, K_T, 5 K_T and Coulomb.
    Deflection,
    /// End of the microslip zone X against F.
    SlipBoundary,
    /// Interface shear tau(x) along the beams at F.
    Shear,
    /// The hysteresis loop of a cycle between +F and -F.
    Loop,
    /// Dissipation per cycle D against the amplitude F_a.
    Dissipation,
}

impl ChartSet for BeamChart {
    const ALL: &'static [Self] = &[
        BeamChart::Deflection,
        BeamChart::SlipBoundary,
        BeamChart::Shear,
        BeamChart::Loop,
        BeamChart::Dissipation,
    ];

    fn title(self) -> &'static str {
        match self {
            BeamChart::Deflection => "w(L) vs F",
            BeamChart::SlipBoundary => "X vs F",
            BeamChart::Shear => "tau(x) at F",
            BeamChart::Loop => "loop +-F",
            BeamChart::Dissipation => "D vs F_a",
        }
    }

    fn key(self) -> &'static str {
        match self {
            BeamChart::Deflection => "w-vs-f",
            BeamChart::SlipBoundary => "x-vs-f",
            BeamChart::Shear => "tau",
            BeamChart::Loop => "loop",
            BeamChart::Dissipation => "d-vs-fa",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            BeamChart::Deflection | BeamChart::SlipBoundary => Some(Param::Beam(BeamParam::Force)),
            BeamChart::Shear | BeamChart::Loop | BeamChart::Dissipation => None,
        }
    }

    fn load_axis(self) -> bool {
        match self {
            BeamChart::Deflection | BeamChart::SlipBoundary | BeamChart::Dissipation => true,
            BeamChart::Shear | BeamChart::Loop => false,
        }
    }

    fn spans_decades(self) -> bool {
        match self {
            BeamChart::Dissipation => true,
            BeamChart::Deflection
            | BeamChart::SlipBoundary
            | BeamChart::Shear
            | BeamChart::Loop => false,
        }
    }
}

impl ChartFace for TwinBeamsProblem {
    type Chart = BeamChart;

    fn plot(model: &Self::Model, chart: BeamChart, f_data: f64, span: Option<f64>) -> Option<Plot> {
        beam_plot(&model.beams, model.force, chart, f_data, span)
    }

    fn numeric_points(
        model: &Self::Model,
        chart: BeamChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        beam_numeric_points(&model.beams, model.force, chart, density)
    }

    /// The beam theory (`EB`, `Timo`): a pin of the other theory says so.
    fn setting_label(params: &Self::Params) -> Option<(&'static str, &'static str)> {
        let label = match params.structure.theory {
            BeamTheory::EulerBernoulli => "EB",
            BeamTheory::Timoshenko => "Timo",
        };
        Some(("theory", label))
    }
}

/// What the twin beams' load charts call their quantities: the loop is one beam's, D both's.
const BEAM_LABELS: LoadLabels = LoadLabels {
    response: "w(L)",
    response_axis: "w(L) (mm)",
    loop_title: ("1 beam ", "D(2)"),
    dissipation_axis: "D, 2 beams (N mm)",
};

/// The force range of the beam charts: up to `span` (kept by the app while parameters change) or
/// 3 F_thre, or further to show the current F and the largest measured force, but never beyond the
/// largest accepted force (the sweeps refuse it).
fn force_range(beams: &TwinBeams, force: TipForce, f_data: f64, span: Option<f64>) -> f64 {
    let wanted = span
        .unwrap_or(3.0 * beams.threshold_force())
        .max(1.25 * force.newtons())
        .max(1.05 * f_data);
    TipForce::clamped(wanted).newtons()
}

fn beam_plot(
    beams: &TwinBeams,
    force: TipForce,
    chart: BeamChart,
    f_data: f64,
    span: Option<f64>,
) -> Option<Plot> {
    let p = beams.params();
    let f_max = force_range(beams, force, f_data, span);
    let forces = samples(0.0, f_max, Spacing::Linear)?;
    let kt = p.tangential_stiffness;
    let companions = companions(kt, |k| beams.with_tangential_stiffness(k).ok());
    let f = force.newtons();
    match chart {
        BeamChart::Deflection => {
            response_plot::<TwinBeamsProblem>(beams, &BEAM_LABELS, forces, (f, f_max))
        }
        BeamChart::SlipBoundary => {
            let mut series = Vec::new();
            for (role, label, other) in &companions {
                series.push(line(
                    *role,
                    *label,
                    curves::slip_boundary_vs_force::<TwinBeamsProblem>(other, forces).ok()?,
                ));
            }
            series.push(line(
                SeriesRole::Current,
                "K_T",
                curves::slip_boundary_vs_force::<TwinBeamsProblem>(beams, forces).ok()?,
            ));
            series.push(cursor(f, [0.0, p.length]));
            Some(Plot {
                caption: None,
                title: format!(
                    "X vs F, K_T = {} MPa/mm, F_1 = {} N",
                    number(kt),
                    number(beams.first_macroslip_force())
                ),
                x: linear_axis("F (N)", 0.0, f_max),
                y: linear_axis("X (mm)", 0.0, p.length),
                series,
            })
        }
        BeamChart::Loop => loop_chart::<TwinBeamsProblem>(beams, &BEAM_LABELS, force),
        BeamChart::Dissipation => {
            let amplitudes = samples(0.0, f_max, Spacing::Linear)?;
            dissipation_chart::<TwinBeamsProblem>(beams, &BEAM_LABELS, force, amplitudes, f_max)
        }
        BeamChart::Shear => {
            let positions = samples(0.0, p.length, Spacing::Linear)?;
            Some(profile_plot(
                ("tau(x)", "tau (MPa)"),
                (f, kt),
                load_words::<TwinBeamsProblem>(),
                p.length,
                curves::shear_along_of::<TwinBeamsProblem>(
                    &BeamsModel {
                        beams: *beams,
                        force,
                    },
                    positions,
                ),
                ("mu P", beams.coulomb_stress()),
            ))
        }
    }
}

/// The twin beams' finite-element points for `chart` (none for D vs F_a, a closed-form integral
/// of the loop). Beside them, on tau(x), the 2-D plane-stress continuum
/// ([`solve_beams_continuum_path`]): the answer without beam theory's assumptions, the
/// reference an FE code is judged against. Where the continuum refuses the beams (a mesh too
/// large) its series is empty: a gap, not an error.
fn beam_numeric_points(
    beams: &TwinBeams,
    force: TipForce,
    chart: BeamChart,
    density: MeshDensity,
) -> Result<Option<NumericPoints>, NumericError> {
    match chart {
        BeamChart::Deflection | BeamChart::SlipBoundary => {
            // One model loaded monotonically through the sample forces: one load step per point.
            let f_max = force_range(beams, force, 0.0, None);
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            let mut points = Vec::with_capacity(OVERLAY_POINTS);
            let (mut failed, mut failure) = (0, None);
            let mut first_failure = None;
            for i in 1..=OVERLAY_POINTS {
                let f = f_max * i as f64 / OVERLAY_POINTS as f64;
                // A very stiff interface can make Newton cycle at one load (the whole interface
                // on the yield limit to round-off): that point is a gap, the model stays at the
                // last converged load and the next point goes on from there.
                match fe.load_to(f, 2) {
                    Ok(()) => {}
                    Err(e @ NumericError::NoConvergence { .. }) => {
                        failed += 1;
                        first_failure.get_or_insert_with(|| PointFailure {
                            at: format!("F = {} N", number(f)),
                            why: e.to_string(),
                        });
                        failure = Some(e);
                        continue;
                    }
                    Err(e) => return Err(e),
                }
                points.push((
                    f,
                    if chart == BeamChart::Deflection {
                        fe.tip_deflection()
                    } else {
                        fe.micro_zone_end()
                    },
                ));
            }
            match failure {
                Some(e) if points.is_empty() => Err(e),
                _ => Ok(Some(NumericPoints {
                    points,
                    continuum: Vec::new(),
                    failed,
                    failure: first_failure,
                })),
            }
        }
        BeamChart::Loop => {
            // The FE model driven round the same cycle: its own slider histories, no Masing rule.
            let fa = force.newtons();
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(fa, 4)?;
            let points = fe_loop(fa, OVERLAY_POINTS, |f| {
                fe.load_to(f, 2)?;
                Ok(fe.tip_deflection())
            })?;
            Ok(Some(NumericPoints {
                points,
                continuum: Vec::new(),
                failed: 0,
                failure: None,
            }))
        }
        BeamChart::Shear => {
            let mut fe = TwinBeamsFe::new(beams.params(), density);
            fe.load_to(force.newtons(), 4)?;
            let samples = fe.interface();
            let stride = (samples.len() / 40).max(1);
            let continuum = solve_beams_continuum_path(
                beams.params(),
                &[force.newtons()],
                BeamsContinuumMesh::default(),
            )
            .map_or_else(
                |_| Vec::new(),
                |mut states| states.pop().map_or_else(Vec::new, |state| state.shear),
            );
            Ok(Some(NumericPoints {
                continuum,
                failed: 0,
                failure: None,
                points: samples
                    .iter()
                    .step_by(stride)
                    .map(|s| (s.x, s.stress))
                    .collect(),
            }))
        }
        BeamChart::Dissipation => Ok(None),
    }
}
