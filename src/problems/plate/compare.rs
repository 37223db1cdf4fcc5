//! The squeezed plate's FE results against its closed forms, run by run: u(L) against the strip
//! theory, and per run the K_T whose closed-form u(L) equals the FE value. Then the report of it
//! ([`TableReport`] with the plate's columns, row verdicts and closing verdict) that
//! `compare plate` and `bench` print.

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::compare::{on_mesh, relative_difference};
use crate::fe::continuum_verdict::{ContinuumVerdict, NotSolved, judged};
use crate::fe::results::FeInterface;
use crate::fe::verdict::{Envelope, InterfaceMesh, MeshDifference};
use crate::kernel::params::ParamError;
use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::report::compare::continuum::Check;
use crate::report::compare::table::{CompareTable, TableReport};
use crate::report::compare::verdict::{Names, RowVerdict, Summary, tally_summary};
use crate::report::compare::{CompareFace, UNDEFINED_NOTE, optional, percent, percent_or_na};
use crate::report::{number, sanitize};

use super::closed_form::SqueezedPlate;
use super::fe_points::PlateFePoint;
use super::params::PlateParam;
use super::problem::SqueezedPlateProblem;

/// One FE point of the plate beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateCompared {
    /// The FE point.
    pub fe: PlateFePoint,
    /// The strip theory's u(L) under the regularized law at the FE run's K_T (mm).
    pub closed: f64,
    /// Under the plain Coulomb law (mm).
    pub coulomb: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's X_r (mm).
    pub micro_zone_end: f64,
    /// The K_T (MPa/mm) whose closed-form u(L) equals the FE value; `None` when no accepted K_T
    /// does (the FE value is outside the range the strip theory can give), or when the strip
    /// theory does not hold at the run's K_T ([`PlateCompared::strip_validity`]): there the
    /// difference is the strip theory's, not the interface's, and inverting it would name a K_T
    /// the run did not have (a run at 1e7 "implied" 5.8e5).
    pub implied_stiffness: Option<f64>,
    /// (V1) for the thickness mean at the run's K_T.
    pub strip_validity: Validity,
    /// (V1)'s bound on the thickness mean's difference, a fraction; `None` where no calibration
    /// reaches.
    pub strip_within: Option<f64>,
    /// FE X_r against the closed form's in elements of the FE mesh (CalculiX results).
    pub micro_zone_end_mesh: Option<MeshDifference>,
    /// u(L) against the plane-strain continuum at the run's parameters, where it was solved
    /// (`compare`, `bench`; the TUI's pane leaves it out): the verdict, or why there is none.
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl PlateCompared {
    /// (FE - closed form) / closed form for u(L); `None` where the closed form is 0.
    pub fn difference(&self) -> Option<f64> {
        relative_difference(self.fe.end_displacement, self.closed)
    }

    /// The thickness mean's difference against its envelope (V1).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(self.difference(), self.strip_within)
    }

    /// The same at the contact face and at mid-thickness, when the results have them and the
    /// closed form is not 0.
    pub fn differences_through_thickness(&self) -> Option<[f64; 2]> {
        let [face, mid] = self.fe.through_thickness?;
        Some([
            relative_difference(face, self.closed)?,
            relative_difference(mid, self.closed)?,
        ])
    }

    /// The FE interface state, when the results have the slip.
    pub fn fe_interface(&self) -> Option<FeInterface> {
        self.fe.interface
    }
}

/// Compares FE points of the plate (each at its own K_T) with the closed forms of `plate` at that
/// K_T. Points whose K_T is outside the accepted domain cannot occur: the readers refuse them.
/// `mesh`: the FE mesh along the contact face, to count the X_r difference in elements.
pub fn compare_plate(
    plate: &SqueezedPlate,
    points: &[PlateFePoint],
    mesh: Option<&InterfaceMesh>,
) -> Vec<PlateCompared> {
    points
        .iter()
        .map(|&fe| {
            let at = plate.with_clamped(PlateParam::Stiffness, fe.stiffness);
            let state = at.regularized();
            let validity = at.validity();
            let strip_validity = validity.validity;
            let micro_zone_end = state.micro_zone_end();
            PlateCompared {
                fe,
                closed: state.end_displacement(),
                coulomb: at.coulomb().end_displacement(),
                regime: state.regime(),
                micro_zone_end,
                implied_stiffness: (strip_validity == Validity::Holds)
                    .then(|| at.stiffness_for_end_displacement(fe.end_displacement))
                    .flatten(),
                strip_validity,
                strip_within: validity.expected_error(),
                micro_zone_end_mesh: on_mesh(mesh, fe.interface, micro_zone_end),
                continuum: None,
            }
        })
        .collect()
}

