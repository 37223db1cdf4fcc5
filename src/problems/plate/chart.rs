//! The squeezed plate's charts as data: u(L) against K_T (log axis), X_r against mu, the contact
//! pressure, and the finite-element and continuum points of u(L) (the problem's [`ChartFace`]).

use super::SqueezedPlateProblem;
use super::profiles::contact_pressure_along;
use super::{ContinuumMesh, PlateFe, solve_plate_continuum};
use crate::SqueezedPlate;
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{
    NumericPoints, OVERLAY_POINTS, Plot, PointFailure, SeriesRole, cursor, line, linear_axis,
    log_axis, max_y, samples,
};
use crate::kernel::format::number;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::{Param, PlateParam};
use crate::study::curves::{self, Series, Spacing};

/// The squeezed plate's charts, in the order the TUI cycles through them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlateChart {
    /// End displacement u(L) against K_T (logarithmic K_T axis).
    Displacement,
    /// End of the microslip zone X_r against mu.
    SlipBoundary,
    /// Contact pressure ratio P_r(x)/P along the half-plate.
    ContactPressure,
}

impl ChartSet for PlateChart {
    const ALL: &'static [Self] = &[
        PlateChart::Displacement,
        PlateChart::SlipBoundary,
        PlateChart::ContactPressure,
    ];

    fn title(self) -> &'static str {
        match self {
            PlateChart::Displacement => "u(L) vs K_T",
            PlateChart::SlipBoundary => "X_r vs mu",
            PlateChart::ContactPressure => "P_r(x)/P",
        }
    }

    fn key(self) -> &'static str {
        match self {
            PlateChart::Displacement => "u-vs-kt",
            PlateChart::SlipBoundary => "xr-vs-mu",
            PlateChart::ContactPressure => "pressure",
        }
    }

    fn x_param(self) -> Option<Param> {
        match self {
            PlateChart::Displacement => Some(Param::Plate(PlateParam::Stiffness)),
            PlateChart::SlipBoundary => Some(Param::Plate(PlateParam::Friction)),
            PlateChart::ContactPressure => None,
        }
    }

    fn load_axis(self) -> bool {
        // The plate has no load parameter: its pressure is fixed.
        false
    }

    fn spans_decades(self) -> bool {
        match self {
            PlateChart::Displacement => true,
            PlateChart::SlipBoundary | PlateChart::ContactPressure => false,
        }
    }
}

impl ChartFace for SqueezedPlateProblem {
    type Chart = PlateChart;

    fn plot(
        model: &Self::Model,
        chart: PlateChart,
        _f_data: f64,
        _span: Option<f64>,
    ) -> Option<Plot> {
        plate_plot(model, chart)
    }

    fn numeric_points(
        model: &Self::Model,
        chart: PlateChart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        plate_numeric_points(model, chart, density)
    }

    /// The u(L) chart runs along log10 K_T.
    fn external_point((kt, u): (f64, f64)) -> (f64, f64) {
        (kt.log10(), u)
    }
}

/// The K_T range of the plate's displacement chart: four decades either side of K_T, within the
/// accepted stiffnesses (ends in MPa/mm).
fn stiffness_range(kt: f64) -> (f64, f64) {
    let domain = PlateParam::Stiffness.spec().domain;
    (domain.clamp(kt / 1e4), domain.clamp(kt * 1e4))
}

