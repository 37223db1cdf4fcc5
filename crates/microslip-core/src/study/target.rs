//! Solving for a target: the value of one parameter at which a quantity of the solution (w(L),
//! u(L), X, the ratio to Coulomb, F_1, D, zeta) takes a given value, all other inputs fixed.
//!
//! How: the parameter's range (its whole accepted domain, or the caller's part of it) is scanned on
//! a grid (logarithmic for positive parameters spanning more than a decade), every grid interval
//! where the quantity crosses the target is a bracket, and each bracket is solved by
//! `solve::find_root_in_bracket` (Brent, certified, with bisection as the fallback). Each root is then
//! checked: the quantity there must equal the target to 1e-6 relative, otherwise the quantity
//! jumps across the target (a discontinuity, not a root) and the answer says so. No crossing is an
//! error that gives the range of the quantity over the range scanned; more than one crossing gives
//! every root found. A pair of roots closer together than a grid step can be missed; the scan has
//! [`SCAN_POINTS`] points, and narrowing the range refines it.
//!
//! This scan is a loop over a parameter, like those of `curves`; it lives here because it is part of
//! the root finding (the brackets), and `curves` sits above `model`.

use thiserror::Error;

use crate::kernel::family;
use crate::kernel::params::{Compact, parse_number, significant};
use crate::kernel::solve::find_root_in_bracket;
use crate::problems::inputs::Model;
use crate::problems::{ModelKind, Param, QuantityName};

/// Grid points of the scan for brackets.
pub const SCAN_POINTS: usize = 400;

/// Largest relative misfit of the quantity at an accepted root.
const ROOT_CHECK: f64 = 1e-6;

/// The quantities' own rounding level, relative: a closed form of hyperbolic functions of
/// products loses some digits (measured: the ratio to Coulomb scatters by 6e-16 around 1 once
/// K_T passes 1e10 MPa/mm on the paper's beams). Misfits within this band are the target to within
/// rounding, never a sign change: the band is 500 times that scatter, and a million times below
/// the largest misfit accepted at a root (1e-6). Without it, `solve --vary KT --target ratio=1` listed ten "certified" roots
/// between 1.6e10 and 7e11 MPa/mm, one achieving 0.9999999999999994 (below 1 is impossible).
pub const ROUNDING: f64 = 3e-13;

pub use crate::problems::Quantity;

/// How the targets see a problem's quantities: the names, meanings and values its description
/// and its folder give ([`crate::problems::Description::quantities`]).
impl Quantity {
    /// True when the quantity depends on the load (the beams' tip force, the joint's force):
    /// F_1 is a property of the structure alone, so a search for it must not be cut by the
    /// load's own limit (the lap joint's F <= F_gross).
    pub fn depends_on_load(self) -> bool {
        !matches!(self, Quantity::FirstMacroslipForce)
    }

    /// True when `kind` has this quantity.
    pub fn applies_to(self, kind: ModelKind) -> bool {
        Self::named(self, kind).is_some()
    }

    fn named(self, kind: ModelKind) -> Option<&'static QuantityName> {
        kind.description()
            .quantities
            .iter()
            .find(|n| n.quantity == self)
    }

    /// The name as targets spell it for `kind` (`w(L)`, `X_r`, `ratio`); empty for a quantity
    /// `kind` does not have.
    pub fn name(self, kind: ModelKind) -> &'static str {
        self.named(kind).map_or("", |n| n.name)
    }

    /// What it is, in words, for `kind`.
    pub fn meaning(self, kind: ModelKind) -> &'static str {
        self.named(kind).map_or("", |n| n.meaning)
    }

    /// Its unit for `kind` (`mm`, `N`, `N mm`; empty for a ratio).
    pub fn unit(self, kind: ModelKind) -> &'static str {
        self.named(kind).map_or("", |n| n.unit)
    }

    /// The names targets accept for `kind`, as error messages list them.
    pub fn names(kind: ModelKind) -> String {
        kind.description()
            .quantities
            .iter()
            .map(|n| n.name)
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// Parses a quantity name of `kind` (case-sensitive, as
    /// [`Description::quantities`](crate::problems::Description::quantities) names them, or
    /// an alias: `w`, `u`, `Xr`, `F1`).
    ///
    /// # Errors
    /// [`TargetError::Quantity`] for a name `kind` does not have.
    pub fn parse(text: &str, kind: ModelKind) -> Result<Quantity, TargetError> {
        kind.description()
            .quantities
            .iter()
            .find(|n| n.is_named(text))
            .map(|n| n.quantity)
            .ok_or_else(|| TargetError::Quantity {
                name: text.to_string(),
                kind,
            })
    }
}

