//! The problem registry as Python sees it: every problem of `ModelKind::ALL` with its key, title,
//! parameters (name, unit, meaning, domain, paper value), load and quantities, read from the core's
//! descriptions. `microslip/__init__.py` builds one class per entry from this, so a problem added
//! to the core's registry appears in Python with no binding code of its own.

use microslip::kernel::params::Unit;
use microslip::problems::{ModelKind, Param, QuantityName};
use pyo3::exceptions::{PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// The problem whose registry key is `key` (`beam`), as `ValueError` with the keys otherwise.
pub fn kind_of(key: &str) -> PyResult<ModelKind> {
    key.parse::<ModelKind>()
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A unit as the `units` mappings spell it: the core's symbol (`mm`, `MPa/mm`, `-`).
pub fn unit_symbol(unit: Unit) -> &'static str {
    unit.symbol()
}

/// The place of the parameter `key` in `kind`'s parameter list.
pub fn param_index(kind: ModelKind, key: &str) -> Option<usize> {
    kind.params().iter().position(|p| p.name() == key)
}

/// [`param_index`], or the `TypeError` Python gives an unexpected keyword, in the core's words
/// ("unknown key 'Kt' for the beam model (allowed: L b h E nu P mu KT F)").
pub fn param_index_or_error(kind: ModelKind, key: &str) -> PyResult<usize> {
    param_index(kind, key).ok_or_else(|| {
        PyTypeError::new_err(
            kind.param(key)
                .err()
                .map_or(key.to_string(), |e| e.to_string()),
        )
    })
}

/// Every parameter of `kind` with its value in `values`, by name, in display order.
pub fn params_dict<'py>(
    py: Python<'py>,
    kind: ModelKind,
    values: &[f64],
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (param, value) in kind.params().iter().zip(values) {
        dict.set_item(param.name(), value)?;
    }
    Ok(dict)
}

/// The index of the problem's load in its parameter list, where it has one.
pub fn load_index(kind: ModelKind) -> Option<usize> {
    let load = kind.description().load?;
    kind.params().iter().position(|&p| p == load)
}

/// The alias a load-driven problem whose load is a force (N) or a line load (N/mm) takes for its
/// load's keyword in `solve`: `F`, the name the load had in every problem before the cylinder's
/// line load Q (documented in the guide); not a torque's.
const LOAD_ALIAS: &str = "F";

/// The load `solve` was given, positionally (`load`) or by keyword (`named`: the problem's load
/// name, `Q` for the cylinder, or its alias `F`), as a number; None when none was given. A bool
/// is refused (Python takes `True` as 1), as are any other keyword and a load given twice, each
/// in the problem's words.
pub fn load_argument(
    kind: ModelKind,
    load: Option<&Bound<'_, PyAny>>,
    named: Option<&Bound<'_, PyDict>>,
) -> PyResult<Option<f64>> {
    let info = kind.description();
    let words = info.load_words();
    let expected = || match words {
        Some((name, unit)) => format!(
            "solve() of the {} takes its load {name} ({unit}), positionally or as {name}=",
            info.title
        ),
        None => format!("the {} has no load: its solve() takes none", info.title),
    };
    let mut given = load.cloned();
    if let Some(named) = named {
        for (key, value) in named.iter() {
            let key: String = key.extract()?;
            // The alias is a force's name: a load that is no force (the twisted fit's torque,
            // N mm) takes only its own, so that F= never sets a torque.
            let known = words.is_some_and(|(name, unit)| {
                key == name || (key == LOAD_ALIAS && matches!(unit, "N" | "N/mm"))
            });
            if !known {
                return Err(PyTypeError::new_err(format!(
                    "unexpected keyword '{key}': {}",
                    expected()
                )));
            }
            if given.is_some() {
                return Err(PyTypeError::new_err(format!(
                    "the load is given twice: {}",
                    expected()
                )));
            }
            given = Some(value);
        }
    }
    let Some(value) = given else {
        return Ok(None);
    };
    if words.is_none() {
        return Err(PyTypeError::new_err(expected()));
    }
    if value.is_instance_of::<pyo3::types::PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "the load must be a number, not a bool: {}",
            expected()
        )));
    }
    value
        .extract::<f64>()
        .map(Some)
        .map_err(|_| PyTypeError::new_err(format!("the load must be a number: {}", expected())))
}

/// The quantity of `kind` named `name` or one of its aliases, or a `KeyError` listing them.
pub fn quantity_named(kind: ModelKind, name: &str) -> PyResult<&'static QuantityName> {
    let quantities = kind.description().quantities;
    quantities
        .iter()
        .find(|q| q.name == name || q.aliases.contains(&name))
        .ok_or_else(|| {
            let names: Vec<&str> = quantities.iter().map(|q| q.name).collect();
            PyKeyError::new_err(format!(
                "the {kind} problem has no quantity {name:?} (it has: {})",
                names.join(", ")
            ))
        })
}

fn param_entry<'py>(py: Python<'py>, param: Param, paper: f64) -> PyResult<Bound<'py, PyDict>> {
    let spec = param.spec();
    let entry = PyDict::new(py);
    entry.set_item("name", spec.name)?;
    entry.set_item("unit", unit_symbol(spec.unit))?;
    entry.set_item("meaning", spec.meaning)?;
    entry.set_item("allowed", spec.domain.describe(spec.unit))?;
    entry.set_item("min", spec.domain.min())?;
    entry.set_item("max", spec.domain.max())?;
    entry.set_item("usual", spec.usual)?;
    entry.set_item("default", paper)?;
    Ok(entry)
}

fn quantity_entry<'py>(py: Python<'py>, q: &QuantityName) -> PyResult<Bound<'py, PyDict>> {
    let entry = PyDict::new(py);
    entry.set_item("name", q.name)?;
    entry.set_item("aliases", q.aliases.to_vec())?;
    entry.set_item("meaning", q.meaning)?;
    entry.set_item("unit", if q.unit.is_empty() { "-" } else { q.unit })?;
    Ok(entry)
}

/// Every problem of the registry as a list of plain dicts (`key`, `title`, `summary`,
/// `paper_preset`, `response_symbol`, `load`, `params`, `quantities`), in registry order.
#[pyfunction]
pub fn problems(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for kind in ModelKind::ALL {
        let info = kind.description();
        let paper = kind.problem().paper_values();
        let entry = PyDict::new(py);
        entry.set_item("key", info.key)?;
        entry.set_item("title", info.title)?;
        entry.set_item("summary", info.summary)?;
        entry.set_item("paper_preset", info.paper_preset)?;
        entry.set_item("response_symbol", info.response_symbol)?;
        entry.set_item("load", info.load.map(|p| p.name()))?;
        let params = PyList::empty(py);
        for (&param, &value) in kind.params().iter().zip(&paper) {
            params.append(param_entry(py, param, value)?)?;
        }
        entry.set_item("params", params)?;
        let quantities = PyList::empty(py);
        for q in info.quantities {
            quantities.append(quantity_entry(py, q)?)?;
        }
        entry.set_item("quantities", quantities)?;
        list.append(entry)?;
    }
    Ok(list)
}
