//! Properties every double-lap joint solution must have (docs/theory.md section 9): the
//! equilibrium, kinematics and law the closed forms come from (re-evaluated here by finite
//! differences), continuity at every regime change, monotonicity, the limits (K_T -> infinity
//! gives plain Coulomb, the rigid base, the balanced joint, the mirror joint) and dimensional
//! scaling, over the whole accepted domain.

mod common;

use common::{relative_error, second_derivative};
use microslip::Regime;
use microslip::kernel::regime::{Law, Zone};
use microslip::problems::lap::closed_form::{FirstSlip, LapJoint, LapParams, LapState};
use proptest::prelude::*;

fn joint_with(edit: impl FnOnce(&mut LapParams)) -> LapJoint {
    let mut params = LapParams::ALUMINIUM;
    edit(&mut params);
    LapJoint::new(params).unwrap()
}

fn at(joint: &LapJoint, law: Law, force: f64) -> LapState {
    let force = joint.force(force).unwrap();
    match law {
        Law::Coulomb => joint.coulomb(force),
        Law::Regularized => joint.regularized(force),
    }
}

/// The state's slip, re-checked against (L1): s'' = 2 c tau, s'(0) = -F/(b K2),
/// s'(L) = F/(b k1), and the law: tau = K_T s <= mu P where elastic, tau = mu P with
/// s >= mu P / K_T where sliding (Coulomb: s = 0 where it sticks).
fn check_field_equations(joint: &LapJoint, state: &LapState) -> Result<(), String> {
    let p = joint.params();
    let (k1, k2) = (p.inner_stiffness(), p.covers_stiffness());
    let c = 1.0 / k1 + 1.0 / k2;
    let mu_p = p.friction * p.pressure;
    let f = state.force();
    let l = p.length;
    let scale = joint.decay_rate().recip().min(l);
    let step = 1e-3 * scale;
    let s = |x: f64| state.slip_at(x);
    let slope_scale = f / (p.width * k1.min(k2));
    // End slopes, one-sided (the stencil reaches 4 steps inside).
    let left = (-25.0 * s(0.0) + 48.0 * s(step) - 36.0 * s(2.0 * step) + 16.0 * s(3.0 * step)
        - 3.0 * s(4.0 * step))
        / (12.0 * step);
    let right = (25.0 * s(l) - 48.0 * s(l - step) + 36.0 * s(l - 2.0 * step)
        - 16.0 * s(l - 3.0 * step)
        + 3.0 * s(l - 4.0 * step))
        / (12.0 * step);
    let g0 = f / (p.width * k2);
    let gl = f / (p.width * k1);
    if (left + g0).abs() > 1e-5 * slope_scale || (right - gl).abs() > 1e-5 * slope_scale {
        return Err(format!("end slopes {left} {right} vs {} {gl}", -g0));
    }
    let (start, end) = state.middle_zone();
    for i in 1..60 {
        let x = l * f64::from(i) / 60.0;
        if (x - start).abs() < 5.0 * step || (x - end).abs() < 5.0 * step {
            continue; // tau jumps or kinks at the zone edges
        }
        let tau = state.shear_at(x);
        let curvature = second_derivative(s, x, step);
        if (curvature - 2.0 * c * tau).abs() > 1e-4 * 2.0 * c * mu_p {
            return Err(format!(
                "s'' = {curvature} vs 2 c tau = {} at x = {x}",
                2.0 * c * tau
            ));
        }
        if tau > mu_p * (1.0 + 1e-12) || tau < 0.0 {
            return Err(format!("tau = {tau} outside [0, mu P] at {x}"));
        }
        let sliding = x < start || x > end;
        match (state.law(), sliding) {
            (_, true) if tau != mu_p => return Err(format!("sliding at {x} with tau {tau}")),
            (Law::Regularized, true) if s(x) < joint.saturation_slip() * (1.0 - 1e-9) => {
                return Err(format!("sliding at {x} below the saturation slip"));
            }
            (Law::Regularized, false)
                if (tau - p.tangential_stiffness * s(x)).abs() > 1e-9 * mu_p =>
            {
                return Err(format!("elastic at {x}: tau {tau} != K_T s"));
            }
            (Law::Coulomb, false) if s(x) != 0.0 => {
                return Err(format!("stick at {x}: s {}", s(x)));
            }
            _ => {}
        }
    }
    // The two interfaces carry F/2 each.
    let carried = 2.0 * p.width * common::integrate(|x| state.shear_at(x), 0.0, l, 400);
    if relative_error(carried, f) > 1e-3 {
        return Err(format!("interfaces carry {carried} of F = {f}"));
    }
    Ok(())
}

