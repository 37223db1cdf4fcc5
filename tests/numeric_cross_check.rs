//! The closed forms against the project's own finite-element solvers (which never call them), and
//! the solvers' loading-history behaviour on load-unload-reload cycles.

mod common;

use common::{reference_rows, relative_error};
use microslip::numeric::MeshDensity;
use microslip::problems::ModelKind;
use microslip::problems::plate::PlateFe;
use microslip::problems::twin_beams::TwinBeamsFe;
use microslip::verify::{self, Grid};
use microslip::{PlateParams, Regime, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};
use proptest::prelude::*;

#[test]
fn quick_grid_agrees_far_below_the_target() {
    // Target of the issue: 1e-3 at the default mesh. Measured worst case: ~1e-6 for the beams
    // and the plate; 3.4e-5 (Delta) and 1.6e-5 L (zones) for the lap joint at K_T = 1e5 MPa/mm,
    // where its mesh is the 12 elements per 1/lambda of `LapFe` (docs/theory.md section 5).
    for worst in verify::run(Grid::Quick, MeshDensity::default()).unwrap() {
        assert!(worst.cases >= 6, "{worst:?}");
        // The cylinder: c/a to 4.3e-4 at K_T = 1e7 MPa/mm, Q = 0.6 mu P on the discretized
        // solver's default cells (docs/theory.md section 11): the 1e-3 target.
        // The press fit, pushed out or twisted, is the same two-bar solver as the lap joint
        // (12 elements per 1/lambda at least): 2.5e-5 measured on theta at K_T = 1e5 MPa/mm,
        // the #98 fit twisted (lambda L = 10, its torsional rigidities make lambda 1.8 times the
        // push-out's).
        let bound = match worst.quantity.kind() {
            ModelKind::Lap | ModelKind::PressFit | ModelKind::PressFitTorque => 1e-4,
            ModelKind::Cylinder => 1e-3,
            _ => 2e-5,
        };
        assert!(worst.error < bound, "{worst:?}");
    }
}

#[test]
fn errors_shrink_with_mesh_refinement() {
    // Mixed regime for the beams (K_T = 120, F = 120 N), macroslip at the plate's edge (K_T = 1e7).
    let beams = TwinBeamsParams {
        tangential_stiffness: 120.0,
        ..TwinBeamsParams::PAPER
    };
    let exact = TwinBeams::new(beams)
        .unwrap()
        .regularized(TipForce::new(120.0).unwrap());
    let beam_errors: Vec<(f64, f64)> = [25, 100, 400]
        .iter()
        .map(|&n| {
            let mut fe = TwinBeamsFe::new(beams, MeshDensity::with_elements(n));
            fe.load_to(120.0, 4).unwrap();
            (
                relative_error(fe.tip_deflection(), exact.tip_deflection()),
                relative_error(fe.micro_zone_end(), exact.micro_zone_end()),
            )
        })
        .collect();
    let plate = PlateParams {
        tangential_stiffness: 1e7,
        ..PlateParams::PAPER
    };
    let exact = SqueezedPlate::new(plate).unwrap().regularized();
    let plate_errors: Vec<(f64, f64)> = [25, 100, 400]
        .iter()
        .map(|&n| {
            // The graded mesh alone: the refinement at the slip front would reach round-off.
            let density = MeshDensity {
                refine_at_front: false,
                ..MeshDensity::with_elements(n)
            };
            let mut fe = PlateFe::new(plate, density);
            fe.load_to(10.0, 2).unwrap();
            (
                relative_error(fe.end_displacement(), exact.end_displacement()),
                relative_error(fe.micro_zone_end(), exact.micro_zone_end()),
            )
        })
        .collect();
    // Every refinement must gain, and 16x must gain at least 16x (first order at the very least). The
    // observed order is 2 to 2.5 but irregular: the element that contains X integrates the kink of the
    // interface law at Gauss points (docs/theory.md, "Mesh convergence").
    for errors in [&beam_errors, &plate_errors] {
        for pair in errors.windows(2) {
            assert!(
                pair[1].0 < pair[0].0 && pair[1].1 < pair[0].1,
                "{beam_errors:?} {plate_errors:?}"
            );
        }
        assert!(
            errors[2].0 < errors[0].0 / 16.0 && errors[2].1 < errors[0].1 / 16.0,
            "{errors:?}"
        );
    }
}

#[test]
fn finite_elements_reproduce_the_shared_fe_reference() {
    // A third, external opinion: the shared reference was computed with another FE code.
    for row in reference_rows("twin-beams-paper-fe.csv").iter().step_by(3) {
        let (kt, f, w_ref, x_ref) = (row[0], row[1], row[2], row[3]);
        let params = TwinBeamsParams {
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        };
        let mut fe = TwinBeamsFe::new(params, MeshDensity::default());
        fe.load_to(f, 4).unwrap();
        assert!(
            relative_error(fe.tip_deflection(), w_ref) < 1e-6,
            "K_T={kt} F={f}"
        );
        assert!(
            (fe.micro_zone_end() - x_ref).abs() < 1e-4 * x_ref,
            "K_T={kt} F={f}"
        );
    }
}

