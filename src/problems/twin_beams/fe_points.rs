//! The twin beams' FE points ([`BeamFePoint`]): what a CalculiX run of a beam deck gives (its
//! `.dat` read against its deck) and what a CSV `F_N,w_mm` from any FE code gives.

use crate::fe::results::{
    CcxRun, FeInterface, ResultsError, cut_short, interface_state, mean, points_from_csv,
    relative_slip,
};
use crate::measured::{Curve, MEASURED_DEFLECTION};

use super::deck::sets;
use super::problem::BeamsInputs;

/// One FE point of the twin beams.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamFePoint {
    /// Tip force on each beam (N).
    pub force: f64,
    /// Tip deflection w(L) (mm).
    pub deflection: f64,
    /// What the interface slip shows, when the results have it.
    pub interface: Option<FeInterface>,
}

/// The CSV form of the beam curve: the measurement format of `fit`, one row or more.
pub(super) const BEAM_CURVE: Curve = Curve {
    min_rows: 1,
    ..MEASURED_DEFLECTION
};

/// Beam points from a CSV `F_N,w_mm`.
///
/// # Errors
/// As [`crate::measured::parse_curve`].
pub fn beam_points_from_csv(text: &str) -> Result<Vec<BeamFePoint>, ResultsError> {
    points_from_csv(text, &BEAM_CURVE, |force, deflection| BeamFePoint {
        force,
        deflection,
        interface: None,
    })
}

/// The beam points of a beam deck's run: one per load step that CalculiX finished.
///
/// # Errors
/// A malformed `.dat` line, or no result for the deck's first load step (a run that failed
/// before it, or the `.dat` of another deck).
pub(super) fn beam_points(
    run: &CcxRun,
    inputs: &BeamsInputs,
) -> Result<Vec<BeamFePoint>, ResultsError> {
    let structure = inputs.structure;
    let dat = run.read()?;
    let saturation = structure.friction * structure.pressure / structure.tangential_stiffness;
    let loads = &run.header.loads;
    let mut points = Vec::with_capacity(loads.len());
    for step in run.load_steps() {
        let [tip, lower, upper] = [sets::BEAM_TIP, sets::BEAM_LOWER_FACE, sets::BEAM_UPPER_FACE]
            .map(|set| {
                dat.block(set, step.time).map_err(|why| {
                    let before_any = points.is_empty() || why.starts_with("no ");
                    let why = format!("{}: {why}", step.label());
                    if before_any {
                        cut_short(&why, points.len(), loads.len())
                    } else {
                        ResultsError::Missing(why)
                    }
                })
            });
        let (tip, lower, upper) = (tip?, lower?, upper?);
        let deflection = mean(tip.rows.iter().map(|(_, u)| u[1]));
        let (xs, slips) = relative_slip(&dat.nodes, lower, Some(upper))?;
        points.push(BeamFePoint {
            force: step.force,
            deflection,
            interface: Some(interface_state(&xs, &slips, saturation)),
        });
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_csv_curve_takes_one_row() {
        let beams = beam_points_from_csv("F_N,w_mm\n100,0.039\n").unwrap();
        assert_eq!(beams[0].deflection, 0.039);
    }
}
