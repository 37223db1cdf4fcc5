//! CalculiX input decks (Abaqus keyword syntax) for the two benchmarks.
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
//! A deck is plain text built in memory: deterministic bytes for the same inputs, no I/O. Its first
//! lines carry a machine-readable header ([`DeckHeader`]) that `microslip compare` reads back, so
//! that results are compared with the parameters that produced them.

use std::fmt::Write as _;

use thiserror::Error;

use super::header::{DeckHeader, StickSlope};
use super::mesh::{Block, Face, graded_toward_end, graded_toward_end_count, uniform};
use crate::kernel::params::Compact;
use crate::{SqueezedPlate, TipForce, TwinBeams};

/// How fine the deck's mesh is. `Fine` halves every element size of `Coarse`: running both is the
/// mesh-convergence check (docs/guide.md, "Benchmark your FE code").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DeckMesh {
    /// About 100 elements along the beam and 2 through each beam's height; 4 through the plate.
    #[default]
    Coarse,
    /// Every element size halved.
    Fine,
}

impl DeckMesh {
    /// The name used in headers and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            DeckMesh::Coarse => "coarse",
            DeckMesh::Fine => "fine",
        }
    }

    /// 1 for coarse, 2 for fine: the number of elements per coarse element along each direction.
    pub(crate) fn refinement(self) -> usize {
        match self {
            DeckMesh::Coarse => 1,
            DeckMesh::Fine => 2,
        }
    }
}

