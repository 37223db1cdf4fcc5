//! The charts of every problem, with what the generic layers need to know of each (its key,
//! title, x parameter, load axis, default y scale): `plot`, `figures`, families and the TUI
//! name them the same way. A chart is never an index. Which one the TUI shows, and the table it
//! can show instead, are the TUI's (`tui/views.rs`).
//!
//! Each problem's charts are its own: an enum in its face folder (`src/problems/<name>/chart.rs`)
//! implementing [`ChartSet`], drawn by its [`ChartFace`] impl. [`AnyChart`], a chart of any
//! problem, is generated from the registry ([`microslip_core::with_problems!`]), so that this
//! layer names no problem and a new one adds its charts without an edit here.

use std::fmt::Debug;
use std::hash::Hash;

use crate::chart::{NumericPoints, Plot};
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::{ModelKind, Param, Problem};

/// The charts of one problem.
pub trait ChartSet: Debug + Copy + Eq + Hash + Send + Sync + 'static {
    /// Every chart, in cycling order. The first is the chart of the problem's response against
    /// its load or stiffness (w(L) vs F, u(L) vs K_T, Delta vs F): the TUI opens on it and shows
    /// measured and external points on it.
    const ALL: &'static [Self];
    /// The short title of the chart.
    fn title(self) -> &'static str;
    /// The chart's name on the command line and in file names (`w-vs-f`), unique over every
    /// problem.
    fn key(self) -> &'static str;
    /// The parameter the chart runs along its x axis (F, K_T, mu), whose value a caption need
    /// not give; None where the x axis is no parameter (tau(x), the loop, P_r(x), D vs F_a).
    fn x_param(self) -> Option<Param>;
    /// True where the x axis is the problem's load (F, or the amplitude F_a), which a family of
    /// curves widens to the span its widest member needs.
    fn load_axis(self) -> bool;
    /// True where the chart's quantity spans decades: it opens on a log y axis.
    fn spans_decades(self) -> bool;
}

/// How a problem is charted: its charts and how each is drawn from its model. Implemented in
/// each problem's face folder (`src/problems/<name>/chart.rs`), so that the chart layer holds
/// the generic parts (overlays, finite-element legends, y modes, pins, families) once and no
/// `match` on the problem.
pub trait ChartFace: Problem {
    /// The problem's charts.
    type Chart: ChartSet;

    /// The legend's name of the points [`ChartFace::numeric_points`] gives: what the
    /// problem's discretized solver is (`finite elements` unless it is something else).
    const NUMERIC_NAME: &'static str = "finite elements";

    /// The chart `chart` of `model`, without overlays; `f_data`: the largest force of the points
    /// overlaid on it (a force axis may widen to show them), `span`: the force span a family of
    /// curves asks for. None where a curve cannot be sampled (every range is checked, so this is
    /// a guard).
    fn plot(
        model: &Self::Model,
        chart: Self::Chart,
        f_data: f64,
        span: Option<f64>,
    ) -> Option<Plot>;

