//! The twin beams' FE results against their closed forms, point by point: the FE w(L) against
//! the paper's Euler-Bernoulli closed form and against it plus each beam's shear deflection
//! (B13), which continuum elements include; the implied K_T (and mu) from the existing fit
//! ([`crate::fit`]) run on the FE points with the shear deflection taken off, so that it measures
//! the interface, not the beam theory. Then the report of it ([`TableReport`] with the beams'
//! columns, row verdicts and closing verdict) that `compare beam` and `bench` print.

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::compare::{on_mesh, relative_difference};
use crate::fe::continuum_verdict::{ContinuumVerdict, NotSolved, judged};
use crate::fe::verdict::{Envelope, InterfaceMesh, MeshDifference, StiffnessMatch};
use crate::fit::{self, FitError, FitResult, Measurement};
use crate::kernel::params::{Compact, ParamError};
use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::report::compare::continuum::Check;
use crate::report::compare::table::{CompareTable, TableReport};
use crate::report::compare::verdict::{Names, RowVerdict, Summary, Tally, opening, z_words};
use crate::report::compare::{CompareFace, UNDEFINED_NOTE, optional, percent_or_na};
use crate::report::{count_of, number, number_with, sanitize};

use super::closed_form::{TipForce, TwinBeams};
use super::fe_points::BeamFePoint;
use super::params::BeamTheory;
use super::problem::{BeamsModel, TwinBeamsProblem};

/// One FE point of the beams beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamCompared {
    /// The FE point.
    pub fe: BeamFePoint,
    /// Euler-Bernoulli w(L) under the regularized law (mm): the paper's closed form.
    pub euler: f64,
    /// The same plus the shear deflection (mm).
    pub shear_corrected: f64,
    /// The closed form's regime.
    pub regime: Regime,
    /// The closed form's start of the macroslip zone X (mm): L when there is none.
    pub macroslip_start: f64,
    /// The envelope (V2) of the shear-corrected (Timoshenko) value: the stated bound on its
    /// difference from continuum FE; `None` where (V2) is not calibrated (friction strain).
    pub shear_corrected_within: Option<f64>,
    /// FE X against the closed form's in elements of the FE mesh, when the results have the slip
    /// and the mesh is known (CalculiX results with their deck).
    pub macroslip_start_mesh: Option<MeshDifference>,
    /// This point's w(L) against the beams' plane-stress continuum at the deck's parameters and
    /// load (`None`: not checked).
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl BeamCompared {
    /// (FE - closed form) / closed form against the Euler-Bernoulli value; `None` at F = 0.
    pub fn difference_euler(&self) -> Option<f64> {
        relative_difference(self.fe.deflection, self.euler)
    }

    /// (FE - closed form) / closed form against the shear-corrected value; `None` at F = 0.
    pub fn difference_shear_corrected(&self) -> Option<f64> {
        relative_difference(self.fe.deflection, self.shear_corrected)
    }

    /// The shear-corrected difference against its envelope (V2).
    pub fn envelope(&self) -> Envelope {
        Envelope::judge(
            self.difference_shear_corrected(),
            self.shear_corrected_within,
        )
    }
}

/// The beams' comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct BeamComparison {
    /// Point by point.
    pub rows: Vec<BeamCompared>,
    /// The Poisson ratio used for the shear deflection.
    pub poisson: f64,
    /// mu and K_T fitted to the FE points less their shear deflection.
    pub implied: Result<FitResult, FitError>,
    /// The K_T the closed forms used: the deck's stick slope (MPa/mm).
    pub stiffness: f64,
}

impl BeamComparison {
    /// Whether the beam theory holds (V2 within 2 %) at every point, so that a K_T fitted through
    /// it measures the interface; false too where (V2) is not calibrated.
    pub fn closed_form_holds(&self) -> bool {
        self.rows.iter().all(|r| {
            r.shear_corrected_within
                .is_some_and(|bound| Validity::of_error(bound) == Validity::Holds)
        })
    }

    /// Whether (V2) has a bound at every point (the friction strain within its calibration).
    pub fn closed_form_calibrated(&self) -> bool {
        self.rows.iter().all(|r| r.shear_corrected_within.is_some())
    }

