//! Two deformable bodies meeting on one interface through Jenkins points, condensed onto the
//! interface: the machinery the lap joint's continuum (inner plate and cover) and the twin beams'
//! continuum (lower and upper beam) share, written once.
//!
//! - [`TwoBodyGrid`]: two structured Q8 grids, the lower body's top row against the upper body's
//!   bottom row over the columns both have, numbered column by column across both bodies (a
//!   narrow band) with each interface node pair sharing its normal unknown: an exact normal tie,
//!   no penalty stiffness to choose. The pair's contact force comes out of the solution (the
//!   upper body's internal force at that unknown).
//! - [`Condensed`]: the elastic bodies condensed onto the m pair slips (`numeric::condense`):
//!   the stiffness with every interface spring elastic factored once, solved for the m unit pair
//!   loads and the two external loads (a first load, "P", applied alone, then a driving load,
//!   "F"), kept only through their readings (pair slips, contact forces, one response).
//! - [`Reduced`]: the interface problem on the m slips at given strengths (the Newton driver's
//!   model, `numeric::newton`), the fixed point on the contact forces (the strengths are mu times
//!   them), the elastic limit of the driving load and the path through increments
//!   ([`Reduced::advance`]).
//!
//! A problem supplies its bodies, its held unknowns, its two loads and its reading, and turns the
//! committed state into its own answer (profiles, zones) through [`Reduced`]'s accessors.

mod condensed;
mod grid;
mod profiles;
mod reduced;
mod zones;

pub(crate) use condensed::Condensed;
pub(crate) use grid::TwoBodyGrid;
pub(crate) use profiles::Profiles;
pub(crate) use reduced::{Reduced, State, check_path};
pub(crate) use zones::{last_of_run, nominal_front};
