//! Sampling: the one place that loops over a parameter. The CLI's sweeps, its single-point reports and
//! (later) the TUI's charts all take their numbers from here, so a value on screen and the same value
//! in a CSV file come from the same function.
//!
//! Sweeps are iterators: a million-row sweep streams without building the table first.

use thiserror::Error;

use crate::{Regime, SqueezedPlate, TipForce, TwinBeams};

/// Largest number of points a sweep accepts: beyond it a sweep is a mistake, not a request.
pub const MAX_POINTS: u64 = 100_000_000;

/// A rejected sweep range.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RangeError {
    /// Start above end.
    #[error(
        "invalid range: {from_flag} = {from} is above {to_flag} = {to}; the start must not exceed the end"
    )]
    Reversed {
        /// Flag naming the start.
        from_flag: &'static str,
        /// Start value.
        from: f64,
        /// Flag naming the end.
        to_flag: &'static str,
        /// End value.
        to: f64,
    },
    /// Too few or too many points.
    #[error("invalid --points = {0}: must be an integer in [2, {MAX_POINTS}]")]
    Points(u64),
    /// A bound outside the allowed values.
    #[error("invalid {flag} = {value}: {allowed}")]
    Bound {
        /// The flag.
        flag: &'static str,
        /// The value.
        value: f64,
        /// What is allowed.
        allowed: &'static str,
    },
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
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Samples {
    from: f64,
    to: f64,
    points: u64,
    spacing: Spacing,
}

impl Samples {
    /// Checks the range; `flags` name the two bounds in messages (e.g. `("--from", "--to")`).
    pub fn new(
        from: f64,
        to: f64,
        points: u64,
        spacing: Spacing,
        flags: (&'static str, &'static str),
    ) -> Result<Self, RangeError> {
        let allowed = match spacing {
            Spacing::Linear => "must be a finite number",
            Spacing::Logarithmic => "must be > 0 and finite (logarithmic spacing)",
        };
        for (flag, value) in [(flags.0, from), (flags.1, to)] {
            if !value.is_finite() || (spacing == Spacing::Logarithmic && value <= 0.0) {
                return Err(RangeError::Bound {
                    flag,
                    value,
                    allowed,
                });
            }
        }
        if from > to {
            return Err(RangeError::Reversed {
                from_flag: flags.0,
                from,
                to_flag: flags.1,
                to,
            });
        }
        if !(2..=MAX_POINTS).contains(&points) {
            return Err(RangeError::Points(points));
        }
        Ok(Samples {
            from,
            to,
            points,
            spacing,
        })
    }

    /// Number of samples.
    pub fn len(&self) -> u64 {
        self.points
    }

    /// Always false: a valid sampling has at least two points.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The i-th sample value (0-based); the last one is exactly `to`.
    pub fn value(&self, i: u64) -> f64 {
        if i + 1 >= self.points {
            return self.to;
        }
        let t = i as f64 / (self.points - 1) as f64;
        match self.spacing {
            Spacing::Linear => self.from + t * (self.to - self.from),
            Spacing::Logarithmic => self.from * (self.to / self.from).powf(t),
        }
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
    /// End of the microslip zone X (mm); L without macroslip.
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: Regime,
    /// Regularized regime.
    pub regime_regularized: Regime,
}

/// The twin beams at one force.
pub fn beam_point(beams: &TwinBeams, force: TipForce) -> BeamPoint {
    let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
    BeamPoint {
        force: force.newtons(),
        w_coulomb: coulomb.tip_deflection(),
        w_regularized: regularized.tip_deflection(),
        micro_end: regularized.micro_zone_end(),
        regime_coulomb: coulomb.regime(),
        regime_regularized: regularized.regime(),
    }
}

/// The twin beams over a range of forces. Forces come from a [`Samples`] whose bounds the caller
/// checked to be >= 0 (see [`force_samples`]); a sample that still fails [`TipForce::new`] is skipped.
pub fn beam_force_sweep(beams: TwinBeams, forces: Samples) -> impl Iterator<Item = BeamPoint> {
    forces
        .values()
        .filter_map(move |f| TipForce::new(f).ok())
        .map(move |f| beam_point(&beams, f))
}

/// A force sampling for [`beam_force_sweep`]: both bounds must be valid tip forces (>= 0, finite).
pub fn force_samples(from: f64, to: f64, points: u64) -> Result<Samples, RangeError> {
    for (flag, value) in [("--from", from), ("--to", to)] {
        if TipForce::new(value).is_err() {
            return Err(RangeError::Bound {
                flag,
                value,
                allowed: "must be >= 0 and finite (N)",
            });
        }
    }
    Samples::new(from, to, points, Spacing::Linear, ("--from", "--to"))
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
    }
}

