//! PROVISIONAL (s-deck): the application's faces of the core's `pressfit` problem, until the
//! lead's `mod.rs` lands (branch s44-register); `scaffold.rs` holds throw-away faces.

pub use microslip_core::problems::pressfit::*;

pub mod ccx_read;
pub mod compare;
pub mod deck;
mod deck_writer;
mod scaffold;

/// Its bundled presets.
pub const BUNDLED_PRESETS: &[(&str, &str)] = &[(
    "pressfit-ccx98",
    include_str!("../../../presets/pressfit-ccx98.toml"),
)];

/// Its figures in `microslip figures`: none yet.
#[cfg(all(feature = "figures", any(feature = "app", test)))]
pub(crate) const PAPER_FIGURES: &[crate::report::figure::PaperFigure] = &[];
