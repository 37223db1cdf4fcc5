//! What every problem's reader of FE results is written with: CalculiX's `.dat` file read against
//! the deck it came from (`DatRead`: its displacement blocks, the deck's nodes and node sets, a
//! block checked complete), the load steps of a deck's header, slip profiles and thickness means,
//! and plain CSV curves that any FE code can write (`points_from_csv`).
//!
//! What a problem's FE point is, which node sets it reads and which columns its CSV has are the
//! problem's own, in its folder (`src/problems/<name>/fe_points.rs`, the cylinder's
//! `ccx_read.rs`): this file names no problem, so that a new problem's reader is its folder.
//!
//! Parsing only: the caller reads the files (with a size cap, [`crate::file`]) and hands the text
//! here. Every problem names its line where there is one.

use std::collections::HashMap;
use std::path::Path;

use thiserror::Error;

use super::face::{Deck, deck_face};
use super::header::DeckHeader;
use super::verdict::InterfaceMesh;
use crate::kernel::params::{Compact, Domain, Unit};
use crate::kernel::regime::Regime;
use crate::measured::{self as data, Curve};

/// What is wrong with an FE result file.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum ResultsError {
    /// A problem on a line.
    #[error("line {line}: {problem}")]
    Line {
        /// 1-based line.
        line: usize,
        /// What is wrong.
        problem: String,
    },
    /// Something the file should hold and does not.
    #[error("{0}")]
    Missing(String),
}

impl From<data::DataError> for ResultsError {
    fn from(e: data::DataError) -> Self {
        ResultsError::Line {
            line: e.line,
            problem: e.problem,
        }
    }
}

/// The interface state read from the slip profile: macroslip where K_T |s| >= mu P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeInterface {
    /// Where the macroslip zone at the free end starts (mm): L when there is none.
    pub macroslip_start: f64,
    /// The regime of the regularized law the profile shows.
    pub regime: Regime,
}

/// A microslip deck's `.dat` output, with the deck it came from.
#[derive(Debug, Clone)]
pub struct CcxRun<'a> {
    /// The deck's header.
    pub header: &'a DeckHeader,
    /// The deck's text (for node coordinates).
    pub deck: &'a str,
    /// The `.dat` file's text.
    pub dat: &'a str,
    /// Where the `.dat` is: a reader that needs the run's `.frd` beside it (the cylinder's contact
    /// pressure, [`crate::fe::load::frd_contact`]) finds it there.
    pub dat_path: &'a Path,
}

/// One block of a `.dat` file: a quantity of a node set at one time.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DatBlock {
    pub(crate) set: String,
    pub(crate) time: f64,
    pub(crate) rows: Vec<(usize, [f64; 3])>,
}

/// The points of a CSV curve, each made of its (abscissa, ordinate) by `point`: every problem's
/// [`Deck::csv_points`] is this with its curve's columns.
///
/// # Errors
/// As [`data::parse_curve`].
pub(crate) fn points_from_csv<P>(
    text: &str,
    curve: &Curve,
    point: impl Fn(f64, f64) -> P,
) -> Result<Vec<P>, ResultsError> {
    Ok(data::parse_curve(text, curve)?
        .into_iter()
        .map(|(x, y)| point(x, y))
        .collect())
}

impl CcxRun<'_> {
    /// The points of the run, as problem `P`'s: what its deck's load steps give.
    ///
    /// # Errors
    /// A deck of another problem (naming the command that reads it), a malformed `.dat` line, or
    /// a result the deck asks for and the `.dat` lacks.
    pub fn points<P: Deck>(&self) -> Result<Vec<P::FePoint>, ResultsError> {
        let params = P::from_inputs(&self.header.inputs).ok_or_else(|| self.other_deck())?;
        P::ccx_points(self, &params)
    }

    /// Results asked for as one problem's of a deck of another: the command that reads them.
    pub(crate) fn other_deck(&self) -> ResultsError {
        let kind = self.header.inputs.kind();
        ResultsError::Missing(format!(
            "the deck is a {kind} deck; use `microslip compare {kind}`"
        ))
    }
}

