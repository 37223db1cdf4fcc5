//! The lap joint's mesh: the element boundaries along x it shares with the CalculiX deck
//! (`fe::lap_deck`), counted before they are built, and the two bodies (inner plate half and
//! cover) on structured Q8 grids (`numeric::grid`) whose interface pairs share their normal
//! unknown.

use super::{LAP_POISSON, LapContinuumMesh, decay_rate};
use crate::numeric::grid::Q8Grid;
use crate::numeric::mesh::graded_toward_end;
use crate::numeric::q8::plane_stress;
use crate::numeric::two_body::TwoBodyGrid;
use crate::problems::lap::params::LapParams;

/// Growth ratio of neighbouring elements along x (the deck's).
const GROWTH: f64 = 1.15;

/// The element boundaries along x of the joint's continuum model, shared by this solver and the
/// CalculiX deck (`fe::lap_deck`) so that the two mesh the joint the same way.
#[derive(Debug, Clone, PartialEq)]
pub struct LapBreaks {
    /// Over the overlap [0, L], finest at both ends.
    pub overlap: Vec<f64>,
    /// The cover's extension [-H, 0], finest at x = 0 (H = 2 (t1 + t2)).
    pub cover_extension: Vec<f64>,
    /// The inner plate's extension [L, L + H], finest at x = L.
    pub inner_extension: Vec<f64>,
    /// The layer height: the thinner of t1/2 and t2 over `layers` (mm).
    pub layer: f64,
    /// The element size at the overlap's ends (mm).
    pub finest: f64,
}

/// The sizes behind the joint's mesh of `layers` elements through each body (its K_T sets the
/// decay length): finest at the overlap's ends, where the shear peaks, two thirds of a layer or a
/// quarter of the decay length; the coarsest half a decay length, at most 8/3 layers; the
/// extensions up to four times that, all growing by [`GROWTH`]. One function for the breaks and
/// their count, so that a mesh is counted exactly as it would be built.
struct LapSizing {
    layer: f64,
    finest: f64,
    coarsest: f64,
    extension: f64,
}

fn lap_sizing(p: &LapParams, layers: usize) -> LapSizing {
    let layer = (0.5 * p.inner_thickness / layers as f64).min(p.cover_thickness / layers as f64);
    let decay = 1.0 / decay_rate(p);
    let finest = (2.0 / 3.0 * layer).min(0.25 * decay);
    LapSizing {
        layer,
        finest,
        coarsest: (8.0 / 3.0 * layer).min(0.5 * decay).max(finest),
        extension: 2.0 * (p.inner_thickness + p.cover_thickness),
    }
}

/// The number of elements along x of the joint's mesh ([`lap_breaks`]), counted without making
/// it: a stiff interface over a long overlap asks for 1e13 of them, which must be refused by
/// their count before anything of that size is allocated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LapCounts {
    /// Elements over half the overlap.
    pub half_overlap: f64,
    /// Elements over the cover's extension.
    pub cover_extension: f64,
    /// Elements over the inner plate's extension.
    pub inner_extension: f64,
}

impl LapCounts {
    /// Elements along the inner plate (the overlap and its extension).
    pub(crate) fn inner(&self) -> f64 {
        2.0 * self.half_overlap + self.inner_extension
    }

    /// Elements along the cover (its extension and the overlap).
    pub(crate) fn cover(&self) -> f64 {
        self.cover_extension + 2.0 * self.half_overlap
    }

    /// Elements of both bodies, `layers` deep each.
    pub fn elements(&self, layers: usize) -> f64 {
        (self.inner() + self.cover()) * layers as f64
    }
}

/// The counts of [`lap_breaks`]`(p, layers)`, with no allocation that grows with them.
pub fn lap_counts(p: &LapParams, layers: usize) -> LapCounts {
    use crate::numeric::mesh::graded_toward_end_count as count;
    let LapSizing {
        finest,
        coarsest,
        extension,
        ..
    } = lap_sizing(p, layers);
    let length = p.length;
    LapCounts {
        half_overlap: count(0.5 * length, length, finest, coarsest, GROWTH),
        cover_extension: count(-extension, 0.0, finest, 4.0 * coarsest, GROWTH),
        inner_extension: count(length, length + extension, finest, 4.0 * coarsest, GROWTH),
    }
}

