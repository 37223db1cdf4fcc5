//! The application's faces of the core's `pressfit` problem (see [`crate::problems`]): the core's
//! folder re-exported whole, so `crate::problems::pressfit::...` keeps naming the same items.

pub use microslip_core::problems::pressfit::*;

pub mod ccx_read;
mod chart;
pub mod compare;
pub mod deck;
mod deck_writer;
#[cfg(feature = "app")]
mod pane;
pub mod report;
pub mod torque_fe;
pub mod torque_report;

pub use chart::{FitChart, PressFitChart};

/// Its bundled presets, (name, TOML text), embedded in the binary: `preset::bundled` lists every
/// problem's from the registry, so a problem's presets are named here and nowhere else.
pub const BUNDLED_PRESETS: &[(&str, &str)] = &[
    (
        "pressfit-ccx98",
        include_str!("../../../presets/pressfit-ccx98.toml"),
    ),
    (
        "pressfit-ccx98-torque",
        include_str!("../../../presets/pressfit-ccx98-torque.toml"),
    ),
];

/// Its figures in `microslip figures`: none of a paper (`figures --preset NAME` draws all its
/// charts).
#[cfg(all(feature = "figures", any(feature = "app", test)))]
pub(crate) const PAPER_FIGURES: &[crate::report::figure::PaperFigure] = &[];
