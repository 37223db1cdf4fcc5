//! The double-lap joint as a 2-D plane-stress continuum of two deformable bodies: the judge of the
//! shear-lag closed forms where they assume too much.
//!
//! The shear-lag theory (`closed_form`, docs/theory.md section 9) takes each plate's axial
//! displacement uniform through its thickness and the contact pressure equal to P. This model
//! drops both, and solves the very continuum problem the CalculiX deck `microslip deck ccx lap`
//! writes (`src/fe/lap_deck.rs`), so that the two can be compared number for number:
//!
//! - half the joint, about the inner plate's mid-plane: the inner plate y in [0, t1/2] with
//!   u_y = 0 at y = 0, one cover y in [t1/2, t1/2 + t2];
//! - plane stress (a thin slice with free faces: the axial modulus is E, as in the 1-D theory),
//!   with nu = [`LAP_POISSON`] = 0.3 in both plates. The joint's keys have no Poisson ratio; the
//!   deck uses the same one, and nu = 0 instead moved CalculiX's Delta by at most 0.06 %;
//! - the cover runs over x in [-H, L], H = 2 (t1 + t2), and its end face x = -H is held
//!   (u_x = u_y = 0); the inner plate runs over [0, L + H] and is pulled at x = L + H by the
//!   uniform traction F / (b t1) (consistent nodal loads); the pressure P acts on the cover's
//!   outer face over [0, L] only;
//! - 8-node quadrilaterals (Q8, 3 x 3 Gauss points, `numeric::q8`) in both bodies,
//!   `layers` of them through the inner half thickness and as many through the cover, graded
//!   along x toward both overlap ends exactly as the deck grades its mesh (finest min(2/3 layer,
//!   1/(4 lambda)), coarsest min(8/3 layer, 1/(2 lambda)), growth 1.15);
//! - the interface over [0, L] with matching nodes. **Normal:** each node pair shares its normal
//!   displacement (one unknown for both nodes): an exact tie, with no penalty stiffness to choose
//!   and no conditioning to lose (CalculiX's penalty of 100 E / h lets the faces interpenetrate by
//!   p / K_N ~ 5e-7 mm, a 1e-4 fraction of Delta). The pair's contact force is then the cover's
//!   share of the equilibrium at that unknown, and comes out of the solution. A pair in tension
//!   would be held by the tie: it gets no friction strength, and is listed in
//!   [`ContinuumLap::separated`] so that a caller can see the tie was used where the faces would
//!   open (none does on the bundled joint: its smallest contact pressure under load is about
//!   6 MPa). **Tangential:** at each pair a Jenkins point on the relative slip
//!   u_inner - u_cover, stiffness K_T times the node's share of the face (Simpson weights),
//!   strength mu times the pair's contact force.
//!
//! What differs from the deck is numerical only: CalculiX's face-to-face penalty contact
//! (integrated over each face, K_N = 100 E / h) against the tie and nodal Jenkins points here, its
//! weak spring (1e-7 of the inner plate's axial stiffness) that holds the inner plate before
//! contact engages, and its 3-D slice of C3D20R bricks against Q8 in plane stress. Measured on the
//! bundled joint, Delta agrees within 0.014 % (docs/theory.md (L13), tests/lap_continuum.rs).
//!
//! **Load path.** Step 1 applies P alone, in one increment: the reference state (Delta and the
//! slip are measured from it, as the deck's header says: P alone stretches both plates through
//! Poisson, a third of Delta at 1000 N). Then F rises monotonically from 0 in equal increments
//! ([`LapContinuumMesh::force_increments`] over [0, F_gross]). Friction is path-dependent once a
//! point slides, and the strengths change with F because the covers bend (the pressure falls to
//! about 6 MPa at x = L and rises to 11-14 MPa at x = 0 on the bundled joint), so each increment
//! is solved at its own contact forces: a fixed point on them (solve with given strengths, take
//! the contact forces, repeat), each solve a Newton iteration with the shared driver
//! (`numeric::newton`), from the history committed at the end of the previous
//! increment.
//!
//! **Speed.** The only nonlinearity sits on the interface, so the elastic bodies are condensed
//! onto the pair slips once: the stiffness with every interface spring elastic, K0, is factored
//! once (banded Cholesky, nodes numbered column by column across both bodies), and solved for the
//! m pair loads, P and F. The Newton iterations then work on m unknowns (the slips) with the
//! condensed stiffness, and the contact forces and Delta are linear in the plastic slips. The
//! answer is the same as that of the full system (the condensation is exact).

use super::params::{LapParam, LapParams};
use crate::kernel::params::Compact;
use crate::numeric::{NumericError, short};
use std::cell::RefCell;

use crate::numeric::banded::{BandCholesky, NotPositiveDefinite, SymmetricBand};
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::mesh::graded_toward_end;
use crate::numeric::newton::{self, Discretized};
use crate::numeric::q8::{EDGE_WEIGHTS, Elasticity, Q8, plane_stress, q8_stiffness};

pub use super::params::LAP_POISSON;

/// Growth ratio of neighbouring elements along x (the deck's).
const GROWTH: f64 = 1.15;

/// Most interface node pairs the solver accepts: the condensed interface is a dense m x m
/// system, built from m solves with the banded factor, and its cost grows like m^2 to m^3
/// (release build, bundled joint, default mesh: 20-30 ms at m = 101 (K_T = 1e3, 1e4), 0.1-0.2 s
/// at m = 217 (1e5), 1.4-5 s at m = 661 (1e6), 9 s at m = 797; L = 300 mm at K_T = 1e3 is
/// m = 621, 1.7 s).
const MAX_PAIRS: usize = 801;

/// Largest lambda t1 accepted (K_T = 1.04e6 MPa/mm for the bundled joint): the stiffest
/// interface CalculiX was run at is lambda t1 = 12.2 (K_T = 1e6), where the closed form at K_eff
/// is within 0.9 % of it. Beyond, the interface is Coulomb-like, the mesh that resolves 1/lambda
/// grows like lambda and the solve takes seconds.
const MAX_LAMBDA_T1: f64 = 12.5;

/// Right-hand sides solved together with the banded factor: enough to read each factor entry
/// once for many, few enough to keep the block small (n x 64).
const CHUNK: usize = 64;

/// Most elements in both bodies together (the mesh is counted before it is built).
const MAX_ELEMENTS: usize = 50_000;

/// Most entries of the banded stiffness (128 MB).
const MAX_BAND_ENTRIES: f64 = 1.6e7;

/// Most elements through each body's thickness.
const MAX_LAYERS: usize = 32;

/// Fixed-point iterations allowed on the contact forces per increment. The iteration contracts
/// at a rate set by how much the strengths move the contact forces, which grows with mu: on the
/// bundled joint a few iterations at mu = 0.3, but about 0.85 per iteration at mu = 2 near
/// F = 10 kN with the covers lifting at x = 0 (about 130 iterations; 60 failed there, issue
/// 36). Each iteration is one Newton solve on the pairs, mostly with a kept factor.
const MAX_CONTACT_ITERATIONS: usize = 400;
/// Times a load increment whose fixed point fails may be halved.
const MAX_CUTS: u32 = 6;
/// Most height over length of the overlap's elements: L = 1e-3 mm on the bundled joint (375)
/// solves, 1e-4 mm (3750) loses precision and 1e-6 mm gives a singular stiffness.
const MAX_ASPECT: f64 = 500.0;
/// Largest [`clamping_slide`] accepted (measured: solved at 210, failed at 332).
const MAX_CLAMPING_SLIDE: f64 = 200.0;
/// The bounds of the contact forces' relaxation (Aitken's factor is clamped to them).
const MIN_RELAXATION: f64 = 1.0 / 64.0;
const MAX_RELAXATION: f64 = 2.0;
/// Change of the contact forces, relative to the largest, that ends the fixed point.
const CONTACT_TOLERANCE: f64 = 1e-10;
/// Largest imbalance of the inner plate's half accepted, relative to F/2 + F_gross/2: measured
/// 1.5e-8 at K_T = 0.01 MPa/mm and below 1e-9 from K_T = 1 up on the bundled joint (7.5e-5 at
/// K_T = 1e-6, refused).
const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;
/// The local sliding reading: |tau| >= (1 - this) mu p.
const LOCAL_SLIDING: f64 = 1e-3;

/// How fine the continuum model is, in space and in load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LapContinuumMesh {
    /// Elements through the inner plate's half thickness, and as many through the cover (the
    /// element sizes along x scale with the layer height).
    pub layers: usize,
    /// Load increments over [0, F_gross]: a force F is reached in ceil(F / F_gross x this)
    /// increments (at least one).
    pub force_increments: usize,
}

