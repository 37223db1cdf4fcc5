//! How the double-lap joint shows on the terminal screen beside its charts (its [`PaneFace`]):
//! the regime pane's lines and its shear-lag envelope title, the K_T table's row, the measured
//! curve `d` reads (`F_N,Delta_mm`) and what `f` fits.

use super::LapJointProblem;
use super::LapValidity;
use super::closed_form::{FirstSlip, JointForce, LapJoint};
use super::compare::{LapCompared, compare_lap, lap_summary as closing_verdict};
use super::cycle::{LapCycle, MasingCycle};
use super::fe_points::LapFePoint;
use crate::chart::panes::{
    ContinuumState, KT_UM_MEANING, PaneFace, RATIO_MEANING, SATURATION_MEANING, SummaryLine,
    envelope_title, load_regimes, load_tolerance_lines, ratio_text,
};
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};
use crate::report::compare::percent_range;
use crate::study::curves::lap_point;

impl PaneFace for LapJointProblem {
    const STRIP_ORIGIN: &'static str = "inner end";
    const KT_COLUMNS: &'static [(&'static str, usize)] =
        &[("F_1 N", 7), ("a+d mm", 7), ("Delta mm", 8)];

    fn parameters_title(_params: &Self::Params) -> String {
        "Double-lap joint".to_string()
    }

    /// The joint's pane is full at 80x24, so its envelope goes in the title, as the beams' does.
    fn title_line(model: &Self::Model) -> Option<SummaryLine> {
        let (joint, force) = (&model.joint, &model.force);
        Some(SummaryLine::plain(
            validity_title(&joint.validity(*force)),
            "how far a 2-D plane-stress continuum (FE) of this joint is expected from the Delta \
             shown: the shear-lag theory's envelope at this force (docs/theory.md (L14)). \
             'FE: >10 %, n solves': the theory is outside its envelope, n draws the continuum; \
             'not calibrated': no measured joint is like this one",
        ))
    }

    fn summary_lines(model: &Self::Model, _continuum: &ContinuumState) -> Vec<SummaryLine> {
        lap_lines(&model.joint, model.force)
    }

    fn kt_values(model: &Self::Model, kt: f64) -> Option<Vec<f64>> {
        let joint = model.joint.with_tangential_stiffness(kt).ok()?;
        let state = joint.regularized(model.force);
        Some(vec![
            joint.first_slip_force(),
            state.slide_at_inner_end() + state.slide_at_cover_ends(),
            state.joint_displacement(),
        ])
    }

    fn kt_tolerance_lines(model: &Self::Model, within: &str, element: f64) -> Vec<String> {
        load_tolerance_lines::<Self>(&model.joint, model.force.newtons(), within, element)
    }

    fn fe_xy(point: &LapFePoint) -> (f64, f64) {
        (point.force, point.joint_displacement)
    }

    fn fe_brief(
        model: &Self::Model,
        loaded: &Loaded<LapFePoint>,
        code: &str,
    ) -> Result<String, String> {
        compare_lap(&model.joint, &loaded.points, loaded.interface_mesh.as_ref())
            .map(|rows| lap_summary(code, &rows))
            .map_err(|e| e.to_string())
    }
}

