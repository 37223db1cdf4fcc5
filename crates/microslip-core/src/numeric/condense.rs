//! Static condensation of an elastic body onto a few interface unknowns: when the only
//! nonlinearity sits on m interface points, the stiffness K0 with every interface spring elastic
//! is factored once, solved for m unit interface loads (and the external loads), and the m x m
//! flexibility C = B K0^-1 B^T inverted into the condensed stiffness S = C^-1. Newton then works
//! on the m interface unknowns alone, and the answer is that of the full system (the
//! condensation is exact).

use super::NumericError;
use super::banded::{BandCholesky, SymmetricBand};

/// Right-hand sides solved together with the banded factor: enough to read each factor entry
/// once for many, few enough to keep the block small (n x 64).
const CHUNK: usize = 64;

/// Solves `factor` (n unknowns) for `total` right-hand sides, [`CHUNK`] at a time, keeping each
/// solution only through what `read` takes from it: `load(column, add)` builds right-hand side
/// `column` by `add(unknown, value)` from zero, and `read(at)` gets the solution, `at(unknown)`,
/// column after column in order. The block is n x CHUNK, whatever `total` is.
pub(crate) fn solve_columns(
    factor: &BandCholesky,
    n: usize,
    total: usize,
    mut load: impl FnMut(usize, &mut dyn FnMut(usize, f64)),
    mut read: impl FnMut(&dyn Fn(usize) -> f64),
) {
    for first in (0..total).step_by(CHUNK) {
        let columns = CHUNK.min(total - first);
        let mut rhs = vec![0.0; n * columns];
        for c in 0..columns {
            load(first + c, &mut |dof, value| rhs[dof * columns + c] += value);
        }
        factor.solve_many(&mut rhs, columns);
        for c in 0..columns {
            read(&|dof| rhs[dof * columns + c]);
        }
    }
}

/// The condensed stiffness S = C^-1 of the m x m flexibility whose column j is `flexibility[j]`
/// (C_ij = `flexibility[j][i]`, symmetrized against round-off), as a full band (the Newton
/// tangent's elastic part) and row major (for the residual's products).
///
/// # Errors
/// [`NumericError::Singular`] when C is not positive definite (an interface point that nothing
/// holds).
pub(crate) fn condensed_stiffness(
    flexibility: &[Vec<f64>],
) -> Result<(SymmetricBand, Vec<f64>), NumericError> {
    let m = flexibility.len();
    let mut symmetric = SymmetricBand::zeros(m, m.saturating_sub(1));
    for (i, row) in flexibility.iter().enumerate() {
        for (j, column) in flexibility.iter().enumerate().take(i + 1) {
            symmetric.add(i, j, 0.5 * (column[i] + row[j]));
        }
    }
    let factor = symmetric
        .factor()
        .map_err(|e| NumericError::Singular(e.row))?;
    let mut inverse = vec![0.0; m * m];
    for i in 0..m {
        inverse[i * m + i] = 1.0;
    }
    factor.solve_many(&mut inverse, m);
    let mut condensed = SymmetricBand::zeros(m, m.saturating_sub(1));
    let mut rows = vec![0.0; m * m];
    for i in 0..m {
        for j in 0..=i {
            let value = 0.5 * (inverse[i * m + j] + inverse[j * m + i]);
            condensed.add(i, j, value);
            rows[i * m + j] = value;
            rows[j * m + i] = value;
        }
    }
    Ok((condensed, rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn condensing_a_chain_of_springs_gives_back_its_stiffness() {
        // Three unit springs in a chain, ground - 0 - 1 - 2: K = [[2,-1,0],[-1,2,-1],[0,-1,1]].
        let mut k = SymmetricBand::zeros(3, 1);
        for (i, j, v) in [
            (0, 0, 2.0),
            (1, 0, -1.0),
            (1, 1, 2.0),
            (2, 1, -1.0),
            (2, 2, 1.0),
        ] {
            k.add(i, j, v);
        }
        let factor = k.factor().unwrap();
        // Condensed onto unknowns 0 and 2 (a unit load at each, reading both).
        let mut flexibility = Vec::new();
        solve_columns(
            &factor,
            3,
            2,
            |column, add| add(2 * column, 1.0),
            |at| flexibility.push(vec![at(0), at(2)]),
        );
        // Flexibility [[1, 1], [1, 3]]; its inverse [[1.5, -0.5], [-0.5, 0.5]].
        let (_, rows) = condensed_stiffness(&flexibility).unwrap();
        for (got, want) in rows.iter().zip([1.5, -0.5, -0.5, 0.5]) {
            assert!((got - want).abs() < 1e-12, "{rows:?}");
        }
        // A point nothing holds: no condensed stiffness.
        assert!(condensed_stiffness(&[vec![0.0]]).is_err());
    }
}
