//! Properties every twin-beam solution must have, each checked against something other than the code
//! under test: hand limits, the equilibrium and kinematics the closed forms were derived from
//! (re-integrated here numerically), continuity, monotonicity and dimensional scaling.

mod common;

use common::{derivative, integrate, relative_error, second_derivative};
use microslip::{Regime, RegularizedBeams, TipForce, TwinBeams, TwinBeamsParams};

fn beams_with(kt: f64) -> TwinBeams {
    TwinBeams::new(TwinBeamsParams {
        tangential_stiffness: kt,
        ..TwinBeamsParams::PAPER
    })
    .unwrap()
}

fn force(f: f64) -> TipForce {
    TipForce::new(f).unwrap()
}

/// Integral of tau over [from, L], by quadrature split at X where tau has a kink.
fn shear_resultant(state: &RegularizedBeams, from: f64, length: f64, panels: usize) -> f64 {
    let x = state.micro_zone_end();
    let tau = |s: f64| state.shear_stress(s);
    if from < x {
        integrate(tau, from, x, panels) + integrate(tau, x, length, panels)
    } else {
        integrate(tau, from, length, panels)
    }
}

#[test]
fn stiff_interface_recovers_coulomb_with_the_hand_derived_asymptotics() {
    // docs/theory.md, "Limit K_T -> infinity". In stick (F < F_thre) the only boundary layer sits at the
    // clamp, where the lever arm vanishes, so w/w_Coulomb - 1 ~ 9 / (kL)^2. In slip the microslip zone
    // shrinks to X ~ q / (k^2 L), q = F_thre / (F - F_thre), and w/w_Coulomb - 1 ~ mu P b h X^2 /
    // (2 (F - mu P b h) L^2): both vanish as K_T -> infinity, at the predicted rates.
    let (length, mu_p_bh) = (200.0, 0.3 * 1.0 * 20.0 * 10.0);
    for kt in [1e5, 1e7, 1e9] {
        let beams = beams_with(kt);
        let lambda = beams.decay_rate() * length;
        for f in [40.0, 79.0] {
            let coulomb = beams.coulomb(force(f)).tip_deflection();
            let gap = beams.regularized(force(f)).tip_deflection() / coulomb - 1.0;
            let predicted = 9.0 / (lambda * lambda);
            assert!(
                (gap / predicted - 1.0).abs() < 1.5 / lambda,
                "K_T={kt} F={f}: gap {gap}, predicted {predicted}"
            );
        }
        if kt > 1e8 {
            continue; // the slip gap (~1e-15) is below f64 resolution of w(L)
        }
        for f in [100.0, 300.0] {
            let state = beams.regularized(force(f));
            let q = 80.0 / (f - 80.0);
            let k = beams.decay_rate();
            let x = state.micro_zone_end();
            assert!(
                relative_error(x, q / (k * k * length)) < 2e-3,
                "K_T={kt} F={f}: X = {x}"
            );
            let coulomb = beams.coulomb(force(f)).tip_deflection();
            let gap = state.tip_deflection() / coulomb - 1.0;
            let predicted = mu_p_bh * x * x / (2.0 * (f - mu_p_bh) * length * length);
            assert!(
                relative_error(gap, predicted) < 2e-2,
                "K_T={kt} F={f}: gap {gap}, predicted {predicted}"
            );
        }
    }
    // Thresholds converge too: F_1 -> F_thre.
    let stiff = beams_with(1e9);
    assert!(relative_error(stiff.first_macroslip_force(), stiff.threshold_force()) < 1e-12);
}

#[test]
fn soft_interface_decouples_the_beams() {
    // K_T -> 0: no shear transfer, each beam bends alone: w(L) = F L^3 / (3 E (2 b h^3 / 3)).
    let alone = 50.0 * 200.0_f64.powi(3) / (2.0 * 210_000.0 * 20.0 * 1000.0);
    let w = beams_with(1e-3).regularized(force(50.0)).tip_deflection();
    // The first correction is O((kL)^2) = 7.6e-5 here.
    assert!(relative_error(w, alone) < 1e-4, "{w} vs {alone}");
    assert!(w < alone);
}

