//! JSON reports of single points, with unit-suffixed names (`w_tip_mm`, `KT_MPa_per_mm`): beam,
//! plate, cycle, K_T candidates, fit and solve serialize their [`super::point`] types, which the
//! text reports render too; `kt --tolerance` is still built here. Tables (sweeps) are serialized
//! from [`super::rows`] instead.

use serde_json::Value;

use super::point::beam::BeamReport;
use super::point::cycle::CycleReport;
use super::point::fit::FitReport;
use super::point::plate::{PlateReport, StripTheory};
use super::point::solve::SolveReport;
use super::point::stiffness::StiffnessReport;
use super::point::to_json;

use crate::kernel::params::Unit;
use crate::study::curves::StiffnessComparison;
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// `KEY_unit` with the unit spelled for identifiers: `L_mm`, `E_MPa`, `KT_MPa_per_mm`, `mu`.
pub fn suffixed(key: &str, unit: Unit) -> String {
    match unit {
        Unit::Dimensionless => key.to_string(),
        unit => format!("{key}_{}", unit.symbol().replace('/', "_per_")),
    }
}

/// One cycle's summary for both laws.
pub fn cycle(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> Value {
    to_json(&CycleReport::new(preset, beams, amplitude))
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
    structure: &crate::TwinBeamsParams,
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

/// `microslip kt --tolerance` as JSON.
pub fn tolerance(preset: &str, answer: &crate::study::tolerance::ToleranceAnswer) -> Value {
    use crate::study::tolerance::{Setting, Threshold};
    let (threshold, note) = match answer.threshold {
        Threshold::Stiffness(k) => (Some(k), "smallest K_T within the tolerance"),
        Threshold::Everywhere(k) => (Some(k), "every accepted K_T is within the tolerance"),
        Threshold::Nowhere { .. } => (None, "no accepted K_T is within the tolerance"),
    };
    let settings: Vec<Value> = answer
        .settings
        .iter()
        .map(|s| {
            let mut object = serde_json::json!({
                "code": s.code.code,
                "default_KT_MPa_per_mm": s.default.map(|d| d.0),
                "default_enough": s.default.map(|d| d.1),
            });
            match s.needed {
                Setting::SlipTolerance {
                    fraction,
                    element,
                    slip,
                    element_max,
                } => {
                    object["slip_tolerance_max"] = fraction.into();
                    object["element_size_mm"] = element.into();
                    object["elastic_slip_max_mm"] = slip.into();
                    object["element_size_max_mm_with_default"] = element_max.into();
                }
                Setting::StickSlope(k) => object["stick_slope_min_MPa_per_mm"] = k.into(),
                Setting::ElementSize(h) => object["h_min_max_mm"] = h.into(),
                Setting::Stiffness(k) => object["stiffness_min_MPa_per_mm"] = k.into(),
            }
            object
        })
        .collect();
    serde_json::json!({
        "preset": preset,
        "tolerance": answer.tolerance,
        "force_range_N": answer.forces,
        "KT_min_MPa_per_mm": threshold,
        "note": note,
        "current_KT_MPa_per_mm": answer.current.0,
        "current_deviation": answer.current.1,
        "codes": settings,
        "of": if answer.near_current.is_some() { "current" } else { "coulomb" },
        "KT_max_MPa_per_mm": answer.near_current.and_then(|n| n.upper),
        "coulomb_vs_current": answer.near_current.map(|n| n.coulomb),
    })
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
