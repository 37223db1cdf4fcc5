//! Properties every squeezed-plate solution must have, checked against hand limits, the equilibrium
//! and constitutive law the closed forms come from (re-evaluated here by finite differences),
//! continuity, monotonicity and dimensional scaling.

mod common;

use common::{derivative, relative_error};
use microslip::{PlateParams, Regime, SqueezedPlate};

fn plate_with(kt: f64) -> SqueezedPlate {
    SqueezedPlate::new(PlateParams {
        tangential_stiffness: kt,
        ..PlateParams::PAPER
    })
    .unwrap()
}

#[test]
fn stiff_interface_recovers_coulomb() {
    // (P6) with alpha -> infinity: L - X_r + coth(alpha X_r) / alpha = l gives X_r = X_s + 1/alpha + o(1/alpha).
    let coulomb = plate_with(1.0).coulomb();
    for kt in [1e7, 1e8, 1e9, 1e11] {
        let plate = plate_with(kt);
        let r = plate.regularized();
        let alpha = plate.decay_rate();
        assert!(
            relative_error(r.micro_zone_end() - coulomb.stick_end(), 1.0 / alpha) < 1e-9,
            "K_T={kt}"
        );
        assert!(r.end_displacement() > coulomb.end_displacement());
    }
    // Hand result (docs/theory.md): once tanh(alpha X_r) = 1 to f64 precision,
    // u(L) - u_Coulomb(L) = mu P / K_T - kappa / (2 alpha^2) = mu P / (2 K_T) exactly.
    for kt in [1e7, 1e9, 1e11] {
        let gap = plate_with(kt).regularized().end_displacement() - coulomb.end_displacement();
        assert!(
            relative_error(gap, 3.0 / (2.0 * kt)) < 1e-6,
            "K_T={kt}: gap {gap}"
        );
    }
}

#[test]
fn soft_interface_lets_the_plate_expand_freely() {
    // K_T -> 0: no friction at all, plane-strain free expansion eps_x = nu (1 + nu) P / E.
    let free = 0.3 * 1.3 * 10.0 * 10.0 / 70_000.0;
    let plate = plate_with(1e-3);
    let u = plate.regularized().end_displacement();
    // u(L) = free L tanh(aL) / (aL) and tanh(z)/z = 1 - z^2/3 + O(z^4), aL = 2.5e-3.
    let al = plate.decay_rate() * 10.0;
    assert!(
        relative_error(u, free * (1.0 - al * al / 3.0)) < 1e-10,
        "{u} vs {free}"
    );
}

#[test]
fn solution_satisfies_equilibrium_constitution_and_the_friction_law() {
    // sigma_x = (E u' - nu (1 + nu) P) / (1 - nu^2) (plane strain, sigma_y = -P);
    // t_p sigma_x' = tau; sigma_x(L) = 0; u(0) = 0; tau = K_T u <= mu P, or mu P with u >= mu P / K_T.
    let (l, t, e, nu, mu, p) = (10.0, 0.2, 70_000.0, 0.3, 0.3, 10.0);
    for kt in [1.0, 1e3, 1e5, 1e6, 1e7] {
        let plate = plate_with(kt);
        let state = plate.regularized();
        let step = 1e-3_f64.min(0.01 / plate.decay_rate());
        let u = |x: f64| state.displacement(x);
        let sigma = |x: f64| (e * derivative(u, x, step) - nu * (1.0 + nu) * p) / (1.0 - nu * nu);
        assert_eq!(state.displacement(0.0), 0.0);
        // Free end: one-sided evaluation just inside the plate.
        // Free end sigma(L) = 0: quadratic extrapolation from L - 3d, L - 4d, L - 5d (stencils stay inside).
        let edge_sigma = 10.0 * sigma(l - 3.0 * step) - 15.0 * sigma(l - 4.0 * step)
            + 6.0 * sigma(l - 5.0 * step);
        assert!(
            edge_sigma.abs() < 1e-6 * p,
            "K_T={kt}: sigma(L) = {edge_sigma}"
        );
        for i in 1..40 {
            let x = l * f64::from(i) / 40.0;
            if (x - state.micro_zone_end()).abs() < 25.0 * step {
                continue; // sigma'' jumps at X_r; the stencil would straddle it
            }
            let tau = state.shear_stress(x);
            let equilibrium = t * derivative(sigma, x, 10.0 * step);
            assert!(
                (equilibrium - tau).abs() < 1e-5 * mu * p,
                "K_T={kt} x={x}: t sigma' = {equilibrium}, tau = {tau}"
            );
            if x < state.micro_zone_end() {
                assert!(relative_error(tau, kt * u(x)) < 1e-12);
                assert!(tau <= mu * p * (1.0 + 1e-12));
            } else {
                assert_eq!(tau, mu * p);
                assert!(u(x) >= plate.saturation_slip() * (1.0 - 1e-12));
            }
        }
    }
}