    /// The deck's K_T against the implied one.
    pub fn stiffness_match(&self) -> StiffnessMatch {
        match &self.implied {
            Err(_) => StiffnessMatch::NotImplied,
            Ok(_) if !self.closed_form_calibrated() => StiffnessMatch::ClosedFormNotCalibrated,
            Ok(_) if !self.closed_form_holds() => StiffnessMatch::ClosedFormDoesNotHold,
            Ok(fit) => match fit.kt.evidence {
                fit::Evidence::NoDegreesOfFreedom { points, parameters } => {
                    StiffnessMatch::UncertaintyUnknown { points, parameters }
                }
                _ => StiffnessMatch::judge(self.stiffness, fit.kt.value, fit.kt.std_error),
            },
        }
    }
}

/// Compares FE points of the beams with the closed forms of `beams` (the K_T the deck gave the FE
/// code; its nu for the shear deflection), under both beam theories whichever `beams` has. `mesh`:
/// the FE mesh along the interface, to count the X difference in elements.
pub fn compare_beams(
    beams: &TwinBeams,
    points: &[BeamFePoint],
    mesh: Option<&InterfaceMesh>,
) -> BeamComparison {
    let euler_bernoulli = beams.with_theory(BeamTheory::EulerBernoulli);
    let timoshenko = beams.with_theory(BeamTheory::Timoshenko);
    let rows: Vec<BeamCompared> = points
        .iter()
        .map(|&fe| {
            let force = TipForce::clamped(fe.force);
            let state = euler_bernoulli.regularized(force);
            let euler = state.tip_deflection();
            let macroslip_start = state.micro_zone_end();
            BeamCompared {
                fe,
                euler,
                shear_corrected: euler + beams.shear_deflection(force),
                regime: state.regime(),
                macroslip_start,
                shear_corrected_within: timoshenko.validity(force).expected_error,
                macroslip_start_mesh: on_mesh(mesh, fe.interface, macroslip_start),
                continuum: None,
            }
        })
        .collect();
    let bending_only: Vec<Measurement> = rows
        .iter()
        .map(|r| Measurement {
            force: r.fe.force,
            response: r.fe.deflection - (r.shear_corrected - r.euler),
        })
        .collect();
    let implied = fit::fit_curve::<TwinBeamsProblem>(
        &euler_bernoulli,
        &bending_only,
        (None, None),
        fit::Weights::Absolute,
        &mut |_| {},
    );
    BeamComparison {
        rows,
        poisson: beams.params().poisson,
        implied,
        stiffness: beams.params().tangential_stiffness,
    }
}

/// The comparison of the FE `points` of `model`'s deck, each row also against the beams'
/// continuum at its load ([`crate::fe::face::Deck::compare`]).
pub(super) fn compare(
    model: &BeamsModel,
    points: &[BeamFePoint],
    mesh: Option<&InterfaceMesh>,
) -> BeamComparison {
    let mut comparison = compare_beams(&model.beams, points, mesh);
    for row in &mut comparison.rows {
        let at = BeamsModel {
            beams: model.beams,
            force: TipForce::clamped(row.fe.force),
        };
        row.continuum = judged::<TwinBeamsProblem>(&at, row.fe.deflection);
    }
    comparison
}

/// One row of `microslip compare beam`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct BeamCompareRow {
    /// Tip force on each beam (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// FE w(L) (mm).
    pub w_fe_mm: f64,
    /// Closed form, Euler-Bernoulli (the paper's) (mm).
    pub w_euler_mm: f64,
    /// (FE - Euler-Bernoulli) / Euler-Bernoulli; empty (null) at F = 0, where it is undefined.
    pub diff_euler: Option<f64>,
    /// Closed form plus the shear deflection (mm).
    pub w_shear_corrected_mm: f64,
    /// (FE - shear corrected) / shear corrected; empty (null) at F = 0.
    pub diff_shear_corrected: Option<f64>,
    /// The stated bound on that difference (V2), a fraction; empty (null) where (V2) is not
    /// calibrated.
    pub shear_corrected_within: Option<f64>,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows (empty without one).
    pub regime_fe: Option<&'static str>,
    /// Closed-form start of the macroslip zone X (mm).
    #[serde(rename = "X_mm")]
    pub macroslip_start: f64,
    /// FE X (mm), from K_T |slip| = mu P (empty without a slip profile).
    #[serde(rename = "X_fe_mm")]
    pub macroslip_start_fe: Option<f64>,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_euler_fraction: Option<f64>,
    pub diff_shear_corrected_fraction: Option<f64>,
    pub shear_corrected_within_fraction: Option<f64>,
}

