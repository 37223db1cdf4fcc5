//! TEMPORARY (not to land): the deck and comparison faces, until the branch that writes them is
//! merged; only so that the other faces compile and can be tried.
#![allow(missing_docs, clippy::all)]

use super::registered::problem::{PressFitInputs, PressFitModel, PressFitProblem};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::DeckHeader;
use crate::fe::load::Loaded;
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::params::ParamError;
use crate::report::compare::{CompareFace, verdict};

#[derive(Debug, Clone, PartialEq)]
pub struct FitFePoint {
    pub force: f64,
    pub delta: f64,
}

impl Deck for PressFitProblem {
    const SOURCE: &'static str = " (docs/theory.md section 18)";
    const INTERFACE_SET: &'static str = "NFIT";
    type FePoint = FitFePoint;
    type Compared = Vec<f64>;

    fn expected(_model: &PressFitModel, _header: &DeckHeader) -> String {
        "** Expected".to_string()
    }

    fn ccx_points(
        _run: &CcxRun,
        _params: &PressFitInputs,
    ) -> Result<Vec<FitFePoint>, ResultsError> {
        unimplemented!()
    }

    const CSV_CURVE: crate::measured::Curve = crate::measured::Curve {
        min_rows: 1,
        ..crate::measured::MEASURED_JOINT_DISPLACEMENT
    };

    fn csv_points(_text: &str) -> Result<Vec<FitFePoint>, ResultsError> {
        unimplemented!()
    }

    fn compare(_m: &PressFitModel, _p: &[FitFePoint], _mesh: Option<&InterfaceMesh>) -> Vec<f64> {
        Vec::new()
    }

    fn write_deck(_model: &PressFitModel, _request: &DeckRequest) -> Result<String, DeckError> {
        unimplemented!()
    }

    fn without_envelope(_compared: &mut Vec<f64>) {}
}

#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct Row;

#[derive(Debug, Clone, serde::Serialize)]
pub struct Report {
    pub summary: verdict::Summary,
}

impl CompareFace for PressFitProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<f64>;
    type CompareRow = Row;
    type CompareReport = Report;

    fn checked(compared: Vec<f64>) -> Result<Vec<f64>, ParamError> {
        Ok(compared)
    }

    fn compare_report(_s: &str, _f: Vec<f64>, _m: Vec<Vec<f64>>) -> (Report, Vec<Row>) {
        unimplemented!()
    }

    fn compare_text(_report: &Report) -> String {
        String::new()
    }

    fn summary_mut(report: &mut Report) -> &mut verdict::Summary {
        &mut report.summary
    }
}

pub(crate) fn pane_xy(point: &FitFePoint) -> (f64, f64) {
    (point.force, point.delta)
}

pub(crate) fn pane_brief(
    _model: &PressFitModel,
    _loaded: &Loaded<FitFePoint>,
    code: &str,
) -> Result<String, String> {
    Ok(code.to_string())
}
