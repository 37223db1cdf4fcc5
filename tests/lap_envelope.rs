//! The shear-lag theory's envelope (docs/theory.md (L14)) against the CalculiX measurements it was
//! fitted on and held out from (`tests/data/calculix/lap-envelope.csv`: 22 joints, 74 states,
//! measured by `validation/calculix/lap/envelope/`). The closed form is recomputed here, so a change to it
//! that moves Delta shows as a changed difference; the bound must stay above every measured
//! difference inside its calibrated ranges, and the joints measured far off must stay outside
//! them.

use microslip::kernel::validity::Validity;
use microslip::problems::lap::closed_form::{LapJoint, LapParams};

struct State {
    joint: String,
    calibration: bool,
    params: LapParams,
    force: f64,
    delta_ccx: f64,
}

fn states() -> Vec<State> {
    let text = include_str!("data/calculix/lap-envelope.csv");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header = lines.next().unwrap();
    assert!(header.starts_with("joint,role,KT_MPa_per_mm,"), "{header}");
    lines
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            let n = |i: usize| f[i].parse::<f64>().unwrap();
            State {
                joint: f[0].to_string(),
                calibration: f[1] == "calibration",
                params: LapParams {
                    tangential_stiffness: n(2),
                    inner_thickness: n(3),
                    cover_thickness: n(4),
                    length: n(5),
                    inner_modulus: n(6),
                    cover_modulus: n(7),
                    friction: n(8),
                    pressure: n(9),
                    width: n(10),
                },
                force: n(11),
                delta_ccx: n(12),
            }
        })
        .collect()
}

/// (|CalculiX / closed form - 1|, the envelope) of a state.
fn judged(s: &State) -> (f64, microslip::problems::lap::LapValidity) {
    let joint = LapJoint::new(s.params).unwrap();
    let force = joint.force(s.force).unwrap();
    let closed = joint.regularized(force).joint_displacement();
    ((s.delta_ccx / closed - 1.0).abs(), joint.validity(force))
}

#[test]
fn every_measured_state_inside_the_calibration_is_under_the_bound() {
    let all = states();
    assert_eq!(all.len(), 86);
    let mut inside = 0;
    let mut worst: f64 = 0.0;
    for s in &all {
        let (error, v) = judged(s);
        let Some(bound) = v.expected_error else {
            continue;
        };
        inside += 1;
        worst = worst.max(error / bound);
        assert!(
            error <= bound,
            "{} at {} N: measured {error}, bound {bound}",
            s.joint,
            s.force
        );
    }
    // 73 states lie in the domain: not C02 and H5 (short), nor since issue 33 C08, H2 and H4
    // (dissimilar plates with E2 t2 / (E1 t1) above 3, where the continuum measured the bound
    // exceeded on joints the grid did not have); the margin leaves room.
    assert_eq!(inside, 73);
    assert!(worst < 0.85, "largest measured / bound {worst}");
}

#[test]
fn the_fitted_bound_covers_its_calibration_and_the_margin_covers_the_hold_outs() {
    // Without the 1.25 margin, the linear programme's bound (rounded up) is above every
    // calibration state it was fitted on; one state of the first hold-outs exceeded it (by 2.5 %
    // of itself: H4, outside the domain since issue 33), which is why the margin is there, and
    // one of the fresh joints, run after the margin was set, exceeds it too (by 4 %): the margin
    // is needed, not decoration.
    let mut exceeded = Vec::new();
    for s in states() {
        let (error, v) = judged(&s);
        let Some(bound) = v.expected_error else {
            continue;
        };
        let fitted = bound / 1.25;
        if s.calibration {
            assert!(
                error <= fitted,
                "{} at {} N: {error} > {fitted}",
                s.joint,
                s.force
            );
        } else if error > fitted {
            assert!(error <= 1.05 * fitted, "{} at {} N", s.joint, s.force);
            exceeded.push(s.joint.clone());
        }
    }
    assert_eq!(exceeded, ["J2"], "hold-out states over the fitted bound");
}

#[test]
fn the_joints_measured_far_off_are_outside_the_calibration() {
    for s in states()
        .iter()
        .filter(|s| s.joint == "C02" || s.joint == "H5")
    {
        let (error, v) = judged(s);
        assert_eq!(
            v.validity,
            Validity::NotCalibrated,
            "{} {}",
            s.joint,
            s.force
        );
        assert!(v.outside_calibration.is_some());
        // C02 at 0.9 F_gross: the covers lift off, +236 %.
        if s.joint == "C02" && s.force > 10_000.0 {
            assert!(error > 2.0, "{error}");
        }
    }
}

#[test]
fn verdicts_span_the_levels() {
    let mut seen = std::collections::BTreeSet::new();
    for s in states() {
        seen.insert(judged(&s).1.validity.label());
    }
    for level in ["approximate", "outside", "not calibrated"] {
        assert!(seen.contains(level), "{seen:?}");
    }
}
