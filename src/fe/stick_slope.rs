//! The stick slope an FE code really used, read from its own interface output (issue 33, item 1).
//!
//! Under the regularized Coulomb law a node that sticks carries a shear stress proportional to its
//! slip, tau = K_T s, with the slope the contact was given; one that slides carries mu p. So over
//! the nodes that stick, CSHEAR / CSLIP *is* the stick slope the code used, whatever the deck says
//! and whatever the beam or plate theory says: a judge that sees the contact itself, sharp to the
//! digits the code prints (CalculiX's `.frd` prints 6: the ratio is exact to about 1e-5 on every
//! bundled deck, docs/theory.md "The stick slope the FE code used").
//!
//! - [`read_frd_contact`]: the `CONTACT` blocks (COPEN, CSLIP1/2, CPRESS, CSHEAR1/2 per slave node)
//!   that the decks' `*CONTACT FILE` / `CDIS, CSTR` write to the `.frd`, the last one of each step.
//! - [`read_interface_csv`]: the same from any code, as CSV `x_mm,slip_mm,shear_MPa` per load step.
//! - [`step_slope`]: which nodes stick and the slope over them, with its spread.
//! - [`StickSlopeUsed`]: every step's slope, the one the verdict reads, and the verdict.
//!
//! Which nodes stick: in contact (CPRESS > 0), with a shear below the friction limit by a margin
//! (|CSHEAR| < (1 - [`STICK_MARGIN`]) mu CPRESS: a node at the limit may be sliding, and its ratio
//! is then no slope), and with a slip that is not ~0 ([`MIN_SLIP_SHARE`] of the step's largest:
//! a clamped or symmetric node has 0 / 0). The slope of a node is the projection
//! (CSHEAR . CSLIP) / |CSLIP|^2, signed: an output whose shear and slip have opposite signs gives
//! a negative slope, never a plausible one. The step's slope is the median over its sticking
//! nodes: near the clamp and at the edge of the slip zone, a node whose element holds both
//! sticking and sliding integration points has an extrapolated ratio that is not the slope (the
//! paper's beams: 2 to 13 % of the sticking nodes at 1.25 to 2.5 F_thre), and the median does not
//! follow them.

use std::collections::BTreeMap;
use std::io::BufRead;

use super::results::ResultsError;

/// The relative margin below the friction limit a node must keep to count as sticking.
pub const STICK_MARGIN: f64 = 0.1;

/// A slip below this share of the step's largest is ~0: its ratio is 0 / 0.
pub const MIN_SLIP_SHARE: f64 = 1e-3;

/// How far the used stick slope may be from the deck's K_T and agree (a fraction).
///
/// Measured on the unedited bundled decks (validation/calculix/RESULTS.md, "Stick slope used"):
/// the median of CSHEAR / CSLIP is within 0.0001 % of the deck's K_T (or of the edited slope) at
/// the step the verdict reads, and its quartiles within 0.0003 %: the
/// `.frd`'s 6 printed digits. 1 % is 500 times that, so that another code's contact elements
/// (whose nodal values are extrapolated differently) and a mesh whose stick zone is short are not
/// refused for noise, and it is a tenth of the 10 % edits, which it resolves with a wide
/// margin.
pub const STICK_SLOPE_TOLERANCE: f64 = 0.01;

/// The least sticking nodes a step needs for its slope to be given.
pub const MIN_STICKING_NODES: usize = 3;

/// One node's (or one profile point's) interface state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactNode {
    /// Node number (the CSV's row number).
    pub node: usize,
    /// Tangential slip, two components (mm).
    pub slip: [f64; 2],
    /// Contact pressure (MPa); `None` where the output has none (CSV): the nominal pressure of the
    /// model is used.
    pub pressure: Option<f64>,
    /// Tangential shear stress, two components (MPa).
    pub shear: [f64; 2],
}

/// The interface at the end of one step.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactStep {
    /// The FE code's step number (CalculiX: from 1, step 1 the pressure alone; CSV: the load
    /// step's number as given).
    pub step: usize,
    /// The step's end time (CalculiX's total time; CSV: the step number).
    pub time: f64,
    /// The nodes in the output.
    pub nodes: Vec<ContactNode>,
}

