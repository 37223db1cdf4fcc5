//! Sweeps and profiles of any problem: a problem over a range of one of its parameters, its
//! responses against a parameter, its shear along the interface, the load-driven charts' zone
//! edges against F. The CLI's sweeps, its single-point reports and the TUI's charts take their
//! numbers from here, so a value on screen and the same value in a CSV file come from the same
//! function. The load-driven studies (force sweeps, cycles, loops) are written once in
//! [`crate::study::load`]. Everything here is written once, generic over the capability it
//! needs ([`Pointwise`], [`Profiled`], [`LoadDriven`], or [`Problem`] alone), or dispatched from
//! the registry over every problem ([`response_vs_param`], [`shear_along`]); each problem's point
//! type (`BeamPoint`, `beam_point`, ...) is re-exported here from its folder's `point` module,
//! generated from the registry.
//!
//! Sweeps are iterators: a million-row sweep streams without building the table first. Each
//! sweep walks one family of its parameter, its rows computed in one [`family::scope`], where a
//! solver may continue from the previous row (the cylinder, issue 47).

use crate::kernel::family;
use crate::kernel::regime::Law;
use crate::problems::inputs::Model;
use crate::problems::load_driven::LoadDriven;
use crate::problems::pointwise::Pointwise;
use crate::problems::problem::{BothLaws, Listed, Visit};
use crate::problems::profiled::Profiled;
use crate::problems::{Param, ParamKey, Problem};
use crate::study::load;

pub use crate::study::candidates::{
    Answer, CandidateSource, ComparedStiffness, StiffnessCandidate, StiffnessComparison,
    compare_stiffnesses,
};
pub use crate::study::load::{Branch, CyclePoint, LoopPoint};
pub use crate::study::samples::{
    MAX_POINTS, RangeEnd, RangeError, Samples, Series, Spacing, check_points,
};
pub use crate::study::zones::{InterfaceZones, Zone, ZoneBoundary, ZoneSpan, interface_zones};

/// Re-exports each registered problem's point (its `point` module: the row type and the function
/// that makes it), so that `curves::beam_point` and the like are found here without this file
/// naming a problem.
macro_rules! problem_points {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        // A folder that two registry lines name is re-exported twice: the same items.
        $(#[allow(unused_imports)] pub use crate::problems::$folder::point::*;)+
    };
}

crate::with_problems!(problem_points);

/// A sampling of the load of the load-driven problem `P` (its F): both bounds must be accepted
/// forces, evenly spaced.
///
/// # Errors
/// See [`Samples::of_param`].
pub fn load_samples<P: LoadDriven>(from: f64, to: f64, points: u64) -> Result<Samples, RangeError> {
    Samples::of_param(P::FORCE, from, to, points, Spacing::Linear)
}

/// The parameter of `P` that `key` is.
fn param_of<P: Problem>(key: P::Key) -> Result<Param, RangeError> {
    P::INFO
        .params
        .get(key.index())
        .copied()
        .ok_or_else(|| RangeError::Bound {
            end: RangeEnd::Start,
            value: f64::NAN,
            allowed: format!("{} has no parameter {}", P::INFO.key, key.spec().name),
        })
}

/// `model` over a range of one of its parameters `key` (the others, the load included, as in
/// `model`): one model per sample, the sample value first. Every end of `values` must be an
/// accepted value of the parameter and give a valid model with the others: a problem whose
/// inputs bound one another (the lap joint's F <= F_gross = 2 b mu P L) refuses, before the
/// first row, a range at one of whose ends the model has no state. Both ends checked check every
/// sample where the bound is monotonic in the parameter (F_gross grows with L, b, P and mu and
/// does not depend on the others).
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of the parameter, or
/// the model at an end is refused: for the load, with the range the structure carries (as
/// [`load::check_forces`]); for another parameter, naming it, its value and the refusal.
pub fn param_models<P: Problem>(
    model: P::Model,
    key: P::Key,
    values: Samples,
) -> Result<impl Iterator<Item = (f64, P::Model)>, RangeError> {
    let param = param_of::<P>(key)?;
    values.check_within(param)?;
    let load = P::INFO.load == Some(param);
    for (end, value) in [
        (RangeEnd::Start, values.value(0)),
        (RangeEnd::End, values.value(values.len() - 1)),
    ] {
        let mut params = P::params(&model);
        let Some(slot) = P::slot(&mut params, key.index()) else {
            continue;
        };
        *slot = value;
        if let Err(error) = P::model(&params) {
            let allowed = if load {
                error.allowed()
            } else {
                format!("at {param} = {value}, {error}")
            };
            return Err(RangeError::Bound {
                end,
                value,
                allowed,
            });
        }
    }
    Ok(values
        .values()
        .map(move |v| (v, P::with_clamped(&model, key, v))))
}

