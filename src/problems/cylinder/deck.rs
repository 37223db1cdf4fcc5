//! The Hertzian cylinder's FE deck ([`Deck`]): the CalculiX deck (`deck_writer.rs`), the
//! header it carries, its results (`ccx_read.rs`) and their comparison with the half-plane
//! solution (Hertz's a and p0, the regularized c, s(a), s(0) at the deck's stick slope, and
//! Mindlin's c beside them).

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::deck::{DeckMesh, DeckTooLarge};
use crate::fe::face::{Deck, DeckError, DeckRequest};
use crate::fe::header::{DeckHeader, StickSlope};
use crate::fe::ladder::{LadderQuantity, ValueScale};
use crate::fe::results::{CcxRun, ResultsError};
use crate::fe::verdict::InterfaceMesh;
use crate::kernel::format::number;
use crate::kernel::params::{Compact, Domain, ParamError, Unit};
use crate::kernel::regime::Regime;
use crate::measured::{self as data, Curve};
use crate::problems::Problem;
use crate::report::compare::CompareFace;
use crate::report::compare::verdict::Summary;
use crate::report::sanitize;

pub use super::ccx_read::{CylinderFePoint, FeContact};
use super::ccx_read::{CylinderReading, cylinder_points};
use super::closed_form::{Cylinder, TangentialLoad};
use super::deck_writer::{
    BODY_SIZE, CylinderDeckInputs, Layout, MAX_HALF_WIDTH_OVER_RADIUS, cylinder_deck, layout, sets,
};
use super::problem::{CylinderInputs, CylinderModel, CylinderProblem};

/// The default load steps, as fractions of the gross-slip load mu P.
const DEFAULT_LOADS: [f64; 2] = [0.3, 0.6];
/// The default largest change of Q per increment, as a fraction of mu P: halving it (mu P/20)
/// moved s(a) by 0.02 % and c by less than 0.001 a on the coarse deck (docs/theory.md, "The
/// Hertzian cylinder in CI").
pub const DEFAULT_STEP: f64 = 0.1;
/// K_T a / E* of the near-Coulomb stick slope: the regularized c/a is then within about 1 % of
/// a of Mindlin's (docs/theory.md, the cylinder's CalculiX judge).
const NEAR_COULOMB_GROUP: f64 = 100.0;

/// The CSV form of the cylinder's curve: Q (N/mm) and the edge slip s(a) (mm).
const CYLINDER_CURVE: Curve = Curve {
    x: "Q_N_per_mm",
    y: "sa_mm",
    x_what: "tangential line loads",
    x_domain: Domain::NonNegative { max: 1e9 },
    x_unit: Unit::NewtonPerMillimetre,
    min_rows: 1,
};

/// The stick slope (MPa/mm) a deck of `cylinder` gives CalculiX: the model's K_T, or near
/// Coulomb K_T = 100 E* / a.
pub fn stick_slope_of(stick_slope: StickSlope, cylinder: &Cylinder) -> f64 {
    match stick_slope {
        StickSlope::Model => cylinder.params().tangential_stiffness,
        StickSlope::NearCoulomb => {
            NEAR_COULOMB_GROUP * cylinder.contact_modulus() / cylinder.half_width()
        }
    }
}

/// The header of a cylinder deck: K_T is the deck's stick slope, Q the last load.
pub fn header(
    cylinder: &Cylinder,
    loads: &[TangentialLoad],
    mesh: DeckMesh,
    stick_slope: StickSlope,
) -> DeckHeader {
    let mut structure = cylinder.params();
    structure.tangential_stiffness = stick_slope_of(stick_slope, cylinder);
    DeckHeader {
        inputs: CylinderProblem::to_inputs(CylinderInputs {
            structure,
            load: loads.last().map_or(0.0, |q| q.newtons_per_mm()),
        }),
        loads: loads.iter().map(|q| q.newtons_per_mm()).collect(),
        mesh,
        stick_slope,
        poisson: structure.poisson,
    }
}

/// The deck of `cylinder`: P, then one step per load of `loads` (N/mm, increasing), in
/// increments of at most `q_step` N/mm (default mu P / 10).
///
/// # Errors
/// [`DeckTooLarge`] (only a mesh far finer than the fine one meets it).
pub fn write_cylinder_deck(
    cylinder: &Cylinder,
    loads: &[TangentialLoad],
    mesh: DeckMesh,
    stick_slope: StickSlope,
    q_step: Option<f64>,
) -> Result<String, DeckTooLarge> {
    write_laid_out_deck(cylinder, loads, mesh, layout(mesh), stick_slope, q_step)
}

