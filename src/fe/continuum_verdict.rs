//! The FE code's global response judged against the problem's own 2-D continuum at the deck's
//! exact parameters and load state (issue 33, item 3), written once for every problem with a
//! [`Continuum`]: the closed form's envelope says how far the benchmark's 1-D theory is from a
//! continuum (several %), which is wider than the effect of a wrong stick slope; the continuum
//! solves the problem the deck writes and agrees with converged CalculiX to a few hundredths of a
//! percent, so against it a K_T 10 % off shows.
//!
//! Three numbers per FE point, each from the continuum alone:
//! - the **difference** (FE - continuum) / continuum at the deck's K_T, against the problem's
//!   measured tolerance ([`ContinuumJudged::CONTINUUM_TOLERANCE`]);
//! - the **sensitivity** s = d ln R / d ln K_T of the continuum's response R at the deck's K_T
//!   (R falls with K_T: s < 0), and from it the **resolution**: the smallest relative K_T error
//!   this case can detect, tolerance / |s| (a stick slope that far off moves R by the tolerance);
//! - the **implied K_T**: the K_T whose continuum response equals the FE value (R is monotonic in
//!   K_T, so the root is unique), found by a bracketed secant on ln R against ln K_T, with the
//!   interval the tolerance leaves, K exp(+-tolerance / |s|), s taken at the implied K_T.
//!
//! Nothing here names a problem: each reaches it through [`ContinuumJudged`], which its
//! application folder implements beside its [`Deck`](super::face::Deck).

use crate::kernel::params::{Domain, Unit};
use crate::numeric::NumericError;
use crate::problems::problem::{Continuum, ParamKey, Problem};

/// A problem whose FE response is judged against its continuum: the tolerance that its measured
/// continuum-vs-CalculiX agreement supports, and the words for its response.
pub trait ContinuumJudged: Continuum {
    /// The largest |FE - continuum| / continuum a converged FE model with the deck's stick slope
    /// gives, a fraction: the measured continuum-vs-CalculiX agreement with a margin
    /// (docs/theory.md, "The verdict against the continuum").
    const CONTINUUM_TOLERANCE: f64;
    /// The response as reports name it (`u(L)`, `Delta`).
    const RESPONSE: &'static str;
}

/// Relative step in K_T of the sensitivity's finite difference: small enough that ln R is
/// straight over it (R is smooth in K_T), large enough that the solver's convergence (1e-10) is
/// far below the change (about 0.1 % to 1 % of R).
const SENSITIVITY_STEP: f64 = 0.02;
/// The implied K_T's root is accepted when ln R is this close to ln R_FE (1e-7 % of R).
const ROOT_TOLERANCE: f64 = 1e-9;
/// Most continuum solves spent on one root (bracketing plus secant).
const MAX_ROOT_SOLVES: usize = 40;
/// Smallest |s| at which a K_T is implied: below, R barely depends on K_T (a factor 1e4 on K_T
/// moves R by under 1e-4 %), and any FE value "implies" a K_T the tolerance cannot bound.
const MIN_SENSITIVITY: f64 = 1e-6;

/// The K_T (MPa/mm) the FE response implies through the continuum, with its interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpliedStiffness {
    /// The K_T whose continuum response equals the FE value (MPa/mm).
    pub value: f64,
    /// The smallest K_T whose response is within the tolerance of the FE value (MPa/mm).
    pub low: f64,
    /// The largest (MPa/mm).
    pub high: f64,
}

/// One FE point against the continuum at the deck's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuumVerdict {
    /// The FE response (mm).
    pub fe: f64,
    /// The continuum's, at the deck's K_T (mm).
    pub continuum: f64,
    /// The tolerance, a fraction: [`ContinuumJudged::CONTINUUM_TOLERANCE`] plus
    /// [`ContinuumVerdict::allowance`].
    pub tolerance: f64,
    /// The part of the tolerance the run's kinematics adds ([`ContinuumVerdict::with_allowance`]),
    /// a fraction: 0 unless the problem states one for it (the beams' `NLGEOM` runs).
    pub allowance: f64,
    /// The deck's K_T (MPa/mm).
    pub deck_stiffness: f64,
    /// d ln R / d ln K_T of the continuum at the deck's K_T (negative: R falls with K_T).
    pub sensitivity: f64,
    /// The K_T the FE value implies, where one does (`None`: no accepted K_T gives it, or R does
    /// not depend on K_T here).
    pub implied: Option<ImpliedStiffness>,
}

impl ContinuumVerdict {
    /// (FE - continuum) / continuum.
    pub fn difference(&self) -> f64 {
        self.fe / self.continuum - 1.0
    }

