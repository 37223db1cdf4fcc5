//! microslip: exact friction benchmarks under the plain and the regularized Coulomb law, one
//! problem a type (the registry, `microslip_core::with_problems!`, lists them: the two of Ligier
//! & Bonhote, 2014, and the ones added since), with their references, FE decks and the judge of
//! FE results.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! # Crates and layers
//! The physics lives in the `microslip-core` crate (kernel, numeric, problems, study, fit,
//! verify), which depends on nothing with a terminal, a file format or a command line in it; this
//! package is the application above it and re-exports the core's modules under their own names
//! (`microslip::problems` is `microslip_core::problems`), so both read as one layered whole. Data
//! flows one way, lowest first; `tests/layering.rs` reads every `crate::` path of the shipped
//! code of both crates and fails on an edge that runs up or sideways:
//!
//! ```text
//! kernel, file <- numeric <- problems <- study, fit, verify, preset <- measured <- fe <- chart <- report <- faces <- suite, tui <- cli
//! ```
//!
//! - [`kernel`], [`numeric`], [`study`], [`fit`], [`verify`]: the core crate (its own docs say
//!   what each holds); [`problems`] is the core's, re-exported whole, plus each problem's
//!   *faces* in a folder of its own (`src/problems/<name>/`: its charts, report and deck, the
//!   layer `faces` between `report` and `tui`).
//! - [`mod@file`]: reading a file a user named (a size cap, never blocking) and writing one without
//!   clobbering it; the lowest layer beside the kernel.
//! - [`preset`]: TOML parse and write, and the file store (atomic, no clobber).
//! - [`measured`]: measured curves read from CSV for the fits and the FE readers (the core's
//!   fits take points, not files).
//! - [`fe`]: decks for CalculiX (Abaqus keyword syntax), result readers, the comparison of an FE
//!   code's answer with the closed forms (it uses [`fit`] for the implied K_T, so it sits above it).
//! - [`chart`]: what every chart shows, as data (title, axes, series), built from the layers
//!   below; which charts exist and what each is ([`chart::view`]: the [`chart::view::ChartFace`]
//!   each problem's face folder implements, and [`chart::view::AnyChart`], generated from the
//!   registry); the text the TUI shows beside them (`chart::panes`, with the feature `app`: the
//!   `PaneFace` of each problem's face folder); drawn by the TUI and by the SVG
//!   figures of `report::figure`, which choose each series' look from its role
//!   ([`chart::SeriesRole`]: Coulomb, the current K_T, a pin, a family member, ...), set where
//!   the series is built; families of one chart over a parameter ([`chart::family`]).
//! - [`report`]: every format (text, JSON, CSV, SVG), from one serde struct per report and per
//!   table row; it computes nothing.
//! - [`suite`]: `microslip suite`, many FE runs as cases x ladders, their result files, the local
//!   pool that runs them and the scorecard of converged verdicts (text, JSON, JUnit, an HTML page),
//!   over the problems' faces; the whole run is one function (`suite::run`) that the command line
//!   and the Python face both call.
//! - `cli` and `tui` (behind the default feature `app`): thin layers that parse flags or keys, call
//!   the library and hand the results to `report` or the screen. They are private: the binary
//!   calls `app::main`, and the TUI's frame and monkey tests drive it through `app::testing`
//!   (state, actions, effects performed in place, themes, drawing), both hidden from these docs
//!   because they are the program, not a library API. With `default-features = false` none of
//!   clap, ratatui, crossterm or signal-hook is compiled.
//!
//! # What a problem is, and what adding one touches
//! A problem is a type: a folder of the core's `problems` (its parameters, closed forms, cycle,
//! validity envelope, discretized solver, its [`problems::Description`] and the capabilities it
//! has), a folder of faces here (`src/problems/<name>/`: its charts, panes, deck and reports, as
//! impls of the traits of `chart`, `fe` and `report`), and one line of the registry
//! (`microslip_core::with_problems!`), from which every layer generates its dispatch; the
//! checklist a new problem follows is in the docs of [`problems`]. No other file names a problem
//! (`tests/layering.rs` checks it).
//!
//! Dispatch is in one place per crate: the core turns the registry into erased faces once, as
//! each problem's table of capabilities (`problems::problem::ProblemFaces`, from `AnyProblem`);
//! the application once, as [`report::face::for_problem`] (a command written generic over the
//! problem's faces, which the command line and the Python face run) and the table built on it,
//! [`report::face::faces`] (report, cycle and screen faces). The layers below `report` keep a
//! registry expansion of their own where they generate a type with a variant per problem
//! (`fe::face::AnyLoaded`, `chart::view::AnyChart`), and `fe` its deck face, which its header
//! and result readers need and cannot reach from above.
//!
//! Where this departs from the project's intended shape, and why: FE decks, readers and the
//! comparison are a module of the application ([`fe`]) rather than a crate of their own, because
//! they are used only by the application and a crate boundary would add a published surface
//! without a user; `verify` is in the core because it calls both sides of every problem and is
//! neither I/O nor presentation; `cli` sits above `tui` because `microslip` with no command starts
//! the TUI.
//!
//! # Example
//! ```
//! use microslip::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};
//! let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
//! let state = beams.regularized(TipForce::new(100.0)?);
//! assert_eq!(state.regime().label(), "microslip+macroslip");
//! // The paper's plate at K_T = 1e6 MPa/mm has both zones (paper section 2.2.3).
//! let plate = SqueezedPlate::new(PlateParams::PAPER)?;
//! let squeezed = plate.regularized();
//! assert_eq!(squeezed.regime().label(), "microslip+macroslip");
//! assert!(squeezed.micro_zone_end() < 10.0 && squeezed.end_displacement() > 0.0);
//! # Ok::<(), microslip::ParamError>(())
//! ```

