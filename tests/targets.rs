//! Solving for targets and sweeping any parameter, against independent answers: closed-form
//! thresholds inverted by hand, and brute-force bisection written here on the public solution
//! methods (not on the solver under test).

use microslip::problems::inputs::{Inputs, Model};
use microslip::problems::plate::SqueezedPlateProblem;
use microslip::problems::twin_beams::TwinBeamsProblem;
use microslip::problems::twin_beams::problem::BeamsModel;
use microslip::problems::{BeamParam, ModelKind, Param, PlateParam};
use microslip::study::curves::{Samples, Spacing, param_sweep};
use microslip::study::target::{Target, TargetError, solve_for_target};
use microslip::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

/// Plain bisection of a sign change of `f` on [lo, hi] in log space, 200 halvings.
fn bisect_log(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let fa = f(lo);
    assert!(fa * f(hi) < 0.0, "no sign change in [{lo}, {hi}]");
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if f(m.exp()).signum() == fa.signum() {
            a = m;
        } else {
            b = m;
        }
    }
    (0.5 * (a + b)).exp()
}

fn paper(kind: ModelKind) -> Model {
    Inputs::paper(kind).validate().unwrap()
}

#[test]
fn smallest_kt_within_one_percent_of_coulomb_matches_bisection() {
    // Task 1 of issue 16: w(L) within 1 % of Coulomb at F = 100 N (the paper's beams).
    let solved = solve_for_target(
        &paper(ModelKind::Beam),
        Param::Beam(BeamParam::Stiffness),
        Target::parse("ratio=1.01", ModelKind::Beam).unwrap(),
        None,
    )
    .unwrap();
    assert_eq!(solved.roots.len(), 1, "{solved:?}");
    let force = TipForce::new(100.0).unwrap();
    let ratio = |kt: f64| {
        let beams = TwinBeams::new(TwinBeamsParams {
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        beams.regularized(force).tip_deflection() / beams.coulomb(force).tip_deflection() - 1.01
    };
    let brute = bisect_log(ratio, 10.0, 1e5);
    let root = solved.roots[0];
    assert!(root.certified);
    assert!(
        (root.value / brute - 1.0).abs() < 1e-9,
        "{} vs {brute}",
        root.value
    );
    assert!((root.value - 423.0).abs() < 1.0, "the issue's 'about 423'");
}

#[test]
fn kt_for_a_given_first_macroslip_force_inverts_the_closed_form() {
    // F_1 = F_thre / (1 - sech kL), k = 2 sqrt(K_T / (E h)) (theory (B7)), inverted by hand:
    // kL = acosh(1 / (1 - F_thre / F_1)), K_T = (k / 2)^2 E h.
    let p = TwinBeamsParams::PAPER;
    let f_thre = 4.0 * p.friction * p.width * p.half_height * p.pressure / 3.0;
    for f1 in [80.5, 90.0, 150.0] {
        let kl = (1.0 / (1.0 - f_thre / f1)).acosh();
        let expected = (kl / p.length / 2.0).powi(2) * p.youngs_modulus * p.half_height;
        let solved = solve_for_target(
            &paper(ModelKind::Beam),
            Param::Beam(BeamParam::Stiffness),
            Target::parse(&format!("F_1={f1}"), ModelKind::Beam).unwrap(),
            None,
        )
        .unwrap();
        assert_eq!(solved.roots.len(), 1);
        assert!(
            (solved.roots[0].value / expected - 1.0).abs() < 1e-9,
            "F_1 = {f1}: {} vs {expected}",
            solved.roots[0].value
        );
    }
}

#[test]
fn plate_macroslip_onset_is_where_the_regime_changes() {
    // Task 3 of issue 16: the paper's plate. Brute force: bisect the regime itself over K_T.
    let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
    let onset = plate.macroslip_onset_stiffness().unwrap();
    let slides = |kt: f64| {
        let p = plate.with_tangential_stiffness(kt).unwrap();
        if p.regularized().regime().has_macroslip() {
            1.0
        } else {
            -1.0
        }
    };
    let brute = bisect_log(slides, 1.0, 1e9);
    assert!((onset / brute - 1.0).abs() < 1e-9, "{onset} vs {brute}");
    assert!(
        (onset - 188_465.0).abs() < 10.0,
        "the issue's 'about 188 465': {onset}"
    );
    // coth(alpha L) / alpha = l_s there (the closed form).
    let p = PlateParams::PAPER;
    let alpha = ((1.0 - p.poisson * p.poisson) * onset / (p.youngs_modulus * p.thickness)).sqrt();
    let slide_length = p.poisson * p.thickness / (p.friction * (1.0 - p.poisson));
    let lhs = 1.0 / (alpha * p.half_length).tanh() / alpha;
    assert!((lhs / slide_length - 1.0).abs() < 1e-12);
    // The solver finds the same edge as the end of the plateau X_r = L.
    let solved = solve_for_target(
        &paper(ModelKind::Plate),
        Param::Plate(PlateParam::Stiffness),
        Target::parse("X_r=10", ModelKind::Plate).unwrap(),
        None,
    )
    .unwrap();
    assert_eq!(solved.roots.len(), 1);
    assert!(solved.roots[0].plateau);
    assert!((solved.roots[0].value / onset - 1.0).abs() < 1e-9);
    // nu = 0: nothing slides at any K_T.
    let flat = SqueezedPlate::new(PlateParams {
        poisson: 0.0,
        ..PlateParams::PAPER
    })
    .unwrap();
    assert_eq!(flat.macroslip_onset_stiffness(), None);
}

#[test]
fn onset_over_many_plates_agrees_with_the_regime() {
    for (l, t, nu, mu) in [
        (10.0, 0.2, 0.3, 0.3),
        (1.0, 1.0, 0.45, 0.05),
        (1000.0, 0.01, 0.01, 1.0),
        (0.01, 5.0, 0.2, 0.8),
    ] {
        let plate = SqueezedPlate::new(PlateParams {
            half_length: l,
            thickness: t,
            poisson: nu,
            friction: mu,
            ..PlateParams::PAPER
        })
        .unwrap();
        let Some(onset) = plate.macroslip_onset_stiffness() else {
            panic!("no onset for {l} {t} {nu} {mu}");
        };
        for (factor, slides) in [(0.999, false), (1.001, true)] {
            let kt = onset * factor;
            if (1e-6..=1e12).contains(&kt) {
                let p = plate.with_tangential_stiffness(kt).unwrap();
                assert_eq!(
                    p.regularized().regime().has_macroslip(),
                    slides,
                    "{l} {t} {nu} {mu}: K_T = {kt}"
                );
            }
        }
    }
}

#[test]
fn two_roots_are_both_found_and_none_is_an_error() {
    // The ratio to Coulomb is never below 1: no mu gives 0.9, and the error says so.
    let model = paper(ModelKind::Beam);
    let err = solve_for_target(
        &model,
        Param::Beam(BeamParam::Friction),
        Target::parse("ratio=0.9", ModelKind::Beam).unwrap(),
        None,
    )
    .unwrap_err();
    assert!(matches!(err, TargetError::NoRoot { .. }), "{err}");
    // zeta against mu at F = 100 N: zero while mu is so large that nothing slides, zero again as
    // mu -> 0 (no friction, nothing dissipated): a hump, so a small target has two roots.
    let solved = solve_for_target(
        &model,
        Param::Beam(BeamParam::Friction),
        Target::parse("zeta=0.01", ModelKind::Beam).unwrap(),
        None,
    )
    .unwrap();
    assert_eq!(solved.roots.len(), 2, "{solved:?}");
    for root in &solved.roots {
        assert!(root.certified && (root.achieved / 0.01 - 1.0).abs() < 1e-6);
    }
}

#[test]
fn sweeps_of_any_parameter_equal_the_model_at_each_value() {
    // Task 2 of issue 16: w(L) at F = 120 N for mu from 0.1 to 0.5.
    let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
    let force = TipForce::new(120.0).unwrap();
    let values = Samples::of_param(
        Param::Beam(BeamParam::Friction),
        0.1,
        0.5,
        9,
        Spacing::Linear,
    )
    .unwrap();
    let model = BeamsModel { beams, force };
    let rows: Vec<_> = param_sweep::<TwinBeamsProblem>(model, BeamParam::Friction, values)
        .unwrap()
        .collect();
    assert_eq!(rows.len(), 9);
    for (mu, row) in rows {
        let direct = TwinBeams::new(TwinBeamsParams {
            friction: mu,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        assert_eq!(
            row.w_regularized,
            direct.regularized(force).tip_deflection()
        );
        assert_eq!(row.force, 120.0);
    }
    // One point is a sweep too.
    let one = Samples::of_param(
        Param::Plate(PlateParam::Poisson),
        0.2,
        0.2,
        1,
        Spacing::Linear,
    )
    .unwrap();
    let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
    let rows: Vec<_> = param_sweep::<SqueezedPlateProblem>(plate, PlateParam::Poisson, one)
        .unwrap()
        .collect();
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0].0, 0.2);
    assert!(
        Samples::of_param(
            Param::Plate(PlateParam::Poisson),
            0.2,
            0.3,
            1,
            Spacing::Linear
        )
        .is_err()
    );
}