impl CcxRun<'_> {
    /// The deck's mesh along the interface (the lower beam's face, the plate's contact face), from
    /// the positions of the nodes of its node set: what an X difference is counted in.
    ///
    /// # Errors
    /// A malformed `*NODE` line, a node of the set the deck does not list, or a set that is not a
    /// line of quadratic elements.
    pub fn interface_mesh(&self) -> Result<InterfaceMesh, ResultsError> {
        let set = deck_face(self.header.inputs.kind()).interface_set();
        let nodes = parse_nodes(self.deck)?;
        let ids = parse_node_sets(self.deck).remove(set).unwrap_or_default();
        let xs: Vec<f64> = ids
            .iter()
            .map(|&id| node_coordinate(&nodes, id).map(|c| c[0]))
            .collect::<Result<_, _>>()?;
        InterfaceMesh::from_quadratic_nodes(&xs).ok_or_else(|| {
            ResultsError::Missing(format!(
                "set {set} of the deck is not a line of quadratic elements ({} nodes)",
                xs.len()
            ))
        })
    }
}

/// A CalculiX run's `.dat` read against its deck: what every problem's reader starts from (the
/// `.dat`'s displacement blocks, the deck's node coordinates and node sets), read in that order
/// so that a broken `.dat` is named before a broken deck.
#[derive(Debug, Clone)]
pub(crate) struct DatRead {
    /// The displacement blocks of the `.dat`.
    pub(crate) blocks: Vec<DatBlock>,
    /// The deck's node coordinates (mm).
    pub(crate) nodes: HashMap<usize, [f64; 3]>,
    /// The deck's node sets, by upper-case name.
    pub(crate) sets: HashMap<String, Vec<usize>>,
}

/// What a `.dat` that lacks a result probably is, said after what it lacks.
pub(crate) const NOT_FINISHED: &str = "(did ccx finish, and is this the .dat of this deck?)";

impl DatRead {
    /// The `.dat` text `dat` of a run of the deck text `deck`.
    ///
    /// # Errors
    /// A malformed `.dat` line, or a deck without nodes or with a malformed `*NODE` line.
    pub(crate) fn of(deck: &str, dat: &str) -> Result<DatRead, ResultsError> {
        let blocks = parse_dat(dat)?;
        let nodes = parse_nodes(deck)?;
        let sets = parse_node_sets(deck);
        Ok(DatRead {
            blocks,
            nodes,
            sets,
        })
    }

    /// The block of `set` at `time`, checked complete against the deck ([`complete_block`]).
    ///
    /// # Errors
    /// What is missing, in words, for the caller to place.
    pub(crate) fn block(&self, set: &str, time: f64) -> Result<&DatBlock, String> {
        complete_block(&self.blocks, &self.sets, set, time)
    }
}

impl CcxRun<'_> {
    /// The run's `.dat` read against its deck ([`DatRead::of`]).
    ///
    /// # Errors
    /// As [`DatRead::of`].
    pub(crate) fn read(&self) -> Result<DatRead, ResultsError> {
        DatRead::of(self.deck, self.dat)
    }
}

/// One load step of a deck's header, as a reader of its run walks them ([`CcxRun::load_steps`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LoadStep<'a> {
    /// The load's index (from 0).
    n: usize,
    /// The header's loads.
    loads: &'a [f64],
    /// The load (the header's unit: the problem's load).
    pub(crate) force: f64,
    /// The total time at the step's end.
    pub(crate) time: f64,
}

impl LoadStep<'_> {
    /// "load step 2 of 4 (F = 100 N, time 3)", for error messages ([`load_step_label`]).
    pub(crate) fn label(&self) -> String {
        load_step_label(self.n, self.loads)
    }
}

impl CcxRun<'_> {
    /// The load steps of the deck's header, in order.
    pub(crate) fn load_steps(&self) -> impl Iterator<Item = LoadStep<'_>> {
        let loads = &self.header.loads;
        (0..loads.len()).map(move |n| LoadStep {
            n,
            loads,
            force: loads[n],
            time: load_step_time(n),
        })
    }
}

/// A load step's result missing from a `.dat` after `read` of the deck's `loads` load steps were
/// read: `why` (which names the step), how many the `.dat` holds, and what that suggests.
pub(crate) fn cut_short(why: &str, read: usize, loads: usize) -> ResultsError {
    ResultsError::Missing(format!(
        "{why}; the .dat holds {read} of the deck's {loads} load steps {NOT_FINISHED}"
    ))
}

/// The total time at the end of load `n` (from 0) of a deck: step 1 applies the pressure, load n
/// ends step n + 2, at total time n + 2.
pub(crate) fn load_step_time(n: usize) -> f64 {
    (n + 2) as f64
}