impl Default for LapContinuumMesh {
    /// Four elements through each body, as CalculiX's calibration (the deck's coarse mesh), and
    /// 8 force increments over [0, F_gross] (750 N for the bundled joint). The strengths
    /// change smoothly and monotonically with F, so the path barely matters: 4, 8, 16 and 64
    /// increments give the same Delta to 10 digits on the bundled joint at K_T = 1e3, 1e4 and
    /// 1e5 and F = 2000, 2400 and 5500 N (more increments only cost time: 19 -> 40 ms at 1e3,
    /// 111 -> 430 ms at 1e5, 4 -> 64 increments to 5500 N).
    fn default() -> Self {
        LapContinuumMesh {
            layers: 4,
            force_increments: 8,
        }
    }
}

/// Sliding zones measured from each end of the overlap (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingZones {
    /// From x = 0, the inner plate's end (the closed form's a).
    pub from_inner_end: f64,
    /// From x = L, the covers' ends (the closed form's d).
    pub from_cover_ends: f64,
}

/// The continuum solution at the requested force.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuumLap {
    /// The force through the joint (N).
    pub force: f64,
    /// The joint displacement (mm): the thickness mean of u_x of the inner plate at x = L minus
    /// that of the cover at x = 0 (Simpson's rule per element, exact for the element's field),
    /// each minus its value after the clamping step: the closed form's Delta.
    pub delta: f64,
    /// The same reading at the end of the clamping step (mm), which `delta` is measured from:
    /// P alone stretches both plates through Poisson.
    pub clamping_delta: f64,
    /// The interface slip u_inner - u_cover at each pair, from the clamped state, (x (mm), s (mm)).
    pub slip: Vec<(f64, f64)>,
    /// The interface shear stress at each pair (x (mm), tau (MPa)): the pair's Jenkins force over
    /// its share of the face, positive where the cover drags the inner plate back toward x < 0.
    pub shear: Vec<(f64, f64)>,
    /// The contact pressure at each pair (x (mm), p (MPa)): the pair's contact force over its
    /// share of the face; negative where the faces would open ([`ContinuumLap::separated`]).
    pub contact_pressure: Vec<(f64, f64)>,
    /// The sliding zones as the closed form defines them: contiguous runs from each end where
    /// K_T |s| >= mu P, with the nominal P, interpolated at the crossing (mm).
    pub nominal_zones: SlidingZones,
    /// The sliding zones by the local law: contiguous runs of pairs from each end where
    /// |tau| >= mu p within 0.1 %, at node resolution: the distance from the end to the last
    /// sliding pair of the run (mm); 0 when the end pair does not slide.
    pub local_zones: SlidingZones,
    /// The x (mm) of the pairs whose contact force is tensile at the requested force: the tie
    /// holds them where the faces would open, and they carry no friction. Empty on the bundled
    /// joint.
    pub separated: Vec<f64>,
    /// The force the interface transfers, b times the integral of tau over [0, L] (N): F/2 by
    /// equilibrium of the inner plate's half (the other half crosses the other interface).
    pub transferred_force: f64,
    /// Load increments of F from 0 to this force (after the clamping step).
    pub increments: usize,
    /// Fixed-point iterations on the contact forces, over all steps.
    pub iterations: usize,
    /// Interface node pairs (the condensed system's size).
    pub pairs: usize,
}

/// Solves the joint of `params` under the clamping pressure, then the force `force` (N).
///
/// # Errors
/// [`NumericError::OutOfRange`] for inputs outside their domains (the parameters, a force
/// beyond F_gross = 2 b mu P L, layers outside 1..=32, no force increment), an interface too
/// stiff for the solver (lambda t1 > 12.5) or a mesh too large (more than 801 interface pairs);
/// [`NumericError::OutOfRange`] also for an overlap too short for its plates (elements more
/// than 500 times shorter than high: L < 0.0015 mm on the bundled joint) and for a friction so
/// low that P alone slides nearly the whole interface (nu K_T / (E lambda mu) > 200: mu <
/// 1.66e-4 on the bundled joint), both with the least value accepted;
/// [`NumericError::Unsolved`] when the solve fails, saying where: at or within a few tenths of a
/// percent of F_gross (the continuum's own gross-slip force differs from 2 b mu P L: the held
/// cover end carries part of the clamping force), or when the contact forces do not settle even
/// on halved increments (covers lifting off over a wide zone: mu = 10 beyond 28 kN on the
/// bundled joint); [`NumericError::OutOfRange`] also when the answer fails its equilibrium check
/// (an interface too soft for the condensed solve, K_T = 1e-6 MPa/mm on the bundled joint).
pub fn solve_lap_continuum(
    params: LapParams,
    force: f64,
    mesh: LapContinuumMesh,
) -> Result<ContinuumLap, NumericError> {
    let mut states = solve_lap_continuum_path(params, &[force], mesh)?;
    states.pop().ok_or(NumericError::BadLoad(force))
}

