//! CalculiX input decks (Abaqus keyword syntax): what every problem's deck is written with (its
//! mesh, size limit, load path and cards). Each problem writes its own deck in its application
//! folder (`src/problems/<name>/deck.rs`, the [`Deck`](super::face::Deck) of it) from these.
//!
//! What the decks model, and how that differs from the paper's Ansys model (2000 quadratic
//! plane-stress elements) and from the closed forms, is in docs/theory.md, "Benchmarking an FE code".
//! In short: 20-node bricks with reduced integration (C3D20R), one element across the width;
//! face-to-face penalty contact with a stiff linear normal law; `*FRICTION` with mu and a stick slope
//! equal to K_T (CalculiX's stick slope is a shear stress per slip, MPa/mm, exactly K_T). The
//! beams' steps are `NLGEOM` (the pressure follows the rotating faces) and follow the load path in
//! increments ([`LoadPath`]); the plate's single step is linear. The beams are in plane stress
//! (free side faces), the plate in plane strain (every node held across the width) on a fixed block
//! standing for the rigid plane.
//!
//! A deck is plain text built in memory: deterministic bytes for the same inputs, no I/O. Its
//! first lines carry a machine-readable header ([`DeckHeader`](super::header::DeckHeader)) that
//! `microslip compare` reads back, so that results are compared with the parameters that
//! produced them.

use std::fmt::Write as _;

use thiserror::Error;

use super::mesh::{Block, Face};
use crate::kernel::params::Compact;

/// How fine the deck's mesh is. `Fine` halves every element size of `Coarse`, `Finest` halves
/// them again: h, h/2, h/4, the three rungs of a mesh ladder whose answers Richardson
/// extrapolation takes to the converged one ([`super::ladder`]; running coarse and fine alone is
/// the quick convergence check of docs/guide.md, "Benchmark your FE code"). Every deck writer
/// takes the density through [`DeckMesh::refinement`] alone, so a new rung is one variant here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DeckMesh {
    /// The problem's own default (each deck's node and element lists give its size).
    #[default]
    Coarse,
    /// Every element size halved.
    Fine,
    /// Every element size a quarter of the coarse one.
    Finest,
}

impl DeckMesh {
    /// The name used in headers and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            DeckMesh::Coarse => "coarse",
            DeckMesh::Fine => "fine",
            DeckMesh::Finest => "finest",
        }
    }

    /// Every density, coarsest first.
    pub const ALL: [DeckMesh; 3] = [DeckMesh::Coarse, DeckMesh::Fine, DeckMesh::Finest];

    /// The density of `name` ([`DeckMesh::name`]).
    pub fn from_name(name: &str) -> Option<DeckMesh> {
        DeckMesh::ALL.into_iter().find(|m| m.name() == name)
    }

    /// 1 for coarse, 2 for fine, 4 for finest: the number of elements per coarse element along
    /// each direction (the element size is h / refinement).
    pub fn refinement(self) -> usize {
        match self {
            DeckMesh::Coarse => 1,
            DeckMesh::Fine => 2,
            DeckMesh::Finest => 4,
        }
    }
}

/// The largest deck written: 20 000 elements. The fine decks have about a thousand (888 for the
/// paper's beams, 1 002 for its plate), and halving the coarse decks' element size changes w(L) by
/// 0.03 %; a deck twenty times the fine one gains nothing a benchmark can see, while the time and
/// memory of CalculiX's direct solver grow faster than the element count (a run at the limit was
/// not measured). Beyond it a deck is refused by its element count, before anything is allocated
/// ([`DeckTooLarge`]).
pub const MAX_DECK_ELEMENTS: usize = 20_000;

/// A deck over [`MAX_DECK_ELEMENTS`]: its element count and how to get a smaller one.
///
/// The largest L/h that fits is found by bisection on the count itself (the grading at the clamp
/// adds a part that does not grow with L/h, so a proportion would overshoot).
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "the deck would have {} elements, more than the {MAX_DECK_ELEMENTS} a CalculiX run on one \
     machine can take in reasonable time (docs/theory.md, \"Benchmarking an FE code\"); {advice}",
    count(*elements)
)]
pub struct DeckTooLarge {
    /// The number of elements the deck would have.
    pub elements: f64,
    /// What to change to get a smaller mesh.
    pub advice: String,
}

/// A count in words a reader takes in at once: whole up to a million, then "2.00e9".
fn count(n: f64) -> String {
    if n < 1e6 {
        format!("{n:.0}")
    } else {
        format!("{n:.2e}")
    }
}