#[test]
fn solution_satisfies_equilibrium_kinematics_and_the_friction_law() {
    // Re-check the derivation numerically: with T(x) = int_x^L tau,
    //   moment:      w''(x) = 3 (F (L - x) - h b T(x)) / (2 E b h^3)
    //   kinematics:  slip(x) = 2 (h w'(x) - u0(x)),  u0(x) = int_0^x T / (2 E h)
    //   law:         tau = K_T slip <= mu P in microslip, tau = mu P and slip >= mu P / K_T beyond X.
    let (length, width, h, e) = (200.0, 20.0, 10.0, 210_000.0);
    for kt in [0.05, 120.0, 600.0, 2e4] {
        let beams = beams_with(kt);
        let k = beams.decay_rate();
        for f in [30.0, beams.first_macroslip_force(), 95.0, 160.0, 600.0] {
            let state = beams.regularized(force(f));
            let panels = ((length * k * 4.0) as usize).max(200);
            let step = (length * 1e-3).min(0.02 / k);
            let saturation = beams.saturation_slip();
            for i in 1..20 {
                let x = length * f64::from(i) / 20.0;
                let resultant = shear_resultant(&state, x, length, panels);
                let curvature = second_derivative(|s| state.deflection(s), x, step);
                let moment = 3.0 * (f * (length - x) - h * width * resultant)
                    / (2.0 * e * width * h.powi(3));
                assert!(
                    (curvature - moment).abs() <= 1e-6 * moment.abs().max(1e-12),
                    "K_T={kt} F={f} x={x}: w'' = {curvature}, moment/EI = {moment}"
                );
                // u0(x) = int_0^L tau(s) min(s, x) ds / (2 E h), split at x and X.
                let xm = state.micro_zone_end();
                let weighted = |s: f64| state.shear_stress(s) * s.min(x);
                let mut cuts = [0.0, x, xm, length];
                cuts.sort_by(f64::total_cmp);
                let u0 = cuts
                    .windows(2)
                    .map(|c| integrate(weighted, c[0], c[1], panels))
                    .sum::<f64>()
                    / (2.0 * e * h);
                let slope = derivative(|s| state.deflection(s), x, step);
                let kinematic = 2.0 * (h * slope - u0);
                let slip = state.slip(x);
                assert!(
                    (kinematic - slip).abs() <= 1e-7 * slip.abs().max(saturation),
                    "K_T={kt} F={f} x={x}: kinematic slip {kinematic}, solution {slip}"
                );
                let tau = state.shear_stress(x);
                if x < xm {
                    assert!(relative_error(tau, kt * slip) < 1e-12 || tau == 0.0);
                    assert!(tau <= beams.coulomb_stress() * (1.0 + 1e-12));
                } else {
                    assert_eq!(tau, beams.coulomb_stress());
                    assert!(slip >= saturation * (1.0 - 1e-12));
                }
            }
        }
    }
}

#[test]
fn tip_deflection_is_continuous_at_f1_and_x_leaves_l_like_a_square_root() {
    for kt in [1e-2, 120.0, 600.0, 1e4] {
        let beams = beams_with(kt);
        let f1 = beams.first_macroslip_force();
        let below = beams.regularized(force(f1 * (1.0 - 1e-10)));
        let above = beams.regularized(force(f1 * (1.0 + 1e-10)));
        assert_eq!(below.regime(), Regime::MICROSLIP);
        assert_eq!(above.regime(), Regime::MICROSLIP_MACROSLIP);
        assert!(
            relative_error(above.tip_deflection(), below.tip_deflection()) < 1e-8,
            "K_T={kt}"
        );
        // g'(kL) = 0 at F_1, so X leaves L like a square root (docs/theory.md):
        // k (L - X) ~ sqrt(2 (1 - r / cosh kL)), r = F / (F - F_thre).
        let lambda = beams.decay_rate() * 200.0;
        for eps in [1e-6, 1e-8] {
            let f = f1 * (1.0 + eps);
            let gap = beams.decay_rate() * (200.0 - beams.regularized(force(f)).micro_zone_end());
            let r = f / (f - beams.threshold_force());
            let predicted = (2.0 * (1.0 - r / lambda.cosh())).sqrt();
            if kt > 1e3 {
                // F_1 / F_thre - 1 ~ 2 exp(-kL) = 2e-12 here: eps is far outside the asymptotic range.
                continue;
            }
            assert!(
                relative_error(gap, predicted) < 1e-2,
                "K_T={kt} eps={eps}: k(L-X) = {gap}, predicted {predicted}"
            );
        }
    }
}

