//! The twisted fit's FE face ([`Deck`], [`CompareFace`]): no CalculiX deck, and another code's
//! curve of theta against T read and shown beside the closed forms, not judged.
//!
//! Why no deck: the push-out's deck is axisymmetric (CAX4), and CalculiX's axisymmetric elements
//! carry no circumferential displacement, so a twist cannot be put on them; a deck of the fit in
//! 3-D solids is another model (a mesh of a sector with cyclic symmetry), not written here.
//! Why not judged: no torsional continuum calibrates the 1-D theory of the twisted fit
//! (docs/theory.md section 18, (S6)), so there is no tolerance to judge a curve against: the
//! comparison shows theta's differences from the shear lag and says "not judged", which `compare`
//! exits with as "not agreeing" (a CI cannot take it for a pass).

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::DeckHeader;
use crate::fe::results::{CcxRun, ResultsError, points_from_csv};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::params::{ParamError, Unit};
use crate::measured::Curve;
use crate::report::compare::verdict::Summary;
use crate::report::compare::{CompareFace, percent_or_na};
use crate::report::{number, sanitize};

use super::params::TORQUE;
use super::registered::problem::{PressFitInputs, PressFitModel, PressFitTorqueProblem};

/// One FE point of the twisted fit: a torque (N mm) and the twist there (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueFePoint {
    /// Torque (N mm).
    pub torque: f64,
    /// Twist theta (rad).
    pub twist: f64,
}

/// A CSV of another code's twisted fit: `T_Nmm,theta_rad`, one row at least.
const TORQUE_CURVE: Curve = Curve {
    x: "T_Nmm",
    y: "theta_rad",
    x_what: "torques",
    x_domain: TORQUE,
    x_unit: Unit::NewtonMillimetre,
    min_rows: 1,
};

/// One FE point beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueCompared {
    /// The FE point.
    pub fe: TorqueFePoint,
    /// The shear lag's theta at the point's torque, regularized at the model's K_T, and under
    /// plain Coulomb (rad).
    pub closed: f64,
    pub coulomb: f64,
}

impl Deck for PressFitTorqueProblem {
    const SOURCE: &'static str = " (docs/theory.md section 18, (S6); CalculiX issue #98's fit)";
    const INTERFACE_SET: &'static str = "no deck";
    type FePoint = TorqueFePoint;
    type Compared = Result<Vec<TorqueCompared>, ParamError>;

    fn expected(model: &PressFitModel, header: &DeckHeader) -> String {
        let axis = model.fit.torsion();
        let mut text = format!(
            "** Expected from the closed forms (Lamé and the shear lag of two tubes, docs/theory.md \
             section 18, (S6)):\n\
             **   T_1 = {} N mm; T_2 = {} N mm; T_gross = mu p 2 pi r^2 L = {} N mm\n\
             **   T (N mm) | theta Coulomb (rad) | theta regularized (rad)\n",
            number(axis.first_slip_load()),
            number(axis.second_slip_load()),
            number(axis.gross_load()),
        );
        for &t in &header.loads {
            let load = axis.clamped(t);
            let _ = writeln!(
                text,
                "**   {} | {} | {}",
                number(t),
                number(axis.coulomb(load).response()),
                number(axis.regularized(load).response())
            );
        }
        text
    }

    fn ccx_points(
        _run: &CcxRun,
        _params: &PressFitInputs,
    ) -> Result<Vec<TorqueFePoint>, ResultsError> {
        Err(ResultsError::Missing(NO_DECK.to_string()))
    }

    fn interface_mesh(_run: &CcxRun) -> Result<Option<InterfaceMesh>, ResultsError> {
        Ok(None)
    }

    const CSV_CURVE: Curve = TORQUE_CURVE;

    fn csv_points(text: &str) -> Result<Vec<TorqueFePoint>, ResultsError> {
        points_from_csv(text, &TORQUE_CURVE, |torque, twist| TorqueFePoint {
            torque,
            twist,
        })
    }

    fn compare(
        model: &PressFitModel,
        points: &[TorqueFePoint],
        _mesh: Option<&InterfaceMesh>,
    ) -> Result<Vec<TorqueCompared>, ParamError> {
        let axis = model.fit.torsion();
        points
            .iter()
            .map(|&fe| {
                let load = axis.load(fe.torque)?;
                Ok(TorqueCompared {
                    fe,
                    closed: axis.regularized(load).response(),
                    coulomb: axis.coulomb(load).response(),
                })
            })
            .collect()
    }

    /// Nothing to take away: nothing is judged.
    fn without_envelope(_compared: &mut Result<Vec<TorqueCompared>, ParamError>) {}

    fn write_deck(_model: &PressFitModel, _request: &DeckRequest) -> Result<String, DeckError> {
        Err(DeckError::Usage(NO_DECK))
    }

    const NO_DECK: Option<&'static str> = Some(NO_DECK);
}

