//! Cyclic loading of the twin beams: Masing branches and dissipation against the independent
//! finite-element solver driven through the same cycle, the Coulomb closed form derived from friction
//! work, the K_T -> infinity limit, and the amplitude exponents.

use microslip::numeric::MeshDensity;
use microslip::problems::twin_beams::TwinBeamsFe;
use microslip::problems::twin_beams::cycle::{BeamsCycle, Law, MasingCycle};
use microslip::{TipForce, TwinBeams, TwinBeamsParams};

fn beams(kt: f64) -> TwinBeams {
    TwinBeams::new(TwinBeamsParams {
        tangential_stiffness: kt,
        ..TwinBeamsParams::PAPER
    })
    .unwrap()
}

fn cycle(kt: f64, law: Law, amplitude: f64) -> BeamsCycle {
    BeamsCycle::new(&beams(kt), law, TipForce::new(amplitude).unwrap())
}

#[test]
fn finite_elements_driven_round_the_cycle_follow_the_masing_branches() {
    // The FE model never uses Masing's rule: each Gauss point keeps its own slider history.
    for (kt, amplitude) in [(120.0, 150.0), (600.0, 100.0), (600.0, 300.0)] {
        let params = TwinBeamsParams {
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        };
        let exact = cycle(kt, Law::Regularized, amplitude);
        let mut fe = TwinBeamsFe::new(params, MeshDensity::with_elements(100));
        fe.load_to(amplitude, 8).unwrap();
        let steps = 80;
        let mut loop_points = vec![(amplitude, fe.tip_deflection())];
        for (from, branch) in [(amplitude, -1.0), (-amplitude, 1.0)] {
            for i in 1..=steps {
                let f = from + branch * 2.0 * amplitude * f64::from(i) / f64::from(steps);
                fe.load_to(f, 1).unwrap();
                let w = fe.tip_deflection();
                let expected = if branch < 0.0 {
                    exact.unloading(f)
                } else {
                    exact.reloading(f)
                };
                assert!(
                    (w - expected).abs() < 1e-5 * exact.peak_deflection(),
                    "K_T={kt} F_a={amplitude} F={f}: {w} vs {expected}"
                );
                loop_points.push((f, w));
            }
        }
        // Energy through the two tips: 2 x loop area, trapezoidal rule over the FE points.
        let area: f64 = loop_points
            .windows(2)
            .map(|p| 0.5 * (p[0].0 + p[1].0) * (p[1].1 - p[0].1))
            .sum();
        let d = exact.dissipation();
        assert!(
            (2.0 * area / d - 1.0).abs() < 2e-3,
            "K_T={kt} F_a={amplitude}: FE {} vs {d}",
            2.0 * area
        );
    }
}

#[test]
fn dissipation_formula_equals_the_area_of_its_own_loop() {
    // (C3) is an algebraic shortcut; integrate the branches directly instead (Simpson, 20000 steps).
    for (law, amplitude) in [
        (Law::Regularized, 95.0),
        (Law::Regularized, 400.0),
        (Law::Coulomb, 150.0),
    ] {
        let c = cycle(120.0, law, amplitude);
        let n = 20_000;
        let h = 2.0 * amplitude / f64::from(n);
        let gap = |f: f64| c.unloading(f) - c.reloading(f);
        let simpson: f64 = (0..=n)
            .map(|i| {
                let weight = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                weight * gap(-amplitude + h * f64::from(i))
            })
            .sum::<f64>()
            * h
            / 3.0;
        let d = c.dissipation();
        assert!(
            (2.0 * simpson / d - 1.0).abs() < 1e-6,
            "{law:?} F_a={amplitude}: {} vs {d}",
            2.0 * simpson
        );
    }
}

