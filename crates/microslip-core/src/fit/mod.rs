//! Identification of mu and K_T from a measured load-response curve u(F) of any fittable problem
//! ([`Fittable`]: the twin beams' w(L), the lap joint's Delta), written once.
//!
//! The paper's practical point (its section 2.1.3): below F_1 the whole interface is in microslip and
//! u depends on K_T but not on mu; past F_1 the slope changes (towards the Coulomb slip slope, which
//! carries mu). So K_T comes from the curve's stiffness, mu from where and how the slope changes.
//!
//! Method: nonlinear least squares on the closed form, in log-parameters (both must stay positive and
//! span decades). A coarse grid over both (the bracket) gives a start that does not depend on the
//! user's guess, then Levenberg-Marquardt refines it. The residuals are weighted by what the
//! scatter of each measurement is assumed to be ([`Weights`]: absolute, relative to u, or given per
//! point); standard errors and the mu-K_T correlation come from the Jacobian at the optimum
//! ((J^T W J)^-1, times the reduced chi-square unless the sigmas are known; delta method back to
//! linear units; derived in docs/theory.md).
//!
//! Cost: the model takes well under a microsecond per point, and a long curve (a million rows) is
//! fitted in seconds. Above 1024 rows the grid and the first refinements run on evenly spread
//! subsamples (32 times larger at each level), so the full data are only visited by the last two
//! or three Gauss-Newton steps; the normal equations are summed point by point, never storing the
//! Jacobian. Up to 1024 rows the fit is the same computation as ever.
//! [`fit_weighted`] reports how far it got, for callers that show progress. Identifiability is
//! judged from the physics first (no data beyond F_1: mu cannot be seen) and from the standard
//! errors second.
//!
//! A structure that carries a bounded force (the lap joint carries none beyond F_gross = 2 b mu
//! P L, docs/theory.md (L11) and section 3b) is searched only where mu carries every measured
//! force ([`Fittable::force_per_friction`]).
//!
//! Results are data only: the reason behind each verdict is an [`Evidence`] carrying its numbers;
//! the words for people are written by the `report` module.

pub mod measurement;
pub mod weights;

mod evidence;
mod least_squares;
mod progress;
mod small;
mod structure;

use thiserror::Error;

pub use evidence::{Estimate, Evidence, FitResult, Status};
pub use measurement::{MIN_ROWS, Measured, Measurement};
pub use progress::{Pass, Progress};
pub use structure::Structure;
pub use weights::{Scatter, Weights};

use crate::kernel::family;
use crate::kernel::params::ParamError;
use crate::problems::fittable::Fittable;
use evidence::summarize;
use least_squares::{LADDER, Problem, SUBSAMPLE, bracket, refine, spread};

/// Search range of mu (-) and K_T (MPa/mm): wide enough for any real interface.
const MU_RANGE: (f64, f64) = (1e-3, 5.0);
const KT_RANGE: (f64, f64) = (1e-3, 1e9);

/// Why a fit could not run.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The structure or a fixed value is invalid.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// Not enough points for the free parameters.
    #[error("{points} measurements cannot determine {free} parameters; at least {} are needed", free + 1)]
    TooFewPoints {
        /// Measurements given.
        points: usize,
        /// Free parameters.
        free: usize,
    },
    /// Given standard deviations that cannot weigh the measurements.
    #[error("invalid sigma: {0}")]
    Sigma(String),
    /// Every measured response is 0: no displacement under load, which no finite K_T gives, so
    /// there is nothing to fit (a column of zeros is a file or unit mistake, not a measurement).
    #[error(
        "every {column} is 0 mm: nothing to fit (a curve without displacement under load has no \
         finite K_T and shows no mu; check the column and its unit)"
    )]
    NothingToFit {
        /// The response column (`w_mm`, `Delta_mm`).
        column: &'static str,
    },
    /// The best fit explains none of the weighted variation of the measured response about its
    /// mean (R^2 <= [`LEAST_EXPLAINED`]: the mean fits it as well): the curve is not one the
    /// problem's structure gives (every one grows with its load,
    /// [`LoadDriven`](crate::problems::load_driven::LoadDriven)), whatever mu and K_T: a falling
    /// curve, another quantity's column, a unit mistake.
    #[error(
        "the curve is not a {fitted}'s: the best fit (mu = {mu}, K_T = {kt} MPa/mm) explains none \
         of the variation of {response} against {load} (R^2 = {r_squared:.3}: their mean fits \
         them as well), while a {fitted}'s {response} grows with {load}; check the columns, their \
         units and the problem"
    )]
    NotThisModel {
        /// What is fitted ([`Fittable::FITTED`]).
        fitted: &'static str,
        /// The response column.
        response: &'static str,
        /// The load column.
        load: &'static str,
        /// The best fit's mu (-).
        mu: f64,
        /// The best fit's K_T (MPa/mm).
        kt: f64,
        /// 1 - SSE / SST of the weighted residuals (-).
        r_squared: f64,
    },
    /// (A structure that carries a bounded force: the lap joint, the cylinder) A measured force
    /// beyond the bound of every mu searched: no state of the structure carries it.
    #[error(
        "invalid {column} = {force}: beyond {bound} (for every mu up to {}, the bound is at most \
         {largest} {unit}), so no mu fits it",
        MU_RANGE.1
    )]
    BeyondGrossSlip {
        /// The largest measured force (in the load's unit).
        force: f64,
        /// The bound at the largest mu searched (in the load's unit).
        largest: f64,
        /// The load column ([`Fittable::LOAD_COLUMN`]: `F_N`, `Q_N_per_mm`).
        column: &'static str,
        /// The load's unit (`N`, `N/mm`).
        unit: &'static str,
        /// The bound in the problem's words (`F_gross = 2 b mu P L: the joint slides through
        /// beyond it`).
        bound: String,
    },
}

