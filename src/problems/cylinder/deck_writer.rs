//! The CalculiX deck of the Hertzian cylinder on a flat (issue 34, item 5), written from plain
//! numbers: the mesh, the loads and the cards. The [`Deck`](crate::fe::face::Deck) face of the
//! cylinder wraps it (its header, its readers, its comparison).
//!
//! What the deck models (docs/theory.md, "The Hertzian cylinder: the CalculiX judge"):
//!
//! - plane strain: one layer of C3D20R bricks across a slice of width w, every node held across
//!   it (u_z = 0), as the plate's deck; every load is per unit length times w;
//! - two bodies of the same material: the flat is a block 2 L wide and L deep, L =
//!   [`BODY_SIZE`] a (32 a); the cylinder is the disc of radius R below the chord at the height
//!   H = min(32 a, R) above its lowest point (the half disc once R <= 32 a), its thin tips cut off
//!   where the arc has risen H / 2. Its contact face is the arc itself (every node of the bottom
//!   row, midside nodes too, on the circle). Why this geometry (issue 45, item 5): the half-plane
//!   answer is the limit of large bodies, and the older deck's 6 a bodies (a block whose top edge
//!   was lifted onto the arc) measured its own size, not the theory: +2.2 % in s(a) against 12 a.
//!   At a / R > 1/32 the cylinder cannot be 32 a deep; it is then what the real cylinder is
//!   (a half disc), no longer the flat's mirror image: the faces slide against each other in the
//!   normal step, and `ccx_read`'s node-pair pressure (which assumes they do not) misreads a, p0
//!   and c there (docs/theory.md section 16; s(a) is read right). Up to a / R = 1/40 the
//!   cylinder is the flat's block but for its arc;
//! - a mesh graded toward the contact: elements of a / n over |x| <= [`FINE_ZONE`] a (n =
//!   [`PER_HALF_WIDTH`] coarse, 16 fine, 32 finest: the suite's ladder), growing by [`GROWTH`]
//!   per element away from it in x and in depth up to 4 a: the bodies' size costs a few
//!   elements per doubling;
//! - the cylinder's top moves as a rigid translation (every top node's u_x, u_y tied to the
//!   centre's by `*EQUATION`): the line loads P and Q act on that node, and the top cannot tilt,
//!   so Q's moment about the contact is carried by the top, not by an asymmetric pressure (a pad
//!   held in its fretting rig). The flat's bottom is held;
//! - face-to-face penalty contact, the stick slope K_T (`*FRICTION`'s second value, MPa/mm,
//!   exactly the law's K_T), a stiff linear normal law;
//! - step 1 applies P (in [`NORMAL_INCREMENTS`] increments: the contact grows from a line);
//!   step n + 1 takes Q to the n-th load of the list, in increments of at most `q_step` N/mm
//!   (friction is path-dependent as soon as the edges slip, which they do for any Q > 0).

use std::fmt::Write as _;

use crate::fe::deck::{
    DeckMesh, DeckTooLarge, Geometry, MAX_DECK_ELEMENTS, normal_stiffness, real, start_step,
    write_contact_pair, write_elements, write_interaction, write_material, write_nset,
    write_surface,
};
use crate::fe::mesh::{Block, Breaks, Face, graded_toward_end, graded_toward_end_count};
use crate::kernel::params::Compact;

/// The flat's half-width and depth, and the cap on the cylinder's height, in contact half-widths
/// a: 32 a. The half-plane answer is the limit of bodies large against a; the older 6 a bodies
/// moved s(a) by +2.2 % against 12 a (docs/theory.md section 16), and an independent model with
/// bodies of 32 to 96 a found the tool right within 0.4 %. The mesh grows geometrically away from
/// the contact, so the bodies' size costs a few elements per doubling, not a square of them.
pub const BODY_SIZE: f64 = 32.0;
/// The largest a / R the deck is written for: R >= 7.5 a. The cylinder is then a half disc 7.5 a
/// deep (the deck holds its arc at any a / R < 1), far past where the half-plane answer was
/// measured (a / R <= 0.06, `validity`); beyond it the contact is no longer small against the
/// cylinder, and the deck refuses rather than pretend a half-plane.
pub const MAX_HALF_WIDTH_OVER_RADIUS: f64 = 2.0 / 15.0;
/// The weak springs that hold the cylinder's loaded node before the faces press (face-to-face
/// contact engages only then), per unit length, as a fraction of E. They carry load in parallel
/// with the contact: a spring of k carries k delta of P, delta the top's approach (about
/// 3 P / E* with these bodies), so about 5e-5 of P here. The older spring, a millionth of the
/// contact's penalty stiffness over 2 a, grew as the mesh was refined (the penalty is
/// 100 E / h): it carried 1 %, 2 % and 4 % of P on the a/8, a/16 and a/32 decks of 32 a bodies,
/// and the contact's a and p0 fell with the mesh instead of converging (issue 45, item 5).
pub const SPRING_OVER_MODULUS: f64 = 1e-5;
/// Elements per contact half-width of the coarse mesh (the fine mesh has twice as many).
pub const PER_HALF_WIDTH: usize = 8;

