//! The press fit's FE results against its closed forms ([`CompareFace`]): each load step's Delta
//! against the shear lag's (regularized, at the deck's K_T, and Coulomb's beside it), its
//! contact pressure against Lamé's, its sliding zones against the closed form's, and the push-out
//! capacity against F_gross = mu p 2 pi r L.
//!
//! What is judged: the capacity and the pressure, which every sound axisymmetric model of the
//! fit must give whatever the members' shear compliance, and which CalculiX issue #98 gets wrong
//! with a node slave (docs/theory.md section 18, "CalculiX": the surface-to-surface run is within
//! 0.4 % of F_gross, the node slave 2.2 times it); and Delta against the axisymmetric continuum
//! at the deck's K_T (the problem's [`ContinuumJudged`] tolerance). Delta against the 1-D shear
//! lag is shown, not judged: the 1-D theory leaves out the members' shear across their walls,
//! which doubles Delta on the #98 fit ((ro - r)/L = 0.56); where it holds is the continuum's to
//! measure (issue 44, item 2), not a tolerance of this comparison.

use std::fmt::Write as _;

use serde::Serialize;

use crate::fe::compare::relative_difference;
use crate::fe::continuum_verdict::{ContinuumJudged, ContinuumVerdict, NotSolved, judged};
use crate::fe::ladder::{LadderQuantity, ValueScale};
use crate::kernel::format::number;
use crate::kernel::params::{Compact, ParamError};
use crate::kernel::regime::Regime;
use crate::report::compare::verdict::Summary;
use crate::report::compare::{CompareFace, optional, percent_or_na};
use crate::report::sanitize;

use super::ccx_read::{FitPointKind, PressFitFePoint};
use super::closed_form::PressFit;
use super::registered::problem::{PressFitModel, PressFitProblem};
#[cfg(feature = "app")]
use crate::fe::load::Loaded;

/// How far CalculiX's push-out capacity may be from F_gross and agree (a fraction): measured
/// converged within 0.2 % in mesh and increments on the #98 fit (docs/theory.md section 18,
/// "CalculiX"); 2 % leaves a margin for other meshes and codes, and is 60 times below the node
/// slave's error.
pub const CAPACITY_WITHIN: f64 = 0.02;
/// How far the median contact pressure after the interference step may be from Lamé's
/// plane-stress p and agree (a fraction): the runs' medians are within 0.3 % of it (docs/theory.md
/// section 18, "CalculiX"); 2 % as the capacity. The push-out's steps are shown, not judged: the
/// shaft's compression swells it (1 % at 0.8 F_gross on the #98 fit, (S9)'s Poisson term).
pub const PRESSURE_WITHIN: f64 = 0.02;

/// How far CalculiX's Delta may be from the axisymmetric continuum's at the deck's K_T and
/// agree (a fraction): on the #98 fit the continuum (branch s-cont's, its default mesh) is within
/// 0.45 % and 0.30 % of the coarse deck's Delta at 0.3 and 0.8 F_gross, 0.08 % and 0.05 % of the
/// fine deck's (halving the force step moved neither by 0.001 %: docs/theory.md section 18,
/// "CalculiX"); 1 % is the coarse deck's difference with a margin of 2.
pub const CONTINUUM_WITHIN: f64 = 0.01;

/// One FE point of the press fit beside the closed forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressFitCompared {
    /// The FE point.
    pub fe: PressFitFePoint,
    /// The closed form's Delta under the regularized law at the deck's K_T (mm): at the point's
    /// force, or at F_gross for the capacity.
    pub closed: f64,
    /// Under plain Coulomb (mm).
    pub coulomb: f64,
    /// The closed form's sliding zones from x = 0 and from x = L (mm) and its regime.
    pub zones: (f64, f64),
    pub regime: Regime,
    /// F_gross = mu p 2 pi r L (N) and Lamé's plane-stress p (MPa).
    pub gross: f64,
    pub pressure: f64,
    /// Whether the tolerances judge this point: they were measured on linear-geometry runs.
    pub judged: bool,
    /// Delta against the axisymmetric continuum at the deck's parameters and this force, where
    /// it was solved (`compare`, a load row): the verdict, or why there is none.
    pub continuum: Option<Result<ContinuumVerdict, NotSolved>>,
}

