//! How the squeezed plate shows on the terminal screen beside its charts (its [`PaneFace`]): the
//! regime pane's lines with its own 2-D continuum solve (u(L) and the edge pressure, on a
//! worker) and the strip theory's validity, and the K_T table's row.

use super::compare::{PlateCompared, compare_plate, plate_summary as closing_verdict};
use super::fe_points::PlateFePoint;
use super::params::PlateParams;
use super::validity::PlateValidity;
use super::{ContinuumMesh, SqueezedPlateProblem, solve_plate_continuum};
use crate::SqueezedPlate;
use crate::chart::panes::{
    ContinuumState, ContinuumSummary, PaneContinuum, PaneFace, RATIO_MEANING, SATURATION_MEANING,
    SummaryLine, TABLE_TOLERANCE, ratio_text, shown,
};
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::kernel::validity::Validity;
use crate::problems::stiffness::mm_to_um;
use crate::report::compare::{percent, percent_or_na};
use crate::study::curves::plate_point;
use crate::study::tolerance::state_stiffness_for_tolerance;

/// The regime pane's continuum: the plane-strain solve on the default mesh, u(L) averaged
/// through the thickness and the edge pressure.
fn pane_continuum(plate: &SqueezedPlate) -> Result<ContinuumSummary, String> {
    solve_plate_continuum(plate.params(), ContinuumMesh::default())
        .map(|plate| ContinuumSummary {
            end_displacement: plate.end_displacement_mean,
            edge_pressure: plate.edge_pressure_ratio,
        })
        .map_err(|e| e.to_string())
}

impl PaneFace for SqueezedPlateProblem {
    const STRIP_ORIGIN: &'static str = "centre";
    const PANE_CONTINUUM: Option<PaneContinuum<SqueezedPlate>> = Some(pane_continuum);
    const KT_COLUMNS: &'static [(&'static str, usize)] = &[("u(L) mm", 9), ("X_r mm", 8)];

    fn parameters_title(_params: &Self::Params) -> String {
        "Squeezed plate".to_string()
    }

    fn summary_lines(plate: &Self::Model, continuum: &ContinuumState) -> Vec<SummaryLine> {
        let row = plate_point(plate);
        let ratio = ratio_text(row.u_regularized, row.u_coulomb, "-");
        let onset = match plate.macroslip_onset_stiffness() {
            Some(kt) => format!("macroslip K_T > {} MPa/mm", number(kt)),
            None => "no macroslip at any K_T".into(),
        };
        let mut lines = vec![
            SummaryLine::regime(
                "Coulomb",
                row.regime_coulomb.to_string(),
                "plain Coulomb law: stick near the centre, sliding (macroslip) near the free end",
            ),
            SummaryLine::regime(
                "regularized",
                row.regime_regularized.to_string(),
                "regularized law: microslip = every point slips elastically; +macroslip = \
                     the part near the free end slides at mu P",
            ),
            SummaryLine::plain(
                format!("X_s = {} mm stick end", number(row.stick_end)),
                "Coulomb law: the plate sticks from the centre (x = 0) to X_s, slides beyond",
            ),
            SummaryLine::plain(
                format!("X_r = {} mm microslip end", number(row.micro_end)),
                "regularized law: microslip from the centre to X_r, macroslip beyond; \
                     X_r = L: no macroslip",
            ),
            SummaryLine::plain(
                onset,
                "the K_T above which macroslip appears at the free end (closed form, \
                     theory (P11)): the plate's F_1",
            ),
            SummaryLine::plain(
                format!("u(L) Coulomb {} mm", number(row.u_coulomb)),
                "displacement of the free end under the plain Coulomb law",
            )
            .dropped(3),
            SummaryLine::plain(
                format!("u(L) regularized {} mm", number(row.u_regularized)),
                "displacement of the free end under the regularized law",
            ),
            SummaryLine::plain(format!("ratio to Coulomb {ratio}"), RATIO_MEANING),
        ];
        let continuum_line = match continuum {
            ContinuumState::Off => None,
            ContinuumState::Solving => Some("u(L) 2-D FE: solving...".to_string()),
            // Three digits and a whole percent above 10 %: the line fits the 80-column pane.
            ContinuumState::Solved(solved) if row.u_regularized > 0.0 => {
                let u = solved.end_displacement;
                let off = 100.0 * (u / row.u_regularized - 1.0);
                let digits = if off.abs() >= 10.0 { 0 } else { 1 };
                Some(format!(
                    "u(L) 2-D FE {} mm ({off:+.digits$} %)",
                    number_with(u, 3)
                ))
            }
            ContinuumState::Solved(solved) => Some(format!(
                "u(L) 2-D FE {} mm",
                number_with(solved.end_displacement, 3)
            )),
            // The reason, in the words the line has room for (the whole of it in i's text
            // would need the pane's lines to own their meanings).
            ContinuumState::Failed(reason) if reason.contains("too stiff") => {
                Some("u(L) 2-D FE: K_T too stiff".to_string())
            }
            ContinuumState::Failed(_) => Some("u(L) 2-D FE: not converged".to_string()),
        };
        lines.extend(continuum_line.map(|text| {
            SummaryLine::plain(
                text,
                "the project's plane-strain continuum FE (2-D, 4 layers, contact pressure \
                     solved): u(L) averaged through the thickness, the best answer here; in % \
                     against the strip theory's regularized u(L). None when K_T is too stiff \
                     for it (alpha t_p > 20) or it does not converge",
            )
        }));
        lines.extend([
            SummaryLine::plain(
                format!(
                    "saturation slip {} um",
                    number(mm_to_um(plate.saturation_slip()))
                ),
                SATURATION_MEANING,
            )
            .dropped(1),
            SummaryLine::plain(
                pressure_words(plate, continuum),
                "contact pressure: the plane-strain continuum's (microslip plate --continuum) \
                     is flat away from the free end and peaks at it; once solved, this line gives \
                     its peak, the mean over the last t_p/10 (the corner node itself grows with \
                     every refinement). The paper's flat-plate model (P7-P9, friction saturated \
                     everywhere), shown until then, is right only for the mean over the last t_p \
                     where the slip zone is at least t_p long (theory (P12))",
            ),
            SummaryLine::plain(
                format!("strip theory {}", strip_validity_short(&plate.validity())),
                "the closed forms treat the plate as a strip (u uniform through t_p); this \
                     says how far a 2-D continuum's thickness-mean u(L) differs (V1); the contact \
                     face and mid-thickness have their own bounds (microslip plate), X_r none",
            ),
        ]);
        lines
    }

    fn kt_values(plate: &Self::Model, kt: f64) -> Option<Vec<f64>> {
        let state = plate.with_tangential_stiffness(kt).ok()?.regularized();
        Some(vec![state.end_displacement(), state.micro_zone_end()])
    }

    fn kt_tolerance_lines(plate: &Self::Model, within: &str, element: f64) -> Vec<String> {
        vec![format!(
            "u(L) {within} {}",
            shown(state_stiffness_for_tolerance::<SqueezedPlateProblem>(
                plate,
                TABLE_TOLERANCE,
                element
            ))
        )]
    }

    fn fe_xy(point: &PlateFePoint) -> (f64, f64) {
        (point.stiffness, point.end_displacement)
    }

    /// The first run's (a plate's results are one run per K_T).
    fn fe_brief(
        plate: &Self::Model,
        loaded: &Loaded<PlateFePoint>,
        code: &str,
    ) -> Result<String, String> {
        let rows = compare_plate(plate, &loaded.points, loaded.interface_mesh.as_ref());
        Ok(rows
            .first()
            .map(|row| plate_summary(code, row))
            .unwrap_or_default())
    }

    /// Runs of one deck but for K_T: the points of u(L) against K_T.
    fn same_curve(a: &Self::Params, b: &Self::Params) -> bool {
        PlateParams {
            tangential_stiffness: b.tangential_stiffness,
            ..*a
        } == *b
    }
}