/// One step's stick slope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepSlope {
    /// The step ([`ContactStep::step`]).
    pub step: usize,
    /// Its end time.
    pub time: f64,
    /// Nodes counted as sticking.
    pub sticking: usize,
    /// Nodes in contact (pressure > 0, or every node of a CSV).
    pub in_contact: usize,
    /// The median of CSHEAR / CSLIP over the sticking nodes (MPa/mm).
    pub used: f64,
    /// Its lower and upper quartiles over the sticking nodes (MPa/mm): the spread. Quartiles, not
    /// wider percentiles: near a clamp and at the edge of a slip zone up to an eighth of the
    /// sticking nodes have disturbed ratios (the paper's beams at 2.5 F_thre), and the spread
    /// should say how well the slope is told, not how many nodes sit at an edge.
    pub low: f64,
    /// See [`StepSlope::low`].
    pub high: f64,
}

impl StepSlope {
    /// The spread as fractions of the median: (low / median - 1, high / median - 1).
    pub fn spread(&self) -> (f64, f64) {
        (self.low / self.used - 1.0, self.high / self.used - 1.0)
    }
}

/// The friction law the stick test reads: mu, and the pressure to use where the output has none.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    /// The friction coefficient the FE code was given (-).
    pub coefficient: f64,
    /// The nominal contact pressure (MPa), for outputs without one (CSV).
    pub nominal_pressure: f64,
}

/// The slope of one step over its sticking nodes; `None` when fewer than
/// [`MIN_STICKING_NODES`] stick.
pub fn step_slope(step: &ContactStep, friction: Friction) -> Option<StepSlope> {
    let norm = |v: [f64; 2]| v[0].hypot(v[1]);
    let pressure = |n: &ContactNode| n.pressure.unwrap_or(friction.nominal_pressure);
    let in_contact: Vec<&ContactNode> = step.nodes.iter().filter(|n| pressure(n) > 0.0).collect();
    let largest = in_contact
        .iter()
        .map(|n| norm(n.slip))
        .fold(0.0_f64, f64::max);
    let mut slopes: Vec<f64> = in_contact
        .iter()
        .filter(|n| {
            let slip = norm(n.slip);
            slip > MIN_SLIP_SHARE * largest
                && slip > 0.0
                && norm(n.shear) < (1.0 - STICK_MARGIN) * friction.coefficient * pressure(n)
        })
        .map(|n| (n.shear[0] * n.slip[0] + n.shear[1] * n.slip[1]) / norm(n.slip).powi(2))
        .filter(|k| k.is_finite())
        .collect();
    if slopes.len() < MIN_STICKING_NODES {
        return None;
    }
    slopes.sort_by(f64::total_cmp);
    Some(StepSlope {
        step: step.step,
        time: step.time,
        sticking: slopes.len(),
        in_contact: in_contact.len(),
        used: quantile(&slopes, 0.5),
        low: quantile(&slopes, 0.25),
        high: quantile(&slopes, 0.75),
    })
}

/// The `q` quantile of sorted `values` (linear between order statistics), not empty.
fn quantile(values: &[f64], q: f64) -> f64 {
    let at = q * (values.len() - 1) as f64;
    let (below, above) = (at.floor() as usize, at.ceil() as usize);
    values[below] + (at - below as f64) * (values[above] - values[below])
}

/// The stick slope of a run: every step's, and the verdict on it.
#[derive(Debug, Clone, PartialEq)]
pub struct StickSlopeUsed {
    /// The steps with enough sticking nodes, in order.
    pub steps: Vec<StepSlope>,
    /// The K_T the benchmark asks for: the deck header's (MPa/mm).
    pub deck: f64,
    /// The stick slope on the deck's `*FRICTION` card, when it differs from the header's (a deck
    /// edited after it was written).
    pub friction_card: Option<f64>,
}

/// Whether the used stick slope is the deck's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StickSlopeVerdict {
    /// Within [`STICK_SLOPE_TOLERANCE`].
    Agrees,
    /// Farther.
    DoesNotAgree,
    /// No step had enough sticking nodes, or the headline step's quartiles spread beyond the
    /// tolerance: the output does not tell one slope.
    NotJudged,
}

impl StickSlopeVerdict {
    /// A label for JSON.
    pub fn label(self) -> &'static str {
        match self {
            StickSlopeVerdict::Agrees => "agrees",
            StickSlopeVerdict::DoesNotAgree => "does not agree",
            StickSlopeVerdict::NotJudged => "not judged",
        }
    }
}

impl StickSlopeUsed {
    /// The steps of `contact` measured with `friction`, against the deck's K_T `deck`.
    pub fn measure(contact: &[ContactStep], friction: Friction, deck: f64) -> StickSlopeUsed {
        StickSlopeUsed {
            steps: contact
                .iter()
                .filter_map(|s| step_slope(s, friction))
                .collect(),
            deck,
            friction_card: None,
        }
    }

