//! The lines of the regime pane and what each means: shared by the pane, the explanation of `i`
//! and the app (which moves through them). Text only, no drawing.

use crate::kernel::regime::Law;
use crate::problems::inputs::Model;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::lap::cycle::{LapCycle, MasingCycle};
use crate::problems::stiffness::{mm_to_um, mpa_per_mm_to_mpa_per_um};
use crate::report::{number, number_with};
use crate::study::curves::lap_point;
use crate::study::curves::{beam_point, plate_point};

/// One line of the regime pane: its text (a regime line has a label and a styled value) and what
/// it means, in words for someone who has not read the paper (`i`, and the spare height of tall
/// screens).
#[derive(Debug, Clone, PartialEq)]
pub struct SummaryLine {
    /// The text, or the label of a regime line.
    pub text: String,
    /// The regime, for regime lines.
    pub regime: Option<String>,
    /// What the line means.
    pub meaning: &'static str,
    /// When the pane is short of rows, lines are dropped in increasing order of this rank; 0: kept
    /// always. What is dropped can be read elsewhere (the ratio and one w(L) give the other).
    pub drop_rank: u8,
}

impl SummaryLine {
    /// The same line, dropped `rank`-th when rows are short.
    fn dropped(self, rank: u8) -> SummaryLine {
        SummaryLine {
            drop_rank: rank,
            ..self
        }
    }
}

fn plain(text: String, meaning: &'static str) -> SummaryLine {
    SummaryLine {
        text,
        regime: None,
        meaning,
        drop_rank: 0,
    }
}

fn regime_line(label: &str, regime: String, meaning: &'static str) -> SummaryLine {
    SummaryLine {
        text: format!("{label:<12}"),
        regime: Some(regime),
        meaning,
        drop_rank: 0,
    }
}

/// Where the plate's 2-D continuum solution (the regime pane's best answer for u(L)) stands: it is
/// solved on a worker, since it takes up to a tenth of a second.
#[derive(Debug, Clone, PartialEq)]
pub enum ContinuumState {
    /// Not asked for (the beams, or an app that does not solve it).
    Off,
    /// Asked for the current values, not there yet.
    Solving,
    /// Solved at the current values.
    Solved(crate::tui::effects::ContinuumSummary),
    /// Why there is none (out of the solver's range, no convergence).
    Failed(String),
}