#[test]
fn x_falls_and_deflection_rises_with_force() {
    for kt in [1.0, 120.0, 600.0, 1e5, 1e9] {
        let beams = beams_with(kt);
        let (f_thre, f1) = (beams.threshold_force(), beams.first_macroslip_force());
        let mut last_x = f64::INFINITY;
        let mut last_w = -1.0;
        let mut last_wc = -1.0;
        // Log-spaced forces from 1e-3 F_thre to 1e3 F_thre, plus a dense run just above F_1.
        let mut forces: Vec<f64> = (0..=300)
            .map(|i| f_thre * 10f64.powf(-3.0 + 6.0 * f64::from(i) / 300.0))
            .collect();
        forces.extend((1..50).map(|i| f1 * (1.0 + 1e-6 * f64::from(i))));
        forces.sort_by(f64::total_cmp);
        for f in forces {
            let state = beams.regularized(force(f));
            let (x, w) = (state.micro_zone_end(), state.tip_deflection());
            let wc = beams.coulomb(force(f)).tip_deflection();
            assert!(x <= last_x, "K_T={kt} F={f}: X rose to {x} from {last_x}");
            assert!(w > last_w && wc > last_wc, "K_T={kt} F={f}");
            if state.regime() == Regime::MICROSLIP_MACROSLIP {
                assert!(
                    x < last_x || x == 0.0,
                    "K_T={kt} F={f}: X not strictly falling"
                );
            }
            // The elastic interface is softer than the Coulomb one in stick, stiffer in slip.
            if f <= f_thre {
                assert!(w >= wc * (1.0 - 1e-12), "K_T={kt} F={f}");
            }
            (last_x, last_w, last_wc) = (x, w, wc);
        }
    }
}

#[test]
fn solutions_are_invariant_under_a_change_of_units() {
    // Lengths x s, stresses x sigma: F x sigma s^2, K_T x sigma / s; then w, X x s and tau x sigma.
    let base = TwinBeamsParams {
        tangential_stiffness: 120.0,
        ..TwinBeamsParams::PAPER
    };
    // mm -> m, MPa -> GPa (forces in GN): SI's Pa would put E = 2.1e11 beyond the accepted
    // [1e-4, 1e7] MPa, which is what it is meant to catch.
    let (s, sigma) = (1e-3, 1e-3);
    let scaled = TwinBeamsParams {
        length: base.length * s,
        width: base.width * s,
        half_height: base.half_height * s,
        youngs_modulus: base.youngs_modulus * sigma,
        pressure: base.pressure * sigma,
        friction: base.friction,
        tangential_stiffness: base.tangential_stiffness * sigma / s,
        ..base
    };
    let (a, b) = (
        TwinBeams::new(base).unwrap(),
        TwinBeams::new(scaled).unwrap(),
    );
    assert!(
        relative_error(
            b.first_macroslip_force(),
            a.first_macroslip_force() * sigma * s * s
        ) < 1e-13
    );
    for f in [20.0, 85.0, 100.0, 200.0, 1e4] {
        let (ra, rb) = (
            a.regularized(force(f)),
            b.regularized(force(f * sigma * s * s)),
        );
        assert_eq!(ra.regime(), rb.regime());
        assert!(
            relative_error(rb.tip_deflection(), ra.tip_deflection() * s) < 1e-11,
            "F={f}"
        );
        assert!(
            relative_error(rb.micro_zone_end(), ra.micro_zone_end() * s) < 1e-11,
            "F={f}"
        );
        assert!(
            relative_error(rb.deflection(100.0 * s), ra.deflection(100.0) * s) < 1e-11,
            "F={f}"
        );
        assert!(
            relative_error(rb.shear_stress(50.0 * s), ra.shear_stress(50.0) * sigma) < 1e-11,
            "F={f}"
        );
    }
}

#[test]
fn microslip_boundary_solves_its_equation_to_1e_10_everywhere() {
    // Independent transcription of (B8): continuity of the slip gradient at X,
    //   k [tau_b / sinh(kX) + (mu P - tau_b) coth(kX)] = k^2 (L - X) (tau_b - mu P),
    // checked as a sign change across X (1 -+ 1e-10), evaluated in extended form where it can be.
    for kt in [1e-3, 1.0, 600.0, 1e5, 1e9] {
        let beams = beams_with(kt);
        let k = beams.decay_rate();
        for factor in [1.000_001, 1.01, 2.0, 10.0, 1e3] {
            let f = factor * beams.first_macroslip_force();
            if f > 1e3 * beams.threshold_force() * 1.0001 {
                continue;
            }
            let state = beams.regularized(force(f));
            assert_eq!(state.regime(), Regime::MICROSLIP_MACROSLIP);
            let x = state.micro_zone_end();
            let tb = 3.0 * f / (4.0 * 20.0 * 10.0);
            let g = |s: f64| {
                let z = k * s;
                let (inv_sinh, coth) = if z > 300.0 {
                    (0.0, 1.0)
                } else {
                    (1.0 / z.sinh(), 1.0 / z.tanh())
                };
                (tb * inv_sinh + (0.3 - tb) * coth) / (tb - 0.3) - k * (200.0 - s)
            };
            let (lo, hi) = (g(x * (1.0 - 1e-10)), g(x * (1.0 + 1e-10)));
            assert!(
                lo * hi <= 0.0,
                "K_T={kt} F={f}: X={x}, g(X-)={lo}, g(X+)={hi}"
            );
        }
    }
}

