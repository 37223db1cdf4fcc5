//! `microslip cycle`: one load cycle's summary for both laws, of any load-driven problem (the
//! twin beams, the lap joint): the same numbers from [`MasingCycle`], each problem's own words.

use std::fmt::Write;

use serde::Serialize;
use serde::ser::SerializeStruct;

use super::InputsReport;
use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::inputs::{Inputs, Model};
use crate::problems::load_driven::{LoadDriven, MasingCycle};
use crate::report::rows::CycleRow;
use crate::report::table::{TableFormat, write_table, write_table_headed};
use crate::report::{number, sanitize};
use crate::study::curves::{RangeError, Samples};
use crate::study::load::{self, LoopPoint};
use crate::study::tolerance::{self, ToleranceAnswer, ToleranceError};

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

    /// One row of the loop's CSV (`cycle --format csv`), its columns in the problem's words
    /// (`w_..._mm`, `Delta_..._mm`).
    type LoopRow: Serialize + Default + for<'a> From<&'a LoopPoint>;

    /// One row of the problem's own F sweep (`sweep beam|lap`, `sweep --vary F`).
    type LoadRow: Serialize + Default + for<'a> From<&'a Self::Point>;

    /// The largest load the structure carries, in the load's unit, where it has one (the lap
    /// joint's F_gross, the cylinder's Q_gross): `kt --tolerance` refuses a range beyond it in
    /// the words of the problem's [`Description::load_bound`](crate::problems::Description).
    /// `None` for a structure that carries any load (the beams slide on, their deflection
    /// grows).
    fn force_limit(_structure: &Self::Structure) -> Option<f64> {
        None
    }

    /// The keys the problem's cycle report wrote before its keys said its load's unit, written
    /// beside them for one release (the cylinder's `Fa_N` beside `Qa_N_per_mm`); `None` (the
    /// default) for a problem whose keys never changed, so that no key names a unit its number
    /// is not in.
    const DEPRECATED_KEYS: Option<CycleKeys> = None;
}

/// Why a table of a load-driven problem was not written: a force the structure does not carry,
/// a sample range refused, or the output failed.
#[derive(Debug)]
pub enum LoadTableError {
    /// The amplitude or force is not accepted by the structure (said of the flag that gave it).
    Force(ParamError),
    /// The samples (count, ends) are refused.
    Range(RangeError),
    /// Writing failed.
    Output(std::io::Error),
}

impl From<std::io::Error> for LoadTableError {
    fn from(e: std::io::Error) -> Self {
        LoadTableError::Output(e)
    }
}

/// A [`CycleFace`] with its types erased: what a command reaches from a problem's kind
/// ([`crate::report::face::AppFaces::cycle`]), each method `None` for a model of another
/// problem. Only the load-driven problems have one, so a command that needs a load (`cycle`,
/// `sweep cycle`, an F sweep) finds out from the problem, not from a list of problems.
pub trait AnyCycleFace: Send + Sync {
    /// The cycle report of `model`'s structure at `amplitude` (N).
    fn report(
        &self,
        preset: &str,
        model: &Model,
        amplitude: f64,
    ) -> Option<Result<CycleReport, ParamError>>;

    /// The loop at `amplitude` (N), `points` per branch, as a table.
    fn write_loop(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        amplitude_points: (f64, u64),
    ) -> Option<Result<(), LoadTableError>>;

    /// One cycle summary per amplitude of `amplitudes`, as a table.
    fn write_cycle_sweep(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        amplitudes: Samples,
    ) -> Option<Result<(), LoadTableError>>;

    /// The problem's own F sweep over `forces`, as a table.
    fn write_force_sweep(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        forces: Samples,
    ) -> Option<Result<(), LoadTableError>>;

    /// [`CycleFace::force_limit`] of `model`'s structure; `None` also for another problem's
    /// model.
    fn force_limit(&self, model: &Model) -> Option<f64>;

    /// The K_T that keeps the response within `tolerance` over the forces `range` (N), of
    /// Coulomb's (`current` false) or of the current K_T's (`current` true), for contact
    /// elements `element` long (`kt --tolerance`).
    fn tolerance(
        &self,
        model: &Model,
        range: [f64; 2],
        tolerance_element: (f64, f64),
        current: bool,
    ) -> Option<Result<ToleranceAnswer, ToleranceError>>;
}

/// The [`AnyCycleFace`] of a [`CycleFace`] problem `P`.
struct CycleOf<P>(std::marker::PhantomData<P>);

/// The erased [`CycleFace`] of `P`: what its [`crate::report::face::ReportFace::cycle`] returns.
pub fn erased<P: CycleFace>() -> &'static dyn AnyCycleFace {
    &CycleOf::<P>(std::marker::PhantomData)
}