/// A target: a quantity and the value it should take, as typed `ratio=1.01`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    /// The quantity.
    pub quantity: Quantity,
    /// Its wanted value, in the quantity's unit.
    pub value: f64,
}

impl Target {
    /// Parses `QUANTITY=VALUE` for `kind` (`ratio=1.01`, `w(L)=0.05`, `X_r=9.5`).
    ///
    /// # Errors
    /// A missing `=`, an unknown quantity, or a value that is not a finite number.
    pub fn parse(text: &str, kind: ModelKind) -> Result<Target, TargetError> {
        let Some((name, value)) = text.split_once('=') else {
            return Err(TargetError::Syntax(text.to_string()));
        };
        let quantity = Quantity::parse(name.trim(), kind)?;
        let value = parse_number(value.trim()).ok_or_else(|| TargetError::Value {
            text: value.trim().to_string(),
        })?;
        Ok(Target { quantity, value })
    }
}

/// Why a target cannot be solved.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TargetError {
    /// No `=` in the target.
    #[error("invalid target '{0}': expected QUANTITY=VALUE, e.g. ratio=1.01")]
    Syntax(String),
    /// A quantity the model does not have.
    #[error("unknown quantity '{name}' for the {kind} model (allowed: {})", Quantity::names(*kind))]
    Quantity {
        /// As typed.
        name: String,
        /// The model.
        kind: ModelKind,
    },
    /// The value is not a number.
    #[error("invalid target value '{text}': not a finite number")]
    Value {
        /// As typed.
        text: String,
    },
    /// The range to search is not part of the parameter's domain, or reversed.
    #[error("invalid range for {param}: {reason}")]
    Range {
        /// The parameter's key.
        param: &'static str,
        /// Why.
        reason: String,
    },
    /// The quantity does not reach the target anywhere in the range.
    #[error(
        "no {param} in [{}, {}]{unit} gives {quantity} = {}{quantity_unit}: over that range \
         {quantity} goes from {}{quantity_unit} to {}{quantity_unit} (min {}{quantity_unit}, max {}{quantity_unit}){}",
        Compact(range.0), Compact(range.1), Compact(*target), significant(scan.ends.0, 6),
        significant(scan.ends.1, 6), significant(scan.extremes.0, 6),
        significant(scan.extremes.1, 6),
        scan.cut.as_ref().map_or_else(String::new, |c| format!("; {}", c.words(param, &unit.to_string())))
    )]
    NoRoot {
        /// The parameter's key.
        param: &'static str,
        /// The parameter's unit, shown after a space (nothing when dimensionless).
        unit: UnitSuffix,
        /// The quantity's name.
        quantity: &'static str,
        /// The quantity's unit, shown after a space (nothing when dimensionless).
        quantity_unit: UnitSuffix,
        /// The target value.
        target: f64,
        /// The range scanned.
        range: (f64, f64),
        /// What the scan found (boxed: the error stays small).
        scan: Box<Scan>,
    },
    /// The quantity is not defined anywhere in the range.
    #[error("{quantity} is not defined for any {param} in the range (zero load?)")]
    Undefined {
        /// The parameter's key.
        param: &'static str,
        /// The quantity's name.
        quantity: &'static str,
    },
}

/// One value of the parameter where the quantity crosses the target.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// The parameter's value.
    pub value: f64,
    /// The grid interval it was found in.
    pub bracket: (f64, f64),
    /// The quantity there.
    pub achieved: f64,
    /// True when the quantity equals the target there (to 1e-6 relative); false when it jumps
    /// across the target (a discontinuity at `value`).
    pub certified: bool,
    /// True when the quantity equals the target on every grid point of `bracket` (a plateau:
    /// X = L below the onset of macroslip); `value` is then the plateau's upper end.
    pub plateau: bool,
    /// True for a plateau on which the quantity equals the target only to within its rounding
    /// ([`ROUNDING`]), not exactly: it tends to the target there (the ratio to Coulomb tends to 1
    /// as K_T grows), so this is where the target is reached in the limit, not a root.
    pub within_rounding: bool,
}

