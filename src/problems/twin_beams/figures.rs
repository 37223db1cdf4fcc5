//! The twin beams's figures in `microslip figures` (the paper's data set, with the project's
//! finite-element points where the paper compares with FE, then the cyclic loading this
//! project adds).

use crate::chart::YMode;
use crate::report::figure::PaperFigure;

/// Its figures, in the order `figures` draws them ([`crate::report::figure::PAPER_FIGURES`]
/// gathers every problem's).
pub(crate) const PAPER_FIGURES: &[PaperFigure] = &[
    PaperFigure {
        stem: "beam-w-vs-f",
        preset: "paper-beams",
        chart_key: "w-vs-f",
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T = 600 MPa/mm: tip deflection w(L) against the tip force F, \
                  Coulomb and regularized (K_T/5, K_T, K_T x 5), finite-element points at K_T",
    },
    PaperFigure {
        stem: "beam-w-vs-f-relative",
        preset: "paper-beams",
        chart_key: "w-vs-f",
        y: YMode::Relative,
        finite_elements: true,
        caption: "Twin beams: the same curves as w(L) / w(L)_Coulomb - 1 in %, where the K_T \
                  family separates: constant in stick, falling once Coulomb slides",
    },
    PaperFigure {
        stem: "beam-soft-w-vs-f",
        preset: "paper-beams-soft",
        chart_key: "w-vs-f",
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T/5 = 120 MPa/mm: w(L) against F, finite-element points at \
                  120 MPa/mm",
    },
    PaperFigure {
        stem: "beam-x-vs-f",
        preset: "paper-beams",
        chart_key: "x-vs-f",
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams: end X of the microslip zone (from the clamp) against F, \
                  finite-element points at K_T",
    },
    PaperFigure {
        stem: "beam-soft-x-vs-f",
        preset: "paper-beams-soft",
        chart_key: "x-vs-f",
        y: YMode::Linear,
        finite_elements: true,
        caption: "Twin beams, K_T/5: X against F, finite-element points at 120 MPa/mm",
    },
    PaperFigure {
        stem: "beam-loop",
        preset: "paper-beams",
        chart_key: "loop",
        y: YMode::Linear,
        finite_elements: true,
        caption: "One beam cycled between +F and -F (F = 100 N): the hysteresis loop, both laws, \
                  finite-element points of the same cycle",
    },
    PaperFigure {
        stem: "beam-d-vs-fa",
        preset: "paper-beams",
        chart_key: "d-vs-fa",
        y: YMode::Log,
        finite_elements: false,
        caption: "Twin beams: dissipation per cycle D (both beams) against the amplitude F_a",
    },
];
