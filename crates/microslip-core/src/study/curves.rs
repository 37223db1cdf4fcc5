//! Sampling: the one place that loops over a parameter. The CLI's sweeps, its single-point reports and
//! (later) the TUI's charts all take their numbers from here, so a value on screen and the same value
//! in a CSV file come from the same function.
//!
//! Sweeps are iterators: a million-row sweep streams without building the table first.

use thiserror::Error;

use crate::kernel::code_defaults::CodeDefault;
use crate::kernel::params::Compact;
use crate::kernel::validity::Validity;
use crate::problems::inputs::Model;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::problems::twin_beams::cycle::{Cycle, Law};
use crate::problems::twin_beams::problem::{BeamsModel, TwinBeamsProblem};
use crate::problems::twin_beams::validity::BeamValidity;
use crate::problems::{BeamParam, Param, PlateParam, Problem};
use crate::{Regime, SqueezedPlate, TipForce, TwinBeams};

/// Largest number of points a sweep (or a branch of a cycle's loop) accepts: beyond it a request is
/// a mistake, not a need.
pub const MAX_POINTS: u64 = 100_000_000;

/// Which end of a range a value is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RangeEnd {
    /// The first value.
    Start,
    /// The last value.
    End,
}

/// A rejected sampling. Messages say `start`, `end` and `points`; a caller with its own names for
/// them (command-line flags) formats the same message with [`RangeError::message`].
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RangeError {
    /// Start above end.
    #[error("{}", self.message(["start", "end", "points"]))]
    Reversed {
        /// Start value.
        from: f64,
        /// End value.
        to: f64,
    },
    /// Too few or too many points.
    #[error("{}", self.message(["start", "end", "points"]))]
    Points(u64),
    /// A bound outside the allowed values.
    #[error("{}", self.message(["start", "end", "points"]))]
    Bound {
        /// Which end.
        end: RangeEnd,
        /// The value.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
}

impl RangeError {
    /// The message with the caller's names for the start, the end and the number of points.
    pub fn message(&self, [start, end, points]: [&str; 3]) -> String {
        match self {
            RangeError::Reversed { from, to } => format!(
                "invalid range: {start} = {} is above {end} = {}; the start must not exceed the end",
                Compact(*from),
                Compact(*to)
            ),
            // Without a range (a loop's points per branch), the one-point case does not exist.
            RangeError::Points(n) if start.is_empty() => {
                format!("invalid {points} = {n}: must be an integer in [2, {MAX_POINTS}]")
            }
            RangeError::Points(n) => {
                format!(
                    "invalid {points} = {n}: must be an integer in [2, {MAX_POINTS}], or 1 when {start} = {end}"
                )
            }
            RangeError::Bound {
                end: which,
                value,
                allowed,
            } => {
                let name = match which {
                    RangeEnd::Start => start,
                    RangeEnd::End => end,
                };
                format!("invalid {name} = {}: {allowed}", Compact(*value))
            }
        }
    }
}

/// Checks a number of points: 2 to [`MAX_POINTS`].
///
/// # Errors
/// [`RangeError::Points`] outside that range.
pub fn check_points(points: u64) -> Result<u64, RangeError> {
    if (2..=MAX_POINTS).contains(&points) {
        Ok(points)
    } else {
        Err(RangeError::Points(points))
    }
}

/// How sample values are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spacing {
    /// Equal steps.
    Linear,
    /// Equal ratios (both ends must be > 0).
    Logarithmic,
}

/// A validated sampling of [from, to] with `points` values, both ends included exactly.
///
/// # Examples
/// ```
/// use microslip_core::study::curves::{beam_force_sweep, force_samples};
/// use microslip_core::{Regime, TwinBeams, TwinBeamsParams};
/// let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
/// let forces = force_samples(0.0, 300.0, 4)?; // 0, 100, 200, 300 N
/// let rows: Vec<_> = beam_force_sweep(beams, forces)?.collect();
/// assert_eq!(rows[1].force, 100.0);
/// assert_eq!(rows[1].regime_regularized, Regime::MICROSLIP_MACROSLIP);
/// assert!(force_samples(0.0, -1.0, 4).is_err()); // -1 N is not a tip force
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Samples {
    from: f64,
    to: f64,
    points: u64,
    spacing: Spacing,
}

impl Samples {
    /// Checks the range: finite ends (> 0 for logarithmic spacing), start <= end, 2 to
    /// [`MAX_POINTS`] points, or a single point when start = end.
    ///
    /// # Errors
    /// The first problem found, as a [`RangeError`].
    pub fn new(from: f64, to: f64, points: u64, spacing: Spacing) -> Result<Self, RangeError> {
        let allowed = match spacing {
            Spacing::Linear => "must be a finite number",
            Spacing::Logarithmic => "must be > 0 and finite (logarithmic spacing)",
        };
        for (end, value) in [(RangeEnd::Start, from), (RangeEnd::End, to)] {
            if !value.is_finite() || (spacing == Spacing::Logarithmic && value <= 0.0) {
                return Err(RangeError::Bound {
                    end,
                    value,
                    allowed: allowed.to_string(),
                });
            }
        }
        if from > to {
            return Err(RangeError::Reversed { from, to });
        }
        if !(points == 1 && from == to) {
            check_points(points)?;
        }
        Ok(Samples {
            from,
            to,
            points,
            spacing,
        })
    }

