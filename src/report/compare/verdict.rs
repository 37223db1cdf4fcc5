//! The verdicts of [`crate::fe::verdict`] in words: one line per row, one closing line, and a short
//! form for the TUI's status line. The judging is done in `fe`; this file only says it.

use serde::{Serialize, Serializer};

use super::percent;
use crate::fe::compare::BeamComparison;
use crate::fe::verdict::{Envelope, MeshDifference, StiffnessMatch};
use crate::report::{count_of, number, number_with};

/// A verdict as its label in JSON.
fn envelope_label<S: Serializer>(e: &Envelope, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(e.label())
}

fn stiffness_label<S: Serializer>(m: &StiffnessMatch, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(m.label())
}

/// The verdict on one row of the beams: w(L) against (V2), X in elements of the mesh.
#[derive(Debug, Clone, Serialize)]
pub struct BeamRowVerdict {
    /// The shear-corrected w(L) against its envelope: `within`, `outside`, `undefined`.
    #[serde(serialize_with = "envelope_label")]
    pub envelope: Envelope,
    /// The envelope's bound, a fraction.
    pub envelope_bound: Option<f64>,
    /// The same bound under the name that says its unit (a fraction); `envelope_bound` is
    /// deprecated, kept one release.
    pub envelope_bound_fraction: Option<f64>,
    /// |FE X - closed-form X| in elements of the FE mesh (CalculiX results only).
    #[serde(rename = "X_elements")]
    pub zone_end_elements: Option<f64>,
    /// Whether that is under one element.
    #[serde(rename = "X_within_mesh_resolution")]
    pub zone_end_within_resolution: Option<bool>,
    /// The verdict in words.
    pub text: String,
}

/// The verdict on one run of the plate: u(L) (thickness mean) against (V1), X_r in elements.
#[derive(Debug, Clone, Serialize)]
pub struct PlateRowVerdict {
    /// The thickness mean against its envelope: `within`, `outside`, `not calibrated`,
    /// `undefined`.
    #[serde(serialize_with = "envelope_label")]
    pub envelope: Envelope,
    /// The envelope's bound, a fraction; null where not calibrated.
    pub envelope_bound: Option<f64>,
    /// The same bound under the name that says its unit (a fraction); `envelope_bound` is
    /// deprecated, kept one release.
    pub envelope_bound_fraction: Option<f64>,
    /// |FE X_r - closed-form X_r| in elements of the FE mesh (CalculiX results only).
    #[serde(rename = "Xr_elements")]
    pub zone_end_elements: Option<f64>,
    /// Whether that is under one element.
    #[serde(rename = "Xr_within_mesh_resolution")]
    pub zone_end_within_resolution: Option<bool>,
    /// The verdict in words.
    pub text: String,
}

/// The verdict on one load step of the lap joint: Delta against the shear-lag envelope (L14), a
/// and d in elements of the mesh (not bounded by the envelope).
#[derive(Debug, Clone, Serialize)]
pub struct LapRowVerdict {
    /// Delta against its envelope: `within`, `outside`, `not calibrated`, `undefined`.
    #[serde(serialize_with = "envelope_label")]
    pub envelope: Envelope,
    /// The envelope's bound, a fraction; null where not calibrated.
    pub envelope_bound: Option<f64>,
    /// The same bound under the name that says its unit (a fraction); `envelope_bound` is
    /// deprecated, kept one release.
    pub envelope_bound_fraction: Option<f64>,
    /// |FE a - closed-form a| in elements of the FE mesh (CalculiX results only).
    pub a_elements: Option<f64>,
    /// |FE d - closed-form d| in elements of the FE mesh (CalculiX results only).
    pub d_elements: Option<f64>,
    /// The verdict in words.
    pub text: String,
}

