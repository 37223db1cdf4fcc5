//! Benchmarking an external FE code: input decks for CalculiX (Abaqus keyword syntax) and the
//! comparison of its results with the closed forms.
//!
//! - [`face`]: [`Deck`](face::Deck), what a problem's deck, reader and comparison are (each
//!   problem's in its folder: `src/problems/<name>/deck.rs`, `fe_points.rs`, `compare.rs`), and
//!   their dispatch from the registry.
//! - [`deck`]: what every deck is written with (mesh, size limit, load path, cards).
//! - [`header`]: the header a deck starts with, which `compare` reads back.
//! - [`results`]: what every problem's reader is written with: CalculiX's `.dat` output read
//!   against its deck (`DatRead`), slip profiles, thickness means, and plain CSV
//!   curves from any FE code.
//! - [`compare`]: what every comparison with the closed forms is written with (a relative
//!   difference, a zone end in elements of the mesh).
//!
//! This layer names no problem (`tests/layering.rs`): a problem's FE points, readers and
//! comparison are in its folder, so that a new problem's are too.
//! - [`verdict`]: whether they agree: each difference against its stated envelope, X in elements
//!   of the FE mesh, the implied K_T in standard errors.
//! - [`stick_slope`]: the stick slope the FE code used, CSHEAR / CSLIP over the nodes that
//!   stick, from its own interface output; [`kinematics`]: `NLGEOM` or linear geometry;
//!   [`peak_pressure`]: the largest contact pressure there, which tells a contact that locked.
//! - [`ladder`]: a quantity's answers on a mesh ladder (h, h/2, h/4) and two increments taken
//!   to a converged estimate with its uncertainty (Richardson), and judged against a bound.
//! - [`run`]: running CalculiX on a deck in a work folder of its own, with its log kept.
//!
//! Why the decks are built as they are, and how they differ from the paper's Ansys model, is in
//! docs/theory.md, "Benchmarking an FE code"; the measured agreement is in docs/guide.md.

pub mod compare;
pub mod continuum_verdict;
pub mod deck;
pub mod face;
pub mod header;
pub mod kinematics;
pub mod ladder;
pub mod load;
pub(crate) mod mesh;
pub mod peak_pressure;
pub mod results;
pub mod run;
pub mod stick_slope;
pub mod verdict;
