//! The press fit as an axisymmetric continuum of two elastic bodies (issue 44, item 2): the judge
//! of the 1-D theory (docs/theory.md section 18) where Lamé's uniform pressure and the bars'
//! uniform axial strain assume too much. The theory takes p uniform over L and untouched by the
//! push, and each member's axial strain uniform over its section; this model drops both, and
//! measures where the 1-D Delta departs from it (`validity.rs`, theory.md (S10)).
//!
//! **The model** (what a CalculiX deck of the same problem must model, boundary condition for
//! boundary condition):
//!
//! - x is the axis, r the radius; the shaft occupies r in [ri, r], the hub r in [r, ro], **both
//!   over exactly x in [0, L]** (the geometry: the fit length is both members' length;
//!   no shaft beyond the hub, whose extension would add a length of free shaft in series and a
//!   different end effect, and which the issue does not have). Their faces at x = 0 lie in one
//!   plane, and so do those at x = L;
//! - both bodies axisymmetric and linear elastic (Es, nus; Eh, nuh): 8-node ring elements
//!   (`numeric::q8::q8_axisymmetric_stiffness`, 3 x 3 Gauss points, weight 2 pi r, hoop strain
//!   u_r / r), `layers` of them through each wall, graded along x toward both faces;
//! - held: u_x = 0 on the hub's whole face x = L (u_r free there: a frictionless support, the
//!   "hub held on its far face"); u_r = 0 on the axis of a solid shaft (ri = 0, where the hoop
//!   strain requires it). Nothing else: the shaft is held axially by the interface alone, and
//!   its face x = L, the hub's face x = 0 and the outer and bore surfaces are free;
//! - **step 1, the interference**, resolved with the interface tangentially free: the hub's
//!   interface nodes are tied to the shaft's with a prescribed radial overlap (the hub's u_r is
//!   the shaft's plus delta: the pair shares one radial unknown, offset by delta; an exact tie,
//!   no penalty stiffness to choose). The contact pressure comes out of the solution. It is
//!   Lamé's plane-stress p at every x, not only far from the faces: with both members spanning
//!   L, free faces and no friction, sigma_z = 0 with eps_z uniform in each member and u_r
//!   independent of x is an exact solution (the members slide past each other by their
//!   different eps_z), docs/theory.md (S10); the hub's faces raise p only where the shaft runs
//!   on beyond them, which the geometry does not have. Under the push p does change:
//!   the compressed shaft swells (Poisson) and raises it near the loaded face. The interface
//!   carries no shear after step 1 (the shrink fit: the hub slides onto the shaft
//!   freely and grips as it cools): the Jenkins points' sliders are set at the step's slips
//!   (`Reduced::frictionless_first_stage`). A deck reproduces this with a frictionless first
//!   step (or by changing the friction after it) and measures Delta and the slips from its end;
//! - **step 2, the push-out**: an axial force F on the shaft's face x = 0 as a uniform traction
//!   F / (pi (r^2 - ri^2)) toward +x (consistent ring loads), rising from 0 in increments
//!   ([`PressFitContinuumMesh::force_increments`] over [0, F_gross]). Both members are in
//!   compression. The interface follows the 1-D theory's law pointwise: at each node pair a
//!   Jenkins point on the relative axial slip u_x,shaft - u_x,hub, stiffness K_T times the
//!   pair's share of the face (2 pi r times its Simpson share of the length), strength mu times
//!   the pair's own contact force (its local p(x)), which the push changes through Poisson's
//!   ratio: each increment is a fixed point on the contact forces, each iterate a Newton solve
//!   with the shared driver (`numeric::two_body::Reduced`, as the lap joint's continuum);
//! - the response Delta: the area mean of the shaft's u_x over its face x = 0, from the end of
//!   step 1 (the hub's support does not move): the closed form's Delta = u_s(0) - u_h(L).
//!
//! A pair whose contact force turns tensile is held by the tie, gets no friction strength and is
//! listed in [`ContinuumPressFit::separated`] (none on the bundled fit).
//!
//! **Speed.** The elastic bodies are condensed onto the pair slips once (`numeric::two_body`):
//! the interface is the only nonlinearity. Release build, default mesh, F at 0.3 and 0.8 F_gross
//! on one path: 5 ms for the bundled fit, at most 0.3 s over the calibration grid of (S10) (a
//! long thin-walled fit at lambda L = 36, 200 pairs), inside a TUI worker's budget.

