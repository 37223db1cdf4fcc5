//! Identification of mu and K_T from a measured twin-beam deflection curve w(L) vs F.
//!
//! The paper's practical point (its section 2.1.3): below F_1 the whole interface is in microslip and
//! w depends on K_T but not on mu; past F_1 the slope changes (towards the Coulomb slip slope, which
//! carries mu). So K_T comes from the curve's stiffness, mu from where and how the slope changes.
//!
//! Method: nonlinear least squares on the closed form, in log-parameters (both must stay positive and
//! span decades). A coarse grid over both (the bracket) gives a start that does not depend on the
//! user's guess, then Levenberg-Marquardt refines it. Standard errors come from the Jacobian at the
//! optimum (s^2 (J^T J)^-1, delta method back to linear units). Identifiability is judged from the
//! physics first (no data beyond F_1: mu cannot be seen) and from the standard errors second.
//!
//! Results are data only: the reason behind each verdict is an [`Evidence`] carrying its numbers;
//! the words for people are written by the `report` module.

pub mod data;

use thiserror::Error;

pub use data::{DataError, Measurement};

use crate::model::params::ParamError;
use crate::{TipForce, TwinBeams, TwinBeamsParams};

/// Search range of mu (-) and K_T (MPa/mm): wide enough for any real interface.
const MU_RANGE: (f64, f64) = (1e-3, 5.0);
const KT_RANGE: (f64, f64) = (1e-3, 1e9);
/// Grid points per decade of the bracketing search.
const GRID_PER_DECADE: f64 = 4.0;
/// Relative standard error below which a parameter is called identified, and above which it is not
/// identifiable at all.
const IDENTIFIED: f64 = 0.25;
const UNIDENTIFIABLE: f64 = 1.0;

/// How well the data determine a parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Held at a given value (`--fix`).
    Fixed,
    /// Relative standard error <= 25 %.
    Identified,
    /// Between 25 % and 100 %, or too few points in the informative range.
    Weak,
    /// The data do not determine it.
    NotIdentifiable,
}

impl Status {
    /// Plain words for reports.
    pub fn label(self) -> &'static str {
        match self {
            Status::Fixed => "fixed",
            Status::Identified => "identified",
            Status::Weak => "weakly identified",
            Status::NotIdentifiable => "NOT identifiable",
        }
    }
}

/// Why a parameter got its [`Status`]: the finding behind the verdict, with its numbers.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Evidence {
    /// Held at a given value (`--fix`), not fitted.
    HeldFixed,
    /// The standard error at the optimum, relative to the value.
    StandardError {
        /// Standard error / value (-).
        relative: f64,
    },
    /// The best fit sits at the edge of the search range, so no standard error means anything.
    AtSearchBound,
    /// The residuals do not depend on the parameter at all.
    NoDependence,
    /// (mu only) Every measurement is at or below F_1, where the deflection does not depend on mu:
    /// the data only bound mu from below.
    NoDataAboveFirstMacroslip {
        /// F_1 at the fitted values (N).
        first_macroslip_force: f64,
        /// The lower bound on mu the data do show (-): the fitted mu scaled by F_max / F_1.
        mu_at_least: f64,
    },
    /// (mu only) A small standard error, but from too few measurements above F_1 to trust it.
    FewPointsAboveFirstMacroslip {
        /// Standard error / value (-).
        relative: f64,
        /// Measurements above F_1.
        points: usize,
    },
}

/// One fitted (or fixed) parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Best value.
    pub value: f64,
    /// Standard error in the same unit, when it could be computed.
    pub std_error: Option<f64>,
    /// Identifiability.
    pub status: Status,
    /// Why: the finding behind `status`.
    pub evidence: Evidence,
}

impl Estimate {
    /// A parameter held at `value` (`--fix`).
    fn fixed(value: f64) -> Estimate {
        Estimate {
            value,
            std_error: None,
            status: Status::Fixed,
            evidence: Evidence::HeldFixed,
        }
    }
}