/// The lap joint's lines of the regime pane.
fn lap_lines(joint: &LapJoint, force: JointForce) -> Vec<SummaryLine> {
    let row = lap_point(joint, force);
    let ratio = ratio_text(row.delta_regularized, row.delta_coulomb, "- (no load)");
    let (coulomb, regularized, heading) = load_regimes(
        row.force,
        ("F", "N"),
        "joint force",
        || row.regime_coulomb.short_label().to_string(),
        || row.regime_regularized.short_label().to_string(),
    );
    let cycle = LapCycle::new(joint, Law::Regularized, force);
    let (a, d) = row.zones_regularized;
    let end = match joint.first_slip() {
        FirstSlip::InnerEnd => "x=0",
        FirstSlip::CoverEnds => "x=L",
        FirstSlip::BothEnds => "both ends",
    };
    vec![
        SummaryLine::plain(
            heading,
            "the force through the joint (each interface carries half); every line below is at \
             this force",
        ),
        SummaryLine::regime(
            "Coulomb",
            coulomb,
            "plain Coulomb law: both ends slide from the first newton (macroslip), the middle \
             sticks and carries no shear",
        ),
        SummaryLine::regime(
            "regularized",
            regularized,
            "regularized law, zones from x = 0 (the inner plate's end) to x = L (the covers' \
             ends): micro(slip) = elastic slip below mu P; macro(slip) = sliding at mu P",
        ),
        SummaryLine::plain(
            format!("F_1 {} N: {end} slides", number(joint.first_slip_force())),
            "regularized law: sliding starts above F_1 at the end where the more compliant \
             member carries the load (x = L: the inner plate, x = 0: the covers)",
        ),
        SummaryLine::plain(
            format!("F_2 {} N: both slide", number(joint.second_slip_force())),
            "regularized law: above F_2 the other end slides too",
        )
        .dropped(4),
        SummaryLine::plain(
            format!("F_gross {} N: all slides", number(joint.gross_slip_force())),
            "2 b mu P L: both interfaces slide over the whole overlap; the joint carries no more \
             (F is refused above it)",
        )
        .dropped(6),
        SummaryLine::plain(
            format!("a {} d {} mm sliding", number_with(a, 3), number_with(d, 3)),
            "regularized law: the sliding zones, a from x = 0 (inner plate's end), d from x = L \
             (covers' ends)",
        ),
        SummaryLine::plain(
            format!("Delta Coulomb {} mm", number(row.delta_coulomb)),
            "joint displacement u_inner(L) - u_cover(0) under the plain Coulomb law",
        )
        .dropped(3),
        SummaryLine::plain(
            format!("Delta regularized {} mm", number(row.delta_regularized)),
            "joint displacement u_inner(L) - u_cover(0) under the regularized law: what an \
             extensometer across the overlap reads",
        ),
        SummaryLine::plain(format!("ratio to Coulomb {ratio}"), RATIO_MEANING).dropped(5),
        SummaryLine::plain(
            format!(
                "D {} N mm zeta {}",
                number_with(cycle.dissipation(), 3),
                number_with(cycle.damping_ratio(), 3)
            ),
            "a force cycling between +F and -F (regularized law): energy dissipated per cycle D \
             and the equivalent damping ratio D / (4 pi U), U = F Delta / 2",
        ),
        SummaryLine::plain(
            format!(
                "saturation slip {} um",
                number(mm_to_um(joint.saturation_slip()))
            ),
            SATURATION_MEANING,
        )
        .dropped(2),
        SummaryLine::plain(
            format!(
                "K_T = {} MPa/um",
                number(mpa_per_mm_to_mpa_per_um(
                    joint.params().tangential_stiffness
                ))
            ),
            KT_UM_MEANING,
        )
        .dropped(1),
        SummaryLine::plain(
            format!(
                "shear lag {}",
                lap_validity_words(&joint.validity_at(force, row.delta_regularized))
            ),
            "the closed forms strain each plate uniformly through its thickness under a contact \
             pressure P; this bounds how far a 2-D continuum's Delta differs (docs/theory.md \
             (L14), measured against CalculiX on 22 joints; the title gives the bound); where \
             it fails, n draws the continuum (microslip lap --continuum)",
        )
        .dropped(1),
    ]
}

/// The envelope's level in a few words, for the regime pane's line.
fn lap_validity_words(v: &LapValidity) -> String {
    match v.outside_calibration {
        Some(_) => "not calibrated".to_string(),
        None => v.validity.label().to_string(),
    }
}

/// The shear-lag theory's envelope in the lap joint's regime-pane title ((L14)).
fn validity_title(v: &LapValidity) -> String {
    envelope_title(v.validity, v.expected_error)
}

/// One line for the TUI's status: the lap joint's comparison in brief, the verdict first.
fn lap_summary(code: &str, rows: &[LapCompared]) -> String {
    format!(
        "{code}, {} points: {}; Delta {} vs shear lag",
        rows.len(),
        closing_verdict(rows).short,
        percent_range(rows.iter().map(LapCompared::difference))
    )
}
