//! `Problem.sweep(**{key: array})`: the problem solved at every value of one parameter, the
//! others held, into numpy arrays. Each point is `AnyProblem::answers` (and `quantity_at` for the
//! quantities asked for) at the same values a scalar `solve` would use, so a sweep equals the
//! scalar loop bit for bit; the loop runs with the GIL released, into `Vec`s that numpy then owns
//! without a copy.

use microslip::kernel::regime::Regime;
use microslip::problems::problem::ProblemError;
use microslip::problems::{ModelKind, QuantityName};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::errors::{guard, problem_error};
use crate::problem::Problem;
use crate::registry::{param_index_or_error, quantity_named};

/// The regime labels a sweep's integer codes index, first seen first.
struct Regimes(Vec<Regime>);

impl Regimes {
    fn code(&mut self, regime: Regime) -> i8 {
        let index = self.0.iter().position(|&r| r == regime).unwrap_or_else(|| {
            self.0.push(regime);
            self.0.len() - 1
        });
        // At most 4^3 regimes exist (three zones of three kinds or none): fits an i8.
        i8::try_from(index).unwrap_or(i8::MAX)
    }
}

/// What one sweep computes, column by column.
struct Columns {
    responses: [Vec<f64>; 2],
    zone_ends: [Vec<f64>; 2],
    regimes: [Vec<i8>; 2],
    quantities: Vec<Vec<f64>>,
    labels: Regimes,
}

/// Solves at each of `xs` set at `index`, from `values`: the first refusal stops the loop and
/// says at which element of `xs`.
fn run(
    kind: ModelKind,
    mut values: Vec<f64>,
    index: usize,
    xs: &[f64],
    wanted: &[&'static QuantityName],
) -> Result<Columns, (usize, ProblemError)> {
    let problem = kind.problem();
    let n = xs.len();
    let column = || Vec::with_capacity(n);
    let mut out = Columns {
        responses: [column(), column()],
        zone_ends: [column(), column()],
        regimes: [Vec::with_capacity(n), Vec::with_capacity(n)],
        quantities: wanted.iter().map(|_| column()).collect(),
        labels: Regimes(Vec::new()),
    };
    for (i, &x) in xs.iter().enumerate() {
        values[index] = x;
        let answers = problem.answers(&values).map_err(|e| (i, e))?;
        for (law, answer) in [answers.coulomb, answers.regularized]
            .into_iter()
            .enumerate()
        {
            out.responses[law].push(answer.response);
            out.zone_ends[law].push(answer.zone_end);
            let code = out.labels.code(answer.regime);
            out.regimes[law].push(code);
        }
        for (q, column) in wanted.iter().zip(&mut out.quantities) {
            let value = problem
                .quantity_at(&values, q.quantity)
                .map_err(|e| (i, e))?;
            column.push(value.unwrap_or(f64::NAN));
        }
    }
    Ok(out)
}

/// Fewest points a thread is given: below this, starting it costs more than it saves.
const MIN_CHUNK: usize = 32_768;

/// [`run`] over `xs` split into one contiguous chunk per available core (points are
/// independent, and each is solved exactly as alone, so the split cannot change a bit), the
/// chunks' columns joined in order. The refusal reported is the one at the lowest index.
fn run_parallel(
    kind: ModelKind,
    values: &[f64],
    index: usize,
    xs: &[f64],
    wanted: &[&'static QuantityName],
) -> Result<Columns, (usize, ProblemError)> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let threads = cores.min(xs.len() / MIN_CHUNK).max(1);
    if threads == 1 {
        return run(kind, values.to_vec(), index, xs, wanted);
    }
    let size = xs.len().div_ceil(threads);
    let parts: Vec<Result<Columns, (usize, ProblemError)>> = std::thread::scope(|scope| {
        let handles: Vec<_> = xs
            .chunks(size)
            .enumerate()
            .map(|(c, chunk)| {
                scope.spawn(move || {
                    run(kind, values.to_vec(), index, chunk, wanted)
                        .map_err(|(i, e)| (c * size + i, e))
                })
            })
            .collect();
        // A panicking chunk re-raises here, on the caller's thread, where `guard` turns it into
        // a RuntimeError.
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    });
    let mut joined: Option<Columns> = None;
    for part in parts {
        let part = part?;
        match &mut joined {
            None => joined = Some(part),
            Some(all) => all.append(part),
        }
    }
    joined.ok_or((
        0,
        ProblemError::Count {
            problem: kind.name(),
            expected: 0,
            got: 0,
        },
    ))
}

impl Columns {
    /// `other`'s rows after these, its regime codes renumbered into these labels.
    fn append(&mut self, other: Columns) {
        let Columns {
            responses,
            zone_ends,
            regimes,
            quantities,
            labels,
        } = other;
        for (mine, theirs) in self.responses.iter_mut().zip(responses) {
            mine.extend(theirs);
        }
        for (mine, theirs) in self.zone_ends.iter_mut().zip(zone_ends) {
            mine.extend(theirs);
        }
        let renumber: Vec<i8> = labels.0.iter().map(|&r| self.labels.code(r)).collect();
        for (mine, theirs) in self.regimes.iter_mut().zip(regimes) {
            mine.extend(theirs.into_iter().map(|c| renumber[c as usize]));
        }
        for (mine, theirs) in self.quantities.iter_mut().zip(quantities) {
            mine.extend(theirs);
        }
    }
}

/// The quantities named in `names` (names or aliases), `KeyError` for one the problem lacks.
fn wanted_quantities(
    kind: ModelKind,
    names: Option<&Bound<'_, PyAny>>,
) -> PyResult<Vec<&'static QuantityName>> {
    let Some(names) = names else {
        return Ok(Vec::new());
    };
    let names: Vec<String> = if let Ok(one) = names.extract::<String>() {
        if one == "all" {
            return Ok(kind.description().quantities.iter().collect());
        }
        vec![one]
    } else {
        names.extract()?
    };
    names
        .iter()
        .map(|name| quantity_named(kind, name))
        .collect()
}

