//! What a fit found and how sure it is: the estimates, their standard errors and correlation from
//! the normal equations at the optimum, and each parameter's identifiability with the evidence
//! behind it.

use super::least_squares::{Problem, Refined};
use super::small::{self, MAX_FREE};
use super::{KT_RANGE, Scatter, Weights};

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
    /// Fitted through as many loaded measurements as parameters, with the scatter unknown: the
    /// curve passes through every point, so nothing is left to say how far off the value may be.
    UncertaintyUnknown,
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
            Status::UncertaintyUnknown => "uncertainty unknown",
            Status::NotIdentifiable => "NOT identifiable",
        }
    }
}

/// Why a parameter got its [`Status`]: the finding behind the verdict, with its numbers.
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
    /// As many loaded measurements (F > 0; every mu and K_T give 0 at F = 0) as parameters
    /// fitted, and the scatter estimated from the residuals: the residuals are 0 by construction,
    /// so a standard error from them would be 0 too, a certainty the data do not have.
    NoDegreesOfFreedom {
        /// Loaded measurements.
        points: usize,
        /// Parameters fitted through them.
        parameters: usize,
    },
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
    pub(super) fn fixed(value: f64) -> Estimate {
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
    /// Root-mean-square residual (mm), unweighted.
    pub rms: f64,
    /// The scatter the standard errors assume, as the residuals estimate it.
    pub scatter: Scatter,
    /// Loaded measurements (F > 0) less the parameters the residuals depend on: 0 when the
    /// curve passes through every point, and then the scatter is unknown.
    pub degrees_of_freedom: usize,
    /// Correlation coefficient of the mu and K_T estimates, cov_12 / sqrt(cov_11 cov_22), when both
    /// have a standard error.
    pub correlation: Option<f64>,
    /// Number of measurements.
    pub points: usize,
    /// Measurements above the fitted F_1.
    pub beyond_first_macroslip: usize,
    /// F_thre (beams) or F_gross (lap joint) at the fitted mu (N): where everything slides under
    /// Coulomb.
    pub threshold_force: f64,
    /// F_1 at the fitted mu and K_T (N).
    pub first_macroslip_force: f64,
}

/// Estimates, standard errors, their correlation and identifiability at the optimum.
pub(super) fn summarize(problem: &Problem, refined: &Refined, weights: Weights) -> FitResult {
    let Refined {
        theta,
        sse,
        normal,
        residuals,
    } = refined;
    let (theta, sse) = (theta.as_slice(), *sse);
    let (mu, kt) = problem.unpack(theta);
    let n = problem.data.len();
    let free = theta.len();
    // A parameter the residuals do not depend on at all (mu when every F is below F_1) has a zero
    // Jacobian column; it is left out so that the other's error is still computed.
    let scale = (0..free).map(|i| normal[i][i]).fold(0.0, f64::max);
    let informative: Vec<usize> = (0..free)
        .filter(|&i| normal[i][i] > 1e-20 * scale && normal[i][i] > 0.0)
        .collect();
    // The degrees of freedom: loaded measurements (at F = 0 every mu and K_T give 0, so such a
    // row constrains nothing) less the parameters the residuals depend on.
    let loaded = problem.data.iter().filter(|m| m.force > 0.0).count();
    let dof = loaded.saturating_sub(informative.len());
    // The reduced chi-square: the common factor of the sigmas squared, when it is unknown; with
    // no degree of freedom it is unknown too (None), not 0.
    let reduced_chi_square = (dof > 0).then(|| sse / dof as f64);
    let exact = !weights.known() && reduced_chi_square.is_none();
    let variance = if weights.known() {
        1.0
    } else {
        reduced_chi_square.unwrap_or(f64::NAN)
    };
    let mut reduced = [[0.0; MAX_FREE]; MAX_FREE];
    for (row, &i) in reduced.iter_mut().zip(&informative) {
        for (entry, &j) in row.iter_mut().zip(&informative) {
            *entry = normal[i][j];
        }
    }
    let covariance = small::scaled_inverse(&reduced, informative.len(), variance);
    let log_errors: Vec<Option<f64>> = (0..free)
        .map(|i| {
            let k = informative.iter().position(|&j| j == i)?;
            covariance.as_ref().map(|c| c[k][k].max(0.0).sqrt())
        })
        .collect();
    let (f_thre, f_1) = problem
        .structure
        .at(mu, kt)
        .map_or((f64::NAN, f64::NAN), |c| c.regime_forces());
    let beyond = problem.data.iter().filter(|m| m.force > f_1).count();
    let f_max = problem.data.last().map_or(0.0, |m| m.force);
    let judge = |log_error: Option<f64>, value: f64, bound: (f64, f64)| -> Estimate {
        let at_bound = value <= bound.0 * 1.0001 || value >= bound.1 / 1.0001;
        let (std_error, status, evidence) = match log_error {
            Some(_) if exact && !at_bound => (
                None,
                Status::UncertaintyUnknown,
                Evidence::NoDegreesOfFreedom {
                    points: loaded,
                    parameters: informative.len(),
                },
            ),
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
            let mut estimate = judge(next.next().flatten(), mu, problem.mu_range);
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
    // In log units as in linear ones (the delta method scales each by its value): both fitted,
    // both with an error.
    let correlation = match (&covariance, mu_estimate.std_error, kt_estimate.std_error) {
        (Some(c), Some(_), Some(_)) if informative.len() == 2 => {
            Some(c[0][1] / (c[0][0] * c[1][1]).sqrt())
        }
        _ => None,
    };
    // The RMS in mm, whatever the weights.
    let unweighted: f64 = residuals.as_ref().map_or(f64::INFINITY, |r| {
        r.iter()
            .zip(problem.sigma)
            .map(|(r, sigma)| (r * sigma).powi(2))
            .sum()
    });
    FitResult {
        mu: mu_estimate,
        kt: kt_estimate,
        rms: (unweighted / n as f64).sqrt(),
        scatter: weights.scatter(reduced_chi_square),
        degrees_of_freedom: dof,
        correlation,
        points: n,
        beyond_first_macroslip: beyond,
        threshold_force: f_thre,
        first_macroslip_force: f_1,
    }
}
