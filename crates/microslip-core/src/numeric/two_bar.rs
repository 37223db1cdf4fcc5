//! Finite elements for two bars coupled through one frictional interface, independent of the
//! closed forms (`kernel::shear_lag`): the discretized solver the double-lap joint and the press
//! fit share, each mapping its members onto the two bars.
//!
//! Two bars over [0, L] (axial rigidities A0 and A1, N), linear elements, one axial displacement
//! per bar per node, the unknowns interleaved (u0, u1) node by node so that the stiffness is a
//! band of half-width 2. Bar 0 carries the load F at one end and bar 1 is held at the other
//! ([`TwoBarSpec::loaded_at_start`] says which ends: the lap joint pulls its inner plate at x = L
//! and holds the covers at x = 0; the press fit pushes its shaft at x = 0 and holds the hub at
//! x = L, so its solver works in its own coordinate, not in the joint's mirror image).
//!
//! Between the bars, at every node, one Jenkins point (`numeric::interface`) stands for the
//! interface over the node's tributary length w_i: a spring K_T W w_i in series with a slider of
//! strength mu P W w_i (W the interface's width), acting on the slip s = u0 - u1. Lumping the
//! interface at the nodes (the trapezoidal rule) rather than integrating it at Gauss points keeps
//! the model a chain of springs whose equations are a second-order finite difference of
//! s'' = W tau (1/A0 + 1/A1): the error falls 4x per halving of the element size, and the sliding
//! zones end between two nodes that hold the slip's own values, not interpolations of them.
//!
//! The plastic slip of every point is the history, so any load path can be followed: up, down,
//! through zero to negative forces (a real load reversal) and back. Each load step is solved by
//! Newton's method on the banded system with the consistent tangent (K_T on elastic points, 0 on
//! sliding ones); the system is linear for a fixed set of sliding points, so Newton is an exact
//! active-set iteration. Nothing here reads a closed form: what this model agrees with, it agrees
//! with on its own.

use crate::numeric::banded::SymmetricBand;
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::mesh::MeshDensity;
use crate::numeric::newton::{self, Discretized};
use crate::numeric::{NumericError, short, stiffness_advice};

/// Fewest elements per decay length 1/lambda of the elastic slip (lambda^2 = W K_T (1/A0 +
/// 1/A1)): [`TwoBarFe::new`] refines the requested mesh to at least this. The onset of sliding
/// is what a coarse mesh gets worst: the end point's spring stands for half an element of a slip
/// that decays over 1/lambda, and F_1 comes out high by 0.125 (lambda h)^2, whatever lambda L
/// (measured on the lap joint from lambda L = 25 to 1600 against (L3): 12 %, 3.1 %, 0.78 %,
/// 0.20 % at 1, 2, 4, 8 elements per 1/lambda). 12 keeps it below the project's 1e-3; Delta is
/// then within 1e-6 and the zone ends within 0.002/lambda.
pub const ELEMENTS_PER_DECAY: f64 = 12.0;

/// Most elements [`TwoBarFe::new`] builds: 16000. With [`ELEMENTS_PER_DECAY`] that resolves
/// lambda L up to 1333 (the bundled aluminium joint: K_T up to 6.7e7 MPa/mm), where the
/// interface is plain Coulomb to within mu P / K_T = 4.5e-8 mm in Delta (3e-6 of it). The cap is
/// set by time: each Newton iteration moves a sliding zone's end by a few 1/lambda only, so a
/// load path costs some lambda L / 3 iterations of O(elements) each, growing as (lambda L)^2.
/// Measured (release, the aluminium joint, one step to 0.6 F_gross / 40 steps to 0.95 F_gross):
/// lambda L = 333, 4000 elements: 0.03 s / 0.19 s; 1333, 16000: 0.43 s / 1.3 s; 2667, 32000:
/// 1.9 s / 4.0 s; 5164, 62000: 8.5 s for the single step.
pub const MAX_ELEMENTS: usize = 16_000;

