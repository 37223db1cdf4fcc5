//! One-dimensional meshes graded towards the end where the interface's boundary layer sits.
//!
//! The interface stress changes over a length 1/k (beams) or 1/alpha (plate) next to the clamp, the
//! slip front or the free edge, while it is flat elsewhere: a geometric grading puts small elements
//! where they matter without a huge mesh. The grading uses only the material length scale, never a
//! closed-form result.

/// Mesh density of the finite-element models.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshDensity {
    /// Number of elements.
    pub elements: usize,
    /// Smallest element, as a fraction of the interface's shortest length scale.
    pub smallest_fraction: f64,
    /// Refine around the slip front the solver found, where the grading did not put small elements
    /// (the plate's microslip end near its centre, found while its 1-D solver steps the load):
    /// on by default; off to study the convergence of the graded mesh alone.
    pub refine_at_front: bool,
}

impl Default for MeshDensity {
    /// The default mesh: 400 elements, smallest element 1/50 of the shortest length scale.
    fn default() -> Self {
        MeshDensity {
            elements: 400,
            smallest_fraction: 0.02,
            refine_at_front: true,
        }
    }
}

impl MeshDensity {
    /// Fewest elements accepted by the command line: 25. With 20 or fewer, the graded plate mesh of
    /// the stiffest interface of `verify`'s grid (K_T = 1e8 MPa/mm) puts whole elements inside the
    /// slip zone at the free end and Newton cycles between sliding directions at the first load
    /// step (measured: 10 to 20 fail, 22 converges over the full grid).
    pub const MIN_ELEMENTS: usize = 25;
    /// Most elements accepted by the command line: the Hermite bending matrix has a condition number
    /// growing like n^4, and beyond ~800 elements (L/h = 20) Newton's refinement can no longer push
    /// the round-off below the discretization error (measured: 1e-13 at 400, 1e-4 at 1200).
    pub const MAX_ELEMENTS: usize = 800;

    /// `elements` elements with the default grading (the smallest element shrinks in proportion).
    pub fn with_elements(elements: usize) -> Self {
        let default = MeshDensity::default();
        MeshDensity {
            elements,
            smallest_fraction: default.smallest_fraction * default.elements as f64
                / elements.max(1) as f64,
            refine_at_front: true,
        }
    }
}

/// Node positions on [0, length] with `elements` elements, geometrically graded so that the element
/// next to x = 0 is about `ratio` times smaller than the last one (ratio 1: uniform).
pub(crate) fn graded_from_start(length: f64, elements: usize, ratio: f64) -> Vec<f64> {
    let elements = elements.max(1);
    let ratio = ratio.max(1.0);
    if ratio == 1.0 {
        return (0..=elements)
            .map(|i| length * i as f64 / elements as f64)
            .collect();
    }
    // x(t) = L (exp(beta t) - 1) / (exp(beta) - 1), t in [0, 1]: element sizes grow by exp(beta / n).
    let beta = ratio.ln();
    let scale = beta.exp_m1();
    let mut nodes: Vec<f64> = (0..=elements)
        .map(|i| length * (beta * i as f64 / elements as f64).exp_m1() / scale)
        .collect();
    nodes[elements] = length;
    nodes
}

/// The mirror image: small elements next to x = length.
pub(crate) fn graded_towards_end(length: f64, elements: usize, ratio: f64) -> Vec<f64> {
    graded_from_start(length, elements, ratio)
        .iter()
        .rev()
        .map(|x| length - x)
        .collect()
}

/// Grading ratio that makes the smallest of `elements` elements about `smallest` long (>= 1).
pub(crate) fn ratio_for_smallest(length: f64, elements: usize, smallest: f64) -> f64 {
    let uniform = length / elements.max(1) as f64;
    if smallest >= uniform {
        return 1.0;
    }
    // Smallest element ~ L beta / (n (exp(beta) - 1)); solve for beta by fixed-point bisection.
    let n = elements.max(1) as f64;
    let size = |beta: f64| length * beta / (n * beta.exp_m1());
    let (mut lo, mut hi) = (1e-9_f64, 700.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if size(mid) > smallest {
            lo = mid
        } else {
            hi = mid
        }
    }
    hi.exp()
}

