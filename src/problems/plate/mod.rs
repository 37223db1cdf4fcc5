//! A thin plate squeezed on a rigid plane (paper section 2.2): the parameters, the strip theory's
//! closed forms under both laws, its validity envelope (V1), the independent 1-D finite-element
//! solver and the 2-D plane-strain continuum that measures where the strip theory fails. The closed
//! forms and the discretized solvers never import each other (tests/layering.rs checks it).

pub mod closed_form;
pub mod continuum;
pub mod discretized;
pub mod params;
pub mod validity;

pub use continuum::{ContinuumMesh, ContinuumPlate, solve_plate_continuum};
pub use discretized::PlateFe;

use crate::problems::{Description, Param};
use params::PlateParam;

/// The squeezed plate as the generic layers see it.
pub const DESCRIPTION: Description = Description {
    key: "plate",
    title: "squeezed plate",
    paper_preset: "paper-plate",
    params: &PARAMS,
};

/// Every parameter, in display order.
const PARAMS: [Param; PlateParam::ALL.len()] = param_list!(Param::Plate, PlateParam);
