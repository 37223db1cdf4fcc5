//! The squeezed plate as a 2-D plane-strain continuum: the answer where the strip theory fails.
//!
//! The strip theory (`problems::plate::closed_form`) assumes the displacement uniform through the thickness and the
//! contact pressure equal to P. For stiff interfaces the slip zone at the free end is no wider than
//! about two plate thicknesses, and neither holds (docs/theory.md, "Validity of the closed forms").
//! This model drops both assumptions: 8-node quadrilaterals (Q8, 3 x 3 Gauss points) in plane strain
//! over [0, L] x [0, t_p], symmetry u = 0 at x = 0, the pressure P on the upper face, and on the
//! lower face the rigid plane: no normal motion (v = 0) and, at every node, the same Jenkins point as
//! the 1-D solvers (tangential stiffness K_T times the node's share of the face, strength mu times
//! the node's contact force). The contact force is the reaction of v = 0, so it comes out of the
//! solution: the strengths are found by a fixed point (solve with given strengths, take the
//! reactions, repeat), each solve being a Newton iteration with the shared driver. Loading is
//! proportional (every force scales with P), so one load step reaches P.
//!
//! Nodes are numbered column by column from x = 0, so the stiffness is banded (half-bandwidth about
//! 5 ny + 4 unknowns for ny elements through the thickness).

use super::params::PlateParams;
use crate::numeric::NumericError;
use crate::numeric::banded::SymmetricBand;
use crate::numeric::grid::Q8Grid;
use crate::numeric::interface::{InterfacePoint, Response};
use crate::numeric::mesh::graded_toward_end;
use crate::numeric::newton::{self, Discretized};
use crate::numeric::q8::plane_strain;

/// How fine the continuum mesh is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ContinuumMesh {
    /// Elements through the thickness (the element sizes along x scale with it).
    pub layers: usize,
}

impl Default for ContinuumMesh {
    /// Four elements through the thickness, as CalculiX's calibration decks.
    fn default() -> Self {
        ContinuumMesh { layers: 4 }
    }
}

/// The converged continuum solution at the applied pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct ContinuumPlate {
    /// u(L) on the contact face (y = 0) (mm).
    pub end_displacement_face: f64,
    /// u(L) at mid-thickness (mm).
    pub end_displacement_mid: f64,
    /// u(L) averaged through the thickness (Simpson's rule per element: exact for the element's
    /// field) (mm): what the strip theory's u stands for.
    pub end_displacement_mean: f64,
    /// Where K_T |u| = mu P on the contact face, walking from the free end: X_r as the strip theory
    /// defines it (mm); L when the end does not reach it.
    pub micro_zone_end: f64,
    /// Contact pressure at the free end over P: the stress concentration the strip theory ignores.
    /// The end node's force over its share of the face: at the free-end corner the traction is
    /// singular, so this grows as the mesh is refined (docs/theory.md, (P12)); a value at the
    /// mesh's resolution, [`ContinuumPlate::end_layer_pressure_ratio`] is the converged measure.
    pub end_pressure_ratio: f64,
    /// The contact pressure over P at each contact-face node, (x (mm), P_r / P), from x = 0 to L:
    /// the node's share of the plane's reaction over its share of the face (Simpson weights).
    pub contact_pressure: Vec<(f64, f64)>,
    /// Mean contact pressure over the last t_p before the free end (over the whole half-length
    /// when L < t_p), over P: the resultant there, which converges with the mesh where the peak
    /// does not (to 0.02 % between 4 and 32 layers).
    pub end_layer_pressure_ratio: f64,
    /// Mean contact pressure over the last t_p / 10, over P: the free-end peak at a resolution of
    /// t_p / 10, which converges (the nodal peak grows like the logarithm of the mesh refinement).
    pub edge_pressure_ratio: f64,
    /// Smallest and largest P_r / P at the nodes at least t_p from the free end ((1, 1) when
    /// L <= t_p): how flat the pressure is away from the edge.
    pub interior_pressure_range: (f64, f64),
    /// (x, u) along the contact face (mm, mm).
    pub face: Vec<(f64, f64)>,
    /// Fixed-point iterations on the contact pressure.
    pub iterations: usize,
}

/// Largest alpha t_p the solver accepts (K_T = 1.5e8 MPa/mm for the paper's plate): Newton stops
/// converging somewhere below 51 (the paper's plate at K_T = 1e9 MPa/mm fails after 1.5 s), while
/// the answer has nearly stopped changing (u(L) mean 1.2329e-5 mm at alpha t_p = 5.1, 1.2141e-5 at
/// 16.1: 1.5 %).
const MAX_THICKNESS_OVER_LAYER: f64 = 20.0;

