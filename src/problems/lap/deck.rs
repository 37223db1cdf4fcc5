//! The CalculiX deck of the double-lap joint (issue 24, item 5): a continuum model the shear-lag
//! closed forms can be judged against. Its conventions are the ones the first converged CalculiX
//! look at the joint settled (docs/theory.md (L12), `validation/calculix/lap/`):
//!
//! - half the joint, about the inner plate's mid-plane (u_y = 0 there): the inner plate's half
//!   thickness t1/2 and one cover t2;
//! - a plane-stress slice: one C3D20R element across a width W, u_z = 0 on z = 0 and the other
//!   side free. Every load is a traction, so W does not enter; a slice keeps the bricks from
//!   being hundreds of times wider than long;
//! - the cover runs on beyond x = 0 and is held on its end face there; the inner plate runs on
//!   beyond x = L and is pulled by F on its end face. Both extensions are 2 (t1 + t2) long (10 mm
//!   for the bundled joint: doubling them moved Delta by at most 0.06 %);
//! - the clamping pressure P on the cover's outer face over the overlap only; face-to-face penalty
//!   contact with stick slope K_T, as the other decks;
//! - step 1 applies P. Delta is then measured from the end of that step, because P alone stretches
//!   the plates through Poisson (a third of Delta at 1000 N on the bundled joint);
//! - loads up to F_1 in one increment. Many increments there leave CalculiX's shear near x = L up
//!   to 50 % above K_T s, which the law cannot produce. Beyond F_1, increments of at most F_1/40
//!   of force (`--increment`), a step that crosses F_1 reaching it in its first increment, as the
//!   beam decks do.
//!
//! `compare lap` reads its results (the [`Deck`] of the lap joint, below; its reader is
//! `fe_points.rs`) and compares them with the closed forms (`compare.rs`).

use std::fmt::Write as _;

use crate::fe::continuum_verdict::ContinuumJudged;
use crate::fe::deck::{
    DeckMesh, DeckTooLarge, Geometry, LoadPath, MAX_DECK_ELEMENTS, load_steps, normal_stiffness,
    real, start_step, write_cload, write_contact_pair, write_elements, write_interaction,
    write_nodes, write_nset, write_surface,
};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::{DeckHeader, StickSlope};
use crate::fe::mesh::{Block, Face, uniform};
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::format::number;
use crate::kernel::params::{Compact, Domain, ParamError, Unit};
use crate::problems::Problem;

use super::closed_form::{JointForce, LapJoint};
use super::compare::LapCompared;
use super::continuum::{LapBreaks, lap_breaks, lap_counts};
use super::fe_points::LapFePoint;
use super::problem::{LapInputs, LapJointProblem, LapModel};

/// The Poisson ratio the deck gives both materials: the shear-lag closed forms do not use one,
/// and nu = 0 instead of 0.3 moved CalculiX's Delta by at most 0.06 % (docs/theory.md (L12)).
pub(crate) const LAP_POISSON: f64 = super::continuum::LAP_POISSON;

/// Node sets the deck prints and a reader will read.
pub(crate) mod sets {
    /// The inner plate's nodes at x = L through its half thickness (z = 0).
    pub(crate) const LAP_INNER_END: &str = "DINNERL";
    /// The cover's nodes at x = 0 through its thickness (z = 0).
    pub(crate) const LAP_COVER_END: &str = "DCOVER0";
    /// The inner plate's interface nodes over the overlap (z = 0).
    pub(crate) const LAP_INNER_FACE: &str = "IFINNER";
    /// The cover's interface nodes over the overlap (z = 0).
    pub(crate) const LAP_COVER_FACE: &str = "IFCOVER";
}