impl Root {
    /// A run of the parameter over which the quantity equals the target (`value` one of its ends).
    fn plateau(bracket: (f64, f64), value: f64, achieved: f64, exact: bool) -> Root {
        Root {
            value,
            bracket,
            achieved,
            certified: true,
            plateau: true,
            within_rounding: !exact,
        }
    }
}

/// A unit as a number's suffix: ` mm` after a space, nothing for a dimensionless value (an
/// empty unit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct UnitSuffix(pub &'static str);

impl std::fmt::Display for UnitSuffix {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0.is_empty() {
            Ok(())
        } else {
            write!(f, " {}", self.0)
        }
    }
}

/// What a scan without a root found: the quantity over the range, and what cut the range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scan {
    /// The quantity at both ends of the range.
    pub ends: (f64, f64),
    /// Its smallest and largest value found on the scan.
    pub extremes: (f64, f64),
    /// Where the load cut the range's lower end, if it did.
    pub cut: Option<RangeCut>,
}

/// Where the searched range was cut short of the parameter's domain by the load's bound (the
/// problem's [`Description::load_bound`](crate::problems::Description::load_bound)): the lap
/// joint's F must not exceed F_gross = 2 b mu P L, so L, b, P and mu cannot go below the value at
/// which F_gross falls to F; the cylinder's Q the same of Q_gross = mu P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RangeCut {
    /// The least value searched (the parameter's unit).
    pub least: f64,
    /// The load that cut it (in the load's unit).
    pub load: f64,
    /// The problem, whose words the cut is said in.
    pub kind: ModelKind,
}

impl RangeCut {
    /// In words, for `param` in `unit` (with its leading space): "P >= 5 MPa: below it the
    /// given F = 300 N exceeds F_gross = 2 b mu P L (lower F to search further)", in the
    /// problem's words (its load's name and unit, its bound).
    pub fn words(&self, param: &str, unit: &str) -> String {
        let info = self.kind.description();
        let name = info.load_words().map_or("the load", |(name, _)| name);
        format!(
            "{param} >= {}{unit} only: below it the given {} exceeds {} (lower {name} to search \
             further)",
            Compact(self.least),
            info.load_value(self.load),
            info.bound_formula().unwrap_or_default(),
        )
    }
}

/// The answer: every crossing found, in increasing order of the parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// The parameter varied.
    pub param: Param,
    /// The target.
    pub target: Target,
    /// The range scanned.
    pub range: (f64, f64),
    /// Where the load cut the range, if it did.
    pub cut: Option<RangeCut>,
    /// The roots.
    pub roots: Vec<Root>,
}

/// The scan grid over [lo, hi] within `domain`: logarithmic when both ends are positive and more
/// than a decade apart; from 0, the point 0 then a logarithmic grid from 1e-15 of `hi`; else linear.
fn scan_grid(lo: f64, hi: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    let log = |a: f64, b: f64, n: usize| -> Vec<f64> {
        let (la, lb) = (a.ln(), b.ln());
        (0..n)
            .map(|i| {
                if i == 0 {
                    a
                } else if i + 1 == n {
                    b
                } else {
                    (la + (lb - la) * i as f64 / (n - 1) as f64)
                        .exp()
                        .clamp(a, b)
                }
            })
            .collect()
    };
    if lo > 0.0 && hi / lo > 10.0 {
        log(lo, hi, n)
    } else if lo == 0.0 && hi > 0.0 {
        let start = (hi * 1e-15).max(f64::MIN_POSITIVE);
        std::iter::once(0.0).chain(log(start, hi, n - 1)).collect()
    } else {
        (0..n)
            .map(|i| {
                if i + 1 == n {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / (n - 1) as f64
                }
            })
            .collect()
    }
}

