//! The double-lap joint's FE points ([`LapFePoint`]): what a CalculiX run of a lap deck gives
//! (its `.dat` read against its deck: Delta from thickness means, zeroed after the clamping step,
//! and the sliding zones its slip profile shows) and what a CSV `F_N,Delta_mm` from any FE code
//! gives.

use crate::fe::results::DatBlock;
use crate::fe::results::{
    CcxRun, NOT_FINISHED, ResultsError, cut_short, facing_slip, points_from_csv, sliding_zones,
    thickness_mean,
};
use crate::kernel::regime::{Law, Regime};
use crate::measured::{Curve, MEASURED_JOINT_DISPLACEMENT};

use super::closed_form::zones_regime;
use super::deck::sets;
use super::problem::LapInputs;

/// One FE point of the double-lap joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapFePoint {
    /// The force through the joint (N).
    pub force: f64,
    /// The joint displacement Delta (mm): for CalculiX results the thickness mean of the inner
    /// plate's u_x at x = L minus the cover's at x = 0, each from the end of the clamping step
    /// (P alone stretches both plates through Poisson, which the 1-D theory does not have); the
    /// given value for CSV.
    pub joint_displacement: f64,
    /// The sliding zones the slip profile shows, when the results have it.
    pub interface: Option<LapFeInterface>,
}

/// The lap joint's interface state read from the slip profile: sliding where K_T |s| >= mu P
/// (nominal P: the closed form's definition), contiguous from each end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapFeInterface {
    /// Length a of the sliding zone from x = 0 (mm).
    pub slide_from_start: f64,
    /// Length d of the sliding zone from x = L (mm).
    pub slide_from_end: f64,
    /// The regime of the regularized law the profile shows.
    pub regime: Regime,
}

/// The CSV form of the lap joint's curve: the measurement format of `fit lap`, one row or more.
pub(super) const LAP_CURVE: Curve = Curve {
    min_rows: 1,
    ..MEASURED_JOINT_DISPLACEMENT
};

/// Lap-joint points from a CSV `F_N,Delta_mm`.
///
/// # Errors
/// As [`crate::measured::parse_curve`].
pub fn lap_points_from_csv(text: &str) -> Result<Vec<LapFePoint>, ResultsError> {
    points_from_csv(text, &LAP_CURVE, |force, joint_displacement| LapFePoint {
        force,
        joint_displacement,
        interface: None,
    })
}

/// The lap-joint points of a lap deck's run: one per load step that CalculiX finished, each
/// measured from the end of the clamping step (step 1, time 1), as the deck's header says.
///
/// # Errors
/// A malformed `.dat` line, no result at the end of the clamping step or of the deck's first
/// load step (a run that failed before it, or the `.dat` of another deck).
pub(super) fn lap_points(
    run: &CcxRun,
    inputs: &LapInputs,
) -> Result<Vec<LapFePoint>, ResultsError> {
    let structure = inputs.structure;
    let dat = run.read()?;
    let nodes = &dat.nodes;
    let state_at = |time: f64, what: &dyn Fn() -> String| -> Result<LapState, String> {
        let [inner, cover, inner_face, cover_face] = [
            sets::LAP_INNER_END,
            sets::LAP_COVER_END,
            sets::LAP_INNER_FACE,
            sets::LAP_COVER_FACE,
        ]
        .map(|set| {
            dat.block(set, time)
                .map_err(|why| format!("{}: {why}", what()))
        });
        let mean =
            |block: &DatBlock| thickness_mean(nodes, block).map_err(|e| format!("{}: {e}", what()));
        let (xs, slips) =
            facing_slip(nodes, inner_face?, cover_face?).map_err(|e| format!("{}: {e}", what()))?;
        Ok(LapState {
            joint_displacement: mean(inner?)? - mean(cover?)?,
            xs,
            slips,
        })
    };
    let clamped = state_at(1.0, &|| {
        "at the end of the clamping step (time 1)".to_string()
    })
    .map_err(|why| ResultsError::Missing(format!("{why} {NOT_FINISHED}")))?;
    let saturation = structure.friction * structure.pressure / structure.tangential_stiffness;
    let loads = &run.header.loads;
    let mut points = Vec::with_capacity(loads.len());
    for step in run.load_steps() {
        let state = state_at(step.time, &|| step.label())
            .map_err(|why| cut_short(&why, points.len(), loads.len()))?;
        let slips: Vec<f64> = state
            .slips
            .iter()
            .zip(&clamped.slips)
            .map(|(s, s0)| s - s0)
            .collect();
        points.push(LapFePoint {
            force: step.force,
            joint_displacement: state.joint_displacement - clamped.joint_displacement,
            interface: Some(lap_interface_state(&state.xs, &slips, saturation)),
        });
    }
    Ok(points)
}

/// What a lap run's `.dat` gives at one time: Delta (not yet zeroed) and the slip profile.
struct LapState {
    joint_displacement: f64,
    xs: Vec<f64>,
    slips: Vec<f64>,
}

/// The sliding zones of a lap joint's slip profile: where K_T |s| >= mu P (|s| >= `saturation`),
/// contiguous from x = 0 and from x = L, each end interpolated linearly between the last sliding
/// node and the first that does not.
fn lap_interface_state(xs: &[f64], slips: &[f64], saturation: f64) -> LapFeInterface {
    let (a, d) = sliding_zones(xs, slips, saturation);
    let length = xs.last().copied().unwrap_or(0.0) - xs.first().copied().unwrap_or(0.0);
    LapFeInterface {
        slide_from_start: a,
        slide_from_end: d,
        regime: if xs.is_empty() {
            Regime::MICROSLIP
        } else {
            zones_regime(Law::Regularized, a, d, length)
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::regime::Zone;

    #[test]
    fn a_csv_curve_takes_one_row() {
        let lap = lap_points_from_csv("F_N,Delta_mm\n3000,0.0141\n").unwrap();
        assert_eq!((lap[0].force, lap[0].joint_displacement), (3000.0, 0.0141));
    }

    #[test]
    fn lap_zones_are_read_from_both_ends() {
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        // Sliding from x = 0 to between nodes 1 and 2 (interpolated at |s| = 1), and at x = L
        // over the last node only, to between nodes 3 and 4; the signs of the slip do not matter.
        let state = lap_interface_state(&xs, &[-3.0, -2.0, 0.5, 0.0, 2.0], 1.0);
        assert!((state.slide_from_start - (1.0 + 1.0 / 1.5)).abs() < 1e-12);
        assert!((state.slide_from_end - 0.5).abs() < 1e-12);
        assert_eq!(
            state.regime,
            Regime::from_zones(&[Zone::Macroslip, Zone::Microslip, Zone::Macroslip])
        );
        let elastic = lap_interface_state(&xs, &[0.9, 0.5, 0.1, 0.5, 0.9], 1.0);
        assert_eq!(
            (elastic.slide_from_start, elastic.slide_from_end),
            (0.0, 0.0)
        );
        assert_eq!(elastic.regime, Regime::MICROSLIP);
        let one_end = lap_interface_state(&xs, &[0.9, 0.5, 0.1, 0.5, 1.5], 1.0);
        assert_eq!(one_end.regime, Regime::MICROSLIP_MACROSLIP);
        // Sliding everywhere: the whole overlap, counted once.
        let through = lap_interface_state(&xs, &[2.0; 5], 1.0);
        assert_eq!(
            (through.slide_from_start, through.slide_from_end),
            (4.0, 0.0)
        );
        assert_eq!(through.regime, Regime::MACROSLIP);
    }
}