/// The deck of `cylinder` on `layout` (its header names `mesh`).
fn write_laid_out_deck(
    cylinder: &Cylinder,
    loads: &[TangentialLoad],
    mesh: DeckMesh,
    layout: Layout,
    stick_slope: StickSlope,
    q_step: Option<f64>,
) -> Result<String, DeckTooLarge> {
    let p = cylinder.params();
    let inputs = CylinderDeckInputs {
        radius: p.radius,
        half_width: cylinder.half_width(),
        peak_pressure: cylinder.peak_pressure(),
        modulus: p.modulus,
        poisson: p.poisson,
        normal_load: p.normal_load,
        friction: p.friction,
        stick_slope: stick_slope_of(stick_slope, cylinder),
    };
    let newtons: Vec<f64> = loads.iter().map(|q| q.newtons_per_mm()).collect();
    cylinder_deck(
        &inputs,
        &newtons,
        layout,
        q_step.unwrap_or(DEFAULT_STEP * cylinder.gross_slip_load()),
        &header(cylinder, loads, mesh, stick_slope).to_comment(),
    )
}

/// One FE point against the half-plane solution at its load and the deck's K_T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderCompared {
    /// The FE point.
    pub fe: CylinderFePoint,
    /// Hertz's a (mm) and p0 (MPa).
    pub half_width: f64,
    pub peak_pressure: f64,
    /// The regularized microslip zone's half-width c (mm).
    pub zone: f64,
    /// Mindlin's stick zone's half-width (mm).
    pub zone_mindlin: f64,
    /// The regularized s(a) and s(0) (mm).
    pub edge_slip: f64,
    pub centre_slip: f64,
    /// The regularized regime.
    pub regime: Regime,
    /// Whether the half-plane envelope judges this point: it was measured on linear-geometry
    /// runs (the deck's), so a run of other kinematics is not judged against it.
    pub envelope_applies: bool,
    /// The half-plane envelope of this cylinder ([`Cylinder::validity`]): c within this
    /// fraction of a and s(a) within this fraction; `None` outside the measured envelope.
    pub zone_within: Option<f64>,
    pub edge_slip_within: Option<f64>,
    /// Why the envelope does not reach this cylinder; `None` inside it.
    pub outside_because: Option<&'static str>,
}

impl CylinderCompared {
    /// (FE - half-plane) c, as a fraction of a.
    pub fn zone_difference(&self) -> Option<f64> {
        self.fe
            .contact
            .map(|c| (c.micro_half_width - self.zone) / self.half_width)
    }

    /// (FE - half-plane) / half-plane s(a), a fraction.
    pub fn edge_slip_difference(&self) -> Option<f64> {
        (self.edge_slip > 0.0).then(|| self.fe.edge_slip / self.edge_slip - 1.0)
    }
}

/// Compares FE points of the cylinder with the half-plane solution of `cylinder` (at the K_T the
/// deck gave the FE code). The rows are one family of loads, solved in one
/// [`family::scope`](crate::kernel::family::scope) (each continued from the rows before, issue
/// 47: a 1e5-row CSV in seconds), the same for `compare`, the TUI and Python.
///
/// # Errors
/// A point's load beyond mu P: the contact slides through there.
pub fn compare_cylinder(
    cylinder: &Cylinder,
    points: &[CylinderFePoint],
) -> Result<Vec<CylinderCompared>, ParamError> {
    crate::kernel::family::scope(|| compare_rows(cylinder, points))
}

/// [`compare_cylinder`] in its scope.
fn compare_rows(
    cylinder: &Cylinder,
    points: &[CylinderFePoint],
) -> Result<Vec<CylinderCompared>, ParamError> {
    let envelope = cylinder.validity();
    points
        .iter()
        .map(|&fe| {
            let load = cylinder.load(fe.load)?;
            let state = cylinder.regularized(load);
            Ok(CylinderCompared {
                fe,
                half_width: cylinder.half_width(),
                peak_pressure: cylinder.peak_pressure(),
                zone: state.micro_half_width(),
                zone_mindlin: cylinder.coulomb(load).stick_half_width(),
                edge_slip: state.edge_slip(),
                centre_slip: state.centre_slip(),
                regime: state.regime(),
                envelope_applies: true,
                zone_within: envelope.zone_within,
                edge_slip_within: envelope.edge_slip_within,
                outside_because: envelope.outside_because,
            })
        })
        .collect()
}

/// The loads of a cylinder deck's steps: `loads` (increasing, each below mu P), or 0.3 and 0.6
/// mu P.
fn deck_loads(
    cylinder: &Cylinder,
    loads: Option<&[f64]>,
) -> Result<Vec<TangentialLoad>, DeckError> {
    let Some(loads) = loads else {
        return Ok(DEFAULT_LOADS
            .iter()
            .map(|f| cylinder.clamped_load(f * cylinder.gross_slip_load()))
            .collect());
    };
    DeckError::increasing_loads(loads, |q| cylinder.load(q))
}

