//! Structured blocks of 20-node bricks (CalculiX/Abaqus C3D20R), the only mesh shape the decks need.
//!
//! Both benchmark bodies are rectangles extruded across their width, so a block is given by its
//! element boundaries along x, y and z. Nodes live on the "half grid": index 2i is boundary i, index
//! 2i + 1 the midpoint of element i. A 20-node brick has corner and edge nodes only, so a half-grid
//! point is a node unless two or more of its indices are odd (face and body centres).

pub(crate) use crate::numeric::mesh::{graded_toward_end, graded_toward_end_count};

/// Element boundaries along one axis (mm), strictly increasing, at least two.
pub(crate) type Breaks = Vec<f64>;

/// One structured block of C3D20R elements with its own node and element numbering.
#[derive(Debug, Clone)]
pub(crate) struct Block {
    breaks: [Breaks; 3],
    first_element: usize,
    /// Node id for each half-grid point (x fastest), `None` for face and body centres.
    node_ids: Vec<Option<usize>>,
    node_count: usize,
}

/// A face of a brick, numbered as CalculiX numbers them for our node order (x = xi, y = eta,
/// z = zeta): S3 is the y-min face and S5 the y-max face.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Face {
    YMin,
    YMax,
}

impl Face {
    /// The label used in `*SURFACE` (S..) and `*DLOAD` (P..) cards.
    pub(crate) fn number(self) -> u8 {
        match self {
            Face::YMin => 3,
            Face::YMax => 5,
        }
    }
}

/// Half-grid offsets of the 20 nodes of a brick, in CalculiX's C3D20 order: corners 1-8 (z-min
/// face counter-clockwise, then z-max), edge midpoints 9-12 (z-min), 13-16 (z-max), 17-20 (along z).
const BRICK: [[usize; 3]; 20] = [
    [0, 0, 0],
    [2, 0, 0],
    [2, 2, 0],
    [0, 2, 0],
    [0, 0, 2],
    [2, 0, 2],
    [2, 2, 2],
    [0, 2, 2],
    [1, 0, 0],
    [2, 1, 0],
    [1, 2, 0],
    [0, 1, 0],
    [1, 0, 2],
    [2, 1, 2],
    [1, 2, 2],
    [0, 1, 2],
    [0, 0, 1],
    [2, 0, 1],
    [2, 2, 1],
    [0, 2, 1],
];