    /// A sampling of a parameter's values: both ends must be in the parameter's domain (so every
    /// sample between them is too), then as [`Samples::new`].
    ///
    /// # Errors
    /// An end outside the domain (with the domain in words), or a problem of [`Samples::new`].
    pub fn of_param(
        param: Param,
        from: f64,
        to: f64,
        points: u64,
        spacing: Spacing,
    ) -> Result<Self, RangeError> {
        let spec = param.spec();
        for (end, value) in [(RangeEnd::Start, from), (RangeEnd::End, to)] {
            if !spec.domain.contains(value) {
                return Err(RangeError::Bound {
                    end,
                    value,
                    allowed: spec.domain.refusal(value, spec.unit),
                });
            }
        }
        Samples::new(from, to, points, spacing)
    }

    /// Checks that every sample is an accepted value of `param`: both ends are (the samples lie
    /// between them and a domain is an interval). What every sweep checks before its first row, so
    /// that no row is ever dropped or computed at another value than the one asked for.
    ///
    /// # Errors
    /// [`RangeError::Bound`] for the first end outside the domain.
    pub(crate) fn check_within(&self, param: Param) -> Result<(), RangeError> {
        let spec = param.spec();
        for (end, value) in [(RangeEnd::Start, self.from), (RangeEnd::End, self.to)] {
            if !spec.domain.contains(value) {
                return Err(RangeError::Bound {
                    end,
                    value,
                    allowed: spec.domain.refusal(value, spec.unit),
                });
            }
        }
        Ok(())
    }

    /// Number of samples.
    pub fn len(&self) -> u64 {
        self.points
    }

    /// Always false: a valid sampling has at least one point.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The i-th sample value (0-based); the first one is exactly `from`, the last one exactly `to`,
    /// and none is outside [from, to] (round-off of the spacing is clamped away).
    pub fn value(&self, i: u64) -> f64 {
        if i + 1 >= self.points {
            return self.to;
        }
        let t = i as f64 / (self.points - 1) as f64;
        let value = match self.spacing {
            // Monotonic in t; to - from overflows only for ends of opposite signs near f64::MAX,
            // where the weighted form takes over.
            Spacing::Linear if (self.to - self.from).is_finite() => {
                self.from + t * (self.to - self.from)
            }
            Spacing::Linear => (1.0 - t) * self.from + t * self.to,
            Spacing::Logarithmic => self.from * (self.to / self.from).powf(t),
        };
        value.clamp(self.from, self.to)
    }

    /// The sample values in order.
    pub fn values(self) -> impl Iterator<Item = f64> {
        (0..self.points).map(move |i| self.value(i))
    }
}

/// Everything the reports show about the twin beams at one force, for both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeamPoint {
    /// Tip force F (N).
    pub force: f64,
    /// Coulomb tip deflection (mm).
    pub w_coulomb: f64,
    /// Regularized tip deflection (mm).
    pub w_regularized: f64,
    /// End of the Coulomb stick zone (mm): L in stick, 0 once the interface slides.
    pub stick_end: f64,
    /// End of the microslip zone X (mm); L without macroslip.
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
    /// Where the beam theory stands against continuum FE at this force (V2).
    pub validity: BeamValidity,
}

/// The twin beams at one force.
pub fn beam_point(beams: &TwinBeams, force: TipForce) -> BeamPoint {
    let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
    let w_regularized = regularized.tip_deflection();
    BeamPoint {
        force: force.newtons(),
        w_coulomb: coulomb.tip_deflection(),
        w_regularized,
        stick_end: coulomb.stick_end(),
        micro_end: regularized.micro_zone_end(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
        validity: beams.validity_at(force, w_regularized),
    }
}

/// The twin beams over a range of forces: one row per sample, every one computed at the force
/// asked for.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `forces` is not an accepted tip force (see
/// [`force_samples`], which checks this when the range is made).
pub fn beam_force_sweep(
    beams: TwinBeams,
    forces: Samples,
) -> Result<impl Iterator<Item = BeamPoint>, RangeError> {
    forces.check_within(Param::Beam(BeamParam::Force))?;
    // Every sample lies in the force domain, so clamping changes nothing.
    Ok(forces
        .values()
        .map(move |f| beam_point(&beams, TipForce::clamped(f))))
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

/// A sampled curve: (x, y) points in order of x.
pub type Series = Vec<(f64, f64)>;

/// Tip deflection w(L) (mm) against F (N): (Coulomb, regularized).
///
/// # Errors
/// As [`beam_force_sweep`].
pub fn beam_deflection_vs_force(
    beams: &TwinBeams,
    forces: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(beam_force_sweep(*beams, forces)?
        .map(|p| ((p.force, p.w_coulomb), (p.force, p.w_regularized)))
        .unzip())
}

/// End of the microslip zone X (mm) against F (N), regularized law (X = L below F_1).
///
/// # Errors
/// As [`beam_force_sweep`].
pub fn beam_slip_boundary_vs_force(
    beams: &TwinBeams,
    forces: Samples,
) -> Result<Series, RangeError> {
    Ok(beam_force_sweep(*beams, forces)?
        .map(|p| (p.force, p.micro_end))
        .collect())
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

/// What one stretch of the interface does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Zone {
    /// No relative displacement (Coulomb law below the stress mu P).
    Stick,
    /// Elastic slip below mu P (regularized law).
    Microslip,
    /// Sliding at tau = mu P.
    Macroslip,
    /// No load at all (the beams at F = 0).
    Unloaded,
}

/// One stretch [from, to] (mm) of the interface and its zone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneSpan {
    /// Start (mm from x = 0).
    pub from: f64,
    /// End (mm from x = 0).
    pub to: f64,
    /// What the stretch does.
    pub zone: Zone,
}

/// A named zone boundary inside the interface (X, X_s, X_r), in mm from x = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneBoundary {
    /// `X`, `X_s` or `X_r`, as in the theory and the regime pane.
    pub name: &'static str,
    /// Position (mm).
    pub at: f64,
}