/// How a deck is laid out, in units of the contact half-width a: the element size at the
/// contact and the bodies' size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// Elements per contact half-width over the fine zone.
    pub per_half_width: usize,
    /// The half-width and the depth of each body, in a.
    pub body_size: f64,
    /// The growth of the element size per element away from the fine zone.
    pub growth: f64,
}
/// The half-width of the uniformly fine zone, in contact half-widths a.
pub const FINE_ZONE: f64 = 1.25;
/// The growth of the element size per element away from the fine zone: 1.5, a third fewer
/// elements than 1.3 (880 against 1300 at a/10, bodies 8 a); its own effect was not measured
/// apart, it is inside the mesh check (a/8 against a/16, both at 1.5; docs/theory.md, "The
/// Hertzian cylinder in CI").
pub const GROWTH: f64 = 1.5;
/// The coarsest element, in contact half-widths a.
const COARSEST: f64 = 4.0;
/// Increments of the normal step.
pub const NORMAL_INCREMENTS: usize = 5;

/// Node sets the deck prints and a reader reads.
pub(crate) mod sets {
    /// The flat's contact-face nodes (y = 0, z = 0) over the fine zone, by x.
    pub(crate) const FLAT_FACE: &str = "IFFLAT";
    /// The cylinder's contact-face nodes (its arc, z = 0) over the fine zone, by x.
    pub(crate) const CYLINDER_FACE: &str = "IFCYL";
    /// The node at the centre of the cylinder's top, which carries P and Q.
    pub(crate) const LOADED: &str = "LOADED";
}

/// The numbers a cylinder deck is written from: mm, MPa, N/mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderDeckInputs {
    /// Radius of the cylinder R (mm).
    pub radius: f64,
    /// Hertz's contact half-width a (mm): the mesh is laid out in units of it.
    pub half_width: f64,
    /// Hertz's peak pressure p0 (MPa), for the deck's comments.
    pub peak_pressure: f64,
    /// Young's modulus of both bodies E (MPa).
    pub modulus: f64,
    /// Poisson's ratio of both bodies nu.
    pub poisson: f64,
    /// Normal line load P (N/mm).
    pub normal_load: f64,
    /// Friction coefficient mu.
    pub friction: f64,
    /// The stick slope CalculiX is given (MPa/mm).
    pub stick_slope: f64,
}

/// The element boundaries along x (mm) of a body of half-width `half` (mm): a / n over the fine
/// zone, growing away from it.
fn x_breaks(a: f64, half: f64, layout: Layout) -> Breaks {
    let h = a / layout.per_half_width as f64;
    let fine_end = FINE_ZONE * a;
    let n_fine = (fine_end / h).round() as usize;
    let outer = graded_toward_end(0.0, half - fine_end, h, COARSEST * a, layout.growth);
    // Toward its end is toward the contact: mirrored, it grows away from the fine zone.
    let total = *outer.last().unwrap_or(&0.0);
    let right: Vec<f64> = outer.iter().rev().map(|x| fine_end + total - x).collect();
    let mut xs: Vec<f64> = right.iter().rev().map(|x| -x).collect();
    xs.pop();
    // Symmetric to the last bit, with the centre at 0 exactly (no rounding noise at x = 0).
    xs.extend((0..=2 * n_fine).map(|i| (i as f64 - n_fine as f64) * fine_end / n_fine as f64));
    xs.pop();
    xs.extend(right);
    xs
}

/// The element boundaries of a depth `depth` (mm, from -depth to 0), finest at 0 (the contact).
fn depth_breaks(a: f64, depth: f64, layout: Layout) -> Breaks {
    let h = a / layout.per_half_width as f64;
    graded_toward_end(-depth, 0.0, h, COARSEST * a, layout.growth)
}