/// The K_T at which macroslip first appears, by bisection on the regime alone (no closed form used).
fn first_macroslip_stiffness() -> f64 {
    let (mut lo, mut hi) = (1e3_f64, 1e7_f64);
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if plate_with(mid).regularized().regime() == Regime::MICROSLIP {
            lo = mid
        } else {
            hi = mid
        }
    }
    hi
}

#[test]
fn end_displacement_is_continuous_where_macroslip_appears() {
    let kt = first_macroslip_stiffness();
    let below = plate_with(kt * (1.0 - 1e-9)).regularized();
    let above = plate_with(kt * (1.0 + 1e-9)).regularized();
    assert_eq!(below.regime(), Regime::MICROSLIP);
    assert_eq!(above.regime(), Regime::MICROSLIP_MACROSLIP);
    assert!(relative_error(above.end_displacement(), below.end_displacement()) < 1e-8);
    assert!(
        10.0 - above.micro_zone_end() < 1e-3,
        "X_r = {}",
        above.micro_zone_end()
    );
    // At the transition the end shear reaches mu P: K_T u(L) = mu P.
    assert!(relative_error(kt * below.end_displacement(), 3.0) < 1e-8);
}

#[test]
fn stiffer_interfaces_hold_the_plate_back() {
    let mut last = (f64::INFINITY, f64::INFINITY);
    for i in 0..=240 {
        let kt = 10f64.powf(-3.0 + 12.0 * f64::from(i) / 240.0);
        let r = plate_with(kt).regularized();
        let now = (r.end_displacement(), r.micro_zone_end());
        assert!(
            now.0 < last.0 && now.1 <= last.1,
            "K_T={kt}: {now:?} after {last:?}"
        );
        last = now;
    }
    // More friction, more stick: X_r rises with mu (paper Fig. 15) for a K_T with macroslip.
    let mut last_x = 0.0;
    for mu in [0.05, 0.1, 0.2, 0.3, 0.5, 1.0] {
        let plate = SqueezedPlate::new(PlateParams {
            friction: mu,
            tangential_stiffness: 1e7,
            ..PlateParams::PAPER
        });
        let x = plate.unwrap().regularized().micro_zone_end();
        assert!(x >= last_x, "mu={mu}: X_r = {x}");
        last_x = x;
    }
}

#[test]
fn microslip_boundary_does_not_depend_on_pressure() {
    // (P6) contains no P (the paper notes it too); u scales linearly with P.
    let base = plate_with(1e6).regularized();
    for p in [0.01, 1.0, 1e3] {
        let plate = SqueezedPlate::new(PlateParams {
            pressure: p,
            tangential_stiffness: 1e6,
            ..PlateParams::PAPER
        });
        let r = plate.unwrap().regularized();
        assert!(relative_error(r.micro_zone_end(), base.micro_zone_end()) < 1e-13);
        assert!(relative_error(r.end_displacement(), base.end_displacement() * p / 10.0) < 1e-12);
    }
}

#[test]
fn solutions_are_invariant_under_a_change_of_units() {
    let (s, sigma) = (25.4, 1.0 / 6.894_757); // mm -> inch-like lengths, MPa -> ksi-like stresses
    let base = PlateParams {
        tangential_stiffness: 3e6,
        ..PlateParams::PAPER
    };
    let scaled = PlateParams {
        half_length: base.half_length * s,
        thickness: base.thickness * s,
        youngs_modulus: base.youngs_modulus * sigma,
        pressure: base.pressure * sigma,
        tangential_stiffness: base.tangential_stiffness * sigma / s,
        ..base
    };
    let (a, b) = (
        SqueezedPlate::new(base).unwrap(),
        SqueezedPlate::new(scaled).unwrap(),
    );
    let (ra, rb) = (a.regularized(), b.regularized());
    assert!(relative_error(rb.micro_zone_end(), ra.micro_zone_end() * s) < 1e-12);
    assert!(relative_error(rb.end_displacement(), ra.end_displacement() * s) < 1e-12);
    assert!(
        relative_error(
            b.coulomb().end_displacement(),
            a.coulomb().end_displacement() * s
        ) < 1e-12
    );
    assert!(
        relative_error(
            b.contact_pressure().ratio(4.0 * s),
            a.contact_pressure().ratio(4.0)
        ) < 1e-12
    );
}