impl PressFitCompared {
    /// (FE - closed form) / closed form of Delta; `None` at F = 0.
    pub fn delta_difference(&self) -> Option<f64> {
        relative_difference(self.fe.delta, self.closed)
    }

    /// The continuum's verdict on Delta, where the continuum was solved.
    pub fn solved(&self) -> Option<&ContinuumVerdict> {
        self.continuum.as_ref().and_then(|c| c.as_ref().ok())
    }

    /// (FE capacity - F_gross) / F_gross, on the capacity's row.
    pub fn capacity_difference(&self) -> Option<f64> {
        (self.fe.kind == FitPointKind::Capacity).then(|| self.fe.force / self.gross - 1.0)
    }

    /// (FE median CPRESS after the interference step - Lamé's p) / p, where the results carry
    /// the contact.
    pub fn pressure_difference(&self) -> Option<f64> {
        self.fe
            .contact
            .map(|c| c.assembled_pressure / self.pressure - 1.0)
    }
}

/// Compares FE points of the press fit with the closed forms of `fit` (at the K_T the deck gave
/// the FE code).
///
/// # Errors
/// A load point's force beyond F_gross (a CSV of another fit): no static state there. The
/// capacity's is not checked: it is what is judged.
pub fn compare_fit(
    fit: &PressFit,
    points: &[PressFitFePoint],
) -> Result<Vec<PressFitCompared>, ParamError> {
    let gross = fit.gross_slip_force();
    points
        .iter()
        .map(|&fe| {
            let force = match fe.kind {
                FitPointKind::Load => fit.force(fe.force)?,
                FitPointKind::Capacity => fit.axial().clamped(gross),
            };
            let state = fit.regularized(force);
            Ok(PressFitCompared {
                fe,
                closed: state.response(),
                coulomb: fit.coulomb(force).response(),
                zones: (state.slide_from_loaded_face(), state.slide_from_held_face()),
                regime: state.regime(),
                gross,
                pressure: fit.contact_pressure(),
                judged: true,
                continuum: None,
            })
        })
        .collect()
}

/// The comparison of the FE `points` of `model`'s deck ([`crate::fe::face::Deck::compare`]):
/// [`compare_fit`], each loaded row's Delta also against the axisymmetric continuum at its force.
///
/// # Errors
/// As [`compare_fit`].
pub(super) fn compare(
    model: &PressFitModel,
    points: &[PressFitFePoint],
) -> Result<Vec<PressFitCompared>, ParamError> {
    let mut rows = compare_fit(&model.fit, points)?;
    for row in rows
        .iter_mut()
        .filter(|r| r.fe.kind == FitPointKind::Load && r.fe.force > 0.0)
    {
        let at = PressFitModel {
            fit: model.fit,
            force: model.fit.force(row.fe.force)?,
        };
        row.continuum = judged::<PressFitProblem>(&at, row.fe.delta);
    }
    Ok(rows)
}

/// The press fit's Delta against its axisymmetric continuum (docs/theory.md section 18,
/// "CalculiX"): the continuum against the converged CalculiX runs of the #98 fit.
impl ContinuumJudged for PressFitProblem {
    const CONTINUUM_TOLERANCE: f64 = CONTINUUM_WITHIN;
    const RESPONSE: &'static str = "Delta";
}

