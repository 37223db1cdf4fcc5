//! `microslip kt`: the K_T candidates (the model's, from K_N, the FE codes' defaults) and what
//! each does to the answer.

use std::fmt::Write;

use serde::Serialize;

use super::regime_label;
use crate::Regime;
use crate::problems::lap::stiffness_answer::LapAnswer;
use crate::problems::plate::stiffness_answer::PlateAnswer;
use crate::problems::twin_beams::stiffness_answer::BeamAnswer;
use crate::problems::{BeamParam, ModelKind, Quantity};
use crate::report::{number, sanitize};
use crate::study::curves::{Answer, CandidateSource, ComparedStiffness, StiffnessComparison};

/// The K_T comparison.
#[derive(Debug, Clone, Serialize)]
pub struct StiffnessReport {
    pub preset: String,
    /// Contact element length the codes' defaults scale with (mm).
    #[serde(rename = "element_size_mm")]
    pub element: f64,
    /// The problem, for the text's layout.
    #[serde(skip)]
    pub kind: ModelKind,
    /// The load case, for the text's heading: the beams' tip force (N), or `None` for the plate.
    #[serde(skip)]
    pub force: Option<f64>,
    /// mu P (MPa), for the text's heading.
    #[serde(skip)]
    pub friction_stress: f64,
    pub candidates: Vec<CandidateReport>,
}

/// One candidate K_T and the answer at it.
#[derive(Debug, Clone, Serialize)]
pub struct CandidateReport {
    /// Where it comes from (`candidate_name`).
    pub source: &'static str,
    /// How it was obtained (`candidate_basis`).
    pub basis: String,
    /// `None` (null) where it needs an input not given (eq. 4 without K_N).
    #[serde(rename = "KT_MPa_per_mm")]
    pub kt: Option<f64>,
    /// The answer's fields beside the candidate's; none without a K_T.
    #[serde(flatten)]
    pub answer: Option<CandidateAnswer>,
    /// Its w(L) or u(L) against the current K_T's, in % (0 for the current row); left out without
    /// an answer.
    #[serde(rename = "vs_current_percent", skip_serializing_if = "Option::is_none")]
    pub vs_current: Option<f64>,
    /// Its w(L), u(L) or Delta against Coulomb's (K_T -> infinity), in %; left out without an
    /// answer or at no load.
    #[serde(rename = "vs_coulomb_percent", skip_serializing_if = "Option::is_none")]
    pub vs_coulomb: Option<f64>,
}

/// What a candidate K_T does to the answer, or why it was not evaluated.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum CandidateAnswer {
    Beam {
        #[serde(rename = "F_1_N")]
        first_macroslip_force: f64,
        #[serde(rename = "X_mm")]
        micro_end: f64,
        #[serde(rename = "w_tip_mm")]
        tip_deflection: f64,
        #[serde(serialize_with = "regime_label")]
        regime: Regime,
    },
    Plate {
        #[serde(rename = "u_end_mm")]
        end_displacement: f64,
        #[serde(rename = "Xr_mm")]
        micro_end: f64,
        #[serde(serialize_with = "regime_label")]
        regime: Regime,
    },
    Lap {
        #[serde(rename = "F_1_N")]
        first_slip_force: f64,
        #[serde(rename = "a_mm")]
        slide_at_inner_end: f64,
        #[serde(rename = "d_mm")]
        slide_at_cover_ends: f64,
        #[serde(rename = "Delta_mm")]
        joint_displacement: f64,
        #[serde(serialize_with = "regime_label")]
        regime: Regime,
    },
    /// A K_T the model refuses: said rather than left out silently.
    Refused { not_evaluated: String },
}

/// The name of a K_T candidate's source, as reports show it.
pub(crate) fn candidate_name(source: &CandidateSource) -> &'static str {
    source.name()
}

/// How a K_T candidate was obtained, and how sure we are.
pub(crate) fn candidate_basis(source: &CandidateSource) -> String {
    match source {
        CandidateSource::Current => "the model's K_T".into(),
        CandidateSource::NormalLow => "measured K_T/K_N, low end".into(),
        CandidateSource::Equation4 { nu } => format!("pi (1 - nu) / (2 (2 - nu)) K_N, nu = {nu}"),
        CandidateSource::NormalHigh => "measured K_T/K_N, high end".into(),
        CandidateSource::Code(code) => {
            format!("{} ({})", code.description, code.confirmation.label())
        }
    }
}