/// The outcome of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FitResult {
    /// Friction coefficient (-).
    pub mu: Estimate,
    /// Tangential stiffness (MPa/mm).
    pub kt: Estimate,
    /// Root-mean-square residual (mm).
    pub rms: f64,
    /// Number of measurements.
    pub points: usize,
    /// Measurements above the fitted F_1.
    pub beyond_first_macroslip: usize,
    /// F_thre at the fitted mu (N).
    pub threshold_force: f64,
    /// F_1 at the fitted mu and K_T (N).
    pub first_macroslip_force: f64,
}

/// Why a fit could not run.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The structure or a fixed value is invalid.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// Not enough points for the free parameters.
    #[error("{points} measurements cannot determine {free} parameters; at least {} are needed", free + 1)]
    TooFewPoints {
        /// Measurements given.
        points: usize,
        /// Free parameters.
        free: usize,
    },
}

/// The fit problem: structure fixed, mu and K_T free unless fixed, in log units.
struct Problem<'a> {
    structure: TwinBeamsParams,
    data: &'a [Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
}

impl Problem<'_> {
    /// (mu, K_T) from the free log-parameters.
    fn unpack(&self, theta: &[f64]) -> (f64, f64) {
        let mut free = theta.iter();
        let mu = self
            .fixed_mu
            .unwrap_or_else(|| free.next().map_or(f64::NAN, |t| t.exp()));
        let kt = self
            .fixed_kt
            .unwrap_or_else(|| free.next().map_or(f64::NAN, |t| t.exp()));
        (mu, kt)
    }

    fn beams(&self, mu: f64, kt: f64) -> Option<TwinBeams> {
        TwinBeams::new(TwinBeamsParams {
            friction: mu,
            tangential_stiffness: kt,
            ..self.structure
        })
        .ok()
    }

    /// Residuals model - measured (mm); None for parameters outside the valid domain.
    fn residuals(&self, theta: &[f64]) -> Option<Vec<f64>> {
        let (mu, kt) = self.unpack(theta);
        let beams = self.beams(mu, kt)?;
        self.data
            .iter()
            .map(|m| {
                TipForce::new(m.force)
                    .ok()
                    .map(|f| beams.regularized(f).tip_deflection() - m.deflection)
            })
            .collect()
    }

    fn sse(&self, theta: &[f64]) -> f64 {
        self.residuals(theta)
            .map_or(f64::INFINITY, |r| r.iter().map(|x| x * x).sum())
    }

    /// Forward-difference Jacobian d residual / d theta (columns per free parameter).
    fn jacobian(&self, theta: &[f64], base: &[f64]) -> Vec<Vec<f64>> {
        (0..theta.len())
            .map(|j| {
                let step = 1e-6;
                let mut shifted = theta.to_vec();
                shifted[j] += step;
                let moved = self.residuals(&shifted).unwrap_or_else(|| base.to_vec());
                moved
                    .iter()
                    .zip(base)
                    .map(|(a, b)| (a - b) / step)
                    .collect()
            })
            .collect()
    }

    fn bounds(&self) -> Vec<(f64, f64)> {
        let mut b = Vec::new();
        if self.fixed_mu.is_none() {
            b.push((MU_RANGE.0.ln(), MU_RANGE.1.ln()));
        }
        if self.fixed_kt.is_none() {
            b.push((KT_RANGE.0.ln(), KT_RANGE.1.ln()));
        }
        b
    }
}

/// Log-spaced grid over `bounds` (in log units), GRID_PER_DECADE points per decade.
fn grid(bounds: (f64, f64)) -> Vec<f64> {
    let decades = (bounds.1 - bounds.0) / std::f64::consts::LN_10;
    let n = (decades * GRID_PER_DECADE).ceil().max(1.0) as usize;
    (0..=n)
        .map(|i| bounds.0 + (bounds.1 - bounds.0) * i as f64 / n as f64)
        .collect()
}

