//! The lap joint's elastic bodies condensed onto its interface pairs (`numeric::condense`): the
//! joint's loads (P on the cover, F at the inner plate's end) and readings (the pair slips, the
//! contact forces, Delta).

use super::mesh::Grid;
use crate::numeric::NumericError;
use crate::numeric::banded::SymmetricBand;
use crate::numeric::condense::{condensed_stiffness, solve_columns};
use crate::numeric::grid::edge_weights;
use crate::numeric::q8::Q8;
use crate::problems::lap::params::LapParams;

/// The elastic bodies condensed onto the interface pairs: every quantity the interface needs,
/// linear in the loads and in the plastic slips q_i (the pairs' Jenkins forces are
/// t_i = k_i (s_i - q_i)).
pub(super) struct Condensed {
    pub(super) pairs: usize,
    /// Jenkins stiffness of each pair, K_T times its share of the face (N/mm per mm of width).
    pub(super) stiffness: Vec<f64>,
    /// The condensed stiffness S = (B K0^-1 B^T)^-1 (dense, in a full band), the Newton
    /// tangent's elastic part.
    pub(super) condensed: SymmetricBand,
    /// The same, row major, for the residual's products (plain sums: the residual's terms are
    /// interface forces of the same size, so nothing cancels to below the tolerance).
    pub(super) condensed_rows: Vec<f64>,
    /// Slip, contact force and Delta reading per unit pressure (MPa) and per newton of F, with
    /// every pair elastic and no plastic slip.
    pub(super) slip_p: Vec<f64>,
    pub(super) slip_f: Vec<f64>,
    pub(super) contact_p: Vec<f64>,
    pub(super) contact_f: Vec<f64>,
    pub(super) delta_p: f64,
    pub(super) delta_f: f64,
    /// Contact force at pair i per unit Jenkins force pair at j ((R K0^-1 B^T)_ij), row major.
    pub(super) contact_per_pair: Vec<f64>,
    /// Delta reading per unit Jenkins force pair at j.
    pub(super) delta_per_pair: Vec<f64>,
}

impl Condensed {
    pub(super) fn new(grid: &Grid, p: &LapParams) -> Result<Condensed, NumericError> {
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
        // then P = 1 on the cover's outer face over the overlap, then F = 1 N; each solution kept
        // only through its readings: the pair slips, the contact forces, Delta.
        let total = m + 2;
        let cover_top = grid.cover.rows() - 1;
        let end = grid.inner.columns() - 1;
        let traction = 1.0 / (p.width * p.inner_thickness);
        let inner_end = 2 * grid.overlap_elements;
        let inner_mean = edge_weights(&grid.inner.ys);
        let cover_mean = edge_weights(&grid.cover.ys);
        let (h1, h2) = (0.5 * p.inner_thickness, p.cover_thickness);
        let mut slips: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut contacts: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut deltas: Vec<f64> = Vec::with_capacity(total);
        let load = |column: usize, add: &mut dyn FnMut(usize, f64)| {
            if column < m {
                let (a, b) = grid.pair_dofs(column);
                add(a, 1.0);
                add(b, -1.0);
            } else if column == m {
                for (i, w) in grid.pair_weights.iter().enumerate() {
                    let [_, v] = grid.cover.dof(grid.inner.first_column + i, cover_top);
                    add(v, -w);
                }
            } else {
                for (j, w) in inner_mean.iter().enumerate() {
                    let [u, _] = grid.inner.dof(end, j);
                    add(u, traction * w);
                }
            }
        };
        solve_columns(&factor, n, total, load, |at| {
            slips.push(
                (0..m)
                    .map(|i| {
                        let (a, b) = grid.pair_dofs(i);
                        at(a) - at(b)
                    })
                    .collect(),
            );
            contacts.push(
                contact_rows
                    .iter()
                    .map(|row| row.iter().map(|&(d, k)| k * at(d)).sum())
                    .collect(),
            );
            let inner: f64 = inner_mean
                .iter()
                .enumerate()
                .map(|(j, w)| w * at(grid.inner.dof(inner_end, j)[0]))
                .sum();
            let cover: f64 = cover_mean
                .iter()
                .enumerate()
                .map(|(j, w)| w * at(grid.cover.dof(grid.inner.first_column, j)[0]))
                .sum();
            deltas.push(inner / h1 - cover / h2);
        });
        let slip_f = slips.pop().unwrap_or_default();
        let slip_p = slips.pop().unwrap_or_default();
        let contact_f = contacts.pop().unwrap_or_default();
        let contact_p = contacts.pop().unwrap_or_default();
        let delta_f = deltas.pop().unwrap_or_default();
        let delta_p = deltas.pop().unwrap_or_default();

        // C = B K0^-1 B^T, symmetrized against round-off, and its inverse.
        let (condensed, condensed_rows) = condensed_stiffness(&slips)?;
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
