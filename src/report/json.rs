//! JSON reports of single points, with unit-suffixed names (`w_tip_mm`, `KT_MPa_per_mm`): cycle,
//! K_T candidates, fit and solve serialize their [`super::point`] types, a problem's own point
//! report ([`of`]) its folder's struct, which the text reports render too; `kt --tolerance` too
//! ([`super::point::tolerance`]). Tables (sweeps) are serialized from [`super::rows`] instead.

use serde_json::Value;

use super::point::cycle::{CycleFace, CycleReport};
use super::point::fit::FitReport;
use super::point::solve::SolveReport;
use super::point::stiffness::StiffnessReport;
use super::point::to_json;

use crate::kernel::params::Unit;
use crate::study::curves::StiffnessComparison;

/// `KEY_unit` with the unit spelled for identifiers ([`Unit::key`]): `L_mm`, `E_MPa`,
/// `KT_MPa_per_mm`, `T_Nmm`, `mu`.
pub(crate) fn suffixed(key: &str, unit: Unit) -> String {
    match unit {
        Unit::Dimensionless => key.to_string(),
        unit => format!("{key}_{}", unit.key()),
    }
}

/// A report of one point as JSON (sorted keys): any of the [`super::point`] types, or a
/// problem's own (`src/problems/<name>/report.rs`).
pub fn of(report: &impl serde::Serialize) -> Value {
    to_json(report)
}

/// One cycle's summary of any load-driven problem, both laws.
pub fn cycle<P: CycleFace>(preset: &str, structure: &P::Structure, amplitude: P::Force) -> Value {
    to_json(&CycleReport::new::<P>(preset, structure, amplitude))
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
