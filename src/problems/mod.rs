//! The problems as the application sees them: the core's problems (re-exported whole, so
//! `crate::problems::...` names the same items as `microslip_core::problems::...`) and, in each
//! problem's folder here, its **faces**: how the application's layers show, report and export
//! it (its charts, its report, its FE deck), each the impl of a trait its layer defines
//! (`chart`, `report`, `fe`).
//!
//! Why a second folder per problem: the core crate knows no chart, report or deck (it depends
//! on no file format or terminal), so what a problem looks like in the application cannot live
//! in its core folder; and a chart or a deck written per problem outside a problem's folder is
//! what made a new problem cost forty files. So a problem is two folders, both named after it
//! (`crates/microslip-core/src/problems/<name>/` and `src/problems/<name>/`), and the
//! registry's one line ([`microslip_core::with_problems!`]); every layer generates its dispatch
//! over the problems from that line, never from a list of its own. A face file sits above
//! `report` and below `tui` (`tests/layering.rs`: the module `faces`): it may use any layer a
//! face is written in, and the TUI and the command line reach it only through those layers'
//! traits, never by its path.

pub use microslip_core::problems::*;

/// Declares each problem's folder of faces from the registry, so that this file lists none: each
/// folder once, however many registry lines name it (one folder may hold two problems of one
/// structure, as the press fit's will hold the push-out and the torque). `macro_rules` cannot
/// compare two identifiers, so each step defines a matcher whose rules are the folders declared
/// so far and declares the next folder only where none of them matches it.
macro_rules! face_folders {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        face_folders!(@once [] $($folder)+);
    };
    (@once [$($declared:ident)*]) => {};
    (@once [$($declared:ident)*] $folder:ident $($rest:ident)*) => {
        macro_rules! declare_unless_declared {
            $(($declared) => {};)*
            ($name:ident) => { pub mod $name; };
        }
        declare_unless_declared!($folder);
        face_folders!(@once [$($declared)* $folder] $($rest)*);
    };
}

microslip_core::with_problems!(face_folders);
