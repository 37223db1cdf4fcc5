//! What a CalculiX run of the press fit's deck gives ([`PressFitFePoint`]), read from its `.dat`
//! against its deck (`deck_writer.rs` says what the deck prints), and what a CSV `F_N,Delta_mm`
//! from any FE code gives:
//!
//! - **Delta**: the shaft's end face's axial displacement, averaged over the face's area (the
//!   axisymmetric mean, weight r: exact for the elements' linear field between nodes), from the
//!   end of step 1. The hub is held on x = L, so this is Delta as the closed forms define it.
//!   Step 1 moves the end face through the interference's Poisson strains, which the 1-D theory
//!   does not have: hence the reference there, as the lap joint's clamping step;
//! - **CPRESS**: CalculiX's contact pressure (`*CONTACT PRINT`, CSTR) over the interface: its
//!   median (the uniform p of Lamé's theory, which the end-face peaks do not move) and its
//!   largest value (the peaks at the faces);
//! - **CSHEAR**: the largest |shear| (both tangential components);
//! - **CSLIP**: the relative axial displacement of facing interface nodes (shaft minus hub), from
//!   the end of step 1, at both faces; the sliding zones where K_T |slip| >= mu p (the FE's p),
//!   contiguous from each face;
//! - **the push-out capacity**: the hub's axial reaction on x = L at the end of the capacity
//!   step. CalculiX reports a CAX model's forces for its 2-degree wedge: the reader scales them
//!   by the run's own ratio F / reaction at the last force step (180.04 on the #98 fit, the
//!   0.02 % over 180 being the chords of the expanded wedge);
//! - **the contact formulation** the deck's `*CONTACT PAIR` names (surface-to-surface, node to
//!   surface with a node slave or with face slaves): issue #98's question.

use std::collections::HashMap;

use crate::fe::results::{
    CcxRun, DatBlock, NOT_FINISHED, ResultsError, cut_short, facing_slip_along, load_step_time,
    node_coordinate, points_from_csv, sliding_zones,
};
use crate::measured::{Curve, MEASURED_JOINT_DISPLACEMENT};

use super::deck_writer::sets;
use super::registered::problem::PressFitInputs;

/// The axial coordinate's index in an axisymmetric deck's node (r, x).
const AXIAL: usize = 1;

/// What a point of the press fit is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitPointKind {
    /// A push-out force's state (a force step, or a CSV row).
    Load,
    /// The push-out capacity: the force the fit carries in gross slip (the capacity step).
    Capacity,
}

/// One FE point of the press fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitFePoint {
    /// The push-out force (N): the step's load, or the capacity read from the reaction.
    pub force: f64,
    /// Delta (mm), from the end of step 1 for CalculiX results.
    pub delta: f64,
    /// A load's state or the capacity.
    pub kind: FitPointKind,
    /// The contact (CalculiX results); `None` from a CSV curve.
    pub contact: Option<FitContact>,
}

/// The contact formulation of the deck's `*CONTACT PAIR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formulation {
    /// `TYPE=SURFACE TO SURFACE` (the deck's own).
    SurfaceToSurface,
    /// `TYPE=NODE TO SURFACE` with a `TYPE=NODE` slave surface (CalculiX issue #98's ~3200 N).
    NodeSlave,
    /// `TYPE=NODE TO SURFACE` with an element-face slave (the issue's ~1400 N).
    NodeToSurface,
    /// A pair the reader does not recognise.
    Unknown,
}

impl Formulation {
    /// Its words in reports.
    pub fn label(self) -> &'static str {
        match self {
            Formulation::SurfaceToSurface => "surface-to-surface",
            Formulation::NodeSlave => "node-to-surface, node slave",
            Formulation::NodeToSurface => "node-to-surface, face slave",
            Formulation::Unknown => "unrecognised contact pair",
        }
    }

    /// The formulation of `deck`'s first `*CONTACT PAIR`.
    pub fn of_deck(deck: &str) -> Formulation {
        let mut lines = deck
            .lines()
            .map(str::trim)
            .filter(|l| !l.starts_with("**") && !l.is_empty());
        let Some(card) = lines.find(|l| l.to_ascii_uppercase().starts_with("*CONTACT PAIR")) else {
            return Formulation::Unknown;
        };
        let card = card.to_ascii_uppercase().replace(' ', "");
        if card.contains("TYPE=SURFACETOSURFACE") {
            return Formulation::SurfaceToSurface;
        }
        if !card.contains("TYPE=NODETOSURFACE") {
            return Formulation::Unknown;
        }
        let slave = lines
            .next()
            .and_then(|l| l.split(',').next())
            .map(|s| s.trim().to_ascii_uppercase())
            .unwrap_or_default();
        let node_surface = deck.lines().any(|l| {
            let l = l.to_ascii_uppercase().replace(' ', "");
            l.starts_with("*SURFACE,")
                && l.contains(&format!("NAME={slave},"))
                && l.contains("TYPE=NODE")
                || l.starts_with("*SURFACE,")
                    && l.ends_with(&format!("NAME={slave}"))
                    && l.contains("TYPE=NODE")
        });
        if node_surface {
            Formulation::NodeSlave
        } else {
            Formulation::NodeToSurface
        }
    }
}

