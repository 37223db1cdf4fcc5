//! How the Hertzian cylinder shows on the terminal screen beside its charts (its [`PaneFace`]):
//! Hertz's contact, both laws' c and s(a), the K_T table's row.

use super::deck::{CylinderCompared, compare_cylinder};
use super::point::cylinder_point;
use super::problem::{CylinderModel, CylinderProblem};
use super::validity::{
    LEAST_BODY_OVER_HALF_WIDTH, MEASURED_HALF_WIDTH_OVER_RADIUS, MEASURED_STIFFNESS_GROUP,
    ZONE_WITHIN,
};
use crate::chart::panes::{
    ContinuumState, KT_UM_MEANING, PaneFace, RATIO_MEANING, SummaryLine, TABLE_TOLERANCE,
    ratio_text, shown,
};
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};
use crate::study::tolerance::state_stiffness_for_tolerance;

use super::cycle::CylinderCycle;
use super::deck::CylinderFePoint;
use crate::kernel::regime::Law;
use crate::problems::load_driven::MasingCycle;

impl PaneFace for CylinderProblem {
    const STRIP_ORIGIN: &'static str = "centre";
    /// The strip divides the shear by the interface's `friction * pressure`, mu p0 here (the
    /// peak pressure, `problem.rs`'s `interface`); the strength mu p(x) falls to 0 at the edges.
    const STRIP_SHEAR: &'static str = "q(x) / mu p0";
    const KT_COLUMNS: &'static [(&'static str, usize)] =
        &[("KTa/E*", 7), ("c mm", 8), ("s(a) mm", 9)];

    fn parameters_title(_params: &Self::Params) -> String {
        "Hertzian cylinder (P, Q N/mm)".to_string()
    }

    /// The half-plane answer's envelope in the regime pane's title, as the lap joint's: "FE
    /// within 4 %" (s(a) against a finite-body CalculiX model), "FE: not calibrated" outside it.
    fn title_line(model: &CylinderModel) -> Option<SummaryLine> {
        let v = model.cylinder.validity();
        Some(SummaryLine::plain(
            match v.edge_slip_within {
                Some(e) => format!("FE within {} %", number_with(100.0 * e, 2)),
                None => "FE: not calibrated".to_string(),
            },
            format!(
                "how far a converged FE model (bodies at least {} a wide and deep) is expected \
                 from the half-plane s(a) shown (c: within {} % of a): the envelope measured \
                 against converged CalculiX ladders over K_T a/E* {}-{} and a/R up to {} \
                 (docs/theory.md section 16); 'not calibrated': outside it",
                number(LEAST_BODY_OVER_HALF_WIDTH),
                number(100.0 * v.zone_within.unwrap_or(ZONE_WITHIN)),
                number(MEASURED_STIFFNESS_GROUP.0),
                number(MEASURED_STIFFNESS_GROUP.1),
                number(MEASURED_HALF_WIDTH_OVER_RADIUS),
            ),
        ))
    }

    fn summary_lines(model: &CylinderModel, _continuum: &ContinuumState) -> Vec<SummaryLine> {
        let row = cylinder_point(&model.cylinder, model.load);
        let p = model.cylinder.params();
        let (mindlin, regularized) = (
            CylinderCycle::new(&model.cylinder, Law::Coulomb, model.load),
            CylinderCycle::new(&model.cylinder, Law::Regularized, model.load),
        );
        vec![
            SummaryLine::plain(
                format!("at Q {} N/mm", number(row.load)),
                "the tangential line load (N per mm of the cylinder's length), applied after P; \
                 every line below is at it",
            ),
            SummaryLine::regime(
                "Mindlin",
                row.regime_coulomb.to_string(),
                "plain Coulomb law (Mindlin): the centre |x| < c sticks, the edges slide at mu p",
            ),
            SummaryLine::regime(
                "regularized",
                row.regime_regularized.to_string(),
                "regularized law: |x| < c slips elastically (q = K_T s < mu p), the edges slide \
                 at mu p; with a finite K_T they slide for any Q > 0",
            ),
            SummaryLine::plain(
                format!(
                    "a {} mm p0 {} MPa",
                    number_with(row.half_width, 4),
                    number_with(row.peak_pressure, 4)
                ),
                "Hertz: contact half-width a and peak pressure p0 (two half-planes of one \
                 material: Q leaves them unchanged)",
            ),
            SummaryLine::plain(
                format!(
                    "c {} mm c/a {}",
                    number_with(row.zone_regularized, 4),
                    number_with(row.zone_regularized / row.half_width, 3)
                ),
                "regularized law: half-width c of the zone where |q| < mu p (the microslip zone), \
                 and c over a",
            ),
            SummaryLine::plain(
                format!(
                    "c Mindlin {} mm c/a {}",
                    number_with(row.zone_coulomb, 4),
                    number_with(row.zone_coulomb / row.half_width, 3)
                ),
                "plain Coulomb law (Mindlin): the stick zone's half-width, c/a = sqrt(1 - Q/mu P)",
            )
            .dropped(3),
            SummaryLine::plain(
                format!("s(a) {} um", number(mm_to_um(row.edge_slip_regularized))),
                "regularized law: the slip at the contact's edge, the fretting slip amplitude",
            ),
            SummaryLine::plain(
                format!(
                    "s(a) Mindlin {} um",
                    number(mm_to_um(row.edge_slip_coulomb))
                ),
                "plain Coulomb law (Mindlin): the slip at the contact's edge",
            )
            .dropped(5),
            SummaryLine::plain(
                format!(
                    "ratio to Mindlin {}",
                    ratio_text(
                        row.edge_slip_regularized,
                        row.edge_slip_coulomb,
                        "- (no load)"
                    )
                ),
                RATIO_MEANING,
            )
            .dropped(6),
            SummaryLine::plain(
                format!("s(0) {} um", number(mm_to_um(row.centre_slip_regularized))),
                "regularized law: the slip at the centre (0 under Mindlin below gross slip)",
            )
            .dropped(2),
            SummaryLine::plain(
                format!(
                    "D(+-Q) {} N mm/mm",
                    number_with(regularized.dissipation(), 3)
                ),
                "regularized law: the energy dissipated per fully reversed cycle +-Q, per mm of \
                 the cylinder's length (the area of the rigid shift's loop; c shows the loops)",
            ),
            SummaryLine::plain(
                format!(
                    "D Mindlin {} N mm/mm",
                    number_with(mindlin.dissipation(), 3)
                ),
                "plain Coulomb law: Mindlin-Deresiewicz's dissipation per cycle +-Q (N mm per mm)",
            )
            .dropped(4),
            SummaryLine::plain(
                format!("K_T a/E* {}", number_with(row.stiffness_group, 3)),
                "how compliant the interface is beside the bodies: the answer depends on it and \
                 on Q/mu P only; large -> Mindlin",
            ),
            SummaryLine::plain(
                format!(
                    "Q_gross = mu P {} N/mm",
                    number(model.cylinder.gross_slip_load())
                ),
                "gross slip: the whole contact slides; no larger Q is carried",
            )
            .dropped(7),
            SummaryLine::plain(
                format!(
                    "K_T = {} MPa/um",
                    number(mpa_per_mm_to_mpa_per_um(p.tangential_stiffness))
                ),
                KT_UM_MEANING,
            )
            .dropped(1),
        ]
    }

    fn kt_values(model: &CylinderModel, kt: f64) -> Option<Vec<f64>> {
        let cylinder = model.cylinder.with_tangential_stiffness(kt).ok()?;
        let state = cylinder.regularized(model.load);
        Some(vec![
            cylinder.stiffness_group(),
            state.micro_half_width(),
            state.edge_slip(),
        ])
    }

    fn kt_tolerance_lines(model: &CylinderModel, within: &str, element: f64) -> Vec<String> {
        vec![format!(
            "s(a) {within} {}",
            shown(state_stiffness_for_tolerance::<CylinderProblem>(
                model,
                TABLE_TOLERANCE,
                element
            ))
        )]
    }

    fn fe_xy(point: &CylinderFePoint) -> (f64, f64) {
        (point.load, point.edge_slip)
    }

    fn fe_brief(
        model: &CylinderModel,
        loaded: &Loaded<CylinderFePoint>,
        code: &str,
    ) -> Result<String, String> {
        compare_cylinder(&model.cylinder, &loaded.points)
            .map(|rows| cylinder_summary(code, &rows))
            .map_err(|e| e.to_string())
    }
}

/// One line for the TUI's status: the comparison in brief.
fn cylinder_summary(code: &str, rows: &[CylinderCompared]) -> String {
    let worst = |f: &dyn Fn(&CylinderCompared) -> Option<f64>| {
        rows.iter()
            .filter_map(f)
            .map(f64::abs)
            .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))))
            .map_or_else(|| "-".to_string(), |d| format!("{:.2} %", 100.0 * d))
    };
    format!(
        "{code}, {} points: s(a) within {}, c within {} of a (half-plane at the deck's K_T)",
        rows.len(),
        worst(&CylinderCompared::edge_slip_difference),
        worst(&CylinderCompared::zone_difference)
    )
}
