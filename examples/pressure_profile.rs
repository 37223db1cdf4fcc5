//! The plane-strain continuum's contact pressure along the face of one plate (docs/theory.md, (P12)):
//! x (mm), P_r / P and u (mm) at each contact-face node, then its summary measures on stderr.
//!
//! ```text
//! cargo run --release --example pressure_profile --no-default-features -- L tp E nu mu P KT layers
//! ```
use microslip::PlateParams;
use microslip::problems::plate::continuum::{ContinuumMesh, solve_plate_continuum};
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap_or(0.0))
        .collect();
    let params = PlateParams {
        half_length: a[0],
        thickness: a[1],
        youngs_modulus: a[2],
        poisson: a[3],
        friction: a[4],
        pressure: a[5],
        tangential_stiffness: a[6],
    };
    let c = solve_plate_continuum(
        params,
        ContinuumMesh {
            layers: a[7] as usize,
        },
    )?;
    for ((x, r), (_, u)) in c.contact_pressure.iter().zip(&c.face) {
        println!("{x:.6} {r:.5} {u:.6e}");
    }
    eprintln!(
        "last t_p {:.5} P, last t_p/10 {:.5} P, end node {:.5} P, beyond t_p {:.5} to {:.5} P; \
         u(L) mean {:.6e} mm, X_r {:.6} mm",
        c.end_layer_pressure_ratio,
        c.edge_pressure_ratio,
        c.end_pressure_ratio,
        c.interior_pressure_range.0,
        c.interior_pressure_range.1,
        c.end_displacement_mean,
        c.micro_zone_end
    );
    Ok(())
}
