//! Speed of the solvers: `cargo bench --bench solvers`. Results and machine: BENCHMARKS.md.

use divan::{Bencher, black_box};
use microslip::fit::{Measurement, Structure, Weights, fit_curve, fit_measured};
use microslip::kernel::family;
use microslip::numeric::MeshDensity;
use microslip::problems::cylinder::collocation::Collocation;
use microslip::problems::cylinder::continued;
use microslip::problems::cylinder::regularized::solve_normalized;
use microslip::problems::cylinder::{Cylinder, CylinderParams, CylinderProblem};
use microslip::problems::lap::closed_form::{LapJoint, LapParams};
use microslip::problems::lap::{LapContinuumMesh, LapFe, solve_lap_continuum};
use microslip::problems::plate::{ContinuumMesh, PlateFe, solve_plate_continuum};
use microslip::problems::twin_beams::{
    BeamsContinuumMesh, TwinBeamsFe, TwinBeamsProblem, solve_beams_continuum,
};
use microslip::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

fn main() {
    divan::main();
}

/// Closed form, regularized twin beams at one load: root find for X, then w(L).
#[divan::bench(args = [60.0, 120.0, 800.0])]
fn beam_closed_form(bencher: Bencher, force: f64) {
    let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
    let force = TipForce::new(force).unwrap();
    bencher.bench_local(|| {
        let state = black_box(&beams).regularized(black_box(force));
        (state.micro_zone_end(), state.tip_deflection())
    });
}

/// Closed form, regularized lap joint at one force (the bundled joint): all microslip (1000 N),
/// one end sliding (2400 N: a root for e), both ends (4000 N: a root for l), then Delta.
#[divan::bench(args = [1000.0, 2400.0, 4000.0])]
fn lap_closed_form(bencher: Bencher, force: f64) {
    let joint = LapJoint::new(LapParams::ALUMINIUM).unwrap();
    let force = joint.force(force).unwrap();
    bencher.bench_local(|| {
        let state = black_box(&joint).regularized(black_box(force));
        (state.slide_at_cover_ends(), state.joint_displacement())
    });
}

/// The lap joint's discretized solver (`LapFe`), the default 400 elements, loaded from rest to
/// 4000 N (both ends sliding) in 4 steps: what `n` and `verify` run per point.
#[divan::bench(sample_count = 30)]
fn lap_finite_elements(bencher: Bencher) {
    bencher.bench_local(|| {
        let mut fe = LapFe::new(LapParams::ALUMINIUM, MeshDensity::default());
        fe.load_to(black_box(4000.0), 4).unwrap();
        fe.joint_displacement()
    });
}

/// Closed form, regularized plate: root find for X_r, then u(L).
#[divan::bench(args = [1e3, 1e6])]
fn plate_closed_form(bencher: Bencher, kt: f64) {
    let plate = SqueezedPlate::new(PlateParams {
        tangential_stiffness: kt,
        ..PlateParams::PAPER
    })
    .unwrap();
    bencher.bench_local(|| {
        let state = black_box(&plate).regularized();
        (state.micro_zone_end(), state.end_displacement())
    });
}

/// Finite elements, default mesh (400 elements), one load level from rest.
#[divan::bench(args = [60.0, 120.0], sample_count = 30)]
fn beam_finite_elements(bencher: Bencher, force: f64) {
    bencher.bench_local(|| {
        let mut fe = TwinBeamsFe::new(TwinBeamsParams::PAPER, MeshDensity::default());
        fe.load_to(black_box(force), 1).unwrap();
        fe.tip_deflection()
    });
}

/// Finite elements, default mesh (400 elements), the plate loaded to P in one level.
#[divan::bench(sample_count = 30)]
fn plate_finite_elements(bencher: Bencher) {
    bencher.bench_local(|| {
        let mut fe = PlateFe::new(PlateParams::PAPER, MeshDensity::default());
        fe.load_to(black_box(10.0), 1).unwrap();
        fe.end_displacement()
    });
}

