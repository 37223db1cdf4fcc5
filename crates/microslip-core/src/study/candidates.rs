//! Which K_T to use: the candidates worth comparing for a model (its own, those from a normal
//! stiffness K_N, each FE code's default) and what each does to its answer, computed once for the
//! text and JSON reports and the TUI's table.

use crate::kernel::code_defaults::CodeDefault;
use crate::problems::Problem;
use crate::problems::inputs::Model;
use crate::problems::stiffness_answer::StiffnessAnswer;

/// Where a K_T to compare comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CandidateSource {
    /// The model's own K_T.
    Current,
    /// K_N times the low end of the measured K_T/K_N range.
    NormalLow,
    /// Paper eq. 4 from K_N at Poisson ratio `nu`.
    Equation4 {
        /// The Poisson ratio used (-).
        nu: f64,
    },
    /// K_N times the high end of the measured K_T/K_N range.
    NormalHigh,
    /// A finite-element code's default.
    Code(&'static CodeDefault),
}

impl CandidateSource {
    /// The candidate's short name in tables and charts ("current", "eq. 4", a code's name).
    pub fn name(&self) -> &'static str {
        match self {
            CandidateSource::Current => "current",
            CandidateSource::NormalLow => "K_N x 0.5",
            CandidateSource::Equation4 { .. } => "eq. 4",
            CandidateSource::NormalHigh => "K_N x 0.7",
            CandidateSource::Code(code) => code.code,
        }
    }
}

/// A K_T to compare: where it comes from and its value (`None`: that source gives no value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StiffnessCandidate {
    /// Source.
    pub source: CandidateSource,
    /// The stiffness (MPa/mm), when the source gives one.
    pub kt: Option<f64>,
}

/// Writes [`Answer`] and its dispatch from the registry: one variant per problem, holding its
/// [`StiffnessAnswer::Answer`], so that this file names no problem.
macro_rules! answers {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// What a K_T does to the model: one variant per problem (generated from the registry),
        /// holding that problem's [`StiffnessAnswer::Answer`].
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum Answer {
            $($(#[$doc])* $variant(
                <crate::problems::$folder::$problem as StiffnessAnswer>::Answer
            )),+
        }

        impl Answer {
            /// The displacement the benchmark compares: the beams' w(L), the plate's u(L), the
            /// lap joint's Delta (mm).
            pub fn response(&self) -> f64 {
                match self {
                    $(Answer::$variant(answer) => {
                        <crate::problems::$folder::$problem as StiffnessAnswer>::answer_response(
                            answer,
                        )
                    })+
                }
            }
        }

        /// What `kt` does to `model` (at the model's force where it has one); `None` for an
        /// invalid K_T.
        fn answer_for_stiffness(model: &Model, kt: f64) -> Option<Answer> {
            $(if let Some(typed) = <crate::problems::$folder::$problem as Problem>::from_model(model) {
                return <crate::problems::$folder::$problem as StiffnessAnswer>::answer(&typed, kt)
                    .map(Answer::$variant);
            })+
            None
        }

        /// Coulomb's w(L) (beams), u(L) (plate) or Delta (lap) for `model` at its force: the
        /// K_T -> infinity limit the `vs Coulomb` column divides by.
        fn coulomb_response(model: &Model) -> f64 {
            $(if let Some(typed) = <crate::problems::$folder::$problem as Problem>::from_model(model) {
                return <crate::problems::$folder::$problem as StiffnessAnswer>::coulomb_response(
                    &typed,
                );
            })+
            f64::NAN
        }
    };
}

crate::with_problems!(answers);

/// One row of the K_T comparison: the candidate and, when it has a valid K_T, its answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComparedStiffness {
    /// The candidate.
    pub candidate: StiffnessCandidate,
    /// What it does to the model.
    pub answer: Option<Answer>,
    /// How far its w(L) (beams) or u(L) (plate) is from the current K_T's (fraction: +0.6 is 60 %
    /// more): what an FE model with this K_T gets wrong when the model's K_T is the interface's
    /// true one. None without an answer, or when the current answer is zero (no load).
    pub off_current: Option<f64>,
    /// How far its w(L), u(L) or Delta is from Coulomb's (K_T -> infinity), as a fraction: what
    /// an FE model with this K_T gets wrong when the interface is rigid until it slides (the
    /// figure users otherwise compute by hand). None without an answer, or when Coulomb's answer
    /// is zero (no load).
    pub off_coulomb: Option<f64>,
}

