//! How the press fit shows on the terminal screen beside its charts (its [`PaneFace`]): the
//! regime pane's lines (Lamé's pressure, the thresholds and the face that slides first, both
//! laws' Delta and zones, a cycle's damping), the 1-D theory's standing in its title, the K_T
//! table's row.

use super::PressFitProblem;
use super::closed_form::{CarriedLoad, PressFit};
use super::cycle::FitCycle;
use super::point::fit_point;
use super::registered::problem::PressFitModel;
use super::validity::{CALIBRATED, PressFitValidity};
use crate::chart::panes::{
    ContinuumState, KT_UM_MEANING, PaneFace, RATIO_MEANING, SummaryLine, envelope_title,
    load_regimes, load_tolerance_lines, ratio_text,
};
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::problems::load_driven::MasingCycle;
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};

impl PaneFace for PressFitProblem {
    const STRIP_ORIGIN: &'static str = "loaded face";
    /// The strip divides the shear by the interface's `friction * pressure`: mu p, Lamé's p.
    const STRIP_SHEAR: &'static str = "tau(x) / mu p";
    const KT_COLUMNS: &'static [(&'static str, usize)] =
        &[("F_1 N", 7), ("a+d mm", 7), ("Delta um", 8)];

    fn parameters_title(_params: &Self::Params) -> String {
        "Press fit (pushed out)".to_string()
    }

    /// The pane is full at 80x24, so the 1-D theory's envelope goes in the title, as the lap
    /// joint's does.
    fn title_line(model: &PressFitModel) -> Option<SummaryLine> {
        let v = model.fit.validity(model.force);
        Some(SummaryLine::plain(
            envelope_title(v.validity, v.expected_error),
            "how far an axisymmetric continuum (FE) of this fit is expected from the Delta shown: \
             the 1-D theory's envelope (docs/theory.md (S10), measured on 135 steel fits, held \
             out on 24). 'FE: >10 %, n solves': outside its envelope, n draws the continuum; \
             'not calibrated': no measured fit is like this one (short fits, L < 2 r, were off \
             by up to 68 %)",
        ))
    }

    fn summary_lines(model: &PressFitModel, _continuum: &ContinuumState) -> Vec<SummaryLine> {
        fit_lines(&model.fit, model.force)
    }

    fn kt_values(model: &PressFitModel, kt: f64) -> Option<Vec<f64>> {
        let fit = model.fit.with_tangential_stiffness(kt).ok()?;
        let state = fit.regularized(model.force);
        Some(vec![
            fit.first_slip_force(),
            state.slide_from_loaded_face() + state.slide_from_held_face(),
            mm_to_um(state.response()),
        ])
    }

    fn kt_tolerance_lines(model: &PressFitModel, within: &str, element: f64) -> Vec<String> {
        load_tolerance_lines::<Self>(&model.fit, model.force.value(), within, element)
    }

    fn fe_xy(point: &Self::FePoint) -> (f64, f64) {
        super::compare::pane_xy(point)
    }

    fn fe_brief(
        model: &PressFitModel,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String> {
        super::compare::pane_brief(model, loaded, code)
    }
}

