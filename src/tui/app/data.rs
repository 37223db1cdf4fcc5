//! Loading (`d`) and dropping (`D`) measurements and FE results.

use super::fit::fit_structure;
use super::{App, Measurements, Mode};
use crate::chart;
use crate::chart::panes::FeRead;
use crate::fit::Measurement;
use crate::problems::ModelKind;
use crate::report::face::faces;
use crate::tui::effects::Effect;
use crate::tui::views::View;

impl App {
    /// Asks to read what `d` names: a CalculiX `.dat` (FE results, of the model its deck is), a
    /// plate CSV `KT_MPa_per_mm,u_mm` on the plate (FE results), else the measured load-response
    /// curve of a load-driven problem for the fit (`F_N,w_mm` for the beams, `F_N,Delta_mm` for
    /// the lap joint, as `microslip fit` takes them). The file is read on a worker, in
    /// [`Mode::Loading`] until it is in.
    pub(super) fn load_data(&mut self, path: String) {
        let is_dat = std::path::Path::new(&path)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("dat"));
        // A CSV is a measured curve to fit where the problem has one (a load: a fit structure).
        let measurements = !is_dat && self.model().is_some_and(|m| fit_structure(&m).is_some());
        self.info(format!("loading {path}... (Esc cancels)"));
        self.mode = Mode::Loading { path: path.clone() };
        self.asked.push(if !measurements {
            Effect::ReadFeResults {
                path,
                kind: self.kind,
            }
        } else {
            Effect::ReadMeasurements {
                path,
                kind: self.kind,
            }
        });
    }

    /// Measurements read for the fit; problems go to the status line and keep the previous data.
    pub(super) fn measurements_read(
        &mut self,
        path: String,
        kind: ModelKind,
        result: Result<Vec<Measurement>, String>,
    ) {
        match result {
            Ok(points) => {
                self.info(format!(
                    "loaded {} from {path}; f fits mu and K_T",
                    crate::report::count_of(points.len(), "measurement")
                ));
                self.measurements = Some(Measurements { path, points });
                self.measured_kind = kind;
            }
            Err(reason) => self.error(format!("{path}: {reason}")),
        }
    }

    /// FE results: shown on the w(L) or u(L) chart, labelled with the code's name; a deck's
    /// parameters become the model's (the points mean nothing against others), and the status line
    /// gives the comparison `microslip compare` prints.
    pub(super) fn fe_results_read(&mut self, path: &str, loaded: &crate::fe::load::AnyLoaded) {
        let FeRead {
            kind: model,
            origin,
            points,
            code,
        } = faces(loaded.kind()).pane.fe_read(loaded);
        // Measurements were taken on the values the deck now replaces: they go (the help's rule).
        let mut dropped = String::new();
        if let Some(inputs) = origin {
            self.kind = model;
            self.state_mut().inputs = inputs;
            if let Some(m) = self.measurements.take() {
                dropped = format!(
                    "; dropped {} ({}): they were for the previous values",
                    crate::report::count_of(m.points.len(), "measurement"),
                    m.path
                );
            }
        }
        // Runs of one curve (the plate's, of one deck but for K_T) add up; anything else
        // (a CSV's points, a run of the beams) replaces.
        let mut points: Vec<(f64, f64)> = points;
        if let Some((previous, Some(previous_origin))) = &self.external
            && let Some(origin) = &origin
            && previous.model == model
            && faces(model).pane.same_curve(previous_origin, origin)
        {
            points.extend(previous.points.iter().copied());
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            points.dedup_by(|a, b| a.0 == b.0);
        }
        let Some(current) = self.model() else {
            return self.error(format!("{path}: the deck's parameters are not valid"));
        };
        let summary = match faces(model).pane.fe_brief(loaded, &current, code) {
            Some(Ok(summary)) => summary,
            Some(Err(e)) => return self.error(format!("{path}: {e}")),
            None => format!("{path}: FE results of another problem: press m"),
        };
        let adopted = if origin.is_some() {
            " (deck parameters adopted)"
        } else {
            ""
        };
        self.info(format!("{path}{adopted}: {summary}{dropped}"));
        self.external = Some((
            chart::ExternalPoints {
                label: code.to_string(),
                model,
                points,
            },
            origin,
        ));
        // The external points are of the problem's response: its first chart.
        self.views = self.views.with(model, View::first(model));
    }

    /// Forgets the measurements and FE results; says what went, as `25 measurements and the
    /// CalculiX points` (empty when nothing was loaded).
    pub(super) fn forget_data(&mut self) -> String {
        let measured = self.measurements.take().map(|m| {
            format!(
                "{} ({})",
                crate::report::count_of(m.points.len(), "measurement"),
                m.path
            )
        });
        let external = self
            .external
            .take()
            .map(|(points, _)| format!("the {} points", points.label));
        [measured, external]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join(" and ")
    }

    /// `D`: drops the loaded measurements and FE results.
    pub(super) fn drop_data(&mut self) {
        let dropped = self.forget_data();
        if dropped.is_empty() {
            return self.info("no loaded data to drop (d loads measurements or FE results)");
        }
        self.recompute();
        self.info(format!("dropped {dropped}; d loads again"));
    }
}
