//! The twin beams as a 2-D plane-stress continuum of two deformable bodies: the reference an FE
//! code's beams are judged against at the deck's exact parameters (issue 33), and the judge of
//! the beam theories (Euler-Bernoulli, Timoshenko) where they assume too much.
//!
//! It solves the problem the CalculiX deck `microslip deck ccx beam` writes
//! (`src/problems/twin_beams/deck.rs`), in small strain:
//!
//! - two beams of length L and height 2h, the lower one over y in [-2h, 0], the upper one over
//!   [0, 2h], each clamped at x = 0 (u = v = 0 on the whole end face);
//! - plane stress with thickness b (the deck's slice of width b has free side faces), modulus E
//!   and Poisson ratio nu;
//! - 8-node quadrilaterals (Q8, 3 x 3 Gauss points, `numeric::q8`), `layers` of them through
//!   each beam, graded along x toward the clamp as the deck grades its mesh
//!   (`mesh::beam_breaks`);
//! - the pressure P on both outer faces (y = -2h and y = 2h), pressing the beams together, and
//!   the tip force F on each beam as a uniform shear traction F / (2 b h) on its end face x = L,
//!   in +y (consistent nodal loads);
//! - the interface y = 0 with matching nodes (`numeric::two_body`). **Normal:** each node pair
//!   shares its normal displacement: an exact tie; the pair's contact force is the upper beam's
//!   share of the equilibrium at that unknown, out of the solution. A pair in tension would be
//!   held by the tie: it gets no friction strength and is listed in
//!   [`ContinuumBeams::separated`]. **Tangential:** at each pair a Jenkins point on the relative
//!   slip, stiffness K_T times the node's share of the face (Simpson weights), strength mu times
//!   the pair's contact force. The pair at the clamp is held by it and carries no slip.
//!
//! **Load path.** P alone first, in one increment (by symmetry it makes no slip). Then F rises
//! from 0: exactly (linearly) up to the continuum's own elastic limit F_e, the force at which
//! the first pair saturates (the closed form's F_1 = F_thre / (1 - sech kL)); beyond it in equal
//! increments of at most F_e / `force_increments` ([`BeamsContinuumMesh`]), each solved at its own
//! contact forces (a fixed point on them, each iterate a Newton solve from the history committed
//! at the end of the previous increment), as the deck's steps of F_1/40. Friction is
//! path-dependent once a point slides: a path through several forces ([`solve_beams_continuum_path`])
//! is one history, as one deck's steps are.
//!
//! **Kinematics.** Small strain, linear geometry: the pressure keeps its direction and the
//! interface its place. Beam theory assumes the same, and where the beams rotate (theta = w'), a
//! CalculiX run in linear geometry mixes both (its contact works on the deformed faces while its
//! pressure keeps its direction: an axial traction P theta on each outer face); with `NLGEOM` the
//! pressure follows the faces as in this model, up to terms of order theta^2
//! (docs/theory.md, "The twin beams' continuum").

mod mesh;

use super::params::{BeamParam, TwinBeamsParams};
use crate::kernel::params::Compact;
use crate::numeric::NumericError;
use crate::numeric::grid::edge_weights;
use crate::numeric::two_body::{Condensed, Profiles, Reduced, State, check_path, nominal_front};
use mesh::{Grid, elements_along};

/// Most interface node pairs: the condensed interface is a dense m x m system built from m
/// solves with the banded factor (the lap joint's limit).
const MAX_PAIRS: usize = 801;
/// Most elements through each beam's height.
const MAX_LAYERS: usize = 16;
/// Most force increments per F_e.
const MAX_INCREMENTS: usize = 10_000;

/// How fine the continuum model is, in space and in load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BeamsContinuumMesh {
    /// Elements through each beam's height 2h (the element sizes along x scale with it).
    pub layers: usize,
    /// Increments per F_e (the continuum's elastic limit, the closed form's F_1) beyond F_e: a
    /// force F > F_e is reached from F_e in ceil((F - F_e) / F_e x this) increments.
    pub force_increments: usize,
    /// Whether w(L) is extrapolated to zero element height (Richardson): solved on `layers` and
    /// on `layers / 2` (even `layers`), w(L) = 2 w_fine - w_coarse; everything else is the
    /// fine mesh's. The extrapolation from 4 and 8 layers is within 0.006 % of the 16-layer
    /// answer on the paper's beams at 1.25 F_thre.
    pub extrapolate: bool,
}

