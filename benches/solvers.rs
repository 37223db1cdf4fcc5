//! Speed of the solvers: `cargo bench --bench solvers`. Results and machine: BENCHMARKS.md.

use divan::{Bencher, black_box};
use microslip::numeric::{MeshDensity, PlateFe, TwinBeamsFe};
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