/// One row of `microslip compare pressfit`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PressFitCompareRow {
    /// The push-out force (N): the load, or CalculiX's capacity.
    #[serde(rename = "F_N")]
    pub force: f64,
    /// `load` or `capacity`.
    pub kind: &'static str,
    /// FE Delta (mm), from the end of the interference step.
    #[serde(rename = "Delta_fe_mm")]
    pub delta_fe: f64,
    /// Closed form, regularized law at the deck's K_T (mm); at F_gross on the capacity's row.
    #[serde(rename = "Delta_mm")]
    pub delta: f64,
    /// Plain Coulomb (mm).
    #[serde(rename = "Delta_coulomb_mm")]
    pub delta_coulomb: f64,
    /// (FE - closed form) / closed form of Delta, a fraction (shown, not judged).
    pub delta_diff: Option<f64>,
    /// The axisymmetric continuum's Delta at the deck's K_T (mm), where solved.
    #[serde(rename = "Delta_continuum_mm")]
    pub delta_continuum: Option<f64>,
    /// (FE - continuum) / continuum of Delta, a fraction (judged against the continuum's
    /// tolerance).
    pub continuum_diff: Option<f64>,
    /// The K_T whose continuum Delta equals the FE value (MPa/mm), where one does.
    #[serde(rename = "KT_implied_continuum_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// F_gross = mu p 2 pi r L (N).
    #[serde(rename = "F_gross_N")]
    pub gross: f64,
    /// (FE capacity - F_gross) / F_gross on the capacity's row.
    pub capacity_diff: Option<f64>,
    /// FE median CPRESS after the interference step, at this step, and Lamé's plane-stress p
    /// (MPa); the first's difference from Lamé's (a fraction, judged).
    #[serde(rename = "p_assembled_fe_MPa")]
    pub assembled_pressure_fe: Option<f64>,
    #[serde(rename = "p_fe_MPa")]
    pub pressure_fe: Option<f64>,
    #[serde(rename = "p_MPa")]
    pub pressure: f64,
    pub pressure_diff: Option<f64>,
    /// FE largest CPRESS and |CSHEAR| (MPa).
    #[serde(rename = "p_peak_fe_MPa")]
    pub pressure_peak_fe: Option<f64>,
    #[serde(rename = "shear_peak_fe_MPa")]
    pub shear_peak_fe: Option<f64>,
    /// FE slip at x = 0 and at x = L (mm).
    #[serde(rename = "slip_x0_fe_mm")]
    pub slip_loaded_fe: Option<f64>,
    #[serde(rename = "slip_xL_fe_mm")]
    pub slip_held_fe: Option<f64>,
    /// Sliding zones from x = 0 (a) and from x = L (d): closed form and FE (mm).
    #[serde(rename = "a_mm")]
    pub slide_loaded: f64,
    #[serde(rename = "a_fe_mm")]
    pub slide_loaded_fe: Option<f64>,
    #[serde(rename = "d_mm")]
    pub slide_held: f64,
    #[serde(rename = "d_fe_mm")]
    pub slide_held_fe: Option<f64>,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The FE deck's contact formulation.
    pub formulation: Option<&'static str>,
}

impl From<&PressFitCompared> for PressFitCompareRow {
    fn from(r: &PressFitCompared) -> Self {
        let contact = r.fe.contact;
        PressFitCompareRow {
            force: r.fe.force,
            kind: match r.fe.kind {
                FitPointKind::Load => "load",
                FitPointKind::Capacity => "capacity",
            },
            delta_fe: r.fe.delta,
            delta: r.closed,
            delta_coulomb: r.coulomb,
            delta_diff: r.delta_difference(),
            delta_continuum: r.solved().map(|v| v.continuum),
            continuum_diff: r.solved().map(|v| v.difference()),
            implied_stiffness: r.solved().and_then(|v| v.implied).map(|k| k.value),
            gross: r.gross,
            capacity_diff: r.capacity_difference(),
            assembled_pressure_fe: contact.map(|c| c.assembled_pressure),
            pressure_fe: contact.map(|c| c.pressure),
            pressure: r.pressure,
            pressure_diff: r.pressure_difference(),
            pressure_peak_fe: contact.map(|c| c.pressure_peak),
            shear_peak_fe: contact.map(|c| c.shear_peak),
            slip_loaded_fe: contact.map(|c| c.slip_at_faces.0),
            slip_held_fe: contact.map(|c| c.slip_at_faces.1),
            slide_loaded: r.zones.0,
            slide_loaded_fe: contact.map(|c| c.zones.0),
            slide_held: r.zones.1,
            slide_held_fe: contact.map(|c| c.zones.1),
            regime: r.regime.label(),
            formulation: contact.map(|c| c.formulation.label()),
        }
    }
}

