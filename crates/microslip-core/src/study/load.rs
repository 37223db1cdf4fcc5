//! Every load-driven study written once, generic over [`LoadDriven`]: the response and the
//! sliding zones against the force, the cycle at an amplitude (dissipation D, damping ratio zeta)
//! and over a range of amplitudes, and the closed hysteresis loop. The twin beams and the lap
//! joint take their sweeps, loops and D vs F_a from here; the CLI's CSV rows, the reports and
//! the charts from the same functions. Each walks a family of loads, so each runs in one
//! [`family::scope`] (a lazy sweep's rows in one [`family::iter`]): solvers that can continue
//! from the previous point do (the cylinder, issue 47), within the study and nowhere else.

use crate::kernel::family;
use crate::kernel::regime::Law;
use crate::problems::load_driven::{LoadDriven, MasingCycle};
use crate::study::samples::{RangeEnd, RangeError, Samples, Series, check_points};

/// Checks that every sample is a force `model` carries: both ends are accepted values of the
/// load parameter and forces of this structure (the joint's F_gross bounds them; the samples
/// lie between the ends and the range is an interval).
///
/// # Errors
/// [`RangeError::Bound`] for the first end outside, with the range and why.
pub fn check_forces<P: LoadDriven>(
    model: &P::Structure,
    forces: &Samples,
) -> Result<(), RangeError> {
    forces.check_within(P::FORCE)?;
    for (end, value) in [
        (RangeEnd::Start, forces.value(0)),
        (RangeEnd::End, forces.value(forces.len() - 1)),
    ] {
        if let Err(error) = P::force(model, value) {
            return Err(RangeError::Bound {
                end,
                value,
                allowed: error.allowed(),
            });
        }
    }
    Ok(())
}

/// `model` over a range of forces: one row ([`LoadDriven::Point`]) per sample, every one computed
/// at the force asked for.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `forces` is not a force `model` carries.
pub fn force_sweep<P: LoadDriven>(
    model: P::Structure,
    forces: Samples,
) -> Result<impl Iterator<Item = P::Point>, RangeError> {
    check_forces::<P>(&model, &forces)?;
    // Every sample is accepted, so clamping changes nothing.
    Ok(family::iter(forces.values().map(move |f| {
        P::point(&model, P::clamped_force(&model, f))
    })))
}

/// The response u (mm) against F (N): (Coulomb, regularized). The chart "w(L) vs F" of the
/// beams, "Delta vs F" of the joint.
///
/// # Errors
/// As [`force_sweep`].
pub fn response_vs_force<P: LoadDriven>(
    model: &P::Structure,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    check_forces::<P>(model, &forces)?;
    Ok(family::scope(|| {
        forces
            .values()
            .map(|f| {
                let force = P::clamped_force(model, f);
                let at = |law| (f, P::response(model, law, force));
                (at(Law::Coulomb), at(Law::Regularized))
            })
            .unzip()
    }))
}

/// The edges of the zone that does not slide ([`LoadDriven::holding_zone`]) under `law` against
/// F (N): one `[from, to]` (mm) per sample.
///
/// # Errors
/// As [`force_sweep`].
pub fn holding_zone_vs_force<P: LoadDriven>(
    model: &P::Structure,
    law: Law,
    forces: Samples,
) -> Result<Vec<(f64, [f64; 2])>, RangeError> {
    check_forces::<P>(model, &forces)?;
    Ok(family::scope(|| {
        forces
            .values()
            .map(|f| (f, P::holding_zone(model, law, P::clamped_force(model, f))))
            .collect()
    }))
}

/// One cyclic amplitude, both laws: dissipation per cycle (N mm) and equivalent damping ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CyclePoint {
    /// Amplitude F_a (N).
    pub amplitude: f64,
    /// Coulomb dissipation per cycle (N mm).
    pub d_coulomb: f64,
    /// Regularized dissipation per cycle (N mm).
    pub d_regularized: f64,
    /// Coulomb D / (4 pi U).
    pub zeta_coulomb: f64,
    /// Regularized D / (4 pi U).
    pub zeta_regularized: f64,
}

/// `model` cycled at one amplitude, both laws.
pub fn cycle_point<P: LoadDriven>(model: &P::Structure, amplitude: P::Force) -> CyclePoint {
    family::scope(|| cycle_point_in_scope::<P>(model, amplitude))
}

/// [`cycle_point`] in its caller's scope.
fn cycle_point_in_scope<P: LoadDriven>(model: &P::Structure, amplitude: P::Force) -> CyclePoint {
    let (c, r) = (
        P::cycle(model, Law::Coulomb, amplitude),
        P::cycle(model, Law::Regularized, amplitude),
    );
    CyclePoint {
        amplitude: P::load_value(amplitude),
        d_coulomb: c.dissipation(),
        d_regularized: r.dissipation(),
        zeta_coulomb: c.damping_ratio(),
        zeta_regularized: r.damping_ratio(),
    }
}