/// The K_T values worth comparing for one model and what each does to the answer: computed once,
/// shown by the text and JSON reports and the TUI table alike.
///
/// # Examples
/// ```
/// use microslip_core::study::candidates::{Answer, CandidateSource, compare_stiffnesses};
/// use microslip_core::{Inputs, ModelKind};
/// let model = Inputs::paper(ModelKind::Plate).validate()?;
/// // Contact elements of 0.1 mm, and K_N = 1e6 MPa/mm at nu = 0.3 for paper eq. 4.
/// let table = compare_stiffnesses(&model, 0.1, Some((1e6, 0.3)));
/// let eq4 = table
///     .rows
///     .iter()
///     .find(|r| matches!(r.candidate.source, CandidateSource::Equation4 { .. }))
///     .unwrap();
/// assert!((eq4.candidate.kt.unwrap() - 6.47e5).abs() < 1e3); // MPa/mm
/// assert!(matches!(eq4.answer, Some(Answer::Plate(_))));
/// # Ok::<(), microslip_core::ParamError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessComparison {
    /// The model compared (its own K_T is the first row).
    pub model: Model,
    /// Contact element length assumed for the codes' defaults (mm).
    pub element: f64,
    /// The rows: current, those from K_N (when given), then each code.
    pub rows: Vec<ComparedStiffness>,
}

/// Compares the K_T values worth comparing for `model`: the current one, those from a normal contact
/// stiffness `normal` = (K_N (MPa/mm), nu) (paper eq. 4 and the measured K_T/K_N range), and those
/// FE codes assume by default for contact elements of length `element` (mm).
pub fn compare_stiffnesses(
    model: &Model,
    element: f64,
    normal: Option<(f64, f64)>,
) -> StiffnessComparison {
    use crate::kernel::code_defaults::{CODE_DEFAULTS, MEASURED_RATIO_RANGE};
    use crate::problems::stiffness::tangential_from_normal;
    let data = model.interface();
    let mut candidates = vec![StiffnessCandidate {
        source: CandidateSource::Current,
        kt: Some(data.stiffness),
    }];
    if let Some((kn, nu)) = normal {
        let (low, high) = MEASURED_RATIO_RANGE;
        candidates.extend([
            StiffnessCandidate {
                source: CandidateSource::NormalLow,
                kt: Some(low * kn),
            },
            StiffnessCandidate {
                source: CandidateSource::Equation4 { nu },
                kt: tangential_from_normal(kn, nu).ok(),
            },
            StiffnessCandidate {
                source: CandidateSource::NormalHigh,
                kt: Some(high * kn),
            },
        ]);
    }
    candidates.extend(CODE_DEFAULTS.iter().map(|code| StiffnessCandidate {
        source: CandidateSource::Code(code),
        kt: code.implied_stiffness(data.friction, data.pressure, data.modulus, element),
    }));
    let current = answer_for_stiffness(model, data.stiffness)
        .map(|a| a.response())
        .filter(|r| *r != 0.0);
    let coulomb = Some(coulomb_response(model)).filter(|r| *r != 0.0 && r.is_finite());
    let rows = candidates
        .into_iter()
        .map(|candidate| {
            let answer = candidate.kt.and_then(|kt| answer_for_stiffness(model, kt));
            ComparedStiffness {
                candidate,
                answer,
                off_current: answer.zip(current).map(|(a, c)| a.response() / c - 1.0),
                off_coulomb: answer.zip(coulomb).map(|(a, c)| a.response() / c - 1.0),
            }
        })
        .collect();
    StiffnessComparison {
        model: *model,
        element,
        rows,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stiffness_comparison_answers_every_valid_candidate() {
        let model = crate::Inputs::paper(crate::ModelKind::Beam)
            .validate()
            .unwrap();
        let table = compare_stiffnesses(&model, 2.0, Some((1000.0, 0.3)));
        assert_eq!(table.rows[0].candidate.source, CandidateSource::Current);
        assert!(matches!(
            table.rows[0].answer,
            Some(Answer::Beam(a)) if (a.micro_end - 17.3095).abs() < 1e-4
        ));
        assert!(matches!(
            table.rows[2].candidate.source,
            CandidateSource::Equation4 { nu } if nu == 0.3
        ));
        for row in &table.rows {
            assert_eq!(row.answer.is_some(), row.candidate.kt.is_some());
            assert_eq!(row.off_current.is_some(), row.answer.is_some());
        }
        // How far off each candidate is: its w(L) over the current K_T's, from the beams solved
        // at both stiffnesses here; 0 for the current row, above for softer, below for stiffer.
        let Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, force }) = model
        else {
            panic!()
        };
        let w = |kt: f64| {
            beams
                .with_tangential_stiffness(kt)
                .unwrap()
                .regularized(force)
                .tip_deflection()
        };
        for row in &table.rows {
            let (Some(kt), Some(off)) = (row.candidate.kt, row.off_current) else {
                continue;
            };
            let expected = w(kt) / w(600.0) - 1.0;
            assert!((off - expected).abs() < 1e-12, "{kt}: {off} vs {expected}");
            assert_eq!(off > 0.0, kt < 600.0, "{kt}: {off}");
        }
        assert_eq!(table.rows[0].off_current, Some(0.0));
        // No load, no displacement to compare against: nothing is said.
        let unloaded = Model::Beam(crate::problems::twin_beams::problem::BeamsModel {
            beams,
            force: crate::TipForce::new(0.0).unwrap(),
        });
        let table = compare_stiffnesses(&unloaded, 2.0, None);
        assert!(table.rows.iter().all(|r| r.off_current.is_none()));
    }
}
