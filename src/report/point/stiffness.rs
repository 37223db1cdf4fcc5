//! `microslip kt`: the K_T candidates (the model's, from K_N, the FE codes' defaults) and what
//! each does to the answer.

use std::fmt::Write;

use serde::Serialize;

use crate::kernel::params::ParamSpec;
use crate::problems::{ModelKind, Quantity};
use crate::report::face::{KtHeading, KtRow, ReportFace, faces, kt_row};
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

/// Writes [`CandidateAnswer`] from the registry: a variant per problem holding its
/// [`ReportFace::KtAnswer`], and the dispatch to its [`ReportFace`].
macro_rules! candidate_answers {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// What a K_T candidate does to the answer (the problem's own fields, flattened into
        /// the row), or why it was not evaluated.
        #[derive(Debug, Clone, Serialize)]
        #[serde(untagged)]
        pub enum CandidateAnswer {
            $($(#[$doc])* $variant(<crate::problems::$folder::$problem as ReportFace>::KtAnswer),)+
            /// A K_T the model refuses: said rather than left out silently.
            Refused {
                /// Why.
                not_evaluated: String,
            },
        }

        impl CandidateAnswer {
            /// `answer` as problem `kind`'s.
            fn of(kind: ModelKind, answer: &Answer) -> Option<CandidateAnswer> {
                match kind {
                    $(ModelKind::$variant => {
                        <crate::problems::$folder::$problem as ReportFace>::kt_answer(answer)
                            .map(CandidateAnswer::$variant)
                    })+
                }
            }

            /// The table row of `row` with `answer` (dashes without one, in `kind`'s columns).
            fn row(answer: Option<&CandidateAnswer>, kind: ModelKind, row: &KtRow) -> String {
                match answer {
                    $(Some(CandidateAnswer::$variant(a)) => {
                        kt_row::<crate::problems::$folder::$problem>(row, Some(a))
                    })+
                    None | Some(CandidateAnswer::Refused { .. }) => {
                        faces(kind).report.kt_row_unanswered(row)
                    }
                }
            }
        }
    };
}

microslip_core::with_problems!(candidate_answers);

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

impl CandidateReport {
    /// The report of `row`, a candidate of a problem `kind`.
    fn new(kind: ModelKind, row: &ComparedStiffness) -> Self {
        let kt = row.candidate.kt;
        let refused = |kt: f64| {
            let spec = stiffness_spec(kind)?;
            spec.domain.check(spec.name, kt, spec.unit).err()
        };
        let answer = match &row.answer {
            Some(answer) => CandidateAnswer::of(kind, answer),
            None => kt
                .and_then(refused)
                .map(|refused| CandidateAnswer::Refused {
                    not_evaluated: refused.to_string(),
                }),
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

/// The spec of `kind`'s tangential stiffness K_T (its domain says which K_T it refuses).
fn stiffness_spec(kind: ModelKind) -> Option<ParamSpec> {
    kind.params()
        .iter()
        .find(|p| p.is_stiffness())
        .map(|p| p.spec())
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
                .faces()
                .load_driven
                .and_then(|load_driven| load_driven.applied_force(model)),
            friction_stress: interface.friction * interface.pressure,
            candidates: comparison
                .rows
                .iter()
                .map(|row| CandidateReport::new(comparison.model.kind(), row))
                .collect(),
        }
    }

    /// The readable table: each candidate and what it does to the answer.
    pub fn text(&self) -> String {
        let preset = sanitize(&self.preset);
        let mut out = String::new();
        let (mu_p, element) = (number(self.friction_stress), number(self.element));
        let face = faces(self.kind).report;
        out.push_str(&face.kt_heading(&KtHeading {
            preset: &preset,
            force: self.force,
            friction_stress: &mu_p,
            element: &element,
        }));
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
            let line = KtRow {
                source,
                kt: &kt,
                vs_current: &off,
                vs_coulomb: &off_coulomb,
                unanswered,
                basis,
            };
            out.push_str(&CandidateAnswer::row(row.answer.as_ref(), self.kind, &line));
        }
        let refused = self.candidates.iter().any(|row| {
            row.kt.is_some() && matches!(row.answer, None | Some(CandidateAnswer::Refused { .. }))
        });
        if let (true, Some(stiffness)) = (refused, stiffness_spec(self.kind)) {
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
        let mu_p = crate::report::face::faces(self.kind)
            .report
            .friction_stress();
        let _ = writeln!(
            out,
            "Elastic-slip defaults scale like {mu_p} / element length, here contact elements of \
             {element} mm (a hundredth of the contact's length unless --element-size MM gives \
             your mesh's): halve the elements, double K_T."
        );
        out
    }
}
