//! Cross-check of the closed forms against the independent finite-element solvers, over a grid that
//! spans every regime and the transitions between them. This is the only module that runs both; the
//! solvers in [`crate::numeric`] never see a closed form. Written once for every problem that can
//! be cross-checked ([`CrossChecked`](crate::problems::cross_check::CrossChecked): its grid, what
//! it compares and its cases are its folder's). Results are data (the worst case of each
//! quantity); the table for people is written by the `report` module.

use crate::numeric::{MeshDensity, NumericError};
use crate::problems::ModelKind;
use crate::problems::cross_check::AnyCrossChecked;
use crate::problems::inputs::Model;

/// Default tolerance on every relative error (the target of the numerical-solver issue).
pub const DEFAULT_TOLERANCE: f64 = 1e-3;

/// How much of the grid to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grid {
    /// Every case (about 130).
    Full,
    /// One geometry per model: a smoke test for CI.
    Quick,
}

/// A quantity both the closed forms and the finite elements compute: one of a problem's
/// [`CrossChecked::COMPARED`](crate::problems::cross_check::CrossChecked::COMPARED).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quantity {
    kind: ModelKind,
    index: usize,
}

impl Quantity {
    /// Every quantity compared, problem by problem in the registry's order.
    pub fn all() -> Vec<Quantity> {
        ModelKind::ALL
            .into_iter()
            .filter_map(|kind| Some((kind, kind.problem().faces().cross_checked?)))
            .flat_map(|(kind, check)| {
                (0..check.compared().len()).map(move |index| Quantity { kind, index })
            })
            .collect()
    }

    /// The problem it belongs to.
    pub fn kind(self) -> ModelKind {
        self.kind
    }

    /// What it is, with its unit (`beam w(L) (mm)`).
    pub fn label(self) -> &'static str {
        self.kind
            .problem()
            .faces()
            .cross_checked
            .and_then(|check| check.compared().get(self.index).copied())
            .unwrap_or_default()
    }
}

/// One compared case: the full model (parameters and, for a load-driven problem, its force), so
/// that it can be rerun.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case(Model);

impl Case {
    /// The case of `model`.
    pub fn new(model: Model) -> Case {
        Case(model)
    }

    /// The model compared.
    pub fn model(&self) -> &Model {
        &self.0
    }

    /// Every parameter on one line, with units, so that it can be rerun.
    pub fn describe(&self) -> String {
        self.0
            .kind()
            .problem()
            .faces()
            .cross_checked
            .and_then(|check| check.describe(&self.0))
            .unwrap_or_default()
    }
}

/// The worst disagreement found for one quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Worst {
    /// What was compared.
    pub quantity: Quantity,
    /// How many cases compared it.
    pub cases: usize,
    /// Largest relative error.
    pub error: f64,
    /// The case of that error (None when no case compared the quantity).
    pub case: Option<Case>,
}

impl Worst {
    fn new(quantity: Quantity) -> Self {
        Worst {
            quantity,
            cases: 0,
            error: 0.0,
            case: None,
        }
    }

    #[cfg(test)]
    fn record(&mut self, numeric: f64, exact: f64, case: Case) {
        self.record_error(
            crate::problems::cross_check::relative_error(numeric, exact),
            case,
        );
    }

    fn record_error(&mut self, error: f64, case: Case) {
        self.cases += 1;
        if error > self.error || self.case.is_none() {
            self.error = error;
            self.case = Some(case);
        }
    }

    /// Whether the worst relative error is within `tolerance` (a NaN error is not).
    pub fn passes(&self, tolerance: f64) -> bool {
        self.error <= tolerance
    }
}

/// How many of the quantities exceed `tolerance`.
pub fn failures(results: &[Worst], tolerance: f64) -> usize {
    results.iter().filter(|w| !w.passes(tolerance)).count()
}

/// Runs the comparison; returns the worst case of each quantity, in the order of
/// [`Quantity::all`].
///
/// # Errors
///
/// The [`NumericError`] of the first finite-element solve that fails.
pub fn run(grid: Grid, density: MeshDensity) -> Result<Vec<Worst>, NumericError> {
    let mut worst = Vec::new();
    for kind in ModelKind::ALL {
        if let Some(check) = kind.problem().faces().cross_checked {
            worst.extend(run_problem(kind, check, grid, density)?);
        }
    }
    Ok(worst)
}

/// One problem over its grid: the worst case of each quantity it compares.
fn run_problem(
    kind: ModelKind,
    check: &dyn AnyCrossChecked,
    grid: Grid,
    density: MeshDensity,
) -> Result<Vec<Worst>, NumericError> {
    let mut worst: Vec<Worst> = (0..check.compared().len())
        .map(|index| Worst::new(Quantity { kind, index }))
        .collect();
    for model in check.grid(grid == Grid::Full) {
        let Some(errors) = check.compare(&model, density) else {
            continue;
        };
        for (w, error) in worst.iter_mut().zip(errors?) {
            w.record_error(error, Case(model));
        }
    }
    Ok(worst)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::cross_check::relative_error;
    use crate::problems::inputs::Inputs;

    #[test]
    fn relative_error_handles_zero_references() {
        assert_eq!(relative_error(1e-3, 0.0), 1e-3);
        assert!((relative_error(1.01, 1.0) - 0.01).abs() < 1e-12);
    }

    #[test]
    fn the_worst_case_is_kept_and_failures_are_counted_against_the_tolerance() {
        let case = |force| {
            let mut inputs = Inputs::paper(ModelKind::Beam);
            inputs
                .set(ModelKind::Beam.description().load.unwrap(), force)
                .unwrap();
            Case(inputs.validate().unwrap())
        };
        let quantities = Quantity::all();
        let mut worst = Worst::new(quantities[0]);
        worst.record(1.0, 1.0, case(10.0));
        assert_eq!((worst.error, worst.case), (0.0, Some(case(10.0))));
        worst.record(1.02, 1.0, case(20.0));
        worst.record(1.01, 1.0, case(30.0));
        assert_eq!(worst.cases, 3);
        assert_eq!(worst.case, Some(case(20.0)));
        assert!(worst.passes(0.03) && !worst.passes(0.01));
        let mut broken = Worst::new(quantities[2]);
        let plate = Inputs::paper(ModelKind::Plate).validate().unwrap();
        broken.record(f64::NAN, 1.0, Case(plate));
        assert!(!broken.passes(1.0));
        let results = [worst, broken];
        assert_eq!(failures(&results, 0.03), 1);
        assert_eq!(failures(&results, 0.01), 2);
    }

    /// Every problem that can be cross-checked compares at least one quantity, each with its
    /// unit, and its quick grid is not empty.
    #[test]
    fn every_quantity_has_its_unit_and_every_grid_cases() {
        let quantities = Quantity::all();
        assert!(quantities.len() >= 2 * ModelKind::ALL.len());
        for q in quantities {
            assert!(q.label().ends_with(')'), "{q:?}");
        }
        for kind in ModelKind::ALL {
            let check = kind.problem().faces().cross_checked.unwrap();
            assert!(!check.grid(false).is_empty(), "{kind}");
        }
    }
}
