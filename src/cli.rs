//! The headless command line: reports, sweeps and presets for scripts and FE benchmarking.
//!
//! A thin layer: presets and `--set` come from [`crate::preset`], numbers from [`crate::study::curves`],
//! formats from [`crate::report`]; this file only parses flags, checks the flags that are not model
//! parameters, and names flags in error messages. Errors are one line on stderr; the exit codes
//! follow one table ([`CliError::exit_code`]): 1 when a command ran and its answer is "no" (`check`,
//! `verify`, a `solve` with no root) or could not be computed, 2 for usage or input problems, 3
//! when the external solver failed, 128 + N after signal N. Nothing goes to stdout before the inputs
//! are known to be valid, so a failed run never leaves half a table behind.

use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Args, Parser, Subcommand, ValueEnum};
use thiserror::Error;

use crate::chart::view::AnyChart;
use crate::chart::{SeriesRole, YMode};
use crate::fe;
use crate::fe::deck::{self, DeckMesh};
use crate::fe::header::StickSlope;
use crate::fe::load::LoadError;
use crate::fit::{self, FitError};
use crate::kernel::params::{Compact, Domain, ParamError, Unit, parse_number};
use crate::numeric::{MeshDensity, NumericError};
use crate::preset::{self, Preset, PresetError, PresetSource};
use crate::problems::inputs::{Inputs, Model};
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::lap::load_driven::LapLoad;
use crate::problems::twin_beams::closed_form::BeamTheory;
use crate::problems::twin_beams::load_driven::TwinBeamsLoad;
use crate::problems::{BeamParam, LapParam, ModelKind, Param, PlateParam, UnknownParam};
use crate::report::figure::{self, FigureError};
use crate::report::rows::{BeamRow, CycleRow, LapLoopRow, LapRow, LoopRow, PlateRow};
use crate::report::table::{TableFormat, write_json, write_table, write_table_after};
use crate::report::{self, json, text};
use crate::study::curves::{self, RangeError, Samples, Spacing};
use crate::study::load;
use crate::study::target::{Target, TargetError, solve_for_target};
use crate::tui::theme::Charset;
use crate::verify::{self, Grid};
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// microslip: friction benchmarks under the regularized Coulomb law (Ligier & Bonhote, 2014).
///
/// Units: mm, N, MPa; K_T in MPa/mm. Without a subcommand, opens the terminal UI.
#[derive(Debug, Parser)]
#[command(
    name = "microslip",
    version,
    // The doc comment above, not the crate description: the help speaks to users, Cargo.toml to
    // crates.io.
    long_about = None,
    // A fixed width: help text (and its snapshot) must not depend on the terminal running it.
    term_width = 100,
    after_help = after_help()
)]
pub struct Cli {
    /// What to do (default: the terminal UI).
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Characters the terminal UI may use (ascii: 7-bit only, for any terminal).
    #[arg(long, value_enum, default_value_t = Charset::Unicode)]
    pub charset: Charset,
    /// Preset to open in the terminal UI (bundled or user name, or a .toml path).
    #[arg(long, value_name = "P")]
    pub preset: Option<String>,
    /// Measured twin-beam curve (CSV with columns F_N,w_mm) to show and fit in the terminal UI.
    #[arg(long, value_name = "DATA.csv")]
    pub data: Option<PathBuf>,
}

/// The closing lines of `--help`: units, and the parameter keys as the model defines them.
fn after_help() -> String {
    format!(
        "Units: mm, N, MPa; K_T in MPa/mm (1 MPa/um = 1000 MPa/mm).\n\
         Keys for --set and preset files: {}.\n\
         Without a command, microslip opens the terminal UI (keys: press ? inside).",
        ModelKind::key_docs()
    )
}

/// The help of `--set`: every model's keys as the specs define them.
fn set_help() -> String {
    format!("Set a parameter, e.g. KT=120 ({})", ModelKind::key_docs())
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Report of the paper's two data sets (twin beams and plate), as text.
    Report,
    /// Twin cantilever beams at one tip force: thresholds, X, w(L) for both laws, regimes.
    Beam(PointArgs),
    /// Squeezed plate: X_s, X_r, u(L) for both laws, regimes, contact-pressure check, validity.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Plate {
        #[command(flatten)]
        point: PointArgs,
        /// Also solve the plane-strain continuum (done anyway when the strip theory is not
        /// expected within 2 %).
        #[arg(long)]
        continuum: bool,
    },
    /// Clamped double-lap joint at one force: F_1 (and where), F_2, F_gross, Delta and both
    /// sliding zones for both laws, regimes, the shear-lag theory's envelope.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Lap {
        #[command(flatten)]
        point: PointArgs,
        /// Also solve the 2-D plane-stress continuum (done anyway when the shear-lag theory is
        /// not expected within 2 %).
        #[arg(long)]
        continuum: bool,
    },
    /// Tables over a parameter range, as CSV or JSON.
    #[command(subcommand)]
    Sweep(SweepCommand),
    /// The value of one parameter at which a quantity takes a target value (a certified root).
    ///
    /// Quantities: beam w(L) X ratio F_1 D zeta; plate u(L) X_r ratio; lap Delta a d ratio F_1 D
    /// zeta (ratio: regularized over Coulomb, e.g. ratio=1.01 for "within 1 % of Coulomb"). The parameter's whole accepted range
    /// is searched unless --from/--to narrow it; every root is listed, and none is an error.
    Solve {
        /// Which benchmark.
        #[arg(value_parser = model_kind_parser())]
        model: ModelKind,
        /// The parameter to solve for (beam: L b h E P mu KT F; plate: L tp E nu mu P KT; lap: L b
        /// t1 t2 E1 E2 P mu KT F).
        #[arg(long, value_name = "NAME")]
        vary: String,
        /// The target, QUANTITY=VALUE (e.g. ratio=1.01, w(L)=0.05, X_r=9.5).
        #[arg(long, value_name = "QUANTITY=VALUE")]
        target: String,
        /// Lowest value of the parameter searched (default: its smallest accepted value).
        #[arg(long, value_name = "A", allow_negative_numbers = true, requires = "to")]
        from: Option<f64>,
        /// Highest value searched (default: its largest accepted value).
        #[arg(
            long,
            value_name = "B",
            allow_negative_numbers = true,
            requires = "from"
        )]
        to: Option<f64>,
        #[command(flatten)]
        inputs: InputArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
    /// K_T from K_N and the K_T that FE codes assume, with what each does to the answer.
    ///
    /// Each answer is given against the current K_T's and against Coulomb's (`vs current`,
    /// `vs Coulomb`, in %).
    Kt {
        #[command(flatten)]
        inputs: InputArgs,
        /// Contact element length of your FE model (mm, in [1e-8, 1e6]), which the codes' default
        /// K_T scale with; default: L/100 (0.4 mm on lap-aluminium, 2 mm on paper-beams).
        #[arg(long, value_name = "LE", allow_negative_numbers = true)]
        element_size: Option<f64>,
        /// Normal contact stiffness K_N (MPa/mm), for paper eq. 4 and the measured K_T/K_N range.
        #[arg(long, value_name = "KN", allow_negative_numbers = true)]
        kn: Option<f64>,
        /// Poisson ratio for eq. 4 with --kn (default: the plate's nu, else 0.3).
        #[arg(
            long,
            value_name = "NU",
            allow_negative_numbers = true,
            requires = "kn"
        )]
        nu: Option<f64>,
        /// Instead of the table: the smallest K_T for which the regularized w(L) (beams), u(L)
        /// (plate) or Delta (lap) is within T of Coulomb (1% or 0.01), and each FE code's setting
        /// for it.
        #[arg(long, value_name = "T", conflicts_with_all = ["kn", "nu"], allow_hyphen_values = true)]
        tolerance: Option<String>,
        /// With --tolerance: T of what. coulomb: of the Coulomb answer (K_T -> infinity);
        /// current: of the current K_T's answer (the K_T interval around it).
        #[arg(long, value_enum, value_name = "REF", default_value_t = ToleranceOf::Coulomb, requires = "tolerance")]
        of: ToleranceOf,
        /// With --tolerance, beams and lap: lowest force checked (N; default: the preset's F).
        #[arg(
            long,
            value_name = "A",
            allow_negative_numbers = true,
            requires = "tolerance"
        )]
        from: Option<f64>,
        /// With --tolerance, beams and lap: highest force checked (N; default: the preset's F).
        #[arg(
            long,
            value_name = "B",
            allow_negative_numbers = true,
            requires = "tolerance"
        )]
        to: Option<f64>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
    /// Twin beams (default) or the lap joint (a lap preset) cycled between +FA and -FA: loop,
    /// dissipation, damping.
    Cycle {
        /// Amplitude F_a (N).
        #[arg(long, value_name = "FA", allow_negative_numbers = true)]
        amplitude: f64,
        #[command(flatten)]
        inputs: InputArgs,
        /// Points per branch of the loop (csv format).
        #[arg(long, value_name = "N", default_value_t = 101, value_parser = parse_count, allow_negative_numbers = true)]
        points: u64,
        /// Output format: text summary, JSON summary, or the loop as CSV.
        #[arg(long, value_enum, default_value_t = CycleFormat::Text)]
        format: CycleFormat,
    },
    /// Identify mu and K_T from a measured deflection curve.
    #[command(subcommand)]
    Fit(FitCommand),
    /// List bundled and user presets with their descriptions.
    Presets,
    /// Cross-check the closed forms against the finite-element solvers; exit 1 above tolerance.
    Verify {
        /// Run one geometry per model only (a smoke test).
        #[arg(long)]
        quick: bool,
        #[arg(
            long,
            value_name = "N",
            default_value_t = MeshDensity::default().elements,
            help = format!(
                "Elements per model ({} to {}; the smallest element shrinks in proportion)",
                MeshDensity::MIN_ELEMENTS,
                MeshDensity::MAX_ELEMENTS
            )
        )]
        elements: usize,
        /// Largest relative error accepted on w(L), X, u(L) and X_r.
        #[arg(long, value_name = "T", default_value_t = verify::DEFAULT_TOLERANCE)]
        tolerance: f64,
    },
    /// Write a CalculiX input deck for these parameters (see docs/guide.md).
    Deck {
        /// The FE code (ccx: CalculiX 2.20; Abaqus reads the same keywords, see docs/guide.md).
        #[arg(value_enum)]
        code: FeCode,
        /// Which benchmark.
        #[arg(value_parser = model_kind_parser())]
        model: ModelKind,
        #[command(flatten)]
        deck: DeckArgs,
        /// Write the deck to FILE instead of stdout (replaced atomically if it exists).
        #[arg(short = 'o', long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// Benchmark CalculiX in one command: write the deck, run ccx on it (progress on stderr, its
    /// files and log kept in a work folder) and print the comparison with the closed forms.
    ///
    /// When stderr is not a terminal, one progress line per increment ccx starts. Exit 3 when
    /// ccx is not found, fails or writes no results (the last lines of its log follow); on
    /// SIGTERM, SIGINT or SIGHUP, ccx and what it started are ended first, then exit 128 + the
    /// signal.
    Bench {
        /// The FE code (ccx: CalculiX 2.20).
        #[arg(value_enum)]
        code: FeCode,
        /// Which benchmark.
        #[arg(value_parser = model_kind_parser())]
        model: ModelKind,
        #[command(flatten)]
        deck: DeckArgs,
        /// Work folder (made if missing; refused if it holds the job's files already). Default:
        /// a new folder microslip-ccx-JOB-N in the system's temporary folder.
        #[arg(long, value_name = "DIR")]
        workdir: Option<PathBuf>,
        /// The ccx program to run: a name is looked up on the PATH, a path (`./ccx_2.20`) is
        /// taken from the current folder.
        #[arg(long, value_name = "PROGRAM", default_value = "ccx")]
        ccx: String,
        /// Output format of the comparison.
        #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
        format: CompareFormat,
    },
    /// Compare FE results with the closed forms, point by point, and the K_T they imply.
    Compare {
        /// Which benchmark.
        #[arg(value_parser = model_kind_parser())]
        model: ModelKind,
        /// Result files: the .dat of a `microslip deck ccx` run (its deck JOB.inp beside it), or a
        /// CSV from any FE code: F_N,w_mm (beam), KT_MPa_per_mm,u_mm (plate) or F_N,Delta_mm (lap).
        /// Several plate or lap runs may be given.
        #[arg(required = true, value_name = "RESULT")]
        results: Vec<PathBuf>,
        /// The deck of a .dat result (default: the result's name with .inp).
        #[arg(long, value_name = "FILE")]
        deck: Option<PathBuf>,
        /// Parameters for CSV results (a .dat takes them from its deck).
        #[command(flatten)]
        inputs: InputArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
        format: CompareFormat,
    },
    /// Draw a chart of the terminal UI as an SVG figure, or write its data as CSV.
    Plot {
        /// The chart (its model's paper preset unless --preset names another).
        #[arg(value_enum)]
        chart: AnyChart,
        #[command(flatten)]
        inputs: InputArgs,
        /// Add the project's finite-element points (w-vs-f, x-vs-f, tau, loop, u-vs-kt, delta-vs-f,
        /// zones-vs-f, lap-tau, lap-slip, lap-loop).
        #[arg(long)]
        fe: bool,
        /// The y axis: linear, log, or relative (each curve / Coulomb - 1, in %); default: log for
        /// u-vs-kt and d-vs-fa, linear otherwise. A mode the chart cannot show is refused.
        #[arg(long, value_enum, value_name = "MODE")]
        y: Option<YMode>,
        /// Add the chart at other values, as the TUI's pins (g): the same --set on top of the
        /// inputs, several joined by commas (--pin mu=0.2 --pin mu=0.45,KT=1000); at most 4.
        #[arg(long = "pin", value_name = "KEY=VALUE,...")]
        pins: Vec<String>,
        /// Draw the chart's main curve once per value of one parameter, all of equal rank and
        /// named with the unit (--family P=0.5,1,2: "P = 0.5 MPa", ...); the other parameters
        /// go in a caption. At most 6 values; not with --pin or --fe.
        #[arg(long, value_name = "KEY=V1,V2,...")]
        family: Option<String>,
        /// The chart's series to draw, by role, comma-separated: current, coulomb, softer
        /// (K_T/5, K_T/10), stiffer (K_T*5, K_T*10), limit (mu P, P_r = P), fe, continuum,
        /// cursor. Default: all the chart has; with --family, only the members (a role added
        /// to a family must be the same for every member).
        #[arg(long, value_name = "ROLE,...")]
        series: Option<String>,
        /// Leave out the cursor (the vertical line at the current value).
        #[arg(long)]
        no_cursor: bool,
        /// Output format; default: the FILE's extension (.svg, .png, .pdf or .csv; another
        /// extension is refused), else svg.
        #[arg(long, value_enum)]
        format: Option<FigureFormat>,
        /// Write to FILE instead of stdout (replaced atomically if it exists).
        #[arg(short = 'o', long, value_name = "FILE.svg|png|pdf|csv")]
        output: Option<PathBuf>,
    },
    /// Regenerate the paper's figures, the cycle loop and D vs F_a: SVG + CSV each, and an
    /// index.html that shows them all; with --preset or --set, every chart of that bench instead,
    /// its values in each caption.
    Figures {
        /// The directory to write into (made if missing; files in it are replaced).
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// Leave out the finite-element points (faster).
        #[arg(long)]
        no_fe: bool,
        /// The figures' format: svg, png (1600 x 1000 px) or pdf; each with its CSV data.
        #[arg(long, value_enum, default_value = "svg")]
        format: FigureFormat,
        /// Your bench instead of the paper's (default without them: the paper's figure set).
        #[command(flatten)]
        inputs: InputArgs,
    },
    /// Validate presets (files, or names as --preset takes them); report every problem; exit 1 if
    /// any.
    Check {
        /// Preset files (TOML), or preset names (bundled, or in the user preset folder).
        #[arg(required = true, value_name = "FILE|NAME")]
        files: Vec<PathBuf>,
    },
}