/// Fits mu and K_T (each unless `fixed`, (mu, K_T)) of the typed `structure` of the fittable
/// problem `P` to its measured load-response curve: [`fit_weighted`] of
/// [`Structure::typed`]. Only the structure's geometry, moduli and pressure are used; its own mu
/// and K_T are not a start (the grid is), only what a fixed value replaces.
///
/// Equal weights ([`Weights::Absolute`]) are right for a curve whose error does not grow with u,
/// such as a model's mismatch to another model; measured curves usually scatter in proportion to
/// u: fit them with [`Weights::default`] (relative), or with their own sigmas.
///
/// # Errors
/// As [`fit_weighted`].
///
/// # Examples
///
/// A curve measured on beams with mu = 0.4 and K_T = 200 MPa/mm, well past F_1, gives both back:
///
/// ```
/// use microslip_core::fit::{Measurement, Status, Weights, fit_curve};
/// use microslip_core::prelude::*;
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
///     .collect::<Result<_, ParamError>>()?;
///
/// // Only the geometry, E and P of the structure are used.
/// let paper = TwinBeams::new(TwinBeamsParams::PAPER)?;
/// let fit = fit_curve::<TwinBeamsProblem>(&paper, &data, (None, None), Weights::Absolute, &mut |_| {})?;
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// assert!((fit.kt.value - 200.0).abs() < 1e-3);
/// assert_eq!(fit.mu.status, Status::Identified);
/// assert!(fit.beyond_first_macroslip > 2);
///
/// // Holding K_T fixed fits mu alone.
/// let fit = fit_curve::<TwinBeamsProblem>(&paper, &data, (None, Some(200.0)), Weights::Absolute, &mut |_| {})?;
/// assert_eq!(fit.kt.status, Status::Fixed);
/// assert!((fit.mu.value - 0.4).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fit_curve<P: Fittable>(
    structure: &P::Structure,
    data: &[Measurement],
    fixed: (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    fit_weighted(
        Structure::typed::<P>(structure),
        data,
        fixed,
        weights,
        progress,
    )
}

/// The mu range to search for `structure` with the trial (`mu`, `kt`) (fixed values, else the
/// structure's own), checked through its own constructor: [`MU_RANGE`], from above the smallest
/// mu that carries every measured force where the force it carries is bounded (a fit on that
/// bound is reported as at the search bound).
///
/// # Errors
/// The structure at (`mu`, `kt`) is invalid; a `fixed_mu` does not carry the largest measured
/// force; or no mu searched carries it ([`FitError::BeyondGrossSlip`]).
fn mu_range(
    structure: &Structure,
    (mu, kt): (f64, f64),
    fixed_mu: bool,
    data: &[Measurement],
) -> Result<(f64, f64), FitError> {
    let Some(at) = structure.checked_at(mu, kt) else {
        return Ok(MU_RANGE);
    };
    let at = at?;
    let Some(per_mu) = structure.force_per_friction() else {
        return Ok(MU_RANGE);
    };
    let Some(largest) = data.iter().map(|m| m.force).reduce(f64::max) else {
        return Ok(MU_RANGE);
    };
    // A fixed mu must carry every measured force.
    if fixed_mu {
        at.carries(largest)?;
    }
    let least = largest / per_mu * (1.0 + 1e-9);
    if least > MU_RANGE.1 {
        return Err(FitError::BeyondGrossSlip {
            force: largest,
            largest: per_mu * MU_RANGE.1,
            column: structure.load_column(),
            unit: structure.load().unit().symbol(),
            bound: structure.bound(),
        });
    }
    Ok((MU_RANGE.0.max(least), MU_RANGE.1))
}