impl Default for BeamsContinuumMesh {
    /// Eight elements through each beam, w(L) extrapolated with four, and increments of F_e / 40
    /// (the deck's F_1 / 40). On the paper's beams at 1.25 F_thre, w(L) on 2, 4, 8 and 16
    /// layers is -0.05, -0.02, -0.010 and -0.004 % from the default (in stick below 0.04 %);
    /// the element sizes along x matter little (a quarter of them moved w(L) by 1e-6 of
    /// itself), and halving the increments changed none of w(L)'s 8 digits. Four layers, not
    /// extrapolated, is within 0.03 % for a third of the cost. docs/theory.md, (BC3).
    fn default() -> Self {
        BeamsContinuumMesh {
            layers: 8,
            force_increments: 40,
            extrapolate: true,
        }
    }
}

/// The continuum solution at one tip force.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuumBeams {
    /// The tip force on each beam (N).
    pub force: f64,
    /// The tip deflection w(L) (mm): the mean transverse displacement of both beams' tip nodes
    /// at mid-height, from the pressed state (the deck's WTIP reading).
    pub tip_deflection: f64,
    /// The same reading after the pressure step alone (mm): zero by symmetry, to round-off.
    pub pressure_deflection: f64,
    /// Where the macroslip zone starts, from the clamp (mm), as the closed form's X and the FE
    /// comparison read it: walking from the tip, where K_T |s| falls to mu P (nominal P),
    /// interpolated between pairs; L when the tip does not reach it.
    pub macroslip_start: f64,
    /// The same by the local law: the first pair of the run from the tip where
    /// |tau| >= mu p within 0.1 %, at node resolution (mm); L when the tip pair does not slide.
    pub local_macroslip_start: f64,
    /// The force at which the first pair saturates (N): the continuum's F_1.
    pub elastic_limit: f64,
    /// The interface slip s = u_upper - u_lower at each pair (x (mm), s (mm)).
    pub slip: Vec<(f64, f64)>,
    /// The interface shear stress on the lower beam at each pair (x (mm), tau (MPa)): the
    /// pair's Jenkins force over its share of the face, positive where it has the sign of s.
    pub shear: Vec<(f64, f64)>,
    /// The contact pressure at each pair (x (mm), p (MPa)); negative where the faces would
    /// open ([`ContinuumBeams::separated`]).
    pub contact_pressure: Vec<(f64, f64)>,
    /// The x (mm) of the pairs whose contact force is tensile: the tie holds them where the
    /// faces would open, and they carry no friction.
    pub separated: Vec<f64>,
    /// Load increments of F from 0 to this force.
    pub increments: usize,
    /// Fixed-point iterations on the contact forces, over all steps.
    pub iterations: usize,
    /// Interface node pairs (the condensed system's size).
    pub pairs: usize,
}

/// Solves the beams of `params` under P, then the tip force `force` (N) on each beam.
///
/// # Errors
/// As [`solve_beams_continuum_path`].
pub fn solve_beams_continuum(
    params: TwinBeamsParams,
    force: f64,
    mesh: BeamsContinuumMesh,
) -> Result<ContinuumBeams, NumericError> {
    let mut states = solve_beams_continuum_path(params, &[force], mesh)?;
    states.pop().ok_or(NumericError::BadLoad(force))
}

/// Solves the beams along one monotonic loading path: P, then F rising through each of `forces`
/// (N, non-decreasing) in turn; the state at each.
///
/// # Errors
/// [`NumericError::OutOfRange`] for parameters outside their domains (naming the field), forces
/// that are negative, not finite or decreasing, layers outside 1..=16, no force increment or
/// more than 10 000, and a mesh of more than 801 interface pairs (very slender beams or a very
/// stiff interface); [`NumericError::Unsolved`] when an increment does not converge.
pub fn solve_beams_continuum_path(
    params: TwinBeamsParams,
    forces: &[f64],
    mesh: BeamsContinuumMesh,
) -> Result<Vec<ContinuumBeams>, NumericError> {
    check(&params, forces, mesh)?;
    let fine = solve_on(params, forces, mesh)?;
    if !mesh.extrapolate {
        return Ok(fine);
    }
    let coarse = solve_on(
        params,
        forces,
        BeamsContinuumMesh {
            layers: mesh.layers / 2,
            ..mesh
        },
    )?;
    Ok(fine
        .iter()
        .zip(&coarse)
        .map(|(f, c)| extrapolated(f, c))
        .collect())
}

