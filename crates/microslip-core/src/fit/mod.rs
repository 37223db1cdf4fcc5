//! Identification of mu and K_T from a measured twin-beam deflection curve w(L) vs F.
//!
//! The paper's practical point (its section 2.1.3): below F_1 the whole interface is in microslip and
//! w depends on K_T but not on mu; past F_1 the slope changes (towards the Coulomb slip slope, which
//! carries mu). So K_T comes from the curve's stiffness, mu from where and how the slope changes.
//!
//! Method: nonlinear least squares on the closed form, in log-parameters (both must stay positive and
//! span decades). A coarse grid over both (the bracket) gives a start that does not depend on the
//! user's guess, then Levenberg-Marquardt refines it. The residuals are weighted by what the
//! scatter of each measurement is assumed to be ([`Weights`]: absolute, relative to w, or given per
//! point); standard errors and the mu-K_T correlation come from the Jacobian at the optimum
//! ((J^T W J)^-1, times the reduced chi-square unless the sigmas are known; delta method back to
//! linear units; derived in docs/theory.md).
//!
//! Cost: the model takes well under a microsecond per point, and a long curve (a million rows) is
//! fitted in seconds. Above 1024 rows the grid and the first refinements run on evenly spread
//! subsamples (32 times larger at each level), so the full data are only visited by the last two
//! or three Gauss-Newton steps; the normal equations are summed point by point, never storing the
//! Jacobian. Up to 1024 rows the fit is the same computation as ever.
//! [`fit_twin_beams_with_progress`] reports how far it got, for callers that show progress. Identifiability is judged from the
//! physics first (no data beyond F_1: mu cannot be seen) and from the standard errors second.
//!
//! Results are data only: the reason behind each verdict is an [`Evidence`] carrying its numbers;
//! the words for people are written by the `report` module.

pub mod measurement;
pub mod weights;

use thiserror::Error;

pub use measurement::{MIN_ROWS, Measured, Measurement};
pub use weights::{Scatter, Weights};

use crate::kernel::params::ParamError;
use crate::problems::lap::closed_form::{LapJoint, LapParams};
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
    /// Given standard deviations that cannot weigh the measurements.
    #[error("invalid sigma: {0}")]
    Sigma(String),
    /// Every measured response is 0: no displacement under load, which no finite K_T gives, so
    /// there is nothing to fit (a column of zeros is a file or unit mistake, not a measurement).
    #[error(
        "every {column} is 0 mm: nothing to fit (a curve without displacement under load has no \
         finite K_T and shows no mu; check the column and its unit)"
    )]
    NothingToFit {
        /// The response column (`w_mm`, `Delta_mm`).
        column: &'static str,
    },
    /// (Lap joint) A measured force beyond the gross-slip force of every mu searched: no state
    /// of the joint carries it.
    #[error(
        "invalid F_N = {force}: beyond the gross-slip force 2 b mu P L of every mu up to {} \
         ({largest} N): the joint slides through, so no mu fits it",
        MU_RANGE.1
    )]
    BeyondGrossSlip {
        /// The largest measured force (N).
        force: f64,
        /// F_gross at the largest mu searched (N).
        largest: f64,
    },
}

/// Progress of a fit, for a caller that wants to show it (the library prints nothing): reported
/// per grid node and every few thousand measurements of a pass over the data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Progress {
    /// The grid search for a start on `points` measurements (an evenly spread subsample when there
    /// are many): `done` of `total` grid nodes evaluated.
    Bracket {
        /// Grid nodes evaluated.
        done: usize,
        /// Grid nodes in all.
        total: usize,
        /// Measurements the grid search uses.
        points: usize,
    },
    /// Levenberg-Marquardt iteration `iteration` (from 1) on `points` measurements (evenly spread
    /// subsamples first when there are many, then all of them): `done` of them evaluated in the
    /// current `pass`.
    Refine {
        /// Iteration, from 1 for each set of points.
        iteration: usize,
        /// Measurements this refinement uses.
        points: usize,
        /// What the current pass over them computes.
        pass: Pass,
        /// Measurements evaluated in the current pass.
        done: usize,
    },
}

/// One pass of a refinement over its measurements.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pass {
    /// The residuals at the start.
    Residuals,
    /// The derivatives (normal equations) where the fit is.
    Derivatives,
    /// The residuals of a trial step.
    Step,
}

