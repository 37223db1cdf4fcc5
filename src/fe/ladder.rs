//! Mesh and increment ladders: one quantity's FE answers at element sizes h, h/2, h/4 (the
//! [`DeckMesh`](super::deck::DeckMesh) rungs) and at two increment sizes, taken to a converged
//! estimate with its uncertainty ([`extrapolate`]), and that estimate judged against the
//! closed form's tolerance ([`judge`]).
//!
//! Why: one coarse run's difference from the closed form mixes the FE discretization error with
//! the closed form's own; the envelopes that absorbed both were 5 to 20 times wider than
//! converged FE needs (issue 45). Richardson extrapolation with the order the ladder itself
//! shows (not an assumed one: contact makes the formal order of the elements meaningless) takes
//! the discretization error out and says how well it did; where the ladder is not in the
//! asymptotic range it says so and keeps the spread of the rungs as the uncertainty.
//!
//! The quantity extrapolated is a run's relative difference from the closed form
//! ([`LadderQuantity::difference`]): the closed form is the same on every rung (the same
//! parameters and loads), so extrapolating the difference is extrapolating the FE answer.

use serde::Serialize;

/// One quantity a run of a problem's deck gives against its closed form, as a ladder
/// extrapolates it: named with its load step (`s(a) at Q = 180 N/mm`), its difference from the
/// closed form as a fraction (of the closed form's value, or of the length the problem's
/// envelope measures it in: the cylinder's c in a), and the envelope's bound on that difference
/// (`None`: not calibrated there).
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct LadderQuantity {
    /// The quantity and its load step.
    pub name: String,
    /// (FE - closed form) / scale, a fraction.
    pub difference: f64,
    /// The bound the problem's envelope states on it, a fraction; `None`: not calibrated.
    pub bound: Option<f64>,
    /// The quantity itself where the problem states it: the closed form's value and the scale
    /// the difference is a fraction of, in `unit` (the FE value is value + difference x scale).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<ValueScale>,
}

/// How a [`LadderQuantity`]'s difference maps back to the quantity.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct ValueScale {
    /// The reference's value: the closed form's, or the problem's continuum's where the judge
    /// compares with it (the press fit's Delta).
    pub closed_form: f64,
    /// The length or value the difference is a fraction of.
    pub scale: f64,
    /// Their unit.
    pub unit: String,
}

impl ValueScale {
    /// The quantity at difference `d`.
    pub fn at(&self, d: f64) -> f64 {
        self.closed_form + d * self.scale
    }
}

/// The band of observed orders taken as asymptotic: outside it the three rungs are not yet on
/// one power law (first order is the lowest a consistent discretization gives; quadratic
/// elements with a smooth answer give 3 to 4).
pub const SANE_ORDER: (f64, f64) = (0.5, 4.0);

/// Roache's factor of safety on a three-rung Richardson estimate (the grid convergence index):
/// the uncertainty stated is 1.25 times the extrapolation's own correction.
pub const SAFETY_FACTOR: f64 = 1.25;

/// How the rungs behaved.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Convergence {
    /// Three rungs whose differences shrink monotonically with an observed order in
    /// [`SANE_ORDER`]: Richardson's estimate.
    Asymptotic,
    /// Three rungs that do not (the differences change sign, do not shrink, or the order is
    /// outside the band): the finest answer, with the spread of the rungs as its uncertainty.
    NotAsymptotic,
    /// Two rungs: the finer answer, with the last change as its uncertainty (the error left is
    /// at most the last change for any order of at least 1); no order can be observed.
    TwoRungs,
    /// One run: nothing to extrapolate.
    SingleRun,
}

impl Convergence {
    /// The words a scorecard says.
    pub fn words(self) -> &'static str {
        match self {
            Convergence::Asymptotic => "Richardson, in the asymptotic range",
            Convergence::NotAsymptotic => {
                "not in the asymptotic range: the finest answer, the rungs' spread as uncertainty"
            }
            Convergence::TwoRungs => "two meshes: the finer answer, the last change as uncertainty",
            Convergence::SingleRun => "single run, not converged",
        }
    }
}

/// A quantity's ladder taken to its converged estimate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Extrapolation {
    /// The converged estimate.
    pub estimate: f64,
    /// Its uncertainty (absolute, in the quantity's unit), the increment's change included;
    /// `None` for a single run.
    pub uncertainty: Option<f64>,
    /// The observed order p = ln((f1 - f2) / (f2 - f3)) / ln 2, where three rungs give one.
    pub order: Option<f64>,
    /// How the rungs behaved.
    pub convergence: Convergence,
    /// |f(dt) - f(dt / 2)| on the finest mesh, where the half increment was run.
    pub increment_change: Option<f64>,
}