#[test]
fn every_corner_of_the_domain_gives_finite_physical_numbers() {
    for shape in [
        PlateParams::PAPER,
        PlateParams {
            half_length: 1e4,
            thickness: 1e-3,
            ..PlateParams::PAPER
        },
        PlateParams {
            half_length: 0.01,
            thickness: 10.0,
            poisson: 0.499_999,
            ..PlateParams::PAPER
        },
        PlateParams {
            friction: 1e-6,
            poisson: 0.0,
            ..PlateParams::PAPER
        },
        PlateParams {
            friction: 1e-6,
            ..PlateParams::PAPER
        },
    ] {
        for kt in [1e-3, 1.0, 1e3, 1e6, 1e9] {
            let plate = SqueezedPlate::new(PlateParams {
                tangential_stiffness: kt,
                ..shape
            })
            .unwrap();
            let (r, c, cp) = (
                plate.regularized(),
                plate.coulomb(),
                plate.contact_pressure(),
            );
            let l = shape.half_length;
            assert!((0.0..=l).contains(&r.micro_zone_end()) && (0.0..=l).contains(&c.stick_end()));
            for x in [0.0, 0.5 * l, r.micro_zone_end(), l] {
                let v = [
                    r.displacement(x),
                    r.shear_stress(x),
                    c.displacement(x),
                    cp.ratio(x),
                ];
                assert!(
                    v.iter().all(|v| v.is_finite() && *v >= 0.0),
                    "{shape:?} K_T={kt} x={x}: {v:?}"
                );
            }
            assert!(cp.mean_deviation().is_finite());
        }
    }
}

#[test]
fn contact_pressure_solves_the_flat_timoshenko_plate_equation() {
    // With q = Q / P = int_0^x (P_r / P - 1) and beta^2 = 5 (1 - nu) / t^2 (plane-strain Timoshenko
    // plate, shear factor 5/6), (P7) reads q'' - beta^2 mu h q' - beta^2 q = beta^2 mu h.
    use common::integrate;
    for (l, t) in [(10.0, 0.2), (1.0, 0.2), (3.0, 1.0)] {
        let plate = SqueezedPlate::new(PlateParams {
            half_length: l,
            thickness: t,
            ..PlateParams::PAPER
        })
        .unwrap();
        let cp = plate.contact_pressure();
        let (beta2, mu_h) = (5.0 * 0.7 / (t * t), 0.3 * t / 2.0);
        let excess = |x: f64| cp.ratio(x) - 1.0;
        let step = 1e-3 * t;
        for i in 1..20 {
            let x = l * f64::from(i) / 20.0;
            let q = integrate(excess, 0.0, x, 400);
            let residual =
                derivative(excess, x, step) - beta2 * mu_h * excess(x) - beta2 * q - beta2 * mu_h;
            assert!(
                residual.abs() < 1e-6 * beta2 * mu_h,
                "L={l} t={t} x={x}: residual {residual}"
            );
        }
        // Mean |P_r/P - 1| by quadrature against the closed form 2 |Q(x0)| / (P L).
        let mean = integrate(|x| excess(x).abs(), 0.0, l, 20_000) / l;
        assert!(
            relative_error(cp.mean_deviation(), mean) < 1e-6,
            "L={l} t={t}: {} vs {mean}",
            cp.mean_deviation()
        );
    }
}

