//! The read-only view model: every number, text and curve the screen shows that comes of the
//! physics, computed once when the state changes ([`App`](super::app::App) rebuilds it after each
//! action and outcome; `recompute` rebuilds the chart). The drawing (`ui/`) reads only this and
//! the app's plain UI state (the mode, the text being typed, the selection, the message), so a
//! frame costs no solve, and the layering test (`tests/layering.rs`) holds `ui/` to it: no file
//! there names `kernel`, `numeric`, `problems`, `study`, `fit` or `verify`.
//!
//! The zone types are re-exported here because they are the strip's vocabulary (plain data,
//! labels of stretches of the interface): the drawing names them through the view, and reaches
//! no function of the physics that way.

use crate::chart::Plot;
use crate::kernel::params::Unit;
use crate::problems::inputs::{Inputs, Model};
use crate::problems::{ModelKind, Param};
use crate::report::face::faces;
use crate::report::number;
use crate::study::curves::{Samples, Series, Spacing, interface_zones, shear_along};
use crate::tui::summary::{self, ContinuumState};

pub use crate::study::curves::{InterfaceZones, Zone, ZoneSpan};
pub use crate::tui::summary::SummaryLine;

/// What the screen shows of the state: see the module docs.
#[derive(Debug, Clone, Default)]
pub struct View {
    /// The parameter pane's title (`Twin beams, Euler-Bernoulli`).
    pub parameters_title: String,
    /// The active problem's parameters, in display order.
    pub rows: Vec<ParamRow>,
    /// The regime pane; None while the parameters are not valid.
    pub regime: Option<RegimeView>,
    /// The chart pane.
    pub chart: ChartView,
    /// The active problem's name, as the status line starts (`beam`).
    pub kind: String,
    /// The preset the active problem came from.
    pub preset: String,
    /// True when the parameters differ from that preset (`*` after its name).
    pub modified: bool,
    /// The quantities a target (`t`) can be set on, as the prompt lists them.
    pub target_quantities: String,
}

/// One row of the parameter pane.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamRow {
    /// `L`, `mu`, ...
    pub name: &'static str,
    /// The value as the pane shows it.
    pub value: String,
    /// The unit symbol (empty for a number without one) and the parameter's note (`half`).
    pub unit: String,
    /// True when the value differs from the loaded preset's (`*`).
    pub edited: bool,
    /// What the status line says while a value is typed for it: `L (mm, ...)`.
    pub prompt: String,
}

/// The regime pane: its lines, what `i` walks through, and the zone strip under them.
#[derive(Debug, Clone)]
pub struct RegimeView {
    /// What the title states after `Regime (i), ` (the envelope), where it states one.
    pub title_line: Option<SummaryLine>,
    /// The pane's lines.
    pub lines: Vec<SummaryLine>,
    /// The strip under the lines.
    pub strip: StripView,
}

impl RegimeView {
    /// The lines `i` walks through: the title where it states an envelope, then the lines.
    pub fn explained(&self) -> impl Iterator<Item = &SummaryLine> {
        self.title_line.iter().chain(&self.lines)
    }
}

/// The zone strip: where each law sticks, slips and slides, and the interface shear.
#[derive(Debug, Clone, PartialEq)]
pub struct StripView {
    /// What x = 0 is (`clamp`, `centre`, `inner end`).
    pub origin: &'static str,
    /// What the sparkline rows show (`tau(x) / mu P`, `q(x) / mu p0`).
    pub shear_name: &'static str,
    /// The zones of both laws along the interface.
    pub zones: InterfaceZones,
    /// tau(x) / (mu P) of each law at the centres of the strip's cells, for each width the pane
    /// can have (the drawing picks the one it draws at).
    pub shear: Vec<ShearRow>,
}

impl StripView {
    /// The shear ratios for a strip of `cells` cells, if the view sampled that width.
    pub fn shear_for(&self, cells: usize) -> Option<&ShearRow> {
        self.shear.iter().find(|s| s.cells == cells)
    }
}