/// The interface from x = 0 (clamp, plate centre) to L under both laws: the zone strip of the TUI.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceZones {
    /// L (mm): beam length or plate half-length.
    pub length: f64,
    /// Coulomb's stretches, from x = 0 outward, covering [0, L].
    pub coulomb: Vec<ZoneSpan>,
    /// The regularized law's stretches.
    pub regularized: Vec<ZoneSpan>,
    /// Boundaries strictly inside (0, L), Coulomb's first.
    pub boundaries: Vec<ZoneBoundary>,
}

/// Two stretches split at `at`: `inner` on [0, at], `outer` on [at, L], leaving out an empty one.
fn split_at(length: f64, at: f64, inner: Zone, outer: Zone) -> Vec<ZoneSpan> {
    let at = at.clamp(0.0, length);
    [(0.0, at, inner), (at, length, outer)]
        .into_iter()
        .filter(|(from, to, _)| to > from)
        .map(|(from, to, zone)| ZoneSpan { from, to, zone })
        .collect()
}

/// The zones of both laws at the model's state: Coulomb sticks up to its stick end and slides
/// beyond; the regularized law slips elastically up to X (X_r) and slides beyond. From the same
/// `beam_point` / `plate_point` as the regime pane, so strip and text cannot disagree.
pub fn interface_zones(model: &Model) -> InterfaceZones {
    let (length, stick_end, micro_end, coulomb, regularized, names) = match model {
        Model::Beam { beams, force } => {
            let row = beam_point(beams, *force);
            let p = (row.stick_end, row.micro_end);
            let r = (row.regime_coulomb, row.regime_regularized);
            (beams.params().length, p.0, p.1, r.0, r.1, ("X_s", "X"))
        }
        Model::Plate(plate) => {
            let row = plate_point(plate);
            let p = (row.stick_end, row.micro_end);
            let r = (row.regime_coulomb, row.regime_regularized);
            (
                plate.params().half_length,
                p.0,
                p.1,
                r.0,
                r.1,
                ("X_s", "X_r"),
            )
        }
        Model::Lap { joint, force } => return lap_zones(joint, *force),
    };
    let zones = |regime: Regime, end: f64, inner: Zone| {
        if regime == Regime::UNLOADED {
            split_at(length, length, Zone::Unloaded, Zone::Unloaded)
        } else {
            split_at(length, end, inner, Zone::Macroslip)
        }
    };
    let inside = |at: f64| at > 0.0 && at < length;
    let boundaries = [
        (names.0, stick_end, coulomb),
        (names.1, micro_end, regularized),
    ]
    .into_iter()
    .filter(|&(_, at, regime)| regime != Regime::UNLOADED && inside(at))
    .map(|(name, at, _)| ZoneBoundary { name, at })
    .collect();
    InterfaceZones {
        length,
        coulomb: zones(coulomb, stick_end, Zone::Stick),
        regularized: zones(regularized, micro_end, Zone::Microslip),
        boundaries,
    }
}

