//! One state of a problem: `microslip PROBLEM`'s report (text or JSON), written once for
//! every problem through its [`ReportFace`](crate::report::face::ReportFace).

use super::*;

/// `microslip PROBLEM`: the problem `kind` at one state. `continuum` is the command's
/// `--continuum` (false for a problem without one, which does not declare the flag): what it
/// does is the problem's own
/// ([`ReportFace::point_report`](crate::report::face::ReportFace::point_report)).
pub(super) fn run_point(
    out: &mut impl Write,
    kind: ModelKind,
    args: &PointArgs,
    continuum: bool,
) -> Result<(), CliError> {
    for_problem(
        kind,
        Point {
            out,
            args,
            continuum,
        },
    )
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
