//! The application's faces of the core's `twin_beams` problem (see [`crate::problems`]): the core's
//! folder re-exported whole, so `crate::problems::twin_beams::...` keeps naming the same items.

pub use microslip_core::problems::twin_beams::*;

mod chart;
#[cfg(feature = "app")]
mod pane;

pub use chart::BeamChart;
pub mod compare;
pub mod deck;
pub mod fe_points;
#[cfg(all(feature = "figures", any(feature = "app", test)))]
mod figures;
pub mod report;

#[cfg(all(feature = "figures", any(feature = "app", test)))]
pub(crate) use figures::PAPER_FIGURES;

/// Its bundled presets, (name, TOML text), embedded in the binary: `preset::bundled` lists every
/// problem's from the registry, so a problem's presets are named here and nowhere else.
pub const BUNDLED_PRESETS: &[(&str, &str)] = &[
    (
        "paper-beams",
        include_str!("../../../presets/paper-beams.toml"),
    ),
    (
        "paper-beams-soft",
        include_str!("../../../presets/paper-beams-soft.toml"),
    ),
];