/// The press fit's lines of the regime pane: Delta right after the regimes, so that an 80x24
/// screen, which shows the first five, shows it.
fn fit_lines(fit: &PressFit, force: CarriedLoad) -> Vec<SummaryLine> {
    let row = fit_point(fit.axial(), force);
    let p = fit.params();
    let ratio = ratio_text(row.delta_regularized, row.delta_coulomb, "- (no load)");
    let (coulomb, regularized, heading) = load_regimes(
        row.force,
        "push-out",
        || row.regime_coulomb.short_label().to_string(),
        || row.regime_regularized.short_label().to_string(),
    );
    let cycle = FitCycle::new(fit.axial(), Law::Regularized, force);
    let (a, d) = row.zones_regularized;
    let saturation = p.friction * fit.contact_pressure() / p.tangential_stiffness;
    vec![
        SummaryLine::plain(
            heading,
            "the axial force on the shaft's end face x = 0, the hub held on its far face x = L; \
             every line below is at this force",
        ),
        SummaryLine::regime(
            "Coulomb",
            coulomb,
            "plain Coulomb law: the loaded face slides from the first newton, the rest sticks",
        ),
        SummaryLine::regime(
            "regularized",
            regularized,
            "regularized law, zones from x = 0 (the shaft's loaded face) to x = L (the hub's held \
             face): micro(slip) = elastic slip below mu p; macro(slip) = sliding at mu p",
        ),
        SummaryLine::plain(
            format!(
                "Delta regularized {} um",
                number(mm_to_um(row.delta_regularized))
            ),
            "the shaft's loaded end relative to the hub's held face under the regularized law: \
             what a dial gauge between shaft end and hub support reads",
        ),
        SummaryLine::plain(
            format!(
                "p {} MPa (strain {})",
                number_with(fit.contact_pressure(), 4),
                number_with(fit.plane_strain_pressure(), 4)
            ),
            "Lamé's contact pressure of the interference, in plane stress (what every number \
             here uses: short members with free faces), and in plane strain (long members)",
        )
        .dropped(3),
        SummaryLine::plain(
            format!(
                "F_1 {} N: {} slides",
                number(fit.first_slip_force()),
                fit.first_slip_face().key()
            ),
            "regularized law: sliding starts above F_1 at the face where the more compliant \
             member carries the load (x=0: the shaft, x=L: the hub)",
        ),
        SummaryLine::plain(
            format!("F_2 {} N: both slide", number(fit.second_slip_force())),
            "regularized law: above F_2 the other face slides too",
        )
        .dropped(4),
        SummaryLine::plain(
            format!("F_gross {} N: all slides", number(fit.gross_slip_force())),
            "mu p 2 pi r L: the whole fit slides and the shaft comes out; no larger force is \
             carried (F is refused above it)",
        )
        .dropped(6),
        SummaryLine::plain(
            format!("a {} d {} mm sliding", number_with(a, 3), number_with(d, 3)),
            "regularized law: the sliding zones, a from x = 0 (the loaded face), d from x = L \
             (the held face)",
        ),
        SummaryLine::plain(
            format!("Delta Coulomb {} um", number(mm_to_um(row.delta_coulomb))),
            "the shaft's loaded end relative to the hub's held face under plain Coulomb",
        )
        .dropped(3),
        SummaryLine::plain(format!("ratio to Coulomb {ratio}"), RATIO_MEANING).dropped(5),
        SummaryLine::plain(
            format!(
                "D {} N mm zeta {}",
                number_with(cycle.dissipation(), 3),
                number_with(cycle.damping_ratio(), 3)
            ),
            "a push cycling between +F and -F (regularized law): energy dissipated per cycle D \
             and the equivalent damping ratio D / (4 pi U), U = F Delta / 2",
        ),
        SummaryLine::plain(
            format!("saturation slip {} um", number(mm_to_um(saturation))),
            "mu p / K_T: the elastic slip at which the regularized law reaches the friction \
             stress mu p and the interface slides",
        )
        .dropped(2),
        SummaryLine::plain(
            format!(
                "K_T = {} MPa/um",
                number(mpa_per_mm_to_mpa_per_um(p.tangential_stiffness))
            ),
            KT_UM_MEANING,
        )
        .dropped(1),
        SummaryLine::plain(
            format!("1-D theory {}", theory_words(&fit.validity(force))),
            "the closed forms take Lamé's pressure uniform over L and each member's section \
             strained uniformly; this bounds how far an axisymmetric continuum's Delta differs \
             (docs/theory.md (S10)); where it fails, n draws the continuum (microslip pressfit \
             --continuum)",
        )
        .dropped(1),
    ]
}

/// The envelope's level in a few words, for the regime pane's line: the calibrated range the fit
/// leaves, where it leaves one.
fn theory_words(v: &PressFitValidity) -> String {
    match v.outside_calibration {
        Some(why) => {
            let group = CALIBRATED
                .iter()
                .find(|(_, _, _, words)| *words == why)
                .map_or("range", |(name, ..)| name);
            format!("uncalibrated ({group})")
        }
        None => v.validity.label().to_string(),
    }
}
