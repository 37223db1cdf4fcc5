//! One interface point of the regularized Coulomb law with its loading history (a Jenkins element:
//! a spring K_T in series with a Coulomb slider of strength mu P).
//!
//! The slider's displacement (the plastic slip) is the history variable: it is what lets a load path
//! go up, down and up again, and what makes an unloading branch differ from the loading one.

/// Relative overshoot of the yield limit still treated as elastic.
pub(crate) const YIELD_TOLERANCE: f64 = 1e-9;

/// The committed state of one point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct InterfacePoint {
    /// Plastic slip: the slider's displacement (mm).
    pub plastic_slip: f64,
}

/// Stress and consistent tangent of a trial slip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Response {
    /// Shear stress (MPa).
    pub stress: f64,
    /// d stress / d slip (MPa/mm): K_T while elastic, 0 while sliding.
    pub tangent: f64,
    /// True when the slider moves.
    pub sliding: bool,
    /// The plastic slip this response implies (to commit if the step is accepted).
    pub plastic_slip: f64,
}

impl InterfacePoint {
    /// Return mapping for a trial total slip: elastic predictor, then projection on |tau| <= strength.
    ///
    /// A trial stress within [`YIELD_TOLERANCE`] (relative) of the strength stays elastic: points that
    /// sit on the yield limit to round-off (the whole interface does at F = F_thre when K_T is large)
    /// would otherwise flip between elastic and sliding from one Newton iteration to the next.
    pub(crate) fn respond(&self, slip: f64, stiffness: f64, strength: f64) -> Response {
        let trial = stiffness * (slip - self.plastic_slip);
        if trial.abs() <= strength * (1.0 + YIELD_TOLERANCE) {
            Response {
                stress: trial,
                tangent: stiffness,
                sliding: false,
                plastic_slip: self.plastic_slip,
            }
        } else {
            let stress = strength.copysign(trial);
            Response {
                stress,
                tangent: 0.0,
                sliding: true,
                plastic_slip: slip - stress / stiffness,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn load_unload_reload_by_hand() {
        // K_T = 100 MPa/mm, mu P = 1 MPa: saturation slip 0.01 mm.
        let (k, tau_max) = (100.0, 1.0);
        let mut point = InterfacePoint::default();
        let r = point.respond(0.005, k, tau_max);
        assert_eq!((r.stress, r.sliding), (0.5, false));
        // Load to 0.03 mm: slides, slider at 0.02 mm.
        let r = point.respond(0.03, k, tau_max);
        assert!(
            r.sliding && (r.stress - 1.0).abs() < 1e-15 && (r.plastic_slip - 0.02).abs() < 1e-15
        );
        point.plastic_slip = r.plastic_slip;
        // Unload to 0.02 mm: elastic, zero stress; to 0.0 mm: elastic limit in reverse is reached at 0.01.
        let r = point.respond(0.02, k, tau_max);
        assert!(!r.sliding && r.stress.abs() < 1e-12);
        let r = point.respond(0.0, k, tau_max);
        assert!(
            r.sliding && (r.stress + 1.0).abs() < 1e-15 && (r.plastic_slip - 0.01).abs() < 1e-15
        );
        assert_eq!(r.tangent, 0.0);
        point.plastic_slip = r.plastic_slip;
        // Reload to 0.03 mm: elastic up to 0.02 mm (stress +1), then sliding again.
        let r = point.respond(0.02, k, tau_max);
        assert!(!r.sliding && (r.stress - 1.0).abs() < 1e-12);
    }
}
