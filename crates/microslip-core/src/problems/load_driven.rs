//! The capability of a **load-driven** problem: a linear elastic structure held together by a
//! frictional interface under a constant normal pressure P, loaded by one scalar force F that can
//! grow from zero and cycle between +F_a and -F_a (the twin beams' tip force, the lap joint's force
//! through the joint). Its answer at a force is one displacement, the *response* u(F) (w(L) of the
//! beams, Delta of the joint), under plain Coulomb and under the regularized law
//! (tau = K_T s up to mu P).
//!
//! What makes such a problem load-driven, and what the generic studies over it
//! ([`crate::study::load`]: sweeps against F, the K_T tolerance, loops and dissipation) rely on:
//!
//! - **A force axis with a scale.** F lives in [0, F_max] ([`LoadDriven::force`] checks it, F_max
//!   is the parameter's domain or the joint's F_gross), and one force of the structure sets the
//!   regime scale ([`LoadDriven::force_scale`]: F_thre of the beams, F_gross of the joint) that
//!   the charts' force axes are measured against. It is the number [`Problem::regime_scale`]
//!   gives for every model of the structure (whatever its force): that one is `Option`al
//!   because a problem without a load has none, and a load-driven problem writes it as
//!   `Some(force_scale)`.
//! - **Monotonic first loading.** The response grows with F, and at a fixed F it does not increase
//!   with K_T (docs/theory.md (T1), (L11)): the deviation from Coulomb is then non-increasing in
//!   K_T, which is what makes the smallest K_T within a tolerance one bracketed root.
//! - **Masing's rule.** The structure is linear, mu P does not change with the load, every interface
//!   point's shear grows monotonically on first loading and a point elastic at the turning point
//!   stays elastic over the reversal (docs/theory.md (C1), (L9)). Then, with u_v the virgin
//!   (first-loading) curve extended as an odd function and u_a = u_v(F_a), the cycle between +F_a
//!   and -F_a is
//!
//! ```text
//! unloading from +F_a:  u(F) = u_a - 2 u_v((F_a - F) / 2)
//! reloading from -F_a:  u(F) = -u_a + 2 u_v((F_a + F) / 2)
//! D   = the area of the loop, the friction work of the plastic slip at +F_a (C3), (L10)
//! zeta = D / (4 pi U),  U = the peak elastic energy of the loading (secant definition)
//! ```
//!
//! [`MasingCycle`] writes the branches and zeta once from u_v, u_a and D; each problem gives its
//! virgin curve, its D (a closed form of its own) and its U (the beams count both tip forces).
//!
//! A problem is load-driven by implementing [`LoadDriven`] on its [`Problem`] type in its own
//! folder (`problems/<name>/load_driven.rs`); every study, chart and report of a load-driven
//! feature is then written once, generic over it.
//!
//! # Structure and model
//! [`Problem::Model`] is the validated structure *at its force* (what one solve answers);
//! the studies here vary the force themselves (sweeps, cycles, the tolerance's grid of forces),
//! so they take [`LoadDriven::Structure`], the validated structure without it, and a
//! [`LoadDriven::Force`] checked against it. [`LoadDriven::structure`] and
//! [`LoadDriven::applied_force`] split a model into the two.

use crate::kernel::params::ParamError;
use crate::kernel::regime::Law;
use crate::problems::Param;
use crate::problems::Problem;
use crate::problems::inputs::Model;
use crate::problems::problem::Registered;

/// What the generic load-driven studies need of a problem: its force, its response under both
/// laws, its regime scale, its cycle and its interface (see the module docs for the physics).
/// A capability of a [`Problem`] (implemented on the problem's own type); which problem it is
/// comes from the registry ([`Registered::KIND`]).
pub trait LoadDriven: Problem + Registered {
    /// The structure without its force, valid by construction (built by the problem's checked
    /// constructor): what the studies vary the force on (module docs).
    type Structure: Copy;
    /// A force the structure carries, checked against its range (N).
    type Force: Copy;
    /// One law's cycle between +F_a and -F_a.
    type Cycle: MasingCycle + Copy;
    /// Everything the reports show at one force, for both laws.
    type Point;

    /// The load parameter F: its name, unit and domain.
    const FORCE: Param;
    /// The interface stiffness K_T (MPa/mm): its domain is where the tolerance searches.
    const STIFFNESS: Param;