/// Boundaries over [start, end] that are `finest` wide at `end` and grow by `ratio` per element
/// toward `start`, up to `coarsest`; the remaining length is split evenly so that no element is
/// wider than `coarsest`. Used to resolve the slip zone at a free end.
pub fn graded_toward_end(start: f64, end: f64, finest: f64, coarsest: f64, ratio: f64) -> Vec<f64> {
    let Grading { widths, rest, even } = grading(end - start, finest, coarsest, ratio);
    let even = even as usize;
    let mut breaks: Vec<f64> = (0..=even)
        .map(|i| start + rest * i as f64 / even as f64)
        .collect();
    let mut x = start + rest;
    for w in widths.iter().rev() {
        x += w;
        breaks.push(x);
    }
    if let Some(last) = breaks.last_mut() {
        *last = end;
    }
    breaks
}

/// How [`graded_toward_end`] splits a length: the growing widths at the end, then `even` elements
/// over the `rest`.
struct Grading {
    widths: Vec<f64>,
    rest: f64,
    even: f64,
}

/// The grading of `length`. Only the growing part is stored (its count is logarithmic in
/// `coarsest / finest`); the even part is a count, so that the size of a mesh can be known without
/// allocating it ([`graded_toward_end_count`]).
fn grading(length: f64, finest: f64, coarsest: f64, ratio: f64) -> Grading {
    let mut widths = Vec::new();
    let mut covered = 0.0;
    let mut width = finest.min(length);
    while covered + width < length && width < coarsest {
        widths.push(width);
        covered += width;
        width = (width * ratio).min(coarsest);
    }
    let rest = length - covered;
    Grading {
        widths,
        rest,
        even: (rest / coarsest).ceil().max(1.0),
    }
}

/// The number of elements [`graded_toward_end`] would make, without making them (a deck too large
/// to write is refused by its size before any allocation).
pub fn graded_toward_end_count(
    start: f64,
    end: f64,
    finest: f64,
    coarsest: f64,
    ratio: f64,
) -> f64 {
    let g = grading(end - start, finest, coarsest, ratio);
    g.even + g.widths.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_count_of_a_graded_mesh_is_known_without_making_it() {
        for (end, finest, coarsest) in [(300.0, 0.25, 4.0), (10.0, 1e-3, 0.5), (1.0, 2.0, 3.0)] {
            let breaks = graded_toward_end(0.0, end, finest, coarsest, 1.2);
            let count = graded_toward_end_count(0.0, end, finest, coarsest, 1.2);
            assert_eq!(
                count,
                (breaks.len() - 1) as f64,
                "{end} {finest} {coarsest}"
            );
        }
        // Far too many to make: counted all the same, with no allocation of that size.
        let count = graded_toward_end_count(0.0, 1e6, 1e-9, 1e-7, 1.2);
        assert!((count - 1e13).abs() < 1e7, "{count}");
    }

    #[test]
    fn graded_meshes_cover_the_interval_monotonically() {
        let nodes = graded_from_start(200.0, 100, 1000.0);
        assert_eq!(nodes.len(), 101);
        assert_eq!((nodes[0], nodes[100]), (0.0, 200.0));
        assert!(nodes.windows(2).all(|w| w[1] > w[0]));
        let (first, last) = (nodes[1] - nodes[0], nodes[100] - nodes[99]);
        assert!(
            (last / first / 1000.0 - 1.0).abs() < 0.1,
            "{}",
            last / first
        );
        let mirrored = graded_towards_end(10.0, 20, 50.0);
        assert_eq!((mirrored[0], mirrored[20]), (0.0, 10.0));
        assert!(mirrored[20] - mirrored[19] < mirrored[1] - mirrored[0]);
        assert_eq!(
            graded_from_start(1.0, 4, 1.0),
            vec![0.0, 0.25, 0.5, 0.75, 1.0]
        );
    }

    #[test]
    fn ratio_gives_the_requested_smallest_element() {
        let r = ratio_for_smallest(200.0, 400, 0.01);
        let nodes = graded_from_start(200.0, 400, r);
        assert!(
            ((nodes[1] - nodes[0]) / 0.01 - 1.0).abs() < 0.05,
            "{}",
            nodes[1]
        );
        assert_eq!(ratio_for_smallest(200.0, 400, 1.0), 1.0);
    }
}
