//! The least-squares search: a log grid over the free parameters for a start that does not
//! depend on the user's guess, then Levenberg-Marquardt on the weighted residuals, on ever larger
//! evenly spread subsamples of a long curve.

use super::progress::{PROGRESS_EVERY, Pass, Progress};
use super::small::{self, MAX_FREE, Matrix, Vector};
use super::structure::Structure;
use super::{KT_RANGE, Measurement};
use crate::numeric::cancel::checkpoint;
use crate::problems::fittable::FitCurve;

/// Grid points per decade of the bracketing search.
const GRID_PER_DECADE: f64 = 4.0;
/// Above this many measurements, the grid search and a first refinement use this many of them,
/// spread evenly over the rows (so over the curve as sampled), and the refinement goes on with
/// [`LADDER`] times more at each level until it runs on all of them. Up to this many, everything
/// uses all of them.
pub(super) const SUBSAMPLE: usize = 1024;
/// Growth of the subsample from one refinement to the next. The start of each level is a fit to
/// the previous level's points, off by about sqrt(LADDER) of its own standard errors, which
/// Gauss-Newton closes in two steps: three passes over a million rows (each evaluating the model
/// three times per row), where the grid alone used to evaluate it 784 times per row.
pub(super) const LADDER: usize = 32;
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

/// The fit problem: structure fixed, mu and K_T free unless fixed, in log units.
pub(super) struct Problem<'a> {
    pub(super) structure: Structure,
    /// The mu searched: [`MU_RANGE`], from above the smallest mu that carries every measured force
    /// for the lap joint (its F_gross = 2 b mu P L grows with mu).
    pub(super) mu_range: (f64, f64),
    pub(super) data: &'a [Measurement],
    /// The sigma of each measurement ([`Weights::sigmas`]): residuals are divided by it.
    pub(super) sigma: &'a [f64],
    pub(super) fixed_mu: Option<f64>,
    pub(super) fixed_kt: Option<f64>,
}

impl Problem<'_> {
    /// (mu, K_T) from the free log-parameters.
    pub(super) fn unpack(&self, theta: &[f64]) -> (f64, f64) {
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
    fn curve_at(&self, theta: &[f64]) -> Option<Box<dyn FitCurve>> {
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
            // A caller that cancels the fit (the Python face's Ctrl-C, a UI worker) stops it at
            // the next measurement: one point of a slow structure (the cylinder's collocation)
            // takes milliseconds, a progress tick's PROGRESS_EVERY of them a minute.
            checkpoint();
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
            checkpoint();
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
    ) -> (Matrix, Vector) {
        let free = theta.len();
        let shifted: [Option<Box<dyn FitCurve>>; MAX_FREE] = std::array::from_fn(|j| {
            (j < free)
                .then(|| {
                    let mut moved = theta.to_vec();
                    moved[j] += JACOBIAN_STEP;
                    self.curve_at(&moved)
                })
                .flatten()
        });
        let mut normal = [[0.0; MAX_FREE]; MAX_FREE];
        let mut gradient = [0.0; MAX_FREE];
        let mut row = [0.0; MAX_FREE];
        for (i, ((m, sigma), &r)) in self.data.iter().zip(self.sigma).zip(base).enumerate() {
            if i % PROGRESS_EVERY == 0 {
                tick(i);
            }
            checkpoint();
            for (entry, curve) in row.iter_mut().zip(&shifted).take(free) {
                *entry = match curve.as_ref().and_then(|c| c.response(m.force)) {
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

    pub(super) fn bounds(&self) -> Vec<(f64, f64)> {
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
pub(super) fn grid(bounds: (f64, f64)) -> Vec<f64> {
    let decades = (bounds.1 - bounds.0) / std::f64::consts::LN_10;
    let n = (decades * GRID_PER_DECADE).ceil().max(1.0) as usize;
    (0..=n)
        .map(|i| bounds.0 + (bounds.1 - bounds.0) * i as f64 / n as f64)
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

/// Where the refinement ended: the parameters, their (weighted) sum of squares, the normal matrix
/// and the weighted residuals there (None when the start was outside the valid domain).
pub(super) struct Refined {
    pub(super) theta: Vec<f64>,
    pub(super) sse: f64,
    pub(super) normal: Matrix,
    pub(super) residuals: Option<Vec<f64>>,
}

/// The best node of a log grid over every free parameter (odometer order; the first of equals).
pub(super) fn bracket(
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
pub(super) fn refine(
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
            normal: [[0.0; MAX_FREE]; MAX_FREE],
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
        if predict && let Some(step) = small::solve(&small::damped(&normal, 0.0), &gradient, free) {
            let trial = clamped(&theta, &step, bounds);
            let delta: Vec<f64> = trial.iter().zip(&theta).map(|(t, s)| t - s).collect();
            if small::predicted_decrease(&normal, &gradient, &delta) <= CONVERGED * sse + floor {
                break;
            }
        }
        let mut improved = false;
        let mut moved = false;
        while damping < 1e12 {
            let Some(step) = small::solve(&small::damped(&normal, damping), &gradient, free) else {
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
                let largest = step[..free].iter().map(|s| s.abs()).fold(0.0, f64::max);
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
pub(super) fn spread(len: usize, count: usize) -> impl Iterator<Item = usize> {
    (0..count).map(move |i| {
        if count < 2 {
            0
        } else {
            ((i as f64) * (len - 1) as f64 / (count - 1) as f64).round() as usize
        }
    })
}
