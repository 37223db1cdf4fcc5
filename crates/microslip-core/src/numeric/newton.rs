//! Load stepping and Newton iterations, shared by both finite-element models.
//!
//! Each model only says how to linearize itself at a trial displacement (residual, consistent
//! tangent, interface responses) and how to commit a converged state; the iteration, its
//! convergence test and the step cutting live here once.

use super::banded::{NotPositiveDefinite, SymmetricBand};
use super::error::NumericError;
use super::interface::Response;

/// Newton iterations allowed per load step before the step is cut, beyond those the sliding
/// front may need to cross the interface ([`solve`]).
const MAX_ITERATIONS: usize = 60;
/// Residual accepted once the set of sliding points has settled and the residual stopped falling:
/// the linear solve is then exact and what remains is round-off (near 1e-6 of the load scale for
/// finely graded meshes of stiff interfaces, whose bending terms 12 E I / l^3 are huge); this bound
/// only guards against a pathological solve.
const ROUND_OFF_TOLERANCE: f64 = 1e-4;
/// Times a failing load step may be halved.
const MAX_CUTS: u32 = 12;

/// A discretized model driven by one load parameter (tip force, pressure).
pub(crate) trait Discretized {
    /// Residual norm, relative to [`Discretized::load_scale`], that counts as converged.
    const RESIDUAL_TOLERANCE: f64;

    /// The committed load.
    fn load(&self) -> f64;

    /// The committed displacement vector.
    fn displacement(&self) -> &[f64];

    /// A force scale of the problem at `load`, for the relative residual test.
    fn load_scale(&self, load: f64) -> f64;

    /// Residual (internal minus external, zero on fixed rows), consistent tangent and interface
    /// responses at a trial displacement, from the committed interface history.
    fn linearize(
        &self,
        displacement: &[f64],
        load: f64,
    ) -> (Vec<f64>, SymmetricBand, Vec<Response>);

    /// Adopts a converged state and its interface history.
    fn commit(&mut self, displacement: Vec<f64>, responses: Vec<Response>, load: f64);

    /// Solves tangent x = rhs for a Newton step. A model whose tangent is fixed by the set of
    /// sliding points (and repeats across solves) may keep its factor instead of refactoring.
    fn solve_step(
        &self,
        tangent: SymmetricBand,
        rhs: &[f64],
        _responses: &[Response],
    ) -> Result<Vec<f64>, NotPositiveDefinite> {
        tangent.solve(rhs)
    }
}

/// Moves the load from its committed value to `target` in `steps` equal increments, halving an
/// increment whose Newton iterations fail (up to 12 times).
pub(crate) fn load_to<M: Discretized>(
    model: &mut M,
    target: f64,
    steps: usize,
) -> Result<(), NumericError> {
    if !target.is_finite() {
        return Err(NumericError::BadLoad(target));
    }
    let start = model.load();
    let steps = steps.max(1);
    for i in 1..=steps {
        step_with_cuts(
            model,
            start + (target - start) * i as f64 / steps as f64,
            MAX_CUTS,
        )?;
    }
    Ok(())
}

/// One load step; on failure (nothing is committed then) two half steps.
fn step_with_cuts<M: Discretized>(
    model: &mut M,
    target: f64,
    cuts_left: u32,
) -> Result<(), NumericError> {
    match solve(model, target) {
        Err(NumericError::NoConvergence { .. }) if cuts_left > 0 => {
            let middle = 0.5 * (model.load() + target);
            step_with_cuts(model, middle, cuts_left - 1)?;
            step_with_cuts(model, target, cuts_left - 1)
        }
        Err(NumericError::NoConvergence { load, .. }) => Err(NumericError::NoConvergence {
            load,
            cuts: MAX_CUTS,
        }),
        other => other,
    }
}