/// The plane-strain continuum plate (Q8, 4 layers, fixed point on the contact pressure), paper
/// plate at K_T = 1e4 (no macroslip), 1e6 (the paper's) and 1e7.
#[divan::bench(args = [1e4, 1e6, 1e7], sample_count = 10)]
fn plate_continuum(bencher: Bencher, kt: f64) {
    let params = PlateParams {
        tangential_stiffness: kt,
        ..PlateParams::PAPER
    };
    bencher.bench_local(|| {
        solve_plate_continuum(black_box(params), ContinuumMesh::default())
            .unwrap()
            .end_displacement_mean
    });
}

/// The lap joint's plane-stress continuum (two Q8 bodies, 4 layers, the interface condensed onto
/// its node pairs, 8 force increments over F_gross), the bundled joint clamped then loaded to
/// 4000 N (both ends sliding) at K_T = 1e3 (the bundled), 1e4 and 1e5 MPa/mm.
#[divan::bench(args = [1e3, 1e4, 1e5], sample_count = 10)]
fn lap_continuum(bencher: Bencher, kt: f64) {
    let params = LapParams {
        tangential_stiffness: kt,
        ..LapParams::ALUMINIUM
    };
    bencher.bench_local(|| {
        solve_lap_continuum(black_box(params), 4000.0, LapContinuumMesh::default())
            .unwrap()
            .delta
    });
}

/// A measured curve of `rows` points from 1 to 300 N (mu = 0.4, K_T = 200 MPa/mm, the paper's
/// geometry) with reproducible noise of +-5e-5 mm, about a quarter of a percent of the largest w.
fn measured_curve(rows: usize) -> Vec<Measurement> {
    let beams = TwinBeams::new(TwinBeamsParams {
        friction: 0.4,
        tangential_stiffness: 200.0,
        ..TwinBeamsParams::PAPER
    })
    .unwrap();
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    (0..rows)
        .map(|i| {
            let force = 1.0 + 299.0 * i as f64 / (rows - 1) as f64;
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let noise = 1e-4 * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
            let w = beams
                .regularized(TipForce::new(force).unwrap())
                .tip_deflection();
            Measurement {
                force,
                response: w + noise,
            }
        })
        .collect()
}

