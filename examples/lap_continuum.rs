//! The double-lap joint's continuum solver against CalculiX 2.20 and the shear-lag closed form:
//! the tables of the solver's validation (validation/calculix/lap/FIRST-LOOK.md gives CalculiX's
//! numbers; the closed form at K_eff, 1/K_eff = 1/K_T + (t1/2 + t2)/(3G), is its one-line
//! correction).
//!
//! ```text
//! cargo run --release --example lap_continuum --no-default-features
//! ```

use std::time::Instant;

use microslip::problems::lap::closed_form::{LapJoint, LapParams};
use microslip::problems::lap::{
    LAP_POISSON, LapContinuumMesh, solve_lap_continuum, solve_lap_continuum_path,
};

/// CalculiX's Delta (mm), fine meshes (FIRST-LOOK.md section 2: k3_f_100 with p1_f_1000 at
/// 1000 N, k4_f_100 with k4_1000_f1 at 1000 N, k5_f_200).
const FORCES: [f64; 6] = [1000.0, 2000.0, 2400.0, 3000.0, 4500.0, 5500.0];
const CALCULIX: [(f64, [f64; 6]); 3] = [
    (
        1e3,
        [
            0.00462917, 0.00928078, 0.0111975, 0.0141663, 0.0225502, 0.0292301,
        ],
    ),
    (
        1e4,
        [
            0.00379545, 0.00793827, 0.00976758, 0.0126925, 0.0209369, 0.0272012,
        ],
    ),
    (
        1e5,
        [
            0.00364845, 0.00779399, 0.00962541, 0.0125504, 0.0207917, 0.027025,
        ],
    ),
];

fn closed(params: LapParams, force: f64) -> f64 {
    let joint = LapJoint::new(params).unwrap();
    joint
        .regularized(joint.force(force).unwrap())
        .joint_displacement()
}

fn effective(params: LapParams) -> LapParams {
    let shear = params.inner_modulus / (2.0 * (1.0 + LAP_POISSON));
    let compliance = (0.5 * params.inner_thickness + params.cover_thickness) / (3.0 * shear);
    LapParams {
        tangential_stiffness: 1.0 / (1.0 / params.tangential_stiffness + compliance),
        ..params
    }
}

fn pct(a: f64, b: f64) -> String {
    format!("{:+.4} %", 100.0 * (a / b - 1.0))
}

fn main() {
    println!(
        "| K_T | F (N) | CalculiX (mm) | continuum (mm) | vs CalculiX | layers 8 | closed | K_eff closed | a, d nominal | a, d local |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (kt, ccx) in CALCULIX {
        let params = LapParams {
            tangential_stiffness: kt,
            ..LapParams::ALUMINIUM
        };
        let t = Instant::now();
        let ours = solve_lap_continuum_path(params, &FORCES, LapContinuumMesh::default()).unwrap();
        let time = t.elapsed();
        let fine = solve_lap_continuum_path(
            params,
            &FORCES,
            LapContinuumMesh {
                layers: 8,
                ..LapContinuumMesh::default()
            },
        )
        .unwrap();
        for (i, &f) in FORCES.iter().enumerate() {
            let (o, c) = (ours[i].delta, ccx[i]);
            let (n, l) = (ours[i].nominal_zones, ours[i].local_zones);
            println!(
                "| {kt:e} | {f} | {c:.6e} | {o:.7e} | {} | {} | {} | {} | {:.2}, {:.2} | {:.2}, {:.2} |",
                pct(o, c),
                pct(fine[i].delta, o),
                pct(o, closed(params, f)),
                pct(o, closed(effective(params), f)),
                n.from_inner_end,
                n.from_cover_ends,
                l.from_inner_end,
                l.from_cover_ends,
            );
        }
        println!(
            "(path of 6 forces, layers 4: {time:?}; pairs {})",
            ours[0].pairs
        );
    }
    println!("\nIncrements (layers 4): 16 -> 32 -> 8 per F_gross");
    for kt in [1e3, 1e4, 1e5] {
        let params = LapParams {
            tangential_stiffness: kt,
            ..LapParams::ALUMINIUM
        };
        for f in [2400.0, 5500.0] {
            let d = |n: usize| {
                solve_lap_continuum(
                    params,
                    f,
                    LapContinuumMesh {
                        force_increments: n,
                        ..LapContinuumMesh::default()
                    },
                )
                .unwrap()
                .delta
            };
            let (base, double, half) = (d(16), d(32), d(8));
            println!(
                "K_T {kt:e} F {f}: {base:.9e}, 32: {}, 8: {}",
                pct(double, base),
                pct(half, base)
            );
        }
    }
    println!("\nSingle solves, default mesh (the TUI's n):");
    for kt in [1e3, 1e4, 1e5] {
        for f in [1000.0, 5500.0] {
            let params = LapParams {
                tangential_stiffness: kt,
                ..LapParams::ALUMINIUM
            };
            let t = Instant::now();
            let r = solve_lap_continuum(params, f, LapContinuumMesh::default()).unwrap();
            println!(
                "K_T {kt:e} F {f}: {:?} ({} increments, {} fixed-point iterations)",
                t.elapsed(),
                r.increments,
                r.iterations
            );
        }
    }
    println!("\nSoft interfaces and the elastic regime against the closed form (nothing slides):");
    for (label, params, f) in [
        (
            "bundled, K_T 100",
            LapParams {
                tangential_stiffness: 100.0,
                ..LapParams::ALUMINIUM
            },
            1000.0,
        ),
        (
            "bundled, K_T 300",
            LapParams {
                tangential_stiffness: 300.0,
                ..LapParams::ALUMINIUM
            },
            1000.0,
        ),
        ("bundled, K_T 1e3", LapParams::ALUMINIUM, 1000.0),
        (
            "bundled, K_T 1e4",
            LapParams {
                tangential_stiffness: 1e4,
                ..LapParams::ALUMINIUM
            },
            300.0,
        ),
        (
            "bundled, K_T 1e5",
            LapParams {
                tangential_stiffness: 1e5,
                ..LapParams::ALUMINIUM
            },
            100.0,
        ),
        (
            "t1 1 t2 0.5, K_T 100",
            LapParams {
                tangential_stiffness: 100.0,
                inner_thickness: 1.0,
                cover_thickness: 0.5,
                ..LapParams::ALUMINIUM
            },
            200.0,
        ),
        (
            "t1 1 t2 0.5, K_T 30",
            LapParams {
                tangential_stiffness: 30.0,
                inner_thickness: 1.0,
                cover_thickness: 0.5,
                ..LapParams::ALUMINIUM
            },
            200.0,
        ),
        (
            "t1 0.5 t2 0.25, K_T 100",
            LapParams {
                tangential_stiffness: 100.0,
                inner_thickness: 0.5,
                cover_thickness: 0.25,
                ..LapParams::ALUMINIUM
            },
            100.0,
        ),
    ] {
        let t = Instant::now();
        let r = solve_lap_continuum(params, f, LapContinuumMesh::default()).unwrap();
        let joint = LapJoint::new(params).unwrap();
        println!(
            "{label}, F {f}: 1/(lambda t1) = {:.2}, continuum {:.7e} closed {} K_eff {} zones {:?} ({:?}, {} pairs)",
            1.0 / (joint.decay_rate() * params.inner_thickness),
            r.delta,
            pct(r.delta, closed(params, f)),
            pct(r.delta, closed(effective(params), f)),
            r.local_zones,
            t.elapsed(),
            r.pairs
        );
    }
}