impl Deck for CylinderProblem {
    const SOURCE: &'static str = " (docs/theory.md, the Hertzian cylinder)";
    const INTERFACE_SET: &'static str = sets::FLAT_FACE;
    type FePoint = CylinderFePoint;
    type Compared = Result<Vec<CylinderCompared>, ParamError>;

    fn expected(model: &CylinderModel, header: &DeckHeader) -> String {
        let cylinder = &model.cylinder;
        let mut text = format!(
            "** Expected from the half-plane solution: a = {} mm, p0 = {} MPa (Hertz); the flat \
             {BODY_SIZE} a wide and deep, the cylinder the disc below a chord {BODY_SIZE} a (at \
             most R) above the contact\n\
             **   Q (N/mm) | c Mindlin (mm) | c regularized (mm) | s(a) (mm) | s(0) (mm)\n",
            number(cylinder.half_width()),
            number(cylinder.peak_pressure()),
        );
        for &q in &header.loads {
            // One solve per load step: a caller that cancels the deck stops here.
            crate::numeric::cancel::checkpoint();
            let load = cylinder.clamped_load(q);
            let state = cylinder.regularized(load);
            let _ = writeln!(
                text,
                "**   {} | {} | {} | {} | {}",
                number(q),
                number(cylinder.coulomb(load).stick_half_width()),
                number(state.micro_half_width()),
                number(state.edge_slip()),
                number(state.centre_slip())
            );
        }
        text
    }

    fn ccx_points(
        run: &CcxRun,
        params: &CylinderInputs,
    ) -> Result<Vec<CylinderFePoint>, ResultsError> {
        let cylinder = Cylinder::new(params.structure).map_err(|e| {
            ResultsError::Missing(format!("the deck's header holds no valid cylinder: {e}"))
        })?;
        // The .frd's CPRESS where the run left it (a CSV or a .dat alone: the node pairs').
        let contact = crate::fe::load::frd_contact(run.dat_path).ok();
        cylinder_points(
            run.deck,
            run.dat,
            &CylinderReading {
                contact: contact.as_deref(),
                loads: &run.header.loads,
                pressing: params.structure.normal_load,
                kt: params.structure.tangential_stiffness,
                mu: params.structure.friction,
                edge: cylinder.half_width(),
            },
        )
    }

    const CSV_CURVE: Curve = CYLINDER_CURVE;

    fn csv_points(text: &str) -> Result<Vec<CylinderFePoint>, ResultsError> {
        Ok(data::parse_curve(text, &CYLINDER_CURVE)?
            .into_iter()
            .map(|(load, edge_slip)| CylinderFePoint {
                load,
                edge_slip,
                contact: None,
            })
            .collect())
    }

    fn compare(
        model: &CylinderModel,
        points: &[CylinderFePoint],
        _mesh: Option<&InterfaceMesh>,
    ) -> Result<Vec<CylinderCompared>, ParamError> {
        compare_cylinder(&model.cylinder, points)
    }

    /// The half-plane envelope was measured on linear-geometry runs (the deck's steps).
    fn without_envelope(compared: &mut Result<Vec<CylinderCompared>, ParamError>) {
        for row in compared.iter_mut().flatten() {
            row.envelope_applies = false;
        }
    }

    fn default_increment(model: &CylinderModel) -> Option<f64> {
        Some(DEFAULT_STEP * model.cylinder.gross_slip_load())
    }

    fn write_deck(model: &CylinderModel, request: &DeckRequest) -> Result<String, DeckError> {
        let cylinder = &model.cylinder;
        fits_the_deck(cylinder)?;
        let loads = deck_loads(cylinder, request.loads)?;
        let q_step = request
            .increment
            .map(|f| {
                DeckError::check(
                    "--increment",
                    f,
                    Domain::FORCE_STEP,
                    Unit::NewtonPerMillimetre,
                )
            })
            .transpose()?;
        Ok(write_cylinder_deck(
            cylinder,
            &loads,
            request.mesh,
            request.slope,
            q_step,
        )?)
    }
}

