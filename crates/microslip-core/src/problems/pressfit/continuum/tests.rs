//! Tests of the press fit's continuum (docs/theory.md (S10)). Debug builds run them: the meshes
//! are kept small where the answer allows.

use super::*;
use crate::kernel::validity::Validity;
use crate::problems::pressfit::closed_form::PressFit;

const FIT: PressFitParams = PressFitParams::CCX98;

fn mesh(layers: usize) -> PressFitContinuumMesh {
    PressFitContinuumMesh {
        layers,
        force_increments: 8,
    }
}

/// A steel fit of the sweep's groups (theory.md (S10)): r = 20 mm, delta = 1e-4 r, mu = 0.1,
/// K_T = kappa Es / r.
fn grid_fit(l_over_r: f64, shaft_wall: f64, hub_wall: f64, kappa: f64) -> PressFitParams {
    PressFitParams {
        fit_radius: 20.0,
        bore_radius: 20.0 * (1.0 - shaft_wall),
        outer_radius: 20.0 * (1.0 + hub_wall),
        length: 20.0 * l_over_r,
        interference: 2e-3,
        tangential_stiffness: kappa * 210_000.0 / 20.0,
        ..FIT
    }
}

/// |Delta 1-D / Delta continuum - 1| at `fraction` of F_gross, and the envelope there.
fn departure(params: PressFitParams, fraction: f64, layers: usize) -> (f64, PressFitValidityOf) {
    let fit = PressFit::new(params).unwrap();
    let force = fit.force(fraction * fit.gross_slip_force()).unwrap();
    let state = solve_pressfit_continuum(params, force.value(), mesh(layers)).unwrap();
    let closed = fit.regularized(force).response();
    ((closed / state.delta - 1.0).abs(), fit.validity(force))
}

type PressFitValidityOf = crate::problems::pressfit::validity::PressFitValidity;

/// (S10): assembled without friction, shaft and hub both spanning L with free faces, the
/// members' state is Lamé's in plane stress exactly (sigma_z = 0, eps_z uniform in each, u_r
/// independent of x: an exact 3-D solution, the members sliding freely along the interface by
/// their different eps_z). So the pressure is plane stress's at every x, for short and long
/// fits and dissimilar members alike, and not plane strain's (1 / (1 - nu^2) = 10 % higher for
/// equal steels): only the discretization moves it (measured at 4 layers: 1.2e-5 inside, 6e-4
/// at the bundled fit's corners, 3.7e-3 at the steel-aluminium corner's).
#[test]
fn after_assembly_the_pressure_is_lame_s_plane_stress_value_all_along() {
    let long_dissimilar = PressFitParams {
        length: 160.0,
        hub_modulus: 70_000.0,
        hub_poisson: 0.33,
        bore_radius: 0.0,
        ..FIT
    };
    for params in [FIT, long_dissimilar] {
        let state = solve_pressfit_continuum(params, 0.0, mesh(4)).unwrap();
        let stress = contact_pressure(&params, PlaneState::Stress);
        let strain = contact_pressure(&params, PlaneState::Strain);
        assert!(strain / stress - 1.0 > 0.05, "{strain} {stress}");
        let length = params.length;
        for &(x, p) in &state.pressure {
            let off = (p / stress - 1.0).abs();
            let allowed = if x > 0.2 * length && x < 0.8 * length {
                1e-4
            } else {
                5e-3
            };
            assert!(off < allowed, "x = {x}: p = {p} against {stress}");
        }
        assert!((state.mean_pressure / stress - 1.0).abs() < 1e-4);
        assert!(state.delta == 0.0 && state.separated.is_empty());
    }
}

