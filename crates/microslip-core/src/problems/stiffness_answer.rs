//! What a K_T does to a problem: the numbers the K_T comparison (`crate::study::candidates`,
//! the `kt` report and the TUI's K_T table) shows for each candidate stiffness. Each problem
//! writes its [`StiffnessAnswer`] in its folder; the comparison holds the answers of every
//! problem in one enum generated from the registry.

use std::fmt::Debug;

use crate::problems::Problem;

/// What a K_T does to a problem's model (module docs).
pub trait StiffnessAnswer: Problem {
    /// The numbers one candidate K_T gives: the response, the regime and what locates it.
    type Answer: Debug + Clone + Copy + PartialEq;

    /// What `kt` (MPa/mm) does to `model`, all else (the force included) as it is; `None` for a
    /// K_T the model refuses.
    fn answer(model: &Self::Model, kt: f64) -> Option<Self::Answer>;

    /// The displacement the benchmark compares (mm): the beams' w(L), the plate's u(L), the lap
    /// joint's Delta.
    fn answer_response(answer: &Self::Answer) -> f64;

    /// The same displacement under plain Coulomb friction (K_T -> infinity), at `model`'s
    /// state: what the `vs Coulomb` column divides by.
    fn coulomb_response(model: &Self::Model) -> f64;
}