/// `microslip compare pressfit`: the rows, the tolerances and the verdict.
#[derive(Debug, Clone, Serialize)]
pub struct PressFitCompareReport {
    /// `pressfit`.
    pub model: &'static str,
    /// The results compared.
    pub source: String,
    pub rows: Vec<PressFitCompareRow>,
    /// The capacity's and the pressure's tolerances (fractions).
    pub capacity_within_fraction: f64,
    pub pressure_within_fraction: f64,
    /// The closing verdict.
    pub verdict: Summary,
}

/// The closing verdict of `rows`: the capacity against F_gross, the pressure against Lamé's
/// (each where the results have it); "not judged" where they have neither, or the run is of
/// other kinematics than the tolerances'.
fn fit_summary(rows: &[PressFitCompared]) -> Summary {
    let capacity = rows
        .iter()
        .find_map(|r| r.capacity_difference().map(|d| (r.fe.force, r.gross, d)));
    let worst_pressure = rows
        .iter()
        .filter_map(|r| r.pressure_difference().map(|d| (d, r)))
        .max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
    let worst_delta = rows
        .iter()
        .filter_map(|r| r.solved().map(|v| (v, r)))
        .max_by(|a, b| a.0.difference().abs().total_cmp(&b.0.difference().abs()));
    let formulation = rows
        .iter()
        .find_map(|r| r.fe.contact.map(|c| c.formulation.label()));
    let all_judged = rows.iter().all(|r| r.judged);
    if !all_judged || (capacity.is_none() && worst_pressure.is_none() && worst_delta.is_none()) {
        return Summary {
            agrees: false,
            summary: "Verdict: not judged. The press fit is judged on its push-out capacity, its \
                      contact pressure and its Delta against the axisymmetric continuum, from a \
                      linear-geometry run; these results carry none of them (docs/theory.md \
                      section 18, \"CalculiX\")."
                .to_string(),
            stiffness: None,
            stiffness_z: None,
            short: "not judged: no capacity, pressure or continuum".to_string(),
        };
    }
    let mut parts = Vec::new();
    let mut within = true;
    if let Some((force, gross, d)) = capacity {
        within &= d.abs() <= CAPACITY_WITHIN;
        parts.push(format!(
            "push-out capacity {} N against F_gross = mu p 2 pi r L = {} N ({:+.2} %, tolerance {} %)",
            number(force),
            number(gross),
            100.0 * d,
            Compact(100.0 * CAPACITY_WITHIN)
        ));
    }
    if let Some((d, row)) = worst_pressure {
        within &= d.abs() <= PRESSURE_WITHIN;
        parts.push(format!(
            "median contact pressure after the interference step {} MPa against Lamé's {} MPa \
             ({:+.2} %, tolerance {} %)",
            number(row.pressure * (1.0 + d)),
            number(row.pressure),
            100.0 * d,
            Compact(100.0 * PRESSURE_WITHIN),
        ));
    }
    if let Some((v, row)) = worst_delta {
        within &= v.agrees();
        parts.push(format!(
            "Delta against the axisymmetric continuum at the deck's K_T {:+.2} % at F = {} N (the \
             farthest of {} loads; tolerance {} %)",
            100.0 * v.difference(),
            number(row.fe.force),
            rows.iter().filter(|r| r.solved().is_some()).count(),
            Compact(100.0 * v.tolerance)
        ));
    }
    let (word, short) = if within {
        ("agrees", "agrees".to_string())
    } else {
        ("does not agree", "does not agree".to_string())
    };
    let how = formulation.map_or_else(String::new, |f| format!(" Contact: {f}."));
    let shear_lag = rows
        .iter()
        .filter_map(|r| {
            r.delta_difference()
                .filter(|_| r.fe.kind == FitPointKind::Load)
        })
        .map(|d| format!("{:+.1} %", 100.0 * d))
        .collect::<Vec<_>>();
    let shear_lag = if shear_lag.is_empty() {
        String::new()
    } else {
        format!(
            " Delta against the 1-D shear lag {}: shown, not judged (the members' shear across \
             their walls, which the 1-D theory leaves out; the continuum measures its domain).",
            shear_lag.join(", ")
        )
    };
    Summary {
        agrees: within,
        summary: format!("Verdict: {word}. {}.{how}{shear_lag}", parts.join("; ")),
        stiffness: None,
        stiffness_z: None,
        short,
    }
}

