//! The clamped double-lap joint (issue 24): an inner plate between two cover plates, clamped at a
//! pressure P and pulled by a force F: the parameters, the shear-lag closed forms under both
//! laws, cyclic loading and the independent discretized solver. The closed forms and the
//! discretized solver never import each other (tests/layering.rs checks it).

pub mod closed_form;
pub mod discretized;
pub mod params;

pub use discretized::LapFe;
