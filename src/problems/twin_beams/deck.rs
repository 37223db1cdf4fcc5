//! The twin beams' FE deck ([`Deck`]): the CalculiX deck of two clamped beams pressed together and
//! the header lines it expects; the points a run gives are read in `fe_points.rs` and compared
//! with the closed forms in `compare.rs`.

use std::fmt::Write as _;

use crate::fe::continuum_verdict::ContinuumJudged;
use crate::fe::deck::{
    DeckMesh, DeckTooLarge, Geometry, LoadPath, MAX_DECK_ELEMENTS, load_steps, normal_stiffness,
    real, start_step, write_cload, write_contact_pair, write_elements, write_interaction,
    write_material, write_nodes, write_nset, write_pressure, write_surface,
};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::{DeckHeader, StickSlope};
use crate::fe::kinematics::Kinematics;
use crate::fe::mesh::{Block, Face, graded_toward_end, graded_toward_end_count, uniform};
use crate::fe::peak_pressure::LockedPressure;
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::format::number;
use crate::kernel::params::{Compact, Domain, Unit};
use crate::problems::Problem;

use super::closed_form::{TipForce, TwinBeams};
use super::compare::BeamComparison;
use super::fe_points::BeamFePoint;
use super::params::{BeamTheory, TwinBeamsParams};
use super::problem::{BeamsInputs, BeamsModel, TwinBeamsProblem};

/// Names of the node sets the deck prints to the .dat file, which the reader looks up.
pub(crate) mod sets {
    /// Tip nodes on the centre line of both beams (w(L) is their mean transverse displacement).
    pub(crate) const BEAM_TIP: &str = "WTIP";
    /// Lower beam's interface nodes along x (at z = 0).
    pub(crate) const BEAM_LOWER_FACE: &str = "IFLOWER";
    /// Upper beam's interface nodes along x (at z = 0); they start where `IFLOWER`'s are.
    pub(crate) const BEAM_UPPER_FACE: &str = "IFUPPER";
}

/// The stick slope (MPa/mm) a deck of `beams` gives CalculiX: the model's K_T, or near Coulomb a
/// boundary layer a tenth of the half-height h (1/k = h/10, K_T = 25 E / h).
pub fn stick_slope_of(stick_slope: StickSlope, beams: &TwinBeams) -> f64 {
    let p = beams.params();
    match stick_slope {
        StickSlope::Model => p.tangential_stiffness,
        StickSlope::NearCoulomb => 25.0 * p.youngs_modulus / p.half_height,
    }
}

