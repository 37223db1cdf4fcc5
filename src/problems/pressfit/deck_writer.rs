//! The press fit's CalculiX deck written from plain numbers (the mesh, the steps and the cards);
//! [`deck.rs`](super::deck) wraps it in the [`Deck`](crate::fe::face::Deck) face (its header, its
//! loads, its expected values).
//!
//! What the deck models (docs/theory.md section 18, "CalculiX"), and why:
//!
//! - **axisymmetric CAX4 elements**, CalculiX's (and Abaqus') convention: the first coordinate is
//!   the radius, the second the axis. So a node is `(r, x)` with x the fit's axial coordinate
//!   (the loaded face at x = 0, the held face at x = L). CalculiX expands each CAX element into a
//!   wedge of 2 degrees, and reports forces (`RF`, totals) for that wedge: the reader scales them
//!   back with the run's own load ([`super::ccx_read`]). First-order elements because CalculiX
//!   issue #98, whose case this deck answers, ran CAX4 (its node-slave failure is a CAX4 one);
//! - **two bodies over the fit length**: the shaft from ri to r + delta (the interference is the
//!   overlap of the meshes, as the 40.005 mm shaft in a 40.000 mm bore) and the hub from
//!   r to ro, both from x = 0 to x = L, on the same axial breaks so that every shaft node on the
//!   interface faces a hub node. The breaks are refined toward both faces, where slip starts
//!   (end elements half the mean size, the middle ones 1.5 times it); the radial breaks are
//!   uniform;
//! - **penalty contact**, `PRESSURE-OVERCLOSURE=LINEAR` with K_N = 100 E over the radial element
//!   size (at least 10 K_T): the overclosure left is p / K_N, 2e-7 of the interference on the
//!   #98 fit; `*FRICTION mu, K_T`, CalculiX's stick slope being exactly the law's K_T;
//! - **step 1 resolves the interference without friction**: a shrink fit leaves no shear at the
//!   interface (docs/theory.md (S1)), but the interference's Poisson strains slide the members
//!   axially against each other (2.3e-4 mm at the faces of the #98 fit, 4 times the slip K_T
//!   turns into mu p): with friction on, step 1 left mu p of shear over most of the interface.
//!   So step 1 changes the friction to 1e-5 mu (`*CHANGE FRICTION`) and holds one shaft node
//!   axially (frictionless, the shaft would have a free axial motion); the push-out steps restore
//!   mu and release the node (its reaction is the 1e-5 mu p friction's, nothing);
//! - **the push-out**: step n + 1 takes the traction F / As on the shaft's end face x = 0 to the
//!   n-th load, in increments of at most the force step (friction is path-dependent once a face
//!   slides); the hub is held axially on its far face x = L, free radially;
//! - **the capacity step** (the last): the shaft's end face pushed axially to
//!   [`CAPACITY_PUSH`] times the closed form's Delta at F_gross, the traction taken off; the
//!   hub's reaction at its end is the push-out capacity, CalculiX's F_gross;
//! - **the contact formulation**: surface-to-surface with the shaft's element faces as slave. The
//!   deck also defines the node surface [`sets::NODE_SLAVE`] of the same nodes: replacing the
//!   pair by `TYPE=NODE TO SURFACE` with it as slave is CalculiX issue #98's node slave
//!   ([`NODE_SLAVE_PAIR`]; `validation/calculix/pressfit_campaign.py` runs both).

use std::fmt::Write as _;

use crate::fe::deck::{
    DeckTooLarge, Geometry, LoadPath, MAX_DECK_ELEMENTS, normal_stiffness, real, start_step,
    write_interaction, write_nset,
};
use crate::kernel::params::Compact;