impl<P: CycleFace> AnyCycleFace for CycleOf<P> {
    fn report(
        &self,
        preset: &str,
        model: &Model,
        amplitude: f64,
    ) -> Option<Result<CycleReport, ParamError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some(
            P::force(&structure, amplitude)
                .map(|amplitude| CycleReport::new::<P>(preset, &structure, amplitude)),
        )
    }

    fn write_loop(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        (amplitude, points): (f64, u64),
    ) -> Option<Result<(), LoadTableError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some((|| {
            let amplitude = P::force(&structure, amplitude).map_err(LoadTableError::Force)?;
            let points = load::cycle_loop::<P>(&structure, amplitude, points)
                .map_err(LoadTableError::Range)?;
            write_table(&mut &mut *out, format, points.map(|p| P::LoopRow::from(&p)))?;
            Ok(())
        })())
    }

    fn write_cycle_sweep(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        amplitudes: Samples,
    ) -> Option<Result<(), LoadTableError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some((|| {
            let rows =
                load::cycle_sweep::<P>(structure, amplitudes).map_err(LoadTableError::Range)?;
            let keys = P::CYCLE_WORDS.keys;
            write_table_headed(
                &mut &mut *out,
                format,
                &CycleRow::header(keys),
                rows.map(|r| CycleRow::new(&r, keys)),
            )?;
            Ok(())
        })())
    }

    fn write_force_sweep(
        &self,
        out: &mut dyn std::io::Write,
        format: TableFormat,
        model: &Model,
        forces: Samples,
    ) -> Option<Result<(), LoadTableError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some((|| {
            let rows = load::force_sweep::<P>(structure, forces).map_err(LoadTableError::Range)?;
            write_table(&mut &mut *out, format, rows.map(|r| P::LoadRow::from(&r)))?;
            Ok(())
        })())
    }

    fn force_limit(&self, model: &Model) -> Option<f64> {
        P::force_limit(&P::structure(&P::from_model(model)?))
    }

    fn tolerance(
        &self,
        model: &Model,
        range: [f64; 2],
        (tol, element): (f64, f64),
        current: bool,
    ) -> Option<Result<ToleranceAnswer, ToleranceError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some(if current {
            tolerance::stiffness_near_current::<P>(&structure, range, tol, element)
        } else {
            tolerance::stiffness_for_tolerance::<P>(&structure, range, tol, element)
        })
    }
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
    /// Amplitude F_a, in the load's unit, under its key ([`CycleKeys::amplitude`]: `Fa_N`,
    /// the cylinder's `Qa_N_per_mm`, and the deprecated one too where they differ).
    #[serde(flatten)]
    pub amplitude: Keyed,
    pub coulomb: LawCycle,
    pub regularized: LawCycle,
    /// A note on the units: what D, U and the secant stiffness are of ([`CycleWords::note`]).
    pub note: &'static str,
    /// The problem's words in the text.
    #[serde(skip)]
    words: CycleWords,
    /// The unit of the cycled load (`N`; the cylinder's line load `N/mm`), for the text.
    #[serde(skip)]
    load_unit: &'static str,
}

/// A number under a key of the problem's words, and under the key every problem had before the
/// keys said the load's unit (deprecated, kept one release) where the two differ.
#[derive(Debug, Clone, Copy)]
pub struct Keyed {
    /// The value.
    pub value: f64,
    /// Its key, in the problem's words (`Qa_N_per_mm`).
    pub key: &'static str,
    /// The deprecated key (`Fa_N`), written too where there is one.
    pub deprecated: Option<&'static str>,
}

impl Serialize for Keyed {
    fn serialize<Z: serde::Serializer>(&self, serializer: Z) -> Result<Z::Ok, Z::Error> {
        use serde::ser::SerializeMap;
        let mut out = serializer.serialize_map(None)?;
        out.serialize_entry(self.key, &self.value)?;
        if let Some(deprecated) = self.deprecated.filter(|&d| d != self.key) {
            out.serialize_entry(deprecated, &self.value)?;
        }
        out.end()
    }
}

/// The keys of a cycle's numbers in JSON and CSV, in the problem's units: a force in N (the
/// beams, the lap joint: [`CycleKeys::FORCE`]) or a line load in N/mm (energies per mm, a
/// secant stiffness per mm), which its problem writes in its [`CycleWords`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CycleKeys {
    /// The amplitude (`Fa_N`).
    pub amplitude: &'static str,
    /// The load at which sliding starts (`onset_N`).
    pub onset: &'static str,
    /// The dissipation per cycle (`D_Nmm`).
    pub dissipation: &'static str,
    /// The peak energy (`U_Nmm`).
    pub peak_energy: &'static str,
    /// The secant stiffness (`secant_stiffness_N_per_mm`).
    pub secant: &'static str,
    /// `sweep cycle`'s dissipation columns, Coulomb's and the regularized law's
    /// (`D_coulomb_Nmm`, `D_regularized_Nmm`).
    pub dissipations: [&'static str; 2],
}