/// The regime pane's contact-pressure line: the continuum's free-end peak (mean over the last
/// t_p / 10) once solved, else the flat model's mean over the last t_p where it was measured right
/// (slip zone >= t_p), else where the plate's pressure is found.
fn pressure_words(plate: &SqueezedPlate, continuum: &ContinuumState) -> String {
    if let ContinuumState::Solved(solved) = continuum {
        return format!(
            "contact P 2-D: {} P at end",
            number_with(solved.edge_pressure, 3)
        );
    }
    plate.end_layer_pressure().map_or_else(
        || "contact P: 2-D only".to_string(),
        |mean| format!("P last t_p ~{} P (flat)", number_with(mean, 3)),
    )
}

/// The strip theory's validity in a few words (TUI regime pane, one line of 30 characters), for
/// the thickness-mean u(L): "mean holds (~1.6 %)", "mean approx. (~5.2 %)", "mean OUTSIDE",
/// "not calibrated". The number is the expected difference from a plane-strain continuum, (V1).
fn strip_validity_short(v: &PlateValidity) -> String {
    let e = v.expected_error();
    match v.validity {
        Validity::Holds => format!("mean holds (~{} %)", percent_of(e)),
        Validity::Approximate => format!("mean approx. (~{} %)", percent_of(e)),
        Validity::Outside => format!("mean OUTSIDE (>{} %)", 100.0 * Validity::APPROXIMATE),
        Validity::NotCalibrated => "not calibrated".to_string(),
        Validity::MeasuredWrong => format!(
            "mean WRONG (>{} %)",
            v.measured_at_least
                .map_or_else(|| "-".to_string(), |e| number_with(100.0 * e, 2))
        ),
    }
}

fn percent_of(error: Option<f64>) -> String {
    error.map_or_else(|| "-".to_string(), |e| number_with(100.0 * e, 2))
}

/// One line for the TUI's status: one plate run in brief, the verdict first.
fn plate_summary(code: &str, row: &PlateCompared) -> String {
    let through = row
        .differences_through_thickness()
        .map_or(String::new(), |[face, mid]| {
            format!("; face {}, mid {}", percent(face), percent(mid))
        });
    format!(
        "{code} at K_T = {} MPa/mm: {}; u(L) {} mm, strip theory {} mm ({}{through})",
        number(row.fe.stiffness),
        closing_verdict(std::slice::from_ref(row)).short,
        number(row.fe.end_displacement),
        number(row.closed),
        percent_or_na(row.difference())
    )
}
