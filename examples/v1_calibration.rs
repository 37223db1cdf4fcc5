//! The calibration of (V1), the strip theory's envelope (docs/theory.md, section 8): the plane-strain
//! continuum solver over a grid of plates, and for each quantity the strip theory states (u(L) as
//! the thickness mean, and as the contact-face and mid-thickness values it stands for; the slip-zone
//! length L - X_r) the worst relative difference, by alpha t_p and by the strip theory's slip-zone
//! length over the thickness, (L - X_r) / t_p.
//!
//! ```text
//! cargo run --release --example v1_calibration --no-default-features
//! cargo run --release --example v1_calibration --no-default-features -- --measured-wrong
//! cargo run --release --example v1_calibration --no-default-features -- --hold-out
//! ```
//!
//! `--measured-wrong` runs the grid that drew the region (V1c) where the strip theory is measured
//! wrong (alpha t_p from 0.55 to 20, short slip zones); `--hold-out` the plates that test it
//! (every value off both grids).

use microslip::problems::plate::continuum::{ContinuumMesh, solve_plate_continuum};
use microslip::{PlateParams, SqueezedPlate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mode = std::env::args().nth(1).unwrap_or_default();
    let (ratios, poissons, frictions, slenderness): (&[f64], &[f64], &[f64], &[f64]) =
        match mode.as_str() {
            "--measured-wrong" => (
                &[0.55, 0.6, 0.7, 0.85, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 20.0],
                &[0.05, 0.2, 0.3, 0.45, 0.49],
                &[0.02, 0.05, 0.1, 0.3, 1.0, 3.0, 10.0],
                &[0.005, 0.02, 0.1, 0.3],
            ),
            "--hold-out" => (
                &[0.58, 0.65, 0.8, 1.3, 2.6, 6.0, 14.0],
                &[0.15, 0.35, 0.47],
                &[0.03, 0.2, 0.6, 2.0],
                &[0.01, 0.05, 0.2],
            ),
            _ => (
                &[0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 2.0, 3.5],
                &[0.05, 0.2, 0.3, 0.45, 0.49],
                &[0.05, 0.1, 0.3, 1.0],
                &[0.005, 0.02, 0.1],
            ),
        };
    println!("alpha_tp,nu,mu,tp_over_L,slip_over_tp,err_mean,err_face,err_mid,err_slip_length");
    for &ratio in ratios {
        for &nu in poissons {
            for &mu in frictions {
                for &t_over_l in slenderness {
                    let thickness = 0.2;
                    let youngs = 70_000.0;
                    // alpha t_p = ratio: K_T = ratio^2 E / ((1 - nu^2) t_p).
                    let kt = ratio * ratio * youngs / ((1.0 - nu * nu) * thickness);
                    let params = PlateParams {
                        half_length: thickness / t_over_l,
                        thickness,
                        youngs_modulus: youngs,
                        poisson: nu,
                        friction: mu,
                        pressure: 10.0,
                        tangential_stiffness: kt,
                    };
                    let strip = SqueezedPlate::new(params)?.regularized();
                    let u = strip.end_displacement();
                    let slip = params.half_length - strip.micro_zone_end();
                    let Ok(c) = solve_plate_continuum(params, ContinuumMesh::default()) else {
                        continue;
                    };
                    let slip_c = params.half_length - c.micro_zone_end;
                    let slip_err = if slip > 0.0 {
                        slip / slip_c.max(1e-300) - 1.0
                    } else if slip_c > 0.0 {
                        f64::INFINITY
                    } else {
                        0.0
                    };
                    println!(
                        "{ratio},{nu},{mu},{t_over_l},{:.4},{:.5},{:.5},{:.5},{:.4}",
                        slip / thickness,
                        c.end_displacement_mean / u - 1.0,
                        c.end_displacement_face / u - 1.0,
                        c.end_displacement_mid / u - 1.0,
                        slip_err
                    );
                }
            }
        }
    }
    Ok(())
}
