//! JSON reports of single points (beam, plate, cycle, fit, K_T comparison): the text reports'
//! fields, with unit-suffixed names (`w_tip_mm`, `KT_MPa_per_mm`). Tables (sweeps) are serialized
//! from [`super::rows`] instead.

use serde_json::{Map, Value};

use crate::kernel::params::Unit;
use crate::problems::BeamParam;
use crate::problems::inputs::Inputs;
use crate::study::curves::{Answer, StiffnessComparison, beam_point, plate_point};
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// `KEY_unit` with the unit spelled for identifiers: `L_mm`, `E_MPa`, `KT_MPa_per_mm`, `mu`.
pub fn suffixed(key: &str, unit: Unit) -> String {
    match unit {
        Unit::Dimensionless => key.to_string(),
        unit => format!("{key}_{}", unit.symbol().replace('/', "_per_")),
    }
}

fn inputs_object(inputs: &Inputs) -> Value {
    let map: Map<String, Value> = inputs
        .kind()
        .params()
        .iter()
        .map(|&param| {
            (
                suffixed(param.name(), param.unit()),
                // `get` cannot miss: the parameters come from the inputs' own model.
                Value::from(inputs.get(param).unwrap_or(f64::NAN)),
            )
        })
        .collect();
    Value::Object(map)
}

