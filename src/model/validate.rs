//! Checked construction of model inputs: the only place that decides what a valid number is.
//!
//! Every error names the field, the rejected value and the allowed range, so that the CLI, the TUI and
//! the preset loader can show it as is.

use thiserror::Error;

/// A rejected input value.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("invalid {field} = {value}: {allowed}")]
pub struct ParamError {
    /// Field name as the user writes it (preset key), e.g. `KT`.
    pub field: &'static str,
    /// The rejected value (may be NaN or infinite).
    pub value: f64,
    /// Human-readable allowed range, with units.
    pub allowed: &'static str,
}

/// Passes `value` through when it is finite and `in_range`, otherwise builds the error.
fn check(
    field: &'static str,
    value: f64,
    allowed: &'static str,
    in_range: bool,
) -> Result<f64, ParamError> {
    if value.is_finite() && in_range {
        Ok(value)
    } else {
        Err(ParamError {
            field,
            value,
            allowed,
        })
    }
}

/// Accepts finite values strictly above zero (lengths, moduli, pressures, friction, stiffness).
pub fn positive(field: &'static str, value: f64, allowed: &'static str) -> Result<f64, ParamError> {
    check(field, value, allowed, value > 0.0)
}

/// Accepts finite values at or above zero (loads).
pub fn non_negative(
    field: &'static str,
    value: f64,
    allowed: &'static str,
) -> Result<f64, ParamError> {
    check(field, value, allowed, value >= 0.0)
}

/// Accepts a Poisson ratio of a stable isotropic solid that does not expand under compression:
/// 0 <= nu < 0.5 (0.5 is incompressible and makes the plane-strain compliance singular).
pub fn poisson_ratio(field: &'static str, value: f64) -> Result<f64, ParamError> {
    check(
        field,
        value,
        "must be in [0, 0.5) (dimensionless)",
        (0.0..0.5).contains(&value),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_field_value_and_range() {
        let err = positive("L", -3.0, "must be > 0 and finite (mm)").unwrap_err();
        assert_eq!(
            err.to_string(),
            "invalid L = -3: must be > 0 and finite (mm)"
        );
        assert!(positive("E", f64::NAN, "x").is_err());
        assert!(positive("E", f64::INFINITY, "x").is_err());
        assert!(positive("E", 0.0, "x").is_err());
        assert_eq!(non_negative("F", 0.0, "x"), Ok(0.0));
        assert!(non_negative("F", -1e-300, "x").is_err());
        assert_eq!(poisson_ratio("nu", 0.0), Ok(0.0));
        assert!(poisson_ratio("nu", 0.5).is_err());
        assert!(poisson_ratio("nu", -0.1).is_err());
        assert_eq!(
            poisson_ratio("nu", 0.7).unwrap_err().to_string(),
            "invalid nu = 0.7: must be in [0, 0.5) (dimensionless)"
        );
    }
}