/// The lap joint's zones: sliding from both ends, [0, a] and [L - d, L], sticking (Coulomb) or
/// elastic (regularized) between; boundaries named `a`, `L-d` (regularized) and `a_C`, `L-d_C`
/// (Coulomb).
fn lap_zones(joint: &LapJoint, force: JointForce) -> InterfaceZones {
    let length = joint.params().length;
    let row = crate::study::lap::lap_point(joint, force);
    let spans = |regime: Regime, (a, d): (f64, f64), middle: Zone| {
        if regime == Regime::UNLOADED {
            return split_at(length, length, Zone::Unloaded, Zone::Unloaded);
        }
        [
            (0.0, a, Zone::Macroslip),
            (a, length - d, middle),
            (length - d, length, Zone::Macroslip),
        ]
        .into_iter()
        .filter(|(from, to, _)| to > from)
        .map(|(from, to, zone)| ZoneSpan { from, to, zone })
        .collect()
    };
    let inside = |at: f64| at > 0.0 && at < length;
    let (ac, dc) = row.zones_coulomb;
    let (ar, dr) = row.zones_regularized;
    let boundaries = [
        ("a_C", ac, row.regime_coulomb),
        ("L-d_C", length - dc, row.regime_coulomb),
        ("a", ar, row.regime_regularized),
        ("L-d", length - dr, row.regime_regularized),
    ]
    .into_iter()
    .filter(|&(_, at, regime)| regime != Regime::UNLOADED && inside(at))
    .map(|(name, at, _)| ZoneBoundary { name, at })
    .collect();
    InterfaceZones {
        length,
        coulomb: spans(row.regime_coulomb, row.zones_coulomb, Zone::Stick),
        regularized: spans(
            row.regime_regularized,
            row.zones_regularized,
            Zone::Microslip,
        ),
        boundaries,
    }
}

/// Where a K_T to compare comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CandidateSource {
    /// The model's own K_T.
    Current,
    /// K_N times the low end of the measured K_T/K_N range.
    NormalLow,
    /// Paper eq. 4 from K_N at Poisson ratio `nu`.
    Equation4 {
        /// The Poisson ratio used (-).
        nu: f64,
    },
    /// K_N times the high end of the measured K_T/K_N range.
    NormalHigh,
    /// A finite-element code's default.
    Code(&'static CodeDefault),
}

impl CandidateSource {
    /// The candidate's short name in tables and charts ("current", "eq. 4", a code's name).
    pub fn name(&self) -> &'static str {
        match self {
            CandidateSource::Current => "current",
            CandidateSource::NormalLow => "K_N x 0.5",
            CandidateSource::Equation4 { .. } => "eq. 4",
            CandidateSource::NormalHigh => "K_N x 0.7",
            CandidateSource::Code(code) => code.code,
        }
    }
}

/// A K_T to compare: where it comes from and its value (`None`: that source gives no value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StiffnessCandidate {
    /// Source.
    pub source: CandidateSource,
    /// The stiffness (MPa/mm), when the source gives one.
    pub kt: Option<f64>,
}

/// What a K_T does to the model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Answer {
    /// Twin beams at the model's force.
    Beam {
        /// First-macroslip force F_1 (N).
        first_macroslip_force: f64,
        /// End of the microslip zone X (mm).
        micro_end: f64,
        /// Tip deflection w(L) (mm).
        tip_deflection: f64,
        /// Regime.
        regime: Regime,
    },
    /// The plate.
    Plate {
        /// End displacement u(L) (mm).
        end_displacement: f64,
        /// End of the microslip zone X_r (mm).
        micro_end: f64,
        /// Regime.
        regime: Regime,
    },
    /// The lap joint at the model's force.
    Lap {
        /// Force of first sliding F_1 (N).
        first_slip_force: f64,
        /// Sliding zones a (from x = 0) and d (from x = L) (mm).
        zones: (f64, f64),
        /// Joint displacement Delta (mm).
        joint_displacement: f64,
        /// Regime.
        regime: Regime,
    },
}

impl Answer {
    /// The displacement the benchmark compares: the beams' w(L), the plate's u(L), the lap
    /// joint's Delta (mm).
    pub fn response(&self) -> f64 {
        match *self {
            Answer::Beam { tip_deflection, .. } => tip_deflection,
            Answer::Plate {
                end_displacement, ..
            } => end_displacement,
            Answer::Lap {
                joint_displacement, ..
            } => joint_displacement,
        }
    }
}

/// One row of the K_T comparison: the candidate and, when it has a valid K_T, its answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComparedStiffness {
    /// The candidate.
    pub candidate: StiffnessCandidate,
    /// What it does to the model.
    pub answer: Option<Answer>,
    /// How far its w(L) (beams) or u(L) (plate) is from the current K_T's (fraction: +0.6 is 60 %
    /// more): what an FE model with this K_T gets wrong when the model's K_T is the interface's
    /// true one. None without an answer, or when the current answer is zero (no load).
    pub off_current: Option<f64>,
    /// How far its w(L), u(L) or Delta is from Coulomb's (K_T -> infinity), as a fraction: what
    /// an FE model with this K_T gets wrong when the interface is rigid until it slides (the
    /// figure users otherwise compute by hand). None without an answer, or when Coulomb's answer
    /// is zero (no load).
    pub off_coulomb: Option<f64>,
}

