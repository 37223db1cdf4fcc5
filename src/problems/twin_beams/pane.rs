//! How the twin beams show on the terminal screen beside their charts (their [`PaneFace`]): the
//! parameter pane's title with the beam theory, the regime pane's lines and its envelope title,
//! the K_T table's row, the theory `b` toggles and the curve `f` fits.

use super::TwinBeamsProblem;
use super::compare::{BeamComparison, beam_summary as closing_verdict, compare_beams};
use super::fe_points::BeamFePoint;
use crate::chart::panes::{
    ContinuumState, KT_UM_MEANING, PaneFace, RATIO_MEANING, SATURATION_MEANING, SummaryLine,
    load_regimes, load_tolerance_lines, ratio_text,
};
use crate::fe::load::Loaded;
use crate::kernel::format::{number, number_with};
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};
use crate::problems::twin_beams::closed_form::BeamTheory;
use crate::report::compare::percent_range;
use crate::study::curves::beam_point;

/// The largest beam-theory envelope (V2) the regime pane's title states (10 %): past it the
/// bound's 4 w(L)/L term speaks of deflections far beyond the largest measured (w/L about 1.3 %,
/// docs/theory.md (V2)), so no number is claimed there.
const MAX_SHOWN_ENVELOPE: f64 = 0.1;

