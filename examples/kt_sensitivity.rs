//! How much does the answer depend on K_T? A table for the paper's twin beams: for K_T from 1/100 to
//! 100 times the paper's 600 MPa/mm, the first-macroslip force F_1, the slip boundary X and the tip
//! deflection w(L) at F = 100 N, against plain Coulomb.
//!
//! Uses the library alone (no command line, no terminal):
//!
//! ```text
//! cargo run --example kt_sensitivity --no-default-features
//! ```

use microslip::study::curves::{Samples, Spacing};
use microslip::{ParamError, TipForce, TwinBeams, TwinBeamsParams};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let paper = TwinBeams::new(TwinBeamsParams::PAPER)?;
    let force = TipForce::new(100.0)?;
    let coulomb = paper.coulomb(force).tip_deflection();
    println!(
        "Twin beams of the paper at F = {} N; Coulomb: F_thre = {} N, w(L) = {coulomb:.6} mm",
        force.newtons(),
        paper.threshold_force()
    );
    println!(
        "{:>12}  {:>9}  {:>9}  {:>12}  {:>10}  regime",
        "K_T (MPa/mm)", "F_1 (N)", "X (mm)", "w(L) (mm)", "w/w_C - 1"
    );
    let stiffnesses = Samples::new(6.0, 60_000.0, 9, Spacing::Logarithmic)?;
    for kt in stiffnesses.values() {
        let beams = paper.with_tangential_stiffness(kt)?;
        let state = beams.regularized(force);
        let w = state.tip_deflection();
        println!(
            "{kt:>12.4}  {:>9.3}  {:>9.3}  {w:>12.6}  {:>9.3} %  {}",
            beams.first_macroslip_force(),
            state.micro_zone_end(),
            100.0 * (w / coulomb - 1.0),
            state.regime()
        );
    }
    // Invalid input is an error naming the field, the value and the range, never a NaN.
    let refused: ParamError = paper.with_tangential_stiffness(-1.0).unwrap_err();
    println!("K_T = -1 is refused: {refused}");
    Ok(())
}