impl From<&BeamCompared> for BeamCompareRow {
    fn from(r: &BeamCompared) -> Self {
        BeamCompareRow {
            force: r.fe.force,
            w_fe_mm: r.fe.deflection,
            w_euler_mm: r.euler,
            diff_euler: r.difference_euler(),
            w_shear_corrected_mm: r.shear_corrected,
            diff_shear_corrected: r.difference_shear_corrected(),
            shear_corrected_within: r.shear_corrected_within,
            regime: r.regime.label(),
            regime_fe: r.fe.interface.map(|i| i.regime.label()),
            macroslip_start: r.macroslip_start,
            macroslip_start_fe: r.fe.interface.map(|i| i.macroslip_start),
            diff_euler_fraction: r.difference_euler(),
            diff_shear_corrected_fraction: r.difference_shear_corrected(),
            shear_corrected_within_fraction: r.shear_corrected_within,
        }
    }
}

/// X in a row verdict of the beams: in elements of the FE mesh (CalculiX results only).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamZones {
    /// |FE X - closed-form X| in elements of the FE mesh.
    #[serde(rename = "X_elements")]
    pub zone_end_elements: Option<f64>,
    /// Whether that is under one element.
    #[serde(rename = "X_within_mesh_resolution")]
    pub zone_end_within_resolution: Option<bool>,
}

/// The keys of the beams' report before its rows.
#[derive(Debug, Clone, Serialize)]
pub struct BeamHead {
    /// The K_T the closed forms use: the deck's stick slope (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub stiffness: f64,
    /// The Poisson ratio of the shear deflection.
    pub nu: f64,
}

/// The keys of the beams' report after its rows.
#[derive(Debug, Clone, Serialize)]
pub struct BeamTail {
    pub implied: ImpliedReport,
}

/// What the FE points imply: the fit's values, or why there are none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum ImpliedReport {
    /// The fit of mu and K_T to w(L) less the shear deflection.
    Fit {
        #[serde(rename = "KT_MPa_per_mm")]
        stiffness: f64,
        #[serde(rename = "KT_status")]
        stiffness_status: &'static str,
        /// The fit's standard error of K_T, when it has one.
        #[serde(rename = "KT_std_error_MPa_per_mm")]
        stiffness_std_error: Option<f64>,
        mu: f64,
        mu_status: &'static str,
        rms_mm: f64,
        /// Loaded points less fitted parameters: at 0 the fit passes through every point and
        /// its error is unknown (the RMS is 0 by construction).
        degrees_of_freedom: usize,
    },
    /// Why no fit ran.
    Error { error: String },
}

/// `microslip compare beam`.
pub type BeamCompareReport = TableReport<TwinBeamsProblem>;

/// The report of `comparison` of the results named `source`.
pub fn beam_compare_report(source: &str, comparison: &BeamComparison) -> BeamCompareReport {
    let implied = match &comparison.implied {
        Ok(fit) => ImpliedReport::Fit {
            stiffness: fit.kt.value,
            stiffness_status: fit.kt.status.label(),
            stiffness_std_error: fit.kt.std_error,
            mu: fit.mu.value,
            mu_status: fit.mu.status.label(),
            rms_mm: fit.rms,
            degrees_of_freedom: fit.degrees_of_freedom,
        },
        Err(e) => ImpliedReport::Error {
            error: e.to_string(),
        },
    };
    let head = BeamHead {
        stiffness: comparison.stiffness,
        nu: comparison.poisson,
    };
    TableReport::new(
        source,
        &comparison.rows,
        (head, BeamTail { implied }),
        beam_summary(comparison),
    )
}

/// "F = 40 N": a row of the beams by its force.
fn force_label(force: f64) -> String {
    format!("F = {} N", number(force))
}

impl CompareTable for TwinBeamsProblem {
    type Compared = BeamCompared;
    type CsvRow = BeamCompareRow;
    type Zones = BeamZones;
    type Note = ();
    type Head = BeamHead;
    type Tail = BeamTail;
    const CONTINUUM: &'static str = "plane-stress continuum (BC1)";

    fn label(row: &BeamCompared) -> String {
        force_label(row.fe.force)
    }

    fn check(row: &BeamCompared) -> Check {
        row.continuum
    }

    fn note(_row: &BeamCompared) {}

    /// w(L) against (V2), X in elements of the mesh.
    fn verdict(row: &BeamCompared) -> RowVerdict<BeamZones> {
        let mesh = row.macroslip_start_mesh;
        RowVerdict::new(
            &force_label(row.fe.force),
            ("w(L)", row.difference_shear_corrected(), row.envelope()),
            &mesh.iter().map(|m| ("X", m)).collect::<Vec<_>>(),
            BeamZones {
                zone_end_elements: mesh.map(|m| m.elements),
                zone_end_within_resolution: mesh.map(|m| m.within_resolution()),
            },
        )
    }