/// Where the parameters come from.
#[derive(Debug, Args)]
pub struct InputArgs {
    /// Bundled or user preset name, or a path to a TOML file.
    #[arg(long, value_name = "P")]
    pub preset: Option<String>,
    // The help names each model's keys from the specs (`set_help`), half sizes marked.
    #[arg(long = "set", value_name = "KEY=VALUE", help = set_help())]
    pub assignments: Vec<String>,
    /// Beam theory of the twin beams' deflection (default: the preset's, else the paper's
    /// Euler-Bernoulli); timoshenko adds each beam's shear deflection.
    #[arg(long, value_name = "THEORY", value_parser = ["euler-bernoulli", "timoshenko"])]
    pub beam_theory: Option<String>,
}

impl InputArgs {
    /// The files these flags read, with the flag that names each: the preset's file, given as a
    /// path or as the name of a user preset (bundled presets are no files). A preset that does
    /// not resolve reads nothing: loading it reports why.
    fn read_files(&self) -> Vec<(&'static str, PathBuf)> {
        let Some(name) = &self.preset else {
            return Vec::new();
        };
        match preset::resolve(name).map(|p| p.source) {
            Ok(preset::PresetSource::File(path)) => vec![("--preset", path)],
            _ => Vec::new(),
        }
    }

    /// The parameter flags given, as a command line repeats them (`--preset P`, `--set K=V`, ...).
    fn flags(&self) -> Vec<String> {
        let mut given: Vec<String> = self
            .preset
            .iter()
            .map(|p| format!("--preset {p}"))
            .collect();
        given.extend(self.assignments.iter().map(|a| format!("--set {a}")));
        given.extend(
            self.beam_theory
                .iter()
                .map(|t| format!("--beam-theory {t}")),
        );
        given
    }
}

/// Arguments of `beam` and `plate`.
#[derive(Debug, Args)]
pub struct PointArgs {
    #[command(flatten)]
    inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    format: ReportFormat,
}

/// Sweep subcommands.
#[derive(Debug, Subcommand)]
pub enum SweepCommand {
    /// Twin beams over a range of tip forces F (N), linearly spaced (replaces the preset's F), or
    /// of any parameter with --vary.
    Beam {
        /// The parameter to vary: L b h E P mu KT F (default F). Columns: the parameter's (e.g.
        /// mu, KT_MPa_per_mm) then those of the F sweep; for F, the F sweep's own.
        #[arg(long, value_name = "NAME")]
        vary: Option<String>,
        /// First value of the varied parameter (F: N).
        #[arg(long, value_name = "A", allow_negative_numbers = true)]
        from: f64,
        /// Last value.
        #[arg(long, value_name = "B", allow_negative_numbers = true)]
        to: f64,
        /// Number of rows, both ends included (2 to 100000000; 1 when --from = --to).
        #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
        points: u64,
        #[command(flatten)]
        spacing: SpacingArgs,
        #[command(flatten)]
        inputs: InputArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
        format: TableFormat,
    },
    /// Twin beams (default) or the lap joint (a lap preset) cycled at amplitudes F_a from F0 to F1
    /// (N): dissipation and damping per cycle.
    Cycle {
        /// First amplitude (N).
        #[arg(long, value_name = "F0", allow_negative_numbers = true)]
        from: f64,
        /// Last amplitude (N).
        #[arg(long, value_name = "F1", allow_negative_numbers = true)]
        to: f64,
        /// Number of rows, both ends included (2 to 100000000).
        #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
        points: u64,
        #[command(flatten)]
        inputs: InputArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
        format: TableFormat,
    },
    /// Double-lap joint over a range of forces F (N, up to F_gross), linearly spaced (replaces the
    /// preset's F), or of any parameter with --vary.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Lap(LapSweepArgs),
    /// Squeezed plate over a range of K_T (MPa/mm), logarithmically spaced unless --linear, or of
    /// any parameter with --vary NAME --from A --to B.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Plate {
        /// First K_T (MPa/mm).
        #[arg(long, value_name = "A", allow_negative_numbers = true, conflicts_with_all = ["vary", "from"])]
        kt_from: Option<f64>,
        /// Last K_T (MPa/mm).
        #[arg(long, value_name = "B", allow_negative_numbers = true, conflicts_with_all = ["vary", "to"])]
        kt_to: Option<f64>,
        /// The parameter to vary: L tp E nu mu P KT (default KT). Columns: the parameter's (e.g.
        /// mu) then those of the K_T sweep; for KT, the K_T sweep's own.
        #[arg(long, value_name = "NAME")]
        vary: Option<String>,
        /// First value of the varied parameter (with --vary).
        #[arg(long, value_name = "A", allow_negative_numbers = true)]
        from: Option<f64>,
        /// Last value of the varied parameter (with --vary).
        #[arg(long, value_name = "B", allow_negative_numbers = true)]
        to: Option<f64>,
        /// Number of rows, both ends included (2 to 100000000; 1 when both ends are equal).
        #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
        points: u64,
        #[command(flatten)]
        spacing: SpacingArgs,
        #[command(flatten)]
        inputs: InputArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
        format: TableFormat,
    },
}

/// How sweep values are spaced; the default is logarithmic for K_T, linear for the others.
#[derive(Debug, Args)]
pub struct LapSweepArgs {
    /// The parameter to vary: L b t1 t2 E1 E2 P mu KT F (default F). Columns: the parameter's
    /// then those of the F sweep; for F, the F sweep's own.
    #[arg(long, value_name = "NAME")]
    vary: Option<String>,
    /// First value of the varied parameter (F: N, at most F_gross).
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    from: f64,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true)]
    to: f64,
    /// Number of rows, both ends included (2 to 100000000; 1 when --from = --to).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    points: u64,
    #[command(flatten)]
    spacing: SpacingArgs,
    #[command(flatten)]
    inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    format: TableFormat,
}

/// How sweep values are spaced; the default is logarithmic for K_T, linear for the others.
#[derive(Debug, Args)]
pub struct SpacingArgs {
    /// Space the values linearly.
    #[arg(long, conflicts_with = "log")]
    linear: bool,
    /// Space the values logarithmically (both ends > 0).
    #[arg(long)]
    log: bool,
}

impl SpacingArgs {
    /// The spacing asked for, or the parameter's default.
    fn spacing(&self, param: Param) -> Spacing {
        if self.linear {
            Spacing::Linear
        } else if self.log || param.is_stiffness() {
            Spacing::Logarithmic
        } else {
            Spacing::Linear
        }
    }
}

/// Fit subcommands.
#[derive(Debug, Subcommand)]
pub enum FitCommand {
    /// Twin beams: fit mu and K_T to measured w(L) vs F (CSV with columns F_N,w_mm); geometry, E
    /// and P come from the preset.
    Beam {
        /// Measurements: CSV with a header naming F_N and w_mm (other columns are ignored).
        #[arg(value_name = "DATA.csv")]
        data: PathBuf,
        #[command(flatten)]
        inputs: InputArgs,
        /// Hold a parameter at a value instead of fitting it: mu=0.3 or KT=600 (repeatable).
        #[arg(long = "fix", value_name = "KEY=VALUE")]
        fixed: Vec<String>,
        /// What the standard errors assume about the scatter of w [default: relative; a sigma_mm
        /// column in the data gives each point's own, taken as known].
        #[arg(long, value_enum)]
        weights: Option<WeightsArg>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
    /// Lap joint: fit mu and K_T to measured Delta vs F (CSV with columns F_N,Delta_mm); the
    /// geometry, moduli and P come from the preset (default lap-aluminium).
    Lap {
        /// Measurements: CSV with a header naming F_N and Delta_mm (other columns are ignored).
        #[arg(value_name = "DATA.csv")]
        data: PathBuf,
        #[command(flatten)]
        inputs: InputArgs,
        /// Hold a parameter at a value instead of fitting it: mu=0.3 or KT=1000 (repeatable).
        #[arg(long = "fix", value_name = "KEY=VALUE")]
        fixed: Vec<String>,
        /// What the standard errors assume about the scatter of Delta [default: relative; a
        /// sigma_mm column in the data gives each point's own, taken as known].
        #[arg(long, value_enum)]
        weights: Option<WeightsArg>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
}

/// `fit beam --weights`: the scatter of the measured w that the standard errors assume.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum WeightsArg {
    /// The same at every point (a gauge whose error does not grow with the reading).
    Absolute,
    /// Proportional to the response, w or Delta (gain, calibration): the default.
    Relative,
}

/// Formats of `cycle`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CycleFormat {
    /// Readable summary.
    Text,
    /// JSON summary.
    Json,
    /// The loop points, both laws, as CSV.
    Csv,
}

/// Formats of single-point reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReportFormat {
    /// Readable report.
    Text,
    /// JSON object with unit-suffixed names.
    Json,
}

/// What a deck is made of: the parameters, the mesh and the load path (`deck` and `bench`).
#[derive(Debug, Args)]
pub struct DeckArgs {
    #[command(flatten)]
    inputs: InputArgs,
    /// Mesh density (fine halves every element size: run both to check convergence).
    #[arg(long, value_enum, default_value_t = DeckMesh::Coarse)]
    mesh: DeckMesh,
    /// Forces of the load steps (N, increasing): the beams' tip force (default F_thre x 0.5,
    /// 0.75, 1, 1.25, 1.875, 2.5) or the lap joint's F (default 0.5 F_1, (F_1 + F_2)/2,
    /// (F_2 + F_gross)/2, 0.9 F_gross); not the plate's.
    #[arg(
        long,
        value_name = "F0,F1,...",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    loads: Option<Vec<f64>>,
    /// Give the FE code a stiff stick slope (boundary layer a tenth of h or t_p) instead of
    /// K_T: plain Coulomb to within what the mesh resolves.
    #[arg(long)]
    near_coulomb: bool,
    /// Largest force change per increment (N) in the load steps that end beyond F_1 (friction
    /// is path-dependent once it saturates), beams and lap joint; default: F_1 / 40.
    #[arg(long, value_name = "N")]
    increment: Option<f64>,
}