/// Richardson's extrapolation of w(L) from `fine` (layer height e) and `coarse` (2 e) to
/// e = 0: 2 fine - coarse. The rest is the fine mesh's: X and F_e change with the layers by
/// less than a millimetre and 1e-5 of themselves from 4 layers on, but not smoothly (a pair
/// saturates on one mesh and not yet on the other), and the contact pressure at the corners is
/// singular.
fn extrapolated(fine: &ContinuumBeams, coarse: &ContinuumBeams) -> ContinuumBeams {
    ContinuumBeams {
        tip_deflection: 2.0 * fine.tip_deflection - coarse.tip_deflection,
        ..fine.clone()
    }
}

/// [`solve_beams_continuum_path`] on the mesh `mesh` alone (checked).
fn solve_on(
    params: TwinBeamsParams,
    forces: &[f64],
    mesh: BeamsContinuumMesh,
) -> Result<Vec<ContinuumBeams>, NumericError> {
    let grid = Grid::new(&params, mesh);
    let condensed = condense(&grid, &params)?;
    let top = forces.iter().fold(0.0_f64, |m, f| m.max(*f));
    let scale = params.pressure * params.length + top / params.width;
    let mut model = Reduced::new(&condensed, params.friction, params.pressure, scale);
    let iterations = model.step(1.0).map_err(|e| {
        NumericError::Unsolved(format!(
            "the twin beams' continuum: the pressure step (P = {} MPa alone) could not be \
             solved: {e}",
            Compact(params.pressure)
        ))
    })?;
    let clamped = model.state();
    model.start_force_step();
    let stick = model.stick_limit();
    // The increment's scale: F_e, or where no pair ever saturates (not met) the Coulomb
    // threshold of the bonded pair 4 mu b h P / 3 (equilibrium of the stuck section).
    let unit = if stick.is_finite() && stick > 0.0 {
        stick
    } else {
        4.0 * params.friction * params.width * params.half_height * params.pressure / 3.0
    };
    let mut states = Vec::with_capacity(forces.len());
    let (mut increments, mut iterations) = (0, iterations);
    for &force in forces {
        let unsolved = |model: &Reduced<'_>, e: NumericError| {
            NumericError::Unsolved(format!(
                "the twin beams' continuum could not be solved beyond F = {} N on the way to \
                 {} N: {e}",
                Compact(model.load),
                Compact(force)
            ))
        };
        if model.load < stick && stick < force {
            // Up to F_e exactly, in one increment (the law is linear below it).
            model
                .advance(&clamped, stick, stick, 1)
                .map_err(|e| unsolved(&model, e))?;
            increments += 1;
        }
        let from = model.load;
        let steps = (((force - from) / unit * mesh.force_increments as f64).ceil() as usize).max(1);
        let (slip_from_clamp, taken, iterated) = model
            .advance(&clamped, force, stick, steps)
            .map_err(|e| unsolved(&model, e))?;
        increments += taken;
        iterations += iterated;
        let state = answer(
            &model,
            &grid,
            &clamped,
            &slip_from_clamp,
            stick,
            (increments, iterations),
        );
        let finite = state.tip_deflection.is_finite()
            && [&state.slip, &state.shear, &state.contact_pressure]
                .iter()
                .all(|v| v.iter().all(|(_, y)| y.is_finite()));
        if !finite {
            return Err(NumericError::NoConvergence {
                load: force,
                cuts: 0,
            });
        }
        states.push(state);
    }
    Ok(states)
}

/// The inputs' domains, the path's order and the mesh's size, checked before anything is built.
fn check(
    params: &TwinBeamsParams,
    forces: &[f64],
    mesh: BeamsContinuumMesh,
) -> Result<(), NumericError> {
    let out_of_range =
        |e: crate::kernel::params::ParamError| NumericError::OutOfRange(e.to_string());
    let mut fields = *params;
    for param in BeamParam::ALL {
        if let Some(&mut value) = fields.value_mut(param) {
            param.check(value).map_err(out_of_range)?;
        }
    }
    for &force in forces {
        BeamParam::Force.check(force).map_err(out_of_range)?;
    }
    check_path(forces)?;
    if mesh.layers == 0
        || mesh.layers > MAX_LAYERS
        || (mesh.extrapolate && !mesh.layers.is_multiple_of(2))
    {
        return Err(NumericError::OutOfRange(format!(
            "layers = {} is outside 1..={MAX_LAYERS}{}",
            mesh.layers,
            if mesh.extrapolate {
                " or odd (extrapolating needs half as many)"
            } else {
                ""
            }
        )));
    }
    if mesh.force_increments == 0 || mesh.force_increments > MAX_INCREMENTS {
        return Err(NumericError::OutOfRange(format!(
            "force_increments = {} is outside 1..={MAX_INCREMENTS}",
            mesh.force_increments
        )));
    }
    // Two pairs per element along x, less the held one at the clamp.
    let pairs = 2.0 * elements_along(params, mesh.layers);
    if pairs.is_nan() || pairs > MAX_PAIRS as f64 {
        return Err(NumericError::OutOfRange(format!(
            "the beams' continuum mesh would have {} interface node pairs at {} layers, more \
             than the {MAX_PAIRS} the solver takes: the elements along x are at most 1.6 \
             layers long and a quarter of the boundary layer sqrt(E h / K_T) / 2 = {} mm; use \
             fewer layers, stubbier beams (L/h = {}) or a smaller K_T",
            Compact(pairs),
            mesh.layers,
            Compact(
                0.5 * (params.youngs_modulus * params.half_height / params.tangential_stiffness)
                    .sqrt()
            ),
            Compact(params.length / params.half_height),
        )));
    }
    Ok(())
}