/// Names of the node sets the decks print to the .dat file; [`super::results`] looks them up.
pub(crate) mod sets {
    /// Tip nodes on the centre line of both beams (w(L) is their mean transverse displacement).
    pub(crate) const BEAM_TIP: &str = "WTIP";
    /// Lower beam's interface nodes along x (at z = 0).
    pub(crate) const BEAM_LOWER_FACE: &str = "IFLOWER";
    /// Upper beam's interface nodes along x (at z = 0); they start where `IFLOWER`'s are.
    pub(crate) const BEAM_UPPER_FACE: &str = "IFUPPER";
    /// Plate end nodes through the thickness (x = L, z = 0), from the contact face up.
    pub(crate) const PLATE_END: &str = "UEND";
    /// Plate contact-face nodes along x (y = 0, z = 0): the slip, since the plane does not move.
    pub(crate) const PLATE_FACE: &str = "IFPLATE";
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

/// The grading along the beams: (finest at the clamp, coarsest, growth ratio), mm.
///
/// Elements a fifth of a beam's height, graded down to 1/80 of it at the clamp, where the clamped
/// face meets the interface and stresses are singular. A uniform mesh of the same size left w(L)
/// 0.4 % too stiff, converging slowly (docs/theory.md, "Benchmarking an FE code"); two quadratic
/// elements through each beam's height carry its bending exactly.
fn beam_grading(beams: &TwinBeams, mesh: DeckMesh) -> (f64, f64, f64) {
    let height = 2.0 * beams.params().half_height;
    let r = mesh.refinement() as f64;
    (height / 80.0 / r, height / 5.0 / r, 1.2)
}

/// The number of elements of the beam deck (two blocks, `2 r` elements through each beam's
/// height, one across the width), counted without building it.
fn beam_element_count(beams: &TwinBeams, mesh: DeckMesh) -> f64 {
    let (finest, coarsest, ratio) = beam_grading(beams, mesh);
    let along = graded_toward_end_count(0.0, beams.params().length, finest, coarsest, ratio);
    2.0 * along * (2 * mesh.refinement()) as f64
}

/// Refuses a beam deck over [`MAX_DECK_ELEMENTS`], with the slenderness that would fit.
fn check_beam_size(beams: &TwinBeams, mesh: DeckMesh) -> Result<(), DeckTooLarge> {
    let elements = beam_element_count(beams, mesh);
    if elements <= MAX_DECK_ELEMENTS as f64 {
        return Ok(());
    }
    let p = beams.params();
    let slenderness = p.length / p.half_height;
    let count_at = |ratio: f64| {
        let params = crate::TwinBeamsParams {
            half_height: p.length / ratio,
            ..p
        };
        TwinBeams::new(params).map_or(f64::INFINITY, |b| beam_element_count(&b, mesh))
    };
    let (mut fits, mut too_many) = (1.0_f64, slenderness);
    for _ in 0..60 {
        let mid = (fits * too_many).sqrt();
        if count_at(mid) <= MAX_DECK_ELEMENTS as f64 {
            fits = mid;
        } else {
            too_many = mid;
        }
    }
    let finer = match mesh {
        DeckMesh::Fine => "use --mesh coarse (4 times fewer elements) or ",
        DeckMesh::Coarse => "",
    };
    Err(DeckTooLarge {
        elements,
        advice: format!(
            "elements along the beams are h/5 long, so the count grows with L/h = {} (L = {} mm, \
             h = {} mm); {finer}choose beams with L/h below about {}",
            Compact(slenderness),
            Compact(p.length),
            Compact(p.half_height),
            Compact(fits.floor()),
        ),
    })
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

    /// The force step (N) for `beams` (K_T = the deck's stick slope).
    pub fn force_step(self, beams: &TwinBeams) -> f64 {
        self.force_step
            .unwrap_or_else(|| Self::DEFAULT_FRACTION * beams.first_macroslip_force())
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

/// The twin-beam deck: the pressure P in a first step, then one step per tip force in `loads`
/// (N on each beam, increasing), each printed at its end, on the default load path.
///
/// Every step is `NLGEOM`. CalculiX's contact always works on the deformed faces; with linear
/// geometry the pressure on the outer faces keeps its direction while the beams rotate by
/// theta = w', so in the beams' frame it carries an axial traction P theta on each outer face, an
/// extra "friction" that beam theory does not have. Against mu P it is theta / mu: at macroslip
/// onset of h/L = 1/30, mu P = 1.5 MPa it made CalculiX 1 % stiffer than Timoshenko, whatever mu
/// (docs/theory.md, "How the decks are built"). With `NLGEOM` the pressure follows the faces, as
/// the closed forms assume; what remains of large rotations is of order theta^2.
///
/// # Errors
/// [`DeckTooLarge`] when the mesh would have more than [`MAX_DECK_ELEMENTS`] elements (very
/// slender beams).
pub fn beam_deck(
    beams: &TwinBeams,
    loads: &[TipForce],
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> Result<String, DeckTooLarge> {
    beam_deck_on_path(beams, loads, mesh, stick_slope, LoadPath::default())
}

/// [`beam_deck`] with the load path `path`.
///
/// # Errors
/// As [`beam_deck`].
pub fn beam_deck_on_path(
    beams: &TwinBeams,
    loads: &[TipForce],
    mesh: DeckMesh,
    stick_slope: StickSlope,
    path: LoadPath,
) -> Result<String, DeckTooLarge> {
    check_beam_size(beams, mesh)?;
    let p = beams.params();
    let poisson = p.poisson;
    let slope = stick_slope.value_for_beams(beams);
    let header = DeckHeader::beams(beams, loads, mesh, stick_slope);
    let r = mesh.refinement();
    let height = 2.0 * p.half_height;
    let (finest, coarsest, ratio) = beam_grading(beams, mesh);
    let from_clamp = graded_toward_end(0.0, p.length, finest, coarsest, ratio);
    let mut xs: Vec<f64> = from_clamp.iter().rev().map(|x| p.length - x).collect();
    xs[0] = 0.0;
    let through = 2 * r;
    let zs = uniform(0.0, p.width, 1);
    let lower = Block::new(
        [xs.clone(), uniform(-height, 0.0, through), zs.clone()],
        1,
        1,
    );
    let upper = Block::new(
        [xs, uniform(0.0, height, through), zs],
        lower.node_count() + 1,
        lower.element_count() + 1,
    );
    let normal_slope = normal_stiffness(p.youngs_modulus, height / through as f64, slope);

    let mut deck = header.to_comment();
    deck.push_str("*HEADING\n");
    let _ = writeln!(
        deck,
        "microslip twin beams, K_T = {} MPa/mm",
        Compact(slope)
    );
    write_nodes(&mut deck, &[&lower, &upper]);
    write_elements(&mut deck, "LOWER", &lower);
    write_elements(&mut deck, "UPPER", &upper);

    let [nx, ny, _] = lower.elements_along();
    let mut clamp = lower.nodes_at_x(0);
    clamp.extend(upper.nodes_at_x(0));
    write_nset(&mut deck, "CLAMP", &clamp);
    // Centre line of each beam: half-grid row ny (mid-height), on both side faces.
    let tip: Vec<usize> = [&lower, &upper]
        .iter()
        .flat_map(|b| [0, 2].map(|k| b.node([2 * nx, ny, k])))
        .flatten()
        .collect();
    write_nset(&mut deck, sets::BEAM_TIP, &tip);
    let face_line = |b: &Block, j: usize| -> Vec<usize> {
        (0..=2 * nx).filter_map(|i| b.node([i, j, 0])).collect()
    };
    write_nset(&mut deck, sets::BEAM_LOWER_FACE, &face_line(&lower, 2 * ny));
    write_nset(&mut deck, sets::BEAM_UPPER_FACE, &face_line(&upper, 0));
    write_surface(
        &mut deck,
        "SLOWERTOP",
        &lower.boundary_faces(Face::YMax),
        Face::YMax,
    );
    write_surface(
        &mut deck,
        "SUPPERBOT",
        &upper.boundary_faces(Face::YMin),
        Face::YMin,
    );

    write_material(&mut deck, p.youngs_modulus, poisson, &["LOWER", "UPPER"]);
    write_interaction(&mut deck, normal_slope, p.friction, slope);
    write_contact_pair(
        &mut deck,
        "upper beam's lower face",
        "lower beam's upper face",
        ["SUPPERBOT", "SLOWERTOP"],
    );
    deck.push_str("*BOUNDARY\nCLAMP, 1, 3\n");

    // A near-Coulomb slope beyond K_T's accepted range: F_1 is F_thre there to many digits.
    let at_slope = beams.with_tangential_stiffness(slope).unwrap_or(*beams);
    let onset = at_slope.first_macroslip_force();
    let force_step = path.force_step(&at_slope);
    let _ = writeln!(
        deck,
        "** load path: steps ending beyond F_1 = {} N (at this stick slope) in increments of at most\n\
         ** {} N of tip force beyond F_1 (friction is path-dependent once it saturates), a step that\n\
         ** crosses F_1 reaching it in its first increment (the law is linear below); the others in one",
        Compact(onset),
        Compact(force_step)
    );
    // Steps that cross F_1: their loads follow an amplitude that reaches F_1 in one increment
    // (CalculiX reads amplitudes in the model definition, before the first step).
    let newtons: Vec<f64> = loads.iter().map(|f| f.newtons()).collect();
    let steps = load_steps(&mut deck, &newtons, force_step, onset);
    deck.push_str("** step 1: the interface pressure P, pressing the beams together\n");
    start_step(&mut deck, 1.0, Geometry::Nonlinear);
    write_pressure(
        &mut deck,
        &[(&lower, Face::YMin), (&upper, Face::YMax)],
        p.pressure,
    );
    end_beam_step(&mut deck);
    for (n, (force, (increment, amplitude))) in loads.iter().zip(steps).enumerate() {
        let _ = writeln!(
            deck,
            "** step {}: tip force F = {} N on each beam (uniform shear traction on the end face)",
            n + 2,
            Compact(force.newtons())
        );
        start_step(&mut deck, increment, Geometry::Nonlinear);
        write_cload(&mut deck, amplitude.as_deref());
        for block in [&lower, &upper] {
            for (id, f) in block.end_face_loads(force.newtons()) {
                let _ = writeln!(deck, "{id}, 2, {}", real(f));
            }
        }
        end_beam_step(&mut deck);
    }
    Ok(deck)
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
    match amplitude {
        Some(name) => {
            let _ = writeln!(deck, "*CLOAD, AMPLITUDE={name}");
        }
        None => deck.push_str("*CLOAD\n"),
    }
}

/// The grading along the plate: (finest at the free end, coarsest, growth ratio), mm.
fn plate_grading(plate: &SqueezedPlate, mesh: DeckMesh, slope: f64) -> (f64, f64, f64) {
    let p = plate.params();
    let r = mesh.refinement() as f64;
    let layer = p.thickness / (4.0 * r);
    // The slip zone at the free end is about 1/alpha wide (L - X_r <= l and X_r - X_s -> 1/alpha):
    // elements a tenth of that at the end, or half a layer if smaller (the contact face corner at
    // the free end is where the displacement varies most)...
    let alpha_squared = (1.0 - p.poisson * p.poisson) * slope / (p.youngs_modulus * p.thickness);
    let finest = (0.1 / alpha_squared.sqrt()).min(0.5 * layer) / r;
    // ...growing by 20 % per element to half the thickness, or L/50 on a long plate.
    let coarsest = (p.thickness / (2.0 * r))
        .max(p.half_length / (50.0 * r))
        .max(finest);
    (finest, coarsest, 1.2)
}

/// The number of elements of the plate deck, counted without building it: `4 r` layers through
/// the plate, and the base block under it, one element thick and one element longer.
fn plate_element_count(plate: &SqueezedPlate, mesh: DeckMesh, slope: f64) -> f64 {
    let (finest, coarsest, ratio) = plate_grading(plate, mesh, slope);
    let along = graded_toward_end_count(0.0, plate.params().half_length, finest, coarsest, ratio);
    along * (4 * mesh.refinement()) as f64 + along + 1.0
}

/// The squeezed-plate deck: one step that applies P; the plate's end and contact face are printed.
///
/// # Errors
/// [`DeckTooLarge`] when the mesh would have more than [`MAX_DECK_ELEMENTS`] elements. The
/// grading keeps a plate deck to a few thousand elements over the whole accepted domain (at most
/// 50 per refinement level along L plus a logarithmic grading), so this is a guard, not a limit
/// users meet.
pub fn plate_deck(
    plate: &SqueezedPlate,
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> Result<String, DeckTooLarge> {
    let p = plate.params();
    let slope = stick_slope.value_for_plate(plate);
    let header = DeckHeader::plate(plate, mesh, stick_slope);
    let through = 4 * mesh.refinement();
    let layer = p.thickness / through as f64;
    let (finest, coarsest, ratio) = plate_grading(plate, mesh, slope);
    let elements = plate_element_count(plate, mesh, slope);
    if elements > MAX_DECK_ELEMENTS as f64 {
        return Err(DeckTooLarge {
            elements,
            advice: "the plate's mesh is graded toward its free end; report this case".into(),
        });
    }
    let xs = graded_toward_end(0.0, p.half_length, finest, coarsest, ratio);
    let width = layer;
    let zs = vec![0.0, width];
    let plate_block = Block::new(
        [xs.clone(), uniform(0.0, p.thickness, through), zs.clone()],
        1,
        1,
    );
    // The rigid plane: a fixed block under the plate, one coarse element longer than it.
    let mut base_xs = xs;
    base_xs.push(p.half_length + coarsest);
    let base = Block::new(
        [base_xs, vec![-p.thickness, 0.0], zs],
        plate_block.node_count() + 1,
        plate_block.element_count() + 1,
    );
    let normal_slope = normal_stiffness(p.youngs_modulus, layer, slope);

    let mut deck = header.to_comment();
    deck.push_str("*HEADING\n");
    let _ = writeln!(
        deck,
        "microslip squeezed plate, K_T = {} MPa/mm",
        Compact(slope)
    );
    write_nodes(&mut deck, &[&plate_block, &base]);
    // Ground nodes for the weak springs, one plate thickness below the block.
    let ground = plate_block.node_count() + base.node_count() + 1;
    let corners = [0, 2].map(|k| plate_block.node([0, 0, k]).expect("a corner is a node"));
    for (n, _) in corners.iter().enumerate() {
        let _ = writeln!(
            deck,
            "{}, 0., {}, {}",
            ground + n,
            real(-2.0 * p.thickness),
            real(width * n as f64)
        );
    }
    write_elements(&mut deck, "PLATE", &plate_block);
    write_elements(&mut deck, "BASE", &base);
    let spring = plate_block.element_count() + base.element_count() + 1;
    deck.push_str(
        "** weak springs: face-to-face contact engages only once the plate penetrates, so the\n\
         ** plate would float at the first iteration; they carry a negligible share of the load\n\
         *ELEMENT, TYPE=SPRINGA, ELSET=ESPRING\n",
    );
    for (n, node) in corners.iter().enumerate() {
        let _ = writeln!(deck, "{}, {}, {}", spring + n, node, ground + n);
    }
    // Stiffness: a millionth of the contact's over the whole face.
    let spring_stiffness = 1e-6 * normal_slope * p.half_length * width;
    let _ = writeln!(deck, "*SPRING, ELSET=ESPRING\n\n{}", real(spring_stiffness));

    let [nx, ny, _] = plate_block.elements_along();
    write_nset(&mut deck, "SYMMETRY", &plate_block.nodes_at_x(0));
    let all_plate: Vec<usize> = plate_block.nodes().map(|(id, _)| id).collect();
    write_nset(&mut deck, "PLATEALL", &all_plate);
    let mut fixed: Vec<usize> = base.nodes().map(|(id, _)| id).collect();
    fixed.extend([ground, ground + 1]);
    write_nset(&mut deck, "FIXED", &fixed);
    let end: Vec<usize> = (0..=2 * ny)
        .filter_map(|j| plate_block.node([2 * nx, j, 0]))
        .collect();
    write_nset(&mut deck, sets::PLATE_END, &end);
    let face: Vec<usize> = (0..=2 * nx)
        .filter_map(|i| plate_block.node([i, 0, 0]))
        .collect();
    write_nset(&mut deck, sets::PLATE_FACE, &face);
    write_surface(
        &mut deck,
        "SPLATEBOT",
        &plate_block.boundary_faces(Face::YMin),
        Face::YMin,
    );
    write_surface(
        &mut deck,
        "SBASETOP",
        &base.boundary_faces(Face::YMax),
        Face::YMax,
    );

    write_material(&mut deck, p.youngs_modulus, p.poisson, &["PLATE", "BASE"]);
    write_interaction(&mut deck, normal_slope, p.friction, slope);
    write_contact_pair(
        &mut deck,
        "the plate's lower face",
        "the fixed block's upper face",
        ["SPLATEBOT", "SBASETOP"],
    );
    deck.push_str(
        "** symmetry at x = 0, plane strain (no node moves across the width), fixed plane\n\
         *BOUNDARY\nSYMMETRY, 1, 1\nPLATEALL, 3, 3\nFIXED, 1, 3\n",
    );
    // One increment: the plate's problem is homogeneous of degree one in P (slip, traction and
    // mu p all scale with it), so every point's history is a ramp and the path cannot matter.
    deck.push_str("** step 1: the pressure P on the plate's upper face\n");
    start_step(&mut deck, 1.0, Geometry::Linear);
    write_pressure(&mut deck, &[(&plate_block, Face::YMax)], p.pressure);
    for set in [sets::PLATE_END, sets::PLATE_FACE] {
        let _ = writeln!(deck, "*NODE PRINT, NSET={set}\nU");
    }
    deck.push_str("*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n");
    Ok(deck)
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

fn end_beam_step(deck: &mut String) {
    for set in [sets::BEAM_TIP, sets::BEAM_LOWER_FACE, sets::BEAM_UPPER_FACE] {
        let _ = writeln!(deck, "*NODE PRINT, NSET={set}\nU");
    }
    deck.push_str("*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n");
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
fn write_pressure(deck: &mut String, faces: &[(&Block, Face)], pressure: f64) {
    deck.push_str("*DLOAD\n");
    for &(block, face) in faces {
        for id in block.boundary_faces(face) {
            let _ = writeln!(deck, "{id}, P{}, {}", face.number(), real(pressure));
        }
    }
}

fn write_material(deck: &mut String, modulus: f64, poisson: f64, sets: &[&str]) {
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

/// A number as CalculiX must read it: shortest round-trip digits, always with a decimal point
/// (some cards read an integer-looking first field as a degree of freedom).
pub(crate) fn real(x: f64) -> String {
    let text = format!("{x:?}");
    match text.find('e') {
        Some(e) if !text[..e].contains('.') => format!("{}.{}", &text[..e], &text[e..]),
        _ => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{PlateParams, TwinBeamsParams};

    fn paper_beam_deck(mesh: DeckMesh) -> String {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let loads = [40.0, 100.0].map(|f| TipForce::new(f).unwrap());
        beam_deck(&beams, &loads, mesh, StickSlope::Model).unwrap()
    }

    /// Elements in a written deck: the lines of its `*ELEMENT` cards, springs excluded.
    fn elements_written(deck: &str) -> usize {
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

    #[test]
    fn the_counted_size_is_the_written_size() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        for mesh in [DeckMesh::Coarse, DeckMesh::Fine] {
            assert_eq!(
                beam_element_count(&beams, mesh),
                elements_written(&paper_beam_deck(mesh)) as f64
            );
            let counted =
                plate_element_count(&plate, mesh, StickSlope::Model.value_for_plate(&plate));
            let deck = plate_deck(&plate, mesh, StickSlope::Model).unwrap();
            assert_eq!(counted, elements_written(&deck) as f64);
        }
    }

    /// `h = 1e-6` used to abort on a 20 TB allocation; `L = 1e6` wrote 574 MB.
    #[test]
    fn a_deck_too_large_is_refused_with_its_count_the_limit_and_a_way_out() {
        let loads = [TipForce::new(1.0).unwrap()];
        for (length, half_height) in [(200.0, 1e-6), (1e6, 10.0), (200.0, 1e-3)] {
            let params = TwinBeamsParams {
                length,
                half_height,
                ..TwinBeamsParams::PAPER
            };
            let beams = TwinBeams::new(params).unwrap();
            for mesh in [DeckMesh::Coarse, DeckMesh::Fine] {
                let refused = beam_deck(&beams, &loads, mesh, StickSlope::Model).unwrap_err();
                assert!(refused.elements > MAX_DECK_ELEMENTS as f64);
                let message = refused.to_string();
                assert!(message.contains("more than the 20000"), "{message}");
                assert!(message.contains("L/h below about"), "{message}");
            }
        }
        // The advice holds: beams at the slenderness it names fit.
        let params = TwinBeamsParams {
            half_height: 1e-3,
            ..TwinBeamsParams::PAPER
        };
        let refused = beam_deck(
            &TwinBeams::new(params).unwrap(),
            &loads,
            DeckMesh::Coarse,
            StickSlope::Model,
        )
        .unwrap_err();
        let fits: f64 = refused.advice.rsplit(' ').next().unwrap().parse().unwrap();
        let params = TwinBeamsParams {
            half_height: params.length / fits,
            ..TwinBeamsParams::PAPER
        };
        let beams = TwinBeams::new(params).unwrap();
        assert!(beam_deck(&beams, &loads, DeckMesh::Coarse, StickSlope::Model).is_ok());
        let params = TwinBeamsParams {
            half_height: params.length / (1.05 * fits),
            ..TwinBeamsParams::PAPER
        };
        let beams = TwinBeams::new(params).unwrap();
        assert!(beam_deck(&beams, &loads, DeckMesh::Coarse, StickSlope::Model).is_err());
    }

    #[test]
    fn numbers_always_carry_a_decimal_point() {
        assert_eq!(real(200.0), "200.0");
        assert_eq!(real(0.1), "0.1");
        assert_eq!(real(1e-7), "1.e-7");
        assert_eq!(real(-2.5e20), "-2.5e20");
    }

    #[test]
    fn the_same_inputs_give_the_same_bytes() {
        assert_eq!(
            paper_beam_deck(DeckMesh::Coarse),
            paper_beam_deck(DeckMesh::Coarse)
        );
    }

    #[test]
    fn beam_deck_has_one_step_per_load_after_the_pressure() {
        let deck = paper_beam_deck(DeckMesh::Coarse);
        assert_eq!(deck.matches("*STEP").count(), 3);
        assert_eq!(deck.matches("*END STEP").count(), 3);
        assert!(
            deck.contains("*FRICTION\n0.3, 600.0\n"),
            "stick slope = K_T"
        );
        assert!(deck.contains("*ELASTIC\n210000.0, 0.3\n"));
    }

    #[test]
    fn steps_beyond_macroslip_onset_are_cut_into_force_steps() {
        // Below F_1 (or a step that does not rise) one increment; beyond, step / (to - from),
        // clamped to [1e-3, 1].
        assert_eq!(LoadPath::increment(2.0, 100.0, 40.0, 100.0), 1.0);
        assert_eq!(LoadPath::increment(2.0, 100.0, 100.0, 100.0), 1.0);
        assert!((LoadPath::increment(2.0, 100.0, 80.0, 120.0) - 0.05).abs() < 1e-15);
        assert_eq!(LoadPath::increment(50.0, 100.0, 80.0, 120.0), 1.0);
        assert_eq!(LoadPath::increment(1e-6, 100.0, 80.0, 120.0), 1e-3);
        // A ramp only for a step that crosses F_1 and needs more than one increment.
        assert_eq!(LoadPath::ramp(2.0, 100.0, 40.0, 90.0), None);
        assert_eq!(LoadPath::ramp(2.0, 100.0, 100.0, 120.0), None);
        assert_eq!(LoadPath::ramp(80.0, 100.0, 40.0, 120.0), None);
        let (t1, points) = LoadPath::ramp(2.0, 100.0, 40.0, 120.0).unwrap();
        assert!((t1 - 2.0 / 22.0).abs() < 1e-15);
        assert_eq!(
            points,
            [(0.0, 40.0 / 120.0), (t1, 100.0 / 120.0), (1.0, 1.0)]
        );
        assert_eq!(LoadPath::ramp(1e-6, 100.0, 40.0, 120.0).unwrap().0, 1e-3);
        // The paper's beams: F_1 = F_thre / (1 - sech kL) with F_thre = 80 N; the default step is
        // F_1 / 40.
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let default = LoadPath::default().force_step(&beams);
        assert!((default - beams.first_macroslip_force() / 40.0).abs() < 1e-12);
        let given = LoadPath {
            force_step: Some(3.0),
        };
        assert_eq!(given.force_step(&beams), 3.0);
    }

    #[test]
    fn beam_steps_are_nonlinear_and_fine_beyond_onset() {
        // F_1 of the paper's beams is about 80 N: the 40 N step keeps one increment; the step
        // from 40 to 100 N reaches F_1 in its first increment (an amplitude), then goes on by
        // at most 2 N; the step from 100 to 120 N starts beyond F_1: 2 N increments, 1/10 of it.
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let onset = beams.first_macroslip_force();
        let loads = [40.0, 100.0, 120.0].map(|f| TipForce::new(f).unwrap());
        let path = LoadPath {
            force_step: Some(2.0),
        };
        let deck =
            beam_deck_on_path(&beams, &loads, DeckMesh::Coarse, StickSlope::Model, path).unwrap();
        assert_eq!(
            deck.matches("*STEP, NLGEOM, INC=1000\n*STATIC\n1., 1.\n")
                .count(),
            2
        );
        let amplitude = deck
            .split("*AMPLITUDE, NAME=RAMP3\n")
            .nth(1)
            .unwrap()
            .lines()
            .next()
            .unwrap();
        let points: Vec<f64> = amplitude.split(", ").map(|v| v.parse().unwrap()).collect();
        let t1 = points[2];
        assert_eq!([points[0], points[1]], [0.0, 0.4], "{amplitude}");
        assert!((points[3] - onset / 100.0).abs() < 1e-15, "{amplitude}");
        assert_eq!([points[4], points[5]], [1.0, 1.0]);
        // Each later increment of step time t1 adds (100 - F_1) t1 / (1 - t1): 2 N.
        assert!(((100.0 - onset) * t1 / (1.0 - t1) - 2.0).abs() < 1e-9);
        let line = format!("{t1:.9e}, 1., {:.9e}, {t1:.9e}", t1 * 1e-3);
        assert_eq!(deck.matches(&line).count(), 1, "{line}");
        assert_eq!(deck.matches("*CLOAD, AMPLITUDE=RAMP3\n").count(), 1);
        assert_eq!(
            deck.matches("AMPLITUDE").count(),
            2,
            "one ramp, defined once"
        );
        let line = "1.000000000e-1, 1., 1.000000000e-4, 1.000000000e-1";
        assert_eq!(deck.matches(line).count(), 1, "{line}");
        // Amplitudes belong to the model definition: before the first step.
        assert!(deck.find("*AMPLITUDE").unwrap() < deck.find("*STEP").unwrap());
        // The plate keeps one linear increment: its problem scales with P.
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let plate = plate_deck(&plate, DeckMesh::Coarse, StickSlope::Model).unwrap();
        assert!(plate.contains("*STEP, INC=1000\n*STATIC\n1., 1.\n"));
        assert!(!plate.contains("NLGEOM"));
    }

    #[test]
    fn tip_loads_add_up_to_the_force_on_each_beam() {
        let deck = paper_beam_deck(DeckMesh::Coarse);
        // The step of F = 100 N crosses F_1: its loads follow an amplitude, ending at 1.
        let step = deck.split("*CLOAD").nth(2).unwrap();
        assert!(step.starts_with(", AMPLITUDE=RAMP"), "{}", &step[..40]);
        let step = step.split_once('\n').unwrap().1;
        let total: f64 = step
            .lines()
            .take_while(|l| !l.starts_with('*'))
            .map(|l| l.split(", ").nth(2).unwrap().parse::<f64>().unwrap())
            .sum();
        assert!(
            (total - 200.0).abs() < 1e-9,
            "two beams x 100 N, got {total}"
        );
    }

    #[test]
    fn fine_mesh_has_about_four_times_the_elements() {
        let count = |deck: &str| {
            deck.split("*ELEMENT, TYPE=C3D20R")
                .skip(1)
                .map(|s| {
                    s.lines()
                        .skip(1)
                        .take_while(|l| !l.starts_with('*'))
                        .count()
                        / 2
                })
                .sum::<usize>()
        };
        // Every size halved along x and y (the grading toward the clamp rounds the count), one
        // element across the width in both.
        let ratio = count(&paper_beam_deck(DeckMesh::Fine)) as f64
            / count(&paper_beam_deck(DeckMesh::Coarse)) as f64;
        assert!((3.5..4.5).contains(&ratio), "{ratio}");
    }

    #[test]
    fn plate_deck_resolves_the_slip_zone() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let deck = plate_deck(&plate, DeckMesh::Coarse, StickSlope::Model).unwrap();
        assert!(deck.contains("*FRICTION\n0.3, 1000000.0\n"));
        // The nodes of the contact face, in x order: the last two are 1/(4 alpha) apart at most.
        let xs: Vec<f64> = node_x_of_set(&deck, sets::PLATE_FACE);
        let last = xs[xs.len() - 1] - xs[xs.len() - 3];
        let alpha = plate.decay_rate();
        assert!(
            last <= 0.1 / alpha + 1e-12,
            "end element {last} mm, 1/alpha {}",
            1.0 / alpha
        );
        assert_eq!(*xs.last().unwrap(), 10.0);
    }

    fn node_x_of_set(deck: &str, set: &str) -> Vec<f64> {
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
