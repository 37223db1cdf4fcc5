//! What is fitted: the load-driven structures whose load-response curve a fit matches, each at
//! a trial (mu, K_T).

use crate::problems::lap::closed_form::{LapJoint, LapParams};
use crate::{TipForce, TwinBeams, TwinBeamsParams};

/// What is fitted: a problem with a load-response curve, its structure (all but mu and K_T) fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Structure {
    /// Twin beams: w(L) against the tip force.
    Beam(TwinBeamsParams),
    /// The lap joint: Delta against the force through it (a force beyond F_gross at a trial mu
    /// has no state there: that mu is outside the fit's domain).
    Lap(LapParams),
}

/// The structure at one (mu, K_T): its response at a force, and the forces where it changes
/// regime.
#[derive(Debug, Clone, Copy)]
pub(super) enum Curve {
    Beam(TwinBeams),
    Lap(LapJoint),
}

impl Structure {
    /// The structure at `mu`, `kt`; None where they (or the structure) are not accepted.
    pub(super) fn at(&self, mu: f64, kt: f64) -> Option<Curve> {
        match *self {
            Structure::Beam(structure) => TwinBeams::new(TwinBeamsParams {
                friction: mu,
                tangential_stiffness: kt,
                ..structure
            })
            .ok()
            .map(Curve::Beam),
            Structure::Lap(structure) => LapJoint::new(LapParams {
                friction: mu,
                tangential_stiffness: kt,
                ..structure
            })
            .ok()
            .map(Curve::Lap),
        }
    }

    /// The header of its response column in a measurement file.
    pub(super) fn response_column(&self) -> &'static str {
        match self {
            Structure::Beam(_) => "w_mm",
            Structure::Lap(_) => "Delta_mm",
        }
    }

    /// The structure's own mu and K_T.
    pub(super) fn own(&self) -> (f64, f64) {
        match self {
            Structure::Beam(p) => (p.friction, p.tangential_stiffness),
            Structure::Lap(p) => (p.friction, p.tangential_stiffness),
        }
    }
}

impl Curve {
    /// The regularized response at `force` (mm); None for a force the structure does not accept.
    pub(super) fn response(&self, force: f64) -> Option<f64> {
        match self {
            Curve::Beam(beams) => Some(
                beams
                    .regularized(TipForce::new(force).ok()?)
                    .tip_deflection(),
            ),
            Curve::Lap(joint) => Some(
                joint
                    .regularized(joint.force(force).ok()?)
                    .joint_displacement(),
            ),
        }
    }

    /// (the force above which all slides under Coulomb, F_1) (N): F_thre and F_1 of the beams,
    /// F_gross and F_1 of the joint.
    pub(super) fn regime_forces(&self) -> (f64, f64) {
        match self {
            Curve::Beam(beams) => (beams.threshold_force(), beams.first_macroslip_force()),
            Curve::Lap(joint) => (joint.gross_slip_force(), joint.first_slip_force()),
        }
    }
}
