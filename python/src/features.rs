//! The features beyond one solve, behind `Problem`'s methods: each runs with the GIL released,
//! the panic guard and Ctrl-C heard (`interrupt::interruptible`), and returns the application's JSON report as a `microslip.Report` (or
//! text, a number). Those that need only the core live here (`fe_defaults`, `continuum`); those
//! that mirror a CLI command's body (reports, decks, comparisons) go through `bridge`.

use microslip::fe::deck::DeckMesh;
use microslip::kernel::params::{Domain, Unit};
use microslip::report::json;
use microslip::study::candidates::compare_stiffnesses;
use microslip::study::tolerance::parse_tolerance;
use pyo3::prelude::*;
use serde_json::Value;

use crate::bridge::{self, Of, check_flag};
use crate::errors::{ensure_memory, value_error};
use crate::interrupt::interruptible;
use crate::json::to_python;
use crate::problem::Problem;

/// Runs `work` with the GIL released and the panic guard, stopped by Ctrl-C
/// ([`interruptible`]: `KeyboardInterrupt`); its refusal as a `ValueError`.
pub fn released<T: Send>(
    py: Python<'_>,
    work: impl FnOnce() -> Result<T, String> + Send,
) -> PyResult<T> {
    interruptible(py, |_| work())?.map_err(value_error)
}

/// A JSON report as a `microslip.Report` (read-only, attribute access, `to_dict()`).
pub fn report<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    let dict = to_python(py, value)?;
    py.import("microslip._report")?
        .getattr("Report")?
        .call1((dict,))
}

/// The contact element length the FE comparisons assume: `element_size` checked as the CLI
/// checks `--element-size`, else a hundredth of the interface's length (`src/cli/cycle.rs`).
fn element(problem: &Problem, element_size: Option<f64>) -> Result<f64, String> {
    match element_size {
        Some(e) => check_flag("element_size", e, Domain::ELEMENT_SIZE, Unit::Millimetre),
        None => Ok(model(problem)?.interface().length / 100.0),
    }
}

fn model(problem: &Problem) -> Result<microslip::Model, String> {
    let inputs = problem
        .kind
        .problem()
        .inputs_at(&problem.values)
        .map_err(|e| e.to_string())?;
    inputs.validate().map_err(|e| e.to_string())
}

/// `microslip kt --format json`: the K_T each FE code assumes and what it does to the answer.
pub fn fe_defaults<'py>(
    py: Python<'py>,
    problem: &Problem,
    element_size: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let value = released(py, || {
        let element = element(problem, element_size)?;
        let comparison = compare_stiffnesses(&model(problem)?, element, None);
        Ok(json::stiffness_table(&problem.name, &comparison))
    })?;
    report(py, &value)
}

/// The continuum reference's response (mm) on the default mesh, where the problem has one.
pub fn continuum(py: Python<'_>, problem: &Problem) -> PyResult<f64> {
    released(py, || {
        let kind = problem.kind;
        let reference = kind
            .problem()
            .faces()
            .continuum
            .ok_or_else(|| format!("the {kind} problem has no continuum reference yet"))?;
        let model = model(problem)?;
        match reference(&model) {
            Some(answer) => answer.map_err(|e| format!("numerical solver: {e}")),
            None => Err(format!("the {kind} continuum did not take its own model")),
        }
    })
}

/// `microslip cycle --amplitude A --format json`.
pub fn cycle<'py>(
    py: Python<'py>,
    problem: &Problem,
    amplitude: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let value = released(py, || {
        bridge::cycle_report(problem.kind, &problem.values, &problem.name, amplitude)
    })?;
    report(py, &value)
}

/// `microslip kt --tolerance T --of REF [--from F] [--to F] --format json`; `tolerance` as the CLI
/// takes it (`"1%"`, `"0.01"`) or a fraction.
pub fn kt_tolerance<'py>(
    py: Python<'py>,
    problem: &Problem,
    tolerance: &Bound<'py, PyAny>,
    of: &str,
    range: [Option<f64>; 2],
    element_size: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let text = match tolerance.extract::<f64>() {
        Ok(fraction) => format!("{fraction:?}"),
        Err(_) => tolerance.extract::<String>()?,
    };
    let tol = parse_tolerance(&text).map_err(value_error)?;
    let of = match of {
        "coulomb" => Of::Coulomb,
        "current" => Of::Current,
        other => {
            return Err(value_error(format!(
                "invalid of = {other:?}: must be \"coulomb\" or \"current\""
            )));
        }
    };
    let value = released(py, || {
        let element = element(problem, element_size)?;
        bridge::kt_tolerance_report(
            problem.kind,
            &problem.values,
            &problem.name,
            (tol, of),
            range,
            element,
        )
    })?;
    report(py, &value)
}