/// The extent of the cylinder's body (mm): its half-width and its height above its lowest point.
///
/// The body is the part of the disc of radius R below the chord at height H = min(size a, R)
/// (the half disc when R <= size a), with the two thin tips where the arc meets the chord at a
/// grazing angle cut off vertically at the half-width L where the arc has risen H / 2 (and at
/// most size a): every column of the mapped mesh is then at least H / 2 tall, none degenerate.
fn cylinder_extent(radius: f64, a: f64, layout: Layout) -> (f64, f64) {
    let height = (layout.body_size * a).min(radius);
    let rise = 0.5 * height;
    let half = (rise * (2.0 * radius - rise)).sqrt();
    (half.min(layout.body_size * a), height)
}

/// The number of elements a deck of half-width `a` and radius `radius` would have, counted
/// without building it.
fn element_count(a: f64, radius: f64, layout: Layout) -> f64 {
    let h = a / layout.per_half_width as f64;
    let fine = 2.0 * (FINE_ZONE * a / h).round();
    let size = layout.body_size * a;
    let columns = |half: f64| {
        fine + 2.0
            * graded_toward_end_count(0.0, half - FINE_ZONE * a, h, COARSEST * a, layout.growth)
    };
    let rows = |depth: f64| graded_toward_end_count(-depth, 0.0, h, COARSEST * a, layout.growth);
    let (half, height) = cylinder_extent(radius, a, layout);
    columns(size) * rows(size) + columns(half) * rows(height)
}

/// The layout of a mesh density: elements of a / 8 (coarse), a / 16 (fine) or a / 32 (finest),
/// the flat [`BODY_SIZE`] a wide and deep.
pub fn layout(mesh: DeckMesh) -> Layout {
    Layout {
        per_half_width: PER_HALF_WIDTH * mesh.refinement(),
        body_size: BODY_SIZE,
        growth: GROWTH,
    }
}

/// The height of the cylinder's arc above its lowest point at `x` (mm): R - sqrt(R^2 - x^2).
fn arc(radius: f64, x: f64) -> f64 {
    x * x / (radius + (radius * radius - x * x).sqrt())
}

/// A coordinate (mm) as CalculiX reads it, at most 20 characters a field: 11 significant digits
/// (1e-11 of the largest coordinate, far below any element), and no rounding noise at zero.
fn coordinate(x: f64) -> String {
    format!("{x:.10e}")
}

