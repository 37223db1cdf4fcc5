//! The command line as clap parses it: the subcommands, their flags and the values they take.

use super::*;
use clap::{Args, Subcommand, ValueEnum};

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Report of the paper's two data sets (twin beams and plate), as text.
    Report,
    /// Twin cantilever beams at one tip force: thresholds, X, w(L) for both laws, regimes.
    Beam(BeamPointArgs),
    /// Squeezed plate: X_s, X_r, u(L) for both laws, regimes, contact-pressure check, validity.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Plate(PlatePointArgs),
    /// Clamped double-lap joint at one force: F_1 (and where), F_2, F_gross, Delta and both
    /// sliding zones for both laws, regimes, the shear-lag theory's envelope.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Lap(LapPointArgs),
    /// Any other problem of the registry at one state, by its key (`microslip KEY --preset P
    /// --set K=V --format json`, the flags of `beam`): a problem that has no subcommand written
    /// here is reached through its registry key.
    #[command(external_subcommand)]
    OtherProblem(Vec<String>),
    /// Tables over a parameter range, as CSV or JSON.
    Sweep(SweepArgs),
    /// The value of one parameter at which a quantity takes a target value (a certified root).
    ///
    /// Quantities: beam w(L) X ratio F_1 D zeta; plate u(L) X_r ratio; lap Delta a d ratio F_1 D
    /// zeta (ratio: regularized over Coulomb, e.g. ratio=1.01 for "within 1 % of Coulomb"). The parameter's whole accepted range
    /// is searched unless --from/--to narrow it; every root is listed, and none is an error.
    Solve(SolveArgs),
    /// K_T from K_N and the K_T that FE codes assume, with what each does to the answer.
    ///
    /// Each answer is given against the current K_T's and against Coulomb's (`vs current`,
    /// `vs Coulomb`, in %).
    Kt {
        #[command(flatten)]
        inputs: InputArgs,
        /// Contact element length of your FE model (mm, in [1e-8, 1e6]), which the codes' default
        /// K_T scale with; default: a hundredth of the contact's length (L; 0.4 mm on lap-aluminium,
        /// 2 mm on paper-beams; the cylinder's is its half-width a).
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
    /// Identify mu and K_T from a measured curve (the problem's response against its load).
    Fit(FitArgs),
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
        /// The interface profile of a CSV result, from which the stick slope your FE code used is
        /// read: x_mm,slip_mm,shear_MPa (one load step) or step,x_mm,slip_mm,shear_MPa (a .dat
        /// reads it from the run's .frd).
        #[arg(long, value_name = "FILE")]
        interface: Option<PathBuf>,
        /// The kinematics of a CSV result's FE run, which the verdict names and the beams'
        /// envelope (V2, calibrated on NLGEOM runs) depends on (a .dat's deck says it).
        #[arg(long, value_enum)]
        kinematics: Option<KinematicsArg>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = CompareFormat::Text)]
        format: CompareFormat,
    },
    /// Draw a chart of the terminal UI as an SVG figure, or write its data as CSV.
    Plot(PlotArgs),
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
#[derive(Debug, Clone, Args)]
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
    pub(super) fn read_files(&self) -> Vec<(&'static str, PathBuf)> {
        let Some(name) = &self.preset else {
            return Vec::new();
        };
        match preset::resolve(name).map(|p| p.source) {
            Ok(preset::PresetSource::File(path)) => vec![("--preset", path)],
            _ => Vec::new(),
        }
    }

    /// The parameter flags given, as a command line repeats them (`--preset P`, `--set K=V`, ...).
    pub(super) fn flags(&self) -> Vec<String> {
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
    pub(super) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(super) format: ReportFormat,
}

/// A generic command of any problem (its own flags, when no subcommand is given) or one of its
/// per-problem subcommands, kept as aliases with their own flags and help (`sweep beam`, `fit
/// lap`). A subcommand and the generic flags exclude each other, so an alias's `--help` is what
/// it was.
#[derive(Debug, Args)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    subcommand_value_name = "PROBLEM",
    subcommand_help_heading = "Aliases (one problem each, their own flags)"
)]
pub struct WithAliases<A: Subcommand, G: Args> {
    #[command(subcommand)]
    pub(super) command: Option<A>,
    #[command(flatten)]
    pub(super) generic: G,
}

