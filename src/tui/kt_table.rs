//! The K_T table the TUI shows in place of a chart (`c` past the last chart): which K_T each FE
//! code assumes and what it does to the answer, laid out to fit the chart pane of an 80x24
//! screen (44 columns). Text for the screen, so it lives with the screen; `microslip kt` prints
//! the full comparison from the same `study::curves::compare_stiffnesses`.

use crate::kernel::format::{number, number_with};
use crate::problems::LoadDriven;
use crate::problems::inputs::Model;
use crate::problems::lap::LapJointProblem;
use crate::problems::twin_beams::TwinBeamsProblem;
use crate::study::curves::{self, Answer, CandidateSource};
use crate::study::tolerance::{
    Threshold, ToleranceAnswer, ToleranceError, plate_stiffness_for_tolerance,
    stiffness_for_tolerance,
};

/// The table's title.
pub const TITLE: &str = "K_T that FE codes assume by default";

/// Contact elements assumed by the K_T table: L/100, a typical benchmark mesh (the command line's
/// `microslip kt --element-size` sets any other).
const TABLE_ELEMENTS_PER_LENGTH: f64 = 100.0;

/// A table cell of at most `width` characters: 3 significant digits, fewer for the long exponent
/// forms of extreme values (`6.67e-17` becomes `6.7e-17`).
fn cell(value: f64, width: usize) -> String {
    (1..=3)
        .rev()
        .map(|digits| number_with(value, digits))
        .find(|text| text.len() <= width)
        .unwrap_or_else(|| number_with(value, 1))
}

/// The tolerance the K_T table answers for: 1 % of Coulomb (`microslip kt --tolerance` takes any).
const TABLE_TOLERANCE: f64 = 0.01;

/// A tolerance answer in a cell: `>= K_T`, `> K_T` where even the stiffest is not within, `-`
/// where there is no answer.
fn shown(answer: Result<ToleranceAnswer, ToleranceError>) -> String {
    match answer.map(|a| a.threshold) {
        Ok(Threshold::Stiffness(k) | Threshold::Everywhere(k)) => format!(">= {}", cell(k, 7)),
        Ok(Threshold::Nowhere { stiffness, .. }) => format!("> {}", cell(stiffness, 7)),
        Err(_) => "-".to_string(),
    }
}

/// The K_T table's answer to "how stiff for Coulomb within 1 %": the beams at F and over 0..F, the
/// plate at its pressure.
fn tolerance_lines(model: &Model, element: f64) -> Vec<String> {
    let within = format!(
        "within {} % of Coulomb: K_T",
        number(100.0 * TABLE_TOLERANCE)
    );
    let heading = format!("W{}", &within[1..]);
    match model {
        Model::Beam { beams, force } => {
            load_tolerance_lines::<TwinBeamsProblem>(beams, force.newtons(), &heading, element)
        }
        Model::Lap { joint, force } => {
            load_tolerance_lines::<LapJointProblem>(joint, force.newtons(), &heading, element)
        }
        Model::Plate(plate) => vec![format!(
            "u(L) {within} {}",
            shown(plate_stiffness_for_tolerance(
                plate,
                TABLE_TOLERANCE,
                element
            ))
        )],
    }
}

/// [`tolerance_lines`] of any load-driven problem at the force `f` (N): the smallest K_T within
/// the table's tolerance at F and at every F up to F; any K_T at F = 0, where nothing slides.
fn load_tolerance_lines<P: LoadDriven>(
    structure: &P::Structure,
    f: f64,
    heading: &str,
    element: f64,
) -> Vec<String> {
    if f <= 0.0 {
        return vec![format!("{heading}: any, at F = 0")];
    }
    let within = |range| stiffness_for_tolerance::<P>(structure, range, TABLE_TOLERANCE, element);
    vec![
        format!("{heading} {} at F,", shown(within([f, f]))),
        format!("  {} at all F up to F", shown(within([0.0, f]))),
    ]
}

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
    let mut lines = vec![match model {
        Model::Beam { .. } => format!(
            "{:<10} {:>7} {:>7} {:>7} {:>8}",
            "source", "K_T", "F_1 N", "X mm", "w(L) mm"
        ),
        Model::Plate(_) => format!(
            "{:<10} {:>7} {:>9} {:>8}",
            "source", "K_T", "u(L) mm", "X_r mm"
        ),
        Model::Lap { .. } => format!(
            "{:<10} {:>7} {:>7} {:>7} {:>8}",
            "source", "K_T", "F_1 N", "a+d mm", "Delta mm"
        ),
    }];
    for row in &comparison.rows {
        let cells = match (row.candidate.kt, row.answer) {
            (
                Some(k),
                Some(Answer::Beam {
                    first_macroslip_force,
                    micro_end,
                    tip_deflection,
                    ..
                }),
            ) => format!(
                "{:>7} {:>7} {:>7} {:>8}",
                cell(k, 7),
                cell(first_macroslip_force, 7),
                cell(micro_end, 7),
                cell(tip_deflection, 8)
            ),
            (
                Some(k),
                Some(Answer::Plate {
                    end_displacement,
                    micro_end,
                    ..
                }),
            ) => format!(
                "{:>7} {:>9} {:>8}",
                cell(k, 7),
                cell(end_displacement, 9),
                cell(micro_end, 8)
            ),
            (
                Some(k),
                Some(Answer::Lap {
                    first_slip_force,
                    zones: (a, d),
                    joint_displacement,
                    ..
                }),
            ) => format!(
                "{:>7} {:>7} {:>7} {:>8}",
                cell(k, 7),
                cell(first_slip_force, 7),
                cell(a + d, 7),
                cell(joint_displacement, 8)
            ),
            (Some(k), None) => format!("{:>7} out of range", cell(k, 7)),
            (None, _) => format!("{:>7}", "none"),
        };
        lines.push(format!("{:<10} {cells}", short(&row.candidate.source)));
    }
    lines.push(String::new());
    lines.extend(tolerance_lines(model, element));
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
