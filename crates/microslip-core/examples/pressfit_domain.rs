//! Measures the press fit's 1-D theory against its axisymmetric continuum (docs/theory.md
//! (S10)): `cargo run --release -p microslip-core --example pressfit_domain -- converge` prints
//! the mesh and increment ladder of one fit, `-- sweep` the table of fits.

use microslip_core::problems::pressfit::closed_form::PressFit;
use microslip_core::problems::pressfit::continuum::{
    PressFitContinuumMesh, solve_pressfit_continuum_path,
};
use microslip_core::problems::pressfit::params::PressFitParams;

/// A fit of the given dimensionless groups: r = 20 mm, steel, delta = 1e-4 r, mu = 0.1, K_T
/// from kappa = K_T r / E.
fn fit(l_over_r: f64, shaft_wall: f64, hub_wall: f64, kappa: f64) -> PressFitParams {
    let r = 20.0;
    PressFitParams {
        fit_radius: r,
        bore_radius: r * (1.0 - shaft_wall),
        outer_radius: r * (1.0 + hub_wall),
        length: l_over_r * r,
        shaft_modulus: 210_000.0,
        shaft_poisson: 0.3,
        hub_modulus: 210_000.0,
        hub_poisson: 0.3,
        interference: 1e-4 * r,
        friction: 0.1,
        tangential_stiffness: kappa * 210_000.0 / r,
    }
}

fn row(params: PressFitParams, mesh: PressFitContinuumMesh) {
    let fit = PressFit::new(params).unwrap();
    let gross = fit.gross_slip_force();
    let fractions = [0.3, 0.8];
    let forces: Vec<f64> = fractions.iter().map(|f| f * gross).collect();
    let start = std::time::Instant::now();
    let states = solve_pressfit_continuum_path(params, &forces, mesh);
    let time = start.elapsed().as_secs_f64();
    let v = fit.validity(fit.force(forces[1]).unwrap());
    print!(
        "L/r {:5.2} ts/r {:4.2} th/r {:4.2} KT {:9.3e} lamL {:6.2} m {:2} inc {:2} |",
        params.length / params.fit_radius,
        (params.fit_radius - params.bore_radius) / params.fit_radius,
        (params.outer_radius - params.fit_radius) / params.fit_radius,
        params.tangential_stiffness,
        fit.axial().decay_rate() * params.length,
        mesh.layers,
        mesh.force_increments,
    );
    match states {
        Ok(states) => {
            let soft = fit
                .with_tangential_stiffness(fit.effective_stiffness())
                .unwrap();
            for (state, force) in states.iter().zip(&forces) {
                let closed = fit.regularized(fit.force(*force).unwrap()).response();
                let eff = soft.regularized(soft.force(*force).unwrap()).response();
                let rw = fit.wall_shear(fit.force(*force).unwrap());
                print!(
                    " {:.5e} {:+7.2}% eff {:+6.2}% rw {:.3} |",
                    state.delta,
                    100.0 * (closed / state.delta - 1.0),
                    100.0 * (eff / state.delta - 1.0),
                    rw,
                );
            }
            let pmax = states[1].pressure.iter().fold(0.0_f64, |m, p| m.max(p.1));
            println!(
                " pc {:.3} {:.3} {:.3} s pairs {}",
                pmax / fit.contact_pressure(),
                v.poisson_coupling,
                time,
                states[0].pairs
            );
        }
        Err(e) => println!(" {e}"),
    }
}

/// One line per load fraction: the groups, the indicators and the 1-D Delta's error against the
/// continuum (at K_T and at K_eff).
fn csv(params: PressFitParams, mesh: PressFitContinuumMesh) {
    let fit = PressFit::new(params).unwrap();
    let soft = fit
        .with_tangential_stiffness(fit.effective_stiffness())
        .unwrap();
    let gross = fit.gross_slip_force();
    let fractions = [0.3, 0.8];
    let forces: Vec<f64> = fractions.iter().map(|f| f * gross).collect();
    let r = params.fit_radius;
    let head = format!(
        "{},{},{},{:.4},{:.4}",
        params.length / r,
        (r - params.bore_radius) / r,
        (params.outer_radius - r) / r,
        params.tangential_stiffness * r / params.shaft_modulus,
        fit.axial().decay_rate() * params.length
    );
    match solve_pressfit_continuum_path(params, &forces, mesh) {
        Ok(states) => {
            for ((state, force), fraction) in states.iter().zip(&forces).zip(fractions) {
                let load = fit.force(*force).unwrap();
                let v = fit.validity(load);
                let closed = fit.regularized(load).response();
                let eff = soft.regularized(soft.force(*force).unwrap()).response();
                println!(
                    "{head},{fraction},{:.5},{:.5},{:.5},{:.5},{:.5},{:.6e},{:.5}",
                    v.wall_shear,
                    v.poisson_coupling,
                    v.end_effect,
                    closed / state.delta - 1.0,
                    eff / state.delta - 1.0,
                    state.delta,
                    v.expected_error.unwrap_or(f64::NAN)
                );
            }
        }
        Err(e) => println!("{head},error,{e}"),
    }
}