/// Newton iterations at one load level from the committed state; commits only on convergence.
fn solve<M: Discretized>(model: &mut M, load: f64) -> Result<(), NumericError> {
    let scale = model.load_scale(load);
    let mut displacement = model.displacement().to_vec();
    let mut previous_set: Option<Vec<bool>> = None;
    let mut previous_norm = f64::INFINITY;
    // From a sticking start the active set grows from the loaded end a few integration points per
    // iteration (each Newton step is exact for its set, and the next set is where that step
    // overshot mu P): on a long interface with little friction the front crosses hundreds of
    // points (the plate, mu = 0.05, L 47 mm, K_T 6e7 MPa/mm: 640 points, about 4 an iteration,
    // the step failing at 60 iterations at every load, since the plate's answer is proportional
    // to P and halving the step does not shorten the front's path). So the budget grows by one
    // iteration per point the front may cross; a set that cycles still fails, only later.
    let mut iteration = 0;
    let mut current = model.linearize(&displacement, load);
    loop {
        // A solve nobody waits for any more (the TUI moved on) stops here.
        super::cancel::checkpoint();
        let (residual, tangent, responses) = current;
        if iteration == MAX_ITERATIONS + responses.len() {
            return Err(NumericError::NoConvergence { load, cuts: 0 });
        }
        iteration += 1;
        let norm = norm_of(&residual);
        let sliding: Vec<bool> = responses.iter().map(|r| r.sliding).collect();
        // The system is linear for a fixed set of sliding points, so the Newton step taken with that
        // set is exact: an unchanged set whose residual stopped falling has converged to round-off.
        let same_set = previous_set.as_ref() == Some(&sliding);
        if norm <= M::RESIDUAL_TOLERANCE * scale
            || (same_set && norm > 0.5 * previous_norm && norm <= ROUND_OFF_TOLERANCE * scale)
        {
            model.commit(displacement, responses, load);
            return Ok(());
        }
        previous_set = Some(sliding);
        previous_norm = norm;
        let rhs: Vec<f64> = residual.iter().map(|r| -r).collect();
        let step = model
            .solve_step(tangent, &rhs, &responses)
            .map_err(|e| NumericError::Singular(e.row))?;
        (displacement, current) = damped(model, &displacement, &step, load, norm);
    }
}

/// The Euclidean norm of a residual.
fn norm_of(residual: &[f64]) -> f64 {
    residual.iter().map(|r| r * r).sum::<f64>().sqrt()
}

/// Halvings of a Newton step tried when the full step raises the residual.
const BACKTRACKS: u32 = 4;

/// The next iterate from `displacement` along the Newton `step`, with its linearization: the full
/// step, unless it raises the residual above `norm` and a step of 1/2, 1/4, ... 1/16 of it
/// lowers it, the first such. Why: the interface law is piecewise linear, and where many points
/// change state in one step the full step can overshoot back and forth across the slip front
/// until every point slides and the step fails (the plate, mu 0.05 to 0.09, K_T 2e7 to 1e8
/// MPa/mm, L 15 to 47 mm: 23 of 6 000 such plates). A shorter step that lowers the residual
/// stops the overshoot; where none does, the full step keeps the front moving, as before.
/// A converged state does not depend on the path of the iterations (each step's solution is
/// unique), only the number of iterations does.
#[allow(clippy::type_complexity)]
fn damped<M: Discretized>(
    model: &M,
    displacement: &[f64],
    step: &[f64],
    load: f64,
    norm: f64,
) -> (Vec<f64>, (Vec<f64>, SymmetricBand, Vec<Response>)) {
    let along = |fraction: f64| -> Vec<f64> {
        displacement
            .iter()
            .zip(step)
            .map(|(d, s)| d + fraction * s)
            .collect()
    };
    let full = along(1.0);
    let at_full = model.linearize(&full, load);
    if norm_of(&at_full.0) <= norm {
        return (full, at_full);
    }
    let mut fraction = 1.0;
    for _ in 0..BACKTRACKS {
        fraction *= 0.5;
        let trial = along(fraction);
        let at_trial = model.linearize(&trial, load);
        if norm_of(&at_trial.0) < norm {
            return (trial, at_trial);
        }
    }
    (full, at_full)
}
