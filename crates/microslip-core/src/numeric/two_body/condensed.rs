//! The two elastic bodies condensed onto their interface pairs ([`Condensed`]).

use super::TwoBodyGrid;
use crate::numeric::NumericError;
use crate::numeric::banded::SymmetricBand;
use crate::numeric::condense::{condensed_stiffness, solve_columns};
use crate::numeric::q8::Q8;

/// An external load per unit of its magnitude, built by `add(unknown, value)` from zero.
pub(crate) type LoadVector<'a> = &'a dyn Fn(&mut dyn FnMut(usize, f64));
/// The upper body's own share of an external load (per unit of its magnitude) at pair i's
/// normal unknown: what its internal force there carries besides the contact force.
pub(crate) type OwnLoad<'a> = &'a dyn Fn(usize) -> f64;
/// The response a problem reads from a displacement field, `at(unknown)`, linear in it.
pub(crate) type Reading<'a> = &'a dyn Fn(&dyn Fn(usize) -> f64) -> f64;

/// The elastic bodies condensed onto the interface pairs: every quantity the interface needs,
/// linear in the loads and in the plastic slips q_i (the pairs' Jenkins forces are
/// t_i = k_i (s_i - q_i)). The slip of a pair is u_lower - u_upper.
pub(crate) struct Condensed {
    pub(crate) pairs: usize,
    /// Jenkins stiffness of each pair, K_T times its share of the face (N/mm per mm of width).
    pub(crate) stiffness: Vec<f64>,
    /// The condensed stiffness S = (B K0^-1 B^T)^-1 (dense, in a full band), the Newton
    /// tangent's elastic part.
    pub(crate) condensed: SymmetricBand,
    /// The same, row major, for the residual's products (plain sums: the residual's terms are
    /// interface forces of the same size, so nothing cancels to below the tolerance).
    pub(crate) condensed_rows: Vec<f64>,
    /// Slip, contact force and reading per unit of the first load (P) and of the driving load
    /// (F), with every pair elastic and no plastic slip.
    pub(crate) slip_p: Vec<f64>,
    pub(crate) slip_f: Vec<f64>,
    pub(crate) contact_p: Vec<f64>,
    pub(crate) contact_f: Vec<f64>,
    pub(crate) reading_p: f64,
    pub(crate) reading_f: f64,
    /// Contact force at pair i per unit Jenkins force pair at j ((R K0^-1 B^T)_ij), row major.
    pub(crate) contact_per_pair: Vec<f64>,
    /// The reading per unit Jenkins force pair at j.
    pub(crate) reading_per_pair: Vec<f64>,
}

impl Condensed {
    /// Condenses the bodies of `grid` (unknowns `fixed` held at zero) with Jenkins springs of
    /// `stiffness_per_area` (K_T, MPa/mm) at its pairs, under the loads `first` (P) and `driving`
    /// (F), read by `reading`; `own` gives the upper body's own share of each load at each
    /// pair's normal unknown (the contact force is the upper body's internal force there less
    /// it: the beams' end traction loads the tip pair's corner node, the lap joint's loads no
    /// pair).
    ///
    /// # Errors
    /// [`NumericError::Singular`] for a stiffness that is not positive definite (a body that
    /// nothing holds).
    pub(crate) fn new(
        grid: &TwoBodyGrid,
        stiffness_per_area: f64,
        fixed: &[usize],
        [first, driving]: [LoadVector<'_>; 2],
        own: [OwnLoad<'_>; 2],
        reading: Reading<'_>,
    ) -> Result<Condensed, NumericError> {
        let n = grid.unknowns;
        let m = grid.pairs();
        let mut k0 = SymmetricBand::zeros(n, grid.bandwidth);
        // The contact force at each pair: the upper body's internal force at the shared normal
        // unknown (nothing else loads it), a sparse row of the upper body's stiffness.
        let mut contact_rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); m];
        for (body, is_upper) in [(&grid.lower, false), (&grid.upper, true)] {
            for ex in 0..body.xs.len() - 1 {
                for ey in 0..body.ys.len() - 1 {
                    let k = body.element_stiffness(ex, ey);
                    let dofs = body.element_dofs(ex, ey);
                    for a in 0..16 {
                        for b in 0..=a {
                            k0.add(dofs[a], dofs[b], k[a][b]);
                        }
                    }
                    if is_upper && ey == 0 {
                        for (node, &(a, b)) in Q8.iter().enumerate() {
                            let column = body.first_column + 2 * ex + a;
                            if b != 0 {
                                continue;
                            }
                            let Some(pair) = grid.pair_at(column) else {
                                continue;
                            };
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
            .map(|w| stiffness_per_area * w)
            .collect();
        for (i, k) in stiffness.iter().enumerate() {
            let (a, b) = grid.pair_dofs(i);
            k0.add(a, a, *k);
            k0.add(b, b, *k);
            k0.add(a.max(b), a.min(b), -k);
        }
        for &dof in fixed {
            k0.fix(dof);
        }
        let factor = k0.factor().map_err(|e| NumericError::Singular(e.row))?;

        // Right-hand sides: the m unit pair loads (+1 on the lower body's u, -1 on the upper
        // body's), then P = 1, then F = 1; each solution kept only through its readings: the
        // pair slips, the contact forces, the response.
        let total = m + 2;
        let mut slips: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut contacts: Vec<Vec<f64>> = Vec::with_capacity(total);
        let mut readings: Vec<f64> = Vec::with_capacity(total);
        // A load on a held unknown goes to the support (its row is the identity's): the
        // press fit's hub is held on a face whose interface corner is also a pair's node.
        let mut held = vec![false; n];
        for &dof in fixed {
            held[dof] = true;
        }
        let load = |column: usize, add: &mut dyn FnMut(usize, f64)| {
            let add = &mut |dof: usize, value: f64| {
                if !held[dof] {
                    add(dof, value);
                }
            };
            if column < m {
                let (a, b) = grid.pair_dofs(column);
                add(a, 1.0);
                add(b, -1.0);
            } else if column == m {
                first(add);
            } else {
                driving(add);
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
            readings.push(reading(at));
        });
        let slip_f = slips.pop().unwrap_or_default();
        let slip_p = slips.pop().unwrap_or_default();
        let without_own = |contact: Vec<f64>, own: OwnLoad<'_>| -> Vec<f64> {
            contact
                .iter()
                .enumerate()
                .map(|(i, c)| c - own(i))
                .collect()
        };
        let contact_f = without_own(contacts.pop().unwrap_or_default(), own[1]);
        let contact_p = without_own(contacts.pop().unwrap_or_default(), own[0]);
        let reading_f = readings.pop().unwrap_or_default();
        let reading_p = readings.pop().unwrap_or_default();

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
            reading_p,
            reading_f,
            contact_per_pair,
            reading_per_pair: readings,
        })
    }
}