impl PressFitCompareReport {
    /// The report of `rows` compared from `source`.
    pub fn new(source: &str, rows: &[PressFitCompared]) -> PressFitCompareReport {
        PressFitCompareReport {
            model: "pressfit",
            source: source.to_string(),
            rows: rows.iter().map(PressFitCompareRow::from).collect(),
            capacity_within_fraction: CAPACITY_WITHIN,
            pressure_within_fraction: PRESSURE_WITHIN,
            verdict: fit_summary(rows),
        }
    }

    /// The readable comparison.
    pub fn text(&self) -> String {
        let mut out = format!(
            "Press fit: {} against the closed forms (Lamé's p, shear lag, F_gross = mu p 2 pi r L)\n\
             F in N; Delta = u_shaft(x = 0) - u_hub(x = L) in mm (FE: the end face's area mean,\n\
             from the end of the interference step), against the axisymmetric continuum at the\n\
             deck's K_T (judged) and the 1-D shear lag (shown); p FE: median CPRESS at the step (MPa); dp:\n\
             the median after the interference step against Lamé's plane-stress p; a, d: sliding\n\
             zones from x = 0 and x = L (mm; FE: K_T |slip| >= mu p).\n",
            sanitize(&self.source)
        );
        let _ = writeln!(
            out,
            "  {:>9} {:>11} {:>11} {:>9} {:>11} {:>9} {:>11} {:>8} {:>8} {:>7} {:>7} {:>7} {:>7}",
            "F",
            "Delta FE",
            "continuum",
            "vs cont.",
            "shear lag",
            "vs 1-D",
            "Coulomb",
            "p FE",
            "dp",
            "a FE",
            "a",
            "d FE",
            "d"
        );
        for r in &self.rows {
            let label = if r.kind == "capacity" {
                format!("{}*", number(r.force))
            } else {
                number(r.force)
            };
            let _ = writeln!(
                out,
                "  {:>9} {:>11} {:>11} {:>9} {:>11} {:>9} {:>11} {:>8} {:>8} {:>7} {:>7} {:>7} {:>7}",
                label,
                number(r.delta_fe),
                optional(r.delta_continuum),
                percent_or_na(r.continuum_diff),
                number(r.delta),
                percent_or_na(r.delta_diff),
                number(r.delta_coulomb),
                optional(r.pressure_fe),
                percent_or_na(r.pressure_diff),
                optional(r.slide_loaded_fe),
                number(r.slide_loaded),
                optional(r.slide_held_fe),
                number(r.slide_held),
            );
        }
        if let Some(r) = self.rows.iter().find(|r| r.kind == "capacity") {
            let _ = writeln!(
                out,
                "  * the capacity: CalculiX's push-out force in gross slip, against F_gross = {} N \
                 ({}); its Delta columns are at F_gross",
                number(r.gross),
                percent_or_na(r.capacity_diff)
            );
        }
        let _ = writeln!(out, "{}", self.verdict.summary);
        out
    }
}

/// An FE point on the axes of the press fit's first chart (`PaneFace::fe_xy`): (F, Delta).
#[cfg(feature = "app")]
pub(crate) fn pane_xy(point: &PressFitFePoint) -> (f64, f64) {
    (point.force, point.delta)
}