/// The closing verdict of a comparison.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// No quantity judged disagrees, and at least one row was judged within its envelope.
    pub agrees: bool,
    /// The closing line.
    pub summary: String,
    /// The deck's K_T against the implied one (beams only).
    #[serde(
        rename = "KT",
        serialize_with = "stiffness_option",
        skip_serializing_if = "Option::is_none"
    )]
    pub stiffness: Option<StiffnessMatch>,
    /// (deck - implied) / standard error (beams only; null where not judged).
    #[serde(rename = "KT_z", skip_serializing_if = "Option::is_none")]
    pub stiffness_z: Option<Option<f64>>,
    /// The same, short, for a status line.
    #[serde(skip)]
    pub short: String,
}

fn stiffness_option<S: Serializer>(m: &Option<StiffnessMatch>, s: S) -> Result<S::Ok, S::Error> {
    match m {
        Some(m) => stiffness_label(m, s),
        None => s.serialize_none(),
    }
}

/// "w(L) -0.27 % is within the envelope (bound 1.07 %)", for `what` = "w(L)".
pub(crate) fn envelope_words(what: &str, difference: Option<f64>, envelope: Envelope) -> String {
    let d = difference.map_or_else(String::new, |d| format!(" {}", percent(d)));
    match envelope {
        Envelope::Within { bound } => {
            format!("{what}{d} is within the envelope (bound {})", bare(bound))
        }
        Envelope::Outside { bound, by } => format!(
            "{what}{d} is outside the envelope by {} (bound {})",
            bare(by),
            bare(bound)
        ),
        Envelope::NotCalibrated => {
            format!("{what}{d}: not judged, the envelope is not calibrated here")
        }
        Envelope::Undefined => format!("{what}: not judged, the closed form is 0"),
    }
}

/// A fraction in percent without a sign: "1.07 %".
fn bare(x: f64) -> String {
    format!("{} %", number_with(100.0 * x, 3))
}

/// "X differs by 0.42 elements (0.26 mm; element 0.62 mm): within the mesh's resolution".
pub(crate) fn mesh_words(what: &str, mesh: &MeshDifference) -> String {
    if mesh.elements == 0.0 {
        return format!("{what} the same");
    }
    let meaning = if mesh.within_resolution() {
        "within the mesh's resolution"
    } else {
        "a real difference, beyond the mesh's resolution"
    };
    format!(
        "{what} differs by {} elements ({} mm; element {} mm): {meaning}",
        number_with(mesh.elements, 2),
        number_with(mesh.difference, 3),
        number_with(mesh.local_size, 3)
    )
}

/// The row verdict of the beams, from the compared row.
pub(crate) fn beam_row(row: &crate::fe::compare::BeamCompared) -> BeamRowVerdict {
    let envelope = row.envelope();
    let mut text = format!(
        "F = {} N: {}",
        number(row.fe.force),
        envelope_words("w(L)", row.difference_shear_corrected(), envelope)
    );
    if let Some(mesh) = &row.macroslip_start_mesh {
        text.push_str("; ");
        text.push_str(&mesh_words("X", mesh));
    }
    BeamRowVerdict {
        envelope,
        envelope_bound: envelope.bound(),
        envelope_bound_fraction: envelope.bound(),
        zone_end_elements: row.macroslip_start_mesh.map(|m| m.elements),
        zone_end_within_resolution: row.macroslip_start_mesh.map(|m| m.within_resolution()),
        text,
    }
}

/// The row verdict of the plate, from the compared row.
pub(crate) fn plate_row(row: &crate::fe::compare::PlateCompared) -> PlateRowVerdict {
    let envelope = row.envelope();
    let mut text = format!(
        "K_T = {} MPa/mm: {}",
        number(row.fe.stiffness),
        envelope_words("u(L) (thickness mean)", row.difference(), envelope)
    );
    if let Some(mesh) = &row.micro_zone_end_mesh {
        text.push_str("; ");
        text.push_str(&mesh_words("X_r", mesh));
    }
    PlateRowVerdict {
        envelope,
        envelope_bound: envelope.bound(),
        envelope_bound_fraction: envelope.bound(),
        zone_end_elements: row.micro_zone_end_mesh.map(|m| m.elements),
        zone_end_within_resolution: row.micro_zone_end_mesh.map(|m| m.within_resolution()),
        text,
    }
}

