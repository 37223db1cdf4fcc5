//! Finite elements for the double-lap joint, independent of the closed forms.
//!
//! The covers move alike and nothing bends (docs/theory.md section 9), so the joint is two bars
//! over the overlap [0, L]: the inner plate (axial rigidity E1 t1 b) and both covers lumped into
//! one (2 E2 t2 b). Linear elements, one axial displacement per bar per node, the unknowns
//! interleaved (u_inner, u_cover) node by node so that the stiffness is a band of half-width 2.
//! The cover bar is held at x = 0, where the covers hand the force to the clamp; F pulls the inner
//! bar at x = L.
//!
//! Between the bars, at every node, one Jenkins point (`numeric::interface`) stands for both
//! faces over the node's tributary length w_i: a spring K_T 2 b w_i in series with a slider of
//! strength mu P 2 b w_i, acting on the slip s = u_inner - u_cover. Lumping the interface at the
//! nodes (the trapezoidal rule) rather than integrating it at Gauss points keeps the model a chain
//! of springs whose equations are a second-order finite difference of s'' = 2 c tau: the error
//! falls 4x per halving of the element size, and the sliding zones end between two nodes that
//! hold the slip's own values, not interpolations of them.
//!
//! The plastic slip of every point is the history, so any load path can be followed: up, down,
//! through zero to negative forces (a real load reversal) and back. Each load step is solved by
//! Newton's method on the banded system with the consistent tangent (K_T on elastic points, 0 on
//! sliding ones); the system is linear for a fixed set of sliding points, so Newton is an exact
//! active-set iteration. Nothing here reads a closed form: what this model agrees with, it agrees
//! with on its own.

use super::params::LapParams;
use crate::numeric::banded::SymmetricBand;
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::mesh::MeshDensity;
use crate::numeric::newton::{self, Discretized};
use crate::numeric::{NumericError, short, stiffness_advice};

/// Fewest elements per decay length 1/lambda of the elastic slip (lambda^2 = 2 K_T (1/(E1 t1) +
/// 1/(2 E2 t2))): [`LapFe::new`] refines the requested mesh to at least this. The onset of
/// sliding is what a coarse mesh gets worst: the end point's spring stands for half an element
/// of a slip that decays over 1/lambda, and F_1 comes out high by 0.125 (lambda h)^2, whatever
/// lambda L (measured from lambda L = 25 to 1600 against (L3): 12 %, 3.1 %, 0.78 %, 0.20 % at 1,
/// 2, 4, 8 elements per 1/lambda). 12 keeps it below the project's 1e-3; Delta is then within
/// 1e-6 and the zone ends within 0.002/lambda.
pub const ELEMENTS_PER_DECAY: f64 = 12.0;

/// Most elements [`LapFe::new`] builds: 16000. With [`ELEMENTS_PER_DECAY`] that resolves lambda
/// L up to 1333 (the bundled aluminium joint: K_T up to 6.7e7 MPa/mm), where the interface is
/// plain Coulomb to within mu P / K_T = 4.5e-8 mm in Delta (3e-6 of it). The cap is set by time:
/// each Newton iteration moves a sliding zone's end by a few 1/lambda only, so a load path costs
/// some lambda L / 3 iterations of O(elements) each, growing as (lambda L)^2. Measured (release,
/// the aluminium joint, one step to 0.6 F_gross / 40 steps to 0.95 F_gross): lambda L = 333, 4000
/// elements: 0.03 s / 0.19 s; 1333, 16000: 0.43 s / 1.3 s; 2667, 32000: 1.9 s / 4.0 s; 5164,
/// 62000: 8.5 s for the single step.
pub const MAX_ELEMENTS: usize = 16_000;

/// Relative distance below mu P at which a point counts as at the friction limit
/// ([`LapFe::sliding_zones`], and the tangent of a point on the limit): the return mapping lets
/// an elastic point reach 1e-9 beyond it.
const AT_LIMIT: f64 = 1e-9;

/// Unknowns per node: u_inner, u_cover.
const NODE_DOFS: usize = 2;
/// The cover bar's unknown at x = 0, held.
const HELD: usize = 1;

