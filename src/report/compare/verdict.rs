//! The verdicts of [`crate::fe::verdict`] in words: one line per row ([`RowVerdict`]), one closing
//! line ([`Summary`], from a `Tally` of the rows), and a short form for the TUI's status line.
//! The judging is done in `fe`; this file only says it, in the words each problem gives it
//! (`Names`; each problem's row verdict and closing verdict are in its folder,
//! `src/problems/<name>/compare.rs`).

use serde::{Serialize, Serializer};

use super::percent;
use crate::fe::ladder::LadderQuantity;
use crate::fe::verdict::{Envelope, MeshDifference, StiffnessMatch};
use crate::report::number_with;

/// A verdict as its label in JSON.
pub(crate) fn envelope_label<S: Serializer>(e: &Envelope, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(e.label())
}

pub(crate) fn stiffness_label<S: Serializer>(m: &StiffnessMatch, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(m.label())
}

/// The verdict on one row of a comparison: its response against the closed form's envelope, its
/// zone ends in elements of the FE mesh (`Z`, the problem's own keys: the beams' `X_elements`,
/// the lap joint's `a_elements` and `d_elements`), and the verdict in words.
#[derive(Debug, Clone, Serialize)]
pub struct RowVerdict<Z> {
    /// The response against its envelope: `within`, `outside`, `not calibrated`, `undefined`.
    #[serde(serialize_with = "envelope_label")]
    pub envelope: Envelope,
    /// The envelope's bound, a fraction; null where not calibrated.
    pub envelope_bound: Option<f64>,
    /// The same bound under the name that says its unit (a fraction); `envelope_bound` is
    /// deprecated, kept one release.
    pub envelope_bound_fraction: Option<f64>,
    /// The zone ends against the closed form's, in elements of the FE mesh (CalculiX results).
    #[serde(flatten)]
    pub zones: Z,
    /// The verdict in words.
    pub text: String,
    /// The difference judged, as a ladder of runs extrapolates it (not in the JSON: the rows
    /// carry it under the problem's own key).
    #[serde(skip)]
    pub quantity: Option<LadderQuantity>,
}

impl<Z> RowVerdict<Z> {
    /// The verdict on the row named `label` ("F = 40 N"): `what` ("w(L)") with its relative
    /// `difference` against `envelope`, then each zone end of `meshes` ("X") in elements.
    pub fn new(
        label: &str,
        (what, difference, envelope): (&str, Option<f64>, Envelope),
        meshes: &[(&str, &MeshDifference)],
        zones: Z,
    ) -> RowVerdict<Z> {
        let mut text = format!("{label}: {}", envelope_words(what, difference, envelope));
        for (zone, mesh) in meshes {
            text.push_str("; ");
            text.push_str(&mesh_words(zone, mesh));
        }
        RowVerdict {
            envelope,
            envelope_bound: envelope.bound(),
            envelope_bound_fraction: envelope.bound(),
            zones,
            text,
            quantity: difference.map(|difference| LadderQuantity {
                name: format!("{what} at {label}"),
                difference,
                bound: envelope.bound(),
                value: None,
            }),
        }
    }
}

/// The closing verdict of a comparison.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// No quantity judged disagrees, and at least one row was judged within its envelope.
    pub agrees: bool,
    /// The closing line.
    pub summary: String,
    /// The deck's K_T against the implied one (only where the problem implies one).
    #[serde(
        rename = "KT",
        serialize_with = "stiffness_option",
        skip_serializing_if = "Option::is_none"
    )]
    pub stiffness: Option<StiffnessMatch>,
    /// (deck - implied) / standard error (only where the problem implies a K_T; null where not
    /// judged).
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

/// What the rows of a comparison say together: which are within, outside, not judged, and which
/// have a zone end beyond the mesh's resolution.
pub(crate) struct Tally {
    within: usize,
    outside: Vec<String>,
    not_judged: Vec<String>,
    beyond_mesh: Vec<String>,
    mesh_judged: bool,
}

impl Tally {
    /// `rows`: each row's label ("F = 40 N" without the quantity's name: "40"), envelope and zone
    /// end on the mesh.
    pub(crate) fn of(
        rows: impl Iterator<Item = (String, Envelope, Option<MeshDifference>)>,
    ) -> Tally {
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
    pub(crate) fn disagrees(&self, names: &Names) -> bool {
        !self.outside.is_empty() || (names.zone_bounded && !self.beyond_mesh.is_empty())
    }

    /// The clauses of the closing line: `what` the quantity ("w(L)"), `zone` its zone end ("X"),
    /// `at` how a row is named ("F =", "K_T ="), `unit` ("N", "MPa/mm"), `steps` ("load steps").
    pub(crate) fn clauses(&self, names: &Names) -> Vec<String> {
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
    pub(crate) fn short(&self, names: &Names) -> String {
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
pub(crate) struct Names {
    /// The response judged ("w(L)").
    pub(crate) what: &'static str,
    /// Its zone end ("X").
    pub(crate) zone: &'static str,
    /// Whether the closed form's zone end is meant to match the continuum's (a problem whose
    /// envelope bounds its zone end too), so that a zone end beyond the mesh's resolution is a
    /// disagreement; where the envelope bounds the response only, it is said, not judged.
    pub(crate) zone_bounded: bool,
    /// How a row is named ("F =").
    pub(crate) at: &'static str,
    /// The unit of a row's name ("N").
    pub(crate) unit: &'static str,
    /// What the rows are ("load steps").
    pub(crate) steps: &'static str,
}

/// The verdict's first words, and whether it is agreement: where some rows could not be judged,
/// agreement holds only where they could; where none could, there is no verdict.
pub(crate) fn opening(disagrees: bool, tally: &Tally) -> (&'static str, bool) {
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

/// The closing verdict of the rows `rows` (each its label, envelope and zone end on the mesh) of
/// a comparison that implies no K_T of its own, in the words of `names`.
pub(crate) fn tally_summary(
    rows: impl Iterator<Item = (String, Envelope, Option<MeshDifference>)>,
    names: &Names,
) -> Summary {
    let tally = &Tally::of(rows);
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
pub(crate) fn z_words(z: f64) -> String {
    number_with(z, 2)
}