#[test]
fn stiff_interface_dissipates_like_coulomb() {
    for amplitude in [100.0, 200.0, 800.0] {
        let coulomb = cycle(1.0, Law::Coulomb, amplitude).dissipation();
        let gaps: Vec<f64> = [1e4, 1e6, 1e8]
            .iter()
            .map(|&kt| (cycle(kt, Law::Regularized, amplitude).dissipation() / coulomb - 1.0).abs())
            .collect();
        assert!(
            gaps[0] > gaps[1] && gaps[1] > gaps[2],
            "F_a={amplitude}: {gaps:?}"
        );
        assert!(gaps[2] < 1e-3, "F_a={amplitude}: {gaps:?}");
    }
}

#[test]
fn amplitude_exponents() {
    let b = beams(120.0);
    let f1 = b.first_macroslip_force();
    let d =
        |fa: f64| BeamsCycle::new(&b, Law::Regularized, TipForce::new(fa).unwrap()).dissipation();
    // Just above F_1: D ~ (F_a - F_1)^(3/2) (docs/theory.md, (C6)).
    let slope = (d(f1 * (1.0 + 1e-5)) / d(f1 * (1.0 + 1e-6))).log10();
    assert!(
        (slope - 1.5).abs() < 0.05,
        "small-amplitude exponent {slope}"
    );
    // Far above: D ~ F_a - F_thre, like Coulomb (the whole interface slides at mu P each cycle).
    let slope = (d(8e4) / d(8e3)).log10();
    let coulomb_slope = ((8e4 - 80.0) / (8e3 - 80.0_f64)).log10();
    assert!(
        (slope - coulomb_slope).abs() < 2e-3,
        "large-amplitude exponent {slope} vs {coulomb_slope}"
    );
    // D grows with the amplitude; the secant stiffness falls.
    let mut last = (0.0, f64::INFINITY);
    for i in 1..200 {
        let c = BeamsCycle::new(
            &b,
            Law::Regularized,
            TipForce::new(2.0 * f64::from(i)).unwrap(),
        );
        let now = (c.dissipation(), c.secant_stiffness());
        assert!(
            now.0 >= last.0 && now.1 <= last.1 * (1.0 + 1e-12),
            "F_a={}",
            2 * i
        );
        last = now;
    }
}

#[test]
fn coulomb_damping_peaks_at_2_over_3_pi_at_one_and_a_half_times_the_threshold() {
    // zeta = 6 (r - 1) / (pi r (4 r - 3)), r = F_a / F_thre (docs/theory.md, (C6)), for any beam.
    for params in [
        TwinBeamsParams::PAPER,
        TwinBeamsParams {
            length: 500.0,
            half_height: 3.0,
            friction: 0.7,
            ..TwinBeamsParams::PAPER
        },
    ] {
        let b = TwinBeams::new(params).unwrap();
        let ft = b.threshold_force();
        let zeta = |r: f64| {
            BeamsCycle::new(&b, Law::Coulomb, TipForce::new(r * ft).unwrap()).damping_ratio()
        };
        let peak = 2.0 / (3.0 * std::f64::consts::PI);
        assert!((zeta(1.5) - peak).abs() < 1e-12);
        assert!(zeta(1.45) < peak && zeta(1.55) < peak);
        let r = 4.0;
        assert!(
            (zeta(r) - 6.0 * (r - 1.0) / (std::f64::consts::PI * r * (4.0 * r - 3.0))).abs()
                < 1e-12
        );
    }
}

#[test]
fn coulomb_cycle_sticks_below_threshold_and_slides_linearly_above() {
    assert_eq!(cycle(600.0, Law::Coulomb, 80.0).dissipation(), 0.0);
    let (d1, d2) = (
        cycle(600.0, Law::Coulomb, 100.0).dissipation(),
        cycle(600.0, Law::Coulomb, 120.0).dissipation(),
    );
    // Linear in F_a - F_thre: D(120) / D(100) = 40 / 20.
    assert!((d2 / d1 - 2.0).abs() < 1e-12);
}

