//! THROW-AWAY (s-deck): minimal faces so that the app compiles until the lead's faces land.
#![allow(missing_docs, clippy::all)]

use serde::Serialize;

use super::point::FitPoint;
use super::registered::problem::{PressFitModel, PressFitProblem};
use crate::chart::view::{ChartFace, ChartSet};
use crate::chart::{NumericPoints, Plot};
use crate::kernel::regime::Regime;
use crate::numeric::{MeshDensity, NumericError};
use crate::problems::Param;
use crate::report::face::{KtColumn, ReportFace};
use crate::study::curves::Answer;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ScaffoldChart {
    Delta,
}

impl ChartSet for ScaffoldChart {
    const ALL: &'static [Self] = &[ScaffoldChart::Delta];
    fn title(self) -> &'static str {
        "Delta vs F"
    }
    fn key(self) -> &'static str {
        "delta"
    }
    fn x_param(self) -> Option<Param> {
        None
    }
    fn load_axis(self) -> bool {
        true
    }
    fn spans_decades(self) -> bool {
        false
    }
}

impl ChartFace for PressFitProblem {
    type Chart = ScaffoldChart;
    fn plot(_: &PressFitModel, _: ScaffoldChart, _: f64, _: Option<f64>) -> Option<Plot> {
        None
    }
    fn numeric_points(
        _: &PressFitModel,
        _: ScaffoldChart,
        _: MeshDensity,
    ) -> Result<Option<NumericPoints>, NumericError> {
        Ok(None)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ScaffoldRow {
    pub f: f64,
}

impl From<&FitPoint> for ScaffoldRow {
    fn from(_: &FitPoint) -> Self {
        ScaffoldRow::default()
    }
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct ScaffoldKt;

#[derive(Debug, Clone, Copy, Serialize)]
pub struct ScaffoldReport;

impl ReportFace for PressFitProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(S8)";
    const KT_TITLE: &'static str = "press fit";
    const KT_COLUMNS: &'static [KtColumn] = &[KtColumn::VsCurrent];
    const KT_REGIME_WIDTH: usize = 20;
    type KtAnswer = ScaffoldKt;
    type PointReport = ScaffoldReport;
    type SweepRow = ScaffoldRow;
    fn point_report(_: &str, _: &PressFitModel, _: bool) -> Result<ScaffoldReport, NumericError> {
        Ok(ScaffoldReport)
    }
    fn point_text(_: &ScaffoldReport) -> String {
        String::new()
    }
    fn kt_answer(_: &Answer) -> Option<ScaffoldKt> {
        None
    }
    fn kt_values(_: &ScaffoldKt) -> (Vec<f64>, Regime) {
        (Vec::new(), Regime::MICROSLIP)
    }
}

#[cfg(feature = "app")]
mod pane {
    use super::super::registered::problem::{PressFitModel, PressFitProblem};
    use crate::chart::panes::{ContinuumState, PaneFace, SummaryLine};
    impl PaneFace for PressFitProblem {
        const STRIP_ORIGIN: &'static str = "loaded face";
        const KT_COLUMNS: &'static [(&'static str, usize)] = &[];
        fn parameters_title(_: &Self::Params) -> String {
            "press fit".into()
        }
        fn summary_lines(_: &PressFitModel, _: &ContinuumState) -> Vec<SummaryLine> {
            Vec::new()
        }
        fn kt_values(_: &PressFitModel, _: f64) -> Option<Vec<f64>> {
            None
        }
        fn kt_tolerance_lines(_: &PressFitModel, _: &str, _: f64) -> Vec<String> {
            Vec::new()
        }
        fn fe_xy(point: &super::super::ccx_read::PressFitFePoint) -> (f64, f64) {
            (point.force, point.delta)
        }
        fn fe_brief(
            model: &PressFitModel,
            loaded: &crate::fe::load::Loaded<super::super::ccx_read::PressFitFePoint>,
            code: &str,
        ) -> Result<String, String> {
            super::super::compare::fit_brief(&model.fit, &loaded.points, code)
        }
    }
}