/// The friction step 1 resolves the interference with (`*CHANGE FRICTION`), a fraction of mu:
/// 1e-5 (CalculiX wants a positive coefficient; the shear it leaves is 1e-5 mu p).
pub const ASSEMBLY_FRICTION: f64 = 1e-5;
/// The capacity step pushes the shaft's end to this many times the closed form's Delta at
/// F_gross (regularized law): far into gross slip, where the reaction is flat.
pub const CAPACITY_PUSH: f64 = 10.0;
/// The print frequency of the `.dat`'s blocks: beyond any step's increments, so that CalculiX
/// prints each step's last increment only.
const STEP_END: usize = 100_000;
/// Increments of the capacity step.
pub const CAPACITY_INCREMENTS: usize = 50;
/// Axial elements of the coarse mesh (the fine one has twice as many in each direction).
pub const AXIAL_ELEMENTS: usize = 40;
/// Radial elements per member of the coarse mesh.
pub const RADIAL_ELEMENTS: usize = 8;
/// The amplitude of the axial grading: element sizes from (1 - g) to (1 + g) times the mean.
pub const GRADING: f64 = 0.5;

/// The contact pair the deck writes (surface-to-surface, the shaft's faces as slave).
pub const SURFACE_PAIR: &str =
    "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=SURFACE TO SURFACE\nSSHAFT, SHUB";
/// CalculiX issue #98's node slave: the pair that replaces [`SURFACE_PAIR`] to run it.
pub const NODE_SLAVE_PAIR: &str =
    "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=NODE TO SURFACE\nNSHAFT, SHUB";

/// Node sets the deck prints and the reader reads.
pub(crate) mod sets {
    /// The shaft's loaded end face x = 0 (its nodes by radius).
    pub(crate) const SHAFT_END: &str = "SHAFTEND";
    /// The hub's held face x = L.
    pub(crate) const HUB_HELD: &str = "HUBHELD";
    /// The shaft's interface nodes (radius r + delta), by x.
    pub(crate) const SHAFT_FACE: &str = "IFSHAFT";
    /// The hub's interface nodes (radius r), by x.
    pub(crate) const HUB_FACE: &str = "IFHUB";
    /// The shaft node held axially in step 1.
    pub(crate) const SHAFT_FIX: &str = "SHAFTFIX";
    /// The node surface of the shaft's interface nodes (CalculiX issue #98's node slave).
    pub(crate) const NODE_SLAVE: &str = "NSHAFT";
}

/// What the deck is written from (mm, MPa, MPa/mm, N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitDeckInputs {
    /// Fit radius r, bore radius ri, hub's outer radius ro, length L (mm).
    pub radii: [f64; 3],
    pub length: f64,
    /// Shaft's and hub's (E, nu).
    pub shaft: (f64, f64),
    pub hub: (f64, f64),
    /// Radial interference (mm).
    pub interference: f64,
    /// Friction coefficient and stick slope (MPa/mm).
    pub friction: f64,
    pub stick_slope: f64,
    /// The capacity step's push of the shaft's end (mm, total displacement).
    pub push: f64,
}

/// The mesh's element counts: axial, shaft radial, hub radial.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    pub axial: usize,
    pub shaft: usize,
    pub hub: usize,
}

impl Layout {
    /// The layout at `refinement` (1 coarse, 2 fine): [`AXIAL_ELEMENTS`] times the refinement,
    /// more where the interface's decay length 1/lambda is short against L (at least 10
    /// elements over 1/lambda), [`RADIAL_ELEMENTS`] times it radially.
    pub fn at(refinement: usize, length_over_decay: f64) -> Layout {
        let resolve = (10.0 * length_over_decay / (1.0 + GRADING)).ceil();
        let axial = AXIAL_ELEMENTS.max(if resolve.is_finite() && resolve < 1e6 {
            resolve as usize
        } else {
            usize::MAX / 4
        });
        Layout {
            axial: axial.saturating_mul(refinement),
            shaft: RADIAL_ELEMENTS * refinement,
            hub: RADIAL_ELEMENTS * refinement,
        }
    }

    /// Elements of the deck.
    pub fn elements(&self) -> f64 {
        self.axial as f64 * (self.shaft + self.hub) as f64
    }
}

