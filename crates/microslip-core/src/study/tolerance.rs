//! The question FE users ask: how stiff must the friction penalty K_T be for the regularized answer
//! to stay within a tolerance of Coulomb? The smallest such K_T, and what it means in each FE code's
//! own setting (docs/theory.md, (T1)-(T3)).
//!
//! Both answers rest on monotonicity, derived in docs/theory.md: at a fixed tip force the twin beams'
//! regularized w(L) does not increase with K_T (T1), the plate's u(L) falls strictly with K_T
//! (P10), and at a fixed force the lap joint's Delta does not increase with K_T (L11). The deviation from Coulomb is then a non-increasing function of K_T, its worst value over
//! a force range too, and "within tolerance" holds on one interval [K_T*, infinity): one bracketed
//! root on ln K_T finds K_T*.

use crate::kernel::code_defaults::{CODE_DEFAULTS, CodeDefault, DefaultRule};
use crate::kernel::params::{Domain, ParamError, significant};
use crate::kernel::regime::Law;
use crate::kernel::solve::find_root_in_bracket;
use crate::problems::load_driven::LoadDriven;
use crate::problems::problem::{BothLaws, Registered};
use crate::problems::{ModelKind, ParamKey, Problem};

/// Force samples over a range of the load, besides its ends and regime changes: the deviation is
/// flat below F_thre and falls above it (T2), and over the joint's range it is largest near zero
/// (L11), so the samples only guard that analysis.
const FORCE_SAMPLES: usize = 64;

/// The accepted tolerances (fractions): from 1e-9 (round-off of the closed forms is ~1e-12) to 10
/// (1000 %).
const TOLERANCE: Domain = Domain::Positive {
    min: 1e-9,
    max: 10.0,
};

/// The smallest K_T within the tolerance, if the accepted K_T range holds one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Threshold {
    /// Every K_T at least this (MPa/mm) is within the tolerance; smaller ones are not.
    Stiffness(f64),
    /// Even the smallest accepted K_T (the value given) is within the tolerance.
    Everywhere(f64),
    /// Not even the largest accepted K_T (the value given) is: its deviation is given too.
    Nowhere {
        /// The largest accepted K_T (MPa/mm).
        stiffness: f64,
        /// Its deviation from Coulomb (fraction).
        deviation: f64,
    },
}

impl Threshold {
    /// The K_T that meets the tolerance with the least stiffness, if any.
    pub fn stiffness(self) -> Option<f64> {
        match self {
            Threshold::Stiffness(k) | Threshold::Everywhere(k) => Some(k),
            Threshold::Nowhere { .. } => None,
        }
    }
}

/// What the tolerance asks of K_T, for one model and range.
#[derive(Debug, Clone, PartialEq)]
pub struct ToleranceAnswer {
    /// The problem answered.
    pub kind: ModelKind,
    /// The tolerance (fraction: 0.01 for 1 %).
    pub tolerance: f64,
    /// Beams: the tip-force range checked [from, to] (N); plate: None.
    pub forces: Option<[f64; 2]>,
    /// The smallest K_T within the tolerance.
    pub threshold: Threshold,
    /// The current K_T (MPa/mm) and its worst deviation from Coulomb over the range (fraction).
    pub current: (f64, f64),
    /// What the threshold means in each FE code's setting.
    pub settings: Vec<CodeSetting>,
    /// The other reading, when asked for ([`stiffness_near_current`]): the tolerance is of
    /// the current K_T's answer, not of Coulomb's; `threshold` is then the interval's lower end.
    pub near_current: Option<NearCurrent>,
}

/// The K_T interval whose answer stays within the tolerance of the current K_T's (the reading
/// "within 1 % of what my model gives", beside "within 1 % of Coulomb").
///
/// The answer does not increase with K_T (T1, P10), so its ratio to the current K_T's answer,
/// minus 1, falls through 0 at the current K_T: the K_T within the tolerance form one interval
/// around it, found by one bracketed root on each side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NearCurrent {
    /// The largest K_T within (MPa/mm): a root, or the largest accepted K_T when even that one is
    /// within while Coulomb is not; None only when Coulomb's answer itself is within, and with it
    /// every stiffer K_T.
    pub upper: Option<f64>,
    /// True when `upper` is the largest accepted K_T, not a root (Coulomb itself is outside).
    pub upper_is_largest_accepted: bool,
    /// Coulomb's answer against the current K_T's, worst over the forces (fraction, <= 0).
    pub coulomb: f64,
}

