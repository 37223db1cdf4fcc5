//! The application's faces of the core's `plate` problem (see [`crate::problems`]): the core's
//! folder re-exported whole, so `crate::problems::plate::...` keeps naming the same items.

pub use microslip_core::problems::plate::*;

mod chart;
#[cfg(feature = "app")]
mod pane;

pub use chart::PlateChart;
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
        "paper-plate",
        include_str!("../../../presets/paper-plate.toml"),
    ),
    (
        "plate-bench",
        include_str!("../../../presets/plate-bench.toml"),
    ),
];