/// Measurements evaluated between two progress reports.
const PROGRESS_EVERY: usize = 1 << 14;
/// Above this many measurements, the grid search and a first refinement use this many of them,
/// spread evenly over the rows (so over the curve as sampled), and the refinement goes on with
/// [`LADDER`] times more at each level until it runs on all of them. Up to this many, everything
/// uses all of them.
const SUBSAMPLE: usize = 1024;
/// Growth of the subsample from one refinement to the next. The start of each level is a fit to
/// the previous level's points, off by about sqrt(LADDER) of its own standard errors, which
/// Gauss-Newton closes in two steps: three passes over a million rows (each evaluating the model
/// three times per row), where the grid alone used to evaluate it 784 times per row.
const LADDER: usize = 32;
/// Forward-difference step of the Jacobian, in log units.
const JACOBIAN_STEP: f64 = 1e-6;
/// Refinement stops when the Gauss-Newton step predicts a decrease of the sum of squares below this
/// fraction of it (plus the floor below): the same relative gain below which a step no longer
/// counts as an improvement. From a nearby start (the previous level's fit) Gauss-Newton converges
/// quadratically, so this costs one pass more than a looser limit would and leaves nothing to gain.
const CONVERGED: f64 = 1e-15;
/// ...or below the sum of squares of residuals this fraction of the largest deflection: a change no
/// measurement can show, and the round-off level of noise-free data.
const RESIDUAL_FLOOR: f64 = 1e-12;
/// Most Levenberg-Marquardt iterations.
const MAX_ITERATIONS: usize = 200;

/// What is fitted: a problem with a load-response curve, its structure (all but mu and K_T) fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Structure {
    /// Twin beams: w(L) against the tip force.
    Beam(TwinBeamsParams),
    /// The lap joint: Delta against the force through it (a force beyond F_gross at a trial mu
    /// has no state there: that mu is outside the fit's domain).
    Lap(LapParams),
}

/// The structure at one (mu, K_T): its response at a force, and the forces where it changes
/// regime.
#[derive(Debug, Clone, Copy)]
enum Curve {
    Beam(TwinBeams),
    Lap(LapJoint),
}

impl Structure {
    /// The structure at `mu`, `kt`; None where they (or the structure) are not accepted.
    fn at(&self, mu: f64, kt: f64) -> Option<Curve> {
        match *self {
            Structure::Beam(structure) => TwinBeams::new(TwinBeamsParams {
                friction: mu,
                tangential_stiffness: kt,
                ..structure
            })
            .ok()
            .map(Curve::Beam),
            Structure::Lap(structure) => LapJoint::new(LapParams {
                friction: mu,
                tangential_stiffness: kt,
                ..structure
            })
            .ok()
            .map(Curve::Lap),
        }
    }

    /// The header of its response column in a measurement file.
    fn response_column(&self) -> &'static str {
        match self {
            Structure::Beam(_) => "w_mm",
            Structure::Lap(_) => "Delta_mm",
        }
    }

    /// The structure's own mu and K_T.
    fn own(&self) -> (f64, f64) {
        match self {
            Structure::Beam(p) => (p.friction, p.tangential_stiffness),
            Structure::Lap(p) => (p.friction, p.tangential_stiffness),
        }
    }
}

impl Curve {
    /// The regularized response at `force` (mm); None for a force the structure does not accept.
    fn response(&self, force: f64) -> Option<f64> {
        match self {
            Curve::Beam(beams) => Some(
                beams
                    .regularized(TipForce::new(force).ok()?)
                    .tip_deflection(),
            ),
            Curve::Lap(joint) => Some(
                joint
                    .regularized(joint.force(force).ok()?)
                    .joint_displacement(),
            ),
        }
    }

    /// (the force above which all slides under Coulomb, F_1) (N): F_thre and F_1 of the beams,
    /// F_gross and F_1 of the joint.
    fn regime_forces(&self) -> (f64, f64) {
        match self {
            Curve::Beam(beams) => (beams.threshold_force(), beams.first_macroslip_force()),
            Curve::Lap(joint) => (joint.gross_slip_force(), joint.first_slip_force()),
        }
    }
}