/// The row verdict of the lap joint, from the compared row.
pub(crate) fn lap_row(row: &crate::fe::compare::LapCompared) -> LapRowVerdict {
    let envelope = row.envelope();
    let mut text = format!(
        "F = {} N: {}",
        number(row.fe.force),
        envelope_words("Delta", row.difference(), envelope)
    );
    if let Some([a, d]) = &row.zones_mesh {
        text.push_str("; ");
        text.push_str(&mesh_words("a", a));
        text.push_str("; ");
        text.push_str(&mesh_words("d", d));
    }
    LapRowVerdict {
        envelope,
        envelope_bound: envelope.bound(),
        envelope_bound_fraction: envelope.bound(),
        a_elements: row.zones_mesh.map(|[a, _]| a.elements),
        d_elements: row.zones_mesh.map(|[_, d]| d.elements),
        text,
    }
}

/// What the rows of a comparison say together: which are within, outside, not judged, and which
/// have a zone end beyond the mesh's resolution.
struct Tally {
    within: usize,
    outside: Vec<String>,
    not_judged: Vec<String>,
    beyond_mesh: Vec<String>,
    mesh_judged: bool,
}

impl Tally {
    /// `rows`: each row's label ("F = 40 N" without the quantity's name: "40"), envelope and zone
    /// end on the mesh.
    fn of(rows: impl Iterator<Item = (String, Envelope, Option<MeshDifference>)>) -> Tally {
        let mut tally = Tally {
            within: 0,
            outside: Vec::new(),
            not_judged: Vec::new(),
            beyond_mesh: Vec::new(),
            mesh_judged: false,
        };
        for (label, envelope, mesh) in rows {
            match envelope {
                Envelope::Within { .. } => tally.within += 1,
                Envelope::Outside { .. } => tally.outside.push(label.clone()),
                Envelope::NotCalibrated | Envelope::Undefined => {
                    tally.not_judged.push(label.clone())
                }
            }
            if let Some(mesh) = mesh {
                tally.mesh_judged = true;
                if !mesh.within_resolution() {
                    tally.beyond_mesh.push(label);
                }
            }
        }
        tally
    }

    /// Whether a quantity judged disagrees; a zone end beyond the mesh counts only where the
    /// closed form states it (`names.zone_bounded`).
    fn disagrees(&self, names: &Names) -> bool {
        !self.outside.is_empty() || (names.zone_bounded && !self.beyond_mesh.is_empty())
    }

    /// The clauses of the closing line: `what` the quantity ("w(L)"), `zone` its zone end ("X"),
    /// `at` how a row is named ("F =", "K_T ="), `unit` ("N", "MPa/mm"), `steps` ("load steps").
    fn clauses(&self, names: &Names) -> Vec<String> {
        let total = self.within + self.outside.len() + self.not_judged.len();
        let list = |labels: &[String]| format!("{} {} {}", names.at, labels.join(", "), names.unit);
        let mut clauses = Vec::new();
        if self.outside.is_empty() && self.not_judged.is_empty() {
            clauses.push(format!(
                "{} within the stated envelope on all {total} {}",
                names.what, names.steps
            ));
        } else {
            if !self.outside.is_empty() {
                clauses.push(format!(
                    "{} outside the stated envelope at {}",
                    names.what,
                    list(&self.outside)
                ));
            }
            if self.within > 0 {
                let what = if self.outside.is_empty() {
                    format!("{} within the stated envelope", names.what)
                } else {
                    "within it".to_string()
                };
                clauses.push(format!(
                    "{what} on {} of {total} {}",
                    self.within, names.steps
                ));
            }
            if !self.not_judged.is_empty() {
                clauses.push(format!("not judged at {}", list(&self.not_judged)));
            }
        }
        if self.beyond_mesh.is_empty() {
            if self.mesh_judged {
                clauses.push(format!("{} within one element of the mesh", names.zone));
            }
        } else {
            let note = if names.zone_bounded {
                ""
            } else {
                " (not a disagreement: the envelope does not bound it)"
            };
            clauses.push(format!(
                "{} differs by more than one element at {}{note}",
                names.zone,
                list(&self.beyond_mesh)
            ));
        }
        clauses
    }