/// Solves the joint along one monotonic loading path: the clamping pressure, then F rising
/// through each of `forces` (N, non-decreasing) in turn; the state at each. One path gives the
/// same states as separate solves (the increments between two forces are
/// ceil((F_k - F_(k-1)) / F_gross x `force_increments`)), for the cost of one.
///
/// # Errors
/// As [`solve_lap_continuum`]; also [`NumericError::OutOfRange`] for forces that decrease.
pub fn solve_lap_continuum_path(
    params: LapParams,
    forces: &[f64],
    mesh: LapContinuumMesh,
) -> Result<Vec<ContinuumLap>, NumericError> {
    let out_of_range =
        |e: crate::kernel::params::ParamError| NumericError::OutOfRange(e.to_string());
    params.check().map_err(out_of_range)?;
    let gross = params.gross_slip_force();
    for &force in forces {
        let force = LapParam::Force.check(force).map_err(out_of_range)?;
        if force > gross {
            return Err(NumericError::OutOfRange(format!(
                "F = {} N is beyond F_gross = 2 b mu P L = {} N: the joint slides through beyond it",
                Compact(force),
                Compact(gross)
            )));
        }
    }
    if forces.windows(2).any(|w| w[1] < w[0]) {
        return Err(NumericError::OutOfRange(
            "the forces of one loading path must not decrease (friction is path-dependent: \
             unloading is another problem)"
                .into(),
        ));
    }
    if mesh.layers == 0 || mesh.layers > MAX_LAYERS {
        return Err(NumericError::OutOfRange(format!(
            "layers = {} is outside 1..={MAX_LAYERS}",
            mesh.layers
        )));
    }
    if mesh.force_increments == 0 {
        return Err(NumericError::OutOfRange(
            "force_increments = 0: at least one increment is needed".into(),
        ));
    }
    let lambda_t1 = decay_rate(&params) * params.inner_thickness;
    if lambda_t1 > MAX_LAMBDA_T1 {
        return Err(NumericError::OutOfRange(format!(
            "K_T = {} MPa/mm is too stiff for the continuum solver: lambda t1 = {:.3} > {}, \
             beyond the stiffest interface it was checked at against CalculiX (K_T = 1e6 on \
             the bundled joint, lambda t1 = 12.2); the interface is then Coulomb-like, and the \
             closed form at K_eff is within 0.9 % of CalculiX there",
            Compact(params.tangential_stiffness),
            lambda_t1,
            MAX_LAMBDA_T1
        )));
    }
    let (pairs, elements) = Grid::counts(&params, mesh);
    if elements > MAX_ELEMENTS {
        return Err(NumericError::OutOfRange(format!(
            "the continuum mesh would have {elements} elements (more than {MAX_ELEMENTS}): at \
             {} layers the elements are {} mm high, and the plates' extensions of 2 (t1 + t2) = \
             {} mm are meshed at that scale; use fewer layers or plates of closer thicknesses",
            mesh.layers,
            Compact(
                (0.5 * params.inner_thickness).min(params.cover_thickness) / mesh.layers as f64
            ),
            Compact(2.0 * (params.inner_thickness + params.cover_thickness)),
        )));
    }
    if pairs > MAX_PAIRS {
        return Err(NumericError::OutOfRange(format!(
            "K_T = {} MPa/mm over L = {} mm needs {} interface node pairs at {} layers (1/lambda \
             = {} mm resolved over the overlap), more than the {MAX_PAIRS} the solver takes; \
             use fewer layers, a smaller K_T or a shorter overlap",
            Compact(params.tangential_stiffness),
            Compact(params.length),
            pairs,
            mesh.layers,
            Compact(1.0 / decay_rate(&params)),
        )));
    }
    let breaks = lap_breaks(&params, mesh.layers);
    let shortest = breaks
        .overlap
        .windows(2)
        .fold(f64::INFINITY, |m, w| m.min(w[1] - w[0]));
    let aspect = breaks.layer / shortest;
    // Also refuses a NaN aspect (no overlap element at all).
    if aspect.is_nan() || aspect > MAX_ASPECT {
        return Err(NumericError::OutOfRange(format!(
            "L = {} mm is too short for the continuum solver against plates this thick: the \
             overlap's elements would be {} times shorter than their height of {} mm (at most \
             {MAX_ASPECT}, beyond which the plane-stress stiffness loses its digits); L must be \
             at least {} mm here",
            Compact(params.length),
            short(aspect),
            short(breaks.layer),
            short(round_up(2.0 * breaks.layer / MAX_ASPECT)),
        )));
    }
    let clamp_sliding = clamping_slide(&params);
    if clamp_sliding > MAX_CLAMPING_SLIDE {
        return Err(NumericError::OutOfRange(format!(
            "mu = {} is too small for the continuum solver on this joint: the clamping \
             pressure's Poisson expansion alone would make the interface slide over nearly all \
             the overlap (nu K_T / (E lambda mu) = {} > {MAX_CLAMPING_SLIDE}), leaving the inner \
             plate no stuck point to hold it; mu must be at least {} here (or K_T lower)",
            Compact(params.friction),
            short(clamp_sliding),
            short(round_up(
                params.friction * clamp_sliding / MAX_CLAMPING_SLIDE
            )),
        )));
    }
    let grid = Grid::new(&params, mesh);
    let band = grid.unknowns as f64 * (grid.bandwidth + 1) as f64;
    if band > MAX_BAND_ENTRIES {
        return Err(NumericError::OutOfRange(format!(
            "the continuum mesh's stiffness would hold {} entries ({} unknowns, half-bandwidth \
             {}), more than {}: use fewer layers",
            Compact(band),
            grid.unknowns,
            grid.bandwidth,
            Compact(MAX_BAND_ENTRIES)
        )));
    }
    let condensed = Condensed::new(&grid, &params)?;
    let top = forces.iter().fold(0.0_f64, |m, f| m.max(*f));
    let mut model = Reduced::new(&condensed, &params, top);
    // Step 1: P alone (the load parameter scales P from 0 to 1), one increment.
    let mut iterations = model.step(1.0).map_err(|e| {
        NumericError::Unsolved(format!(
            "the continuum's clamping step (P = {} MPa alone) could not be solved: {}",
            Compact(params.pressure),
            why(&e)
        ))
    })?;
    let clamped = model.state();
    // Step 2: F from 0 in equal increments between the requested forces (the load parameter
    // is F in N).
    model.start_force_step();
    let stick = model.stick_limit();
    let mut states = Vec::with_capacity(forces.len());
    let mut increments = 0;
    for &force in forces {
        let from = model.load;
        let slip_from_clamp = if force <= stick {
            // Below first slip the answer is the clamped state plus F times the unit-force
            // solution, exactly: no increment can lose F's digits against the clamping state.
            increments += 1;
            model.stick_at(&clamped, force)
        } else {
            let steps =
                (((force - from) / gross * mesh.force_increments as f64).ceil() as usize).max(1);
            for i in 1..=steps {
                let target = if i == steps {
                    force
                } else {
                    from + (force - from) * i as f64 / steps as f64
                };
                iterations += model
                    .step_with_cuts(target, MAX_CUTS)
                    .map_err(|e| unsolved_force_step(&params, &model, force, &e))?;
            }
            increments += steps;
            model
                .slip
                .iter()
                .zip(&clamped.slip)
                .map(|(s, s0)| s - s0)
                .collect()
        };
        let result = model.result(&grid, &clamped, &slip_from_clamp, increments, iterations);
        let finite = result.delta.is_finite()
            && result.clamping_delta.is_finite()
            && [&result.slip, &result.shear, &result.contact_pressure]
                .iter()
                .all(|v| v.iter().all(|(_, y)| y.is_finite()));
        if !finite {
            return Err(NumericError::NoConvergence {
                load: force,
                cuts: 0,
            });
        }
        // The inner plate's half is held by the interface alone: the transferred force must be
        // F/2. A very soft interface holds it so weakly against its rigid sliding that the
        // condensed system loses digits (K_T = 1e-6 MPa/mm on the bundled joint: 7.5e-5 of F/2);
        // such an answer is refused rather than returned (every number is finite by now).
        let imbalance = (result.transferred_force - 0.5 * force).abs();
        let allowed = EQUILIBRIUM_TOLERANCE * (0.5 * force + 0.5 * gross);
        if imbalance > allowed {
            return Err(NumericError::OutOfRange(format!(
                "K_T = {} MPa/mm: the continuum solution lost precision (the interface carries \
                 {} N where equilibrium needs F/2 = {} N, off by more than {} of it); the \
                 interface is too soft against the plates (E1 t1 = {} N/mm) for the condensed \
                 solve",
                Compact(params.tangential_stiffness),
                Compact(result.transferred_force),
                Compact(0.5 * force),
                Compact(EQUILIBRIUM_TOLERANCE),
                Compact(params.inner_stiffness()),
            )));
        }
        states.push(result);
    }
    Ok(states)
}

/// Why the force step failed beyond the committed state of `model`, on the way to `force` (N).
fn unsolved_force_step(
    params: &LapParams,
    model: &Reduced<'_>,
    force: f64,
    e: &NumericError,
) -> NumericError {
    let open = model.contact_forces().iter().filter(|c| **c < 0.0).count();
    let gross = params.gross_slip_force();
    let cause = if open > 0 {
        format!(
            "{open} of {} pairs would open there, held by the tie: the covers lift off as mu \
             (t1/2 + t2) / L = {} grows",
            model.c.pairs,
            short(
                params.friction * (0.5 * params.inner_thickness + params.cover_thickness)
                    / params.length
            )
        )
    } else {
        format!(
            "{} N is {} % below F_gross = 2 b mu P L = {} N, but the continuum's own \
             gross-slip force is lower: the held cover end carries part of the clamping force",
            short(model.load),
            short(100.0 * (1.0 - model.load / gross)),
            Compact(gross)
        )
    };
    NumericError::Unsolved(format!(
        "the continuum could not be solved beyond F = {} N on the way to {} N ({}; {cause})",
        short(model.load),
        Compact(force),
        why(e)
    ))
}

/// `x` rounded up to three significant digits: a least value to advise, which the advice
/// must not undercut.
fn round_up(x: f64) -> f64 {
    let unit = 10f64.powf(x.abs().log10().floor() - 2.0);
    (x / unit).ceil() * unit
}

/// What a failed increment means, in the solver's own terms (the shared error's "load" is the
/// clamping step's fraction of P or F in N, and its cuts are this solver's halvings).
fn why(e: &NumericError) -> String {
    match e {
        NumericError::NoConvergence { cuts, .. } => format!(
            "the contact forces did not settle, even after {cuts} halvings of the load increment"
        ),
        NumericError::Singular(row) => {
            format!("the interface's tangent stiffness was singular (row {row})")
        }
        other => other.to_string(),
    }
}

/// nu K_T / (E lambda mu), E the softer plate's modulus: the slip the clamping pressure's
/// Poisson strain nu P / E demands over the shear-lag length 1/lambda, over the saturation slip
/// mu P / K_T (P cancels). Where it is large, P alone makes nearly every pair slide; the inner
/// plate, held only by the interface, then has no stuck pair to fix its position and the
/// condensed tangent is singular along its rigid sliding. Measured on the bundled joint (K_T =
/// 1e2, 1e3, 1e4 MPa/mm): solved up to 166 to 210, failed from 332 to 350 on.
fn clamping_slide(p: &LapParams) -> f64 {
    let modulus = p.inner_modulus.min(p.cover_modulus);
    LAP_POISSON * p.tangential_stiffness / (modulus * decay_rate(p) * p.friction)
}

/// lambda = sqrt(2 K_T (1/(E1 t1) + 1/(2 E2 t2))) (1/mm): the rate at which the elastic slip
/// decays from a loaded end in the shear-lag theory, docs/theory.md (L2). Only the mesh grading
/// and the stiffness limit use it (a material length scale, not a closed-form result).
fn decay_rate(p: &LapParams) -> f64 {
    let c = 1.0 / p.inner_stiffness() + 1.0 / p.covers_stiffness();
    (2.0 * c * p.tangential_stiffness).sqrt()
}

/// The element boundaries along x of the joint's continuum model, shared by this solver and the
/// CalculiX deck (`fe::lap_deck`) so that the two mesh the joint the same way.
#[derive(Debug, Clone, PartialEq)]
pub struct LapBreaks {
    /// Over the overlap [0, L], finest at both ends.
    pub overlap: Vec<f64>,
    /// The cover's extension [-H, 0], finest at x = 0 (H = 2 (t1 + t2)).
    pub cover_extension: Vec<f64>,
    /// The inner plate's extension [L, L + H], finest at x = L.
    pub inner_extension: Vec<f64>,
    /// The layer height: the thinner of t1/2 and t2 over `layers` (mm).
    pub layer: f64,
    /// The element size at the overlap's ends (mm).
    pub finest: f64,
}