/// `model` over a range of one of its parameters `key` ([`param_models`]): one row
/// ([`Pointwise::Point`]) per sample, the sample value first. For the load of a load-driven
/// problem this is [`load::force_sweep`] with the force repeated in front.
///
/// # Errors
/// As [`param_models`].
pub fn param_sweep<P: Pointwise>(
    model: P::Model,
    key: P::Key,
    values: Samples,
) -> Result<impl Iterator<Item = (f64, P::Point)>, RangeError> {
    // The rows walk one family of the parameter (a solver may continue along it, issue 47):
    // each is computed inside the walk's scope.
    let models = param_models::<P>(model, key, values)?;
    Ok(family::iter(models.map(|(v, at)| (v, P::point(&at)))))
}

/// The response of `model` (mm: w(L) of the beams, u(L) of the plate, Delta of the lap joint)
/// against its parameter `key`: (Coulomb, regularized).
///
/// # Errors
/// As [`param_models`].
pub fn responses_over<P: Problem>(
    model: P::Model,
    key: P::Key,
    values: Samples,
) -> Result<(Series, Series), RangeError> {
    let models = param_models::<P>(model, key, values)?;
    Ok(family::scope(|| {
        models
            .map(|(v, at)| {
                let state = P::solve(&at);
                (
                    (v, state.coulomb().response()),
                    (v, state.regularized().response()),
                )
            })
            .unzip()
    }))
}

/// Where the regularized law's zone ends (mm: X_r of the plate, X of the beams) against the
/// parameter `key` of `model`: one point per sample.
///
/// # Errors
/// As [`param_models`].
pub fn zone_end_over<P: Problem>(
    model: P::Model,
    key: P::Key,
    values: Samples,
) -> Result<Series, RangeError> {
    let models = param_models::<P>(model, key, values)?;
    Ok(family::scope(|| {
        models
            .map(|(v, at)| (v, P::solve(&at).regularized().zone_end()))
            .collect()
    }))
}

/// `param` of another problem than `model`'s.
fn another_problem(param: Param) -> RangeError {
    RangeError::Bound {
        end: RangeEnd::Start,
        value: f64::NAN,
        allowed: format!("{param} is a parameter of another problem"),
    }
}

/// Interface shear tau (MPa) along the interface of `model` at its state: (Coulomb, regularized).
pub fn shear_along_of<P: Profiled>(model: &P::Model, positions: Samples) -> (Series, Series) {
    P::shear_along(model, positions.values())
}

/// The response of `model` (w(L) of the beams, u(L) of the plate, Delta of the lap joint, mm)
/// against any one of its parameters: (Coulomb, regularized). The chart "w(L) vs this
/// parameter" ([`responses_over`] of the model's problem).
///
/// # Errors
/// [`RangeError::Bound`] when an end of `values` is not an accepted value of `param` (or `param`
/// belongs to another problem).
pub fn response_vs_param(
    model: &Model,
    param: Param,
    values: Samples,
) -> Result<(Series, Series), RangeError> {
    model.kind().visit(ResponseVsParam(model, param, values))
}

/// [`response_vs_param`]'s body, typed.
struct ResponseVsParam<'a>(&'a Model, Param, Samples);

impl Visit for ResponseVsParam<'_> {
    type Output = Result<(Series, Series), RangeError>;

    fn run<P: Listed>(self) -> Self::Output {
        let ResponseVsParam(model, param, values) = self;
        let key = P::index_of(param).and_then(|i| P::Key::KEYS.get(i).copied());
        match (P::from_model(model), key) {
            (Some(typed), Some(key)) => responses_over::<P>(typed, key, values),
            _ => Err(another_problem(param)),
        }
    }
}

/// Interface shear tau (MPa) along the interface of `model` at its state: (Coulomb,
/// regularized) ([`shear_along_of`] of the model's problem).
pub fn shear_along(model: &Model, positions: Samples) -> (Series, Series) {
    model.kind().visit(ShearAlong(model, positions))
}

/// [`shear_along`]'s body, typed.
struct ShearAlong<'a>(&'a Model, Samples);

impl Visit for ShearAlong<'_> {
    type Output = (Series, Series);

    fn run<P: Listed>(self) -> Self::Output {
        let ShearAlong(model, positions) = self;
        P::from_model(model).map_or_else(
            || (Vec::new(), Vec::new()),
            |typed| shear_along_of::<P>(&typed, positions),
        )
    }
}