/// The two bars and their interface, as the caller has validated them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBarSpec {
    /// Axial rigidities (N): [bar 0, loaded; bar 1, held].
    pub rigidities: [f64; 2],
    /// Interface width W (mm): the length of its cross-section line.
    pub width: f64,
    /// Interface length L (mm).
    pub length: f64,
    /// Friction coefficient mu (-).
    pub friction: f64,
    /// Normal pressure P on the interface (MPa).
    pub pressure: f64,
    /// Tangential stiffness K_T (MPa/mm).
    pub stiffness: f64,
    /// Bar 0 is loaded at x = 0 and bar 1 held at x = L (true), or bar 0 loaded at x = L and
    /// bar 1 held at x = 0 (false).
    pub loaded_at_start: bool,
}

impl TwoBarSpec {
    /// W mu P L (N): the whole interface sliding.
    pub fn gross_slip_force(&self) -> f64 {
        self.width * self.friction * self.pressure * self.length
    }
}

/// How a refusal names the caller's problem: its gross-slip bound with formula, what happens at
/// it, and its interface length.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TwoBarWords {
    /// `F_gross = 2 b mu P L`.
    pub gross: &'static str,
    /// What happens at F_gross: `both interfaces slide over the whole overlap and the inner
    /// plate's position is undetermined`.
    pub at_gross: &'static str,
    /// The interface length in words: `the overlap L`.
    pub length: &'static str,
}

/// Unknowns per node: u0, u1.
const NODE_DOFS: usize = 2;

/// Relative distance below mu P at which a point counts as at the friction limit
/// ([`TwoBarFe::sliding_zones`], and the tangent of a point on the limit): the return mapping lets
/// an elastic point reach 1e-9 beyond it.
const AT_LIMIT: f64 = 1e-9;

/// Two bars and their interface discretized, with the current force and interface history.
#[derive(Debug, Clone)]
pub struct TwoBarFe {
    spec: TwoBarSpec,
    words: TwoBarWords,
    /// Node positions, uniform over [0, L].
    nodes: Vec<f64>,
    /// Interface area 2 b w_i of each node's Jenkins point (both faces), mm^2.
    areas: Vec<f64>,
    /// (u0, u1) at every node, interleaved (mm).
    displacement: Vec<f64>,
    pub(crate) points: Vec<InterfacePoint>,
    force: f64,
    /// The two bars' stiffness, bar 1 held.
    stiffness: SymmetricBand,
    /// Interface responses of the last converged step; empty before the first.
    pub(crate) converged: Vec<Response>,
}

impl TwoBarFe {
    /// The unloaded bars (F = 0) on a uniform mesh of `density.elements` elements, refined to at
    /// least [`ELEMENTS_PER_DECAY`] per 1/lambda and capped at [`MAX_ELEMENTS`].
    ///
    /// Uniform, unlike the beams' and the plate's graded meshes: on a load path the sliding
    /// zones grow inward from both ends and, after a reversal, new ones grow from the ends again,
    /// so the elastic zone's boundary layers travel across the whole interface and no place can
    /// be left coarse (`density.smallest_fraction` is therefore not used). The refinement to
    /// 1/lambda is the only reading of the parameters the mesh makes: a material length, never a
    /// closed-form result. The count is capped so that no input allocates without bound; bars
    /// the cap cannot resolve are refused by [`TwoBarFe::load_to`].
    pub fn new(spec: TwoBarSpec, words: TwoBarWords, density: MeshDensity) -> Self {
        let needed = (ELEMENTS_PER_DECAY * decay_rate(&spec) * spec.length).ceil();
        let needed = if needed.is_finite() {
            needed.min(MAX_ELEMENTS as f64) as usize
        } else {
            MAX_ELEMENTS
        };
        let elements = density.elements.max(needed).clamp(1, MAX_ELEMENTS);
        let length = spec.length;
        let nodes: Vec<f64> = (0..=elements)
            .map(|i| length * i as f64 / elements as f64)
            .collect();
        let areas: Vec<f64> = (0..=elements)
            .map(|i| {
                let left = if i > 0 { nodes[i] - nodes[i - 1] } else { 0.0 };
                let right = if i < elements {
                    nodes[i + 1] - nodes[i]
                } else {
                    0.0
                };
                spec.width * 0.5 * (left + right)
            })
            .collect();
        let unknowns = NODE_DOFS * (elements + 1);
        let mut stiffness = SymmetricBand::zeros(unknowns, 2);
        for e in 0..elements {
            let l = nodes[e + 1] - nodes[e];
            for (bar, rigidity) in spec.rigidities.into_iter().enumerate() {
                let (i, j) = (NODE_DOFS * e + bar, NODE_DOFS * (e + 1) + bar);
                let k = rigidity / l;
                stiffness.add(i, i, k);
                stiffness.add(j, j, k);
                stiffness.add(j, i, -k);
            }
        }
        let mut fe = TwoBarFe {
            spec,
            words,
            points: vec![InterfacePoint::default(); nodes.len()],
            areas,
            displacement: vec![0.0; unknowns],
            force: 0.0,
            stiffness,
            converged: Vec::new(),
            nodes,
        };
        fe.stiffness.fix(fe.held());
        fe
    }