/// The window, in thicknesses, over which [`ContinuumPlate::edge_pressure_ratio`] averages.
const EDGE_WINDOW: f64 = 0.1;

/// Fixed-point iterations allowed on the contact forces.
const MAX_PRESSURE_ITERATIONS: usize = 60;
/// Relative change of the contact forces that ends the fixed point.
const PRESSURE_TOLERANCE: f64 = 1e-9;

/// Solves the plate of `params` under its pressure P.
///
/// # Errors
/// [`NumericError::OutOfRange`] for inputs outside their domains or an interface too stiff for it
/// (alpha t_p > 20); other [`NumericError`]s when Newton or the fixed point does not converge.
pub fn solve_plate_continuum(
    params: PlateParams,
    mesh: ContinuumMesh,
) -> Result<ContinuumPlate, NumericError> {
    // Only accepted inputs (every one finite and in its domain) reach the mesh.
    params
        .check()
        .map_err(|e| NumericError::OutOfRange(e.to_string()))?;
    let p = &params;
    let ratio = ((1.0 - p.poisson * p.poisson) * p.tangential_stiffness
        / (p.youngs_modulus * p.thickness))
        .sqrt()
        * p.thickness;
    if ratio > MAX_THICKNESS_OVER_LAYER {
        return Err(NumericError::OutOfRange(format!(
            "K_T = {} MPa/mm is too stiff for the continuum solver: alpha t_p = {:.3} > {}, where \
             Newton no longer converges; the interface is then Coulomb-like (the continuum u(L) \
             changes by 1.5 % between alpha t_p = 5 and 16)",
            crate::kernel::params::Compact(p.tangential_stiffness),
            ratio,
            MAX_THICKNESS_OVER_LAYER
        )));
    }
    let grid = Grid::new(&params, mesh);
    if p.poisson == 0.0 {
        return Ok(unstrained(&grid, &params));
    }
    let pressure = params.pressure;
    // Start from the strip theory's contact force: P times each node's share of the face.
    let mut contact: Vec<f64> = grid.face_weights.iter().map(|w| w * pressure).collect();
    for iteration in 1..=MAX_PRESSURE_ITERATIONS {
        let mut model = Continuum::new(&grid, &params, &contact);
        newton::load_to(&mut model, pressure, 1)?;
        let reactions = model.face_reactions();
        let scale = reactions.iter().fold(0.0_f64, |m, r| m.max(r.abs()));
        let change = reactions
            .iter()
            .zip(&contact)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        // A node pulled upward would need tension from the plane: it carries no friction.
        contact = reactions.iter().map(|r| r.max(0.0)).collect();
        if change <= PRESSURE_TOLERANCE * scale {
            return Ok(model.result(iteration, &contact));
        }
    }
    Err(NumericError::NoConvergence {
        load: pressure,
        cuts: 0,
    })
}

/// The solution at nu = 0, exactly: the uniform stress sigma_y = -P, sigma_x = sigma_z = tau = 0
/// satisfies equilibrium, the loaded and free faces and the symmetry plane, and in plane strain
/// with nu = 0 it strains nothing along x, so no point moves along x, nothing slips, and the
/// interface carries no shear; the elastic solution being unique, it is the solution. Newton
/// would return it to rounding (u(L) = 2e-21 mm), which a report then divided by the strip
/// theory's exact 0 ("+inf %").
fn unstrained(grid: &Grid, params: &PlateParams) -> ContinuumPlate {
    let last = grid.face_weights.len() - 1;
    let face = (0..=last).map(|i| (grid.face_x(i), 0.0)).collect();
    ContinuumPlate {
        end_displacement_face: 0.0,
        end_displacement_mid: 0.0,
        end_displacement_mean: 0.0,
        micro_zone_end: params.half_length,
        end_pressure_ratio: 1.0,
        contact_pressure: (0..=last).map(|i| (grid.face_x(i), 1.0)).collect(),
        end_layer_pressure_ratio: 1.0,
        edge_pressure_ratio: 1.0,
        interior_pressure_range: (1.0, 1.0),
        face,
        iterations: 0,
    }
}