/// How finely a beam deck follows the load path: the largest change of the tip force (N) within one
/// increment, in every load step that ends beyond F_1.
///
/// Friction is path-dependent once the interface saturates: a point that slides at mu p while p
/// changes, or that stops sliding, ends where its history took it. CalculiX's answer in macroslip
/// changes with the increment size (docs/theory.md, "Benchmarking an FE code": -1.0 % one increment
/// per step, -1.7 % converged against Timoshenko at h/L = 1/30, mu P = 1.5 MPa) and converges
/// about linearly in it. Below F_1 nothing saturates, the interface law is linear, and one
/// increment is exact: those steps keep one.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LoadPath {
    /// Largest tip-force change per increment (N); `None`: [`LoadPath::DEFAULT_FRACTION`] F_1.
    pub force_step: Option<f64>,
}

impl LoadPath {
    /// The default force step as a fraction of F_1 (at the deck's stick slope). Measured at
    /// h/L = 1/30, mu P = 1.5 MPa, F = 1.25 F_1: steps of F_1/20, /40, /80 gave -0.18, -0.27,
    /// -0.31 % against Timoshenko, first-order convergence to -0.35 %; F_1/40 leaves 0.08 points.
    pub const DEFAULT_FRACTION: f64 = 0.025;
    /// The validation's increment check: halving the force step may move w(L) by this much at
    /// most. Convergence is first order, so the error left is about twice the move: 0.2 %.
    /// Measured moves (h/L = 1/30, mu P = 1.5 MPa, F_1/40 to F_1/80): 0.050 % at 1.0125 F_1,
    /// 0.043 % at 1.25 F_1, 0.004 % at 1.025 F_1.
    pub const CONVERGED: f64 = 0.001;
    /// Smallest increment as a fraction of a step: at most 1000 increments per step.
    const SMALLEST: f64 = 1e-3;

    /// The force step (N) for a structure whose macroslip starts at `onset` (F_1 at the deck's
    /// stick slope, N).
    pub fn force_step(self, onset: f64) -> f64 {
        self.force_step.unwrap_or(Self::DEFAULT_FRACTION * onset)
    }

    /// The increment of a step from `from` to `to` (N) as a fraction of the step: 1 when the step
    /// ends at or below F_1 (`onset`), else `step / (to - from)`, between 1e-3 and 1.
    pub(crate) fn increment(step: f64, onset: f64, from: f64, to: f64) -> f64 {
        if to <= onset || to <= from {
            1.0
        } else {
            (step / (to - from)).clamp(Self::SMALLEST, 1.0)
        }
    }

    /// A step from `from` to `to` (N) that crosses F_1 (`onset`) and needs several increments goes
    /// up to F_1 in its first increment: below F_1 the interface law is linear and one increment
    /// is exact, so the fine increments are spent beyond it only. Returns the step's increment
    /// `t1` (fraction of the step) and its load amplitude, (step time, tip force / `to`) at
    /// 0, t1 and 1: F_1 at the end of the first increment, then `to - F_1` over the other
    /// `(1 - t1) / t1` increments, each at most `step` N. None when the step does not cross F_1
    /// or one increment does (then [`LoadPath::increment`] alone applies).
    pub(crate) fn ramp(
        step: f64,
        onset: f64,
        from: f64,
        to: f64,
    ) -> Option<(f64, [(f64, f64); 3])> {
        if !(from < onset && onset < to) || step >= to - from {
            return None;
        }
        let t1 = (step / (to - onset + step)).max(Self::SMALLEST);
        Some((t1, [(0.0, from / to), (t1, onset / to), (1.0, 1.0)]))
    }
}

/// Each load step's increment (fraction of the step) and, for a step that crosses F_1 (`onset`)
/// in several increments, the name of its `*AMPLITUDE`, written into `deck` here: CalculiX reads
/// amplitudes in the model definition, before the first step. `loads` (N) increase from 0.
pub(crate) fn load_steps(
    deck: &mut String,
    loads: &[f64],
    force_step: f64,
    onset: f64,
) -> Vec<(f64, Option<String>)> {
    let mut from = 0.0;
    let mut steps = Vec::with_capacity(loads.len());
    for (n, &to) in loads.iter().enumerate() {
        // A deck of many load steps is long work: a caller that cancels it (the Python face's
        // Ctrl-C) stops here and at each step's `*CLOAD` ([`write_cload`]).
        crate::numeric::cancel::checkpoint();
        let step = match LoadPath::ramp(force_step, onset, from, to) {
            Some((t1, points)) => {
                let name = format!("RAMP{}", n + 2);
                let _ = writeln!(
                    deck,
                    "** step {}: up to F_1 in its first increment, then by at most {} N\n\
                     *AMPLITUDE, NAME={name}",
                    n + 2,
                    Compact(force_step)
                );
                let row: Vec<String> = points
                    .iter()
                    .map(|(t, a)| format!("{}, {}", real(*t), real(*a)))
                    .collect();
                let _ = writeln!(deck, "{}", row.join(", "));
                (t1, Some(name))
            }
            None => (LoadPath::increment(force_step, onset, from, to), None),
        };
        steps.push(step);
        from = to;
    }
    steps
}