#[test]
fn the_interface_carries_f_and_below_first_slip_delta_is_linear() {
    let fit = PressFit::new(FIT).unwrap();
    let gross = fit.gross_slip_force();
    let forces = [0.0, 0.05 * gross, 0.1 * gross, 0.8 * gross];
    let states = solve_pressfit_continuum_path(FIT, &forces, mesh(4)).unwrap();
    for (state, force) in states.iter().zip(forces) {
        assert!(
            (state.transferred_force - force).abs() <= 1e-8 * gross,
            "{} {force}",
            state.transferred_force
        );
        // The shear integrates to the same force over the interface's area (2 pi r dx).
        let grid = Grid::new(&FIT, mesh(4), 1.0 / decay_rate(&FIT));
        let area: Vec<f64> = grid
            .two
            .pair_weights
            .iter()
            .map(|w| w * FIT.interface_width())
            .collect();
        let integral: f64 = area
            .iter()
            .zip(&state.shear)
            .map(|(a, (_, tau))| a * tau)
            .sum();
        assert!((integral - force).abs() <= 1e-8 * gross, "{integral}");
    }
    assert_eq!(states[0].delta, 0.0);
    assert!((states[2].delta / states[1].delta - 2.0).abs() < 1e-9);
    let z = states[1].local_zones;
    assert_eq!((z.from_loaded_face, z.from_held_face), (0.0, 0.0));
    // At 0.8 F_gross the interface slides from a face, and Delta grew faster than F.
    let zones = states[3].local_zones;
    assert!(
        zones.from_loaded_face + zones.from_held_face > 0.0,
        "{zones:?}"
    );
    assert!(states[3].delta / states[2].delta > 8.0);
    // The push swells the shaft: the continuum's capacity rises above mu p 2 pi r L.
    assert!(states[3].capacity > gross && states[3].capacity < 1.01 * gross);
}

#[test]
fn delta_converges_with_the_mesh_and_not_with_the_increments() {
    let fit = PressFit::new(FIT).unwrap();
    let force = 0.8 * fit.gross_slip_force();
    let delta = |layers: usize, increments: usize| {
        let mesh = PressFitContinuumMesh {
            layers,
            force_increments: increments,
        };
        solve_pressfit_continuum(FIT, force, mesh).unwrap().delta
    };
    let (d2, d4, d8) = (delta(2, 8), delta(4, 8), delta(8, 8));
    // Differences fall with h (measured: 2.2e-3, 9.7e-4 relative; 16 layers moves 8's by 4.6e-4).
    assert!((d4 - d8).abs() < 0.6 * (d2 - d4).abs(), "{d2} {d4} {d8}");
    assert!((d8 / d4 - 1.0).abs() < 2e-3, "{d4} {d8}");
    // The path is monotonic and the strengths move little: 32 increments give 8's Delta.
    assert!((delta(4, 32) / d4 - 1.0).abs() < 1e-9);
}

/// K_T -> infinity: the continuum's Delta approaches its Coulomb limit with a gap falling like
/// 1/K_T (the interface's compliance in series), as the closed form's does.
#[test]
fn a_stiff_interface_approaches_its_limit_like_one_over_k_t() {
    let short = PressFitParams { length: 8.0, ..FIT };
    let fit = PressFit::new(short).unwrap();
    let force = 0.3 * fit.gross_slip_force();
    let delta = |kt: f64| {
        let params = PressFitParams {
            tangential_stiffness: kt,
            ..short
        };
        solve_pressfit_continuum(params, force, mesh(2))
            .unwrap()
            .delta
    };
    let d = [delta(1e5), delta(1e6), delta(1e7)];
    let (first, second) = (d[0] - d[1], d[1] - d[2]);
    assert!(first > 0.0 && second > 0.0, "{d:?}");
    assert!((first / second / 10.0 - 1.0).abs() < 0.3, "{d:?}");
}

/// Where the theory holds (long, thin walls, a soft interface) the 1-D Delta is within its
/// envelope of the continuum, and within 2 %; a short thick fit (the bundled one: L/r = 0.89,
/// walls of half the radius) departs by half (the walls' shear and the faces' load paths), and
/// the envelope does not vouch for it.
#[test]
fn the_1d_delta_holds_on_long_thin_fits_and_departs_on_short_thick_ones() {
    let (error, envelope) = departure(grid_fit(4.0, 0.1, 0.1, 0.1), 0.3, 2);
    let bound = envelope.expected_error.unwrap();
    assert!(error < 0.02 && error < bound, "{error} {bound}");
    let (error, envelope) = departure(FIT, 0.3, 4);
    assert!(error > 0.45, "{error}");
    assert_eq!(envelope.validity, Validity::NotCalibrated);
    assert!(envelope.outside_calibration.unwrap().contains("L/r"));
}