    /// The step the verdict reads: the one with the most sticking nodes (the first of equals),
    /// where the stick zone is longest and the slope least disturbed by the edge of a slip zone.
    pub fn headline(&self) -> Option<&StepSlope> {
        self.steps.iter().rev().max_by_key(|s| s.sticking)
    }

    /// (used - deck) / deck at the headline step.
    pub fn difference(&self) -> Option<f64> {
        self.headline().map(|s| s.used / self.deck - 1.0)
    }

    /// The verdict.
    pub fn verdict(&self) -> StickSlopeVerdict {
        let Some(step) = self.headline() else {
            return StickSlopeVerdict::NotJudged;
        };
        let (low, high) = step.spread();
        if !(low.abs() <= STICK_SLOPE_TOLERANCE && high.abs() <= STICK_SLOPE_TOLERANCE) {
            return StickSlopeVerdict::NotJudged;
        }
        match self.difference() {
            Some(d) if d.abs() <= STICK_SLOPE_TOLERANCE => StickSlopeVerdict::Agrees,
            Some(_) => StickSlopeVerdict::DoesNotAgree,
            None => StickSlopeVerdict::NotJudged,
        }
    }
}

/// The largest `.frd` read for its contact output (4 GiB): a fine deck's is some hundred MB.
pub const MAX_FRD_BYTES: u64 = 4 << 30;

/// The column of each contact quantity in a `CONTACT` block, from its `-5` lines.
#[derive(Debug, Default)]
struct Columns {
    names: Vec<String>,
}

impl Columns {
    fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n.eq_ignore_ascii_case(name))
    }
}

/// The contact state at the end of every step of a CalculiX `.frd` (ASCII), from the `CONTACT`
/// blocks `*CONTACT FILE` with `CDIS, CSTR` writes (one per increment; the last of each step is
/// kept). Nodes whose six values are all 0 (not on a slave face) are left out.
///
/// The columns are found by name (COPEN CSLIP1 CSLIP2 CPRESS CSHEAR1 CSHEAR2), the values by
/// position: 12 characters each after the node number (10), as CalculiX writes them, so that
/// `-4.77814E-07-9.09640E-06` reads as two numbers.
///
/// # Errors
/// A `CONTACT` block without one of the six columns, or a malformed data line (with its number).
pub fn read_frd_contact(reader: impl BufRead) -> Result<Vec<ContactStep>, ResultsError> {
    let mut steps: BTreeMap<usize, ContactStep> = BTreeMap::new();
    let (mut step, mut time) = (0usize, f64::NAN);
    let mut block: Option<(Columns, Vec<ContactNode>)> = None;
    for (index, line) in reader.lines().enumerate() {
        let line = line.map_err(|e| ResultsError::Missing(format!("the .frd: {e}")))?;
        let fail = |problem: String| ResultsError::Line {
            line: index + 1,
            problem: format!(".frd: {problem}"),
        };
        let trimmed = line.trim_start();
        if trimmed.starts_with("1PSTEP") {
            // "    1PSTEP   4   1   2": result block, increment, step.
            step = trimmed
                .split_whitespace()
                .nth(3)
                .and_then(|s| s.parse().ok())
                .ok_or_else(|| fail(format!("a step line without a step number: {trimmed}")))?;
        } else if trimmed.starts_with("100C") {
            // "  100CL  102 2.000000000  2344 ...": ' 100', 'C', a 6-character name, then the
            // time in 12 characters (columns 13 to 24).
            time = line
                .get(12..24)
                .and_then(|s| s.trim().parse().ok())
                .filter(|t: &f64| t.is_finite())
                .ok_or_else(|| fail(format!("a block header without a time: {trimmed}")))?;
        } else if let Some(rest) = trimmed.strip_prefix("-4 ") {
            block = (rest.split_whitespace().next() == Some("CONTACT"))
                .then(|| (Columns::default(), Vec::new()));
        } else if let Some(rest) = trimmed.strip_prefix("-5 ") {
            if let Some((columns, _)) = block.as_mut() {
                let name = rest.split_whitespace().next().unwrap_or_default();
                columns.names.push(name.to_string());
            }
        } else if line.starts_with(" -1")
            && let Some((columns, nodes)) = block.as_mut()
        {
            if let Some(node) = contact_row(&line, columns).map_err(fail)? {
                nodes.push(node);
            }
        } else if trimmed.starts_with("-3")
            && let Some((_, nodes)) = block.take()
        {
            steps.insert(step, ContactStep { step, time, nodes });
        }
    }
    Ok(steps.into_values().collect())
}

