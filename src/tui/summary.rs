//! The lines of the regime pane and what each means: shared by the pane, the explanation of `i`
//! and the app (which moves through them). Text only, no drawing. Each problem writes its own
//! lines in its face folder (`src/problems/<name>/pane.rs`, a [`PaneFace`]); this file asks the
//! face of the model's problem.
//!
//! [`PaneFace`]: crate::chart::panes::PaneFace

use crate::problems::inputs::Model;
use crate::report::face::faces;

pub use crate::chart::panes::{ContinuumState, SummaryLine};

/// The regime pane's title after "Regime (i), " ("FE within 3.02 %") and what it means: a pane
/// full at 80x24 (the beams', the lap joint's) puts its envelope in the title, and `i` explains
/// it as the first of the pane's lines. None where the validity is a line (the plate).
pub fn title_line(model: &Model) -> Option<SummaryLine> {
    faces(model.kind()).pane.title_line(model)
}

/// The lines of the regime pane for `model`; `continuum`: the pane's own 2-D continuum solve.
pub fn summary_lines(model: &Model, continuum: &ContinuumState) -> Vec<SummaryLine> {
    faces(model.kind()).pane.summary_lines(model, continuum)
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
