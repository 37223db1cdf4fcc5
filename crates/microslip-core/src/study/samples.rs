//! Sampling a range: the one place that says which values a sweep, a family or a chart visits
//! ([`Samples`]), the errors a range is refused with ([`RangeError`]) and the curve a sampling
//! gives ([`Series`]). Every study loops over a [`Samples`], so a value on screen and the same
//! value in a CSV file come from the same sample.

use thiserror::Error;

use crate::kernel::params::Compact;
use crate::problems::Param;

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
/// use microslip_core::prelude::*;
/// use microslip_core::study::curves::load_samples;
/// use microslip_core::study::load::force_sweep;
/// let beams = TwinBeams::new(TwinBeamsParams::PAPER)?;
/// let forces = load_samples::<TwinBeamsProblem>(0.0, 300.0, 4)?; // 0, 100, 200, 300 N
/// let rows: Vec<_> = force_sweep::<TwinBeamsProblem>(beams, forces)?.collect();
/// assert_eq!(rows[1].force, 100.0);
/// assert_eq!(rows[1].regime_regularized, Regime::MICROSLIP_MACROSLIP);
/// assert!(load_samples::<TwinBeamsProblem>(0.0, -1.0, 4).is_err()); // -1 N is not a tip force
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

/// A sampled curve: (x, y) points in order of x.
pub type Series = Vec<(f64, f64)>;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::twin_beams::TwinBeamsProblem;
    use crate::problems::{Param, PlateParam};
    use crate::study::curves::load_samples;

    fn force_samples(from: f64, to: f64, points: u64) -> Result<Samples, RangeError> {
        load_samples::<TwinBeamsProblem>(from, to, points)
    }

    fn stiffness_samples(
        from: f64,
        to: f64,
        points: u64,
        spacing: Spacing,
    ) -> Result<Samples, RangeError> {
        let stiffness = Param::Plate(PlateParam::Stiffness);
        Samples::of_param(stiffness, from, to, points, spacing)
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
}
