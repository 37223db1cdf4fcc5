//! `microslip cycle`: one load cycle's summary for both laws.

use std::fmt::Write;

use serde::Serialize;

use super::InputsReport;
use crate::problems::inputs::Inputs;
use crate::problems::twin_beams::cycle::{Cycle, Law, MasingCycle};
use crate::report::{number, sanitize};
use crate::{TipForce, TwinBeams, TwinBeamsParams};

/// What D, U and the secant stiffness refer to: said wherever they appear (text, JSON, help, TUI).
pub(crate) const CYCLE_UNITS_NOTE: &str = "D and U are for the pair (both beams' tip forces, the whole \
     interface; U = 1/2 (2 F_a) w_a); the secant stiffness F_a/w_a and the loop w(F) are one beam's \
     (the loop's area is D/2).";

/// The twin beams cycled between +F_a and -F_a.
#[derive(Debug, Clone, Serialize)]
pub struct CycleReport {
    /// Always `beam`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// The structure, for the text's one-line summary.
    #[serde(skip)]
    pub structure: TwinBeamsParams,
    /// Amplitude F_a (N).
    #[serde(rename = "Fa_N")]
    pub amplitude: f64,
    pub coulomb: LawCycle,
    pub regularized: LawCycle,
    /// A note on the units: D and U are for the pair of beams (the text of `CYCLE_UNITS_NOTE`).
    pub note: &'static str,
}

/// One law's cycle.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct LawCycle {
    /// Force at which sliding starts (N).
    #[serde(rename = "onset_N")]
    pub onset: f64,
    /// Peak deflection w_a (mm).
    #[serde(rename = "w_peak_mm")]
    pub peak_deflection: f64,
    /// Dissipation per cycle, both beams (N mm).
    #[serde(rename = "D_Nmm")]
    pub dissipation: f64,
    /// Peak energy, both beams (N mm).
    #[serde(rename = "U_Nmm")]
    pub peak_energy: f64,
    /// D / (4 pi U).
    #[serde(rename = "zeta")]
    pub damping_ratio: f64,
    /// F_a / w_a, one beam (N/mm).
    #[serde(rename = "secant_stiffness_N_per_mm")]
    pub secant_stiffness: f64,
}

impl LawCycle {
    fn new(beams: &TwinBeams, law: Law, amplitude: TipForce) -> LawCycle {
        let c = Cycle::new(beams, law, amplitude);
        LawCycle {
            onset: c.onset(),
            peak_deflection: c.peak_deflection(),
            dissipation: c.dissipation(),
            peak_energy: c.peak_energy(),
            damping_ratio: c.damping_ratio(),
            secant_stiffness: c.secant_stiffness(),
        }
    }
}

impl CycleReport {
    pub fn new(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> CycleReport {
        CycleReport {
            model: "beam",
            preset: preset.to_string(),
            inputs: InputsReport(Inputs::Beam {
                structure: beams.params(),
                force: amplitude.newtons(),
            }),
            structure: beams.params(),
            amplitude: amplitude.newtons(),
            coulomb: LawCycle::new(beams, Law::Coulomb, amplitude),
            regularized: LawCycle::new(beams, Law::Regularized, amplitude),
            note: CYCLE_UNITS_NOTE,
        }
    }

    /// The readable summary: both laws side by side.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Twin beams, tip force cycling between +{0} N and -{0} N (Masing branches) - preset {1}",
            number(self.amplitude),
            sanitize(&self.preset)
        );
        let p = &self.structure;
        let _ = writeln!(
            out,
            "  L = {} mm, b = {} mm, h = {} mm, E = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
            number(p.length),
            number(p.width),
            number(p.half_height),
            number(p.youngs_modulus),
            number(p.pressure),
            number(p.friction),
            number(p.tangential_stiffness)
        );
        let _ = writeln!(out, "{:<34}{:<18}regularized", "", "Coulomb");
        let (c, r) = (&self.coulomb, &self.regularized);
        let rows: [(&str, f64, f64); 6] = [
            ("onset of sliding (N)", c.onset, r.onset),
            (
                "peak deflection w_a (mm)",
                c.peak_deflection,
                r.peak_deflection,
            ),
            (
                "D per cycle, both beams (N mm)",
                c.dissipation,
                r.dissipation,
            ),
            ("peak energy U, both (N mm)", c.peak_energy, r.peak_energy),
            (
                "damping ratio D / (4 pi U) (-)",
                c.damping_ratio,
                r.damping_ratio,
            ),
            (
                "secant F_a/w_a, 1 beam (N/mm)",
                c.secant_stiffness,
                r.secant_stiffness,
            ),
        ];
        write_law_rows(&mut out, &rows);
        let _ = writeln!(out, "  {}", self.note);
        out
    }
}

/// A cycle summary's table: its heading, then a label and the Coulomb and regularized values per
/// row.
pub(crate) fn write_law_rows(out: &mut String, rows: &[(&str, f64, f64)]) {
    for (label, coulomb, regularized) in rows {
        let _ = writeln!(
            out,
            "  {label:<32}{:<18}{}",
            number(*coulomb),
            number(*regularized)
        );
    }
}