/// Refuses a cylinder whose arc the deck's bodies cannot hold (a / R above
/// [`MAX_HALF_WIDTH_OVER_RADIUS`]), naming R, a / R and the least R the deck takes at this P and
/// E: a / R = sqrt(4 P / (pi E* R)), so a / R <= k is R >= 4 P / (pi E* k^2) (rounded up to 4
/// digits, so that the R it names is taken). Where that is beyond R's own domain, no R helps and
/// the message says to change P or E.
fn fits_the_deck(cylinder: &Cylinder) -> Result<(), DeckError> {
    let p = cylinder.params();
    let ratio = cylinder.half_width() / p.radius;
    if ratio <= MAX_HALF_WIDTH_OVER_RADIUS {
        return Ok(());
    }
    let least = 4.0 * p.normal_load
        / (std::f64::consts::PI * cylinder.contact_modulus() * MAX_HALF_WIDTH_OVER_RADIUS.powi(2));
    let scale = 10f64.powf(least.log10().floor() - 3.0);
    let least = (least / scale).ceil() * scale;
    let why = format!(
        "a / R = {} here, and the deck is written up to a / R = 2/15 (R >= 7.5 a: a contact \
         small against the cylinder)",
        number(ratio)
    );
    let allowed = if least <= Domain::LENGTH.max() {
        format!(
            "the deck takes R >= {} mm at P = {} N/mm and E = {} MPa ({why}); or a smaller P \
             or a stiffer E",
            Compact(least),
            Compact(p.normal_load),
            Compact(p.modulus)
        )
    } else {
        format!(
            "no accepted R (at most {} mm) holds this contact in the deck at P = {} N/mm and \
             E = {} MPa ({why}); a smaller P or a stiffer E",
            Compact(Domain::LENGTH.max()),
            Compact(p.normal_load),
            Compact(p.modulus)
        )
    };
    Err(DeckError::Flag {
        flag: "R",
        value: p.radius,
        allowed,
    })
}

/// One row of `microslip compare cylinder`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct CylinderCompareRow {
    /// Tangential line load Q (N/mm).
    #[serde(rename = "Q_N_per_mm")]
    pub load: f64,
    /// FE and Hertz contact half-width a (mm); FE None from a CSV curve.
    pub a_fe_mm: Option<f64>,
    pub a_mm: f64,
    /// FE and Hertz peak pressure p0 (MPa).
    #[serde(rename = "p0_fe_MPa")]
    pub p0_fe: Option<f64>,
    #[serde(rename = "p0_MPa")]
    pub p0: f64,
    /// FE and half-plane (regularized) microslip half-width c (mm), Mindlin's stick zone.
    pub c_fe_mm: Option<f64>,
    pub c_mm: f64,
    pub c_mindlin_mm: f64,
    /// (FE - half-plane) c / a.
    pub c_diff_over_a: Option<f64>,
    /// FE and half-plane edge slip s(a) (mm), and their difference as a fraction.
    pub sa_fe_mm: f64,
    pub sa_mm: f64,
    pub sa_diff_fraction: Option<f64>,
    /// FE and half-plane centre slip s(0) (mm).
    pub s0_fe_mm: Option<f64>,
    pub s0_mm: f64,
    /// The half-plane regime.
    pub regime: &'static str,
}

impl From<&CylinderCompared> for CylinderCompareRow {
    fn from(c: &CylinderCompared) -> Self {
        let contact = c.fe.contact;
        CylinderCompareRow {
            load: c.fe.load,
            a_fe_mm: contact.map(|x| x.half_width),
            a_mm: c.half_width,
            p0_fe: contact.map(|x| x.peak_pressure),
            p0: c.peak_pressure,
            c_fe_mm: contact.map(|x| x.micro_half_width),
            c_mm: c.zone,
            c_mindlin_mm: c.zone_mindlin,
            c_diff_over_a: c.zone_difference(),
            sa_fe_mm: c.fe.edge_slip,
            sa_mm: c.edge_slip,
            sa_diff_fraction: c.edge_slip_difference(),
            s0_fe_mm: contact.map(|x| x.centre_slip),
            s0_mm: c.centre_slip,
            regime: c.regime.label(),
        }
    }
}

/// What the half-plane answer is expected within against CalculiX: the envelope of
/// [`super::validity`] (c within this fraction of a, s(a) within [`EDGE_SLIP_WITHIN`]), measured
/// on the deck's meshes and larger bodies (docs/theory.md, "The Hertzian cylinder in CI and how
/// far the half-plane answer holds").
pub use super::validity::{EDGE_SLIP_WITHIN, ZONE_WITHIN};