/// The range a search covers: `range` checked against the parameter's domain, or the whole domain
/// (for the Poisson ratio, up to the largest value below 0.5).
fn search_range(
    model: &Model,
    param: Param,
    range: Option<(f64, f64)>,
) -> Result<((f64, f64), Option<RangeCut>), TargetError> {
    let spec = param.spec();
    let domain = spec.domain;
    // Where the other inputs bound the parameter (the lap joint's F <= F_gross): only there has
    // the model a state.
    let (least, most) = model.accepted_range(param);
    let (lo, hi) = match range {
        Some(r) => r,
        None => (least, domain.clamp(most)),
    };
    // The load the cut was found at (none for a problem without a load).
    let kind = model.kind();
    let info = kind.description();
    let load = info
        .load
        .and_then(|load| model.inputs().get(load))
        .unwrap_or(0.0);
    let cut = (range.is_none() && least > domain.min()).then_some(RangeCut { least, load, kind });
    for value in [lo, hi] {
        if !domain.contains(value) {
            return Err(TargetError::Range {
                param: spec.name,
                reason: format!("{} {}", Compact(value), domain.refusal(value, spec.unit)),
            });
        }
        if !(least..=most).contains(&value) {
            return Err(TargetError::Range {
                param: spec.name,
                reason: format!(
                    "{} leaves no state with the other values: the accepted range is [{}, {}] \
                     (the given {} must not exceed {})",
                    Compact(value),
                    Compact(least),
                    Compact(most),
                    info.load_value(load),
                    info.bound_formula().unwrap_or_default(),
                ),
            });
        }
    }
    if lo >= hi {
        return Err(TargetError::Range {
            param: spec.name,
            reason: format!("from = {} must be below to = {}", Compact(lo), Compact(hi)),
        });
    }
    Ok(((lo, hi), cut))
}

/// The last point of [a, b] where `holds` (true at `a`, false at `b`), by bisection to 1e-12
/// relative: where a plateau ends.
fn edge(holds: &impl Fn(f64) -> bool, mut a: f64, mut b: f64) -> f64 {
    while b - a > 1e-12 * a.abs().max(b.abs()) {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if holds(mid) {
            a = mid;
        } else {
            b = mid;
        }
    }
    a
}

/// Solves for the values of `param` in `range` (default: its whole domain) at which `target`'s
/// quantity equals the target value, all other inputs as in `model`.
///
/// # Errors
/// A quantity of another problem, a range outside the domain, no crossing in the range, or a
/// quantity undefined everywhere.
///
/// # Examples
/// ```
/// use microslip_core::problems::inputs::Inputs;
/// use microslip_core::problems::{BeamParam, ModelKind, Param};
/// use microslip_core::study::target::{Target, solve_for_target};
/// let model = Inputs::paper(ModelKind::Beam).validate()?;
/// let target = Target::parse("ratio=1.01", ModelKind::Beam)?;
/// let solved = solve_for_target(&model, Param::Beam(BeamParam::Stiffness), target, None)?;
/// assert_eq!(solved.roots.len(), 1);
/// assert!((solved.roots[0].value - 423.0).abs() < 1.0); // MPa/mm
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_for_target(
    model: &Model,
    param: Param,
    target: Target,
    range: Option<(f64, f64)>,
) -> Result<Solved, TargetError> {
    // The scan and the root search walk one family of the parameter (issue 47).
    family::scope(|| solve_in_scope(model, param, target, range))
}