/// "load step 2 of 4 (F = 100 N, time 3)": load `n` (from 0) of `loads`, for error messages.
pub(crate) fn load_step_label(n: usize, loads: &[f64]) -> String {
    format!(
        "load step {} of {} (F = {} N, time {})",
        n + 1,
        loads.len(),
        Compact(loads[n]),
        load_step_time(n)
    )
}

fn find<'a>(blocks: &'a [DatBlock], set: &str, time: f64) -> Option<&'a DatBlock> {
    // Blocks are printed at every increment; the last one at the step's end time is the result.
    blocks
        .iter()
        .rev()
        .find(|b| b.set.eq_ignore_ascii_case(set) && (b.time - time).abs() < 1e-6 * time.max(1.0))
}

/// The block of `set` at `time`, checked against the deck: exactly the nodes the deck's `*NSET`
/// lists, each once. A `.dat` cut short, or edited, fails here with what is missing, instead of
/// giving a mean or a profile over part of the set (a plate `.dat` cut inside its `UEND` block
/// used to give a thickness mean 40 % low and an implied K_T 70 times too stiff).
pub(crate) fn complete_block<'a>(
    blocks: &'a [DatBlock],
    deck_sets: &HashMap<String, Vec<usize>>,
    set: &str,
    time: f64,
) -> Result<&'a DatBlock, String> {
    let block = find(blocks, set, time).ok_or_else(|| format!("no displacements of set {set}"))?;
    let Some(expected) = deck_sets.get(&set.to_ascii_uppercase()) else {
        return Err(format!("the deck has no *NSET {set}"));
    };
    let mut found: Vec<usize> = block.rows.iter().map(|(id, _)| *id).collect();
    found.sort_unstable();
    let mut wanted = expected.clone();
    wanted.sort_unstable();
    if found == wanted {
        return Ok(block);
    }
    let missing = wanted
        .iter()
        .filter(|id| found.binary_search(id).is_err())
        .count();
    let mut unique = found.clone();
    unique.dedup();
    let repeated = found.len() - unique.len();
    let foreign = unique
        .iter()
        .filter(|id| wanted.binary_search(id).is_err())
        .count();
    let mut problems = Vec::new();
    if missing > 0 {
        problems.push(format!("{missing} missing"));
    }
    if repeated > 0 {
        problems.push(format!("{repeated} repeated"));
    }
    if foreign > 0 {
        problems.push(format!("{foreign} not in the set"));
    }
    Err(format!(
        "set {set} has {} rows for the deck's {} nodes ({})",
        found.len(),
        wanted.len(),
        problems.join(", ")
    ))
}

/// The data lines of a deck, each with its 0-based line index and the keyword card it belongs to
/// (`*NODE, NSET=NALL`); comments (`**`) and blank lines are skipped, as are data lines before any
/// keyword.
fn deck_data_lines(deck: &str) -> impl Iterator<Item = (usize, &str, &str)> {
    let mut keyword = None;
    deck.lines().enumerate().filter_map(move |(index, line)| {
        let trimmed = line.trim();
        if trimmed.starts_with("**") || trimmed.is_empty() {
            return None;
        }
        if trimmed.starts_with('*') {
            keyword = Some(trimmed);
            return None;
        }
        keyword.map(|card| (index, card, trimmed))
    })
}

/// The keyword of a card (`*NODE` of `*NODE, NSET=NALL`) is `name`, in any case.
fn card_is(card: &str, name: &str) -> bool {
    card.split(',')
        .next()
        .is_some_and(|k| k.trim().eq_ignore_ascii_case(name))
}

/// The node sets a deck defines (`*NSET, NSET=NAME` then node numbers), by upper-case name.
pub(crate) fn parse_node_sets(deck: &str) -> HashMap<String, Vec<usize>> {
    let mut found: HashMap<String, Vec<usize>> = HashMap::new();
    for (_, card, data) in deck_data_lines(deck).filter(|(_, card, _)| card_is(card, "*NSET")) {
        let name = card
            .split(',')
            .filter_map(|f| f.split_once('='))
            .find(|(k, _)| k.trim().eq_ignore_ascii_case("NSET"))
            .map(|(_, name)| name.trim().to_ascii_uppercase());
        if let Some(name) = name {
            let ids = data
                .split(',')
                .filter_map(|f| f.trim().parse::<usize>().ok());
            found.entry(name).or_default().extend(ids);
        }
    }
    found
}

