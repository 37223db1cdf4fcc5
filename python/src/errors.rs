//! How the core's refusals and a Rust panic reach Python: a refused parameter is a
//! [`ParameterError`] (a `ValueError`) whose message is the core's own text (field, value and
//! range, as the CLI prints it) and whose attributes carry the same three facts for code; a panic
//! becomes a `RuntimeError` instead of unwinding into the interpreter.

use std::panic::{AssertUnwindSafe, catch_unwind};

use microslip::kernel::params::ParamError;
use microslip::problems::problem::ProblemError;
use pyo3::exceptions::{PyMemoryError, PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(
    microslip,
    ParameterError,
    PyValueError,
    "A parameter outside its domain: `field`, `value` and `allowed` (the range, with its unit) \
     as attributes; the message is the command line's."
);

/// The core's refusal of one value as a [`ParameterError`], `prefix` (where in an array, which
/// flag) before its message.
pub fn param_error(py: Python<'_>, error: &ParamError, prefix: &str) -> PyErr {
    let err = ParameterError::new_err(format!("{prefix}{error}"));
    let instance = err.value(py);
    // Setting attributes on a fresh exception instance cannot fail short of memory; if it did,
    // the message still says all three.
    let _ = instance.setattr("field", error.field);
    let _ = instance.setattr("value", error.value);
    let _ = instance.setattr("allowed", error.allowed());
    err
}

/// A [`ProblemError`]: a refused value as [`param_error`]; a wrong count (a bug of this binding,
/// which always passes one value per parameter) as a `TypeError`.
pub fn problem_error(py: Python<'_>, error: &ProblemError, prefix: &str) -> PyErr {
    match error {
        ProblemError::Param(e) => param_error(py, e, prefix),
        ProblemError::Count { .. } => PyTypeError::new_err(format!("{prefix}{error}")),
    }
}

/// A refusal that is not one parameter's (a file that cannot be read, a tolerance outside its
/// range): a plain `ValueError` with the application's message.
pub fn value_error(message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// Runs `work`, turning a panic into a `RuntimeError` that says it is a bug: a Rust panic must
/// never abort Python, and PyO3's own `PanicException` derives from `BaseException`, which
/// `except Exception` in a user's script would not catch. Used around every call into the
/// physics, usually inside `Python::detach` (the GIL released).
pub fn guard<T>(work: impl FnOnce() -> T) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(work)).map_err(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        PyRuntimeError::new_err(format!(
            "microslip internal error (a bug, please report it): {what}"
        ))
    })
}

/// Panics on a worker path the way a physics bug would (GIL released, inside [`guard`]), so that
/// the test suite can check a panic reaches Python as a `RuntimeError` and the interpreter goes
/// on. Hidden (`_native._panic_check`); not an API.
#[pyfunction]
pub fn _panic_check(py: Python<'_>) -> PyResult<()> {
    py.detach(|| guard(|| -> () { panic!("deliberate panic for the test suite") }))
}

/// Refuses, as a `MemoryError`, work whose largest allocations (about `bytes` in all) the process
/// cannot make (issue 46, item 8): Rust aborts the interpreter on a failed allocation, so the
/// address space is asked for first, all at once, and given back at once (the pages are never
/// touched, so it costs nothing where it succeeds). `what` says what needed it.
pub fn ensure_memory(bytes: f64, what: impl FnOnce() -> String) -> PyResult<()> {
    let refused = || {
        PyMemoryError::new_err(format!(
            "{} needs about {:.3} GB, more than this process can allocate",
            what(),
            bytes / 1e9
        ))
    };
    // NaN or beyond what one allocation may be: refused as such.
    if bytes.is_nan() || bytes >= isize::MAX as f64 {
        return Err(refused());
    }
    let mut probe: Vec<u8> = Vec::new();
    probe
        .try_reserve_exact(bytes as usize)
        .map_err(|_| refused())
}