    /// "6/6 in envelope, X < 1 element" for a status line; the zone end only where it is judged
    /// (`names.zone_bounded`), as in the closing line's verdict.
    fn short(&self, names: &Names) -> String {
        let total = self.within + self.outside.len() + self.not_judged.len();
        let mut short = if self.within == 0 && self.outside.is_empty() {
            "no calibrated envelope".to_string()
        } else {
            format!("{}/{total} in envelope", self.within)
        };
        if names.zone_bounded && self.mesh_judged {
            let side = if self.beyond_mesh.is_empty() {
                "<"
            } else {
                ">"
            };
            short.push_str(&format!(", {} {side} 1 element", names.zone));
        }
        short
    }
}

/// How a comparison names its quantity, zone end and rows.
struct Names {
    what: &'static str,
    zone: &'static str,
    /// Whether the closed form's zone end is meant to match the continuum's: the beams' X is the
    /// benchmark's second quantity; the strip theory's X_r is not bounded by (V1) (its slip zone
    /// was measured up to 2.4 times the continuum's where u(L) holds, docs/theory.md).
    zone_bounded: bool,
    at: &'static str,
    unit: &'static str,
    steps: &'static str,
}

/// The verdict's first words, and whether it is agreement: where some rows could not be judged,
/// agreement holds only where they could; where none could, there is no verdict.
fn opening(disagrees: bool, tally: &Tally) -> (&'static str, bool) {
    if disagrees {
        ("does not agree", false)
    } else if tally.within == 0 {
        ("not judged", false)
    } else if tally.not_judged.is_empty() {
        ("agrees", true)
    } else {
        ("agrees where judged", true)
    }
}

/// The closing verdict of the beams.
pub fn beam_summary(comparison: &BeamComparison) -> Summary {
    let tally = Tally::of(
        comparison
            .rows
            .iter()
            .map(|r| (number(r.fe.force), r.envelope(), r.macroslip_start_mesh)),
    );
    let names = Names {
        what: "w(L)",
        zone: "X",
        zone_bounded: true,
        at: "F =",
        unit: "N",
        steps: "load steps",
    };
    let stiffness = comparison.stiffness_match();
    let deck = number(comparison.stiffness);
    let stiffness_clause = match stiffness {
        StiffnessMatch::Matches { z } => {
            format!(
                "implied K_T matches the deck's {deck} MPa/mm (z = {})",
                z_words(z)
            )
        }
        StiffnessMatch::DoesNotMatch { z } => format!(
            "implied K_T does not match the deck's {deck} MPa/mm (z = {})",
            z_words(z)
        ),
        StiffnessMatch::NoStandardError => {
            "implied K_T not judged (the fit has no positive standard error)".to_string()
        }
        StiffnessMatch::UncertaintyUnknown { points, parameters } => format!(
            "implied K_T not judged (uncertainty unknown: {} = {})",
            count_of(points, "loaded point"),
            count_of(parameters, "parameter")
        ),
        StiffnessMatch::ClosedFormDoesNotHold => "implied K_T not judged (the beam theory's \
            envelope exceeds 2 % at some step: the fit would measure the theory)"
            .to_string(),
        StiffnessMatch::ClosedFormNotCalibrated => "implied K_T not judged (the beam theory's \
            envelope is not calibrated at some step: its friction strain mu P L / (2 E h) is beyond \
            the measured range, docs/theory.md (V2))"
            .to_string(),
        StiffnessMatch::NotImplied => "no K_T implied".to_string(),
    };
    let (opening, agrees) = opening(
        tally.disagrees(&names) || matches!(stiffness, StiffnessMatch::DoesNotMatch { .. }),
        &tally,
    );
    let mut clauses = tally.clauses(&names);
    clauses.push(stiffness_clause);
    let mut short = tally.short(&names);
    if let Ok(fit) = &comparison.implied {
        short.push_str(&format!(", K_T {}", number_with(fit.kt.value, 4)));
        if let Some(z) = stiffness.z() {
            short.push_str(&format!(": z = {}", z_words(z)));
        }
    }
    Summary {
        agrees,
        summary: format!("Verdict: {opening}. {}.", clauses.join("; ")),
        stiffness: Some(stiffness),
        stiffness_z: Some(stiffness.z()),
        short: format!("{opening} ({short})"),
    }
}