/// The beams condensed onto their interface pairs: P = 1 MPa on both outer faces, F = 1 N on
/// each beam's end face, and w(L), the mean v of both beams' tip nodes at mid-height.
fn condense(grid: &Grid, p: &TwinBeamsParams) -> Result<Condensed, NumericError> {
    let two = &grid.two;
    let (lower, upper) = (&two.lower, &two.upper);
    let along = edge_weights(&lower.xs);
    let through = edge_weights(&lower.ys);
    let end = lower.columns() - 1;
    let top = upper.rows() - 1;
    let middle = lower.rows() / 2;
    let traction = 1.0 / (p.width * 2.0 * p.half_height);
    let pressure = |add: &mut dyn FnMut(usize, f64)| {
        for (i, w) in along.iter().enumerate() {
            add(lower.dof(i, 0)[1], *w);
            add(upper.dof(i, top)[1], -w);
        }
    };
    let force = |add: &mut dyn FnMut(usize, f64)| {
        for body in [lower, upper] {
            for (j, w) in through.iter().enumerate() {
                add(body.dof(end, j)[1], traction * w);
            }
        }
    };
    // The upper beam's end traction at its corner node (x = L, y = 0): the last pair's normal
    // unknown, which the contact reading must not count.
    let last = two.pairs() - 1;
    let own_force = |pair: usize| {
        if pair == last {
            traction * through[0]
        } else {
            0.0
        }
    };
    let deflection = |at: &dyn Fn(usize) -> f64| {
        0.5 * (at(lower.dof(end, middle)[1]) + at(upper.dof(end, middle)[1]))
    };
    Condensed::new(
        two,
        p.tangential_stiffness,
        &grid.fixed,
        [&pressure, &force],
        [&|_| 0.0, &own_force],
        &deflection,
    )
}

/// The state's answer; `slip_from_clamp` is the generic slip u_lower - u_upper from the pressed
/// state at each pair (mm), `stick` the elastic limit F_e (N).
fn answer(
    model: &Reduced<'_>,
    grid: &Grid,
    clamped: &State,
    slip_from_clamp: &[f64],
    stick: f64,
    (increments, iterations): (usize, usize),
) -> ContinuumBeams {
    let c = model.c;
    let weights = &grid.two.pair_weights;
    let xs = &grid.two.pair_x;
    // The closed form's convention: s = u_upper - u_lower, tau on the lower beam with the sign
    // of s; the generic pair reads u_lower - u_upper.
    let profiles = Profiles::read(model, &grid.two, slip_from_clamp, -1.0, 1.0);
    let length = xs.last().copied().unwrap_or(0.0);
    let saturation = model.friction() * model.pressure();
    let level = |i: usize| c.stiffness[i] / weights[i] * profiles.slip[i].1.abs();
    let from_tip = &mut (0..xs.len()).rev();
    let macroslip_start = nominal_front(xs, level, saturation, from_tip);
    let local_macroslip_start = profiles
        .run_from_end(model.friction())
        .map_or(length, |i| xs[i]);
    ContinuumBeams {
        force: model.load,
        tip_deflection: model.reading_from(clamped),
        pressure_deflection: model.first_reading(),
        macroslip_start,
        local_macroslip_start,
        elastic_limit: stick,
        separated: profiles.separated,
        slip: profiles.slip,
        shear: profiles.shear,
        contact_pressure: profiles.pressure,
        increments,
        iterations,
        pairs: c.pairs,
    }
}