impl Block {
    /// A block over the given element boundaries; its nodes are numbered from `first_node` and its
    /// elements from `first_element`, both 1-based as the input format wants.
    pub(crate) fn new(breaks: [Breaks; 3], first_node: usize, first_element: usize) -> Block {
        let [nx, ny, nz] = breaks.clone().map(|b| 2 * (b.len() - 1) + 1);
        let mut node_ids = Vec::with_capacity(nx * ny * nz);
        let mut next = first_node;
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    let odd = [i, j, k].iter().filter(|&&n| n % 2 == 1).count();
                    node_ids.push((odd < 2).then(|| {
                        next += 1;
                        next - 1
                    }));
                }
            }
        }
        Block {
            breaks,
            first_element,
            node_ids,
            node_count: next - first_node,
        }
    }

    /// Number of elements along each axis.
    pub(crate) fn elements_along(&self) -> [usize; 3] {
        [0, 1, 2].map(|a| self.breaks[a].len() - 1)
    }

    fn half_grid_len(&self) -> [usize; 3] {
        self.elements_along().map(|n| 2 * n + 1)
    }

    /// Number of nodes in the block.
    pub(crate) fn node_count(&self) -> usize {
        self.node_count
    }

    /// Number of elements in the block.
    pub(crate) fn element_count(&self) -> usize {
        self.elements_along().iter().product()
    }

    /// The node at half-grid point `[i, j, k]`, if there is one.
    pub(crate) fn node(&self, [i, j, k]: [usize; 3]) -> Option<usize> {
        let [nx, ny, nz] = self.half_grid_len();
        if i >= nx || j >= ny || k >= nz {
            return None;
        }
        self.node_ids[(k * ny + j) * nx + i]
    }

    /// Coordinate (mm) of half-grid index `index` along `axis`.
    pub(crate) fn coordinate(&self, axis: usize, index: usize) -> f64 {
        let breaks = &self.breaks[axis];
        if index.is_multiple_of(2) {
            breaks[index / 2]
        } else {
            0.5 * (breaks[index / 2] + breaks[index / 2 + 1])
        }
    }

    /// Every node as (id, [x, y, z]) in id order.
    pub(crate) fn nodes(&self) -> impl Iterator<Item = (usize, [f64; 3])> + '_ {
        let [nx, ny, _] = self.half_grid_len();
        self.node_ids.iter().enumerate().filter_map(move |(n, id)| {
            let (i, j, k) = (n % nx, (n / nx) % ny, n / (nx * ny));
            id.map(|id| {
                (
                    id,
                    [
                        self.coordinate(0, i),
                        self.coordinate(1, j),
                        self.coordinate(2, k),
                    ],
                )
            })
        })
    }

    /// The id of element `[ex, ey, ez]`.
    pub(crate) fn element(&self, [ex, ey, ez]: [usize; 3]) -> usize {
        let [nx, ny, _] = self.elements_along();
        self.first_element + (ez * ny + ey) * nx + ex
    }

    /// Every element as (id, its 20 node ids in C3D20 order), in id order.
    pub(crate) fn elements(&self) -> impl Iterator<Item = (usize, [usize; 20])> + '_ {
        let [nx, ny, nz] = self.elements_along();
        (0..nz).flat_map(move |ez| {
            (0..ny).flat_map(move |ey| {
                (0..nx).map(move |ex| {
                    let nodes = BRICK.map(|[a, b, c]| {
                        self.node([2 * ex + a, 2 * ey + b, 2 * ez + c])
                            .expect("corner and edge points of a brick are nodes")
                    });
                    (self.element([ex, ey, ez]), nodes)
                })
            })
        })
    }

    /// The ids of the elements whose `face` lies on the block's boundary.
    pub(crate) fn boundary_faces(&self, face: Face) -> Vec<usize> {
        let [nx, ny, nz] = self.elements_along();
        let ey = if face == Face::YMin { 0 } else { ny - 1 };
        (0..nz)
            .flat_map(|ez| (0..nx).map(move |ex| self.element([ex, ey, ez])))
            .collect()
    }

    /// Consistent nodal forces (N) of a uniform traction on the x-max face that adds up to `total`:
    /// on each 8-node face, -1/12 of the face's share at each corner and 1/3 at each edge midpoint
    /// (the integrals of the serendipity shape functions). Returned in node id order.
    pub(crate) fn end_face_loads(&self, total: f64) -> Vec<(usize, f64)> {
        let [nx, ny, nz] = self.elements_along();
        let i = 2 * nx;
        let area =
            (self.breaks[1][ny] - self.breaks[1][0]) * (self.breaks[2][nz] - self.breaks[2][0]);
        let mut loads: Vec<(usize, f64)> = Vec::new();
        for ez in 0..nz {
            for ey in 0..ny {
                let share = total
                    * (self.breaks[1][ey + 1] - self.breaks[1][ey])
                    * (self.breaks[2][ez + 1] - self.breaks[2][ez])
                    / area;
                for (a, b) in [(0, 0), (2, 0), (2, 2), (0, 2)] {
                    loads.push((self.corner(i, 2 * ey + a, 2 * ez + b), -share / 12.0));
                }
                for (a, b) in [(1, 0), (2, 1), (1, 2), (0, 1)] {
                    loads.push((self.corner(i, 2 * ey + a, 2 * ez + b), share / 3.0));
                }
            }
        }
        loads.sort_by_key(|&(id, _)| id);
        let mut summed: Vec<(usize, f64)> = Vec::with_capacity(loads.len());
        for (id, force) in loads {
            match summed.last_mut() {
                Some(last) if last.0 == id => last.1 += force,
                _ => summed.push((id, force)),
            }
        }
        summed
    }

    fn corner(&self, i: usize, j: usize, k: usize) -> usize {
        self.node([i, j, k])
            .expect("face corners and edge midpoints are nodes")
    }

    /// The nodes on the plane x = x-boundary `i` (half-grid index), in id order.
    pub(crate) fn nodes_at_x(&self, i: usize) -> Vec<usize> {
        let [_, ny, nz] = self.half_grid_len();
        let mut ids: Vec<usize> = (0..nz)
            .flat_map(|k| (0..ny).filter_map(move |j| self.node([i, j, k])))
            .collect();
        ids.sort_unstable();
        ids
    }
}