    /// The held unknown: bar 1 at the end opposite the load.
    fn held(&self) -> usize {
        if self.spec.loaded_at_start {
            NODE_DOFS * (self.nodes.len() - 1) + 1
        } else {
            1
        }
    }

    /// The loaded unknown: bar 0 at its loaded end.
    fn loaded(&self) -> usize {
        if self.spec.loaded_at_start {
            0
        } else {
            NODE_DOFS * (self.nodes.len() - 1)
        }
    }

    /// Moves the force from its current value to `force` (N, either sign: a negative force
    /// reverses it) in `steps` equal increments, halving an increment whose Newton iterations
    /// fail (up to 12 times). Every point keeps its plastic slip from step to step, so the answer
    /// depends on the path: unloading and reloading follow the hysteresis loop.
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] for bars whose 1/lambda the largest mesh cannot resolve
    /// ([`TwoBarFe::check_resolvable`]), or |F| >= F_gross = W mu P L (beyond it no static state
    /// exists; at it the whole interface slides and the loaded bar's position is undetermined);
    /// [`NumericError::BadLoad`] for a non-finite force; [`NumericError::NoConvergence`] when an
    /// increment fails even after 12 halvings; [`NumericError::Singular`] should never happen
    /// below F_gross.
    pub fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError> {
        Self::check_resolvable(&self.spec, &self.words)?;
        if !force.is_finite() {
            return Err(NumericError::BadLoad(force));
        }
        let gross = self.spec.gross_slip_force();
        if force.abs() >= gross {
            return Err(NumericError::OutOfRange(format!(
                "|F| = {} N must be below {} = {} N: at it {}; beyond it no static state exists",
                short(force.abs()),
                self.words.gross,
                short(gross),
                self.words.at_gross
            )));
        }
        newton::load_to(self, force, steps)
    }

    /// Refuses bars this solver cannot answer: those whose decay length 1/lambda of the elastic
    /// slip is shorter than [`ELEMENTS_PER_DECAY`] elements of the largest mesh
    /// ([`MAX_ELEMENTS`]), i.e. lambda L above 1333, and those whose elements are so much stiffer
    /// than the whole interface that the solve keeps fewer than three digits. The slip and the
    /// shear change within a few 1/lambda of each loaded end and of each sliding zone's end; a
    /// coarser mesh puts F_1 off by 0.125 (lambda h)^2 and the zone ends by a fraction of an
    /// element. Such an interface is plain Coulomb to within mu P / K_T in Delta (L7), so the
    /// message says to lower K_T to where the solver works.
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] with lambda L and the largest K_T that is resolved, or with
    /// the conditioning.
    pub fn check_resolvable(spec: &TwoBarSpec, words: &TwoBarWords) -> Result<(), NumericError> {
        let decays = decay_rate(spec) * spec.length;
        let most = MAX_ELEMENTS as f64 / ELEMENTS_PER_DECAY;
        // Conditioning: the loaded bar is held only by the interface, so the stiffness matrix's
        // smallest eigenvalue is about the interface's total stiffness K_T W L and its largest
        // 2 A / h (A the stiffer bar's rigidity): their ratio costs its digits to the solve, so
        // beyond 1e13 fewer than three are left (a lap overlap of 1e-5 mm at the default mesh:
        // 2e15, a singular matrix).
        let elements = (MeshDensity::default().elements as f64)
            .max((ELEMENTS_PER_DECAY * decays).ceil())
            .min(MAX_ELEMENTS as f64);
        let stiffer = spec.rigidities[0].max(spec.rigidities[1]);
        let condition =
            4.0 * stiffer * elements / (spec.width * spec.stiffness * spec.length * spec.length);
        if condition > 1e13 {
            return Err(NumericError::OutOfRange(format!(
                "the bars' elements are {} times stiffer than the whole interface (at most 1e13, \
                 where the solve keeps three digits): lengthen {} = {} mm or raise \
                 K_T = {} MPa/mm",
                short(condition),
                words.length,
                short(spec.length),
                short(spec.stiffness)
            )));
        }
        if decays <= most {
            return Ok(());
        }
        // lambda scales as sqrt(K_T); a hair below the bound, so that the value the message
        // names, rounded to four digits, is accepted.
        let largest = 0.999 * spec.stiffness * (most / decays).powi(2);
        let shorten = format!("shorten {}", words.length);
        Err(NumericError::OutOfRange(format!(
            "the elastic slip decays over 1/lambda = {} mm, lambda L = {}: resolving it with \
             {ELEMENTS_PER_DECAY} elements per 1/lambda needs more than the {MAX_ELEMENTS} \
             elements the solver builds (lambda L <= {}); {} (the interface is then plain \
             Coulomb to within mu P / K_T in Delta)",
            short(spec.length / decays),
            short(decays),
            short(most),
            stiffness_advice(largest, Some(&shorten))
        )))
    }

    /// The current force (N).
    pub fn force(&self) -> f64 {
        self.force
    }

    /// Number of elements (after the refinement of [`TwoBarFe::new`]).
    pub fn elements(&self) -> usize {
        self.nodes.len() - 1
    }

    /// The end displacement Delta (mm): bar 0's loaded end relative to bar 1's held end, in the
    /// load's direction (the held end is at 0; it is subtracted all the same so that the
    /// definition does not hang on how the model is held).
    pub fn end_displacement(&self) -> f64 {
        self.displacement[self.loaded()] - self.displacement[self.held()]
    }

    /// Slip s = u0 - u1 at any x in [0, L] (mm), linear between nodes.
    pub fn slip_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.slip(&self.displacement, i))
    }

    /// Interface shear tau on bar 0 at any x in [0, L] (MPa), positive resisting a
    /// positive F; linear between the nodes' values (0 before the first load step).
    pub fn shear_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.converged.get(i).map_or(0.0, |r| r.stress))
    }

    /// The largest |tau| over the interface's points at the last converged step (MPa); 0 before
    /// the first. Below the first sliding the model is linear, so mu P over this at a small
    /// load, times that load, is the model's own F_1.
    pub fn peak_shear(&self) -> f64 {
        self.converged
            .iter()
            .map(|r| r.stress.abs())
            .fold(0.0, f64::max)
    }

    /// Plastic slip (the sliders' displacement) at any x in [0, L] (mm), linear between nodes:
    /// the history a load path leaves behind; 0 wherever no point has slid.
    pub fn plastic_slip_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.points[i].plastic_slip)
    }

    /// The shear integrated over the interface, sum of W w_i tau_i (N): equal to F at every
    /// converged step (bar 0's equilibrium; the interface, not the support, carries the
    /// load), to the Newton tolerance: 1e-12 of F_gross on a few hundred elements, up to 2e-7 at
    /// 16000, where the residual's round-off floor decides (the solver's load scale).
    pub fn transferred_force(&self) -> f64 {
        self.converged
            .iter()
            .zip(&self.areas)
            .map(|(r, a)| a * r.stress)
            .sum()
    }

    /// Lengths (a, d) of the zones from x = 0 and from x = L over which |tau| = mu P (mm).
    ///
    /// Measured as the twin-beams solver measures its microslip zone's end: a zone is the run of
    /// points at the friction limit from its end of the overlap, and it ends between its last
    /// point and the first point below the limit, where the slip, interpolated linearly, reaches
    /// the saturation slip mu P / K_T (in the sliding direction, and counted from the first
    /// elastic point's plastic slip: on a rising load that is 0 and the rule is exactly the
    /// beams' |s(x)| = mu P / K_T). The slip is smooth across a zone end (tau is continuous), so
    /// this puts the end within O(h^2), like Delta; taking the last node at the limit instead
    /// would be off by up to a whole element. After a reversal the zones are those sliding now,
    /// in whichever direction. (0, 0) before the first load step.
    pub fn sliding_zones(&self) -> (f64, f64) {
        let Some(last) = self.converged.len().checked_sub(1) else {
            return (0.0, 0.0);
        };
        let a = self.zone_end(0..=last);
        let d = self.spec.length - self.zone_end((0..=last).rev());
        let a = a.clamp(0.0, self.spec.length);
        (a, d.clamp(0.0, self.spec.length - a))
    }

    /// Where the zone at the limit that starts at the first node of `order` ends (x, mm): the
    /// starting node's position when it is not at the limit, the far end when every node is.
    fn zone_end(&self, mut order: impl Iterator<Item = usize>) -> f64 {
        let mu_p = self.spec.friction * self.spec.pressure;
        let at_limit = |i: usize| self.converged[i].stress.abs() >= mu_p * (1.0 - AT_LIMIT);
        let Some(start) = order.next() else {
            return 0.0;
        };
        if !at_limit(start) {
            return self.nodes[start];
        }
        let mut previous = start;
        for next in order {
            if !at_limit(next) {
                // The sliding direction, and the slip at which the elastic point would reach
                // the limit in it.
                let sign = self.converged[previous].stress.signum();
                let saturation = mu_p / self.spec.stiffness;
                let target = self.points[next].plastic_slip + sign * saturation;
                let (s0, s1) = (
                    self.slip(&self.displacement, previous),
                    self.slip(&self.displacement, next),
                );
                let fraction = if s1 == s0 {
                    0.0
                } else {
                    ((target - s0) / (s1 - s0)).clamp(0.0, 1.0)
                };
                return self.nodes[previous] + fraction * (self.nodes[next] - self.nodes[previous]);
            }
            previous = next;
        }
        self.nodes[previous]
    }

    /// || |K| |u| || (N) at the committed displacement: what rounding every u to its nearest
    /// double moves the residual by, over eps / 2.
    fn magnitude_of_rows(&self) -> f64 {
        let rigidities = self.spec.rigidities;
        let u = &self.displacement;
        let last = self.nodes.len() - 1;
        let mut sum = 0.0;
        for i in 0..=last {
            for (bar, rigidity) in rigidities.iter().enumerate() {
                let at = |node: usize| u[NODE_DOFS * node + bar].abs();
                let mut row = 0.0;
                if i > 0 {
                    row += rigidity / (self.nodes[i] - self.nodes[i - 1]) * (at(i) + at(i - 1));
                }
                if i < last {
                    row += rigidity / (self.nodes[i + 1] - self.nodes[i]) * (at(i) + at(i + 1));
                }
                sum += row * row;
            }
        }
        sum.sqrt()
    }

    fn slip(&self, displacement: &[f64], node: usize) -> f64 {
        displacement[NODE_DOFS * node] - displacement[NODE_DOFS * node + 1]
    }

    /// A nodal quantity at any x in [0, L], linear between nodes.
    fn interpolate(&self, x: f64, value: impl Fn(usize) -> f64) -> f64 {
        let x = x.clamp(0.0, self.spec.length);
        let e = self
            .nodes
            .partition_point(|&n| n <= x)
            .clamp(1, self.nodes.len() - 1)
            - 1;
        let r = (x - self.nodes[e]) / (self.nodes[e + 1] - self.nodes[e]);
        (1.0 - r) * value(e) + r * value(e + 1)
    }
}

