//! `Solution` and `Law`: one solve of any problem, frozen. The numbers come from
//! `AnyProblem::answers` and `quantity_at` (both laws' response, zone end and regime, and every
//! quantity of the problem's description), the full report from the application's JSON report
//! (`to_dict()`, through `bridge`), so each number is the one the CLI prints.

use microslip::kernel::regime::Regime;
use microslip::problems::ModelKind;
use microslip::problems::problem::{Answers, LawAnswer};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::bridge;
use crate::errors::{guard, problem_error};
use crate::json::to_python;
use crate::registry::{load_index, params_dict, quantity_named, unit_symbol};

/// One law's answer: the response (mm), the regime and its zones, where the law's zone ends (mm).
#[pyclass(frozen, module = "microslip")]
pub struct Law {
    answer: LawAnswer,
}

#[pymethods]
impl Law {
    /// The benchmarked response (mm): the beams' tip deflection w(L), the plate's end
    /// displacement u(L), the joint's Delta.
    #[getter]
    fn response(&self) -> f64 {
        self.answer.response
    }

    /// The regime's label as the CLI writes it (`microslip+macroslip`, `unloaded`).
    #[getter]
    fn regime(&self) -> &'static str {
        self.answer.regime.label()
    }

    /// The zones from x = 0 outward (`("microslip", "macroslip")`); empty when unloaded.
    #[getter]
    fn zones(&self) -> Vec<&'static str> {
        self.answer.regime.zones().map(|z| z.name()).collect()
    }

    /// Where the zone this law is about ends (mm): the stick zone under Coulomb, the microslip
    /// zone under the regularized law.
    #[getter]
    fn zone_end(&self) -> f64 {
        self.answer.zone_end
    }

    fn __repr__(&self) -> String {
        format!(
            "Law(response={:?}, regime={:?}, zone_end={:?})",
            self.answer.response,
            self.answer.regime.label(),
            self.answer.zone_end
        )
    }
}

/// One solve of a problem at one set of values, under both laws (frozen).
#[pyclass(frozen, module = "microslip")]
pub struct Solution {
    kind: ModelKind,
    values: Vec<f64>,
    name: String,
    answers: Answers,
    quantities: Vec<Option<f64>>,
}

impl Solution {
    /// Solves `kind` at `values` with the GIL released.
    pub fn new(
        py: Python<'_>,
        kind: ModelKind,
        values: Vec<f64>,
        name: String,
    ) -> PyResult<Solution> {
        let problem = kind.problem();
        let solved = py.detach(|| {
            guard(|| {
                let answers = problem.answers(&values)?;
                let quantities = kind
                    .description()
                    .quantities
                    .iter()
                    .map(|q| problem.quantity_at(&values, q.quantity))
                    .collect::<Result<Vec<_>, _>>()?;
                Ok((answers, quantities))
            })
        })?;
        let (answers, quantities) = solved.map_err(|e| problem_error(py, &e, ""))?;
        Ok(Solution {
            kind,
            values,
            name,
            answers,
            quantities,
        })
    }
}

#[pymethods]
impl Solution {
    /// The registry key of the problem solved.
    #[getter]
    fn model(&self) -> &'static str {
        self.kind.name()
    }

    /// The parameter values solved at, by name.
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        params_dict(py, self.kind, &self.values)
    }

    /// The load (N) solved at; None for a problem without one (the plate).
    #[getter]
    #[allow(non_snake_case)]
    fn F(&self) -> Option<f64> {
        load_index(self.kind).map(|i| self.values[i])
    }

    /// Plain Coulomb's answer.
    #[getter]
    fn coulomb(&self) -> Law {
        Law {
            answer: self.answers.coulomb,
        }
    }

    /// The regularized law's answer.
    #[getter]
    fn regularized(&self) -> Law {
        Law {
            answer: self.answers.regularized,
        }
    }

    /// Every quantity of the problem by its name (`w(L)`, `X`, `ratio`, `F_1`, `D`, `zeta`
    /// for the beams); None where it is not defined (the ratio at zero load).
    #[getter]
    fn quantities<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (q, value) in self
            .kind
            .description()
            .quantities
            .iter()
            .zip(&self.quantities)
        {
            dict.set_item(q.name, value)?;
        }
        Ok(dict)
    }

    /// The unit of every parameter, of every quantity (`-` for a ratio) and of `response` and
    /// `zone_end` (mm).
    #[getter]
    fn units<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for param in self.kind.params() {
            dict.set_item(param.name(), unit_symbol(param.unit()))?;
        }
        for q in self.kind.description().quantities {
            dict.set_item(q.name, if q.unit.is_empty() { "-" } else { q.unit })?;
        }
        dict.set_item("response", "mm")?;
        dict.set_item("zone_end", "mm")?;
        Ok(dict)
    }

    /// A quantity by name or alias (`s["w(L)"]`, `s["X"]`); None where not defined.
    fn __getitem__(&self, name: &str) -> PyResult<Option<f64>> {
        let quantity = quantity_named(self.kind, name)?;
        let index = self
            .kind
            .description()
            .quantities
            .iter()
            .position(|q| q.quantity == quantity.quantity)
            .unwrap_or(0);
        Ok(self.quantities.get(index).copied().flatten())
    }

    /// The report `microslip <model> --format json` prints for the same values, as a dict (its
    /// `preset` is this data set's name). The plate's and the joint's include the continuum
    /// reference where the reduced theory does not hold, as the CLI's do (the GIL is released
    /// while it solves, and Ctrl-C stops it).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let value = crate::features::released(py, || {
            bridge::point_report(self.kind, &self.values, &self.name)
        })?;
        to_python(py, &value)
    }

    fn __repr__(&self) -> String {
        let label = |r: Regime| r.label();
        format!(
            "<{} solution: coulomb {:?} {}, regularized {:?} {}>",
            self.kind.description().title,
            self.answers.coulomb.response,
            label(self.answers.coulomb.regime),
            self.answers.regularized.response,
            label(self.answers.regularized.regime)
        )
    }
}
