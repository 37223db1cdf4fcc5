//! The plane-strain continuum solver of the squeezed plate against CalculiX 2.20 (real results in
//! `tests/data/calculix/`), and the strip theory's validity envelope (V1) against the solver.

use std::path::PathBuf;

use microslip::fe::load::results;
use microslip::kernel::validity::Validity;
use microslip::problems::plate::SqueezedPlateProblem;
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
        let loaded = results::<SqueezedPlateProblem>(&fixture(file), None).unwrap();
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

/// CalculiX's contact pressure along the plate's contact face, (x, P_r / P): the deck's penalty
/// (linear pressure-overclosure, the base fixed) times each IFPLATE node's penetration -v.
fn calculix_pressure(name: &str) -> Vec<(f64, f64)> {
    let inp = std::fs::read_to_string(fixture(&format!("{name}.inp"))).unwrap();
    let dat = std::fs::read_to_string(fixture(&format!("{name}.dat"))).unwrap();
    let mut nodes = std::collections::HashMap::new();
    let (mut section, mut penalty, mut pressure) = ("", 0.0, 0.0);
    let mut interface = Vec::new();
    for line in inp.lines().filter(|l| !l.starts_with("**")) {
        if line.starts_with('*') {
            let upper = line.to_uppercase();
            section = if upper.starts_with("*NODE,") {
                "node"
            } else if upper.starts_with("*NSET, NSET=IFPLATE") {
                "interface"
            } else if upper.starts_with("*SURFACE BEHAVIOR") {
                "penalty"
            } else if upper.starts_with("*DLOAD") {
                "load"
            } else {
                ""
            };
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        match section {
            "node" => {
                nodes.insert(
                    fields[0].parse::<u32>().unwrap(),
                    fields[1].parse::<f64>().unwrap(),
                );
            }
            "interface" => interface.extend(fields.iter().filter_map(|f| f.parse::<u32>().ok())),
            "penalty" => {
                penalty = fields[0].parse().unwrap();
                section = "";
            }
            "load" => pressure = fields[2].parse().unwrap(),
            _ => {}
        }
    }
    let mut inside = false;
    let mut profile = Vec::new();
    for line in dat.lines() {
        if line.contains("displacements") {
            inside = line.contains("IFPLATE");
            continue;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        if inside && f.len() == 4 {
            let node: u32 = f[0].parse().unwrap();
            assert!(interface.contains(&node));
            let v: f64 = f[2].parse().unwrap();
            profile.push((nodes[&node], -penalty * v / pressure));
        }
    }
    profile.sort_by(|a, b| a.0.total_cmp(&b.0));
    profile
}

/// The mean of a nodal profile (x, P_r / P) over [from, end] by trapezoids between the nodes.
fn trapezoid_mean(profile: &[(f64, f64)], from: f64) -> f64 {
    let end = profile[profile.len() - 1].0;
    let mut sum = 0.0;
    for w in profile.windows(2) {
        let ((mut x0, mut r0), (x1, r1)) = (w[0], w[1]);
        if x1 <= from {
            continue;
        }
        if x0 < from {
            r0 += (r1 - r0) * (from - x0) / (x1 - x0);
            x0 = from;
        }
        sum += 0.5 * (r0 + r1) * (x1 - x0);
    }
    sum / (end - from)
}

#[test]
fn continuum_contact_pressure_agrees_with_calculix_away_from_the_corner() {
    // The paper's plate at K_T = 1e6 and 1e4 (CalculiX's coarse decks, the same mesh as ours):
    // the dip below P beyond t_p from the free end to 0.002 P, the mean over the last t_p to 2 %
    // (both profiles integrated alike); the corner node is singular in both and is not compared.
    for (name, kt) in [("paper-plate", 1e6), ("plate-kt1e4", 1e4)] {
        let ccx = calculix_pressure(name);
        let params = PlateParams {
            tangential_stiffness: kt,
            ..PlateParams::PAPER
        };
        let ours = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
        let (l, t) = (params.half_length, params.thickness);
        let dip = |p: &[(f64, f64)]| {
            p.iter()
                .filter(|(x, _)| *x <= l - t)
                .fold(f64::INFINITY, |m, q| m.min(q.1))
        };
        assert!(
            (dip(&ccx) - ours.interior_pressure_range.0).abs() < 2e-3,
            "{name}: {} vs CalculiX {}",
            ours.interior_pressure_range.0,
            dip(&ccx)
        );
        let (a, b) = (
            trapezoid_mean(&ours.contact_pressure, l - t),
            trapezoid_mean(&ccx, l - t),
        );
        assert!(
            (a / b - 1.0).abs() < 0.02,
            "{name}: last t_p {a} vs CalculiX {b}"
        );
        assert!(ccx.iter().all(|q| q.1 > 0.9), "{name}: CalculiX >= 0.9 P");
    }
}

#[test]
fn the_pressure_over_the_last_thickness_converges_and_the_corner_node_does_not() {
    let solve =
        |layers| solve_plate_continuum(PlateParams::PAPER, ContinuumMesh { layers }).unwrap();
    let (coarse, fine, finer) = (solve(4), solve(8), solve(16));
    for (a, b, band) in [
        (
            coarse.end_layer_pressure_ratio,
            fine.end_layer_pressure_ratio,
            1e-3,
        ),
        (
            fine.end_layer_pressure_ratio,
            finer.end_layer_pressure_ratio,
            1e-3,
        ),
        (fine.edge_pressure_ratio, finer.edge_pressure_ratio, 0.02),
    ] {
        assert!((a / b - 1.0).abs() < band, "{a} vs {b}");
    }
    // The free-end node's value grows by about the same amount at each halving: a logarithmic
    // singularity at the corner, not a number to converge.
    let (g1, g2) = (
        fine.end_pressure_ratio - coarse.end_pressure_ratio,
        finer.end_pressure_ratio - fine.end_pressure_ratio,
    );
    assert!(
        g1 > 0.3 && g2 > 0.3 && (g2 / g1 - 1.0).abs() < 0.1,
        "{g1}, {g2}"
    );
    // The whole face carries P L.
    let total = coarse.end_layer_pressure_ratio * 0.2
        + coarse
            .contact_pressure
            .windows(2)
            .filter(|w| w[1].0 <= 9.8)
            .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
            .sum::<f64>();
    assert!((total / 10.0 - 1.0).abs() < 2e-3, "{total}");
}

/// Plates off every calibration grid (`examples/v1_calibration.rs --hold-out` takes these values).
fn hold_out(alpha_tp: f64, nu: f64, mu: f64, t_over_l: f64) -> PlateParams {
    let thickness = 0.2;
    PlateParams {
        half_length: thickness / t_over_l,
        thickness,
        youngs_modulus: 70_000.0,
        poisson: nu,
        friction: mu,
        pressure: 10.0,
        tangential_stiffness: alpha_tp * alpha_tp * 70_000.0 / ((1.0 - nu * nu) * thickness),
    }
}

#[test]
fn where_the_strip_theory_is_measured_wrong_it_is_off_by_more_than_stated() {
    let mut judged = 0;
    for alpha_tp in [0.8, 1.3, 2.6, 6.0] {
        for nu in [0.15, 0.47] {
            for mu in [0.2, 2.0] {
                let params = hold_out(alpha_tp, nu, mu, 0.05);
                let plate = SqueezedPlate::new(params).unwrap();
                let v = plate.validity();
                let Some(least) = v.measured_at_least else {
                    continue;
                };
                assert_eq!(v.validity, Validity::MeasuredWrong);
                let c = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
                let error =
                    (c.end_displacement_mean / plate.regularized().end_displacement() - 1.0).abs();
                assert!(
                    error > least,
                    "alpha t_p {alpha_tp} nu {nu} mu {mu}: {error} <= {least}"
                );
                judged += 1;
            }
        }
    }
    assert!(judged >= 10, "{judged}");
}

#[test]
fn the_flat_plate_model_gets_the_last_thickness_only_where_friction_slides_there() {
    // Where the strip theory's slip zone is at least t_p, the flat model's mean over the last t_p
    // was measured within -30 % to +41 % of the continuum's excess over P; elsewhere it is not
    // given, and its mu-driven values were measured up to 1400 times the continuum's excess.
    let mut applied = 0;
    for (alpha_tp, nu, mu) in [
        (0.8, 0.35, 0.03),
        (2.6, 0.47, 0.2),
        (6.0, 0.35, 0.03),
        (1.3, 0.15, 0.03),
    ] {
        let params = hold_out(alpha_tp, nu, mu, 0.01);
        let plate = SqueezedPlate::new(params).unwrap();
        let c = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
        let measured = c.end_layer_pressure_ratio - 1.0;
        match plate.end_layer_pressure() {
            Some(flat) => {
                let ratio = (flat - 1.0) / measured;
                assert!(
                    (0.65..1.45).contains(&ratio),
                    "alpha t_p {alpha_tp}: {ratio}"
                );
                applied += 1;
            }
            None => assert!(plate.regularized().macroslip_length() < params.thickness),
        }
    }
    assert!(applied >= 3, "{applied}");
    // No slip zone (mu = 2): the flat model's edge value is driven by mu, the plate's is not.
    let params = hold_out(0.8, 0.35, 2.0, 0.01);
    let plate = SqueezedPlate::new(params).unwrap();
    assert_eq!(plate.end_layer_pressure(), None);
    let c = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
    let flat = plate.contact_pressure();
    assert!(flat.ratio(params.half_length) > 3.0 && c.end_layer_pressure_ratio < 1.2);
    assert!(flat.ratio(0.0) < 0.5 && c.contact_pressure[0].1 > 0.99);
}