#[test]
fn every_regime_satisfies_the_field_equations() {
    // The bundled joint (x = L first), its mirror (x = 0 first) and a balanced one.
    for joint in [
        joint_with(|_| {}),
        joint_with(|p| p.inner_thickness = 5.0),
        joint_with(|p| p.inner_thickness = 4.0),
    ] {
        let gross = joint.gross_slip_force();
        for fraction in [0.05, 0.2, 0.4, 0.44, 0.5, 0.7, 0.9, 0.99] {
            for law in [Law::Coulomb, Law::Regularized] {
                let state = at(&joint, law, fraction * gross);
                let check = check_field_equations(&joint, &state);
                assert!(
                    check.is_ok(),
                    "{law:?} at {fraction} F_gross: {}",
                    check.unwrap_err()
                );
            }
        }
    }
}

#[test]
fn regimes_follow_each_other_and_zones_are_continuous_at_every_change() {
    let joint = joint_with(|_| {});
    assert_eq!(joint.first_slip(), FirstSlip::CoverEnds);
    let (f1, f2, gross) = (
        joint.first_slip_force(),
        joint.second_slip_force(),
        joint.gross_slip_force(),
    );
    assert!(0.0 < f1 && f1 < f2 && f2 < gross);
    let regime = |f: f64| at(&joint, Law::Regularized, f).regime();
    assert_eq!(regime(0.0), Regime::UNLOADED);
    assert_eq!(regime(0.999 * f1), Regime::MICROSLIP);
    assert_eq!(regime(1.001 * f1), Regime::MICROSLIP_MACROSLIP);
    assert_eq!(
        regime(1.001 * f2),
        Regime::from_zones(&[Zone::Macroslip, Zone::Microslip, Zone::Macroslip])
    );
    assert_eq!(regime(gross), Regime::MACROSLIP);
    assert_eq!(
        at(&joint, Law::Coulomb, 1.0).regime(),
        Regime::from_zones(&[Zone::Macroslip, Zone::Stick, Zone::Macroslip])
    );
    // Continuity of Delta, a and d across F_1 and F_2.
    for f in [f1, f2] {
        let (below, above) = (
            at(&joint, Law::Regularized, f * (1.0 - 1e-9)),
            at(&joint, Law::Regularized, f * (1.0 + 1e-9)),
        );
        assert!(
            relative_error(below.joint_displacement(), above.joint_displacement()) < 1e-7,
            "Delta at {f}"
        );
        assert!((below.slide_at_inner_end() - above.slide_at_inner_end()).abs() < 1e-5);
        assert!((below.slide_at_cover_ends() - above.slide_at_cover_ends()).abs() < 1e-5);
    }
    // Continuous at F_gross too, but with an infinite slope: near it the elastic zone l solves
    // lambda^2 l^3 / 12 = L (1 - F/F_gross) (L5), and the end slips differ from their top value
    // by c mu P (l/2)^2 ((L6) with a = G0 - l/2), so Delta's gap falls as (1 - F/F_gross)^(2/3):
    // a factor 100 per factor 1000.
    let top = at(&joint, Law::Regularized, gross).joint_displacement();
    let gaps: Vec<f64> = [1e-6, 1e-9, 1e-12]
        .iter()
        .map(|e| top - at(&joint, Law::Regularized, gross * (1.0 - e)).joint_displacement())
        .collect();
    assert!(gaps.iter().all(|&g| g > 0.0), "{gaps:?}");
    // Approaching the asymptote: 106 then 100.6 measured.
    let ratios = [gaps[0] / gaps[1], gaps[1] / gaps[2]];
    assert!(relative_error(ratios[0], 100.0) < 0.1, "{gaps:?}");
    assert!(relative_error(ratios[1], 100.0) < 0.01, "{gaps:?}");
    // At F_1 the sliding end's slip is exactly the saturation slip; at F_2 the other's.
    let first = at(&joint, Law::Regularized, f1);
    assert!(relative_error(first.slip_at(40.0), joint.saturation_slip()) < 1e-9);
    let second = at(&joint, Law::Regularized, f2);
    assert!(relative_error(second.slip_at(0.0), joint.saturation_slip()) < 1e-7);
    // At F_gross both interfaces slide everywhere.
    let all = at(&joint, Law::Regularized, gross);
    assert!(relative_error(all.slide_at_inner_end() + all.slide_at_cover_ends(), 40.0) < 1e-9);
}