/// The axial breaks over [0, L]: x(t) = L (t - g sin(2 pi t) / (2 pi)), t = i / n, elements of
/// (1 - g) L/n at both faces and (1 + g) L/n in the middle.
pub fn axial_breaks(length: f64, n: usize) -> Vec<f64> {
    let tau = std::f64::consts::TAU;
    (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            length * (t - GRADING * (tau * t).sin() / tau)
        })
        .collect()
}

/// A CAX4 grid of one member: nodes (i along x, j along r) numbered from `first_node`,
/// elements from `first_element`.
struct Grid<'a> {
    xs: &'a [f64],
    rs: Vec<f64>,
    first_node: usize,
    first_element: usize,
}

impl Grid<'_> {
    fn node(&self, i: usize, j: usize) -> usize {
        self.first_node + i * self.rs.len() + j
    }

    fn element(&self, i: usize, j: usize) -> usize {
        self.first_element + i * (self.rs.len() - 1) + j
    }

    fn node_count(&self) -> usize {
        self.xs.len() * self.rs.len()
    }

    fn element_count(&self) -> usize {
        (self.xs.len() - 1) * (self.rs.len() - 1)
    }

    /// `*NODE` lines: (r, x).
    fn write_nodes(&self, deck: &mut String) {
        for (i, x) in self.xs.iter().enumerate() {
            for (j, r) in self.rs.iter().enumerate() {
                let _ = writeln!(deck, "{}, {}, {}", self.node(i, j), real(*r), real(*x));
            }
        }
    }

    /// CAX4 elements, counter-clockwise in the (r, x) plane: faces S1 at x_i, S2 at the outer
    /// radius, S3 at x_i+1, S4 at the inner radius.
    fn write_elements(&self, deck: &mut String, set: &str) {
        let _ = writeln!(deck, "*ELEMENT, TYPE=CAX4, ELSET={set}");
        for i in 0..self.xs.len() - 1 {
            for j in 0..self.rs.len() - 1 {
                let _ = writeln!(
                    deck,
                    "{}, {}, {}, {}, {}",
                    self.element(i, j),
                    self.node(i, j),
                    self.node(i, j + 1),
                    self.node(i + 1, j + 1),
                    self.node(i + 1, j)
                );
            }
        }
    }
}

fn uniform(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|j| from + (to - from) * j as f64 / n as f64)
        .collect()
}