/// Fits mu and K_T (each unless `fixed`, (mu, K_T)) of any [`Structure`] to its measured
/// load-response curve (the beams' w(L), the lap joint's Delta against F), the measurements
/// weighed by `weights` (what their scatter is assumed to be, which the standard errors and the
/// correlation depend on), telling `progress` how far it got (see [`Progress`]; the result is
/// the same).
///
/// A million measurements take a few seconds: the grid search and a first refinement run on an
/// evenly spread subsample of a few thousand rows, and the refinement finishes on all of them,
/// where it typically needs one or two steps.
///
/// # Errors
/// [`FitError::Param`] when the structure or a fixed value is invalid (the model's own checks),
/// or a fixed mu (or the structure's own) does not carry the largest measured force;
/// [`FitError::TooFewPoints`] when there are not more measurements than free parameters;
/// [`FitError::Sigma`] when `weights` gives sigmas that are not one positive finite value per
/// measurement; [`FitError::NothingToFit`] for a curve of zeros;
/// [`FitError::BeyondGrossSlip`] for a force no mu searched carries.
pub fn fit_weighted(
    structure: Structure,
    data: &[Measurement],
    fixed: (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    Ok(fit_explained(structure, data, fixed, weights, progress)?.0)
}

/// [`fit_weighted`] of a measured curve, which must be the structure's: refused
/// ([`FitError::NotThisModel`]) when the best fit explains none of its variation (R^2 <=
/// [`LEAST_EXPLAINED`], with a degree of freedom left). What `microslip fit`, the terminal UI's
/// `f` and the Python `fit` call; a comparison that fits FE points to imply a K_T
/// (`compare beam`) calls [`fit_weighted`] and judges the misfit itself.
///
/// # Errors
/// As [`fit_weighted`], and [`FitError::NotThisModel`].
pub fn fit_measured(
    structure: Structure,
    data: &[Measurement],
    fixed: (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    let (result, explained) = fit_explained(structure, data, fixed, weights, progress)?;
    if let Some(explained) = explained
        && result.degrees_of_freedom > 0
        && explained <= LEAST_EXPLAINED
    {
        return Err(FitError::NotThisModel {
            fitted: structure.fitted(),
            response: structure.response_column(),
            load: structure.load_column(),
            mu: result.mu.value,
            kt: result.kt.value,
            r_squared: explained,
        });
    }
    Ok(result)
}

/// [`fit_weighted`], with the R^2 of its optimum ([`explained`]): one [`family::scope`], so its
/// residuals at one trial stiffness continue from each other and from the earlier trials' (the
/// cylinder's rows, issue 47), and the fit depends on its inputs only.
fn fit_explained(
    structure: Structure,
    data: &[Measurement],
    fixed: (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<(FitResult, Option<f64>), FitError> {
    family::scope(|| fit_in_scope(structure, data, fixed, weights, progress))
}

/// [`fit_explained`] inside its scope.
fn fit_in_scope(
    structure: Structure,
    data: &[Measurement],
    (fixed_mu, fixed_kt): (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<(FitResult, Option<f64>), FitError> {
    // Validate the structure and any fixed values through the model's own constructor; the mu
    // searched is the structure's own business (the lap joint's carries every measured force).
    let (own_mu, own_kt) = structure.own();
    let (mu, kt) = (fixed_mu.unwrap_or(own_mu), fixed_kt.unwrap_or(own_kt));
    let mu_range = mu_range(&structure, (mu, kt), fixed_mu.is_some(), data)?;
    let sigma = weights.sigmas(data)?;
    let problem = Problem {
        structure,
        mu_range,
        data,
        sigma: &sigma,
        fixed_mu,
        fixed_kt,
    };
    let bounds = problem.bounds();
    let free = bounds.len();
    if data.len() <= free {
        return Err(FitError::TooFewPoints {
            points: data.len(),
            free,
        });
    }
    // Relative weights would make any curve through zeros look perfect: refuse a flat zero curve.
    if data.iter().all(|m| m.response == 0.0) {
        return Err(FitError::NothingToFit {
            column: structure.response_column(),
        });
    }
    // Many measurements: the grid search on an evenly spread subsample (whose sum of squares is
    // the whole curve's in miniature), then refinements on ever larger ones, each starting from the
    // previous one's fit.
    let mut sizes = Vec::new();
    let mut size = SUBSAMPLE;
    while size < data.len() {
        sizes.push(size);
        size = size.saturating_mul(LADDER);
    }
    let mut theta = None;
    for size in sizes {
        let (sample, sample_sigma): (Vec<Measurement>, Vec<f64>) = spread(data.len(), size)
            .map(|i| (data[i], sigma[i]))
            .unzip();
        let level = Problem {
            data: &sample,
            sigma: &sample_sigma,
            ..problem
        };
        let start = match theta {
            Some(theta) => theta,
            None => bracket(&level, &bounds, progress),
        };
        theta = Some(refine(&level, start, &bounds, progress).theta);
    }
    let start = match theta {
        Some(theta) => theta,
        None => bracket(&problem, &bounds, progress),
    };
    let refined = refine(&problem, start, &bounds, progress);
    Ok((
        summarize(&problem, &refined, weights),
        explained(&problem, &refined),
    ))
}

/// The fraction of the measured response's weighted variation (R^2) a fit must explain, more
/// than which it is reported: at or below it the mean of the responses fits them as well as the
/// structure does, and the curve is not the structure's ([`FitError::NotThisModel`]). A curve of
/// the structure with a scatter s (a fraction of its range) is explained to about 1 - s^2; one
/// that falls as the load grows, or rises and falls back, which no mu or K_T gives, to less than
/// nothing (docs/theory.md, "Fitting mu and K_T to the cylinder's s(a) against Q").
pub const LEAST_EXPLAINED: f64 = 0.0;

/// 1 - SSE / SST of the weighted residuals at the optimum: the fraction of the measured
/// response's variation about its weighted mean that the fit explains; `None` without
/// residuals or variation.
fn explained(problem: &Problem, refined: &least_squares::Refined) -> Option<f64> {
    let residuals = refined.residuals.as_ref()?;
    let sse: f64 = residuals.iter().map(|r| r * r).sum();
    let (sum, norm) = problem
        .data
        .iter()
        .zip(problem.sigma)
        .fold((0.0, 0.0), |(sum, norm), (m, s)| {
            (sum + m.response / (s * s), norm + 1.0 / (s * s))
        });
    let mean = sum / norm;
    let sst: f64 = problem
        .data
        .iter()
        .zip(problem.sigma)
        .map(|(m, s)| ((m.response - mean) / s).powi(2))
        .sum();
    (sst > 0.0 && sse.is_finite()).then(|| 1.0 - sse / sst)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::lap::LapJointProblem;
    use crate::problems::lap::closed_form::{LapJoint, LapParams};
    use crate::problems::twin_beams::TwinBeamsProblem;
    use crate::{TipForce, TwinBeams, TwinBeamsParams};

    /// The beams of `params`, fitted with equal weights (what `fit_twin_beams` was).
    fn fit_twin_beams(
        params: TwinBeamsParams,
        data: &[Measurement],
        fixed_mu: Option<f64>,
        fixed_kt: Option<f64>,
    ) -> Result<FitResult, FitError> {
        fit_twin_beams_with_progress(params, data, fixed_mu, fixed_kt, &mut |_| {})
    }

    fn fit_twin_beams_with_progress(
        params: TwinBeamsParams,
        data: &[Measurement],
        fixed_mu: Option<f64>,
        fixed_kt: Option<f64>,
        progress: &mut dyn FnMut(Progress),
    ) -> Result<FitResult, FitError> {
        fit_weighted(
            beams(params),
            data,
            (fixed_mu, fixed_kt),
            Weights::Absolute,
            progress,
        )
    }

    /// The beams' structure with the geometry, E and P of `params` (mu and K_T as the paper's,
    /// which the fits replace).
    fn beams(params: TwinBeamsParams) -> Structure {
        Structure::typed::<TwinBeamsProblem>(&TwinBeams::new(params).unwrap())
    }

    fn joint(params: LapParams) -> Structure {
        Structure::typed::<LapJointProblem>(&LapJoint::new(params).unwrap())
    }

    fn synthetic(mu: f64, kt: f64, forces: impl Iterator<Item = f64>) -> Vec<Measurement> {
        let beams = TwinBeams::new(TwinBeamsParams {
            friction: mu,
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        })
        .unwrap();
        forces
            .map(|f| Measurement {
                force: f,
                response: beams
                    .regularized(TipForce::new(f).unwrap())
                    .tip_deflection(),
            })
            .collect()
    }

    #[test]
    fn exact_data_are_recovered_exactly_from_a_poor_start() {
        let data = synthetic(0.45, 150.0, (1..=30).map(|i| 10.0 * f64::from(i)));
        // The structure's own mu and K_T (0.3, 600) are deliberately wrong: they are not used.
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
        assert!((fit.mu.value / 0.45 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!((fit.kt.value / 150.0 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!(fit.rms < 1e-10);
        assert_eq!(
            (fit.mu.status, fit.kt.status),
            (Status::Identified, Status::Identified)
        );
    }

    /// The lap joint's Delta against F, measured on a joint with mu 0.4 and K_T 2500 MPa/mm up to
    /// 0.9 F_gross: both come back from the bundled joint's wrong guesses (mu 0.3, K_T 1000), and
    /// below F_1 mu is not seen.
    #[test]
    fn a_lap_joint_curve_gives_back_its_mu_and_k_t() {
        let truth = LapJoint::new(LapParams {
            friction: 0.4,
            tangential_stiffness: 2500.0,
            ..LapParams::ALUMINIUM
        })
        .unwrap();
        let gross = truth.gross_slip_force();
        let curve = |top: f64| -> Vec<Measurement> {
            (1..=30)
                .map(|i| {
                    let force = top * f64::from(i) / 30.0;
                    let f = truth.force(force).unwrap();
                    Measurement {
                        force,
                        response: truth.regularized(f).joint_displacement(),
                    }
                })
                .collect()
        };
        let fit = fit_weighted(
            joint(LapParams::ALUMINIUM),
            &curve(0.9 * gross),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
        .unwrap();
        assert!((fit.mu.value / 0.4 - 1.0).abs() < 1e-6, "{fit:?}");
        assert!((fit.kt.value / 2500.0 - 1.0).abs() < 1e-6, "{fit:?}");
        assert_eq!(
            (fit.mu.status, fit.kt.status),
            (Status::Identified, Status::Identified)
        );
        assert!((fit.threshold_force / gross - 1.0).abs() < 1e-6);
        // Only microslip: K_T is seen, mu only bounded from below.
        let below = fit_weighted(
            joint(LapParams::ALUMINIUM),
            &curve(0.9 * truth.first_slip_force()),
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        )
        .unwrap();
        assert!((below.kt.value / 2500.0 - 1.0).abs() < 1e-6, "{below:?}");
        assert!(matches!(
            below.mu.evidence,
            Evidence::NoDataAboveFirstMacroslip { .. }
        ));
        // Forces no mu of the search carries: refused, naming the force and the largest F_gross.
        let over = [1e5, 2e5, 2.5e5].map(|force| Measurement {
            force,
            response: force * 1e-5,
        });
        let refused = fit_weighted(
            joint(LapParams::ALUMINIUM),
            &over,
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        );
        assert_eq!(
            refused,
            Err(FitError::BeyondGrossSlip {
                force: 2.5e5,
                largest: 1e5,
                column: "F_N",
                unit: "N",
                bound: "F_gross = 2 b mu P L: the joint slides through beyond it".to_string(),
            })
        );
        assert_eq!(
            refused.unwrap_err().to_string(),
            "invalid F_N = 250000: beyond F_gross = 2 b mu P L: the joint slides through beyond \
             it (for every mu up to 5, the bound is at most 100000 N), so no mu fits it"
        );
        // A fixed mu that cannot carry the largest force is refused by name.
        let refused = fit_weighted(
            joint(LapParams::ALUMINIUM),
            &curve(0.9 * gross),
            (Some(0.1), None),
            Weights::Absolute,
            &mut |_| {},
        );
        assert!(refused.unwrap_err().to_string().contains("F_gross"));
    }

    #[test]
    fn fixing_one_parameter_fits_the_other() {
        let data = synthetic(0.3, 600.0, (1..=20).map(|i| 15.0 * f64::from(i)));
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, Some(0.3), None).unwrap();
        assert_eq!(fit.mu.status, Status::Fixed);
        assert!((fit.kt.value / 600.0 - 1.0).abs() < 1e-6);
        let fit = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, Some(600.0)).unwrap();
        assert!((fit.mu.value / 0.3 - 1.0).abs() < 1e-6);
    }

    /// A curve of `n` points from 1 to 300 N with deterministic noise of +-`noise` mm.
    fn noisy(n: usize, noise: f64) -> Vec<Measurement> {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut data = synthetic(
            0.4,
            200.0,
            (0..n).map(|i| 1.0 + 299.0 * i as f64 / (n - 1) as f64),
        );
        for m in &mut data {
            // xorshift: reproducible noise without a dependency.
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            m.response += noise * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
        }
        data
    }

    #[test]
    fn progress_is_reported_and_changes_nothing() {
        let data = noisy(300, 1e-4);
        let plain = fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None).unwrap();
        let mut events = Vec::new();
        let reported =
            fit_twin_beams_with_progress(TwinBeamsParams::PAPER, &data, None, None, &mut |p| {
                events.push(p)
            })
            .unwrap();
        assert_eq!(plain, reported);
        // 16 mu nodes (1e-3 to 5) x 49 K_T nodes (1e-3 to 1e9), on all 300 points.
        assert_eq!(
            events
                .iter()
                .filter(|p| matches!(p, Progress::Bracket { .. }))
                .count(),
            16 * 49
        );
        assert!(events.contains(&Progress::Bracket {
            done: 784,
            total: 784,
            points: 300
        }));
        assert!(events.iter().any(|p| matches!(
            p,
            Progress::Refine {
                iteration: 1,
                points: 300,
                ..
            }
        )));
    }

    #[test]
    fn long_curves_visit_every_point_only_in_the_last_few_steps() {
        // 5000 points: the grid and a first refinement on 1024 of them, then all.
        let n = 5000;
        let data = noisy(n, 1e-4);
        let mut grid_points = Vec::new();
        let mut full_iterations = 0;
        let fit = fit_twin_beams_with_progress(
            TwinBeamsParams::PAPER,
            &data,
            None,
            None,
            &mut |p| match p {
                Progress::Bracket { points, .. } => grid_points.push(points),
                Progress::Refine {
                    iteration, points, ..
                } if points == n => full_iterations = full_iterations.max(iteration),
                _ => {}
            },
        )
        .unwrap();
        assert!(
            grid_points.iter().all(|&p| p == SUBSAMPLE),
            "{grid_points:?}"
        );
        assert!(
            (1..=4).contains(&full_iterations),
            "{full_iterations} iterations on every point"
        );
        // The answer is the curve's: within a few standard errors of the truth, and the same
        // (to far below a standard error) as refining on all points from the grid's start.
        for (estimate, truth) in [(&fit.mu, 0.4), (&fit.kt, 200.0)] {
            let error = estimate.std_error.unwrap();
            assert!((estimate.value - truth).abs() < 5.0 * error, "{fit:?}");
        }
        let sigma = vec![1.0; data.len()];
        let problem = Problem {
            structure: beams(TwinBeamsParams::PAPER),
            mu_range: MU_RANGE,
            data: &data,
            sigma: &sigma,
            fixed_mu: None,
            fixed_kt: None,
        };
        let bounds = problem.bounds();
        let direct = refine(
            &problem,
            bracket(&problem, &bounds, &mut |_| {}),
            &bounds,
            &mut |_| {},
        );
        let (mu, kt) = problem.unpack(&direct.theta);
        assert!((fit.mu.value - mu).abs() < 1e-3 * fit.mu.std_error.unwrap());
        assert!((fit.kt.value - kt).abs() < 1e-3 * fit.kt.std_error.unwrap());
    }

    #[test]
    fn bad_fixed_values_and_too_few_points_are_refused() {
        let data = synthetic(0.3, 600.0, [10.0, 20.0].into_iter());
        assert_eq!(
            fit_twin_beams(TwinBeamsParams::PAPER, &data, Some(-1.0), None)
                .unwrap_err()
                .to_string(),
            "invalid mu = -1: must be > 0 and finite (dimensionless)"
        );
        assert!(matches!(
            fit_twin_beams(TwinBeamsParams::PAPER, &data, None, None),
            Err(FitError::TooFewPoints { points: 2, free: 2 })
        ));
    }
}