/// One cycle's summary for both laws.
pub fn cycle(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> Value {
    use crate::problems::twin_beams::cycle::{Cycle, Law};
    let law = |law: Law| {
        let c = Cycle::new(beams, law, amplitude);
        serde_json::json!({
            "onset_N": c.onset(),
            "w_peak_mm": c.peak_deflection(),
            "D_Nmm": c.dissipation(),
            "U_Nmm": c.peak_energy(),
            "zeta": c.damping_ratio(),
            "secant_stiffness_N_per_mm": c.secant_stiffness(),
        })
    };
    serde_json::json!({
        "model": "beam",
        "preset": preset,
        "inputs": inputs_object(&Inputs::Beam { structure: beams.params(), force: amplitude.newtons() }),
        "Fa_N": amplitude.newtons(),
        "coulomb": law(Law::Coulomb),
        "regularized": law(Law::Regularized),
        "note": super::text::CYCLE_UNITS_NOTE,
    })
}

/// Twin-beam report at one force.
pub fn beam(preset: &str, beams: &TwinBeams, force: TipForce) -> Value {
    let row = beam_point(beams, force);
    serde_json::json!({
        "model": "beam",
        "preset": preset,
        "inputs": inputs_object(&Inputs::Beam { structure: beams.params(), force: force.newtons() }),
        "F_thre_N": beams.threshold_force(),
        "F_1_N": beams.first_macroslip_force(),
        "first_macroslip_at_mm": beams.first_macroslip_position(),
        "saturation_slip_mm": beams.saturation_slip(),
        "coulomb": {
            "regime": row.regime_coulomb.label(),
            "w_tip_mm": row.w_coulomb,
            "stick_end_mm": row.stick_end,
        },
        "regularized": {
            "regime": row.regime_regularized.label(),
            "w_tip_mm": row.w_regularized,
            "X_mm": row.micro_end,
        },
        "beam_theory": {
            "theory": row.validity.theory.key(),
            "shear_deflection_share": row.validity.shear_share,
            "vs_continuum_within": row.validity.expected_error,
            "validity": row.validity.validity.label(),
        },
    })
}

/// Squeezed-plate report.
pub fn plate(
    preset: &str,
    plate: &SqueezedPlate,
    continuum: Option<
        &Result<crate::problems::plate::ContinuumPlate, crate::numeric::NumericError>,
    >,
) -> Value {
    let mut value = plate_closed_form(preset, plate);
    // K_T at the onset of macroslip (P11); absent when nothing ever slides (nu = 0).
    if let (Some(kt), Value::Object(map)) = (plate.macroslip_onset_stiffness(), &mut value) {
        map.insert("KT_macroslip_onset_MPa_per_mm".into(), Value::from(kt));
    }
    if let (Some(solved), Value::Object(map)) = (continuum, &mut value) {
        map.insert(
            "continuum".into(),
            match solved {
                Ok(c) => serde_json::json!({
                    "u_end_mean_mm": c.end_displacement_mean,
                    "u_end_contact_face_mm": c.end_displacement_face,
                    "u_end_mid_thickness_mm": c.end_displacement_mid,
                    "Xr_mm": c.micro_zone_end,
                    "end_pressure_ratio": c.end_pressure_ratio,
                }),
                Err(e) => serde_json::json!({ "error": e.to_string() }),
            },
        );
    }
    value
}

/// The closed forms' part of the plate report.
fn plate_closed_form(preset: &str, plate: &SqueezedPlate) -> Value {
    let row = plate_point(plate);
    let pressure = plate.contact_pressure();
    let half_length = plate.params().half_length;
    serde_json::json!({
        "model": "plate",
        "preset": preset,
        "inputs": inputs_object(&Inputs::Plate(plate.params())),
        "saturation_slip_mm": plate.saturation_slip(),
        "coulomb": {
            "regime": row.regime_coulomb.label(),
            "u_end_mm": row.u_coulomb,
            "Xs_mm": row.stick_end,
        },
        "regularized": {
            "regime": row.regime_regularized.label(),
            "u_end_mm": row.u_regularized,
            "Xr_mm": row.micro_end,
        },
        "contact_pressure": {
            "ratio_centre": pressure.ratio(0.0),
            "ratio_edge": pressure.ratio(half_length),
            "mean_deviation": pressure.mean_deviation(),
            "peak_deviation": pressure.peak_deviation(),
            "mean_deviation_limit": crate::problems::plate::closed_form::PRESSURE_DEVIATION_LIMIT,
            "peak_deviation_limit": crate::problems::plate::closed_form::PRESSURE_PEAK_LIMIT,
            "constant_pressure_holds": pressure.constant_pressure_holds(),
        },
        "strip_theory": strip_validity(plate),
    })
}

fn estimate(e: &crate::fit::Estimate) -> Value {
    serde_json::json!({
        "value": e.value,
        "std_error": e.std_error,
        "status": e.status.label(),
        "note": super::text::evidence(&e.evidence),
    })
}

/// Fit report.
pub fn fit(data: &str, preset: &str, result: &crate::fit::FitResult) -> Value {
    serde_json::json!({
        "data": data,
        "preset": preset,
        "points": result.points,
        "mu": estimate(&result.mu),
        "KT_MPa_per_mm": estimate(&result.kt),
        "rms_mm": result.rms,
        "F_thre_N": result.threshold_force,
        "F_1_N": result.first_macroslip_force,
        "points_above_F_1": result.beyond_first_macroslip,
    })
}

/// The K_T comparison.
pub fn stiffness_table(preset: &str, comparison: &StiffnessComparison) -> Value {
    let rows: Vec<Value> = comparison
        .rows
        .iter()
        .map(|row| {
            let mut object = serde_json::json!({
                "source": super::text::candidate_name(&row.candidate.source),
                "basis": super::text::candidate_basis(&row.candidate.source),
                "KT_MPa_per_mm": row.candidate.kt,
            });
            match row.answer {
                Some(Answer::Beam {
                    first_macroslip_force,
                    micro_end,
                    tip_deflection,
                    regime,
                }) => {
                    object["F_1_N"] = first_macroslip_force.into();
                    object["X_mm"] = micro_end.into();
                    object["w_tip_mm"] = tip_deflection.into();
                    object["regime"] = regime.label().into();
                }
                Some(Answer::Plate {
                    end_displacement,
                    micro_end,
                    regime,
                }) => {
                    object["u_end_mm"] = end_displacement.into();
                    object["Xr_mm"] = micro_end.into();
                    object["regime"] = regime.label().into();
                }
                // A K_T the model refuses: say why rather than leave the answer out silently.
                None => {
                    if let Some(Err(refused)) =
                        row.candidate.kt.map(|kt| BeamParam::Stiffness.check(kt))
                    {
                        object["not_evaluated"] = refused.to_string().into();
                    }
                }
            }
            object
        })
        .collect();
    serde_json::json!({ "preset": preset, "element_size_mm": comparison.element, "candidates": rows })
}

/// The strip theory's envelope (V1) as JSON: the verdict on the thickness-mean u(L) and, where a
/// calibration reaches, the bound on each quantity (thickness mean, contact face, mid-thickness);
/// X_r is not bounded.
pub fn strip_validity(plate: &SqueezedPlate) -> Value {
    use crate::problems::plate::validity as v1;
    let v = plate.validity();
    let mut value = serde_json::json!({
        "validity": v.validity.label(),
        "validity_covers": "u(L) thickness mean",
        "alpha_tp": v.thickness_over_layer,
        "slip_zone_over_tp": v.slip_over_thickness,
        "calibrated_up_to_alpha_tp": v1::CALIBRATED_RATIO,
        "calibrated_from_slip_zone_over_tp": v1::CALIBRATED_SLIP,
        "calibrated_slip_zone_up_to_alpha_tp": v1::CALIBRATED_RATIO_SLIP,
        "X_r_bounded": false,
    });
    if let (Some(e), Value::Object(map)) = (v.expected, &mut value) {
        map.insert(
            "expected_difference_from_continuum".into(),
            serde_json::json!(e[0]),
        );
        map.insert(
            "expected_difference_contact_face".into(),
            serde_json::json!(e[1]),
        );
        map.insert(
            "expected_difference_mid_thickness".into(),
            serde_json::json!(e[2]),
        );
    }
    value
}

/// The answer of `microslip solve`.
pub fn solved(
    preset: &str,
    kind: crate::ModelKind,
    solved: &crate::study::target::Solved,
) -> Value {
    let quantity = solved.target.quantity;
    let roots: Vec<Value> = solved
        .roots
        .iter()
        .map(|r| {
            serde_json::json!({
                "value": r.value,
                "achieved": r.achieved,
                "bracket": [r.bracket.0, r.bracket.1],
                "certified": r.certified,
                "plateau": r.plateau,
                "within_rounding": r.within_rounding,
            })
        })
        .collect();
    serde_json::json!({
        "model": kind.name(),
        "preset": preset,
        "param": solved.param.name(),
        "unit": solved.param.unit().symbol(),
        "quantity": quantity.name(kind),
        "target": solved.target.value,
        "range": [solved.range.0, solved.range.1],
        "roots": roots,
    })
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
