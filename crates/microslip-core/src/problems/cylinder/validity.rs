//! How far the half-plane answer holds (issue 34, item 6): the envelope, as numbers, inside which
//! the half-plane solution's c and s(a) were measured against CalculiX, and the verdict for one
//! cylinder.
//!
//! The half-plane solution depends on K_T a / E* and Q / mu P only (docs/theory.md, section 13);
//! a real contact also on a / R (Hertz's small-strain, shallow-arc assumption) and on the bodies'
//! size over a (the half-plane's). The envelope was measured with the CalculiX decks of
//! `deck ccx cylinder` (plane strain, C3D20R, linear geometry), one ccx at a time, over
//! K_T a / E*, a / R and the bodies' size, at Q = 0.3 and 0.6 mu P (docs/theory.md, "The Hertzian
//! cylinder in CI and how far the half-plane answer holds"). The bodies' size is not a parameter
//! of the model: the envelope states the least size it was measured for, and the verdict says it.

use super::closed_form::Cylinder;
use crate::kernel::validity::Validity;

/// The measured range of K_T a / E* (-): 0.064 to 64.
pub const MEASURED_STIFFNESS_GROUP: (f64, f64) = (0.064, 64.0);
/// The largest a / R measured (-).
pub const MEASURED_HALF_WIDTH_OVER_RADIUS: f64 = 0.09;
/// The least size of the bodies (half-width and depth, in a) the envelope holds for: the
/// CalculiX deck's.
pub const LEAST_BODY_OVER_HALF_WIDTH: f64 = 6.0;
/// Inside the envelope: |c_FE - c| / a at most this (the largest measured, 0.045 a at
/// K_T a / E* = 0.64 and 0.3 mu P on the a/16 mesh, plus a margin of a/100).
pub const ZONE_WITHIN: f64 = 0.05;
/// Inside the envelope: |s(a)_FE / s(a) - 1| at most this (the largest measured, 3.1 %, plus
/// a margin of 1 %).
pub const EDGE_SLIP_WITHIN: f64 = 0.04;

/// The half-plane answer's envelope for one cylinder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderValidity {
    /// K_T a / E* (-).
    pub stiffness_group: f64,
    /// a / R (-).
    pub half_width_over_radius: f64,
    /// Bound on |c_FE - c| / a inside the envelope; `None` outside it.
    pub zone_within: Option<f64>,
    /// Bound on |s(a)_FE / s(a) - 1| inside the envelope; `None` outside it.
    pub edge_slip_within: Option<f64>,
    /// The level of the s(a) bound (`NotCalibrated` outside the envelope).
    pub validity: Validity,
    /// Why the envelope does not reach this cylinder; `None` inside it.
    pub outside_because: Option<&'static str>,
}

impl Cylinder {
    /// Where the half-plane answer stands for this cylinder, for bodies at least
    /// [`LEAST_BODY_OVER_HALF_WIDTH`] a wide and deep.
    pub fn validity(&self) -> CylinderValidity {
        let group = self.stiffness_group();
        let ratio = self.half_width() / self.params().radius;
        let (low, high) = MEASURED_STIFFNESS_GROUP;
        let outside_because = if group < low {
            Some(
                "K_T a/E* below the measured 0.064: not measured (the CalculiX deck's contact \
                 is then nearly all microslip, and its c is read where K_T s crosses mu p near \
                 the edge, where p -> 0)",
            )
        } else if group > high {
            Some(
                "K_T a/E* above the measured 64: not measured (the answer is Mindlin's there to \
                 about 1 % of a; a finer mesh than a/16 would be needed to judge it)",
            )
        } else if ratio > MEASURED_HALF_WIDTH_OVER_RADIUS {
            Some(
                "a/R above the measured 0.09: Hertz's shallow-arc assumption (a << R) is not \
                 measured beyond it",
            )
        } else {
            None
        };
        let inside = outside_because.is_none();
        CylinderValidity {
            stiffness_group: group,
            half_width_over_radius: ratio,
            zone_within: inside.then_some(ZONE_WITHIN),
            edge_slip_within: inside.then_some(EDGE_SLIP_WITHIN),
            validity: if inside {
                Validity::of_error(EDGE_SLIP_WITHIN)
            } else {
                Validity::NotCalibrated
            },
            outside_because,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::cylinder::params::CylinderParams;

    fn cylinder(radius: f64, load: f64, kt: f64) -> Cylinder {
        Cylinder::new(CylinderParams {
            radius,
            modulus: 210_000.0,
            poisson: 0.3,
            normal_load: load,
            friction: 0.6,
            tangential_stiffness: kt,
        })
        .unwrap()
    }

    #[test]
    fn the_bundled_pad_is_inside_the_envelope() {
        let v = cylinder(50.0, 1000.0, 1e5).validity();
        assert_eq!(v.validity, Validity::Approximate);
        assert_eq!(v.zone_within, Some(ZONE_WITHIN));
        assert_eq!(v.edge_slip_within, Some(EDGE_SLIP_WITHIN));
        assert!(v.outside_because.is_none());
        assert!(
            (v.stiffness_group - 0.6438).abs() < 1e-3,
            "{}",
            v.stiffness_group
        );
    }

    #[test]
    fn each_edge_of_the_envelope_is_said() {
        let pad = cylinder(50.0, 1000.0, 1e5);
        let per_group = pad.contact_modulus() / pad.half_width();
        let (low, high) = MEASURED_STIFFNESS_GROUP;
        for (group, inside) in [
            (0.99 * low, false),
            (1.01 * low, true),
            (0.99 * high, true),
            (1.01 * high, false),
        ] {
            let v = pad
                .with_tangential_stiffness(group * per_group)
                .unwrap()
                .validity();
            assert_eq!(v.outside_because.is_none(), inside, "{group}");
            assert_eq!(v.zone_within.is_some(), inside, "{group}");
            if !inside {
                assert_eq!(v.validity, Validity::NotCalibrated);
                assert!(v.outside_because.unwrap().contains("K_T a/E*"));
            }
        }
        // a / R grows as sqrt(P / R) / sqrt(R): a small radius leaves the envelope by a / R.
        let sharp = cylinder(1.0, 1000.0, 1e5);
        let ratio = sharp.half_width() / 1.0;
        assert!(ratio > MEASURED_HALF_WIDTH_OVER_RADIUS, "{ratio}");
        let sharp = sharp
            .with_tangential_stiffness(0.64 * sharp.contact_modulus() / sharp.half_width())
            .unwrap();
        let v = sharp.validity();
        assert!(v.outside_because.unwrap().contains("a/R"));
        assert_eq!(v.validity, Validity::NotCalibrated);
    }
}
