//! The squeezed plate's figures in `microslip figures` (the paper's data set, with the project's
//! finite-element points where the paper compares with FE).

use crate::chart::YMode;
use crate::report::figure::PaperFigure;

/// Its figures, in the order `figures` draws them ([`crate::report::figure::PAPER_FIGURES`]
/// gathers every problem's).
pub(crate) const PAPER_FIGURES: &[PaperFigure] = &[
    PaperFigure {
        stem: "plate-u-vs-kt",
        preset: "paper-plate",
        chart_key: "u-vs-kt",
        y: YMode::Log,
        finite_elements: true,
        caption: "Squeezed plate: end displacement u(L) against K_T, Coulomb and regularized, \
                  finite-element points and the 2-D plane-strain continuum",
    },
    PaperFigure {
        stem: "plate-xr-vs-mu",
        preset: "paper-plate",
        chart_key: "xr-vs-mu",
        y: YMode::Linear,
        finite_elements: false,
        caption: "Squeezed plate: end X_r of the microslip zone against mu, for K_T/10, K_T, \
                  K_T x 10",
    },
    PaperFigure {
        stem: "plate-pressure",
        preset: "paper-plate",
        chart_key: "pressure",
        y: YMode::Linear,
        finite_elements: false,
        caption: "Squeezed plate: contact pressure P_r(x)/P along the half-plate of the paper's \
                  flat-plate model (P7-P9, friction saturated everywhere); the plane-strain \
                  continuum's is flat away from the free end (docs/theory.md (P12))",
    },
];
