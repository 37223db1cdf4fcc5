//! `microslip compare`: FE results beside the closed forms, as text, CSV or JSON. The numbers come
//! from [`crate::fe::compare`] and the verdicts from [`crate::fe::verdict`]; this folder only words
//! and lays them out. Each model's report is one type ([`beam::BeamCompareReport`],
//! [`plate::PlateCompareReport`]): JSON is serde of it, text a renderer of it, and the CSV is its
//! rows' table columns ([`BeamCompareRow`], [`PlateCompareRow`]) without the verdict.

pub mod beam;
pub mod continuum;
pub mod lap;
pub mod plate;
pub mod run;
pub mod stick_slope;
pub mod verdict;

use serde::Serialize;

use super::number;
use crate::fe::compare::{BeamCompared, LapCompared, PlateCompared};
use crate::fe::face::Deck;
use crate::kernel::params::ParamError;

/// A problem's comparison as `compare` and `bench` report it: how many result files one report
/// takes, how one file's comparison is checked, and the report and CSV rows of them all. Each
/// problem's application folder implements it (`src/problems/<name>/deck.rs`), so that the
/// command is written once for every problem with a deck.
pub trait CompareFace: Deck {
    /// Why a comparison takes one result file, when it does (the beams': all the load steps of
    /// one run, fitted together); `None` when the rows of several files are put together.
    const ONE_RUN: Option<&'static str>;
    /// One file's comparison, checked.
    type Checked;
    /// The CSV row of a comparison.
    type CompareRow: Serialize + Default;
    /// The report of a comparison: its JSON is serde of it, its text [`Self::compare_text`].
    type CompareReport: Serialize;

    /// `compared`, checked.
    ///
    /// # Errors
    /// A point the closed forms cannot be evaluated at (a force the structure does not carry).
    fn checked(compared: Self::Compared) -> Result<Self::Checked, ParamError>;

    /// The report of the comparisons of the files `source` names, `first` and then `more` (empty
    /// when [`Self::ONE_RUN`]), and its CSV rows.
    fn compare_report(
        source: &str,
        first: Self::Checked,
        more: Vec<Self::Checked>,
    ) -> (Self::CompareReport, Vec<Self::CompareRow>);

    /// The report as text.
    fn compare_text(report: &Self::CompareReport) -> String;

    /// The report's closing verdict, which the stick slope the FE code used may turn
    /// ([`stick_slope::add_to_summary`]).
    fn summary_mut(report: &mut Self::CompareReport) -> &mut verdict::Summary;
}

/// One row of `microslip compare beam`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct BeamCompareRow {
    /// Tip force on each beam (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// FE w(L) (mm).
    pub w_fe_mm: f64,
    /// Closed form, Euler-Bernoulli (the paper's) (mm).
    pub w_euler_mm: f64,
    /// (FE - Euler-Bernoulli) / Euler-Bernoulli; empty (null) at F = 0, where it is undefined.
    pub diff_euler: Option<f64>,
    /// Closed form plus the shear deflection (mm).
    pub w_shear_corrected_mm: f64,
    /// (FE - shear corrected) / shear corrected; empty (null) at F = 0.
    pub diff_shear_corrected: Option<f64>,
    /// The stated bound on that difference (V2), a fraction; empty (null) where (V2) is not
    /// calibrated.
    pub shear_corrected_within: Option<f64>,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows (empty without one).
    pub regime_fe: Option<&'static str>,
    /// Closed-form start of the macroslip zone X (mm).
    #[serde(rename = "X_mm")]
    pub macroslip_start: f64,
    /// FE X (mm), from K_T |slip| = mu P (empty without a slip profile).
    #[serde(rename = "X_fe_mm")]
    pub macroslip_start_fe: Option<f64>,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_euler_fraction: Option<f64>,
    pub diff_shear_corrected_fraction: Option<f64>,
    pub shear_corrected_within_fraction: Option<f64>,
}