/// `microslip compare cylinder`: the rows and the verdict.
#[derive(Debug, Clone, Serialize)]
pub struct CylinderCompareReport {
    /// Always `cylinder`.
    pub model: &'static str,
    /// The files compared.
    pub source: String,
    pub rows: Vec<CylinderCompareRow>,
    /// True when every row's c and s(a) are within the envelope.
    pub within_envelope: bool,
    /// The envelope: c within `c_within_fraction_of_a` of a, s(a) within
    /// `sa_within_fraction`.
    pub c_within_fraction_of_a: f64,
    pub sa_within_fraction: f64,
    /// What the comparison assumes.
    pub note: &'static str,
    /// The closing verdict, as every problem's (the stick slope used and the run's kinematics
    /// are added to it by the generic comparison).
    pub verdict: Summary,
    /// Whether the envelope judged the rows (a run of its kinematics, within its reach): where
    /// not, a ladder's quantities carry no bound.
    #[serde(skip)]
    pub envelope_judged: bool,
}

/// What the half-plane solution assumes, said wherever the comparison of a run of the
/// project's own deck is shown.
pub const HALF_PLANE_NOTE: &str = "half-plane solution (Hertz, regularized Cattaneo-Mindlin at \
     the deck's K_T); the deck's flat is 32 a wide and deep, its cylinder the disc below a chord \
     32 a (at most R) above the contact";
/// The same for a CSV curve: its bodies and its K_T are what the flags say, not a deck's.
pub const HALF_PLANE_NOTE_CSV: &str = "half-plane solution (Hertz, regularized Cattaneo-Mindlin \
     at the given K_T); the envelope holds for bodies at least 32 a wide and deep, which a CSV \
     curve does not say";

impl CylinderCompareReport {
    /// The report of `rows`, compared from the files `source` names.
    pub fn new(source: &str, rows: &[CylinderCompared]) -> CylinderCompareReport {
        // A row is judged where it has a difference to judge: s(a) where the half-plane's is
        // not 0 (Q > 0), c where the results carry it (a CalculiX run, not a CSV curve).
        let judged_rows = rows
            .iter()
            .filter(|r| r.edge_slip_difference().is_some() || r.zone_difference().is_some())
            .count();
        let judged = judged_rows > 0 && rows.iter().all(|r| r.envelope_applies);
        let has_zone = rows.iter().any(|r| r.zone_difference().is_some());
        let outside = rows.iter().find_map(|r| r.outside_because);
        let zone = rows
            .first()
            .and_then(|r| r.zone_within)
            .unwrap_or(ZONE_WITHIN);
        let edge = rows
            .first()
            .and_then(|r| r.edge_slip_within)
            .unwrap_or(EDGE_SLIP_WITHIN);
        let within = outside.is_none()
            && rows.iter().all(|r| {
                r.zone_difference().is_none_or(|d| d.abs() <= zone)
                    && r.edge_slip_difference().is_none_or(|d| d.abs() <= edge)
            });
        CylinderCompareReport {
            model: "cylinder",
            source: source.to_string(),
            rows: rows.iter().map(CylinderCompareRow::from).collect(),
            within_envelope: within,
            c_within_fraction_of_a: zone,
            sa_within_fraction: edge,
            note: if rows.iter().any(|r| r.fe.contact.is_some()) {
                HALF_PLANE_NOTE
            } else {
                HALF_PLANE_NOTE_CSV
            },
            envelope_judged: judged && outside.is_none(),
            verdict: envelope_summary(
                Judged {
                    within,
                    judged,
                    rows: (judged_rows, rows.len()),
                    has_zone,
                },
                (zone, edge),
                outside,
            ),
        }
    }

    /// The readable comparison.
    pub fn text(&self) -> String {
        let mut out = format!(
            "Hertzian cylinder: {} against the {}\n",
            sanitize(&self.source),
            self.note
        );
        let opt = |v: Option<f64>| v.map_or_else(|| "-".to_string(), number);
        let pct =
            |v: Option<f64>| v.map_or_else(|| "-".to_string(), |d| format!("{:+.2} %", 100.0 * d));
        if let Some(first) = self.rows.first() {
            let _ = writeln!(
                out,
                "  a: FE {} mm, Hertz {} mm; p0: FE {} MPa, Hertz {} MPa",
                opt(first.a_fe_mm),
                number(first.a_mm),
                opt(first.p0_fe),
                number(first.p0)
            );
        }
        let _ = writeln!(
            out,
            "  {:>10} {:>10} {:>10} {:>10} {:>9} {:>11} {:>11} {:>9}",
            "Q (N/mm)",
            "c FE (mm)",
            "c (mm)",
            "Mindlin",
            "dc/a",
            "s(a) FE mm",
            "s(a) (mm)",
            "ds(a)"
        );
        for r in &self.rows {
            let _ = writeln!(
                out,
                "  {:>10} {:>10} {:>10} {:>10} {:>9} {:>11} {:>11} {:>9}",
                number(r.load),
                opt(r.c_fe_mm),
                number(r.c_mm),
                number(r.c_mindlin_mm),
                pct(r.c_diff_over_a),
                number(r.sa_fe_mm),
                number(r.sa_mm),
                pct(r.sa_diff_fraction)
            );
        }
        let _ = writeln!(out, "{}", self.verdict.summary);
        out
    }
}

