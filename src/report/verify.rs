//! The `verify` table: the worst relative error of each quantity between the closed forms and the
//! finite elements, against the tolerance, with the case that produced it.

use std::fmt::Write;

use super::number;
use crate::verify::{Case, Quantity, Worst};

/// What a quantity is, with its unit: the table's first column.
pub(crate) fn quantity(quantity: Quantity) -> &'static str {
    quantity.label()
}

/// Every parameter of a case on one line, with units, so that it can be rerun.
pub(crate) fn case(case: &Case) -> String {
    case.describe()
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
    use crate::problems::ModelKind;
    use crate::problems::inputs::Inputs;

    #[test]
    fn the_table_marks_each_quantity_against_the_tolerance_and_names_its_case() {
        let paper = |kind: ModelKind| Case::new(Inputs::paper(kind).validate().unwrap());
        // The beams' w(L) and the plate's X_r.
        let find = |label: &str| {
            Quantity::all()
                .into_iter()
                .find(|q| q.label() == label)
                .unwrap()
        };
        let beam = paper(ModelKind::Beam);
        let results = [
            Worst {
                quantity: find("beam w(L) (mm)"),
                cases: 3,
                error: 2e-4,
                case: Some(beam),
            },
            Worst {
                quantity: find("plate X_r (mm)"),
                cases: 1,
                error: 5e-3,
                case: Some(paper(ModelKind::Plate)),
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
        for q in Quantity::all() {
            assert!(quantity(q).ends_with(')'), "{q:?}");
        }
    }
}
