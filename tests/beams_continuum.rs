//! The twin beams' continuum (`problems::twin_beams::continuum`, docs/theory.md "The twin beams'
//! continuum") against the beam theories where they hold, its own mesh convergence, its Coulomb
//! limit, and CalculiX 2.20 on the bundled deck (numbers copied from runs of `microslip deck ccx
//! beam --preset paper-beams`, NLGEOM, coarse mesh, default load path; the runs are not in the
//! repository, so these tests need no ccx).

use std::sync::OnceLock;

use microslip::problems::twin_beams::closed_form::{TipForce, TwinBeams};
use microslip::problems::twin_beams::params::{BeamTheory, TwinBeamsParams};
use microslip::problems::twin_beams::{
    BeamsContinuumMesh, ContinuumBeams, solve_beams_continuum, solve_beams_continuum_path,
};

const PAPER: TwinBeamsParams = TwinBeamsParams::PAPER;

/// The continuum on `layers` elements through each beam, not extrapolated.
fn path(params: TwinBeamsParams, forces: &[f64], layers: usize) -> Vec<ContinuumBeams> {
    let mesh = BeamsContinuumMesh {
        layers,
        extrapolate: false,
        ..BeamsContinuumMesh::default()
    };
    solve_beams_continuum_path(params, forces, mesh).unwrap()
}

/// The continuum on the default mesh (8 layers, w(L) extrapolated with 4) at the bundled deck's
/// loads, solved once for the tests that read it.
fn bundled() -> &'static [ContinuumBeams] {
    static STATES: OnceLock<Vec<ContinuumBeams>> = OnceLock::new();
    STATES.get_or_init(|| {
        solve_beams_continuum_path(PAPER, &BUNDLED_LOADS, BeamsContinuumMesh::default()).unwrap()
    })
}

/// The bundled deck's loads (N): `microslip deck ccx beam --preset paper-beams --loads
/// 40,79.4,81.79,100` (0.5 F_thre, 0.99 F_1, 1.02 F_1, 1.25 F_thre).
const BUNDLED_LOADS: [f64; 4] = [40.0, 79.4, 81.79, 100.0];

fn timoshenko(params: TwinBeamsParams, force: f64) -> (f64, f64) {
    let beams = TwinBeams::new(params)
        .unwrap()
        .with_theory(BeamTheory::Timoshenko);
    let state = beams.regularized(TipForce::new(force).unwrap());
    (state.tip_deflection(), state.micro_zone_end())
}

/// The paper's beams (L/h = 20) in stick (40 N), at macroslip onset (81.79 N = 1.02 F_1) and deep
/// in macroslip (100 N): w(L) within 0.5 % of Timoshenko's (measured: -0.34 % in stick, -0.43 %
/// at 100 N: the clamp's local flexibility and the interface's pressure concentrations are what
/// beam theory leaves out), and 2 % and more from Euler-Bernoulli's (which leaves out the shear
/// deflection, 1.9 % of w(L)); X within 2.5 mm (0.6 of an element) of the closed form's.
#[test]
fn the_papers_beams_follow_timoshenko_within_half_a_percent() {
    for (state, force) in bundled().iter().zip(BUNDLED_LOADS) {
        let (w, x) = timoshenko(PAPER, force);
        let euler = TwinBeams::new(PAPER)
            .unwrap()
            .regularized(TipForce::new(force).unwrap())
            .tip_deflection();
        let off = state.tip_deflection / w - 1.0;
        assert!(off.abs() < 5e-3, "F = {force}: {off:+e}");
        assert!(
            state.tip_deflection / euler - 1.0 > 0.01,
            "F = {force}: {}",
            state.tip_deflection / euler
        );
        assert!(
            (state.macroslip_start - x).abs() < 2.5,
            "F = {force}: X {} vs {x}",
            state.macroslip_start
        );
    }
    // Stick: nothing slides, no macroslip zone; the pressure alone bends nothing.
    assert_eq!(bundled()[0].macroslip_start, PAPER.length);
    assert!(bundled()[0].pressure_deflection.abs() < 1e-12);
    assert!(bundled().iter().all(|s| s.separated.is_empty()));
}

/// Below the continuum's elastic limit w(L) is linear in F and the shear is K_T times the slip,
/// with the sign of the slip (the upper beam's bottom fibre stretches, the lower one's top fibre
/// shortens: s = u_upper - u_lower > 0 and the shear on the lower beam pulls it toward the tip).
#[test]
fn in_stick_the_answer_is_linear_and_the_shear_follows_the_slip() {
    let states = path(PAPER, &[20.0, 40.0], 2);
    assert!(
        (states[1].tip_deflection / states[0].tip_deflection - 2.0).abs() < 1e-9,
        "{} {}",
        states[0].tip_deflection,
        states[1].tip_deflection
    );
    let kt = PAPER.tangential_stiffness;
    for ((x, s), (_, tau)) in states[1].slip.iter().zip(&states[1].shear) {
        assert!(*s > 0.0, "x = {x}: s = {s}");
        assert!((tau / (kt * s) - 1.0).abs() < 1e-9, "x = {x}: {tau} vs {s}");
        assert!(*tau < PAPER.friction * 1.2 * PAPER.pressure);
    }
    // The shear along the interface follows the closed form's (B4) within 3 % away from the
    // clamp and the tip (a beam height from each), where the continuum's corners act.
    let closed = TwinBeams::new(PAPER)
        .unwrap()
        .regularized(TipForce::new(40.0).unwrap());
    for (x, tau) in &states[1].shear {
        if (20.0..180.0).contains(x) {
            let expected = closed.shear_stress(*x);
            assert!(
                (tau / expected - 1.0).abs() < 0.03,
                "x = {x}: {tau} vs {expected}"
            );
        }
    }
}

