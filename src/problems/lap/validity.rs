//! How far the joint's 1-D shear-lag theory holds: its expected difference from a plane-stress
//! continuum, as numbers. The theory assumes each plate's axial strain uniform through its
//! thickness and the contact pressure equal to P; both fail when the interface shear decays over
//! a length comparable to the thicknesses (stiff interfaces, thick plates) and where the covers
//! bend (docs/theory.md, (L12) and (L14)).

use super::closed_form::{JointForce, LapJoint};
use crate::kernel::validity::Validity;

/// The shear-lag theory's envelope for one joint at one force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapValidity {
    /// The decay length of the interface shear over the thicker plate, (1/lambda) / max(t1, t2):
    /// small values are where uniform strain through the thickness is doubtful.
    pub decay_over_thickness: f64,
    /// The bound on |Delta continuum / Delta closed form - 1|, a fraction; `None` where no
    /// calibration reaches.
    pub expected_error: Option<f64>,
    /// The level of that bound.
    pub validity: Validity,
}

impl LapJoint {
    /// Where the shear-lag theory stands for this joint at `force` (L14).
    pub fn validity(&self, force: JointForce) -> LapValidity {
        let _ = force;
        let p = self.params();
        LapValidity {
            decay_over_thickness: 1.0
                / (self.decay_rate() * p.inner_thickness.max(p.cover_thickness)),
            expected_error: None,
            validity: Validity::NotCalibrated,
        }
    }
}