/// The cylinder deck: P in step 1, then Q to each of `loads` (N/mm, increasing from 0) in steps
/// of increments of at most `q_step` (N/mm). `header` is written first (the deck's comment lines).
///
/// # Errors
/// [`DeckTooLarge`] beyond [`MAX_DECK_ELEMENTS`] elements (the mesh is fixed in units of a, so
/// only a fine mesh far finer than the bundled ones meets it).
pub fn cylinder_deck(
    inputs: &CylinderDeckInputs,
    loads: &[f64],
    layout: Layout,
    q_step: f64,
    header: &str,
) -> Result<String, DeckTooLarge> {
    let a = inputs.half_width;
    let elements = element_count(a, inputs.radius, layout);
    if elements > MAX_DECK_ELEMENTS as f64 {
        return Err(DeckTooLarge {
            elements,
            advice: "use the coarse mesh".into(),
        });
    }
    let h = a / layout.per_half_width as f64;
    let size = layout.body_size * a;
    let width = h;
    let zs = vec![0.0, width];
    let flat = Block::new(
        [
            x_breaks(a, size, layout),
            depth_breaks(a, size, layout),
            zs.clone(),
        ],
        1,
        1,
    );
    // The cylinder in its own coordinates: eta from 0 (the arc) to H (the top), graded as a
    // depth mirrored; y = arc(x) (1 - eta / H) + eta puts the bottom row on the arc exactly and
    // the top on the chord y = H.
    let (half, depth) = cylinder_extent(inputs.radius, a, layout);
    let etas: Breaks = depth_breaks(a, depth, layout)
        .iter()
        .rev()
        .map(|y| -y)
        .collect();
    let cylinder = Block::new(
        [x_breaks(a, half, layout), etas, zs],
        flat.node_count() + 1,
        flat.element_count() + 1,
    );
    let on_arc = |[x, eta, z]: [f64; 3]| [x, arc(inputs.radius, x) * (1.0 - eta / depth) + eta, z];
    let normal_slope = normal_stiffness(inputs.modulus, h, inputs.stick_slope);

    let mut deck = header.to_string();
    deck.push_str("*HEADING\n");
    let _ = writeln!(
        deck,
        "microslip Hertzian cylinder on a flat, K_T = {} MPa/mm",
        Compact(inputs.stick_slope)
    );
    deck.push_str("*NODE, NSET=NALL\n");
    for (id, [x, y, z]) in flat.nodes() {
        let _ = writeln!(
            deck,
            "{id}, {}, {}, {}",
            coordinate(x),
            coordinate(y),
            coordinate(z)
        );
    }
    for (id, point) in cylinder.nodes() {
        let [x, y, z] = on_arc(point);
        let _ = writeln!(
            deck,
            "{id}, {}, {}, {}",
            coordinate(x),
            coordinate(y),
            coordinate(z)
        );
    }
    let ground = flat.node_count() + cylinder.node_count() + 1;
    let [nx, ny, _] = flat.elements_along();
    let [cx, cy, _] = cylinder.elements_along();
    let loaded = cylinder
        .node([cx, 2 * cy, 0])
        .expect("the top's centre is a node");
    // Two ground nodes for weak springs on the loaded node, along y and along x: face-to-face
    // contact engages only once the faces press, so the cylinder would float at first.
    let _ = writeln!(
        deck,
        "{ground}, 0., {}, 0.\n{}, {}, {}, 0.",
        real(-depth),
        ground + 1,
        real(-depth),
        real(depth)
    );
    write_elements(&mut deck, "FLAT", &flat);
    write_elements(&mut deck, "CYL", &cylinder);
    let spring = flat.element_count() + cylinder.element_count() + 1;
    let _ = writeln!(
        deck,
        "** weak springs on the loaded node ({} E per unit length)\n\
         *ELEMENT, TYPE=SPRINGA, ELSET=ESPRING\n{spring}, {loaded}, {ground}\n{}, {loaded}, {}\n\
         *SPRING, ELSET=ESPRING\n\n{}",
        Compact(SPRING_OVER_MODULUS),
        spring + 1,
        ground + 1,
        real(SPRING_OVER_MODULUS * inputs.modulus * width)
    );

    let fine = FINE_ZONE * a * (1.0 + 1e-9);
    let face_nodes = |block: &Block, j: usize| -> Vec<usize> {
        let [n, _, _] = block.elements_along();
        (0..=2 * n)
            .filter(|&i| block.coordinate(0, i).abs() <= fine)
            .filter_map(|i| block.node([i, j, 0]))
            .collect()
    };
    write_nset(&mut deck, sets::FLAT_FACE, &face_nodes(&flat, 2 * ny));
    write_nset(&mut deck, sets::CYLINDER_FACE, &face_nodes(&cylinder, 0));
    write_nset(&mut deck, sets::LOADED, &[loaded]);
    let all: Vec<usize> = flat
        .nodes()
        .chain(cylinder.nodes())
        .map(|(id, _)| id)
        .collect();
    write_nset(&mut deck, "ALL", &all);
    let bottom: Vec<usize> = (0..=2 * nx)
        .flat_map(|i| [0, 1, 2].map(|k| flat.node([i, 0, k])))
        .flatten()
        .collect();
    let mut held = bottom;
    held.extend([ground, ground + 1]);
    write_nset(&mut deck, "HELD", &held);
    // The contact surfaces span the fine zone only: beyond it the faces never touch (Hertz's
    // contact ends at a), and CalculiX's contact search and the friction's unsymmetric solve
    // grow with every face pair it is given.
    let in_fine_zone = |block: &Block, face: Face| -> Vec<usize> {
        block
            .boundary_faces(face)
            .into_iter()
            .enumerate()
            .filter(|&(ex, _)| block.coordinate(0, 2 * ex + 1).abs() <= fine)
            .map(|(_, element)| element)
            .collect()
    };
    write_surface(
        &mut deck,
        "SFLATTOP",
        &in_fine_zone(&flat, Face::YMax),
        Face::YMax,
    );
    write_surface(
        &mut deck,
        "SCYLBOT",
        &in_fine_zone(&cylinder, Face::YMin),
        Face::YMin,
    );
    write_material(&mut deck, inputs.modulus, inputs.poisson, &["FLAT", "CYL"]);
    write_interaction(&mut deck, normal_slope, inputs.friction, inputs.stick_slope);
    write_contact_pair(
        &mut deck,
        "the flat's upper face",
        "the cylinder's arc",
        ["SFLATTOP", "SCYLBOT"],
    );
    deck.push_str(
        "** plane strain (no node moves across the slice), the flat's bottom held\n\
         *BOUNDARY\nALL, 3, 3\nHELD, 1, 3\n\
         ** the cylinder's top translates as a rigid line: u_x, u_y of every top node = the loaded node's\n\
         *EQUATION\n",
    );
    for k in [0, 2] {
        for i in 0..=2 * cx {
            if let Some(node) = cylinder.node([i, 2 * cy, k])
                && node != loaded
            {
                for dof in [1, 2] {
                    let _ = writeln!(deck, "2\n{node}, {dof}, 1., {loaded}, {dof}, -1.");
                }
            }
        }
    }
    let outputs = |deck: &mut String| {
        for set in [sets::FLAT_FACE, sets::CYLINDER_FACE, sets::LOADED] {
            let _ = writeln!(deck, "*NODE PRINT, NSET={set}\nU");
        }
        deck.push_str(
            "*CONTACT PRINT\nCSTR\n*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n",
        );
    };
    let _ = writeln!(
        deck,
        "** step 1: the normal line load P = {} N/mm (a = {} mm, p0 = {} MPa by Hertz)",
        Compact(inputs.normal_load),
        Compact(a),
        Compact(inputs.peak_pressure)
    );
    start_step(&mut deck, 1.0 / NORMAL_INCREMENTS as f64, Geometry::Linear);
    let _ = writeln!(
        deck,
        "*CLOAD\n{loaded}, 2, {}",
        real(-inputs.normal_load * width)
    );
    outputs(&mut deck);
    let mut from = 0.0;
    for (n, &q) in loads.iter().enumerate() {
        // A deck of many load steps is long work: a caller that cancels it stops here.
        crate::numeric::cancel::checkpoint();
        let _ = writeln!(
            deck,
            "** step {}: the tangential line load Q = {} N/mm, in increments of at most {} N/mm",
            n + 2,
            Compact(q),
            Compact(q_step)
        );
        let increment = if q > from {
            (q_step / (q - from)).clamp(1e-3, 1.0)
        } else {
            1.0
        };
        start_step(&mut deck, increment, Geometry::Linear);
        let _ = writeln!(
            deck,
            "*CLOAD\n{loaded}, 2, {}\n{loaded}, 1, {}",
            real(-inputs.normal_load * width),
            real(q * width)
        );
        outputs(&mut deck);
        from = q;
    }
    Ok(deck)
}

