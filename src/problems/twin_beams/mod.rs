//! Twin cantilever beams pressed together and bent by equal tip forces (paper section 2.1): the
//! parameters, the closed forms under both laws, cyclic loading, the validity envelope (V2) and the
//! independent finite-element solver. The closed forms and the discretized solver never import
//! each other (tests/layering.rs checks it), so that their agreement means something.

pub mod closed_form;
pub mod cycle;
pub mod discretized;
pub mod params;
pub mod validity;

pub use discretized::{InterfaceSample, TwinBeamsFe};

use crate::problems::{Description, Param};
use params::BeamParam;

/// The twin beams as the generic layers see them.
pub const DESCRIPTION: Description = Description {
    key: "beam",
    title: "twin cantilever beams",
    paper_preset: "paper-beams",
    params: &PARAMS,
};

/// Every parameter, in display order.
const PARAMS: [Param; BeamParam::ALL.len()] = param_list!(Param::Beam, BeamParam);
