//! The Hertzian cylinder on a flat under a tangential load (issue 34): until the problem's own
//! `mod.rs` lands, only the independent discretized solver, its cycles and the cross-check.

pub mod cross_check;
pub mod cycle;
pub mod discretized;
