//! The quantities of a problem's solution that a target can be set on (`solve`, the TUI's `t`):
//! one idea, one name across problems. Each problem lists the ones it has, with the names users
//! type and what they mean for it, in its [`Description`](super::Description), and computes them
//! in its folder; `study::target` works from that list and knows no problem.

/// A quantity of a problem's solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// The response the problem is benchmarked on, regularized law (mm): the beams' tip deflection
    /// w(L), the plate's end displacement u(L).
    Response,
    /// End of the microslip zone, regularized law (mm): X (beams), X_r (plate).
    MicroEnd,
    /// The response under the regularized law over that under plain Coulomb (-).
    Ratio,
    /// Length of the sliding zone from x = 0 (mm): the lap joint's a, from the inner plate's end.
    SlideFromStart,
    /// Length of the sliding zone from x = L (mm): the lap joint's d, from the covers' ends.
    SlideFromEnd,
    /// The force at which macroslip first appears (N).
    FirstMacroslipForce,
    /// Dissipation per load cycle of the current amplitude, regularized law (N mm).
    Dissipation,
    /// Equivalent damping ratio of that cycle, regularized law (-).
    DampingRatio,
}

/// One law's solution of any problem, under names that mean the same in every problem. Each
/// problem keeps its own names beside them, as its physics says them (the beams'
/// `tip_deflection`, the plate's `end_displacement`); these are what code written for any problem
/// calls.
pub trait Solution {
    /// The response the problem is benchmarked on (mm): [`Quantity::Response`].
    fn response(&self) -> f64;
    /// The regime: which zones the interface has.
    fn regime(&self) -> crate::Regime;
    /// Where the zone this law is about ends, from the problem's origin (mm): the stick zone under
    /// plain Coulomb, the microslip zone under the regularized law ([`Quantity::MicroEnd`]).
    fn zone_end(&self) -> f64;
}

/// [`Quantity::Ratio`] from the two responses: `None` where the Coulomb one is not positive (no
/// load, nothing squeezed), where a ratio means nothing.
pub(crate) fn ratio_to_coulomb(regularized: f64, coulomb: f64) -> Option<f64> {
    (coulomb > 0.0).then(|| regularized / coulomb)
}

/// A quantity as one problem names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct QuantityName {
    /// The quantity.
    pub quantity: Quantity,
    /// The name targets use and outputs print (`w(L)`, `X_r`, `ratio`).
    pub name: &'static str,
    /// Other spellings accepted when typed (`w`, `Xr`, `F1`).
    pub aliases: &'static [&'static str],
    /// What it is for this problem, in words.
    pub meaning: &'static str,
    /// Its unit for this problem (`mm`, `N`, `N mm`; empty for a ratio).
    pub unit: &'static str,
}

impl QuantityName {
    /// True when `text` is this quantity's name or one of its aliases.
    pub(crate) fn is_named(&self, text: &str) -> bool {
        self.name == text || self.aliases.contains(&text)
    }
}