/// External FE codes `deck` writes for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FeCode {
    /// CalculiX's solver, ccx (tested with 2.20).
    Ccx,
}

/// Output formats of `compare`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CompareFormat {
    /// A table with the K_T the results imply.
    Text,
    /// One row per FE point.
    Csv,
    /// Rows and the implied K_T.
    Json,
}

/// Formats of `microslip plot`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FigureFormat {
    /// An SVG figure: axes with units, legend, the chart's curves and points.
    Svg,
    /// The same figure as a PNG image of 1600 x 1000 px.
    Png,
    /// The same figure as a one-page PDF (vector, font embedded).
    Pdf,
    /// The chart's points: series, x, y (with the axis titles).
    Csv,
}

impl FigureFormat {
    /// The figure format, or `None` for CSV.
    fn figure(self) -> Option<figure::Format> {
        match self {
            FigureFormat::Svg => Some(figure::Format::Svg),
            FigureFormat::Png => Some(figure::Format::Png),
            FigureFormat::Pdf => Some(figure::Format::Pdf),
            FigureFormat::Csv => None,
        }
    }

    /// The extension, also the name `--format` takes.
    fn extension(self) -> &'static str {
        self.figure().map_or("csv", figure::Format::extension)
    }

    /// The format of `output`'s extension and `--format`, which must agree: a file named `w.png`
    /// holds a PNG. No extension (or stdout) takes `--format`, else `default`. An extension no
    /// format has is refused, so a figure is never written under a name that lies about it.
    fn choose(
        format: Option<FigureFormat>,
        output: Option<&std::path::Path>,
        flag: &str,
        accepted: &[FigureFormat],
        default: FigureFormat,
    ) -> Result<FigureFormat, CliError> {
        let list = accepted
            .iter()
            .map(|f| format!(".{}", f.extension()))
            .collect::<Vec<_>>()
            .join(", ");
        let shown = || {
            report::sanitize(&output.map(|p| p.display().to_string()).unwrap_or_default())
                .into_owned()
        };
        let by_name = match output.and_then(|p| p.extension()) {
            None => None,
            Some(extension) => Some(
                accepted
                    .iter()
                    .copied()
                    .find(|f| extension.eq_ignore_ascii_case(f.extension()))
                    .ok_or_else(|| {
                        CliError::Invalid(format!(
                            "invalid {flag} = '{}': microslip writes {list} (the extension chooses the format)",
                            shown()
                        ))
                    })?,
            ),
        };
        match (format, by_name) {
            (Some(asked), _) if !accepted.contains(&asked) => Err(CliError::Invalid(format!(
                "invalid --format = {}: accepted here: {}",
                asked.extension(),
                list.replace('.', "")
            ))),
            (Some(asked), Some(named)) if asked != named => Err(CliError::Invalid(format!(
                "invalid --format = {} with {flag} = '{}': the file's extension says .{}; name the file .{} or leave out --format",
                asked.extension(),
                shown(),
                named.extension(),
                asked.extension()
            ))),
            (asked, named) => Ok(named.or(asked).unwrap_or(default)),
        }
    }
}

/// What `kt --tolerance` is a tolerance of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ToleranceOf {
    /// Of the Coulomb answer (the K_T -> infinity limit): the smallest K_T within it.
    Coulomb,
    /// Of the current K_T's answer: the K_T interval around it.
    Current,
}

/// clap's view of a library enum: each value with the key users type and its help line. The
/// library's own types carry no clap derive (the library compiles without clap, and what a
/// command line accepts is this layer's business), so each lists its values here.
macro_rules! value_enum {
    ($ty:ty { $($variant:expr => ($key:expr, $help:expr)),+ $(,)? }) => {
        impl ValueEnum for $ty {
            fn value_variants<'a>() -> &'a [Self] {
                &[$($variant),+]
            }

            fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
                $(
                    if *self == $variant {
                        return Some(clap::builder::PossibleValue::new($key).help($help));
                    }
                )+
                None
            }
        }
    };
}

/// `--model` and the `model` positional: the problems' keys, each with its summary in `--help`
/// (a parser rather than `ValueEnum`, which the core crate's type cannot implement here).
fn model_kind_parser() -> impl clap::builder::TypedValueParser<Value = ModelKind> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(ModelKind::ALL.map(|kind| {
        let d = kind.description();
        clap::builder::PossibleValue::new(d.key).help(d.summary)
    }))
    .try_map(|key| key.parse::<ModelKind>())
}

value_enum!(TableFormat {
    TableFormat::Csv => ("csv", "CSV with a header line"),
    TableFormat::Json => ("json", "JSON array of row objects"),
});

value_enum!(YMode {
    YMode::Linear => (YMode::Linear.key(), "The values, on a linear axis"),
    YMode::Log => (YMode::Log.key(), "The values, on a logarithmic axis (decades)"),
    YMode::Relative => (YMode::Relative.key(), "Each curve over the Coulomb curve, minus 1, in %"),
});

value_enum!(DeckMesh {
    DeckMesh::Coarse => (DeckMesh::Coarse.name(), "About 100 elements along the beam and 2 through each beam's height; 4 through the plate, the lap joint's inner half plate and cover"),
    DeckMesh::Fine => (DeckMesh::Fine.name(), "Every element size halved"),
});

impl ValueEnum for AnyChart {
    fn value_variants<'a>() -> &'a [Self] {
        AnyChart::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let model = self.kind().name();
        Some(
            clap::builder::PossibleValue::new(self.key())
                .help(format!("{model}: {}", self.title())),
        )
    }
}