/// `sweep`: the generic sweep, or `sweep beam|plate|lap|cycle`.
pub type SweepArgs = WithAliases<SweepCommand, GenericSweepArgs>;

/// The flags of the generic `sweep`: the problem comes from --model or the preset.
#[derive(Debug, Args)]
pub struct GenericSweepArgs {
    /// The problem (default: the preset's; without --preset, beam). Given with --preset, both
    /// must name the same problem.
    #[arg(long, value_parser = model_kind_parser())]
    pub(super) model: Option<ModelKind>,
    // The help lists each problem's keys from the registry (`vary_help`).
    #[arg(long, value_name = "NAME", help = vary_help())]
    pub(super) vary: Option<String>,
    /// First value of the varied parameter (in its unit: F in N, K_T in MPa/mm, ...).
    #[arg(long, value_name = "A", allow_negative_numbers = true, required = true)]
    pub(super) from: Option<f64>,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true, required = true)]
    pub(super) to: Option<f64>,
    /// Number of rows, both ends included (2 to 100000000; default 11, or 1 when --from = --to).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub(super) points: Option<u64>,
    #[command(flatten)]
    pub(super) spacing: SpacingArgs,
    #[command(flatten)]
    pub(super) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub(super) format: TableFormat,
}

/// The help of the generic sweep's `--vary`: every problem's keys, as the registry lists them.
fn vary_help() -> String {
    let keys: Vec<String> = ModelKind::ALL
        .iter()
        .map(|kind| {
            let names: Vec<&str> = kind.params().iter().map(|p| p.name()).collect();
            format!("{kind}: {}", names.join(" "))
        })
        .collect();
    format!(
        "The parameter to vary ({}). Default: the problem's load F, else KT. Columns: the \
         parameter's then those of the default's sweep; for the default, that sweep's own",
        keys.join("; ")
    )
}

/// Rows of a generic `sweep` without --points: the ends and nine steps between, so a range of
/// round ends gives round values (0.1 to 0.5: steps of 0.04).
pub(super) const DEFAULT_SWEEP_POINTS: u64 = 11;

/// Sweep subcommands.
#[derive(Debug, Subcommand)]
pub enum SweepCommand {
    /// Twin beams over a range of tip forces F (N), linearly spaced (replaces the preset's F), or
    /// of any parameter with --vary.
    Beam(BeamSweepArgs),
    /// Twin beams (default) or the lap joint (a lap preset) cycled at amplitudes F_a from F0 to F1
    /// (N): dissipation and damping per cycle.
    Cycle(CycleSweepArgs),
    /// Double-lap joint over a range of forces F (N, up to F_gross), linearly spaced (replaces the
    /// preset's F), or of any parameter with --vary.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Lap(LapSweepArgs),
    /// Squeezed plate over a range of K_T (MPa/mm), logarithmically spaced unless --linear, or of
    /// any parameter with --vary NAME --from A --to B.
    // --beam-theory has no effect here: hidden from the help (and refused if given).
    #[command(mut_arg("beam_theory", |a| a.hide(true)))]
    Plate(PlateSweepArgs),
}

/// How sweep values are spaced; the default is logarithmic for K_T, linear for the others.
#[derive(Debug, Args)]
pub struct LapSweepArgs {
    /// The parameter to vary: L b t1 t2 E1 E2 P mu KT F (default F). Columns: the parameter's
    /// then those of the F sweep; for F, the F sweep's own.
    #[arg(long, value_name = "NAME")]
    pub(super) vary: Option<String>,
    /// First value of the varied parameter (F: N, at most F_gross).
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub(super) from: f64,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true)]
    pub(super) to: f64,
    /// Number of rows, both ends included (2 to 100000000; 1 when --from = --to).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub(super) points: u64,
    #[command(flatten)]
    pub(super) spacing: SpacingArgs,
    #[command(flatten)]
    pub(super) inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub(super) format: TableFormat,
}

