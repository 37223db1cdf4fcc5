//! `verify`: the closed forms against the project's own discretized solvers.

use super::*;

pub(super) fn run_verify(
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
                "must be an integer in [{}, {}] (below {}, the stiffest interface of the grid \
                 puts whole elements inside its slip zone and Newton cycles; beyond {}, \
                 round-off of the discretized stiffness dominates)",
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
