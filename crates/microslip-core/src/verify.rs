//! Cross-check of the closed forms against the independent finite-element solvers, over a grid that
//! spans every regime and the transitions between them. This is the only module that calls both; the
//! solvers in [`crate::numeric`] never see a closed form. Results are data (the worst case of each
//! quantity); the table for people is written by the `report` module.

use crate::numeric::{MeshDensity, NumericError};
use crate::problems::ModelKind;
use crate::problems::lap::LapFe;
use crate::problems::lap::closed_form::{LapJoint, LapParams};
use crate::problems::plate::PlateFe;
use crate::problems::twin_beams::TwinBeamsFe;
use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

/// Default tolerance on every relative error (the target of the numerical-solver issue).
pub const DEFAULT_TOLERANCE: f64 = 1e-3;

/// How much of the grid to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grid {
    /// Every case (about 130).
    Full,
    /// One geometry per model: a smoke test for CI.
    Quick,
}

/// A quantity both the closed forms and the finite elements compute.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Twin beams: tip deflection w(L) (mm).
    BeamTipDeflection,
    /// Twin beams: end X of the microslip zone (mm).
    BeamMicroslipEnd,
    /// Plate: end displacement u(L) (mm).
    PlateEndDisplacement,
    /// Plate: end X_r of the microslip zone (mm).
    PlateMicroslipEnd,
    /// Lap joint: joint displacement Delta (mm).
    LapJointDisplacement,
    /// Lap joint: the sliding zones a and d (mm), their error over the overlap L (a zone of zero
    /// length has no relative error).
    LapSlidingZones,
}

/// One compared case: the full parameters, so that it can be rerun.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Case {
    /// Twin beams at a tip force.
    Beam {
        /// The beams.
        params: TwinBeamsParams,
        /// Tip force (N).
        force: f64,
    },
    /// A plate at its own pressure.
    Plate(PlateParams),
    /// A lap joint at a force.
    Lap {
        /// The joint.
        params: LapParams,
        /// Force through it (N).
        force: f64,
    },
}

/// The worst disagreement found for one quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Worst {
    /// What was compared.
    pub quantity: Quantity,
    /// How many cases compared it.
    pub cases: usize,
    /// Largest relative error.
    pub error: f64,
    /// The case of that error (None when no case compared the quantity).
    pub case: Option<Case>,
}

impl Worst {
    fn new(quantity: Quantity) -> Self {
        Worst {
            quantity,
            cases: 0,
            error: 0.0,
            case: None,
        }
    }

    fn record(&mut self, numeric: f64, exact: f64, case: Case) {
        self.record_error(relative_error(numeric, exact), case);
    }

    fn record_error(&mut self, error: f64, case: Case) {
        self.cases += 1;
        if error > self.error || self.case.is_none() {
            self.error = error;
            self.case = Some(case);
        }
    }

    /// Whether the worst relative error is within `tolerance` (a NaN error is not).
    pub fn passes(&self, tolerance: f64) -> bool {
        self.error <= tolerance
    }
}

/// How many of the quantities exceed `tolerance`.
pub fn failures(results: &[Worst], tolerance: f64) -> usize {
    results.iter().filter(|w| !w.passes(tolerance)).count()
}

