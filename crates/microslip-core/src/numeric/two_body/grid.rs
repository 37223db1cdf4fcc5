//! Two Q8 bodies over one interface ([`TwoBodyGrid`]).

use crate::numeric::grid::{Q8Grid, edge_weights};

/// Two bodies on structured Q8 grids, the lower one's top row facing the upper one's bottom row
/// over the global columns both have (each body's `first_column` places it), with the interface
/// pairs, their positions and their shares of the face.
#[derive(Debug, Clone)]
pub(crate) struct TwoBodyGrid {
    pub(crate) lower: Q8Grid,
    pub(crate) upper: Q8Grid,
    pub(crate) unknowns: usize,
    pub(crate) bandwidth: usize,
    /// x (mm) and share of the face (mm per mm of width) of each interface pair.
    pub(crate) pair_x: Vec<f64>,
    pub(crate) pair_weights: Vec<f64>,
    /// The global column of pair 0.
    first_pair: usize,
}

impl TwoBodyGrid {
    /// Numbers both bodies column by column across both (the lower body's points of a column
    /// first), the facing points of the shared columns sharing their normal unknown (the lower
    /// body's). The first `held` shared columns are no pairs (a clamped end, where the slip is
    /// held at zero): their points still share the normal unknown.
    pub(crate) fn new(mut lower: Q8Grid, mut upper: Q8Grid, held: usize) -> TwoBodyGrid {
        let lower_end = lower.first_column + lower.columns();
        let upper_end = upper.first_column + upper.columns();
        let shared = lower.first_column.max(upper.first_column)..lower_end.min(upper_end);
        let total = lower_end.max(upper_end);
        let mut next = 0;
        let top = lower.rows() - 1;
        for g in 0..total {
            if (lower.first_column..lower_end).contains(&g) {
                let i = g - lower.first_column;
                for j in 0..lower.rows() {
                    if Q8Grid::is_node(i, j) {
                        lower.set_dof(i, j, [next, next + 1]);
                        next += 2;
                    }
                }
            }
            if (upper.first_column..upper_end).contains(&g) {
                let i = g - upper.first_column;
                for j in 0..upper.rows() {
                    if !Q8Grid::is_node(i, j) {
                        continue;
                    }
                    if j == 0 && shared.contains(&g) {
                        let [_, v] = lower.dof(g - lower.first_column, top);
                        upper.set_dof(i, 0, [next, v]);
                        next += 1;
                    } else {
                        upper.set_dof(i, j, [next, next + 1]);
                        next += 2;
                    }
                }
            }
        }
        let mut bandwidth = lower.bandwidth().max(upper.bandwidth());
        // The element boundaries of the shared columns (they start and end at corners).
        let first = (shared.start - lower.first_column) / 2;
        let last = (shared.end - 1 - lower.first_column) / 2;
        let breaks = &lower.xs[first..=last];
        let weights = edge_weights(breaks);
        let pair_x: Vec<f64> = (0..weights.len())
            .map(|i| {
                if i % 2 == 0 {
                    breaks[i / 2]
                } else {
                    0.5 * (breaks[i / 2] + breaks[i / 2 + 1])
                }
            })
            .skip(held)
            .collect();
        let pair_weights: Vec<f64> = weights.into_iter().skip(held).collect();
        let mut grid = TwoBodyGrid {
            lower,
            upper,
            unknowns: next,
            bandwidth: 0,
            pair_x,
            pair_weights,
            first_pair: shared.start + held,
        };
        for i in 0..grid.pairs() {
            let (a, b) = grid.pair_dofs(i);
            bandwidth = bandwidth.max(a.abs_diff(b));
        }
        grid.bandwidth = bandwidth;
        grid
    }

    /// Per-pair values over each pair's share of the face, (x (mm), `sign` x value / share):
    /// a force per mm of width read as a stress (MPa).
    pub(crate) fn per_face(&self, values: &[f64], sign: f64) -> Vec<(f64, f64)> {
        self.pair_x
            .iter()
            .zip(values.iter().zip(&self.pair_weights))
            .map(|(&x, (v, w))| (x, sign * v / w))
            .collect()
    }

    pub(crate) fn pairs(&self) -> usize {
        self.pair_x.len()
    }

    /// The pair at global column `column`, if any.
    pub(crate) fn pair_at(&self, column: usize) -> Option<usize> {
        let pair = column.checked_sub(self.first_pair)?;
        (pair < self.pairs()).then_some(pair)
    }

    /// The lower body's and the upper body's u unknowns of pair `i`.
    pub(crate) fn pair_dofs(&self, i: usize) -> (usize, usize) {
        let top = self.lower.rows() - 1;
        let column = self.first_pair + i;
        (
            self.lower.dof(column - self.lower.first_column, top)[0],
            self.upper.dof(column - self.upper.first_column, 0)[0],
        )
    }
}