impl CycleKeys {
    /// A load that is a force (N): the keys every load-driven problem had before a line load
    /// joined them, kept as the deprecated keys of the others.
    pub const FORCE: CycleKeys = CycleKeys {
        amplitude: "Fa_N",
        onset: "onset_N",
        dissipation: "D_Nmm",
        peak_energy: "U_Nmm",
        secant: "secant_stiffness_N_per_mm",
        dissipations: ["D_coulomb_Nmm", "D_regularized_Nmm"],
    };
}

/// One law's cycle: the same six numbers for every load-driven problem. Its JSON keys are the
/// problem's [`CycleKeys`] (`onset_N`, the peak's `w_peak_mm` or `Delta_peak_mm`, `D_Nmm`,
/// `U_Nmm`, `zeta` and `secant_stiffness_N_per_mm` for a force), in that order, then the
/// problem's deprecated ones ([`CycleFace::DEPRECATED_KEYS`]) where they differ.
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
    /// The other keys.
    pub keys: CycleKeys,
    /// The deprecated keys written beside them, if any.
    pub deprecated: Option<CycleKeys>,
}

impl LawCycle {
    fn new(
        c: &impl MasingCycle,
        peak_key: &'static str,
        (keys, deprecated): (CycleKeys, Option<CycleKeys>),
    ) -> LawCycle {
        LawCycle {
            onset: c.onset(),
            peak: c.peak_response(),
            dissipation: c.dissipation(),
            peak_energy: c.peak_energy(),
            damping_ratio: c.damping_ratio(),
            secant_stiffness: c.secant_stiffness(),
            peak_key,
            keys,
            deprecated,
        }
    }
}

impl Serialize for LawCycle {
    fn serialize<Z: serde::Serializer>(&self, serializer: Z) -> Result<Z::Ok, Z::Error> {
        let keys = self.keys;
        let mut out = serializer.serialize_struct("LawCycle", 6)?;
        out.serialize_field(keys.onset, &self.onset)?;
        out.serialize_field(self.peak_key, &self.peak)?;
        out.serialize_field(keys.dissipation, &self.dissipation)?;
        out.serialize_field(keys.peak_energy, &self.peak_energy)?;
        out.serialize_field("zeta", &self.damping_ratio)?;
        out.serialize_field(keys.secant, &self.secant_stiffness)?;
        if let Some(old) = self.deprecated.filter(|old| old.onset != keys.onset) {
            out.serialize_field(old.onset, &self.onset)?;
            out.serialize_field(old.dissipation, &self.dissipation)?;
            out.serialize_field(old.peak_energy, &self.peak_energy)?;
            out.serialize_field(old.secant, &self.secant_stiffness)?;
        }
        out.end()
    }
}

/// A problem's words in its cycle report: the JSON key of the peak, the heading, the labels of
/// the six rows of the text's table, and the note.
#[derive(Debug, Clone, Copy)]
pub struct CycleWords {
    /// The peak's JSON key (`w_peak_mm`).
    pub peak_key: &'static str,
    /// The other numbers' keys, in the load's units.
    pub keys: CycleKeys,
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
        let law = |law| {
            LawCycle::new(
                &P::cycle(structure, law, amplitude),
                words.peak_key,
                (words.keys, P::DEPRECATED_KEYS),
            )
        };
        // The cycle walks one family of loads (its branches, the work integrals): one scope
        // (issue 47), the same for the CLI, the TUI and Python.
        crate::kernel::family::scope(|| CycleReport {
            model: P::INFO.key,
            preset: preset.to_string(),
            inputs: InputsReport(P::cycle_inputs(structure, amplitude)),
            structure: P::structure_line(structure),
            amplitude: Keyed {
                value: P::load_value(amplitude),
                key: words.keys.amplitude,
                deprecated: P::DEPRECATED_KEYS.map(|old| old.amplitude),
            },
            coulomb: law(Law::Coulomb),
            regularized: law(Law::Regularized),
            note: words.note,
            words,
            load_unit: P::INFO.load.map_or("N", |load| load.spec().unit.symbol()),
        })
    }

    /// The readable summary: what is cycled and its structure, then both laws side by side.
    pub fn text(&self) -> String {
        let words = self.words;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{2}, {3} cycling between +{0} {4} and -{0} {4} (Masing branches) - preset {1}",
            number(self.amplitude.value),
            sanitize(&self.preset),
            words.heading.0,
            words.heading.1,
            self.load_unit,
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
