//! `f`: the fit of mu and K_T to the measurements, on a worker, and its result adopted.

use super::{App, Mode};
use crate::problems::inputs::Model;
use crate::problems::{BeamParam, ModelKind, Param};
use crate::report::{number, number_with};
use crate::tui::effects::Effect;

impl App {
    /// `f`: asks to fit mu and K_T of the twin beams to the measurements ([`Effect::Fit`]), in
    /// [`Mode::Fitting`] until the result comes (or Esc cancels).
    pub(super) fn fit(&mut self) {
        if self.kind == ModelKind::Lap {
            return self.error(
                "the terminal UI fits the twin beams; for the lap joint run `microslip fit lap \
                 DATA.csv` (columns F_N,Delta_mm)",
            );
        }
        let Some(measurements) = &self.measurements else {
            return self.error("no measurements: press d to load a CSV with columns F_N,w_mm");
        };
        // The fit identifies mu and K_T from a force-deflection curve: the beams'.
        let beams = match self.model() {
            Some(Model::Beam { beams, .. }) => beams,
            Some(Model::Plate(_) | Model::Lap { .. }) => {
                return self.error("fitting needs the twin-beam model: press m");
            }
            None => return self.error("the parameters are not valid: nothing to fit"),
        };
        self.jobs += 1;
        self.asked.push(Effect::Fit {
            job: self.jobs,
            structure: beams.params(),
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
                for (param, estimate) in [
                    (BeamParam::Friction, &result.mu),
                    (BeamParam::Stiffness, &result.kt),
                ] {
                    let error = estimate
                        .std_error
                        .map_or(String::new(), |e| format!(" +- {}", number_with(e, 2)));
                    text.push(format!(
                        "{param} = {}{error} ({})",
                        number(estimate.value),
                        estimate.status.label()
                    ));
                    if matches!(
                        estimate.status,
                        crate::fit::Status::Identified | crate::fit::Status::Weak
                    ) {
                        let _ = inputs.set(Param::Beam(param), estimate.value);
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
