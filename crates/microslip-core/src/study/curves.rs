//! Sweeps and profiles: the twin beams and the plate over a range of a parameter, their
//! responses against a parameter, their shear along the interface. The CLI's sweeps, its
//! single-point reports and the TUI's charts take their numbers from here, so a value on screen
//! and the same value in a CSV file come from the same function. The load-driven studies (force
//! sweeps, cycles, loops) are written once in [`crate::study::load`].
//!
//! Sweeps are iterators: a million-row sweep streams without building the table first.

use crate::kernel::regime::Law;
use crate::kernel::validity::Validity;
use crate::problems::inputs::Model;
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};
use crate::problems::{BeamParam, Param, PlateParam, Problem};
use crate::study::load;
use crate::{Regime, SqueezedPlate, TipForce, TwinBeams};

pub use crate::problems::twin_beams::load_driven::{BeamPoint, beam_point};
pub use crate::study::candidates::{
    Answer, CandidateSource, ComparedStiffness, StiffnessCandidate, StiffnessComparison,
    compare_stiffnesses,
};
pub use crate::study::load::{Branch, CyclePoint, LoopPoint};
pub use crate::study::samples::{
    MAX_POINTS, RangeEnd, RangeError, Samples, Series, Spacing, check_points,
};
pub use crate::study::zones::{InterfaceZones, Zone, ZoneBoundary, ZoneSpan, interface_zones};

/// The twin beams over a range of forces: one row per sample, every one computed at the force
/// asked for ([`load::force_sweep`]).
///
/// # Errors
/// [`RangeError::Bound`] when an end of `forces` is not an accepted tip force (see
/// [`force_samples`], which checks this when the range is made).
pub fn beam_force_sweep(
    beams: TwinBeams,
    forces: Samples,
) -> Result<impl Iterator<Item = BeamPoint>, RangeError> {
    load::force_sweep::<TwinBeamsProblem>(beams, forces)
}

/// A force sampling for [`beam_force_sweep`]: both bounds must be accepted tip forces.
///
/// # Errors
/// See [`Samples::of_param`].
pub fn force_samples(from: f64, to: f64, points: u64) -> Result<Samples, RangeError> {
    Samples::of_param(
        Param::Beam(BeamParam::Force),
        from,
        to,
        points,
        Spacing::Linear,
    )
}

/// Everything the reports show about the plate at one K_T, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlatePoint {
    /// K_T (MPa/mm).
    pub kt: f64,
    /// Coulomb end displacement (mm).
    pub u_coulomb: f64,
    /// Regularized end displacement (mm).
    pub u_regularized: f64,
    /// End of the Coulomb stick zone X_s (mm); 0 when all slides.
    pub stick_end: f64,
    /// End of the microslip zone X_r (mm); L without macroslip.
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// Where the strip theory stands against a plane-strain continuum (V1).
    pub strip_validity: Validity,
}