/// The double-lap joint discretized, with its current force and interface history.
#[derive(Debug, Clone)]
pub struct LapFe {
    params: LapParams,
    /// Node positions, uniform over [0, L].
    nodes: Vec<f64>,
    /// Interface area 2 b w_i of each node's Jenkins point (both faces), mm^2.
    areas: Vec<f64>,
    /// (u_inner, u_cover) at every node, interleaved (mm).
    displacement: Vec<f64>,
    points: Vec<InterfacePoint>,
    force: f64,
    /// The two bars' stiffness, the cover held at x = 0.
    stiffness: SymmetricBand,
    /// Interface responses of the last converged step; empty before the first.
    converged: Vec<Response>,
}

impl LapFe {
    /// The unloaded joint (F = 0) on a uniform mesh of `density.elements` elements, refined to at
    /// least [`ELEMENTS_PER_DECAY`] per 1/lambda and capped at [`MAX_ELEMENTS`].
    ///
    /// Uniform, unlike the beams' and the plate's graded meshes: on a load path the sliding
    /// zones grow inward from both ends and, after a reversal, new ones grow from the ends again,
    /// so the elastic zone's boundary layers travel across the whole overlap and no place can be
    /// left coarse (`density.smallest_fraction` is therefore not used). The default 400 elements
    /// ([`MeshDensity::default`]) put 77 elements in each 1/lambda of the bundled joint (lambda L
    /// = 5.2): F_1 within 2e-5, Delta within 6e-6 and the zone ends within 3e-4 mm (measured
    /// against the closed forms in tests/lap_cross_check.rs). The refinement to 1/lambda is the
    /// only reading of the parameters the mesh makes: a material length, never a closed-form
    /// result. The count is capped so that no input allocates without bound; a joint the cap
    /// cannot resolve is refused by [`LapFe::load_to`].
    pub fn new(params: LapParams, density: MeshDensity) -> Self {
        let needed = (ELEMENTS_PER_DECAY * decay_rate(&params) * params.length).ceil();
        let needed = if needed.is_finite() {
            needed.min(MAX_ELEMENTS as f64) as usize
        } else {
            MAX_ELEMENTS
        };
        let elements = density.elements.max(needed).clamp(1, MAX_ELEMENTS);
        let length = params.length;
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
                2.0 * params.width * 0.5 * (left + right)
            })
            .collect();
        let unknowns = NODE_DOFS * (elements + 1);
        let mut stiffness = SymmetricBand::zeros(unknowns, 2);
        let inner = params.inner_modulus * params.inner_thickness * params.width;
        let covers = 2.0 * params.cover_modulus * params.cover_thickness * params.width;
        for e in 0..elements {
            let l = nodes[e + 1] - nodes[e];
            for (bar, rigidity) in [(0, inner), (1, covers)] {
                let (i, j) = (NODE_DOFS * e + bar, NODE_DOFS * (e + 1) + bar);
                let k = rigidity / l;
                stiffness.add(i, i, k);
                stiffness.add(j, j, k);
                stiffness.add(j, i, -k);
            }
        }
        stiffness.fix(HELD);
        LapFe {
            params,
            points: vec![InterfacePoint::default(); nodes.len()],
            areas,
            displacement: vec![0.0; unknowns],
            force: 0.0,
            stiffness,
            converged: Vec::new(),
            nodes,
        }
    }

    /// Moves the force from its current value to `force` (N, either sign: a negative force pushes
    /// the inner plate back in) in `steps` equal increments, halving an increment whose Newton
    /// iterations fail (up to 12 times). Every point keeps its plastic slip from step to step, so
    /// the answer depends on the path: unloading and reloading follow the hysteresis loop.
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] for parameters outside their domains, a joint whose 1/lambda
    /// the largest mesh cannot resolve ([`LapFe::check_resolvable`]), or |F| >= F_gross = 2 b mu
    /// P L (beyond it no static state exists; at it both interfaces slide whole and the inner
    /// plate's position is undetermined); [`NumericError::BadLoad`] for a non-finite force;
    /// [`NumericError::NoConvergence`] when an increment fails even after 12 halvings;
    /// [`NumericError::Singular`] should never happen below F_gross.
    pub fn load_to(&mut self, force: f64, steps: usize) -> Result<(), NumericError> {
        Self::check_resolvable(&self.params)?;
        if !force.is_finite() {
            return Err(NumericError::BadLoad(force));
        }
        let gross = self.params.gross_slip_force();
        if force.abs() >= gross {
            return Err(NumericError::OutOfRange(format!(
                "|F| = {} N must be below F_gross = 2 b mu P L = {} N: at it both interfaces \
                 slide over the whole overlap and the inner plate's position is undetermined; \
                 beyond it no static state exists",
                short(force.abs()),
                short(gross)
            )));
        }
        newton::load_to(self, force, steps)
    }

    /// Refuses joints this solver cannot answer: parameters outside their domains (the bars
    /// would have no stiffness or the interface no strength), and joints whose decay length
    /// 1/lambda of the elastic slip is shorter than [`ELEMENTS_PER_DECAY`] elements of the
    /// largest mesh ([`MAX_ELEMENTS`]), i.e. lambda L above 1333. The slip and the shear change
    /// within a few 1/lambda of each loaded end and of each sliding zone's end; a coarser mesh
    /// puts F_1 off by 0.125 (lambda h)^2 and the zone ends by a fraction of an element. Such an
    /// interface is plain Coulomb to within mu P / K_T in Delta (L7), so the message says to
    /// lower K_T to where the solver works.
    ///
    /// # Errors
    /// [`NumericError::OutOfRange`] with the field out of its domain, or with lambda L and the
    /// largest K_T that is resolved.
    pub fn check_resolvable(params: &LapParams) -> Result<(), NumericError> {
        params
            .check()
            .map_err(|e| NumericError::OutOfRange(e.to_string()))?;
        let decays = decay_rate(params) * params.length;
        let most = MAX_ELEMENTS as f64 / ELEMENTS_PER_DECAY;
        // Conditioning: the inner plate is held only by the interface, so the stiffness matrix's
        // smallest eigenvalue is about the interface's total stiffness 2 K_T b L and its largest
        // 4 k b / h (k the stiffer member's E t): their ratio costs its digits to the solve, so
        // beyond 1e13 fewer than three are left (an overlap of 1e-5 mm at the default mesh: 2e15,
        // a singular matrix).
        let elements = (MeshDensity::default().elements as f64)
            .max((ELEMENTS_PER_DECAY * decays).ceil())
            .min(MAX_ELEMENTS as f64);
        let stiffer = params.inner_stiffness().max(params.covers_stiffness());
        let condition = 2.0 * stiffer * elements
            / (params.tangential_stiffness * params.length * params.length);
        if condition > 1e13 {
            return Err(NumericError::OutOfRange(format!(
                "the bars' elements are {} times stiffer than the whole interface (at most 1e13, \
                 where the solve keeps three digits): lengthen the overlap L = {} mm or raise \
                 K_T = {} MPa/mm",
                short(condition),
                short(params.length),
                short(params.tangential_stiffness)
            )));
        }
        if decays <= most {
            return Ok(());
        }
        // lambda scales as sqrt(K_T); a hair below the bound, so that the value the message
        // names, rounded to four digits, is accepted.
        let largest = 0.999 * params.tangential_stiffness * (most / decays).powi(2);
        Err(NumericError::OutOfRange(format!(
            "the elastic slip decays over 1/lambda = {} mm, lambda L = {}: resolving it with \
             {ELEMENTS_PER_DECAY} elements per 1/lambda needs more than the {MAX_ELEMENTS} \
             elements the solver builds (lambda L <= {}); {} (the interface is then plain \
             Coulomb to within mu P / K_T in Delta)",
            short(params.length / decays),
            short(decays),
            short(most),
            stiffness_advice(largest, Some("shorten the overlap L"))
        )))
    }

    /// The current force (N).
    pub fn force(&self) -> f64 {
        self.force
    }

    /// Number of elements (after the refinement of [`LapFe::new`]).
    pub fn elements(&self) -> usize {
        self.nodes.len() - 1
    }

    /// The joint displacement Delta = u_inner(L) - u_cover(0) (mm): what an extensometer across
    /// the overlap reads (u_cover(0) is held at 0; it is subtracted all the same so that the
    /// definition does not hang on where the model is held).
    pub fn joint_displacement(&self) -> f64 {
        let last = self.nodes.len() - 1;
        self.displacement[NODE_DOFS * last] - self.displacement[HELD]
    }

    /// Slip s = u_inner - u_cover at any x in [0, L] (mm), linear between nodes.
    pub fn slip_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.slip(&self.displacement, i))
    }

    /// Interface shear tau on the inner plate at any x in [0, L] (MPa), positive resisting a
    /// positive F; linear between the nodes' values (0 before the first load step).
    pub fn shear_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.converged.get(i).map_or(0.0, |r| r.stress))
    }

    /// Plastic slip (the sliders' displacement) at any x in [0, L] (mm), linear between nodes:
    /// the history a load path leaves behind; 0 wherever no point has slid.
    pub fn plastic_slip_at(&self, x: f64) -> f64 {
        self.interpolate(x, |i| self.points[i].plastic_slip)
    }

    /// The shear integrated over both interfaces, sum of 2 b w_i tau_i (N): equal to F at every
    /// converged step (the inner plate's equilibrium; the interface, not the support, carries the
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
        let d = self.params.length - self.zone_end((0..=last).rev());
        let a = a.clamp(0.0, self.params.length);
        (a, d.clamp(0.0, self.params.length - a))
    }

    /// Where the zone at the limit that starts at the first node of `order` ends (x, mm): the
    /// starting node's position when it is not at the limit, the far end when every node is.
    fn zone_end(&self, mut order: impl Iterator<Item = usize>) -> f64 {
        let mu_p = self.params.friction * self.params.pressure;
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
                let saturation = mu_p / self.params.tangential_stiffness;
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
        let p = &self.params;
        let rigidities = [
            p.width * p.inner_stiffness(),
            p.width * p.covers_stiffness(),
        ];
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
        let x = x.clamp(0.0, self.params.length);
        let e = self
            .nodes
            .partition_point(|&n| n <= x)
            .clamp(1, self.nodes.len() - 1)
            - 1;
        let r = (x - self.nodes[e]) / (self.nodes[e + 1] - self.nodes[e]);
        (1.0 - r) * value(e) + r * value(e + 1)
    }
}

