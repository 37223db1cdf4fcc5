//! After every change: the load axes, the chart (with its pins and FE points), the K_T table,
//! the y-axis mode, and the plate's continuum asked of a worker.

use super::{App, PinnedChart};
use crate::chart::view::AnyChart;
use crate::chart::{self, NumericPoints, Plot, YMode, pins};
use crate::fit::Measurement;
use crate::problems::inputs::Inputs;
use crate::problems::inputs::Model;
use crate::problems::{ModelKind, Param};
use crate::report::number;
use crate::tui::effects::Effect;
use crate::tui::workers::Lane;

/// The legend's word for the overlay (`n`) while its points are solved on a worker: the screen
/// says they are coming rather than showing those of other values as these.
use crate::tui::kt_table;
use crate::tui::summary::SummaryLine;
use crate::tui::view;

impl App {
    /// The load axis of each problem's charts that run along its load: 3 times its regime scale
    /// (3 F_thre for the beams); none for a problem without a load.
    pub(super) fn fit_axes(&mut self) {
        for kind in ModelKind::ALL {
            let span = kind.description().load_span;
            self.force_span[kind] = self.regime_scale_of(kind).map(|s| span * s);
        }
    }

    /// `kind`'s regime scale at its current values (F_thre for the beams), where it has one.
    pub(super) fn regime_scale_of(&self, kind: ModelKind) -> Option<f64> {
        self.states[kind].inputs.validate().ok()?.regime_scale()
    }

    /// What the regime pane shows of its own continuum solution (the plate's), where its
    /// problem's face has one ([`PaneFace::PANE_CONTINUUM`]).
    ///
    /// [`PaneFace::PANE_CONTINUUM`]: crate::chart::panes::PaneFace::PANE_CONTINUUM
    pub fn continuum(&self) -> crate::tui::summary::ContinuumState {
        use crate::tui::summary::ContinuumState;
        let current = match self.model() {
            Some(model) if self.solve_continuum && self.has_pane_continuum(&model) => {
                model.inputs()
            }
            Some(_) | None => return ContinuumState::Off,
        };
        match &self.continuum {
            Some((inputs, Some(Ok(solved)))) if *inputs == current => {
                ContinuumState::Solved(*solved)
            }
            Some((inputs, Some(Err(e)))) if *inputs == current => ContinuumState::Failed(e.clone()),
            _ => ContinuumState::Solving,
        }
    }

    /// True where the regime pane of `model`'s problem solves a continuum of its own.
    fn has_pane_continuum(&self, model: &Model) -> bool {
        crate::report::face::faces(model.kind())
            .pane
            .has_pane_continuum()
    }

    /// The lines of the regime pane.
    pub fn summary_lines(&self) -> Vec<SummaryLine> {
        self.view
            .regime
            .as_ref()
            .map_or_else(Vec::new, |r| r.lines.clone())
    }

    /// The lines `i` walks through: the regime pane's title where it states an envelope, then
    /// its lines.
    pub fn explained_lines(&self) -> Vec<SummaryLine> {
        self.view
            .regime
            .as_ref()
            .map_or_else(Vec::new, |r| r.explained().cloned().collect())
    }

    /// Rebuilds what the screen shows of the state, but the chart ([`App::recompute`] builds
    /// it): the parameter rows, the regime pane and its strip, the status line's names. Run
    /// after every action and outcome, so that it is never stale; it costs closed forms only.
    pub(super) fn refresh_view(&mut self) {
        let state = self.state();
        let (title, rows) = view::parameters(self.kind, &state.inputs, &state.preset.inputs);
        let regime = self
            .model()
            .map(|m| view::regime(&m, &self.continuum(), &crate::tui::ui::strip_cells()));
        let (name, position, count) = self.views.describe(self.kind);
        let chart_title = match self.varied() {
            Some(param) => format!("vs {param} (v or c: back to {name})"),
            None => format!("{name} ({position}/{count}, c cycles)"),
        };
        let target_quantities = crate::study::target::Quantity::names(self.kind);
        let preset = self.state().preset.name.clone();
        let modified = self.modified();
        let view = &mut self.view;
        view.parameters_title = title;
        view.rows = rows;
        view.regime = regime;
        view.chart.title = chart_title;
        view.kind = self.kind.to_string();
        view.preset = preset;
        view.modified = modified;
        view.target_quantities = target_quantities.to_string();
    }

    /// Asks for the regime pane's continuum (the plate's) at the current values when it is
    /// shown and not asked yet.
    pub(super) fn ask_continuum(&mut self) {
        let Some(model) = self.model().filter(|m| self.has_pane_continuum(m)) else {
            return;
        };
        let inputs = model.inputs();
        if !self.solve_continuum || self.continuum.as_ref().is_some_and(|(p, _)| *p == inputs) {
            return;
        }
        self.continuum = Some((inputs, None));
        self.asked.push(Effect::SolveContinuum { inputs });
    }