pub(crate) fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, count) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    sum / count.max(1) as f64
}

pub(crate) fn node_coordinate(
    nodes: &HashMap<usize, [f64; 3]>,
    id: usize,
) -> Result<[f64; 3], ResultsError> {
    nodes.get(&id).copied().ok_or_else(|| {
        ResultsError::Missing(format!(
            "node {id} of the .dat is not in the deck's *NODE list: the .dat is of another deck"
        ))
    })
}

/// Positions x (mm) and slips |u_other - u| (mm) along an interface, in x order. `other` is the
/// facing surface's node set (same x positions); `None` for a fixed rigid plane.
pub(crate) fn relative_slip(
    nodes: &HashMap<usize, [f64; 3]>,
    own: &DatBlock,
    other: Option<&DatBlock>,
) -> Result<(Vec<f64>, Vec<f64>), ResultsError> {
    let mut points: Vec<(f64, f64)> = Vec::with_capacity(own.rows.len());
    for (n, (id, u)) in own.rows.iter().enumerate() {
        let x = node_coordinate(nodes, *id)?[0];
        let facing = match other {
            Some(block) => {
                let (other_id, v) = block.rows.get(n).ok_or_else(|| {
                    ResultsError::Missing(format!(
                        "sets {} and {} differ in length",
                        own.set, block.set
                    ))
                })?;
                let other_x = node_coordinate(nodes, *other_id)?[0];
                if (other_x - x).abs() > 1e-9 * x.abs().max(1.0) {
                    return Err(ResultsError::Missing(format!(
                        "nodes {id} and {other_id} do not face each other (x = {x} and {other_x})"
                    )));
                }
                v[0]
            }
            None => 0.0,
        };
        points.push((x, (facing - u[0]).abs()));
    }
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(points.into_iter().unzip())
}

/// The regime and the start of the macroslip zone at the free end from a slip profile: macroslip
/// where |s| >= the saturation slip mu P / K_T. The start is found walking from the free end toward
/// x = 0 and interpolated linearly between the last sliding node and the first one that does not.
pub(crate) fn interface_state(xs: &[f64], slips: &[f64], saturation: f64) -> FeInterface {
    let n = xs.len();
    let last = n.saturating_sub(1);
    if n == 0 || slips[last] < saturation {
        return FeInterface {
            macroslip_start: xs.last().copied().unwrap_or(0.0),
            regime: Regime::MICROSLIP,
        };
    }
    let mut i = last;
    while i > 0 && slips[i - 1] >= saturation {
        i -= 1;
    }
    if i == 0 {
        return FeInterface {
            macroslip_start: xs[0],
            regime: Regime::MACROSLIP,
        };
    }
    let (x0, x1, s0, s1) = (xs[i - 1], xs[i], slips[i - 1], slips[i]);
    let start = x0 + (x1 - x0) * (saturation - s0) / (s1 - s0);
    FeInterface {
        macroslip_start: start,
        regime: Regime::MICROSLIP_MACROSLIP,
    }
}

/// The (y, u_x) of a block's nodes, which make one column through a thickness (x fixed), sorted
/// by y: the corner and mid-side nodes of a column of quadratic elements, an odd number, 3 or
/// more.
pub(crate) fn column_of(
    nodes: &HashMap<usize, [f64; 3]>,
    block: &DatBlock,
) -> Result<Vec<(f64, f64)>, ResultsError> {
    let mut column: Vec<(f64, f64)> = block
        .rows
        .iter()
        .map(|(id, u)| node_coordinate(nodes, *id).map(|c| (c[1], u[0])))
        .collect::<Result<_, _>>()?;
    column.sort_by(|a, b| a.0.total_cmp(&b.0));
    if column.len() < 3 || column.len().is_multiple_of(2) {
        return Err(ResultsError::Missing(format!(
            "set {} has {} nodes; a column of quadratic elements has an odd number, 3 or more",
            block.set,
            column.len()
        )));
    }
    Ok(column)
}

/// The thickness mean of u_x over a column ([`column_of`]): Simpson's rule over each quadratic
/// element gives it exactly for the element's field.
pub(crate) fn simpson_mean(column: &[(f64, f64)]) -> f64 {
    let thickness = column[column.len() - 1].0 - column[0].0;
    column
        .windows(3)
        .step_by(2)
        .map(|w| (w[2].0 - w[0].0) * (w[0].1 + 4.0 * w[1].1 + w[2].1) / 6.0)
        .sum::<f64>()
        / thickness
}