/// Solves the (at most 2x2) symmetric system a x = b; None when singular.
fn solve_small(a: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    match a.len() {
        1 => (a[0][0] > 0.0).then(|| vec![b[0] / a[0][0]]),
        2 => {
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            let scale = a[0][0].abs() * a[1][1].abs();
            (det.abs() > 1e-14 * scale && det != 0.0).then(|| {
                vec![
                    (b[0] * a[1][1] - b[1] * a[0][1]) / det,
                    (a[0][0] * b[1] - a[1][0] * b[0]) / det,
                ]
            })
        }
        _ => Some(Vec::new()),
    }
}

fn normal_matrix(jac: &[Vec<f64>]) -> Vec<Vec<f64>> {
    jac.iter()
        .map(|ci| {
            jac.iter()
                .map(|cj| ci.iter().zip(cj).map(|(a, b)| a * b).sum())
                .collect()
        })
        .collect()
}

/// Fits mu and K_T (each unless fixed) of twin beams with the geometry, E and P of `structure` to
/// a measured w(L) vs F curve. The structure's own mu and K_T are not used as a start: the grid is.
///
/// # Errors
///
/// [`FitError::Param`] when the structure or a fixed value is invalid (the model's own checks), and
/// [`FitError::TooFewPoints`] when there are not more measurements than free parameters.
///
/// # Examples
///
/// A curve measured on beams with mu = 0.4 and K_T = 200 MPa/mm, well past F_1, gives both back:
///
/// ```
/// use microslip::fit::{Measurement, Status, fit_twin_beams};
/// use microslip::{TipForce, TwinBeams, TwinBeamsParams};
///
/// let truth = TwinBeams::new(TwinBeamsParams {
///     friction: 0.4,
///     tangential_stiffness: 200.0,
///     ..TwinBeamsParams::PAPER
/// })?;
/// let data: Vec<Measurement> = (1..=30)
///     .map(|i| {
///         let force = 10.0 * f64::from(i);
///         let w = truth.regularized(TipForce::new(force)?).tip_deflection();
///         Ok(Measurement { force, deflection: w })
///     })
///     .collect::<Result<_, microslip::ParamError>>()?;
///
/// // Only the geometry, E and P of the structure are used.
/// let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None)?;
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// assert!((fit.kt.value - 200.0).abs() < 1e-3);
/// assert_eq!(fit.mu.status, Status::Identified);
/// assert!(fit.beyond_first_macroslip > 2);
///
/// // Holding K_T fixed fits mu alone.
/// let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, Some(200.0))?;
/// assert_eq!(fit.kt.status, Status::Fixed);
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_twin_beams(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
) -> Result<FitResult, FitError> {
    // Validate the structure and any fixed values through the model's own constructor.
    TwinBeams::new(TwinBeamsParams {
        friction: fixed_mu.unwrap_or(structure.friction),
        tangential_stiffness: fixed_kt.unwrap_or(structure.tangential_stiffness),
        ..structure
    })?;
    let problem = Problem {
        structure,
        data,
        fixed_mu,
        fixed_kt,
    };
    let bounds = problem.bounds();
    let free = bounds.len();
    if data.len() <= free {
        return Err(FitError::TooFewPoints {
            points: data.len(),
            free,
        });
    }
    // Bracket: the best point of a log grid over every free parameter.
    let mut theta: Vec<f64> = bounds.iter().map(|b| 0.5 * (b.0 + b.1)).collect();
    let mut best = problem.sse(&theta);
    let axes: Vec<Vec<f64>> = bounds.iter().map(|&b| grid(b)).collect();
    let mut index = vec![0usize; free];
    loop {
        let candidate: Vec<f64> = index.iter().zip(&axes).map(|(&i, axis)| axis[i]).collect();
        let sse = problem.sse(&candidate);
        if sse < best {
            best = sse;
            theta = candidate;
        }
        // Next grid point (odometer order); done when every index wrapped.
        let mut k = 0;
        while k < free {
            index[k] += 1;
            if index[k] < axes[k].len() {
                break;
            }
            index[k] = 0;
            k += 1;
        }
        if k == free {
            break;
        }
    }
    // Levenberg-Marquardt from the grid's best point.
    let mut damping = 1e-3;
    for _ in 0..200 {
        if free == 0 {
            break;
        }
        let Some(base) = problem.residuals(&theta) else {
            break;
        };
        let jac = problem.jacobian(&theta, &base);
        let normal = normal_matrix(&jac);
        let gradient: Vec<f64> = jac
            .iter()
            .map(|c| -c.iter().zip(&base).map(|(a, r)| a * r).sum::<f64>())
            .collect();
        let mut improved = false;
        while damping < 1e12 {
            let damped: Vec<Vec<f64>> = normal
                .iter()
                .enumerate()
                .map(|(i, row)| {
                    row.iter()
                        .enumerate()
                        .map(|(j, &v)| {
                            if i == j {
                                v * (1.0 + damping) + 1e-300
                            } else {
                                v
                            }
                        })
                        .collect()
                })
                .collect();
            let Some(step) = solve_small(&damped, &gradient) else {
                damping *= 10.0;
                continue;
            };
            let trial: Vec<f64> = theta
                .iter()
                .zip(&step)
                .zip(&bounds)
                .map(|((t, s), b)| (t + s).clamp(b.0, b.1))
                .collect();
            let sse = problem.sse(&trial);
            if sse < best {
                let gain = (best - sse) / best.max(f64::MIN_POSITIVE);
                let moved = step.iter().map(|s| s.abs()).fold(0.0, f64::max);
                theta = trial;
                best = sse;
                damping = (damping / 10.0).max(1e-12);
                improved = gain > 1e-15 && moved > 1e-12;
                break;
            }
            damping *= 10.0;
        }
        if !improved {
            break;
        }
    }
    Ok(summarize(&problem, &theta, best))
}

