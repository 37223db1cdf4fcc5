//! Plain-text report of the paper's two data sets: what `microslip` prints until the TUI exists.
//!
//! Pure string building over the model, so it is testable and the binary stays a one-liner.

use std::fmt::Write;

use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

/// Tip forces of the beam table, as multiples of F_thre: stick, threshold, then deeper into slip.
const BEAM_FORCE_FACTORS: [f64; 7] = [0.5, 1.0, 1.125, 1.25, 1.5, 2.5, 3.75];

/// K_T values of the plate table (MPa/mm): the decades the paper's displacement figure spans.
const PLATE_STIFFNESSES: [f64; 8] = [1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7];

/// The report for the paper's twin-beam and plate data sets.
pub fn paper_report() -> String {
    let mut out = String::new();
    // The paper's parameters are valid constants: construction cannot fail.
    if let (Ok(beams), Ok(plate)) = (
        TwinBeams::new(TwinBeamsParams::PAPER),
        SqueezedPlate::new(PlateParams::PAPER),
    ) {
        write_beams(&mut out, &beams);
        out.push('\n');
        write_plate(&mut out, &plate);
    }
    out
}

fn write_beams(out: &mut String, beams: &TwinBeams) {
    let p = beams.params();
    let _ = writeln!(
        out,
        "Twin cantilever beams (Ligier & Bonhote 2014, section 2.1)"
    );
    let _ = writeln!(
        out,
        "  L = {} mm, b = {} mm, h = {} mm, E = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
        p.length,
        p.width,
        p.half_height,
        p.youngs_modulus,
        p.pressure,
        p.friction,
        p.tangential_stiffness
    );
    let _ = writeln!(
        out,
        "  F_thre = {:.4} N (Coulomb slip), F_1 = {:.4} N (first macroslip, at x = {} mm), mu P / K_T = {:.4} um",
        beams.threshold_force(),
        beams.first_macroslip_force(),
        beams.first_macroslip_position(),
        beams.saturation_slip() * 1e3
    );
    let _ = writeln!(
        out,
        "  {:>8}  {:>13}  {:>16}  {:>10}  {:<10}  {:<20}",
        "F (N)", "w_Coulomb(mm)", "w_regularized(mm)", "X (mm)", "Coulomb", "regularized"
    );
    for factor in BEAM_FORCE_FACTORS {
        let Ok(force) = TipForce::new(factor * beams.threshold_force()) else {
            continue;
        };
        let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
        let _ = writeln!(
            out,
            "  {:>8.2}  {:>13.6e}  {:>16.6e}  {:>10.4}  {:<10}  {:<20}",
            force.newtons(),
            coulomb.tip_deflection(),
            regularized.tip_deflection(),
            regularized.micro_zone_end(),
            coulomb.regime(),
            regularized.regime()
        );
    }
}

fn write_plate(out: &mut String, plate: &SqueezedPlate) {
    let p = plate.params();
    let coulomb = plate.coulomb();
    let pressure = plate.contact_pressure();
    let _ = writeln!(
        out,
        "Squeezed plate on a rigid plane (Ligier & Bonhote 2014, section 2.2)"
    );
    let _ = writeln!(
        out,
        "  L = {} mm (half-length), t_p = {} mm, E = {} MPa, nu = {}, mu = {}, P = {} MPa",
        p.half_length, p.thickness, p.youngs_modulus, p.poisson, p.friction, p.pressure
    );
    let _ = writeln!(
        out,
        "  Coulomb: X_s = {:.6} mm, u(L) = {:.6e} mm, {}",
        coulomb.stick_end(),
        coulomb.end_displacement(),
        coulomb.regime()
    );
    let _ = writeln!(
        out,
        "  contact pressure: P_r/P from {:.3} (centre) to {:.3} (edge), mean deviation {:.2} % -> constant-pressure assumption {}",
        pressure.ratio(0.0),
        pressure.ratio(p.half_length),
        pressure.mean_deviation() * 100.0,
        if pressure.constant_pressure_holds() {
            "holds"
        } else {
            "does NOT hold"
        }
    );
    let _ = writeln!(
        out,
        "  {:>13}  {:>16}  {:>10}  {:<20}",
        "K_T (MPa/mm)", "u_regularized(mm)", "X_r (mm)", "regularized"
    );
    for kt in PLATE_STIFFNESSES {
        let Ok(plate) = plate.with_tangential_stiffness(kt) else {
            continue;
        };
        let r = plate.regularized();
        let _ = writeln!(
            out,
            "  {:>13.0e}  {:>16.6e}  {:>10.6}  {:<20}",
            kt,
            r.end_displacement(),
            r.micro_zone_end(),
            r.regime()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_names_both_models_units_and_regimes() {
        let text = paper_report();
        assert!(text.contains("Twin cantilever beams"));
        assert!(text.contains("Squeezed plate"));
        assert!(text.contains("F_thre = 80.0000 N"));
        assert!(text.contains("microslip+macroslip"));
        assert!(text.contains("stick+macroslip"));
        assert!(!text.contains("NaN") && !text.contains("inf"));
    }
}
