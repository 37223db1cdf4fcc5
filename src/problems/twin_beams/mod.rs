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
pub mod report;