/// One FE code's setting that gives at least the K_T needed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CodeSetting {
    /// The code.
    pub code: &'static CodeDefault,
    /// The K_T its default gives here (MPa/mm), if it has one; and whether that is enough.
    pub default: Option<(f64, bool)>,
    /// The setting needed.
    pub needed: Setting,
}

/// A code's own setting, in its own terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Setting {
    /// Allowable elastic slip: at most `fraction` of the contact face length `element` (mm), i.e. at
    /// most `slip` (mm) absolute; or, keeping the default fraction, faces no longer than
    /// `element_max` (mm).
    SlipTolerance {
        /// The largest fraction of the element length.
        fraction: f64,
        /// The element length it is a fraction of (mm).
        element: f64,
        /// The largest absolute elastic slip, mu P / K_T* (mm).
        slip: f64,
        /// The largest element length with the code's default fraction (mm).
        element_max: f64,
    },
    /// A stick slope (penalty) of at least this (MPa/mm).
    StickSlope(f64),
    /// A penalty E / (d h_min): the smallest contact element at most this (mm).
    ElementSize(f64),
    /// The friction stiffness the user gives: at least this (MPa/mm).
    Stiffness(f64),
}

/// Why a question cannot be answered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ToleranceError {
    /// The tolerance is out of range.
    #[error("invalid tolerance = {value}: a fraction from 1e-9 to 10, e.g. 0.01 or 1%")]
    Tolerance {
        /// The value given.
        value: f64,
    },
    /// The force range is empty of loads or out of range.
    #[error(transparent)]
    Force(#[from] ParamError),
    /// Only zero force: no deflection to compare.
    #[error("the force range [{from}, {to}] N holds no positive force: nothing moves")]
    Unloaded {
        /// Start (N).
        from: f64,
        /// End (N).
        to: f64,
    },
    /// The deviation from Coulomb has no bound as the load falls to zero, at every finite K_T
    /// ([`LoadDriven::unbounded_at_zero`]): no K_T holds over a range from 0.
    #[error(
        "no K_T keeps the regularized answer within {} % of Coulomb's at every load from 0 to {to}{unit}: {reason}",
        significant(100.0 * tolerance, 6)
    )]
    UnboundedAtZero {
        /// The tolerance asked (fraction).
        tolerance: f64,
        /// The range's end.
        to: f64,
        /// The load's unit with a leading space (` N/mm`).
        unit: String,
        /// Why, in the problem's words.
        reason: &'static str,
    },
    /// The problem has no interface stiffness K_T parameter to search (every bundled problem
    /// has one).
    #[error("the {kind} problem has no interface stiffness K_T")]
    NoStiffness {
        /// The problem.
        kind: ModelKind,
    },
}

fn check_tolerance(tolerance: f64) -> Result<f64, ToleranceError> {
    if TOLERANCE.contains(tolerance) {
        Ok(tolerance)
    } else {
        Err(ToleranceError::Tolerance { value: tolerance })
    }
}

/// The regularized response of `model` over Coulomb's, minus 1: its deviation at its own state.
fn state_deviation<P: Problem>(model: &P::Model) -> f64 {
    let state = P::solve(model);
    state.regularized().response() / state.coulomb().response() - 1.0
}

/// The key of `P`'s interface stiffness K_T: its parameter in MPa/mm.
fn stiffness_key<P: Problem>() -> Option<P::Key> {
    let index = P::INFO.params.iter().position(|p| p.is_stiffness())?;
    <P::Key as ParamKey>::KEYS.get(index).copied()
}