    fn table_text(report: &BeamCompareReport) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "FE results ({}) vs the closed forms: twin beams, K_T = {} MPa/mm\n\
             w(L) in mm; E-B: Euler-Bernoulli (the paper's closed form); +shear: plus each beam's shear\n\
             deflection F L / (kappa G b 2h), kappa = 5/6, G = E / (2 (1 + nu)), nu = {}; X (mm): start of\n\
             the macroslip zone, from the clamp (FE: where K_T |slip| = mu P).\n",
            sanitize(&report.results),
            number(report.head.stiffness),
            Compact(report.head.nu)
        );
        let _ = writeln!(
            out,
            "{:>8} {:>11} {:>11} {:>9} {:>11} {:>9}  {:>9} {:>9}  regime (closed form / FE)",
            "F (N)", "w FE", "w E-B", "diff", "w +shear", "diff", "X FE", "X"
        );
        for r in &report.rows {
            let row = &r.row;
            let _ = writeln!(
                out,
                "{:>8} {:>11} {:>11} {:>9} {:>11} {:>9}  {:>9} {:>9}  {} / {}",
                number(row.force),
                number(row.w_fe_mm),
                number(row.w_euler_mm),
                percent_or_na(row.diff_euler),
                number(row.w_shear_corrected_mm),
                percent_or_na(row.diff_shear_corrected),
                optional(row.macroslip_start_fe),
                number(row.macroslip_start),
                row.regime,
                row.regime_fe.unwrap_or("-")
            );
        }
        if report.rows.iter().any(|r| r.row.diff_euler.is_none()) {
            let _ = writeln!(out, "{UNDEFINED_NOTE}");
        }
        if report
            .rows
            .iter()
            .any(|r| r.verdict.zones.zone_end_elements.is_some())
        {
            let _ = writeln!(
                out,
                "\nPer load step: w(L) +shear against its envelope for the run's kinematics (docs/theory.md\n\
                 (V2) with NLGEOM, (V2L) in linear geometry: the kinematics line below names it); X against the\n\
                 closed form's in elements of the deck's mesh along the interface (under one: within what\n\
                 the mesh resolves, the FE X being interpolated between nodes)."
            );
        } else {
            let _ = writeln!(
                out,
                "\nPer load step: w(L) +shear against its envelope for the run's kinematics (docs/theory.md\n\
                 (V2) with NLGEOM, (V2L) in linear geometry: the kinematics line below names it); X is not\n\
                 judged (the results carry no slip profile and no mesh)."
            );
        }
        out
    }

    /// What the FE points imply: the fit of mu and K_T, or why there is none.
    fn tail_text(report: &BeamCompareReport) -> String {
        let mut out = String::from("\n");
        match &report.tail.implied {
            ImpliedReport::Fit {
                stiffness,
                stiffness_status,
                stiffness_std_error,
                mu,
                mu_status,
                rms_mm,
                degrees_of_freedom,
            } => {
                let exact = if *degrees_of_freedom == 0 {
                    " (0 by construction: no degree of freedom left)"
                } else {
                    ""
                };
                let error =
                    stiffness_std_error.map_or_else(String::new, |e| format!(" +- {}", number(e)));
                let _ = writeln!(
                    out,
                    "What the FE points imply (fit of mu and K_T to w(L) less the shear deflection):\n  \
                     K_T = {}{error} MPa/mm ({stiffness_status}; the closed forms used {}), mu = {} \
                     ({mu_status}), RMS {} mm{exact}",
                    number(*stiffness),
                    number(report.head.stiffness),
                    number(*mu),
                    number(*rms_mm)
                );
            }
            ImpliedReport::Error { error } => {
                let _ = writeln!(out, "No K_T implied: {error}");
            }
        }
        out
    }
}