impl From<&BeamCompared> for BeamCompareRow {
    fn from(r: &BeamCompared) -> Self {
        BeamCompareRow {
            force: r.fe.force,
            w_fe_mm: r.fe.deflection,
            w_euler_mm: r.euler,
            diff_euler: r.difference_euler(),
            w_shear_corrected_mm: r.shear_corrected,
            diff_shear_corrected: r.difference_shear_corrected(),
            shear_corrected_within: r.shear_corrected_within,
            regime: r.regime.label(),
            regime_fe: r.fe.interface.map(|i| i.regime.label()),
            macroslip_start: r.macroslip_start,
            macroslip_start_fe: r.fe.interface.map(|i| i.macroslip_start),
            diff_euler_fraction: r.difference_euler(),
            diff_shear_corrected_fraction: r.difference_shear_corrected(),
            shear_corrected_within_fraction: r.shear_corrected_within,
        }
    }
}

/// One row of `microslip compare plate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PlateCompareRow {
    /// The run's stick slope K_T (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub stiffness: f64,
    /// FE u(L) (mm): thickness mean for CalculiX, the given value for CSV.
    pub u_fe_mm: f64,
    /// FE u(L) at the contact face (mm).
    pub u_fe_contact_face_mm: Option<f64>,
    /// FE u(L) at mid-thickness (mm).
    pub u_fe_mid_thickness_mm: Option<f64>,
    /// Strip theory, regularized law (mm).
    pub u_mm: f64,
    /// (FE - closed form) / closed form; empty (null) where the closed form is 0 (nu = 0).
    pub diff: Option<f64>,
    /// The same at the contact face.
    pub diff_contact_face: Option<f64>,
    /// The same at mid-thickness.
    pub diff_mid_thickness: Option<f64>,
    /// Strip theory, plain Coulomb law (mm).
    pub u_coulomb_mm: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows.
    pub regime_fe: Option<&'static str>,
    /// Closed-form X_r (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_zone_end: f64,
    /// FE X_r (mm), from K_T |slip| = mu P.
    #[serde(rename = "Xr_fe_mm")]
    pub micro_zone_end_fe: Option<f64>,
    /// The K_T whose closed-form u(L) equals the FE value (MPa/mm).
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// (V1) for the thickness mean at the run's K_T; the implied K_T is given only where it holds.
    pub strip_theory: &'static str,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_fraction: Option<f64>,
    pub diff_contact_face_fraction: Option<f64>,
    pub diff_mid_thickness_fraction: Option<f64>,
}

impl From<&PlateCompared> for PlateCompareRow {
    fn from(r: &PlateCompared) -> Self {
        let through = r.fe.through_thickness;
        let diffs = r.differences_through_thickness();
        PlateCompareRow {
            stiffness: r.fe.stiffness,
            u_fe_mm: r.fe.end_displacement,
            u_fe_contact_face_mm: through.map(|u| u[0]),
            u_fe_mid_thickness_mm: through.map(|u| u[1]),
            u_mm: r.closed,
            diff: r.difference(),
            diff_contact_face: diffs.map(|d| d[0]),
            diff_mid_thickness: diffs.map(|d| d[1]),
            u_coulomb_mm: r.coulomb,
            regime: r.regime.label(),
            regime_fe: r.fe_interface().map(|i| i.regime.label()),
            micro_zone_end: r.micro_zone_end,
            micro_zone_end_fe: r.fe_interface().map(|i| i.macroslip_start),
            implied_stiffness: r.implied_stiffness,
            strip_theory: r.strip_validity.label(),
            diff_fraction: r.difference(),
            diff_contact_face_fraction: diffs.map(|d| d[0]),
            diff_mid_thickness_fraction: diffs.map(|d| d[1]),
        }
    }
}