/// The stick slope (MPa/mm) a deck of `joint` gives CalculiX: the model's K_T, or near Coulomb
/// the elastic slip's decay length a tenth of the thinner half (min(t1/2, t2)), as the other
/// decks resolve theirs.
pub fn stick_slope_of(stick_slope: StickSlope, joint: &LapJoint) -> f64 {
    let p = joint.params();
    match stick_slope {
        StickSlope::Model => p.tangential_stiffness,
        StickSlope::NearCoulomb => {
            let decay = 0.1 * (0.5 * p.inner_thickness).min(p.cover_thickness);
            let c = 1.0 / p.inner_stiffness() + 1.0 / p.covers_stiffness();
            1.0 / (2.0 * c * decay * decay)
        }
    }
}

/// The header of a double-lap joint deck: K_T is the deck's stick slope, F the last load.
pub fn header(
    joint: &LapJoint,
    loads: &[JointForce],
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> DeckHeader {
    let mut structure = joint.params();
    structure.tangential_stiffness = stick_slope_of(stick_slope, joint);
    DeckHeader {
        inputs: LapJointProblem::to_inputs(LapInputs {
            structure,
            force: loads.last().map_or(0.0, |f| f.newtons()),
        }),
        loads: loads.iter().map(|f| f.newtons()).collect(),
        mesh,
        stick_slope,
        poisson: LAP_POISSON,
    }
}

/// The deck of `joint` with one load step per force of `loads` (N, increasing).
///
/// # Errors
/// [`DeckTooLarge`] when the mesh would have more than [`MAX_DECK_ELEMENTS`] elements (a stiff
/// interface resolved over a long overlap).
pub fn lap_deck(
    joint: &LapJoint,
    loads: &[JointForce],
    mesh: DeckMesh,
    stick_slope: StickSlope,
    path: LoadPath,
) -> Result<String, DeckTooLarge> {
    let p = joint.params();
    let slope = stick_slope_of(stick_slope, joint);
    let at_slope = joint.with_tangential_stiffness(slope).unwrap_or(*joint);
    let header = header(joint, loads, mesh, stick_slope);
    let r = mesh.refinement();
    let (n1, n2) = (4 * r, 4 * r);
    let half = 0.5 * p.inner_thickness;
    let decay = 1.0 / at_slope.decay_rate();
    // Counted from the parameters before any break is made: a stiff interface over a long
    // overlap asks for 1e13 elements, whose breaks alone would not fit in memory.
    let elements = lap_counts(&at_slope.params(), n1).elements(n1);
    if elements > MAX_DECK_ELEMENTS as f64 {
        return Err(DeckTooLarge {
            elements,
            advice: too_large_advice(mesh, decay, p.length),
        });
    }
    // The continuum solver's mesh (its 4 r layers through each body): the two judges of the
    // shear-lag theory mesh the joint the same way.
    let LapBreaks {
        overlap,
        cover_extension,
        inner_extension,
        layer,
        finest,
    } = lap_breaks(&at_slope.params(), n1);
    let length = p.length;
    let extension = 2.0 * (p.inner_thickness + p.cover_thickness);
    let mut xs_cover = cover_extension.clone();
    xs_cover.pop();
    xs_cover.extend(&overlap);
    let mut xs_inner = overlap.clone();
    xs_inner.extend(&inner_extension[1..]);
    let width = 2.0 * finest;
    let zs = uniform(0.0, width, 1);
    debug_assert_eq!(
        ((xs_inner.len() - 1) * n1 + (xs_cover.len() - 1) * n2) as f64,
        elements
    );
    let inner = Block::new([xs_inner, uniform(0.0, half, n1), zs.clone()], 1, 1);
    let cover = Block::new(
        [xs_cover, uniform(half, half + p.cover_thickness, n2), zs],
        inner.node_count() + 1,
        inner.element_count() + 1,
    );
    let overlap_elements = overlap.len() - 1;
    let before = cover_extension.len() - 1;
    let normal_slope = normal_stiffness(p.inner_modulus.max(p.cover_modulus), layer, slope);

    let mut deck = header.to_comment();
    deck.push_str("*HEADING\n");
    let _ = writeln!(
        deck,
        "microslip double-lap joint, K_T = {} MPa/mm",
        Compact(slope)
    );
    write_nodes(&mut deck, &[&inner, &cover]);
    // A ground node for a weak spring on the inner plate: face-to-face contact engages only once
    // the faces press, so the inner plate would float at the first iteration.
    let ground = inner.node_count() + cover.node_count() + 1;
    let _ = writeln!(deck, "{ground}, {}, 0., 0.", real(length + 2.0 * extension));
    write_elements(&mut deck, "INNER", &inner);
    write_elements(&mut deck, "COVER", &cover);
    let [nx_inner, ny_inner, _] = inner.elements_along();
    let [_, ny_cover, _] = cover.elements_along();
    let pulled = inner
        .node([2 * nx_inner, 0, 0])
        .expect("a corner is a node");
    let spring = inner.element_count() + cover.element_count() + 1;
    let axial = p.inner_modulus * half * width / length;
    let _ = writeln!(
        deck,
        "*ELEMENT, TYPE=SPRINGA, ELSET=ESPRING\n{spring}, {pulled}, {ground}\n\
         *SPRING, ELSET=ESPRING\n\n{}",
        real(1e-7 * axial)
    );

    let at_z0 = |block: &Block, i: usize, rows: std::ops::RangeInclusive<usize>| -> Vec<usize> {
        rows.filter_map(|j| block.node([i, j, 0])).collect()
    };
    let symmetry: Vec<usize> = (0..=2 * nx_inner)
        .flat_map(|i| [0, 1, 2].map(|k| inner.node([i, 0, k])))
        .flatten()
        .collect();
    write_nset(&mut deck, "SYMY", &symmetry);
    let mut slice: Vec<usize> = inner
        .nodes()
        .chain(cover.nodes())
        .filter(|(_, [_, _, z])| *z == 0.0)
        .map(|(id, _)| id)
        .collect();
    slice.sort_unstable();
    write_nset(&mut deck, "SYMZ", &slice);
    write_nset(&mut deck, "HELD", &cover.nodes_at_x(0));
    write_nset(&mut deck, "GROUND", &[ground]);
    let overlap_end = 2 * overlap_elements;
    write_nset(
        &mut deck,
        sets::LAP_INNER_END,
        &at_z0(&inner, overlap_end, 0..=2 * ny_inner),
    );
    write_nset(
        &mut deck,
        sets::LAP_COVER_END,
        &at_z0(&cover, 2 * before, 0..=2 * ny_cover),
    );
    let face = |block: &Block, j: usize, from: usize| -> Vec<usize> {
        (from..=from + overlap_end)
            .filter_map(|i| block.node([i, j, 0]))
            .collect()
    };
    write_nset(
        &mut deck,
        sets::LAP_INNER_FACE,
        &face(&inner, 2 * ny_inner, 0),
    );
    write_nset(
        &mut deck,
        sets::LAP_COVER_FACE,
        &face(&cover, 0, 2 * before),
    );
    let inner_top: Vec<usize> = (0..overlap_elements)
        .map(|ex| inner.element([ex, ny_inner - 1, 0]))
        .collect();
    let cover_bottom: Vec<usize> = (before..before + overlap_elements)
        .map(|ex| cover.element([ex, 0, 0]))
        .collect();
    let cover_top: Vec<usize> = (before..before + overlap_elements)
        .map(|ex| cover.element([ex, ny_cover - 1, 0]))
        .collect();
    write_surface(&mut deck, "SINNERTOP", &inner_top, Face::YMax);
    write_surface(&mut deck, "SCOVERBOT", &cover_bottom, Face::YMin);

    for (name, modulus, set) in [
        ("INNERMAT", p.inner_modulus, "INNER"),
        ("COVERMAT", p.cover_modulus, "COVER"),
    ] {
        let _ = writeln!(
            deck,
            "*MATERIAL, NAME={name}\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET={set}, MATERIAL={name}",
            real(modulus),
            real(LAP_POISSON)
        );
    }
    write_interaction(&mut deck, normal_slope, p.friction, slope);
    write_contact_pair(
        &mut deck,
        "the cover's inner face",
        "the inner plate's outer face",
        ["SCOVERBOT", "SINNERTOP"],
    );
    deck.push_str(
        "** symmetry about the inner plate's mid-plane, a plane-stress slice (z = 0 held, the \
         other side free), the cover held beyond x = 0\n\
         *BOUNDARY\nSYMY, 2, 2\nSYMZ, 3, 3\nHELD, 1, 2\nGROUND, 1, 3\n",
    );

    let onset = at_slope.first_slip_force();
    let force_step = path
        .force_step
        .unwrap_or(LoadPath::DEFAULT_FRACTION * onset);
    let _ = writeln!(
        deck,
        "** load path: up to F_1 = {} N (at this stick slope) in one increment; beyond it in\n\
         ** increments of at most {} N of force (friction is path-dependent once it saturates)",
        Compact(onset),
        Compact(force_step)
    );
    let newtons: Vec<f64> = loads.iter().map(|f| f.newtons()).collect();
    let steps = load_steps(&mut deck, &newtons, force_step, onset);
    let outputs = |deck: &mut String| {
        for set in [
            sets::LAP_INNER_END,
            sets::LAP_COVER_END,
            sets::LAP_INNER_FACE,
            sets::LAP_COVER_FACE,
        ] {
            let _ = writeln!(deck, "*NODE PRINT, NSET={set}\nU");
        }
        deck.push_str("*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n");
    };
    deck.push_str(
        "** step 1: the clamping pressure P on the cover's outer face over the overlap\n",
    );
    start_step(&mut deck, 1.0, Geometry::Linear);
    deck.push_str("*DLOAD\n");
    for id in &cover_top {
        let _ = writeln!(deck, "{id}, P{}, {}", Face::YMax.number(), real(p.pressure));
    }
    outputs(&mut deck);
    // The inner plate's share of F on this slice: F/2 over the half model, W/b of it.
    let share = 0.5 * width / p.width;
    for (n, (force, (increment, amplitude))) in loads.iter().zip(steps).enumerate() {
        let _ = writeln!(
            deck,
            "** step {}: F = {} N through the joint (a traction F / (b t1) on the inner plate's end)",
            n + 2,
            Compact(force.newtons())
        );
        start_step(&mut deck, increment, Geometry::Linear);
        write_cload(&mut deck, amplitude.as_deref());
        for (id, f) in inner.end_face_loads(share * force.newtons()) {
            let _ = writeln!(deck, "{id}, 1, {}", real(f));
        }
        outputs(&mut deck);
    }
    Ok(deck)
}

/// Why a lap deck is too large and what makes it smaller: the coarse mesh only where it is not
/// the mesh already (advising the mesh the user has sends them in a circle), then a smaller K_T
/// (a longer decay length) or a shorter overlap.
fn too_large_advice(mesh: DeckMesh, decay: f64, length: f64) -> String {
    let coarse = match mesh {
        DeckMesh::Fine | DeckMesh::Finest => "the coarse mesh, ",
        DeckMesh::Coarse => "",
    };
    format!(
        "the interface's decay length 1/lambda = {} mm is resolved over an overlap of {} mm; \
         use {coarse}a smaller K_T or a shorter overlap L",
        crate::numeric::short(decay),
        Compact(length)
    )
}

impl Deck for LapJointProblem {
    const SOURCE: &'static str = " (docs/theory.md section 9)";
    const INTERFACE_SET: &'static str = sets::LAP_INNER_FACE;
    type FePoint = LapFePoint;
    type Compared = Result<Vec<LapCompared>, ParamError>;

    fn expected(model: &LapModel, header: &DeckHeader) -> String {
        let mut text = String::new();
        let joint = &model.joint;
        let _ = writeln!(
            text,
            "** Expected from the closed forms (shear lag):\n\
             **   F (N) | Delta Coulomb (mm) | Delta regularized (mm) | a (mm) | d (mm) | regime"
        );
        for &f in &header.loads {
            // One solve per load step: a caller that cancels the deck stops here.
            crate::numeric::cancel::checkpoint();
            let force = joint.clamped_force(f);
            let state = joint.regularized(force);
            let _ = writeln!(
                text,
                "**   {} | {} | {} | {} | {} | {}",
                number(f),
                number(joint.coulomb(force).joint_displacement()),
                number(state.joint_displacement()),
                number(state.slide_at_inner_end()),
                number(state.slide_at_cover_ends()),
                state.regime().label()
            );
        }
        text
    }

    fn ccx_points(run: &CcxRun, params: &LapInputs) -> Result<Vec<LapFePoint>, ResultsError> {
        super::fe_points::lap_points(run, params)
    }

    const CSV_CURVE: crate::measured::Curve = super::fe_points::LAP_CURVE;

    fn csv_points(text: &str) -> Result<Vec<LapFePoint>, ResultsError> {
        super::fe_points::lap_points_from_csv(text)
    }

    const BENCH_PRESET: Option<(&'static str, &'static str)> = Some((
        "lap-aluminium",
        "the bundled joint: Delta tells K_T within +-2.7 % at 0.5 F_1, the shear-lag envelope \
         is 3.2-3.6 % and the continuum agrees with CalculiX within 0.02 % there",
    ));

    fn compare(
        model: &LapModel,
        points: &[LapFePoint],
        mesh: Option<&InterfaceMesh>,
    ) -> Result<Vec<LapCompared>, ParamError> {
        super::compare::compare(model, points, mesh)
    }

    fn without_envelope(compared: &mut Result<Vec<LapCompared>, ParamError>) {
        for row in compared.iter_mut().flatten() {
            row.theory_within = None;
        }
    }

    fn default_increment(model: &LapModel) -> Option<f64> {
        Some(LoadPath::DEFAULT_FRACTION * model.joint.first_slip_force())
    }

    fn write_deck(model: &LapModel, request: &DeckRequest) -> Result<String, DeckError> {
        let joint = &model.joint;
        let loads = deck_loads(joint, request.loads, request.slope)?;
        let force_step = request
            .increment
            .map(|f| DeckError::check("--increment", f, Domain::FORCE_STEP, Unit::Newton))
            .transpose()?;
        Ok(lap_deck(
            joint,
            &loads,
            request.mesh,
            request.slope,
            LoadPath { force_step },
        )?)
    }
}

/// The joint's Delta against its plane-stress continuum (docs/theory.md, "The verdict against the
/// continuum"): the continuum is within 0.015 % of CalculiX on the bundled joint, 0.06 % on the
/// three fresh joints of (L14), and 0.003 to 0.3 % over 38 load states of 10 joints of an
/// independent CalculiX model (issue 33; the largest in elastic states of stiff, thick joints);
/// 0.4 % keeps a margin over the largest.
impl ContinuumJudged for LapJointProblem {
    const CONTINUUM_TOLERANCE: f64 = 0.004;
    const RESPONSE: &'static str = "Delta";
}

/// The forces of a lap deck's steps: `loads` (increasing, each at most F_gross), or one in each
/// regime: all microslip (F_1/2), one end sliding, both ends, and 0.9 F_gross (at the deck's
/// stick slope).
fn deck_loads(
    joint: &LapJoint,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<JointForce>, DeckError> {
    let at_slope = joint
        .with_tangential_stiffness(stick_slope_of(slope, joint))
        .unwrap_or(*joint);
    let Some(loads) = loads else {
        let (f1, f2, gross) = (
            at_slope.first_slip_force(),
            at_slope.second_slip_force(),
            at_slope.gross_slip_force(),
        );
        let mut forces: Vec<f64> = vec![0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.9 * gross];
        forces.dedup_by(|a, b| *a <= *b);
        return Ok(forces.into_iter().map(|f| joint.clamped_force(f)).collect());
    };
    DeckError::increasing_loads(loads, |f| joint.force(f))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problems::lap::closed_form::LapParams;

    fn aluminium() -> LapJoint {
        LapJoint::new(LapParams::ALUMINIUM).unwrap()
    }

    fn deck(loads: &[f64], mesh: DeckMesh) -> String {
        let joint = aluminium();
        let loads: Vec<JointForce> = loads.iter().map(|&f| joint.force(f).unwrap()).collect();
        lap_deck(&joint, &loads, mesh, StickSlope::Model, LoadPath::default()).unwrap()
    }

    /// Issue 36 (20): a deck too large on the coarse mesh does not advise the coarse mesh.
    #[test]
    fn a_deck_too_large_advises_only_what_the_user_can_change() {
        let joint = aluminium().with_tangential_stiffness(1e8).unwrap();
        let loads = [joint.force(3000.0).unwrap()];
        for (mesh, advises_coarse) in [(DeckMesh::Coarse, false), (DeckMesh::Fine, true)] {
            let result = lap_deck(&joint, &loads, mesh, StickSlope::Model, LoadPath::default());
            let Err(e) = result else {
                panic!("{mesh:?} not refused")
            };
            assert_eq!(
                e.advice.contains("coarse mesh"),
                advises_coarse,
                "{}",
                e.advice
            );
            assert!(
                e.advice.contains("a smaller K_T or a shorter overlap L"),
                "{}",
                e.advice
            );
        }
    }

    #[test]
    fn the_header_reads_back_and_every_set_and_step_is_there() {
        let text = deck(&[1000.0, 2400.0, 4000.0], DeckMesh::Coarse);
        let header = DeckHeader::parse(&text).unwrap().unwrap();
        assert_eq!(header.loads, [1000.0, 2400.0, 4000.0]);
        assert_eq!(header.model().unwrap().kind(), crate::ModelKind::Lap);
        for set in [
            sets::LAP_INNER_END,
            sets::LAP_COVER_END,
            sets::LAP_INNER_FACE,
            sets::LAP_COVER_FACE,
        ] {
            assert_eq!(
                text.matches(&format!("*NODE PRINT, NSET={set}\n")).count(),
                4
            );
        }
        // The pressure, then one step per force: the first (below F_1 = 2016 N) in one
        // increment, the second crossing F_1 on a ramp, the third in steps of F_1/40.
        assert_eq!(text.matches("*STEP").count(), 4);
        assert_eq!(text.matches("*STATIC\n1., 1.\n").count(), 2);
        assert!(text.contains("*CLOAD, AMPLITUDE=RAMP3"));
        assert!(text.contains("** Compare it:  microslip compare lap JOB.dat"));
        assert!(!text.contains("Ligier"));
    }

    #[test]
    fn the_end_loads_add_up_to_the_slices_share_of_f() {
        // The half model's inner plate carries F/2; the slice of width W carries W/b of it.
        let text = deck(&[3000.0], DeckMesh::Coarse);
        let step = &text[text.rfind("*CLOAD").unwrap()..];
        let total: f64 = step
            .lines()
            .skip(1)
            .take_while(|l| !l.starts_with('*'))
            .map(|l| l.split(", ").nth(2).unwrap().parse::<f64>().unwrap())
            .sum();
        let width: f64 = {
            let nodes = &text[text.find("*NODE, NSET=NALL").unwrap()..];
            nodes
                .lines()
                .skip(1)
                .take_while(|l| !l.starts_with('*'))
                .map(|l| l.split(", ").nth(3).unwrap().parse::<f64>().unwrap())
                .fold(0.0, f64::max)
        };
        assert!(
            (total / (3000.0 * 0.5 * width / 25.0) - 1.0).abs() < 1e-12,
            "{total}"
        );
    }

    #[test]
    fn the_fine_mesh_halves_every_size() {
        let count = |text: &str| text.matches(", S5\n").count() + text.matches(", S3\n").count();
        let (coarse, fine) = (
            deck(&[1000.0], DeckMesh::Coarse),
            deck(&[1000.0], DeckMesh::Fine),
        );
        // Interface faces along the overlap, both sides: about twice as many.
        let ratio = count(&fine) as f64 / count(&coarse) as f64;
        assert!((1.8..=2.2).contains(&ratio), "{ratio}");
    }
}