    /// The structure of `model`, without its force.
    fn structure(model: &Self::Model) -> Self::Structure;
    /// The force `model` is at.
    fn applied_force(model: &Self::Model) -> Self::Force;
    /// The model of `structure` at `force`: the inverse of [`LoadDriven::structure`] and
    /// [`LoadDriven::applied_force`].
    fn at_force(structure: &Self::Structure, force: Self::Force) -> Self::Model;

    /// Accepts `newtons` as a force this structure carries.
    ///
    /// # Errors
    /// [`ParamError`] naming F, its value and the allowed range (and why, where the structure
    /// bounds it: the joint's F_gross).
    fn force(structure: &Self::Structure, newtons: f64) -> Result<Self::Force, ParamError>;
    /// The accepted force nearest to `newtons` (0 for negative values and NaN).
    fn clamped_force(structure: &Self::Structure, newtons: f64) -> Self::Force;
    /// The load in its unit (N for a force, N/mm for the cylinder's line load).
    fn load_value(force: Self::Force) -> f64;
    /// The force that sets the regime scale of `structure` (N): F_thre of the beams, F_gross of
    /// the joint. [`Problem::regime_scale`] of any model of it is `Some` of this (module docs).
    fn force_scale(structure: &Self::Structure) -> f64;
    /// The forces (N) at which the regime of first loading changes (F_thre; F_1 and F_2 of the
    /// joint): where a search over forces must look besides its even samples.
    fn regime_changes(structure: &Self::Structure) -> Vec<f64>;

    /// The response u(F) (mm) at `force` under `law`: w(L) of the beams, Delta of the joint.
    fn response(structure: &Self::Structure, law: Law, force: Self::Force) -> f64;
    /// Everything the reports show at `force`, both laws.
    fn point(structure: &Self::Structure, force: Self::Force) -> Self::Point;
    /// The stretch of interface that does not slide at `force` under `law`, `[from, to]` (mm
    /// along the interface): the stick (Coulomb) or elastic-slip (regularized) zone, whose edges
    /// are the zone boundaries the charts draw against F.
    fn holding_zone(structure: &Self::Structure, law: Law, force: Self::Force) -> [f64; 2];
    /// The cycle between +`amplitude` and -`amplitude` under `law`.
    fn cycle(structure: &Self::Structure, law: Law, amplitude: Self::Force) -> Self::Cycle;

    /// The interface stiffness K_T (MPa/mm).
    fn tangential_stiffness(structure: &Self::Structure) -> f64;
    /// The same structure with K_T = `kt` (MPa/mm), all else equal.
    ///
    /// # Errors
    /// [`ParamError`] for a K_T outside its domain.
    fn with_tangential_stiffness(
        structure: &Self::Structure,
        kt: f64,
    ) -> Result<Self::Structure, ParamError>;
    /// The interface strength mu P (MPa): the FE codes' elastic-slip settings scale with it.
    fn interface_strength(structure: &Self::Structure) -> f64;
    /// The Young's modulus (MPa) the FE codes' default penalties scale with (the beams' E, the
    /// joint's inner plate E1).
    fn modulus(structure: &Self::Structure) -> f64;
    /// Forces (N) besides the even samples and the regime changes at which the deviation from
    /// Coulomb must be checked over `[from, to]`: the joint's limit at zero (its regularized
    /// Delta is elastic, Coulomb's bonded, and their ratio is largest there); none for the beams,
    /// whose deviation is flat below F_thre.
    fn deviation_probes(_structure: &Self::Structure, [_from, _to]: [f64; 2]) -> Vec<f64> {
        Vec::new()
    }
    /// Why the regularized response over Coulomb's grows without bound as the load falls to 0
    /// at every finite K_T, if it does (then no K_T keeps it within a tolerance over a range
    /// from 0, and a K_T search must say so rather than sample its way to a finite answer);
    /// `None` where the ratio has a finite limit (the beams, the joint).
    fn unbounded_at_zero(_structure: &Self::Structure) -> Option<&'static str> {
        None
    }
}

