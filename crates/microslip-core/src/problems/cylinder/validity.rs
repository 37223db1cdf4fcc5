//! How far the half-plane answer holds (issue 34, item 6; measured again on converged FE in
//! issue 45, item 5): the envelope, as numbers, inside which the half-plane solution's c and s(a)
//! were measured against CalculiX, and the verdict for one cylinder.
//!
//! The half-plane solution depends on K_T a / E* and Q / mu P only (docs/theory.md, section 13);
//! a real contact also on a / R (Hertz's small-strain, shallow-arc assumption) and on the bodies'
//! size over a (the half-plane's). The envelope was measured with `microslip suite` on the
//! CalculiX deck of `deck ccx cylinder` (plane strain, C3D20R, linear geometry; the flat 32 a
//! wide and deep, the cylinder the disc below a chord 32 a (at most R) above the contact), each
//! case on a mesh ladder (a/8, a/16, a/32 over the contact, and at half the Q increment) whose
//! answers are extrapolated to the converged one, at Q = 0.3 and 0.6 mu P
//! (`validation/cylinder/envelope.toml`; docs/theory.md section 16, "The envelope on converged
//! FE"). A bound is what the converged answers support: the worst converged departure measured
//! plus its uncertainty, never the error of a coarse deck (the older bounds, 4 % to 7 % in s(a),
//! were the a/8 deck's own error with 6 a bodies). The bodies' size is not a parameter of the
//! model: the envelope states the least size it was measured for, and the verdict says it.

use super::closed_form::Cylinder;
use crate::kernel::validity::Validity;

/// The measured range of K_T a / E* (-): 0.1 to 30 (cal-k0.1 and cal-k30 of the case list at the
/// range's ends; beyond them no ladder was run).
pub const MEASURED_STIFFNESS_GROUP: (f64, f64) = (0.1, 30.0);
/// The largest a / R of the envelope (-): 0.015 (the calibration cases' 0.0105, the bundled
/// pad's 0.0149 held out). Beyond it one case was measured, not held out: at a / R = 0.04
/// (K_T a/E* = 1, a/8 and a/16) s(a) +0.91, +0.61 % and c -2.1, -0.4 % of a at 0.3 mu P, the
/// pressure read from CalculiX's CPRESS; at 0.06 s(a) +1.31, +1.02 % (docs/theory.md section
/// 16). (Read from the node pairs, as before issue 45's reader fix, the same runs seemed to
/// diverge in c and a: the pairs carried 91 % of P.) The older curved tier (c 0.09 a, s(a) 5 %
/// up to 0.047) was the 6 a deck's a/8 error, and is not kept.
pub const MEASURED_HALF_WIDTH_OVER_RADIUS: f64 = 0.015;
/// The least size of the bodies (half-width and depth, in a) the envelope holds for: the deck's
/// (the flat 32 a; the cylinder too, up to a / R = 1/32).
pub const LEAST_BODY_OVER_HALF_WIDTH: f64 = 32.0;
/// |c_FE - c| / a at most this: the worst converged c measured, |estimate| + uncertainty, was
/// 2.9 % of a (cal-k0.1, 0.3 mu P: +0.09 % +- 2.83 %, two rungs); cal-k1 (three rungs) -1.67 %
/// +- 1.11 %, cal-k30 -1.15 % +- 0.63 %; held out: the pad -1.35 % +- 0.06 %, hold-k10-r0.0149
/// -2.38 % +- 0.93 % (inside 3 % plus its uncertainty, as the suite judges). Those c were read
/// from the node pairs' pressure, whose drift made the ladders not monotone. Re-read from
/// CalculiX's CPRESS (the reader since), the same cases' a/8 and a/16 rungs converge toward the
/// half-plane's c (a/16 within 0.0122 a everywhere), the worst two-rung estimate plus
/// uncertainty 2.59 % of a (cal-k0.1, 0.3 mu P): the bound holds, set by the a/8 rung's
/// distance (docs/theory.md section 16, "c and a re-read with CalculiX's CPRESS").
pub const ZONE_WITHIN: f64 = 0.03;
/// |s(a)_FE / s(a) - 1| at most this for K_T a / E* in [`MEASURED_STIFFNESS_GROUP`] and a / R
/// up to [`MEASURED_HALF_WIDTH_OVER_RADIUS`]: the worst converged s(a) measured, |estimate| +
/// uncertainty (the increment's change in it), was 0.61 % (cal-k0.1, 0.3 mu P: +0.28 % +-
/// 0.33 %; cal-k1, three rungs a/8 to a/32: +0.19 % +- 0.40 %; cal-k30: +0.18 % +- 0.01 %);
/// held out: the bundled pad +0.20 % +- 0.44 %, hold-k10-r0.0149 +0.31 % +- 0.21 %. The older 4 %
/// and 7 % were the 6 a deck's a/8 error.
pub const EDGE_SLIP_WITHIN: f64 = 0.01;

