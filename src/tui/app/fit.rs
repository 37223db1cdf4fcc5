//! `f`: the fit of mu and K_T to the measurements, on a worker, and its result adopted; the same
//! for every load-driven problem (the twin beams' w(L), the lap joint's Delta against F).

use super::{App, Mode};

use crate::fit::Structure;
use crate::problems::inputs::Model;
use crate::report::{number, number_with};
use crate::tui::effects::Effect;

/// What `f` fits for `model`: its structure (all but mu and K_T) when it has a load-response
/// curve to fit ([`Structure::of`] says which problems have one).
pub(super) fn fit_structure(model: &Model) -> Option<Structure> {
    Structure::of(model)
}

impl App {
    /// `f`: asks to fit mu and K_T of the problem shown to its measured curve ([`Effect::Fit`]),
    /// in [`Mode::Fitting`] until the result comes (or Esc cancels).
    pub(super) fn fit(&mut self) {
        let Some(model) = self.model() else {
            return self.error("the parameters are not valid: nothing to fit");
        };
        let Some(structure) = fit_structure(&model) else {
            // The problems with a curve to fit, from the registry.
            let fittable: Vec<&str> = crate::problems::ModelKind::ALL
                .into_iter()
                .filter(|k| k.problem().faces().fittable.is_some())
                .map(|k| k.description().title)
                .collect();
            return self.error(format!(
                "the {} has no measured curve to fit; these have: {} (press m)",
                self.kind.description().title,
                fittable.join(", ")
            ));
        };
        let measurements = self
            .measurements
            .as_ref()
            .filter(|_| self.measured_kind == self.kind);
        let Some(measurements) = measurements else {
            return self.error(format!(
                "no measurements: press d to load a CSV with columns {},{}",
                structure.load_column(),
                structure.response_column()
            ));
        };
        self.jobs += 1;
        self.asked.push(Effect::Fit {
            job: self.jobs,
            structure,
            points: measurements.points.clone(),
        });
        self.mode = Mode::Fitting { job: self.jobs };
    }

    /// A fit's result: adopts each estimate the data determine (identified or weakly) and says
    /// what it did.
    pub(super) fn fitted(&mut self, fitted: Result<crate::fit::FitResult, crate::fit::FitError>) {
        match fitted {
            Ok(result) => {
                let mut inputs = self.state().inputs;
                let mut text = Vec::new();
                for (key, estimate) in [("mu", &result.mu), ("KT", &result.kt)] {
                    let Ok(param) = self.kind.param(key) else {
                        continue;
                    };
                    let error = estimate
                        .std_error
                        .map_or(String::new(), |e| format!(" +- {}", number_with(e, 2)));
                    // With its unit, as every number on screen (K_T in MPa/mm; mu has none).
                    text.push(format!(
                        "{param} = {}{error}{} ({})",
                        number(estimate.value),
                        param.unit_suffix(),
                        estimate.status.label()
                    ));
                    if matches!(
                        estimate.status,
                        crate::fit::Status::Identified | crate::fit::Status::Weak
                    ) {
                        let _ = inputs.set(param, estimate.value);
                    }
                }
                if inputs.validate().is_ok() {
                    self.state_mut().inputs = inputs;
                }
                self.recompute();
                self.info(format!(
                    "fit: {}; RMS {} mm",
                    text.join(", "),
                    number_with(result.rms, 3)
                ));
            }
            Err(e) => self.error(format!("fit failed: {e}")),
        }
    }
}