/// A K_T sampling for [`plate_kt_sweep`]: both bounds must be valid stiffnesses (> 0, finite).
pub fn stiffness_samples(
    from: f64,
    to: f64,
    points: u64,
    spacing: Spacing,
) -> Result<Samples, RangeError> {
    for (flag, value) in [("--kt-from", from), ("--kt-to", to)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(RangeError::Bound {
                flag,
                value,
                allowed: "must be > 0 and finite (MPa/mm)",
            });
        }
    }
    Samples::new(from, to, points, spacing, ("--kt-from", "--kt-to"))
}

/// The plate over a range of K_T (other parameters fixed). Values between two valid stiffnesses are
/// valid, so no sample is lost in practice; one that failed validation would be skipped.
pub fn plate_kt_sweep(
    plate: SqueezedPlate,
    stiffnesses: Samples,
) -> impl Iterator<Item = PlatePoint> {
    stiffnesses
        .values()
        .filter_map(move |kt| plate.with_tangential_stiffness(kt).ok())
        .map(|p| plate_point(&p))
}

/// A sampled curve: (x, y) points in order of x.
pub type Series = Vec<(f64, f64)>;

/// Tip deflection w(L) (mm) against F (N): (Coulomb, regularized).
pub fn beam_deflection_vs_force(beams: &TwinBeams, forces: Samples) -> (Series, Series) {
    beam_force_sweep(*beams, forces)
        .map(|p| ((p.force, p.w_coulomb), (p.force, p.w_regularized)))
        .unzip()
}

/// End of the microslip zone X (mm) against F (N), regularized law (X = L below F_1).
pub fn beam_slip_boundary_vs_force(beams: &TwinBeams, forces: Samples) -> Series {
    beam_force_sweep(*beams, forces)
        .map(|p| (p.force, p.micro_end))
        .collect()
}

/// Interface shear tau (MPa) along the beams at one force: (Coulomb, regularized).
pub fn beam_shear_along(
    beams: &TwinBeams,
    force: TipForce,
    positions: Samples,
) -> (Series, Series) {
    let (coulomb, regularized) = (beams.coulomb(force), beams.regularized(force));
    positions
        .values()
        .map(|x| {
            (
                (x, coulomb.shear_stress(x)),
                (x, regularized.shear_stress(x)),
            )
        })
        .unzip()
}

/// End displacement u(L) (mm) against K_T (MPa/mm): (Coulomb, regularized).
pub fn plate_end_displacement_vs_stiffness(
    plate: &SqueezedPlate,
    stiffnesses: Samples,
) -> (Series, Series) {
    plate_kt_sweep(*plate, stiffnesses)
        .map(|p| ((p.kt, p.u_coulomb), (p.kt, p.u_regularized)))
        .unzip()
}

/// End of the microslip zone X_r (mm) against mu, at the plate's K_T.
pub fn plate_slip_boundary_vs_friction(plate: &SqueezedPlate, frictions: Samples) -> Series {
    frictions
        .values()
        .filter_map(|mu| {
            SqueezedPlate::new(crate::PlateParams {
                friction: mu,
                ..plate.params()
            })
            .ok()
        })
        .map(|p| (p.params().friction, p.regularized().micro_zone_end()))
        .collect()
}

/// Contact pressure ratio P_r / P along the half-plate.
pub fn plate_contact_pressure_along(plate: &SqueezedPlate, positions: Samples) -> Series {
    let pressure = plate.contact_pressure();
    positions.values().map(|x| (x, pressure.ratio(x))).collect()
}

/// A K_T to compare: where it comes from and its value (None: that source has no value).
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessCandidate {
    /// Source: the preset, the normal stiffness, or a code.
    pub source: String,
    /// The stiffness (MPa/mm), when the source gives one.
    pub kt: Option<f64>,
    /// How it was obtained, and how sure we are.
    pub basis: String,
}

/// The K_T values worth comparing for one interface: the current one, those from a normal contact
/// stiffness K_N (paper eq. 4 and the measured K_T/K_N range), and those FE codes assume by default
/// for contact elements of length `element` (mm).
pub fn stiffness_candidates(
    current: f64,
    mu: f64,
    pressure: f64,
    modulus: f64,
    element: f64,
    normal: Option<(f64, f64)>,
) -> Vec<StiffnessCandidate> {
    use crate::model::code_defaults::{CODE_DEFAULTS, MEASURED_RATIO_RANGE};
    use crate::model::stiffness::tangential_from_normal;
    let mut rows = vec![StiffnessCandidate {
        source: "current".into(),
        kt: Some(current),
        basis: "the model's K_T".into(),
    }];
    if let Some((kn, nu)) = normal {
        let (low, high) = MEASURED_RATIO_RANGE;
        rows.push(StiffnessCandidate {
            source: "K_N x 0.5".into(),
            kt: Some(low * kn),
            basis: "measured K_T/K_N, low end".into(),
        });
        rows.push(StiffnessCandidate {
            source: "eq. 4".into(),
            kt: tangential_from_normal(kn, nu).ok(),
            basis: format!("pi (1 - nu) / (2 (2 - nu)) K_N, nu = {nu}"),
        });
        rows.push(StiffnessCandidate {
            source: "K_N x 0.7".into(),
            kt: Some(high * kn),
            basis: "measured K_T/K_N, high end".into(),
        });
    }
    for code in CODE_DEFAULTS {
        rows.push(StiffnessCandidate {
            source: code.code.into(),
            kt: code.implied_stiffness(mu, pressure, modulus, element),
            basis: format!("{} ({})", code.description, code.confirmation.label()),
        });
    }
    rows
}

