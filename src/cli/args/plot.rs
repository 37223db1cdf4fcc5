//! `plot` and `figures`: charts as figures or CSV.

use super::*;
use clap::Args;

// The flags of `plot` (Command::Plot); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// The chart (its model's paper preset unless --preset names another).
    #[arg(value_enum)]
    pub chart: AnyChart,
    #[command(flatten)]
    pub inputs: InputArgs,
    /// Add the project's own numerical points (its finite-element or discretized solver's, and
    /// a continuum's where the problem has one); a chart without them is refused.
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

// The flags of `figures` (Command::Figures); its help is the variant's doc comment.
#[derive(Debug, Args)]
pub struct FiguresArgs {
    /// The directory to write into (made if missing; files in it are replaced).
    #[arg(long, value_name = "DIR")]
    pub(in crate::cli) out: PathBuf,
    /// Leave out the finite-element points (faster).
    #[arg(long)]
    pub(in crate::cli) no_fe: bool,
    /// The figures' format: svg, png (1600 x 1000 px) or pdf; each with its CSV data.
    #[arg(long, default_value = "svg", value_parser = figure_formats())]
    pub(in crate::cli) format: FigureFormat,
    /// Your bench instead of the paper's (default without them: the paper's figure set).
    #[command(flatten)]
    pub(in crate::cli) inputs: InputArgs,
}

/// `figures --format`: the [`FigureFormat`]s, CSV hidden from the help (the CSV data is written
/// beside each figure anyway); given, it is refused by [`FigureFormat::choose`] with what is
/// accepted.
fn figure_formats() -> impl clap::builder::TypedValueParser<Value = FigureFormat> {
    use clap::ValueEnum;
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(
        FigureFormat::value_variants()
            .iter()
            .filter_map(|f| Some(f.to_possible_value()?.hide(f.figure().is_none()))),
    )
    .try_map(|name| {
        FigureFormat::from_str(&name, false)
            .map_err(|e| clap::Error::raw(clap::error::ErrorKind::InvalidValue, e))
    })
}