/// lambda = sqrt(W K_T (1/A0 + 1/A1)) (1/mm): the elastic slip obeys s'' = lambda^2 s (two bars
/// coupled by a spring layer), so 1/lambda is the length the mesh must resolve.
fn decay_rate(spec: &TwoBarSpec) -> f64 {
    let compliance = 1.0 / spec.rigidities[0] + 1.0 / spec.rigidities[1];
    (spec.width * compliance * spec.stiffness).sqrt()
}

impl Discretized for TwoBarFe {
    const RESIDUAL_TOLERANCE: f64 = 1e-11;

    fn load(&self) -> f64 {
        self.force
    }

    fn displacement(&self) -> &[f64] {
        &self.displacement
    }

    /// |F| + F_gross, or, when larger, the residual's own round-off floor over the tolerance: a
    /// row of K u sums terms (k / h) u, and the nearest representable u leaves each row off by
    /// up to (k / h) ulp(u). On a fine mesh of stiff bars that floor (observed: 1.8e-10 of
    /// |F| + F_gross at 2605 elements, k / h up to 1e10 N/mm; the estimate from |K| |u| is about
    /// 5 times that) is above the tolerance, and where points sit on the limit without being
    /// loaded (a zone frozen at mu P deep inside the overlap, which the load increment, decaying
    /// over 1/lambda, does not reach) the noise flips them between sliding and sticking from one
    /// iterate to the next, so the set of sliding points never repeats and Newton failed at the
    /// floor after 12 step cuts. With this floor and the tangent of points on the limit
    /// ([`Discretized::linearize`]), 300 random load paths (8 loads each, up to 0.999 F_gross
    /// either way; K_T from 10 to 1e7 MPa/mm, t1 from 1 to 7 mm, t2 from 0.5 to 4.5 mm, E2 from
    /// 1e3 to 1e6 MPa; up to 16000 elements) all converge, 5 refused beyond lambda L = 1333;
    /// before, 4 in 60 failed.
    fn load_scale(&self, force: f64) -> f64 {
        let physical = force.abs() + self.spec.gross_slip_force();
        let floor = 0.5 * f64::EPSILON * self.magnitude_of_rows();
        physical.max(floor / Self::RESIDUAL_TOLERANCE)
    }