/// `microslip fit beam|lap|cylinder --format json` on the points `(load, measured)` (the load in
/// its unit: N, or N/mm for the cylinder's line load; mm), each with its
/// standard deviation (mm) when `sigma` is given. The points are written as the CSV the CLI
/// reads and read back by the CLI's own parser, so they are refused exactly where a file with
/// them would be.
pub fn fit<'py>(
    py: Python<'py>,
    problem: &Problem,
    points: (Vec<f64>, Vec<f64>, Option<Vec<f64>>),
    fixed: (Option<f64>, Option<f64>),
    weights: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let (forces, measured, sigma) = points;
    if forces.len() != measured.len() || sigma.as_ref().is_some_and(|s| s.len() != forces.len()) {
        return Err(value_error(format!(
            "F, measured and sigma must have one value per point (got {}, {} and {})",
            forces.len(),
            measured.len(),
            sigma
                .as_ref()
                .map_or_else(|| "none".to_string(), |s| s.len().to_string())
        )));
    }
    // The points written as the CLI's CSV (up to three numbers of 25 characters a row), read
    // back, and the fit's residuals and subsamples: generously 256 bytes a point.
    ensure_memory(forces.len() as f64 * FIT_BYTES_PER_POINT, || {
        format!("a fit of {} points", forces.len())
    })?;
    let value = released(py, || {
        bridge::fit_report(
            problem.kind,
            &problem.values,
            &problem.name,
            ("<arrays>", (&forces, &measured, sigma.as_deref())),
            fixed,
            weights,
        )
    })?;
    report(py, &value)
}

/// What a fit allocates per measured point, at most (see [`fit`]).
const FIT_BYTES_PER_POINT: f64 = 256.0;

/// `microslip deck ccx MODEL --format ...`: the deck's text.
pub fn deck(
    py: Python<'_>,
    problem: &Problem,
    code: &str,
    mesh: &str,
    loads: Option<Vec<f64>>,
) -> PyResult<String> {
    if code != "ccx" {
        return Err(value_error(format!(
            "invalid code = {code:?}: the decks are CalculiX's (\"ccx\"; Abaqus reads the same keywords)"
        )));
    }
    let mesh = DeckMesh::from_name(mesh).ok_or_else(|| {
        value_error(format!(
            "invalid mesh = {mesh:?}: must be \"coarse\", \"fine\" or \"finest\""
        ))
    })?;
    let (kind, values) = (problem.kind, &problem.values);
    interruptible(py, |_| {
        if let Some(loads) = loads.as_deref().filter(|l| l.len() > DECK_UNCHECKED) {
            ensure_memory(deck_bytes(kind, values, mesh, loads)?, || {
                format!("a deck of {} load steps", loads.len())
            })?;
        }
        bridge::deck_text(kind, values, mesh, loads.as_deref()).map_err(value_error)
    })?
}

/// Up to how many load steps a deck is written without first checking that its text fits in
/// memory (a few MB at most).
const DECK_UNCHECKED: usize = 4096;

/// How many bytes writing the deck of `loads` takes at its peak: its text (from the decks of
/// the first load and the first [`DECK_SAMPLE`] loads, the steps' mean length), up to twice that
/// while the text grows, and its copy as a Python `str`.
fn deck_bytes(
    kind: microslip::problems::ModelKind,
    values: &[f64],
    mesh: DeckMesh,
    loads: &[f64],
) -> PyResult<f64> {
    let text = |n: usize| -> PyResult<f64> {
        let deck = bridge::deck_text(kind, values, mesh, Some(&loads[..n])).map_err(value_error)?;
        Ok(deck.len() as f64)
    };
    let (one, some) = (text(1)?, text(DECK_SAMPLE)?);
    let step = (some - one) / (DECK_SAMPLE - 1) as f64;
    Ok(3.0 * (one + step * (loads.len() - 1) as f64))
}

/// How many load steps [`deck_bytes`] writes to measure a step's length.
const DECK_SAMPLE: usize = 17;

/// `microslip compare MODEL RESULT [--deck INP] --format json` for one result file.
#[pyfunction]
#[pyo3(signature = (path, problem, deck = None))]
pub fn compare<'py>(
    py: Python<'py>,
    path: std::path::PathBuf,
    problem: PyRef<'py, Problem>,
    deck: Option<std::path::PathBuf>,
) -> PyResult<Bound<'py, PyAny>> {
    let (kind, values) = (problem.kind, problem.values.clone());
    let value = released(py, || {
        bridge::compare_report(kind, &values, &path, deck.as_deref())
    })?;
    report(py, &value)
}