#[test]
fn every_corner_of_the_domain_gives_finite_physical_numbers() {
    let shapes = [
        TwinBeamsParams::PAPER,
        TwinBeamsParams {
            length: 1e4,
            half_height: 0.01,
            ..TwinBeamsParams::PAPER
        },
        TwinBeamsParams {
            length: 0.01,
            half_height: 100.0,
            youngs_modulus: 1.0,
            ..TwinBeamsParams::PAPER
        },
        TwinBeamsParams {
            friction: 5.0,
            pressure: 1e3,
            ..TwinBeamsParams::PAPER
        },
    ];
    for shape in shapes {
        for kt in [1e-3, 1e-1, 10.0, 1e3, 1e5, 1e7, 1e9] {
            let beams = TwinBeams::new(TwinBeamsParams {
                tangential_stiffness: kt,
                ..shape
            })
            .unwrap();
            let f_thre = beams.threshold_force();
            for factor in [0.0, 1e-9, 0.5, 1.0, 1.0 + 1e-12, 1.5, 10.0, 1e3] {
                let f = factor * f_thre;
                for state in [beams.regularized(force(f))] {
                    let x = state.micro_zone_end();
                    assert!(
                        (0.0..=shape.length).contains(&x),
                        "{shape:?} K_T={kt} F={f}: X={x}"
                    );
                    for s in [0.0, 0.3 * shape.length, x, shape.length] {
                        let values = [state.deflection(s), state.shear_stress(s), state.slip(s)];
                        assert!(
                            values.iter().all(|v| v.is_finite() && *v >= 0.0),
                            "{shape:?} K_T={kt} F={f} x={s}: {values:?}"
                        );
                    }
                }
                let c = beams.coulomb(force(f));
                assert!(c.tip_deflection().is_finite() && c.slip(shape.length).is_finite());
            }
        }
    }
}

/// (B13) Timoshenko: in the bonded limit (stiff interface, below F_thre) the pair is one beam of
/// height 4h under 2F; its tip deflection with shear is 2F L^3 / (3 E I) + 2F L / (kappa G b 4h),
/// I = b (4h)^3 / 12, written out here by hand. Soft interface: two free beams of height 2h under F.
#[test]
fn timoshenko_deflection_matches_hand_derived_limits() {
    use microslip::problems::twin_beams::closed_form::BeamTheory;
    let p = TwinBeamsParams {
        tangential_stiffness: 1e12,
        poisson: 0.25,
        theory: BeamTheory::Timoshenko,
        ..TwinBeamsParams::PAPER
    };
    let g = p.youngs_modulus / (2.0 * 1.25);
    let f = 40.0;
    let inertia = p.width * (4.0 * p.half_height).powi(3) / 12.0;
    let bonded = 2.0 * f * p.length.powi(3) / (3.0 * p.youngs_modulus * inertia)
        + 2.0 * f * p.length / (5.0 / 6.0 * g * p.width * 4.0 * p.half_height);
    let w = TwinBeams::new(p)
        .unwrap()
        .coulomb(force(f))
        .tip_deflection();
    assert!(relative_error(w, bonded) < 1e-12, "{w} vs {bonded}");
    let regularized = TwinBeams::new(p)
        .unwrap()
        .regularized(force(f))
        .tip_deflection();
    assert!(
        relative_error(regularized, bonded) < 1e-4,
        "{regularized} vs {bonded}"
    );
    let soft = TwinBeamsParams {
        tangential_stiffness: 1e-6,
        ..p
    };
    let inertia = p.width * (2.0 * p.half_height).powi(3) / 12.0;
    let free = f * p.length.powi(3) / (3.0 * p.youngs_modulus * inertia)
        + f * p.length / (5.0 / 6.0 * g * p.width * 2.0 * p.half_height);
    let w = TwinBeams::new(soft)
        .unwrap()
        .regularized(force(f))
        .tip_deflection();
    assert!(relative_error(w, free) < 1e-6, "{w} vs {free}");
}
