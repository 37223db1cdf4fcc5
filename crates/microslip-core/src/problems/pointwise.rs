//! Everything the reports show of one solve, as one value: the row a sweep yields per sample and
//! the single-point reports read (`crate::study::curves::param_sweep`). Each problem writes its
//! point type and [`Pointwise`] impl in its folder's `point.rs`.

use crate::problems::Problem;

/// A problem whose solve the reports show as one row (module docs).
pub trait Pointwise: Problem {
    /// Everything the reports show at one state, both laws.
    type Point;

    /// The point of `model`.
    fn point(model: &Self::Model) -> Self::Point;
}