/// The converged estimate of a quantity from its answers on a mesh ladder `meshes` (coarsest
/// first, each rung halving the element size: h, h/2, h/4; the last three are used), and
/// `half_increment`: the same quantity on the finest mesh at half the load increment, whose
/// change is added to the uncertainty. `None` when `meshes` is empty or holds a non-finite value.
pub fn extrapolate(meshes: &[f64], half_increment: Option<f64>) -> Option<Extrapolation> {
    if meshes.iter().any(|v| !v.is_finite()) || half_increment.is_some_and(|v| !v.is_finite()) {
        return None;
    }
    let finest = *meshes.last()?;
    let increment_change = half_increment.map(|v| (v - finest).abs());
    let (estimate, uncertainty, order, convergence) = match *meshes {
        [_] => (finest, None, None, Convergence::SingleRun),
        [f1, f2] => (f2, Some((f1 - f2).abs()), None, Convergence::TwoRungs),
        [.., f1, f2, f3] => three_rungs(f1, f2, f3),
        [] => return None,
    };
    Some(Extrapolation {
        estimate,
        uncertainty: uncertainty.map(|u| u + increment_change.unwrap_or(0.0)),
        order,
        convergence,
        increment_change,
    })
}

/// Richardson on three rungs f1 (h), f2 (h/2), f3 (h/4).
fn three_rungs(f1: f64, f2: f64, f3: f64) -> (f64, Option<f64>, Option<f64>, Convergence) {
    let (e21, e32) = (f1 - f2, f2 - f3);
    if e21 == 0.0 && e32 == 0.0 {
        // Every rung the same: converged to the last digit.
        return (f3, Some(0.0), None, Convergence::Asymptotic);
    }
    let shrinking = e21 * e32 > 0.0 && e32.abs() < e21.abs();
    let order = shrinking.then(|| (e21 / e32).ln() / std::f64::consts::LN_2);
    match order {
        Some(p) if (SANE_ORDER.0..=SANE_ORDER.1).contains(&p) => {
            let correction = e32 / (2f64.powf(p) - 1.0);
            let estimate = f3 - correction;
            (
                estimate,
                Some(SAFETY_FACTOR * correction.abs()),
                Some(p),
                Convergence::Asymptotic,
            )
        }
        _ => {
            let spread = f1.max(f2).max(f3) - f1.min(f2).min(f3);
            (f3, Some(spread), order, Convergence::NotAsymptotic)
        }
    }
}

/// A ladder's verdict on a quantity or a case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub enum Verdict {
    /// The converged estimate is within the tolerance.
    #[serde(rename = "agrees")]
    Agrees,
    /// No bound is calibrated for it: shown, not judged.
    #[serde(rename = "not judged")]
    NotJudged,
    /// The ladder's uncertainty is larger than the reference's own accuracy: it cannot judge
    /// at the accuracy the reference has (refine, or run the full ladder).
    #[serde(rename = "not converged")]
    NotConverged,
    /// The converged estimate is outside the tolerance.
    #[serde(rename = "does not agree")]
    DoesNotAgree,
}

impl Verdict {
    /// Its label, as JSON and the scorecard write it.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::NotJudged => "not judged",
            Verdict::NotConverged => "not converged",
            Verdict::DoesNotAgree => "does not agree",
        }
    }
}