#[test]
fn delta_and_the_zones_grow_with_the_force_and_delta_falls_with_k_t() {
    for joint in [joint_with(|_| {}), joint_with(|p| p.inner_thickness = 5.0)] {
        let gross = joint.gross_slip_force();
        for law in [Law::Coulomb, Law::Regularized] {
            let mut last = at(&joint, law, 0.0);
            for i in 1..=400 {
                let state = at(&joint, law, gross * f64::from(i) / 400.0);
                assert!(
                    state.joint_displacement() > last.joint_displacement(),
                    "{law:?} {i}"
                );
                assert!(state.slide_at_inner_end() >= last.slide_at_inner_end());
                assert!(state.slide_at_cover_ends() >= last.slide_at_cover_ends());
                last = state;
            }
        }
    }
    // Delta falls as K_T grows and stays above Coulomb's.
    for f in [500.0, 2500.0, 4000.0, 5900.0] {
        let mut last = f64::INFINITY;
        for kt in [1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e7, 1e9] {
            let joint = joint_with(|p| p.tangential_stiffness = kt);
            let delta = at(&joint, Law::Regularized, f).joint_displacement();
            assert!(delta < last, "K_T {kt} F {f}");
            assert!(delta > at(&joint, Law::Coulomb, f).joint_displacement());
            last = delta;
        }
    }
}

#[test]
fn a_stiff_interface_recovers_plain_coulomb() {
    // (L7) is (L5) with T -> 0 and mu P / K_T -> 0: the zones converge like 1/lambda and Delta's
    // gap like 1/K_T at large K_T (the saturation slip dominates it).
    for f in [300.0, 3000.0, 5500.0] {
        let coulomb = at(&joint_with(|_| {}), Law::Coulomb, f);
        let mut gaps = Vec::new();
        for kt in [1e8, 1e10, 1e12] {
            let joint = joint_with(|p| p.tangential_stiffness = kt);
            let r = at(&joint, Law::Regularized, f);
            let lambda = joint.decay_rate();
            assert!((r.slide_at_inner_end() - coulomb.slide_at_inner_end()).abs() < 2.0 / lambda);
            assert!((r.slide_at_cover_ends() - coulomb.slide_at_cover_ends()).abs() < 2.0 / lambda);
            gaps.push(r.joint_displacement() - coulomb.joint_displacement());
        }
        assert!(gaps.iter().all(|&g| g > 0.0));
        for pair in gaps.windows(2) {
            assert!(
                relative_error(pair[0] / pair[1], 100.0) < 0.05,
                "F {f}: {gaps:?}"
            );
        }
    }
    // Coulomb's own closed forms by hand: a : d = k1 : K2, a + d = L F / F_gross.
    let joint = joint_with(|_| {});
    let s = at(&joint, Law::Coulomb, 3000.0);
    assert!(
        relative_error(
            s.slide_at_inner_end() / s.slide_at_cover_ends(),
            210e3 / 280e3
        ) < 1e-12
    );
    assert!(relative_error(s.slide_at_inner_end() + s.slide_at_cover_ends(), 20.0) < 1e-12);
    // Under the regularized law the first slip force falls like 1/sqrt(K_T): Coulomb slides at once.
    let f1 = |kt: f64| joint_with(|p| p.tangential_stiffness = kt).first_slip_force();
    assert!(relative_error(f1(1e8) / f1(1e10), 10.0) < 1e-3);
}

