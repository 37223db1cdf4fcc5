//! Single-point reports as types: one `Serialize` struct per report (beam, plate, cycle, K_T
//! candidates, K_T tolerance, fit, solve), built once from the physics results. Its JSON is serde
//! of the struct and its text a renderer of the same struct, so the two forms state the same facts
//! and cannot drift; the JSON keys are the struct's field names (renamed where a key carries a
//! unit), pinned by tests/report_contract.rs.
//!
//! JSON goes through [`serde_json::Value`], whose maps are sorted: the keys come out in the
//! alphabetical order scripts have always seen, whatever the order of the fields. Enums the text
//! needs (regimes, validity levels) stay typed in the structs and serialize as their labels.

pub mod cycle;
pub mod fit;
pub mod solve;
pub mod stiffness;
pub mod tolerance;

use std::fmt::Write;

use serde::{Serialize, Serializer};
use serde_json::Value;

use super::json::suffixed;
use super::number;
use crate::Regime;
use crate::kernel::params::Unit;
use crate::kernel::validity::Validity;
use crate::problems::inputs::Inputs;
use crate::problems::stiffness::mpa_per_mm_to_mpa_per_um;

/// A report as a JSON value (sorted keys). Serializing these structs cannot fail: every map key is
/// a string.
pub(crate) fn to_json(report: &impl Serialize) -> Value {
    serde_json::to_value(report).unwrap_or(Value::Null)
}

/// A regime as its label (`stick+macroslip`), as in the CSV files.
pub(crate) fn regime_label<S: Serializer>(regime: &Regime, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(regime.label())
}

/// A validity level as its label (`holds`, `not calibrated`).
pub(crate) fn validity_label<S: Serializer>(v: &Validity, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(v.label())
}

/// Ratios written twice in a JSON object: under the key they always had (deprecated, kept one
/// release) and under that key with `_fraction`, the unit every ratio's name now carries (0.034
/// is 3.4 %), so that no ratio reads as a percentage or a length.
pub(crate) fn serialize_fractions<S: Serializer>(
    entries: &[(&str, f64)],
    s: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut map = s.serialize_map(Some(2 * entries.len()))?;
    for (key, value) in entries {
        map.serialize_entry(key, value)?;
        map.serialize_entry(&format!("{key}_fraction"), value)?;
    }
    map.end()
}

/// The model's parameters: in JSON an object `KEY_unit: value` (`L_mm`, `KT_MPa_per_mm`, `mu`);
/// in text one line per parameter with value, unit and meaning. The keys are the `--set` keys, so
/// two are half sizes: the beams' `h_mm` is the half height (each beam is 2 h_mm high) and the
/// plate's `L_mm` the half-length, where the beams' and the lap joint's `L_mm` are whole lengths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputsReport(pub Inputs);

impl InputsReport {
    /// Each parameter of the model and its value. `get` cannot miss: the parameters come from the
    /// inputs' own model.
    fn values(&self) -> impl Iterator<Item = (crate::problems::Param, f64)> + '_ {
        let inputs = self.0;
        inputs
            .kind()
            .params()
            .iter()
            .map(move |&param| (param, inputs.get(param).unwrap_or(f64::NAN)))
    }

    /// The inputs block of the text reports.
    pub(crate) fn write(&self, out: &mut String) {
        let _ = writeln!(out, "Inputs");
        // The keys' column as wide as the longest key (the press fit's `delta`), at least 3; the
        // values' column narrower by as much, so the meanings stay where they are.
        let key = self
            .values()
            .map(|(p, _)| p.name().len())
            .fold(3, usize::max);
        let value_width = 21usize.saturating_sub(key).max(12);
        for (param, value) in self.values() {
            let spec = param.spec();
            let unit = match spec.unit {
                Unit::Dimensionless => String::new(),
                unit => format!(" {unit}"),
            };
            let mut line = format!(
                "  {:<key$} = {:<value_width$} {}",
                spec.name,
                format!("{}{unit}", number(value)),
                spec.meaning
            );
            if param.is_stiffness() {
                line.push_str(&format!(
                    " ({} MPa/um)",
                    number(mpa_per_mm_to_mpa_per_um(value))
                ));
            }
            let _ = writeln!(out, "{line}");
        }
    }
}

impl Serialize for InputsReport {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(
            self.values()
                .map(|(param, value)| (suffixed(param.name(), param.unit()), value)),
        )
    }
}

/// One threshold of a text report, its name, value (with its unit) and words in columns:
/// `  F_1        = 970.702 N      regularized: sliding starts above it`.
pub(crate) fn threshold_line(out: &mut String, name: &str, value: String, words: &str) {
    let _ = writeln!(out, "  {name:<10} = {value:<14} {words}");
}

/// The two laws side by side in the shear-lag problems' text reports (the lap joint, the press
/// fit): wider than [`SideBySide`], their regimes having three zones. `heading` at the load,
/// then one [`WideLaws::row`] per quantity.
pub(crate) struct WideLaws<'a>(pub &'a mut String);

impl WideLaws<'_> {
    /// The table's heading: `At F = 100 N`, then the laws' names over their columns.
    pub fn heading(&mut self, at: String) {
        let _ = writeln!(self.0, "{at:<28}{:<31}regularized", "Coulomb");
    }

    /// One quantity, Coulomb's value and the regularized law's.
    pub fn row(&mut self, label: &str, coulomb: String, regularized: String) {
        let _ = writeln!(self.0, "  {label:<26}{coulomb:<31}{regularized}");
    }

    /// A value of both laws together (their ratio), in the first column.
    pub fn both(&mut self, label: &str, value: String) {
        let _ = writeln!(self.0, "  {label:<26}{value}");
    }
}

/// The two laws side by side in the text reports: regime, response, zone end and the ratio of
/// the responses.
pub(crate) struct SideBySide {
    pub response: &'static str,
    pub ratio: &'static str,
    pub values: (f64, f64),
    pub regimes: (Regime, Regime),
    pub zone_ends: (String, String),
}

impl SideBySide {
    pub fn write(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "  {:<22}{:<22}{}",
            "regime", self.regimes.0, self.regimes.1
        );
        let _ = writeln!(
            out,
            "  {:<22}{:<22}{}",
            self.response,
            number(self.values.0),
            number(self.values.1)
        );
        let _ = writeln!(
            out,
            "  {:<22}{:<22}{}",
            "zone end (mm)", self.zone_ends.0, self.zone_ends.1
        );
        if self.values.0 > 0.0 {
            let _ = writeln!(
                out,
                "  {:<22}{}",
                self.ratio,
                number(self.values.1 / self.values.0)
            );
        }
    }
}