/// The header of a twin-beam deck: K_T is the deck's stick slope, F the last load.
pub fn header(
    beams: &TwinBeams,
    loads: &[TipForce],
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> DeckHeader {
    let mut structure = beams.params();
    structure.tangential_stiffness = stick_slope_of(stick_slope, beams);
    DeckHeader {
        inputs: TwinBeamsProblem::to_inputs(BeamsInputs {
            structure,
            force: loads.last().map_or(0.0, |f| f.newtons()),
        }),
        loads: loads.iter().map(|f| f.newtons()).collect(),
        mesh,
        stick_slope,
        poisson: structure.poisson,
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
        let params = TwinBeamsParams {
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
        DeckMesh::Finest => "use --mesh coarse (16 times fewer elements) or ",
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
    let slope = stick_slope_of(stick_slope, beams);
    let header = header(beams, loads, mesh, stick_slope);
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
    let force_step = path.force_step(onset);
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

/// The end of a beam load step: its node sets printed, its displacements and contact saved.
fn end_beam_step(deck: &mut String) {
    for set in [sets::BEAM_TIP, sets::BEAM_LOWER_FACE, sets::BEAM_UPPER_FACE] {
        let _ = writeln!(deck, "*NODE PRINT, NSET={set}\nU");
    }
    deck.push_str("*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n");
}

/// The beams' w(L) against their plane-stress continuum (docs/theory.md, "The twin beams'
/// continuum", (BC4)): within 0.12 % of converged CalculiX runs on the cases used to state it
/// (0.25 % is twice that), plus, for an `NLGEOM` run, [`nlgeom_allowance`]: the continuum is
/// small-strain, and `NLGEOM` moves w(L) by a measured amount that grows as P L^2 / (E h^2) and
/// as the interface softens (0.02 % on the paper's beams, 0.8 % on thin beams on a soft one).
impl ContinuumJudged for TwinBeamsProblem {
    const CONTINUUM_TOLERANCE: f64 = 0.0025;
    const RESPONSE: &'static str = "w(L)";
}

/// The floor and the interface part of the `NLGEOM` envelope f(kL) of [`nlgeom_allowance`].
const NLGEOM_FLOOR: f64 = 0.06;
const NLGEOM_INTERFACE_PART: f64 = 1.0;

/// How far a converged `NLGEOM` run's w(L) may be from the beams' small-strain continuum beyond
/// the continuum's tolerance, a fraction (docs/theory.md (BC4), "NLGEOM against small strain").
///
/// Measured on CalculiX (the same deck with and without `NLGEOM`, in stick): the difference is
/// proportional to P and independent of F (a pre-stress effect: the pressure's stress and its
/// follower load on faces that rotate by w', which beam theory and the continuum leave out), and
/// once divided by (P / E) (L / h)^2 it is one decreasing function of k L on 8 cases from
/// kL = 0.87 to 27.6 (0.55 down to 0.054): the interface carries part of it as slip (the
/// `NLGEOM` slip was 0.63 % above the linear run's all along the soft case), which a stiff
/// interface (large kL) suppresses. The envelope (P / E) (L / h)^2 (0.06 + tanh(kL) / kL) keeps
/// a margin over those coarse runs (1.3 to 2.4 times each). Re-measured on mesh ladders (h, h/2,
/// h/4; docs/theory.md (BC4a), "On converged ladders", `validation/calculix/nlgeom_ladder.sh`) it
/// bounds every rung and every converged estimate with its uncertainty of the calibration cases
/// and of the hold-outs H1 and H2, and is kept: CalculiX's `NLGEOM` ladders are not asymptotic in
/// this term (the finest mesh moved the soft case from 0.21 to 0.27, and its answer depends on
/// the contact state CalculiX settles on), so no tighter envelope is supported. The hold-outs H3
/// and H4 fall outside it on the fine and finest decks (up to 7 times it), where the `NLGEOM` runs
/// turn the beams at the clamp: on such decks an `NLGEOM` run can be judged "does not agree" by
/// this allowance. Beyond first slip [`nlgeom_slip_allowance`] joins it.
pub fn nlgeom_allowance(beams: &TwinBeams) -> f64 {
    let p = beams.params();
    let kl = beams.decay_rate() * p.length;
    let slenderness = p.length / p.half_height;
    let interface = if kl > 0.0 { kl.tanh() / kl } else { 1.0 };
    p.pressure / p.youngs_modulus
        * slenderness
        * slenderness
        * (NLGEOM_FLOOR + NLGEOM_INTERFACE_PART * interface)
}

/// What an `NLGEOM` run's w(L) may differ by beyond first slip on top of [`nlgeom_allowance`], a
/// fraction: theta_L / mu, theta_L = 1.5 w(L) / L the tip slope of a cantilever under a tip
/// force, w(L) the continuum's (docs/theory.md (BC4a)). Where the interface slides its strength
/// is mu p on faces that `NLGEOM` turns by theta and small strain does not: the turning pressure
/// P theta acts beside the friction mu P, a relative change theta / mu of the slipping zone's
/// traction, and w(L) moves less than the traction that holds the beams together. Measured
/// differences beyond first slip were 0.3 to 0.6 of it (the issue's, the soft and the first
/// hold-out beams).
pub fn nlgeom_slip_allowance(beams: &TwinBeams, deflection: f64) -> f64 {
    beams.slip_turn_ratio(deflection)
}

impl Deck for TwinBeamsProblem {
    const SOURCE: &'static str = " (Ligier & Bonhote 2014)";
    const INTERFACE_SET: &'static str = sets::BEAM_LOWER_FACE;
    type FePoint = BeamFePoint;
    type Compared = BeamComparison;

    fn expected(model: &BeamsModel, header: &DeckHeader) -> String {
        let mut text = String::new();
        let beams = &model.beams;
        // The columns are Euler-Bernoulli whatever theory the preset chose: "+ shear"
        // adds the shear deflection once (a Timoshenko model's w(L) already holds it).
        let beams = &beams.with_theory(BeamTheory::EulerBernoulli);
        let _ = writeln!(
            text,
            "** Expected from the closed forms (Euler-Bernoulli, the paper's model; \"+ shear\"\n\
             ** adds each beam's shear deflection F L / (kappa G b 2h), kappa = 5/6, nu = {}):\n\
             **   F (N) | w(L) Coulomb (mm) | w(L) regularized (mm) | + shear (mm) | X (mm) | regime",
            Compact(header.poisson)
        );
        for &f in &header.loads {
            // One solve per load step: a caller that cancels the deck stops here.
            crate::numeric::cancel::checkpoint();
            let force = TipForce::clamped(f);
            let state = beams.regularized(force);
            let w = state.tip_deflection();
            let _ = writeln!(
                text,
                "**   {} | {} | {} | {} | {} | {}",
                number(f),
                number(beams.coulomb(force).tip_deflection()),
                number(w),
                number(w + beams.shear_deflection(force)),
                number(state.micro_zone_end()),
                state.regime().label()
            );
        }
        text
    }

    fn ccx_points(run: &CcxRun, params: &BeamsInputs) -> Result<Vec<BeamFePoint>, ResultsError> {
        super::fe_points::beam_points(run, params)
    }

    const CSV_CURVE: crate::measured::Curve = super::fe_points::BEAM_CURVE;

    fn csv_points(text: &str) -> Result<Vec<BeamFePoint>, ResultsError> {
        super::fe_points::beam_points_from_csv(text)
    }

    fn compare(
        model: &BeamsModel,
        points: &[BeamFePoint],
        mesh: Option<&InterfaceMesh>,
    ) -> BeamComparison {
        super::compare::compare(model, points, mesh)
    }

    /// (V2) was calibrated on the decks' `NLGEOM` runs (docs/theory.md); in linear geometry an
    /// independent model moved w(L) by -1.3 % against -0.1 % (issues 33, 48), which (V2L), wider
    /// beyond first slip, bounds.
    const ENVELOPE_KINEMATICS: &'static [Kinematics] = &[Kinematics::Nlgeom, Kinematics::Linear];

    /// Five times P: every sound run of the converged ladders of docs/theory.md (BC4a) peaks at
    /// 1.0 to 2.6 P (at the clamp), and the finest decks whose clamp corner locked at 50 to
    /// 134 P, with w(L) 0.3 to 1 % off.
    const LOCKED_PRESSURE: Option<LockedPressure> = Some(LockedPressure {
        ratio: 5.0,
        advice: "the finest deck's first elements at the clamp (0.0125 to 0.016 mm) pressed the \
                 corner shut; judge on --mesh fine, whose ladder converges there",
    });

    fn without_envelope(compared: &mut BeamComparison) {
        for row in &mut compared.rows {
            row.shear_corrected_within = None;
        }
    }

    /// A run that is not linear geometry (`NLGEOM`, mixed, or a CSV that does not say) is judged
    /// against the continuum with [`nlgeom_allowance`] on top of its tolerance, and beyond the
    /// closed form's first slip [`nlgeom_slip_allowance`] too; a linear run without (in stick
    /// the continuum is within 0.03 % of linear-geometry CalculiX).
    ///
    /// The closed form's envelope of a linear run, or of one that does not state its kinematics,
    /// is (V2L), the linear-geometry one (the wider: it holds in both).
    fn judge_kinematics(compared: &mut BeamComparison, model: &BeamsModel, kinematics: Kinematics) {
        if matches!(kinematics, Kinematics::Linear | Kinematics::NotStated) {
            let timoshenko = model.beams.with_theory(BeamTheory::Timoshenko);
            for row in &mut compared.rows {
                if row.shear_corrected_within.is_some() {
                    let force = TipForce::clamped(row.fe.force);
                    row.shear_corrected_within = timoshenko.validity(force).linear_geometry_error;
                }
            }
        }
        if kinematics == Kinematics::Linear {
            return;
        }
        let beams = &model.beams;
        let stick = nlgeom_allowance(beams);
        let first_slip = beams.first_macroslip_force();
        for row in &mut compared.rows {
            if let Some(Ok(verdict)) = &mut row.continuum {
                let slip = if row.fe.force > first_slip {
                    nlgeom_slip_allowance(beams, verdict.continuum)
                } else {
                    0.0
                };
                *verdict = verdict.with_allowance(stick + slip);
            }
        }
    }

    const OVERRIDES_NOTE: &'static str = " (compare shows both beam theories)";

    fn default_increment(model: &BeamsModel) -> Option<f64> {
        Some(LoadPath::default().force_step(model.beams.first_macroslip_force()))
    }

    fn write_deck(model: &BeamsModel, request: &DeckRequest) -> Result<String, DeckError> {
        let beams = &model.beams;
        let loads = deck_loads(beams, request.loads, request.slope)?;
        let force_step = request
            .increment
            .map(|f| DeckError::check("--increment", f, Domain::FORCE_STEP, Unit::Newton))
            .transpose()?;
        let path = LoadPath { force_step };
        Ok(beam_deck_on_path(
            beams,
            &loads,
            request.mesh,
            request.slope,
            path,
        )?)
    }
}

/// The load steps of a beam deck: `loads` checked (each a valid force, strictly increasing), or
/// the default multiples of F_thre, which span microslip and macroslip. With a near-Coulomb stick
/// slope the interface is on the edge of sliding everywhere at exactly F_thre, and CalculiX's
/// contact iterations can chatter there until they give up; the default then stops at 0.95 F_thre.
fn deck_loads(
    beams: &TwinBeams,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<TipForce>, DeckError> {
    let Some(loads) = loads else {
        let thre = beams.threshold_force();
        let at_threshold = match slope {
            StickSlope::Model => 1.0,
            StickSlope::NearCoulomb => 0.95,
        };
        return Ok([0.5, 0.75, at_threshold, 1.25, 1.875, 2.5]
            .map(|m| TipForce::clamped(m * thre))
            .to_vec());
    };
    let mut forces = Vec::with_capacity(loads.len());
    for &f in loads {
        let force = DeckError::check("--loads", f, Domain::FORCE, Unit::Newton)?;
        if forces
            .last()
            .is_some_and(|last: &TipForce| last.newtons() >= force)
        {
            return Err(DeckError::Flag {
                flag: "--loads",
                value: f,
                allowed: "the loads must increase from one step to the next".to_string(),
            });
        }
        forces.push(TipForce::clamped(force));
    }
    Ok(forces)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::deck::test_support::elements_written;

    fn paper_beam_deck(mesh: DeckMesh) -> String {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let loads = [40.0, 100.0].map(|f| TipForce::new(f).unwrap());
        beam_deck(&beams, &loads, mesh, StickSlope::Model).unwrap()
    }

    /// The NLGEOM - linear difference of w(L) in stick, measured with CalculiX 2.20 on the
    /// decks of `deck ccx beam` (coarse mesh) run with and without `NLGEOM` (docs/theory.md
    /// (BC4), "NLGEOM against small strain"): (L, h, E, P, K_T) and the difference. The soft
    /// case's fine-mesh run is the largest. The last five are the hold-out beams H1 to H4 (H2 on
    /// both meshes), measured after the envelope was drawn (their b, E and nu differ, which the
    /// envelope does not use).
    const NLGEOM_MEASURED: [([f64; 5], f64); 14] = [
        ([200.0, 5.0, 210_000.0, 2.0, 50.0], 0.003213),
        ([200.0, 5.0, 210_000.0, 2.0, 50.0], 0.004917),
        ([200.0, 5.0, 210_000.0, 1.0, 50.0], 0.001603),
        ([200.0, 5.0, 210_000.0, 4.0, 50.0], 0.006355),
        ([200.0, 5.0, 210_000.0, 2.0, 5.0], 0.008426),
        ([200.0, 5.0, 210_000.0, 2.0, 5000.0], 0.000823),
        ([200.0, 10.0, 210_000.0, 2.0, 50.0], 0.001161),
        ([200.0, 10.0, 210_000.0, 1.0, 600.0], 0.00017),
        ([250.0, 8.0, 210_000.0, 3.5, 2500.0], 0.000955),
        ([300.0, 6.0, 70_000.0, 1.5, 200.0], 0.00324),
        ([120.0, 4.0, 210_000.0, 3.0, 20.0], 0.00741),
        ([120.0, 4.0, 210_000.0, 3.0, 20.0], 0.00822),
        ([200.0, 12.0, 110_000.0, 5.0, 3000.0], 0.00071),
        ([180.0, 7.0, 200_000.0, 2.5, 150.0], 0.00125),
    ];

    /// The NLGEOM - linear difference of w(L) in stick on the mesh ladders of
    /// `validation/calculix/nlgeom_ladder.sh` (docs/theory.md (BC4a), "On converged ladders",
    /// CalculiX 2.20): (L, h, E, P, K_T) and the difference on the coarse, fine and finest decks
    /// (h, h/2, h/4), NaN where that rung's NLGEOM run settled on a spurious contact state
    /// (a contact pressure above 5 P at the clamp, left out as the campaign leaves it out) or
    /// did not finish within the campaign's limit. The
    /// hold-outs' ladders are in [`NLGEOM_LADDERS_HELD_OUT`].
    const NLGEOM_LADDERS: [([f64; 5], [f64; 3]); 7] = [
        // C3, the soft case (kL 2.76), at 20 N and (coarse and fine only) at 45.8 N.
        (
            [200.0, 5.0, 210_000.0, 2.0, 50.0],
            [3.2090e-3, 3.2151e-3, 4.1338e-3],
        ),
        (
            [200.0, 5.0, 210_000.0, 2.0, 50.0],
            [3.2176e-3, 4.7449e-4, f64::NAN],
        ),
        // C3 with both steps in 4 increments instead of 1 (coarse and fine only).
        (
            [200.0, 5.0, 210_000.0, 2.0, 50.0],
            [3.1946e-3, 2.0854e-3, f64::NAN],
        ),
        // C1 (kL 0.87): its finest NLGEOM run locked the clamp's corner (peak 134 P).
        (
            [200.0, 5.0, 210_000.0, 2.0, 5.0],
            [8.4329e-3, 8.4460e-3, f64::NAN],
        ),
        // C2 (kL 1.95), C6 the paper's beams (kL 6.76), C5 the stubby ones (kL 5.35).
        (
            [200.0, 10.0, 210_000.0, 2.0, 50.0],
            [1.1647e-3, 1.1602e-3, 1.1554e-3],
        ),
        (
            [200.0, 10.0, 210_000.0, 1.0, 600.0],
            [1.6437e-4, 1.6216e-4, 1.6171e-4],
        ),
        (
            [150.0, 15.0, 210_000.0, 2.0, 1000.0],
            [9.7596e-5, 9.6272e-5, 1.1894e-4],
        ),
    ];

    /// As [`NLGEOM_LADDERS`], the hold-out beams' stick rows (chosen before their runs; none
    /// used to draw the allowance). H3 and H4 are left out because their ladders fall outside
    /// the allowance: a failure of those hold-outs, recorded in docs/theory.md (BC4a), "On
    /// converged ladders" (on the fine and finest decks the `NLGEOM` excess grows linearly from
    /// the clamp, a rotation there). This test cannot hold them while the constants stand, and a
    /// hold-out never moves the constants. H4 (180, 7, 200 000, 2.5, 150; kL 3.73) measured
    /// 1.2541e-3, 2.6735e-3, 9.2982e-3 against an allowance of 2.711e-3; H3 (200, 12, 110 000,
    /// 5, 3000; kL 19.1) measured 7.1274e-4, 5.3196e-3, 1.0010e-2 against 1.420e-3.
    const NLGEOM_LADDERS_HELD_OUT: [([f64; 5], [f64; 3]); 2] = [
        // H2 (kL 1.17): its finest NLGEOM run did not converge within 900 s.
        (
            [120.0, 4.0, 210_000.0, 3.0, 20.0],
            [7.4120e-3, 8.2247e-3, f64::NAN],
        ),
        // H1 (kL 13.1; b 15, nu 0.33, mu 0.4, which the allowance does not use): its finest
        // NLGEOM run did not converge within 600 s (run for 1436 s, it locked: peak 6.3 P).
        (
            [300.0, 6.0, 70_000.0, 1.5, 200.0],
            [3.2366e-3, 3.3353e-3, f64::NAN],
        ),
    ];

    fn beams_of([length, half_height, youngs_modulus, pressure, kt]: [f64; 5]) -> TwinBeams {
        TwinBeams::new(TwinBeamsParams {
            length,
            half_height,
            youngs_modulus,
            pressure,
            tangential_stiffness: kt,
            ..TwinBeamsParams::PAPER
        })
        .unwrap()
    }

    /// The allowance lies above every measured NLGEOM difference, but not far (within a factor
    /// 3: an allowance that bounds by being huge would blunt the judge).
    #[test]
    fn the_nlgeom_allowance_bounds_the_measured_differences_closely() {
        for (case, measured) in NLGEOM_MEASURED {
            let allowance = nlgeom_allowance(&beams_of(case));
            assert!(allowance >= measured, "{case:?}: {allowance} < {measured}");
            assert!(
                allowance <= 3.0 * measured,
                "{case:?}: {allowance} >> {measured}"
            );
        }
    }

    /// The allowance bounds every rung of every converged ladder, and each ladder's converged
    /// estimate with its uncertainty (`fe::ladder::extrapolate`: Richardson where the rungs are
    /// asymptotic, else the finest rung with the rungs' spread), calibration and hold-out cases.
    #[test]
    fn the_nlgeom_allowance_bounds_the_converged_ladders() {
        for (case, rungs) in NLGEOM_LADDERS.iter().chain(&NLGEOM_LADDERS_HELD_OUT) {
            let allowance = nlgeom_allowance(&beams_of(*case));
            let valid: Vec<f64> = rungs.iter().copied().filter(|d| d.is_finite()).collect();
            for d in &valid {
                assert!(allowance >= d.abs(), "{case:?}: {allowance} < |{d}|");
            }
            let e = crate::fe::ladder::extrapolate(&valid, None).unwrap();
            let reach = e.estimate.abs() + e.uncertainty.unwrap_or(0.0);
            assert!(
                allowance >= reach,
                "{case:?}: {allowance} < {reach} ({e:?})"
            );
        }
    }

    /// Proportional to P, growing with L / h, falling as K_T grows (the interface carries part
    /// of it as slip), and for a stiff interface the floor's (P / E)(L / h)^2 0.06.
    #[test]
    fn the_nlgeom_allowance_scales_as_measured() {
        let base = [200.0, 5.0, 210_000.0, 2.0, 50.0];
        let at = |i: usize, v: f64| {
            let mut c = base;
            c[i] = v;
            nlgeom_allowance(&beams_of(c))
        };
        let a = nlgeom_allowance(&beams_of(base));
        assert!((at(3, 4.0) / a - 2.0).abs() < 1e-12);
        assert!(at(1, 10.0) < a && at(0, 300.0) > a);
        assert!(at(4, 500.0) < a && a < at(4, 5.0));
        let floor = 2.0 / 210_000.0 * 40.0 * 40.0 * NLGEOM_FLOOR;
        // kL = 1.2e4 there: the interface part is 1 / kL against the floor's 0.06.
        let ratio = at(4, 1e9) / floor;
        assert!(
            ratio > 1.0 && ratio < 1.0 + 1.0 / 1.2e4 / 0.06 * 1.01,
            "{ratio}"
        );
    }

    /// An NLGEOM run gets the allowance on its continuum verdicts; a linear run does not.
    #[test]
    fn only_a_run_that_is_not_linear_geometry_gets_the_allowance() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let model = BeamsModel {
            beams,
            force: TipForce::clamped(40.0),
        };
        let point = BeamFePoint {
            force: 40.0,
            deflection: 0.0113785,
            interface: None,
        };
        let allowance = nlgeom_allowance(&beams);
        for (kinematics, expected) in [
            (Kinematics::Linear, 0.0),
            (Kinematics::Nlgeom, allowance),
            (Kinematics::NotStated, allowance),
        ] {
            let mut compared = TwinBeamsProblem::compare(&model, &[point], None);
            TwinBeamsProblem::judge_kinematics(&mut compared, &model, kinematics);
            let Some(Ok(v)) = compared.rows[0].continuum else {
                panic!("not judged")
            };
            assert_eq!(v.allowance, expected, "{kinematics:?}");
            assert!((v.tolerance - 0.0025 - expected).abs() < 1e-15);
        }
        // Beyond first slip (F_1 about 80 N) the slip part joins: theta_L / mu of the continuum.
        let point = BeamFePoint {
            force: 100.0,
            deflection: 0.0388257,
            interface: None,
        };
        let mut compared = TwinBeamsProblem::compare(&model, &[point], None);
        TwinBeamsProblem::judge_kinematics(&mut compared, &model, Kinematics::Nlgeom);
        let Some(Ok(v)) = compared.rows[0].continuum else {
            panic!("not judged")
        };
        let slip = 1.5 * v.continuum / 200.0 / 0.3;
        assert!((v.allowance - allowance - slip).abs() < 1e-15, "{v:?}");
    }

    #[test]
    fn the_counted_size_is_the_written_size() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        for mesh in [DeckMesh::Coarse, DeckMesh::Fine] {
            assert_eq!(
                beam_element_count(&beams, mesh),
                elements_written(&paper_beam_deck(mesh)) as f64
            );
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
        let default = LoadPath::default().force_step(beams.first_macroslip_force());
        assert!((default - beams.first_macroslip_force() / 40.0).abs() < 1e-12);
        let given = LoadPath {
            force_step: Some(3.0),
        };
        assert_eq!(given.force_step(beams.first_macroslip_force()), 3.0);
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
}