impl From<&ComparedStiffness> for CandidateReport {
    fn from(row: &ComparedStiffness) -> Self {
        let kt = row.candidate.kt;
        let answer = match row.answer {
            Some(Answer::Beam(BeamAnswer {
                first_macroslip_force,
                micro_end,
                tip_deflection,
                regime,
            })) => Some(CandidateAnswer::Beam {
                first_macroslip_force,
                micro_end,
                tip_deflection,
                regime,
            }),
            Some(Answer::Plate(PlateAnswer {
                end_displacement,
                micro_end,
                regime,
            })) => Some(CandidateAnswer::Plate {
                end_displacement,
                micro_end,
                regime,
            }),
            Some(Answer::Lap(LapAnswer {
                first_slip_force,
                zones: (slide_at_inner_end, slide_at_cover_ends),
                joint_displacement,
                regime,
            })) => Some(CandidateAnswer::Lap {
                first_slip_force,
                slide_at_inner_end,
                slide_at_cover_ends,
                joint_displacement,
                regime,
            }),
            None => match kt.map(|kt| BeamParam::Stiffness.check(kt)) {
                Some(Err(refused)) => Some(CandidateAnswer::Refused {
                    not_evaluated: refused.to_string(),
                }),
                _ => None,
            },
        };
        CandidateReport {
            source: candidate_name(&row.candidate.source),
            basis: candidate_basis(&row.candidate.source),
            kt,
            answer,
            vs_current: row.off_current.map(|f| 100.0 * f),
            vs_coulomb: row.off_coulomb.map(|f| 100.0 * f),
        }
    }
}

/// A deviation in % with its sign ("+3.97 %", "0 %"), "-" without one.
fn signed_percent(percent: Option<f64>) -> String {
    percent.map_or("-".to_string(), |p| {
        if p == 0.0 {
            "0 %".to_string()
        } else {
            let sign = if p > 0.0 { "+" } else { "" };
            format!("{sign}{} %", crate::report::number_with(p, 3))
        }
    })
}

impl StiffnessReport {
    pub fn new(preset: &str, comparison: &StiffnessComparison) -> StiffnessReport {
        let model = &comparison.model;
        let interface = model.interface();
        StiffnessReport {
            preset: preset.to_string(),
            element: comparison.element,
            kind: comparison.model.kind(),
            // The force where the problem is driven by one (none for the plate's pressure).
            force: model
                .kind()
                .problem()
                .load_driven()
                .and_then(|load_driven| load_driven.applied_force(model)),
            friction_stress: interface.friction * interface.pressure,
            candidates: comparison.rows.iter().map(CandidateReport::from).collect(),
        }
    }