/// `model` cycled over a range of amplitudes (forces it carries): one row per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `amplitudes` is not a force `model` carries.
pub fn cycle_sweep<P: LoadDriven>(
    model: P::Structure,
    amplitudes: Samples,
) -> Result<impl Iterator<Item = CyclePoint>, RangeError> {
    check_forces::<P>(&model, &amplitudes)?;
    Ok(family::iter(amplitudes.values().map(move |f| {
        cycle_point_in_scope::<P>(&model, P::clamped_force(&model, f))
    })))
}

/// Dissipation per cycle D (N mm) against F_a (N): (Coulomb, regularized).
///
/// # Errors
/// As [`cycle_sweep`].
pub fn dissipation_vs_amplitude<P: LoadDriven>(
    model: &P::Structure,
    amplitudes: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(cycle_sweep::<P>(*model, amplitudes)?
        .map(|p| ((p.amplitude, p.d_coulomb), (p.amplitude, p.d_regularized)))
        .unzip())
}

/// A branch of the hysteresis loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Branch {
    /// From +F_a down to -F_a.
    Unloading,
    /// From -F_a back up to +F_a.
    Reloading,
}

impl Branch {
    /// `unloading` or `reloading`, as the CSV column says it.
    pub fn label(self) -> &'static str {
        match self {
            Branch::Unloading => "unloading",
            Branch::Reloading => "reloading",
        }
    }
}

/// One point of the hysteresis loop, both laws; the `w_*` fields hold the problem's response
/// (the beams' tip deflection w(L), the joint's Delta).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopPoint {
    /// The branch.
    pub branch: Branch,
    /// Force F (N).
    pub force: f64,
    /// Coulomb response (mm).
    pub w_coulomb: f64,
    /// Regularized response (mm).
    pub w_regularized: f64,
}

