//! The application's faces of the core's `cylinder` problem (see [`crate::problems`]): the core's
//! folder re-exported whole, so `crate::problems::cylinder::...` keeps naming the same items.

pub use microslip_core::problems::cylinder::*;

mod ccx_read;
mod chart;
pub mod deck;
mod deck_writer;
mod overlay;
#[cfg(feature = "app")]
mod pane;
pub mod report;

pub use chart::CylinderChart;

/// Its bundled presets, (name, TOML text), embedded in the binary: `preset::bundled` lists every
/// problem's from the registry, so a problem's presets are named here and nowhere else.
pub const BUNDLED_PRESETS: &[(&str, &str)] = &[(
    "cylinder-steel-pad",
    include_str!("../../../presets/cylinder-steel-pad.toml"),
)];

/// Its figures in `microslip figures`: none yet (`figures --preset NAME` draws all its charts).
#[cfg(all(feature = "figures", any(feature = "app", test)))]
pub(crate) const PAPER_FIGURES: &[crate::report::figure::PaperFigure] = &[];