/// The deck: `header` (comment lines), then the model, step 1 (the interference), one step per
/// load of `loads` (N, increasing) in increments of at most `force_step` N, and the capacity step.
///
/// # Errors
/// [`DeckTooLarge`] when `layout` has more than [`MAX_DECK_ELEMENTS`] elements.
pub fn fit_deck(
    inputs: &FitDeckInputs,
    loads: &[f64],
    layout: Layout,
    force_step: f64,
    header: &str,
) -> Result<String, DeckTooLarge> {
    if layout.elements() > MAX_DECK_ELEMENTS as f64 {
        return Err(DeckTooLarge {
            elements: layout.elements(),
            advice: format!(
                "the fit is {} decay lengths 1/lambda long and each takes 10 elements; use the \
                 coarse mesh, a smaller K_T or a shorter L",
                Compact(layout.axial as f64 / 10.0)
            ),
        });
    }
    let [r, ri, ro] = inputs.radii;
    let xs = axial_breaks(inputs.length, layout.axial);
    let shaft = Grid {
        xs: &xs,
        rs: uniform(ri, r + inputs.interference, layout.shaft),
        first_node: 1,
        first_element: 1,
    };
    let hub = Grid {
        xs: &xs,
        rs: uniform(r, ro, layout.hub),
        first_node: 1 + shaft.node_count(),
        first_element: 1 + shaft.element_count(),
    };
    let (na, ns) = (layout.axial, layout.shaft);
    let radial_size = ((r - ri) / ns as f64).min((ro - r) / layout.hub as f64);
    let normal = normal_stiffness(
        inputs.shaft.0.max(inputs.hub.0),
        radial_size,
        inputs.stick_slope,
    );

    let mut deck = header.to_string();
    let _ = writeln!(
        deck,
        "*HEADING\nmicroslip press fit (axisymmetric CAX4: r, then x), K_T = {} MPa/mm",
        Compact(inputs.stick_slope)
    );
    deck.push_str("*NODE, NSET=NALL\n");
    shaft.write_nodes(&mut deck);
    hub.write_nodes(&mut deck);
    shaft.write_elements(&mut deck, "SHAFT");
    hub.write_elements(&mut deck, "HUB");
    let end: Vec<usize> = (0..=ns).map(|j| shaft.node(0, j)).collect();
    write_nset(&mut deck, sets::SHAFT_END, &end);
    let held: Vec<usize> = (0..=layout.hub).map(|j| hub.node(na, j)).collect();
    write_nset(&mut deck, sets::HUB_HELD, &held);
    let shaft_face: Vec<usize> = (0..=na).map(|i| shaft.node(i, ns)).collect();
    write_nset(&mut deck, sets::SHAFT_FACE, &shaft_face);
    let hub_face: Vec<usize> = (0..=na).map(|i| hub.node(i, 0)).collect();
    write_nset(&mut deck, sets::HUB_FACE, &hub_face);
    write_nset(&mut deck, sets::SHAFT_FIX, &[shaft.node(na / 2, 0)]);
    deck.push_str("*SURFACE, NAME=SSHAFT, TYPE=ELEMENT\n");
    for i in 0..na {
        let _ = writeln!(deck, "{}, S2", shaft.element(i, ns - 1));
    }
    deck.push_str("*SURFACE, NAME=SHUB, TYPE=ELEMENT\n");
    for i in 0..na {
        let _ = writeln!(deck, "{}, S4", hub.element(i, 0));
    }
    let _ = writeln!(
        deck,
        "*SURFACE, NAME={}, TYPE=NODE\n{}",
        sets::NODE_SLAVE,
        sets::SHAFT_FACE
    );
    for (name, (modulus, poisson), set) in [
        ("SHAFTMAT", inputs.shaft, "SHAFT"),
        ("HUBMAT", inputs.hub, "HUB"),
    ] {
        let _ = writeln!(
            deck,
            "*MATERIAL, NAME={name}\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET={set}, MATERIAL={name}",
            real(modulus),
            real(poisson)
        );
    }
    write_interaction(&mut deck, normal, inputs.friction, inputs.stick_slope);
    let _ = writeln!(
        deck,
        "** contact formulation: surface-to-surface, the shaft's element faces as slave, the hub's\n\
         ** bore as master. CalculiX issue #98's node slave: replace the two lines below by\n\
         ** `{}` (the node surface {} is defined above)\n{SURFACE_PAIR}",
        NODE_SLAVE_PAIR.replace('\n', "` and `"),
        sets::NODE_SLAVE
    );
    let _ = writeln!(
        deck,
        "** the hub held axially on its far face x = L (free radially)\n*BOUNDARY\n{}, 2, 2",
        sets::HUB_HELD
    );

    // The `.dat` at each step's end only (CalculiX always prints a step's last increment): the
    // reader reads nothing else, and every increment's contact stresses made the coarse run's
    // `.dat` 12 MB instead of 0.5 MB.
    let outputs = |deck: &mut String| {
        for set in [sets::SHAFT_END, sets::SHAFT_FACE, sets::HUB_FACE] {
            let _ = writeln!(deck, "*NODE PRINT, NSET={set}, FREQUENCY={STEP_END}\nU");
        }
        let _ = writeln!(
            deck,
            "*NODE PRINT, NSET={}, TOTALS=ONLY, FREQUENCY={STEP_END}\nRF\n\
             *CONTACT PRINT, FREQUENCY={STEP_END}\nCSTR\n*NODE FILE\nU\n\
             *CONTACT FILE\nCDIS, CSTR\n*END STEP",
            sets::HUB_HELD
        );
    };
    // CalculiX reads at most 20 characters per field: 1e-5 mu is written with 7 digits.
    let friction_line = |deck: &mut String, mu: &str| {
        let _ = writeln!(
            deck,
            "*CHANGE FRICTION, INTERACTION=JENKINS\n*FRICTION\n{mu}, {}",
            real(inputs.stick_slope)
        );
    };
    let _ = writeln!(
        deck,
        "** step 1: the interference delta = {} mm resolved with friction {} mu (a shrink fit leaves\n\
         ** no shear), one shaft node held axially",
        Compact(inputs.interference),
        Compact(ASSEMBLY_FRICTION)
    );
    start_step(&mut deck, 1.0, Geometry::Linear);
    friction_line(
        &mut deck,
        &format!("{:.6e}", ASSEMBLY_FRICTION * inputs.friction),
    );
    let _ = writeln!(deck, "*BOUNDARY\n{}, 2, 2", sets::SHAFT_FIX);
    outputs(&mut deck);
    let area = std::f64::consts::PI * ((r + inputs.interference).powi(2) - ri * ri);
    let released = |deck: &mut String| {
        let _ = writeln!(deck, "*BOUNDARY, OP=NEW\n{}, 2, 2", sets::HUB_HELD);
    };
    let mut from = 0.0;
    for (n, &force) in loads.iter().enumerate() {
        crate::numeric::cancel::checkpoint();
        let _ = writeln!(
            deck,
            "** step {}: F = {} N on the shaft's end face x = 0 (the traction F / As), increments of \
             at most {} N",
            n + 2,
            Compact(force),
            Compact(force_step)
        );
        start_step(
            &mut deck,
            LoadPath::increment(force_step, 0.0, from, force),
            Geometry::Linear,
        );
        released(&mut deck);
        if n == 0 {
            friction_line(&mut deck, &real(inputs.friction));
        }
        deck.push_str("*DLOAD\n");
        for j in 0..ns {
            let _ = writeln!(deck, "{}, P1, {}", shaft.element(0, j), real(force / area));
        }
        outputs(&mut deck);
        from = force;
    }
    let _ = writeln!(
        deck,
        "** step {}: the capacity: the shaft's end face pushed to u_x = {} mm (the traction off);\n\
         ** the hub's reaction on x = L is the push-out force",
        loads.len() + 2,
        Compact(inputs.push)
    );
    start_step(
        &mut deck,
        1.0 / CAPACITY_INCREMENTS as f64,
        Geometry::Linear,
    );
    released(&mut deck);
    let _ = writeln!(deck, "{}, 2, 2, {}", sets::SHAFT_END, real(inputs.push));
    if loads.is_empty() {
        friction_line(&mut deck, &real(inputs.friction));
    }
    deck.push_str("*DLOAD, OP=NEW\n");
    outputs(&mut deck);
    Ok(deck)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_axial_breaks_are_finer_at_both_faces() {
        let xs = axial_breaks(10.0, 40);
        assert_eq!(xs.len(), 41);
        assert!(xs[0] == 0.0 && (xs[40] - 10.0).abs() < 1e-12);
        let sizes: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
        let mean = 10.0 / 40.0;
        assert!(
            (sizes[0] / mean - (1.0 - GRADING)).abs() < 0.01,
            "{}",
            sizes[0]
        );
        assert!((sizes[39] / mean - (1.0 - GRADING)).abs() < 0.01);
        assert!(
            (sizes[20] / mean - (1.0 + GRADING)).abs() < 0.01,
            "{}",
            sizes[20]
        );
        // Symmetric about the middle.
        for i in 0..20 {
            assert!((sizes[i] - sizes[39 - i]).abs() < 1e-12);
        }
    }
}