/// The K_T values worth comparing for one model and what each does to the answer: computed once,
/// shown by the text and JSON reports and the TUI table alike.
///
/// # Examples
/// ```
/// use microslip_core::study::curves::{Answer, CandidateSource, compare_stiffnesses};
/// use microslip_core::{Inputs, ModelKind};
/// let model = Inputs::paper(ModelKind::Plate).validate()?;
/// // Contact elements of 0.1 mm, and K_N = 1e6 MPa/mm at nu = 0.3 for paper eq. 4.
/// let table = compare_stiffnesses(&model, 0.1, Some((1e6, 0.3)));
/// let eq4 = table
///     .rows
///     .iter()
///     .find(|r| matches!(r.candidate.source, CandidateSource::Equation4 { .. }))
///     .unwrap();
/// assert!((eq4.candidate.kt.unwrap() - 6.47e5).abs() < 1e3); // MPa/mm
/// assert!(matches!(eq4.answer, Some(Answer::Plate { .. })));
/// # Ok::<(), microslip_core::ParamError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessComparison {
    /// The model compared (its own K_T is the first row).
    pub model: Model,
    /// Contact element length assumed for the codes' defaults (mm).
    pub element: f64,
    /// The rows: current, those from K_N (when given), then each code.
    pub rows: Vec<ComparedStiffness>,
}

/// Coulomb's w(L) (beams), u(L) (plate) or Delta (lap) for `model` at its force: the K_T ->
/// infinity limit the `vs Coulomb` column divides by.
fn coulomb_response(model: &Model) -> f64 {
    match model {
        Model::Beam { beams, force } => beams.coulomb(*force).tip_deflection(),
        Model::Plate(plate) => plate.coulomb().end_displacement(),
        Model::Lap { joint, force } => joint.coulomb(*force).joint_displacement(),
    }
}

/// What `kt` does to `model` (at the model's force for the beams); `None` for an invalid K_T.
fn answer_for_stiffness(model: &Model, kt: f64) -> Option<Answer> {
    Some(match model {
        Model::Beam { beams, force } => {
            let beams = beams.with_tangential_stiffness(kt).ok()?;
            let state = beams.regularized(*force);
            Answer::Beam {
                first_macroslip_force: beams.first_macroslip_force(),
                micro_end: state.micro_zone_end(),
                tip_deflection: state.tip_deflection(),
                regime: state.regime(),
            }
        }
        Model::Plate(plate) => {
            let state = plate.with_tangential_stiffness(kt).ok()?.regularized();
            Answer::Plate {
                end_displacement: state.end_displacement(),
                micro_end: state.micro_zone_end(),
                regime: state.regime(),
            }
        }
        Model::Lap { joint, force } => {
            let joint = joint.with_tangential_stiffness(kt).ok()?;
            let state = joint.regularized(*force);
            Answer::Lap {
                first_slip_force: joint.first_slip_force(),
                zones: (state.slide_at_inner_end(), state.slide_at_cover_ends()),
                joint_displacement: state.joint_displacement(),
                regime: state.regime(),
            }
        }
    })
}

/// Compares the K_T values worth comparing for `model`: the current one, those from a normal contact
/// stiffness `normal` = (K_N (MPa/mm), nu) (paper eq. 4 and the measured K_T/K_N range), and those
/// FE codes assume by default for contact elements of length `element` (mm).
pub fn compare_stiffnesses(
    model: &Model,
    element: f64,
    normal: Option<(f64, f64)>,
) -> StiffnessComparison {
    use crate::kernel::code_defaults::{CODE_DEFAULTS, MEASURED_RATIO_RANGE};
    use crate::problems::stiffness::tangential_from_normal;
    let data = model.interface();
    let mut candidates = vec![StiffnessCandidate {
        source: CandidateSource::Current,
        kt: Some(data.stiffness),
    }];
    if let Some((kn, nu)) = normal {
        let (low, high) = MEASURED_RATIO_RANGE;
        candidates.extend([
            StiffnessCandidate {
                source: CandidateSource::NormalLow,
                kt: Some(low * kn),
            },
            StiffnessCandidate {
                source: CandidateSource::Equation4 { nu },
                kt: tangential_from_normal(kn, nu).ok(),
            },
            StiffnessCandidate {
                source: CandidateSource::NormalHigh,
                kt: Some(high * kn),
            },
        ]);
    }
    candidates.extend(CODE_DEFAULTS.iter().map(|code| StiffnessCandidate {
        source: CandidateSource::Code(code),
        kt: code.implied_stiffness(data.friction, data.pressure, data.modulus, element),
    }));
    let current = answer_for_stiffness(model, data.stiffness)
        .map(|a| a.response())
        .filter(|r| *r != 0.0);
    let coulomb = Some(coulomb_response(model)).filter(|r| *r != 0.0 && r.is_finite());
    let rows = candidates
        .into_iter()
        .map(|candidate| {
            let answer = candidate.kt.and_then(|kt| answer_for_stiffness(model, kt));
            ComparedStiffness {
                candidate,
                answer,
                off_current: answer.zip(current).map(|(a, c)| a.response() / c - 1.0),
                off_coulomb: answer.zip(coulomb).map(|(a, c)| a.response() / c - 1.0),
            }
        })
        .collect();
    StiffnessComparison {
        model: *model,
        element,
        rows,
    }
}

/// One cyclic amplitude, both laws: dissipation per cycle (N mm) and equivalent damping ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CyclePoint {
    /// Amplitude F_a (N).
    pub amplitude: f64,
    /// Coulomb dissipation per cycle (N mm).
    pub d_coulomb: f64,
    /// Regularized dissipation per cycle (N mm).
    pub d_regularized: f64,
    /// Coulomb D / (4 pi U).
    pub zeta_coulomb: f64,
    /// Regularized D / (4 pi U).
    pub zeta_regularized: f64,
}