/// What the rows of a comparison gave the verdict to judge.
struct Judged {
    /// Every judged difference within its bound.
    within: bool,
    /// At least one row with a difference to judge, and every row of the envelope's kinematics.
    judged: bool,
    /// Rows with a difference to judge, of all rows.
    rows: (usize, usize),
    /// Whether any row carries c (a CalculiX run; a CSV curve has s(a) only).
    has_zone: bool,
}

/// The closing verdict of the half-plane envelope: c within `bounds.0` of a (where the results
/// carry c) and s(a) within `bounds.1` on every row that has them (`outside`: why the envelope
/// does not reach this cylinder, which is then not judged).
fn envelope_summary(
    Judged {
        within,
        judged,
        rows: (judged_rows, all_rows),
        has_zone,
    }: Judged,
    (zone, edge): (f64, f64),
    outside: Option<&str>,
) -> Summary {
    if let Some(why) = outside {
        return Summary {
            agrees: false,
            summary: format!(
                "Verdict: not judged. The half-plane envelope measured against CalculiX does not \
                 reach this cylinder: {why}."
            ),
            stiffness: None,
            stiffness_z: None,
            short: "not judged: outside the measured envelope".to_string(),
        };
    }
    let edge_words = format!(
        "s(a) within {} % of the half-plane answer",
        Compact(100.0 * edge)
    );
    let envelope = if has_zone {
        format!("c within {} % of a and {edge_words}", Compact(100.0 * zone))
    } else {
        edge_words
    };
    let envelope = format!("{envelope} (the envelope measured against CalculiX, docs/theory.md)");
    let (agrees, word, short) = match (judged, within) {
        (false, _) => (
            false,
            "not judged",
            "not judged: no row with Q > 0, or a run of other kinematics than the envelope's"
                .to_string(),
        ),
        (true, true) => (true, "agrees", "agrees".to_string()),
        (true, false) => (false, "does not agree", "does not agree".to_string()),
    };
    let counted = if judged_rows == all_rows {
        format!("on every row ({all_rows})")
    } else {
        format!(
            "on every row that has one ({judged_rows} of {all_rows}: s(a) is 0 at Q = 0, nothing \
             to judge)"
        )
    };
    let body = if !judged {
        format!("the envelope ({envelope}) judges linear-geometry runs with a row at Q > 0 only")
    } else if within {
        format!("{envelope} {counted}")
    } else {
        format!("not {envelope} {counted}")
    };
    let body = if has_zone || !judged {
        body
    } else {
        format!("{body}; c is not judged: the results carry no c")
    };
    Summary {
        agrees,
        summary: format!("Verdict: {word}. {body}."),
        stiffness: None,
        stiffness_z: None,
        short,
    }
}

impl CompareFace for CylinderProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<CylinderCompared>;
    type CompareRow = CylinderCompareRow;
    type CompareReport = CylinderCompareReport;

    fn checked(
        compared: Result<Vec<CylinderCompared>, ParamError>,
    ) -> Result<Vec<CylinderCompared>, ParamError> {
        compared
    }

    fn compare_report(
        source: &str,
        first: Vec<CylinderCompared>,
        more: Vec<Vec<CylinderCompared>>,
    ) -> (CylinderCompareReport, Vec<CylinderCompareRow>) {
        let rows: Vec<CylinderCompared> = first
            .into_iter()
            .chain(more.into_iter().flatten())
            .collect();
        let report = CylinderCompareReport::new(source, &rows);
        let table = report.rows.clone();
        (report, table)
    }

    fn compare_text(report: &CylinderCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut CylinderCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    /// s(a) against the half-plane's (its difference a fraction of it) and c (its difference a
    /// fraction of a, as the envelope bounds it), per load step.
    fn ladder_quantities(report: &CylinderCompareReport) -> Vec<LadderQuantity> {
        let judged = report.envelope_judged;
        let mut quantities = Vec::new();
        for row in &report.rows {
            let at = format!("Q = {} N/mm", number(row.load));
            if let Some(difference) = row.sa_diff_fraction {
                quantities.push(LadderQuantity {
                    name: format!("s(a) at {at}"),
                    difference,
                    bound: judged.then_some(report.sa_within_fraction),
                    value: Some(ValueScale {
                        closed_form: row.sa_mm,
                        scale: row.sa_mm,
                        unit: "mm".to_string(),
                    }),
                });
            }
            if let Some(difference) = row.c_diff_over_a {
                quantities.push(LadderQuantity {
                    name: format!("c at {at}"),
                    difference,
                    bound: judged.then_some(report.c_within_fraction_of_a),
                    value: Some(ValueScale {
                        closed_form: row.c_mm,
                        scale: row.a_mm,
                        unit: "mm".to_string(),
                    }),
                });
            }
        }
        quantities
    }
}

