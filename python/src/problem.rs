//! `microslip._native.Problem`: one validated parameter set of any registered problem, the base
//! class of `TwinBeams`, `Plate`, `LapJoint` (built in `microslip/__init__.py`, each naming its
//! registry key in `_model`). It holds the problem's kind and its values in the order of
//! `kind.params()` and reaches the physics only through `kind.problem()` (`&dyn AnyProblem`), so
//! it names no problem.

use microslip::problems::ModelKind;
use pyo3::exceptions::{PyAttributeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyType};

use crate::errors::{guard, problem_error};
use crate::registry::{
    kind_of, load_index, param_index, param_index_or_error, params_dict, unit_symbol,
};
use crate::solution::Solution;

/// The name a parameter set built from keywords reports as its `preset` (the CLI's JSON key).
const KEYWORD_NAME: &str = "custom";

/// A valid parameter set of one problem (frozen: `replace` gives a changed copy).
#[pyclass(subclass, frozen, module = "microslip")]
pub struct Problem {
    pub(crate) kind: ModelKind,
    pub(crate) values: Vec<f64>,
    pub(crate) name: String,
}

impl Problem {
    /// The values with `changes` (parameter name -> value) applied, refused as Python would
    /// refuse an unknown keyword (`TypeError`, listing the keys) or a non-number.
    pub(crate) fn values_with(
        kind: ModelKind,
        mut values: Vec<f64>,
        changes: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Vec<f64>> {
        for (key, value) in changes.into_iter().flat_map(|d| d.iter()) {
            let key: String = key.extract()?;
            let index = param_index_or_error(kind, &key)?;
            values[index] = value.extract::<f64>().map_err(|_| {
                PyTypeError::new_err(format!(
                    "{key} must be a number, got {}",
                    value
                        .get_type()
                        .name()
                        .map_or_else(|_| "?".into(), |n| n.to_string())
                ))
            })?;
        }
        Ok(values)
    }

    /// Validated through the core's checked constructors: `ParameterError` naming the first
    /// value outside its domain.
    pub(crate) fn checked(
        py: Python<'_>,
        kind: ModelKind,
        values: Vec<f64>,
        name: String,
    ) -> PyResult<Problem> {
        let problem = kind.problem();
        guard(|| problem.check(&values))?.map_err(|e| problem_error(py, &e, ""))?;
        Ok(Problem { kind, values, name })
    }

    /// The registry key of `cls` (its `_model` attribute).
    fn kind_of_class(cls: &Bound<'_, PyType>) -> PyResult<ModelKind> {
        let key: String = cls
            .getattr("_model")
            .and_then(|k| k.extract())
            .map_err(|_| {
                PyTypeError::new_err(
                    "instantiate a problem class (microslip.PROBLEMS lists them), not Problem",
                )
            })?;
        kind_of(&key)
    }
}

#[pymethods]
impl Problem {
    /// Parameters as keywords, in the units of `units`; a parameter not given takes the value
    /// of the problem's bundled paper data set (`defaults`). `name` is what `to_dict()` reports
    /// as its `preset`.
    #[new]
    #[classmethod]
    #[pyo3(signature = (*, name = None, **params))]
    fn new(
        cls: &Bound<'_, PyType>,
        name: Option<String>,
        params: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Problem> {
        let kind = Self::kind_of_class(cls)?;
        let values = Self::values_with(kind, kind.problem().paper_values(), params)?;
        Self::checked(
            cls.py(),
            kind,
            values,
            name.unwrap_or_else(|| KEYWORD_NAME.to_string()),
        )
    }

    /// The registry key (`beam`, `plate`, `lap`).
    #[getter]
    fn model(&self) -> &'static str {
        self.kind.name()
    }

    /// The data set's name: a preset's, or `custom` for keywords (the `preset` of `to_dict()`).
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// Every parameter's value, by name, in display order.
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        params_dict(py, self.kind, &self.values)
    }