/// Why the twisted fit has no deck, as `deck`, `bench` and a `.dat` are refused.
const NO_DECK: &str = "the twisted press fit has no CalculiX deck: the press fit's deck is \
     axisymmetric (CAX4), whose elements carry no twist; compare another code's curve as a CSV \
     `T_Nmm,theta_rad` (microslip compare FILE.csv --preset pressfit-ccx98-torque), or deck the \
     push-out (microslip deck ccx pressfit)";

/// One row of `microslip compare` of the twisted fit.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct TorqueCompareRow {
    /// Torque (N mm).
    #[serde(rename = "T_Nmm")]
    pub torque: f64,
    /// FE twist (rad).
    #[serde(rename = "theta_fe_rad")]
    pub twist_fe: f64,
    /// Closed form, regularized law at the model's K_T (rad).
    #[serde(rename = "theta_rad")]
    pub twist: f64,
    /// Plain Coulomb (rad).
    #[serde(rename = "theta_coulomb_rad")]
    pub twist_coulomb: f64,
    /// (FE - closed form) / closed form, a fraction (shown, not judged); null at T = 0.
    pub theta_diff: Option<f64>,
}

impl From<&TorqueCompared> for TorqueCompareRow {
    fn from(r: &TorqueCompared) -> Self {
        TorqueCompareRow {
            torque: r.fe.torque,
            twist_fe: r.fe.twist,
            twist: r.closed,
            twist_coulomb: r.coulomb,
            theta_diff: crate::fe::compare::relative_difference(r.fe.twist, r.closed),
        }
    }
}

/// `microslip compare` of the twisted fit: the rows and the verdict, which is "not judged".
#[derive(Debug, Clone, Serialize)]
pub struct TorqueCompareReport {
    /// `pressfit-torque`.
    pub model: &'static str,
    /// The results compared.
    pub source: String,
    pub rows: Vec<TorqueCompareRow>,
    /// The closing verdict.
    pub verdict: Summary,
}

/// The verdict: not judged, with the differences shown.
fn not_judged(rows: &[TorqueCompareRow]) -> Summary {
    let worst = rows
        .iter()
        .filter_map(|r| r.theta_diff)
        .max_by(|a, b| a.abs().total_cmp(&b.abs()));
    Summary {
        agrees: false,
        summary: format!(
            "Verdict: not judged. theta against the 1-D shear lag {} at worst: shown, not judged \
             (no torsional continuum calibrates the twisted fit's theory, docs/theory.md section \
             18, (S6)).",
            percent_or_na(worst)
        ),
        stiffness: None,
        stiffness_z: None,
        short: "not judged: the torque's theory is not calibrated".to_string(),
    }
}

impl TorqueCompareReport {
    /// The report of `rows` compared from `source`.
    pub fn new(source: &str, compared: &[TorqueCompared]) -> TorqueCompareReport {
        let rows: Vec<TorqueCompareRow> = compared.iter().map(TorqueCompareRow::from).collect();
        TorqueCompareReport {
            model: <PressFitTorqueProblem as crate::problems::Problem>::INFO.key,
            source: source.to_string(),
            verdict: not_judged(&rows),
            rows,
        }
    }

    /// The readable comparison.
    pub fn text(&self) -> String {
        let mut out = format!(
            "Press fit twisted: {} against the closed forms (Lamé's p, shear lag of two tubes)\n\
             T in N mm; theta = the shaft's loaded end's rotation relative to the hub's held face \
             in rad.\n",
            sanitize(&self.source)
        );
        let _ = writeln!(
            out,
            "  {:>12} {:>12} {:>12} {:>9} {:>12}",
            "T", "theta FE", "shear lag", "vs 1-D", "Coulomb"
        );
        for r in &self.rows {
            let _ = writeln!(
                out,
                "  {:>12} {:>12} {:>12} {:>9} {:>12}",
                number(r.torque),
                number(r.twist_fe),
                number(r.twist),
                percent_or_na(r.theta_diff),
                number(r.twist_coulomb),
            );
        }
        let _ = writeln!(out, "{}", self.verdict.summary);
        out
    }
}

