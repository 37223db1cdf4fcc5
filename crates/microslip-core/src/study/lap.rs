//! Sweeps, profiles and loops of the double-lap joint: what its charts and reports show, computed
//! once here (as `curves` does for the beams and the plate).

use crate::kernel::regime::{Law, Regime};
use crate::problems::inputs::Model;
use crate::problems::lap::closed_form::{JointForce, LapJoint, LapState};
use crate::problems::lap::cycle::LapCycle;
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::{LapParam, Param, Problem};
use crate::study::curves::{
    CyclePoint, LoopPoint, RangeEnd, RangeError, Samples, Series, check_points, loop_points,
};

/// Everything the reports show about the joint at one force, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapPoint {
    /// Force through the joint F (N).
    pub force: f64,
    /// Coulomb joint displacement Delta (mm).
    pub delta_coulomb: f64,
    /// Regularized joint displacement Delta (mm).
    pub delta_regularized: f64,
    /// Coulomb sliding zones from x = 0 (a) and from x = L (d) (mm).
    pub zones_coulomb: (f64, f64),
    /// Regularized sliding zones a and d (mm).
    pub zones_regularized: (f64, f64),
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// The shear-lag envelope's bound on Delta's difference from a continuum (L14), a fraction;
    /// `None` where it is not calibrated.
    pub shear_lag_within: Option<f64>,
}

/// The joint at one force.
pub fn lap_point(joint: &LapJoint, force: JointForce) -> LapPoint {
    let (coulomb, regularized) = (joint.coulomb(force), joint.regularized(force));
    let zones = |s: &LapState| (s.slide_at_inner_end(), s.slide_at_cover_ends());
    LapPoint {
        force: force.newtons(),
        delta_coulomb: coulomb.joint_displacement(),
        delta_regularized: regularized.joint_displacement(),
        zones_coulomb: zones(&coulomb),
        zones_regularized: zones(&regularized),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        shear_lag_within: joint
            .validity_at(force, regularized.joint_displacement())
            .expected_error,
    }
}

/// Checks that every sample is a force this joint carries: in [0, F_gross].
///
/// # Errors
/// [`RangeError::Bound`] for the first end outside, with the range and why.
pub(crate) fn check_forces(joint: &LapJoint, forces: &Samples) -> Result<(), RangeError> {
    forces.check_within(Param::Lap(LapParam::Force))?;
    for (end, value) in [
        (RangeEnd::Start, forces.value(0)),
        (RangeEnd::End, forces.value(forces.len() - 1)),
    ] {
        if let Err(error) = joint.force(value) {
            return Err(RangeError::Bound {
                end,
                value,
                allowed: error.allowed(),
            });
        }
    }
    Ok(())
}

/// The joint over a range of forces: one row per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `forces` is outside [0, F_gross].
pub fn lap_force_sweep(
    joint: LapJoint,
    forces: Samples,
) -> Result<impl Iterator<Item = LapPoint>, RangeError> {
    check_forces(&joint, &forces)?;
    Ok(forces
        .values()
        .map(move |f| lap_point(&joint, joint.clamped_force(f))))
}

/// The joint over a range of any one parameter (the others, F included, as in `joint` and
/// `force`): one row per sample, the sample value first. A sample at which F exceeds that
/// sample's F_gross is refused before the first row (F = 4000 N with mu swept down to where
/// 2 b mu P L < 4000 N has no state).
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of `param`, or the
/// force is beyond an end's F_gross.
pub fn lap_param_sweep(
    joint: LapJoint,
    force: JointForce,
    param: LapParam,
    values: Samples,
) -> Result<impl Iterator<Item = (f64, LapPoint)>, RangeError> {
    let wrapped = Param::Lap(param);
    values.check_within(wrapped)?;
    if param == LapParam::Force {
        check_forces(&joint, &values)?;
    } else {
        // F_gross is monotonic in every parameter (it grows with L, b, P, mu and does not depend
        // on the others), so checking both ends checks every sample.
        for (end, value) in [
            (RangeEnd::Start, values.value(0)),
            (RangeEnd::End, values.value(values.len() - 1)),
        ] {
            let mut inputs = Model::Lap { joint, force }.inputs();
            if inputs.set(wrapped, value).is_ok()
                && let Err(error) = inputs.validate()
            {
                return Err(RangeError::Bound {
                    end,
                    value,
                    allowed: format!("at {param} = {value}, {error}"),
                });
            }
        }
    }
    let model = LapModel { joint, force };
    Ok(values.values().map(move |v| {
        let at = LapJointProblem::with_clamped(&model, param, v);
        (v, lap_point(&at.joint, at.force))
    }))
}