/// The fit problem: structure fixed, mu and K_T free unless fixed, in log units.
struct Problem<'a> {
    structure: Structure,
    /// The mu searched: [`MU_RANGE`], from above the smallest mu that carries every measured force
    /// for the lap joint (its F_gross = 2 b mu P L grows with mu).
    mu_range: (f64, f64),
    data: &'a [Measurement],
    /// The sigma of each measurement ([`Weights::sigmas`]): residuals are divided by it.
    sigma: &'a [f64],
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

    /// The structure at the log-parameters `theta`.
    fn curve_at(&self, theta: &[f64]) -> Option<Curve> {
        let (mu, kt) = self.unpack(theta);
        self.structure.at(mu, kt)
    }

    /// Weighted residuals (model - measured) / sigma; None for parameters outside the valid
    /// domain. `tick` gets the number of measurements done, at the start and every
    /// [`PROGRESS_EVERY`].
    fn residuals(&self, theta: &[f64], tick: &mut dyn FnMut(usize)) -> Option<Vec<f64>> {
        let curve = self.curve_at(theta)?;
        let mut residuals = Vec::with_capacity(self.data.len());
        for (i, (m, sigma)) in self.data.iter().zip(self.sigma).enumerate() {
            if i % PROGRESS_EVERY == 0 {
                tick(i);
            }
            residuals.push((curve.response(m.force)? - m.response) / sigma);
        }
        Some(residuals)
    }

    /// The sum of squared residuals, or a partial sum of at least `limit` as soon as it gets
    /// there: the grid only asks whether a node beats the best so far, and most nodes are far off.
    fn sse_below(&self, theta: &[f64], limit: f64) -> f64 {
        let Some(curve) = self.curve_at(theta) else {
            return f64::INFINITY;
        };
        let mut sum = 0.0;
        for (m, sigma) in self.data.iter().zip(self.sigma) {
            let Some(response) = curve.response(m.force) else {
                return f64::INFINITY;
            };
            let r = (response - m.response) / sigma;
            sum += r * r;
            if sum >= limit {
                return sum;
            }
        }
        sum
    }

    /// The weighted normal equations at `theta` from forward differences: J^T W J and -J^T W r
    /// (J and r of the weighted residuals, so plain J^T J and -J^T r here), accumulated
    /// measurement by measurement (the Jacobian is never stored). `base` holds the residuals at
    /// `theta`. A parameter whose shifted value leaves the valid domain gets a zero column.
    fn normal_equations(
        &self,
        theta: &[f64],
        base: &[f64],
        tick: &mut dyn FnMut(usize),
    ) -> (Vec<Vec<f64>>, Vec<f64>) {
        let free = theta.len();
        let shifted: Vec<Option<Curve>> = (0..free)
            .map(|j| {
                let mut moved = theta.to_vec();
                moved[j] += JACOBIAN_STEP;
                self.curve_at(&moved)
            })
            .collect();
        let mut normal = vec![vec![0.0; free]; free];
        let mut gradient = vec![0.0; free];
        let mut row = vec![0.0; free];
        for (i, ((m, sigma), &r)) in self.data.iter().zip(self.sigma).zip(base).enumerate() {
            if i % PROGRESS_EVERY == 0 {
                tick(i);
            }
            for (entry, curve) in row.iter_mut().zip(&shifted) {
                *entry = match curve.and_then(|c| c.response(m.force)) {
                    Some(response) => ((response - m.response) / sigma - r) / JACOBIAN_STEP,
                    None => 0.0,
                };
            }
            for a in 0..free {
                gradient[a] -= row[a] * r;
                for b in 0..free {
                    normal[a][b] += row[a] * row[b];
                }
            }
        }
        (normal, gradient)
    }

    fn bounds(&self) -> Vec<(f64, f64)> {
        let mut b = Vec::new();
        if self.fixed_mu.is_none() {
            b.push((self.mu_range.0.ln(), self.mu_range.1.ln()));
        }
        if self.fixed_kt.is_none() {
            b.push((KT_RANGE.0.ln(), KT_RANGE.1.ln()));
        }
        b
    }

    /// The (weighted) sum of squares below which no measurement could tell two fits apart (see
    /// [`RESIDUAL_FLOOR`]).
    fn floor(&self) -> f64 {
        let scale = self
            .data
            .iter()
            .zip(self.sigma)
            .map(|(m, sigma)| (m.response / sigma).abs())
            .fold(0.0, f64::max);
        self.data.len() as f64 * (RESIDUAL_FLOOR * scale).powi(2)
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

/// The normal matrix with its diagonal scaled by 1 + `damping` (Levenberg-Marquardt).
fn damped(normal: &[Vec<f64>], damping: f64) -> Vec<Vec<f64>> {
    normal
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
        .collect()
}

/// `theta + step`, kept inside `bounds`.
fn clamped(theta: &[f64], step: &[f64], bounds: &[(f64, f64)]) -> Vec<f64> {
    theta
        .iter()
        .zip(step)
        .zip(bounds)
        .map(|((t, s), b)| (t + s).clamp(b.0, b.1))
        .collect()
}

/// The decrease of the sum of squares that the linearized model predicts for moving by `delta`:
/// 2 delta . g - delta^T N delta, with g = -J^T r.
fn predicted_decrease(normal: &[Vec<f64>], gradient: &[f64], delta: &[f64]) -> f64 {
    let mut decrease = 0.0;
    for (i, &di) in delta.iter().enumerate() {
        decrease += 2.0 * di * gradient[i];
        for (j, &dj) in delta.iter().enumerate() {
            decrease -= di * normal[i][j] * dj;
        }
    }
    decrease
}

/// Where the refinement ended: the parameters, their (weighted) sum of squares, the normal matrix
/// and the weighted residuals there (None when the start was outside the valid domain).
struct Refined {
    theta: Vec<f64>,
    sse: f64,
    normal: Vec<Vec<f64>>,
    residuals: Option<Vec<f64>>,
}

/// The best node of a log grid over every free parameter (odometer order; the first of equals).
fn bracket(
    problem: &Problem,
    bounds: &[(f64, f64)],
    progress: &mut dyn FnMut(Progress),
) -> Vec<f64> {
    let free = bounds.len();
    let mut theta: Vec<f64> = bounds.iter().map(|b| 0.5 * (b.0 + b.1)).collect();
    let mut best = problem.sse_below(&theta, f64::INFINITY);
    let axes: Vec<Vec<f64>> = bounds.iter().map(|&b| grid(b)).collect();
    let total = axes.iter().map(Vec::len).product();
    let mut index = vec![0usize; free];
    let mut done = 0;
    loop {
        let candidate: Vec<f64> = index.iter().zip(&axes).map(|(&i, axis)| axis[i]).collect();
        let sse = problem.sse_below(&candidate, best);
        if sse < best {
            best = sse;
            theta = candidate;
        }
        done += 1;
        progress(Progress::Bracket {
            done,
            total,
            points: problem.data.len(),
        });
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
    theta
}

/// Levenberg-Marquardt from `theta` until the Gauss-Newton step predicts no decrease that matters
/// ([`CONVERGED`]), no step improves the fit any more, or [`MAX_ITERATIONS`].
fn refine(
    problem: &Problem,
    mut theta: Vec<f64>,
    bounds: &[(f64, f64)],
    progress: &mut dyn FnMut(Progress),
) -> Refined {
    let free = theta.len();
    let points = problem.data.len();
    let mut iteration = 1;
    let mut tick = |iteration: usize, pass: Pass, done: usize| {
        progress(Progress::Refine {
            iteration,
            points,
            pass,
            done,
        })
    };
    let Some(mut base) =
        problem.residuals(&theta, &mut |done| tick(iteration, Pass::Residuals, done))
    else {
        return Refined {
            theta,
            sse: f64::INFINITY,
            normal: vec![vec![0.0; free]; free],
            residuals: None,
        };
    };
    let mut sse: f64 = base.iter().map(|r| r * r).sum();
    let (mut normal, mut gradient) = problem.normal_equations(&theta, &base, &mut |done| {
        tick(iteration, Pass::Derivatives, done)
    });
    let floor = problem.floor();
    let mut damping = 1e-3;
    // Up to SUBSAMPLE points a pass is cheap, and the refinement stops as it always did: when no
    // step improves the fit by a relative 1e-15 any more. Beyond, each rejected trial at the optimum
    // would cost a pass over every point; there the Gauss-Newton prediction says when to stop.
    let predict = points > SUBSAMPLE;
    while free > 0 && iteration <= MAX_ITERATIONS {
        // Converged: even the full Gauss-Newton step promises nothing measurable.
        if predict && let Some(step) = solve_small(&damped(&normal, 0.0), &gradient) {
            let trial = clamped(&theta, &step, bounds);
            let delta: Vec<f64> = trial.iter().zip(&theta).map(|(t, s)| t - s).collect();
            if predicted_decrease(&normal, &gradient, &delta) <= CONVERGED * sse + floor {
                break;
            }
        }
        let mut improved = false;
        let mut moved = false;
        while damping < 1e12 {
            let Some(step) = solve_small(&damped(&normal, damping), &gradient) else {
                damping *= 10.0;
                continue;
            };
            let trial = clamped(&theta, &step, bounds);
            let residuals =
                problem.residuals(&trial, &mut |done| tick(iteration, Pass::Step, done));
            let trial_sse = residuals
                .as_ref()
                .map_or(f64::INFINITY, |r| r.iter().map(|x| x * x).sum());
            if trial_sse < sse
                && let Some(residuals) = residuals
            {
                let gain = (sse - trial_sse) / sse.max(f64::MIN_POSITIVE);
                let largest = step.iter().map(|s| s.abs()).fold(0.0, f64::max);
                theta = trial;
                sse = trial_sse;
                base = residuals;
                damping = (damping / 10.0).max(1e-12);
                improved = gain > 1e-15 && largest > 1e-12;
                moved = true;
                break;
            }
            damping *= 10.0;
        }
        if moved {
            // The normal equations where the fit now is: for the next step, or for the errors.
            (normal, gradient) = problem.normal_equations(&theta, &base, &mut |done| {
                tick(iteration, Pass::Derivatives, done)
            });
        }
        if !improved {
            break;
        }
        iteration += 1;
    }
    Refined {
        theta,
        sse,
        normal,
        residuals: Some(base),
    }
}

/// Every `len / count`-th index, first and last included: `count` rows spread evenly.
fn spread(len: usize, count: usize) -> impl Iterator<Item = usize> {
    (0..count).map(move |i| {
        if count < 2 {
            0
        } else {
            ((i as f64) * (len - 1) as f64 / (count - 1) as f64).round() as usize
        }
    })
}

/// Fits mu and K_T (each unless fixed) of twin beams with the geometry, E and P of `structure` to
/// a w(L) vs F curve, every point weighed alike ([`Weights::Absolute`]). The structure's own mu and
/// K_T are not used as a start: the grid is.
///
/// Equal weights are right for a curve whose error does not grow with w, such as a model's
/// mismatch to another model; measured curves usually scatter in proportion to w: fit them with
/// [`fit_twin_beams_weighted`] and [`Weights::default`] (relative), or with their own sigmas.
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
/// use microslip_core::fit::{Measurement, Status, fit_twin_beams};
/// use microslip_core::{TipForce, TwinBeams, TwinBeamsParams};
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
///         Ok(Measurement { force, response: w })
///     })
///     .collect::<Result<_, microslip_core::ParamError>>()?;
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
    fit_twin_beams_with_progress(structure, data, fixed_mu, fixed_kt, &mut |_| {})
}

/// [`fit_twin_beams`], telling `progress` how far it got (see [`Progress`]); the result is the same.
/// [`fit_twin_beams_weighted`] with [`Weights::Absolute`].
///
/// A million measurements take a few seconds: the grid search and a first refinement run on an
/// evenly spread subsample of a few thousand rows, and the refinement finishes on all of them,
/// where it typically needs one or two steps.
///
/// # Errors
///
/// As [`fit_twin_beams`].
///
/// # Examples
///
/// ```
/// use microslip_core::fit::{Measurement, Progress, fit_twin_beams_with_progress};
/// use microslip_core::TwinBeamsParams;
///
/// let data: Vec<Measurement> = (1..=20)
///     .map(|i| Measurement { force: 10.0 * f64::from(i), response: 4e-4 * f64::from(i) })
///     .collect();
/// let mut grid_nodes = 0;
/// let fit = fit_twin_beams_with_progress(TwinBeamsParams::PAPER, &data, None, None, &mut |p| {
///     if let Progress::Bracket { done, .. } = p {
///         grid_nodes = done;
///     }
/// })?;
/// assert!(grid_nodes > 100);
/// assert_eq!(fit.points, 20);
/// # Ok::<(), microslip_core::fit::FitError>(())
/// ```
pub fn fit_twin_beams_with_progress(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    fit_twin_beams_weighted(
        structure,
        data,
        fixed_mu,
        fixed_kt,
        Weights::Absolute,
        progress,
    )
}

/// [`fit_twin_beams_with_progress`] with the measurements weighed by `weights`: what their scatter
/// is assumed to be, which the standard errors and the correlation depend on (see [`Weights`]).
///
/// # Errors
///
/// As [`fit_twin_beams`], and [`FitError::Sigma`] when `weights` gives sigmas that are not one
/// positive finite value per measurement.
///
/// # Examples
///
/// A curve with 1 % scatter: relative weights state errors that match the scatter of refits (the
/// `fit` test `stated_errors_match_the_scatter_of_repeated_fits`), and the correlation of the two
/// estimates.
///
/// ```
/// use microslip_core::fit::{Measurement, Scatter, Weights, fit_twin_beams_weighted};
/// use microslip_core::{TipForce, TwinBeams, TwinBeamsParams};
///
/// let truth = TwinBeams::new(TwinBeamsParams {
///     friction: 0.22,
///     tangential_stiffness: 300.0,
///     ..TwinBeamsParams::PAPER
/// })?;
/// // Alternately 1 % high and 1 % low.
/// let data: Vec<Measurement> = (0..=60)
///     .map(|i| {
///         let force = 5.0 * f64::from(i);
///         let w = truth.regularized(TipForce::new(force)?).tip_deflection();
///         let deflection = w * if i % 2 == 0 { 1.01 } else { 0.99 };
///         Ok(Measurement { force, response: deflection })
///     })
///     .collect::<Result<_, microslip_core::ParamError>>()?;
/// let fit = fit_twin_beams_weighted(
///     TwinBeamsParams::PAPER, &data, None, None, Weights::Relative, &mut |_| {},
/// )?;
/// let Scatter::Relative { fraction: Some(fraction) } = fit.scatter else { unreachable!() };
/// assert!((fraction - 0.01).abs() < 0.002);
/// assert!((fit.kt.value - 300.0).abs() < 3.0 * fit.kt.std_error.unwrap());
/// assert!(fit.correlation.unwrap().abs() < 1.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_twin_beams_weighted(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    fit_weighted(
        Structure::Beam(structure),
        data,
        (fixed_mu, fixed_kt),
        weights,
        progress,
    )
}

