//! The `verify` table: the worst relative error of each quantity between the closed forms and the
//! finite elements, against the tolerance, with the case that produced it.

use std::fmt::Write;

use super::number;
use crate::verify::{Case, Quantity, Worst};

/// What a quantity is, with its unit: the table's first column.
pub(crate) fn quantity(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::BeamTipDeflection => "beam w(L) (mm)",
        Quantity::BeamMicroslipEnd => "beam X (mm)",
        Quantity::PlateEndDisplacement => "plate u(L) (mm)",
        Quantity::PlateMicroslipEnd => "plate X_r (mm)",
        Quantity::LapJointDisplacement => "lap Delta (mm)",
        Quantity::LapSlidingZones => "lap a, d (/L)",
    }
}

/// Every parameter of a case on one line, with units, so that it can be rerun.
pub(crate) fn case(case: &Case) -> String {
    match case {
        Case::Beam { params: p, force } => format!(
            "K_T={} MPa/mm F={} N L={} b={} h={} mm E={} MPa P={} MPa mu={}",
            number(p.tangential_stiffness),
            number(*force),
            number(p.length),
            number(p.width),
            number(p.half_height),
            number(p.youngs_modulus),
            number(p.pressure),
            number(p.friction)
        ),
        Case::Plate(p) => format!(
            "K_T={} MPa/mm L={} t_p={} mm E={} MPa nu={} mu={} P={} MPa",
            number(p.tangential_stiffness),
            number(p.half_length),
            number(p.thickness),
            number(p.youngs_modulus),
            number(p.poisson),
            number(p.friction),
            number(p.pressure)
        ),
        Case::Lap { params: p, force } => format!(
            "K_T={} MPa/mm F={} N L={} b={} t1={} t2={} mm E1={} E2={} MPa P={} MPa mu={}",
            number(p.tangential_stiffness),
            number(*force),
            number(p.length),
            number(p.width),
            number(p.inner_thickness),
            number(p.cover_thickness),
            number(p.inner_modulus),
            number(p.cover_modulus),
            number(p.pressure),
            number(p.friction)
        ),
    }
}

/// The whole report: a title with the mesh, one row per quantity (ok or FAIL against `tolerance`),
/// and the number of cases with the time they took (`seconds`).
pub fn table(results: &[Worst], elements: usize, tolerance: f64, seconds: f64) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Closed forms vs finite elements ({elements} elements per model, regularized law)"
    );
    let _ = writeln!(
        out,
        "{:<18} {:>5}  {:>16}  {:>9}  {:<4}  worst case",
        "quantity", "cases", "worst rel. error", "tolerance", ""
    );
    for w in results {
        let _ = writeln!(
            out,
            "{:<18} {:>5}  {:>16}  {:>9}  {:<4}  {}",
            quantity(w.quantity),
            w.cases,
            format!("{:.2e}", w.error),
            number(tolerance),
            if w.passes(tolerance) { "ok" } else { "FAIL" },
            w.case.as_ref().map(case).unwrap_or_default()
        );
    }
    // Every case compares two quantities of its model.
    let cases: usize = results.iter().map(|w| w.cases).sum::<usize>() / 2;
    let _ = writeln!(out, "{cases} cases in {seconds:.2} s");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

    #[test]
    fn the_table_marks_each_quantity_against_the_tolerance_and_names_its_case() {
        let beam = Case::Beam {
            params: TwinBeamsParams::PAPER,
            force: 100.0,
        };
        let results = [
            Worst {
                quantity: Quantity::BeamTipDeflection,
                cases: 3,
                error: 2e-4,
                case: Some(beam),
            },
            Worst {
                quantity: Quantity::PlateMicroslipEnd,
                cases: 1,
                error: 5e-3,
                case: Some(Case::Plate(PlateParams::PAPER)),
            },
        ];
        let text = table(&results, 200, 1e-3, 1.5);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 5, "{text}");
        assert!(lines[0].contains("(200 elements per model"), "{text}");
        assert!(lines[1].starts_with("quantity") && lines[1].ends_with("worst case"));
        // Beams: the paper's data set (L 200, b 20, h 10 mm, E 210 GPa, P 1 MPa, mu 0.3, K_T 600).
        assert!(lines[2].starts_with("beam w(L) (mm)"), "{text}");
        assert!(lines[2].contains("2.00e-4") && lines[2].contains("0.001  ok "));
        assert!(
            lines[2]
                .ends_with("K_T=600 MPa/mm F=100 N L=200 b=20 h=10 mm E=210000 MPa P=1 MPa mu=0.3")
        );
        // Plate: L 10, t_p 0.2 mm, E 70 GPa, nu 0.3, mu 0.3, P 10 MPa.
        assert!(lines[3].starts_with("plate X_r (mm)"), "{text}");
        assert!(lines[3].contains("5.00e-3") && lines[3].contains(" FAIL "));
        assert!(lines[3].contains("L=10 t_p=0.2 mm E=70000 MPa nu=0.3 mu=0.3 P=10 MPa"));
        // Each case compares two quantities: 4 comparisons are 2 cases.
        assert_eq!(lines[4], "2 cases in 1.50 s");
    }

    #[test]
    fn every_quantity_has_its_unit() {
        for q in [
            Quantity::BeamTipDeflection,
            Quantity::BeamMicroslipEnd,
            Quantity::PlateEndDisplacement,
            Quantity::PlateMicroslipEnd,
        ] {
            assert!(quantity(q).ends_with(" (mm)"), "{q:?}");
        }
    }
}