    /// A problem's load axis (the beams' F), kept while values change so that the curves can be
    /// compared, is fitted again (`load_span` times the regime scale: 3 F_thre, 1 F_gross) when
    /// the regime scale leaves it or is squeezed into its first twelfth (a geometry, mu or P
    /// changed by a large factor); the status says so for the problem shown. K_T does not move F_thre: dragging it never rescales.
    pub(super) fn follow_threshold(&mut self) {
        for kind in ModelKind::ALL {
            let (Some(span), Some(threshold)) = (self.force_span[kind], self.regime_scale_of(kind))
            else {
                continue;
            };
            if threshold <= span && threshold >= span / 12.0 {
                continue;
            }
            let wanted = kind.description().load_span * threshold;
            self.force_span[kind] = Some(wanted);
            let load = kind.description().load;
            let unit = load.map(Param::unit_suffix).unwrap_or_default();
            let note = format!(
                "{} axis rescaled to 0-{}{unit}: {} = {}{unit} {} the old 0-{}{unit}",
                load.map_or("", |p| p.name()),
                number(wanted),
                kind.description().regime_scale_name,
                number(threshold),
                if threshold > span {
                    "is beyond"
                } else {
                    "was squeezed into the start of"
                },
                number(span)
            );
            if self.kind == kind {
                self.axis_note = Some(note);
            }
        }
    }

    /// After any change: follows the load axis, asks for the continuum and the overlay at the
    /// new values, and rebuilds the chart, at once or, once [`App::defer_charts`] was called,
    /// at the next [`App::settle`].
    pub(super) fn recompute(&mut self) {
        self.follow_threshold();
        self.ask_continuum();
        if self.model().is_none() {
            return;
        }
        self.ask_overlay();
        if self.charts_deferred {
            self.chart_stale = true;
        } else {
            self.build_chart();
        }
    }

    /// From now on, changes leave the chart to be rebuilt once by [`App::settle`] rather than
    /// after each: the event loop applies a batch of keys (a held arrow key queues hundreds),
    /// then settles and draws once, so a storm of keys costs one chart per frame, not one per
    /// key (about 4 ms each for the lap joint in a debug build).
    pub fn defer_charts(&mut self) {
        self.charts_deferred = true;
    }

    /// Rebuilds the chart if a change since the last build left it stale; the event loop calls it
    /// before drawing, and everything that reads the chart (the export) before reading it.
    pub fn settle(&mut self) {
        if std::mem::take(&mut self.chart_stale) {
            self.build_chart();
        }
    }

    /// Builds the chart shown (with its pins and the overlay's points), or the K_T table.
    fn build_chart(&mut self) {
        let Some(model) = self.model() else { return };
        let y_mode = self.y_mode();
        let Some(plot) = self.linear_plot(&model) else {
            // The view is the K_T table: text in the chart pane.
            self.view.chart.table = Some(kt_table::stiffness_table(&model));
            self.view.chart.plot = Plot::default();
            return;
        };
        self.view.chart.table = None;
        let mut plot = y_mode.apply(plot);
        if let Some((_, chart, true)) = self.overlay {
            // Said where the points will be, rather than showing those of other values as these.
            plot.series.push(chart::PlotSeries {
                name: format!("{}: solving... (Esc cancels)", chart.numeric_name()),
                points: Vec::new(),
                role: chart::SeriesRole::FiniteElements,
            });
        }
        if self.state().pins.is_empty() {
            self.view.chart.plot = plot;
            return;
        }
        // Each pin: the same chart at its values, in the same y mode, without the overlays, over
        // the shown chart's x range (the current F or measured points may have widened it beyond
        // the kept force span: a pin built over that span alone would stop short of the axis).
        let span = Some(plot.x.bounds[1]);
        let key = PinnedChart {
            views: self.views,
            varied: self.state().varied,
            force_span: span,
            y_mode,
        };
        for i in 0..self.state().pins.len() {
            let pin = &self.state().pins[i];
            if pin.chart.as_ref().is_some_and(|(k, _)| *k == key) {
                continue;
            }
            let built = pin
                .inputs
                .validate()
                .ok()
                .and_then(|m| self.chart_of(&m, None, None, None, span))
                .map(|plot| (key, y_mode.apply(plot)));
            self.state_mut().pins[i].chart = built;
        }
        let current = self.inputs();
        let pinned: Vec<(u8, String, &Plot)> = self
            .state()
            .pins
            .iter()
            .filter_map(|pin| {
                let (_, plot) = pin.chart.as_ref()?;
                Some((pin.number, pins::label(&pin.inputs, &current), plot))
            })
            .collect();
        self.view.chart.plot = pins::add_pins(plot, &pinned);
    }
    /// Asks for the finite-element overlay of the chart shown, at the values shown, when `n` is on
    /// and it was not asked for yet ([`Effect::SolveOverlay`], on a worker: seconds for the lap
    /// joint); until it comes, no points show. With `n` off, a pending solve is cancelled.
    fn ask_overlay(&mut self) {
        let wanted = match (self.show_numeric, self.views.of(self.kind).chart()) {
            (true, Some(shown)) => Some((self.inputs(), shown)),
            _ => None,
        };
        let asked = self.overlay.map(|(inputs, chart, _)| (inputs, chart));
        if wanted == asked {
            return;
        }
        self.numeric = None;
        if self.overlay.is_some_and(|(.., pending)| pending) && wanted.is_none() {
            self.asked.push(Effect::Cancel {
                lane: Lane::Overlay,
            });
        }
        self.overlay = wanted.map(|(inputs, chart)| (inputs, chart, true));
        if let Some((inputs, chart)) = wanted {
            self.asked.push(Effect::SolveOverlay { inputs, chart });
        }
    }