/// lambda = sqrt(2 K_T (1/(E1 t1) + 1/(2 E2 t2))) (1/mm): the elastic slip obeys s'' = lambda^2 s
/// (two bars coupled by a spring layer on both faces), so 1/lambda is the length the mesh must
/// resolve.
fn decay_rate(params: &LapParams) -> f64 {
    let compliance = 1.0 / params.inner_stiffness() + 1.0 / params.covers_stiffness();
    (2.0 * compliance * params.tangential_stiffness).sqrt()
}

impl Discretized for LapFe {
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
        let physical = force.abs() + self.params.gross_slip_force();
        let floor = 0.5 * f64::EPSILON * self.magnitude_of_rows();
        physical.max(floor / Self::RESIDUAL_TOLERANCE)
    }

    fn linearize(
        &self,
        displacement: &[f64],
        force: f64,
    ) -> (Vec<f64>, SymmetricBand, Vec<Response>) {
        let p = &self.params;
        let (kt, mu_p) = (p.tangential_stiffness, p.friction * p.pressure);
        let mut residual = self.stiffness.mul_accurate(displacement);
        let mut tangent = self.stiffness.clone();
        let mut responses = Vec::with_capacity(self.points.len());
        for (i, (point, area)) in self.points.iter().zip(&self.areas).enumerate() {
            let response = point.respond(self.slip(displacement, i), kt, mu_p);
            let (inner, cover) = (NODE_DOFS * i, NODE_DOFS * i + 1);
            residual[inner] += area * response.stress;
            residual[cover] -= area * response.stress;
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
                tangent.add(inner, inner, k);
                tangent.add(cover, cover, k);
                tangent.add(cover, inner, -k);
            }
            responses.push(response);
        }
        let last = residual.len() - NODE_DOFS;
        residual[last] -= force;
        residual[HELD] = 0.0;
        tangent.fix(HELD);
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