/// The far edge of the regularized law's holding zone (mm) against F (N): the end of the beams'
/// microslip zone X (X = L below F_1), the joint's L - d ([`load::holding_zone_vs_force`]).
///
/// # Errors
/// As [`load::force_sweep`].
pub fn slip_boundary_vs_force<P: LoadDriven>(
    structure: &P::Structure,
    forces: Samples,
) -> Result<Series, RangeError> {
    Ok(
        load::holding_zone_vs_force::<P>(structure, Law::Regularized, forces)?
            .into_iter()
            .map(|(f, [_, x])| (f, x))
            .collect(),
    )
}

/// The holding zone's edges against F, one closed outline per law: its near edge (the joint's
/// x = a) from F = 0 up to the last force, then its far edge (x = L - d) back down to F = 0
/// ([`load::holding_zone_vs_force`]). Where the two meet (the joint's F_gross, a + d = L) the
/// outline encloses the zone that sticks (Coulomb) or slips elastically (regularized), and the
/// sliding zones lie outside it: (Coulomb, regularized).
///
/// # Errors
/// As [`load::force_sweep`].
pub fn zone_outline_vs_force<P: LoadDriven>(
    structure: &P::Structure,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    let outline = |law: Law| -> Result<Series, RangeError> {
        let rows = load::holding_zone_vs_force::<P>(structure, law, forces)?;
        let up = rows.iter().map(|&(f, [a, _])| (f, a));
        let down = rows.iter().rev().map(|&(f, [_, far])| (f, far));
        Ok(up.chain(down).collect())
    };
    Ok((outline(Law::Coulomb)?, outline(Law::Regularized)?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::plate::SqueezedPlateProblem;
    use crate::problems::twin_beams::TwinBeamsProblem;
    use crate::problems::{PlateParam, plate::params::PlateParams};
    use crate::{Regime, SqueezedPlate, TwinBeams, TwinBeamsParams};

    const STIFFNESS: Param = Param::Plate(PlateParam::Stiffness);

    fn beam_force_sweep(
        beams: TwinBeams,
        forces: Samples,
    ) -> Result<impl Iterator<Item = BeamPoint>, RangeError> {
        load::force_sweep::<TwinBeamsProblem>(beams, forces)
    }

    fn plate_kt_sweep(
        plate: SqueezedPlate,
        stiffnesses: Samples,
    ) -> Result<impl Iterator<Item = PlatePoint>, RangeError> {
        Ok(
            param_sweep::<SqueezedPlateProblem>(plate, PlateParam::Stiffness, stiffnesses)?
                .map(|(_, p)| p),
        )
    }

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
        assert!(zone_end_over::<SqueezedPlateProblem>(plate, PlateParam::Friction, high).is_err());
    }

    #[test]
    fn sweeps_over_the_whole_domain_give_every_row_finite() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let rows: Vec<BeamPoint> = beam_force_sweep(
            beams,
            load_samples::<TwinBeamsProblem>(0.0, 1e12, 101).unwrap(),
        )
        .unwrap()
        .collect();
        assert_eq!(rows.len(), 101);
        assert!(rows.iter().all(|r| {
            [r.w_coulomb, r.w_regularized, r.micro_end]
                .iter()
                .all(|v| v.is_finite())
        }));
        let cycles: Vec<CyclePoint> = load::cycle_sweep::<TwinBeamsProblem>(
            beams,
            load_samples::<TwinBeamsProblem>(0.0, 1e12, 11).unwrap(),
        )
        .unwrap()
        .collect();
        assert_eq!(cycles.len(), 11);
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let all = Samples::of_param(STIFFNESS, 1e-6, 1e12, 181, Spacing::Logarithmic).unwrap();
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
        let rows: Vec<BeamPoint> = beam_force_sweep(
            beams,
            load_samples::<TwinBeamsProblem>(0.0, 300.0, 31).unwrap(),
        )
        .unwrap()
        .collect();
        assert_eq!(rows.len(), 31);
        assert!((rows[10].force - 100.0).abs() < 1e-12);
        assert_eq!(rows[10].regime_regularized, Regime::MICROSLIP_MACROSLIP);
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let samples = Samples::of_param(STIFFNESS, 1.0, 1e7, 8, Spacing::Logarithmic).unwrap();
        let rows: Vec<PlatePoint> = plate_kt_sweep(plate, samples).unwrap().collect();
        assert_eq!(rows.len(), 8);
        assert_eq!(rows[7].kt, 1e7);
    }
}
