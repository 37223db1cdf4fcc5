//! How the press fit shows on the terminal screen beside its charts (its [`PaneFace`]), pushed
//! out or twisted: the regime pane's lines (Lamé's pressure, the thresholds and the face that
//! slides first, both laws' response and zones, a cycle's damping), the 1-D theory's standing in
//! its title, the K_T table's row. Written once over the kind of load ([`FitKind`]); the kind
//! gives its words ([`FitPane`]).

use super::closed_form::{CarriedLoad, PressFit};
use super::cycle::FitCycle;
use super::point::fit_point;
use super::registered::problem::{
    FitKind, FitProblem, PressFitModel, PressFitProblem, PressFitTorqueProblem, PushOut, Twist,
};
use super::validity::{CALIBRATED, PressFitValidity};
use crate::chart::load::load_words;
use crate::chart::panes::{
    ContinuumState, KT_UM_MEANING, PaneFace, RATIO_MEANING, SummaryLine, envelope_title,
    load_regimes, load_tolerance_lines, ratio_text,
};
use crate::fe::face::LoadedVariant;
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::kernel::regime::Law;
use crate::problems::Problem;
use crate::problems::load_driven::MasingCycle;
use crate::problems::problem::Registered;
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};

/// What one kind of fit's regime pane says: the words that differ between the push-out and the
/// torque. The numbers, their order and the shared words are [`fit_lines`]'.
pub(crate) struct PaneWords {
    /// The parameters pane's title.
    pub parameters_title: &'static str,
    /// The K_T table's columns: the first slip load, a + d, the response in the pane's unit.
    pub kt_columns: &'static [(&'static str, usize)],
    /// The load's name in the heading (`push-out`).
    pub what: &'static str,
    /// What the heading's load is.
    pub load_meaning: &'static str,
    /// Coulomb's regime line's meaning.
    pub coulomb_meaning: &'static str,
    /// The response's name, its pane unit and the factor from its own unit to it (`Delta`,
    /// `um`, 1000: Delta in mm shown in um).
    pub response: (&'static str, &'static str, f64),
    /// What the regularized and the Coulomb response lines are.
    pub response_meaning: [&'static str; 2],
    /// What F_1, F_2 and F_gross's lines say after the value.
    pub thresholds: [&'static str; 3],
    /// Their meanings.
    pub threshold_meaning: [&'static str; 3],
    /// The cycle line's meaning.
    pub cycle_meaning: &'static str,
}

/// A kind of fit as the screen shows it.
pub(crate) trait FitPane: FitKind {
    /// Its words.
    const PANE: PaneWords;
    /// The 1-D theory's envelope against the kind's continuum at `load`; `None` where no
    /// continuum calibrates it.
    fn envelope(fit: &PressFit, load: CarriedLoad) -> Option<PressFitValidity>;
    /// The pane's title meaning (how far a continuum is expected from the response shown).
    const TITLE_MEANING: &'static str;
    /// The theory line's meaning.
    const THEORY_MEANING: &'static str;
}

impl<K: FitPane> PaneFace for FitProblem<K>
where
    FitProblem<K>: FitPaneFe,
{
    const STRIP_ORIGIN: &'static str = "loaded face";
    /// The strip divides the shear by the interface's `friction * pressure`: mu p, Lamé's p.
    const STRIP_SHEAR: &'static str = "tau(x) / mu p";
    const KT_COLUMNS: &'static [(&'static str, usize)] = K::PANE.kt_columns;

    fn parameters_title(_params: &Self::Params) -> String {
        K::PANE.parameters_title.to_string()
    }

    /// The pane is full at 80x24, so the 1-D theory's envelope goes in the title, as the lap
    /// joint's does.
    fn title_line(model: &PressFitModel) -> Option<SummaryLine> {
        let title = match K::envelope(&model.fit, model.force) {
            Some(v) => envelope_title(v.validity, v.expected_error),
            None => envelope_title(crate::kernel::validity::Validity::NotCalibrated, None),
        };
        Some(SummaryLine::plain(title, K::TITLE_MEANING))
    }

    fn summary_lines(model: &PressFitModel, _continuum: &ContinuumState) -> Vec<SummaryLine> {
        fit_lines::<K>(&model.fit, model.force)
    }

    fn kt_values(model: &PressFitModel, kt: f64) -> Option<Vec<f64>> {
        let fit = model.fit.with_tangential_stiffness(kt).ok()?;
        let axis = fit.axis(K::LOAD);
        let state = axis.regularized(model.force);
        Some(vec![
            axis.first_slip_load(),
            state.slide_from_loaded_face() + state.slide_from_held_face(),
            K::PANE.response.2 * state.response(),
        ])
    }

    fn kt_tolerance_lines(model: &PressFitModel, within: &str, element: f64) -> Vec<String> {
        load_tolerance_lines::<Self>(&model.fit, model.force.value(), within, element)
    }

    fn fe_xy(point: &Self::FePoint) -> (f64, f64) {
        <Self as FitPaneFe>::pane_xy(point)
    }

    fn fe_brief(
        model: &PressFitModel,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String> {
        <Self as FitPaneFe>::pane_brief(model, loaded, code)
    }
}

/// What the pane shows of a kind's FE points (its deck's [`FePoint`](crate::fe::face::Deck::FePoint)): each kind's
/// comparison file gives it.
pub(crate) trait FitPaneFe: LoadedVariant + Problem<Model = PressFitModel> {
    /// The point as (load, response) on the response chart.
    fn pane_xy(point: &Self::FePoint) -> (f64, f64);
    /// The comparison of loaded points in one line.
    ///
    /// # Errors
    /// A comparison that cannot be made, in words.
    fn pane_brief(
        model: &PressFitModel,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String>;
}

/// The push-out's words.
impl FitPane for PushOut {
    const PANE: PaneWords = PaneWords {
        parameters_title: "Press fit (pushed out)",
        kt_columns: &[("F_1 N", 7), ("a+d mm", 7), ("Delta um", 8)],
        what: "push-out",
        load_meaning: "the axial force on the shaft's end face x = 0, the hub held on its far \
                       face x = L; every line below is at this force",
        coulomb_meaning: "plain Coulomb law: the loaded face slides from the first newton, the \
                          rest sticks",
        response: ("Delta", "um", 1e3),
        response_meaning: [
            "the shaft's loaded end relative to the hub's held face under the regularized law: \
             what a dial gauge between shaft end and hub support reads",
            "the shaft's loaded end relative to the hub's held face under plain Coulomb",
        ],
        thresholds: ["slides", "both slide", "all slides"],
        threshold_meaning: [
            "regularized law: sliding starts above F_1 at the face where the more compliant \
             member carries the load (x=0: the shaft, x=L: the hub)",
            "regularized law: above F_2 the other face slides too",
            "mu p 2 pi r L: the whole fit slides and the shaft comes out; no larger force is \
             carried (F is refused above it)",
        ],
        cycle_meaning: "a push cycling between +F and -F (regularized law): energy dissipated \
                        per cycle D and the equivalent damping ratio D / (4 pi U), U = F Delta / 2",
    };

    fn envelope(fit: &PressFit, load: CarriedLoad) -> Option<PressFitValidity> {
        Some(fit.validity(load))
    }

    const TITLE_MEANING: &'static str = "how far an axisymmetric continuum (FE) of this fit is \
         expected from the Delta shown: the 1-D theory's envelope (docs/theory.md (S10), \
         measured on 135 steel fits, held out on 24). 'FE: >10 %, n solves': outside its \
         envelope, n draws the continuum; 'not calibrated': no measured fit is like this one \
         (short fits, L < 2 r, were off by up to 68 %)";

    const THEORY_MEANING: &'static str = "the closed forms take Lamé's pressure uniform over L \
         and each member's section strained uniformly; this bounds how far an axisymmetric \
         continuum's Delta differs (docs/theory.md (S10)); where it fails, n draws the continuum \
         (microslip pressfit --continuum)";
}

/// A kind's lines of the regime pane: the response right after the regimes, so that an 80x24
/// screen, which shows the first five, shows it.
fn fit_lines<K: FitPane>(fit: &PressFit, load: CarriedLoad) -> Vec<SummaryLine>
where
    FitProblem<K>: Registered,
{
    let words = K::PANE;
    let axis = fit.axis(K::LOAD);
    let (symbol, unit) = load_words::<FitProblem<K>>();
    let row = fit_point(axis, load);
    let p = fit.params();
    let ratio = ratio_text(row.delta_regularized, row.delta_coulomb, "- (no load)");
    let (coulomb, regularized, heading) = load_regimes(
        row.force,
        (symbol, unit),
        words.what,
        || row.regime_coulomb.short_label().to_string(),
        || row.regime_regularized.short_label().to_string(),
    );
    let cycle = FitCycle::new(axis, Law::Regularized, load);
    let (a, d) = row.zones_regularized;
    let saturation = p.friction * fit.contact_pressure() / p.tangential_stiffness;
    let (response, response_unit, scale) = words.response;
    let [first, second, gross] = words.thresholds;
    let [first_meaning, second_meaning, gross_meaning] = words.threshold_meaning;
    let theory = match K::envelope(fit, load) {
        Some(v) => theory_words(&v),
        None => "not calibrated".to_string(),
    };
    vec![
        SummaryLine::plain(heading, words.load_meaning),
        SummaryLine::regime("Coulomb", coulomb, words.coulomb_meaning),
        SummaryLine::regime(
            "regularized",
            regularized,
            "regularized law, zones from x = 0 (the shaft's loaded face) to x = L (the hub's held \
             face): micro(slip) = elastic slip below mu p; macro(slip) = sliding at mu p",
        ),
        SummaryLine::plain(
            format!(
                "{response} regularized {} {response_unit}",
                number(scale * row.delta_regularized)
            ),
            words.response_meaning[0],
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
                "{symbol}_1 {} {unit}: {} {first}",
                number(axis.first_slip_load()),
                axis.first_slip_face().key()
            ),
            first_meaning,
        ),
        SummaryLine::plain(
            format!(
                "{symbol}_2 {} {unit}: {second}",
                number(axis.second_slip_load())
            ),
            second_meaning,
        )
        .dropped(4),
        SummaryLine::plain(
            format!(
                "{symbol}_gross {} {unit}: {gross}",
                number(axis.gross_load())
            ),
            gross_meaning,
        )
        .dropped(6),
        SummaryLine::plain(
            format!("a {} d {} mm sliding", number_with(a, 3), number_with(d, 3)),
            "regularized law: the sliding zones, a from x = 0 (the loaded face), d from x = L \
             (the held face)",
        ),
        SummaryLine::plain(
            format!(
                "{response} Coulomb {} {response_unit}",
                number(scale * row.delta_coulomb)
            ),
            words.response_meaning[1],
        )
        .dropped(3),
        SummaryLine::plain(format!("ratio to Coulomb {ratio}"), RATIO_MEANING).dropped(5),
        SummaryLine::plain(
            format!(
                "D {} N mm zeta {}",
                number_with(cycle.dissipation(), 3),
                number_with(cycle.damping_ratio(), 3)
            ),
            words.cycle_meaning,
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
        SummaryLine::plain(format!("1-D theory {theory}"), K::THEORY_MEANING).dropped(1),
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

impl FitPaneFe for PressFitProblem {
    fn pane_xy(point: &Self::FePoint) -> (f64, f64) {
        super::compare::pane_xy(point)
    }

    fn pane_brief(
        model: &PressFitModel,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String> {
        super::compare::pane_brief(model, loaded, code)
    }
}

/// The torque's words: theta in urad on the screen (rad in every file), the circumferential
/// slip's zones, no envelope.
impl FitPane for Twist {
    const PANE: PaneWords = PaneWords {
        parameters_title: "Press fit (twisted)",
        kt_columns: &[("T_1 N mm", 9), ("a+d mm", 7), ("theta urad", 10)],
        what: "torque",
        load_meaning: "the torque on the shaft's end x = 0, the hub held on its far face x = L; \
                       every line below is at this torque",
        coulomb_meaning: "plain Coulomb law: the loaded face slides from the first newton \
                          millimetre, the rest sticks",
        response: ("theta", "urad", 1e6),
        response_meaning: [
            "the shaft's loaded end's rotation relative to the hub's held face under the \
             regularized law (1 urad = 1e-6 rad; files give rad)",
            "the shaft's loaded end's rotation relative to the hub's held face under plain \
             Coulomb",
        ],
        thresholds: ["slides", "both slide", "all slides"],
        threshold_meaning: [
            "regularized law: sliding starts above T_1 at the face where the more compliant \
             member (in torsion) carries the torque (x=0: the shaft, x=L: the hub)",
            "regularized law: above T_2 the other face slides too",
            "mu p 2 pi r^2 L: the whole fit slides and the shaft turns in the hub; no larger \
             torque is carried (T is refused above it)",
        ],
        cycle_meaning: "a torque cycling between +T and -T (regularized law): energy dissipated \
                        per cycle D and the equivalent damping ratio D / (4 pi U), U = T theta / 2",
    };

    /// None: no torsional continuum calibrates the twisted fit's theory.
    fn envelope(_fit: &PressFit, _load: CarriedLoad) -> Option<PressFitValidity> {
        None
    }

    const TITLE_MEANING: &'static str = "how far a continuum (FE) of the twisted fit is \
         expected from the theta shown: not calibrated, no torsional continuum measured the 1-D \
         theory (docs/theory.md section 18, (S6))";

    const THEORY_MEANING: &'static str = "the closed forms take Lamé's pressure uniform over L \
         and each member's section turning rigidly (Saint-Venant torsion); no continuum \
         measured how far theta is from a twisted fit's";
}

impl FitPaneFe for PressFitTorqueProblem {
    fn pane_xy(point: &Self::FePoint) -> (f64, f64) {
        super::torque_fe::pane_xy(point)
    }

    fn pane_brief(
        model: &PressFitModel,
        loaded: &Loaded<Self::FePoint>,
        code: &str,
    ) -> Result<String, String> {
        super::torque_fe::pane_brief(model, loaded, code)
    }
}