    /// The readable table: each candidate and what it does to the answer.
    pub fn text(&self) -> String {
        let preset = sanitize(&self.preset);
        let mut out = String::new();
        let (mu_p, element) = (number(self.friction_stress), number(self.element));
        match self.kind {
            ModelKind::Beam => {
                let _ = writeln!(
                    out,
                    "K_T candidates for preset {preset}: twin beams at F = {} N, mu P = {mu_p} MPa, contact elements {element} mm",
                    self.force.map_or_else(|| "-".to_string(), number),
                );
                let _ = writeln!(
                    out,
                    "{:<16} {:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {:<20} basis",
                    "source",
                    "K_T (MPa/mm)",
                    "F_1 (N)",
                    "X (mm)",
                    "w(L) (mm)",
                    "vs current",
                    "vs Coulomb",
                    "regime"
                );
            }
            ModelKind::Lap => {
                let _ = writeln!(
                    out,
                    "K_T candidates for preset {preset}: double-lap joint at F = {} N, mu P = {mu_p} MPa, contact elements {element} mm",
                    self.force.map_or_else(|| "-".to_string(), number),
                );
                let _ = writeln!(
                    out,
                    "{:<16} {:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {:<29} basis",
                    "source",
                    "K_T (MPa/mm)",
                    "F_1 (N)",
                    "a (mm)",
                    "d (mm)",
                    "Delta (mm)",
                    "vs current",
                    "vs Coulomb",
                    "regime"
                );
            }
            ModelKind::Plate => {
                let _ = writeln!(
                    out,
                    "K_T candidates for preset {preset}: squeezed plate, mu P = {mu_p} MPa, contact elements {element} mm",
                );
                let _ = writeln!(
                    out,
                    "{:<16} {:>12} {:>12} {:>10} {:>10} {:>10}  {:<20} basis",
                    "source",
                    "K_T (MPa/mm)",
                    "u(L) (mm)",
                    "vs current",
                    "vs Coulomb",
                    "X_r (mm)",
                    "regime"
                );
            }
        }
        for row in &self.candidates {
            let (source, basis) = (row.source, &row.basis);
            let kt = row.kt.map_or("-".to_string(), number);
            // A candidate without an answer: no K_T at all, or one the model refuses.
            let off = signed_percent(row.vs_current);
            let off_coulomb = signed_percent(row.vs_coulomb);
            let unanswered = if row.kt.is_some() {
                "K_T out of range"
            } else {
                "-"
            };
            let _ = match (&row.answer, self.kind) {
                (
                    Some(CandidateAnswer::Beam {
                        first_macroslip_force,
                        micro_end,
                        tip_deflection,
                        regime,
                    }),
                    _,
                ) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {:<20} {basis}",
                    number(*first_macroslip_force),
                    number(*micro_end),
                    number(*tip_deflection),
                    off,
                    off_coulomb,
                    regime.label(),
                ),
                (
                    Some(CandidateAnswer::Plate {
                        end_displacement,
                        micro_end,
                        regime,
                    }),
                    _,
                ) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>12} {:>10} {:>10} {:>10}  {:<20} {basis}",
                    number(*end_displacement),
                    off,
                    off_coulomb,
                    number(*micro_end),
                    regime.label(),
                ),
                (
                    Some(CandidateAnswer::Lap {
                        first_slip_force,
                        slide_at_inner_end,
                        slide_at_cover_ends,
                        joint_displacement,
                        regime,
                    }),
                    _,
                ) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {:<29} {basis}",
                    number(*first_slip_force),
                    number(*slide_at_inner_end),
                    number(*slide_at_cover_ends),
                    number(*joint_displacement),
                    off,
                    off_coulomb,
                    regime.label(),
                ),
                // No answer: the columns of the problem's table.
                (None | Some(CandidateAnswer::Refused { .. }), ModelKind::Beam) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {unanswered:<20} {basis}",
                    "-", "-", "-", "-", "-",
                ),
                (None | Some(CandidateAnswer::Refused { .. }), ModelKind::Lap) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {unanswered:<29} {basis}",
                    "-", "-", "-", "-", "-", "-",
                ),
                (None | Some(CandidateAnswer::Refused { .. }), ModelKind::Plate) => writeln!(
                    out,
                    "{source:<16} {kt:>12} {:>12} {:>10} {:>10} {:>10}  {unanswered:<20} {basis}",
                    "-", "-", "-", "-",
                ),
            };
        }
        if self.candidates.iter().any(|row| {
            row.kt.is_some() && matches!(row.answer, None | Some(CandidateAnswer::Refused { .. }))
        }) {
            let stiffness = BeamParam::Stiffness.spec();
            let _ = writeln!(
                out,
                "K_T out of range: not evaluated, K_T {}.",
                stiffness.domain.describe(stiffness.unit)
            );
        }
        let quantity = Quantity::Response.name(self.kind);
        let _ = writeln!(
            out,
            "vs current: each K_T's {quantity} against the current K_T's, in % (what an FE model \
             with that K_T gets wrong if the current K_T is the interface's true one)."
        );
        let _ = writeln!(
            out,
            "vs Coulomb: each K_T's {quantity} against Coulomb's (the limit of an infinitely \
             stiff K_T), in % (what it gets wrong if the interface is rigid until it slides)."
        );
        let _ = writeln!(
            out,
            "Elastic-slip defaults scale like mu P / element length, here contact elements of \
             {element} mm (L/100 unless --element-size MM gives your mesh's): halve the elements, \
             double K_T."
        );
        out
    }
}