/// The plate as it is.
pub fn plate_point(plate: &SqueezedPlate) -> PlatePoint {
    let (coulomb, regularized) = (plate.coulomb(), plate.regularized());
    PlatePoint {
        kt: plate.params().tangential_stiffness,
        u_coulomb: coulomb.end_displacement(),
        u_regularized: regularized.end_displacement(),
        stick_end: coulomb.stick_end(),
        micro_end: regularized.micro_zone_end(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        strip_validity: plate.validity().validity,
    }
}

/// A K_T sampling for [`plate_kt_sweep`]: both bounds must be accepted stiffnesses.
///
/// # Errors
/// See [`Samples::of_param`].
pub fn stiffness_samples(
    from: f64,
    to: f64,
    points: u64,
    spacing: Spacing,
) -> Result<Samples, RangeError> {
    Samples::of_param(
        Param::Plate(PlateParam::Stiffness),
        from,
        to,
        points,
        spacing,
    )
}

/// The plate over a range of K_T (other parameters fixed): one row per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `stiffnesses` is not an accepted K_T (see
/// [`stiffness_samples`]).
pub fn plate_kt_sweep(
    plate: SqueezedPlate,
    stiffnesses: Samples,
) -> Result<impl Iterator<Item = PlatePoint>, RangeError> {
    stiffnesses.check_within(Param::Plate(PlateParam::Stiffness))?;
    Ok(stiffnesses
        .values()
        .map(move |kt| plate_point(&plate.with_clamped(PlateParam::Stiffness, kt))))
}

/// The twin beams over a range of any one parameter (the others, F included, as in `model`): one
/// row per sample, the sample value first. For F this is [`beam_force_sweep`] with the force
/// repeated in front.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of `param`.
pub fn beam_param_sweep(
    beams: TwinBeams,
    force: TipForce,
    param: BeamParam,
    values: Samples,
) -> Result<impl Iterator<Item = (f64, BeamPoint)>, RangeError> {
    values.check_within(Param::Beam(param))?;
    let model = BeamsModel { beams, force };
    Ok(values.values().map(move |v| {
        let at = TwinBeamsProblem::with_clamped(&model, param, v);
        (v, beam_point(&at.beams, at.force))
    }))
}

/// The plate over a range of any one parameter (the others as in `plate`): one row per sample, the
/// sample value first.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of `param`.
pub fn plate_param_sweep(
    plate: SqueezedPlate,
    param: PlateParam,
    values: Samples,
) -> Result<impl Iterator<Item = (f64, PlatePoint)>, RangeError> {
    values.check_within(Param::Plate(param))?;
    Ok(values
        .values()
        .map(move |v| (v, plate_point(&plate.with_clamped(param, v)))))
}

/// The response of `model` (w(L) of the beams, u(L) of the plate, Delta of the lap joint, mm) against any one of its
/// parameters: (Coulomb, regularized). The chart "w(L) vs this parameter".
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of `param` (or `param`
/// belongs to another problem).
pub fn response_vs_param(
    model: &Model,
    param: Param,
    values: Samples,
) -> Result<(Series, Series), RangeError> {
    match (*model, param) {
        (Model::Beam { beams, force }, Param::Beam(p)) => {
            Ok(beam_param_sweep(beams, force, p, values)?
                .map(|(v, r)| ((v, r.w_coulomb), (v, r.w_regularized)))
                .unzip())
        }
        (Model::Plate(plate), Param::Plate(p)) => Ok(plate_param_sweep(plate, p, values)?
            .map(|(v, r)| ((v, r.u_coulomb), (v, r.u_regularized)))
            .unzip()),
        (Model::Lap { joint, force }, Param::Lap(p)) => {
            Ok(crate::study::lap::lap_param_sweep(joint, force, p, values)?
                .map(|(v, r)| ((v, r.delta_coulomb), (v, r.delta_regularized)))
                .unzip())
        }
        (Model::Beam { .. }, Param::Plate(_) | Param::Lap(_))
        | (Model::Plate(_), Param::Beam(_) | Param::Lap(_))
        | (Model::Lap { .. }, Param::Beam(_) | Param::Plate(_)) => Err(RangeError::Bound {
            end: RangeEnd::Start,
            value: f64::NAN,
            allowed: format!("{param} is a parameter of another problem"),
        }),
    }
}

/// End of the microslip zone X (mm) against F (N), regularized law (X = L below F_1): the far
/// edge of the beams' holding zone ([`load::holding_zone_vs_force`]).
///
/// # Errors
/// As [`beam_force_sweep`].
pub fn beam_slip_boundary_vs_force(
    beams: &TwinBeams,
    forces: Samples,
) -> Result<Series, RangeError> {
    Ok(
        load::holding_zone_vs_force::<TwinBeamsProblem>(beams, Law::Regularized, forces)?
            .into_iter()
            .map(|(f, [_, x])| (f, x))
            .collect(),
    )
}

/// Interface shear tau (MPa) along the beams at one force: (Coulomb, regularized).
pub fn beam_shear_along(
    beams: &TwinBeams,
    force: TipForce,
    positions: Samples,
) -> (Series, Series) {
    let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
    both_along(
        positions,
        |x| coulomb.shear_stress(x),
        |x| regularized.shear_stress(x),
    )
}

/// One quantity of both laws at each position: (Coulomb, regularized).
fn both_along(
    positions: Samples,
    coulomb: impl Fn(f64) -> f64,
    regularized: impl Fn(f64) -> f64,
) -> (Series, Series) {
    positions
        .values()
        .map(|x| ((x, coulomb(x)), (x, regularized(x))))
        .unzip()
}

/// End displacement u(L) (mm) against K_T (MPa/mm): (Coulomb, regularized).
///
/// # Errors
/// As [`plate_kt_sweep`].
pub fn plate_end_displacement_vs_stiffness(
    plate: &SqueezedPlate,
    stiffnesses: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(plate_kt_sweep(*plate, stiffnesses)?
        .map(|p| ((p.kt, p.u_coulomb), (p.kt, p.u_regularized)))
        .unzip())
}

/// End of the microslip zone X_r (mm) against mu, at the plate's K_T: one point per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `frictions` is not an accepted friction coefficient.
pub fn plate_slip_boundary_vs_friction(
    plate: &SqueezedPlate,
    frictions: Samples,
) -> Result<Series, RangeError> {
    frictions.check_within(Param::Plate(PlateParam::Friction))?;
    Ok(frictions
        .values()
        .map(|mu| plate.with_clamped(PlateParam::Friction, mu))
        .map(|p| (p.params().friction, p.regularized().micro_zone_end()))
        .collect())
}

/// Contact pressure ratio P_r / P along the half-plate.
pub fn plate_contact_pressure_along(plate: &SqueezedPlate, positions: Samples) -> Series {
    let pressure = plate.contact_pressure();
    positions.values().map(|x| (x, pressure.ratio(x))).collect()
}

/// Interface shear tau (MPa) along the half-plate: (Coulomb, regularized).
pub fn plate_shear_along(plate: &SqueezedPlate, positions: Samples) -> (Series, Series) {
    let (coulomb, regularized) = (plate.coulomb(), plate.regularized());
    both_along(
        positions,
        |x| coulomb.shear_stress(x),
        |x| regularized.shear_stress(x),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

    #[test]
    fn sweeps_refuse_a_range_outside_the_domain_before_the_first_row() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let wide = Samples::new(-1.0, 1e13, 3, Spacing::Linear).unwrap();
        assert!(matches!(
            beam_force_sweep(beams, wide),
            Err(RangeError::Bound {
                end: RangeEnd::Start,
                ..
            })
        ));
        assert!(load::cycle_sweep::<TwinBeamsProblem>(beams, wide).is_err());
        let high = Samples::new(1.0, 1e13, 3, Spacing::Linear).unwrap();
        assert_eq!(
            load::cycle_sweep::<TwinBeamsProblem>(beams, high)
                .err()
                .unwrap()
                .to_string(),
            "invalid end = 1e13: must be in [0, 1e12] N"
        );
        let soft = Samples::new(1e-7, 1.0, 3, Spacing::Logarithmic).unwrap();
        assert!(plate_kt_sweep(plate, soft).is_err());
        assert!(plate_slip_boundary_vs_friction(&plate, high).is_err());
    }

    #[test]
    fn sweeps_over_the_whole_domain_give_every_row_finite() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let rows: Vec<BeamPoint> = beam_force_sweep(beams, force_samples(0.0, 1e12, 101).unwrap())
            .unwrap()
            .collect();
        assert_eq!(rows.len(), 101);
        assert!(rows.iter().all(|r| {
            [r.w_coulomb, r.w_regularized, r.micro_end]
                .iter()
                .all(|v| v.is_finite())
        }));
        let cycles: Vec<CyclePoint> =
            load::cycle_sweep::<TwinBeamsProblem>(beams, force_samples(0.0, 1e12, 11).unwrap())
                .unwrap()
                .collect();
        assert_eq!(cycles.len(), 11);
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let all = stiffness_samples(1e-6, 1e12, 181, Spacing::Logarithmic).unwrap();
        let rows: Vec<PlatePoint> = plate_kt_sweep(plate, all).unwrap().collect();
        assert_eq!(rows.len(), 181);
        assert_eq!((rows[0].kt, rows[180].kt), (1e-6, 1e12));
        assert!(rows.iter().all(|r| {
            [r.u_coulomb, r.u_regularized, r.micro_end]
                .iter()
                .all(|v| v.is_finite())
        }));
    }

    #[test]
    fn sweeps_yield_one_row_per_sample() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let rows: Vec<BeamPoint> = beam_force_sweep(beams, force_samples(0.0, 300.0, 31).unwrap())
            .unwrap()
            .collect();
        assert_eq!(rows.len(), 31);
        assert!((rows[10].force - 100.0).abs() < 1e-12);
        assert_eq!(rows[10].regime_regularized, Regime::MICROSLIP_MACROSLIP);
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let samples = stiffness_samples(1.0, 1e7, 8, Spacing::Logarithmic).unwrap();
        let rows: Vec<PlatePoint> = plate_kt_sweep(plate, samples).unwrap().collect();
        assert_eq!(rows.len(), 8);
        assert_eq!(rows[7].kt, 1e7);
    }
}