#[test]
fn beam_load_cycle_obeys_masing_and_returns_to_its_turning_point() {
    // Load 0 -> F_a, unload to -F_a, reload to F_a. Hand-checkable properties of an elastic structure
    // with elastic-perfectly-plastic interface points loaded in proportion:
    // - unloading starts with the virgin (all-elastic) stiffness;
    // - Masing: w(F_a) - w(F) on unloading equals 2 w_virgin((F_a - F) / 2);
    // - the reloading branch closes the loop exactly at (F_a, w(F_a)).
    let params = TwinBeamsParams {
        tangential_stiffness: 120.0,
        ..TwinBeamsParams::PAPER
    };
    let density = MeshDensity::with_elements(100);
    let f_a = 150.0;
    let virgin_at = |f: f64| {
        let mut fe = TwinBeamsFe::new(params, density);
        fe.load_to(f, 4).unwrap();
        fe.tip_deflection()
    };
    let mut fe = TwinBeamsFe::new(params, density);
    fe.load_to(f_a, 6).unwrap();
    let w_a = fe.tip_deflection();
    let mut unloading = Vec::new();
    for f in [130.0, 100.0, 40.0, 0.0, -60.0, -f_a] {
        fe.load_to(f, 4).unwrap();
        unloading.push((f, fe.tip_deflection()));
    }
    let small = virgin_at(1.0);
    let (f1, w1) = unloading[0];
    assert!(
        relative_error((w_a - w1) / (f_a - f1), small) < 1e-6,
        "initial unloading compliance"
    );
    for &(f, w) in &unloading {
        let masing = w_a - 2.0 * virgin_at((f_a - f) / 2.0);
        assert!(
            (w - masing).abs() < 1e-6 * w_a,
            "F={f}: w={w}, Masing {masing}"
        );
    }
    // The loop is symmetric: w(-F_a) = -w(F_a); then reload.
    assert!(relative_error(unloading[5].1, -w_a) < 1e-6);
    fe.load_to(f_a, 10).unwrap();
    assert!(
        relative_error(fe.tip_deflection(), w_a) < 1e-6,
        "loop does not close"
    );
    // And energy was dissipated: unloading to zero leaves a residual deflection.
    assert!(unloading[3].1 > 1e-3 * w_a);
}

#[test]
fn plate_pressure_cycle_shows_hysteresis() {
    // Virgin loading is proportional (X_r does not depend on P), so u(P/2) = u(P)/2 on the way up.
    // Unloading to P/2, the slid edge zone cannot spring back fully: u stays above u(P)/2. The answer
    // on reloading depends on the path, not on the step size. Unloading to P = 0 removes all friction
    // and all load: u = 0. (Unlike the beams, the plate's loop does not close: friction strength
    // follows the load, and reloading ends beyond the first u(P), a cumulative microslip; see
    // docs/theory.md.)
    let params = PlateParams {
        tangential_stiffness: 1e7,
        ..PlateParams::PAPER
    };
    let mut fe = PlateFe::new(params, MeshDensity::with_elements(100));
    fe.load_to(5.0, 2).unwrap();
    let half = fe.end_displacement();
    fe.load_to(10.0, 2).unwrap();
    assert!(fe.micro_zone_end() < 10.0);
    let loaded = fe.end_displacement();
    assert!(relative_error(half, loaded / 2.0) < 1e-6);
    fe.load_to(5.0, 4).unwrap();
    let unloaded = fe.end_displacement();
    assert!(
        unloaded > half * (1.0 + 1e-3),
        "{unloaded} vs virgin {half}"
    );
    let (mut coarse, mut fine) = (fe.clone(), fe.clone());
    coarse.load_to(10.0, 1).unwrap();
    fine.load_to(10.0, 16).unwrap();
    assert!(relative_error(coarse.end_displacement(), fine.end_displacement()) < 1e-9);
    fe.load_to(0.0, 4).unwrap();
    assert!(fe.end_displacement().abs() < 1e-9 * loaded);
}

