//! Identification of mu and K_T from a measured twin-beam deflection curve w(L) vs F.
//!
//! The paper's practical point (its section 2.1.3): below F_1 the whole interface is in microslip and
//! w depends on K_T but not on mu; past F_1 the slope changes (towards the Coulomb slip slope, which
//! carries mu). So K_T comes from the curve's stiffness, mu from where and how the slope changes.
//!
//! Method: nonlinear least squares on the closed form, in log-parameters (both must stay positive and
//! span decades). A coarse grid over both (the bracket) gives a start that does not depend on the
//! user's guess, then Levenberg-Marquardt refines it. The residuals are weighted by what the
//! scatter of each measurement is assumed to be ([`Weights`]: absolute, relative to w, or given per
//! point); standard errors and the mu-K_T correlation come from the Jacobian at the optimum
//! ((J^T W J)^-1, times the reduced chi-square unless the sigmas are known; delta method back to
//! linear units; derived in docs/theory.md).
//!
//! Cost: the model takes well under a microsecond per point, and a long curve (a million rows) is
//! fitted in seconds. Above 1024 rows the grid and the first refinements run on evenly spread
//! subsamples (32 times larger at each level), so the full data are only visited by the last two
//! or three Gauss-Newton steps; the normal equations are summed point by point, never storing the
//! Jacobian. Up to 1024 rows the fit is the same computation as ever.
//! [`fit_twin_beams_with_progress`] reports how far it got, for callers that show progress. Identifiability is judged from the
//! physics first (no data beyond F_1: mu cannot be seen) and from the standard errors second.
//!
//! Results are data only: the reason behind each verdict is an [`Evidence`] carrying its numbers;
//! the words for people are written by the `report` module.

pub mod measurement;
pub mod weights;

mod beam;
mod evidence;
mod lap;
mod least_squares;
mod progress;
mod small;
mod structure;

use thiserror::Error;

pub use beam::{fit_twin_beams, fit_twin_beams_weighted, fit_twin_beams_with_progress};
pub use evidence::{Estimate, Evidence, FitResult, Status};
pub use measurement::{MIN_ROWS, Measured, Measurement};
pub use progress::{Pass, Progress};
pub use structure::Structure;
pub use weights::{Scatter, Weights};

use crate::kernel::params::ParamError;
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
    /// (Lap joint) A measured force beyond the gross-slip force of every mu searched: no state
    /// of the joint carries it.
    #[error(
        "invalid F_N = {force}: beyond the gross-slip force 2 b mu P L of every mu up to {} \
         ({largest} N): the joint slides through, so no mu fits it",
        MU_RANGE.1
    )]
    BeyondGrossSlip {
        /// The largest measured force (N).
        force: f64,
        /// F_gross at the largest mu searched (N).
        largest: f64,
    },
}

/// Fits mu and K_T (each unless `fixed`, (mu, K_T)) of any [`Structure`] to its measured
/// load-response curve, as [`fit_twin_beams_weighted`] does for the beams: the lap joint's Delta
/// against F (docs/theory.md (L11) and section 3b).
///
/// # Errors
/// As [`fit_twin_beams_weighted`]; for the joint also a fixed mu or the structure's own at which
/// the largest measured force exceeds F_gross.
pub fn fit_weighted(
    structure: Structure,
    data: &[Measurement],
    (fixed_mu, fixed_kt): (Option<f64>, Option<f64>),
    weights: Weights,
    progress: &mut dyn FnMut(Progress),
) -> Result<FitResult, FitError> {
    // Validate the structure and any fixed values through the model's own constructor; the mu
    // searched is the structure's own business (the lap joint's carries every measured force).
    let (own_mu, own_kt) = structure.own();
    let (mu, kt) = (fixed_mu.unwrap_or(own_mu), fixed_kt.unwrap_or(own_kt));
    let mu_range = match structure {
        Structure::Beam(p) => {
            beam::check(p, mu, kt)?;
            MU_RANGE
        }
        Structure::Lap(p) => lap::mu_range(p, (mu, kt), fixed_mu.is_some(), data)?,
    };
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
    Ok(summarize(&problem, &refined, weights))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::lap::closed_form::{LapJoint, LapParams};
    use crate::{TipForce, TwinBeams, TwinBeamsParams};

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
            Structure::Lap(LapParams::ALUMINIUM),
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
            Structure::Lap(LapParams::ALUMINIUM),
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
            Structure::Lap(LapParams::ALUMINIUM),
            &over,
            (None, None),
            Weights::Absolute,
            &mut |_| {},
        );
        assert_eq!(
            refused,
            Err(FitError::BeyondGrossSlip {
                force: 2.5e5,
                largest: 1e5
            })
        );
        // A fixed mu that cannot carry the largest force is refused by name.
        let refused = fit_weighted(
            Structure::Lap(LapParams::ALUMINIUM),
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
            structure: Structure::Beam(TwinBeamsParams::PAPER),
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