#[test]
fn short_thick_plates_solve_the_plate_equation_too() {
    // Plates shorter than the edge layers ((r_p - r_m) L <= 1) take the power series of (P8); the
    // same residual check as above, with steps scaled to L, and the mean deviation by quadrature.
    use common::integrate;
    for (l, t, nu, mu) in [
        (0.05, 1.0, 0.3, 0.3),
        (1e-3, 0.5, 0.3, 10.0),
        // nu small but not 0: at nu = 0 no friction acts and the pressure is P everywhere (the
        // saturated-friction equation checked here does not apply; src/problems/plate/closed_form.rs tests it).
        (1e-5, 100.0, 1e-3, 1.0),
        (2.0, 1e3, 0.49, 0.05),
    ] {
        let plate = SqueezedPlate::new(PlateParams {
            half_length: l,
            thickness: t,
            poisson: nu,
            friction: mu,
            ..PlateParams::PAPER
        })
        .unwrap();
        let cp = plate.contact_pressure();
        let (beta2, mu_h) = (5.0 * (1.0 - nu) / (t * t), mu * t / 2.0);
        let excess = |x: f64| cp.ratio(x) - 1.0;
        let step = 1e-3 * l;
        for i in 1..20 {
            let x = l * f64::from(i) / 20.0;
            let q = integrate(excess, 0.0, x, 400);
            let residual =
                derivative(excess, x, step) - beta2 * mu_h * excess(x) - beta2 * q - beta2 * mu_h;
            assert!(
                residual.abs() < 1e-6 * beta2 * mu_h,
                "L={l} t={t} x={x}: residual {residual}"
            );
        }
        // Q(L) = 0: the pressure still balances the load.
        let balance = integrate(excess, 0.0, l, 400);
        assert!(
            balance.abs() < 1e-9 * beta2 * mu_h * l * l,
            "L={l} t={t}: {balance}"
        );
        let mean = integrate(|x| excess(x).abs(), 0.0, l, 20_000) / l;
        assert!(
            relative_error(cp.mean_deviation(), mean) < 1e-6,
            "L={l} t={t}: {} vs {mean}",
            cp.mean_deviation()
        );
    }
}

#[test]
fn contact_pressure_is_continuous_where_its_evaluation_switches() {
    // The series serves (r_p - r_m) L <= 1, the exponentials beyond; r_p - r_m = 2 a_2 with
    // a_1 = beta^2 mu h / 2, a_2 = sqrt(a_1^2 + beta^2) (P8).
    let (t, nu, mu) = (0.2, 0.3, 0.3);
    let beta2: f64 = 5.0 * (1.0 - nu) / (t * t);
    let a1 = 0.5 * beta2 * mu * t / 2.0;
    let switch = 1.0 / (2.0 * (a1 * a1 + beta2).sqrt());
    let at = |l: f64| {
        SqueezedPlate::new(PlateParams {
            half_length: l,
            thickness: t,
            poisson: nu,
            friction: mu,
            ..PlateParams::PAPER
        })
        .unwrap()
        .contact_pressure()
    };
    let (below, above) = (at(switch * (1.0 - 1e-9)), at(switch * (1.0 + 1e-9)));
    for (a, b) in [
        (below.ratio(0.0), above.ratio(0.0)),
        (below.mean_deviation(), above.mean_deviation()),
    ] {
        assert!(relative_error(a, b) < 1e-7, "{a} vs {b}");
    }
    // ratio(L) - 1 and ratio(0) - 1 as well (they are small here: compare the deviations).
    let (db, da) = (below.ratio(switch) - 1.0, above.ratio(switch) - 1.0);
    assert!(relative_error(db, da) < 1e-7, "{db} vs {da}");
}

#[test]
fn the_coulomb_end_displacement_does_not_depend_on_the_length() {
    // Once the slide zone l = nu t_p / (mu (1 - nu)) fits in the half-plate, u(L) = kappa l^2 / 2
    // (P3) whatever L, up to the largest accepted L: no L - X_s that rounds to 0.
    let expected = 1.3 * 0.09 * 0.2 * 10.0 / (2.0 * 0.7 * 0.3 * 70_000.0);
    for l in [1.0, 10.0, 1e3, 123_456.7, 1e6] {
        let plate = SqueezedPlate::new(PlateParams {
            half_length: l,
            ..PlateParams::PAPER
        })
        .unwrap();
        let c = plate.coulomb();
        assert_eq!(c.regime(), Regime::STICK_MACROSLIP, "L = {l}");
        assert!(
            relative_error(c.end_displacement(), expected) < 1e-12,
            "L = {l}"
        );
        assert!(relative_error(c.slide_zone(), 0.2 / 0.7) < 1e-15, "L = {l}");
        // The regularized plate at K_T = 1e8: u(L) = u_Coulomb + mu P / (2 K_T) once
        // tanh(alpha X_r) = 1 (see stiff_interface_recovers_coulomb), whatever L.
        let r = plate.with_tangential_stiffness(1e8).unwrap().regularized();
        let gap = r.end_displacement() - expected;
        assert!(relative_error(gap, 3.0 / 2e8) < 1e-6, "L = {l}: {gap}");
        // X_r ~ L + 1/alpha - l (P6) with the macroslip length solved for directly.
        let alpha = (0.91_f64 * 1e8 / (70_000.0 * 0.2)).sqrt();
        assert!(
            relative_error(r.macroslip_length(), 0.2 / 0.7 - 1.0 / alpha) < 1e-9,
            "L = {l}: {}",
            r.macroslip_length()
        );
    }
}

