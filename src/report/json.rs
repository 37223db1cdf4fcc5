//! JSON reports of single points, with unit-suffixed names (`w_tip_mm`, `KT_MPa_per_mm`): beam,
//! plate, cycle, K_T candidates, fit and solve serialize their [`super::point`] types, which the
//! text reports render too, `kt --tolerance` too ([`super::point::tolerance`]). Tables (sweeps) are serialized
//! from [`super::rows`] instead.

use serde_json::Value;

use super::point::beam::BeamReport;
use super::point::cycle::{BeamCycleReport, LapCycleReport};
use super::point::fit::FitReport;
use super::point::lap::LapReport;
use super::point::plate::{PlateReport, StripTheory};
use super::point::solve::SolveReport;
use super::point::stiffness::StiffnessReport;
use super::point::to_json;

use crate::kernel::params::Unit;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::study::curves::StiffnessComparison;
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// `KEY_unit` with the unit spelled for identifiers: `L_mm`, `E_MPa`, `KT_MPa_per_mm`, `mu`.
pub(crate) fn suffixed(key: &str, unit: Unit) -> String {
    match unit {
        Unit::Dimensionless => key.to_string(),
        unit => format!("{key}_{}", unit.symbol().replace('/', "_per_")),
    }
}

/// One cycle's summary for both laws.
pub fn cycle(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> Value {
    to_json(&BeamCycleReport::new(preset, beams, amplitude))
}

/// Lap-joint report at one force.
pub fn lap(
    preset: &str,
    joint: &LapJoint,
    force: JointForce,
    continuum: Option<&Result<crate::problems::lap::ContinuumLap, crate::numeric::NumericError>>,
) -> Value {
    to_json(&LapReport::new(preset, joint, force, continuum))
}

/// One cycle of the lap joint, both laws.
pub fn lap_cycle(preset: &str, joint: &LapJoint, amplitude: JointForce) -> Value {
    to_json(&LapCycleReport::new(preset, joint, amplitude))
}

/// Twin-beam report at one force.
pub fn beam(preset: &str, beams: &TwinBeams, force: TipForce) -> Value {
    to_json(&BeamReport::new(preset, beams, force))
}

/// Squeezed-plate report.
pub fn plate(
    preset: &str,
    plate: &SqueezedPlate,
    continuum: Option<
        &Result<crate::problems::plate::ContinuumPlate, crate::numeric::NumericError>,
    >,
) -> Value {
    to_json(&PlateReport::new(preset, plate, continuum))
}

/// Fit report.
pub fn fit(
    data: &str,
    preset: &str,
    structure: &crate::fit::Structure,
    result: &crate::fit::FitResult,
) -> Value {
    to_json(&FitReport::new(data, preset, structure, result))
}

/// The K_T comparison.
pub fn stiffness_table(preset: &str, comparison: &StiffnessComparison) -> Value {
    to_json(&StiffnessReport::new(preset, comparison))
}

/// The strip theory's envelope (V1) as JSON: the plate report's `strip_theory`.
pub fn strip_validity(plate: &SqueezedPlate) -> Value {
    to_json(&StripTheory::new(plate))
}

/// The answer of `microslip solve`.
pub fn solved(
    preset: &str,
    kind: crate::ModelKind,
    solved: &crate::study::target::Solved,
) -> Value {
    to_json(&SolveReport::new(preset, kind, solved))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_suffixes_are_identifier_friendly() {
        assert_eq!(
            suffixed("KT", Unit::MegapascalPerMillimetre),
            "KT_MPa_per_mm"
        );
        assert_eq!(suffixed("mu", Unit::Dimensionless), "mu");
        assert_eq!(suffixed("F", Unit::Newton), "F_N");
    }
}