#[cfg(test)]
mod tests {
    use super::*;

    const PAD: CylinderDeckInputs = CylinderDeckInputs {
        radius: 50.0,
        half_width: 0.525_231_918_323_660_1,
        peak_pressure: 606.036_828_834_992_3,
        modulus: 210_000.0,
        poisson: 0.3,
        normal_load: 500.0,
        friction: 0.6,
        stick_slope: 5e4,
    };

    #[test]
    fn the_mesh_is_symmetric_and_fine_at_the_contact() {
        let a = PAD.half_width;
        let layout = Layout {
            per_half_width: 20,
            body_size: BODY_SIZE,
            growth: GROWTH,
        };
        let xs = x_breaks(a, BODY_SIZE * a, layout);
        assert!((xs[0] + BODY_SIZE * a).abs() < 1e-9 * a);
        assert!((xs[xs.len() - 1] - BODY_SIZE * a).abs() < 1e-9 * a);
        for (l, r) in xs.iter().zip(xs.iter().rev()) {
            assert!((l + r).abs() < 1e-9 * a, "{l} {r}");
        }
        let widths: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(widths.iter().all(|&w| w > 0.0));
        let centre = widths[widths.len() / 2];
        assert!((centre - a / 20.0).abs() < 1e-9 * a, "{centre}");
    }

    /// The nodes of a deck (id -> x, y) and the node set `name`, read back from its text.
    fn nodes_and_set(
        deck: &str,
        name: &str,
    ) -> (std::collections::HashMap<usize, [f64; 2]>, Vec<usize>) {
        let mut nodes = std::collections::HashMap::new();
        let mut set = Vec::new();
        let mut section = "";
        for line in deck.lines() {
            if line.starts_with('*') {
                section = if line.starts_with("*NODE, NSET=NALL") {
                    "node"
                } else if line == format!("*NSET, NSET={name}") {
                    "set"
                } else {
                    ""
                };
                continue;
            }
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            match section {
                "node" => {
                    let v: Vec<f64> = fields.iter().map(|f| f.parse().unwrap()).collect();
                    nodes.insert(v[0] as usize, [v[1], v[2]]);
                }
                "set" => set.extend(fields.iter().map(|f| f.parse::<usize>().unwrap())),
                _ => {}
            }
        }
        (nodes, set)
    }