/// One row of `microslip compare lap`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct LapCompareRow {
    /// The force through the joint (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// FE Delta (mm): thickness means, zeroed after clamping, for CalculiX; the given value for
    /// CSV.
    #[serde(rename = "Delta_fe_mm")]
    pub delta_fe: f64,
    /// Shear-lag closed form, regularized law (mm).
    #[serde(rename = "Delta_mm")]
    pub delta: f64,
    /// (FE - closed form) / closed form; empty (null) at F = 0.
    pub diff: Option<f64>,
    /// The shear-lag envelope's bound on that difference (L14), a fraction; empty (null) where
    /// not calibrated.
    pub shear_lag_within: Option<f64>,
    /// Plain Coulomb law (mm).
    #[serde(rename = "Delta_coulomb_mm")]
    pub delta_coulomb: f64,
    /// The closed form's regime.
    pub regime: &'static str,
    /// The regime the FE slip profile shows.
    pub regime_fe: Option<&'static str>,
    /// Closed-form sliding zone from x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_start: f64,
    /// FE a (mm), from K_T |slip| = mu P.
    #[serde(rename = "a_fe_mm")]
    pub slide_from_start_fe: Option<f64>,
    /// Closed-form sliding zone from x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_end: f64,
    /// FE d (mm).
    #[serde(rename = "d_fe_mm")]
    pub slide_from_end_fe: Option<f64>,
    /// The K_T whose closed-form Delta equals the FE value (MPa/mm), given only where the
    /// shear-lag theory holds.
    #[serde(rename = "KT_implied_MPa_per_mm")]
    pub implied_stiffness: Option<f64>,
    /// The shear-lag theory's level at this force (L14).
    pub shear_lag: &'static str,
    /// Deprecated names above (kept one release): the same values under names that say their
    /// unit, a fraction (0.034 is 3.4 %). Added last, so no column moves.
    pub diff_fraction: Option<f64>,
    pub shear_lag_within_fraction: Option<f64>,
}

impl From<&LapCompared> for LapCompareRow {
    fn from(r: &LapCompared) -> Self {
        LapCompareRow {
            force: r.fe.force,
            delta_fe: r.fe.joint_displacement,
            delta: r.closed,
            diff: r.difference(),
            shear_lag_within: r.theory_within,
            delta_coulomb: r.coulomb,
            regime: r.regime.label(),
            regime_fe: r.fe.interface.map(|i| i.regime.label()),
            slide_from_start: r.zones.0,
            slide_from_start_fe: r.fe.interface.map(|i| i.slide_from_start),
            slide_from_end: r.zones.1,
            slide_from_end_fe: r.fe.interface.map(|i| i.slide_from_end),
            implied_stiffness: r.implied_stiffness,
            shear_lag: r.theory_validity.label(),
            diff_fraction: r.difference(),
            shear_lag_within_fraction: r.theory_within,
        }
    }
}

/// A relative difference in percent: two decimals, or the exponent form beyond 1e5 % (a number of
/// 200 digits helps nobody), "n/a" where it is undefined (a closed form of 0).
pub(crate) fn percent(x: f64) -> String {
    let p = 100.0 * x;
    if p.abs() < 1e5 {
        format!("{p:+.2} %")
    } else {
        format!("{p:+.2e} %")
    }
}

pub(crate) fn percent_or_na(x: Option<f64>) -> String {
    x.map_or_else(|| "n/a".to_string(), percent)
}

/// The range of the defined `values` as "a to b %", or the one value; "n/a" when none is.
/// Compact: it goes on the status line.
#[cfg(feature = "app")]
pub(crate) fn percent_range(values: impl Iterator<Item = Option<f64>>) -> String {
    let (lo, hi) = values
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        "n/a".to_string()
    } else if lo == hi {
        percent(lo)
    } else {
        format!("{:+.2} to {}", 100.0 * lo, percent(hi))
    }
}

/// The note under a table with an undefined relative difference.
pub(crate) const UNDEFINED_NOTE: &str = "n/a: the closed form is 0 there (no load, or nothing squeezes the \
plate sideways), so a relative difference is undefined; compare the values themselves.";

fn optional(x: Option<f64>) -> String {
    x.map_or_else(|| "-".to_string(), number)
}
