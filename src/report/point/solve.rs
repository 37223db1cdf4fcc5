//! `microslip solve`: every value of one parameter at which a quantity takes a target value, or
//! the plateau it lies on.

use std::fmt::Write;

use serde::{Serialize, Serializer};

use crate::ModelKind;
use crate::kernel::params::Unit;
use crate::problems::Param;
use crate::report::{number, sanitize};
use crate::study::target::{ROUNDING, RangeCut, Root, SCAN_POINTS, Solved};

/// The answer of `solve`.
#[derive(Debug, Clone, Serialize)]
pub struct SolveReport {
    /// `beam` or `plate`.
    #[serde(serialize_with = "by_name")]
    pub model: ModelKind,
    pub preset: String,
    /// The parameter solved for.
    #[serde(serialize_with = "by_name")]
    pub param: Param,
    /// The parameter's unit (`-` for none).
    #[serde(serialize_with = "symbol")]
    pub unit: Unit,
    /// The quantity's name for this model (`w(L)`, `ratio`).
    pub quantity: &'static str,
    /// What the quantity is, for the text.
    #[serde(skip)]
    pub quantity_meaning: &'static str,
    /// The quantity's unit, for the text ("" for none).
    #[serde(skip)]
    pub quantity_unit: &'static str,
    /// The target value of the quantity.
    pub target: f64,
    /// The range of the parameter searched.
    pub range: (f64, f64),
    /// Where the load cut the range's lower end short of the parameter's domain (absent when it
    /// did not): `least`, in the parameter's unit, and the force that cut it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range_cut: Option<RangeCutReport>,
    pub roots: Vec<RootReport>,
}

/// [`RangeCut`] for JSON: `least` (in the parameter's unit) and the load that cut it under its
/// own key (`F_N`, the cylinder's `Q_N_per_mm`: below `least`, the load's bound would fall under
/// it). A load whose key is not `F_N` is also written as `F_N`, deprecated (kept one release:
/// the key every problem's cut had before the key said the load's name and unit).
#[derive(Debug, Clone, Copy)]
pub struct RangeCutReport {
    /// The least value searched, in the parameter's unit.
    pub least: f64,
    /// The load that cut it, in the load's unit.
    pub load: f64,
    /// Why, in words, and whose load it is.
    cut: RangeCut,
}

impl Serialize for RangeCutReport {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        const DEPRECATED: &str = "F_N";
        let key = self
            .cut
            .kind
            .description()
            .load_key("")
            .unwrap_or_else(|| DEPRECATED.to_string());
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("least", &self.least)?;
        map.serialize_entry(&key, &self.load)?;
        if key != DEPRECATED {
            map.serialize_entry(DEPRECATED, &self.load)?;
        }
        map.end()
    }
}

/// One root, or a plateau of roots.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct RootReport {
    pub value: f64,
    /// The quantity there.
    pub achieved: f64,
    pub bracket: (f64, f64),
    /// A sign change bracketed it: a root, not a jump across the target.
    pub certified: bool,
    /// The quantity is flat over the bracket.
    pub plateau: bool,
    /// Flat and equal to the target within the rounding band.
    pub within_rounding: bool,
}

fn by_name<T: std::fmt::Display, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
    s.collect_str(v)
}

fn symbol<S: Serializer>(unit: &Unit, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(unit.symbol())
}

impl From<&Root> for RootReport {
    fn from(r: &Root) -> Self {
        RootReport {
            value: r.value,
            achieved: r.achieved,
            bracket: r.bracket,
            certified: r.certified,
            plateau: r.plateau,
            within_rounding: r.within_rounding,
        }
    }
}

impl SolveReport {
    pub fn new(preset: &str, kind: ModelKind, solved: &Solved) -> SolveReport {
        let quantity = solved.target.quantity;
        SolveReport {
            model: kind,
            preset: preset.to_string(),
            param: solved.param,
            unit: solved.param.unit(),
            quantity: quantity.name(kind),
            quantity_meaning: quantity.meaning(kind),
            quantity_unit: quantity.unit(kind),
            target: solved.target.value,
            range: solved.range,
            range_cut: solved.cut.map(|cut| RangeCutReport {
                least: cut.least,
                load: cut.load,
                cut,
            }),
            roots: solved.roots.iter().map(RootReport::from).collect(),
        }
    }

    /// The readable answer: every root found, or why there is none.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let (kind, param, name) = (self.model, self.param, self.quantity);
        let unit_of = |u: &str| {
            if u.is_empty() {
                String::new()
            } else {
                format!(" {u}")
            }
        };
        let unit = unit_of(self.quantity_unit);
        let punit = match self.unit {
            Unit::Dimensionless => String::new(),
            u => format!(" {u}"),
        };
        let target = number(self.target);
        let _ = writeln!(
            out,
            "{kind} ({}): {param} such that {name} = {target}{unit}",
            sanitize(&self.preset)
        );
        let _ = writeln!(out, "  {name}: {}", self.quantity_meaning);
        for root in &self.roots {
            let (from, to) = (number(root.bracket.0), number(root.bracket.1));
            if root.plateau && root.within_rounding {
                let limit = if root.bracket.1 >= self.range.1 {
                    format!(
                        "; it tends to {target} as {param} grows: reached in the limit, not at a root"
                    )
                } else {
                    String::new()
                };
                let _ = writeln!(
                    out,
                    "{name} = {target}{unit} to within {ROUNDING:e} relative (the rounding band) for every {param} in [{from}, {to}]{punit}{limit}",
                );
            } else if root.plateau && root.bracket.0 < root.bracket.1 {
                let _ = writeln!(
                    out,
                    "{name} = {}{unit} for every {param} in [{from}, {to}]{punit} (a plateau; its ends found by bisection)",
                    number(root.achieved),
                );
            } else if root.certified && root.bracket.0 == root.bracket.1 {
                // A point, not a bracket: the quantity is on the target there and at no
                // neighbouring value the search resolves.
                let _ = writeln!(
                    out,
                    "{name} = {}{unit} only at {param} = {}{punit}",
                    number(root.achieved),
                    number(root.value),
                );
            } else if root.certified {
                let _ = writeln!(
                    out,
                    "{param} = {}{punit}   ({name} = {}{unit} there; root bracketed in [{from}, {to}]{punit})",
                    number(root.value),
                    number(root.achieved),
                );
            } else {
                let _ = writeln!(
                    out,
                    "{param} = {}{punit}: {name} jumps across the target there ({} on one side): not a root",
                    number(root.value),
                    number(root.achieved)
                );
            }
        }
        if self.roots.len() > 1 {
            let _ = writeln!(
                out,
                "more than one {param} gives {name} = {target}: narrow the search with --from/--to",
            );
        }
        let _ = writeln!(
            out,
            "searched {param} in [{}, {}]{punit} ({SCAN_POINTS}-point scan; each bracket solved to 1e-12 relative)",
            number(self.range.0),
            number(self.range.1),
        );
        if let Some(cut) = &self.range_cut {
            let _ = writeln!(out, "  {}", cut.cut.words(&param.to_string(), &punit));
        }
        out
    }
}