    /// Within the tolerance.
    pub fn agrees(&self) -> bool {
        self.difference().abs() <= self.tolerance
    }

    /// The smallest relative K_T error this point can detect, tolerance / |s| (a fraction);
    /// `None` where R does not depend on K_T.
    pub fn resolution(&self) -> Option<f64> {
        (self.sensitivity.abs() >= MIN_SENSITIVITY).then(|| self.tolerance / self.sensitivity.abs())
    }

    /// The verdict with `allowance` (a fraction, >= 0) added to its tolerance: what a converged
    /// run of other kinematics than the continuum's small strain may differ by on top (the
    /// beams' `NLGEOM`, docs/theory.md (BC4)). The implied K_T's interval widens with it: its
    /// half-width in ln K_T is the tolerance over the sensitivity at the implied K_T, so it
    /// scales by (tolerance + allowance) / tolerance.
    pub fn with_allowance(mut self, allowance: f64) -> ContinuumVerdict {
        if allowance.is_nan()
            || allowance <= 0.0
            || allowance.is_infinite()
            || self.tolerance <= 0.0
        {
            return self;
        }
        let scale = (self.tolerance + allowance) / self.tolerance;
        if let Some(k) = &mut self.implied {
            k.low = k.value * (k.low / k.value).powf(scale);
            k.high = k.value * (k.high / k.value).powf(scale);
        }
        self.tolerance += allowance;
        self.allowance += allowance;
        self
    }

    /// (implied - deck) / deck.
    pub fn implied_difference(&self) -> Option<f64> {
        self.implied.map(|k| k.value / self.deck_stiffness - 1.0)
    }
}

/// The key of `P`'s tangential stiffness: `KT`, in MPa/mm over the stiffness domain (every
/// problem's K_T is the kernel's one spec).
fn stiffness_key<P: Problem>() -> Option<P::Key> {
    <P::Key as ParamKey>::KEYS.iter().copied().find(|k| {
        let spec = k.spec();
        spec.name == "KT"
            && spec.unit == Unit::MegapascalPerMillimetre
            && spec.domain == Domain::STIFFNESS
    })
}

/// `model` with K_T = `stiffness`, refused (not clamped) where the model refuses it.
fn with_stiffness<P: Problem>(model: &P::Model, key: P::Key, stiffness: f64) -> Option<P::Model> {
    let mut params = P::params(model);
    *P::slot(&mut params, key.index())? = stiffness;
    P::model(&params).ok()
}

/// The continuum's response of `model` at K_T = `stiffness` (mm).
fn response_at<P: Continuum>(
    model: &P::Model,
    key: P::Key,
    stiffness: f64,
) -> Result<f64, NumericError> {
    let at = with_stiffness::<P>(model, key, stiffness).ok_or_else(|| {
        NumericError::OutOfRange(format!("K_T = {stiffness} MPa/mm is refused by the model"))
    })?;
    P::solve_continuum(&at, P::Mesh::default()).map(|r| P::continuum_response(&r))
}

/// The FE response `fe` (mm) of `model` (at the deck's K_T and load) against its continuum.
///
/// # Errors
/// A continuum solve that fails at the deck's K_T ([`NumericError`]); a failure while looking
/// for the implied K_T leaves it `None` instead.
pub fn judge<P: ContinuumJudged>(
    model: &P::Model,
    fe: f64,
) -> Result<ContinuumVerdict, NumericError> {
    let key = stiffness_key::<P>()
        .ok_or_else(|| NumericError::OutOfRange("the problem has no K_T".into()))?;
    let deck_stiffness = P::interface(model).stiffness;
    let continuum = response_at::<P>(model, key, deck_stiffness)?;
    let stepped = deck_stiffness * (1.0 + SENSITIVITY_STEP);
    let at_stepped = response_at::<P>(model, key, stepped)?;
    let sensitivity = (at_stepped / continuum).ln() / (1.0 + SENSITIVITY_STEP).ln();
    let tolerance = P::CONTINUUM_TOLERANCE;
    let known = [(deck_stiffness, continuum), (stepped, at_stepped)];
    let implied = implied_stiffness::<P>(model, key, fe, known, tolerance);
    Ok(ContinuumVerdict {
        fe,
        continuum,
        tolerance,
        allowance: 0.0,
        deck_stiffness,
        sensitivity,
        implied,
    })
}