    /// Every parameter's unit (`mm`, `N`, `MPa`, `MPa/mm`, `-`), by name.
    #[getter]
    fn units<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for param in self.kind.params() {
            dict.set_item(param.name(), unit_symbol(param.unit()))?;
        }
        Ok(dict)
    }

    /// The load (N) at which the regimes change, which the load is measured against: the beams'
    /// F_thre, the joint's F_gross; None for a problem without a load.
    #[getter]
    fn regime_scale(&self) -> PyResult<Option<f64>> {
        let problem = self.kind.problem();
        let scale = guard(|| {
            problem
                .inputs_at(&self.values)
                .ok()
                .and_then(|inputs| inputs.validate_without_load().ok())
                .and_then(|model| model.regime_scale())
        })?;
        Ok(scale)
    }

    /// A parameter's value as an attribute (`beams.KT`).
    fn __getattr__(&self, key: &str) -> PyResult<f64> {
        param_index(self.kind, key)
            .map(|i| self.values[i])
            .ok_or_else(|| {
                PyAttributeError::new_err(format!("{} has no parameter {key:?}", self.kind))
            })
    }

    /// A copy with `changes` applied (checked as the constructor checks); its name says it was
    /// modified when a value differs.
    #[pyo3(signature = (**changes))]
    fn replace<'py>(
        slf: &Bound<'py, Self>,
        changes: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let this = slf.get();
        let values = Self::values_with(this.kind, this.values.clone(), changes)?;
        let name = if values == this.values || this.name.ends_with(" (modified)") {
            this.name.clone()
        } else {
            format!("{} (modified)", this.name)
        };
        let kwargs = PyDict::new(slf.py());
        for (param, value) in this.kind.params().iter().zip(&values) {
            kwargs.set_item(param.name(), value)?;
        }
        kwargs.set_item("name", name)?;
        slf.get_type().call((), Some(&kwargs))
    }

    /// Solves both laws at this data set, or at the problem's load when given (problems driven
    /// by a load only), by its own name (`F=` in N for the beams and the lap joint, `Q=` in N/mm
    /// for the cylinder) or positionally. `F=` is also taken as the load of a problem whose load
    /// has another name (the cylinder's Q): an alias kept for scripts written before the load
    /// kept its own name. The answer is a frozen `Solution`.
    #[pyo3(signature = (load = None, **named))]
    fn solve(
        &self,
        py: Python<'_>,
        load: Option<&Bound<'_, PyAny>>,
        named: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Solution> {
        let mut values = self.values.clone();
        if let Some(value) = crate::registry::load_argument(self.kind, load, named)? {
            let index = load_index(self.kind).ok_or_else(|| {
                PyTypeError::new_err(format!(
                    "the {} has no load to set",
                    self.kind.description().title
                ))
            })?;
            values[index] = value;
        }
        Solution::new(py, self.kind, values, self.name.clone())
    }

    /// The problem solved at every value of one parameter given as a keyword (`F=array`,
    /// `KT=np.logspace(2, 6, 50)`; any shape, in that parameter's unit), every other parameter as
    /// in this data set. Returns a dict of numpy arrays of the same shape:
    ///
    /// - the swept parameter itself (float64);
    /// - `<r>_coulomb`, `<r>_regularized`: the response (mm), `<r>` its symbol (`w`, `u`,
    ///   `Delta`);
    /// - `zone_end_coulomb`, `zone_end_regularized` (mm): where each law's zone ends;
    /// - `regime_coulomb`, `regime_regularized` (int8): indices into `regimes`, the tuple of
    ///   regime labels that occur;
    /// - each quantity named in `quantities` (a list of names or aliases, or `"all"`), NaN where
    ///   undefined.
    ///
    /// A value outside its domain raises `ParameterError` naming its index. The GIL is released
    /// while it solves; Ctrl-C raises `KeyboardInterrupt` within a fraction of a second; result
    /// arrays too large for memory raise `MemoryError` before any point is solved.
    #[pyo3(signature = (*, quantities = None, **parameter))]
    fn sweep<'py>(
        &self,
        py: Python<'py>,
        quantities: Option<&Bound<'py, PyAny>>,
        parameter: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        crate::sweep::sweep(self, py, quantities, parameter)
    }

    /// One load cycle between +amplitude and -amplitude (N), both laws: the loop, the
    /// dissipation D (N mm) and the damping ratio, as `microslip cycle --amplitude A --format
    /// json` reports them. Problems driven by a load only.
    fn cycle<'py>(&self, py: Python<'py>, amplitude: f64) -> PyResult<Bound<'py, PyAny>> {
        crate::features::cycle(py, self, amplitude)
    }

    /// The K_T each FE code assumes by default for a contact element of `element_size` mm
    /// (default a hundredth of the interface) and what it does to the answer, as `microslip kt
    /// --format json`.
    #[pyo3(signature = (element_size = None))]
    fn fe_defaults<'py>(
        &self,
        py: Python<'py>,
        element_size: Option<f64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        crate::features::fe_defaults(py, self, element_size)
    }

    /// The K_T (MPa/mm) that keeps the answer within `tolerance` (`"1%"`, `"0.01"` or 0.01) of
    /// `of` (`"coulomb"`: K_T -> infinity; `"current"`: this K_T) over the forces F_from..F_to
    /// (N; each this data set's F when not given), with each FE code's setting, as `microslip kt
    /// --tolerance T --of REF --from F --to F --format json`.
    #[pyo3(signature = (tolerance, *, of = "coulomb", F_from = None, F_to = None, element_size = None))]
    #[allow(non_snake_case)]
    fn kt_tolerance<'py>(
        &self,
        py: Python<'py>,
        tolerance: &Bound<'py, PyAny>,
        of: &str,
        F_from: Option<f64>,
        F_to: Option<f64>,
        element_size: Option<f64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        crate::features::kt_tolerance(py, self, tolerance, of, [F_from, F_to], element_size)
    }

    /// mu and K_T fitted to a measured load-response curve: loads `F` (in the load's unit: N, or
    /// N/mm for the cylinder's line load Q) and the measured response (mm: w(L) of the beams,
    /// Delta of the joint, the cylinder's edge slip s(a)), with each point's standard deviation
    /// `sigma` (mm) when known; `fix_mu`/`fix_KT` hold one; `weights` is `"relative"` (default)
    /// or `"absolute"` without sigma. The report has the estimates, their uncertainty and the
    /// identifiability verdicts, as `microslip fit beam|lap|cylinder --format json`.
    #[pyo3(signature = (F, measured, sigma = None, *, fix_mu = None, fix_KT = None, weights = None))]
    #[allow(non_snake_case, clippy::too_many_arguments)]
    fn fit<'py>(
        &self,
        py: Python<'py>,
        F: Vec<f64>,
        measured: Vec<f64>,
        sigma: Option<Vec<f64>>,
        fix_mu: Option<f64>,
        fix_KT: Option<f64>,
        weights: Option<&str>,
    ) -> PyResult<Bound<'py, PyAny>> {
        crate::features::fit(py, self, (F, measured, sigma), (fix_mu, fix_KT), weights)
    }

    /// The 2-D plane-strain continuum reference's response (mm) on the default mesh: u(L) of the
    /// plate, Delta of the joint (what the reduced theory's answer is compared with). The GIL is
    /// released while it solves.
    fn continuum(&self, py: Python<'_>) -> PyResult<f64> {
        crate::features::continuum(py, self)
    }

    /// The CalculiX input deck of this data set (Abaqus keyword syntax), as `microslip deck ccx
    /// MODEL` writes it: `mesh` `"coarse"`, `"fine"` or `"finest"`, `loads` the load steps' forces (N,
    /// increasing; default the CLI's, spanning every regime).
    #[pyo3(signature = (code = "ccx", *, mesh = "coarse", loads = None))]
    fn deck(
        &self,
        py: Python<'_>,
        code: &str,
        mesh: &str,
        loads: Option<Vec<f64>>,
    ) -> PyResult<String> {
        crate::features::deck(py, self, code, mesh, loads)
    }

    /// Pickling (multiprocessing pools, caches): rebuilt through the constructor, so a pickle
    /// is checked again when loaded.
    fn __getnewargs_ex__<'py>(&self, py: Python<'py>) -> PyResult<((), Bound<'py, PyDict>)> {
        let kwargs = params_dict(py, self.kind, &self.values)?;
        kwargs.set_item("name", &self.name)?;
        Ok(((), kwargs))
    }

    fn __repr__(&self) -> String {
        let args: Vec<String> = self
            .kind
            .params()
            .iter()
            .zip(&self.values)
            .map(|(p, v)| format!("{}={v:?}", p.name()))
            .collect();
        format!(
            "<{} {:?}: {}>",
            self.kind.description().title,
            self.name,
            args.join(", ")
        )
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<Problem>().is_ok_and(|o| {
            let o = o.get();
            o.kind == self.kind && o.values == self.values
        })
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        self.kind.hash(&mut hasher);
        for v in &self.values {
            // -0 and 0 compare equal, so they must hash equal.
            (v + 0.0).to_bits().hash(&mut hasher);
        }
        hasher.finish()
    }
}