/// Mesh convergence: 2 and 4 layers through each beam against the default (8 layers, w(L)
/// extrapolated with 4). In stick and in macroslip (100 N) the error shrinks with the layer
/// height (measured: -0.046 % at 2 layers, -0.019 % at 4 at 100 N), below 0.05 % from 4 on.
#[test]
fn the_tip_deflection_converges_with_the_mesh() {
    let forces = [40.0, 100.0];
    let [two, four] = [2, 4].map(|layers| path(PAPER, &forces, layers));
    let converged = [&bundled()[0], &bundled()[3]];
    for i in 0..2 {
        let e2 = two[i].tip_deflection / converged[i].tip_deflection - 1.0;
        let e4 = four[i].tip_deflection / converged[i].tip_deflection - 1.0;
        assert!(
            e4.abs() < 0.6 * e2.abs(),
            "F = {}: {e2:e} {e4:e}",
            forces[i]
        );
        assert!(e4.abs() < 5e-4, "F = {}: {e4:e}", forces[i]);
    }
}

/// CalculiX 2.20 (NLGEOM, coarse deck, default path) on the bundled deck: the continuum within
/// 0.15 % in w(L) at every load step (measured: -0.01 to +0.12 %) and X within one deck element
/// (4 mm).
#[test]
fn the_bundled_deck_s_calculix_run_agrees_with_the_continuum() {
    // w(L) (mm) and X (mm) of the run of `microslip deck ccx beam --preset paper-beams --loads
    // 40,79.4,81.79,100`, per load.
    const CALCULIX: [(f64, f64); 4] = [
        (0.01137855, 200.0),
        (0.022585345, 200.0),
        (0.02347978, 88.619),
        (0.03882572, 17.617),
    ];
    for ((state, force), (w, x)) in bundled().iter().zip(BUNDLED_LOADS).zip(CALCULIX) {
        let off = state.tip_deflection / w - 1.0;
        assert!(off.abs() < 1.5e-3, "F = {force}: {off:+e}");
        assert!((state.macroslip_start - x).abs() < 4.0, "F = {force}");
    }
}

/// K_T -> infinity gives plain Coulomb: the tip deflection falls monotonically toward the
/// Coulomb closed form plus the shear deflection, and the continuum's ratio between two K_T
/// follows the closed form's.
#[test]
fn a_stiff_interface_gives_the_coulomb_limit() {
    let params = |kt: f64| TwinBeamsParams {
        length: 100.0,
        half_height: 5.0,
        tangential_stiffness: kt,
        ..PAPER
    };
    let beams = TwinBeams::new(params(600.0)).unwrap();
    let force = 1.3 * beams.threshold_force();
    let coulomb = beams
        .coulomb(TipForce::new(force).unwrap())
        .tip_deflection()
        + beams.shear_deflection(TipForce::new(force).unwrap());
    let mut last = f64::INFINITY;
    let mut gaps = Vec::new();
    for kt in [60.0, 600.0, 6000.0] {
        let w = path(params(kt), &[force], 2)[0].tip_deflection;
        assert!(w < last, "K_T {kt}: {w} after {last}");
        last = w;
        gaps.push(w / coulomb - 1.0);
    }
    // The gap to Coulomb shrinks with K_T (about as 1/sqrt(K_T) in the closed form) down to
    // what beam theory leaves out (under 1 %).
    assert!(gaps[2].abs() < 0.4 * gaps[0].abs(), "{gaps:?}");
    assert!(gaps[2].abs() < 0.01, "{gaps:?}");
}

#[test]
fn inputs_outside_the_domain_are_refused_with_their_reason() {
    let mesh = BeamsContinuumMesh::default();
    let message = |params: TwinBeamsParams, force: f64, mesh: BeamsContinuumMesh| {
        solve_beams_continuum(params, force, mesh)
            .unwrap_err()
            .to_string()
    };
    assert!(message(PAPER, -1.0, mesh).contains('F'));
    assert!(message(PAPER, f64::NAN, mesh).contains('F'));
    let bad = TwinBeamsParams {
        friction: -0.3,
        ..PAPER
    };
    assert!(message(bad, 10.0, mesh).contains("mu = -0.3"));
    let slender = TwinBeamsParams {
        length: 5000.0,
        ..PAPER
    };
    assert!(message(slender, 10.0, mesh).contains("more than the 801"));
    for bad_mesh in [
        BeamsContinuumMesh { layers: 0, ..mesh },
        BeamsContinuumMesh { layers: 17, ..mesh },
        BeamsContinuumMesh {
            force_increments: 0,
            ..mesh
        },
    ] {
        assert!(solve_beams_continuum(PAPER, 10.0, bad_mesh).is_err());
    }
    let back = solve_beams_continuum_path(PAPER, &[90.0, 80.0], mesh).unwrap_err();
    assert!(back.to_string().contains("must not decrease"), "{back}");
}
