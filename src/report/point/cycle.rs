//! `microslip cycle`: one load cycle's summary for both laws, of any load-driven problem (the
//! twin beams, the lap joint): the same numbers from [`MasingCycle`], each problem's own words.

use std::fmt::Write;

use serde::Serialize;
use serde::ser::SerializeStruct;

use super::InputsReport;
use crate::kernel::regime::Law;
use crate::problems::inputs::Inputs;
use crate::problems::lap::LapJointProblem;
use crate::problems::lap::closed_form::{JointForce, LapJoint, LapParams};
use crate::problems::load_driven::{LoadDriven, MasingCycle};
use crate::problems::twin_beams::TwinBeamsProblem;
use crate::report::{number, sanitize};
use crate::{TipForce, TwinBeams, TwinBeamsParams};

/// What D, U and the secant stiffness refer to: said wherever they appear (text, JSON, help, TUI).
pub(crate) const CYCLE_UNITS_NOTE: &str = "D and U are for the pair (both beams' tip forces, the whole \
     interface; U = 1/2 (2 F_a) w_a); the secant stiffness F_a/w_a and the loop w(F) are one beam's \
     (the loop's area is D/2).";

/// What D, U and the secant stiffness of the lap joint refer to.
pub(crate) const LAP_CYCLE_NOTE: &str = "D is the whole joint's (both interfaces); U = 1/2 F_a \
     Delta_a; the secant stiffness is F_a / Delta_a of the joint.";

/// A load-driven structure cycled between +F_a and -F_a: `S` is its parameters (the twin
/// beams', the lap joint's), for the text's one-line summary.
#[derive(Debug, Clone, Serialize)]
pub struct CycleReport<S: 'static> {
    /// `beam` or `lap`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// The structure, for the text's one-line summary.
    #[serde(skip)]
    pub structure: S,
    /// Amplitude F_a (N).
    #[serde(rename = "Fa_N")]
    pub amplitude: f64,
    pub coulomb: LawCycle,
    pub regularized: LawCycle,
    /// A note on the units: what D, U and the secant stiffness are of (`CYCLE_UNITS_NOTE`,
    /// `LAP_CYCLE_NOTE`).
    pub note: &'static str,
    /// The problem's words in the text.
    #[serde(skip)]
    words: &'static CycleWords<S>,
}

/// The twin beams cycled between +F_a and -F_a.
pub type BeamCycleReport = CycleReport<TwinBeamsParams>;

/// The lap joint cycled between +F_a and -F_a.
pub type LapCycleReport = CycleReport<LapParams>;

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

/// A problem's words in its cycle report: the JSON key of the peak, the heading, the line that
/// gives the structure `S`, the labels of the six rows of the text's table, and the note.
#[derive(Debug)]
struct CycleWords<S> {
    model: &'static str,
    peak_key: &'static str,
    /// What is cycled and by which load: (`Twin beams`, `tip force`).
    heading: (&'static str, &'static str),
    structure: fn(&S) -> String,
    rows: [&'static str; 6],
    note: &'static str,
}

static BEAM_WORDS: CycleWords<TwinBeamsParams> = CycleWords {
    model: "beam",
    peak_key: "w_peak_mm",
    heading: ("Twin beams", "tip force"),
    structure: |p| {
        format!(
            "L = {} mm, b = {} mm, h = {} mm, E = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
            number(p.length),
            number(p.width),
            number(p.half_height),
            number(p.youngs_modulus),
            number(p.pressure),
            number(p.friction),
            number(p.tangential_stiffness)
        )
    },
    rows: [
        "onset of sliding (N)",
        "peak deflection w_a (mm)",
        "D per cycle, both beams (N mm)",
        "peak energy U, both (N mm)",
        "damping ratio D / (4 pi U) (-)",
        "secant F_a/w_a, 1 beam (N/mm)",
    ],
    note: CYCLE_UNITS_NOTE,
};

static LAP_WORDS: CycleWords<LapParams> = CycleWords {
    model: "lap",
    peak_key: "Delta_peak_mm",
    heading: ("Double-lap joint", "force"),
    structure: |p| {
        format!(
            "L = {} mm, b = {} mm, t1 = {} mm, t2 = {} mm, E1 = {} MPa, E2 = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
            number(p.length),
            number(p.width),
            number(p.inner_thickness),
            number(p.cover_thickness),
            number(p.inner_modulus),
            number(p.cover_modulus),
            number(p.pressure),
            number(p.friction),
            number(p.tangential_stiffness)
        )
    },
    rows: [
        "onset of sliding (N)",
        "peak displacement Delta_a (mm)",
        "D per cycle (N mm)",
        "peak energy U (N mm)",
        "damping ratio D / (4 pi U) (-)",
        "secant F_a/Delta_a (N/mm)",
    ],
    note: LAP_CYCLE_NOTE,
};

impl<S: 'static> CycleReport<S> {
    /// The report of `model` cycled at `amplitude`, both laws, in the problem's `words`.
    fn cycled<P: LoadDriven>(
        words: &'static CycleWords<S>,
        preset: &str,
        (inputs, structure): (Inputs, S),
        model: &P::Structure,
        amplitude: P::Force,
    ) -> CycleReport<S> {
        let law = |law| LawCycle::new(&P::cycle(model, law, amplitude), words.peak_key);
        CycleReport {
            model: words.model,
            preset: preset.to_string(),
            inputs: InputsReport(inputs),
            structure,
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
        let _ = writeln!(out, "  {}", (words.structure)(&self.structure));
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

impl CycleReport<TwinBeamsParams> {
    pub fn new(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> BeamCycleReport {
        let inputs = Inputs::Beam(crate::problems::twin_beams::problem::BeamsInputs {
            structure: beams.params(),
            force: amplitude.newtons(),
        });
        Self::cycled::<TwinBeamsProblem>(
            &BEAM_WORDS,
            preset,
            (inputs, beams.params()),
            beams,
            amplitude,
        )
    }
}

impl CycleReport<LapParams> {
    pub fn new(preset: &str, joint: &LapJoint, amplitude: JointForce) -> LapCycleReport {
        let inputs = Inputs::Lap(crate::problems::lap::problem::LapInputs {
            structure: joint.params(),
            force: amplitude.newtons(),
        });
        Self::cycled::<LapJointProblem>(
            &LAP_WORDS,
            preset,
            (inputs, joint.params()),
            joint,
            amplitude,
        )
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