/// The sizes behind the joint's mesh of `layers` elements through each body (its K_T sets the
/// decay length): finest at the overlap's ends, where the shear peaks, two thirds of a layer or a
/// quarter of the decay length; the coarsest half a decay length, at most 8/3 layers; the
/// extensions up to four times that, all growing by [`GROWTH`]. One function for the breaks and
/// their count, so that a mesh is counted exactly as it would be built.
struct LapSizing {
    layer: f64,
    finest: f64,
    coarsest: f64,
    extension: f64,
}

fn lap_sizing(p: &LapParams, layers: usize) -> LapSizing {
    let layer = (0.5 * p.inner_thickness / layers as f64).min(p.cover_thickness / layers as f64);
    let decay = 1.0 / decay_rate(p);
    let finest = (2.0 / 3.0 * layer).min(0.25 * decay);
    LapSizing {
        layer,
        finest,
        coarsest: (8.0 / 3.0 * layer).min(0.5 * decay).max(finest),
        extension: 2.0 * (p.inner_thickness + p.cover_thickness),
    }
}

/// The number of elements along x of the joint's mesh ([`lap_breaks`]), counted without making
/// it: a stiff interface over a long overlap asks for 1e13 of them, which must be refused by
/// their count before anything of that size is allocated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapCounts {
    /// Elements over half the overlap.
    pub half_overlap: f64,
    /// Elements over the cover's extension.
    pub cover_extension: f64,
    /// Elements over the inner plate's extension.
    pub inner_extension: f64,
}

impl LapCounts {
    /// Elements along the inner plate (the overlap and its extension).
    pub(crate) fn inner(&self) -> f64 {
        2.0 * self.half_overlap + self.inner_extension
    }

    /// Elements along the cover (its extension and the overlap).
    pub(crate) fn cover(&self) -> f64 {
        self.cover_extension + 2.0 * self.half_overlap
    }

    /// Elements of both bodies, `layers` deep each.
    pub fn elements(&self, layers: usize) -> f64 {
        (self.inner() + self.cover()) * layers as f64
    }
}

/// The counts of [`lap_breaks`]`(p, layers)`, with no allocation that grows with them.
pub fn lap_counts(p: &LapParams, layers: usize) -> LapCounts {
    use crate::numeric::mesh::graded_toward_end_count as count;
    let LapSizing {
        finest,
        coarsest,
        extension,
        ..
    } = lap_sizing(p, layers);
    let length = p.length;
    LapCounts {
        half_overlap: count(0.5 * length, length, finest, coarsest, GROWTH),
        cover_extension: count(-extension, 0.0, finest, 4.0 * coarsest, GROWTH),
        inner_extension: count(length, length + extension, finest, 4.0 * coarsest, GROWTH),
    }
}

/// The element boundaries of the joint `p` with `layers` elements through each body, sized by
/// `lap_sizing`. Count them first ([`lap_counts`]): nothing here bounds their number.
pub fn lap_breaks(p: &LapParams, layers: usize) -> LapBreaks {
    let LapSizing {
        layer,
        finest,
        coarsest,
        extension,
    } = lap_sizing(p, layers);
    let length = p.length;
    let right = graded_toward_end(0.5 * length, length, finest, coarsest, GROWTH);
    let mut overlap: Vec<f64> = right.iter().rev().map(|x| length - x).collect();
    overlap.pop();
    overlap.extend(&right);
    let cover_extension = graded_toward_end(-extension, 0.0, finest, 4.0 * coarsest, GROWTH);
    let inner_extension: Vec<f64> =
        graded_toward_end(length, length + extension, finest, 4.0 * coarsest, GROWTH)
            .iter()
            .rev()
            .map(|x| 2.0 * length + extension - x)
            .collect();
    LapBreaks {
        overlap,
        cover_extension,
        inner_extension,
        layer,
        finest,
    }
}

/// One body's mesh: element boundaries and the unknowns of its half-grid points.
#[derive(Debug, Clone)]
struct Body {
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// The global half-grid column of the body's first column.
    first_column: usize,
    /// (u, v) unknowns of each half-grid point, column by column; `None` at element centres.
    dofs: Vec<Option<[usize; 2]>>,
    elasticity: Elasticity,
}

impl Body {
    fn new(xs: Vec<f64>, ys: Vec<f64>, first_column: usize, modulus: f64) -> Body {
        let points = (2 * xs.len() - 1) * (2 * ys.len() - 1);
        Body {
            xs,
            ys,
            first_column,
            dofs: vec![None; points],
            elasticity: plane_stress(modulus, LAP_POISSON),
        }
    }

    fn columns(&self) -> usize {
        2 * self.xs.len() - 1
    }

    fn rows(&self) -> usize {
        2 * self.ys.len() - 1
    }

    fn dof(&self, i: usize, j: usize) -> [usize; 2] {
        self.dofs[i * self.rows() + j].expect("corner and midside points are nodes")
    }

    /// The 16 unknowns of element (ex, ey): (u, v) of each Q8 node.
    fn element_dofs(&self, ex: usize, ey: usize) -> [usize; 16] {
        let mut dofs = [0; 16];
        for (k, &(a, b)) in Q8.iter().enumerate() {
            let [u, v] = self.dof(2 * ex + a, 2 * ey + b);
            dofs[2 * k] = u;
            dofs[2 * k + 1] = v;
        }
        dofs
    }

    fn element_stiffness(&self, ex: usize, ey: usize) -> [[f64; 16]; 16] {
        q8_stiffness(
            self.xs[ex + 1] - self.xs[ex],
            self.ys[ey + 1] - self.ys[ey],
            &self.elasticity,
        )
    }

    /// Simpson weights of the half-grid points along a row of boundaries `breaks` (each
    /// element's length times 1/6, 4/6, 1/6): a uniform traction's consistent nodal loads, and
    /// each point's share of the edge.
    fn edge_weights(breaks: &[f64]) -> Vec<f64> {
        let mut w = vec![0.0; 2 * breaks.len() - 1];
        for (e, pair) in breaks.windows(2).enumerate() {
            let length = pair[1] - pair[0];
            for (k, share) in EDGE_WEIGHTS.iter().enumerate() {
                w[2 * e + k] += share * length;
            }
        }
        w
    }
}

/// Both bodies and the interface.
#[derive(Debug, Clone)]
struct Grid {
    inner: Body,
    cover: Body,
    /// Elements along the overlap.
    overlap_elements: usize,
    unknowns: usize,
    bandwidth: usize,
    /// Fixed unknowns: v on the symmetry plane, u and v on the cover's held end.
    fixed: Vec<usize>,
    /// x (mm) and share of the face (mm per mm of width) of each interface pair.
    pair_x: Vec<f64>,
    pair_weights: Vec<f64>,
}

impl Grid {
    /// The number of interface pairs and of elements the mesh would have, without building it.
    fn counts(p: &LapParams, mesh: LapContinuumMesh) -> (usize, usize) {
        let counts = lap_counts(p, mesh.layers);
        // 2 half overlaps, 2 pairs per element and one more.
        let pairs = 4.0 * counts.half_overlap + 1.0;
        let elements = counts.elements(mesh.layers);
        let whole = |x: f64| {
            if x.is_finite() && x < usize::MAX as f64 {
                x as usize
            } else {
                usize::MAX
            }
        };
        (whole(pairs), whole(elements))
    }