#[cfg(test)]
mod study {
    use super::*;
    use crate::problems::cylinder::params::CylinderParams;

    fn var(name: &str, default: f64) -> f64 {
        std::env::var(name).map_or(default, |v| v.parse().unwrap())
    }

    /// The decks of the CalculiX study (docs/theory.md, the cylinder's CI case and envelope):
    /// the bundled pad's material, any R, P, K_T a / E*, mesh and body size, with its header.
    #[test]
    #[ignore = "writes a study deck to $CYL_DECK"]
    fn write_study_deck() {
        let base = Cylinder::new(CylinderParams {
            radius: var("CYL_R", 50.0),
            modulus: 210_000.0,
            poisson: 0.3,
            normal_load: var("CYL_P", 500.0),
            friction: 0.6,
            tangential_stiffness: 1e5,
        })
        .unwrap();
        let kt = var("CYL_GROUP", 0.23) * base.contact_modulus() / base.half_width();
        let cylinder = base.with_tangential_stiffness(kt).unwrap();
        let gross = cylinder.gross_slip_load();
        let loads: Vec<TangentialLoad> = std::env::var("CYL_LOADS")
            .map_or("0.3,0.6".into(), |v| v)
            .split(',')
            .map(|f| cylinder.load(f.parse::<f64>().unwrap() * gross).unwrap())
            .collect();
        let layout = Layout {
            per_half_width: var("CYL_N", 10.0) as usize,
            body_size: var("CYL_BODY", 20.0),
            growth: var("CYL_GROWTH", 1.3),
        };
        let step = gross / var("CYL_QSTEPS", 10.0);
        let deck = write_laid_out_deck(
            &cylinder,
            &loads,
            DeckMesh::Coarse,
            layout,
            StickSlope::Model,
            Some(step),
        )
        .unwrap();
        std::fs::write(std::env::var("CYL_DECK").unwrap(), deck).unwrap();
    }
}

#[cfg(test)]
mod envelope {
    use super::*;
    use crate::problems::cylinder::params::CylinderParams;

    /// A cylinder of radius `radius` (mm) at K_T a/E* = 0.64, and a point that agrees with its
    /// half-plane answer exactly at 0.3 mu P.
    fn agreeing(radius: f64) -> Vec<CylinderCompared> {
        let base = Cylinder::new(CylinderParams {
            radius,
            ..CylinderParams::STEEL_PAD
        })
        .unwrap();
        let c = base
            .with_tangential_stiffness(0.64 * base.contact_modulus() / base.half_width())
            .unwrap();
        let load = c.load(0.3 * c.gross_slip_load()).unwrap();
        let state = c.regularized(load);
        let fe = CylinderFePoint {
            load: load.newtons_per_mm(),
            edge_slip: state.edge_slip(),
            contact: Some(FeContact {
                half_width: c.half_width(),
                peak_pressure: c.peak_pressure(),
                micro_half_width: state.micro_half_width(),
                centre_slip: state.centre_slip(),
            }),
        };
        compare_cylinder(&c, &[fe]).unwrap()
    }

    #[test]
    fn the_envelope_is_the_cylinder_s_own() {
        // The pad: inside, judged on the base bounds.
        let report = CylinderCompareReport::new("run.dat", &agreeing(50.0));
        assert!(report.within_envelope && report.verdict.agrees);
        assert_eq!(report.sa_within_fraction, EDGE_SLIP_WITHIN);
        // a/R beyond the measured (R = 5 mm: 0.047, the older curved tier's; R = 1 mm): not
        // judged, with the reason, even where the numbers agree.
        for radius in [5.0, 1.0] {
            let report = CylinderCompareReport::new("run.dat", &agreeing(radius));
            assert!(!report.within_envelope && !report.verdict.agrees);
            assert!(
                report.verdict.summary.contains("a/R"),
                "{}",
                report.verdict.summary
            );
        }
        let report = CylinderCompareReport::new("run.dat", &agreeing(1.0));
        assert!(!report.within_envelope && !report.verdict.agrees);
        assert!(
            report.verdict.summary.contains("not judged"),
            "{}",
            report.verdict.summary
        );
        assert!(
            report.verdict.summary.contains("a/R"),
            "{}",
            report.verdict.summary
        );
    }

