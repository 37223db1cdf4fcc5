//! `microslip kt --tolerance`: the smallest K_T within a tolerance of Coulomb (or the interval
//! within a tolerance of the current K_T's answer, `--of current`), and each FE code's setting for
//! it.

use std::fmt::Write;

use serde::Serialize;

use crate::problems::Quantity;
use crate::report::face::{faces, load_words};
use crate::report::{number, number_with, sanitize};
use crate::study::tolerance::{CodeSetting, Setting, Threshold, ToleranceAnswer};

/// The answer, as scripts read it (JSON) and people (text).
#[derive(Debug, Clone, Serialize)]
pub struct ToleranceReport {
    pub preset: String,
    /// The tolerance (fraction).
    pub tolerance: f64,
    /// The loads checked [from, to], in the load's unit, under a key that says it
    /// (`force_range_N`; the cylinder's line load `load_range_N_per_mm`, and `force_range_N`
    /// too, deprecated, kept one release); null for the plate (no load).
    #[serde(flatten)]
    pub loads: LoadRange,
    /// The smallest K_T within (the interval's lower end with `of` = current); null: none.
    #[serde(rename = "KT_min_MPa_per_mm")]
    pub kt_min: Option<f64>,
    /// What `KT_min` is.
    pub note: &'static str,
    #[serde(rename = "current_KT_MPa_per_mm")]
    pub current_kt: f64,
    /// The current K_T's worst deviation from Coulomb (fraction).
    pub current_deviation: f64,
    /// Each code's setting for `KT_min`.
    pub codes: Vec<CodeSettingReport>,
    /// What the tolerance is of: `coulomb` or `current`.
    pub of: &'static str,
    /// With `of` = current: the interval's upper end (null: unbounded, and always with coulomb).
    #[serde(rename = "KT_max_MPa_per_mm")]
    pub kt_max: Option<f64>,
    /// With `of` = current: Coulomb's answer against the current K_T's (fraction).
    pub coulomb_vs_current: Option<f64>,
    /// The answer the text renders.
    #[serde(skip)]
    pub answer: ToleranceAnswer,
}

/// [`ToleranceReport::loads`]: the range and the problem whose load it is.
#[derive(Debug, Clone, Copy)]
pub struct LoadRange {
    /// [from, to], in the load's unit; None without a load.
    pub range: Option<[f64; 2]>,
    /// The problem.
    pub kind: crate::problems::ModelKind,
}

impl Serialize for LoadRange {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        const FORCE: &str = "force_range_N";
        let unit = self.kind.description().load.map(|load| load.spec().unit);
        let key = match unit {
            Some(unit) if unit != crate::kernel::params::Unit::Newton => {
                format!("load_range_{}", unit.key())
            }
            _ => FORCE.to_string(),
        };
        let mut out = serializer.serialize_map(None)?;
        out.serialize_entry(&key, &self.range)?;
        if key != FORCE {
            out.serialize_entry(FORCE, &self.range)?;
        }
        out.end()
    }
}

/// One code's setting for the K_T needed.
#[derive(Debug, Clone, Serialize)]
pub struct CodeSettingReport {
    pub code: &'static str,
    #[serde(rename = "default_KT_MPa_per_mm")]
    pub default_kt: Option<f64>,
    pub default_enough: Option<bool>,
    #[serde(flatten)]
    pub needed: NeededReport,
}

/// A code's own setting, its keys as the JSON has them.
#[derive(Debug, Clone, Copy, Serialize)]
#[serde(untagged)]
pub enum NeededReport {
    SlipTolerance {
        slip_tolerance_max: f64,
        element_size_mm: f64,
        elastic_slip_max_mm: f64,
        element_size_max_mm_with_default: f64,
    },
    StickSlope {
        #[serde(rename = "stick_slope_min_MPa_per_mm")]
        stick_slope_min: f64,
    },
    ElementSize {
        h_min_max_mm: f64,
    },
    Stiffness {
        #[serde(rename = "stiffness_min_MPa_per_mm")]
        stiffness_min: f64,
    },
}

