//! The twin beams' fit: w(L) against the tip force, the paper's identification (its section
//! 2.1.3).

use super::{FitError, FitResult, Measurement, Progress, Structure, Weights, fit_weighted};
use crate::{TwinBeams, TwinBeamsParams};

/// Fits mu and K_T (each unless fixed) of twin beams with the geometry, E and P of `structure` to
/// a w(L) vs F curve, every point weighed alike ([`Weights::Absolute`]). The structure's own mu and
/// K_T are not used as a start: the grid is.
///
/// Equal weights are right for a curve whose error does not grow with w, such as a model's
/// mismatch to another model; measured curves usually scatter in proportion to w: fit them with
/// [`fit_twin_beams_weighted`] and [`Weights::default`] (relative), or with their own sigmas.
///
/// # Errors
///
/// [`FitError::Param`] when the structure or a fixed value is invalid (the model's own checks), and
/// [`FitError::TooFewPoints`] when there are not more measurements than free parameters.
///
/// # Examples
///
/// A curve measured on beams with mu = 0.4 and K_T = 200 MPa/mm, well past F_1, gives both back:
///
/// ```
/// use microslip_core::fit::{Measurement, Status, fit_twin_beams};
/// use microslip_core::{TipForce, TwinBeams, TwinBeamsParams};
///
/// let truth = TwinBeams::new(TwinBeamsParams {
///     friction: 0.4,
///     tangential_stiffness: 200.0,
///     ..TwinBeamsParams::PAPER
/// })?;
/// let data: Vec<Measurement> = (1..=30)
///     .map(|i| {
///         let force = 10.0 * f64::from(i);
///         let w = truth.regularized(TipForce::new(force)?).tip_deflection();
///         Ok(Measurement { force, response: w })
///     })
///     .collect::<Result<_, microslip_core::ParamError>>()?;
///
/// // Only the geometry, E and P of the structure are used.
/// let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None)?;
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// assert!((fit.kt.value - 200.0).abs() < 1e-3);
/// assert_eq!(fit.mu.status, Status::Identified);
/// assert!(fit.beyond_first_macroslip > 2);
///
/// // Holding K_T fixed fits mu alone.
/// let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, Some(200.0))?;
/// assert_eq!(fit.kt.status, Status::Fixed);
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_twin_beams(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
) -> Result<FitResult, FitError> {
    fit_twin_beams_with_progress(structure, data, fixed_mu, fixed_kt, &mut |_| {})
}

/// [`fit_twin_beams`], telling `progress` how far it got (see [`Progress`]); the result is the same.
/// [`fit_twin_beams_weighted`] with [`Weights::Absolute`].
///
/// A million measurements take a few seconds: the grid search and a first refinement run on an
/// evenly spread subsample of a few thousand rows, and the refinement finishes on all of them,
/// where it typically needs one or two steps.
///
/// # Errors
///
/// As [`fit_twin_beams`].
///
/// # Examples
///
/// ```
/// use microslip_core::fit::{Measurement, Progress, fit_twin_beams_with_progress};
/// use microslip_core::TwinBeamsParams;
///
/// let data: Vec<Measurement> = (1..=20)
///     .map(|i| Measurement { force: 10.0 * f64::from(i), response: 4e-4 * f64::from(i) })
///     .collect();
/// let mut grid_nodes = 0;
/// let fit = fit_twin_beams_with_progress(TwinBeamsParams::PAPER, &data, None, None, &mut |p| {
///     if let Progress::Bracket { done, .. } = p {
///         grid_nodes = done;
///     }
/// })?;
/// assert!(grid_nodes > 100);
/// assert_eq!(fit.points, 20);
/// # Ok::<(), microslip_core::fit::FitError>(())
/// ```
pub fn fit_twin_beams_with_progress(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    fit_twin_beams_weighted(
        structure,
        data,
        fixed_mu,
        fixed_kt,
        Weights::Absolute,
        progress,
    )
}

/// [`fit_twin_beams_with_progress`] with the measurements weighed by `weights`: what their scatter
/// is assumed to be, which the standard errors and the correlation depend on (see [`Weights`]).
///
/// # Errors
///
/// As [`fit_twin_beams`], and [`FitError::Sigma`] when `weights` gives sigmas that are not one
/// positive finite value per measurement.
///
/// # Examples
///
/// A curve with 1 % scatter: relative weights state errors that match the scatter of refits (the
/// `fit` test `stated_errors_match_the_scatter_of_repeated_fits`), and the correlation of the two
/// estimates.
///
/// ```
/// use microslip_core::fit::{Measurement, Scatter, Weights, fit_twin_beams_weighted};
/// use microslip_core::{TipForce, TwinBeams, TwinBeamsParams};
///
/// let truth = TwinBeams::new(TwinBeamsParams {
///     friction: 0.22,
///     tangential_stiffness: 300.0,
///     ..TwinBeamsParams::PAPER
/// })?;
/// // Alternately 1 % high and 1 % low.
/// let data: Vec<Measurement> = (0..=60)
///     .map(|i| {
///         let force = 5.0 * f64::from(i);
///         let w = truth.regularized(TipForce::new(force)?).tip_deflection();
///         let deflection = w * if i % 2 == 0 { 1.01 } else { 0.99 };
///         Ok(Measurement { force, response: deflection })
///     })
///     .collect::<Result<_, microslip_core::ParamError>>()?;
/// let fit = fit_twin_beams_weighted(
///     TwinBeamsParams::PAPER, &data, None, None, Weights::Relative, &mut |_| {},
/// )?;
/// let Scatter::Relative { fraction: Some(fraction) } = fit.scatter else { unreachable!() };
/// assert!((fraction - 0.01).abs() < 0.002);
/// assert!((fit.kt.value - 300.0).abs() < 3.0 * fit.kt.std_error.unwrap());
/// assert!(fit.correlation.unwrap().abs() < 1.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_twin_beams_weighted(
    structure: TwinBeamsParams,
    data: &[Measurement],
    fixed_mu: Option<f64>,
    fixed_kt: Option<f64>,
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    fit_weighted(
        Structure::Beam(structure),
        data,
        (fixed_mu, fixed_kt),
        weights,
        progress,
    )
}

/// Checks the beams `p` at the trial (`mu`, `kt`) (fixed values, else the beams' own) through
/// their own constructor.
///
/// # Errors
/// [`FitError::Param`] when the beams refuse them.
pub(super) fn check(p: TwinBeamsParams, mu: f64, kt: f64) -> Result<(), FitError> {
    TwinBeams::new(TwinBeamsParams {
        friction: mu,
        tangential_stiffness: kt,
        ..p
    })?;
    Ok(())
}