/// The `*CLOAD` card of a load step, following its amplitude when it has one.
pub(crate) fn write_cload(deck: &mut String, amplitude: Option<&str>) {
    crate::numeric::cancel::checkpoint();
    match amplitude {
        Some(name) => {
            let _ = writeln!(deck, "*CLOAD, AMPLITUDE={name}");
        }
        None => deck.push_str("*CLOAD\n"),
    }
}

/// The normal penalty K_N (MPa/mm): stiff against the elements it connects (100 E over an element's
/// height), and at least 10 K_T, as CalculiX's manual advises for the stick slope.
pub(crate) fn normal_stiffness(modulus: f64, element_height: f64, stick_slope: f64) -> f64 {
    (100.0 * modulus / element_height).max(10.0 * stick_slope)
}

/// How a deck's steps treat geometry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Geometry {
    /// Small displacements throughout (the plate: its faces do not rotate).
    Linear,
    /// `NLGEOM`: the pressure follows the faces as they rotate (the beams; see [`beam_deck`]).
    Nonlinear,
}

/// A step of unit time whose increments are at most `increment` (CalculiX cuts them further when
/// an increment does not converge, and grows them back up to `increment`).
pub(crate) fn start_step(deck: &mut String, increment: f64, geometry: Geometry) {
    let nlgeom = match geometry {
        Geometry::Linear => "",
        Geometry::Nonlinear => " NLGEOM,",
    };
    if increment >= 1.0 {
        let _ = writeln!(deck, "*STEP,{nlgeom} INC=1000\n*STATIC\n1., 1.");
    } else {
        // CalculiX reads at most 20 characters per field: 10 significant digits.
        let _ = writeln!(
            deck,
            "*STEP,{nlgeom} INC=10000\n*STATIC\n{increment:.9e}, 1., {:.9e}, {increment:.9e}",
            increment * 1e-3
        );
    }
}

pub(crate) fn write_nodes(deck: &mut String, blocks: &[&Block]) {
    deck.push_str("*NODE, NSET=NALL\n");
    for block in blocks {
        for (id, [x, y, z]) in block.nodes() {
            let _ = writeln!(deck, "{id}, {}, {}, {}", real(x), real(y), real(z));
        }
    }
}

pub(crate) fn write_elements(deck: &mut String, set: &str, block: &Block) {
    let _ = writeln!(deck, "*ELEMENT, TYPE=C3D20R, ELSET={set}");
    for (id, nodes) in block.elements() {
        // At most 16 entries on a line: the id and 15 nodes, then the last 5.
        let _ = write!(deck, "{id}");
        for (n, node) in nodes.iter().enumerate() {
            let _ = write!(deck, "{}{node}", if n == 15 { ",\n" } else { ", " });
        }
        deck.push('\n');
    }
}

pub(crate) fn write_nset(deck: &mut String, name: &str, nodes: &[usize]) {
    let _ = writeln!(deck, "*NSET, NSET={name}");
    for line in nodes.chunks(10) {
        let text: Vec<String> = line.iter().map(usize::to_string).collect();
        let _ = writeln!(deck, "{}", text.join(", "));
    }
}

pub(crate) fn write_surface(deck: &mut String, name: &str, elements: &[usize], face: Face) {
    let _ = writeln!(deck, "*SURFACE, NAME={name}, TYPE=ELEMENT");
    for id in elements {
        let _ = writeln!(deck, "{id}, S{}", face.number());
    }
}

/// A `*DLOAD` of pressure `pressure` (MPa) on the given boundary faces.
pub(crate) fn write_pressure(deck: &mut String, faces: &[(&Block, Face)], pressure: f64) {
    deck.push_str("*DLOAD\n");
    for &(block, face) in faces {
        for id in block.boundary_faces(face) {
            let _ = writeln!(deck, "{id}, P{}, {}", face.number(), real(pressure));
        }
    }
}

pub(crate) fn write_material(deck: &mut String, modulus: f64, poisson: f64, sets: &[&str]) {
    let _ = writeln!(
        deck,
        "*MATERIAL, NAME=SOLID\n*ELASTIC\n{}, {}",
        real(modulus),
        real(poisson)
    );
    for set in sets {
        let _ = writeln!(deck, "*SOLID SECTION, ELSET={set}, MATERIAL=SOLID");
    }
}