/// Why a command failed.
#[derive(Debug, Error)]
pub enum CliError {
    /// A preset or `--set` problem.
    #[error(transparent)]
    Preset(#[from] PresetError),
    /// A parameter out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// A sweep range problem, with the command's flags for the start, end and number of points.
    #[error("{}", error.message(*flags))]
    Range {
        /// The problem.
        error: RangeError,
        /// The flags naming the start, the end and the number of points.
        flags: [&'static str; 3],
    },
    /// A flag that is not a model parameter, out of its range.
    #[error("invalid {flag} = {}: {allowed}", Compact(*value))]
    Flag {
        /// The flag.
        flag: &'static str,
        /// The value given.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// A preset of another problem.
    #[error("preset '{preset}' is a {found} preset; `microslip {command}` needs a {wanted} preset")]
    WrongModel {
        /// The preset.
        preset: String,
        /// Its model.
        found: ModelKind,
        /// The model the command needs.
        wanted: ModelKind,
        /// The command, as typed after `microslip` (e.g. `fit beam`).
        command: String,
    },
    /// A parameter name the model does not have.
    #[error("invalid --vary: {0}")]
    Vary(#[from] UnknownParam),
    /// A target that cannot be solved (boxed: its "no root" case carries the whole scan).
    #[error(transparent)]
    Target(Box<TargetError>),
    /// Missing flags.
    #[error("{0}")]
    Usage(&'static str),
    /// The cross-check found errors above tolerance (already reported on stdout).
    #[error("{0} of the quantities checked {verb} the tolerance", verb = if *.0 == 1 { "exceeds" } else { "exceed" })]
    VerifyFailed(usize),
    /// Unreadable or malformed measurements.
    #[error("{path}: {reason}")]
    Data {
        /// The file.
        path: String,
        /// What is wrong (with the line number when there is one).
        reason: String,
    },
    /// A bad `--beam-theory`.
    #[error("{0}")]
    Theory(String),
    /// Another flag the command cannot use as given (the message names it).
    #[error("{0}")]
    Invalid(String),
    /// A bad `--fix`.
    #[error("invalid --fix '{0}': expected mu=VALUE or KT=VALUE with a finite number")]
    Fix(String),
    /// The fit could not run.
    #[error(transparent)]
    Fit(#[from] FitError),
    /// A numerical solve failed, or refused its inputs.
    #[error("numerical solver: {0}")]
    Numeric(#[from] NumericError),
    /// A figure that cannot be drawn.
    #[error(transparent)]
    Figure(#[from] FigureError),
    /// Files with problems (already reported on stdout).
    #[error("{0} of the files checked {verb} problems", verb = if *.0 == 1 { "has" } else { "have" })]
    CheckFailed(usize),
    /// Writing the output failed.
    #[error("cannot write output: {0}")]
    Output(#[from] io::Error),
    /// `bench`: the solver could not be run, failed, or was stopped by a signal; or its work
    /// folder or program was refused.
    #[error(transparent)]
    Solver(#[from] fe::run::RunError),
}

impl From<TargetError> for CliError {
    fn from(e: TargetError) -> Self {
        CliError::Target(Box::new(e))
    }
}

impl CliError {
    /// The exit code, by the one table users read (README, "Exit codes"): 1 when the command ran
    /// and its answer is "no" or could not be computed, 2 when the input was refused before
    /// anything ran, 3 when the external solver failed, 128 + N when signal N stopped it.
    fn exit_code(&self) -> u8 {
        use fe::run::RunError;
        match self {
            CliError::Target(e)
                if matches!(
                    **e,
                    TargetError::NoRoot { .. } | TargetError::Undefined { .. }
                ) =>
            {
                1
            }
            // Inputs the built-in solvers do not take (a K_T too stiff for double precision):
            // refused with the largest value that works, before any solve.
            CliError::Numeric(NumericError::OutOfRange(_) | NumericError::BadLoad(_)) => 2,
            CliError::CheckFailed(_)
            | CliError::VerifyFailed(_)
            | CliError::Output(_)
            | CliError::Numeric(_) => 1,
            CliError::Solver(RunError::Stopped { signal, .. }) => {
                u8::try_from(128 + signal).unwrap_or(u8::MAX)
            }
            CliError::Solver(e) if e.is_solver_failure() => 3,
            _ => 2,
        }
    }

    /// Writes the error on stderr: one line, but for a failed solver the lines of its log
    /// follow, each as a line of its own (each sanitized, as every line shown is).
    fn print(&self) {
        if let CliError::Solver(fe::run::RunError::Failed { status, log, tail }) = self {
            print_error(&format!(
                "ccx failed ({status}); the last lines of its log, {log}:"
            ));
            let mut stderr = io::stderr().lock();
            for line in tail.lines() {
                let _ = writeln!(stderr, "  {}", report::sanitize(line));
            }
        } else {
            print_error(&self.to_string());
        }
    }
}

/// Parses the process arguments and runs; the whole binary.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => return report_clap_error(&error),
    };
    if cli.command.is_none() {
        return match crate::tui::run(cli.charset, cli.preset.as_deref(), cli.data.clone()) {
            Ok(exit) => ExitCode::from(exit.code()),
            Err(error) => {
                print_error(&error.to_string());
                ExitCode::from(2)
            }
        };
    }
    let mut out = BufWriter::with_capacity(1 << 16, io::stdout().lock());
    let result = run(&cli, &mut out).and_then(|()| out.flush().map_err(CliError::from));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // `microslip sweep ... | head`: the reader left; that is not an error.
        Err(CliError::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(error) => {
            error.print();
            ExitCode::from(error.exit_code())
        }
    }
}

/// The one error line on stderr. Errors echo what users gave (preset names, paths, values, CSV
/// headers), so the whole line is sanitized here, once, at the edge: a control character in any of
/// them is shown escaped instead of reaching the terminal.
fn print_error(message: &str) {
    // Not `eprintln!`, which panics when stderr is gone (a terminal that hung up).
    let _ = writeln!(io::stderr(), "microslip: {}", report::sanitize(message));
}

/// Help and version go to stdout as clap writes them; every other parse error becomes one line.
fn report_clap_error(error: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        error.kind(),
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
    ) {
        // Written like any other output: a full disk or a closed terminal is an error, a reader
        // that left (`microslip --help | head -3`) is not.
        let written = error.print().and_then(|()| io::stdout().flush());
        return match written {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            Err(e) => {
                let error = CliError::Output(e);
                print_error(&error.to_string());
                ExitCode::from(error.exit_code())
            }
        };
    }
    let rendered = error.render().to_string();
    let first_block: Vec<&str> = rendered
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect();
    let line = first_block.join(" ");
    let line = line.strip_prefix("error: ").unwrap_or(&line);
    print_error(&format!("{line} (see --help)"));
    ExitCode::from(2)
}

/// Runs a parsed command, writing results to `out`.
pub fn run(cli: &Cli, out: &mut impl Write) -> Result<(), CliError> {
    match &cli.command {
        None | Some(Command::Report) => out.write_all(report::paper_report().as_bytes())?,
        Some(Command::Beam(args)) => {
            let (name, beams, force) = load_beams(&args.inputs, "beam")?;
            match args.format {
                ReportFormat::Text => out.write_all(text::beam(&name, &beams, force).as_bytes())?,
                ReportFormat::Json => write_json(out, &json::beam(&name, &beams, force))?,
            }
        }
        Some(Command::Plate {
            point: args,
            continuum,
        }) => {
            let (name, plate) = load_plate(&args.inputs, "plate")?;
            let solved = (*continuum
                || plate.validity().validity != crate::kernel::validity::Validity::Holds)
                .then(|| {
                    crate::problems::plate::solve_plate_continuum(
                        plate.params(),
                        crate::problems::plate::ContinuumMesh::default(),
                    )
                });
            if *continuum && let Some(Err(e)) = &solved {
                return Err(CliError::Numeric(e.clone()));
            }
            match args.format {
                ReportFormat::Text => {
                    out.write_all(text::plate(&name, &plate, solved.as_ref()).as_bytes())?
                }
                ReportFormat::Json => {
                    write_json(out, &json::plate(&name, &plate, solved.as_ref()))?
                }
            }
        }
        Some(Command::Sweep(SweepCommand::Beam {
            vary,
            from,
            to,
            points,
            spacing,
            inputs,
            format,
        })) => {
            let varied: BeamParam = vary.as_deref().unwrap_or("F").parse()?;
            let param = Param::Beam(varied);
            let values = Samples::of_param(param, *from, *to, *points, spacing.spacing(param))
                .map_err(force_range_error)?;
            let (_, beams, force) = load_beams(inputs, "sweep beam")?;
            if varied == BeamParam::Force {
                let rows =
                    load::force_sweep::<TwinBeamsLoad>(beams, values).map_err(force_range_error)?;
                write_table(out, *format, rows.map(|r| BeamRow::from(&r)))?;
            } else {
                let rows = curves::beam_param_sweep(beams, force, varied, values)
                    .map_err(force_range_error)?;
                write_varied(
                    out,
                    *format,
                    param,
                    rows.map(|(v, r)| (v, BeamRow::from(&r))),
                )?;
            }
        }
        Some(Command::Lap {
            point: args,
            continuum,
        }) => {
            let (name, joint, force) = load_lap(&args.inputs, "lap")?;
            let solved = (*continuum
                || joint.validity(force).validity != crate::kernel::validity::Validity::Holds)
                .then(|| {
                    crate::problems::lap::solve_lap_continuum(
                        joint.params(),
                        force.newtons(),
                        crate::problems::lap::LapContinuumMesh::default(),
                    )
                });
            // An answer asked for with --continuum that could not be given is an error (nothing on
            // stdout; exit 2 for inputs it refuses, 1 for a failed solve: `CliError::exit_code`);
            // the automatic one is reported as failed in the output.
            if *continuum && let Some(Err(e)) = &solved {
                return Err(CliError::Numeric(e.clone()));
            }
            match args.format {
                ReportFormat::Text => {
                    out.write_all(text::lap(&name, &joint, force, solved.as_ref()).as_bytes())?
                }
                ReportFormat::Json => {
                    write_json(out, &json::lap(&name, &joint, force, solved.as_ref()))?
                }
            }
        }
        Some(Command::Sweep(SweepCommand::Lap(args))) => run_lap_sweep(out, args)?,
        Some(Command::Sweep(SweepCommand::Plate {
            kt_from,
            kt_to,
            vary,
            from,
            to,
            points,
            spacing,
            inputs,
            format,
        })) => {
            let (varied, lo, hi, flags) = match (kt_from, kt_to, from, to) {
                (Some(a), Some(b), None, None) => (
                    PlateParam::Stiffness,
                    *a,
                    *b,
                    ["--kt-from", "--kt-to", "--points"],
                ),
                (None, None, Some(a), Some(b)) => (
                    vary.as_deref().unwrap_or("KT").parse()?,
                    *a,
                    *b,
                    ["--from", "--to", "--points"],
                ),
                _ => {
                    return Err(CliError::Usage(
                        "sweep plate needs --kt-from A --kt-to B, or [--vary NAME] --from A --to B",
                    ));
                }
            };
            let param = Param::Plate(varied);
            let range_error = |error| CliError::Range { error, flags };
            let values = Samples::of_param(param, lo, hi, *points, spacing.spacing(param))
                .map_err(range_error)?;
            let (_, plate) = load_plate(inputs, "sweep plate")?;
            if varied == PlateParam::Stiffness {
                let rows = curves::plate_kt_sweep(plate, values).map_err(range_error)?;
                write_table(out, *format, rows.map(|r| PlateRow::from(&r)))?;
            } else {
                let rows = curves::plate_param_sweep(plate, varied, values).map_err(range_error)?;
                write_varied(
                    out,
                    *format,
                    param,
                    rows.map(|(v, r)| (v, PlateRow::from(&r))),
                )?;
            }
        }
        Some(Command::Solve {
            model,
            vary,
            target,
            from,
            to,
            inputs,
            format,
        }) => {
            let param = model.param(vary)?;
            let target = Target::parse(target, *model)?;
            let range = from.zip(*to);
            let (name, validated) = load(inputs, *model, &model_command(*model, "solve"))?;
            let solved = solve_for_target(&validated, param, target, range)?;
            match format {
                ReportFormat::Text => {
                    out.write_all(text::solved(&name, *model, &solved).as_bytes())?
                }
                ReportFormat::Json => write_json(out, &json::solved(&name, *model, &solved))?,
            }
        }
        Some(Command::Fit(FitCommand::Beam {
            data,
            inputs,
            fixed,
            weights,
            format,
        })) => run_fit(out, ModelKind::Beam, data, inputs, fixed, *weights, *format)?,
        Some(Command::Fit(FitCommand::Lap {
            data,
            inputs,
            fixed,
            weights,
            format,
        })) => run_fit(out, ModelKind::Lap, data, inputs, fixed, *weights, *format)?,
        Some(Command::Kt {
            inputs,
            element_size,
            tolerance: Some(tolerance),
            of,
            from,
            to,
            format,
            ..
        }) => run_kt_tolerance(
            out,
            inputs,
            *element_size,
            (tolerance, *of),
            [*from, *to],
            *format,
        )?,
        Some(Command::Kt {
            inputs,
            element_size,
            kn,
            nu,
            format,
            ..
        }) => run_kt(out, inputs, *element_size, *kn, *nu, *format)?,
        Some(Command::Cycle {
            amplitude,
            inputs,
            points,
            format,
        }) => run_cycle(out, *amplitude, inputs, *points, *format)?,
        Some(Command::Sweep(SweepCommand::Cycle {
            from,
            to,
            points,
            inputs,
            format,
        })) => {
            let amplitudes =
                curves::force_samples(*from, *to, *points).map_err(force_range_error)?;
            match load_any_structure(inputs, ModelKind::Beam)?.1 {
                Model::Beam { beams, .. } => {
                    let rows = load::cycle_sweep::<TwinBeamsLoad>(beams, amplitudes)
                        .map_err(force_range_error)?;
                    write_table(out, *format, rows.map(|r| CycleRow::from(&r)))?;
                }
                Model::Lap { joint, .. } => {
                    let rows = load::cycle_sweep::<LapLoad>(joint, amplitudes)
                        .map_err(force_range_error)?;
                    write_table(out, *format, rows.map(|r| CycleRow::from(&r)))?;
                }
                Model::Plate(_) => return Err(plate_has_no_cycle(inputs, "sweep cycle")),
            }
        }
        Some(Command::Presets) => {
            let dir = preset::user_preset_dir();
            let rows = preset::listing(dir.as_deref());
            out.write_all(report::presets::listing(&rows, dir.as_deref()).as_bytes())?
        }
        Some(Command::Check { files }) => check(out, files)?,
        Some(Command::Plot {
            chart,
            inputs,
            fe,
            y,
            pins,
            family,
            series,
            no_cursor,
            format,
            output,
        }) => {
            refuse_overwriting_an_input(output.as_deref(), &inputs.read_files())?;
            // Before any work: a file name that no format has is refused at once.
            let format = FigureFormat::choose(
                *format,
                output.as_deref(),
                "-o/--output",
                &[
                    FigureFormat::Svg,
                    FigureFormat::Png,
                    FigureFormat::Pdf,
                    FigureFormat::Csv,
                ],
                FigureFormat::Svg,
            )?;
            let command = format!("plot (a {} chart)", chart.kind());
            let (_, model) = load(inputs, chart.kind(), &command)?;
            let shown = shown_roles(series.as_deref(), *no_cursor)?;
            if let Some(spec) = family {
                if !pins.is_empty() {
                    return Err(CliError::Invalid(format!(
                        "--family {spec} and --pin: a family has no current curve to pin against; \
                         add the pinned values to the family instead"
                    )));
                }
                if *fe {
                    return Err(CliError::Invalid(format!(
                        "--family {spec} and --fe: finite-element points are of one model; draw \
                         them with one plot per value"
                    )));
                }
            }
            let plot = crate::chart::figure(&model, *chart, *fe, YMode::Linear)?;
            // The chart's own default falls back to linear where it cannot apply (u(L) = 0 at
            // nu = 0 on a log axis); a mode asked for with --y is refused instead.
            let mode = match y {
                Some(mode) => *mode,
                None => Some(YMode::default_for(*chart))
                    .filter(|m| m.applies_to(&plot))
                    .unwrap_or(YMode::Linear),
            };
            if !mode.applies_to(&plot) {
                return Err(CliError::Invalid(format!(
                    "--y {}: chart {} cannot show it (log needs values > 0, none negative; relative needs a Coulomb curve over increasing x, nowhere zero past its start)",
                    mode.label(),
                    chart.key()
                )));
            }
            let plot = match family {
                Some(spec) => {
                    let (param, members) = family_models(&model, spec)?;
                    crate::chart::family::build_family(
                        *chart,
                        param,
                        &members,
                        mode,
                        shown.as_deref().unwrap_or_default(),
                    )
                    .map_err(|e| CliError::Invalid(format!("--family {spec}: {e}")))?
                }
                None => {
                    let mut plot = mode.apply(plot);
                    if let Some(roles) = &shown {
                        keep_roles(&mut plot, roles, chart.key())?;
                    }
                    if *no_cursor {
                        plot.series.retain(|s| s.role != SeriesRole::Cursor);
                    }
                    let pinned = pinned_models(&model, pins)?;
                    let plot =
                        crate::chart::pins::with_pinned_models(plot, &model, *chart, &pinned, mode);
                    // A figure names each curve by its own values (the terminal's `mu 0.2->0.3`
                    // reads as a change on paper); CSV keeps its series names.
                    let own: Vec<(u8, crate::Inputs)> =
                        (1u8..).zip(pinned.iter().map(|m| m.inputs())).collect();
                    let mut plot = match format.figure() {
                        Some(_) => crate::chart::pins::named_by_values(plot, &model.inputs(), &own),
                        None => plot,
                    };
                    plot.caption = Some(crate::chart::family::parameter_text(
                        &model.inputs(),
                        &[chart.x_param()],
                    ));
                    plot
                }
            };
            let bytes = match format.figure() {
                Some(figure_format) => figure::render(&plot, figure_format)?,
                None => chart_csv(&plot)?,
            };
            write_output(out, output.as_deref(), &bytes)?
        }
        Some(Command::Figures {
            out: dir,
            no_fe,
            format,
            inputs,
        }) => {
            let format = FigureFormat::choose(
                Some(*format),
                None,
                "--format",
                &[FigureFormat::Svg, FigureFormat::Png, FigureFormat::Pdf],
                FigureFormat::Svg,
            )?
            .figure()
            .unwrap_or(figure::Format::Svg);
            run_figures(out, dir, !*no_fe, format, inputs)?
        }
        Some(Command::Compare {
            model,
            results,
            deck,
            inputs,
            format,
        }) => run_compare(out, *model, results, deck.as_deref(), inputs, *format)?,
        Some(Command::Deck {
            code: FeCode::Ccx,
            model,
            deck,
            output,
        }) => {
            refuse_overwriting_an_input(output.as_deref(), &deck.inputs.read_files())?;
            let deck = build_deck(*model, deck, &model_command(*model, "deck ccx"))?;
            write_output(out, output.as_deref(), deck.as_bytes())?
        }
        Some(Command::Bench {
            code: FeCode::Ccx,
            model,
            deck,
            workdir,
            ccx,
            format,
        }) => run_bench(out, *model, deck, workdir.as_deref(), ccx, *format)?,
        Some(Command::Verify {
            quick,
            elements,
            tolerance,
        }) => {
            let grid = if *quick { Grid::Quick } else { Grid::Full };
            run_verify(out, grid, *elements, *tolerance)?
        }
    }
    Ok(())
}

/// The deck `deck` describes for `model`, as text. `command` names the subcommand in errors.
fn build_deck(model: ModelKind, deck: &DeckArgs, command: &str) -> Result<String, CliError> {
    let slope = if deck.near_coulomb {
        StickSlope::NearCoulomb
    } else {
        StickSlope::Model
    };
    match load(&deck.inputs, model, command)? {
        (_, Model::Beam { beams, .. }) => {
            let loads = deck_loads(&beams, deck.loads.as_deref(), slope)?;
            let force_step = deck
                .increment
                .map(|f| check_flag("--increment", f, Domain::FORCE_STEP, Unit::Newton))
                .transpose()?;
            let path = deck::LoadPath { force_step };
            deck::beam_deck_on_path(&beams, &loads, deck.mesh, slope, path)
        }
        (_, Model::Lap { joint, .. }) => {
            let loads = lap_deck_loads(&joint, deck.loads.as_deref(), slope)?;
            let force_step = deck
                .increment
                .map(|f| check_flag("--increment", f, Domain::FORCE_STEP, Unit::Newton))
                .transpose()?;
            crate::fe::lap_deck::lap_deck(
                &joint,
                &loads,
                deck.mesh,
                slope,
                deck::LoadPath { force_step },
            )
        }
        (_, Model::Plate(plate)) => {
            if deck.loads.is_some() {
                return Err(CliError::Usage(
                    "--loads are the tip forces of a beam deck; the plate deck applies its \
                     pressure P in one step (set P with --set P=...)",
                ));
            }
            deck::plate_deck(&plate, deck.mesh, slope)
        }
    }
    .map_err(|e| CliError::Invalid(e.to_string()))
}

/// `microslip bench ccx MODEL`: the deck into a work folder, ccx on it with progress on stderr,
/// then the comparison as `compare` prints it. The folder is kept and named on stderr.
fn run_bench(
    out: &mut impl Write,
    model: ModelKind,
    deck: &DeckArgs,
    workdir: Option<&std::path::Path>,
    ccx: &str,
    format: CompareFormat,
) -> Result<(), CliError> {
    let text = build_deck(model, deck, &model_command(model, "bench ccx"))?;
    // Before the folder is made: a refused --ccx leaves nothing behind.
    let program = fe::run::resolve_program(ccx)?;
    let job = model.name();
    let files = match workdir {
        Some(folder) => fe::run::claim_folder(folder, job)?,
        None => {
            let folder = fe::run::fresh_folder(&std::env::temp_dir(), job)?;
            fe::run::RunFiles::new(&folder, job)
        }
    };
    crate::file::write_new_files(&[(files.deck.as_path(), text.as_bytes())])?;
    let stop = StopSignals::install()?;
    let stderr = io::stderr();
    let terminal = stderr.is_terminal();
    let mut progress = ProgressLine::new(stderr.lock(), terminal);
    let shown = files.folder.display().to_string();
    let started = Instant::now();
    let mut announced = false;
    let mut increments_said = 0;
    let result = fe::run::run_ccx(
        &program,
        &files,
        Duration::from_millis(50),
        &mut |p| {
            // Said once ccx runs: a missing ccx is then one line of error, not two.
            if !announced {
                eprintln!("microslip: running {ccx} on {}", files.deck.display());
                announced = true;
            }
            if terminal {
                progress.update(Instant::now(), || text::ccx_progress(p));
            } else if p.increments > increments_said {
                // A log or a CI job sees a line per increment, not minutes of silence.
                increments_said = p.increments;
                eprintln!(
                    "microslip: {}, increment {}",
                    text::ccx_progress(p),
                    p.increments
                );
            }
        },
        &|| stop.received(),
    );
    drop(progress);
    result?;
    if let Some(signal) = stop.received() {
        return Err(fe::run::RunError::Stopped {
            signal,
            folder: shown,
        }
        .into());
    }
    eprintln!(
        "microslip: ccx took {:.0} s; its files and log ({}) are kept in {shown}",
        started.elapsed().as_secs_f64(),
        files.log.display()
    );
    run_compare(
        out,
        model,
        std::slice::from_ref(&files.results),
        Some(&files.deck),
        &deck.inputs,
        format,
    )
}

/// A sweep over `param`: its column (named with its unit, `mu`, `L_mm`) first, then the rows.
fn write_varied<R: serde::Serialize + Default>(
    out: &mut impl Write,
    format: TableFormat,
    param: Param,
    rows: impl Iterator<Item = (f64, R)>,
) -> io::Result<()> {
    write_table_after(
        out,
        format,
        &json::suffixed(param.name(), param.unit()),
        rows,
    )
}

/// SIGTERM, SIGINT and SIGHUP while `bench` runs the solver: recorded instead of ending
/// microslip at once, so that the solver (in a process group of its own, out of the terminal's
/// reach) is ended first; microslip then exits with 128 + the signal, as the default action
/// would have.
struct StopSignals {
    received: std::sync::Arc<std::sync::atomic::AtomicUsize>,
}

impl StopSignals {
    fn install() -> io::Result<StopSignals> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let received = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
        for signal in [SIGTERM, SIGINT, SIGHUP] {
            signal_hook::flag::register_usize(
                signal,
                std::sync::Arc::clone(&received),
                signal as usize,
            )?;
        }
        Ok(StopSignals { received })
    }

    /// The last signal received, if any.
    fn received(&self) -> Option<i32> {
        match self.received.load(std::sync::atomic::Ordering::SeqCst) {
            0 => None,
            n => i32::try_from(n).ok(),
        }
    }
}

/// A force range error, named by the flags `--from`, `--to`, `--points`.
fn force_range_error(error: RangeError) -> CliError {
    CliError::Range {
        error,
        flags: ["--from", "--to", "--points"],
    }
}

/// `microslip compare`: reads every result file, builds the closed forms from its deck's header (or
/// from `--preset`/`--set` for CSV) and prints the comparison.
/// Says on stderr which parameter flags a CalculiX run's deck overrides: its header gives the
/// parameters the run was made with, and comparing at others would mean nothing (they used to be
/// ignored without a word).
fn note_flags_the_deck_overrides(inputs: &InputArgs, model: ModelKind) {
    let given = inputs.flags();
    if given.is_empty() {
        return;
    }
    eprintln!("microslip: note: {}", deck_overrides_words(&given, model));
}

/// The words of [`note_flags_the_deck_overrides`]: only the beams have two beam theories, so
/// only their note says that both are shown.
fn deck_overrides_words(given: &[String], model: ModelKind) -> String {
    let theories = match model {
        ModelKind::Beam => " (compare shows both beam theories)",
        ModelKind::Plate | ModelKind::Lap => "",
    };
    format!(
        "{} not used: the deck's header gives the parameters of the run{theories}; to compare FE \
         points at other parameters, give them as CSV",
        report::sanitize(&given.join(" "))
    )
}

fn run_compare(
    out: &mut impl Write,
    model: ModelKind,
    results: &[PathBuf],
    deck: Option<&std::path::Path>,
    inputs: &InputArgs,
    format: CompareFormat,
) -> Result<(), CliError> {
    let data_error = |e: LoadError| CliError::Data {
        path: e.path,
        reason: e.reason,
    };
    if deck.is_some() && results.len() > 1 {
        return Err(CliError::Flag {
            flag: "--deck",
            value: results.len() as f64,
            allowed: "--deck names the deck of one result file; give one result".to_string(),
        });
    }
    let source: Vec<String> = results.iter().map(|p| p.display().to_string()).collect();
    let source = source.join(", ");
    match model {
        ModelKind::Lap => {
            let mut rows = Vec::new();
            for path in results {
                let loaded = fe::load::lap_results(path, deck).map_err(data_error)?;
                if loaded.header.is_some() && rows.is_empty() {
                    note_flags_the_deck_overrides(inputs, model);
                }
                let joint = match &loaded.header {
                    Some(header) => header.model()?.into_lap().map_err(deck_of_other_model)?.0,
                    // The FE forces are compared, not the preset's F.
                    None => load_lap_structure(inputs, "compare lap")?.1,
                };
                let compared = fe::compare::compare_lap(
                    &joint,
                    &loaded.points,
                    loaded.interface_mesh.as_ref(),
                )
                .map_err(|e| CliError::Data {
                    path: path.display().to_string(),
                    reason: e.to_string(),
                })?;
                rows.extend(compared);
            }
            let report = report::compare::lap::LapCompareReport::new(&source, &rows);
            let csv = rows.iter().map(report::compare::LapCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
        ModelKind::Beam => {
            let [path] = results else {
                return Err(CliError::Flag {
                    flag: "RESULT",
                    value: results.len() as f64,
                    allowed: "compare beam takes one result file (all load steps of one run)"
                        .to_string(),
                });
            };
            let loaded = fe::load::beam_results(path, deck).map_err(data_error)?;
            if loaded.header.is_some() {
                note_flags_the_deck_overrides(inputs, model);
            }
            let beams = match &loaded.header {
                Some(header) => header.model()?.into_beams().map_err(deck_of_other_model)?.0,
                // A CSV has no header: the parameters come from the flags.
                None => load_beams_structure(inputs, "compare beam")?.1,
            };
            let comparison =
                fe::compare::compare_beams(&beams, &loaded.points, loaded.interface_mesh.as_ref());
            let report = report::compare::beam::BeamCompareReport::new(&source, &comparison);
            let csv = comparison
                .rows
                .iter()
                .map(report::compare::BeamCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
        ModelKind::Plate => {
            let mut rows = Vec::new();
            for path in results {
                let loaded = fe::load::plate_results(path, deck).map_err(data_error)?;
                if loaded.header.is_some() && rows.is_empty() {
                    note_flags_the_deck_overrides(inputs, model);
                }
                let plate = match &loaded.header {
                    Some(header) => header.model()?.into_plate().map_err(deck_of_other_model)?,
                    None => load_plate(inputs, "compare plate")?.1,
                };
                rows.extend(fe::compare::compare_plate(
                    &plate,
                    &loaded.points,
                    loaded.interface_mesh.as_ref(),
                ));
            }
            let report = report::compare::plate::PlateCompareReport::new(&source, &rows);
            let csv = rows.iter().map(report::compare::PlateCompareRow::from);
            write_comparison(out, format, &report.text(), &report, csv)?;
        }
    }
    Ok(())
}

/// A comparison in the format asked for: its text, its report as JSON, or its rows as CSV.
fn write_comparison<R: serde::Serialize + Default>(
    out: &mut impl Write,
    format: CompareFormat,
    text: &str,
    report: &impl serde::Serialize,
    rows: impl Iterator<Item = R>,
) -> Result<(), CliError> {
    match format {
        CompareFormat::Text => out.write_all(text.as_bytes())?,
        CompareFormat::Json => write_json(out, &report::point::to_json(report))?,
        CompareFormat::Csv => write_table(out, TableFormat::Csv, rows)?,
    }
    Ok(())
}

/// `command` followed by the model's name, for error messages ("deck ccx beam").
fn model_command(model: ModelKind, command: &str) -> String {
    format!("{command} {model}")
}

/// The load steps of a beam deck: `--loads` checked (each a valid force, strictly increasing), or
/// the default multiples of F_thre, which span microslip and macroslip. With a near-Coulomb stick
/// slope the interface is on the edge of sliding everywhere at exactly F_thre, and CalculiX's
/// contact iterations can chatter there until they give up; the default then stops at 0.95 F_thre.
fn deck_loads(
    beams: &TwinBeams,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<TipForce>, CliError> {
    let Some(loads) = loads else {
        let thre = beams.threshold_force();
        let at_threshold = match slope {
            StickSlope::Model => 1.0,
            StickSlope::NearCoulomb => 0.95,
        };
        return Ok([0.5, 0.75, at_threshold, 1.25, 1.875, 2.5]
            .map(|m| TipForce::clamped(m * thre))
            .to_vec());
    };
    let mut forces = Vec::with_capacity(loads.len());
    for &f in loads {
        let force = check_flag("--loads", f, Domain::FORCE, Unit::Newton)?;
        if forces
            .last()
            .is_some_and(|last: &TipForce| last.newtons() >= force)
        {
            return Err(CliError::Flag {
                flag: "--loads",
                value: f,
                allowed: "the loads must increase from one step to the next".to_string(),
            });
        }
        forces.push(TipForce::clamped(force));
    }
    Ok(forces)
}

/// The forces of a lap deck's steps: `--loads` (increasing, each at most F_gross), or one in each
/// regime: all microslip (F_1/2), one end sliding, both ends, and 0.9 F_gross (at the deck's
/// stick slope).
fn lap_deck_loads(
    joint: &LapJoint,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<JointForce>, CliError> {
    let at_slope = joint
        .with_tangential_stiffness(slope.value_for_lap(joint))
        .unwrap_or(*joint);
    let Some(loads) = loads else {
        let (f1, f2, gross) = (
            at_slope.first_slip_force(),
            at_slope.second_slip_force(),
            at_slope.gross_slip_force(),
        );
        let mut forces: Vec<f64> = vec![0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.9 * gross];
        forces.dedup_by(|a, b| *a <= *b);
        return Ok(forces.into_iter().map(|f| joint.clamped_force(f)).collect());
    };
    let mut forces: Vec<JointForce> = Vec::with_capacity(loads.len());
    for &f in loads {
        let force = joint.force(f).map_err(|e| CliError::Flag {
            flag: "--loads",
            value: f,
            allowed: e.allowed(),
        })?;
        if forces.last().is_some_and(|last| *last >= force) {
            return Err(CliError::Flag {
                flag: "--loads",
                value: f,
                allowed: "the loads must increase from one step to the next".to_string(),
            });
        }
        forces.push(force);
    }
    Ok(forces)
}

/// A count as users write numbers, the README's notation included: `101`, `1e8`. Anything but a
/// whole number of at most 1e15 (a negative, a fraction, a word) is refused with what is expected;
/// the range of each count is checked where it is used.
fn parse_count(text: &str) -> Result<u64, String> {
    let refuse = || format!("must be a whole number such as 101 or 1e8 (got '{text}')");
    let value = parse_number(text.trim()).ok_or_else(refuse)?;
    if value < 0.0 || value.fract() != 0.0 || value > 1e15 {
        return Err(refuse());
    }
    Ok(value as u64)
}

/// Refuses an output file that is one this command reads (`deck ccx lap --preset p.toml -o
/// p.toml` replaced the preset it was reading with the deck): `reads` are the command's input
/// files, `-o` is compared with each as a file ([`crate::file::same_file`]), not as text. Checked
/// before anything is computed or written.
fn refuse_overwriting_an_input(
    output: Option<&std::path::Path>,
    reads: &[(&str, PathBuf)],
) -> Result<(), CliError> {
    let Some(output) = output else {
        return Ok(());
    };
    for (flag, read) in reads {
        if crate::file::same_file(output, read) {
            return Err(CliError::Invalid(format!(
                "-o {}: that is the file this command reads ({flag} {}); write to another file",
                output.display(),
                read.display()
            )));
        }
    }
    Ok(())
}

/// Writes `bytes` to `path` ([`crate::file::write_atomic`]: a regular file replaced atomically with
/// its mode kept, a device or FIFO written through, a link followed, a read-only file refused), or
/// to `out` when there is no path or it is `-` or `/dev/stdout` (the program's own standard output,
/// whatever it is redirected to, is written as a stream, never replaced).
fn write_output(
    out: &mut impl Write,
    path: Option<&std::path::Path>,
    bytes: &[u8],
) -> Result<(), CliError> {
    let to_stdout = |p: &std::path::Path| {
        p == std::path::Path::new("-") || p == std::path::Path::new("/dev/stdout")
    };
    match path {
        Some(path) if !to_stdout(path) => {
            crate::file::write_atomic(path, bytes, true).map_err(|e| CliError::Data {
                path: path.display().to_string(),
                reason: e.to_string(),
            })
        }
        _ => Ok(out.write_all(bytes)?),
    }
}

/// Resolves the preset (default: the paper's data set of `wanted`), applies `--set`, validates.
/// `command` (as typed after `microslip`) names the command when the preset is of another problem.
/// The roles of `plot --series` (None: not given), without the cursor under `--no-cursor`.
fn shown_roles(series: Option<&str>, no_cursor: bool) -> Result<Option<Vec<SeriesRole>>, CliError> {
    let Some(list) = series else {
        return Ok(None);
    };
    let allowed: Vec<&str> = SeriesRole::CHART_ROLES
        .iter()
        .filter_map(|r| r.key())
        .collect();
    let mut roles = Vec::new();
    for key in list.split(',').map(str::trim) {
        let role = SeriesRole::from_key(key).ok_or_else(|| {
            CliError::Invalid(format!(
                "--series {list}: unknown series '{key}' (allowed: {})",
                allowed.join(", ")
            ))
        })?;
        if role == SeriesRole::Cursor && no_cursor {
            return Err(CliError::Invalid(format!(
                "--series {list} and --no-cursor: the one asks for the cursor, the other leaves it out"
            )));
        }
        if !roles.contains(&role) {
            roles.push(role);
        }
    }
    Ok(Some(roles))
}

/// `plot` with only the series of `roles` (and any pins); a role the chart does not have is
/// refused, naming those it has, and so is a selection that leaves nothing but the cursor.
fn keep_roles(
    plot: &mut crate::chart::Plot,
    roles: &[SeriesRole],
    chart: &str,
) -> Result<(), CliError> {
    let present: Vec<SeriesRole> = plot.series.iter().map(|s| s.role).collect();
    if let Some(missing) = roles.iter().find(|r| !present.contains(r)) {
        let keys: Vec<&str> = present.iter().filter_map(|r| r.key()).collect();
        let hint = match missing {
            SeriesRole::FiniteElements => " (fe needs --fe)",
            _ => "",
        };
        return Err(CliError::Invalid(format!(
            "--series: chart {chart} has no {} series{hint}; it has: {}",
            missing.key().unwrap_or("?"),
            keys.join(", ")
        )));
    }
    if roles.iter().all(|&r| r == SeriesRole::Cursor) {
        return Err(CliError::Invalid(
            "--series cursor: nothing to draw but the cursor; add a curve (current, coulomb, ...)"
                .to_string(),
        ));
    }
    plot.series.retain(|s| roles.contains(&s.role));
    Ok(())
}

/// The members of `plot --family KEY=V1,V2,...`: each value set on top of `model`'s inputs and
/// checked as `--set` checks it (the same messages, after the flag).
fn family_models(model: &Model, spec: &str) -> Result<(crate::Param, Vec<(f64, Model)>), CliError> {
    use crate::chart::family::MAX_MEMBERS;
    let refuse = |why: String| CliError::Invalid(format!("--family {spec}: {why}"));
    let (key, values) = spec
        .split_once('=')
        .ok_or_else(|| refuse("expected KEY=V1,V2,... (e.g. P=0.5,1,2)".to_string()))?;
    let key = key.trim();
    let param = model.kind().param(key).map_err(|e| refuse(e.to_string()))?;
    let values: Vec<&str> = values.split(',').map(str::trim).collect();
    if values.len() > MAX_MEMBERS {
        return Err(refuse(format!(
            "{} values given, at most {MAX_MEMBERS} (more curves cannot be told apart)",
            values.len()
        )));
    }
    let mut members: Vec<(f64, Model)> = Vec::with_capacity(values.len());
    for value in values {
        let mut inputs = model.inputs();
        preset::apply_assignment(&mut inputs, &format!("{key}={value}"))
            .map_err(|e| refuse(e.to_string()))?;
        let member = inputs.validate().map_err(|e| refuse(e.to_string()))?;
        let number = member.inputs().get(param).unwrap_or(f64::NAN);
        if members.iter().any(|(v, _)| *v == number) {
            return Err(refuse(format!("{key} = {value} is given twice")));
        }
        members.push((number, member));
    }
    Ok((param, members))
}

/// The models of `plot --pin`: each pin's assignments on top of `model`'s inputs.
fn pinned_models(model: &Model, pins: &[String]) -> Result<Vec<Model>, CliError> {
    use crate::chart::pins::MAX_PINS;
    if pins.len() > MAX_PINS {
        return Err(CliError::Invalid(format!(
            "--pin: {} pins given, at most {MAX_PINS} (more curves cannot be told apart)",
            pins.len()
        )));
    }
    pins.iter()
        .map(|pin| {
            let mut inputs = model.inputs();
            let mut keys: Vec<&str> = Vec::new();
            for assignment in pin.split(',').map(str::trim) {
                let key = assignment.split('=').next().unwrap_or("").trim();
                if keys.contains(&key) {
                    return Err(CliError::Invalid(format!(
                        "--pin {pin}: {key} is given twice; a pin sets each parameter once"
                    )));
                }
                keys.push(key);
                preset::apply_assignment(&mut inputs, assignment)
                    .map_err(|e| CliError::Invalid(format!("--pin {pin}: {e}")))?;
            }
            inputs
                .validate()
                .map_err(|e| CliError::Invalid(format!("--pin {pin}: {e}")))
        })
        .collect()
}

fn load(args: &InputArgs, wanted: ModelKind, command: &str) -> Result<(String, Model), CliError> {
    load_for(args, wanted, command, Load::Used)
}

/// Whether a command reads the model's load (F): one that does not (a cycle's amplitude, a fit's
/// or a comparison's own forces) must not be refused over it (issue 36).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Load {
    /// The command uses F: validated against everything (the lap joint's F <= F_gross).
    Used,
    /// The command does not: F checked against its own domain only, the model unloaded.
    Unused,
}

fn load_for(
    args: &InputArgs,
    wanted: ModelKind,
    command: &str,
    load: Load,
) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, wanted)?;
    if preset.inputs.kind() != wanted {
        return Err(wrong_model(args, preset.inputs.kind(), wanted, command));
    }
    apply_and_validate(args, name, preset, load)
}

/// The twin beams and tip force of `args` (a preset of another problem is refused by name).
fn load_beams(args: &InputArgs, command: &str) -> Result<(String, TwinBeams, TipForce), CliError> {
    let (name, model) = load(args, ModelKind::Beam, command)?;
    let (beams, force) = model
        .into_beams()
        .map_err(|found| wrong_model(args, found, ModelKind::Beam, command))?;
    Ok((name, beams, force))
}

/// The squeezed plate of `args` (a preset of another problem is refused by name).
fn load_plate(args: &InputArgs, command: &str) -> Result<(String, SqueezedPlate), CliError> {
    let (name, model) = load(args, ModelKind::Plate, command)?;
    let plate = model
        .into_plate()
        .map_err(|found| wrong_model(args, found, ModelKind::Plate, command))?;
    Ok((name, plate))
}

/// The lap joint and force of `args` (a preset of another problem is refused by name).
fn load_lap(args: &InputArgs, command: &str) -> Result<(String, LapJoint, JointForce), CliError> {
    let (name, model) = load(args, ModelKind::Lap, command)?;
    let (joint, force) = model
        .into_lap()
        .map_err(|found| wrong_model(args, found, ModelKind::Lap, command))?;
    Ok((name, joint, force))
}

/// The lap joint of `args` for a command that does not use its F ([`Load::Unused`]).
fn load_lap_structure(args: &InputArgs, command: &str) -> Result<(String, LapJoint), CliError> {
    let (name, model) = load_for(args, ModelKind::Lap, command, Load::Unused)?;
    let (joint, _) = model
        .into_lap()
        .map_err(|found| wrong_model(args, found, ModelKind::Lap, command))?;
    Ok((name, joint))
}

/// The twin beams of `args` for a command that does not use their F ([`Load::Unused`]).
fn load_beams_structure(args: &InputArgs, command: &str) -> Result<(String, TwinBeams), CliError> {
    let (name, model) = load_for(args, ModelKind::Beam, command, Load::Unused)?;
    let (beams, _) = model
        .into_beams()
        .map_err(|found| wrong_model(args, found, ModelKind::Beam, command))?;
    Ok((name, beams))
}

/// `cycle` or `sweep cycle` given the plate, which has no load to cycle.
fn plate_has_no_cycle(args: &InputArgs, command: &str) -> CliError {
    CliError::Invalid(format!(
        "preset '{}' is a plate preset; `microslip {command}` needs a beam or lap preset (the \
         squeezed plate has no load to cycle: its pressure is fixed)",
        args.preset.as_deref().unwrap_or_default()
    ))
}

/// `microslip sweep lap`: over F (rows of the F sweep) or any other parameter.
fn run_lap_sweep(out: &mut impl Write, args: &LapSweepArgs) -> Result<(), CliError> {
    use crate::study::lap::lap_param_sweep;
    let varied: LapParam = args.vary.as_deref().unwrap_or("F").parse()?;
    let param = Param::Lap(varied);
    let values = Samples::of_param(
        param,
        args.from,
        args.to,
        args.points,
        args.spacing.spacing(param),
    )
    .map_err(force_range_error)?;
    let (_, joint, force) = load_lap(&args.inputs, "sweep lap")?;
    if varied == LapParam::Force {
        let rows = load::force_sweep::<LapLoad>(joint, values).map_err(force_range_error)?;
        write_table(out, args.format, rows.map(|r| LapRow::from(&r)))?;
    } else {
        let rows = lap_param_sweep(joint, force, varied, values).map_err(force_range_error)?;
        write_varied(
            out,
            args.format,
            param,
            rows.map(|(v, r)| (v, LapRow::from(&r))),
        )?;
    }
    Ok(())
}

/// A preset of the problem `found` given to a command for `wanted`.
fn wrong_model(args: &InputArgs, found: ModelKind, wanted: ModelKind, command: &str) -> CliError {
    CliError::WrongModel {
        preset: args.preset.clone().unwrap_or_default(),
        found,
        wanted,
        command: command.to_string(),
    }
}

/// A deck whose header describes another problem than the results reader was asked for.
fn deck_of_other_model(found: ModelKind) -> CliError {
    CliError::Invalid(format!(
        "the deck's header describes the {found} problem, not the one compared"
    ))
}

/// Like [`load`], for commands that accept any problem (`default` picks the default preset).
fn load_any(args: &InputArgs, default: ModelKind) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, default)?;
    apply_and_validate(args, name, preset, Load::Used)
}

/// As [`load_any`] for a command that does not use the load ([`Load::Unused`]).
fn load_any_structure(args: &InputArgs, default: ModelKind) -> Result<(String, Model), CliError> {
    let (name, preset) = resolve_preset(args, default)?;
    apply_and_validate(args, name, preset, Load::Unused)
}

fn resolve_preset(args: &InputArgs, default: ModelKind) -> Result<(String, Preset), CliError> {
    let preset = preset::resolve(
        args.preset
            .as_deref()
            .unwrap_or(preset::default_name(default)),
    )?;
    Ok((preset.name.clone(), preset))
}

fn apply_and_validate(
    args: &InputArgs,
    name: String,
    preset: Preset,
    load: Load,
) -> Result<(String, Model), CliError> {
    let mut inputs: Inputs = preset.inputs;
    for assignment in &args.assignments {
        preset::apply_assignment(&mut inputs, assignment)?;
    }
    // "modified" only where a value differs from the preset's: `--set F=3000` on a preset whose F
    // is 3000 leaves the preset as it is, and saying otherwise sends users looking for a change.
    let set_changed = inputs != preset.inputs;
    let before_theory = inputs;
    if let Some(theory) = &args.beam_theory {
        let theory = BeamTheory::parse(theory).map_err(|e| CliError::Theory(e.to_string()))?;
        match &mut inputs {
            Inputs::Beam { structure, .. } => structure.theory = theory,
            Inputs::Plate(_) => {
                return Err(CliError::Theory(
                    "--beam-theory applies to the twin beams, not the plate".to_string(),
                ));
            }
            Inputs::Lap { .. } => {
                return Err(CliError::Theory(
                    "--beam-theory applies to the twin beams, not the lap joint".to_string(),
                ));
            }
        }
    }
    let theory_changed = inputs != before_theory;
    let name = match (set_changed, theory_changed) {
        (false, false) => name,
        (true, false) => format!("{name} (modified by --set)"),
        (false, true) => format!("{name} (modified by --beam-theory)"),
        (true, true) => format!("{name} (modified by --set and --beam-theory)"),
    };
    let model = match load {
        Load::Used => inputs.validate()?,
        Load::Unused => inputs.validate_without_load()?,
    };
    Ok((name, model))
}

/// `--fix` values: (mu, K_T). Only those two are fitted, so only they can be held.
fn parse_fixed(fixed: &[String]) -> Result<(Option<f64>, Option<f64>), CliError> {
    let (mut mu, mut kt) = (None, None);
    for text in fixed {
        let bad = || CliError::Fix(text.clone());
        let (key, value) = text.split_once('=').ok_or_else(bad)?;
        let value = parse_number(value.trim()).ok_or_else(bad)?;
        match key.trim().parse::<BeamParam>().map_err(|_| bad())? {
            BeamParam::Friction => mu = Some(value),
            BeamParam::Stiffness => kt = Some(value),
            _ => return Err(bad()),
        }
    }
    Ok((mu, kt))
}

fn run_fit(
    out: &mut impl Write,
    kind: ModelKind,
    path: &PathBuf,
    inputs: &InputArgs,
    fixed: &[String],
    weights: Option<WeightsArg>,
    format: ReportFormat,
) -> Result<(), CliError> {
    let (fixed_mu, fixed_kt) = parse_fixed(fixed)?;
    let (name, structure) = match kind {
        ModelKind::Lap => {
            // The measured forces are fitted, not the preset's F.
            let (name, joint) = load_lap_structure(inputs, "fit lap")?;
            (name, fit::Structure::Lap(joint.params()))
        }
        ModelKind::Beam | ModelKind::Plate => {
            let (name, beams) = load_beams_structure(inputs, "fit beam")?;
            (name, fit::Structure::Beam(beams.params()))
        }
    };
    let data_error = |reason: String| CliError::Data {
        path: path.display().to_string(),
        reason,
    };
    let mut progress = ProgressLine::new(io::stderr(), io::stderr().is_terminal());
    let contents = crate::measured::read_text(path, crate::file::Kinds::AnyReadable)
        .map_err(|e| data_error(e.to_string()))?;
    let mut reading =
        |done, total| progress.update(Instant::now(), || text::reading_progress(done, total));
    let data = match structure {
        fit::Structure::Beam(_) => {
            crate::measured::parse_measured_with_progress(&contents, &mut reading)
        }
        fit::Structure::Lap(_) => {
            crate::measured::parse_measured_joint_with_progress(&contents, &mut reading)
        }
    };
    drop(contents);
    let crate::fit::Measured {
        points: data,
        sigma,
    } = match data {
        Ok(data) => data,
        Err(e) => {
            progress.finish();
            return Err(data_error(e.to_string()));
        }
    };
    let weights = match (sigma.as_deref(), weights) {
        (Some(sigma), None) => fit::Weights::Sigma(sigma),
        (Some(_), Some(chosen)) => {
            progress.finish();
            return Err(data_error(format!(
                "has a {} column, which gives each point's own standard deviation, and --weights {} \
                 asks for another; drop one",
                crate::measured::SIGMA_COLUMN,
                chosen
                    .to_possible_value()
                    .map_or_else(String::new, |v| v.get_name().to_string())
            )));
        }
        (None, Some(WeightsArg::Absolute)) => fit::Weights::Absolute,
        (None, Some(WeightsArg::Relative) | None) => fit::Weights::default(),
    };
    let result = fit::fit_weighted(structure, &data, (fixed_mu, fixed_kt), weights, &mut |p| {
        progress.update(Instant::now(), || text::fit_progress(&p))
    });
    progress.finish();
    // A column of zeros is the file's fault: said with its path.
    let result = result.map_err(|e| match e {
        FitError::NothingToFit { .. } => data_error(e.to_string()),
        e => CliError::Fit(e),
    })?;
    match format {
        ReportFormat::Text => out.write_all(
            text::fit(&path.display().to_string(), &name, &structure, &result).as_bytes(),
        )?,
        ReportFormat::Json => write_json(
            out,
            &json::fit(&path.display().to_string(), &name, &structure, &result),
        )?,
    }
    Ok(())
}

/// A long fit's progress (reading, then fitting) on stderr: shown only when stderr is a terminal (scripts and pipes see
/// nothing) and once the command has run for [`ProgressLine::AFTER`]; one line rewritten in place
/// at most every [`ProgressLine::EVERY`], erased when the fit ends so that the report starts clean.
struct ProgressLine<W: Write> {
    out: W,
    enabled: bool,
    started: Instant,
    last: Option<Instant>,
    shown: bool,
}

impl<W: Write> ProgressLine<W> {
    /// Quiet for this long: short fits print nothing.
    const AFTER: Duration = Duration::from_secs(1);
    /// Fastest refresh.
    const EVERY: Duration = Duration::from_millis(100);

    fn new(out: W, enabled: bool) -> Self {
        ProgressLine {
            out,
            enabled,
            started: Instant::now(),
            last: None,
            shown: false,
        }
    }

    /// Shows `message()` if it is time to; the message is only built then.
    fn update(&mut self, now: Instant, message: impl FnOnce() -> String) {
        if !self.enabled
            || now.saturating_duration_since(self.started) < Self::AFTER
            || self
                .last
                .is_some_and(|last| now.saturating_duration_since(last) < Self::EVERY)
        {
            return;
        }
        self.last = Some(now);
        self.shown = true;
        // Carriage return and erase-line: the line is rewritten in place. A progress line is
        // best-effort: a failed write must not fail the fit.
        let _ = write!(self.out, "\r\x1b[2Kmicroslip: {}", message());
        let _ = self.out.flush();
    }

    fn finish(&mut self) {
        if self.shown {
            let _ = write!(self.out, "\r\x1b[2K");
            let _ = self.out.flush();
        }
    }
}

/// Checks a flag that is not a model parameter against `domain`.
/// [`Domain::check`] (which also turns -0 into 0) with the flag's name in the refusal.
fn check_flag(flag: &'static str, value: f64, domain: Domain, unit: Unit) -> Result<f64, CliError> {
    domain.check(flag, value, unit).map_err(|_| CliError::Flag {
        flag,
        value,
        allowed: domain.refusal(value, unit),
    })
}

fn run_cycle(
    out: &mut impl Write,
    amplitude: f64,
    inputs: &InputArgs,
    points: u64,
    format: CycleFormat,
) -> Result<(), CliError> {
    let amplitude = check_flag("--amplitude", amplitude, Domain::FORCE, Unit::Newton)?;
    let points_error = |error| CliError::Range {
        error,
        flags: ["", "", "--points"],
    };
    curves::check_points(points).map_err(points_error)?;
    // The amplitude is cycled, not the preset's F.
    let (name, model) = load_any_structure(inputs, ModelKind::Beam)?;
    let beams = match model {
        Model::Beam { beams, .. } => beams,
        Model::Lap { joint, .. } => {
            let amplitude = joint.force(amplitude).map_err(|e| CliError::Flag {
                flag: "--amplitude",
                value: amplitude,
                allowed: e.allowed(),
            })?;
            match format {
                CycleFormat::Text => {
                    out.write_all(text::lap_cycle(&name, &joint, amplitude).as_bytes())?
                }
                CycleFormat::Json => write_json(out, &json::lap_cycle(&name, &joint, amplitude))?,
                CycleFormat::Csv => {
                    let points = load::cycle_loop::<LapLoad>(&joint, amplitude, points)
                        .map_err(points_error)?;
                    write_table(out, TableFormat::Csv, points.map(|p| LapLoopRow::from(&p)))?;
                }
            }
            return Ok(());
        }
        Model::Plate(_) => return Err(plate_has_no_cycle(inputs, "cycle")),
    };
    let amplitude = TipForce::new(amplitude)?;
    match format {
        CycleFormat::Text => out.write_all(text::cycle(&name, &beams, amplitude).as_bytes())?,
        CycleFormat::Json => write_json(out, &json::cycle(&name, &beams, amplitude))?,
        CycleFormat::Csv => {
            let points = load::cycle_loop::<TwinBeamsLoad>(&beams, amplitude, points)
                .map_err(points_error)?;
            write_table(out, TableFormat::Csv, points.map(|p| LoopRow::from(&p)))?;
        }
    }
    Ok(())
}

/// The contact element length of `--element-size`, default L/100.
fn element_size(element: Option<f64>, model: &Model) -> Result<f64, CliError> {
    match element {
        Some(e) => check_flag("--element-size", e, Domain::ELEMENT_SIZE, Unit::Millimetre),
        None => Ok(model.interface().length / 100.0),
    }
}

/// The force range of `kt --tolerance`: `--from` and `--to` (each the model's force when not
/// given), accepted forces, in order.
fn tolerance_forces([from, to]: [Option<f64>; 2], force: f64) -> Result<[f64; 2], CliError> {
    let range = [
        check_flag("--from", from.unwrap_or(force), Domain::FORCE, Unit::Newton)?,
        check_flag("--to", to.unwrap_or(force), Domain::FORCE, Unit::Newton)?,
    ];
    // As `solve` and `sweep`: a reversed range is a typo, not a range.
    if range[0] > range[1] {
        return Err(CliError::Flag {
            flag: "--to",
            value: range[1],
            allowed: format!(
                "must not be below --from = {} N (the forces checked run from --from up to --to)",
                Compact(range[0])
            ),
        });
    }
    Ok(range)
}

fn run_kt_tolerance(
    out: &mut impl Write,
    inputs: &InputArgs,
    element: Option<f64>,
    (tolerance, of): (&str, ToleranceOf),
    [from, to]: [Option<f64>; 2],
    format: ReportFormat,
) -> Result<(), CliError> {
    use crate::study::tolerance::{self, parse_tolerance};
    let tol = parse_tolerance(tolerance).map_err(|e| CliError::Invalid(e.to_string()))?;
    let (name, model) = load_any(inputs, ModelKind::Beam)?;
    let element = element_size(element, &model)?;
    let answer = match model {
        Model::Beam { beams, force } => {
            let range = tolerance_forces([from, to], force.newtons())?;
            match of {
                ToleranceOf::Coulomb => {
                    tolerance::stiffness_for_tolerance::<TwinBeamsLoad>(&beams, range, tol, element)
                }
                ToleranceOf::Current => {
                    tolerance::stiffness_near_current::<TwinBeamsLoad>(&beams, range, tol, element)
                }
            }
            .map_err(|e| CliError::Invalid(e.to_string()))?
        }
        Model::Lap { joint, force } => {
            let range = tolerance_forces([from, to], force.newtons())?;
            // The joint carries nothing beyond F_gross: said of the flag that asks for more.
            let gross = joint.gross_slip_force();
            if range[1] > gross {
                let flag = if to.is_some() { "--to" } else { "--from" };
                return Err(CliError::Flag {
                    flag,
                    value: range[1],
                    allowed: format!(
                        "must be at most F_gross = 2 b mu P L = {} N (the joint slides through \
                         beyond it)",
                        Compact(gross)
                    ),
                });
            }
            match of {
                ToleranceOf::Coulomb => {
                    tolerance::stiffness_for_tolerance::<LapLoad>(&joint, range, tol, element)
                }
                ToleranceOf::Current => {
                    tolerance::stiffness_near_current::<LapLoad>(&joint, range, tol, element)
                }
            }
            .map_err(|e| CliError::Invalid(e.to_string()))?
        }
        Model::Plate(plate) => {
            if from.is_some() || to.is_some() {
                return Err(CliError::Usage(
                    "--from/--to are forces of the twin beams and the lap joint; the plate has none",
                ));
            }
            match of {
                ToleranceOf::Coulomb => {
                    tolerance::plate_stiffness_for_tolerance(&plate, tol, element)
                }
                ToleranceOf::Current => {
                    tolerance::plate_stiffness_near_current(&plate, tol, element)
                }
            }
            .map_err(|e| CliError::Invalid(e.to_string()))?
        }
    };
    let report = crate::report::point::tolerance::ToleranceReport::new(&name, &answer);
    match format {
        ReportFormat::Text => out.write_all(report.text().as_bytes())?,
        ReportFormat::Json => write_json(out, &crate::report::point::to_json(&report))?,
    }
    Ok(())
}

fn run_kt(
    out: &mut impl Write,
    inputs: &InputArgs,
    element: Option<f64>,
    kn: Option<f64>,
    nu: Option<f64>,
    format: ReportFormat,
) -> Result<(), CliError> {
    let (name, model) = load_any(inputs, ModelKind::Beam)?;
    let data = model.interface();
    let element = element_size(element, &model)?;
    let normal = match kn {
        Some(kn) => {
            let kn = check_flag("--kn", kn, Domain::STIFFNESS, Unit::MegapascalPerMillimetre)?;
            let nu = nu.or(data.poisson).unwrap_or(0.3);
            let nu = check_flag("--nu", nu, Domain::PoissonRatio, Unit::Dimensionless)?;
            Some((kn, nu))
        }
        None => None,
    };
    let comparison = curves::compare_stiffnesses(&model, element, normal);
    match format {
        ReportFormat::Text => {
            out.write_all(text::stiffness_table(&name, &comparison).as_bytes())?
        }
        ReportFormat::Json => write_json(out, &json::stiffness_table(&name, &comparison))?,
    }
    Ok(())
}

/// A chart's points as CSV (the same rows as the TUI's export).
fn chart_csv(plot: &crate::chart::Plot) -> Result<Vec<u8>, CliError> {
    let mut bytes = Vec::new();
    write_table(&mut bytes, TableFormat::Csv, report::rows::chart_rows(plot))?;
    Ok(bytes)
}

/// `microslip figures`: every figure of [`figure::PAPER_FIGURES`] in `format` and as CSV, then the
/// index.
fn run_figures(
    out: &mut impl Write,
    dir: &std::path::Path,
    fe: bool,
    format: figure::Format,
    inputs: &InputArgs,
) -> Result<(), CliError> {
    let unwritable = |e: io::Error| CliError::Data {
        path: dir.display().to_string(),
        reason: e.to_string(),
    };
    let flags = inputs.flags();
    // Every model is loaded before the folder is made: a bad preset leaves nothing behind.
    let mut figures = Vec::new();
    let intro = if !flags.is_empty() {
        let (name, model) = load_any(inputs, ModelKind::Beam)?;
        let bench = figure::Bench {
            preset: name,
            values: figure::parameter_caption(&model.inputs()),
            flags: flags.join(" "),
            finite_elements: fe,
        };
        for chart in AnyChart::all().filter(|c| c.kind() == model.kind()) {
            let plot = crate::chart::figure(&model, chart, fe, YMode::Linear).map_err(|e| {
                CliError::Invalid(format!(
                    "the finite-element points of chart {}: {e} (--no-fe draws the figures \
                     without them)",
                    chart.key()
                ))
            })?;
            // Each chart's own default axis, where its data allow it (as `plot` chooses).
            let y = Some(YMode::default_for(chart))
                .filter(|m| m.applies_to(&plot))
                .unwrap_or(YMode::Linear);
            figures.push((y.apply(plot), bench.entry(chart, y)));
        }
        bench.intro()
    } else {
        for f in figure::PAPER_FIGURES {
            let inputs = InputArgs {
                preset: Some(f.preset.to_string()),
                assignments: Vec::new(),
                beam_theory: None,
            };
            let (_, model) = load(&inputs, f.chart.kind(), "figures")?;
            let plot = crate::chart::figure(&model, f.chart, fe && f.finite_elements, f.y)?;
            figures.push((plot, f.entry()));
        }
        figure::PAPER_INTRO.to_string()
    };
    std::fs::create_dir_all(dir).map_err(unwritable)?;
    for (plot, entry) in &figures {
        let file = dir.join(format!("{}.{format}", entry.stem));
        write_output(out, Some(&file), &figure::render(plot, format)?)?;
        write_output(
            out,
            Some(&dir.join(format!("{}.csv", entry.stem))),
            &chart_csv(plot)?,
        )?;
        // The folder is the user's text: control characters are shown escaped, never sent.
        let shown = file.display().to_string();
        writeln!(out, "{}  {}", report::sanitize(&shown), entry.title)?;
    }
    let entries: Vec<figure::IndexEntry> = figures.into_iter().map(|(_, e)| e).collect();
    let index = dir.join("index.html");
    write_output(
        out,
        Some(&index),
        figure::index_html(&intro, &entries, format).as_bytes(),
    )?;
    let shown = index.display().to_string();
    writeln!(out, "{}  open it in a browser", report::sanitize(&shown))?;
    Ok(())
}

fn run_verify(
    out: &mut impl Write,
    grid: Grid,
    elements: usize,
    tolerance: f64,
) -> Result<(), CliError> {
    if !(MeshDensity::MIN_ELEMENTS..=MeshDensity::MAX_ELEMENTS).contains(&elements) {
        return Err(CliError::Flag {
            flag: "--elements",
            value: elements as f64,
            allowed: format!(
                "must be an integer in [{}, {}] (below {}, the plate mesh of the stiffest \
                 interface of the grid cannot resolve its slip zone and Newton cycles; beyond {}, \
                 round-off of the bending matrix dominates)",
                MeshDensity::MIN_ELEMENTS,
                MeshDensity::MAX_ELEMENTS,
                MeshDensity::MIN_ELEMENTS,
                MeshDensity::MAX_ELEMENTS
            ),
        });
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(CliError::Flag {
            flag: "--tolerance",
            value: tolerance,
            allowed: "must be > 0 and finite".into(),
        });
    }
    let density = MeshDensity::with_elements(elements);
    let started = std::time::Instant::now();
    let results = verify::run(grid, density)?;
    let seconds = started.elapsed().as_secs_f64();
    let table = report::verify::table(&results, density.elements, tolerance, seconds);
    out.write_all(table.as_bytes())?;
    match verify::failures(&results, tolerance) {
        0 => Ok(()),
        failed => Err(CliError::VerifyFailed(failed)),
    }
}

fn check(out: &mut impl Write, files: &[PathBuf]) -> Result<(), CliError> {
    let mut failed = 0;
    // Paths, descriptions and the values quoted in problems come from users: every line is
    // sanitized before it reaches the terminal.
    let mut say = |line: String| writeln!(out, "{}", report::sanitize(&line));
    for given in files {
        // A name, as --preset takes it: no file of that name here, no folder, no `.toml`.
        let spec = given.to_string_lossy();
        let path = if given.exists() || spec.contains('/') || spec.ends_with(".toml") {
            given.clone()
        } else if preset::is_bundled(&spec) {
            let p = preset::resolve(&spec)?;
            say(format!(
                "{spec}: ok (bundled {} preset: {})",
                p.inputs.kind(),
                p.description
            ))?;
            continue;
        } else {
            match preset::user_preset_dir().map(|dir| dir.join(format!("{spec}.toml"))) {
                Some(file) if file.exists() => file,
                dir => {
                    failed += 1;
                    let folder = dir
                        .and_then(|f| f.parent().map(|d| d.display().to_string()))
                        .unwrap_or_else(|| "none: no configuration folder".to_string());
                    say(format!(
                        "{spec}: no such file, and no preset of that name (bundled: {}; user presets in {folder})",
                        preset::bundled_names().join(" ")
                    ))?;
                    continue;
                }
            }
        };
        let path = &path;
        match preset::store::load(path) {
            Ok(p) => {
                let PresetSource::File(path) = &p.source else {
                    continue;
                };
                let description = if p.description.is_empty() {
                    "no description"
                } else {
                    &p.description
                };
                match p.inputs.validate() {
                    Ok(_) => say(format!(
                        "{}: ok ({} preset: {description})",
                        path.display(),
                        p.inputs.kind()
                    ))?,
                    // A value the file leaves at its default is refused with the others.
                    Err(error) => {
                        failed += 1;
                        say(format!(
                            "{}: {error}; {} is not in the file, so its default was used: give it",
                            path.display(),
                            error.field
                        ))?;
                    }
                }
            }
            Err(problems) => {
                failed += 1;
                for problem in problems {
                    say(format!("{}: {problem}", path.display()))?;
                }
            }
        }
        // A warning, not a problem: the file is fine, only its name loses to a bundled preset.
        if let Some(name) = path.file_stem().and_then(|s| s.to_str())
            && preset::is_bundled(name)
        {
            let warning = PresetError::Shadowed {
                name: name.to_string(),
            };
            say(format!("{}: warning: {warning}", path.display()))?;
        }
    }
    if failed > 0 {
        Err(CliError::CheckFailed(failed))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn clap_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn fit_progress_shows_after_a_second_at_most_ten_times_a_second_and_is_erased() {
        let grid = |done| fit::Progress::Bracket {
            done,
            total: 784,
            points: 1024,
        };
        let mut line = ProgressLine::new(Vec::new(), true);
        let t0 = line.started;
        let show = |p: fit::Progress| move || text::fit_progress(&p);
        line.update(t0 + Duration::from_millis(999), show(grid(1)));
        assert!(line.out.is_empty(), "nothing within the first second");
        line.update(t0 + Duration::from_millis(1000), show(grid(400)));
        line.update(t0 + Duration::from_millis(1050), show(grid(401)));
        line.update(
            t0 + Duration::from_millis(1100),
            show(fit::Progress::Refine {
                iteration: 2,
                points: 1_000_000,
                pass: fit::Pass::Derivatives,
                done: 250_000,
            }),
        );
        line.finish();
        let text = String::from_utf8(line.out).unwrap();
        assert_eq!(
            text,
            "\r\x1b[2Kmicroslip: fitting: grid search for a start on 1024 measurements, 51%\
             \r\x1b[2Kmicroslip: fitting: refining on 1000000 measurements, iteration 2: derivatives 25%\
             \r\x1b[2K"
        );
        // Not a terminal: never anything, not even the erasing.
        let mut quiet = ProgressLine::new(Vec::new(), false);
        let t0 = quiet.started;
        quiet.update(t0 + Duration::from_secs(5), || {
            text::reading_progress(50, 100)
        });
        quiet.finish();
        assert!(quiet.out.is_empty());
        // A quick fit that showed nothing erases nothing.
        let mut quick = ProgressLine::new(Vec::new(), true);
        quick.finish();
        assert!(quick.out.is_empty());
    }
}