/// The physics, from the `microslip-core` crate: re-exported under the same paths, so that
/// `microslip::problems::...` and the application's own `crate::problems::...` name it.
pub use microslip_core::{fit, kernel, numeric, study, verify};

pub mod chart;
#[cfg(feature = "app")]
mod cli;
pub mod fe;
pub mod file;
pub mod measured;
pub mod preset;
pub mod problems;
pub mod report;
pub mod suite;
#[cfg(feature = "app")]
mod tui;

/// The application side (the `cli` and `tui` modules, private): what the `microslip` binary
/// calls, and the narrow surface the TUI's frame, monkey and benchmark tests drive it through.
/// Not a library API: it changes with the program.
#[cfg(feature = "app")]
#[doc(hidden)]
pub mod app {
    pub use crate::cli::main;

    /// What tests and benchmarks need to drive the TUI without a terminal: its state, the
    /// actions keys map to, the effects performed in place, the themes and the drawing.
    pub mod testing {
        pub use crate::tui::action::Action;
        pub use crate::tui::app::{App, AppOptions, Measurements};
        pub use crate::tui::effects::update_blocking;
        pub use crate::tui::theme::{Charset, Theme};
        pub use crate::tui::ui::draw;

        /// What the user guide's generated tables are rendered from (tests/guide_tables.rs):
        /// the key map the `?` overlay prints, and the command line's clap definition.
        pub mod guide {
            pub use crate::tui::keymap::{BINDINGS, Binding, Context, GLOBAL_KEYS, context_title};

            /// The command line as clap defines it: every subcommand with its about and flags.
            pub fn command() -> clap::Command {
                <crate::cli::Cli as clap::CommandFactory>::command()
            }
        }
    }
}

/// The core's prelude at the root (`microslip::TwinBeams`): every registered problem's type,
/// parameter keys and closed forms (generated from the registry), the generic handles and the
/// errors; the root names no problem itself.
pub use microslip_core::prelude::*;