// The reasons a cylinder is outside the envelope, as literals so that two of them join into one
// `&'static str` (a cylinder past two bounds is told both).
macro_rules! too_compliant {
    () => {
        "K_T a/E* below the measured 0.1: no converged ladder was run there (the contact is then \
         nearly all microslip, and c is read where K_T s crosses mu p near the edge, where p -> 0"
    };
}
macro_rules! too_stiff {
    () => {
        "K_T a/E* above the measured 30: no converged ladder was run there (the answer nears \
         Mindlin's"
    };
}
macro_rules! too_curved {
    () => {
        "a/R above the measured 0.015: no case was held out beyond (one measured at 0.04: s(a) \
         within 0.9 % and c within 0.021 a of the half-plane's on the a/8 and a/16 meshes; at \
         0.06 s(a) +1.0 %; docs/theory.md section 16)"
    };
}

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
    /// Why the envelope does not reach this cylinder, every bound it passes named (K_T a/E*
    /// and a/R both, when both are out); `None` inside it.
    pub outside_because: Option<&'static str>,
}

impl Cylinder {
    /// Where the half-plane answer stands for this cylinder, for bodies at least
    /// [`LEAST_BODY_OVER_HALF_WIDTH`] a wide and deep.
    pub fn validity(&self) -> CylinderValidity {
        let group = self.stiffness_group();
        let ratio = self.half_width() / self.params().radius;
        let (low, high) = MEASURED_STIFFNESS_GROUP;
        // Every bound the cylinder passes is named, not only the first (issue 47).
        let curved_out = ratio > MEASURED_HALF_WIDTH_OVER_RADIUS;
        let outside_because = match (group < low, group > high, curved_out) {
            (true, _, false) => Some(concat!(too_compliant!(), ")")),
            (true, _, true) => Some(concat!(too_compliant!(), "); and ", too_curved!())),
            (_, true, false) => Some(concat!(too_stiff!(), ")")),
            (_, true, true) => Some(concat!(too_stiff!(), "); and ", too_curved!())),
            (false, false, true) => Some(too_curved!()),
            (false, false, false) => None,
        };
        let inside = outside_because.is_none();
        // K_T a/E* needs no tier of its own: its whole measured range is inside the bounds.
        let (zone, edge) = (ZONE_WITHIN, EDGE_SLIP_WITHIN);
        CylinderValidity {
            stiffness_group: group,
            half_width_over_radius: ratio,
            zone_within: inside.then_some(zone),
            edge_slip_within: inside.then_some(edge),
            validity: if inside {
                Validity::of_error(edge)
            } else {
                Validity::NotCalibrated
            },
            outside_because,
        }
    }
}

#[cfg(test)]
mod both_bounds {
    use super::*;
    use crate::problems::cylinder::params::CylinderParams;

    /// R = 0.3 mm with the pad's load passes both K_T a/E* (0.05) and a/R (0.19): both named.
    #[test]
    fn a_cylinder_past_two_bounds_is_told_both() {
        let params = CylinderParams {
            radius: 0.3,
            ..CylinderParams::STEEL_PAD
        };
        let v = Cylinder::new(params).unwrap().validity();
        let why = v.outside_because.unwrap();
        assert!(v.stiffness_group < MEASURED_STIFFNESS_GROUP.0, "{why}");
        assert!(
            v.half_width_over_radius > MEASURED_HALF_WIDTH_OVER_RADIUS,
            "{why}"
        );
        assert!(
            why.contains("K_T a/E* below") && why.contains("a/R above"),
            "{why}"
        );
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
        // Converged FE holds it to the level "holds" (the a/8 6 a deck's 4 % was "approximate").
        assert_eq!(v.validity, Validity::Holds);
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
        // No stiff tier: the whole measured range of K_T a/E* has the base bounds.
        for group in [1.001 * low, 1.0, 10.0, 0.999 * high] {
            let v = pad
                .with_tangential_stiffness(group * per_group)
                .unwrap()
                .validity();
            assert_eq!(v.edge_slip_within, Some(EDGE_SLIP_WITHIN), "{group}");
            assert_eq!(v.zone_within, Some(ZONE_WITHIN), "{group}");
        }
        // a / R = sqrt(8 P / (pi E* R)): the pad's 0.0149 is inside; R = 5 mm (a/R = 0.047),
        // inside the older curved tier (measured on the a/8 6 a deck), is not calibrated now.
        let at = |radius: f64| {
            let c = cylinder(radius, 1000.0, 1e5);
            let group = 0.64 * c.contact_modulus() / c.half_width();
            let c = c.with_tangential_stiffness(group).unwrap();
            (c.half_width() / radius, c.validity())
        };
        let (ratio, v) = at(50.0);
        assert!(ratio <= MEASURED_HALF_WIDTH_OVER_RADIUS, "{ratio}");
        assert_eq!(v.edge_slip_within, Some(EDGE_SLIP_WITHIN));
        for radius in [5.0, 1.0] {
            let (ratio, v) = at(radius);
            assert!(ratio > MEASURED_HALF_WIDTH_OVER_RADIUS, "{ratio}");
            assert!(v.outside_because.unwrap().contains("a/R"));
            assert_eq!(v.validity, Validity::NotCalibrated);
        }
    }