/// The twin beams cycled at one amplitude.
pub fn cycle_point(beams: &TwinBeams, amplitude: TipForce) -> CyclePoint {
    let (c, r) = (
        Cycle::new(beams, Law::Coulomb, amplitude),
        Cycle::new(beams, Law::Regularized, amplitude),
    );
    CyclePoint {
        amplitude: amplitude.newtons(),
        d_coulomb: c.dissipation(),
        d_regularized: r.dissipation(),
        zeta_coulomb: c.damping_ratio(),
        zeta_regularized: r.damping_ratio(),
    }
}

/// The twin beams cycled over a range of amplitudes (accepted tip forces): one row per sample.
///
/// # Errors
/// [`RangeError::Bound`] when an end of `amplitudes` is not an accepted tip force.
pub fn cycle_sweep(
    beams: TwinBeams,
    amplitudes: Samples,
) -> Result<impl Iterator<Item = CyclePoint>, RangeError> {
    amplitudes.check_within(Param::Beam(BeamParam::Force))?;
    Ok(amplitudes
        .values()
        .map(move |f| cycle_point(&beams, TipForce::clamped(f))))
}

/// A branch of the hysteresis loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Branch {
    /// From +F_a down to -F_a.
    Unloading,
    /// From -F_a back up to +F_a.
    Reloading,
}

impl Branch {
    /// `unloading` or `reloading`, as the CSV column says it.
    pub fn label(self) -> &'static str {
        match self {
            Branch::Unloading => "unloading",
            Branch::Reloading => "reloading",
        }
    }
}

/// One point of the hysteresis loop, both laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopPoint {
    /// The branch.
    pub branch: Branch,
    /// Tip force F (N).
    pub force: f64,
    /// Coulomb tip deflection (mm).
    pub w_coulomb: f64,
    /// Regularized tip deflection (mm).
    pub w_regularized: f64,
}

/// The closed hysteresis loop of a cycle at `amplitude`: `points` evenly spaced forces per branch,
/// both ends included (so the turning point at -F_a ends one branch and starts the next).
///
/// # Errors
/// [`RangeError::Points`] outside 2 to [`MAX_POINTS`].
pub fn cycle_loop(
    beams: &TwinBeams,
    amplitude: TipForce,
    points: u64,
) -> Result<impl Iterator<Item = LoopPoint>, RangeError> {
    let points = check_points(points)?;
    let (coulomb, regularized) = (
        Cycle::new(beams, Law::Coulomb, amplitude),
        Cycle::new(beams, Law::Regularized, amplitude),
    );
    Ok(loop_points(
        amplitude.newtons(),
        points,
        move |f| (coulomb.unloading(f), regularized.unloading(f)),
        move |f| (coulomb.reloading(f), regularized.reloading(f)),
    ))
}

/// The closed loop of a cycle at amplitude `fa` (N) from its branches, each giving (Coulomb,
/// regularized) at a force: `points` evenly spaced forces per branch (checked, >= 2), both ends
/// included.
pub(crate) fn loop_points(
    fa: f64,
    points: u64,
    unloading: impl Fn(f64) -> (f64, f64) + Copy,
    reloading: impl Fn(f64) -> (f64, f64) + Copy,
) -> impl Iterator<Item = LoopPoint> {
    let last = (points - 1) as f64;
    let branch = move |branch: Branch| {
        (0..points).map(move |i| {
            let t = 2.0 * fa * i as f64 / last;
            let (force, (w_coulomb, w_regularized)) = match branch {
                Branch::Unloading => (fa - t, unloading(fa - t)),
                Branch::Reloading => (t - fa, reloading(t - fa)),
            };
            LoopPoint {
                branch,
                force,
                w_coulomb,
                w_regularized,
            }
        })
    };
    branch(Branch::Unloading).chain(branch(Branch::Reloading))
}