fn plate_plot(plate: &SqueezedPlate, chart: PlateChart) -> Option<Plot> {
    let p = plate.params();
    let kt = p.tangential_stiffness;
    match chart {
        PlateChart::Displacement => {
            let (from, to) = stiffness_range(kt);
            let stiffnesses = samples(from, to, Spacing::Logarithmic)?;
            let (coulomb, regularized) = curves::responses_over::<SqueezedPlateProblem>(
                *plate,
                PlateParam::Stiffness,
                stiffnesses,
            )
            .ok()?;
            let to_log = |s: Series| {
                s.into_iter()
                    .map(|(k, u)| (k.log10(), u))
                    .collect::<Series>()
            };
            let (coulomb, regularized) = (to_log(coulomb), to_log(regularized));
            let top = 1.05 * max_y([&coulomb, &regularized]);
            let y = linear_axis("u(L) (mm)", 0.0, top);
            let cursor = cursor(kt.log10(), y.bounds);
            Some(Plot {
                caption: None,
                title: "u(L) vs K_T".into(),
                x: log_axis("K_T (MPa/mm, log)", from.log10(), to.log10()),
                y,
                series: vec![
                    line(SeriesRole::Coulomb, "Coulomb", coulomb),
                    line(SeriesRole::Current, "regularized", regularized),
                    cursor,
                ],
            })
        }
        PlateChart::SlipBoundary => {
            let mu = p.friction;
            // mu/5 to 5 (or 1.5 mu beyond 5), within the accepted friction coefficients.
            let domain = PlateParam::Friction.spec().domain;
            let (lo, hi) = (
                domain.clamp(mu / 5.0),
                domain.clamp((mu * 5.0).min(5.0).max(mu * 1.5)),
            );
            let frictions = samples(lo, hi, Spacing::Linear)?;
            let mut series = Vec::new();
            for (role, label, factor) in [
                (SeriesRole::Softer, "K_T/10", 0.1),
                (SeriesRole::Stiffer, "K_T*10", 10.0),
                (SeriesRole::Current, "K_T", 1.0),
            ] {
                // Companions only where their K_T is accepted.
                let Ok(other) = plate.with_tangential_stiffness(kt * factor) else {
                    continue;
                };
                series.push(line(
                    role,
                    label,
                    curves::zone_end_over::<SqueezedPlateProblem>(
                        other,
                        PlateParam::Friction,
                        frictions,
                    )
                    .ok()?,
                ));
            }
            // Zoom on the band the curves use: X_r stays near L over most of the range.
            let bottom = series
                .iter()
                .flat_map(|s| &s.points)
                .map(|q| q.1)
                .fold(p.half_length, f64::min);
            let bottom = (bottom - 0.05 * (p.half_length - bottom)).max(0.0);
            let y = linear_axis("X_r (mm)", bottom, p.half_length);
            series.push(cursor(mu, y.bounds));
            Some(Plot {
                caption: None,
                title: format!("X_r vs mu, K_T = {} MPa/mm", number(kt)),
                x: linear_axis("mu (-)", lo, hi),
                y,
                series,
            })
        }
        PlateChart::ContactPressure => {
            let positions = samples(0.0, p.half_length, Spacing::Linear)?;
            let ratio = contact_pressure_along(plate, positions.values());
            let (low, high) = ratio.iter().fold((1.0_f64, 1.0_f64), |(lo, hi), &(_, r)| {
                (lo.min(r), hi.max(r))
            });
            let pad = 0.05 * (high - low).max(0.01);
            Some(Plot {
                caption: None,
                title: "P_r(x)/P: flat-plate model P7-P9 (not 2-D)".to_string(),
                x: linear_axis("x (mm)", 0.0, p.half_length),
                y: linear_axis("P_r/P (-)", low - pad, high + pad),
                series: vec![
                    line(SeriesRole::Current, "P_r/P", ratio),
                    line(
                        SeriesRole::Limit,
                        "P_r = P",
                        vec![(0.0, 1.0), (p.half_length, 1.0)],
                    ),
                ],
            })
        }
    }
}

/// The plate's finite-element points for `chart`: u(L) against K_T, with the 2-D continuum
/// beside it (none for X_r vs mu and the contact pressure).
fn plate_numeric_points(
    plate: &SqueezedPlate,
    chart: PlateChart,
    density: MeshDensity,
) -> Result<Option<NumericPoints>, NumericError> {
    match chart {
        PlateChart::Displacement => {
            let p = plate.params();
            let (from, to) = stiffness_range(p.tangential_stiffness);
            let (lo, hi) = (from.log10(), to.log10());
            let mut points = Vec::with_capacity(OVERLAY_POINTS + 1);
            let mut continuum = Vec::with_capacity(OVERLAY_POINTS + 1);
            let (mut failure, mut first_failure) = (None, None);
            for i in 0..=OVERLAY_POINTS {
                let log_kt = lo + (hi - lo) * i as f64 / OVERLAY_POINTS as f64;
                let params = crate::PlateParams {
                    tangential_stiffness: PlateParam::Stiffness
                        .spec()
                        .domain
                        .clamp(10f64.powf(log_kt)),
                    ..p
                };
                // A solve that fails at an extreme K_T (the 1-D solver at 1e10 MPa/mm, the
                // continuum beyond its stiffness limit) leaves a gap, not an error; only a chart
                // without any point reports the failure.
                let mut fe = PlateFe::new(params, density);
                match fe.load_to(p.pressure, 2) {
                    Ok(()) => points.push((log_kt, fe.end_displacement())),
                    Err(e) => {
                        first_failure.get_or_insert_with(|| PointFailure {
                            at: format!("K_T = {} MPa/mm", number(params.tangential_stiffness)),
                            why: e.to_string(),
                        });
                        failure = Some(e);
                    }
                }
                if let Ok(solution) = solve_plate_continuum(params, ContinuumMesh::default()) {
                    continuum.push((log_kt, solution.end_displacement_mean));
                }
            }
            match failure {
                Some(e) if points.is_empty() => Err(e),
                _ => Ok(Some(NumericPoints {
                    failed: OVERLAY_POINTS + 1 - points.len(),
                    failure: first_failure,
                    points,
                    continuum,
                })),
            }
        }
        PlateChart::SlipBoundary | PlateChart::ContactPressure => Ok(None),
    }
}