/// The press fit's interface in a CalculiX run at one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitContact {
    /// The median CPRESS over the interface at the end of step 1, the interference alone (MPa):
    /// Lamé's p. Under the push-out the shaft's compression swells it (docs/theory.md (S9)).
    pub assembled_pressure: f64,
    /// The median CPRESS over the interface at this step (MPa).
    pub pressure: f64,
    /// The largest CPRESS (MPa): the peaks at the faces.
    pub pressure_peak: f64,
    /// The largest |CSHEAR| (MPa).
    pub shear_peak: f64,
    /// The slip (shaft minus hub, axial, from step 1) at x = 0 and at x = L (mm).
    pub slip_at_faces: (f64, f64),
    /// The sliding zones from x = 0 and from x = L (mm): K_T |slip| >= mu p (the FE's p).
    pub zones: (f64, f64),
    /// The deck's contact formulation.
    pub formulation: Formulation,
}

/// The CSV form of the press fit's curve: the measurement format of `fit`, one row or more.
pub(super) const FIT_CURVE: Curve = Curve {
    min_rows: 1,
    ..MEASURED_JOINT_DISPLACEMENT
};

/// Press fit points from a CSV `F_N,Delta_mm`.
///
/// # Errors
/// As [`crate::measured::parse_curve`].
pub fn fit_points_from_csv(text: &str) -> Result<Vec<PressFitFePoint>, ResultsError> {
    points_from_csv(text, &FIT_CURVE, |force, delta| PressFitFePoint {
        force,
        delta,
        kind: FitPointKind::Load,
        contact: None,
    })
}

/// A block of the `.dat` the generic reader skips: a set's force totals, or the contact stresses.
#[derive(Debug, Clone, PartialEq)]
struct TableBlock {
    /// `total force` or `contact stress`.
    what: &'static str,
    /// The set (force totals), empty for contact stresses.
    set: String,
    time: f64,
    /// The numbers of each row.
    rows: Vec<Vec<f64>>,
}

/// The force-total and contact-stress blocks of a `.dat` (every other line is the generic
/// reader's, [`crate::fe::results::DatRead`], which has read the file before this does).
fn table_blocks(dat: &str) -> Result<Vec<TableBlock>, ResultsError> {
    let mut blocks: Vec<TableBlock> = Vec::new();
    let mut open = false;
    for (index, line) in dat.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        let header = ["total force", "contact stress"]
            .into_iter()
            .find(|what| trimmed.starts_with(what));
        if let Some(what) = header {
            let (head, time) = trimmed.rsplit_once(" and time").ok_or(ResultsError::Line {
                line: index + 1,
                problem: format!("a {what} header without 'and time'"),
            })?;
            let time = time
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|t| t.is_finite())
                .ok_or(ResultsError::Line {
                    line: index + 1,
                    problem: format!("the time of a {what} block is not a number"),
                })?;
            let set = head
                .split_once(" for set ")
                .map(|(_, s)| s.trim().to_string())
                .unwrap_or_default();
            blocks.push(TableBlock {
                what,
                set,
                time,
                rows: Vec::new(),
            });
            open = true;
            continue;
        }
        let numbers: Option<Vec<f64>> = trimmed
            .split_whitespace()
            .map(|f| f.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect();
        match (blocks.last_mut(), numbers) {
            (Some(block), Some(numbers)) if open && !numbers.is_empty() => {
                block.rows.push(numbers);
            }
            _ => open = false,
        }
    }
    Ok(blocks)
}

/// The last block of `what` (of `set`, when given) at `time`.
fn table_at<'a>(
    blocks: &'a [TableBlock],
    what: &str,
    set: &str,
    time: f64,
) -> Option<&'a TableBlock> {
    blocks.iter().rev().find(|b| {
        b.what == what && b.set.eq_ignore_ascii_case(set) && (b.time - time).abs() < 1e-6 * time
    })
}