    /// Issue 45's goal: s(a) within 1.5 % or less for K_T a/E* in [0.1, 30] and a/R <= 0.015
    /// (the older envelope said 4 % and 7 % there: the a/8 deck's own error with 6 a bodies),
    /// and every converged departure measured inside its bound (docs/theory.md section 16: the
    /// suite's extrapolated s(a) and c over a/8, a/16, a/32, as fractions; c of a).
    #[test]
    fn the_converged_envelope_is_tight_and_holds_what_was_measured() {
        let (low, high) = MEASURED_STIFFNESS_GROUP;
        assert!(low <= 0.1 && high >= 30.0);
        for group in [0.1, 0.3, 1.0, 3.0, 10.0, 30.0] {
            for radius in [50.0, 25.0] {
                let c = cylinder(radius, 500.0, 1.0);
                let c = c
                    .with_tangential_stiffness(group * c.contact_modulus() / c.half_width())
                    .unwrap();
                assert!(c.half_width() / radius <= MEASURED_HALF_WIDTH_OVER_RADIUS);
                let v = c.validity();
                let edge = v.edge_slip_within.unwrap();
                assert!(edge <= 0.015, "{group} {radius}: {edge}");
            }
        }
        // (case, converged s(a) departure, its uncertainty, converged c departure / a, its
        // uncertainty), both loads, as the suite's ladders gave them (docs/theory.md section 16).
        let measured: [(&str, f64, f64, f64, f64); 6] = [
            (
                "cal-k1-r0.0105 at 0.3 mu P",
                0.00191,
                0.00401,
                -0.01669,
                0.01114,
            ),
            (
                "cal-k1-r0.0105 at 0.6 mu P",
                0.00159,
                0.00051,
                -0.01333,
                0.00623,
            ),
            (
                "cal-k30-r0.0105 at 0.3 mu P",
                0.00183,
                0.00008,
                -0.01151,
                0.00627,
            ),
            (
                "cal-k30-r0.0105 at 0.6 mu P",
                0.00050,
                0.00013,
                -0.00807,
                0.00838,
            ),
            (
                "cal-k0.1-r0.0105 at 0.3 mu P",
                0.00277,
                0.00334,
                0.00094,
                0.02832,
            ),
            (
                "cal-k0.1-r0.0105 at 0.6 mu P",
                0.00216,
                0.00118,
                0.00364,
                0.00908,
            ),
        ];
        for (case, sa, sa_u, zone, zone_u) in measured {
            assert!(
                sa.abs() + sa_u <= EDGE_SLIP_WITHIN,
                "{case}: s(a) {sa} +- {sa_u}"
            );
            assert!(
                zone.abs() + zone_u <= ZONE_WITHIN,
                "{case}: c {zone} +- {zone_u}"
            );
        }
        // The cases held out (not used to set the bounds) pass as the suite judges them: the
        // estimate within the bound plus its uncertainty, the uncertainty within the bound.
        let held_out: [(&str, f64, f64, f64, f64); 4] = [
            ("the pad at 0.3 mu P", 0.00195, 0.00435, -0.01348, 0.00063),
            ("the pad at 0.6 mu P", 0.00231, 0.00039, -0.00782, 0.00028),
            (
                "hold-k10-r0.0149 at 0.3 mu P",
                0.00308,
                0.00209,
                -0.02381,
                0.00930,
            ),
            (
                "hold-k10-r0.0149 at 0.6 mu P",
                0.00120,
                0.00045,
                -0.01217,
                0.00289,
            ),
        ];
        for (case, sa, sa_u, zone, zone_u) in held_out {
            assert!(
                sa_u <= EDGE_SLIP_WITHIN && sa.abs() <= EDGE_SLIP_WITHIN + sa_u,
                "{case}"
            );
            assert!(
                zone_u <= ZONE_WITHIN && zone.abs() <= ZONE_WITHIN + zone_u,
                "{case}"
            );
        }
    }
}
