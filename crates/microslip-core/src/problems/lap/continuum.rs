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

mod answer;
mod condensed;
mod mesh;

use super::params::{LapParam, LapParams};
use crate::kernel::params::Compact;
use crate::numeric::two_body::{Reduced, check_path};
use crate::numeric::{NumericError, short};
use answer::lap_answer;
use condensed::condense;
use mesh::Grid;

pub use super::params::LAP_POISSON;
pub use mesh::{LapBreaks, LapCounts, lap_breaks, lap_counts};

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

/// Most elements in both bodies together (the mesh is counted before it is built).
const MAX_ELEMENTS: usize = 50_000;

/// Most entries of the banded stiffness (128 MB).
const MAX_BAND_ENTRIES: f64 = 1.6e7;

/// Most elements through each body's thickness.
const MAX_LAYERS: usize = 32;

/// Most height over length of the overlap's elements: L = 1e-3 mm on the bundled joint (375)
/// solves, 1e-4 mm (3750) loses precision and 1e-6 mm gives a singular stiffness.
const MAX_ASPECT: f64 = 500.0;
/// Largest [`clamping_slide`] accepted (measured: solved at 210, failed at 332).
const MAX_CLAMPING_SLIDE: f64 = 200.0;
/// Largest imbalance of the inner plate's half accepted, relative to F/2 + F_gross/2: measured
/// 1.5e-8 at K_T = 0.01 MPa/mm and below 1e-9 from K_T = 1 up on the bundled joint (7.5e-5 at
/// K_T = 1e-6, refused).
const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;

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
    check_path(forces)?;
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
    let band = grid.two.unknowns as f64 * (grid.two.bandwidth + 1) as f64;
    if band > MAX_BAND_ENTRIES {
        return Err(NumericError::OutOfRange(format!(
            "the continuum mesh's stiffness would hold {} entries ({} unknowns, half-bandwidth \
             {}), more than {}: use fewer layers",
            Compact(band),
            grid.two.unknowns,
            grid.two.bandwidth,
            Compact(MAX_BAND_ENTRIES)
        )));
    }
    let condensed = condense(&grid, &params)?;
    let top = forces.iter().fold(0.0_f64, |m, f| m.max(*f));
    let scale = params.pressure * params.length + top / (2.0 * params.width);
    let mut model = Reduced::new(&condensed, params.friction, params.pressure, scale);
    // Step 1: P alone (the load parameter scales P from 0 to 1), one increment.
    let iterations = model.step(1.0).map_err(|e| {
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
    let (mut increments, mut iterations) = (0, iterations);
    for &force in forces {
        let from = model.load;
        let steps =
            (((force - from) / gross * mesh.force_increments as f64).ceil() as usize).max(1);
        let (slip_from_clamp, taken, iterated) = model
            .advance(&clamped, force, stick, steps)
            .map_err(|e| unsolved_force_step(&params, &model, force, &e))?;
        increments += taken;
        iterations += iterated;
        let result = lap_answer(
            &model,
            &grid,
            &clamped,
            &slip_from_clamp,
            (increments, iterations),
            params.width,
        );
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
            assert_eq!(pairs, grid.two.pairs());
            let built = layers * (grid.two.lower.xs.len() + grid.two.upper.xs.len() - 2);
            assert_eq!(elements, built);
            let mut seen = vec![0; grid.two.unknowns];
            for body in [&grid.two.lower, &grid.two.upper] {
                for dofs in body.node_dofs() {
                    for d in dofs {
                        seen[d] += 1;
                    }
                }
            }
            // Each pair's normal unknown is shared by two nodes; every other is one node's.
            assert_eq!(seen.iter().filter(|&&c| c == 2).count(), grid.two.pairs());
            assert!(seen.iter().all(|&c| c == 1 || c == 2));
            // The overlap runs over [0, L] in both bodies, with matching nodes.
            assert_eq!(grid.two.pair_x[0], 0.0);
            assert_eq!(*grid.two.pair_x.last().unwrap(), params.length);
            let faces: f64 = grid.two.pair_weights.iter().sum();
            assert!((faces / params.length - 1.0).abs() < 1e-12);
            // The cover's extension reaches x = -H, the inner plate's x = L + H.
            let h = 2.0 * (params.inner_thickness + params.cover_thickness);
            assert_eq!(grid.two.upper.xs[0], -h);
            assert!((grid.two.lower.xs.last().unwrap() - params.length - h).abs() < 1e-12);
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
                .zip(&grid.two.pair_weights)
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