    fn linearize(
        &self,
        displacement: &[f64],
        force: f64,
    ) -> (Vec<f64>, SymmetricBand, Vec<Response>) {
        let p = &self.spec;
        let (kt, mu_p) = (p.stiffness, p.friction * p.pressure);
        let mut residual = self.stiffness.mul_accurate(displacement);
        let mut tangent = self.stiffness.clone();
        let mut responses = Vec::with_capacity(self.points.len());
        for (i, (point, area)) in self.points.iter().zip(&self.areas).enumerate() {
            let response = point.respond(self.slip(displacement, i), kt, mu_p);
            let (first, second) = (NODE_DOFS * i, NODE_DOFS * i + 1);
            residual[first] += area * response.stress;
            residual[second] -= area * response.stress;
            // A point on the limit has two tangents, K_T if it unloads and 0 if it slides on.
            // The return mapping keeps it elastic (so that it does not flip on round-off), but a
            // step that starts with a whole sliding zone elastic loads it like a spring layer:
            // the excess decays over 1/lambda from the zone's ends, each iteration slides only a
            // few 1/lambda more, and a zone of thousands of elements (lambda L = 1600) took more
            // than the 60 iterations Newton allows however small the step. So a point on the
            // limit in the direction the force is moving is taken as sliding on: its zone
            // carries mu P at once. In the other direction it unloads, elastic (as every point
            // does at a reversal, Masing's premise); a wrong guess is corrected at the next
            // iterate.
            let on_limit = response.stress.abs() >= mu_p * (1.0 - AT_LIMIT)
                && response.stress * (force - self.force) > 0.0;
            let k = if on_limit {
                0.0
            } else {
                area * response.tangent
            };
            if k != 0.0 {
                tangent.add(first, first, k);
                tangent.add(second, second, k);
                tangent.add(second, first, -k);
            }
            responses.push(response);
        }
        residual[self.loaded()] -= force;
        let held = self.held();
        residual[held] = 0.0;
        tangent.fix(held);
        (residual, tangent, responses)
    }

    fn commit(&mut self, displacement: Vec<f64>, responses: Vec<Response>, force: f64) {
        for (point, response) in self.points.iter_mut().zip(&responses) {
            point.plastic_slip = response.plastic_slip;
        }
        self.displacement = displacement;
        self.force = force;
        self.converged = responses;
    }
}