#[test]
fn the_rigid_base_matches_its_own_closed_form() {
    // (L8): E2 t2 -> infinity: a bar pulled over a rough base from both faces. Covers of
    // K2 = 2e13 N/mm against k1 = 2.1e5: terms in k1/K2 are 1e-8.
    let joint = joint_with(|p| {
        p.cover_modulus = 1e7;
        p.cover_thickness = 1e6;
    });
    let (b, mu_p, k1, kt, l): (f64, f64, f64, f64, f64) = (25.0, 3.0, 210e3, 1000.0, 40.0);
    let lambda = (2.0 * kt / k1).sqrt();
    assert!(relative_error(joint.decay_rate(), lambda) < 1e-7);
    let f1 = 2.0 * mu_p * b * (lambda * l).tanh() / lambda;
    assert!(relative_error(joint.first_slip_force(), f1) < 1e-7);
    for f in [1000.0, 3000.0, 5999.0] {
        let coulomb = at(&joint, Law::Coulomb, f);
        let hand = f * f / (4.0 * b * b * mu_p * k1);
        assert!(
            relative_error(coulomb.joint_displacement(), hand) < 1e-6,
            "F {f}"
        );
        assert!(coulomb.slide_at_inner_end() < 1e-6);
        let r = at(&joint, Law::Regularized, f);
        assert!(r.slide_at_inner_end() < 1e-6, "only x = L slides");
    }
}

#[test]
fn a_balanced_joint_slides_at_both_ends_at_once_and_the_mirror_joint_mirrors() {
    // k1 = K2 = 280000 N/mm: symmetric about the middle.
    let balanced = joint_with(|p| p.inner_thickness = 4.0);
    assert_eq!(balanced.first_slip(), FirstSlip::BothEnds);
    assert!(relative_error(balanced.second_slip_force(), balanced.first_slip_force()) < 1e-12);
    for f in [1000.0, 3000.0, 5000.0] {
        let s = at(&balanced, Law::Regularized, f);
        assert!((s.slide_at_inner_end() - s.slide_at_cover_ends()).abs() < 1e-9);
        assert!(relative_error(s.slip_at(10.0), s.slip_at(30.0)) < 1e-9);
    }
    // Swap the members' stiffnesses (k1 = 280000, K2 = 210000 and the reverse): the zones swap
    // ends and Delta is unchanged ((L6) is symmetric under x -> L - x with k1 <-> K2).
    let a = joint_with(|p| {
        p.inner_thickness = 4.0;
        p.cover_thickness = 1.5;
    });
    let b = joint_with(|p| {
        p.inner_thickness = 3.0;
        p.cover_thickness = 2.0;
    });
    assert_eq!(a.first_slip(), FirstSlip::InnerEnd);
    assert_eq!(b.first_slip(), FirstSlip::CoverEnds);
    for f in [1000.0, 2300.0, 4000.0] {
        for law in [Law::Coulomb, Law::Regularized] {
            let (sa, sb) = (at(&a, law, f), at(&b, law, f));
            assert!((sa.slide_at_inner_end() - sb.slide_at_cover_ends()).abs() < 1e-9);
            assert!((sa.slide_at_cover_ends() - sb.slide_at_inner_end()).abs() < 1e-9);
            assert!(relative_error(sa.joint_displacement(), sb.joint_displacement()) < 1e-12);
        }
    }
}

/// Parameters over the accepted domain, on a log scale, with a force anywhere in [0, F_gross].
fn lap_params() -> impl Strategy<Value = (LapParams, f64)> {
    let log = |lo: f64, hi: f64| (lo.log10()..=hi.log10()).prop_map(|e: f64| 10f64.powf(e));
    (
        (
            log(1e-6, 1e6),
            log(1e-6, 1e6),
            log(1e-6, 1e6),
            log(1e-6, 1e6),
        ),
        (
            log(1e-4, 1e7),
            log(1e-4, 1e7),
            log(1e-6, 1e4),
            log(1e-6, 10.0),
        ),
        (log(1e-6, 1e12), 0.0..=1.0_f64),
    )
        .prop_map(|((l, b, t1, t2), (e1, e2, p, mu), (kt, fraction))| {
            (
                LapParams {
                    length: l,
                    width: b,
                    inner_thickness: t1,
                    cover_thickness: t2,
                    inner_modulus: e1,
                    cover_modulus: e2,
                    pressure: p,
                    friction: mu,
                    tangential_stiffness: kt,
                },
                fraction,
            )
        })
}

