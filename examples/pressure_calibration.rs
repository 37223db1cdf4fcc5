//! The contact pressure under the squeezed plate: the flat Timoshenko-plate model (P7-P9,
//! `SqueezedPlate::contact_pressure`) against the plane-strain continuum's own contact pressure
//! (`solve_plate_continuum`), over a grid of plates, with the continuum at two or three meshes
//! (4, 8 and 16 elements through the thickness) to show what converges (docs/theory.md, (P12)).
//!
//! ```text
//! cargo run --release --example pressure_calibration --no-default-features > pressure.csv
//! ```
//!
//! Columns: the plate (alpha t_p, nu, mu, t_p / L, the strip theory's slip zone over t_p); the
//! flat-plate model's P_r / P at the centre and the free end, its mean and peak deviation, its
//! flag and its mean P_r / P over the last t_p; the continuum's P_r / P at the centre, its range at
//! least t_p from the free end, its mean over the last t_p and over the last t_p / 10 and its
//! free-end nodal value, each at 4, 8 and (with `--fine`) 16 layers; the continuum's
//! thickness-mean u(L) over the strip theory's, minus 1; its largest |P_r / P - 1| at least 2 and
//! 3 t_p from the free end and its mean |P_r / P - 1| (8 layers).

use microslip::problems::plate::continuum::{ContinuumMesh, ContinuumPlate, solve_plate_continuum};
use microslip::{PlateParams, SqueezedPlate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let fine = args.iter().any(|a| a == "--fine");
    let ratios = [0.05, 0.2, 0.5, 1.0, 2.0, 3.5, 8.0];
    let poissons = [0.05, 0.3, 0.45, 0.49];
    let frictions = [0.05, 0.3, 1.0, 3.0];
    let slenderness = [0.005, 0.05, 0.3];
    println!(
        "alpha_tp,nu,mu,tp_over_L,slip_over_tp,flat_centre,flat_edge,flat_mean_dev,flat_peak_dev,\
         flat_holds,flat_end_layer,{},{},{},err_mean,c_dev_2tp,c_dev_3tp,c_mean_dev",
        columns(4),
        columns(8),
        columns(16)
    );
    for &ratio in &ratios {
        for &nu in &poissons {
            for &mu in &frictions {
                for &t_over_l in &slenderness {
                    let thickness = 0.2;
                    let youngs = 70_000.0;
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
                    let plate = SqueezedPlate::new(params)?;
                    let strip = plate.regularized();
                    let flat = plate.contact_pressure();
                    let solve = |layers| solve_plate_continuum(params, ContinuumMesh { layers });
                    let (Ok(c4), Ok(c8)) = (solve(4), solve(8)) else {
                        continue;
                    };
                    let c16 = if fine { solve(16).ok() } else { None };
                    println!(
                        "{ratio},{nu},{mu},{t_over_l},{:.4},{:.5},{:.5},{:.5},{:.5},{},{:.5},{},{},{},{:.5},{:.5},{:.5},{:.5}",
                        (params.half_length - strip.micro_zone_end()) / thickness,
                        flat.ratio(0.0),
                        flat.ratio(params.half_length),
                        flat.mean_deviation(),
                        flat.peak_deviation(),
                        flat.constant_pressure_holds(),
                        flat.mean_ratio_over(params.half_length - thickness, params.half_length),
                        measures(Some(&c4)),
                        measures(Some(&c8)),
                        measures(c16.as_ref()),
                        c8.end_displacement_mean / strip.end_displacement() - 1.0,
                        deviation_until(&c8, params.half_length - 2.0 * thickness),
                        deviation_until(&c8, params.half_length - 3.0 * thickness),
                        mean_deviation(&c8, params.half_length),
                    );
                }
            }
        }
    }
    Ok(())
}

/// The column names of [`measures`] at `layers`.
fn columns(layers: usize) -> String {
    [
        "centre",
        "interior_min",
        "interior_max",
        "end_layer",
        "edge",
        "end_node",
    ]
    .map(|c| format!("c_{c}_{layers}"))
    .join(",")
}

/// The continuum's pressure measures: P_r / P at the centre, its range at least t_p from the
/// free end, its mean over the last t_p and over the last t_p / 10, its free-end nodal value.
fn measures(c: Option<&ContinuumPlate>) -> String {
    c.map_or_else(
        || ["NaN"; 6].join(","),
        |c| {
            [
                c.contact_pressure[0].1,
                c.interior_pressure_range.0,
                c.interior_pressure_range.1,
                c.end_layer_pressure_ratio,
                c.edge_pressure_ratio,
                c.end_pressure_ratio,
            ]
            .map(|v| format!("{v:.5}"))
            .join(",")
        },
    )
}

/// Largest |P_r / P - 1| at the nodes with x <= `until`.
fn deviation_until(c: &ContinuumPlate, until: f64) -> f64 {
    c.contact_pressure
        .iter()
        .filter(|(x, _)| *x <= until)
        .fold(0.0, |m: f64, (_, r)| m.max((r - 1.0).abs()))
}

/// Mean |P_r / P - 1| over [0, L] (trapezoids between the nodes).
fn mean_deviation(c: &ContinuumPlate, length: f64) -> f64 {
    c.contact_pressure
        .windows(2)
        .map(|w| 0.5 * ((w[0].1 - 1.0).abs() + (w[1].1 - 1.0).abs()) * (w[1].0 - w[0].0))
        .sum::<f64>()
        / length
}