/// The comparison of the FE `points` of the plate's deck, each run also against the plate's
/// continuum at its K_T ([`crate::fe::face::Deck::compare`]).
pub(super) fn compare(
    plate: &SqueezedPlate,
    points: &[PlateFePoint],
    mesh: Option<&InterfaceMesh>,
) -> Vec<PlateCompared> {
    let mut rows = compare_plate(plate, points, mesh);
    for row in &mut rows {
        let at = plate.with_clamped(PlateParam::Stiffness, row.fe.stiffness);
        row.continuum = judged::<SqueezedPlateProblem>(&at, row.fe.end_displacement);
    }
    rows
}

/// One row of `microslip compare plate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PlateCompareRow {
    /// The run's stick slope K_T (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub stiffness: f64,
    /// FE u(L) (mm): thickness mean for CalculiX, the given value for CSV.
    pub u_fe_mm: f64,
    /// FE u(L) at the contact face (mm).
    pub u_fe_contact_face_mm: Option<f64>,
    /// FE u(L) at mid-thickness (mm).
    pub u_fe_mid_thickness_mm: Option<f64>,
    /// Strip theory, regularized law (mm).
    pub u_mm: f64,
    /// (FE - closed form) / closed form; empty (null) where the closed form is 0 (nu = 0).
    pub diff: Option<f64>,
    /// The same at the contact face.
    pub diff_contact_face: Option<f64>,
    /// The same at mid-thickness.
    pub diff_mid_thickness: Option<f64>,
    /// Strip theory, plain Coulomb law (mm).
    pub u_coulomb_mm: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows.
    pub regime_fe: Option<&'static str>,
    /// Closed-form X_r (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_zone_end: f64,
    /// FE X_r (mm), from K_T |slip| = mu P.
    #[serde(rename = "Xr_fe_mm")]
    pub micro_zone_end_fe: Option<f64>,
    /// The K_T whose closed-form u(L) equals the FE value (MPa/mm).
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// (V1) for the thickness mean at the run's K_T; the implied K_T is given only where it holds.
    pub strip_theory: &'static str,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_fraction: Option<f64>,
    pub diff_contact_face_fraction: Option<f64>,
    pub diff_mid_thickness_fraction: Option<f64>,
}

impl From<&PlateCompared> for PlateCompareRow {
    fn from(r: &PlateCompared) -> Self {
        let through = r.fe.through_thickness;
        let diffs = r.differences_through_thickness();
        PlateCompareRow {
            stiffness: r.fe.stiffness,
            u_fe_mm: r.fe.end_displacement,
            u_fe_contact_face_mm: through.map(|u| u[0]),
            u_fe_mid_thickness_mm: through.map(|u| u[1]),
            u_mm: r.closed,
            diff: r.difference(),
            diff_contact_face: diffs.map(|d| d[0]),
            diff_mid_thickness: diffs.map(|d| d[1]),
            u_coulomb_mm: r.coulomb,
            regime: r.regime.label(),
            regime_fe: r.fe_interface().map(|i| i.regime.label()),
            micro_zone_end: r.micro_zone_end,
            micro_zone_end_fe: r.fe_interface().map(|i| i.macroslip_start),
            implied_stiffness: r.implied_stiffness,
            strip_theory: r.strip_validity.label(),
            diff_fraction: r.difference(),
            diff_contact_face_fraction: diffs.map(|d| d[0]),
            diff_mid_thickness_fraction: diffs.map(|d| d[1]),
        }
    }
}

/// X_r in a row verdict of the plate: in elements of the FE mesh (CalculiX results only).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PlateZones {
    /// |FE X_r - closed-form X_r| in elements of the FE mesh.
    #[serde(rename = "Xr_elements")]
    pub zone_end_elements: Option<f64>,
    /// Whether that is under one element.
    #[serde(rename = "Xr_within_mesh_resolution")]
    pub zone_end_within_resolution: Option<bool>,
}

