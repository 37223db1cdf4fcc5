//! The K_T table the TUI shows in place of a chart (`c` past the last chart): which K_T each FE
//! code assumes and what it does to the answer, laid out to fit the chart pane of an 80x24
//! screen (44 columns). Text for the screen, so it lives with the screen; `microslip kt` prints
//! the full comparison from the same `study::curves::compare_stiffnesses`.

use crate::chart::panes::{TABLE_TOLERANCE, cell};
use crate::kernel::format::number;
use crate::problems::inputs::Model;
use crate::report::face::faces;
use crate::study::curves::{self, CandidateSource};

/// The table's title.
pub const TITLE: &str = "K_T that FE codes assume by default";

/// Contact elements assumed by the K_T table: L/100, a typical benchmark mesh (the command line's
/// `microslip kt --element-size` sets any other).
const TABLE_ELEMENTS_PER_LENGTH: f64 = 100.0;

/// The K_T comparison as a narrow table (fits the 44-column chart pane of an 80x24 screen): its
/// title and lines.
pub fn stiffness_table(model: &Model) -> (&'static str, Vec<String>) {
    use crate::kernel::code_defaults::{CODE_DEFAULTS, Confirmation, DefaultRule};
    let element = model.interface().length / TABLE_ELEMENTS_PER_LENGTH;
    let comparison = curves::compare_stiffnesses(model, element, None);
    let short = |source: &CandidateSource| match source {
        CandidateSource::Code(code) => code.short,
        other => other.name(),
    };
    let face = faces(model.kind()).pane;
    let mut lines = vec![format!("{:<10} {}", "source", face.kt_header())];
    for row in &comparison.rows {
        // The face computes its cells at the candidate's K_T, which the comparison answered.
        let cells = match (row.candidate.kt, row.answer) {
            (Some(k), Some(_)) => face
                .kt_cells(model, k)
                .unwrap_or_else(|| format!("{:>7} out of range", cell(k, 7))),
            (Some(k), None) => format!("{:>7} out of range", cell(k, 7)),
            (None, _) => format!("{:>7}", "none"),
        };
        lines.push(format!("{:<10} {cells}", short(&row.candidate.source)));
    }
    lines.push(String::new());
    let within = format!(
        "within {} % of Coulomb: K_T",
        number(100.0 * TABLE_TOLERANCE)
    );
    lines.extend(face.kt_tolerance_lines(model, &within, element));
    lines.push(format!(
        "K_T MPa/mm; FE elements {} mm (L/100)",
        number(element)
    ));
    for code in CODE_DEFAULTS {
        let how = match (code.rule, code.confirmation) {
            (DefaultRule::UserSupplied, _) => "no default: user input",
            (_, Confirmation::Confirmed) => "default confirmed",
            (_, Confirmation::Indirect) => "seen in solver output only",
            (_, Confirmation::NotConfirmed) => "default NOT confirmed",
        };
        lines.push(format!("{}: {how}", code.short));
    }
    lines.push("Other sizes, K_N, tolerances: microslip kt".into());
    (TITLE, lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At every corner of both domains: every line fits the 44-column chart pane of an 80x24
    /// screen (one column for the border's padding) and shows no NaN, infinity or n/a.
    #[test]
    fn every_line_fits_the_pane_and_is_finite_at_every_corner_of_the_domain() {
        for (what, model) in crate::chart::corner_models() {
            let (title, lines) = stiffness_table(&model);
            assert!(title.len() <= 43);
            for line in lines {
                assert!(line.len() <= 43, "{what}: {line}");
                assert!(
                    !line.contains("n/a") && !line.contains("NaN") && !line.contains("inf"),
                    "{what}: {line}"
                );
            }
        }
    }
}