mod answer;
mod condensed;
mod mesh;

use super::lame::{PlaneState, contact_pressure};
use super::params::{PressFitParam, PressFitParams};
use crate::kernel::params::Compact;
use crate::numeric::NumericError;
use crate::numeric::two_body::{Reduced, check_path};
use answer::pressfit_answer;
use condensed::condense;
use mesh::Grid;

/// Most interface node pairs: the condensed interface is dense, m x m, built from m solves.
/// Release, bundled fit, default mesh, 0.3 and 0.8 F_gross (the example's `kt` mode): 25 pairs
/// and 10 ms at K_T = 1e4 MPa/mm, 81 and 0.08 s at 1e6, 237 and 0.6 s at 1e7, 401 and 2.1 s at
/// 3e7; 4e7 (461 pairs) is refused. The interface is then Coulomb-like (Delta moves 0.02 % from
/// 1e7 to 3e7).
const MAX_PAIRS: usize = 401;
/// Most elements of both bodies together.
const MAX_ELEMENTS: usize = 60_000;
/// Most entries of the banded stiffness (128 MB).
const MAX_BAND_ENTRIES: f64 = 1.6e7;
/// Most elements through each wall.
const MAX_LAYERS: usize = 32;
/// Most height over length of an element (the thicker wall's layers against the finest x).
const MAX_ASPECT: f64 = 500.0;
/// Largest imbalance of the shaft accepted, relative to F + F_gross: the interface alone holds
/// it, so the force it transfers must be F.
const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;

/// How fine the continuum model is, in space and in load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PressFitContinuumMesh {
    /// Elements through each wall (shaft and hub); the element sizes along x follow the thinner
    /// wall's layer and the decay length 1/lambda.
    pub layers: usize,
    /// Load increments over [0, F_gross]: a force F is reached in ceil(F / F_gross x this)
    /// increments (at least one) beyond first sliding.
    pub force_increments: usize,
}

impl Default for PressFitContinuumMesh {
    /// Six elements through each wall and 8 increments over [0, F_gross]: Delta within 0.13 %
    /// of 16 layers' on the ladder of docs/theory.md (S10) (the bundled fit: 0.13 %), and 32
    /// increments give the same Delta to 10 digits.
    fn default() -> Self {
        PressFitContinuumMesh {
            layers: 6,
            force_increments: 8,
        }
    }
}

/// Sliding zones measured from each face of the fit (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitZones {
    /// From x = 0, the shaft's loaded face.
    pub from_loaded_face: f64,
    /// From x = L, the hub's held face.
    pub from_held_face: f64,
}

/// The continuum solution at one push-out force.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuumPressFit {
    /// F, the push on the shaft's face (N).
    pub force: f64,
    /// Delta (mm): the area mean of the shaft's u_x over its loaded face, from the fitted state
    /// (the hub's support is held): the closed form's response.
    pub delta: f64,
    /// mu times the total contact force at this state (N): the continuum's own gross-slip
    /// force, against the closed form's mu p 2 pi r L.
    pub capacity: f64,
    /// The total contact force over 2 pi r L (MPa): the mean contact pressure, against Lamé's.
    pub mean_pressure: f64,
    /// The sum of the pairs' Jenkins forces (N): F by the shaft's equilibrium (nothing else
    /// holds it axially).
    pub transferred_force: f64,
    /// p(x) per pair, (x (mm), MPa): its contact force over its share of the face (2 pi r
    /// times its share of L); negative where the faces would open.
    pub pressure: Vec<(f64, f64)>,
    /// tau(x) per pair, (x (mm), MPa): its Jenkins force over the same share, positive where
    /// the hub holds the shaft back (toward -x).
    pub shear: Vec<(f64, f64)>,
    /// s(x) = u_shaft - u_hub per pair from the fitted state, (x (mm), mm).
    pub slip: Vec<(f64, f64)>,
    /// Where the local law slides: the runs of pairs from each face with |tau| >= mu p(x)
    /// (within 0.1 %), at node resolution (mm); 0 for a face whose pair holds.
    pub local_zones: FitZones,
    /// Where the 1-D theory would say it slides: the runs from each face with K_T |s| >= mu p,
    /// p Lamé's plane-stress value, interpolated at the crossing (mm).
    pub nominal_zones: FitZones,
    /// x (mm) of the pairs in tension (the tie holds them; they get no friction).
    pub separated: Vec<f64>,
    /// Interface node pairs.
    pub pairs: usize,
    /// Increments of F after the interference step, and fixed-point iterations on the contact
    /// forces over them.
    pub increments: usize,
    /// See `increments`.
    pub iterations: usize,
}

