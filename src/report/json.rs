//! JSON output: the text reports' fields, with unit-suffixed names (`w_tip_mm`, `KT_MPa_per_mm`).

use serde::Serialize;
use serde_json::{Map, Value};

use crate::curves::{BeamPoint, PlatePoint, beam_point, plate_point};
use crate::preset::Inputs;
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// `KEY_unit` with the unit spelled for identifiers: `L_mm`, `E_MPa`, `KT_MPa_per_mm`, `mu`.
pub fn suffixed(key: &str, unit: &str) -> String {
    match unit {
        "-" => key.to_string(),
        unit => format!("{key}_{}", unit.replace('/', "_per_")),
    }
}

fn inputs_object(inputs: &Inputs) -> Value {
    let map: Map<String, Value> = inputs
        .kind()
        .keys()
        .iter()
        .map(|k| {
            (
                suffixed(k.name, k.unit),
                Value::from(inputs.get(k.name).unwrap_or(f64::NAN)),
            )
        })
        .collect();
    Value::Object(map)
}

/// One twin-beam sweep row.
#[derive(Serialize)]
pub struct BeamRow {
    #[serde(rename = "F_N")]
    force: f64,
    w_coulomb_mm: f64,
    w_regularized_mm: f64,
    #[serde(rename = "X_mm")]
    micro_end: f64,
    regime_coulomb: &'static str,
    regime_regularized: &'static str,
}

impl From<&BeamPoint> for BeamRow {
    fn from(p: &BeamPoint) -> Self {
        BeamRow {
            force: p.force,
            w_coulomb_mm: p.w_coulomb,
            w_regularized_mm: p.w_regularized,
            micro_end: p.micro_end,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
        }
    }
}

/// One cycle-sweep row.
#[derive(Serialize)]
pub struct CycleRow {
    #[serde(rename = "Fa_N")]
    amplitude: f64,
    #[serde(rename = "D_coulomb_Nmm")]
    d_coulomb: f64,
    #[serde(rename = "D_regularized_Nmm")]
    d_regularized: f64,
    zeta_coulomb: f64,
    zeta_regularized: f64,
}

impl From<&crate::curves::CyclePoint> for CycleRow {
    fn from(p: &crate::curves::CyclePoint) -> Self {
        CycleRow {
            amplitude: p.amplitude,
            d_coulomb: p.d_coulomb,
            d_regularized: p.d_regularized,
            zeta_coulomb: p.zeta_coulomb,
            zeta_regularized: p.zeta_regularized,
        }
    }
}

/// One cycle's summary for both laws.
pub fn cycle(preset: &str, beams: &TwinBeams, amplitude: TipForce) -> Value {
    use crate::model::cycle::{Cycle, Law};
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
    })
}

/// One plate sweep row.
#[derive(Serialize)]
pub struct PlateRow {
    #[serde(rename = "KT_MPa_per_mm")]
    kt: f64,
    u_coulomb_mm: f64,
    u_regularized_mm: f64,
    #[serde(rename = "Xs_mm")]
    stick_end: f64,
    #[serde(rename = "Xr_mm")]
    micro_end: f64,
    regime_coulomb: &'static str,
    regime_regularized: &'static str,
}

impl From<&PlatePoint> for PlateRow {
    fn from(p: &PlatePoint) -> Self {
        PlateRow {
            kt: p.kt,
            u_coulomb_mm: p.u_coulomb,
            u_regularized_mm: p.u_regularized,
            stick_end: p.stick_end,
            micro_end: p.micro_end,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
        }
    }
}

/// Twin-beam report at one force.
pub fn beam(preset: &str, beams: &TwinBeams, force: TipForce) -> Value {
    let row = beam_point(beams, force);
    let stick_end = if row.regime_coulomb.has_macroslip() {
        0.0
    } else {
        beams.params().length
    };
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
            "stick_end_mm": stick_end,
        },
        "regularized": {
            "regime": row.regime_regularized.label(),
            "w_tip_mm": row.w_regularized,
            "X_mm": row.micro_end,
        },
    })
}

/// Squeezed-plate report.
pub fn plate(preset: &str, plate: &SqueezedPlate) -> Value {
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
            "constant_pressure_holds": pressure.constant_pressure_holds(),
        },
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
pub fn stiffness_table(
    preset: &str,
    model: &crate::preset::Model,
    element: f64,
    rows: &[crate::curves::StiffnessCandidate],
) -> Value {
    use crate::curves::{beam_answer, plate_answer};
    use crate::preset::Model;
    let rows: Vec<Value> = rows
        .iter()
        .map(|row| {
            let mut object = serde_json::json!({ "source": row.source, "basis": row.basis, "KT_MPa_per_mm": row.kt });
            match (model, row.kt) {
                (Model::Beam { beams, force }, Some(kt)) => {
                    if let Some((f_1, x, w, regime)) = beam_answer(beams, *force, kt) {
                        object["F_1_N"] = f_1.into();
                        object["X_mm"] = x.into();
                        object["w_tip_mm"] = w.into();
                        object["regime"] = regime.label().into();
                    }
                }
                (Model::Plate(plate), Some(kt)) => {
                    if let Some((u, x, regime)) = plate_answer(plate, kt) {
                        object["u_end_mm"] = u.into();
                        object["Xr_mm"] = x.into();
                        object["regime"] = regime.label().into();
                    }
                }
                _ => {}
            }
            object
        })
        .collect();
    serde_json::json!({ "preset": preset, "element_size_mm": element, "candidates": rows })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_suffixes_are_identifier_friendly() {
        assert_eq!(suffixed("KT", "MPa/mm"), "KT_MPa_per_mm");
        assert_eq!(suffixed("mu", "-"), "mu");
        assert_eq!(suffixed("F", "N"), "F_N");
    }
}
