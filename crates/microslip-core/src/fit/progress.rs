//! What a fit reports while it runs, for a caller that shows progress (the library prints
//! nothing).

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
pub(super) const PROGRESS_EVERY: usize = 1 << 14;