/// `model` with K_T = `kt` (clamped to what it accepts), and K_T's domain; `None` for a problem
/// without a K_T parameter.
fn with_stiffness<P: Problem>(model: &P::Model) -> Option<(impl Fn(f64) -> P::Model + '_, Domain)> {
    let key = stiffness_key::<P>()?;
    Some((
        move |kt: f64| P::with_clamped(model, key, kt),
        key.spec().domain,
    ))
}

/// The smallest K_T at which `deviation(K_T)`, non-increasing, is at most `tolerance`, searched
/// over `domain` on ln K_T.
fn smallest_within(domain: Domain, tolerance: f64, deviation: impl Fn(f64) -> f64) -> Threshold {
    let (lo, hi) = (domain.min(), domain.max());
    if deviation(lo) <= tolerance {
        return Threshold::Everywhere(lo);
    }
    let stiff = deviation(hi);
    if stiff > tolerance {
        return Threshold::Nowhere {
            stiffness: hi,
            deviation: stiff,
        };
    }
    // Relative misfit: numbers near 1 whatever the tolerance's scale.
    let misfit = |ln_k: f64| deviation(ln_k.exp()) / tolerance - 1.0;
    let ln_k = find_root_in_bracket(misfit, lo.ln(), hi.ln());
    Threshold::Stiffness(ln_k.exp())
}

/// The forces at which the deviation is checked: the ends of [from, to], [`FORCE_SAMPLES`]
/// between, the regime changes inside (F_thre; F_1 and F_2 of the joint) and the problem's own
/// probes ([`LoadDriven::deviation_probes`]); zero left out (nothing moves).
fn force_grid<P: LoadDriven>(model: &P::Structure, [from, to]: [f64; 2]) -> Vec<P::Force> {
    let mut forces: Vec<f64> = (0..=FORCE_SAMPLES)
        .map(|i| from + (to - from) * i as f64 / FORCE_SAMPLES as f64)
        .collect();
    forces.extend(P::deviation_probes(model, [from, to]));
    let inside = |f: &f64| (from..=to).contains(f);
    forces.extend(P::regime_changes(model).into_iter().filter(inside));
    forces.retain(|&f| f > 0.0);
    forces.sort_by(f64::total_cmp);
    forces.dedup();
    forces
        .into_iter()
        .map(|f| P::clamped_force(model, f))
        .collect()
}

/// The force range `[from, to]` (N) checked against `model` (each a force it carries) and
/// ordered, and the forces sampled in it.
fn checked_forces<P: LoadDriven>(
    model: &P::Structure,
    [from, to]: [f64; 2],
) -> Result<([f64; 2], Vec<P::Force>), ToleranceError> {
    let (from, to) = (
        P::load_value(P::force(model, from)?),
        P::load_value(P::force(model, to)?),
    );
    let (from, to) = (from.min(to), from.max(to));
    if to <= 0.0 {
        return Err(ToleranceError::Unloaded { from, to });
    }
    Ok(([from, to], force_grid::<P>(model, [from, to])))
}

