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
pub mod report;