/// The area mean of the axial displacement over an axisymmetric face's nodes (radius, u_x):
/// the integral of u r dr over the integral of r dr, u linear between nodes.
pub(crate) fn axisymmetric_mean(
    nodes: &HashMap<usize, [f64; 3]>,
    block: &DatBlock,
) -> Result<f64, ResultsError> {
    let mut line: Vec<(f64, f64)> = block
        .rows
        .iter()
        .map(|(id, u)| node_coordinate(nodes, *id).map(|c| (c[0], u[AXIAL])))
        .collect::<Result<_, _>>()?;
    line.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut moment, mut area) = (0.0, 0.0);
    for w in line.windows(2) {
        let ((r0, u0), (r1, u1)) = (w[0], w[1]);
        moment += (r1 - r0) * (u0 * (2.0 * r0 + r1) + u1 * (r0 + 2.0 * r1)) / 6.0;
        area += (r1 * r1 - r0 * r0) / 2.0;
    }
    if area > 0.0 {
        Ok(moment / area)
    } else {
        Err(ResultsError::Missing(format!(
            "set {} spans no area ({} nodes)",
            block.set,
            line.len()
        )))
    }
}

/// The press fit at one time of a run: Delta (not yet zeroed) and the slip profile.
struct FitState {
    delta: f64,
    xs: Vec<f64>,
    slips: Vec<f64>,
}

/// The contact columns of one CSTR row: (pressure, |shear|). Surface-to-surface rows are
/// `element face press tang1 tang2`, node-to-surface rows `node press tang1 tang2`: the last
/// three numbers either way.
fn pressure_and_shear(row: &[f64]) -> Option<(f64, f64)> {
    let n = row.len();
    (n >= 4).then(|| (row[n - 3], row[n - 2].hypot(row[n - 1])))
}

/// The median of `values` (not empty).
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