/// (P10): u(L) falls strictly as K_T grows, through the regime change, for plates whose macroslip
/// appears at very different K_T; what `compare plate` relies on to name one implied K_T.
#[test]
fn end_displacement_falls_strictly_with_tangential_stiffness() {
    for (tp, nu, mu, length) in [
        (0.2, 0.3, 0.3, 10.0),
        (1.0, 0.1, 0.05, 3.0),
        (0.05, 0.45, 2.0, 100.0),
    ] {
        let plate = SqueezedPlate::new(PlateParams {
            thickness: tp,
            poisson: nu,
            friction: mu,
            half_length: length,
            ..PlateParams::PAPER
        })
        .unwrap();
        let mut previous = f64::INFINITY;
        let mut regimes = std::collections::HashSet::new();
        for i in 0..=600 {
            let kt = 10f64.powf(-2.0 + 12.0 * f64::from(i) / 600.0);
            let state = plate.with_tangential_stiffness(kt).unwrap().regularized();
            let u = state.end_displacement();
            regimes.insert(state.regime());
            assert!(
                u < previous,
                "t_p {tp}: u(L) = {u} at K_T = {kt}, previous {previous}"
            );
            previous = u;
        }
        assert_eq!(regimes.len(), 2, "the sweep crosses the regime change");
    }
}

/// (P9) The pressure flag judges the peak too: the peak |P_r/P - 1| is at an end (checked against a
/// dense scan of P_r), and the flag flips where that scanned peak crosses 50 % on a long plate whose
/// mean deviation stays small.
#[test]
fn constant_pressure_flag_bounds_the_peak_and_flips_at_its_limit() {
    use microslip::problems::plate::closed_form::PRESSURE_PEAK_LIMIT;
    let plate = |mu: f64| {
        SqueezedPlate::new(PlateParams {
            friction: mu,
            poisson: 0.1,
            half_length: 100.0,
            ..PlateParams::PAPER
        })
        .unwrap()
    };
    let scanned_peak = |mu: f64| {
        let pressure = plate(mu).contact_pressure();
        (0..=4000)
            .map(|i| (pressure.ratio(100.0 * f64::from(i) / 4000.0) - 1.0).abs())
            .fold(0.0_f64, f64::max)
    };
    for mu in [0.1, 0.3, 1.0, 2.0] {
        let peak = plate(mu).contact_pressure().peak_deviation();
        assert!((peak - scanned_peak(mu)).abs() < 1e-12, "mu {mu}");
    }
    // The friction coefficient where the scanned peak reaches the limit, by bisection.
    let (mut lo, mut hi) = (0.1, 2.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if scanned_peak(mid) > PRESSURE_PEAK_LIMIT {
            hi = mid
        } else {
            lo = mid
        }
    }
    let below = plate(lo * (1.0 - 1e-6)).contact_pressure();
    let above = plate(hi * (1.0 + 1e-6)).contact_pressure();
    assert!(below.mean_deviation() < 0.03 && above.mean_deviation() < 0.03);
    assert!(below.constant_pressure_holds(), "mu {lo}");
    assert!(!above.constant_pressure_holds(), "mu {hi}");
    // The case the audit found: "holds" with 2.76 P at the edge before the peak was judged.
    let audit = plate(1.0).contact_pressure();
    assert!((audit.ratio(100.0) - 2.763).abs() < 1e-3);
    assert!(!audit.constant_pressure_holds());
}