/// The contact pair `[slave, master]` with the `JENKINS` interaction, and a comment saying which
/// faces they are.
pub(crate) fn write_contact_pair(
    deck: &mut String,
    slave: &str,
    master: &str,
    surfaces: [&str; 2],
) {
    let _ = writeln!(
        deck,
        "** slave: {slave}; master: {master}\n\
         *CONTACT PAIR, INTERACTION=JENKINS, TYPE=SURFACE TO SURFACE\n{}, {}",
        surfaces[0], surfaces[1]
    );
}

pub(crate) fn write_interaction(
    deck: &mut String,
    normal_slope: f64,
    friction: f64,
    stick_slope: f64,
) {
    let _ = writeln!(
        deck,
        "** the regularized Coulomb law: tau = K_T s up to mu p (stick slope = K_T, MPa/mm)\n\
         *SURFACE INTERACTION, NAME=JENKINS\n\
         *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{}\n*FRICTION\n{}, {}",
        real(normal_slope),
        real(friction),
        real(stick_slope)
    );
}

/// The most characters CalculiX reads of a number: ccx 2.20 cuts a longer field, which leaves a
/// decimal fraction a few digits short but an exponent form without its exponent's last digit
/// ("*ERROR reading *SPRING. Card image: 5.3030303030303025E-5", the lap deck's stabilising
/// spring of issue 33's joint A at the finest mesh, issue 45).
const CCX_FIELD: usize = 20;

/// A number as CalculiX must read it: shortest round-trip digits, always with a decimal point
/// (some cards read an integer-looking first field as a degree of freedom); an exponent form
/// longer than [`CCX_FIELD`] keeps as many significant digits as fit.
pub(crate) fn real(x: f64) -> String {
    let text = format!("{x:?}");
    let text = match text.find('e') {
        Some(e) if !text[..e].contains('.') => format!("{}.{}", &text[..e], &text[e..]),
        _ => text,
    };
    if text.len() <= CCX_FIELD || !text.contains('e') {
        return text;
    }
    (1..17)
        .rev()
        .map(|digits| format!("{x:.digits$e}"))
        .find(|short| short.len() <= CCX_FIELD)
        .unwrap_or(text)
}

/// What the decks' tests in the problems' folders read back from a written deck.
#[cfg(test)]
pub(crate) mod test_support {
    /// Elements in a written deck: the lines of its `*ELEMENT` cards, springs excluded.
    pub(crate) fn elements_written(deck: &str) -> usize {
        let mut inside = false;
        let mut count = 0;
        for line in deck.lines() {
            // A 20-node brick takes two lines, the first ending with a comma.
            if line.starts_with('*') {
                inside = line.starts_with("*ELEMENT") && !line.contains("SPRINGA");
            } else if inside && !line.trim_end().ends_with(',') {
                count += 1;
            }
        }
        count
    }

    /// The x of each node of `set`, in the set's order.
    pub(crate) fn node_x_of_set(deck: &str, set: &str) -> Vec<f64> {
        let coords: std::collections::HashMap<usize, f64> = deck
            .split("*NODE, NSET=NALL\n")
            .nth(1)
            .unwrap()
            .lines()
            .take_while(|l| !l.starts_with('*'))
            .map(|l| {
                let f: Vec<&str> = l.split(", ").collect();
                (f[0].parse().unwrap(), f[1].parse().unwrap())
            })
            .collect();
        deck.split(&format!("*NSET, NSET={set}\n"))
            .nth(1)
            .unwrap()
            .lines()
            .take_while(|l| !l.starts_with('*'))
            .flat_map(|l| l.split(", ").map(|n| coords[&n.parse::<usize>().unwrap()]))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_always_carry_a_decimal_point() {
        assert_eq!(real(200.0), "200.0");
        assert_eq!(real(0.1), "0.1");
        assert_eq!(real(1e-7), "1.e-7");
        assert_eq!(real(-2.5e20), "-2.5e20");
    }

    /// ccx reads 20 characters of a field: an exponent form longer than that lost its
    /// exponent's last digit and was refused (issue 45); it now keeps 16 digits, and so reads
    /// back within 1e-15.
    #[test]
    fn exponent_forms_fit_ccx_s_field() {
        let x = 5.303_030_303_030_302_5e-5;
        assert_eq!(format!("{x:?}"), "5.3030303030303025e-5");
        let text = real(x);
        assert!(text.len() <= CCX_FIELD && text.contains('.'), "{text}");
        let back: f64 = text.parse().unwrap();
        assert!((back / x - 1.0).abs() < 1e-15, "{text}");
        assert_eq!(real(-1.234_567_890_123_456_7e-100).len(), CCX_FIELD);
        // Decimal forms are left as they are (ccx drops only their last digits).
        assert_eq!(real(0.000_106_060_606_060_606_05), "0.00010606060606060605");
    }
}