/// Delta (mm) against F (N): (Coulomb, regularized).
///
/// # Errors
/// As [`lap_force_sweep`].
pub fn lap_displacement_vs_force(
    joint: &LapJoint,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(lap_force_sweep(*joint, forces)?
        .map(|p| ((p.force, p.delta_coulomb), (p.force, p.delta_regularized)))
        .unzip())
}

/// The middle zone's edges against F, one closed outline per law: x = a (mm) from F = 0 up to
/// the last force, then x = L - d back down to F = 0. The two meet where a + d = L (F_gross), so
/// the outline encloses the zone that sticks (Coulomb) or slips elastically (regularized), and
/// the sliding zones lie outside it: (Coulomb, regularized).
///
/// # Errors
/// As [`lap_force_sweep`].
pub fn lap_zone_outline_vs_force(
    joint: &LapJoint,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    let length = joint.params().length;
    let rows: Vec<LapPoint> = lap_force_sweep(*joint, forces)?.collect();
    let outline = |zones: fn(&LapPoint) -> (f64, f64)| -> Series {
        let up = rows.iter().map(|p| (p.force, zones(p).0));
        let down = rows.iter().rev().map(|p| (p.force, length - zones(p).1));
        up.chain(down).collect()
    };
    Ok((
        outline(|p| p.zones_coulomb),
        outline(|p| p.zones_regularized),
    ))
}

/// Interface shear tau (MPa) on the inner plate along the overlap at one force: (Coulomb,
/// regularized).
pub fn lap_shear_along(
    joint: &LapJoint,
    force: JointForce,
    positions: Samples,
) -> (Series, Series) {
    along(joint, force, positions, LapState::shear_at)
}

/// Interface slip s(x) = u_inner - u_cover (mm) along the overlap at one force: (Coulomb,
/// regularized).
pub fn lap_slip_along(joint: &LapJoint, force: JointForce, positions: Samples) -> (Series, Series) {
    along(joint, force, positions, LapState::slip_at)
}

/// A profile `at` of both laws' states at `force`, sampled at `positions`: (Coulomb, regularized).
fn along(
    joint: &LapJoint,
    force: JointForce,
    positions: Samples,
    at: fn(&LapState, f64) -> f64,
) -> (Series, Series) {
    let (coulomb, regularized) = (joint.coulomb(force), joint.regularized(force));
    positions
        .values()
        .map(|x| ((x, at(&coulomb, x)), (x, at(&regularized, x))))
        .unzip()
}

/// The joint cycled at one amplitude.
pub fn lap_cycle_point(joint: &LapJoint, amplitude: JointForce) -> CyclePoint {
    let (c, r) = (
        LapCycle::new(joint, Law::Coulomb, amplitude),
        LapCycle::new(joint, Law::Regularized, amplitude),
    );
    CyclePoint {
        amplitude: amplitude.newtons(),
        d_coulomb: c.dissipation(),
        d_regularized: r.dissipation(),
        zeta_coulomb: c.damping_ratio(),
        zeta_regularized: r.damping_ratio(),
    }
}

/// The joint cycled over a range of amplitudes in [0, F_gross]: one row per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `amplitudes` is outside [0, F_gross].
pub fn lap_cycle_sweep(
    joint: LapJoint,
    amplitudes: Samples,
) -> Result<impl Iterator<Item = CyclePoint>, RangeError> {
    check_forces(&joint, &amplitudes)?;
    Ok(amplitudes
        .values()
        .map(move |f| lap_cycle_point(&joint, joint.clamped_force(f))))
}

/// The closed hysteresis loop of Delta at `amplitude`: `points` evenly spaced forces per branch,
/// both ends included; the loop point's `w_*` fields hold Delta (mm).
///
/// # Errors
/// [`RangeError::Points`] outside 2 to [`crate::study::curves::MAX_POINTS`].
pub fn lap_cycle_loop(
    joint: &LapJoint,
    amplitude: JointForce,
    points: u64,
) -> Result<impl Iterator<Item = LoopPoint>, RangeError> {
    let points = check_points(points)?;
    let (coulomb, regularized) = (
        LapCycle::new(joint, Law::Coulomb, amplitude),
        LapCycle::new(joint, Law::Regularized, amplitude),
    );
    Ok(loop_points(
        amplitude.newtons(),
        points,
        move |f| (coulomb.unloading(f), regularized.unloading(f)),
        move |f| (coulomb.reloading(f), regularized.reloading(f)),
    ))
}

/// Dissipation per cycle D (N mm) against F_a (N): (Coulomb, regularized).
///
/// # Errors
/// As [`lap_cycle_sweep`].
pub fn lap_dissipation_vs_amplitude(
    joint: &LapJoint,
    amplitudes: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(lap_cycle_sweep(*joint, amplitudes)?
        .map(|p| ((p.amplitude, p.d_coulomb), (p.amplitude, p.d_regularized)))
        .unzip())
}