/// The lap joint's lines of the regime pane.
fn lap_lines(
    joint: &LapJoint,
    force: JointForce,
    ratio_meaning: &'static str,
    saturation_meaning: &'static str,
) -> Vec<SummaryLine> {
    let row = lap_point(joint, force);
    let ratio = if row.delta_coulomb > 0.0 {
        number(row.delta_regularized / row.delta_coulomb)
    } else {
        "- (no load)".into()
    };
    let (coulomb, regularized, heading) = if row.force == 0.0 {
        (
            "unloaded".to_string(),
            "unloaded".to_string(),
            "At F = 0 N: no load, no slip".to_string(),
        )
    } else {
        (
            row.regime_coulomb.short_label().to_string(),
            row.regime_regularized.short_label().to_string(),
            format!("At F = {} N (joint force)", number(row.force)),
        )
    };
    let cycle = LapCycle::new(joint, Law::Regularized, force);
    let (a, d) = row.zones_regularized;
    let end = match joint.first_slip() {
        crate::problems::lap::closed_form::FirstSlip::InnerEnd => "x=0",
        crate::problems::lap::closed_form::FirstSlip::CoverEnds => "x=L",
        crate::problems::lap::closed_form::FirstSlip::BothEnds => "both ends",
    };
    vec![
        plain(
            heading,
            "the force through the joint (each interface carries half); every line below is at \
             this force",
        ),
        regime_line(
            "Coulomb",
            coulomb,
            "plain Coulomb law: both ends slide from the first newton (macroslip), the middle \
             sticks and carries no shear",
        ),
        regime_line(
            "regularized",
            regularized,
            "regularized law, zones from x = 0 (the inner plate's end) to x = L (the covers' \
             ends): micro(slip) = elastic slip below mu P; macro(slip) = sliding at mu P",
        ),
        plain(
            format!("F_1 {} N: {end} slides", number(joint.first_slip_force())),
            "regularized law: sliding starts above F_1 at the end where the more compliant \
             member carries the load (x = L: the inner plate, x = 0: the covers)",
        ),
        plain(
            format!("F_2 {} N: both slide", number(joint.second_slip_force())),
            "regularized law: above F_2 the other end slides too",
        )
        .dropped(4),
        plain(
            format!("F_gross {} N: all slides", number(joint.gross_slip_force())),
            "2 b mu P L: both interfaces slide over the whole overlap; the joint carries no more \
             (F is refused above it)",
        )
        .dropped(6),
        plain(
            format!("a {} d {} mm sliding", number_with(a, 3), number_with(d, 3)),
            "regularized law: the sliding zones, a from x = 0 (inner plate's end), d from x = L \
             (covers' ends)",
        ),
        plain(
            format!("Delta Coulomb {} mm", number(row.delta_coulomb)),
            "joint displacement u_inner(L) - u_cover(0) under the plain Coulomb law",
        )
        .dropped(3),
        plain(
            format!("Delta regularized {} mm", number(row.delta_regularized)),
            "joint displacement u_inner(L) - u_cover(0) under the regularized law: what an \
             extensometer across the overlap reads",
        ),
        plain(format!("ratio to Coulomb {ratio}"), ratio_meaning).dropped(5),
        plain(
            format!(
                "D {} N mm zeta {}",
                number_with(cycle.dissipation(), 3),
                number_with(cycle.damping_ratio(), 3)
            ),
            "a force cycling between +F and -F (regularized law): energy dissipated per cycle D \
             and the equivalent damping ratio D / (4 pi U), U = F Delta / 2",
        ),
        plain(
            format!(
                "saturation slip {} um",
                number(mm_to_um(joint.saturation_slip()))
            ),
            saturation_meaning,
        )
        .dropped(2),
        plain(
            format!(
                "K_T = {} MPa/um",
                number(mpa_per_mm_to_mpa_per_um(
                    joint.params().tangential_stiffness
                ))
            ),
            "K_T in the unit some FE codes use: 1 MPa/um = 1000 MPa/mm",
        )
        .dropped(1),
        plain(
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
fn lap_validity_words(v: &crate::problems::lap::LapValidity) -> String {
    match v.outside_calibration {
        Some(_) => "not calibrated".to_string(),
        None => v.validity.label().to_string(),
    }
}

/// The largest beam-theory envelope (V2) the regime pane's title states (10 %): past it the
/// bound's 4 w(L)/L term speaks of deflections far beyond the largest measured (w/L about 1.3 %,
/// docs/theory.md (V2)), so no number is claimed there.
const MAX_SHOWN_ENVELOPE: f64 = 0.1;

/// The regime pane's title after "Regime (i), " ("FE within 3.02 %") and what it means: the beams'
/// and the lap joint's pane are full at 80x24, so their envelope goes in the title, and `i`
/// explains it as the first of the pane's lines. None for the plate, whose validity is a line.
pub fn title_line(model: &Model) -> Option<SummaryLine> {
    match model {
        Model::Beam { beams, force } => {
            let text = match beams.validity(*force).expected_error {
                None => "FE: not calibrated".to_string(),
                Some(error) if error > MAX_SHOWN_ENVELOPE => "FE: w/L too big".to_string(),
                Some(error) => format!("FE within {} %", number_with(100.0 * error, 2)),
            };
            Some(plain(
                text,
                "how far continuum FE of these beams (plane stress, fine mesh) is expected from                  the w(L) shown: the beam theory's envelope at this force (docs/theory.md (V2)).                  'not calibrated': mu P L / (2 E h) beyond the measured range; 'w/L too big':                  the bound passes 10 %, deflections far beyond those measured",
            ))
        }
        Model::Plate(_) => None,
        Model::Lap { joint, force } => Some(plain(
            crate::tui::brief::lap_validity_title(&joint.validity(*force)),
            "how far a 2-D plane-stress continuum (FE) of this joint is expected from the Delta              shown: the shear-lag theory's envelope at this force (docs/theory.md (L14)).              'FE: >10 %, n solves': the theory is outside its envelope, n draws the continuum;              'not calibrated': no measured joint is like this one",
        )),
    }
}

/// The lines of the regime pane for `model`; `continuum`: the plate's 2-D continuum u(L).
pub fn summary_lines(model: &Model, continuum: &ContinuumState) -> Vec<SummaryLine> {
    const RATIO: &str =
        "regularized / Coulomb: 1.01 means 1 % more than under the plain Coulomb law";
    const SATURATION: &str = "mu P / K_T: the elastic slip at which the regularized law reaches the \
         Coulomb stress mu P";
    match model {
        Model::Beam { beams, force } => {
            let row = beam_point(beams, *force);
            let ratio = if row.w_coulomb > 0.0 {
                number(row.w_regularized / row.w_coulomb)
            } else {
                "- (no load)".into()
            };
            // At zero load nothing is loaded, whatever the law: say so rather than "microslip".
            let (coulomb, regularized, heading) = if row.force == 0.0 {
                (
                    "unloaded".to_string(),
                    "unloaded".to_string(),
                    "At F = 0 N: no load, no slip".to_string(),
                )
            } else {
                (
                    row.regime_coulomb.to_string(),
                    row.regime_regularized.to_string(),
                    format!("At F = {} N (tip force)", number(row.force)),
                )
            };
            vec![
                plain(
                    heading,
                    "the tip force on each beam; every line below is at this force",
                ),
                regime_line(
                    "Coulomb",
                    coulomb,
                    "plain Coulomb law: stick (nothing slips) below F_thre, the whole interface \
                     slides (macroslip) above it",
                ),
                regime_line(
                    "regularized",
                    regularized,
                    "regularized law (tau = K_T x slip up to mu P): microslip = every point slips \
                     elastically; +macroslip = the part near the free end slides at mu P",
                ),
                plain(
                    format!("F_thre {} N: all slides", number(beams.threshold_force())),
                    "Coulomb threshold 4 mu b h P / 3: above it the whole interface slides",
                ),
                plain(
                    format!(
                        "F_1 {} N: tip slides",
                        number(beams.first_macroslip_force())
                    ),
                    "regularized law: above F_1 macroslip starts at the free end (x = L) and \
                     spreads toward the clamp",
                ),
                plain(
                    format!("X = {} mm from clamp", number(row.micro_end)),
                    "X: where microslip ends and macroslip begins, measured from the clamp \
                     (x = 0); X = L: no macroslip",
                ),
                plain(
                    format!("w(L) Coulomb {} mm", number(row.w_coulomb)),
                    "tip deflection under the plain Coulomb law",
                )
                .dropped(3),
                plain(
                    format!("w(L) regularized {} mm", number(row.w_regularized)),
                    "tip deflection under the regularized law",
                ),
                plain(format!("ratio to Coulomb {ratio}"), RATIO),
                plain(
                    format!(
                        "saturation slip {} um",
                        number(mm_to_um(beams.saturation_slip()))
                    ),
                    SATURATION,
                )
                .dropped(2),
                plain(
                    format!(
                        "K_T = {} MPa/um",
                        number(mpa_per_mm_to_mpa_per_um(
                            beams.params().tangential_stiffness
                        ))
                    ),
                    "K_T in the unit some FE codes use: 1 MPa/um = 1000 MPa/mm",
                )
                .dropped(1),
            ]
        }
        Model::Lap { joint, force } => lap_lines(joint, *force, RATIO, SATURATION),
        Model::Plate(plate) => {
            let row = plate_point(plate);
            let ratio = if row.u_coulomb > 0.0 {
                number(row.u_regularized / row.u_coulomb)
            } else {
                "-".into()
            };
            let onset = match plate.macroslip_onset_stiffness() {
                Some(kt) => format!("macroslip K_T > {} MPa/mm", number(kt)),
                None => "no macroslip at any K_T".into(),
            };
            let mut lines = vec![
                regime_line(
                    "Coulomb",
                    row.regime_coulomb.to_string(),
                    "plain Coulomb law: stick near the centre, sliding (macroslip) near the free end",
                ),
                regime_line(
                    "regularized",
                    row.regime_regularized.to_string(),
                    "regularized law: microslip = every point slips elastically; +macroslip = \
                     the part near the free end slides at mu P",
                ),
                plain(
                    format!("X_s = {} mm stick end", number(row.stick_end)),
                    "Coulomb law: the plate sticks from the centre (x = 0) to X_s, slides beyond",
                ),
                plain(
                    format!("X_r = {} mm microslip end", number(row.micro_end)),
                    "regularized law: microslip from the centre to X_r, macroslip beyond; \
                     X_r = L: no macroslip",
                ),
                plain(
                    onset,
                    "the K_T above which macroslip appears at the free end (closed form, \
                     theory (P11)): the plate's F_1",
                ),
                plain(
                    format!("u(L) Coulomb {} mm", number(row.u_coulomb)),
                    "displacement of the free end under the plain Coulomb law",
                )
                .dropped(3),
                plain(
                    format!("u(L) regularized {} mm", number(row.u_regularized)),
                    "displacement of the free end under the regularized law",
                ),
                plain(format!("ratio to Coulomb {ratio}"), RATIO),
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
                plain(
                    text,
                    "the project's plane-strain continuum FE (2-D, 4 layers, contact pressure \
                     solved): u(L) averaged through the thickness, the best answer here; in % \
                     against the strip theory's regularized u(L). None when K_T is too stiff \
                     for it (alpha t_p > 20) or it does not converge",
                )
            }));
            lines.extend([
                plain(
                    format!(
                        "saturation slip {} um",
                        number(mm_to_um(plate.saturation_slip()))
                    ),
                    SATURATION,
                )
                .dropped(1),
                plain(
                    pressure_words(plate, continuum),
                    "contact pressure: the plane-strain continuum's (microslip plate --continuum) \
                     is flat away from the free end and peaks at it; once solved, this line gives \
                     its peak, the mean over the last t_p/10 (the corner node itself grows with \
                     every refinement). The paper's flat-plate model (P7-P9, friction saturated \
                     everywhere), shown until then, is right only for the mean over the last t_p \
                     where the slip zone is at least t_p long (theory (P12))",
                ),
                plain(
                    format!(
                        "strip theory {}",
                        super::brief::strip_validity_short(&plate.validity())
                    ),
                    "the closed forms treat the plate as a strip (u uniform through t_p); this \
                     says how far a 2-D continuum's thickness-mean u(L) differs (V1); the contact \
                     face and mid-thickness have their own bounds (microslip plate), X_r none",
                ),
            ]);
            lines
        }
    }
}

/// The regime pane's contact-pressure line: the continuum's free-end peak (mean over the last
/// t_p / 10) once solved, else the flat model's mean over the last t_p where it was measured right
/// (slip zone >= t_p), else where the plate's pressure is found.
fn pressure_words(plate: &crate::SqueezedPlate, continuum: &ContinuumState) -> String {
    if let ContinuumState::Solved(solved) = continuum {
        return format!(
            "contact P 2-D: {} P at end",
            crate::report::number_with(solved.edge_pressure, 3)
        );
    }
    plate.end_layer_pressure().map_or_else(
        || "contact P: 2-D only".to_string(),
        |mean| {
            format!(
                "P last t_p ~{} P (flat)",
                crate::report::number_with(mean, 3)
            )
        },
    )
}

/// `text` cut into lines of at most `width` characters at spaces.
pub fn wrap_words(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut current = String::new();
    for word in text.split(' ') {
        if !current.is_empty() && current.len() + 1 + word.len() > width {
            lines.push(std::mem::take(&mut current));
        }
        if !current.is_empty() {
            current.push(' ');
        }
        current.push_str(word);
    }
    if !current.is_empty() {
        lines.push(current);
    }
    lines
}