/// The status line's verdict after the TUI loads FE results (`PaneFace::fe_brief`): the loaded
/// points against `model`'s fit, the verdict first, by `code` (`CalculiX`).
///
/// # Errors
/// A load point beyond F_gross ([`compare_fit`]), in words.
#[cfg(feature = "app")]
pub(crate) fn pane_brief(
    model: &PressFitModel,
    loaded: &Loaded<PressFitFePoint>,
    code: &str,
) -> Result<String, String> {
    let rows = compare_fit(&model.fit, &loaded.points).map_err(|e| e.to_string())?;
    let summary = fit_summary(&rows);
    let deltas: Vec<String> = rows
        .iter()
        .filter(|r| r.fe.kind == FitPointKind::Load)
        .map(|r| percent_or_na(r.delta_difference()))
        .collect();
    Ok(format!(
        "{code}: {}; Delta {} against the shear lag (not judged)",
        summary.short,
        if deltas.is_empty() {
            "-".to_string()
        } else {
            deltas.join(", ")
        }
    ))
}

impl CompareFace for PressFitProblem {
    const ONE_RUN: Option<&'static str> = None;
    type Checked = Vec<PressFitCompared>;
    type CompareRow = PressFitCompareRow;
    type CompareReport = PressFitCompareReport;

    fn checked(
        compared: Result<Vec<PressFitCompared>, ParamError>,
    ) -> Result<Vec<PressFitCompared>, ParamError> {
        compared
    }

    fn compare_report(
        source: &str,
        first: Vec<PressFitCompared>,
        more: Vec<Vec<PressFitCompared>>,
    ) -> (PressFitCompareReport, Vec<PressFitCompareRow>) {
        let rows: Vec<PressFitCompared> = first
            .into_iter()
            .chain(more.into_iter().flatten())
            .collect();
        let report = PressFitCompareReport::new(source, &rows);
        let table = report.rows.clone();
        (report, table)
    }

    fn compare_text(report: &PressFitCompareReport) -> String {
        report.text()
    }

    fn summary_mut(report: &mut PressFitCompareReport) -> &mut Summary {
        &mut report.verdict
    }

    /// Delta against the axisymmetric continuum at each load step (a fraction of the
    /// continuum's), the push-out capacity against F_gross and the pressure after the
    /// interference against Lamé's: what the judge bounds, for a ladder of runs to extrapolate.
    fn ladder_quantities(report: &PressFitCompareReport) -> Vec<LadderQuantity> {
        let mut quantities = Vec::new();
        for row in &report.rows {
            let at = format!("F = {} N", number(row.force));
            if let (Some(difference), Some(continuum)) = (row.continuum_diff, row.delta_continuum) {
                quantities.push(LadderQuantity {
                    name: format!("Delta at {at}"),
                    difference,
                    bound: Some(CONTINUUM_WITHIN),
                    value: Some(ValueScale {
                        closed_form: continuum,
                        scale: continuum,
                        unit: "mm".to_string(),
                    }),
                });
            }
            if let Some(difference) = row.capacity_diff {
                quantities.push(LadderQuantity {
                    name: "push-out capacity".to_string(),
                    difference,
                    bound: Some(report.capacity_within_fraction),
                    value: Some(ValueScale {
                        closed_form: row.gross,
                        scale: row.gross,
                        unit: "N".to_string(),
                    }),
                });
            }
            // The pressure after the interference step: the same on every row of a run.
            let pressure_named = quantities.iter().any(|q| q.name.starts_with("contact"));
            if let (Some(difference), false) = (row.pressure_diff, pressure_named) {
                quantities.push(LadderQuantity {
                    name: "contact pressure after the interference".to_string(),
                    difference,
                    bound: Some(report.pressure_within_fraction),
                    value: Some(ValueScale {
                        closed_form: row.pressure,
                        scale: row.pressure,
                        unit: "MPa".to_string(),
                    }),
                });
            }
        }
        quantities
    }
}