impl CompareFace for PressFitTorqueProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<TorqueCompared>;
    type CompareRow = TorqueCompareRow;
    type CompareReport = TorqueCompareReport;

    fn checked(
        compared: Result<Vec<TorqueCompared>, ParamError>,
    ) -> Result<Vec<TorqueCompared>, ParamError> {
        compared
    }

    fn compare_report(
        source: &str,
        first: Vec<TorqueCompared>,
        more: Vec<Vec<TorqueCompared>>,
    ) -> (TorqueCompareReport, Vec<TorqueCompareRow>) {
        let rows: Vec<TorqueCompared> = first
            .into_iter()
            .chain(more.into_iter().flatten())
            .collect();
        let report = TorqueCompareReport::new(source, &rows);
        let table = report.rows.clone();
        (report, table)
    }

    fn compare_text(report: &TorqueCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut TorqueCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    /// None: nothing is judged.
    fn ladder_quantities(_report: &TorqueCompareReport) -> Vec<crate::fe::ladder::LadderQuantity> {
        Vec::new()
    }
}

/// An FE point on the axes of the twisted fit's first chart: (T, theta).
#[cfg(feature = "app")]
pub(crate) fn pane_xy(point: &TorqueFePoint) -> (f64, f64) {
    (point.torque, point.twist)
}

/// The status line after the TUI loads a curve: not judged, the differences shown.
///
/// # Errors
/// A torque beyond T_gross, in words.
#[cfg(feature = "app")]
pub(crate) fn pane_brief(
    model: &PressFitModel,
    loaded: &crate::fe::load::Loaded<TorqueFePoint>,
    code: &str,
) -> Result<String, String> {
    let compared =
        PressFitTorqueProblem::compare(model, &loaded.points, None).map_err(|e| e.to_string())?;
    let report = TorqueCompareReport::new(code, &compared);
    Ok(format!("{code}: {}", report.verdict.short))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::deck::DeckMesh;
    use crate::problems::Problem;

    fn ccx98() -> PressFitModel {
        PressFitTorqueProblem::model(&PressFitTorqueProblem::paper()).unwrap()
    }

    /// No deck: `deck` is refused with why and what to do instead.
    #[test]
    fn the_deck_is_refused_with_why() {
        let request = DeckRequest {
            loads: None,
            mesh: DeckMesh::Coarse,
            slope: crate::fe::header::StickSlope::Model,
            increment: None,
        };
        let error = PressFitTorqueProblem::write_deck(&ccx98(), &request).unwrap_err();
        let text = error.to_string();
        assert!(
            text.contains("CAX4") && text.contains("T_Nmm,theta_rad"),
            "{text}"
        );
    }

    /// A curve of the closed form's own values, 2 % stiffer: read as T and theta, shown within
    /// -2 %, and not judged (so `compare` exits as not agreeing).
    #[test]
    fn a_curve_is_read_shown_and_not_judged() {
        let model = ccx98();
        let axis = model.fit.torsion();
        let mut csv = String::from("T_Nmm,theta_rad\n");
        for fraction in [0.3, 0.8] {
            let t = fraction * axis.gross_load();
            let theta = axis.regularized(axis.load(t).unwrap()).response();
            let _ = writeln!(csv, "{t},{}", 0.98 * theta);
        }
        let points = PressFitTorqueProblem::csv_points(&csv).unwrap();
        assert_eq!(points.len(), 2);
        let compared = PressFitTorqueProblem::compare(&model, &points, None).unwrap();
        let (report, rows) = PressFitTorqueProblem::compare_report("run.csv", compared, vec![]);
        for row in &rows {
            assert!((row.theta_diff.unwrap() + 0.02).abs() < 1e-12, "{row:?}");
        }
        assert!(!report.verdict.agrees);
        assert!(report.text().contains("not judged"), "{}", report.text());
        // The push-out's columns are refused: a CSV of another problem's curve.
        assert!(PressFitTorqueProblem::csv_points("F_N,Delta_mm\n1,0.001\n").is_err());
    }
}