    /// The project's finite-element points (and the 2-D continuum's, where the problem has one)
    /// for `chart` on `density`; None where the chart has no discretized counterpart.
    ///
    /// # Errors
    /// The discretized solver's, where no point of the chart could be solved.
    fn numeric_points(
        model: &Self::Model,
        chart: Self::Chart,
        density: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError>;

    /// An external code's point `(x, y)` of the response (as read: load or stiffness, response)
    /// placed on the axes of the first chart (the plate's runs along log10 K_T).
    fn external_point(point: (f64, f64)) -> (f64, f64) {
        point
    }

    /// A setting of `params` that is no number, as its name and the short label of its value
    /// (the beams' theory: `("theory", "EB")`), which a pin's label names when it differs; None
    /// where the problem has none.
    fn setting_label(params: &Self::Params) -> Option<(&'static str, &'static str)> {
        let _ = params;
        None
    }
}

/// Writes [`AnyChart`] and its dispatch from the registry.
macro_rules! any_chart {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// A chart of any problem, as `microslip plot CHART` names it: one variant per problem
        /// of the registry, holding one of its [`ChartFace::Chart`]s.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum AnyChart {
            $($(#[$doc])* $variant(<crate::problems::$folder::$problem as ChartFace>::Chart)),+
        }

        /// How many charts the problems have together.
        const CHART_COUNT: usize =
            0 $(+ <<crate::problems::$folder::$problem as ChartFace>::Chart as ChartSet>::ALL.len())+;

        /// Every chart, the problems in registry order, each one's in its cycling order.
        const EVERY_CHART: [AnyChart; CHART_COUNT] = {
            let first = [$(AnyChart::$variant(
                <<crate::problems::$folder::$problem as ChartFace>::Chart as ChartSet>::ALL[0]
            )),+][0];
            let mut all = [first; CHART_COUNT];
            let mut i = 0;
            $(
                let charts =
                    <<crate::problems::$folder::$problem as ChartFace>::Chart as ChartSet>::ALL;
                let mut j = 0;
                while j < charts.len() {
                    all[i] = AnyChart::$variant(charts[j]);
                    i += 1;
                    j += 1;
                }
            )+
            let _ = i;
            all
        };

        impl AnyChart {
            /// The model the chart is of.
            pub fn kind(self) -> ModelKind {
                match self {
                    $(AnyChart::$variant(_) => ModelKind::$variant),+
                }
            }

            /// The parameter the chart runs along its x axis (F, K_T, mu), whose value a caption
            /// need not give; None where the x axis is no parameter (tau(x), the loop, P_r(x)).
            pub fn x_param(self) -> Option<Param> {
                match self {
                    $(AnyChart::$variant(c) => c.x_param()),+
                }
            }

            /// See [`ChartSet::load_axis`].
            pub fn load_axis(self) -> bool {
                match self {
                    $(AnyChart::$variant(c) => c.load_axis()),+
                }
            }

            /// See [`ChartSet::spans_decades`].
            pub fn spans_decades(self) -> bool {
                match self {
                    $(AnyChart::$variant(c) => c.spans_decades()),+
                }
            }

            /// The name on the command line (unique over every problem).
            pub fn key(self) -> &'static str {
                match self {
                    $(AnyChart::$variant(c) => c.key()),+
                }
            }

            /// The short title.
            pub fn title(self) -> &'static str {
                match self {
                    $(AnyChart::$variant(c) => c.title()),+
                }
            }

            /// The chart of `model` (a model of the chart's problem), without overlays: see
            /// [`ChartFace::plot`]. None for a model of another problem.
            pub(crate) fn plot_of(
                self,
                model: &crate::problems::inputs::Model,
                f_data: f64,
                span: Option<f64>,
            ) -> Option<Plot> {
                match self {
                    $(AnyChart::$variant(c) => {
                        type P = crate::problems::$folder::$problem;
                        <P as ChartFace>::plot(&P::from_model(model)?, c, f_data, span)
                    }),+
                }
            }

            /// See [`ChartFace::numeric_points`]; `Ok(None)` for a model of another problem.
            pub(crate) fn numeric_points_of(
                self,
                model: &crate::problems::inputs::Model,
                density: MeshDensity,
            ) -> Result<Option<NumericPoints>, NumericError> {
                match self {
                    $(AnyChart::$variant(c) => {
                        type P = crate::problems::$folder::$problem;
                        match P::from_model(model) {
                            Some(model) => <P as ChartFace>::numeric_points(&model, c, density),
                            None => Ok(None),
                        }
                    }),+
                }
            }

            /// True where the chart is its problem's first, the response's (see
            /// [`ChartSet::ALL`]), on which measured and external points show.
            pub(crate) fn is_response(self) -> bool {
                match self {
                    $(AnyChart::$variant(c) => {
                        <<crate::problems::$folder::$problem as ChartFace>::Chart as ChartSet>::ALL
                            .first() == Some(&c)
                    }),+
                }
            }

            /// True where the chart's problem is driven by a load: measurements (a force and a
            /// response) are of such a problem.
            pub(crate) fn has_load(self) -> bool {
                match self {
                    $(AnyChart::$variant(_) =>
                        <crate::problems::$folder::$problem as Problem>::INFO.load.is_some()),+
                }
            }

            /// The legend's name of the chart's discretized points ([`ChartFace::NUMERIC_NAME`]).
            pub(crate) fn numeric_name(self) -> &'static str {
                match self {
                    $(AnyChart::$variant(_) =>
                        <crate::problems::$folder::$problem as ChartFace>::NUMERIC_NAME),+
                }
            }