/// The mesh: the plate's structured Q8 grid (`numeric::grid`), numbered column by column from
/// x = 0, and its contact face.
#[derive(Debug, Clone)]
struct Grid {
    mesh: Q8Grid,
    /// Unknowns: (u, v) of every node.
    unknowns: usize,
    /// Share of the contact face of each lower-face node (mm per mm of width): Simpson weights.
    face_weights: Vec<f64>,
    bandwidth: usize,
}

impl Grid {
    /// x (mm) of the i-th node along the contact face (corners at even i, midsides at odd i).
    fn face_x(&self, i: usize) -> f64 {
        if i.is_multiple_of(2) {
            self.mesh.xs[i / 2]
        } else {
            0.5 * (self.mesh.xs[i / 2] + self.mesh.xs[i / 2 + 1])
        }
    }

    fn new(p: &PlateParams, mesh: ContinuumMesh) -> Grid {
        let layers = mesh.layers.max(1);
        let refinement = layers as f64 / 4.0;
        let layer = p.thickness / layers as f64;
        let alpha = ((1.0 - p.poisson * p.poisson) * p.tangential_stiffness
            / (p.youngs_modulus * p.thickness))
            .sqrt();
        // As the CalculiX decks (`fe::deck`): 1/(10 alpha) or half a layer at the free end, growing
        // by 20 % per element to half the thickness (or L/50).
        let finest =
            (0.1 / alpha).clamp(layer * refinement / 8.0, 0.5 * layer * refinement) / refinement;
        let coarsest = (p.thickness / (2.0 * refinement))
            .max(p.half_length / (50.0 * refinement))
            .max(finest);
        let xs = graded_toward_end(0.0, p.half_length, finest, coarsest, 1.2);
        let ys: Vec<f64> = (0..=layers)
            .map(|j| p.thickness * j as f64 / layers as f64)
            .collect();
        let ni = 2 * (xs.len() - 1) + 1;
        let mut face_weights = vec![0.0; ni];
        for e in 0..xs.len() - 1 {
            let length = xs[e + 1] - xs[e];
            face_weights[2 * e] += length / 6.0;
            face_weights[2 * e + 1] += 2.0 * length / 3.0;
            face_weights[2 * e + 2] += length / 6.0;
        }
        let mut body = Q8Grid::new(xs, ys, 0, plane_strain(p.youngs_modulus, p.poisson));
        let unknowns = body.number_by_columns(0);
        let bandwidth = body.bandwidth();
        Grid {
            mesh: body,
            unknowns,
            face_weights,
            bandwidth,
        }
    }

    /// The tributary interval of each contact-face node: the part of the face its Simpson weight
    /// stands for (a corner L_e/6 into each neighbouring element, a midside node the middle 2/3).
    fn tributary(&self, i: usize) -> (f64, f64) {
        let e = i / 2;
        if i.is_multiple_of(2) {
            let left = if e == 0 {
                self.mesh.xs[0]
            } else {
                self.mesh.xs[e] - (self.mesh.xs[e] - self.mesh.xs[e - 1]) / 6.0
            };
            let right = if e + 1 == self.mesh.xs.len() {
                self.mesh.xs[e]
            } else {
                self.mesh.xs[e] + (self.mesh.xs[e + 1] - self.mesh.xs[e]) / 6.0
            };
            (left, right)
        } else {
            let length = self.mesh.xs[e + 1] - self.mesh.xs[e];
            (
                self.mesh.xs[e] + length / 6.0,
                self.mesh.xs[e + 1] - length / 6.0,
            )
        }
    }

    /// The mean of the nodal pressures `ratio` (x, P_r / P) over the last `window` before the free
    /// end (the whole face when it is shorter), each node's value held over its tributary interval,
    /// so that the whole face integrates to the total reaction exactly.
    fn mean_over_last(&self, ratio: &[(f64, f64)], window: f64) -> f64 {
        let end = self.mesh.xs[self.mesh.xs.len() - 1];
        let window = window.min(end);
        let from = end - window;
        let resultant: f64 = ratio
            .iter()
            .enumerate()
            .map(|(i, &(_, r))| {
                let (a, b) = self.tributary(i);
                r * (b - a.max(from)).max(0.0)
            })
            .sum();
        resultant / window
    }

    /// The x unknown of node (i, j).
    fn u(&self, i: usize, j: usize) -> usize {
        self.mesh.dof(i, j)[0]
    }

    /// The y unknown of node (i, j).
    fn v(&self, i: usize, j: usize) -> usize {
        self.mesh.dof(i, j)[1]
    }
}

