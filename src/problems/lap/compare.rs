//! The double-lap joint's FE results against its closed forms, load step by load step: Delta
//! against the shear-lag theory, the two sliding zones in elements of the FE mesh, and the K_T
//! whose closed-form Delta equals the FE value. Then the report of it ([`TableReport`] with the
//! joint's columns, row verdicts and closing verdict) that `compare lap` and `bench` print.

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::compare::relative_difference;
use crate::fe::continuum_verdict::{ContinuumVerdict, NotSolved, judged};
use crate::fe::verdict::{Envelope, InterfaceMesh, MeshDifference};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::report::compare::continuum::Check;
use crate::report::compare::table::{CompareTable, TableReport};
use crate::report::compare::verdict::{Names, RowVerdict, Summary, tally_summary};
use crate::report::compare::{CompareFace, optional, percent_or_na};
use crate::report::{number, sanitize};

use super::closed_form::LapJoint;
use super::fe_points::LapFePoint;
use super::problem::{LapJointProblem, LapModel};

/// One FE point of the double-lap joint beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapCompared {
    /// The FE point.
    pub fe: LapFePoint,
    /// The shear-lag Delta under the regularized law at the deck's K_T (mm).
    pub closed: f64,
    /// Under the plain Coulomb law (mm).
    pub coulomb: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's sliding zones from x = 0 and from x = L (mm).
    pub zones: (f64, f64),
    /// The K_T (MPa/mm) whose closed-form Delta equals the FE value at this force; `None` where
    /// none does, or where the shear-lag theory does not hold (the difference would be the
    /// theory's, not the interface's).
    pub implied_stiffness: Option<f64>,
    /// The shear-lag theory's level at this force ((L14)).
    pub theory_validity: Validity,
    /// Its bound on Delta's difference from a continuum, a fraction; `None` where not calibrated.
    pub theory_within: Option<f64>,
    /// FE a and d against the closed form's in elements of the FE mesh (CalculiX results).
    pub zones_mesh: Option<[MeshDifference; 2]>,
    /// Delta against the plane-stress continuum at the deck's parameters and this force, where
    /// it was solved (`compare`, `bench`): the verdict, or why there is none.
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl LapCompared {
    /// (FE - closed form) / closed form for Delta; `None` at F = 0.
    pub fn difference(&self) -> Option<f64> {
        relative_difference(self.fe.joint_displacement, self.closed)
    }

    /// Delta's difference against the theory's envelope (L14).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(self.difference(), self.theory_within)
    }

    /// Of a and d, the one farther from the closed form in elements of the mesh.
    pub fn worse_zone_mesh(&self) -> Option<MeshDifference> {
        self.zones_mesh
            .map(|[a, d]| if a.elements >= d.elements { a } else { d })
    }
}

/// Compares FE points of the lap joint with the closed forms of `joint` (the K_T the deck gave
/// the FE code). `mesh`: the FE mesh along the interface, to count the zone differences in
/// elements.
///
/// # Errors
/// A point's force beyond the joint's gross-slip force (a CSV of another joint, or of a joint
/// that slid through): the closed forms have no static state there.
pub fn compare_lap(
    joint: &LapJoint,
    points: &[LapFePoint],
    mesh: Option<&InterfaceMesh>,
) -> Result<Vec<LapCompared>, ParamError> {
    let length = joint.params().length;
    points
        .iter()
        .map(|&fe| {
            let force = joint.force(fe.force)?;
            let state = joint.regularized(force);
            let zones = (state.slide_at_inner_end(), state.slide_at_cover_ends());
            let validity = joint.validity_at(force, state.joint_displacement());
            let theory_validity = validity.validity;
            let zones_mesh = mesh.zip(fe.interface).map(|(mesh, i)| {
                [
                    MeshDifference::on(mesh, i.slide_from_start, zones.0),
                    // d counts from x = L: its elements are counted between the positions
                    // L - d, its difference is d's own.
                    MeshDifference {
                        difference: i.slide_from_end - zones.1,
                        ..MeshDifference::on(mesh, length - i.slide_from_end, length - zones.1)
                    },
                ]
            });
            Ok(LapCompared {
                fe,
                closed: state.joint_displacement(),
                coulomb: joint.coulomb(force).joint_displacement(),
                regime: state.regime(),
                zones,
                implied_stiffness: (theory_validity == Validity::Holds)
                    .then(|| joint.stiffness_for_joint_displacement(force, fe.joint_displacement))
                    .flatten(),
                theory_validity,
                theory_within: validity.expected_error,
                zones_mesh,
                continuum: None,
            })
        })
        .collect()
}

