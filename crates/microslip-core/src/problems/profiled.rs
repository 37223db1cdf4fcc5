//! Profiles along the interface at one state: what the charts draw against x and the TUI's
//! shear pane shows. Each problem writes its [`Profiled`] impl in its folder's `profiles.rs`
//! (with any profile of its own, such as the lap joint's slip).

use crate::problems::Problem;

/// One profile along the interface under both laws: (Coulomb, regularized), each a list of
/// (x (mm), value).
pub type LawProfiles = (Vec<(f64, f64)>, Vec<(f64, f64)>);

/// A problem whose interface shear is known along it (module docs).
pub trait Profiled: Problem {
    /// Interface shear tau (MPa) at each of `positions` (mm from x = 0): (Coulomb, regularized).
    fn shear_along(model: &Self::Model, positions: impl Iterator<Item = f64>) -> LawProfiles;
}

/// The values of `coulomb` and `regularized` at each position: (Coulomb, regularized).
pub fn both_along(
    positions: impl Iterator<Item = f64>,
    coulomb: impl Fn(f64) -> f64,
    regularized: impl Fn(f64) -> f64,
) -> LawProfiles {
    positions
        .map(|x| ((x, coulomb(x)), (x, regularized(x))))
        .unzip()
}