    /// A CSV curve carries s(a) only: the verdict does not claim a check of c, and its note does
    /// not speak of the deck's bodies, which a CSV's run did not use (issue 46, item 5).
    #[test]
    fn a_csv_curve_is_judged_on_s_a_only_and_said_so() {
        let mut rows = agreeing(50.0);
        for row in &mut rows {
            row.fe.contact = None;
        }
        let report = CylinderCompareReport::new("curve.csv", &rows);
        let summary = &report.verdict.summary;
        assert!(report.verdict.agrees, "{summary}");
        assert!(!summary.contains("c within"), "{summary}");
        assert!(summary.contains("c is not judged"), "{summary}");
        assert_eq!(report.note, HALF_PLANE_NOTE_CSV);
        assert!(
            !report.text().contains("deck's bodies"),
            "{}",
            report.text()
        );
        // A run of the deck keeps both.
        let run = CylinderCompareReport::new("run.dat", &agreeing(50.0));
        assert!(run.verdict.summary.contains("c within"));
        assert_eq!(run.note, HALF_PLANE_NOTE);
    }

    /// A curve whose only row is at Q = 0 has nothing to judge (s(a) is 0 there): it is "not
    /// judged", never "agrees" (issue 46, item 5).
    #[test]
    fn a_curve_with_nothing_to_judge_does_not_agree() {
        let mut rows = agreeing(50.0);
        let c = Cylinder::new(CylinderParams::STEEL_PAD).unwrap();
        rows = compare_cylinder(
            &c,
            &[CylinderFePoint {
                load: 0.0,
                edge_slip: 0.0,
                contact: None,
            }],
        )
        .unwrap_or(rows);
        assert_eq!(rows.len(), 1);
        let report = CylinderCompareReport::new("curve.csv", &rows);
        assert!(!report.verdict.agrees, "{}", report.verdict.summary);
        assert!(report.verdict.summary.starts_with("Verdict: not judged"));
    }

    /// A cylinder the deck does not hold (a / R above 2/15) is refused naming R and the least
    /// R, and never written with NaN coordinates (issue 46, item 4: R = 0.3 mm wrote 208 NaN
    /// node lines); just inside the bound the deck is written and finite.
    #[test]
    fn a_cylinder_the_deck_cannot_hold_is_refused_with_the_least_radius() {
        let params = |radius: f64| CylinderParams {
            radius,
            ..CylinderParams::STEEL_PAD
        };
        let request = DeckRequest {
            loads: None,
            mesh: DeckMesh::Coarse,
            slope: StickSlope::Model,
            increment: None,
        };
        let model = |radius: f64| {
            let cylinder = Cylinder::new(params(radius)).unwrap();
            CylinderModel {
                load: cylinder.clamped_load(0.0),
                cylinder,
            }
        };
        let refused = crate::fe::face::written_deck::<CylinderProblem>(&model(0.3), &request)
            .unwrap_err()
            .to_string();
        assert!(
            refused.starts_with("invalid R = 0.3: the deck takes R >= 0.6208 mm"),
            "{refused}"
        );
        assert!(refused.contains("a / R = 0.191788 here"), "{refused}");
        // Where no R of the domain would do, it says to change P or E instead: the largest R,
        // and an E that makes a / R = 0.5 there (a contact, a < R, that no deck holds).
        let largest = Domain::LENGTH.max();
        let nu = CylinderParams::STEEL_PAD.poisson;
        let cylinder = Cylinder::new(CylinderParams {
            modulus: 2.0 * (1.0 - nu * nu) * 16.0 * 1000.0 / (std::f64::consts::PI * largest),
            ..params(largest)
        })
        .unwrap();
        assert!((cylinder.half_width() / largest - 0.5).abs() < 1e-9);
        let soft = CylinderModel {
            load: cylinder.clamped_load(0.0),
            cylinder,
        };
        let refused = crate::fe::face::written_deck::<CylinderProblem>(&soft, &request)
            .unwrap_err()
            .to_string();
        assert!(refused.contains("no accepted R"), "{refused}");
        // The least R it names is the bound itself: a / R = 2/15 there, and it is written.
        let cylinder = Cylinder::new(params(0.3)).unwrap();
        let least = 4.0 * 1000.0
            / (std::f64::consts::PI
                * cylinder.contact_modulus()
                * MAX_HALF_WIDTH_OVER_RADIUS.powi(2));
        let at = Cylinder::new(params(least * (1.0 + 1e-9))).unwrap();
        assert!(at.half_width() / at.params().radius <= MAX_HALF_WIDTH_OVER_RADIUS);
        let deck = crate::fe::face::written_deck::<CylinderProblem>(
            &model(least * (1.0 + 1e-9)),
            &request,
        )
        .unwrap();
        assert!(!deck.contains("NaN") && !deck.contains("inf,"));
    }
}
