//! The lap joint's fit: Delta against the force through the joint (docs/theory.md (L11) and
//! section 3b). The joint carries no force beyond F_gross = 2 b mu P L, so mu is searched only
//! where it carries every measured force.

use super::{FitError, MU_RANGE, Measurement};
use crate::problems::lap::closed_form::{LapJoint, LapParams};

/// The mu range to search for the joint `p` with the trial (`mu`, `kt`) (fixed values, else the
/// joint's own): [`MU_RANGE`] from above the smallest mu that carries every measured force (a
/// fit on that bound is reported as at the search bound).
///
/// # Errors
/// The joint at (`mu`, `kt`) is invalid; a `fixed_mu` does not carry the largest measured
/// force; or no mu searched carries it ([`FitError::BeyondGrossSlip`]).
pub(super) fn mu_range(
    p: LapParams,
    (mu, kt): (f64, f64),
    fixed_mu: bool,
    data: &[Measurement],
) -> Result<(f64, f64), FitError> {
    let joint = LapJoint::new(LapParams {
        friction: mu,
        tangential_stiffness: kt,
        ..p
    })?;
    let Some(largest) = data.iter().map(|m| m.force).reduce(f64::max) else {
        return Ok(MU_RANGE);
    };
    // A fixed mu must carry every measured force.
    if fixed_mu {
        joint.force(largest)?;
    }
    let per_mu = p.gross_slip_force() / p.friction;
    let least = largest / per_mu * (1.0 + 1e-9);
    if least > MU_RANGE.1 {
        return Err(FitError::BeyondGrossSlip {
            force: largest,
            largest: per_mu * MU_RANGE.1,
        });
    }
    Ok((MU_RANGE.0.max(least), MU_RANGE.1))
}
