//! The cross-check capability: a problem whose closed forms can be compared with its own
//! independent discretized solver (its `discretized.rs`, which never sees a closed form) over a
//! grid that spans every regime and the transitions between them. `crate::verify` runs the
//! comparison once for every problem that has it (the `cross_checked` slot of its
//! [`Problem::FACES`]); each problem
//! writes in its folder its grid, what it compares and how a case is written for people.

use std::fmt::Debug;

use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Problem;
use crate::problems::inputs::Model;
use crate::problems::problem::Registered;

/// What `verify` needs of a problem (module docs).
pub trait CrossChecked: Problem + Registered {
    /// What is compared, with its unit (`beam w(L) (mm)`): the verify table's first column, in
    /// the order of [`CrossChecked::compare`]'s errors.
    const COMPARED: &'static [&'static str];

    /// The models of the grid, in the order they are compared: one geometry unless `full`.
    fn grid(full: bool) -> Vec<Self::Model>;

    /// Solves `model` with the discretized solver on `density` and gives the relative error of
    /// each quantity of [`CrossChecked::COMPARED`] against the closed form.
    ///
    /// # Errors
    /// The [`NumericError`] of a solve that fails.
    fn compare(model: &Self::Model, density: MeshDensity) -> Result<Vec<f64>, NumericError>;

    /// Every parameter of `model` on one line, with units, so that the case can be rerun.
    fn describe(model: &Self::Model) -> String;
}

/// |a - b| / |b|, or |a| when b is 0: the relative error every comparison reports.
pub fn relative_error(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// The [`CrossChecked`] capability of a problem, erased: models are the [`Model`] enum, and
/// every method that takes one answers `None` for another problem's model.
pub trait AnyCrossChecked: Send + Sync {
    /// [`CrossChecked::COMPARED`].
    fn compared(&self) -> &'static [&'static str];
    /// [`CrossChecked::grid`].
    fn grid(&self, full: bool) -> Vec<Model>;
    /// [`CrossChecked::compare`].
    fn compare(
        &self,
        model: &Model,
        density: MeshDensity,
    ) -> Option<Result<Vec<f64>, NumericError>>;
    /// [`CrossChecked::describe`].
    fn describe(&self, model: &Model) -> Option<String>;
}

/// The [`AnyCrossChecked`] of a [`CrossChecked`] problem `P`: what its
/// [`Problem::FACES`] holds.
pub struct CrossCheckedOf<P>(std::marker::PhantomData<P>);

impl<P> Debug for CrossCheckedOf<P> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("CrossCheckedOf")
    }
}

impl<P> CrossCheckedOf<P> {
    /// The erased cross-check of `P`.
    pub const NEW: CrossCheckedOf<P> = CrossCheckedOf(std::marker::PhantomData);
}

impl<P: CrossChecked> AnyCrossChecked for CrossCheckedOf<P> {
    fn compared(&self) -> &'static [&'static str] {
        P::COMPARED
    }

    fn grid(&self, full: bool) -> Vec<Model> {
        P::grid(full).into_iter().map(P::to_model).collect()
    }

    fn compare(
        &self,
        model: &Model,
        density: MeshDensity,
    ) -> Option<Result<Vec<f64>, NumericError>> {
        Some(P::compare(&P::from_model(model)?, density))
    }

    fn describe(&self, model: &Model) -> Option<String> {
        Some(P::describe(&P::from_model(model)?))
    }
}