/// Boundaries of `n` equal elements over [start, end].
pub(crate) fn uniform(start: f64, end: f64, n: usize) -> Breaks {
    (0..=n)
        .map(|i| {
            if i == n {
                end
            } else {
                start + (end - start) * i as f64 / n as f64
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(nx: usize, ny: usize) -> Block {
        Block::new(
            [
                uniform(0.0, 2.0, nx),
                uniform(0.0, 1.0, ny),
                uniform(0.0, 0.5, 1),
            ],
            1,
            1,
        )
    }

    #[test]
    fn node_count_is_that_of_a_20_node_brick_mesh() {
        // One brick has 20 nodes; two side by side share 8 (a face with its 4 edge midpoints).
        assert_eq!(block(1, 1).node_count(), 20);
        assert_eq!(block(2, 1).node_count(), 32);
        assert_eq!(block(2, 1).nodes().count(), 32);
    }

    #[test]
    fn ids_are_consecutive_from_the_first() {
        let b = Block::new(
            [
                uniform(0.0, 1.0, 3),
                uniform(0.0, 1.0, 2),
                uniform(0.0, 1.0, 1),
            ],
            101,
            7,
        );
        let ids: Vec<usize> = b.nodes().map(|(id, _)| id).collect();
        assert_eq!(ids, (101..101 + b.node_count()).collect::<Vec<_>>());
        let elements: Vec<usize> = b.elements().map(|(id, _)| id).collect();
        assert_eq!(elements, (7..13).collect::<Vec<_>>());
    }

    #[test]
    fn brick_corners_span_the_element_in_positive_orientation() {
        let b = block(2, 1);
        let coords: std::collections::HashMap<usize, [f64; 3]> = b.nodes().collect();
        let (_, nodes) = b.elements().nth(1).unwrap();
        let [p1, p2, p4, p5] = [0, 1, 3, 4].map(|n| coords[&nodes[n]]);
        let edge = |a: [f64; 3], b: [f64; 3]| [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let (e1, e2, e3) = (edge(p1, p2), edge(p1, p4), edge(p1, p5));
        let volume = e1[0] * (e2[1] * e3[2] - e2[2] * e3[1])
            - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0])
            + e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]);
        assert!((volume - 0.5).abs() < 1e-12, "volume {volume}");
        assert_eq!(p1, [1.0, 0.0, 0.0]);
        // Node 9 is the midpoint of edge 1-2.
        assert_eq!(coords[&nodes[8]], [1.5, 0.0, 0.0]);
    }

    #[test]
    fn end_face_loads_add_up_and_are_symmetric() {
        let b = block(3, 4);
        let loads = b.end_face_loads(100.0);
        let total: f64 = loads.iter().map(|(_, f)| f).sum();
        assert!((total - 100.0).abs() < 1e-12, "{total}");
        // A uniform traction gives equal loads to the two faces z = 0 and z = b.
        let at = |j, k| {
            let id = b.node([6, j, k]).unwrap();
            loads.iter().find(|(n, _)| *n == id).unwrap().1
        };
        assert_eq!(at(2, 0), at(2, 2));
        assert!(at(0, 0) < 0.0, "serendipity corner loads are negative");
    }

    #[test]
    fn graded_mesh_is_finest_at_the_end_and_covers_the_span() {
        let breaks = graded_toward_end(0.0, 10.0, 0.01, 0.1, 1.2);
        assert_eq!(breaks[0], 0.0);
        assert_eq!(*breaks.last().unwrap(), 10.0);
        let widths: Vec<f64> = breaks.windows(2).map(|w| w[1] - w[0]).collect();
        assert!((widths.last().unwrap() - 0.01).abs() < 1e-12);
        assert!(
            widths.iter().all(|&w| w > 0.0 && w <= 0.1 + 1e-12),
            "{widths:?}"
        );
        assert!(
            widths.windows(2).all(|w| w[1] <= w[0] + 1e-12),
            "widths shrink toward the end"
        );
    }

    #[test]
    fn boundary_faces_pick_the_outer_layer() {
        let b = block(3, 2);
        assert_eq!(b.boundary_faces(Face::YMin), vec![1, 2, 3]);
        assert_eq!(b.boundary_faces(Face::YMax), vec![4, 5, 6]);
    }
}