/// The element boundaries of the joint `p` with `layers` elements through each body, sized by
/// `lap_sizing`. Count them first ([`lap_counts`]): nothing here bounds their number.
pub fn lap_breaks(p: &LapParams, layers: usize) -> LapBreaks {
    let LapSizing {
        layer,
        finest,
        coarsest,
        extension,
    } = lap_sizing(p, layers);
    let length = p.length;
    let right = graded_toward_end(0.5 * length, length, finest, coarsest, GROWTH);
    let mut overlap: Vec<f64> = right.iter().rev().map(|x| length - x).collect();
    overlap.pop();
    overlap.extend(&right);
    let cover_extension = graded_toward_end(-extension, 0.0, finest, 4.0 * coarsest, GROWTH);
    let inner_extension: Vec<f64> =
        graded_toward_end(length, length + extension, finest, 4.0 * coarsest, GROWTH)
            .iter()
            .rev()
            .map(|x| 2.0 * length + extension - x)
            .collect();
    LapBreaks {
        overlap,
        cover_extension,
        inner_extension,
        layer,
        finest,
    }
}

/// Both bodies and the interface: the inner plate's half below, the cover above
/// (`numeric::two_body`).
#[derive(Debug, Clone)]
pub(super) struct Grid {
    /// The inner plate (lower) and the cover (upper), numbered across both.
    pub(super) two: TwoBodyGrid,
    /// Elements along the overlap.
    pub(super) overlap_elements: usize,
    /// Fixed unknowns: v on the symmetry plane, u and v on the cover's held end.
    pub(super) fixed: Vec<usize>,
}

impl Grid {
    /// The number of interface pairs and of elements the mesh would have, without building it.
    pub(super) fn counts(p: &LapParams, mesh: LapContinuumMesh) -> (usize, usize) {
        let counts = lap_counts(p, mesh.layers);
        // 2 half overlaps, 2 pairs per element and one more.
        let pairs = 4.0 * counts.half_overlap + 1.0;
        let elements = counts.elements(mesh.layers);
        let whole = |x: f64| {
            if x.is_finite() && x < usize::MAX as f64 {
                x as usize
            } else {
                usize::MAX
            }
        };
        (whole(pairs), whole(elements))
    }

    pub(super) fn new(p: &LapParams, mesh: LapContinuumMesh) -> Grid {
        let layers = mesh.layers;
        let LapBreaks {
            overlap,
            cover_extension,
            inner_extension,
            ..
        } = lap_breaks(p, layers);
        let half = 0.5 * p.inner_thickness;
        let ys_inner: Vec<f64> = (0..=layers)
            .map(|j| half * j as f64 / layers as f64)
            .collect();
        let ys_cover: Vec<f64> = (0..=layers)
            .map(|j| half + p.cover_thickness * j as f64 / layers as f64)
            .collect();
        let before = cover_extension.len() - 1;
        let mut xs_cover = cover_extension;
        xs_cover.pop();
        xs_cover.extend(&overlap);
        let mut xs_inner = overlap.clone();
        xs_inner.extend(&inner_extension[1..]);
        let overlap_elements = overlap.len() - 1;
        let cover = Q8Grid::new(
            xs_cover,
            ys_cover,
            0,
            plane_stress(p.cover_modulus, LAP_POISSON),
        );
        let inner = Q8Grid::new(
            xs_inner,
            ys_inner,
            2 * before,
            plane_stress(p.inner_modulus, LAP_POISSON),
        );

        let two = TwoBodyGrid::new(inner, cover, 0);
        let mut fixed: Vec<usize> = (0..two.lower.columns())
            .map(|i| two.lower.dof(i, 0)[1])
            .collect();
        for j in 0..two.upper.rows() {
            fixed.extend(two.upper.dof(0, j));
        }
        Grid {
            two,
            overlap_elements,
            fixed,
        }
    }
}
