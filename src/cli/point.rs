//! One state of a problem: `beam`, `plate` and `lap` reports (text or JSON), written once for
//! every problem through its [`ReportFace`](crate::report::face::ReportFace).

use super::*;

/// `beam`, `plate`, `lap`: the problem `alias` names (its key, read through the registry) at
/// one state. `continuum` is the command's `--continuum` (false for a problem without one):
/// what it does is the problem's own
/// ([`ReportFace::point_report`](crate::report::face::ReportFace::point_report)).
pub(super) fn run_point(
    out: &mut impl Write,
    alias: &str,
    args: &PointArgs,
    continuum: bool,
) -> Result<(), CliError> {
    let kind = alias_problem(alias)?;
    for_problem(
        kind,
        Point {
            out,
            args,
            continuum,
        },
    )
}

/// `microslip KEY ...` for a problem of the registry that has no subcommand of its own: the
/// words after the key parsed with the flags of `beam` (`--preset`, `--set`, `--format`), then
/// [`run_point`]. A word that is no problem's key is refused as clap refuses an unknown
/// subcommand.
pub(super) fn run_other_point(out: &mut impl Write, words: &[String]) -> Result<(), CliError> {
    use clap::{Args as _, FromArgMatches as _};
    let name = words.first().map_or("", String::as_str);
    let Ok(kind) = name.parse::<ModelKind>() else {
        return Err(CliError::Invalid(format!(
            "unrecognized subcommand '{name}' (see --help)"
        )));
    };
    let command = PointArgs::augment_args(clap::Command::new(kind.name())).about(
        "One state of the problem: both laws side by side, regimes, zones (the flags of `beam`)",
    );
    let matches = match command.try_get_matches_from(words) {
        Ok(matches) => matches,
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelp => {
            write!(out, "{}", e.render())?;
            return Ok(());
        }
        Err(e) => return Err(CliError::Invalid(clap_error_line(&e))),
    };
    let args = PointArgs::from_arg_matches(&matches)
        .map_err(|e| CliError::Invalid(clap_error_line(&e)))?;
    run_point(out, name, &args, false)
}

/// The arguments of [`run_point`], for [`for_problem`].
struct Point<'a, W> {
    out: &'a mut W,
    args: &'a PointArgs,
    continuum: bool,
}

impl<W: Write> ForProblem for Point<'_, W> {
    type Output = Result<(), CliError>;

    fn run<P: Faces>(self) -> Result<(), CliError> {
        let Point {
            out,
            args,
            continuum,
        } = self;
        let (name, model) = load_problem::<P>(&args.inputs, P::INFO.key, Load::Used)?;
        // An answer asked for with --continuum that could not be given is an error (nothing on
        // stdout; exit 2 for inputs it refuses, 1 for a failed solve: `CliError::exit_code`);
        // the automatic one is reported as failed in the output.
        let report = P::point_report(&name, &model, continuum).map_err(CliError::Numeric)?;
        match args.format {
            ReportFormat::Text => out.write_all(P::point_text(&report).as_bytes())?,
            ReportFormat::Json => write_json(out, &json::of(&report))?,
        }
        Ok(())
    }
}
