//! The squeezed plate's FE deck ([`Deck`]): the CalculiX deck of a plate pressed on a rigid
//! plane and the header lines it expects; the point a run gives is read in `fe_points.rs` and
//! compared with the closed forms in `compare.rs`.

use std::fmt::Write as _;

use crate::fe::continuum_verdict::ContinuumJudged;
use crate::fe::deck::{
    DeckMesh, DeckTooLarge, Geometry, MAX_DECK_ELEMENTS, normal_stiffness, real, start_step,
    write_contact_pair, write_elements, write_interaction, write_material, write_nodes, write_nset,
    write_pressure, write_surface,
};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::{DeckHeader, StickSlope};
use crate::fe::mesh::{Block, Face, graded_toward_end, graded_toward_end_count, uniform};
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::format::number;
use crate::kernel::params::Compact;
use crate::problems::Problem;

use super::closed_form::SqueezedPlate;
use super::compare::PlateCompared;
use super::fe_points::PlateFePoint;
use super::params::PlateParams;
use super::problem::SqueezedPlateProblem;

/// Names of the node sets the deck prints to the .dat file, which the reader looks up.
pub(crate) mod sets {
    /// Plate end nodes through the thickness (x = L, z = 0), from the contact face up.
    pub(crate) const PLATE_END: &str = "UEND";
    /// Plate contact-face nodes along x (y = 0, z = 0): the slip, since the plane does not move.
    pub(crate) const PLATE_FACE: &str = "IFPLATE";
}

/// The stick slope (MPa/mm) a deck of `plate` gives CalculiX: the model's K_T, or near Coulomb a
/// boundary layer a tenth of the thickness (1/alpha = t_p/10).
pub fn stick_slope_of(stick_slope: StickSlope, plate: &SqueezedPlate) -> f64 {
    let p = plate.params();
    match stick_slope {
        StickSlope::Model => p.tangential_stiffness,
        StickSlope::NearCoulomb => {
            100.0 * p.youngs_modulus / ((1.0 - p.poisson * p.poisson) * p.thickness)
        }
    }
}

/// The header of a squeezed-plate deck: K_T is the deck's stick slope; no loads (P alone).
pub fn header(plate: &SqueezedPlate, mesh: DeckMesh, stick_slope: StickSlope) -> DeckHeader {
    let mut params = plate.params();
    params.tangential_stiffness = stick_slope_of(stick_slope, plate);
    DeckHeader {
        inputs: SqueezedPlateProblem::to_inputs(params),
        loads: Vec::new(),
        mesh,
        stick_slope,
        poisson: params.poisson,
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
    let slope = stick_slope_of(stick_slope, plate);
    let header = header(plate, mesh, stick_slope);
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

impl Deck for SqueezedPlateProblem {
    const SOURCE: &'static str = " (Ligier & Bonhote 2014)";
    const INTERFACE_SET: &'static str = sets::PLATE_FACE;
    type FePoint = PlateFePoint;
    type Compared = Vec<PlateCompared>;

    fn expected(plate: &SqueezedPlate, _header: &DeckHeader) -> String {
        let mut text = String::new();
        let state = plate.regularized();
        let coulomb = plate.coulomb();
        let _ = writeln!(
            text,
            "** Expected from the closed forms (strip theory, the paper's model):\n\
             **   u(L) regularized {} mm, Coulomb {} mm; X_r {} mm, X_s {} mm; regime {}",
            number(state.end_displacement()),
            number(coulomb.end_displacement()),
            number(state.micro_zone_end()),
            number(coulomb.stick_end()),
            state.regime().label()
        );
        text
    }

    fn ccx_points(run: &CcxRun, params: &PlateParams) -> Result<Vec<PlateFePoint>, ResultsError> {
        super::fe_points::plate_point(run, params).map(|p| vec![p])
    }

    const CSV_CURVE: crate::measured::Curve = super::fe_points::PLATE_CURVE;

    fn csv_points(text: &str) -> Result<Vec<PlateFePoint>, ResultsError> {
        super::fe_points::plate_points_from_csv(text)
    }

    const BENCH_PRESET: Option<(&'static str, &'static str)> = Some((
        "plate-bench",
        "the paper's plate at K_T = 1e4 MPa/mm: the strip theory holds there and u(L) tells K_T \
         within +-0.6 %; at the paper's 1e6 the strip theory is 48 % off and u(L) tells K_T \
         within +-2.4 % only",
    ));

    fn compare(
        plate: &SqueezedPlate,
        points: &[PlateFePoint],
        mesh: Option<&InterfaceMesh>,
    ) -> Vec<PlateCompared> {
        super::compare::compare(plate, points, mesh)
    }

    fn without_envelope(compared: &mut Vec<PlateCompared>) {
        for row in compared {
            row.strip_within = None;
        }
    }

    /// One step: the pressure, applied at once; the plate has no forces to step through.
    fn write_deck(plate: &SqueezedPlate, request: &DeckRequest) -> Result<String, DeckError> {
        if request.loads.is_some() {
            return Err(DeckError::Usage(
                "--loads are the tip forces of a beam deck; the plate deck applies its \
                 pressure P in one step (set P with --set P=...)",
            ));
        }
        Ok(plate_deck(plate, request.mesh, request.slope)?)
    }
}

/// The plate's u(L) against its plane-strain continuum (docs/theory.md, "The verdict against the
/// continuum"): the continuum is within 0.002 % (K_T = 1e4), 0.03 % (1e5) and 0.19 % (1e6
/// MPa/mm, where the strip theory is 48 % off) of CalculiX's thickness mean on the paper's plate,
/// coarse and fine meshes alike; 0.3 % keeps a margin over the largest.
impl ContinuumJudged for SqueezedPlateProblem {
    const CONTINUUM_TOLERANCE: f64 = 0.003;
    const RESPONSE: &'static str = "u(L)";
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::deck::test_support::{elements_written, node_x_of_set};

    #[test]
    fn the_counted_size_is_the_written_size() {
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        for mesh in [DeckMesh::Coarse, DeckMesh::Fine] {
            let counted =
                plate_element_count(&plate, mesh, stick_slope_of(StickSlope::Model, &plate));
            let deck = plate_deck(&plate, mesh, StickSlope::Model).unwrap();
            assert_eq!(counted, elements_written(&deck) as f64);
        }
    }

    #[test]
    fn the_plate_keeps_one_linear_increment() {
        // Its problem scales with P.
        let plate = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let plate = plate_deck(&plate, DeckMesh::Coarse, StickSlope::Model).unwrap();
        assert!(plate.contains("*STEP, INC=1000\n*STATIC\n1., 1.\n"));
        assert!(!plate.contains("NLGEOM"));
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
}