/// Dissipation per cycle D (N mm) against F_a (N): (Coulomb, regularized).
///
/// # Errors
/// As [`cycle_sweep`].
pub fn dissipation_vs_amplitude(
    beams: &TwinBeams,
    amplitudes: Samples,
) -> Result<(Series, Series), RangeError> {
    Ok(cycle_sweep(*beams, amplitudes)?
        .map(|p| ((p.amplitude, p.d_coulomb), (p.amplitude, p.d_regularized)))
        .unzip())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

    fn beam_zones(force: f64) -> InterfaceZones {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let force = TipForce::new(force).unwrap();
        interface_zones(&Model::Beam { beams, force })
    }

    fn plate_zones(kt: f64) -> InterfaceZones {
        let plate = SqueezedPlate::new(PlateParams {
            tangential_stiffness: kt,
            ..PlateParams::PAPER
        })
        .unwrap();
        interface_zones(&Model::Plate(plate))
    }

    /// Contiguous stretches from 0 to L, whatever the state.
    fn assert_covers(zones: &InterfaceZones) {
        for spans in [&zones.coulomb, &zones.regularized] {
            assert_eq!(spans.first().unwrap().from, 0.0, "{zones:?}");
            assert_eq!(spans.last().unwrap().to, zones.length, "{zones:?}");
            assert!(spans.windows(2).all(|w| w[0].to == w[1].from), "{zones:?}");
            assert!(spans.iter().all(|s| s.to > s.from), "{zones:?}");
        }
    }

    #[test]
    fn the_beams_zones_change_at_f_thre_and_f_1() {
        // F_thre = 4 mu b h P / 3 = 4 (0.3)(20)(10)(1) / 3 = 80 N by hand; F_1 is just above it.
        let zones: Vec<_> = [0.0, 40.0, 79.9, 80.1, 100.0, 150.0, 300.0]
            .map(beam_zones)
            .into();
        zones.iter().for_each(assert_covers);
        let only = |spans: &[ZoneSpan]| (spans.len() == 1).then(|| spans[0].zone);
        assert_eq!(only(&zones[0].coulomb), Some(Zone::Unloaded));
        assert_eq!(only(&zones[0].regularized), Some(Zone::Unloaded));
        assert_eq!(only(&zones[1].coulomb), Some(Zone::Stick));
        assert_eq!(only(&zones[1].regularized), Some(Zone::Microslip));
        assert_eq!(only(&zones[2].coulomb), Some(Zone::Stick));
        assert_eq!(only(&zones[3].coulomb), Some(Zone::Macroslip));
        assert_eq!(only(&zones[3].regularized), Some(Zone::Microslip));
        assert!(zones[..4].iter().all(|z| z.boundaries.is_empty()));
        // Above F_1, microslip then macroslip, with X moving toward the clamp as F grows.
        let x: Vec<f64> = zones[4..]
            .iter()
            .map(|z| {
                let kinds: Vec<Zone> = z.regularized.iter().map(|s| s.zone).collect();
                assert_eq!(kinds, [Zone::Microslip, Zone::Macroslip]);
                assert_eq!(z.boundaries.len(), 1);
                assert_eq!(z.boundaries[0].name, "X");
                assert_eq!(z.boundaries[0].at, z.regularized[0].to);
                z.boundaries[0].at
            })
            .collect();
        assert!(x.windows(2).all(|w| w[1] < w[0]), "{x:?}");
    }

    #[test]
    fn the_plates_microslip_end_tends_to_the_coulomb_stick_end_as_kt_grows() {
        let stick_end = |z: &InterfaceZones| z.coulomb[0].to;
        let micro_end = |z: &InterfaceZones| z.regularized[0].to;
        let soft = plate_zones(1e4);
        assert_covers(&soft);
        // Soft: no macroslip (its onset is K_T = 1.88e5 MPa/mm), so only X_s is inside.
        assert_eq!(soft.regularized.len(), 1);
        let names: Vec<&str> = soft.boundaries.iter().map(|b| b.name).collect();
        assert_eq!(names, ["X_s"]);
        let gaps: Vec<f64> = [1e6, 1e8, 1e10]
            .map(plate_zones)
            .iter()
            .map(|z| {
                assert_covers(z);
                assert_eq!(z.coulomb[0].zone, Zone::Stick);
                assert_eq!(z.regularized[1].zone, Zone::Macroslip);
                micro_end(z) - stick_end(z)
            })
            .collect();
        // The regularized law slips elastically a little further than Coulomb sticks, and the
        // difference vanishes as K_T grows (plain Coulomb in the limit).
        assert!(gaps.iter().all(|&g| g > 0.0), "{gaps:?}");
        assert!(gaps.windows(2).all(|w| w[1] < w[0]), "{gaps:?}");
        assert!(gaps[2] < 1e-3 * soft.length, "{gaps:?}");
    }

    #[test]
    fn samples_hit_both_ends_exactly() {
        let s = Samples::new(0.1, 0.7, 7, Spacing::Linear).unwrap();
        let v: Vec<f64> = s.values().collect();
        assert_eq!(v.len(), 7);
        assert_eq!((v[0], v[6]), (0.1, 0.7));
        assert!((v[3] - 0.4).abs() < 1e-15);
        let s = Samples::new(1.0, 1e6, 7, Spacing::Logarithmic).unwrap();
        let v: Vec<f64> = s.values().collect();
        assert_eq!((v[0], v[6]), (1.0, 1e6));
        assert!((v[3] - 1e3).abs() < 1e-9);
    }

    #[test]
    fn bad_ranges_are_refused_with_the_callers_names() {
        const FLAGS: [&str; 3] = ["--from", "--to", "--points"];
        let err = force_samples(10.0, 5.0, 3).unwrap_err();
        assert_eq!(
            err.message(FLAGS),
            "invalid range: --from = 10 is above --to = 5; the start must not exceed the end"
        );
        assert_eq!(
            err.to_string(),
            "invalid range: start = 10 is above end = 5; the start must not exceed the end"
        );
        assert_eq!(
            force_samples(0.0, 5.0, 1).unwrap_err(),
            RangeError::Points(1)
        );
        assert_eq!(
            RangeError::Points(1).message(FLAGS),
            "invalid --points = 1: must be an integer in [2, 100000000], or 1 when --from = --to"
        );
        assert!(force_samples(0.0, 5.0, MAX_POINTS + 1).is_err());
        assert!(
            force_samples(-1.0, 5.0, 3)
                .unwrap_err()
                .message(FLAGS)
                .starts_with("invalid --from = -1: must be >= 0 and finite (N)")
        );
        let err = stiffness_samples(0.0, 5.0, 3, Spacing::Logarithmic).unwrap_err();
        assert_eq!(
            err.message(["--kt-from", "--kt-to", "--points"]),
            "invalid --kt-from = 0: must be > 0 and finite (MPa/mm)"
        );
    }

    #[test]
    fn samples_never_leave_their_range() {
        // Logarithmic spacing over 18 decades and linear spacing over a range far narrower than its
        // ends: round-off of the spacing must not step outside [from, to].
        for (from, to, spacing) in [
            (1e-6, 1e12, Spacing::Logarithmic),
            (0.3, 0.3 * (1.0 + 4.0 * f64::EPSILON), Spacing::Logarithmic),
            (1e12 - 1e-3, 1e12, Spacing::Linear),
            (-f64::MAX, f64::MAX, Spacing::Linear),
        ] {
            let samples = Samples::new(from, to, 1001, spacing).unwrap();
            assert!(
                samples
                    .values()
                    .all(|v| v.is_finite() && (from..=to).contains(&v)),
                "{from} {to}"
            );
        }
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
        assert!(cycle_sweep(beams, wide).is_err());
        let high = Samples::new(1.0, 1e13, 3, Spacing::Linear).unwrap();
        assert_eq!(
            cycle_sweep(beams, high).err().unwrap().to_string(),
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
        let cycles: Vec<CyclePoint> = cycle_sweep(beams, force_samples(0.0, 1e12, 11).unwrap())
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
    fn the_loop_closes_and_its_branches_meet_at_the_turning_points() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let amplitude = TipForce::new(150.0).unwrap();
        let points: Vec<LoopPoint> = cycle_loop(&beams, amplitude, 11).unwrap().collect();
        assert_eq!(points.len(), 22);
        let (first, turn, restart, last) = (points[0], points[10], points[11], points[21]);
        assert_eq!((first.force, turn.force), (150.0, -150.0));
        assert_eq!((restart.force, last.force), (-150.0, 150.0));
        assert_eq!(turn.branch, Branch::Unloading);
        assert_eq!(restart.branch, Branch::Reloading);
        for (a, b) in [(first, last), (turn, restart)] {
            assert!((a.w_coulomb - b.w_coulomb).abs() <= 1e-12 * a.w_coulomb.abs());
            assert!((a.w_regularized - b.w_regularized).abs() <= 1e-12 * a.w_regularized.abs());
        }
        assert!(cycle_loop(&beams, amplitude, 1).is_err());
    }

    #[test]
    fn the_stiffness_comparison_answers_every_valid_candidate() {
        let model = crate::Inputs::paper(crate::ModelKind::Beam)
            .validate()
            .unwrap();
        let table = compare_stiffnesses(&model, 2.0, Some((1000.0, 0.3)));
        assert_eq!(table.rows[0].candidate.source, CandidateSource::Current);
        assert!(matches!(
            table.rows[0].answer,
            Some(Answer::Beam { micro_end, .. }) if (micro_end - 17.3095).abs() < 1e-4
        ));
        assert!(matches!(
            table.rows[2].candidate.source,
            CandidateSource::Equation4 { nu } if nu == 0.3
        ));
        for row in &table.rows {
            assert_eq!(row.answer.is_some(), row.candidate.kt.is_some());
            assert_eq!(row.off_current.is_some(), row.answer.is_some());
        }
        // How far off each candidate is: its w(L) over the current K_T's, from the beams solved
        // at both stiffnesses here; 0 for the current row, above for softer, below for stiffer.
        let Model::Beam { beams, force } = model else {
            panic!()
        };
        let w = |kt: f64| {
            beams
                .with_tangential_stiffness(kt)
                .unwrap()
                .regularized(force)
                .tip_deflection()
        };
        for row in &table.rows {
            let (Some(kt), Some(off)) = (row.candidate.kt, row.off_current) else {
                continue;
            };
            let expected = w(kt) / w(600.0) - 1.0;
            assert!((off - expected).abs() < 1e-12, "{kt}: {off} vs {expected}");
            assert_eq!(off > 0.0, kt < 600.0, "{kt}: {off}");
        }
        assert_eq!(table.rows[0].off_current, Some(0.0));
        // No load, no displacement to compare against: nothing is said.
        let unloaded = Model::Beam {
            beams,
            force: crate::TipForce::new(0.0).unwrap(),
        };
        let table = compare_stiffnesses(&unloaded, 2.0, None);
        assert!(table.rows.iter().all(|r| r.off_current.is_none()));
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