#[cfg(test)]
mod tests {
    use super::*;

    fn aluminium(elements: usize) -> LapFe {
        LapFe::new(LapParams::ALUMINIUM, MeshDensity::with_elements(elements))
    }

    /// F_1 as this model sees it: below it the model is linear, so the force that brings the
    /// first point to mu P is read off a small load.
    fn own_first_slip_force(elements: usize) -> f64 {
        let mut fe = aluminium(elements);
        fe.load_to(1.0, 1).unwrap();
        let mu_p = 3.0;
        let largest = fe
            .converged
            .iter()
            .map(|r| r.stress.abs())
            .fold(0.0, f64::max);
        mu_p / largest
    }

    fn sliding_points(fe: &LapFe) -> usize {
        fe.converged.iter().filter(|r| r.sliding).count()
    }

    #[test]
    fn the_interface_carries_the_whole_force_at_every_converged_step() {
        let mut fe = aluminium(100);
        let gross = LapParams::ALUMINIUM.gross_slip_force();
        let path = [0.2, 0.5, 0.9, 0.99, 0.3, -0.4, -0.95, 0.0, 0.7];
        for target in path.map(|f| f * gross) {
            // One converged step at a time, so that every step is checked.
            let start = fe.force();
            for i in 1..=4 {
                fe.load_to(start + (target - start) * f64::from(i) / 4.0, 1)
                    .unwrap();
                let error = (fe.transferred_force() - fe.force()).abs();
                assert!(error < 1e-9 * gross, "F = {}: off by {error} N", fe.force());
            }
        }
    }