/// The worst, over `forces`, of the regularized response over Coulomb's, minus 1.
fn worst<P: LoadDriven>(model: &P::Structure, forces: &[P::Force]) -> f64 {
    forces
        .iter()
        .map(|&f| {
            P::response(model, Law::Regularized, f) / P::response(model, Law::Coulomb, f) - 1.0
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The question about `model` over `range` (N) at `tolerance`, checked, and the forces sampled in
/// the range: what both readings start from.
fn load_question<P: LoadDriven>(
    model: &P::Structure,
    range: [f64; 2],
    tolerance: f64,
) -> Result<(Question, Vec<P::Force>), ToleranceError> {
    let tolerance = check_tolerance(tolerance)?;
    let (range, forces) = checked_forces::<P>(model, range)?;
    let question = Question {
        kind: P::KIND,
        tolerance,
        forces: Some(range),
        current: (P::tangential_stiffness(model), worst::<P>(model, &forces)),
        domain: P::STIFFNESS.spec().domain,
    };
    Ok((question, forces))
}

/// `model` with K_T = `kt`; every K_T of the domain is accepted (and no force depends on K_T,
/// nor does the joint's F_gross), so the fallback is never taken.
fn stiffened<P: LoadDriven>(model: &P::Structure, kt: f64) -> P::Structure {
    P::with_tangential_stiffness(model, kt).unwrap_or(*model)
}

/// Each code's setting for `threshold` on `model` with contact elements of `element` (mm).
fn load_settings<P: LoadDriven>(
    model: &P::Structure,
    threshold: Threshold,
    element: f64,
) -> Vec<CodeSetting> {
    code_settings(
        threshold,
        P::interface_strength(model),
        P::modulus(model),
        element,
    )
}

/// Any load-driven problem: the smallest K_T for which the regularized response stays within
/// `tolerance` (fraction) of Coulomb's at every force in `range` = `[from, to]` (N), all else as
/// in `model`. The response does not increase with K_T at a fixed force ((T1), (L11)), so the
/// worst deviation over the forces is non-increasing in K_T and one root on ln K_T finds it.
///
/// # Errors
/// A tolerance outside (0, 10], forces the structure does not carry, no positive force, or a
/// range from 0 where the problem's deviation has no bound there.
pub fn stiffness_for_tolerance<P: LoadDriven>(
    model: &P::Structure,
    range: [f64; 2],
    tolerance: f64,
    element: f64,
) -> Result<ToleranceAnswer, ToleranceError> {
    // Before any solve: the question has no answer, whatever the solutions.
    let ([from, to], _) = checked_forces::<P>(model, range)?;
    if let (Some(reason), 0.0) = (P::unbounded_at_zero(model), from) {
        return Err(ToleranceError::UnboundedAtZero {
            tolerance: check_tolerance(tolerance)?,
            to,
            unit: P::KIND
                .description()
                .load
                .map(|load| load.unit_suffix())
                .unwrap_or_default(),
            reason,
        });
    }
    let (question, forces) = load_question::<P>(model, range, tolerance)?;
    let at = |kt: f64| worst::<P>(&stiffened::<P>(model, kt), &forces);
    let threshold = smallest_within(question.domain, question.tolerance, at);
    Ok(ToleranceAnswer {
        kind: question.kind,
        tolerance: question.tolerance,
        forces: question.forces,
        threshold,
        current: question.current,
        settings: load_settings::<P>(model, threshold, element),
        near_current: None,
    })
}

/// Any load-driven problem, the other reading: the K_T for which the regularized response stays
/// within `tolerance` (fraction) of the current K_T's at every force in `range` (N). The lower
/// end is the answer's `threshold` (with the codes' settings for it), the upper end in
/// `near_current`.
///
/// # Errors
/// As [`stiffness_for_tolerance`].
pub fn stiffness_near_current<P: LoadDriven>(
    model: &P::Structure,
    range: [f64; 2],
    tolerance: f64,
    element: f64,
) -> Result<ToleranceAnswer, ToleranceError> {
    let (question, forces) = load_question::<P>(model, range, tolerance)?;
    Ok(near_current_over_forces(
        question,
        &forces,
        |kt, f| P::response(&stiffened::<P>(model, kt), Law::Regularized, f),
        |f| P::response(model, Law::Coulomb, f),
        |threshold| load_settings::<P>(model, threshold, element),
    ))
}

/// [`near_current`] over a force range: `response(K_T, F)` is the regularized answer at each
/// force, `coulomb(F)` Coulomb's; the current K_T is the question's.
fn near_current_over_forces<F: Copy>(
    question: Question,
    forces: &[F],
    response: impl Fn(f64, F) -> f64,
    coulomb: impl Fn(F) -> f64,
    settings: impl Fn(Threshold) -> Vec<CodeSetting>,
) -> ToleranceAnswer {
    let kt = question.current.0;
    let current: Vec<f64> = forces.iter().map(|&f| response(kt, f)).collect();
    // Each force's answer at K_T over the current's, minus 1: (highest, lowest) over the forces.
    let ratios = |kt: f64| {
        forces
            .iter()
            .zip(&current)
            .map(|(&f, c)| response(kt, f) / c - 1.0)
            .fold((f64::NEG_INFINITY, f64::INFINITY), |(hi, lo), r| {
                (hi.max(r), lo.min(r))
            })
    };
    let coulomb = forces
        .iter()
        .zip(&current)
        .map(|(&f, c)| coulomb(f) / c - 1.0)
        .fold(f64::INFINITY, f64::min);
    near_current(
        question,
        coulomb,
        |kt| ratios(kt).0,
        |kt| -ratios(kt).1,
        settings,
    )
}

/// A problem at its own state (no load to range over: the plate under its pressure), the other
/// reading (see [`stiffness_near_current`]): the K_T interval whose responses stay within
/// `tolerance` of the response at the model's own K_T.
///
/// # Errors
/// As [`state_stiffness_for_tolerance`].
pub fn state_stiffness_near_current<P: Problem + Registered>(
    model: &P::Model,
    tolerance: f64,
    element: f64,
) -> Result<ToleranceAnswer, ToleranceError> {
    let tolerance = check_tolerance(tolerance)?;
    let (at, domain) =
        with_stiffness::<P>(model).ok_or(ToleranceError::NoStiffness { kind: P::KIND })?;
    let own = P::solve(model);
    let current = own.regularized().response();
    let ratio = |kt: f64| P::solve(&at(kt)).regularized().response() / current - 1.0;
    let coulomb = own.coulomb().response() / current - 1.0;
    let data = P::interface(model);
    let question = Question {
        kind: P::KIND,
        tolerance,
        forces: None,
        current: (data.stiffness, state_deviation::<P>(model)),
        domain,
    };
    Ok(near_current(
        question,
        coulomb,
        ratio,
        |kt| -ratio(kt),
        |threshold| {
            code_settings(
                threshold,
                data.friction * data.pressure,
                data.modulus,
                element,
            )
        },
    ))
}

/// What a question of the other reading fixes before any root is searched.
struct Question {
    /// The problem asked about.
    kind: ModelKind,
    /// The checked tolerance (fraction).
    tolerance: f64,
    /// Beams: the force range checked (N); plate: None.
    forces: Option<[f64; 2]>,
    /// The current K_T (MPa/mm) and its worst deviation from Coulomb (fraction).
    current: (f64, f64),
    /// The accepted K_T.
    domain: Domain,
}

/// The interval of `question` against the current K_T: `above(K)` (non-increasing, 0 at the
/// current K_T) is how far over the current answer K_T's goes, `below(K)` (non-decreasing) how far
/// under; `settings` gives each code's setting for a threshold.
fn near_current(
    question: Question,
    coulomb: f64,
    above: impl Fn(f64) -> f64,
    below: impl Fn(f64) -> f64,
    settings: impl Fn(Threshold) -> Vec<CodeSetting>,
) -> ToleranceAnswer {
    let Question {
        kind,
        tolerance,
        forces,
        current,
        domain,
    } = question;
    let (kt, hi) = (current.0, domain.max());
    let threshold = smallest_within(domain, tolerance, above);
    // Unbounded only when Coulomb's answer (K_T -> infinity) is itself within; otherwise the
    // interval ends at the root, or at the largest accepted K_T when even that one is within.
    let upper = if -coulomb <= tolerance {
        None
    } else if below(hi) <= tolerance {
        Some(hi)
    } else {
        let misfit = |ln_k: f64| below(ln_k.exp()) / tolerance - 1.0;
        Some(find_root_in_bracket(misfit, kt.ln(), hi.ln()).exp())
    };
    let mut settings = settings(threshold);
    // A default stiffer than the interval's upper end misses it too.
    for setting in &mut settings {
        if let (Some((k, enough)), Some(upper)) = (&mut setting.default, upper) {
            *enough &= *k <= upper;
        }
    }
    ToleranceAnswer {
        kind,
        tolerance,
        forces,
        threshold,
        current,
        settings,
        near_current: Some(NearCurrent {
            upper,
            coulomb,
            upper_is_largest_accepted: upper == Some(hi),
        }),
    }
}

/// A problem at its own state (the plate under its pressure): the smallest K_T for which its
/// regularized response (the plate's u(L)) is within `tolerance` (fraction) of Coulomb's, all
/// else as in `model`.
///
/// # Errors
/// A tolerance outside (0, 10]; a problem without a K_T parameter.
pub fn state_stiffness_for_tolerance<P: Problem + Registered>(
    model: &P::Model,
    tolerance: f64,
    element: f64,
) -> Result<ToleranceAnswer, ToleranceError> {
    let tolerance = check_tolerance(tolerance)?;
    let (at, domain) =
        with_stiffness::<P>(model).ok_or(ToleranceError::NoStiffness { kind: P::KIND })?;
    let threshold = smallest_within(domain, tolerance, |kt| state_deviation::<P>(&at(kt)));
    let data = P::interface(model);
    Ok(ToleranceAnswer {
        kind: P::KIND,
        tolerance,
        forces: None,
        threshold,
        current: (data.stiffness, state_deviation::<P>(model)),
        settings: code_settings(
            threshold,
            data.friction * data.pressure,
            data.modulus,
            element,
        ),
        near_current: None,
    })
}

/// Each code's setting for a penalty of at least the threshold (T3). `mu_p` is mu P (MPa),
/// `element` the contact element length (mm).
fn code_settings(threshold: Threshold, mu_p: f64, modulus: f64, element: f64) -> Vec<CodeSetting> {
    let Some(needed) = threshold.stiffness() else {
        return Vec::new();
    };
    CODE_DEFAULTS
        .iter()
        .map(|code| {
            let default = code
                .implied_stiffness(mu_p, 1.0, modulus, element)
                .map(|k| (k, k >= needed));
            let setting = match code.rule {
                DefaultRule::ElasticSlipFraction(f) => Setting::SlipTolerance {
                    fraction: mu_p / (needed * element),
                    element,
                    slip: mu_p / needed,
                    element_max: mu_p / (f * needed),
                },
                DefaultRule::ModulusOver(_) => Setting::StickSlope(needed),
                DefaultRule::ModulusOverSize(d) => Setting::ElementSize(modulus / (d * needed)),
                DefaultRule::UserSupplied | DefaultRule::Unknown => Setting::Stiffness(needed),
            };
            CodeSetting {
                code,
                default,
                needed: setting,
            }
        })
        .collect()
}

/// A tolerance that [`parse_tolerance`] refuses: the text typed and what is allowed (a fraction
/// from 1e-9 to 10, written as a number or a percentage). The words are the
/// `--tolerance` flag's, where users type it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ParseToleranceError {
    /// Not a number, with or without `%`.
    #[error("invalid --tolerance '{text}': a number, e.g. 1% or 0.01")]
    NotANumber {
        /// The text typed.
        text: String,
    },
    /// A number outside the allowed fractions, 1e-9 to 10 (1e-7 % to 1000 %).
    #[error("invalid --tolerance '{text}': between 1e-7 % and 1000 %")]
    OutOfRange {
        /// The text typed.
        text: String,
        /// The fraction it reads as.
        value: f64,
        /// The fractions allowed.
        allowed: Domain,
    },
}

/// Parses a tolerance as typed: `1%` or `0.01`.
///
/// # Errors
/// Not a number, or outside (0, 10] as a fraction.
pub fn parse_tolerance(text: &str) -> Result<f64, ParseToleranceError> {
    let trimmed = text.trim();
    let (number, scale) = match trimmed.strip_suffix('%') {
        Some(n) => (n.trim(), 0.01),
        None => (trimmed, 1.0),
    };
    let value = crate::kernel::params::parse_number(number)
        .map(|v| v * scale)
        .ok_or_else(|| ParseToleranceError::NotANumber {
            text: text.to_string(),
        })?;
    check_tolerance(value).map_err(|_| ParseToleranceError::OutOfRange {
        text: text.to_string(),
        value,
        allowed: TOLERANCE,
    })
}