/// Solves the fit of `params`: the interference, then the push-out force `force` (N).
///
/// # Errors
/// [`NumericError::OutOfRange`] for inputs outside their domains (the parameters, a force beyond
/// F_gross = mu p 2 pi r L, layers outside 1..=32, no force increment) and for a mesh too large
/// or too distorted (named with its numbers); [`NumericError::Unsolved`] when the push-out
/// cannot be followed (near F_gross, where the continuum's own capacity,
/// [`ContinuumPressFit::capacity`], may be lower than the closed form's), or the answer fails its
/// equilibrium check.
pub fn solve_pressfit_continuum(
    params: PressFitParams,
    force: f64,
    mesh: PressFitContinuumMesh,
) -> Result<ContinuumPressFit, NumericError> {
    let mut states = solve_pressfit_continuum_path(params, &[force], mesh)?;
    states.pop().ok_or(NumericError::BadLoad(force))
}

/// Solves the fit along one monotonic push: the interference, then F rising through each of
/// `forces` (N, non-decreasing); the state at each, as separate solves would give them.
///
/// # Errors
/// As [`solve_pressfit_continuum`]; also [`NumericError::OutOfRange`] for forces that decrease.
pub fn solve_pressfit_continuum_path(
    params: PressFitParams,
    forces: &[f64],
    mesh: PressFitContinuumMesh,
) -> Result<Vec<ContinuumPressFit>, NumericError> {
    let out_of_range =
        |e: crate::kernel::params::ParamError| NumericError::OutOfRange(e.to_string());
    params.check().map_err(out_of_range)?;
    let lame = contact_pressure(&params, PlaneState::Stress);
    let gross = params.friction * lame * params.interface_width() * params.length;
    for &force in forces {
        let force = PressFitParam::Force.check(force).map_err(out_of_range)?;
        if force > gross {
            return Err(NumericError::OutOfRange(format!(
                "F = {} N is beyond F_gross = mu p 2 pi r L = {} N (p Lamé's, {} MPa): the \
                 shaft slides out beyond it",
                Compact(force),
                Compact(gross),
                Compact(lame)
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
    let decay = 1.0 / decay_rate(&params);
    let (pairs, elements) = Grid::counts(&params, mesh, decay);
    if pairs > MAX_PAIRS || elements > MAX_ELEMENTS {
        return Err(NumericError::OutOfRange(format!(
            "the continuum mesh would have {pairs} interface pairs and {elements} elements (at \
             most {MAX_PAIRS} and {MAX_ELEMENTS}): L = {} mm against walls of {} and {} mm at \
             {} layers, and 1/lambda = {} mm; use fewer layers, a smaller K_T or a shorter fit",
            Compact(params.length),
            Compact(params.fit_radius - params.bore_radius),
            Compact(params.outer_radius - params.fit_radius),
            mesh.layers,
            Compact(decay),
        )));
    }
    let grid = Grid::new(&params, mesh, decay);
    let shortest = grid
        .two
        .lower
        .xs
        .windows(2)
        .fold(f64::INFINITY, |m, w| m.min(w[1] - w[0]));
    let tallest = (params.fit_radius - params.bore_radius)
        .max(params.outer_radius - params.fit_radius)
        / mesh.layers as f64;
    let aspect = tallest / shortest;
    if aspect.is_nan() || aspect > MAX_ASPECT {
        return Err(NumericError::OutOfRange(format!(
            "the continuum's elements would be {} times taller than long (at most {MAX_ASPECT}): \
             the thicker wall, {} mm, against elements of {} mm along L = {} mm; the walls are \
             too unequal or the fit too short for this mesh",
            Compact(aspect),
            Compact(tallest * mesh.layers as f64),
            Compact(shortest),
            Compact(params.length),
        )));
    }
    let band = grid.two.unknowns as f64 * (grid.two.bandwidth + 1) as f64;
    if band > MAX_BAND_ENTRIES {
        return Err(NumericError::OutOfRange(format!(
            "the continuum mesh's stiffness would hold {} entries ({} unknowns), more than {}: \
             use fewer layers",
            Compact(band),
            grid.two.unknowns,
            Compact(MAX_BAND_ENTRIES)
        )));
    }
    let condensed = condense(&grid, &params)?;
    let top = forces.iter().fold(0.0_f64, |m, f| m.max(*f));
    let mut model = Reduced::new(
        &condensed,
        params.friction,
        params.interference,
        gross / params.friction + top,
    );
    model.frictionless_first_stage().map_err(|e| {
        NumericError::Unsolved(format!(
            "the continuum's interference step (delta = {} mm) could not be solved: {e}",
            Compact(params.interference)
        ))
    })?;
    let fitted = model.state();
    model.start_force_step();
    let stick = model.stick_limit();
    let mut states = Vec::with_capacity(forces.len());
    let (mut increments, mut iterations) = (0, 0);
    for &force in forces {
        let from = model.load;
        let steps =
            (((force - from) / gross * mesh.force_increments as f64).ceil() as usize).max(1);
        let (slip, taken, iterated) = model.advance(&fitted, force, stick, steps).map_err(|e| {
            NumericError::Unsolved(format!(
                "the continuum could not be followed beyond F = {} N on the way to {} N ({e}); \
                 F_gross = mu p 2 pi r L = {} N, the continuum's own capacity mu x (its contact \
                 force) = {} N",
                Compact(model.load),
                Compact(force),
                Compact(gross),
                Compact(model.friction() * model.contact_forces().iter().sum::<f64>()),
            ))
        })?;
        increments += taken;
        iterations += iterated;
        let state = pressfit_answer(
            &model,
            &grid,
            &fitted,
            &slip,
            (increments, iterations),
            lame,
        );
        let finite = state.delta.is_finite()
            && [&state.slip, &state.shear, &state.pressure]
                .iter()
                .all(|v| v.iter().all(|(_, y)| y.is_finite()));
        let imbalance = (state.transferred_force - force).abs();
        if !finite || imbalance > EQUILIBRIUM_TOLERANCE * (force + gross) {
            return Err(NumericError::Unsolved(format!(
                "the continuum solution at F = {} N lost precision (the interface carries {} N, \
                 off by more than {} of F + F_gross): K_T = {} MPa/mm against members of axial \
                 rigidity {} and {} N",
                Compact(force),
                Compact(state.transferred_force),
                Compact(EQUILIBRIUM_TOLERANCE),
                Compact(params.tangential_stiffness),
                Compact(params.shaft_modulus * params.shaft_area()),
                Compact(params.hub_modulus * params.hub_area()),
            )));
        }
        states.push(state);
    }
    Ok(states)
}

/// lambda = sqrt(2 pi r K_T (1/(Es As) + 1/(Eh Ah))) (1/mm): the rate at which the elastic slip
/// decays from a loaded face in the shear-lag theory (docs/theory.md (S4)). Only the mesh grading
/// uses it (a material length scale, not a closed-form result).
fn decay_rate(p: &PressFitParams) -> f64 {
    let compliance =
        1.0 / (p.shaft_modulus * p.shaft_area()) + 1.0 / (p.hub_modulus * p.hub_area());
    (p.interface_width() * p.tangential_stiffness * compliance).sqrt()
}

#[cfg(test)]
mod tests;