/// One data line of a `CONTACT` block; `None` for a node with all six values 0.
fn contact_row(line: &str, columns: &Columns) -> Result<Option<ContactNode>, String> {
    let need = |name: &str| {
        columns.index(name).ok_or_else(|| {
            format!(
                "a CONTACT block without {name} (it has {:?})",
                columns.names
            )
        })
    };
    let [slip1, slip2, pressure, shear1, shear2] = [
        need("CSLIP1")?,
        need("CSLIP2")?,
        need("CPRESS")?,
        need("CSHEAR1")?,
        need("CSHEAR2")?,
    ];
    let field = |from: usize, width: usize| line.get(from..from + width).map(str::trim);
    let node = field(3, 10)
        .and_then(|f| f.parse::<usize>().ok())
        .ok_or_else(|| format!("no node number in '{line}'"))?;
    let value = |column: usize| -> Result<f64, String> {
        let text = field(13 + 12 * column, 12)
            .ok_or_else(|| format!("node {node}: no column {} in '{line}'", column + 1))?;
        text.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("node {node}: '{text}' is not a finite number"))
    };
    let values: Vec<f64> = (0..columns.names.len())
        .map(value)
        .collect::<Result<_, _>>()?;
    if values.iter().all(|v| *v == 0.0) {
        return Ok(None);
    }
    Ok(Some(ContactNode {
        node,
        slip: [values[slip1], values[slip2]],
        pressure: Some(values[pressure]),
        shear: [values[shear1], values[shear2]],
    }))
}

/// The stick slope (second number) and friction coefficient (first) on a deck's `*FRICTION` card.
pub fn friction_card(deck: &str) -> Option<(f64, f64)> {
    let mut lines = deck.lines().map(str::trim);
    lines.find(|l| {
        l.split(',')
            .next()
            .is_some_and(|k| k.trim().eq_ignore_ascii_case("*FRICTION"))
    })?;
    let data = lines.find(|l| !l.starts_with("**") && !l.is_empty())?;
    let mut numbers = data.split(',').map(|f| f.trim().parse::<f64>().ok());
    Some((numbers.next()??, numbers.next()??))
}

/// Whether `deck`'s first step changes the friction (`*CHANGE FRICTION`): a deck that resolves an
/// interference so, nearly frictionless (a shrink fit leaves no shear), lets the bodies slide in
/// it through the interference's Poisson strains without shear. CalculiX's CSLIP keeps that
/// slip, so the slope of the later steps is read from the end of the first
/// ([`slips_from_first_step`]).
pub fn first_step_changes_friction(deck: &str) -> bool {
    let upper = format!("\n{}", deck.to_ascii_uppercase());
    let mut steps = upper.split("\n*STEP").skip(1);
    steps.next().is_some_and(|first| {
        first
            .split("\n*END STEP")
            .next()
            .is_some_and(|body| body.contains("\n*CHANGE FRICTION"))
    })
}

/// `contact`'s steps after the first, each node's slip counted from its slip at the end of the
/// first step (the shear is the later step's own: the first carried none).
pub fn slips_from_first_step(contact: Vec<ContactStep>) -> Vec<ContactStep> {
    let mut steps = contact.into_iter();
    let Some(first) = steps.next() else {
        return Vec::new();
    };
    let start: BTreeMap<usize, [f64; 2]> = first.nodes.iter().map(|n| (n.node, n.slip)).collect();
    steps
        .map(|mut step| {
            for node in &mut step.nodes {
                let [s0, s1] = start.get(&node.node).copied().unwrap_or_default();
                node.slip = [node.slip[0] - s0, node.slip[1] - s1];
            }
            step
        })
        .collect()
}

/// The header of the interface CSV.
pub const INTERFACE_CSV_HEADER: &str = "x_mm,slip_mm,shear_MPa";