/// What a K_T does to the twin beams at one force: (F_1 (N), X (mm), w(L) (mm), regime).
pub fn beam_answer(beams: &TwinBeams, force: TipForce, kt: f64) -> Option<(f64, f64, f64, Regime)> {
    let beams = beams.with_tangential_stiffness(kt).ok()?;
    let state = beams.regularized(force);
    Some((
        beams.first_macroslip_force(),
        state.micro_zone_end(),
        state.tip_deflection(),
        state.regime(),
    ))
}

/// What a K_T does to the plate: (u(L) (mm), X_r (mm), regime).
pub fn plate_answer(plate: &SqueezedPlate, kt: f64) -> Option<(f64, f64, Regime)> {
    let state = plate.with_tangential_stiffness(kt).ok()?.regularized();
    Some((
        state.end_displacement(),
        state.micro_zone_end(),
        state.regime(),
    ))
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
    use crate::model::cycle::{Cycle, Law};
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

/// The twin beams cycled over a range of amplitudes (validated like tip forces).
pub fn cycle_sweep(beams: TwinBeams, amplitudes: Samples) -> impl Iterator<Item = CyclePoint> {
    amplitudes
        .values()
        .filter_map(move |f| TipForce::new(f).ok())
        .map(move |f| cycle_point(&beams, f))
}

/// Dissipation per cycle D (N mm) against F_a (N): (Coulomb, regularized).
pub fn dissipation_vs_amplitude(beams: &TwinBeams, amplitudes: Samples) -> (Series, Series) {
    cycle_sweep(*beams, amplitudes)
        .map(|p| ((p.amplitude, p.d_coulomb), (p.amplitude, p.d_regularized)))
        .unzip()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

    #[test]
    fn samples_hit_both_ends_exactly() {
        let s = Samples::new(0.1, 0.7, 7, Spacing::Linear, ("a", "b")).unwrap();
        let v: Vec<f64> = s.values().collect();
        assert_eq!(v.len(), 7);
        assert_eq!((v[0], v[6]), (0.1, 0.7));
        assert!((v[3] - 0.4).abs() < 1e-15);
        let s = Samples::new(1.0, 1e6, 7, Spacing::Logarithmic, ("a", "b")).unwrap();
        let v: Vec<f64> = s.values().collect();
        assert_eq!((v[0], v[6]), (1.0, 1e6));
        assert!((v[3] - 1e3).abs() < 1e-9);
    }

    #[test]
    fn bad_ranges_are_refused_with_their_flags() {
        let err = force_samples(10.0, 5.0, 3).unwrap_err().to_string();
        assert_eq!(
            err,
            "invalid range: --from = 10 is above --to = 5; the start must not exceed the end"
        );
        assert_eq!(
            force_samples(0.0, 5.0, 1).unwrap_err(),
            RangeError::Points(1)
        );
        assert!(force_samples(0.0, 5.0, MAX_POINTS + 1).is_err());
        assert!(
            force_samples(-1.0, 5.0, 3)
                .unwrap_err()
                .to_string()
                .starts_with("invalid --from = -1")
        );
        let err = stiffness_samples(0.0, 5.0, 3, Spacing::Logarithmic)
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "invalid --kt-from = 0: must be > 0 and finite (MPa/mm)"
        );
    }

    #[test]
    fn sweeps_yield_one_row_per_sample() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let rows: Vec<BeamPoint> =
            beam_force_sweep(beams, force_samples(0.0, 300.0, 31).unwrap()).collect();
        assert_eq!(rows.len(), 31);
        assert!((rows[10].force - 100.0).abs() < 1e-12);
        assert_eq!(rows[10].regime_regularized, Regime::MicroslipMacroslip);
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let samples = stiffness_samples(1.0, 1e7, 8, Spacing::Logarithmic).unwrap();
        let rows: Vec<PlatePoint> = plate_kt_sweep(plate, samples).collect();
        assert_eq!(rows.len(), 8);
        assert_eq!(rows[7].kt, 1e7);
    }
}