/// The comparison of the FE `points` of `model`'s deck, each loaded row also against the joint's
/// continuum at its force ([`crate::fe::face::Deck::compare`]).
///
/// # Errors
/// As [`compare_lap`].
pub(super) fn compare(
    model: &LapModel,
    points: &[LapFePoint],
    mesh: Option<&InterfaceMesh>,
) -> Result<Vec<LapCompared>, ParamError> {
    let mut rows = compare_lap(&model.joint, points, mesh)?;
    for row in rows.iter_mut().filter(|r| r.fe.force > 0.0) {
        let at = LapModel {
            joint: model.joint,
            force: model.joint.force(row.fe.force)?,
        };
        row.continuum = judged::<LapJointProblem>(&at, row.fe.joint_displacement);
    }
    Ok(rows)
}

/// One row of `microslip compare lap`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct LapCompareRow {
    /// The force through the joint (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// FE Delta (mm): thickness means, zeroed after clamping, for CalculiX; the given value for
    /// CSV.
    #[serde(rename = "Delta_fe_mm")]
    pub delta_fe: f64,
    /// Shear-lag closed form, regularized law (mm).
    #[serde(rename = "Delta_mm")]
    pub delta: f64,
    /// (FE - closed form) / closed form; empty (null) at F = 0.
    pub diff: Option<f64>,
    /// The shear-lag envelope's bound on that difference (L14), a fraction; empty (null) where
    /// not calibrated.
    pub shear_lag_within: Option<f64>,
    /// Plain Coulomb law (mm).
    #[serde(rename = "Delta_coulomb_mm")]
    pub delta_coulomb: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows.
    pub regime_fe: Option<&'static str>,
    /// Closed-form sliding zone from x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_start: f64,
    /// FE a (mm), from K_T |slip| = mu P.
    #[serde(rename = "a_fe_mm")]
    pub slide_from_start_fe: Option<f64>,
    /// Closed-form sliding zone from x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_end: f64,
    /// FE d (mm).
    #[serde(rename = "d_fe_mm")]
    pub slide_from_end_fe: Option<f64>,
    /// The K_T whose closed-form Delta equals the FE value (MPa/mm), given only where the
    /// shear-lag theory holds.
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// The shear-lag theory's level at this force (L14).
    pub shear_lag: &'static str,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_fraction: Option<f64>,
    pub shear_lag_within_fraction: Option<f64>,
}

impl From<&LapCompared> for LapCompareRow {
    fn from(r: &LapCompared) -> Self {
        LapCompareRow {
            force: r.fe.force,
            delta_fe: r.fe.joint_displacement,
            delta: r.closed,
            diff: r.difference(),
            shear_lag_within: r.theory_within,
            delta_coulomb: r.coulomb,
            regime: r.regime.label(),
            regime_fe: r.fe.interface.map(|i| i.regime.label()),
            slide_from_start: r.zones.0,
            slide_from_start_fe: r.fe.interface.map(|i| i.slide_from_start),
            slide_from_end: r.zones.1,
            slide_from_end_fe: r.fe.interface.map(|i| i.slide_from_end),
            implied_stiffness: r.implied_stiffness,
            shear_lag: r.theory_validity.label(),
            diff_fraction: r.difference(),
            shear_lag_within_fraction: r.theory_within,
        }
    }
}

/// a and d in a row verdict of the lap joint: in elements of the FE mesh (CalculiX results only;
/// not bounded by the envelope).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct LapZones {
    /// |FE a - closed-form a| in elements of the FE mesh.
    pub a_elements: Option<f64>,
    /// |FE d - closed-form d| in elements of the FE mesh.
    pub d_elements: Option<f64>,
}

/// `microslip compare lap`, one row per load step.
pub type LapCompareReport = TableReport<LapJointProblem>;

/// "F = 3000 N": a load step of the joint by its force.
fn force_label(force: f64) -> String {
    format!("F = {} N", number(force))
}

impl CompareTable for LapJointProblem {
    type Compared = LapCompared;
    type CsvRow = LapCompareRow;
    type Zones = LapZones;
    /// (L14) at this force, for the text (the JSON has its label in `shear_lag`).
    type Note = Validity;
    type Head = ();
    type Tail = ();
    const CONTINUUM: &'static str = "plane-stress continuum (L13)";

    fn label(row: &LapCompared) -> String {
        force_label(row.fe.force)
    }

    fn check(row: &LapCompared) -> Check {
        row.continuum
    }

    fn note(row: &LapCompared) -> Validity {
        row.theory_validity
    }

