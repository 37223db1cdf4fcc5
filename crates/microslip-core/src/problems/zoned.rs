//! The interface's layout at one state, as data: under each law, the stretch that holds (sticks
//! under Coulomb, slips elastically under the regularized law) and the sliding beyond it, with the
//! names of the stretch's edges. `crate::study::zones` turns it into the zone strip the TUI draws,
//! written once for every problem; each problem writes its [`Zoned`] in its folder.

use crate::kernel::regime::{Law, Regime};
use crate::problems::Problem;
use crate::problems::inputs::Model;
use crate::problems::problem::Registered;

/// A problem whose interface, under each law, holds over one stretch and slides on either side
/// of it (module docs): the beams and the plate hold from x = 0 to their stick or microslip end,
/// the lap joint between its two sliding zones.
pub trait Zoned: Problem + Registered {
    /// The names of the holding stretch's edges, `[start, end]`, under Coulomb and under the
    /// regularized law (`X_s`, `X`, `a_C`, ...): what the strip labels a boundary inside the
    /// interface with. An edge that never lies inside (the beams' start at the clamp) may be
    /// unnamed.
    const EDGES: [[&'static str; 2]; 2];

    /// The interface's length L (mm): the beams' length, the plate's half-length, the overlap.
    fn interface_length(model: &Self::Model) -> f64;

    /// Under `law`: the regime, and the stretch `[from, to]` (mm from x = 0) that holds.
    fn holding(model: &Self::Model, law: Law) -> (Regime, [f64; 2]);
}

/// One law's layout ([`Zoned::holding`] with its edges' names).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawLayout {
    /// The regime.
    pub regime: Regime,
    /// The stretch that holds, `[from, to]` (mm).
    pub holding: [f64; 2],
    /// The names of its edges ([`Zoned::EDGES`]).
    pub edges: [&'static str; 2],
}

/// The interface's layout under both laws ([`Zoned`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// L (mm).
    pub length: f64,
    /// Coulomb's.
    pub coulomb: LawLayout,
    /// The regularized law's.
    pub regularized: LawLayout,
}

/// The layout of `model` of the problem `P`.
pub fn layout<P: Zoned>(model: &P::Model) -> Layout {
    let law = |law: Law, edges: [&'static str; 2]| {
        let (regime, holding) = P::holding(model, law);
        LawLayout {
            regime,
            holding,
            edges,
        }
    };
    Layout {
        length: P::interface_length(model),
        coulomb: law(Law::Coulomb, P::EDGES[0]),
        regularized: law(Law::Regularized, P::EDGES[1]),
    }
}

/// The layout of `model` of the problem `P`, erased: `None` for another problem's model. What
/// `P` puts in its [`ProblemFaces::zoned`](crate::problems::problem::ProblemFaces::zoned).
pub fn erased_layout<P: Zoned>(model: &Model) -> Option<Layout> {
    Some(layout::<P>(&P::from_model(model)?))
}