    fn new(p: &LapParams, mesh: LapContinuumMesh) -> Grid {
        let layers = mesh.layers;
        let LapBreaks {
            overlap,
            cover_extension,
            inner_extension,
            ..
        } = lap_breaks(p, layers);
        let half = 0.5 * p.inner_thickness;
        let ys_inner: Vec<f64> = (0..=layers)
            .map(|j| half * j as f64 / layers as f64)
            .collect();
        let ys_cover: Vec<f64> = (0..=layers)
            .map(|j| half + p.cover_thickness * j as f64 / layers as f64)
            .collect();
        let before = cover_extension.len() - 1;
        let mut xs_cover = cover_extension;
        xs_cover.pop();
        xs_cover.extend(&overlap);
        let mut xs_inner = overlap.clone();
        xs_inner.extend(&inner_extension[1..]);
        let overlap_elements = overlap.len() - 1;
        let mut cover = Body::new(xs_cover, ys_cover, 0, p.cover_modulus);
        let mut inner = Body::new(xs_inner, ys_inner, 2 * before, p.inner_modulus);

        // Column by column across both bodies, the inner plate's points first: the pairs' shared
        // normal unknown is the inner plate's top point's.
        let total = inner.first_column + inner.columns();
        let mut next = 0;
        let top = inner.rows() - 1;
        for g in 0..total {
            if g >= inner.first_column {
                let i = g - inner.first_column;
                for j in 0..inner.rows() {
                    if i % 2 == 1 && j % 2 == 1 {
                        continue;
                    }
                    let rows = inner.rows();
                    inner.dofs[i * rows + j] = Some([next, next + 1]);
                    next += 2;
                }
            }
            if g < cover.columns() {
                for j in 0..cover.rows() {
                    if g % 2 == 1 && j % 2 == 1 {
                        continue;
                    }
                    let rows = cover.rows();
                    if j == 0 && g >= inner.first_column {
                        let [_, v] = inner.dof(g - inner.first_column, top);
                        cover.dofs[g * rows] = Some([next, v]);
                        next += 1;
                    } else {
                        cover.dofs[g * rows + j] = Some([next, next + 1]);
                        next += 2;
                    }
                }
            }
        }
        let mut bandwidth = 0;
        for body in [&inner, &cover] {
            for ex in 0..body.xs.len() - 1 {
                for ey in 0..body.ys.len() - 1 {
                    let dofs = body.element_dofs(ex, ey);
                    let (lo, hi) = dofs
                        .iter()
                        .fold((usize::MAX, 0), |(lo, hi), &d| (lo.min(d), hi.max(d)));
                    bandwidth = bandwidth.max(hi - lo);
                }
            }
        }
        let mut fixed: Vec<usize> = (0..inner.columns()).map(|i| inner.dof(i, 0)[1]).collect();
        for j in 0..cover.rows() {
            fixed.extend(cover.dof(0, j));
        }
        let weights = Body::edge_weights(&overlap);
        let pair_x: Vec<f64> = (0..weights.len())
            .map(|i| {
                if i % 2 == 0 {
                    overlap[i / 2]
                } else {
                    0.5 * (overlap[i / 2] + overlap[i / 2 + 1])
                }
            })
            .collect();
        for i in 0..pair_x.len() {
            let [a, _] = inner.dof(i, top);
            let [b, _] = cover.dof(inner.first_column + i, 0);
            bandwidth = bandwidth.max(a.abs_diff(b));
        }
        Grid {
            inner,
            cover,
            overlap_elements,
            unknowns: next,
            bandwidth,
            fixed,
            pair_x,
            pair_weights: weights,
        }
    }

    fn pairs(&self) -> usize {
        self.pair_x.len()
    }

    /// The inner plate's and the cover's u unknowns of pair `i`.
    fn pair_dofs(&self, i: usize) -> (usize, usize) {
        let top = self.inner.rows() - 1;
        (
            self.inner.dof(i, top)[0],
            self.cover.dof(self.inner.first_column + i, 0)[0],
        )
    }
}

/// The elastic bodies condensed onto the interface pairs: every quantity the interface needs,
/// linear in the loads and in the plastic slips q_i (the pairs' Jenkins forces are
/// t_i = k_i (s_i - q_i)).
struct Condensed {
    pairs: usize,
    /// Jenkins stiffness of each pair, K_T times its share of the face (N/mm per mm of width).
    stiffness: Vec<f64>,
    /// The condensed stiffness S = (B K0^-1 B^T)^-1 (dense, in a full band), the Newton
    /// tangent's elastic part.
    condensed: SymmetricBand,
    /// The same, row major, for the residual's products (plain sums: the residual's terms are
    /// interface forces of the same size, so nothing cancels to below the tolerance).
    condensed_rows: Vec<f64>,
    /// Slip, contact force and Delta reading per unit pressure (MPa) and per newton of F, with
    /// every pair elastic and no plastic slip.
    slip_p: Vec<f64>,
    slip_f: Vec<f64>,
    contact_p: Vec<f64>,
    contact_f: Vec<f64>,
    delta_p: f64,
    delta_f: f64,
    /// Contact force at pair i per unit Jenkins force pair at j ((R K0^-1 B^T)_ij), row major.
    contact_per_pair: Vec<f64>,
    /// Delta reading per unit Jenkins force pair at j.
    delta_per_pair: Vec<f64>,
}

impl Condensed {
    fn new(grid: &Grid, p: &LapParams) -> Result<Condensed, NumericError> {
        let n = grid.unknowns;
        let m = grid.pairs();
        let mut k0 = SymmetricBand::zeros(n, grid.bandwidth);
        // The contact force at each pair: the cover's internal force at the shared normal
        // unknown (nothing else loads it), a sparse row of the cover's stiffness.
        let mut contact_rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); m];
        for (body, is_cover) in [(&grid.inner, false), (&grid.cover, true)] {
            for ex in 0..body.xs.len() - 1 {
                for ey in 0..body.ys.len() - 1 {
                    let k = body.element_stiffness(ex, ey);
                    let dofs = body.element_dofs(ex, ey);
                    for a in 0..16 {
                        for b in 0..=a {
                            k0.add(dofs[a], dofs[b], k[a][b]);
                        }
                    }
                    if is_cover && ey == 0 {
                        for (node, &(a, b)) in Q8.iter().enumerate() {
                            let column = 2 * ex + a;
                            if b != 0 || column < grid.inner.first_column {
                                continue;
                            }
                            let pair = column - grid.inner.first_column;
                            for s in 0..16 {
                                contact_rows[pair].push((dofs[s], k[2 * node + 1][s]));
                            }
                        }
                    }
                }
            }
        }
        let stiffness: Vec<f64> = grid
            .pair_weights
            .iter()
            .map(|w| p.tangential_stiffness * w)
            .collect();
        for (i, k) in stiffness.iter().enumerate() {
            let (a, b) = grid.pair_dofs(i);
            k0.add(a, a, *k);
            k0.add(b, b, *k);
            k0.add(a.max(b), a.min(b), -k);
        }
        for &dof in &grid.fixed {
            k0.fix(dof);
        }
        let factor = k0.factor().map_err(|e| NumericError::Singular(e.row))?;

        // Right-hand sides: the m unit pair loads (+1 on the inner plate's u, -1 on the cover's),
        // then P = 1 on the cover's outer face over the overlap, then F = 1 N; solved in blocks
        // of CHUNK columns (the block is n x CHUNK), each solution kept only through its
        // readings: the pair slips, the contact forces, Delta.
        let total = m + 2;
        let cover_top = grid.cover.rows() - 1;
        let end = grid.inner.columns() - 1;
        let traction = 1.0 / (p.width * p.inner_thickness);
        let inner_end = 2 * grid.overlap_elements;
        let inner_mean = Body::edge_weights(&grid.inner.ys);
        let cover_mean = Body::edge_weights(&grid.cover.ys);
        let (h1, h2) = (0.5 * p.inner_thickness, p.cover_thickness);
        let mut slips: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut contacts: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut deltas: Vec<f64> = Vec::with_capacity(total);
        for first in (0..total).step_by(CHUNK) {
            let columns = CHUNK.min(total - first);
            let mut rhs = vec![0.0; n * columns];
            for c in 0..columns {
                let column = first + c;
                if column < m {
                    let (a, b) = grid.pair_dofs(column);
                    rhs[a * columns + c] = 1.0;
                    rhs[b * columns + c] = -1.0;
                } else if column == m {
                    for (i, w) in grid.pair_weights.iter().enumerate() {
                        let [_, v] = grid.cover.dof(grid.inner.first_column + i, cover_top);
                        rhs[v * columns + c] -= w;
                    }
                } else {
                    for (j, w) in inner_mean.iter().enumerate() {
                        let [u, _] = grid.inner.dof(end, j);
                        rhs[u * columns + c] += traction * w;
                    }
                }
            }
            factor.solve_many(&mut rhs, columns);
            let at = |dof: usize, c: usize| rhs[dof * columns + c];
            for c in 0..columns {
                slips.push(
                    (0..m)
                        .map(|i| {
                            let (a, b) = grid.pair_dofs(i);
                            at(a, c) - at(b, c)
                        })
                        .collect(),
                );
                contacts.push(
                    contact_rows
                        .iter()
                        .map(|row| row.iter().map(|&(d, k)| k * at(d, c)).sum())
                        .collect(),
                );
                let inner: f64 = inner_mean
                    .iter()
                    .enumerate()
                    .map(|(j, w)| w * at(grid.inner.dof(inner_end, j)[0], c))
                    .sum();
                let cover: f64 = cover_mean
                    .iter()
                    .enumerate()
                    .map(|(j, w)| w * at(grid.cover.dof(grid.inner.first_column, j)[0], c))
                    .sum();
                deltas.push(inner / h1 - cover / h2);
            }
        }
        let slip_f = slips.pop().unwrap_or_default();
        let slip_p = slips.pop().unwrap_or_default();
        let contact_f = contacts.pop().unwrap_or_default();
        let contact_p = contacts.pop().unwrap_or_default();
        let delta_f = deltas.pop().unwrap_or_default();
        let delta_p = deltas.pop().unwrap_or_default();

        // C = B K0^-1 B^T, symmetrized against round-off, and its inverse.
        let mut flexibility = SymmetricBand::zeros(m, m.saturating_sub(1));
        for (i, row) in slips.iter().enumerate() {
            for (j, column) in slips.iter().enumerate().take(i + 1) {
                flexibility.add(i, j, 0.5 * (column[i] + row[j]));
            }
        }
        let flexibility = flexibility
            .factor()
            .map_err(|e| NumericError::Singular(e.row))?;
        let mut inverse = vec![0.0; m * m];
        for i in 0..m {
            inverse[i * m + i] = 1.0;
        }
        flexibility.solve_many(&mut inverse, m);
        let mut condensed = SymmetricBand::zeros(m, m.saturating_sub(1));
        let mut condensed_rows = vec![0.0; m * m];
        for i in 0..m {
            for j in 0..=i {
                let value = 0.5 * (inverse[i * m + j] + inverse[j * m + i]);
                condensed.add(i, j, value);
                condensed_rows[i * m + j] = value;
                condensed_rows[j * m + i] = value;
            }
        }
        let mut contact_per_pair = vec![0.0; m * m];
        for (j, column) in contacts.iter().enumerate() {
            for (i, c) in column.iter().enumerate() {
                contact_per_pair[i * m + j] = *c;
            }
        }
        Ok(Condensed {
            pairs: m,
            stiffness,
            condensed,
            condensed_rows,
            slip_p,
            slip_f,
            contact_p,
            contact_f,
            delta_p,
            delta_f,
            contact_per_pair,
            delta_per_pair: deltas,
        })
    }
}