impl PaneFace for TwinBeamsProblem {
    const STRIP_ORIGIN: &'static str = "clamp";
    const KT_COLUMNS: &'static [(&'static str, usize)] =
        &[("F_1 N", 7), ("X mm", 7), ("w(L) mm", 8)];

    fn parameters_title(params: &Self::Params) -> String {
        format!("Twin beams, {}", params.structure.theory.label())
    }

    /// The beams' pane is full at 80x24, so their envelope goes in the title, and `i` explains
    /// it as the first of the pane's lines.
    fn title_line(model: &Self::Model) -> Option<SummaryLine> {
        let (beams, force) = (&model.beams, &model.force);
        // Each bound named by its kinematics, in the few characters a title has at 80 columns:
        // one number where they agree (below first slip), both beyond it; `i` spells them out.
        let validity = beams.validity(*force);
        let text = match (validity.expected_error, validity.linear_geometry_error) {
            (Some(_), Some(linear)) if linear > MAX_SHOWN_ENVELOPE => "FE: w/L too big".to_string(),
            (Some(nlgeom), Some(linear)) => {
                let (nlgeom, linear) = (
                    number_with(100.0 * nlgeom, 2),
                    number_with(100.0 * linear, 2),
                );
                if nlgeom == linear {
                    format!("FE NL+lin {linear} %")
                } else {
                    format!("FE NL {nlgeom}/lin {linear} %")
                }
            }
            _ => "FE: not calibrated".to_string(),
        };
        let help = match (validity.expected_error, validity.linear_geometry_error) {
            (Some(nlgeom), Some(linear)) => format!(
                "how far continuum FE of these beams (plane stress, fine mesh) is expected from \
                 the w(L) shown, by the FE run's kinematics: NL {} % with NLGEOM (large \
                 rotations, (V2)), lin {} % in linear geometry (V2L: wider beyond first slip, where a linear run's \
                 upright pressure acts on the turning faces); docs/theory.md. 'not calibrated': \
                 mu P L / (2 E h) beyond the measured range; 'w/L too big': the bound passes \
                 10 %, deflections far beyond those measured",
                number_with(100.0 * nlgeom, 2),
                number_with(100.0 * linear, 2)
            ),
            _ => "how far continuum FE of these beams is expected from the w(L) shown, with \
                  NLGEOM (V2) or in linear geometry (V2L): 'not calibrated': mu P L / (2 E h) is \
                  beyond the measured range (docs/theory.md)"
                .to_string(),
        };
        Some(SummaryLine::plain(text, help))
    }

    fn summary_lines(model: &Self::Model, _continuum: &ContinuumState) -> Vec<SummaryLine> {
        let (beams, force) = (&model.beams, &model.force);
        let row = beam_point(beams, *force);
        let ratio = ratio_text(row.w_regularized, row.w_coulomb, "- (no load)");
        let (coulomb, regularized, heading) = load_regimes(
            row.force,
            ("F", "N"),
            "tip force",
            || row.regime_coulomb.to_string(),
            || row.regime_regularized.to_string(),
        );
        vec![
            SummaryLine::plain(
                heading,
                "the tip force on each beam; every line below is at this force",
            ),
            SummaryLine::regime(
                "Coulomb",
                coulomb,
                "plain Coulomb law: stick (nothing slips) below F_thre, the whole interface \
                     slides (macroslip) above it",
            ),
            SummaryLine::regime(
                "regularized",
                regularized,
                "regularized law (tau = K_T x slip up to mu P): microslip = every point slips \
                     elastically; +macroslip = the part near the free end slides at mu P",
            ),
            SummaryLine::plain(
                format!("F_thre {} N: all slides", number(beams.threshold_force())),
                "Coulomb threshold 4 mu b h P / 3: above it the whole interface slides",
            ),
            SummaryLine::plain(
                format!(
                    "F_1 {} N: tip slides",
                    number(beams.first_macroslip_force())
                ),
                "regularized law: above F_1 macroslip starts at the free end (x = L) and \
                     spreads toward the clamp",
            ),
            SummaryLine::plain(
                format!("X = {} mm from clamp", number(row.micro_end)),
                "X: where microslip ends and macroslip begins, measured from the clamp \
                     (x = 0); X = L: no macroslip",
            ),
            SummaryLine::plain(
                format!("w(L) Coulomb {} mm", number(row.w_coulomb)),
                "tip deflection under the plain Coulomb law",
            )
            .dropped(3),
            SummaryLine::plain(
                format!("w(L) regularized {} mm", number(row.w_regularized)),
                "tip deflection under the regularized law",
            ),
            SummaryLine::plain(format!("ratio to Coulomb {ratio}"), RATIO_MEANING),
            SummaryLine::plain(
                format!(
                    "saturation slip {} um",
                    number(mm_to_um(beams.saturation_slip()))
                ),
                SATURATION_MEANING,
            )
            .dropped(2),
            SummaryLine::plain(
                format!(
                    "K_T = {} MPa/um",
                    number(mpa_per_mm_to_mpa_per_um(
                        beams.params().tangential_stiffness
                    ))
                ),
                KT_UM_MEANING,
            )
            .dropped(1),
        ]
    }

    fn kt_values(model: &Self::Model, kt: f64) -> Option<Vec<f64>> {
        let beams = model.beams.with_tangential_stiffness(kt).ok()?;
        let state = beams.regularized(model.force);
        Some(vec![
            beams.first_macroslip_force(),
            state.micro_zone_end(),
            state.tip_deflection(),
        ])
    }

    fn kt_tolerance_lines(model: &Self::Model, within: &str, element: f64) -> Vec<String> {
        load_tolerance_lines::<Self>(&model.beams, model.force.newtons(), within, element)
    }

    fn toggle_setting(params: &mut Self::Params) -> Option<&'static str> {
        let structure = &mut params.structure;
        structure.theory = structure.theory.other();
        Some(match structure.theory {
            BeamTheory::EulerBernoulli => {
                "beam theory: Euler-Bernoulli (the paper's; no shear deflection)"
            }
            BeamTheory::Timoshenko => {
                "beam theory: Timoshenko (adds each beam's shear deflection \
                 F x / (kappa G b 2h), nu from the nu row)"
            }
        })
    }

    fn fe_xy(point: &BeamFePoint) -> (f64, f64) {
        (point.force, point.deflection)
    }

    fn fe_brief(
        model: &Self::Model,
        loaded: &Loaded<BeamFePoint>,
        code: &str,
    ) -> Result<String, String> {
        let comparison =
            compare_beams(&model.beams, &loaded.points, loaded.interface_mesh.as_ref());
        Ok(beam_summary(code, &comparison))
    }
}

/// One line for the TUI's status: the beams' comparison in brief, the verdict first (the line is
/// cut at the screen's width).
fn beam_summary(code: &str, comparison: &BeamComparison) -> String {
    let shear = percent_range(
        comparison
            .rows
            .iter()
            .map(|r| r.difference_shear_corrected()),
    );
    let euler = percent_range(comparison.rows.iter().map(|r| r.difference_euler()));
    format!(
        "{code}, {} points: {}; w(L) {shear} vs Timoshenko (E-B {euler})",
        comparison.rows.len(),
        closing_verdict(comparison).short
    )
}
