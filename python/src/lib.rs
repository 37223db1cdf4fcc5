//! `microslip._native`: the Python face of microslip (issue 35), the native half of the
//! `microslip` package. It exposes the problem registry (`problems()`), one generic class
//! (`Problem`, which `microslip/__init__.py` subclasses once per registry entry: `TwinBeams`,
//! `Plate`, `LapJoint`), its `Solution`, vectorized sweeps, presets and the application's reports.
//!
//! Layout, one job per module: `registry` (the descriptions as data), `problem` (a validated
//! parameter set), `solution` (one solve), `sweep` (many, into numpy), `features` (cycle, K_T,
//! fit, continuum, decks, compare), `presets`, `suite` (`microslip suite` as data), `interrupt` (Ctrl-C during a long call), `bridge` (the CLI's command bodies, written once over
//! the application's generic functions and dispatched from the registry; the only code naming a
//! problem, where the application still has one function per problem), `json` (reports as Python objects), `errors`
//! (refusals as `ParameterError`, panics as `RuntimeError`, work too large for memory as
//! `MemoryError`).
//!
//! Every number comes from the same core functions the CLI calls, so Python and
//! `--format json` agree to the last bit; every solve releases the GIL, and every long one stops at
//! Ctrl-C (`KeyboardInterrupt`).

use pyo3::prelude::*;

mod bridge;
mod errors;
mod features;
mod interrupt;
mod json;
mod presets;
mod problem;
mod registry;
mod solution;
mod suite;
mod sweep;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<problem::Problem>()?;
    m.add_class::<solution::Solution>()?;
    m.add_class::<solution::Law>()?;
    m.add(
        "ParameterError",
        m.py().get_type::<errors::ParameterError>(),
    )?;
    m.add_function(wrap_pyfunction!(registry::problems, m)?)?;
    m.add_function(wrap_pyfunction!(presets::preset_values, m)?)?;
    m.add_function(wrap_pyfunction!(features::compare, m)?)?;
    m.add_function(wrap_pyfunction!(presets::preset_names, m)?)?;
    m.add_function(wrap_pyfunction!(suite::suite, m)?)?;
    m.add_function(wrap_pyfunction!(errors::_panic_check, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