/// Estimates, standard errors and identifiability at the optimum.
fn summarize(problem: &Problem, theta: &[f64], sse: f64) -> FitResult {
    let (mu, kt) = problem.unpack(theta);
    let n = problem.data.len();
    let free = theta.len();
    let base = problem.residuals(theta).unwrap_or_default();
    let jac = problem.jacobian(theta, &base);
    let normal = normal_matrix(&jac);
    let variance = sse / (n - free).max(1) as f64;
    // A parameter the residuals do not depend on at all (mu when every F is below F_1) has a zero
    // Jacobian column; it is left out so that the other's error is still computed.
    let scale = normal
        .iter()
        .enumerate()
        .map(|(i, row)| row[i])
        .fold(0.0, f64::max);
    let informative: Vec<usize> = (0..free)
        .filter(|&i| normal[i][i] > 1e-20 * scale && normal[i][i] > 0.0)
        .collect();
    let reduced: Vec<Vec<f64>> = informative
        .iter()
        .map(|&i| informative.iter().map(|&j| normal[i][j]).collect())
        .collect();
    // Diagonal of (J^T J)^-1 by solving for unit vectors.
    let log_errors: Vec<Option<f64>> = (0..free)
        .map(|i| {
            let k = informative.iter().position(|&j| j == i)?;
            let unit: Vec<f64> = (0..informative.len())
                .map(|j| if j == k { 1.0 } else { 0.0 })
                .collect();
            solve_small(&reduced, &unit).map(|col| (variance * col[k]).max(0.0).sqrt())
        })
        .collect();
    let beams = problem.beams(mu, kt);
    let (f_thre, f_1) = beams.map_or((f64::NAN, f64::NAN), |b| {
        (b.threshold_force(), b.first_macroslip_force())
    });
    let beyond = problem.data.iter().filter(|m| m.force > f_1).count();
    let f_max = problem.data.last().map_or(0.0, |m| m.force);
    let judge = |log_error: Option<f64>, value: f64, bound: (f64, f64)| -> Estimate {
        let at_bound = value <= bound.0 * 1.0001 || value >= bound.1 / 1.0001;
        let (std_error, status, evidence) = match log_error {
            Some(e) if e.is_finite() && !at_bound => {
                let status = if e <= IDENTIFIED {
                    Status::Identified
                } else if e <= UNIDENTIFIABLE {
                    Status::Weak
                } else {
                    Status::NotIdentifiable
                };
                (
                    Some(value * e),
                    status,
                    Evidence::StandardError { relative: e },
                )
            }
            _ if at_bound => (None, Status::NotIdentifiable, Evidence::AtSearchBound),
            _ => (None, Status::NotIdentifiable, Evidence::NoDependence),
        };
        Estimate {
            value,
            std_error,
            status,
            evidence,
        }
    };
    let mut next = log_errors.into_iter();
    let mu_estimate = match problem.fixed_mu {
        Some(v) => Estimate::fixed(v),
        None => {
            let mut estimate = judge(next.next().flatten(), mu, MU_RANGE);
            if beyond == 0 {
                estimate.std_error = None;
                estimate.status = Status::NotIdentifiable;
                estimate.evidence = Evidence::NoDataAboveFirstMacroslip {
                    first_macroslip_force: f_1,
                    mu_at_least: mu * f_max / f_1,
                };
            } else if beyond < 2
                && estimate.status == Status::Identified
                && let Evidence::StandardError { relative } = estimate.evidence
            {
                estimate.status = Status::Weak;
                estimate.evidence = Evidence::FewPointsAboveFirstMacroslip {
                    relative,
                    points: beyond,
                };
            }
            estimate
        }
    };
    let kt_estimate = match problem.fixed_kt {
        Some(v) => Estimate::fixed(v),
        None => judge(next.next().flatten(), kt, KT_RANGE),
    };
    FitResult {
        mu: mu_estimate,
        kt: kt_estimate,
        rms: (sse / n as f64).sqrt(),
        points: n,
        beyond_first_macroslip: beyond,
        threshold_force: f_thre,
        first_macroslip_force: f_1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn synthetic(mu: f64, kt: f64, forces: impl Iterator<Item = f64>) -> Vec<Measurement> {
        let beams = TwinBeams::new(TwinBeamsParams {
            friction: mu,
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        forces
            .map(|f| Measurement {
                force: f,
                deflection: beams
                    .regularized(TipForce::new(f).unwrap())
                    .tip_deflection(),
            })
            .collect()
    }

    #[test]
    fn exact_data_are_recovered_exactly_from_a_poor_start() {
        let data = synthetic(0.45, 150.0, (1..=30).map(|i| 10.0 * f64::from(i)));
        // The structure's own mu and K_T (0.3, 600) are deliberately wrong: they are not used.
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
        assert!((fit.mu.value / 0.45 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!((fit.kt.value / 150.0 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!(fit.rms < 1e-10);
        assert_eq!(
            (fit.mu.status, fit.kt.status),
            (Status::Identified, Status::Identified)
        );
    }

    #[test]
    fn fixing_one_parameter_fits_the_other() {
        let data = synthetic(0.3, 600.0, (1..=20).map(|i| 15.0 * f64::from(i)));
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, Some(0.3), None).unwrap();
        assert_eq!(fit.mu.status, Status::Fixed);
        assert!((fit.kt.value / 600.0 - 1.0).abs() < 1e-6);
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, Some(600.0)).unwrap();
        assert!((fit.mu.value / 0.3 - 1.0).abs() < 1e-6);
    }

    #[test]
    fn bad_fixed_values_and_too_few_points_are_refused() {
        let data = synthetic(0.3, 600.0, [10.0, 20.0].into_iter());
        assert_eq!(
            fit_twin_beams(TwinBeamsParams::PAPER, &data, Some(-1.0), None)
                .unwrap_err()
                .to_string(),
            "invalid mu = -1: must be > 0 and finite (dimensionless)"
        );
        assert!(matches!(
            fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None),
            Err(FitError::TooFewPoints { points: 2, free: 2 })
        ));
    }
}
