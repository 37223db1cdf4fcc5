//! The twin beams' reports: their K_T table columns, their paper table and their sweep row
//! ([`ReportFace`]).

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::Regime;
use crate::report::face::{KtHeading, KtRow, ReportFace};
use crate::report::number;
use crate::report::point::regime_label;
use crate::report::rows::BeamRow;
use crate::study::curves::{Answer, beam_point};

use super::closed_form::{TipForce, TwinBeams};
use super::load_driven::BeamPoint;
use super::params::TwinBeamsParams;
use super::problem::TwinBeamsProblem;

/// What a candidate K_T does to the beams at the model's force (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamKtAnswer {
    /// First-macroslip force F_1 (N).
    #[serde(rename = "F_1_N")]
    pub first_macroslip_force: f64,
    /// End of the microslip zone X (mm).
    #[serde(rename = "X_mm")]
    pub micro_end: f64,
    /// Tip deflection w(L) (mm).
    #[serde(rename = "w_tip_mm")]
    pub tip_deflection: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

/// Tip forces of the paper report's beam table, as multiples of F_thre: stick, threshold, then slip.
const BEAM_FORCE_FACTORS: [f64; 7] = [0.5, 1.0, 1.125, 1.25, 1.5, 2.5, 3.75];

impl ReportFace for TwinBeamsProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(T1)";
    type KtAnswer = BeamKtAnswer;

    fn kt_answer(answer: &Answer) -> Option<BeamKtAnswer> {
        match *answer {
            Answer::Beam {
                first_macroslip_force,
                micro_end,
                tip_deflection,
                regime,
            } => Some(BeamKtAnswer {
                first_macroslip_force,
                micro_end,
                tip_deflection,
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
            "K_T candidates for preset {preset}: twin beams at F = {} N, mu P = {mu_p} MPa, contact elements {element} mm",
            force.map_or_else(|| "-".to_string(), number),
        );
        let _ = writeln!(
            out,
            "{:<16} {:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {:<20} basis",
            "source",
            "K_T (MPa/mm)",
            "F_1 (N)",
            "X (mm)",
            "w(L) (mm)",
            "vs current",
            "vs Coulomb",
            "regime"
        );
        out
    }

    fn kt_row(row: &KtRow, answer: Option<&BeamKtAnswer>) -> String {
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
                "{source:<16} {kt:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {:<20} {basis}",
                number(a.first_macroslip_force),
                number(a.micro_end),
                number(a.tip_deflection),
                off,
                off_coulomb,
                a.regime.label(),
            ),
            None => writeln!(
                out,
                "{source:<16} {kt:>12} {:>10} {:>10} {:>11} {:>10} {:>10}  {unanswered:<20} {basis}",
                "-", "-", "-", "-", "-",
            ),
        };
        out
    }

    fn paper_table() -> Option<String> {
        // The paper's parameters are valid constants: construction cannot fail.
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).ok()?;
        let mut out = String::new();
        write_beam_table(&mut out, &beams);
        Some(out)
    }
}

fn write_beam_table(out: &mut String, beams: &TwinBeams) {
    let p = beams.params();
    let _ = writeln!(
        out,
        "Twin cantilever beams (Ligier & Bonhote 2014, section 2.1)"
    );
    let _ = writeln!(
        out,
        "  L = {} mm, b = {} mm, h = {} mm, E = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
        p.length,
        p.width,
        p.half_height,
        p.youngs_modulus,
        p.pressure,
        p.friction,
        p.tangential_stiffness
    );
    let _ = writeln!(
        out,
        "  F_thre = {} N (Coulomb slip), F_1 = {} N (first macroslip, at x = {} mm), mu P / K_T = {} um",
        number(beams.threshold_force()),
        number(beams.first_macroslip_force()),
        number(beams.first_macroslip_position()),
        number(beams.saturation_slip() * 1e3)
    );
    let _ = writeln!(
        out,
        "  {:>8}  {:>14}  {:>18}  {:>9}  {:<10}  regularized",
        "F (N)", "w_Coulomb (mm)", "w_regularized (mm)", "X (mm)", "Coulomb"
    );
    for factor in BEAM_FORCE_FACTORS {
        let Ok(force) = TipForce::new(factor * beams.threshold_force()) else {
            continue;
        };
        let row = beam_point(beams, force);
        let _ = writeln!(
            out,
            "  {:>8}  {:>14}  {:>18}  {:>9}  {:<10}  {}",
            number(row.force),
            number(row.w_coulomb),
            number(row.w_regularized),
            number(row.micro_end),
            row.regime_coulomb,
            row.regime_regularized
        );
    }
}


impl From<&BeamPoint> for BeamRow {
    fn from(p: &BeamPoint) -> Self {
        BeamRow {
            force: p.force,
            w_coulomb_mm: p.w_coulomb,
            w_regularized_mm: p.w_regularized,
            micro_end: p.micro_end,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
            beam_theory: p.validity.theory.key(),
            vs_continuum_within: p.validity.expected_error,
            vs_continuum_within_fraction: p.validity.expected_error,
        }
    }
}

