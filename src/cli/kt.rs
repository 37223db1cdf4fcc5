//! `kt`: the FE codes' default K_T and the tolerance K_T needs.

use super::*;
use crate::problems::lap::LapJointProblem;
use crate::problems::plate::SqueezedPlateProblem;
use crate::problems::twin_beams::TwinBeamsProblem;

/// The force range of `kt --tolerance`: `--from` and `--to` (each the model's force when not
/// given), accepted forces, in order.
pub(super) fn tolerance_forces(
    [from, to]: [Option<f64>; 2],
    force: f64,
) -> Result<[f64; 2], CliError> {
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

pub(super) fn run_kt_tolerance(
    out: &mut impl Write,
    inputs: &InputArgs,
    element: Option<f64>,
    (tolerance, of): (&str, ToleranceOf),
    [from, to]: [Option<f64>; 2],
    format: ReportFormat,
) -> Result<(), CliError> {
    use crate::study::tolerance::{self, parse_tolerance};
    let tol = parse_tolerance(tolerance).map_err(|e| CliError::Invalid(e.to_string()))?;
    let (name, model) = load_any(inputs, DEFAULT_PROBLEM)?;
    let element = element_size(element, &model)?;
    let answer = match model {
        Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, force }) => {
            let range = tolerance_forces([from, to], force.newtons())?;
            match of {
                ToleranceOf::Coulomb => tolerance::stiffness_for_tolerance::<TwinBeamsProblem>(
                    &beams, range, tol, element,
                ),
                ToleranceOf::Current => tolerance::stiffness_near_current::<TwinBeamsProblem>(
                    &beams, range, tol, element,
                ),
            }
            .map_err(|e| CliError::Invalid(e.to_string()))?
        }
        Model::Lap(crate::problems::lap::problem::LapModel { joint, force }) => {
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
                ToleranceOf::Coulomb => tolerance::stiffness_for_tolerance::<LapJointProblem>(
                    &joint, range, tol, element,
                ),
                ToleranceOf::Current => tolerance::stiffness_near_current::<LapJointProblem>(
                    &joint, range, tol, element,
                ),
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
                ToleranceOf::Coulomb => tolerance::state_stiffness_for_tolerance::<
                    SqueezedPlateProblem,
                >(&plate, tol, element),
                ToleranceOf::Current => tolerance::state_stiffness_near_current::<
                    SqueezedPlateProblem,
                >(&plate, tol, element),
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

pub(super) fn run_kt(
    out: &mut impl Write,
    inputs: &InputArgs,
    element: Option<f64>,
    kn: Option<f64>,
    nu: Option<f64>,
    format: ReportFormat,
) -> Result<(), CliError> {
    let (name, model) = load_any(inputs, DEFAULT_PROBLEM)?;
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
