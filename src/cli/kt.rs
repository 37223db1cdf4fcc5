//! `kt`: the FE codes' default K_T and the tolerance K_T needs.

use super::*;
use crate::study::tolerance::ToleranceError;

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
    use crate::study::tolerance::parse_tolerance;
    let tol = parse_tolerance(tolerance).map_err(|e| CliError::Invalid(e.to_string()))?;
    let (name, model) = load_any(inputs, DEFAULT_PROBLEM)?;
    let element = element_size(element, &model)?;
    let current = match of {
        ToleranceOf::Coulomb => false,
        ToleranceOf::Current => true,
    };
    let kind = model.kind();
    // A load-driven problem is checked over a force range; any other at its one state.
    let answer = match report::face::faces(kind).cycle {
        Some(face) => {
            let no_load = || CliError::Invalid(format!("the {kind} problem has no load"));
            let force = kind
                .problem()
                .faces()
                .load_driven
                .and_then(|load_driven| load_driven.applied_force(&model))
                .ok_or_else(no_load)?;
            let range = tolerance_forces([from, to], force)?;
            // A structure carries nothing beyond its limit: said of the flag that asks for more.
            if let Some(limit) = face.force_limit(&model)
                && range[1] > limit
            {
                let flag = if to.is_some() { "--to" } else { "--from" };
                return Err(CliError::Flag {
                    flag,
                    value: range[1],
                    allowed: kind.description().beyond_bound(limit),
                });
            }
            face.tolerance(&model, range, (tol, element), current)
                .ok_or_else(no_load)?
        }
        None => {
            if from.is_some() || to.is_some() {
                return Err(CliError::Invalid(format!(
                    "--from/--to are loads of a load-driven problem; the {} has none",
                    kind.description().title
                )));
            }
            for_problem(
                kind,
                StateTolerance {
                    model: &model,
                    tolerance: tol,
                    element,
                    current,
                },
            )
            .ok_or_else(|| CliError::Invalid(format!("no {kind} model to check")))?
        }
    }
    .map_err(|e| CliError::Invalid(e.to_string()))?;
    let report = crate::report::point::tolerance::ToleranceReport::new(&name, &answer);
    match format {
        ReportFormat::Text => out.write_all(report.text().as_bytes())?,
        ReportFormat::Json => write_json(out, &crate::report::point::to_json(&report))?,
    }
    Ok(())
}

/// `kt --tolerance` of a problem without a load, at its one state, for [`for_problem`].
struct StateTolerance<'a> {
    model: &'a Model,
    tolerance: f64,
    element: f64,
    current: bool,
}

impl ForProblem for StateTolerance<'_> {
    type Output = Option<Result<crate::study::tolerance::ToleranceAnswer, ToleranceError>>;

    fn run<P: Faces>(self) -> Self::Output {
        use crate::study::tolerance;
        let model = P::from_model(self.model)?;
        Some(if self.current {
            tolerance::state_stiffness_near_current::<P>(&model, self.tolerance, self.element)
        } else {
            tolerance::state_stiffness_for_tolerance::<P>(&model, self.tolerance, self.element)
        })
    }
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