/// The closed hysteresis loop of a cycle at `amplitude`: `points` evenly spaced forces per
/// branch, both ends included (so the turning point at -F_a ends one branch and starts the next).
///
/// # Errors
/// [`RangeError::Points`] outside 2 to [`crate::study::samples::MAX_POINTS`].
pub fn cycle_loop<P: LoadDriven>(
    model: &P::Structure,
    amplitude: P::Force,
    points: u64,
) -> Result<impl Iterator<Item = LoopPoint> + use<P>, RangeError> {
    let points = check_points(points)?;
    let (coulomb, regularized) = (
        P::cycle(model, Law::Coulomb, amplitude),
        P::cycle(model, Law::Regularized, amplitude),
    );
    let fa = P::load_value(amplitude);
    let last = (points - 1) as f64;
    let branch = move |branch: Branch| {
        (0..points).map(move |i| {
            let t = 2.0 * fa * i as f64 / last;
            let (force, (w_coulomb, w_regularized)) = match branch {
                Branch::Unloading => (
                    fa - t,
                    (coulomb.unloading(fa - t), regularized.unloading(fa - t)),
                ),
                Branch::Reloading => (
                    t - fa,
                    (coulomb.reloading(t - fa), regularized.reloading(t - fa)),
                ),
            };
            LoopPoint {
                branch,
                force,
                w_coulomb,
                w_regularized,
            }
        })
    };
    Ok(family::iter(
        branch(Branch::Unloading).chain(branch(Branch::Reloading)),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::cylinder::point::CylinderPoint;
    use crate::problems::cylinder::{Cylinder, CylinderParams, CylinderProblem};
    use crate::problems::lap::LapJointProblem;
    use crate::problems::lap::closed_form::{LapJoint, LapParams};
    use crate::problems::twin_beams::TwinBeamsProblem;
    use crate::study::samples::Spacing;
    use crate::{TipForce, TwinBeams, TwinBeamsParams};

    #[test]
    fn the_loop_closes_and_its_branches_meet_at_the_turning_points() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let amplitude = TipForce::new(150.0).unwrap();
        let points: Vec<LoopPoint> = cycle_loop::<TwinBeamsProblem>(&beams, amplitude, 11)
            .unwrap()
            .collect();
        assert_eq!(points.len(), 22);
        let (first, turn, restart, last) = (points[0], points[10], points[11], points[21]);
        assert_eq!((first.force, turn.force), (150.0, -150.0));
        assert_eq!((restart.force, last.force), (-150.0, 150.0));
        assert_eq!(turn.branch, Branch::Unloading);
        assert_eq!(restart.branch, Branch::Reloading);
        for (a, b) in [(first, last), (turn, restart)] {
            assert!((a.w_coulomb - b.w_coulomb).abs() <= 1e-12 * a.w_coulomb.abs());
            assert!((a.w_regularized - b.w_regularized).abs() <= 1e-12 * a.w_regularized.abs());
        }
        assert!(cycle_loop::<TwinBeamsProblem>(&beams, amplitude, 1).is_err());
    }

    /// The generic sweep refuses what each problem refuses: the joint carries no force beyond
    /// F_gross (its own bound, said with its reason), the beams any force of their domain.
    #[test]
    fn a_force_sweep_refuses_what_the_problem_does_not_carry() {
        let joint = LapJoint::new(LapParams::ALUMINIUM).unwrap();
        let gross = joint.gross_slip_force();
        let beyond =
            Samples::new(0.0, 1.5 * gross, 3, crate::study::samples::Spacing::Linear).unwrap();
        let Err(RangeError::Bound { end, allowed, .. }) =
            force_sweep::<LapJointProblem>(joint, beyond)
        else {
            panic!("a force beyond F_gross was swept");
        };
        assert_eq!(end, RangeEnd::End);
        assert!(allowed.contains("F_gross"), "{allowed}");
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        assert_eq!(
            force_sweep::<TwinBeamsProblem>(beams, beyond)
                .unwrap()
                .count(),
            3
        );
    }

    /// Both laws' holding zones of the joint shrink from both ends as F grows, and sit inside the
    /// overlap; the beams' starts at the clamp.
    #[test]
    fn holding_zones_lie_on_the_interface() {
        let joint = LapJoint::new(LapParams::ALUMINIUM).unwrap();
        let length = joint.params().length;
        let forces = Samples::new(
            0.0,
            0.9 * joint.gross_slip_force(),
            9,
            crate::study::samples::Spacing::Linear,
        )
        .unwrap();
        for law in [Law::Coulomb, Law::Regularized] {
            let zones = holding_zone_vs_force::<LapJointProblem>(&joint, law, forces).unwrap();
            for pair in zones.windows(2) {
                let ([a0, b0], [a1, b1]) = (pair[0].1, pair[1].1);
                assert!(
                    0.0 <= a0 && a0 <= a1 && b1 <= b0 && b0 <= length,
                    "{pair:?}"
                );
            }
        }
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let zone =
            TwinBeamsProblem::holding_zone(&beams, Law::Regularized, TipForce::new(100.0).unwrap());
        assert_eq!(zone[0], 0.0);
        assert!(zone[1] > 0.0 && zone[1] < beams.params().length, "{zone:?}");
    }

    /// The bundled pad's Q sweep from 0 to mu P in `points` rows ([`force_sweep`], what `sweep`
    /// writes), its rows solved in the sweep's own family scope.
    fn pad_sweep(pad: Cylinder, points: u64) -> Vec<CylinderPoint> {
        let loads = Samples::new(0.0, pad.gross_slip_load(), points, Spacing::Linear).unwrap();
        force_sweep::<CylinderProblem>(pad, loads)
            .unwrap()
            .collect()
    }

    /// A sweep continues along its family inside its own scope (issue 47), and nowhere else: the
    /// same sweep twice gives the same bits; each row is the cold solve's (the same sweep in
    /// [`family::cold`]) to 1e-9 in what `sweep` prints; and a plain solve after it, at one of its
    /// loads, is the cold solve of a thread that never swept, bit for bit.
    #[test]
    fn a_sweep_is_its_own_and_a_plain_solve_stays_cold() {
        let pad = Cylinder::new(CylinderParams::STEEL_PAD).unwrap();
        let load = pad.load(0.5 * pad.gross_slip_load()).unwrap();
        let fresh = std::thread::spawn(move || pad.regularized(load))
            .join()
            .unwrap();
        let first = pad_sweep(pad, 401);
        assert_eq!(first[200].load, load.newtons_per_mm());
        assert_eq!(pad.regularized(load), fresh);
        assert_eq!(pad_sweep(pad, 401), first);
        assert_eq!(pad.regularized(load), fresh);
        let cold = family::cold(|| pad_sweep(pad, 401));
        for (warm, cold) in first.iter().zip(&cold) {
            for (w, c) in [
                (warm.edge_slip_regularized, cold.edge_slip_regularized),
                (warm.centre_slip_regularized, cold.centre_slip_regularized),
                (warm.zone_regularized, cold.zone_regularized),
                (warm.peak_shear_regularized, cold.peak_shear_regularized),
            ] {
                assert!(
                    (w - c).abs() <= 1e-9 * c.abs(),
                    "Q {}: {w:e} {c:e}",
                    warm.load
                );
            }
        }
        // The sweep did continue: its row at the plain load is not the cold solve's bits.
        assert_ne!(first[200], cold[200]);
    }
}