/// The K_T whose continuum response equals `fe`, starting from two solved points `known`
/// ((K_T, R)), with the interval `tolerance` leaves; `None` where none is found.
fn implied_stiffness<P: Continuum>(
    model: &P::Model,
    key: P::Key,
    fe: f64,
    known: [(f64, f64); 2],
    tolerance: f64,
) -> Option<ImpliedStiffness> {
    if fe <= 0.0 || !fe.is_finite() {
        return None;
    }
    let mut solves = 0;
    // g(x) = ln R(e^x) - ln R_FE falls with x = ln K_T.
    let mut g = |x: f64| -> Option<f64> {
        solves += 1;
        if solves > MAX_ROOT_SOLVES {
            return None;
        }
        let r = response_at::<P>(model, key, x.exp()).ok()?;
        (r > 0.0).then(|| (r / fe).ln())
    };
    let point = |(k, r): (f64, f64)| (k.ln(), (r / fe).ln());
    let (a, b) = (point(known[0]), point(known[1]));
    let slope = (b.1 - a.1) / (b.0 - a.0);
    // R must fall with K_T (NaN too is refused).
    if slope.is_nan() || slope >= -MIN_SENSITIVITY {
        return None;
    }
    let (lo_x, hi_x) = (Domain::STIFFNESS.min().ln(), Domain::STIFFNESS.max().ln());
    // Bracket: walk from the nearer point along the secant's prediction, doubling the step.
    let (mut low, mut high) = if a.1 >= 0.0 && b.1 <= 0.0 {
        (a, b)
    } else {
        let start = if a.1.abs() <= b.1.abs() { a } else { b };
        let direction = if start.1 > 0.0 { 1.0 } else { -1.0 };
        let mut step = (start.1.abs() / slope.abs()).max(SENSITIVITY_STEP) * 1.2;
        let mut last = start;
        loop {
            let x = (last.0 + direction * step).clamp(lo_x, hi_x);
            if x == last.0 {
                return None;
            }
            let next = (x, g(x)?);
            if (next.1 > 0.0) != (start.1 > 0.0) || next.1 == 0.0 {
                break if direction > 0.0 {
                    (last, next)
                } else {
                    (next, last)
                };
            }
            last = next;
            step *= 2.0;
        }
    };
    // Illinois: regula falsi with the stale end's value halved.
    let mut root = if low.1.abs() < high.1.abs() {
        low
    } else {
        high
    };
    let mut side = 0;
    while root.1.abs() > ROOT_TOLERANCE && high.0 - low.0 > 1e-12 {
        let x = (low.0 * high.1 - high.0 * low.1) / (high.1 - low.1);
        let next = (x, g(x)?);
        root = next;
        if next.1 > 0.0 {
            low = next;
            if side == 1 {
                high.1 *= 0.5;
            }
            side = 1;
        } else {
            high = next;
            if side == -1 {
                low.1 *= 0.5;
            }
            side = -1;
        }
    }
    // The sensitivity at the implied K_T, for the interval.
    let step = (1.0 + SENSITIVITY_STEP).ln();
    let s = (g(root.0 + step)? - root.1) / step;
    if s.is_nan() || s >= -MIN_SENSITIVITY {
        return None;
    }
    let half_width = tolerance / s.abs();
    let value = root.0.exp();
    Some(ImpliedStiffness {
        value,
        low: value * (-half_width).exp(),
        high: value * half_width.exp(),
    })
}

/// The continuum failed to solve at the deck's parameters: nothing is judged against it (the
/// solver's reason is not kept, so that a compared row stays `Copy`; `lap --continuum` and
/// `plate --continuum` at the same parameters say it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NotSolved;