/// The envelope on fits held out of its calibration (theory.md (S10)'s hold-outs, a coarser
/// mesh): each measured departure under the bound.
#[test]
fn the_envelope_bounds_fits_it_was_not_calibrated_on() {
    for (params, fraction) in [
        (grid_fit(3.0, 0.3, 1.0, 0.3), 0.3),
        (
            PressFitParams {
                hub_modulus: 70_000.0,
                hub_poisson: 0.33,
                friction: 0.2,
                interference: 6e-3,
                ..grid_fit(2.2, 1.0, 1.0, 0.03)
            },
            0.8,
        ),
    ] {
        let (error, envelope) = departure(params, fraction, 4);
        let bound = envelope.expected_error.unwrap();
        assert!(error < bound, "{params:?}: {error} > {bound}");
    }
}

#[test]
fn inputs_it_cannot_resolve_are_refused_with_their_reason() {
    let message = |params: PressFitParams, force: f64, mesh: PressFitContinuumMesh| {
        solve_pressfit_continuum(params, force, mesh)
            .unwrap_err()
            .to_string()
    };
    let m = PressFitContinuumMesh::default();
    assert!(message(FIT, 1400.0, m).contains("F_gross"));
    assert!(message(FIT, f64::NAN, m).contains('F'));
    let bad = PressFitParams {
        bore_radius: 25.0,
        ..FIT
    };
    assert!(message(bad, 100.0, m).contains("ri"));
    // Layers outside 1..=32, no increment.
    let refused = [(0, 8), (33, 8), (4, 0)].map(|(layers, force_increments)| {
        let mesh = PressFitContinuumMesh {
            layers,
            force_increments,
        };
        solve_pressfit_continuum(FIT, 100.0, mesh)
            .unwrap_err()
            .to_string()
    });
    assert!(refused[0].contains("layers = 0") && refused[1].contains("layers = 33"));
    assert!(refused[2].contains("force_increments = 0"), "{refused:?}");
    let long = PressFitParams {
        length: 5000.0,
        ..FIT
    };
    assert!(message(long, 100.0, m).contains("interface pairs"));
    let lopsided = PressFitParams {
        bore_radius: 19.99,
        outer_radius: 2000.0,
        length: 1.0,
        ..FIT
    };
    let lopsided = message(lopsided, 1e-3, m);
    assert!(lopsided.contains("taller than long"), "{lopsided}");
    let path = solve_pressfit_continuum_path(FIT, &[500.0, 100.0], m).unwrap_err();
    assert!(path.to_string().contains("must not decrease"), "{path}");
}

/// Every accepted input gives finite numbers or a refusal, never a NaN nor a panic: extreme
/// interfaces, a nearly incompressible shaft, a tiny interference, thin and thick walls.
#[test]
fn extreme_inputs_are_answered_finitely_or_refused() {
    let cases = [
        PressFitParams {
            tangential_stiffness: 1e-6,
            ..FIT
        },
        PressFitParams {
            tangential_stiffness: 1e7,
            ..FIT
        },
        PressFitParams {
            shaft_poisson: 0.49,
            bore_radius: 0.0,
            ..FIT
        },
        PressFitParams {
            interference: 1e-6,
            friction: 1e-3,
            ..FIT
        },
        PressFitParams {
            bore_radius: 19.9,
            outer_radius: 20.1,
            length: 5.0,
            ..FIT
        },
        PressFitParams {
            outer_radius: 400.0,
            hub_modulus: 1e3,
            ..FIT
        },
    ];
    for params in cases {
        let fit = PressFit::new(params).unwrap();
        let forces = [0.3, 0.99].map(|f| f * fit.gross_slip_force());
        match solve_pressfit_continuum_path(params, &forces, mesh(2)) {
            Ok(states) => {
                for state in states {
                    assert!(state.delta.is_finite() && state.delta >= 0.0, "{params:?}");
                    assert!(state.pressure.iter().all(|(_, p)| p.is_finite()));
                }
            }
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    }
    // Stiffer still, the mesh that resolves 1/lambda is refused by its size before it is built.
    let stiff = PressFitParams {
        tangential_stiffness: 1e8,
        ..FIT
    };
    let refused = solve_pressfit_continuum(stiff, 100.0, mesh(2)).unwrap_err();
    assert!(refused.to_string().contains("interface pairs"), "{refused}");
}