/// The [`LoadDriven`] capability of a problem, erased: what code written for any problem asks
/// of one it holds as `&'static dyn` [`AnyProblem`](crate::problems::AnyProblem), through
/// its [`ProblemFaces::load_driven`](crate::problems::problem::ProblemFaces::load_driven) (`None`: the problem is
/// not load-driven), instead of a `match` on its kind. Forces are plain newtons and models the
/// [`Model`] enum; every method answers `None` for another problem's model.
///
/// # Examples
/// ```
/// use microslip_core::kernel::regime::Law;
/// use microslip_core::problems::ModelKind;
/// use microslip_core::problems::inputs::Inputs;
/// for kind in ModelKind::ALL {
///     let model = Inputs::paper(kind).validate()?;
///     // Exactly the problems with a load are load-driven (the plate is loaded by its pressure).
///     let Some(load_driven) = kind.problem().faces().load_driven else {
///         assert!(kind.description().load.is_none(), "{kind}");
///         continue;
///     };
///     let force = load_driven.applied_force(&model).unwrap();
///     let scale = load_driven.force_scale(&model).unwrap();
///     assert!(force > 0.0 && scale > 0.0, "{kind}");
///     // At twice its scale, the lap joint carries no force (no state beyond F_gross).
///     let beyond = load_driven.response(&model, Law::Coulomb, 2.0 * scale).unwrap();
///     assert_eq!(beyond.is_ok(), kind == ModelKind::Beam, "{kind}");
/// }
/// # Ok::<(), microslip_core::kernel::params::ParamError>(())
/// ```
pub trait AnyLoadDriven: Send + Sync {
    /// The load parameter F ([`LoadDriven::FORCE`]).
    fn force_param(&self) -> Param;
    /// The interface stiffness K_T ([`LoadDriven::STIFFNESS`]).
    fn stiffness_param(&self) -> Param;
    /// The force `model` is at (N) ([`LoadDriven::applied_force`]).
    fn applied_force(&self, model: &Model) -> Option<f64>;
    /// The regime scale of `model`'s structure (N) ([`LoadDriven::force_scale`]).
    fn force_scale(&self, model: &Model) -> Option<f64>;
    /// The forces (N) at which the regime of first loading of `model`'s structure changes
    /// ([`LoadDriven::regime_changes`]).
    fn regime_changes(&self, model: &Model) -> Option<Vec<f64>>;
    /// The response (mm) of `model`'s structure at `newtons` under `law`
    /// ([`LoadDriven::response`]); `Err` for a force the structure does not carry
    /// ([`LoadDriven::force`]).
    fn response(&self, model: &Model, law: Law, newtons: f64) -> Option<Result<f64, ParamError>>;
}

/// The [`AnyLoadDriven`] of a [`LoadDriven`] problem `P`: what its
/// [`Problem::FACES`] holds.
#[derive(Debug)]
pub struct LoadDrivenOf<P>(std::marker::PhantomData<P>);

impl<P> LoadDrivenOf<P> {
    /// The erased load-driven capability of `P`.
    pub const NEW: LoadDrivenOf<P> = LoadDrivenOf(std::marker::PhantomData);
}

impl<P: LoadDriven> AnyLoadDriven for LoadDrivenOf<P> {
    fn force_param(&self) -> Param {
        P::FORCE
    }

    fn stiffness_param(&self) -> Param {
        P::STIFFNESS
    }

    fn applied_force(&self, model: &Model) -> Option<f64> {
        Some(P::load_value(P::applied_force(&P::from_model(model)?)))
    }

    fn force_scale(&self, model: &Model) -> Option<f64> {
        Some(P::force_scale(&P::structure(&P::from_model(model)?)))
    }

    fn regime_changes(&self, model: &Model) -> Option<Vec<f64>> {
        Some(P::regime_changes(&P::structure(&P::from_model(model)?)))
    }

    fn response(&self, model: &Model, law: Law, newtons: f64) -> Option<Result<f64, ParamError>> {
        let structure = P::structure(&P::from_model(model)?);
        Some(P::force(&structure, newtons).map(|force| P::response(&structure, law, force)))
    }
}

/// One law's cycle between +F_a and -F_a under Masing's rule (module docs): the branches and the
/// damping ratio come from the virgin curve, the peak and D, written once here.
pub trait MasingCycle {
    /// The amplitude F_a (N).
    fn amplitude(&self) -> f64;
    /// Where sliding starts on first loading (N).
    fn onset(&self) -> f64;
    /// The virgin curve u_v(F) (mm), odd in F.
    fn virgin(&self, force: f64) -> f64;
    /// The peak response u_a = u_v(F_a) (mm).
    fn peak_response(&self) -> f64;
    /// Energy dissipated per cycle D (N mm).
    fn dissipation(&self) -> f64;
    /// Peak elastic energy U (N mm), the secant definition.
    fn peak_energy(&self) -> f64;
    /// Secant stiffness F_a / u_a (N/mm), the initial slope at zero amplitude.
    fn secant_stiffness(&self) -> f64;