/// (C4) written out: D = 4 mu P L^3 (F_a - F_thre) / (E h^2), F_thre = 4 mu b h P / 3.
fn coulomb_dissipation(p: &TwinBeamsParams, amplitude: f64) -> f64 {
    let threshold = 4.0 * p.friction * p.width * p.half_height * p.pressure / 3.0;
    4.0 * p.friction * p.pressure * p.length.powi(3) * (amplitude - threshold)
        / (p.youngs_modulus * p.half_height * p.half_height)
}

/// 1 - D_reg / D_Coulomb predicted for an X small against L: D_reg / D_C = ((L - X) / L)^3
/// ((C3)-(C4)) and X ~ q / (k^2 L), q = F_thre / (F_a - F_thre), k = 2 sqrt(K_T / (E h)) (the
/// small-z asymptote of (B8)), so 1 - D_reg / D_C ~ 3 q / (k L)^2.
fn predicted_shortfall(p: &TwinBeamsParams, amplitude: f64) -> f64 {
    let threshold = 4.0 * p.friction * p.width * p.half_height * p.pressure / 3.0;
    let q = threshold / (amplitude - threshold);
    let kl = 2.0 * (p.tangential_stiffness / (p.youngs_modulus * p.half_height)).sqrt() * p.length;
    3.0 * q / (kl * kl)
}

#[test]
fn dissipation_keeps_its_precision_up_to_the_largest_amplitude() {
    // The paper's beams up to F_a = 1e12 N (1.25e10 F_thre), and a beam of the smallest accepted
    // cross-section where F_a / F_thre reaches 1e35. Coulomb against (C4) to 1e-13; the regularized
    // law against the Coulomb law through the predicted shortfall, to 1e-3 of it (its rounding,
    // ~4e-16, allowed for). The earlier loop-area form lost 3e-6 at 1e12 N and gave a regularized
    // D of 0.4 times the Coulomb one at 1e17 N.
    let tiny = TwinBeamsParams {
        width: 1e-6,
        half_height: 1e-6,
        pressure: 1e-6,
        friction: 1e-6,
        ..TwinBeamsParams::PAPER
    };
    for params in [TwinBeamsParams::PAPER, tiny] {
        let b = TwinBeams::new(params).unwrap();
        for amplitude in [1e4, 1e8, 1e11, 1e12] {
            let force = TipForce::new(amplitude).unwrap();
            let (c, r) = (
                BeamsCycle::new(&b, Law::Coulomb, force).dissipation(),
                BeamsCycle::new(&b, Law::Regularized, force).dissipation(),
            );
            let exact = coulomb_dissipation(&params, amplitude);
            assert!(
                (c / exact - 1.0).abs() < 1e-13,
                "{params:?} F_a={amplitude}: {c} vs {exact}"
            );
            let (shortfall, predicted) = (1.0 - r / c, predicted_shortfall(&params, amplitude));
            assert!(
                (shortfall - predicted).abs() <= 1e-3 * predicted + 4.0 * f64::EPSILON,
                "{params:?} F_a={amplitude}: 1 - D_reg/D_C = {shortfall}, predicted {predicted}"
            );
        }
    }
}

#[test]
fn regularized_dissipation_tends_to_coulomb_as_the_interface_stiffens() {
    // K_T -> infinity at a fixed amplitude: the same shortfall 3 q / (k L)^2 -> 0, checked to 1e-3
    // of itself from K_T = 1e6 to the largest accepted 1e12 MPa/mm, against (C4) written out.
    for amplitude in [100.0, 800.0] {
        for kt in [1e6, 1e8, 1e10, 1e12] {
            let params = TwinBeamsParams {
                tangential_stiffness: kt,
                ..TwinBeamsParams::PAPER
            };
            let d = cycle(kt, Law::Regularized, amplitude).dissipation();
            let shortfall = 1.0 - d / coulomb_dissipation(&params, amplitude);
            let predicted = predicted_shortfall(&params, amplitude);
            assert!(
                (shortfall - predicted).abs() <= 1e-3 * predicted + 4.0 * f64::EPSILON,
                "K_T={kt} F_a={amplitude}: {shortfall} vs {predicted}"
            );
        }
    }
}