/// One solve with given contact forces (the strengths are mu times them).
struct Continuum<'a> {
    grid: &'a Grid,
    params: &'a PlateParams,
    /// Elastic stiffness, without boundary conditions.
    stiffness: SymmetricBand,
    /// Nodal forces of P = 1 on the upper face.
    unit_load: Vec<f64>,
    /// Contact force of each lower-face node at P = 1 (N per mm of width).
    unit_contact: Vec<f64>,
    fixed: Vec<usize>,
    displacement: Vec<f64>,
    points: Vec<InterfacePoint>,
    pressure: f64,
}

impl<'a> Continuum<'a> {
    fn new(grid: &'a Grid, params: &'a PlateParams, contact: &[f64]) -> Continuum<'a> {
        let n = grid.unknowns;
        let mut stiffness = SymmetricBand::zeros(n, grid.bandwidth);
        let mesh = &grid.mesh;
        for ex in 0..mesh.elements_x() {
            for ey in 0..mesh.elements_y() {
                let k = mesh.element_stiffness(ex, ey);
                let dofs = mesh.element_dofs(ex, ey);
                for a in 0..16 {
                    for b in 0..16 {
                        if dofs[a] > dofs[b] || a == b {
                            stiffness.add(dofs[a], dofs[b], k[a][b]);
                        }
                    }
                }
            }
        }
        let top = 2 * mesh.elements_y();
        let mut unit_load = vec![0.0; n];
        for (i, w) in grid.face_weights.iter().enumerate() {
            unit_load[grid.v(i, top)] -= w;
        }
        let columns = grid.face_weights.len();
        let mut fixed: Vec<usize> = (0..=top).map(|j| grid.u(0, j)).collect();
        fixed.extend((0..columns).map(|i| grid.v(i, 0)));
        let pressure = params.pressure;
        Continuum {
            grid,
            params,
            stiffness,
            unit_load,
            unit_contact: contact.iter().map(|c| c / pressure).collect(),
            fixed,
            displacement: vec![0.0; n],
            points: vec![InterfacePoint::default(); columns],
            pressure: 0.0,
        }
    }

    fn responses(&self, displacement: &[f64], pressure: f64) -> Vec<Response> {
        let p = self.params;
        (0..self.points.len())
            .map(|i| {
                let slip = displacement[self.grid.u(i, 0)];
                let stiffness = p.tangential_stiffness * self.grid.face_weights[i];
                let strength = p.friction * self.unit_contact[i] * pressure;
                self.points[i].respond(slip, stiffness, strength)
            })
            .collect()
    }

    /// The upward force the plane exerts on each lower-face node (N per mm of width).
    fn face_reactions(&self) -> Vec<f64> {
        let internal = self.stiffness.mul_accurate(&self.displacement);
        (0..self.points.len())
            .map(|i| {
                let dof = self.grid.v(i, 0);
                internal[dof] - self.pressure * self.unit_load[dof]
            })
            .collect()
    }

    fn result(&self, iterations: usize, contact: &[f64]) -> ContinuumPlate {
        let g = self.grid;
        let p = self.params;
        let last = g.face_weights.len() - 1;
        let layers = g.mesh.elements_y();
        let column: Vec<f64> = (0..=2 * layers)
            .map(|j| self.displacement[g.u(last, j)])
            .collect();
        let mean = column
            .windows(3)
            .step_by(2)
            .map(|w| (w[0] + 4.0 * w[1] + w[2]) / 6.0)
            .sum::<f64>()
            / layers as f64;
        let face: Vec<(f64, f64)> = (0..=last)
            .map(|i| (g.face_x(i), self.displacement[g.u(i, 0)]))
            .collect();
        let saturation = p.friction * p.pressure / p.tangential_stiffness;
        let mut start = p.half_length;
        if face[last].1.abs() >= saturation {
            let mut i = last;
            while i > 0 && face[i - 1].1.abs() >= saturation {
                i -= 1;
            }
            start = if i == 0 {
                0.0
            } else {
                let ((x0, s0), (x1, s1)) = (face[i - 1], face[i]);
                x0 + (x1 - x0) * (saturation - s0.abs()) / (s1.abs() - s0.abs())
            };
        }
        // A node's force over its share of the face is the pressure there.
        let contact_pressure: Vec<(f64, f64)> = (0..=last)
            .map(|i| (g.face_x(i), contact[i] / (g.face_weights[i] * p.pressure)))
            .collect();
        let end_layer_pressure_ratio = g.mean_over_last(&contact_pressure, p.thickness);
        let edge_pressure_ratio = g.mean_over_last(&contact_pressure, EDGE_WINDOW * p.thickness);
        let interior_pressure_range = contact_pressure
            .iter()
            .filter(|(x, _)| *x <= p.half_length - p.thickness)
            .fold(None, |range: Option<(f64, f64)>, &(_, r)| {
                Some(range.map_or((r, r), |(lo, hi)| (lo.min(r), hi.max(r))))
            })
            .unwrap_or((1.0, 1.0));
        ContinuumPlate {
            end_displacement_face: column[0],
            end_displacement_mid: column[layers],
            end_displacement_mean: mean,
            micro_zone_end: start,
            end_pressure_ratio: contact_pressure[last].1,
            contact_pressure,
            end_layer_pressure_ratio,
            edge_pressure_ratio,
            interior_pressure_range,
            face,
            iterations,
        }
    }
}

