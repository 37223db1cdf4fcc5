//! The squeezed plate's FE points ([`PlateFePoint`]): what a CalculiX run of a plate deck gives
//! (its `.dat` read against its deck) and what a CSV `KT_MPa_per_mm,u_mm` from any FE code gives.

use crate::fe::results::{
    CcxRun, FeInterface, NOT_FINISHED, ResultsError, column_of, interface_state, points_from_csv,
    relative_slip, simpson_mean,
};
use crate::kernel::params::{Domain, Unit};
use crate::measured::Curve;

use super::deck::sets;
use super::params::PlateParams;

/// One FE point of the squeezed plate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateFePoint {
    /// The stick slope K_T of the run (MPa/mm).
    pub stiffness: f64,
    /// u(L) (mm): the thickness mean for CalculiX results (what the strip theory's u stands for),
    /// the given value for CSV.
    pub end_displacement: f64,
    /// u(L) at the contact face and at mid-thickness (mm), CalculiX results only.
    pub through_thickness: Option<[f64; 2]>,
    /// What the interface slip shows, when the results have it.
    pub interface: Option<FeInterface>,
}

/// The CSV form of the plate curve.
pub(super) const PLATE_CURVE: Curve = Curve {
    x: "KT_MPa_per_mm",
    y: "u_mm",
    x_what: "stiffnesses",
    x_domain: Domain::STIFFNESS,
    x_unit: Unit::MegapascalPerMillimetre,
    min_rows: 1,
};

/// Plate points from a CSV `KT_MPa_per_mm,u_mm`.
///
/// # Errors
/// As [`crate::measured::parse_curve`].
pub fn plate_points_from_csv(text: &str) -> Result<Vec<PlateFePoint>, ResultsError> {
    points_from_csv(text, &PLATE_CURVE, |stiffness, end_displacement| {
        PlateFePoint {
            stiffness,
            end_displacement,
            through_thickness: None,
            interface: None,
        }
    })
}

/// The plate point of a plate deck's run.
///
/// # Errors
/// A malformed `.dat` line, or no result at the end of the step.
pub(super) fn plate_point(run: &CcxRun, plate: &PlateParams) -> Result<PlateFePoint, ResultsError> {
    let dat = run.read()?;
    let [end, face_nodes] = [sets::PLATE_END, sets::PLATE_FACE].map(|set| {
        dat.block(set, 1.0).map_err(|why| {
            ResultsError::Missing(format!(
                "at the end of the step (time 1): {why} {NOT_FINISHED}"
            ))
        })
    });
    let (end, face_nodes) = (end?, face_nodes?);
    let column = column_of(&dat.nodes, end)?;
    let mean = simpson_mean(&column);
    let face = column[0].1;
    let mid = column[column.len() / 2].1;
    let (xs, slips) = relative_slip(&dat.nodes, face_nodes, None)?;
    let saturation = plate.friction * plate.pressure / plate.tangential_stiffness;
    Ok(PlateFePoint {
        stiffness: plate.tangential_stiffness,
        end_displacement: mean,
        through_thickness: Some([face, mid]),
        interface: Some(interface_state(&xs, &slips, saturation)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_csv_curve_takes_one_row_and_refuses_a_stiffness_out_of_its_domain() {
        let plate = plate_points_from_csv("KT_MPa_per_mm,u_mm\n1e4,6.8e-5\n1e6,1.48e-5\n").unwrap();
        assert_eq!(plate.len(), 2);
        let error = plate_points_from_csv("KT_MPa_per_mm,u_mm\n0,1\n").unwrap_err();
        assert!(
            error
                .to_string()
                .starts_with("line 2: KT_MPa_per_mm = 0 is too small"),
            "{error}"
        );
    }
}