            /// An external point placed on this chart's axes ([`ChartFace::external_point`]).
            pub(crate) fn external_point(self, point: (f64, f64)) -> (f64, f64) {
                match self {
                    $(AnyChart::$variant(_) =>
                        <crate::problems::$folder::$problem as ChartFace>::external_point(point)),+
                }
            }
        }

        /// The setting of `inputs` that is no number ([`ChartFace::setting_label`]): what a pin's
        /// label names.
        #[cfg(feature = "app")]
        pub(crate) fn setting_label(
            inputs: &crate::problems::inputs::Inputs,
        ) -> Option<(&'static str, &'static str)> {
            $(
                if let Some(params) =
                    <crate::problems::$folder::$problem as Problem>::from_inputs(inputs)
                {
                    return <crate::problems::$folder::$problem as ChartFace>::setting_label(&params);
                }
            )+
            None
        }
    };
}

microslip_core::with_problems!(any_chart);

impl AnyChart {
    /// Every chart: each problem's in cycling order, the problems in registry order.
    pub const ALL: &'static [AnyChart] = &EVERY_CHART;

    /// Every chart, as [`AnyChart::ALL`].
    pub fn all() -> impl Iterator<Item = AnyChart> + Clone {
        Self::ALL.iter().copied()
    }

    /// The chart named `key`, if any.
    pub fn parse(key: &str) -> Option<AnyChart> {
        Self::all().find(|c| c.key().eq_ignore_ascii_case(key))
    }

    /// Every chart of `kind`, in cycling order.
    pub fn of(kind: ModelKind) -> impl Iterator<Item = AnyChart> + Clone {
        Self::all().filter(move |c| c.kind() == kind)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every problem has charts, and its first one is its response's (the chart the TUI opens on
    /// and shows loaded external points on).
    #[test]
    fn each_problem_opens_on_the_chart_of_its_response() {
        for kind in ModelKind::ALL {
            let first = AnyChart::all().find(|c| c.kind() == kind);
            let response = crate::problems::Quantity::Response.name(kind);
            assert!(
                first.is_some_and(|c| c.title().starts_with(response)),
                "{kind}: {first:?}"
            );
        }
    }

    #[test]
    fn chart_keys_are_unique_and_parse_back() {
        let keys: Vec<&str> = AnyChart::all().map(AnyChart::key).collect();
        for (i, key) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(key), "{key} twice");
            assert_eq!(AnyChart::parse(key).map(AnyChart::key), Some(*key));
        }
        assert_eq!(AnyChart::parse("nope"), None);
        // ALL holds each model's charts in their own order.
        use crate::problems::lap::LapChart;
        use crate::problems::plate::PlateChart;
        use crate::problems::twin_beams::BeamChart;
        let beams = AnyChart::all().filter_map(|c| match c {
            AnyChart::Beam(b) => Some(b),
            _ => None,
        });
        assert!(beams.eq(BeamChart::ALL.iter().copied()));
        let plates = AnyChart::all().filter_map(|c| match c {
            AnyChart::Plate(p) => Some(p),
            _ => None,
        });
        assert!(plates.eq(PlateChart::ALL.iter().copied()));
        let laps = AnyChart::all().filter_map(|c| match c {
            AnyChart::Lap(p) => Some(p),
            _ => None,
        });
        assert!(laps.eq(LapChart::ALL.iter().copied()));
    }
}
