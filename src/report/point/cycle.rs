//! `microslip cycle`: one load cycle's summary for both laws, of any load-driven problem (the
//! twin beams, the lap joint): the same numbers from [`MasingCycle`], each problem's own words.

use std::fmt::Write;

use serde::Serialize;
use serde::ser::SerializeStruct;

use super::InputsReport;
use crate::kernel::regime::Law;
use crate::problems::inputs::Inputs;
use crate::problems::load_driven::{LoadDriven, MasingCycle};
use crate::report::{number, sanitize};

/// A load-driven problem as its cycle report says it: its words, its structure's summary line
/// and the inputs the report lists. Each problem's folder implements it
/// (`src/problems/<name>/report.rs`), so the report is written once for every load-driven problem.
pub trait CycleFace: LoadDriven {
    /// The problem's words in its cycle report.
    const CYCLE_WORDS: CycleWords;

    /// The structure in one line (its parameters with units), under the text's heading.
    fn structure_line(structure: &Self::Structure) -> String;

    /// The inputs the report lists: the structure at the amplitude.
    fn cycle_inputs(structure: &Self::Structure, amplitude: Self::Force) -> Inputs;
}

/// A load-driven structure cycled between +F_a and -F_a.
#[derive(Debug, Clone, Serialize)]
pub struct CycleReport {
    /// `beam` or `lap`: the problem's key.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// The structure in one line, for the text.
    #[serde(skip)]
    pub structure: String,
    /// Amplitude F_a (N).
    #[serde(rename = "Fa_N")]
    pub amplitude: f64,
    pub coulomb: LawCycle,
    pub regularized: LawCycle,
    /// A note on the units: what D, U and the secant stiffness are of ([`CycleWords::note`]).
    pub note: &'static str,
    /// The problem's words in the text.
    #[serde(skip)]
    words: CycleWords,
}

/// One law's cycle: the same six numbers for every load-driven problem. Its JSON keys are
/// `onset_N`, the peak's (`w_peak_mm`, `Delta_peak_mm`: [`LawCycle::peak_key`]), `D_Nmm`,
/// `U_Nmm`, `zeta` and `secant_stiffness_N_per_mm`, in that order.
#[derive(Debug, Clone, Copy)]
pub struct LawCycle {
    /// Force at which sliding starts (N).
    pub onset: f64,
    /// Peak response u_a: the beams' w_a, the joint's Delta_a (mm).
    pub peak: f64,
    /// Dissipation per cycle (N mm).
    pub dissipation: f64,
    /// Peak energy (N mm).
    pub peak_energy: f64,
    /// D / (4 pi U).
    pub damping_ratio: f64,
    /// F_a / u_a (N/mm).
    pub secant_stiffness: f64,
    /// The peak's JSON key.
    pub peak_key: &'static str,
}

impl LawCycle {
    fn new(c: &impl MasingCycle, peak_key: &'static str) -> LawCycle {
        LawCycle {
            onset: c.onset(),
            peak: c.peak_response(),
            dissipation: c.dissipation(),
            peak_energy: c.peak_energy(),
            damping_ratio: c.damping_ratio(),
            secant_stiffness: c.secant_stiffness(),
            peak_key,
        }
    }
}

impl Serialize for LawCycle {
    fn serialize<Z: serde::Serializer>(&self, serializer: Z) -> Result<Z::Ok, Z::Error> {
        let mut out = serializer.serialize_struct("LawCycle", 6)?;
        out.serialize_field("onset_N", &self.onset)?;
        out.serialize_field(self.peak_key, &self.peak)?;
        out.serialize_field("D_Nmm", &self.dissipation)?;
        out.serialize_field("U_Nmm", &self.peak_energy)?;
        out.serialize_field("zeta", &self.damping_ratio)?;
        out.serialize_field("secant_stiffness_N_per_mm", &self.secant_stiffness)?;
        out.end()
    }
}

/// A problem's words in its cycle report: the JSON key of the peak, the heading, the labels of
/// the six rows of the text's table, and the note.
#[derive(Debug, Clone, Copy)]
pub struct CycleWords {
    /// The peak's JSON key (`w_peak_mm`).
    pub peak_key: &'static str,
    /// What is cycled and by which load: (`Twin beams`, `tip force`).
    pub heading: (&'static str, &'static str),
    /// The labels of the text's rows: onset, peak, D, U, damping ratio, secant stiffness.
    pub rows: [&'static str; 6],
    /// What D, U and the secant stiffness refer to: said wherever they appear (text, JSON,
    /// help, TUI).
    pub note: &'static str,
}

impl CycleReport {
    /// The report of `structure` cycled at `amplitude`, both laws, in the problem's words.
    pub fn new<P: CycleFace>(
        preset: &str,
        structure: &P::Structure,
        amplitude: P::Force,
    ) -> CycleReport {
        let words = P::CYCLE_WORDS;
        let law = |law| LawCycle::new(&P::cycle(structure, law, amplitude), words.peak_key);
        CycleReport {
            model: P::INFO.key,
            preset: preset.to_string(),
            inputs: InputsReport(P::cycle_inputs(structure, amplitude)),
            structure: P::structure_line(structure),
            amplitude: P::newtons(amplitude),
            coulomb: law(Law::Coulomb),
            regularized: law(Law::Regularized),
            note: words.note,
            words,
        }
    }

    /// The readable summary: what is cycled and its structure, then both laws side by side.
    pub fn text(&self) -> String {
        let words = self.words;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{2}, {3} cycling between +{0} N and -{0} N (Masing branches) - preset {1}",
            number(self.amplitude),
            sanitize(&self.preset),
            words.heading.0,
            words.heading.1,
        );
        let _ = writeln!(out, "  {}", self.structure);
        let _ = writeln!(out, "{:<34}{:<18}regularized", "", "Coulomb");
        let (c, r) = (&self.coulomb, &self.regularized);
        let values = [
            (c.onset, r.onset),
            (c.peak, r.peak),
            (c.dissipation, r.dissipation),
            (c.peak_energy, r.peak_energy),
            (c.damping_ratio, r.damping_ratio),
            (c.secant_stiffness, r.secant_stiffness),
        ];
        let rows: Vec<(&str, f64, f64)> = words
            .rows
            .iter()
            .zip(values)
            .map(|(label, (c, r))| (*label, c, r))
            .collect();
        write_law_rows(&mut out, &rows);
        let _ = writeln!(out, "  {}", self.note);
        out
    }
}

/// A cycle summary's table: its heading, then a label and the Coulomb and regularized values per
/// row.
fn write_law_rows(out: &mut String, rows: &[(&str, f64, f64)]) {
    for (label, coulomb, regularized) in rows {
        let _ = writeln!(
            out,
            "  {label:<32}{:<18}{}",
            number(*coulomb),
            number(*regularized)
        );
    }
}