/// The closing verdict of the plate.
pub fn plate_summary(rows: &[crate::fe::compare::PlateCompared]) -> Summary {
    let tally = Tally::of(
        rows.iter()
            .map(|r| (number(r.fe.stiffness), r.envelope(), r.micro_zone_end_mesh)),
    );
    let names = Names {
        what: "u(L)",
        zone: "X_r",
        zone_bounded: false,
        at: "K_T =",
        unit: "MPa/mm",
        steps: "runs",
    };
    summary_without_stiffness(&tally, &names)
}

/// The closing verdict of the lap joint.
pub fn lap_summary(rows: &[crate::fe::compare::LapCompared]) -> Summary {
    let tally = Tally::of(
        rows.iter()
            .map(|r| (number(r.fe.force), r.envelope(), r.worse_zone_mesh())),
    );
    let names = Names {
        what: "Delta",
        zone: "a or d",
        zone_bounded: false,
        at: "F =",
        unit: "N",
        steps: "load steps",
    };
    summary_without_stiffness(&tally, &names)
}

/// The closing verdict of a comparison that implies no K_T of its own (the plate, the lap joint).
fn summary_without_stiffness(tally: &Tally, names: &Names) -> Summary {
    let (opening, agrees) = opening(tally.disagrees(names), tally);
    Summary {
        agrees,
        summary: format!("Verdict: {opening}. {}.", tally.clauses(names).join("; ")),
        stiffness: None,
        stiffness_z: None,
        short: format!("{opening} ({})", tally.short(names)),
    }
}

/// `summary` with the verdict against the continuum: its clause first, and its disagreement a
/// disagreement of the whole; where the envelope judged nothing (a closed form measured wrong),
/// the continuum's agreement is the verdict.
pub(crate) fn with_continuum(
    summary: &mut Summary,
    continuum: &super::continuum::ContinuumSummary,
) {
    let rest = summary
        .summary
        .strip_prefix("Verdict: ")
        .and_then(|s| s.split_once(". "))
        .map_or(String::new(), |(_, rest)| rest.to_string());
    let opening = if continuum.disagrees {
        summary.agrees = false;
        "does not agree"
    } else if continuum.agrees == Some(true)
        && !summary.agrees
        && summary.short.starts_with("not judged")
    {
        summary.agrees = true;
        "agrees"
    } else if summary.agrees {
        if summary.short.starts_with("agrees where judged") {
            "agrees where judged"
        } else {
            "agrees"
        }
    } else if summary.short.starts_with("not judged") {
        "not judged"
    } else {
        "does not agree"
    };
    summary.summary = format!("Verdict: {opening}. {}; {rest}", continuum.text);
    let old = summary.short.split_once(" (").map_or("", |(_, rest)| rest);
    let against = match continuum.agrees {
        Some(true) => "continuum ok",
        Some(false) => "continuum off",
        None => "continuum n/a",
    };
    summary.short = format!("{opening} ({against}, {old}");
}

/// z to two significant figures (one decimal at most beyond them).
fn z_words(z: f64) -> String {
    number_with(z, 2)
}