/// `microslip compare plate`, one row per FE run.
pub type PlateCompareReport = TableReport<SqueezedPlateProblem>;

/// "K_T = 1e4 MPa/mm": a run of the plate by its stick slope.
fn stiffness_label(stiffness: f64) -> String {
    format!("K_T = {} MPa/mm", number(stiffness))
}

impl CompareTable for SqueezedPlateProblem {
    type Compared = PlateCompared;
    type CsvRow = PlateCompareRow;
    type Zones = PlateZones;
    /// (V1) at the run's K_T, for the text (the JSON has its label in `strip_theory`).
    type Note = Validity;
    type Head = ();
    type Tail = ();
    const CONTINUUM: &'static str = "plane-strain continuum";

    fn label(row: &PlateCompared) -> String {
        stiffness_label(row.fe.stiffness)
    }

    fn check(row: &PlateCompared) -> Check {
        row.continuum
    }

    fn note(row: &PlateCompared) -> Validity {
        row.strip_validity
    }

    /// u(L) (thickness mean) against (V1), X_r in elements.
    fn verdict(row: &PlateCompared) -> RowVerdict<PlateZones> {
        let mesh = row.micro_zone_end_mesh;
        RowVerdict::new(
            &stiffness_label(row.fe.stiffness),
            ("u(L) (thickness mean)", row.difference(), row.envelope()),
            &mesh.iter().map(|m| ("X_r", m)).collect::<Vec<_>>(),
            PlateZones {
                zone_end_elements: mesh.map(|m| m.elements),
                zone_end_within_resolution: mesh.map(|m| m.within_resolution()),
            },
        )
    }

    fn table_text(report: &PlateCompareReport) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FE results ({}) vs the closed forms: squeezed plate\n\
             K_T in MPa/mm; u(L) in mm; FE: thickness mean (face: contact face, mid: mid-thickness);\n\
             closed form: strip theory, regularized law; X_r (mm) from the centre (FE: where K_T |slip|\n\
             = mu P); implied K_T (MPa/mm): the K_T whose closed-form u(L) equals the FE mean, given only\n\
             where the strip theory holds (docs/theory.md (V1)); elsewhere the difference is the strip\n\
             theory's, not the interface's.\n",
            sanitize(&report.results)
        );
        let _ = writeln!(
            out,
            "{:>10} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9}  {:>16}  regime (closed form / FE)",
            "K_T", "u FE", "u closed", "diff", "face", "mid", "X_r FE", "X_r", "implied K_T"
        );
        for r in &report.rows {
            let (row, strip_validity) = (&r.row, r.note);
            let _ = writeln!(
                out,
                "{:>10} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9}  {:>16}  {} / {}",
                number(row.stiffness),
                number(row.u_fe_mm),
                number(row.u_mm),
                percent_or_na(row.diff),
                row.diff_contact_face.map_or("-".into(), percent),
                row.diff_mid_thickness.map_or("-".into(), percent),
                optional(row.micro_zone_end_fe),
                number(row.micro_zone_end),
                row.implied_stiffness.map_or_else(
                    || {
                        if strip_validity == Validity::Holds {
                            "none".into()
                        } else {
                            format!("({})", strip_validity.label())
                        }
                    },
                    number
                ),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        if report.rows.iter().any(|r| r.row.diff.is_none()) {
            let _ = writeln!(out, "{UNDEFINED_NOTE}");
        }
        let zone = if report
            .rows
            .iter()
            .any(|r| r.verdict.zones.zone_end_elements.is_some())
        {
            "X_r against the closed form's in elements of the deck's mesh along the contact face\n\
             (under one: within what the mesh resolves, the FE X_r being interpolated between nodes;\n\
             (V1) does not bound X_r)."
        } else {
            "X_r is not judged (the results carry no slip profile\nand no mesh)."
        };
        let _ = writeln!(
            out,
            "\nPer run: the thickness-mean u(L) against the strip theory's envelope (docs/theory.md\n\
             (V1)); {zone}"
        );
        out
    }
}