fn check_finite_and_consistent(params: LapParams, fraction: f64) -> Result<(), String> {
    let joint = LapJoint::new(params).map_err(|e| e.to_string())?;
    let gross = joint.gross_slip_force();
    let Ok(force) = joint.force(fraction * gross) else {
        // F_gross beyond the force domain: the force is refused, as it should be.
        return if fraction * gross > 1e12 {
            Ok(())
        } else {
            Err("refused".into())
        };
    };
    let f1 = joint.first_slip_force();
    let f2 = joint.second_slip_force();
    if !(f1.is_finite() && f2.is_finite() && f1 > 0.0 && f1 <= f2 * (1.0 + 1e-9)) {
        return Err(format!("F1 {f1} F2 {f2}"));
    }
    if f2 > gross * (1.0 + 1e-9) {
        return Err(format!("F2 {f2} beyond F_gross {gross}"));
    }
    for state in [joint.coulomb(force), joint.regularized(force)] {
        let (a, d) = (state.slide_at_inner_end(), state.slide_at_cover_ends());
        let delta = state.joint_displacement();
        let dissipation = state.cycle_dissipation();
        let values = [
            a,
            d,
            delta,
            dissipation,
            state.slip_at(0.0),
            state.shear_at(params.length),
        ];
        if values.iter().any(|v| !v.is_finite() || *v < 0.0) {
            return Err(format!("{:?}: {values:?}", state.law()));
        }
        if a + d > params.length * (1.0 + 1e-12) {
            return Err(format!("zones {a} + {d} beyond L"));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(common::fixed_seed(2000))]

    #[test]
    fn every_accepted_joint_gives_finite_consistent_numbers((params, fraction) in lap_params()) {
        let result = check_finite_and_consistent(params, fraction);
        prop_assert!(result.is_ok(), "{params:?} at {fraction} F_gross: {}", result.unwrap_err());
    }

    #[test]
    fn joints_scale_exactly_with_the_units((params, fraction) in lap_params(), s in 0.1..10.0_f64) {
        // Lengths times s, K_T (stress per length) over s: forces scale as s^2, Delta and the
        // zones as s, the dissipation as s^3.
        let joint = LapJoint::new(params).unwrap();
        let Ok(force) = joint.force(fraction * joint.gross_slip_force()) else { return Ok(()) };
        let scaled_params = LapParams {
            length: params.length * s,
            width: params.width * s,
            inner_thickness: params.inner_thickness * s,
            cover_thickness: params.cover_thickness * s,
            tangential_stiffness: params.tangential_stiffness / s,
            ..params
        };
        let Ok(scaled) = LapJoint::new(scaled_params) else { return Ok(()) };
        let Ok(scaled_force) = scaled.force((force.newtons() * s * s).min(scaled.gross_slip_force())) else {
            return Ok(());
        };
        let (x, y) = (joint.regularized(force), scaled.regularized(scaled_force));
        let close = |u: f64, v: f64| (u - v).abs() <= 1e-7 * u.abs().max(v.abs()) + 1e-300;
        prop_assert!(close(y.joint_displacement(), s * x.joint_displacement()));
        prop_assert!((y.slide_at_cover_ends() - s * x.slide_at_cover_ends()).abs() <= 1e-7 * s * params.length);
        prop_assert!((y.slide_at_inner_end() - s * x.slide_at_inner_end()).abs() <= 1e-7 * s * params.length);
        prop_assert!(close(scaled.first_slip_force(), s * s * joint.first_slip_force()));
    }
}

#[test]
fn a_force_beyond_gross_slip_is_refused_with_its_range() {
    let joint = joint_with(|_| {});
    assert_eq!(
        joint.force(6000.5).unwrap_err().to_string(),
        "invalid F = 6000.5: must be in [0, 6000] N (F_gross = 2 b mu P L: the joint slides \
         through beyond it)"
    );
    assert!(joint.force(-1.0).is_err() && joint.force(f64::NAN).is_err());
    assert_eq!(joint.clamped_force(1e9).newtons(), 6000.0);
    assert_eq!(joint.clamped_force(f64::NAN).newtons(), 0.0);
}