/// The thickness mean of u_x over a block's column of nodes.
pub(crate) fn thickness_mean(
    nodes: &HashMap<usize, [f64; 3]>,
    block: &DatBlock,
) -> Result<f64, ResultsError> {
    column_of(nodes, block).map(|c| simpson_mean(&c))
}

/// Positions x (mm) and slips u_inner - u_cover (mm, signed) along the lap joint's interface, in
/// x order: the two sets' nodes paired by position (the `.dat` lists them by node number, which
/// need not follow x in both bodies the same way).
pub(crate) fn facing_slip(
    nodes: &HashMap<usize, [f64; 3]>,
    inner: &DatBlock,
    cover: &DatBlock,
) -> Result<(Vec<f64>, Vec<f64>), ResultsError> {
    facing_slip_along(nodes, inner, cover, 0)
}

/// [`facing_slip`] along the coordinate `axis` (0 for x; 1 for the axis of an axisymmetric deck,
/// whose first coordinate is the radius): positions and slips `own - other` in that coordinate
/// and that displacement component.
pub(crate) fn facing_slip_along(
    nodes: &HashMap<usize, [f64; 3]>,
    own: &DatBlock,
    other: &DatBlock,
    axis: usize,
) -> Result<(Vec<f64>, Vec<f64>), ResultsError> {
    let along = |block: &DatBlock| -> Result<Vec<(f64, usize, f64)>, ResultsError> {
        let mut line: Vec<(f64, usize, f64)> = block
            .rows
            .iter()
            .map(|(id, u)| node_coordinate(nodes, *id).map(|c| (c[axis], *id, u[axis])))
            .collect::<Result<_, _>>()?;
        line.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(line)
    };
    let (own_line, other_line) = (along(own)?, along(other)?);
    if own_line.len() != other_line.len() {
        return Err(ResultsError::Missing(format!(
            "sets {} and {} differ in length",
            own.set, other.set
        )));
    }
    let mut xs = Vec::with_capacity(own_line.len());
    let mut slips = Vec::with_capacity(own_line.len());
    for (&(x, id, u), &(other_x, other_id, v)) in own_line.iter().zip(&other_line) {
        if (other_x - x).abs() > 1e-9 * x.abs().max(1.0) {
            return Err(ResultsError::Missing(format!(
                "nodes {id} and {other_id} do not face each other (x = {x} and {other_x})"
            )));
        }
        xs.push(x);
        slips.push(u - v);
    }
    Ok((xs, slips))
}

/// The sliding zones of a slip profile with two ends, both of which may slide: where
/// |s| >= `saturation` (mu p / K_T), contiguous from the first position and from the last, each
/// end interpolated linearly between the last sliding node and the first that does not. A
/// profile sliding throughout gives the whole length from the start, counted once.
pub(crate) fn sliding_zones(xs: &[f64], slips: &[f64], saturation: f64) -> (f64, f64) {
    let n = xs.len();
    let sliding = |i: usize| slips[i].abs() >= saturation;
    let crossing = |inside: usize, outside: usize| {
        let (s0, s1) = (slips[inside].abs(), slips[outside].abs());
        xs[inside] + (xs[outside] - xs[inside]) * (s0 - saturation) / (s0 - s1)
    };
    let (start, end) = (
        xs.first().copied().unwrap_or(0.0),
        xs.last().copied().unwrap_or(0.0),
    );
    let length = end - start;
    let mut from_start = 0.0;
    if n > 0 && sliding(0) {
        let mut i = 0;
        while i + 1 < n && sliding(i + 1) {
            i += 1;
        }
        from_start = if i + 1 == n {
            length
        } else {
            crossing(i, i + 1) - start
        };
    }
    let mut from_end = 0.0;
    if n > 0 && sliding(n - 1) {
        let mut i = n - 1;
        while i > 0 && sliding(i - 1) {
            i -= 1;
        }
        from_end = if i == 0 {
            length
        } else {
            end - crossing(i, i - 1)
        };
    }
    if from_start + from_end >= length {
        (from_start.min(length), (length - from_start).max(0.0))
    } else {
        (from_start, from_end)
    }
}