/// The interface problem on the m pair slips at given strengths: the Newton driver's model.
struct Reduced<'a> {
    c: &'a Condensed,
    friction: f64,
    pressure: f64,
    /// The slips of the loads with every pair elastic and no plastic slip: base + load x unit.
    base: Vec<f64>,
    unit: Vec<f64>,
    /// Contact forces and Delta the same way.
    contact_base: Vec<f64>,
    contact_unit: Vec<f64>,
    delta_base: f64,
    delta_unit: f64,
    /// Jenkins strengths, mu times the contact forces of the fixed point's last iterate.
    strengths: Vec<f64>,
    points: Vec<InterfacePoint>,
    slip: Vec<f64>,
    load: f64,
    /// Residual scale (N/mm): the clamping force per width plus the transferred force per width.
    scale: f64,
    /// Joint width b (mm).
    width: f64,
    /// Delta's reading at the end of the clamping step (mm).
    clamping_delta: f64,
    /// The factored tangent and the sliding set it belongs to: the tangent S + diag(k_t - k)
    /// depends on nothing else, and the fixed point's solves mostly repeat the set.
    factor: RefCell<Option<(Vec<bool>, BandCholesky)>>,
}

/// A committed state of [`Reduced`], to restart an increment from.
#[derive(Debug, Clone)]
struct State {
    points: Vec<InterfacePoint>,
    slip: Vec<f64>,
    load: f64,
}

impl<'a> Reduced<'a> {
    fn new(c: &'a Condensed, p: &LapParams, force: f64) -> Reduced<'a> {
        let m = c.pairs;
        let scale = p.pressure * p.length + force / (2.0 * p.width);
        Reduced {
            c,
            friction: p.friction,
            pressure: p.pressure,
            base: vec![0.0; m],
            unit: c.slip_p.iter().map(|s| s * p.pressure).collect(),
            contact_base: vec![0.0; m],
            contact_unit: c.contact_p.iter().map(|s| s * p.pressure).collect(),
            delta_base: 0.0,
            delta_unit: c.delta_p * p.pressure,
            strengths: vec![0.0; m],
            points: vec![InterfacePoint::default(); m],
            slip: vec![0.0; m],
            load: 0.0,
            scale,
            width: p.width,
            clamping_delta: 0.0,
            factor: RefCell::new(None),
        }
    }

    /// After the clamping step: P held, the load parameter becomes F (N) from 0.
    fn start_force_step(&mut self) {
        self.clamping_delta = self.delta();
        let p = self.pressure;
        self.base = self.c.slip_p.iter().map(|s| s * p).collect();
        self.unit = self.c.slip_f.clone();
        self.contact_base = self.c.contact_p.iter().map(|s| s * p).collect();
        self.contact_unit = self.c.contact_f.clone();
        self.delta_base = self.c.delta_p * p;
        self.delta_unit = self.c.delta_f;
        self.load = 0.0;
    }

    fn state(&self) -> State {
        State {
            points: self.points.clone(),
            slip: self.slip.clone(),
            load: self.load,
        }
    }

    fn restore(&mut self, state: &State) {
        self.points.clone_from(&state.points);
        self.slip.clone_from(&state.slip);
        self.load = state.load;
    }

    /// The plastic slips q_i (mm) of the committed state.
    fn plastic(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.plastic_slip)
    }

    /// The contact forces of the committed state (N per mm of width): linear in the load and the
    /// pairs' Jenkins forces t_j = k_j (s_j - q_j). With t = S (s_f - s) the body's answer to the
    /// pair forces, the contact is the elastic contact minus R K0^-1 B^T times (t - k s) = -k q.
    fn contact_forces(&self) -> Vec<f64> {
        let m = self.c.pairs;
        let kq: Vec<f64> = self
            .plastic()
            .zip(&self.c.stiffness)
            .map(|(q, k)| k * q)
            .collect();
        (0..m)
            .map(|i| {
                let row = &self.c.contact_per_pair[i * m..(i + 1) * m];
                self.contact_base[i]
                    + self.load * self.contact_unit[i]
                    + row.iter().zip(&kq).map(|(a, b)| a * b).sum::<f64>()
            })
            .collect()
    }

    fn delta(&self) -> f64 {
        self.delta_base
            + self.load * self.delta_unit
            + self
                .plastic()
                .zip(&self.c.stiffness)
                .zip(&self.c.delta_per_pair)
                .map(|((q, k), d)| d * k * q)
                .sum::<f64>()
    }

    /// One increment to `load`; when its fixed point fails (nothing is committed then), two
    /// half increments, down to `cuts_left` halvings: a closer start is what the fixed point
    /// needs where the covers lift off (mu = 4 near 0.5 F_gross on the bundled joint, issue 36).
    fn step_with_cuts(&mut self, load: f64, cuts_left: u32) -> Result<usize, NumericError> {
        let start = self.state();
        match self.step(load) {
            Err(NumericError::NoConvergence { .. }) if cuts_left > 0 => {
                self.restore(&start);
                let middle = 0.5 * (self.load + load);
                let first = self.step_with_cuts(middle, cuts_left - 1)?;
                Ok(first + self.step_with_cuts(load, cuts_left - 1)?)
            }
            Err(NumericError::NoConvergence { .. }) => {
                self.restore(&start);
                Err(NumericError::NoConvergence {
                    load,
                    cuts: MAX_CUTS,
                })
            }
            other => other,
        }
    }

    /// One increment to `load`: the fixed point on the contact forces, each iterate solved by
    /// Newton from the state committed at the previous increment. Returns the iterations.
    fn step(&mut self, load: f64) -> Result<usize, NumericError> {
        let start = self.state();
        // First guess: the contact forces at the start of the increment, moved elastically.
        let mut contact: Vec<f64> = self
            .contact_forces()
            .iter()
            .zip(&self.contact_unit)
            .map(|(c, u)| c + (load - self.load) * u)
            .collect();
        let mut guess: Option<Vec<f64>> = None;
        // Aitken's relaxation of the contact forces (Irons and Tuck): each update moves by
        // omega times the change, omega from the last two changes r: omega_n = -omega_(n-1)
        // r_(n-1).(r_n - r_(n-1)) / |r_n - r_(n-1)|^2, the secant estimate of the best step along
        // them. The plain iteration (omega = 1) contracts slowly where mu is large (0.85 per
        // iteration at mu = 2) and falls into a two-state cycle with wide lift-off (mu = 5 on
        // the bundled joint), issue 36.
        let mut relaxation: f64 = 1.0;
        let mut previous: Option<Vec<f64>> = None;
        for iteration in 1..=MAX_CONTACT_ITERATIONS {
            self.restore(&start);
            // Newton starts from the last iterate's slips (the history is the increment's start).
            if let Some(slip) = guess.take() {
                self.slip = slip;
            }
            self.strengths = contact.iter().map(|c| self.friction * c.max(0.0)).collect();
            newton::load_to(self, load, 1)?;
            let next = self.contact_forces();
            let scale = next.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
            let change = next
                .iter()
                .zip(&contact)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            let residual: Vec<f64> = next.iter().zip(&contact).map(|(n, c)| n - c).collect();
            if let Some(last) = &previous {
                let (mut along, mut norm) = (0.0, 0.0);
                for (r, l) in residual.iter().zip(last) {
                    along += l * (r - l);
                    norm += (r - l) * (r - l);
                }
                if norm > 0.0 {
                    relaxation = (-relaxation * along / norm).clamp(MIN_RELAXATION, MAX_RELAXATION);
                }
            }
            for (c, r) in contact.iter_mut().zip(&residual) {
                *c += relaxation * r;
            }
            previous = Some(residual);
            guess = Some(self.slip.clone());
            if change <= CONTACT_TOLERANCE * scale {
                // The strengths of the converged contact forces (a last Newton solve would move
                // nothing beyond the tolerance).
                return Ok(iteration);
            }
        }
        Err(NumericError::NoConvergence { load, cuts: 0 })
    }