/// Fit of mu and K_T to a measured curve (both free), from the grid search to the standard errors.
#[divan::bench(args = [10_000, 100_000], sample_count = 10)]
fn fit_mu_and_kt(bencher: Bencher, rows: usize) {
    let data = measured_curve(rows);
    let Ok(beams) = TwinBeams::new(TwinBeamsParams::PAPER) else {
        return;
    };
    bencher.bench_local(|| {
        fit_curve::<TwinBeamsProblem>(
            &beams,
            black_box(&data),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
    });
}

/// The Hertzian cylinder's regularized solution (issue 34) on the default collocation mesh, what
/// every key press in the TUI recomputes: kappa = K_T a / E* = 0.64 (the bundled steel pad) and
/// 64 (near Mindlin), at Q / mu P = 0.5. Called on the normalized solver, because the problem's
/// `regularized` keeps each thread's last answer (a repeated call would time the cache).
#[divan::bench(args = [0.64, 64.0])]
fn cylinder_regularized(bencher: Bencher, kappa: f64) {
    let collocation = Collocation::default_mesh();
    bencher.bench_local(|| solve_normalized(collocation, black_box(kappa), black_box(0.5)));
}

/// The twin beams' plane-stress continuum (issue 33), the paper's beams at F = 100 N (macroslip:
/// the load path in increments), on the default mesh: what `compare beam` solves per FE row
/// (several times, to imply K_T) and the TUI's `n` on a worker.
#[divan::bench(sample_count = 5)]
fn beams_continuum(bencher: Bencher) {
    bencher.bench_local(|| {
        solve_beams_continuum(
            black_box(TwinBeamsParams::PAPER),
            black_box(100.0),
            BeamsContinuumMesh::default(),
        )
    });
}

/// A cylinder Q-sweep at the bundled pad's K_T a / E* = 0.64: `SWEEP_POINTS` loads from 0 to
/// mu P, each a full cold regularized solve (`solve_normalized`, the reference; what each point
/// of `sweep --model cylinder` cost before issue 47).
#[divan::bench(sample_count = 3)]
fn cylinder_q_sweep_cold(bencher: Bencher) {
    let collocation = Collocation::default_mesh();
    bencher.bench_local(|| {
        sweep_loads(SWEEP_POINTS)
            .map(|ratio| solve_normalized(collocation, black_box(0.64), ratio).angle)
            .sum::<f64>()
    });
}

/// The same sweep continued along its family (`continued::solve` in a `family::scope`, what
/// `Cylinder::regularized` does inside a sweep since issue 47), at `SWEEP_POINTS` and at 1e5
/// points (the goal: under 10 s).
#[divan::bench(args = [SWEEP_POINTS, 100_000], sample_count = 3)]
fn cylinder_q_sweep_continued(bencher: Bencher, points: usize) {
    bencher.bench_local(|| {
        family::scope(|| {
            sweep_loads(points)
                .map(|ratio| continued::solve(black_box(0.64), ratio).angle)
                .sum::<f64>()
        })
    });
}

/// `fit cylinder` on 100 rows (issue 47's goal: under 5 s): the exact s(a) of mu 0.45 and K_T
/// 4e4 MPa/mm at 100 loads to 0.9 mu P, fitted from the bundled pad (what `microslip fit` calls),
/// in its own scope (`continued`, what `fit_measured` does) and with every solve cold
/// (`reference`: in `family::cold`, every solve the cold one, as before issue 47).
#[divan::bench(args = ["continued", "reference"], sample_count = 1)]
fn cylinder_fit(bencher: Bencher, solves: &str) {
    let truth = Cylinder::new(CylinderParams {
        friction: 0.45,
        tangential_stiffness: 4e4,
        ..CylinderParams::STEEL_PAD
    })
    .unwrap();
    let data: Vec<Measurement> = (1..=100)
        .map(|i| {
            let q = 405.0 * i as f64 / 100.0;
            Measurement {
                force: q,
                response: truth.regularized(truth.load(q).unwrap()).edge_slip(),
            }
        })
        .collect();
    let held = Cylinder::new(CylinderParams::STEEL_PAD).unwrap();
    let fit = || {
        let structure = Structure::typed::<CylinderProblem>(&held);
        fit_measured(
            structure,
            black_box(&data),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
        .map(|r| r.kt.value)
    };
    bencher.bench_local(|| {
        if solves == "reference" {
            family::cold(fit)
        } else {
            fit()
        }
    });
}

/// `points` loads from 0 to mu P, as Q / mu P.
fn sweep_loads(points: usize) -> impl Iterator<Item = f64> {
    (0..points).map(move |i| i as f64 / (points - 1) as f64)
}

/// Points of the cold cylinder sweep benchmark.
const SWEEP_POINTS: usize = 200;

/// `solve cylinder --vary Q --target sa=0.002` on the bundled pad (issue 47's goal: under
/// 0.5 s): the target search over Q in its scope (`scoped`, what `solve_for_target` does) and with
/// every solve cold (`cold`, in `family::cold`, as before issue 47).
#[divan::bench(args = ["scoped", "cold"], sample_count = 3)]
fn cylinder_solve_vary_q(bencher: Bencher, solves: &str) {
    use microslip::problems::cylinder::CylinderParam;
    use microslip::problems::inputs::Inputs;
    use microslip::problems::{ModelKind, Param};
    use microslip::study::target::{Target, solve_for_target};
    let model = Inputs::paper(ModelKind::Cylinder).validate().unwrap();
    let target = Target::parse("sa=0.002", ModelKind::Cylinder).unwrap();
    let param = Param::Cylinder(CylinderParam::TangentialLoad);
    let solve = || {
        solve_for_target(black_box(&model), param, target, None)
            .map(|s| s.roots.len())
            .unwrap()
    };
    bencher.bench_local(|| {
        if solves == "cold" {
            family::cold(solve)
        } else {
            solve()
        }
    });
}