/// The displacement blocks of a `.dat` file. A block starts with a line like
/// ` displacements (vx,vy,vz) for set WTIP and time  0.2000000E+01` and holds rows
/// `node vx vy vz`; blocks of other quantities are skipped.
pub(crate) fn parse_dat(text: &str) -> Result<Vec<DatBlock>, ResultsError> {
    let mut blocks: Vec<DatBlock> = Vec::new();
    let mut in_block = false;
    for (index, line) in text.lines().enumerate() {
        let fail = |problem: String| ResultsError::Line {
            line: index + 1,
            problem,
        };
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(rest) = trimmed.strip_prefix("displacements (vx,vy,vz) for set ") {
            let (set, time) = rest
                .split_once(" and time")
                .ok_or_else(|| fail("a displacement header without 'and time'".into()))?;
            let time = time.trim();
            let time = time
                .parse::<f64>()
                .ok()
                .filter(|t| t.is_finite())
                .ok_or_else(|| fail(format!("time '{time}' is not a number")))?;
            blocks.push(DatBlock {
                set: set.trim().to_string(),
                time,
                rows: Vec::new(),
            });
            in_block = true;
            continue;
        }
        let fields: Vec<&str> = trimmed.split_whitespace().collect();
        let is_row = fields.first().is_some_and(|f| f.parse::<usize>().is_ok());
        match blocks.last_mut() {
            Some(block) if in_block && is_row => {
                if fields.len() != 4 {
                    return Err(fail(format!(
                        "expected a node and 3 displacements, found {} fields",
                        fields.len()
                    )));
                }
                let mut u = [0.0; 3];
                for (slot, text) in u.iter_mut().zip(&fields[1..]) {
                    *slot = text
                        .parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite())
                        .ok_or_else(|| fail(format!("'{text}' is not a finite number")))?;
                    if !Domain::DISPLACEMENT.contains(*slot) {
                        return Err(fail(format!(
                            "displacement {text} is not one: {}",
                            Domain::DISPLACEMENT.describe(Unit::Millimetre)
                        )));
                    }
                }
                let id = fields[0].parse().unwrap_or_default();
                block.rows.push((id, u));
            }
            _ => in_block = false,
        }
    }
    // CalculiX ends every line it writes; a last line without its end was cut, and its last number
    // may be cut inside its exponent ("1.99E-05" read as "1.99E-0").
    if !text.is_empty() && !text.ends_with('\n') {
        return Err(ResultsError::Line {
            line: text.lines().count(),
            problem: "the file ends inside this line: it was cut short (a run still writing, or \
                      a copy that did not finish)"
                .into(),
        });
    }
    Ok(blocks)
}