/// The points of a press fit deck's run: one per force step CalculiX finished, then the
/// capacity.
///
/// # Errors
/// A malformed `.dat` line, no result at the end of step 1 or of a load step or of the capacity
/// step (a run that failed before it, or the `.dat` of another deck).
pub(super) fn fit_points(
    run: &CcxRun,
    inputs: &PressFitInputs,
) -> Result<Vec<PressFitFePoint>, ResultsError> {
    let structure = inputs.structure;
    let dat = run.read()?;
    let tables = table_blocks(run.dat)?;
    let formulation = Formulation::of_deck(run.deck);
    let state_at = |time: f64, what: &dyn Fn() -> String| -> Result<FitState, String> {
        let [end, shaft, hub] = [sets::SHAFT_END, sets::SHAFT_FACE, sets::HUB_FACE].map(|set| {
            dat.block(set, time)
                .map_err(|why| format!("{}: {why}", what()))
        });
        let (xs, slips) = facing_slip_along(&dat.nodes, shaft?, hub?, AXIAL)
            .map_err(|e| format!("{}: {e}", what()))?;
        Ok(FitState {
            delta: axisymmetric_mean(&dat.nodes, end?).map_err(|e| format!("{}: {e}", what()))?,
            xs,
            slips,
        })
    };
    let assembled = state_at(1.0, &|| {
        "at the end of step 1, the interference (time 1)".into()
    })
    .map_err(|why| ResultsError::Missing(format!("{why} {NOT_FINISHED}")))?;
    let reaction = |time: f64| -> Option<f64> {
        table_at(&tables, "total force", sets::HUB_HELD, time)
            .and_then(|b| b.rows.first())
            .and_then(|row| row.get(AXIAL))
            .map(|f| f.abs())
    };
    let stresses = |time: f64| -> Option<(Vec<f64>, Vec<f64>)> {
        let rows = &table_at(&tables, "contact stress", "", time)?.rows;
        let (pressures, shears): (Vec<f64>, Vec<f64>) = rows
            .iter()
            .filter_map(|r| pressure_and_shear(r))
            .filter(|(p, _)| *p > 0.0)
            .unzip();
        (!pressures.is_empty()).then_some((pressures, shears))
    };
    let assembled_pressure = stresses(1.0).map(|(p, _)| median(p));
    let contact_at = |time: f64, state: &FitState| -> Option<FitContact> {
        let (pressures, shears) = stresses(time)?;
        let pressure = median(pressures.clone());
        let slips: Vec<f64> = state
            .slips
            .iter()
            .zip(&assembled.slips)
            .map(|(s, s0)| s - s0)
            .collect();
        let saturation = structure.friction * pressure / structure.tangential_stiffness;
        Some(FitContact {
            assembled_pressure: assembled_pressure?,
            pressure,
            pressure_peak: pressures.iter().copied().fold(0.0, f64::max),
            shear_peak: shears.iter().copied().fold(0.0, f64::max),
            slip_at_faces: (
                slips.first().copied().unwrap_or(0.0),
                slips.last().copied().unwrap_or(0.0),
            ),
            zones: sliding_zones(&state.xs, &slips, saturation),
            formulation,
        })
    };
    let loads = &run.header.loads;
    let mut points = Vec::with_capacity(loads.len() + 1);
    let mut scale = None;
    for step in run.load_steps() {
        let state = state_at(step.time, &|| step.label())
            .map_err(|why| cut_short(&why, points.len(), loads.len()))?;
        if let Some(r) = reaction(step.time).filter(|r| *r > 0.0) {
            scale = Some(step.force / r);
        }
        points.push(PressFitFePoint {
            force: step.force,
            delta: state.delta - assembled.delta,
            kind: FitPointKind::Load,
            contact: contact_at(step.time, &state),
        });
    }
    let time = load_step_time(loads.len());
    let capacity =
        state_at(time, &|| format!("the capacity step (time {time})")).map_err(|why| {
            ResultsError::Missing(format!(
                "{why}; the .dat holds the {} load steps but not the capacity {NOT_FINISHED}",
                loads.len()
            ))
        })?;
    let force = match (reaction(time), scale) {
        (Some(r), Some(scale)) => r * scale,
        _ => {
            return Err(ResultsError::Missing(format!(
                "no axial reaction of set {} at the last load step and at the capacity step \
                 (time {time}) {NOT_FINISHED}",
                sets::HUB_HELD
            )));
        }
    };
    points.push(PressFitFePoint {
        force,
        delta: capacity.delta - assembled.delta,
        kind: FitPointKind::Capacity,
        contact: contact_at(time, &capacity),
    });
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_formulation_is_read_from_the_pair_and_its_slave() {
        let deck = |pair: &str| {
            format!(
                "*SURFACE, NAME=NSHAFT, TYPE=NODE\nIFSHAFT\n** {}\n{pair}\n",
                super::super::deck_writer::NODE_SLAVE_PAIR
            )
        };
        assert_eq!(
            Formulation::of_deck(&deck(super::super::deck_writer::SURFACE_PAIR)),
            Formulation::SurfaceToSurface
        );
        assert_eq!(
            Formulation::of_deck(&deck(super::super::deck_writer::NODE_SLAVE_PAIR)),
            Formulation::NodeSlave
        );
        assert_eq!(
            Formulation::of_deck(&deck(
                "*CONTACT PAIR, INTERACTION=JENKINS, TYPE=NODE TO SURFACE\nSSHAFT, SHUB"
            )),
            Formulation::NodeToSurface
        );
        assert_eq!(Formulation::of_deck("*NODE\n"), Formulation::Unknown);
    }

    #[test]
    fn the_face_mean_weighs_by_the_radius() {
        // u = r over r in [1, 3]: the mean of r weighted by r is (26/3) / 4 = 13/6, exactly
        // for a field linear between nodes.
        let mut nodes = HashMap::new();
        for (id, r) in [(1, 1.0), (2, 2.0), (3, 3.0)] {
            nodes.insert(id, [r, 0.0, 0.0]);
        }
        let block = DatBlock {
            set: "END".into(),
            time: 1.0,
            rows: vec![
                (3, [0.0, 3.0, 0.0]),
                (1, [0.0, 1.0, 0.0]),
                (2, [0.0, 2.0, 0.0]),
            ],
        };
        let mean = axisymmetric_mean(&nodes, &block).unwrap();
        assert!((mean - 13.0 / 6.0).abs() < 1e-15, "{mean}");
    }

    #[test]
    fn the_table_blocks_are_read_with_their_sets_and_times() {
        let dat = " total force (fx,fy,fz) for set HUBHELD and time  0.2000000E+01\n\n\
                   -9.5E-01 -2.284536E+00 0.0\n\n contact stress (slave element+face,press,tang1,\
                   tang2) for all contact elements and time 0.2000000E+01\n\n  8  4 6.3 0.0 0.16\n \
                   8 4 6.2 0.0 0.15\n";
        let blocks = table_blocks(dat).unwrap();
        assert_eq!(blocks.len(), 2);
        assert_eq!(
            (blocks[0].what, blocks[0].set.as_str(), blocks[0].time),
            ("total force", "HUBHELD", 2.0)
        );
        assert_eq!(blocks[1].rows.len(), 2);
        assert_eq!(pressure_and_shear(&blocks[1].rows[0]), Some((6.3, 0.16)));
        assert!(table_at(&blocks, "contact stress", "", 2.0).is_some());
    }
}
