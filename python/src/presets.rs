//! Presets from Python: the application's loader (`preset::resolve`: a bundled name, a user
//! preset of that name, or a path to a TOML file), read into plain values so that
//! `microslip.preset(name)` builds the problem's class from them like any keyword call.

use microslip::preset;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::value_error;

/// `(model key, {parameter: value}, name, description)` of the preset `spec`.
///
/// # Errors
/// `ValueError` with the loader's message for a name or file it cannot load, and for a preset
/// that sets something beyond its parameter values (a setting such as a problem's choice of theory), which
/// this binding does not carry yet and must not silently drop.
#[pyfunction]
pub fn preset_values<'py>(
    py: Python<'py>,
    spec: &str,
) -> PyResult<(&'static str, Bound<'py, PyDict>, String, String)> {
    let loaded = preset::resolve(spec).map_err(value_error)?;
    let kind = loaded.inputs.kind();
    let params = PyDict::new(py);
    let mut values = Vec::with_capacity(kind.params().len());
    for &param in kind.params() {
        let value = loaded.inputs.get(param).unwrap_or(f64::NAN);
        params.set_item(param.name(), value)?;
        values.push(value);
    }
    let carried = kind.problem().inputs_at(&values).map_err(value_error)?;
    if carried != loaded.inputs {
        // The settings this preset sets away from their defaults, by their preset keys.
        let set: Vec<String> = kind
            .problem()
            .faces()
            .choices
            .iter()
            .filter(|choice| choice.get(&loaded.inputs) != choice.get(&carried))
            .map(|choice| {
                format!(
                    "{} = {}",
                    choice.key(),
                    choice.get(&loaded.inputs).unwrap_or("?")
                )
            })
            .collect();
        return Err(value_error(format!(
            "preset '{spec}' sets more than its parameter values ({}, not the default): the \
             Python API does not carry that yet; use the command line",
            set.join(", ")
        )));
    }
    Ok((kind.name(), params, loaded.name, loaded.description))
}

/// The names `preset()` accepts without a path: the bundled presets, then (unless
/// `bundled_only`) the valid ones in the user's preset directory.
#[pyfunction]
#[pyo3(signature = (bundled_only = false))]
pub fn preset_names(bundled_only: bool) -> Vec<String> {
    if bundled_only {
        return preset::bundled().into_iter().map(|p| p.name).collect();
    }
    preset::listing(preset::user_preset_dir().as_deref())
        .into_iter()
        .filter(|listed| listed.preset.is_ok())
        .map(|listed| listed.name)
        .collect()
}