    /// The largest force F (N) up to which, from the clamped state, every pair sticks: the
    /// plastic slips stay those of the clamping step, and the answer is linear in F. With them
    /// fixed, the condensed equilibrium S (s - s_P - F s_F) = k q has the solution
    /// s = s_clamped + F s_F, so each pair's Jenkins force is t_c + F k s_F and its contact force
    /// c_c + F c_F: the pair sticks while |t_c + F k s_F| <= mu (c_c + F c_F), two inequalities
    /// linear in F. A pair already at its strength and loaded further gives 0.
    fn stick_limit(&self) -> f64 {
        let contact = self.contact_forces();
        let mut limit = f64::INFINITY;
        for (i, c) in contact.iter().enumerate() {
            let k = self.c.stiffness[i];
            let shear = k * (self.slip[i] - self.points[i].plastic_slip);
            let rate = k * self.unit[i];
            let (strength, strength_rate) =
                (self.friction * c, self.friction * self.contact_unit[i]);
            // g(F) = g0 + F g1 <= 0 for tau - strength and -tau - strength.
            for (g0, g1) in [
                (shear - strength, rate - strength_rate),
                (-shear - strength, -rate - strength_rate),
            ] {
                if g1 > 0.0 {
                    limit = limit.min((-g0).max(0.0) / g1);
                }
            }
        }
        limit
    }

    /// Commits the stick state at `force` (N, at most [`Reduced::stick_limit`]) after the
    /// clamping state `clamped`; returns the slips from the clamped state, F s_F, computed as
    /// such rather than as a difference of two nearly equal totals.
    fn stick_at(&mut self, clamped: &State, force: f64) -> Vec<f64> {
        let increment: Vec<f64> = self.unit.iter().map(|u| force * u).collect();
        self.restore(clamped);
        self.slip = clamped
            .slip
            .iter()
            .zip(&increment)
            .map(|(s, ds)| s + ds)
            .collect();
        self.load = force;
        increment
    }

    /// The state's answer; `slip_from_clamp` is s - s_clamped at each pair (mm).
    fn result(
        &self,
        grid: &Grid,
        clamped: &State,
        slip_from_clamp: &[f64],
        increments: usize,
        iterations: usize,
    ) -> ContinuumLap {
        let c = self.c;
        let contact = self.contact_forces();
        let weights = &grid.pair_weights;
        let xs = &grid.pair_x;
        let slip: Vec<(f64, f64)> = xs
            .iter()
            .zip(slip_from_clamp)
            .map(|(&x, ds)| (x, *ds))
            .collect();
        let forces: Vec<f64> = self
            .slip
            .iter()
            .zip(self.plastic())
            .zip(&c.stiffness)
            .map(|((s, q), k)| k * (s - q))
            .collect();
        let shear: Vec<(f64, f64)> = xs
            .iter()
            .zip(forces.iter().zip(weights))
            .map(|(&x, (t, w))| (x, t / w))
            .collect();
        let contact_pressure: Vec<(f64, f64)> = xs
            .iter()
            .zip(contact.iter().zip(weights))
            .map(|(&x, (n, w))| (x, n / w))
            .collect();
        let length = *xs.last().unwrap_or(&0.0);
        // Nominal: K_T |s| >= mu P, P the nominal pressure, slip from the clamped state.
        let saturation = self.friction * self.pressure;
        let nominal = |order: &mut dyn Iterator<Item = usize>| -> f64 {
            let mut previous: Option<(f64, f64)> = None;
            for i in order {
                let (x, s) = slip[i];
                let level = c.stiffness[i] / weights[i] * s.abs();
                if level < saturation {
                    return match previous {
                        None => x,
                        Some((x0, l0)) => x0 + (x - x0) * (saturation - l0) / (level - l0),
                    };
                }
                previous = Some((x, level));
            }
            previous.map_or(0.0, |(x, _)| x)
        };
        let from_start = nominal(&mut (0..slip.len()));
        let from_end = length - nominal(&mut (0..slip.len()).rev());
        let nominal_zones = SlidingZones {
            from_inner_end: from_start,
            from_cover_ends: from_end,
        };
        // Local: |tau| >= (1 - 1e-3) mu p, at node resolution.
        let sliding = |i: usize| {
            let p = contact_pressure[i].1;
            p > 0.0 && shear[i].1.abs() >= (1.0 - LOCAL_SLIDING) * self.friction * p
        };
        let last_of_run = |order: &mut dyn Iterator<Item = usize>| -> Option<usize> {
            let mut last = None;
            for i in order {
                if !sliding(i) {
                    break;
                }
                last = Some(i);
            }
            last
        };
        let local_zones = SlidingZones {
            from_inner_end: last_of_run(&mut (0..xs.len())).map_or(0.0, |i| xs[i]),
            from_cover_ends: last_of_run(&mut (0..xs.len()).rev()).map_or(0.0, |i| length - xs[i]),
        };
        // Delta from the clamped state as F s_F's reading plus the plastic slips' change, not as
        // a difference of totals: P alone gives about 1.7e-3 mm on the bundled joint, whose
        // round-off (4e-19 mm) swallowed Delta at F = 1e-14 N (issue 36).
        let delta = self.load * self.delta_unit
            + self
                .plastic()
                .zip(clamped.points.iter())
                .zip(&c.stiffness)
                .zip(&c.delta_per_pair)
                .map(|(((q, q0), k), d)| d * k * (q - q0.plastic_slip))
                .sum::<f64>();
        ContinuumLap {
            force: self.load,
            delta,
            clamping_delta: self.clamping_delta,
            separated: contact
                .iter()
                .zip(xs)
                .filter(|(n, _)| **n < 0.0)
                .map(|(_, &x)| x)
                .collect(),
            transferred_force: self.width * forces.iter().sum::<f64>(),
            slip,
            shear,
            contact_pressure,
            nominal_zones,
            local_zones,
            increments,
            iterations,
            pairs: c.pairs,
        }
    }
}