/// tau / (mu P) of each law at the centre of each of `cells` cells, in [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub struct ShearRow {
    /// How many cells the strip has.
    pub cells: usize,
    /// Coulomb's law.
    pub coulomb: Vec<f64>,
    /// The regularized law.
    pub regularized: Vec<f64>,
}

/// The chart pane: its title and the chart (or the table shown in its place).
#[derive(Debug, Clone, Default)]
pub struct ChartView {
    /// The pane's title (`w(L) vs F (1/5, c cycles)`).
    pub title: String,
    /// The chart, with its y mode, pins and overlays applied; empty where a table is shown.
    pub plot: Plot,
    /// The K_T table (title and lines) when the view is the table.
    pub table: Option<(&'static str, Vec<String>)>,
}

/// The parameter pane of `kind` at `inputs`; `preset`: the loaded preset's values (edited rows
/// are marked).
pub fn parameters(kind: ModelKind, inputs: &Inputs, preset: &Inputs) -> (String, Vec<ParamRow>) {
    let title = faces(kind).pane.parameters_title(inputs);
    let rows = kind
        .params()
        .iter()
        .map(|&param| {
            // `get` cannot miss: the parameters come from the active model.
            let value = inputs.get(param).unwrap_or(f64::NAN);
            ParamRow {
                name: param.name(),
                value: number(value),
                unit: unit_text(param),
                edited: inputs.get(param) != preset.get(param),
                prompt: prompt(param),
            }
        })
        .collect();
    (title, rows)
}

/// The unit column of a parameter's row: its symbol and its note (`mm half`).
fn unit_text(param: Param) -> String {
    let unit = match param.unit() {
        Unit::Dimensionless => "",
        unit => unit.symbol(),
    };
    let note = param.spec().note;
    if note.is_empty() {
        unit.to_string()
    } else {
        format!("{unit} {note}")
    }
}

/// The parameter as the status line names it while a value is typed: a half size says so where
/// it is typed (`h (mm, half height ...)`), as its row does.
fn prompt(param: Param) -> String {
    let spec = param.spec();
    let meaning = if spec.note.is_empty() {
        String::new()
    } else {
        format!(", {}", spec.meaning)
    };
    format!("{} ({}{meaning})", spec.name, spec.unit)
}

/// The regime pane at `model`; `strip_cells`: the strip widths (cells) the pane can have.
pub fn regime(model: &Model, continuum: &ContinuumState, strip_cells: &[usize]) -> RegimeView {
    RegimeView {
        title_line: summary::title_line(model),
        lines: summary::summary_lines(model, continuum),
        strip: strip(model, strip_cells),
    }
}

/// The zone strip at `model`, with the shear sampled for each of `strip_cells`.
fn strip(model: &Model, strip_cells: &[usize]) -> StripView {
    let zones = interface_zones(model);
    let face = faces(model.kind()).pane;
    let (origin, shear_name) = (face.strip_origin(), face.strip_shear());
    let shear = strip_cells
        .iter()
        .map(|&cells| shear_ratios(model, &zones, cells))
        .collect();
    StripView {
        origin,
        shear_name,
        zones,
        shear,
    }
}

/// tau / (mu P) of each law at the centre of each cell, in [0, 1].
fn shear_ratios(model: &Model, zones: &InterfaceZones, cells: usize) -> ShearRow {
    let half = zones.length / (2 * cells) as f64;
    let Ok(positions) = Samples::new(half, zones.length - half, cells as u64, Spacing::Linear)
    else {
        return ShearRow {
            cells,
            coulomb: Vec::new(),
            regularized: Vec::new(),
        };
    };
    let series: (Series, Series) = shear_along(model, positions);
    // mu P, the stress the interface slides at, for every problem.
    let interface = model.interface();
    let limit = interface.friction * interface.pressure;
    let ratio = |s: Series| -> Vec<f64> {
        s.into_iter()
            .map(|(_, tau)| (tau.abs() / limit).clamp(0.0, 1.0))
            .collect()
    };
    ShearRow {
        cells,
        coulomb: ratio(series.0),
        regularized: ratio(series.1),
    }
}