    /// Unloading branch from (F_a, u_a) down to -F_a (mm): u_a - 2 u_v((F_a - F) / 2).
    fn unloading(&self, force: f64) -> f64 {
        self.peak_response() - 2.0 * self.virgin(0.5 * (self.amplitude() - force))
    }

    /// Reloading branch from (-F_a, -u_a) up to F_a (mm): -u_a + 2 u_v((F_a + F) / 2).
    fn reloading(&self, force: f64) -> f64 {
        -self.peak_response() + 2.0 * self.virgin(0.5 * (self.amplitude() + force))
    }

    /// Equivalent viscous damping ratio D / (4 pi U) (-); 0 at zero amplitude.
    fn damping_ratio(&self) -> f64 {
        let u = self.peak_energy();
        if u > 0.0 {
            self.dissipation() / (4.0 * std::f64::consts::PI * u)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::ModelKind;
    use crate::problems::inputs::Inputs;

    /// The erased capability is found exactly for the problems with a load, names their own F
    /// and K_T, and answers as the typed paths at the bundled data: the force the model is at,
    /// its regime scale (bit for bit [`Problem::regime_scale`]), the responses of one solve,
    /// regime changes inside (0, scale]; another problem's model gets `None`.
    #[test]
    fn the_erased_capability_is_found_for_the_loaded_problems_and_answers_as_typed() {
        let mut found = Vec::new();
        for kind in ModelKind::ALL {
            let problem = kind.problem();
            let Some(load_driven) = problem.faces().load_driven else {
                assert_eq!(kind.description().load, None, "{kind}");
                continue;
            };
            found.push(kind);
            assert_eq!(Some(load_driven.force_param()), kind.description().load);
            let stiffness = load_driven.stiffness_param();
            assert!(
                stiffness.is_stiffness() && stiffness.model() == kind,
                "{kind}"
            );

            let inputs = Inputs::paper(kind);
            let model = inputs.validate().unwrap();
            let force = load_driven.applied_force(&model).unwrap();
            assert_eq!(Some(force), inputs.get(load_driven.force_param()), "{kind}");
            let scale = load_driven.force_scale(&model).unwrap();
            assert_eq!(
                Some(scale.to_bits()),
                model.regime_scale().map(f64::to_bits)
            );
            let changes = load_driven.regime_changes(&model).unwrap();
            assert!(!changes.is_empty(), "{kind}");
            assert!(changes.iter().all(|&f| f > 0.0 && f <= scale), "{kind}");

            let answers = problem.answers(&problem.paper_values()).unwrap();
            for (law, answer) in [
                (Law::Coulomb, answers.coulomb),
                (Law::Regularized, answers.regularized),
            ] {
                let response = load_driven.response(&model, law, force).unwrap().unwrap();
                assert_eq!(
                    response.to_bits(),
                    answer.response.to_bits(),
                    "{kind} {law:?}"
                );
            }
            // A force refused by the checked constructor is refused here too, naming the load
            // (F, or the cylinder's Q).
            let refused = load_driven.response(&model, Law::Coulomb, -1.0).unwrap();
            let message = refused.unwrap_err().to_string();
            let load = load_driven.force_param().spec().name;
            assert!(
                message.starts_with(&format!("invalid {load} = -1")),
                "{message}"
            );

            for other in ModelKind::ALL.into_iter().filter(|&o| o != kind) {
                let theirs = Inputs::paper(other).validate().unwrap();
                assert_eq!(load_driven.applied_force(&theirs), None, "{kind} {other}");
                assert_eq!(load_driven.force_scale(&theirs), None, "{kind} {other}");
                assert!(load_driven.regime_changes(&theirs).is_none());
                assert!(load_driven.response(&theirs, Law::Coulomb, 1.0).is_none());
            }
        }
        // Both branches ran: the registry has load-driven problems and one without a load (the
        // loop above ties each to its description's load, so no list of names is needed).
        assert!(
            found.len() > 1 && found.len() < ModelKind::COUNT,
            "{found:?}"
        );
    }
}