proptest! {
    #![proptest_config(common::fixed_seed(24))]

    #[test]
    fn random_beams_agree_with_the_closed_form(
        length in 50.0..1000.0_f64,
        slenderness in 8.0..60.0_f64,
        width in 5.0..50.0_f64,
        log_kt in 0.0..5.0_f64,
        mu in 0.05..1.0_f64,
        pressure in 0.1..5.0_f64,
        load in 0.1..4.0_f64,
    ) {
        let params = TwinBeamsParams {
            length,
            width,
            half_height: length / slenderness / 2.0,
            youngs_modulus: 200_000.0,
            pressure,
            friction: mu,
            tangential_stiffness: 10f64.powf(log_kt),
            ..TwinBeamsParams::PAPER
        };
        let beams = TwinBeams::new(params).unwrap();
        let f = load * beams.threshold_force();
        let exact = beams.regularized(TipForce::new(f).unwrap());
        let mut fe = TwinBeamsFe::new(params, MeshDensity::with_elements(200));
        fe.load_to(f, 4).unwrap();
        prop_assert!(relative_error(fe.tip_deflection(), exact.tip_deflection()) < 1e-4);
        if exact.regime() == Regime::MICROSLIP_MACROSLIP {
            prop_assert!(relative_error(fe.micro_zone_end(), exact.micro_zone_end()) < 1e-3);
        }
    }

    #[test]
    fn random_plates_agree_with_the_closed_form(
        length in 1.0..50.0_f64,
        thickness in 0.05..1.0_f64,
        nu in 0.0..0.49_f64,
        mu in 0.05..1.0_f64,
        log_kt in 0.0..8.0_f64,
    ) {
        plate_agrees_with_the_closed_form(length, thickness, nu, mu, log_kt)?;
    }
}

/// Found by the property test above: with little friction the macroslip zone covers most of the
/// plate and X_r falls among the coarse elements near the centre (the mesh is graded towards the
/// free end): X_r was 3.6 % off with 200 elements. The solver now refines around its own X_r.
#[test]
fn a_microslip_zone_near_the_centre_is_resolved() {
    let params = PlateParams {
        half_length: 3.849158957579457,
        thickness: 0.2782045449936793,
        youngs_modulus: 70_000.0,
        poisson: 0.4002546053859605,
        friction: 0.05,
        pressure: 10.0,
        tangential_stiffness: 10f64.powf(7.87289960210712),
    };
    let exact = SqueezedPlate::new(params).unwrap().regularized();
    assert_eq!(exact.regime(), Regime::MICROSLIP_MACROSLIP);
    assert!(exact.micro_zone_end() < 0.05 * params.half_length);
    let mut fe = PlateFe::new(params, MeshDensity::with_elements(200));
    fe.load_to(10.0, 2).unwrap();
    assert!(
        relative_error(fe.micro_zone_end(), exact.micro_zone_end()) < 1e-5,
        "{} vs {}",
        fe.micro_zone_end(),
        exact.micro_zone_end()
    );
    let u = exact.end_displacement();
    assert!((fe.end_displacement() - u).abs() <= 1e-6 * u);
}

/// Found by the property test above on a fresh clone (issue 46, item 10), and by a search of
/// 6 000 plates with little friction and stiff interfaces (mu 0.05 to 0.15, K_T 3e6 to 1e8
/// MPa/mm): long plates on which the solver's Newton iterations did not converge at any load
/// (the plate's answer is proportional to P, so halving the step never helped). The first ran
/// out of iterations while the sliding front crossed 640 integration points
/// (`NoConvergence { load: 5.0012, cuts: 12 }`); the second overshot until every point slid.
/// Before the fix 76 of those 6 000 failed; after it none did, nor any of 6 000 over mu 0.01 to
/// 0.31, K_T 1e6 to 1e9 MPa/mm on the default 400-element mesh.
#[test]
fn long_plates_with_little_friction_and_a_stiff_interface_converge() {
    for (half_length, thickness, poisson, friction, log_kt) in [
        (
            46.93103018630898,
            0.9264823855270136,
            0.3533154077099722,
            0.05,
            7.752831596125802,
        ),
        (
            44.46858369271893,
            0.48193772155924175,
            0.31382239434153736,
            0.05012505480144175,
            7.904765677729898,
        ),
    ] {
        plate_agrees_with_the_closed_form(half_length, thickness, poisson, friction, log_kt)
            .unwrap();
    }
}

/// The body of `random_plates_agree_with_the_closed_form`: a steel-like plate (E 70 000 MPa,
/// P 10 MPa) on 200 elements, loaded in two steps, against the closed form: u(L) within 1e-4,
/// X_r within 1e-3 where there is one.
fn plate_agrees_with_the_closed_form(
    half_length: f64,
    thickness: f64,
    poisson: f64,
    friction: f64,
    log_kt: f64,
) -> Result<(), TestCaseError> {
    let params = PlateParams {
        half_length,
        thickness,
        youngs_modulus: 70_000.0,
        poisson,
        friction,
        pressure: 10.0,
        tangential_stiffness: 10f64.powf(log_kt),
    };
    let exact = SqueezedPlate::new(params).unwrap().regularized();
    let mut fe = PlateFe::new(params, MeshDensity::with_elements(200));
    fe.load_to(10.0, 2)
        .map_err(|e| TestCaseError::fail(format!("{params:?}: {e:?}")))?;
    let u = exact.end_displacement();
    prop_assert!((fe.end_displacement() - u).abs() <= 1e-4 * u + 1e-15);
    if exact.regime() == Regime::MICROSLIP_MACROSLIP {
        prop_assert!(relative_error(fe.micro_zone_end(), exact.micro_zone_end()) < 1e-3);
    }
    Ok(())
}