/// The closing verdict of the plate: u(L) against (V1) on every run; X_r said, not judged (the
/// strip theory's slip zone was measured up to 2.4 times the continuum's where u(L) holds,
/// docs/theory.md).
pub fn plate_summary(rows: &[PlateCompared]) -> Summary {
    let names = Names {
        what: "u(L)",
        zone: "X_r",
        zone_bounded: false,
        at: "K_T =",
        unit: "MPa/mm",
        steps: "runs",
    };
    tally_summary(
        rows.iter()
            .map(|r| (number(r.fe.stiffness), r.envelope(), r.micro_zone_end_mesh)),
        &names,
    )
}

impl CompareFace for SqueezedPlateProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<PlateCompared>;
    type CompareRow = PlateCompareRow;
    type CompareReport = PlateCompareReport;

    fn checked(compared: Vec<PlateCompared>) -> Result<Vec<PlateCompared>, ParamError> {
        Ok(compared)
    }

    fn compare_report(
        source: &str,
        first: Vec<PlateCompared>,
        more: Vec<Vec<PlateCompared>>,
    ) -> (PlateCompareReport, Vec<PlateCompareRow>) {
        let rows: Vec<PlateCompared> = first
            .into_iter()
            .chain(more.into_iter().flatten())
            .collect();
        let report = TableReport::new(source, &rows, ((), ()), plate_summary(&rows));
        let csv = report.csv_rows();
        (report, csv)
    }

    fn compare_text(report: &PlateCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut PlateCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    fn ladder_quantities(report: &Self::CompareReport) -> Vec<crate::fe::ladder::LadderQuantity> {
        report.ladder_quantities()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::plate::params::PlateParams;

    #[test]
    fn plate_stiffness_is_recovered_from_its_own_end_displacement() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        for kt in [1e2, 1e4, 3e5, 1e6, 1e8] {
            let u = plate
                .with_tangential_stiffness(kt)
                .unwrap()
                .regularized()
                .end_displacement();
            let found = plate.stiffness_for_end_displacement(u).unwrap();
            assert!((found / kt - 1.0).abs() < 1e-6, "K_T {kt}: found {found}");
        }
        // Below the Coulomb value, or beyond the free expansion, no K_T gives it.
        let coulomb = plate.coulomb().end_displacement();
        assert_eq!(plate.stiffness_for_end_displacement(0.5 * coulomb), None);
        let p = PlateParams::PAPER;
        let free = p.poisson * (1.0 + p.poisson) * p.pressure * p.half_length / p.youngs_modulus;
        assert_eq!(plate.stiffness_for_end_displacement(1.01 * free), None);
    }

    /// The strip theory's u(L) of the paper's plate at `kt`.
    fn paper_u(kt: f64) -> f64 {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let at = plate.with_tangential_stiffness(kt).unwrap();
        at.regularized().end_displacement()
    }

    fn mean_only(stiffness: f64, end_displacement: f64) -> PlateFePoint {
        PlateFePoint {
            stiffness,
            end_displacement,
            through_thickness: None,
            interface: None,
        }
    }

    #[test]
    fn no_stiffness_is_implied_where_the_strip_theory_does_not_hold() {
        // The paper's plate at K_T = 1e7 (alpha t_p = 5.1): a u(L) that the strip theory reaches
        // at a softer K_T would "imply" that K_T; it is withheld.
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let u = paper_u(5.8e5);
        assert!(plate.stiffness_for_end_displacement(u).is_some());
        let rows = compare_plate(&plate, &[mean_only(1e7, u)], None);
        assert_eq!(rows[0].implied_stiffness, None);
        assert_ne!(rows[0].strip_validity, Validity::Holds);
    }

    #[test]
    fn plate_comparison_uses_each_points_stiffness() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let rows = compare_plate(&plate, &[mean_only(1e4, 1.1 * paper_u(1e4))], None);
        assert!((rows[0].difference().unwrap() - 0.1).abs() < 1e-12);
        assert_eq!(rows[0].regime, Regime::MICROSLIP);
        assert_eq!(rows[0].strip_validity, Validity::Holds);
        assert!(
            rows[0].implied_stiffness.unwrap() < 1e4,
            "more displacement, softer"
        );
    }
}
