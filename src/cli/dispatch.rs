//! [`for_problem`]: a command written once, generic over the problem's type, run for the
//! problem of a [`ModelKind`]. The one `match` on a kind the command line has is generated here
//! from the registry (`microslip_core::with_problems!`), so that the handlers name no problem
//! and a new problem reaches every command through its faces and its registry line.

use super::*;
use crate::fe::face::Deck;
use crate::report::compare::CompareFace;
use crate::report::face::ReportFace;

/// Everything a command may ask of any problem: its reports ([`ReportFace`]), its FE deck
/// ([`Deck`]) and its comparison ([`CompareFace`]). What only some problems have is reached through an erased, optional capability
/// of these (`ReportFace::cycle`), never by naming the problems that have it.
pub(super) trait Faces: ReportFace + Deck + CompareFace {}

impl<P: ReportFace + Deck + CompareFace> Faces for P {}

/// A command's body for one problem `P`, given its arguments as `self`.
pub(super) trait ForProblem {
    /// What the command gives back.
    type Output;

    /// Runs the command for the problem `P`.
    fn run<P: Faces>(self) -> Self::Output;
}

/// Writes [`for_problem`] from the registry: one arm per problem, none by hand.
macro_rules! for_problems {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// Runs `command` for the problem `kind`, typed.
        pub(super) fn for_problem<C: ForProblem>(kind: ModelKind, command: C) -> C::Output {
            match kind {
                $(ModelKind::$variant => command.run::<crate::problems::$folder::$problem>()),+
            }
        }
    };
}

microslip_core::with_problems!(for_problems);