impl From<&CodeSetting> for CodeSettingReport {
    fn from(s: &CodeSetting) -> Self {
        let needed = match s.needed {
            Setting::SlipTolerance {
                fraction,
                element,
                slip,
                element_max,
            } => NeededReport::SlipTolerance {
                slip_tolerance_max: fraction,
                element_size_mm: element,
                elastic_slip_max_mm: slip,
                element_size_max_mm_with_default: element_max,
            },
            Setting::StickSlope(k) => NeededReport::StickSlope { stick_slope_min: k },
            Setting::ElementSize(h) => NeededReport::ElementSize { h_min_max_mm: h },
            Setting::Stiffness(k) => NeededReport::Stiffness { stiffness_min: k },
        };
        CodeSettingReport {
            code: s.code.code,
            default_kt: s.default.map(|d| d.0),
            default_enough: s.default.map(|d| d.1),
            needed,
        }
    }
}

impl ToleranceReport {
    pub fn new(preset: &str, answer: &ToleranceAnswer) -> ToleranceReport {
        let (kt_min, note) = match (answer.threshold, answer.near_current.is_some()) {
            (Threshold::Stiffness(k), false) => (Some(k), "smallest K_T within the tolerance"),
            (Threshold::Everywhere(k), false) => {
                (Some(k), "every accepted K_T is within the tolerance")
            }
            (Threshold::Stiffness(k), true) => (
                Some(k),
                "smallest K_T within the tolerance of the current K_T's answer; the largest is \
                 KT_max_MPa_per_mm (null: every stiffer K_T)",
            ),
            (Threshold::Everywhere(k), true) => (
                Some(k),
                "the softest accepted K_T is within the tolerance of the current K_T's answer; \
                 the largest is KT_max_MPa_per_mm (null: every stiffer K_T)",
            ),
            (Threshold::Nowhere { .. }, _) => (None, "no accepted K_T is within the tolerance"),
        };
        ToleranceReport {
            preset: preset.to_string(),
            tolerance: answer.tolerance,
            loads: LoadRange {
                range: answer.forces,
                kind: answer.kind,
            },
            kt_min,
            note,
            current_kt: answer.current.0,
            current_deviation: answer.current.1,
            codes: answer
                .settings
                .iter()
                .map(CodeSettingReport::from)
                .collect(),
            of: if answer.near_current.is_some() {
                "current"
            } else {
                "coulomb"
            },
            kt_max: answer.near_current.and_then(|n| n.upper),
            coulomb_vs_current: answer.near_current.map(|n| n.coulomb),
            answer: answer.clone(),
        }
    }
}

/// A fraction as a percentage, 3 digits.
fn percent_of(fraction: f64) -> String {
    format!("{} %", number_with(100.0 * fraction, 3))
}

/// The name of a code's slip-tolerance setting, read from its description (`SLIP TOLERANCE`,
/// `SLTO`): the words before the default's number.
fn setting_name(description: &str) -> &str {
    description
        .split(|c: char| c.is_ascii_digit())
        .next()
        .unwrap_or(description)
        .trim()
}