/// How sweep values are spaced; the default is logarithmic for K_T, linear for the others.
#[derive(Debug, Args)]
pub struct SpacingArgs {
    /// Space the values linearly.
    #[arg(long, conflicts_with = "log")]
    pub(super) linear: bool,
    /// Space the values logarithmically (both ends > 0).
    #[arg(long)]
    pub(super) log: bool,
}

impl SpacingArgs {
    /// The spacing asked for, or the parameter's default.
    pub(super) fn spacing(&self, param: Param) -> Spacing {
        if self.linear {
            Spacing::Linear
        } else if self.log || param.is_stiffness() {
            Spacing::Logarithmic
        } else {
            Spacing::Linear
        }
    }
}

/// `fit`: the generic fit of any problem with a load, or `fit beam|lap`.
pub type FitArgs = WithAliases<FitCommand, GenericFitArgs>;

/// The arguments of the generic `fit`: the problem comes from --model or the preset.
#[derive(Debug, Args)]
pub struct GenericFitArgs {
    // The help names each problem's columns from the registry (`fit_data_help`). One value is
    // the data; two, the problem and the data (`fit cylinder s.csv`, the problem as --model
    // names it, for a problem without an alias of its own).
    #[arg(
        value_name = "[PROBLEM] DATA.csv",
        required = true,
        num_args = 1..=2,
        help = fit_data_help()
    )]
    pub(super) data: Vec<PathBuf>,
    /// The problem (default: the preset's; without --preset, beam). Given with --preset, both
    /// must name the same problem, one with a load to fit the curve against.
    #[arg(long, value_parser = model_kind_parser())]
    pub(super) model: Option<ModelKind>,
    #[command(flatten)]
    pub(super) inputs: InputArgs,
    /// Hold a parameter at a value instead of fitting it: mu=0.3 or KT=600 (repeatable).
    #[arg(long = "fix", value_name = "KEY=VALUE")]
    pub(super) fixed: Vec<String>,
    /// What the standard errors assume about the scatter of the response [default: relative;
    /// a sigma_mm column in the data gives each point's own, taken as known].
    #[arg(long, value_enum)]
    pub(super) weights: Option<WeightsArg>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(super) format: ReportFormat,
}

/// The help of the generic fit's DATA.csv: the response column of every problem with a load,
/// as the registry lists them.
fn fit_data_help() -> String {
    let columns: Vec<String> = ModelKind::ALL
        .iter()
        .filter_map(|kind| {
            let structure = crate::fit::Structure::of(&Inputs::paper(*kind).validate().ok()?)?;
            Some(format!(
                "{},{} ({kind})",
                structure.load_column(),
                structure.response_column()
            ))
        })
        .collect();
    format!(
        "Measurements: CSV with a header naming the problem's load and response columns, {}; \
         other columns are ignored. Before it, the problem may be named as --model names it \
         (`fit cylinder DATA.csv`)",
        columns.join(" or ")
    )
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
    pub(super) inputs: InputArgs,
    /// Mesh density (fine halves every element size: run both to check convergence).
    #[arg(long, value_enum, default_value_t = DeckMesh::Coarse)]
    pub(super) mesh: DeckMesh,
    /// Forces of the load steps (N, increasing): the beams' tip force (default F_thre x 0.5,
    /// 0.75, 1, 1.25, 1.875, 2.5) or the lap joint's F (default 0.5 F_1, (F_1 + F_2)/2,
    /// (F_2 + F_gross)/2, 0.9 F_gross); not the plate's.
    #[arg(
        long,
        value_name = "F0,F1,...",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    pub(super) loads: Option<Vec<f64>>,
    /// Give the FE code a stiff stick slope (boundary layer a tenth of h or t_p) instead of
    /// K_T: plain Coulomb to within what the mesh resolves.
    #[arg(long)]
    pub(super) near_coulomb: bool,
    /// Largest force change per increment (N) in the load steps that end beyond F_1 (friction
    /// is path-dependent once it saturates), beams and lap joint; default: F_1 / 40.
    #[arg(long, value_name = "N")]
    pub(super) increment: Option<f64>,
}