/// The converged difference `extrapolation` judged against the closed form: the tolerance is
/// the reference's own measured accuracy (`bound`, the problem's envelope) plus the
/// extrapolation's uncertainty. Not converged when that uncertainty exceeds the bound itself
/// (the ladder cannot tell agreement at the reference's accuracy); not judged without a bound.
/// A single run is judged against the bound alone (today's verdict), and its label says it is
/// a single run.
pub fn judge(extrapolation: &Extrapolation, bound: Option<f64>) -> Verdict {
    let Some(bound) = bound else {
        return Verdict::NotJudged;
    };
    let uncertainty = extrapolation.uncertainty.unwrap_or(0.0);
    if uncertainty > bound {
        Verdict::NotConverged
    } else if extrapolation.estimate.abs() <= bound + uncertainty {
        Verdict::Agrees
    } else {
        Verdict::DoesNotAgree
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = f* + C h^p on h, h/2, h/4.
    fn manufactured(exact: f64, c: f64, p: f64) -> [f64; 3] {
        [1.0, 0.5, 0.25].map(|h: f64| exact + c * h.powf(p))
    }

    #[test]
    fn richardson_recovers_the_exact_value_and_the_order() {
        for (exact, c, p) in [
            (0.0123, 0.04, 1.0),
            (-0.02, -0.3, 2.0),
            (1.5, 0.7, 1.37),
            (0.0, 1e-3, 3.5),
        ] {
            let e = extrapolate(&manufactured(exact, c, p), None).unwrap();
            assert_eq!(e.convergence, Convergence::Asymptotic, "{exact} {c} {p}");
            let order = e.order.unwrap();
            assert!((order - p).abs() < 1e-9, "p {order} vs {p}");
            assert!(
                (e.estimate - exact).abs() < 1e-12,
                "{} vs {exact}",
                e.estimate
            );
            // The uncertainty is the correction from the finest rung, times the factor: the
            // finest rung's own error is C (h/4)^p.
            let finest_error = (c * 0.25f64.powf(p)).abs();
            let u = e.uncertainty.unwrap();
            assert!((u - SAFETY_FACTOR * finest_error).abs() < 1e-12, "{u}");
        }
    }

    #[test]
    fn a_ladder_off_a_power_law_is_not_asymptotic_and_keeps_its_spread() {
        // The differences change sign.
        let e = extrapolate(&[0.01, 0.03, 0.02], None).unwrap();
        assert_eq!(e.convergence, Convergence::NotAsymptotic);
        assert_eq!(e.estimate, 0.02);
        assert!((e.uncertainty.unwrap() - 0.02).abs() < 1e-15);
        // They grow.
        let e = extrapolate(&[0.01, 0.012, 0.02], None).unwrap();
        assert_eq!(e.convergence, Convergence::NotAsymptotic);
        // They shrink too fast: p = ln(1000) / ln 2 = 10, outside the band.
        let e = extrapolate(&[1.0, 0.001, 0.000001], None).unwrap();
        assert_eq!(e.convergence, Convergence::NotAsymptotic);
        assert!(e.order.unwrap() > SANE_ORDER.1);
        // Too slowly: p = 0.2.
        let [f1, f2, f3] = manufactured(0.0, 1.0, 0.2);
        let e = extrapolate(&[f1, f2, f3], None).unwrap();
        assert_eq!(e.convergence, Convergence::NotAsymptotic);
        assert!((e.order.unwrap() - 0.2).abs() < 1e-9);
        assert!((e.uncertainty.unwrap() - (f1 - f3)).abs() < 1e-15);
    }

    #[test]
    fn two_rungs_take_the_finer_with_the_last_change_and_one_is_a_single_run() {
        let e = extrapolate(&[0.05, 0.02], Some(0.021)).unwrap();
        assert_eq!(e.convergence, Convergence::TwoRungs);
        assert_eq!(e.estimate, 0.02);
        assert!((e.uncertainty.unwrap() - 0.031).abs() < 1e-15);
        assert!((e.increment_change.unwrap() - 0.001).abs() < 1e-15);
        let e = extrapolate(&[0.05], None).unwrap();
        assert_eq!(e.convergence, Convergence::SingleRun);
        assert_eq!(e.uncertainty, None);
        assert_eq!(extrapolate(&[], None), None);
        assert_eq!(extrapolate(&[0.1, f64::NAN], None), None);
    }

    #[test]
    fn the_increment_change_adds_to_the_uncertainty() {
        let rungs = manufactured(0.01, 0.08, 2.0);
        let plain = extrapolate(&rungs, None).unwrap();
        let with = extrapolate(&rungs, Some(rungs[2] + 0.003)).unwrap();
        assert_eq!(plain.estimate, with.estimate);
        assert!((with.uncertainty.unwrap() - plain.uncertainty.unwrap() - 0.003).abs() < 1e-15);
    }

    #[test]
    fn the_verdict_weighs_the_estimate_against_bound_plus_uncertainty() {
        let at = |estimate, uncertainty| Extrapolation {
            estimate,
            uncertainty: Some(uncertainty),
            order: None,
            convergence: Convergence::Asymptotic,
            increment_change: None,
        };
        assert_eq!(judge(&at(0.012, 0.003), Some(0.01)), Verdict::Agrees);
        assert_eq!(judge(&at(-0.014, 0.003), Some(0.01)), Verdict::DoesNotAgree);
        assert_eq!(judge(&at(0.0, 0.011), Some(0.01)), Verdict::NotConverged);
        assert_eq!(judge(&at(0.0, 0.0), None), Verdict::NotJudged);
        // A manufactured ladder converging to 3 % against a 1.5 % bound does not agree, though
        // its coarse rung alone (4.6 %) and the trend say nothing of it by themselves.
        let rungs = manufactured(0.03, 0.016, 2.0);
        let e = extrapolate(&rungs, None).unwrap();
        assert_eq!(judge(&e, Some(0.015)), Verdict::DoesNotAgree);
        // A coarse ladder that is not converged: rungs 20 %, 2 %, 12 %.
        let e = extrapolate(&[0.2, 0.02, 0.12], None).unwrap();
        assert_eq!(judge(&e, Some(0.05)), Verdict::NotConverged);
        assert!(Verdict::DoesNotAgree > Verdict::NotConverged);
        assert!(Verdict::NotConverged > Verdict::Agrees);
    }
}