/// [`judge`] for a report row: `None` where the continuum's response is 0 (an unloaded step, where
/// a relative difference is undefined, as the closed form's "n/a"; judging it printed "NaN %"), a
/// failure as [`NotSolved`].
pub fn judged<P: ContinuumJudged>(
    model: &P::Model,
    fe: f64,
) -> Option<Result<ContinuumVerdict, NotSolved>> {
    match judge::<P>(model, fe) {
        Ok(verdict) if verdict.continuum == 0.0 => None,
        Ok(verdict) => Some(Ok(verdict)),
        Err(_) => Some(Err(NotSolved)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::plate::closed_form::SqueezedPlate;
    use crate::problems::plate::params::{PlateParam, PlateParams};
    use crate::problems::plate::problem::SqueezedPlateProblem;

    fn plate(kt: f64) -> SqueezedPlate {
        SqueezedPlate::new(PlateParams::PAPER)
            .unwrap()
            .with_clamped(PlateParam::Stiffness, kt)
    }

    /// The continuum's u(L) of the paper's plate at `kt`, solved directly.
    fn continuum_u(kt: f64) -> f64 {
        let reference =
            SqueezedPlateProblem::solve_continuum(&plate(kt), Default::default()).unwrap();
        SqueezedPlateProblem::continuum_response(&reference)
    }

    /// An "FE code" whose stick slope is 10 % off: its u(L) is the continuum's at 1.1 K_T (and
    /// 0.9 K_T). The verdict must say it disagrees, and imply that stick slope, not the deck's.
    #[test]
    fn a_stick_slope_ten_percent_off_is_caught_and_implied() {
        let deck = 1e4;
        for factor in [1.1, 0.9] {
            let fe = continuum_u(factor * deck);
            let v = judge::<SqueezedPlateProblem>(&plate(deck), fe).unwrap();
            assert!(!v.agrees(), "{factor}: {v:?}");
            let k = v.implied.unwrap();
            assert!(
                (k.value / (factor * deck) - 1.0).abs() < 1e-5,
                "{factor}: {k:?}"
            );
            assert!(k.low < k.value && k.value < k.high);
            // The interval is the tolerance over the local sensitivity: about +-0.6 % here.
            let half = (k.high / k.low).ln() / 2.0;
            assert!((0.004..0.008).contains(&half), "{half}");
        }
    }

    /// An allowance widens the tolerance and the implied K_T's interval in proportion (the
    /// half-width in ln K_T is the tolerance over the sensitivity), and leaves the implied K_T;
    /// a value outside the tolerance but inside tolerance + allowance agrees with it only.
    #[test]
    fn an_allowance_widens_the_tolerance_and_the_interval_in_proportion() {
        let deck = 1e4;
        let fe = continuum_u(deck) * 1.004;
        let v = judge::<SqueezedPlateProblem>(&plate(deck), fe).unwrap();
        assert!(!v.agrees());
        let w = v.with_allowance(0.003);
        assert!(w.agrees());
        assert_eq!(w.allowance, 0.003);
        assert!((w.tolerance - v.tolerance - 0.003).abs() < 1e-15);
        let (k, kw) = (v.implied.unwrap(), w.implied.unwrap());
        assert_eq!(k.value, kw.value);
        let scale = w.tolerance / v.tolerance;
        assert!(((kw.high / kw.value).ln() / (k.high / k.value).ln() - scale).abs() < 1e-9);
        assert!(((kw.low / kw.value).ln() / (k.low / k.value).ln() - scale).abs() < 1e-9);
        assert!((w.resolution().unwrap() / v.resolution().unwrap() - scale).abs() < 1e-12);
        for nothing in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(v.with_allowance(nothing), v);
        }
    }

    /// The continuum's own value agrees and implies the deck's K_T; the sensitivity is the
    /// slope of ln u against ln K_T measured over a wider step (u falls with K_T (P10)), and
    /// the resolution is the tolerance over it.
    #[test]
    fn the_continuum_agrees_with_itself_and_states_its_resolution() {
        let deck = 1e4;
        let v = judge::<SqueezedPlateProblem>(&plate(deck), continuum_u(deck)).unwrap();
        assert!(v.agrees());
        assert_eq!(v.difference(), 0.0);
        assert!((v.implied.unwrap().value / deck - 1.0).abs() < 1e-6);
        let wide = (continuum_u(1.1 * deck) / continuum_u(deck / 1.1)).ln() / (1.21f64).ln();
        assert!(v.sensitivity < 0.0);
        assert!(
            (v.sensitivity / wide - 1.0).abs() < 0.02,
            "{} {wide}",
            v.sensitivity
        );
        let resolution = v.resolution().unwrap();
        assert!((resolution - 0.003 / v.sensitivity.abs()).abs() < 1e-12);
        // Just inside and just outside the tolerance.
        let inside = judge::<SqueezedPlateProblem>(&plate(deck), continuum_u(deck) * 1.0029);
        assert!(inside.unwrap().agrees());
        let outside = judge::<SqueezedPlateProblem>(&plate(deck), continuum_u(deck) * 1.0031);
        assert!(!outside.unwrap().agrees());
    }

    /// A value no K_T can give (beyond the free expansion of the plate, or not positive)
    /// implies none, and the verdict says it disagrees.
    #[test]
    fn an_impossible_value_implies_no_stiffness() {
        let p = PlateParams::PAPER;
        let free = p.poisson * (1.0 + p.poisson) * p.pressure * p.half_length / p.youngs_modulus;
        for fe in [2.0 * free, -1e-5] {
            let v = judge::<SqueezedPlateProblem>(&plate(1e4), fe).unwrap();
            assert_eq!(v.implied, None, "{fe}");
            assert!(!v.agrees());
        }
    }
}