/// External FE codes `deck` writes for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FeCode {
    /// CalculiX's solver, ccx (tested with 2.20).
    Ccx,
}

/// The kinematics of a CSV result's FE run (`compare --kinematics`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum KinematicsArg {
    /// Large rotations (NLGEOM in Abaqus and CalculiX).
    Nlgeom,
    /// Linear (small-displacement) geometry.
    Linear,
}

impl KinematicsArg {
    /// The kinematics it names.
    pub fn kinematics(self) -> crate::fe::kinematics::Kinematics {
        match self {
            KinematicsArg::Nlgeom => crate::fe::kinematics::Kinematics::Nlgeom,
            KinematicsArg::Linear => crate::fe::kinematics::Kinematics::Linear,
        }
    }
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
    pub(super) fn figure(self) -> Option<figure::Format> {
        match self {
            FigureFormat::Svg => Some(figure::Format::Svg),
            FigureFormat::Png => Some(figure::Format::Png),
            FigureFormat::Pdf => Some(figure::Format::Pdf),
            FigureFormat::Csv => None,
        }
    }

    /// The extension, also the name `--format` takes.
    pub(super) fn extension(self) -> &'static str {
        self.figure().map_or("csv", figure::Format::extension)
    }

    /// The format of `output`'s extension and `--format`, which must agree: a file named `w.png`
    /// holds a PNG. No extension (or stdout) takes `--format`, else `default`. An extension no
    /// format has is refused, so a figure is never written under a name that lies about it.
    pub(super) fn choose(
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
pub(super) fn model_kind_parser() -> impl clap::builder::TypedValueParser<Value = ModelKind> {
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

// The flags of `beam` (Command::Beam); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct BeamPointArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Also solve the 2-D plane-stress continuum of both beams (seconds): the reference an FE
    /// code's w(L) is judged against.
    #[arg(long)]
    pub continuum: bool,
}

// The flags of `plate` (Command::Plate); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct PlatePointArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Also solve the plane-strain continuum (done anyway when the strip theory is not
    /// expected within 2 %).
    #[arg(long)]
    pub continuum: bool,
}

// The flags of `lap` (Command::Lap); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct LapPointArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Also solve the 2-D plane-stress continuum (done anyway when the shear-lag theory is
    /// not expected within 2 %).
    #[arg(long)]
    pub continuum: bool,
}

// The flags of `solve` (Command::Solve); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct SolveArgs {
    /// Which benchmark.
    #[arg(value_parser = model_kind_parser())]
    pub model: ModelKind,
    /// The parameter to solve for (beam: L b h E P mu KT F; plate: L tp E nu mu P KT; lap: L b
    /// t1 t2 E1 E2 P mu KT F).
    #[arg(long, value_name = "NAME")]
    pub vary: String,
    /// The target, QUANTITY=VALUE (e.g. ratio=1.01, w(L)=0.05, X_r=9.5).
    #[arg(long, value_name = "QUANTITY=VALUE")]
    pub target: String,
    /// Lowest value of the parameter searched (default: its smallest accepted value).
    #[arg(long, value_name = "A", allow_negative_numbers = true, requires = "to")]
    pub from: Option<f64>,
    /// Highest value searched (default: its largest accepted value).
    #[arg(
        long,
        value_name = "B",
        allow_negative_numbers = true,
        requires = "from"
    )]
    pub to: Option<f64>,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub format: ReportFormat,
}

