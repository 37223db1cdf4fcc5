//! Sweeps over any parameter and profiles along the overlap of the double-lap joint: what its
//! charts and reports show besides the load-driven studies, which are written once in
//! [`crate::study::load`].

use crate::kernel::regime::Law;
use crate::problems::inputs::Model;
use crate::problems::lap::closed_form::{JointForce, LapJoint, LapState};
use crate::problems::lap::problem::{LapJointProblem, LapModel};
use crate::problems::{LapParam, Param, Problem};
use crate::study::load::{self, check_forces};
use crate::study::samples::{RangeEnd, RangeError, Samples, Series};

pub use crate::problems::lap::load_driven::{LapPoint, lap_point};

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
        check_forces::<LapJointProblem>(&joint, &values)?;
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

/// The middle zone's edges against F, one closed outline per law: x = a (mm) from F = 0 up to
/// the last force, then x = L - d back down to F = 0 (the edges of the joint's holding zone,
/// [`load::holding_zone_vs_force`]). The two meet where a + d = L (F_gross), so the outline
/// encloses the zone that sticks (Coulomb) or slips elastically (regularized), and the sliding
/// zones lie outside it: (Coulomb, regularized).
///
/// # Errors
/// As [`load::force_sweep`].
pub fn lap_zone_outline_vs_force(
    joint: &LapJoint,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    let outline = |law: Law| -> Result<Series, RangeError> {
        let rows = load::holding_zone_vs_force::<LapJointProblem>(joint, law, forces)?;
        let up = rows.iter().map(|&(f, [a, _])| (f, a));
        let down = rows.iter().rev().map(|&(f, [_, far])| (f, far));
        Ok(up.chain(down).collect())
    };
    Ok((outline(Law::Coulomb)?, outline(Law::Regularized)?))
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