fn main() {
    let mode = std::env::args().nth(1).unwrap_or_default();
    let ladder = [2, 4, 6, 8, 16];
    match mode.as_str() {
        "converge" => {
            for params in [
                PressFitParams::CCX98,
                fit(0.5, 0.5, 0.5, 1.0),
                fit(8.0, 0.1, 0.1, 1.0),
                fit(2.0, 1.0, 2.0, 0.1),
            ] {
                for layers in ladder {
                    row(
                        params,
                        PressFitContinuumMesh {
                            layers,
                            force_increments: 8,
                        },
                    );
                }
                row(
                    params,
                    PressFitContinuumMesh {
                        layers: 8,
                        force_increments: 32,
                    },
                );
            }
        }
        "bundled" => {
            // The bundled fit at 0.3 and 0.8 F_gross on the default mesh: what theory.md quotes.
            let params = PressFitParams::CCX98;
            let fit = PressFit::new(params).unwrap();
            let forces = [0.3, 0.8].map(|f| f * fit.gross_slip_force());
            let states =
                solve_pressfit_continuum_path(params, &forces, PressFitContinuumMesh::default())
                    .unwrap();
            for (state, force) in states.iter().zip(forces) {
                let closed = fit.regularized(fit.force(force).unwrap());
                let (p0, pl) = (state.pressure[0].1, state.pressure[state.pairs - 1].1);
                println!(
                    "F {force:.1} N: Delta {:.5e} (1-D {:.5e}), local zones {:?}, nominal {:?} \
                     (1-D: loaded {:.3}, held {:.3}), capacity {:.1} N, p(0) {p0:.3}, p(L) {pl:.3}",
                    state.delta,
                    closed.response(),
                    state.local_zones,
                    state.nominal_zones,
                    closed.slide_from_loaded_face(),
                    closed.slide_from_held_face(),
                    state.capacity,
                );
            }
        }
        "kt" => {
            // The cost of a stiff interface on the bundled fit: `-- kt 3e7`.
            let kt: f64 = std::env::args().nth(2).unwrap().parse().unwrap();
            let params = PressFitParams {
                tangential_stiffness: kt,
                ..PressFitParams::CCX98
            };
            row(params, PressFitContinuumMesh::default());
        }
        "probe" => {
            let arg = |i: usize| -> f64 { std::env::args().nth(i).unwrap().parse().unwrap() };
            let (l, ts, th) = (arg(2), arg(3), arg(4));
            for kappa in [0.01, 0.1, 1.0, 10.0] {
                for layers in [4, 8, 16] {
                    let params = fit(l, ts, th, kappa);
                    let f = PressFit::new(params).unwrap();
                    let force = 0.1 * f.first_slip_force();
                    let mesh = PressFitContinuumMesh {
                        layers,
                        force_increments: 8,
                    };
                    match solve_pressfit_continuum_path(params, &[force], mesh) {
                        Ok(s) => {
                            let bar = force * params.length
                                / (params.shaft_modulus * params.shaft_area()
                                    + params.hub_modulus * params.hub_area());
                            let closed = f.regularized(f.force(force).unwrap()).response();
                            println!(
                                "kappa {kappa} layers {layers} cont/closed {:.4} cont/bar {:.4} closed/bar {:.4} pairs {}",
                                s[0].delta / closed,
                                s[0].delta / bar,
                                closed / bar,
                                s[0].pairs
                            );
                        }
                        Err(e) => println!("kappa {kappa} layers {layers}: {e}"),
                    }
                }
            }
        }
        "sweep" | "holdout" => {
            // The calibration grid, or the hold-out fits (values the grid does not have, other
            // materials, mu and interference).
            let mesh = PressFitContinuumMesh::default();
            println!("L/r,ts/r,th/r,kappa,lambdaL,fraction,rw,poisson,end,err,err_eff,delta,bound");
            let fits: Vec<PressFitParams> = if mode == "sweep" {
                let mut fits = Vec::new();
                for l in [0.5, 1.0, 2.0, 4.0, 8.0] {
                    for ts in [0.1, 0.5, 1.0] {
                        for th in [0.1, 0.5, 2.0] {
                            for kappa in [0.01, 0.1, 1.0] {
                                fits.push(fit(l, ts, th, kappa));
                            }
                        }
                    }
                }
                fits
            } else {
                let mut fits = Vec::new();
                for (l, ts, th, kappa) in [
                    // Inside the calibrated ranges, at values the grid does not have.
                    (3.0, 0.3, 1.0, 0.3),
                    (6.0, 0.2, 0.3, 0.05),
                    (2.5, 0.75, 0.25, 0.5),
                    (7.0, 0.15, 0.15, 0.2),
                    (2.2, 1.0, 1.0, 0.03),
                    (5.0, 1.0, 0.7, 0.7),
                    // Outside them: shorter, longer, stiffer.
                    (1.5, 0.75, 0.25, 0.5),
                    (12.0, 0.15, 0.15, 0.2),
                    (0.75, 1.0, 1.0, 0.03),
                    (5.0, 1.0, 0.7, 2.0),
                ] {
                    fits.push(fit(l, ts, th, kappa));
                    // An aluminium hub on a steel shaft, mu 0.2, a larger interference.
                    fits.push(PressFitParams {
                        hub_modulus: 70_000.0,
                        hub_poisson: 0.33,
                        friction: 0.2,
                        interference: 3e-4 * 20.0,
                        ..fit(l, ts, th, kappa)
                    });
                }
                fits
            };
            for params in fits {
                csv(params, mesh);
            }
        }
        _ => {
            // The default mesh's cost: the bundled fit and the grid's largest meshes.
            let mesh = PressFitContinuumMesh::default();
            for params in [
                PressFitParams::CCX98,
                fit(8.0, 0.1, 0.1, 1.0),
                fit(8.0, 0.1, 2.0, 1.0),
                fit(8.0, 0.5, 0.1, 1.0),
            ] {
                row(params, mesh);
            }
        }
    }
}