impl Discretized for Reduced<'_> {
    const RESIDUAL_TOLERANCE: f64 = 1e-11;

    fn load(&self) -> f64 {
        self.load
    }

    fn displacement(&self) -> &[f64] {
        &self.slip
    }

    fn load_scale(&self, _load: f64) -> f64 {
        self.scale
    }

    fn linearize(&self, slip: &[f64], load: f64) -> (Vec<f64>, SymmetricBand, Vec<Response>) {
        let m = self.c.pairs;
        let responses: Vec<Response> = (0..m)
            .map(|i| self.points[i].respond(slip[i], self.c.stiffness[i], self.strengths[i]))
            .collect();
        // S (s - s_f) + (t - k s): the body's reaction to the slips plus the Jenkins forces
        // beyond the elastic springs already inside S.
        let offset: Vec<f64> = (0..m)
            .map(|i| slip[i] - self.base[i] - load * self.unit[i])
            .collect();
        let mut residual: Vec<f64> = self
            .c
            .condensed_rows
            .chunks_exact(m.max(1))
            .map(|row| row.iter().zip(&offset).map(|(a, b)| a * b).sum())
            .collect();
        let mut tangent = self.c.condensed.clone();
        for (i, r) in responses.iter().enumerate() {
            let k = self.c.stiffness[i];
            residual[i] += r.stress - k * slip[i];
            tangent.add(i, i, r.tangent - k);
        }
        (residual, tangent, responses)
    }

    fn commit(&mut self, slip: Vec<f64>, responses: Vec<Response>, load: f64) {
        for (point, response) in self.points.iter_mut().zip(&responses) {
            point.plastic_slip = response.plastic_slip;
        }
        self.slip = slip;
        self.load = load;
    }

    fn solve_step(
        &self,
        tangent: SymmetricBand,
        rhs: &[f64],
        responses: &[Response],
    ) -> Result<Vec<f64>, NotPositiveDefinite> {
        let sliding: Vec<bool> = responses.iter().map(|r| r.sliding).collect();
        let mut cache = self.factor.borrow_mut();
        if let Some((set, factor)) = cache.as_ref()
            && *set == sliding
        {
            return Ok(factor.solve(rhs));
        }
        let factor = tangent.factor()?;
        let step = factor.solve(rhs);
        *cache = Some((sliding, factor));
        Ok(step)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const JOINT: LapParams = LapParams::ALUMINIUM;

    fn with_stiffness(kt: f64) -> LapParams {
        LapParams {
            tangential_stiffness: kt,
            ..JOINT
        }
    }

    #[test]
    fn the_grid_numbers_every_unknown_once_and_counts_its_pairs_before_building() {
        for (kt, layers) in [(1e3, 4), (1e5, 4), (1e3, 2), (300.0, 3)] {
            let params = with_stiffness(kt);
            let mesh = LapContinuumMesh {
                layers,
                ..LapContinuumMesh::default()
            };
            let grid = Grid::new(&params, mesh);
            let (pairs, elements) = Grid::counts(&params, mesh);
            assert_eq!(pairs, grid.pairs());
            let built = layers * (grid.inner.xs.len() + grid.cover.xs.len() - 2);
            assert_eq!(elements, built);
            let mut seen = vec![0; grid.unknowns];
            for body in [&grid.inner, &grid.cover] {
                for dofs in body.dofs.iter().flatten() {
                    for &d in dofs {
                        seen[d] += 1;
                    }
                }
            }
            // Each pair's normal unknown is shared by two nodes; every other is one node's.
            assert_eq!(seen.iter().filter(|&&c| c == 2).count(), grid.pairs());
            assert!(seen.iter().all(|&c| c == 1 || c == 2));
            // The overlap runs over [0, L] in both bodies, with matching nodes.
            assert_eq!(grid.pair_x[0], 0.0);
            assert_eq!(*grid.pair_x.last().unwrap(), params.length);
            let faces: f64 = grid.pair_weights.iter().sum();
            assert!((faces / params.length - 1.0).abs() < 1e-12);
            // The cover's extension reaches x = -H, the inner plate's x = L + H.
            let h = 2.0 * (params.inner_thickness + params.cover_thickness);
            assert_eq!(grid.cover.xs[0], -h);
            assert!((grid.inner.xs.last().unwrap() - params.length - h).abs() < 1e-12);
        }
    }

    #[test]
    fn the_interface_carries_half_the_force_and_no_pair_opens() {
        // The inner plate's half is pulled by F/2 and held only by this interface.
        let states =
            solve_lap_continuum_path(JOINT, &[1000.0, 4000.0], LapContinuumMesh::default())
                .unwrap();
        for state in &states {
            let half = 0.5 * state.force;
            assert!(
                (state.transferred_force / half - 1.0).abs() < 1e-8,
                "{} vs {half}",
                state.transferred_force
            );
            assert!(state.separated.is_empty(), "{:?}", state.separated);
            // The integral of the shear over the face is the same force.
            let grid = Grid::new(&JOINT, LapContinuumMesh::default());
            let integral: f64 = state
                .shear
                .iter()
                .zip(&grid.pair_weights)
                .map(|((_, tau), w)| tau * w)
                .sum::<f64>()
                * JOINT.width;
            assert!((integral / half - 1.0).abs() < 1e-8, "{integral}");
        }
        assert_eq!(states[1].force, 4000.0);
        assert!(states[1].increments > states[0].increments);
    }

    #[test]
    fn below_first_sliding_delta_is_linear_in_f_and_nothing_slides() {
        let mesh = LapContinuumMesh::default();
        let states = solve_lap_continuum_path(JOINT, &[0.0, 250.0, 500.0], mesh).unwrap();
        // Nothing moves at F = 0 beyond the clamped state.
        assert!(states[0].delta.abs() < 1e-15, "{}", states[0].delta);
        assert!(states[0].slip.iter().all(|(_, s)| s.abs() < 1e-15));
        assert!(
            (states[2].delta / states[1].delta - 2.0).abs() < 1e-9,
            "{} {}",
            states[1].delta,
            states[2].delta
        );
        for zones in [states[2].nominal_zones, states[2].local_zones] {
            assert_eq!((zones.from_inner_end, zones.from_cover_ends), (0.0, 0.0));
        }
        // P alone stretches both plates through Poisson (CalculiX: 1.71e-3 mm).
        assert!((states[2].clamping_delta / 1.709e-3 - 1.0).abs() < 1e-3);
    }

    #[test]
    fn the_contact_pressure_redistributes_as_the_covers_bend() {
        // CalculiX (FIRST-LOOK.md section 4): about 6 MPa at x = L and 11 to 14 at x = 0 under
        // load (P = 10); nodal values here, node-to-node in CalculiX's.
        let state = solve_lap_continuum(JOINT, 4500.0, LapContinuumMesh::default()).unwrap();
        let p0 = state.contact_pressure[0].1;
        let pl = state.contact_pressure.last().unwrap().1;
        assert!((11.0..14.0).contains(&p0), "{p0}");
        assert!((5.5..8.0).contains(&pl), "{pl}");
        // Both ends slide, the nominal and local readings within half a millimetre.
        let (n, l) = (state.nominal_zones, state.local_zones);
        assert!(n.from_inner_end > 4.0 && n.from_cover_ends > 9.0, "{n:?}");
        assert!(
            (n.from_inner_end - l.from_inner_end).abs() < 0.5,
            "{n:?} {l:?}"
        );
        assert!(
            (n.from_cover_ends - l.from_cover_ends).abs() < 0.5,
            "{n:?} {l:?}"
        );
    }

    /// Issue 36: across the friction coefficients the tool sends users to the continuum for
    /// (mu outside the envelope's 0.1 to 0.6), up to 0.99 F_gross, the solver answers, in
    /// equilibrium, with Delta growing along the path; a coarse mesh keeps it to seconds.
    #[test]
    fn it_answers_across_the_friction_range_up_to_gross_slip() {
        let mesh = LapContinuumMesh {
            layers: 2,
            force_increments: 8,
        };
        for mu in [2e-3, 0.05, 1.0, 2.0, 5.0] {
            let params = LapParams {
                friction: mu,
                ..JOINT
            };
            let gross = params.gross_slip_force();
            let forces = [0.0, 1e-9 * gross, 0.3 * gross, 0.9 * gross, 0.99 * gross];
            let states = solve_lap_continuum_path(params, &forces, mesh)
                .unwrap_or_else(|e| panic!("mu = {mu}: {e}"));
            let mut last = 0.0;
            for (state, force) in states.iter().zip(forces) {
                assert!(
                    state.delta.is_finite() && state.delta >= last,
                    "mu {mu} F {force}"
                );
                last = state.delta;
                let half = 0.5 * force;
                assert!(
                    (state.transferred_force - half).abs() <= 1e-6 * (half + 0.5 * gross),
                    "mu {mu} F {force}: {}",
                    state.transferred_force
                );
            }
        }
    }

    #[test]
    fn inputs_outside_the_domain_are_refused_with_their_reason() {
        let mesh = LapContinuumMesh::default();
        let message = |params: LapParams, force: f64, mesh: LapContinuumMesh| {
            solve_lap_continuum(params, force, mesh)
                .unwrap_err()
                .to_string()
        };
        assert!(message(JOINT, 6000.5, mesh).contains("F_gross = 2 b mu P L = 6000 N"));
        assert!(message(JOINT, -1.0, mesh).contains('F'));
        assert!(message(JOINT, f64::NAN, mesh).contains('F'));
        let bad = LapParams {
            inner_modulus: f64::NAN,
            ..JOINT
        };
        assert!(message(bad, 1000.0, mesh).contains("E1"));
        let stiff = message(with_stiffness(1e7), 100.0, mesh);
        assert!(
            stiff.contains("K_T = 1e7 MPa/mm") && stiff.contains("lambda t1 = 38.730 > 12.5"),
            "{stiff}"
        );
        let long = LapParams {
            length: 5000.0,
            ..JOINT
        };
        let long = message(long, 100.0, mesh);
        assert!(long.contains("more than the 801"), "{long}");
        for bad_mesh in [
            LapContinuumMesh { layers: 0, ..mesh },
            LapContinuumMesh { layers: 33, ..mesh },
            LapContinuumMesh {
                force_increments: 0,
                ..mesh
            },
        ] {
            assert!(solve_lap_continuum(JOINT, 100.0, bad_mesh).is_err());
        }
        // Plates of very different thicknesses: the thin one sets the element size, the thick
        // one the extensions' length.
        let lopsided = LapParams {
            inner_thickness: 0.02,
            cover_thickness: 500.0,
            length: 1.0,
            ..JOINT
        };
        let lopsided = message(lopsided, 1.0, mesh);
        assert!(
            lopsided.contains("elements (more than 50000)"),
            "{lopsided}"
        );
        // An interface so soft that the condensed solve loses digits is refused, not answered.
        let soft = message(with_stiffness(1e-6), 1800.0, mesh);
        assert!(soft.contains("lost precision"), "{soft}");
        let path = solve_lap_continuum_path(JOINT, &[2000.0, 1000.0], mesh).unwrap_err();
        assert!(path.to_string().contains("must not decrease"), "{path}");
        // Just inside the stiffness limit it solves (lambda t1 = 12.2; a short overlap keeps
        // the mesh small), just outside it is refused.
        let short = LapParams {
            length: 5.0,
            ..with_stiffness(1e6)
        };
        let too_stiff = LapParams {
            tangential_stiffness: 1.1e6,
            ..short
        };
        assert!(message(too_stiff, 100.0, mesh).contains("> 12.5"));
        assert!(solve_lap_continuum(short, 100.0, mesh).is_ok());
    }
}
