//! The lap joint's reports: its K_T table columns and its sweep row ([`ReportFace`]).

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::Regime;
use crate::report::face::{KtHeading, KtRow, ReportFace};
use crate::report::number;
use crate::report::point::regime_label;
use crate::report::rows::LapRow;
use crate::study::curves::Answer;

use super::load_driven::LapPoint;
use super::problem::LapJointProblem;

/// What a candidate K_T does to the joint at the model's force (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct LapKtAnswer {
    /// Force of first sliding F_1 (N).
    #[serde(rename = "F_1_N")]
    pub first_slip_force: f64,
    /// Sliding zone a from x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_at_inner_end: f64,
    /// Sliding zone d from x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_at_cover_ends: f64,
    /// Joint displacement Delta (mm).
    #[serde(rename = "Delta_mm")]
    pub joint_displacement: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

impl ReportFace for LapJointProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(L11)";
    type KtAnswer = LapKtAnswer;

    fn kt_answer(answer: &Answer) -> Option<LapKtAnswer> {
        match *answer {
            Answer::Lap {
                first_slip_force,
                zones: (slide_at_inner_end, slide_at_cover_ends),
                joint_displacement,
                regime,
            } => Some(LapKtAnswer {
                first_slip_force,
                slide_at_inner_end,
                slide_at_cover_ends,
                joint_displacement,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_heading(heading: &KtHeading) -> String {
        let KtHeading {
            preset,
            force,
            friction_stress: mu_p,
            element,
        } = *heading;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "K_T candidates for preset {preset}: double-lap joint at F = {} N, mu P = {mu_p} MPa, contact elements {element} mm",
            force.map_or_else(|| "-".to_string(), number),
        );
        let _ = writeln!(
            out,
            "{:<16} {:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {:<29} basis",
            "source",
            "K_T (MPa/mm)",
            "F_1 (N)",
            "a (mm)",
            "d (mm)",
            "Delta (mm)",
            "vs current",
            "vs Coulomb",
            "regime"
        );
        out
    }

    fn kt_row(row: &KtRow, answer: Option<&LapKtAnswer>) -> String {
        let KtRow {
            source,
            kt,
            vs_current: off,
            vs_coulomb: off_coulomb,
            unanswered,
            basis,
        } = *row;
        let mut out = String::new();
        let _ = match answer {
            Some(a) => writeln!(
                out,
                "{source:<16} {kt:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {:<29} {basis}",
                number(a.first_slip_force),
                number(a.slide_at_inner_end),
                number(a.slide_at_cover_ends),
                number(a.joint_displacement),
                off,
                off_coulomb,
                a.regime.label(),
            ),
            None => writeln!(
                out,
                "{source:<16} {kt:>12} {:>10} {:>8} {:>8} {:>12} {:>10} {:>10}  {unanswered:<29} {basis}",
                "-", "-", "-", "-", "-", "-",
            ),
        };
        out
    }
}

impl From<&LapPoint> for LapRow {
    fn from(p: &LapPoint) -> Self {
        LapRow {
            force: p.force,
            delta_coulomb: p.delta_coulomb,
            delta_regularized: p.delta_regularized,
            slide_at_inner_end: p.zones_regularized.0,
            slide_at_cover_ends: p.zones_regularized.1,
            slide_at_inner_end_coulomb: p.zones_coulomb.0,
            slide_at_cover_ends_coulomb: p.zones_coulomb.1,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
            shear_lag_within: p.shear_lag_within,
            shear_lag_within_fraction: p.shear_lag_within,
        }
    }
}