    /// The overlay's answer: adopted if it is for the values and chart shown, dropped otherwise.
    pub(super) fn overlay_solved(
        &mut self,
        inputs: Inputs,
        chart: AnyChart,
        result: Result<Option<NumericPoints>, String>,
    ) {
        if self.overlay != Some((inputs, chart, true)) {
            return;
        }
        self.overlay = Some((inputs, chart, false));
        match result {
            Ok(points) => self.numeric = points,
            Err(e) => {
                self.numeric = None;
                self.error(format!("{} failed: {e}", chart.numeric_name()));
            }
        }
        self.recompute();
        if std::mem::take(&mut self.overlay_toggled) {
            self.explain_overlay();
        }
    }

    /// Esc while the overlay is being solved: stops the solve and turns `n` off; false when no
    /// solve was pending.
    pub(super) fn cancel_overlay(&mut self) -> bool {
        let Some((_, chart, true)) = self.overlay else {
            return false;
        };
        self.show_numeric = false;
        self.overlay_toggled = false;
        self.recompute();
        self.info(format!(
            "{} cancelled; n solves them again",
            chart.numeric_name()
        ));
        true
    }

    /// What `n` says once its points are in: none for this chart, or where they have gaps.
    pub(super) fn explain_overlay(&mut self) {
        if self.show_numeric && self.numeric.is_none() && self.message.is_none() {
            self.info("no finite-element points for this chart (D vs F_a, P_r/P, X_r vs mu and the table have none)");
        }
        // The legend says where the first gap is; the status says why.
        if let Some(words) = self
            .numeric
            .as_ref()
            .filter(|_| self.show_numeric)
            .and_then(NumericPoints::failure_words)
        {
            let name = self
                .overlay
                .map_or("finite elements", |(_, c, _)| c.numeric_name());
            self.info(format!("{name}: {words}"));
        }
    }

    /// The chart shown, with its y axis linear; None where the view is a table.
    pub(super) fn linear_plot(&self, model: &Model) -> Option<Plot> {
        let measured = self
            .measurements
            .as_ref()
            .filter(|_| self.measured_kind == model.kind())
            .map(|m| m.points.as_slice());
        let external = self.external.as_ref().map(|(points, _)| points);
        self.chart_of(
            model,
            self.numeric.as_ref(),
            measured,
            external,
            self.force_span[model.kind()],
        )
    }

    /// The chart shown (the view's, or the one against the parameter of `v`) for `model`; None
    /// where the view is a table (the v chart takes its place too).
    pub(super) fn chart_of(
        &self,
        model: &Model,
        numeric: Option<&NumericPoints>,
        measured: Option<&[Measurement]>,
        external: Option<&chart::ExternalPoints>,
        force_span: Option<f64>,
    ) -> Option<Plot> {
        if let Some(param) = self.state().varied {
            return Some(chart::vary::build(model, param));
        }
        let shown = self.views.of(model.kind()).chart()?;
        Some(chart::build(
            model, shown, numeric, measured, external, force_span,
        ))
    }

    /// Which chart the y-axis mode belongs to: the view's chart, None for the chart of `v`;
    /// tables have none (outer None).
    pub(super) fn y_key(&self) -> Option<Option<AnyChart>> {
        if self.varied().is_some() {
            return Some(None);
        }
        self.views.of(self.kind).chart().map(Some)
    }

    /// The y-axis mode of the chart shown.
    pub fn y_mode(&self) -> YMode {
        let Some(key) = self.y_key() else {
            return YMode::Linear;
        };
        self.y_modes
            .iter()
            .find(|(k, _)| *k == key)
            .map_or_else(|| key.map_or(YMode::Linear, YMode::default_for), |m| m.1)
    }

    /// `y`: the next y-axis mode the chart can show.
    pub(super) fn cycle_y_axis(&mut self) {
        let (Some(key), Some(model)) = (self.y_key(), self.model()) else {
            return self.error("y: a table has no y axis");
        };
        let Some(plot) = self.linear_plot(&model) else {
            return self.error("y: a table has no y axis");
        };
        let current = self.y_mode();
        let next = current.next_for(&plot);
        if next == current {
            return self.info(format!("y axis: only {} for this chart", current.label()));
        }
        self.y_modes.retain(|(k, _)| *k != key);
        self.y_modes.push((key, next));
        self.recompute();
        self.info(format!("y axis: {} (y: next mode)", next.label()));
    }
}