/// |a - b| / |b|, or |a| when b is 0.
fn relative_error(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// Beam geometries of the grid: the paper's, a slender one and a stubby one, each with its own mu, P.
fn beam_shapes(grid: Grid) -> Vec<TwinBeamsParams> {
    let paper = TwinBeamsParams::PAPER;
    let mut shapes = vec![paper];
    if grid == Grid::Full {
        shapes.push(TwinBeamsParams {
            length: 500.0,
            width: 10.0,
            half_height: 2.0,
            friction: 0.15,
            pressure: 2.0,
            ..paper
        });
        shapes.push(TwinBeamsParams {
            length: 50.0,
            width: 30.0,
            half_height: 5.0,
            youngs_modulus: 70_000.0,
            friction: 0.8,
            pressure: 0.5,
            ..paper
        });
    }
    shapes
}

/// Plate variants of the grid.
fn plate_shapes(grid: Grid) -> Vec<PlateParams> {
    let paper = PlateParams::PAPER;
    let mut shapes = vec![paper];
    if grid == Grid::Full {
        shapes.push(PlateParams {
            thickness: 1.0,
            poisson: 0.45,
            friction: 0.8,
            ..paper
        });
        shapes.push(PlateParams {
            half_length: 50.0,
            thickness: 0.1,
            poisson: 0.1,
            friction: 0.1,
            pressure: 1.0,
            ..paper
        });
    }
    shapes
}

/// K_T values (MPa/mm) of the grid: five decades around each data set.
const BEAM_STIFFNESSES: [f64; 5] = [12.0, 120.0, 600.0, 6e3, 6e4];
const PLATE_STIFFNESSES: [f64; 6] = [1.0, 1e3, 1e5, 1e6, 1e7, 1e8];

/// Runs the comparison; returns the worst case of each quantity, in the order of [`Quantity`].
///
/// # Errors
///
/// The [`NumericError`] of the first finite-element solve that fails.
pub fn run(grid: Grid, density: MeshDensity) -> Result<Vec<Worst>, NumericError> {
    let mut worst = Vec::new();
    // Every problem, so that none is left out of `verify` without the compiler saying so.
    for kind in ModelKind::ALL {
        match kind {
            ModelKind::Beam => worst.extend(run_beams(grid, density)?),
            ModelKind::Plate => worst.extend(run_plates(grid, density)?),
            ModelKind::Lap => worst.extend(run_laps(grid, density)?),
        }
    }
    Ok(worst)
}

/// The twin beams over the grid: w(L) and X.
fn run_beams(grid: Grid, density: MeshDensity) -> Result<[Worst; 2], NumericError> {
    let mut w = Worst::new(Quantity::BeamTipDeflection);
    let mut x = Worst::new(Quantity::BeamMicroslipEnd);
    for shape in beam_shapes(grid) {
        for kt in BEAM_STIFFNESSES {
            let params = TwinBeamsParams {
                tangential_stiffness: kt,
                ..shape
            };
            let Ok(beams) = TwinBeams::new(params) else {
                continue;
            };
            let (f_thre, f_1) = (beams.threshold_force(), beams.first_macroslip_force());
            // Stick-like, just below and just above F_1, and two depths of macroslip.
            for f in [
                0.5 * f_thre,
                0.98 * f_1,
                1.02 * f_1,
                1.5 * f_thre,
                3.0 * f_thre,
            ] {
                let Ok(force) = TipForce::new(f) else {
                    continue;
                };
                let exact = beams.regularized(force);
                let mut fe = TwinBeamsFe::new(params, density);
                fe.load_to(f, 4)?;
                let case = Case::Beam { params, force: f };
                w.record(fe.tip_deflection(), exact.tip_deflection(), case);
                x.record(fe.micro_zone_end(), exact.micro_zone_end(), case);
            }
        }
    }
    Ok([w, x])
}

/// Lap joints of the grid: the bundled one (x = L slides first), and on the full grid a balanced
/// one (both ends at once) and one whose inner plate is stiffer (x = 0 first).
fn lap_shapes(grid: Grid) -> Vec<LapParams> {
    let aluminium = LapParams::ALUMINIUM;
    let mut shapes = vec![aluminium];
    if grid == Grid::Full {
        shapes.push(LapParams {
            inner_thickness: 4.0,
            ..aluminium
        });
        shapes.push(LapParams {
            inner_thickness: 6.0,
            friction: 0.6,
            pressure: 5.0,
            ..aluminium
        });
    }
    shapes
}

/// K_T values (MPa/mm) of the lap grid: 1/lambda from 25 mm to 0.25 mm on the bundled joint.
const LAP_STIFFNESSES: [f64; 4] = [100.0, 1e3, 1e4, 1e5];

/// The lap joints over the grid: Delta, and a and d over L, in every regime (all microslip, one
/// end sliding, both, nearly gross slip).
fn run_laps(grid: Grid, density: MeshDensity) -> Result<[Worst; 2], NumericError> {
    let mut delta = Worst::new(Quantity::LapJointDisplacement);
    let mut zones = Worst::new(Quantity::LapSlidingZones);
    for shape in lap_shapes(grid) {
        for kt in LAP_STIFFNESSES {
            let params = LapParams {
                tangential_stiffness: kt,
                ..shape
            };
            let Ok(joint) = LapJoint::new(params) else {
                continue;
            };
            let (f1, f2, gross) = (
                joint.first_slip_force(),
                joint.second_slip_force(),
                joint.gross_slip_force(),
            );
            for f in [0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.95 * gross] {
                let Ok(force) = joint.force(f) else {
                    continue;
                };
                let exact = joint.regularized(force);
                let mut fe = LapFe::new(params, density);
                fe.load_to(f, 4)?;
                let case = Case::Lap { params, force: f };
                delta.record(fe.joint_displacement(), exact.joint_displacement(), case);
                let (a, d) = fe.sliding_zones();
                let off = (a - exact.slide_at_inner_end())
                    .abs()
                    .max((d - exact.slide_at_cover_ends()).abs());
                zones.record_error(off / params.length, case);
            }
        }
    }
    Ok([delta, zones])
}

/// The plate over the grid: u(L) and X_r.
fn run_plates(grid: Grid, density: MeshDensity) -> Result<[Worst; 2], NumericError> {
    let mut u = Worst::new(Quantity::PlateEndDisplacement);
    let mut xr = Worst::new(Quantity::PlateMicroslipEnd);
    for shape in plate_shapes(grid) {
        for kt in PLATE_STIFFNESSES {
            let params = PlateParams {
                tangential_stiffness: kt,
                ..shape
            };
            let Ok(plate) = SqueezedPlate::new(params) else {
                continue;
            };
            let exact = plate.regularized();
            let mut fe = PlateFe::new(params, density);
            fe.load_to(params.pressure, 2)?;
            let case = Case::Plate(params);
            u.record(fe.end_displacement(), exact.end_displacement(), case);
            xr.record(fe.micro_zone_end(), exact.micro_zone_end(), case);
        }
    }
    Ok([u, xr])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_error_handles_zero_references() {
        assert_eq!(relative_error(1e-3, 0.0), 1e-3);
        assert!((relative_error(1.01, 1.0) - 0.01).abs() < 1e-12);
    }

    #[test]
    fn the_worst_case_is_kept_and_failures_are_counted_against_the_tolerance() {
        let case = |force| Case::Beam {
            params: TwinBeamsParams::PAPER,
            force,
        };
        let mut worst = Worst::new(Quantity::BeamTipDeflection);
        worst.record(1.0, 1.0, case(10.0));
        assert_eq!((worst.error, worst.case), (0.0, Some(case(10.0))));
        worst.record(1.02, 1.0, case(20.0));
        worst.record(1.01, 1.0, case(30.0));
        assert_eq!(worst.cases, 3);
        assert_eq!(worst.case, Some(case(20.0)));
        assert!(worst.passes(0.03) && !worst.passes(0.01));
        let mut broken = Worst::new(Quantity::PlateEndDisplacement);
        broken.record(f64::NAN, 1.0, Case::Plate(PlateParams::PAPER));
        assert!(!broken.passes(1.0));
        let results = [worst, broken];
        assert_eq!(failures(&results, 0.03), 1);
        assert_eq!(failures(&results, 0.01), 2);
    }
}