    /// The cylinder is the disc below a chord: its contact face on the circle of radius R (every
    /// node of it, midside nodes too), every node inside the disc; the flat is BODY_SIZE a wide
    /// and deep; where R < BODY_SIZE a the cylinder is the half disc, its tips cut where the arc
    /// has risen R / 2 (issue 45, item 5: the older deck's bodies were 6 a).
    #[test]
    fn the_cylinder_is_a_true_circle_on_a_large_flat() {
        for radius in [PAD.radius, 10.0 * PAD.half_width] {
            let inputs = CylinderDeckInputs { radius, ..PAD };
            let a = inputs.half_width;
            let deck =
                cylinder_deck(&inputs, &[100.0], layout(DeckMesh::Coarse), 30.0, "").unwrap();
            let (nodes, face) = nodes_and_set(&deck, sets::CYLINDER_FACE);
            assert!(face.len() > 20);
            let off_circle = |[x, y]: [f64; 2]| (x * x + (y - radius).powi(2)).sqrt() - radius;
            for id in &face {
                assert!(
                    off_circle(nodes[id]).abs() < 1e-9 * radius,
                    "{:?}",
                    nodes[id]
                );
            }
            let lowest = nodes.values().map(|p| p[1]).fold(f64::INFINITY, f64::min);
            let widest = nodes.values().map(|p| p[0]).fold(0.0, f64::max);
            assert!((lowest + BODY_SIZE * a).abs() < 1e-9 * a, "{lowest}");
            assert!((widest - BODY_SIZE * a).abs() < 1e-9 * a, "{widest}");
            // Every node above the flat's face is the cylinder's: inside the disc, below H.
            let (half, height) = cylinder_extent(radius, a, layout(DeckMesh::Coarse));
            let above: Vec<[f64; 2]> = nodes
                .values()
                .copied()
                .filter(|p| p[1] > 1e-12 * a)
                .collect();
            assert!(above.iter().all(|&p| off_circle(p) < 1e-9 * radius));
            let top = above.iter().map(|p| p[1]).fold(0.0, f64::max);
            let side = above.iter().map(|p| p[0]).fold(0.0, f64::max);
            assert!((top - height).abs() < 1e-9 * a && (side - half).abs() < 1e-9 * a);
            if radius < BODY_SIZE * a {
                assert!((height - radius).abs() < 1e-12 * radius);
                assert!((half - 0.75f64.sqrt() * radius).abs() < 1e-9 * radius);
            } else {
                assert!(
                    (height - BODY_SIZE * a).abs() < 1e-9 * a
                        && half >= BODY_SIZE * a * (1.0 - 1e-12)
                );
            }
        }
    }

    /// The springs that hold the cylinder before the faces press carry load beside the contact:
    /// their stiffness per unit length is the same on every rung of the ladder (it once grew as
    /// the penalty 100 E / h, and carried 1, 2, 4 % of P on a/8, a/16, a/32), and a small
    /// fraction of E.
    #[test]
    fn the_springs_do_not_stiffen_with_the_mesh() {
        let per_length = |mesh: DeckMesh| {
            let deck = cylinder_deck(&PAD, &[100.0], layout(mesh), 30.0, "").unwrap();
            let after = deck.split("*SPRING, ELSET=ESPRING\n\n").nth(1).unwrap();
            let spring: f64 = after.lines().next().unwrap().trim().parse().unwrap();
            let width = PAD.half_width / layout(mesh).per_half_width as f64;
            spring / width
        };
        let expected = SPRING_OVER_MODULUS * PAD.modulus;
        for mesh in DeckMesh::ALL {
            let k = per_length(mesh);
            assert!(
                (k / expected - 1.0).abs() < 1e-9,
                "{mesh:?}: {k} N/mm per mm"
            );
        }
        // Its share of P at the top's approach (about 3 P / E*) is below 1e-4.
        let approach = 3.0 * PAD.normal_load * 2.0 * (1.0 - PAD.poisson.powi(2)) / PAD.modulus;
        assert!(expected * approach / PAD.normal_load < 1e-4);
    }
}