// The flags of `plot` (Command::Plot); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// The chart (its model's paper preset unless --preset names another).
    #[arg(value_enum)]
    pub chart: AnyChart,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Add the project's finite-element points (w-vs-f, x-vs-f, tau, loop, u-vs-kt, delta-vs-f,
    /// zones-vs-f, lap-tau, lap-slip, lap-loop), or its discretized solver's on every cylinder
    /// chart.
    #[arg(long)]
    pub fe: bool,
    /// The y axis: linear, log, or relative (each curve / Coulomb - 1, in %); default: log for
    /// u-vs-kt and d-vs-fa, linear otherwise. A mode the chart cannot show is refused.
    #[arg(long, value_enum, value_name = "MODE")]
    pub y: Option<YMode>,
    /// Add the chart at other values, as the TUI's pins (g): the same --set on top of the
    /// inputs, several joined by commas (--pin mu=0.2 --pin mu=0.45,KT=1000); at most 4.
    #[arg(long = "pin", value_name = "KEY=VALUE,...")]
    pub pins: Vec<String>,
    /// Draw the chart's main curve once per value of one parameter, all of equal rank and
    /// named with the unit (--family P=0.5,1,2: "P = 0.5 MPa", ...); the other parameters
    /// go in a caption. At most 6 values; not with --pin or --fe.
    #[arg(long, value_name = "KEY=V1,V2,...")]
    pub family: Option<String>,
    /// The chart's series to draw, by role, comma-separated: current, coulomb, softer
    /// (K_T/5, K_T/10), stiffer (K_T*5, K_T*10), limit (mu P, P_r = P), fe, continuum,
    /// cursor. Default: all the chart has; with --family, only the members (a role added
    /// to a family must be the same for every member).
    #[arg(long, value_name = "ROLE,...")]
    pub series: Option<String>,
    /// Leave out the cursor (the vertical line at the current value).
    #[arg(long)]
    pub no_cursor: bool,
    /// Output format; default: the FILE's extension (.svg, .png, .pdf or .csv; another
    /// extension is refused), else svg.
    #[arg(long, value_enum)]
    pub format: Option<FigureFormat>,
    /// Write to FILE instead of stdout (replaced atomically if it exists).
    #[arg(short = 'o', long, value_name = "FILE.svg|png|pdf|csv")]
    pub output: Option<PathBuf>,
}

// The flags of `beam` (SweepCommand::Beam); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct BeamSweepArgs {
    /// The parameter to vary: L b h E P mu KT F (default F). Columns: the parameter's (e.g.
    /// mu, KT_MPa_per_mm) then those of the F sweep; for F, the F sweep's own.
    #[arg(long, value_name = "NAME")]
    pub vary: Option<String>,
    /// First value of the varied parameter (F: N).
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub from: f64,
    /// Last value.
    #[arg(long, value_name = "B", allow_negative_numbers = true)]
    pub to: f64,
    /// Number of rows, both ends included (2 to 100000000; 1 when --from = --to).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub points: u64,
    #[command(flatten)]
    pub spacing: SpacingArgs,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub format: TableFormat,
}

// The flags of `plate` (SweepCommand::Plate); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct PlateSweepArgs {
    /// First K_T (MPa/mm).
    #[arg(long, value_name = "A", allow_negative_numbers = true, conflicts_with_all = ["vary", "from"])]
    pub kt_from: Option<f64>,
    /// Last K_T (MPa/mm).
    #[arg(long, value_name = "B", allow_negative_numbers = true, conflicts_with_all = ["vary", "to"])]
    pub kt_to: Option<f64>,
    /// The parameter to vary: L tp E nu mu P KT (default KT). Columns: the parameter's (e.g.
    /// mu) then those of the K_T sweep; for KT, the K_T sweep's own.
    #[arg(long, value_name = "NAME")]
    pub vary: Option<String>,
    /// First value of the varied parameter (with --vary).
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub from: Option<f64>,
    /// Last value of the varied parameter (with --vary).
    #[arg(long, value_name = "B", allow_negative_numbers = true)]
    pub to: Option<f64>,
    /// Number of rows, both ends included (2 to 100000000; 1 when both ends are equal).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub points: u64,
    #[command(flatten)]
    pub spacing: SpacingArgs,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub format: TableFormat,
}

// The flags of `cycle` (SweepCommand::Cycle); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct CycleSweepArgs {
    /// First amplitude (N).
    #[arg(long, value_name = "F0", allow_negative_numbers = true)]
    pub from: f64,
    /// Last amplitude (N).
    #[arg(long, value_name = "F1", allow_negative_numbers = true)]
    pub to: f64,
    /// Number of rows, both ends included (2 to 100000000).
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    pub points: u64,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
    pub format: TableFormat,
}