impl Discretized for Continuum<'_> {
    const RESIDUAL_TOLERANCE: f64 = 1e-11;

    fn load(&self) -> f64 {
        self.pressure
    }

    fn displacement(&self) -> &[f64] {
        &self.displacement
    }

    fn load_scale(&self, pressure: f64) -> f64 {
        pressure.abs() * self.params.half_length + f64::MIN_POSITIVE
    }

    fn linearize(
        &self,
        displacement: &[f64],
        pressure: f64,
    ) -> (Vec<f64>, SymmetricBand, Vec<Response>) {
        let responses = self.responses(displacement, pressure);
        let mut residual = self.stiffness.mul_accurate(displacement);
        for (r, f) in residual.iter_mut().zip(&self.unit_load) {
            *r -= pressure * f;
        }
        let mut tangent = self.stiffness.clone();
        for (i, response) in responses.iter().enumerate() {
            let dof = self.grid.u(i, 0);
            residual[dof] += response.stress;
            tangent.add(dof, dof, response.tangent);
        }
        for &dof in &self.fixed {
            residual[dof] = 0.0;
            tangent.fix(dof);
        }
        (residual, tangent, responses)
    }

    fn commit(&mut self, displacement: Vec<f64>, responses: Vec<Response>, pressure: f64) {
        for (point, response) in self.points.iter_mut().zip(&responses) {
            point.plastic_slip = response.plastic_slip;
        }
        self.displacement = displacement;
        self.pressure = pressure;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frictionless_plate_expands_as_plane_strain_predicts() {
        // K_T tiny: no shear on the face; with v = 0 below and P above, sigma_y = -P, eps_z = 0,
        // sigma_x = 0: u = nu (1 + nu) P x / E exactly, through the whole thickness.
        let params = PlateParams {
            tangential_stiffness: 1e-6,
            ..PlateParams::PAPER
        };
        let plate = solve_plate_continuum(params, ContinuumMesh::default()).unwrap();
        let free = 0.3 * 1.3 * 10.0 * 10.0 / 70_000.0;
        for u in [
            plate.end_displacement_face,
            plate.end_displacement_mid,
            plate.end_displacement_mean,
        ] {
            assert!((u / free - 1.0).abs() < 1e-6, "{u} vs {free}");
        }
        assert!((plate.end_pressure_ratio - 1.0).abs() < 1e-6);
    }

    #[test]
    fn contact_forces_carry_the_applied_pressure() {
        let grid = Grid::new(&PlateParams::PAPER, ContinuumMesh::default());
        let contact: Vec<f64> = grid.face_weights.iter().map(|w| w * 10.0).collect();
        let mut model = Continuum::new(&grid, &PlateParams::PAPER, &contact);
        newton::load_to(&mut model, 10.0, 1).unwrap();
        let total: f64 = model.face_reactions().iter().sum();
        assert!((total / (10.0 * 10.0) - 1.0).abs() < 1e-9, "{total}");
    }
}

#[cfg(test)]
mod limits {
    use super::*;

    #[test]
    fn a_too_stiff_interface_is_refused_at_once_with_its_reason() {
        let params = PlateParams {
            tangential_stiffness: 1e10,
            ..PlateParams::PAPER
        };
        let error = solve_plate_continuum(params, ContinuumMesh::default()).unwrap_err();
        assert!(
            error.to_string().contains("alpha t_p = 161.245 > 20"),
            "{error}"
        );
        // Just inside the limit it solves.
        let inside = PlateParams {
            tangential_stiffness: 1.4e8,
            ..PlateParams::PAPER
        };
        assert!(solve_plate_continuum(inside, ContinuumMesh::default()).is_ok());
    }
}