    #[test]
    fn below_first_slip_nothing_slides_and_the_joint_is_linear() {
        let onset = own_first_slip_force(100);
        // The aluminium joint's onset lies between a third and a half of F_gross = 6000 N.
        assert!(onset > 2000.0 && onset < 3000.0, "{onset}");
        let mut fe = aluminium(100);
        fe.load_to(0.5 * onset, 1).unwrap();
        let half = fe.joint_displacement();
        fe.load_to(0.99 * onset, 3).unwrap();
        assert_eq!(sliding_points(&fe), 0);
        assert_eq!(fe.sliding_zones(), (0.0, 0.0));
        assert!((fe.joint_displacement() / half - 1.98).abs() < 1e-9);
        fe.load_to(1.01 * onset, 1).unwrap();
        assert!(sliding_points(&fe) > 0);
    }

    #[test]
    fn unloading_leaves_residual_slip_only_where_something_slid() {
        let onset = own_first_slip_force(100);
        let mut elastic = aluminium(100);
        elastic.load_to(0.9 * onset, 3).unwrap();
        let loaded = elastic.joint_displacement();
        elastic.load_to(0.0, 3).unwrap();
        assert!(elastic.points.iter().all(|p| p.plastic_slip == 0.0));
        assert!(elastic.joint_displacement().abs() < 1e-12 * loaded);
        assert!(elastic.slip_at(20.0).abs() < 1e-12 * loaded);

        let mut slid = aluminium(100);
        slid.load_to(4800.0, 3).unwrap();
        let loaded = slid.joint_displacement();
        let (a, d) = slid.sliding_zones();
        assert!(a > 0.0 && d > 0.0, "{a} {d}");
        slid.load_to(0.0, 3).unwrap();
        // The slid ends keep a plastic slip, the middle none; the joint stays stretched.
        assert!(slid.plastic_slip_at(0.0) > 0.0 && slid.plastic_slip_at(40.0) > 0.0);
        assert_eq!(slid.plastic_slip_at(20.0), 0.0);
        assert!(slid.joint_displacement() > 1e-3 * loaded);
        assert!(slid.transferred_force().abs() < 1e-9 * 6000.0);
    }

