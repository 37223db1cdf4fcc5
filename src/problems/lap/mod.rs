//! The application's faces of the core's `lap` problem (see [`crate::problems`]): the core's
//! folder re-exported whole, so `crate::problems::lap::...` keeps naming the same items.

pub use microslip_core::problems::lap::*;

mod chart;
#[cfg(feature = "app")]
mod pane;

pub use chart::LapChart;
pub mod compare;
pub mod deck;
pub mod fe_points;
pub mod report;

/// Its bundled presets, (name, TOML text), embedded in the binary: `preset::bundled` lists every
/// problem's from the registry, so a problem's presets are named here and nowhere else.
pub const BUNDLED_PRESETS: &[(&str, &str)] = &[(
    "lap-aluminium",
    include_str!("../../../presets/lap-aluminium.toml"),
)];

/// Its figures in `microslip figures`: none yet (`figures --preset NAME` draws all its charts).
#[cfg(all(feature = "figures", any(feature = "app", test)))]
pub(crate) const PAPER_FIGURES: &[crate::report::figure::PaperFigure] = &[];