/// The node coordinates of a deck's `*NODE` sections (mm).
pub(crate) fn parse_nodes(deck: &str) -> Result<HashMap<usize, [f64; 3]>, ResultsError> {
    let mut nodes = HashMap::new();
    for (index, _, trimmed) in deck_data_lines(deck).filter(|(_, card, _)| card_is(card, "*NODE")) {
        let fail = |problem: String| ResultsError::Line {
            line: index + 1,
            problem: format!("deck: {problem}"),
        };
        let fields: Vec<&str> = trimmed.split(',').map(str::trim).collect();
        let id = fields[0]
            .parse::<usize>()
            .map_err(|_| fail(format!("'{}' is not a node number", fields[0])))?;
        let mut c = [0.0; 3];
        for (axis, slot) in c.iter_mut().enumerate() {
            let text = fields.get(axis + 1).copied().unwrap_or("0");
            *slot = text
                .parse::<f64>()
                .map_err(|_| fail(format!("coordinate '{text}' is not a number")))?;
        }
        nodes.insert(id, c);
    }
    if nodes.is_empty() {
        return Err(ResultsError::Missing(
            "the deck has no *NODE section".into(),
        ));
    }
    Ok(nodes)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DAT: &str = "
 displacements (vx,vy,vz) for set WTIP and time  0.1000000E+01

       253  2.778075E-04  4.785714E-05 -1.428571E-05
       811  2.778075E-04  4.785714E-05  1.428571E-05

 stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set LOWER and time  0.1000000E+01

         1   1  1.0  2.0  3.0  4.0  5.0  6.0

 displacements (vx,vy,vz) for set WTIP and time  0.2000000E+01

       253  1.0E-02  1.1E-02 0.0
       811  1.0E-02  1.3E-02 0.0
";

    #[test]
    fn dat_blocks_are_read_and_other_quantities_skipped() {
        let blocks = parse_dat(DAT).unwrap();
        assert_eq!(blocks.len(), 2);
        assert_eq!(blocks[0].set, "WTIP");
        assert_eq!(blocks[1].time, 2.0);
        assert_eq!(
            blocks[1].rows,
            vec![(253, [1e-2, 1.1e-2, 0.0]), (811, [1e-2, 1.3e-2, 0.0])]
        );
        assert!((mean(blocks[1].rows.iter().map(|r| r.1[1])) - 1.2e-2).abs() < 1e-15);
    }

    #[test]
    fn a_broken_dat_line_is_named() {
        let broken = DAT.replace("1.1E-02", "1.1E-0x");
        assert_eq!(
            parse_dat(&broken).unwrap_err().to_string(),
            "line 13: '1.1E-0x' is not a finite number"
        );
        let short = DAT.replace("  1.3E-02 0.0", "");
        assert!(
            parse_dat(&short)
                .unwrap_err()
                .to_string()
                .starts_with("line 14: expected a node")
        );
    }

    #[test]
    fn macroslip_start_is_interpolated_from_the_free_end() {
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        // Saturation 1: the slip crosses it between x = 2 (0.5) and x = 3 (1.5).
        let state = interface_state(&xs, &[0.0, 0.2, 0.5, 1.5, 3.0], 1.0);
        assert_eq!(state.regime, Regime::MICROSLIP_MACROSLIP);
        assert!((state.macroslip_start - 2.5).abs() < 1e-12);
        let none = interface_state(&xs, &[0.0, 0.1, 0.2, 0.3, 0.9], 1.0);
        assert_eq!(
            (none.macroslip_start, none.regime),
            (4.0, Regime::MICROSLIP)
        );
        let all = interface_state(&xs, &[1.0, 1.1, 1.2, 1.3, 1.4], 1.0);
        assert_eq!((all.macroslip_start, all.regime), (0.0, Regime::MACROSLIP));
    }

    #[test]
    fn facing_sets_pair_by_position_not_by_node_number() {
        let mut nodes = HashMap::new();
        for (id, x) in [
            (1, 0.0),
            (2, 1.0),
            (3, 2.0),
            (10, 2.0),
            (11, 1.0),
            (12, 0.0),
        ] {
            nodes.insert(id, [x, 0.0, 0.0]);
        }
        let block = |set: &str, rows: &[(usize, f64)]| DatBlock {
            set: set.into(),
            time: 1.0,
            rows: rows.iter().map(|&(id, u)| (id, [u, 0.0, 0.0])).collect(),
        };
        let inner = block("IFINNER", &[(1, 0.5), (2, 0.6), (3, 0.7)]);
        let cover = block("IFCOVER", &[(10, 0.1), (11, 0.2), (12, 0.3)]);
        let (xs, slips) = facing_slip(&nodes, &inner, &cover).unwrap();
        assert_eq!(xs, [0.0, 1.0, 2.0]);
        let expected = [0.5 - 0.3, 0.6 - 0.2, 0.7 - 0.1];
        assert!(
            slips
                .iter()
                .zip(expected)
                .all(|(s, e)| (s - e).abs() < 1e-15)
        );
        nodes.insert(12, [0.5, 0.0, 0.0]);
        let error = facing_slip(&nodes, &inner, &cover).unwrap_err();
        assert!(
            error.to_string().contains("do not face each other"),
            "{error}"
        );
    }

    #[test]
    fn a_column_mean_is_simpsons_rule() {
        // u = y^2 over [0, 2] in two quadratic elements: the mean of y^2 is 4/3, exactly.
        let column = [(0.0, 0.0), (0.5, 0.25), (1.0, 1.0), (1.5, 2.25), (2.0, 4.0)];
        assert!((simpson_mean(&column) - 4.0 / 3.0).abs() < 1e-15);
    }

    #[test]
    fn deck_nodes_are_read() {
        let deck = "** c\n*NODE, NSET=NALL\n1, 0.0, -20.0, 0.0\n2, 2.5e-1, 1., 3\n*ELEMENT, TYPE=C3D20R\n1, 2, 3\n";
        let nodes = parse_nodes(deck).unwrap();
        assert_eq!(nodes[&2], [0.25, 1.0, 3.0]);
        assert_eq!(nodes.len(), 2);
        assert!(
            parse_nodes("*NODE\nx, 1, 2, 3\n")
                .unwrap_err()
                .to_string()
                .contains("'x' is not a node number")
        );
    }
}