/// The closing verdict of the beams: w(L) against (V2) and X on the mesh at every load step, and
/// the deck's K_T against the one the FE points imply.
pub fn beam_summary(comparison: &BeamComparison) -> Summary {
    let tally = Tally::of(
        comparison
            .rows
            .iter()
            .map(|r| (number(r.fe.force), r.envelope(), r.macroslip_start_mesh)),
    );
    // X is the benchmark's second quantity: (V2)'s X is meant to match the continuum's.
    let names = Names {
        what: "w(L)",
        zone: "X",
        zone_bounded: true,
        at: "F =",
        unit: "N",
        steps: "load steps",
    };
    let stiffness = comparison.stiffness_match();
    let deck = number(comparison.stiffness);
    let stiffness_clause = match stiffness {
        StiffnessMatch::Matches { z } => {
            format!(
                "implied K_T matches the deck's {deck} MPa/mm (z = {})",
                z_words(z)
            )
        }
        StiffnessMatch::DoesNotMatch { z } => format!(
            "implied K_T does not match the deck's {deck} MPa/mm (z = {})",
            z_words(z)
        ),
        StiffnessMatch::NoStandardError => {
            "implied K_T not judged (the fit has no positive standard error)".to_string()
        }
        StiffnessMatch::UncertaintyUnknown { points, parameters } => format!(
            "implied K_T not judged (uncertainty unknown: {} = {})",
            count_of(points, "loaded point"),
            count_of(parameters, "parameter")
        ),
        StiffnessMatch::ClosedFormDoesNotHold => "implied K_T not judged (the beam theory's \
            envelope exceeds 2 % at some step: the fit would measure the theory)"
            .to_string(),
        StiffnessMatch::ClosedFormNotCalibrated => "implied K_T not judged (the beam theory's \
            envelope is not calibrated at some step: its friction strain mu P L / (2 E h) is beyond \
            the measured range, docs/theory.md (V2))"
            .to_string(),
        StiffnessMatch::NotImplied => "no K_T implied".to_string(),
    };
    let (opening, agrees) = opening(
        tally.disagrees(&names) || matches!(stiffness, StiffnessMatch::DoesNotMatch { .. }),
        &tally,
    );
    let mut clauses = tally.clauses(&names);
    clauses.push(stiffness_clause);
    let mut short = tally.short(&names);
    if let Ok(fit) = &comparison.implied {
        short.push_str(&format!(", K_T {}", number_with(fit.kt.value, 4)));
        if let Some(z) = stiffness.z() {
            short.push_str(&format!(": z = {}", z_words(z)));
        }
    }
    Summary {
        agrees,
        summary: format!("Verdict: {opening}. {}.", clauses.join("; ")),
        stiffness: Some(stiffness),
        stiffness_z: Some(stiffness.z()),
        short: format!("{opening} ({short})"),
    }
}

impl CompareFace for TwinBeamsProblem {
    const ONE_RUN: Option<&'static str> =
        Some("compare beam takes one result file (all load steps of one run)");
    type Checked = BeamComparison;
    type CompareRow = BeamCompareRow;
    type CompareReport = BeamCompareReport;

    fn checked(compared: BeamComparison) -> Result<BeamComparison, ParamError> {
        Ok(compared)
    }

    /// One run's comparison: `more` is empty ([`CompareFace::ONE_RUN`]).
    fn compare_report(
        source: &str,
        first: BeamComparison,
        _more: Vec<BeamComparison>,
    ) -> (BeamCompareReport, Vec<BeamCompareRow>) {
        let report = beam_compare_report(source, &first);
        let rows = report.csv_rows();
        (report, rows)
    }

    fn compare_text(report: &BeamCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut BeamCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    fn ladder_quantities(report: &Self::CompareReport) -> Vec<crate::fe::ladder::LadderQuantity> {
        report.ladder_quantities()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::twin_beams::params::TwinBeamsParams;

    #[test]
    fn closed_form_points_compare_to_zero_and_imply_their_own_stiffness() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let truth = TwinBeams::new(TwinBeamsParams {
            tangential_stiffness: 300.0,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        // "FE" points made of another K_T's closed form plus the shear deflection.
        let points: Vec<BeamFePoint> = [40.0, 60.0, 80.0, 100.0, 150.0, 200.0]
            .map(|f| {
                let force = TipForce::new(f).unwrap();
                BeamFePoint {
                    force: f,
                    deflection: truth.regularized(force).tip_deflection()
                        + truth.shear_deflection(force),
                    interface: None,
                }
            })
            .to_vec();
        let same = compare_beams(&truth, &points, None);
        for row in &same.rows {
            assert!(row.difference_shear_corrected().unwrap().abs() < 1e-12);
            assert!(
                row.difference_euler().unwrap() > 0.0,
                "shear adds deflection"
            );
        }
        let other = compare_beams(&beams, &points, None);
        let fit = other.implied.unwrap();
        assert!(
            (fit.kt.value / 300.0 - 1.0).abs() < 1e-4,
            "{}",
            fit.kt.value
        );
        assert!((fit.mu.value / 0.3 - 1.0).abs() < 1e-4, "{}", fit.mu.value);
    }
}