    /// Delta against the shear-lag envelope (L14), a and d in elements of the mesh.
    fn verdict(row: &LapCompared) -> RowVerdict<LapZones> {
        let meshes: Vec<(&str, &MeshDifference)> = match &row.zones_mesh {
            Some([a, d]) => vec![("a", a), ("d", d)],
            None => Vec::new(),
        };
        RowVerdict::new(
            &force_label(row.fe.force),
            ("Delta", row.difference(), row.envelope()),
            &meshes,
            LapZones {
                a_elements: row.zones_mesh.map(|[a, _]| a.elements),
                d_elements: row.zones_mesh.map(|[_, d]| d.elements),
            },
        )
    }

    fn table_text(report: &LapCompareReport) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FE results ({}) vs the closed forms: clamped double-lap joint\n\
             F in N; Delta = u_inner(L) - u_cover(0) in mm (FE: thickness means, zeroed after the\n\
             clamping step); closed form: shear lag, regularized law (docs/theory.md section 9);\n\
             a, d (mm): sliding zones from x = 0 and from x = L (FE: where K_T |slip| >= mu P);\n\
             implied K_T (MPa/mm): the K_T whose closed-form Delta equals the FE value, given only\n\
             where the shear-lag theory holds (docs/theory.md (L14)); elsewhere the difference is\n\
             the theory's, not the interface's.\n",
            sanitize(&report.results)
        );
        let _ = writeln!(
            out,
            "{:>8} {:>11} {:>11} {:>9} {:>7} {:>7} {:>7} {:>7}  {:>16}  regime (closed form / FE)",
            "F", "Delta FE", "Delta", "diff", "a FE", "a", "d FE", "d", "implied K_T"
        );
        for r in &report.rows {
            let (row, theory_validity) = (&r.row, r.note);
            let _ = writeln!(
                out,
                "{:>8} {:>11} {:>11} {:>9} {:>7} {:>7} {:>7} {:>7}  {:>16}  {} / {}",
                number(row.force),
                number(row.delta_fe),
                number(row.delta),
                percent_or_na(row.diff),
                optional(row.slide_from_start_fe),
                number(row.slide_from_start),
                optional(row.slide_from_end_fe),
                number(row.slide_from_end),
                row.implied_stiffness.map_or_else(
                    || {
                        if theory_validity == Validity::Holds {
                            "none".into()
                        } else {
                            format!("({})", theory_validity.label())
                        }
                    },
                    number
                ),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        let zone = if report
            .rows
            .iter()
            .any(|r| r.verdict.zones.a_elements.is_some())
        {
            "a and d against the closed form's in elements of the deck's mesh along the interface\n\
             (under one: within what the mesh resolves; (L14) does not bound them)."
        } else {
            "a and d are not judged (the results carry no slip profile and no mesh)."
        };
        let _ = writeln!(
            out,
            "\nPer load step: Delta against the shear-lag theory's envelope (docs/theory.md (L14));\n\
             {zone}"
        );
        out
    }
}

/// The closing verdict of the lap joint: Delta against (L14) at every load step; a and d said,
/// not judged ((L14) does not bound them).
pub fn lap_summary(rows: &[LapCompared]) -> Summary {
    let names = Names {
        what: "Delta",
        zone: "a or d",
        zone_bounded: false,
        at: "F =",
        unit: "N",
        steps: "load steps",
    };
    tally_summary(
        rows.iter()
            .map(|r| (number(r.fe.force), r.envelope(), r.worse_zone_mesh())),
        &names,
    )
}

impl CompareFace for LapJointProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<LapCompared>;
    type CompareRow = LapCompareRow;
    type CompareReport = LapCompareReport;

    fn checked(
        compared: Result<Vec<LapCompared>, ParamError>,
    ) -> Result<Vec<LapCompared>, ParamError> {
        compared
    }

    fn compare_report(
        source: &str,
        first: Vec<LapCompared>,
        more: Vec<Vec<LapCompared>>,
    ) -> (LapCompareReport, Vec<LapCompareRow>) {
        let rows: Vec<LapCompared> = first
            .into_iter()
            .chain(more.into_iter().flatten())
            .collect();
        let report = TableReport::new(source, &rows, ((), ()), lap_summary(&rows));
        let csv = report.csv_rows();
        (report, csv)
    }

    fn compare_text(report: &LapCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut LapCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    fn ladder_quantities(report: &Self::CompareReport) -> Vec<crate::fe::ladder::LadderQuantity> {
        report.ladder_quantities()
    }
}
