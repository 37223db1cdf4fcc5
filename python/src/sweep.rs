//! `Problem.sweep(**{key: array})`: the problem solved at every value of one parameter, the
//! others held, into numpy arrays. Each point is `AnyProblem::answers` (and `quantity_at` for the
//! quantities asked for) at the same values a scalar `solve` would use. The points walk one
//! family, in one [`family`](microslip::kernel::family) scope per [`CHUNK`] points (fixed, whatever the number of cores: the
//! result depends on the sweep's values and their order only): a solver that continues from the
//! previous point does (the cylinder, issue 47, to 1e-9 of the scalar `solve`); the closed forms
//! equal the scalar loop bit for bit. The result arrays are numpy's, allocated before any point
//! is solved (a sweep too large for memory is numpy's `MemoryError`, never an abort); the loop
//! runs with the GIL released, its chunks split across cores, each writing its own rows, and
//! stops at Ctrl-C (`interrupt`: every point is a checkpoint).

use microslip::kernel::family::Family;
use microslip::kernel::regime::Regime;
use microslip::problems::problem::ProblemError;
use microslip::problems::{ModelKind, QuantityName};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use microslip::numeric::cancel::{cancellable, checkpoint};
use numpy::{PyArrayDyn, PyArrayMethods, PyReadwriteArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::errors::{guard, problem_error};
use crate::interrupt::interruptible;
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

/// Where one sweep's points go: a mutable slice of each output column, all of one length.
struct Columns<'a> {
    responses: [&'a mut [f64]; 2],
    zone_ends: [&'a mut [f64]; 2],
    regimes: [&'a mut [i8]; 2],
    quantities: Vec<&'a mut [f64]>,
}

impl<'a> Columns<'a> {
    /// These columns cut after `at` rows: the first `at` rows, and the rest.
    fn split_at(self, at: usize) -> (Columns<'a>, Columns<'a>) {
        fn two<T>(column: &mut [T], at: usize) -> (&mut [T], &mut [T]) {
            column.split_at_mut(at)
        }
        let [r0, r1] = self.responses;
        let [z0, z1] = self.zone_ends;
        let [g0, g1] = self.regimes;
        let ((r0a, r0b), (r1a, r1b)) = (two(r0, at), two(r1, at));
        let ((z0a, z0b), (z1a, z1b)) = (two(z0, at), two(z1, at));
        let ((g0a, g0b), (g1a, g1b)) = (two(g0, at), two(g1, at));
        let (qa, qb): (Vec<_>, Vec<_>) = self.quantities.into_iter().map(|q| two(q, at)).unzip();
        (
            Columns {
                responses: [r0a, r1a],
                zone_ends: [z0a, z1a],
                regimes: [g0a, g1a],
                quantities: qa,
            },
            Columns {
                responses: [r0b, r1b],
                zone_ends: [z0b, z1b],
                regimes: [g0b, g1b],
                quantities: qb,
            },
        )
    }
}

/// Solves at each of `xs` set at `index`, from `values`, into `out` (one row per element of
/// `xs`, which starts at a multiple of [`CHUNK`] of the sweep), each [`CHUNK`] points in a scope
/// of their own, and returns the regime labels its codes index. The first refusal stops the loop
/// and says at which element of `xs`; a cancelled call (Ctrl-C, [`crate::interrupt`]) stops at
/// the next point.
fn run(
    kind: ModelKind,
    mut values: Vec<f64>,
    index: usize,
    xs: &[f64],
    wanted: &[&'static QuantityName],
    out: Columns<'_>,
) -> Result<Regimes, (usize, ProblemError)> {
    let problem = kind.problem();
    let mut labels = Regimes(Vec::new());
    let Columns {
        responses,
        zone_ends,
        regimes,
        mut quantities,
    } = out;
    let mut scope = Family::default();
    for (i, &x) in xs.iter().enumerate() {
        checkpoint();
        if i % CHUNK == 0 {
            scope = Family::default();
        }
        values[index] = x;
        let (answers, solved) = scope
            .run(|| {
                let answers = problem.answers(&values)?;
                let solved: Result<Vec<_>, ProblemError> = wanted
                    .iter()
                    .map(|q| problem.quantity_at(&values, q.quantity))
                    .collect();
                Ok((answers, solved?))
            })
            .map_err(|e| (i, e))?;
        for (law, answer) in [answers.coulomb, answers.regularized]
            .into_iter()
            .enumerate()
        {
            responses[law][i] = answer.response;
            zone_ends[law][i] = answer.zone_end;
            regimes[law][i] = labels.code(answer.regime);
        }
        for (value, column) in solved.into_iter().zip(&mut quantities) {
            column[i] = value.unwrap_or(f64::NAN);
        }
    }
    Ok(labels)
}

/// Most points a sweep solves without listening for Ctrl-C ([`interruptible`]).
const INLINE_POINTS: usize = 64;

/// Points solved in one family scope, and the fewest a thread is given (below this, starting it
/// costs more than it saves). Fixed: the scopes, and so the answers, do not depend on the number
/// of cores.
const CHUNK: usize = 32_768;

/// [`run`] over `xs` split into one contiguous run of whole [`CHUNK`]s per available core (each
/// chunk solved in its own scope wherever it runs, so the split cannot change a bit), each
/// writing its own rows of `out`, its regime codes then renumbered into one set of labels.
/// The refusal reported is the one at the lowest index. Every chunk stops once `cancel` is set.
fn run_parallel(
    kind: ModelKind,
    (values, index): (&[f64], usize),
    xs: &[f64],
    wanted: &[&'static QuantityName],
    mut out: Columns<'_>,
    cancel: &Arc<AtomicBool>,
) -> Result<Regimes, (usize, ProblemError)> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let chunks = xs.len().div_ceil(CHUNK);
    let threads = cores.min(chunks).max(1);
    if threads == 1 {
        return run(kind, values.to_vec(), index, xs, wanted, out);
    }
    let size = chunks.div_ceil(threads) * CHUNK;
    let mut parts = Vec::with_capacity(threads);
    for _ in 1..threads {
        let (head, rest) = out.split_at(size);
        parts.push(head);
        out = rest;
    }
    parts.push(out);
    let labels: Vec<Option<Result<Regimes, (usize, ProblemError)>>> = std::thread::scope(|scope| {
        let handles: Vec<_> = xs
            .chunks(size)
            .zip(parts.iter_mut())
            .enumerate()
            .map(|(c, (chunk, part))| {
                let part = Columns {
                    responses: part.responses.each_mut().map(|s| &mut **s),
                    zone_ends: part.zone_ends.each_mut().map(|s| &mut **s),
                    regimes: part.regimes.each_mut().map(|s| &mut **s),
                    quantities: part.quantities.iter_mut().map(|s| &mut **s).collect(),
                };
                scope.spawn(move || {
                    cancellable(cancel, || {
                        run(kind, values.to_vec(), index, chunk, wanted, part)
                            .map_err(|(i, e)| (c * size + i, e))
                    })
                })
            })
            .collect();
        // A panicking chunk re-raises here, on the caller's thread, where `guard` turns it
        // into a RuntimeError.
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    });
    let mut all = Regimes(Vec::new());
    for (part, labels) in parts.into_iter().zip(labels) {
        let Some(labels) = labels else {
            // A chunk was cancelled: so is this call, stopped here.
            checkpoint();
            return Err((
                0,
                ProblemError::Count {
                    problem: kind.name(),
                    expected: 0,
                    got: 0,
                },
            ));
        };
        let labels = labels?;
        let renumber: Vec<i8> = labels.0.iter().map(|&r| all.code(r)).collect();
        for column in part.regimes {
            for code in column.iter_mut() {
                *code = renumber[*code as usize];
            }
        }
    }
    Ok(all)
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

/// An uninitialized output column (`numpy.empty`) of the swept array's shape, in numpy's own
/// memory: a failed allocation is numpy's `MemoryError`, said again with the whole sweep's size
/// (`need`, for `columns` arrays of `points` points), never an abort of the interpreter.
fn column<'py, T: numpy::Element>(
    numpy: &Bound<'py, PyModule>,
    shape: &[usize],
    (points, columns, need): (usize, usize, f64),
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let py = numpy.py();
    let dtype = numpy::dtype::<T>(py);
    let made = numpy.call_method1("empty", (shape.to_vec(), dtype));
    match made {
        Ok(array) => Ok(array.cast_into::<PyArrayDyn<T>>()?),
        Err(e) if e.is_instance_of::<PyMemoryError>(py) => Err(PyMemoryError::new_err(format!(
            "a sweep of {points} points needs {:.3} GB for its {columns} result arrays, more \
             than this process can allocate ({}); sweep fewer points at a time",
            need / 1e9,
            e.value(py)
        ))),
        Err(e) => Err(e),
    }
}

/// The data of each of `arrays` (fresh, C-ordered: never refused).
fn slices<'a, T: numpy::Element>(
    arrays: &'a mut [PyReadwriteArrayDyn<'_, T>],
) -> PyResult<Vec<&'a mut [T]>> {
    arrays
        .iter_mut()
        .map(|a| a.as_slice_mut().map_err(PyErr::from))
        .collect()
}

/// The two slices of a law pair of columns.
fn pair<T>(columns: Vec<&mut [T]>) -> PyResult<[&mut [T]; 2]> {
    <[&mut [T]; 2]>::try_from(columns)
        .map_err(|v| PyTypeError::new_err(format!("internal error: {} columns, not 2", v.len())))
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

    // Every result array, allocated by numpy before any point is solved: four float64 columns,
    // two int8 ones, one float64 per quantity.
    let points = xs.len();
    let columns = 6 + wanted.len();
    let need = points as f64 * (8.0 * (4 + wanted.len()) as f64 + 2.0);
    let size = (points, columns, need);
    let f64s = |n: usize| -> PyResult<Vec<Bound<'py, PyArrayDyn<f64>>>> {
        (0..n)
            .map(|_| column::<f64>(&numpy, &shape, size))
            .collect()
    };
    let responses = f64s(2)?;
    let zone_ends = f64s(2)?;
    let regimes = [
        column::<i8>(&numpy, &shape, size)?,
        column::<i8>(&numpy, &shape, size)?,
    ];
    let quantity_arrays = f64s(wanted.len())?;
    let mut r = responses.iter().map(|a| a.readwrite()).collect::<Vec<_>>();
    let mut z = zone_ends.iter().map(|a| a.readwrite()).collect::<Vec<_>>();
    let mut g = regimes.iter().map(|a| a.readwrite()).collect::<Vec<_>>();
    let mut q = quantity_arrays
        .iter()
        .map(|a| a.readwrite())
        .collect::<Vec<_>>();
    let out = Columns {
        responses: pair(slices(&mut r)?)?,
        zone_ends: pair(slices(&mut z)?)?,
        regimes: pair(slices(&mut g)?)?,
        quantities: slices(&mut q)?,
    };
    let solved = if points <= INLINE_POINTS {
        // Too short to need Ctrl-C (a fifth of a second for the slowest problem): on this
        // thread, without the watcher thread's start (tens of microseconds).
        py.detach(|| guard(|| run(kind, values, index, xs, &wanted, out)))?
    } else {
        interruptible(py, |cancel| {
            run_parallel(kind, (&values, index), xs, &wanted, out, cancel)
        })?
    };
    let labels = solved.map_err(|(i, e)| problem_error(py, &e, &format!("{key}[{i}]: ")))?;
    drop((r, z, g, q, readonly));

    let out = PyDict::new(py);
    out.set_item(&key, array.clone())?;
    let symbol = kind.description().response_symbol;
    let [coulomb, regularized] = &responses[..] else {
        return Err(PyTypeError::new_err(
            "internal error: not two response columns",
        ));
    };
    out.set_item(format!("{symbol}_coulomb"), coulomb)?;
    out.set_item(format!("{symbol}_regularized"), regularized)?;
    let [coulomb, regularized] = &zone_ends[..] else {
        return Err(PyTypeError::new_err(
            "internal error: not two zone-end columns",
        ));
    };
    out.set_item("zone_end_coulomb", coulomb)?;
    out.set_item("zone_end_regularized", regularized)?;
    let [coulomb, regularized] = &regimes;
    out.set_item("regime_coulomb", coulomb)?;
    out.set_item("regime_regularized", regularized)?;
    let names: Vec<&str> = labels.0.iter().map(|r| r.label()).collect();
    out.set_item("regimes", PyTuple::new(py, names)?)?;
    for (q, column) in wanted.iter().zip(quantity_arrays) {
        out.set_item(q.name, column)?;
    }
    Ok(out)
}