impl ToleranceReport {
    /// The readable answer: the K_T (or the interval), the current K_T against it, and each code's
    /// setting.
    pub fn text(&self) -> String {
        let answer = &self.answer;
        let preset = sanitize(&self.preset);
        let tol = percent_of(answer.tolerance);
        let mut out = String::new();
        let quantity = Quantity::Response.name(answer.kind);
        // Where docs/theory.md shows the response never grows with K_T, for this problem.
        let why = faces(answer.kind).report.monotone_in_stiffness();
        let load = answer.kind.description().load;
        let over = match (answer.forces, load) {
            (Some([from, to]), Some(load)) if from == to => {
                format!("at {}", load_words(load, number(to)))
            }
            (Some([from, to]), Some(load)) => {
                let spec = load.spec();
                format!(
                    "at every {} from {} to {} {}",
                    spec.name,
                    number(from),
                    number(to),
                    spec.unit
                )
            }
            _ => format!("at the {}'s pressure", answer.kind),
        };
        let (kt, deviation) = answer.current;
        if let Some(near) = answer.near_current {
            let _ = writeln!(
                out,
                "K_T for which the regularized {quantity} is within {tol} of the current K_T's ({} MPa/mm) {over}, preset {preset}:",
                number(kt)
            );
            // Enough digits to tell the ends apart at a tight tolerance (1e-9: 11 digits).
            let digits = (4.0_f64)
                .max((-answer.tolerance.log10()).ceil() + 2.0)
                .min(15.0) as u32;
            let lower = match answer.threshold {
                Threshold::Stiffness(k) => format!("from {} MPa/mm", number_with(k, digits)),
                Threshold::Everywhere(k) => {
                    format!("from the softest accepted, {} MPa/mm,", number(k))
                }
                // Never: the current K_T itself is within.
                Threshold::Nowhere { .. } => "from the current K_T".to_string(),
            };
            let _ = match near.upper {
                None => writeln!(
                    out,
                    "  {lower} to any stiffer K_T (Coulomb itself is {} off the current answer)",
                    percent_of(near.coulomb)
                ),
                Some(upper) if near.upper_is_largest_accepted => writeln!(
                    out,
                    "  {lower} to the largest accepted K_T, {} MPa/mm (Coulomb itself is {} off the \
                     current answer: outside)",
                    number_with(upper, digits),
                    percent_of(near.coulomb)
                ),
                Some(upper) => writeln!(
                    out,
                    "  {lower} to {} MPa/mm (stiffer ones come closer to Coulomb, {} off the current answer)",
                    number_with(upper, digits),
                    percent_of(near.coulomb)
                ),
            };
            let _ = writeln!(
                out,
                "  (the answer never grows with K_T, docs/theory.md {why} and (T4): every K_T between is \
             within too; the current K_T is {} off Coulomb)",
                percent_of(deviation)
            );
            code_settings_text(&mut out, answer, "the interval's lower end");
            return out;
        }
        let _ = writeln!(
            out,
            "Smallest K_T for which the regularized {quantity} is within {tol} of Coulomb {over}, preset {preset}:"
        );
        let _ = writeln!(
            out,
            "  ({tol} of the Coulomb answer, the K_T -> infinity limit; for {tol} of the current K_T's \
         answer: --of current)"
        );
        let verdict = if deviation <= answer.tolerance {
            "within"
        } else {
            "outside"
        };
        match answer.threshold {
            Threshold::Stiffness(k) => {
                let _ = writeln!(out, "  K_T >= {} MPa/mm", number_with(k, 4));
            }
            Threshold::Everywhere(k) => {
                let _ = writeln!(
                    out,
                    "  any accepted K_T (from {} MPa/mm): even the softest is within {tol}",
                    number(k)
                );
            }
            Threshold::Nowhere {
                stiffness,
                deviation,
            } => {
                let _ = writeln!(
                    out,
                    "  none: even K_T = {} MPa/mm is {} off Coulomb",
                    number(stiffness),
                    percent_of(deviation)
                );
            }
        }
        let _ = writeln!(
            out,
            "  the current K_T = {} MPa/mm is {} off Coulomb: {verdict}",
            number(kt),
            percent_of(deviation)
        );
        let _ = writeln!(
            out,
            "  (the deviation never grows with K_T, docs/theory.md {why}: every stiffer K_T is within too)"
        );
        code_settings_text(&mut out, answer, "it");
        out
    }
}

/// Each FE code's setting for at least the K_T `answer` needs (`what`: the K_T named so).
fn code_settings_text(out: &mut String, answer: &ToleranceAnswer, what: &str) {
    let Some(first) = answer.settings.first() else {
        return;
    };
    let element = match first.needed {
        Setting::SlipTolerance { element, .. } => element,
        _ => f64::NAN,
    };
    let _ = writeln!(
        out,
        "\nIn each FE code's own setting for {what} (contact faces {} mm; --element-size sets another):",
        number(element)
    );
    for s in &answer.settings {
        let needed = match s.needed {
            Setting::SlipTolerance {
                fraction,
                slip,
                element_max,
                ..
            } => format!(
                "{} <= {} (elastic slip <= {} mm), or faces <= {} mm with the default",
                setting_name(s.code.description),
                number_with(fraction, 3),
                number_with(slip, 3),
                number_with(element_max, 3)
            ),
            Setting::StickSlope(k) => {
                format!("stick slope lambda >= {} MPa/mm", number_with(k, 3))
            }
            Setting::ElementSize(h) => {
                format!("smallest contact element h_min <= {} mm", number_with(h, 3))
            }
            Setting::Stiffness(k) => {
                format!("give a friction stiffness >= {} MPa/mm", number_with(k, 3))
            }
        };
        let default = match s.default {
            Some((k, true)) => format!("; its default ({} MPa/mm) is enough", number_with(k, 3)),
            Some((k, false))
                if answer
                    .near_current
                    .and_then(|n| n.upper)
                    .is_some_and(|upper| k > upper) =>
            {
                format!(
                    "; its default ({} MPa/mm) is NOT: above the interval",
                    number_with(k, 3)
                )
            }
            Some((k, false)) => format!("; its default ({} MPa/mm) is NOT", number_with(k, 3)),
            None => String::new(),
        };
        let _ = writeln!(out, "  {:<16} {needed}{default}", s.code.code);
    }
}