    #[test]
    fn a_full_cycle_closes_and_is_antisymmetric() {
        let mut fe = aluminium(100);
        let amplitude = 0.8 * LapParams::ALUMINIUM.gross_slip_force();
        fe.load_to(amplitude, 4).unwrap();
        let top = fe.joint_displacement();
        fe.load_to(-amplitude, 16).unwrap();
        let bottom = fe.joint_displacement();
        fe.load_to(amplitude, 16).unwrap();
        assert!((bottom + top).abs() < 1e-9 * top, "{bottom} vs {top}");
        assert!(
            (fe.joint_displacement() / top - 1.0).abs() < 1e-9,
            "{} vs {top}",
            fe.joint_displacement()
        );
        // And the loop is open: at zero force on the way down the joint is still stretched.
        let mut half = aluminium(100);
        half.load_to(amplitude, 4).unwrap();
        half.load_to(0.0, 8).unwrap();
        assert!(half.joint_displacement() > 1e-3 * top);
    }

    #[test]
    fn a_rising_load_does_not_depend_on_the_steps() {
        let mut one = aluminium(100);
        one.load_to(5000.0, 1).unwrap();
        let mut many = aluminium(100);
        many.load_to(5000.0, 20).unwrap();
        assert!((one.joint_displacement() / many.joint_displacement() - 1.0).abs() < 1e-12);
        let (a1, d1) = one.sliding_zones();
        let (a2, d2) = many.sliding_zones();
        assert!((a1 - a2).abs() < 1e-9 && (d1 - d2).abs() < 1e-9);
    }

    #[test]
    fn the_mesh_resolves_the_decay_length_and_refuses_what_it_cannot() {
        // lambda L = 5.16 for the bundled joint: 62 elements at least.
        assert_eq!(aluminium(10).elements(), 62);
        assert_eq!(aluminium(100).elements(), 100);
        let stiff = LapParams {
            tangential_stiffness: 1e7,
            ..LapParams::ALUMINIUM
        };
        // lambda L = 516: 12 elements per 1/lambda.
        assert_eq!(
            LapFe::new(stiff, MeshDensity::default()).elements(),
            (12.0 * 516.397_779_494_322_3_f64).ceil() as usize
        );
        let too_stiff = LapParams {
            tangential_stiffness: 1e10,
            ..LapParams::ALUMINIUM
        };
        let Err(NumericError::OutOfRange(message)) = LapFe::check_resolvable(&too_stiff) else {
            panic!("refused")
        };
        assert!(
            message.contains("lower K_T to at most 66600000 MPa/mm"),
            "{message}"
        );
        let named = LapParams {
            tangential_stiffness: 6.66e7,
            ..LapParams::ALUMINIUM
        };
        assert!(LapFe::check_resolvable(&named).is_ok());
        let negative = LapParams {
            width: -1.0,
            ..LapParams::ALUMINIUM
        };
        assert!(LapFe::check_resolvable(&negative).is_err());
    }

    #[test]
    fn forces_without_a_static_state_are_refused() {
        let mut fe = aluminium(100);
        assert!(matches!(
            fe.load_to(f64::NAN, 1),
            Err(NumericError::BadLoad(_))
        ));
        for f in [6000.0, -6000.0, 1e9] {
            let Err(NumericError::OutOfRange(message)) = fe.load_to(f, 1) else {
                panic!("{f} refused")
            };
            assert!(
                message.contains("F_gross = 2 b mu P L = 6000 N"),
                "{message}"
            );
        }
        assert_eq!(fe.force(), 0.0);
        // Just below F_gross the elastic middle has shrunk below 1/lambda (7.7 mm here): to 1.7
        // mm, where its equilibrium for a short middle, l^3 lambda^2 / 12 = L (1 - F / F_gross)
        // (by hand from s'' = lambda^2 s with s = mu P / K_T at both ends), puts it.
        fe.load_to(5999.0, 4).unwrap();
        let (a, d) = fe.sliding_zones();
        assert!((40.0 - a - d - 1.69).abs() < 0.05, "{a} {d}");
    }
}
