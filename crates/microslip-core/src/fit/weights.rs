//! What the fit assumes about the scatter of the measured responses (w, Delta), and so how it weighs them.
//!
//! Weighted least squares minimizes sum ((model_i - w_i) / sigma_i)^2. The standard errors are
//! right only when the sigma_i are right, up to one common factor that the residuals estimate
//! (docs/theory.md, "Weighted least squares"):
//!
//! - [`Weights::Absolute`]: the same sigma at every point, estimated from the residuals. Right for
//!   a gauge whose error does not grow with the reading (resolution, electrical noise).
//! - [`Weights::Relative`]: sigma proportional to |w|, the factor estimated from the residuals.
//!   Right for errors that scale with the reading (gain, calibration, a displacement read off a
//!   strain); the default for measured curves, see docs/guide.md, "Fit measurements", for the measurement.
//! - [`Weights::Sigma`]: each point's sigma given in mm and taken as known: no factor is estimated,
//!   and the reduced chi-square says whether the given sigmas fit the residuals.

use super::{FitError, Measurement};

/// A reading below this fraction of the largest |w| is weighed as if it were this large under
/// [`Weights::Relative`]: w = 0 (the unloaded point at F = 0) would otherwise get infinite weight,
/// and a reading within 0.1 % of the full range is at the resolution of any gauge that measures
/// the largest one, where the scatter no longer shrinks with the reading. At F = 0 the model is 0
/// for every mu and K_T, so such a point changes neither the fit nor its errors.
pub const RELATIVE_FLOOR: f64 = 1e-3;

/// How the measured responses are weighted (see the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Weights<'a> {
    /// Every point alike: the same unknown sigma (mm) everywhere.
    Absolute,
    /// sigma_i = s max(|w_i|, [`RELATIVE_FLOOR`] max |w|), with s unknown.
    #[default]
    Relative,
    /// sigma_i (mm) known, one per measurement (the `sigma_mm` column of a data file).
    Sigma(&'a [f64]),
}

/// The scatter the fit assumed, with what the residuals say about it: None when no degree of
/// freedom is left (as many loaded points as parameters), where the residuals are 0 by
/// construction and say nothing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scatter {
    /// [`Weights::Absolute`]: the sigma of every w estimated from the residuals (mm).
    Absolute {
        /// sqrt(sum r_i^2 / (n - p)) (mm).
        sigma: Option<f64>,
    },
    /// [`Weights::Relative`]: the sigma of w as a fraction of w, estimated from the residuals.
    Relative {
        /// sqrt(sum (r_i / w_i)^2 / (n - p)) (-).
        fraction: Option<f64>,
    },
    /// [`Weights::Sigma`]: the given sigmas taken as known; about 1 when they fit the residuals.
    Known {
        /// sum (r_i / sigma_i)^2 / (n - p) (-).
        reduced_chi_square: Option<f64>,
    },
}

impl Weights<'_> {
    /// The sigma of each measurement in the unit the weights assume (1 for the unknown common
    /// factor of the absolute and relative modes).
    ///
    /// # Errors
    /// [`FitError::Sigma`] when given sigmas are not one positive finite value per measurement.
    pub(super) fn sigmas(&self, data: &[Measurement]) -> Result<Vec<f64>, FitError> {
        match *self {
            Weights::Absolute => Ok(vec![1.0; data.len()]),
            Weights::Relative => {
                let largest = data.iter().map(|m| m.response.abs()).fold(0.0, f64::max);
                // All zero: nothing to scale by, every point alike.
                let floor = if largest > 0.0 {
                    RELATIVE_FLOOR * largest
                } else {
                    1.0
                };
                Ok(data.iter().map(|m| m.response.abs().max(floor)).collect())
            }
            Weights::Sigma(sigma) => {
                if sigma.len() != data.len() {
                    return Err(FitError::Sigma(format!(
                        "{} standard deviations for {} measurements",
                        sigma.len(),
                        data.len()
                    )));
                }
                match sigma.iter().position(|s| !(s.is_finite() && *s > 0.0)) {
                    Some(i) => Err(FitError::Sigma(format!(
                        "the standard deviation of measurement {} is {}; it must be finite and > 0",
                        i + 1,
                        sigma[i]
                    ))),
                    None => Ok(sigma.to_vec()),
                }
            }
        }
    }

    /// Whether the sigmas are known (no common factor to estimate from the residuals).
    pub(super) fn known(&self) -> bool {
        matches!(self, Weights::Sigma(_))
    }

    /// What the residuals say about the scatter, from the reduced chi-square of the weighted fit
    /// (None without a degree of freedom).
    pub(super) fn scatter(&self, reduced_chi_square: Option<f64>) -> Scatter {
        match self {
            Weights::Absolute => Scatter::Absolute {
                sigma: reduced_chi_square.map(f64::sqrt),
            },
            Weights::Relative => Scatter::Relative {
                fraction: reduced_chi_square.map(f64::sqrt),
            },
            Weights::Sigma(_) => Scatter::Known { reduced_chi_square },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(responses: &[f64]) -> Vec<Measurement> {
        responses
            .iter()
            .enumerate()
            .map(|(i, &response)| Measurement {
                force: i as f64,
                response,
            })
            .collect()
    }

    #[test]
    fn relative_sigmas_follow_the_reading_down_to_the_floor() {
        let sigma = Weights::Relative
            .sigmas(&data(&[0.0, -1e-5, 0.02, 0.5]))
            .unwrap();
        assert_eq!(sigma, [5e-4, 5e-4, 0.02, 0.5]);
        assert_eq!(
            Weights::Relative.sigmas(&data(&[0.0, 0.0])).unwrap(),
            [1.0, 1.0]
        );
        assert_eq!(
            Weights::Absolute.sigmas(&data(&[0.0, 3.0])).unwrap(),
            [1.0, 1.0]
        );
    }

    #[test]
    fn given_sigmas_must_be_one_positive_value_per_point() {
        let points = data(&[0.1, 0.2]);
        assert_eq!(
            Weights::Sigma(&[1e-3, 2e-3]).sigmas(&points).unwrap(),
            [1e-3, 2e-3]
        );
        assert_eq!(
            Weights::Sigma(&[1e-3])
                .sigmas(&points)
                .unwrap_err()
                .to_string(),
            "invalid sigma: 1 standard deviations for 2 measurements"
        );
        assert_eq!(
            Weights::Sigma(&[1e-3, 0.0])
                .sigmas(&points)
                .unwrap_err()
                .to_string(),
            "invalid sigma: the standard deviation of measurement 2 is 0; it must be finite and > 0"
        );
    }
}
