//! microslip: closed-form solutions of friction benchmarks (the two of Ligier & Bonhote, 2014:
//! twin beams and a squeezed plate; and the clamped double-lap joint) under the plain and the
//! regularized Coulomb law.
//!
//! Units everywhere: mm, N, MPa; tangential stiffness K_T in MPa/mm.
//!
//! # Layers
//! Data flows one way, lowest first; `tests/layering.rs` reads every `crate::` path of the shipped
//! code and fails on an edge that runs up or sideways:
//!
//! ```text
//! kernel, file <- numeric <- problems <- study, fit, verify, preset <- fe <- chart <- report <- tui <- cli
//! ```
//!
//! - [`kernel`]: what no problem owns: typed parameters (units, domains, the error that names a
//!   field, its value and its range), number formatting shared by every output, overflow-free
//!   hyperbolic functions, certified root finding, regimes, validity verdicts, and the FE codes'
//!   default friction penalties (data about K_T). No I/O.
//! - [`mod@file`]: reading a file a user named (a size cap, never blocking) and writing one without
//!   clobbering it; the lowest layer beside the kernel.
//! - [`numeric`]: problem-agnostic finite-element kernels (meshes, elements, banded Cholesky, the
//!   Jenkins interface point, Newton with load stepping).
//! - [`problems`]: one folder per benchmark ([`problems::twin_beams`], [`problems::plate`],
//!   [`problems::lap`]) with its parameters, closed forms, validity envelope and independent
//!   discretized solver; the closed forms and the discretized solvers never import each other
//!   (the layering test checks it), so their agreement proves something. [`problems::ModelKind`] lists the problems and
//!   [`problems::inputs`] holds the inputs and validated models of any of them.
//! - [`study`]: sweeps, families and loops over any parameter, solving for a target value, the
//!   smallest K_T within a tolerance of Coulomb.
//! - [`fit`]: identification of mu and K_T, with structured evidence (no prose).
//! - [`verify`]: the only place that calls both the closed forms and the discretized solvers,
//!   returning the worst cases as data.
//! - [`preset`]: TOML parse and write, and the file store (atomic, no clobber).
//! - [`fe`]: decks for CalculiX (Abaqus keyword syntax), result readers, the comparison of an FE
//!   code's answer with the closed forms (it uses [`fit`] for the implied K_T, so it sits above it).
//! - [`chart`]: what every chart shows, as data (title, axes, series), built from the layers
//!   below; which charts exist and what each is ([`chart::view`]); drawn by the TUI and by the SVG
//!   figures of `report::figure`, which choose each series' look from its role
//!   ([`chart::SeriesRole`]: Coulomb, the current K_T, a pin, a family member, ...), set where
//!   the series is built; families of one chart over a parameter ([`chart::family`]).
//! - [`report`]: every format (text, JSON, CSV, SVG), from one serde struct per report and per
//!   table row; it computes nothing.
//! - `cli` and `tui` (behind the default feature `app`): thin layers that parse flags or keys, call
//!   the library and hand the results to `report` or the screen. They are private: the binary
//!   calls `app::main`, and the TUI's frame and monkey tests drive it through `app::testing`
//!   (state, actions, effects performed in place, themes, drawing), both hidden from these docs
//!   because they are the program, not a library API. With `default-features = false` none of
//!   clap, ratatui, crossterm or signal-hook is compiled.
//!
//! # What a problem is, and what adding one touches
//! A problem is a folder of [`problems`] (its parameters, closed forms, cycle, validity envelope,
//! discretized solver and its [`problems::Description`]) and one line of the list in
//! `problems/mod.rs` (`problem_list!`: the variant and its folder). What the generic layers need
//! to know of it is data they read, not a match they make: its parameters with their domains,
//! units and scales, the quantities a target can be set on ([`problems::Quantity`], named and
//! computed by the problem), its response symbol and its load parameter, its charts with their x
//! parameter, load axis and default y scale ([`chart::view::ChartSet`]); presets, `--set`, the
//! parameter pane, undo, pins, `v`, `t`, `solve` and the deck header work from those. What every
//! problem's solution answers has one name in every problem ([`problems::Solution`]: `response`,
//! `regime`, `zone_end`).
//!
//! This differs from the plan in `ARCHITECTURE.md` (a design note kept outside this repository)
//! in one way, for a reason: the plan puts a problem's deck, report type and chart series in its
//! folder, but those sit in layers above `problems` (a chart is built from `study`'s sampling, a
//! report renders `fe`'s comparison), and a folder that held them would make the layering test
//! meaningless. So a problem's code above the physics lives in one file per layer, named after the
//! problem (`report/point/beam.rs`, `report/compare/plate.rs`, ...), and the enums that carry a
//! problem's own types through those layers (`Param`, `Inputs`, `Model`, `AnyChart`, `AnyLoaded`,
//! `Answer`) have one variant per problem: the compiler then lists every place a new problem must
//! answer (exhaustive matches; no `_ =>` default over problems remains in `cli` or `tui`). Other
//! choices: `verify` sits at the top level because it calls both sides of every problem and is
//! neither physics nor I/O; the charts that exist live in `chart::view` so that figure exports
//! name them as the TUI does, while which one is shown (`Views`) and the text table shown in the
//! chart pane are the TUI's; `cli` sits above `tui` because `microslip` with no command starts the
//! TUI.
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
pub use microslip_core::{fit, kernel, numeric, problems, study, verify};

pub mod chart;
#[cfg(feature = "app")]
mod cli;
pub mod fe;
pub mod file;
pub mod measured;
pub mod preset;
pub mod report;
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

pub use kernel::params::{ParamError, Unit};
pub use kernel::regime::Regime;
pub use problems::inputs::{Inputs, Model};
pub use problems::plate::closed_form::{
    ContactPressure, CoulombPlate, PlateParams, RegularizedPlate, SqueezedPlate,
};
pub use problems::twin_beams::closed_form::{
    CoulombBeams, RegularizedBeams, TipForce, TwinBeams, TwinBeamsParams,
};
pub use problems::{BeamParam, ModelKind, Param, PlateParam};