/// An interface profile from any FE code: CSV `x_mm,slip_mm,shear_MPa`, one row per interface
/// node, or `step,x_mm,slip_mm,shear_MPa` for several load steps (`step` from 1). Slip and shear
/// are signed along the same axis (the shear the node carries, in the direction of its slip: a
/// sticking node has both of one sign). The rows carry no pressure: a node sticks where
/// |shear| < (1 - [`STICK_MARGIN`]) mu P with the model's nominal P.
///
/// # Errors
/// A header that is neither form, a malformed row (with its line), or no row.
pub fn read_interface_csv(text: &str) -> Result<Vec<ContactStep>, ResultsError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let Some((_, header)) = lines.next() else {
        return Err(ResultsError::Missing(format!(
            "an empty interface file: expected the header {INTERFACE_CSV_HEADER}"
        )));
    };
    let header: Vec<String> = header
        .split(',')
        .map(|h| h.trim().trim_start_matches('\u{feff}').to_ascii_lowercase())
        .collect();
    let joined = header.join(",");
    let one = INTERFACE_CSV_HEADER.to_ascii_lowercase();
    let stepped = match joined.as_str() {
        h if h == one => false,
        h if h.strip_prefix("step,") == Some(one.as_str()) => true,
        other => {
            return Err(ResultsError::Line {
                line: 1,
                problem: format!(
                    "header '{other}': expected {INTERFACE_CSV_HEADER} or step,{INTERFACE_CSV_HEADER}"
                ),
            });
        }
    };
    let mut steps: BTreeMap<usize, ContactStep> = BTreeMap::new();
    for (index, line) in lines {
        let fail = |problem: String| ResultsError::Line {
            line: index + 1,
            problem,
        };
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != header.len() {
            return Err(fail(format!(
                "{} fields, expected {}",
                fields.len(),
                header.len()
            )));
        }
        let number = |i: usize| {
            fields[i]
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| fail(format!("{} = '{}' is not a number", header[i], fields[i])))
        };
        let step = if stepped {
            fields[0]
                .parse::<usize>()
                .ok()
                .filter(|s| *s >= 1)
                .ok_or_else(|| fail(format!("step '{}' is not a whole number >= 1", fields[0])))?
        } else {
            1
        };
        let first = usize::from(stepped);
        number(first)?;
        let (slip, shear) = (number(first + 1)?, number(first + 2)?);
        let entry = steps.entry(step).or_insert_with(|| ContactStep {
            step,
            time: step as f64,
            nodes: Vec::new(),
        });
        entry.nodes.push(ContactNode {
            node: index + 1,
            slip: [slip, 0.0],
            pressure: None,
            shear: [shear, 0.0],
        });
    }
    if steps.is_empty() {
        return Err(ResultsError::Missing(
            "the interface file has a header and no row".into(),
        ));
    }
    Ok(steps.into_values().collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(slip: f64, pressure: f64, shear: f64) -> ContactNode {
        ContactNode {
            node: 0,
            slip: [slip, 0.0],
            pressure: Some(pressure),
            shear: [shear, 0.0],
        }
    }

    const FRICTION: Friction = Friction {
        coefficient: 0.3,
        nominal_pressure: 1.0,
    };

    #[test]
    fn sliding_and_slipless_nodes_are_left_out() {
        let k = 600.0;
        let mut nodes: Vec<ContactNode> = (1..=5)
            .map(|i| node(1e-5 * f64::from(i), 1.0, k * 1e-5 * f64::from(i)))
            .collect();
        // At the friction limit (sliding: slip beyond the elastic one), open, and no slip.
        nodes.push(node(1e-3, 1.0, 0.3));
        nodes.push(node(1e-5, 0.0, 0.0));
        nodes.push(node(0.0, 1.0, 0.0));
        let step = ContactStep {
            step: 2,
            time: 2.0,
            nodes,
        };
        let slope = step_slope(&step, FRICTION).unwrap();
        assert_eq!((slope.sticking, slope.in_contact), (5, 7));
        assert!((slope.used / k - 1.0).abs() < 1e-12, "{slope:?}");
    }

    #[test]
    fn the_median_does_not_follow_a_few_disturbed_nodes() {
        let mut nodes: Vec<ContactNode> = (1..=20)
            .map(|i| node(1e-5, 1.0 + 0.01 * f64::from(i), 6e-3))
            .collect();
        nodes[0].shear = [1e-3, 0.0];
        nodes[1].shear = [2e-3, 0.0];
        let step = ContactStep {
            step: 3,
            time: 3.0,
            nodes,
        };
        let slope = step_slope(&step, FRICTION).unwrap();
        assert!((slope.used / 600.0 - 1.0).abs() < 1e-12);
        let used = StickSlopeUsed::measure(&[step], FRICTION, 600.0);
        assert_eq!(used.verdict(), StickSlopeVerdict::Agrees);
        let edited = StickSlopeUsed {
            deck: 545.0,
            ..used
        };
        assert_eq!(edited.verdict(), StickSlopeVerdict::DoesNotAgree);
    }

    #[test]
    fn nodes_that_do_not_tell_one_slope_are_not_judged() {
        // Ratios from 400 to 800 MPa/mm, evenly: quartiles at -17 % and +17 % of the median.
        let nodes: Vec<ContactNode> = (0..=20)
            .map(|i| node(1e-5, 1.0, (400.0 + 20.0 * f64::from(i)) * 1e-5))
            .collect();
        let step = ContactStep {
            step: 2,
            time: 2.0,
            nodes,
        };
        let used = StickSlopeUsed::measure(&[step], FRICTION, 600.0);
        assert!((used.headline().unwrap().used - 600.0).abs() < 1e-9);
        assert_eq!(used.verdict(), StickSlopeVerdict::NotJudged);
        let none = StickSlopeUsed::measure(&[], FRICTION, 600.0);
        assert_eq!(none.verdict(), StickSlopeVerdict::NotJudged);
    }

    #[test]
    fn a_slip_opposite_to_its_shear_is_a_negative_slope() {
        let nodes: Vec<ContactNode> = (1..=4)
            .map(|i| node(-1e-5 * f64::from(i), 1.0, 6e-3 * f64::from(i)))
            .collect();
        let step = ContactStep {
            step: 2,
            time: 2.0,
            nodes,
        };
        let used = StickSlopeUsed::measure(&[step], FRICTION, 600.0);
        assert!((used.headline().unwrap().used + 600.0).abs() < 1e-9);
        assert_eq!(used.verdict(), StickSlopeVerdict::DoesNotAgree);
    }

    #[test]
    fn the_friction_card_is_read() {
        let deck = "*SURFACE INTERACTION, NAME=J\n*FRICTION\n** c\n0.3, 660.0\n*CONTACT PAIR\n";
        assert_eq!(friction_card(deck), Some((0.3, 660.0)));
        assert_eq!(friction_card("*STEP\n"), None);
    }

    #[test]
    fn the_interface_csv_takes_one_or_several_steps() {
        let one =
            read_interface_csv("x_mm,slip_mm,shear_MPa\n0,1e-5,6e-3\n1,2e-5,1.2e-2\n").unwrap();
        assert_eq!(one.len(), 1);
        assert_eq!(one[0].nodes[1].shear, [1.2e-2, 0.0]);
        let two = read_interface_csv(
            "step,x_mm,slip_mm,shear_MPa\n1,0,1e-5,6e-3\n2,0,2e-5,1.2e-2\n2,1,3e-5,1.8e-2\n",
        )
        .unwrap();
        assert_eq!(
            two.iter().map(|s| s.nodes.len()).collect::<Vec<_>>(),
            [1, 2]
        );
        let error = read_interface_csv("x,slip\n").unwrap_err().to_string();
        assert!(error.contains("expected x_mm,slip_mm,shear_MPa"), "{error}");
        let error = read_interface_csv("x_mm,slip_mm,shear_MPa\n0,a,1\n")
            .unwrap_err()
            .to_string();
        assert_eq!(error, "line 2: slip_mm = 'a' is not a number");
    }

    /// A frictionless first step slides without shear: its slip is taken off the later steps',
    /// and only a deck whose first step changes the friction is read so.
    #[test]
    fn slips_are_counted_from_a_frictionless_first_step() {
        let node = |id: usize, slip: f64, shear: f64| ContactNode {
            node: id,
            slip: [slip, 0.0],
            pressure: Some(6.0),
            shear: [shear, 0.0],
        };
        let step = |n: usize, nodes: Vec<ContactNode>| ContactStep {
            step: n,
            time: n as f64,
            nodes,
        };
        let contact = vec![
            step(1, vec![node(1, 2e-4, 0.0), node(2, -1e-4, 0.0)]),
            step(2, vec![node(1, 2.1e-4, 0.1), node(2, -0.9e-4, 0.1)]),
        ];
        let from = slips_from_first_step(contact);
        assert_eq!(from.len(), 1);
        for n in &from[0].nodes {
            assert!((n.shear[0] / n.slip[0] - 1e4).abs() < 1e-6, "{n:?}");
        }
        let deck = "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=I\n*END STEP\n*STEP\n*END STEP\n";
        assert!(first_step_changes_friction(deck));
        let later =
            "*STEP\n*STATIC\n*END STEP\n*STEP\n*CHANGE FRICTION, INTERACTION=I\n*END STEP\n";
        assert!(!first_step_changes_friction(later));
    }
}