/// Fits mu and K_T (each unless `fixed`, (mu, K_T)) of any [`Structure`] to its measured
/// load-response curve, as [`fit_twin_beams_weighted`] does for the beams: the lap joint's Delta
/// against F (docs/theory.md (L11) and section 3b).
///
/// # Errors
/// As [`fit_twin_beams_weighted`]; for the joint also a fixed mu or the structure's own at which
/// the largest measured force exceeds F_gross.
pub fn fit_weighted(
    structure: Structure,
    data: &[Measurement],
    (fixed_mu, fixed_kt): (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    // Validate the structure and any fixed values through the model's own constructor.
    let (own_mu, own_kt) = structure.own();
    let (mu, kt) = (fixed_mu.unwrap_or(own_mu), fixed_kt.unwrap_or(own_kt));
    match structure {
        Structure::Beam(p) => {
            TwinBeams::new(TwinBeamsParams {
                friction: mu,
                tangential_stiffness: kt,
                ..p
            })?;
        }
        Structure::Lap(p) => {
            let joint = LapJoint::new(LapParams {
                friction: mu,
                tangential_stiffness: kt,
                ..p
            })?;
            // A fixed mu must carry every measured force.
            if fixed_mu.is_some()
                && let Some(largest) = data.iter().map(|m| m.force).reduce(f64::max)
            {
                joint.force(largest)?;
            }
        }
    }
    // The lap joint carries no force beyond F_gross = 2 b mu P L: mu is searched only where it
    // carries every measured force (a fit on that bound is reported as at the search bound).
    let mut mu_range = MU_RANGE;
    if let Structure::Lap(p) = structure
        && let Some(largest) = data.iter().map(|m| m.force).reduce(f64::max)
    {
        let per_mu = p.gross_slip_force() / p.friction;
        let least = largest / per_mu * (1.0 + 1e-9);
        if least > MU_RANGE.1 {
            return Err(FitError::BeyondGrossSlip {
                force: largest,
                largest: per_mu * MU_RANGE.1,
            });
        }
        mu_range.0 = mu_range.0.max(least);
    }
    let sigma = weights.sigmas(data)?;
    let problem = Problem {
        structure,
        mu_range,
        data,
        sigma: &sigma,
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
    // Relative weights would make any curve through zeros look perfect: refuse a flat zero curve.
    if data.iter().all(|m| m.response == 0.0) {
        return Err(FitError::NothingToFit {
            column: structure.response_column(),
        });
    }
    // Many measurements: the grid search on an evenly spread subsample (whose sum of squares is
    // the whole curve's in miniature), then refinements on ever larger ones, each starting from the
    // previous one's fit.
    let mut sizes = Vec::new();
    let mut size = SUBSAMPLE;
    while size < data.len() {
        sizes.push(size);
        size = size.saturating_mul(LADDER);
    }
    let mut theta = None;
    for size in sizes {
        let (sample, sample_sigma): (Vec<Measurement>, Vec<f64>) = spread(data.len(), size)
            .map(|i| (data[i], sigma[i]))
            .unzip();
        let level = Problem {
            data: &sample,
            sigma: &sample_sigma,
            ..problem
        };
        let start = match theta {
            Some(theta) => theta,
            None => bracket(&level, &bounds, progress),
        };
        theta = Some(refine(&level, start, &bounds, progress).theta);
    }
    let start = match theta {
        Some(theta) => theta,
        None => bracket(&problem, &bounds, progress),
    };
    let refined = refine(&problem, start, &bounds, progress);
    Ok(summarize(&problem, &refined, weights))
}

/// The covariance of the informative log-parameters: (J^T W J)^-1 scaled by `variance`, as
/// columns; None when singular.
fn covariance(normal: &[Vec<f64>], variance: f64) -> Option<Vec<Vec<f64>>> {
    (0..normal.len())
        .map(|k| {
            let unit: Vec<f64> = (0..normal.len())
                .map(|j| if j == k { 1.0 } else { 0.0 })
                .collect();
            solve_small(normal, &unit).map(|col| col.iter().map(|c| variance * c).collect())
        })
        .collect()
}

/// Estimates, standard errors, their correlation and identifiability at the optimum.
fn summarize(problem: &Problem, refined: &Refined, weights: Weights) -> FitResult {
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
    let scale = normal
        .iter()
        .enumerate()
        .map(|(i, row)| row[i])
        .fold(0.0, f64::max);
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
    let reduced: Vec<Vec<f64>> = informative
        .iter()
        .map(|&i| informative.iter().map(|&j| normal[i][j]).collect())
        .collect();
    let covariance = covariance(&reduced, variance);
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
        (Some(c), Some(_), Some(_)) if c.len() == 2 => Some(c[0][1] / (c[0][0] * c[1][1]).sqrt()),
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
                response: beams
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

    /// The lap joint's Delta against F, measured on a joint with mu 0.4 and K_T 2500 MPa/mm up to
    /// 0.9 F_gross: both come back from the bundled joint's wrong guesses (mu 0.3, K_T 1000), and
    /// below F_1 mu is not seen.
    #[test]
    fn a_lap_joint_curve_gives_back_its_mu_and_k_t() {
        let truth = LapJoint::new(LapParams {
            friction: 0.4,
            tangential_stiffness: 2500.0,
            ..LapParams::ALUMINIUM
        })
        .unwrap();
        let gross = truth.gross_slip_force();
        let curve = |top: f64| -> Vec<Measurement> {
            (1..=30)
                .map(|i| {
                    let force = top * f64::from(i) / 30.0;
                    let f = truth.force(force).unwrap();
                    Measurement {
                        force,
                        response: truth.regularized(f).joint_displacement(),
                    }
                })
                .collect()
        };
        let fit = fit_weighted(
            Structure::Lap(LapParams::ALUMINIUM),
            &curve(0.9 * gross),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
        .unwrap();
        assert!((fit.mu.value / 0.4 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!((fit.kt.value / 2500.0 - 1.0).abs() < 1e-6, "{fit:?}");
        assert_eq!(
            (fit.mu.status, fit.kt.status),
            (Status::Identified, Status::Identified)
        );
        assert!((fit.threshold_force / gross - 1.0).abs() < 1e-6);
        // Only microslip: K_T is seen, mu only bounded from below.
        let below = fit_weighted(
            Structure::Lap(LapParams::ALUMINIUM),
            &curve(0.9 * truth.first_slip_force()),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
        .unwrap();
        assert!((below.kt.value / 2500.0 - 1.0).abs() < 1e-6, "{below:?}");
        assert!(matches!(
            below.mu.evidence,
            Evidence::NoDataAboveFirstMacroslip { .. }
        ));
        // Forces no mu of the search carries: refused, naming the force and the largest F_gross.
        let over = [1e5, 2e5, 2.5e5].map(|force| Measurement {
            force,
            response: force * 1e-5,
        });
        let refused = fit_weighted(
            Structure::Lap(LapParams::ALUMINIUM),
            &over,
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        );
        assert_eq!(
            refused,
            Err(FitError::BeyondGrossSlip {
                force: 2.5e5,
                largest: 1e5
            })
        );
        // A fixed mu that cannot carry the largest force is refused by name.
        let refused = fit_weighted(
            Structure::Lap(LapParams::ALUMINIUM),
            &curve(0.9 * gross),
            (Some(0.1), None),
            Weights::Absolute,
            &mut |_| {},
        );
        assert!(refused.unwrap_err().to_string().contains("F_gross"));
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

    /// A curve of `n` points from 1 to 300 N with deterministic noise of +-`noise` mm.
    fn noisy(n: usize, noise: f64) -> Vec<Measurement> {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut data = synthetic(
            0.4,
            200.0,
            (0..n).map(|i| 1.0 + 299.0 * i as f64 / (n - 1) as f64),
        );
        for m in &mut data {
            // xorshift: reproducible noise without a dependency.
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            m.response += noise * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
        }
        data
    }

    #[test]
    fn progress_is_reported_and_changes_nothing() {
        let data = noisy(300, 1e-4);
        let plain = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
        let mut events = Vec::new();
        let reported =
            fit_twin_beams_with_progress(TwinBeamsParams::PAPER, &data, None, None, &mut |p| {
                events.push(p)
            })
            .unwrap();
        assert_eq!(plain, reported);
        // 16 mu nodes (1e-3 to 5) x 49 K_T nodes (1e-3 to 1e9), on all 300 points.
        assert_eq!(
            events
                .iter()
                .filter(|p| matches!(p, Progress::Bracket { .. }))
                .count(),
            16 * 49
        );
        assert!(events.contains(&Progress::Bracket {
            done: 784,
            total: 784,
            points: 300
        }));
        assert!(events.iter().any(|p| matches!(
            p,
            Progress::Refine {
                iteration: 1,
                points: 300,
                ..
            }
        )));
    }

    #[test]
    fn long_curves_visit_every_point_only_in_the_last_few_steps() {
        // 5000 points: the grid and a first refinement on 1024 of them, then all.
        let n = 5000;
        let data = noisy(n, 1e-4);
        let mut grid_points = Vec::new();
        let mut full_iterations = 0;
        let fit = fit_twin_beams_with_progress(
            TwinBeamsParams::PAPER,
            &data,
            None,
            None,
            &mut |p| match p {
                Progress::Bracket { points, .. } => grid_points.push(points),
                Progress::Refine {
                    iteration, points, ..
                } if points == n => full_iterations = full_iterations.max(iteration),
                _ => {}
            },
        )
        .unwrap();
        assert!(
            grid_points.iter().all(|&p| p == SUBSAMPLE),
            "{grid_points:?}"
        );
        assert!(
            (1..=4).contains(&full_iterations),
            "{full_iterations} iterations on every point"
        );
        // The answer is the curve's: within a few standard errors of the truth, and the same
        // (to far below a standard error) as refining on all points from the grid's start.
        for (estimate, truth) in [(&fit.mu, 0.4), (&fit.kt, 200.0)] {
            let error = estimate.std_error.unwrap();
            assert!((estimate.value - truth).abs() < 5.0 * error, "{fit:?}");
        }
        let sigma = vec![1.0; data.len()];
        let problem = Problem {
            structure: Structure::Beam(TwinBeamsParams::PAPER),
            mu_range: MU_RANGE,
            data: &data,
            sigma: &sigma,
            fixed_mu: None,
            fixed_kt: None,
        };
        let bounds = problem.bounds();
        let direct = refine(
            &problem,
            bracket(&problem, &bounds, &mut |_| {}),
            &bounds,
            &mut |_| {},
        );
        let (mu, kt) = problem.unpack(&direct.theta);
        assert!((fit.mu.value - mu).abs() < 1e-3 * fit.mu.std_error.unwrap());
        assert!((fit.kt.value - kt).abs() < 1e-3 * fit.kt.std_error.unwrap());
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