/// [`solve_for_target`] inside its scope.
fn solve_in_scope(
    model: &Model,
    param: Param,
    target: Target,
    range: Option<(f64, f64)>,
) -> Result<Solved, TargetError> {
    let kind = model.kind();
    let quantity = target.quantity;
    let name = quantity.name(kind);
    if !quantity.applies_to(kind) || param.model() != kind {
        return Err(TargetError::Quantity {
            name: name.to_string(),
            kind,
        });
    }
    // A quantity the load does not change (F_1) is searched unloaded: the load's own limit
    // (the lap joint's F <= F_gross) must not cut the range of a value it does not use.
    let unloaded;
    let model = if quantity.depends_on_load() {
        model
    } else {
        unloaded = model.unloaded();
        &unloaded
    };
    let (range, cut) = search_range(model, param, range)?;
    let at = |x: f64| model.with_clamped(param, x).quantity(quantity);
    // The misfit, relative where the target is not zero so that Brent sees numbers near 1.
    let misfit = |y: f64| {
        if target.value != 0.0 {
            y / target.value - 1.0
        } else {
            y
        }
    };
    // On the target: exactly, or (for a target other than 0) to within the quantity's rounding.
    let on = |m: f64| {
        if target.value != 0.0 {
            m.abs() <= ROUNDING
        } else {
            m == 0.0
        }
    };
    let grid = scan_grid(range.0, range.1, SCAN_POINTS);
    let values: Vec<(f64, Option<f64>)> = grid.iter().map(|&x| (x, at(x))).collect();
    let defined: Vec<(f64, f64)> = values
        .iter()
        .filter_map(|&(x, y)| y.map(|y| (x, y)))
        .collect();
    let (Some(first), Some(last)) = (defined.first(), defined.last()) else {
        return Err(TargetError::Undefined {
            param: param.name(),
            quantity: name,
        });
    };
    let mut roots: Vec<Root> = Vec::new();
    for pair in values.windows(2) {
        let ((a, ya), (b, yb)) = (pair[0], pair[1]);
        let (Some(ya), Some(yb)) = (ya, yb) else {
            continue;
        };
        let (fa, fb) = (misfit(ya), misfit(yb));
        let on_target = |x: f64| at(x).is_some_and(|y| on(misfit(y)));
        if on(fa) {
            // A run of grid points on the target (a plateau, e.g. X = L below the onset of
            // macroslip) is one answer: the interval, its ends found by bisection.
            let end = if on(fb) { b } else { edge(&on_target, a, b) };
            let exact = fa == 0.0 && (fb == 0.0 || !on(fb));
            match roots.last_mut() {
                Some(last) if last.plateau && last.bracket.1 == a => {
                    last.bracket.1 = end;
                    last.value = end;
                    last.within_rounding |= !exact;
                }
                _ => roots.push(Root::plateau((a, end), end, ya, exact)),
            }
            continue;
        }
        if on(fb) {
            // A plateau starts inside (a, b]: its lower end.
            let start = edge(&|x| !on_target(x), a, b);
            roots.push(Root::plateau((start, b), b, yb, fb == 0.0));
            continue;
        }
        if fa.signum() == fb.signum() {
            continue;
        }
        let x = find_root_in_bracket(|x| at(x).map_or(f64::NAN, misfit), a, b);
        let achieved = at(x).unwrap_or(f64::NAN);
        let certified = misfit(achieved).abs()
            <= if target.value != 0.0 {
                ROOT_CHECK
            } else {
                ROOT_CHECK * ya.abs().max(yb.abs())
            };
        roots.push(Root {
            value: x,
            bracket: (a, b),
            achieved,
            certified,
            plateau: false,
            within_rounding: false,
        });
    }
    if let Some(&(x, y)) = defined.last()
        && on(misfit(y))
        && roots.last().is_none_or(|r| r.bracket.1 != x)
    {
        roots.push(Root::plateau((x, x), x, y, misfit(y) == 0.0));
    }
    if roots.is_empty() {
        let (min, max) = defined
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(_, y)| {
                (lo.min(y), hi.max(y))
            });
        return Err(TargetError::NoRoot {
            param: param.name(),
            unit: UnitSuffix(param.unit().in_text()),
            quantity: name,
            quantity_unit: UnitSuffix(quantity.unit(kind)),
            target: target.value,
            range,
            scan: Box::new(Scan {
                ends: (first.1, last.1),
                extremes: (min, max),
                cut,
            }),
        });
    }
    // A plateau narrower than the search resolves (the bisection's 1e-12 of the range) is a
    // point: "Delta = 0 for every F in [0, 7.6e-319] N" was F = 0 and the subnormal forces whose
    // Delta underflows to 0.
    let resolution = 1e-12 * range.0.abs().max(range.1.abs());
    for root in &mut roots {
        if root.plateau && root.bracket.1 - root.bracket.0 <= resolution {
            let point = root.bracket.0;
            *root = Root {
                value: point,
                bracket: (point, point),
                achieved: at(point).unwrap_or(root.achieved),
                certified: true,
                plateau: false,
                within_rounding: root.within_rounding,
            };
        }
    }
    Ok(Solved {
        param,
        target,
        range,
        cut,
        roots,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::inputs::Inputs;
    use crate::problems::{BeamParam, PlateParam};

    fn beams() -> Model {
        Inputs::paper(ModelKind::Beam).validate().unwrap()
    }

    /// The ratio to Coulomb tends to 1 as K_T grows and reaches it nowhere: the scan used to list
    /// ten "certified" roots in the rounding noise above 1.6e10 MPa/mm, one achieving
    /// 0.9999999999999994.
    #[test]
    fn a_target_reached_only_in_a_limit_is_said_to_be_one() {
        let target = Target::parse("ratio=1", ModelKind::Beam).unwrap();
        let solved =
            solve_for_target(&beams(), Param::Beam(BeamParam::Stiffness), target, None).unwrap();
        assert_eq!(solved.roots.len(), 1, "{:?}", solved.roots);
        let root = solved.roots[0];
        assert!(root.plateau && root.within_rounding, "{root:?}");
        assert_eq!(root.bracket.1, 1e12);
        // Where the band starts, the ratio is above 1 by no more than the band, and below it by
        // more: the band is the ratio's approach to 1, not noise around a crossing.
        let at = |kt: f64| {
            beams()
                .with_clamped(Param::Beam(BeamParam::Stiffness), kt)
                .quantity(Quantity::Ratio)
                .unwrap()
        };
        assert!(at(1.01 * root.bracket.0) - 1.0 <= ROUNDING);
        assert!(at(root.bracket.0 / 2.0) - 1.0 > ROUNDING);
        // A target the ratio does reach is still a certified root.
        let target = Target::parse("ratio=1.01", ModelKind::Beam).unwrap();
        let solved =
            solve_for_target(&beams(), Param::Beam(BeamParam::Stiffness), target, None).unwrap();
        assert_eq!(solved.roots.len(), 1);
        assert!(solved.roots[0].certified && !solved.roots[0].within_rounding);
    }

    #[test]
    fn grids_cover_the_range_and_are_increasing() {
        for (lo, hi) in [
            (1e-6, 1e12),
            (0.0, 1e12),
            (0.0, 0.5f64.next_down()),
            (1.0, 2.0),
        ] {
            let g = scan_grid(lo, hi, 50);
            assert_eq!((g[0], *g.last().unwrap()), (lo, hi));
            assert!(g.windows(2).all(|w| w[0] < w[1]), "{lo} {hi}");
        }
    }

    #[test]
    fn targets_parse_and_name_their_quantities() {
        let t = Target::parse("ratio=1.01", ModelKind::Beam).unwrap();
        assert_eq!((t.quantity, t.value), (Quantity::Ratio, 1.01));
        assert_eq!(
            Target::parse(" X_r = 9.5", ModelKind::Plate)
                .unwrap()
                .quantity,
            Quantity::MicroEnd
        );
        assert_eq!(
            Target::parse("w(L)=0.1", ModelKind::Plate)
                .unwrap_err()
                .to_string(),
            "unknown quantity 'w(L)' for the plate model (allowed: u(L) X_r ratio)"
        );
        assert!(Target::parse("ratio", ModelKind::Beam).is_err());
        assert!(Target::parse("ratio=nan", ModelKind::Beam).is_err());
    }

    #[test]
    fn a_target_out_of_reach_says_what_the_range_gives() {
        let err = solve_for_target(
            &beams(),
            Param::Beam(BeamParam::Stiffness),
            Target::parse("ratio=0.5", ModelKind::Beam).unwrap(),
            None,
        )
        .unwrap_err();
        assert!(
            err.to_string()
                .starts_with("no KT in [1e-6, 1e12] MPa/mm gives ratio = 0.5"),
            "{err}"
        );
    }

    #[test]
    fn every_root_is_a_root_and_the_range_is_respected() {
        // X vs F on the beams: X = L up to F_1, then falls: X = 100 mm has exactly one F.
        let solved = solve_for_target(
            &beams(),
            Param::Beam(BeamParam::Force),
            Target::parse("X=100", ModelKind::Beam).unwrap(),
            Some((0.0, 1000.0)),
        )
        .unwrap();
        assert_eq!(solved.roots.len(), 1);
        let root = solved.roots[0];
        assert!(root.certified && (root.achieved - 100.0).abs() < 1e-6);
        let plate = Inputs::paper(ModelKind::Plate).validate().unwrap();
        assert!(
            solve_for_target(
                &plate,
                Param::Plate(PlateParam::Stiffness),
                Target::parse("X_r=9", ModelKind::Plate).unwrap(),
                Some((1.0, 0.5)),
            )
            .is_err()
        );
    }
}
