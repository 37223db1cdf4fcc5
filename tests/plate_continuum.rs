//! The plane-strain continuum solver of the squeezed plate against CalculiX 2.20 (real results in
//! `tests/data/calculix/`), and the strip theory's validity envelope (V1) against the solver.

use std::path::PathBuf;

use microslip::fe::load::plate_results;
use microslip::kernel::validity::Validity;
use microslip::problems::plate::validity::PLATE_QUANTITIES;
use microslip::problems::plate::{ContinuumMesh, solve_plate_continuum};
use microslip::{Model, PlateParams, SqueezedPlate};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/calculix")
        .join(name)
}

#[test]
fn continuum_solver_agrees_with_calculix_on_the_thickness_mean_and_mid_thickness() {
    for (file, face_band) in [("plate-kt1e4.dat", 0.01), ("paper-plate.dat", 0.05)] {
        let loaded = plate_results(&fixture(file), None).unwrap();
        let Model::Plate(plate) = loaded.header.unwrap().model().unwrap() else {
            panic!("a plate deck")
        };
        let ccx = loaded.points[0];
        let [face, mid] = ccx.through_thickness.unwrap();
        let ours = solve_plate_continuum(plate.params(), ContinuumMesh::default()).unwrap();
        let close = |a: f64, b: f64, band: f64, what: &str| {
            assert!(
                (a / b - 1.0).abs() < band,
                "{file} {what}: {a} vs CalculiX {b}"
            );
        };
        close(
            ours.end_displacement_mean,
            ccx.end_displacement,
            0.01,
            "mean",
        );
        close(ours.end_displacement_mid, mid, 0.01, "mid-thickness");
        // The contact face's free-end corner is where meshes disagree most (CalculiX's own
        // coarse and fine meshes differ by 0.3 %, the shared reference's by 2 %).
        close(ours.end_displacement_face, face, face_band, "contact face");
    }
}

#[test]
fn the_strip_theory_stays_within_its_stated_envelope() {
    // Plates outside the calibration grid (nu, mu, t_p/L and alpha t_p all differ from it).
    for nu in [0.15, 0.35, 0.47] {
        for (mu, thickness, length) in [(0.2, 0.1, 3.0), (2.0, 0.5, 40.0)] {
            for alpha_tp in [0.07, 0.14, 0.22, 0.4] {
                let modulus = 70_000.0;
                let kt = alpha_tp * alpha_tp * modulus / ((1.0 - nu * nu) * thickness);
                let params = PlateParams {
                    half_length: length,
                    thickness,
                    poisson: nu,
                    friction: mu,
                    tangential_stiffness: kt,
                    ..PlateParams::PAPER
                };
                let plate = SqueezedPlate::new(params).unwrap();
                let envelope = plate.validity();
                let strip = plate.regularized().end_displacement();
                let c = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
                let bounds = envelope.expected.expect("calibrated below alpha t_p = 0.5");
                // Each quantity the envelope names within its own bound.
                let values = [
                    c.end_displacement_mean,
                    c.end_displacement_face,
                    c.end_displacement_mid,
                ];
                for ((u, bound), what) in values.iter().zip(bounds).zip(PLATE_QUANTITIES) {
                    let error = (u / strip - 1.0).abs();
                    assert!(
                        error <= bound,
                        "nu {nu} mu {mu} alpha t_p {alpha_tp}, {what}: error {error}, bound {bound}"
                    );
                }
                let error = (c.end_displacement_mean / strip - 1.0).abs();
                // "Holds" means within 2 % of the continuum.
                if envelope.validity == Validity::Holds {
                    assert!(error <= 0.02);
                }
            }
        }
    }
}
