//! `solve`: the parameter value at which a quantity takes a target value.

use super::*;

pub(super) fn run_solve(out: &mut impl Write, args: &SolveArgs) -> Result<(), CliError> {
    let SolveArgs {
        model,
        vary,
        target,
        from,
        to,
        inputs,
        format,
    } = args;
    let param = model.param(vary)?;
    let target = Target::parse(target, *model)?;
    let range = from.zip(*to);
    let (name, validated) = load(inputs, *model, &model_command(*model, "solve"))?;
    let solved = solve_for_target(&validated, param, target, range)?;
    match format {
        ReportFormat::Text => out.write_all(text::solved(&name, *model, &solved).as_bytes())?,
        ReportFormat::Json => write_json(out, &json::solved(&name, *model, &solved))?,
    }
    Ok(())
}