/// A column as a numpy array of the swept array's shape.
fn shaped<'py, T: numpy::Element>(
    py: Python<'py>,
    column: Vec<T>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    PyArray1::from_vec(py, column).reshape(shape)
}

/// `Problem.sweep` (its doc comment says what it returns).
pub fn sweep<'py>(
    problem: &Problem,
    py: Python<'py>,
    quantities: Option<&Bound<'py, PyAny>>,
    parameter: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = problem.kind;
    let (key, array) = match parameter.map(|p| p.items()) {
        Some(items) if items.len() == 1 => items
            .get_item(0)?
            .extract::<(String, Bound<'py, PyAny>)>()?,
        _ => {
            return Err(PyTypeError::new_err(format!(
                "sweep takes exactly one parameter as a keyword (one of: {})",
                kind.params()
                    .iter()
                    .map(|p| p.name())
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
    };
    let index = param_index_or_error(kind, &key)?;
    let wanted = wanted_quantities(kind, quantities)?;
    // Any array-like of numbers, as float64 in C order (a copy only where it is not one).
    let numpy = py.import("numpy")?;
    let array = numpy.call_method1("ascontiguousarray", (array, "float64"))?;
    let array = array.cast_into::<PyArrayDyn<f64>>()?;
    let shape = array.shape().to_vec();
    let readonly = array.readonly();
    let xs = readonly.as_slice()?;
    let values = problem.values.clone();
    let solved = py.detach(|| guard(|| run_parallel(kind, &values, index, xs, &wanted)))?;
    let columns = solved.map_err(|(i, e)| problem_error(py, &e, &format!("{key}[{i}]: ")))?;

    let out = PyDict::new(py);
    out.set_item(&key, array.clone())?;
    let symbol = kind.description().response_symbol;
    let [coulomb, regularized] = columns.responses;
    out.set_item(format!("{symbol}_coulomb"), shaped(py, coulomb, &shape)?)?;
    out.set_item(
        format!("{symbol}_regularized"),
        shaped(py, regularized, &shape)?,
    )?;
    let [coulomb, regularized] = columns.zone_ends;
    out.set_item("zone_end_coulomb", shaped(py, coulomb, &shape)?)?;
    out.set_item("zone_end_regularized", shaped(py, regularized, &shape)?)?;
    let [coulomb, regularized] = columns.regimes;
    out.set_item("regime_coulomb", shaped(py, coulomb, &shape)?)?;
    out.set_item("regime_regularized", shaped(py, regularized, &shape)?)?;
    let labels: Vec<&str> = columns.labels.0.iter().map(|r| r.label()).collect();
    out.set_item("regimes", PyTuple::new(py, labels)?)?;
    for (q, column) in wanted.iter().zip(columns.quantities) {
        out.set_item(q.name, shaped(py, column, &shape)?)?;
    }
    Ok(out)
}
