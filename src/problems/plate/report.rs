//! The squeezed plate's reports: its K_T table columns and its paper table ([`ReportFace`]).

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::Regime;
use crate::report::face::{KtHeading, KtRow, ReportFace};
use crate::report::number;
use crate::report::point::regime_label;
use crate::study::curves::{Answer, plate_point};

use super::closed_form::SqueezedPlate;
use super::params::PlateParams;
use super::problem::SqueezedPlateProblem;

/// What a candidate K_T does to the plate (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PlateKtAnswer {
    /// End displacement u(L) (mm).
    #[serde(rename = "u_end_mm")]
    pub end_displacement: f64,
    /// End of the microslip zone X_r (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_end: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

/// K_T values of the paper report's plate table (MPa/mm): the decades of the paper's Fig. 14.
const PLATE_STIFFNESSES: [f64; 8] = [1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7];

impl ReportFace for SqueezedPlateProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(P10)";
    type KtAnswer = PlateKtAnswer;

    fn kt_answer(answer: &Answer) -> Option<PlateKtAnswer> {
        match *answer {
            Answer::Plate {
                end_displacement,
                micro_end,
                regime,
            } => Some(PlateKtAnswer {
                end_displacement,
                micro_end,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_heading(heading: &KtHeading) -> String {
        let KtHeading {
            preset,
            friction_stress: mu_p,
            element,
            ..
        } = *heading;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "K_T candidates for preset {preset}: squeezed plate, mu P = {mu_p} MPa, contact elements {element} mm",
        );
        let _ = writeln!(
            out,
            "{:<16} {:>12} {:>12} {:>10} {:>10} {:>10}  {:<20} basis",
            "source",
            "K_T (MPa/mm)",
            "u(L) (mm)",
            "vs current",
            "vs Coulomb",
            "X_r (mm)",
            "regime"
        );
        out
    }

    fn kt_row(row: &KtRow, answer: Option<&PlateKtAnswer>) -> String {
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
                "{source:<16} {kt:>12} {:>12} {:>10} {:>10} {:>10}  {:<20} {basis}",
                number(a.end_displacement),
                off,
                off_coulomb,
                number(a.micro_end),
                a.regime.label(),
            ),
            None => writeln!(
                out,
                "{source:<16} {kt:>12} {:>12} {:>10} {:>10} {:>10}  {unanswered:<20} {basis}",
                "-", "-", "-", "-",
            ),
        };
        out
    }

    fn paper_table() -> Option<String> {
        // The paper's parameters are valid constants: construction cannot fail.
        let plate = SqueezedPlate::new(PlateParams::PAPER).ok()?;
        let mut out = String::new();
        write_plate_table(&mut out, &plate);
        Some(out)
    }
}

fn write_plate_table(out: &mut String, plate: &SqueezedPlate) {
    let p = plate.params();
    let pressure = plate.contact_pressure();
    let first = plate_point(plate);
    let _ = writeln!(
        out,
        "Squeezed plate on a rigid plane (Ligier & Bonhote 2014, section 2.2)"
    );
    let _ = writeln!(
        out,
        "  L = {} mm (half-length), t_p = {} mm, E = {} MPa, nu = {}, mu = {}, P = {} MPa",
        p.half_length, p.thickness, p.youngs_modulus, p.poisson, p.friction, p.pressure
    );
    let _ = writeln!(
        out,
        "  Coulomb: X_s = {} mm, u(L) = {} mm, {}",
        number(first.stick_end),
        number(first.u_coulomb),
        first.regime_coulomb
    );
    let _ = writeln!(
        out,
        "  contact pressure P_r/P of the paper's flat-plate model (P7-P9, friction saturated \
         everywhere): {} (centre) to {} (edge); not the plate's (docs/theory.md (P12)): \
         `microslip plate` gives the plane-strain continuum's",
        number(pressure.ratio(0.0)),
        number(pressure.ratio(p.half_length)),
    );
    let _ = writeln!(
        out,
        "  {:>14}  {:>18}  {:>10}  regularized",
        "K_T (MPa/mm)", "u_regularized (mm)", "X_r (mm)"
    );
    for kt in PLATE_STIFFNESSES {
        let Ok(plate) = plate.with_tangential_stiffness(kt) else {
            continue;
        };
        let row = plate_point(&plate);
        let _ = writeln!(
            out,
            "  {:>14}  {:>18}  {:>10}  {}",
            number(row.kt),
            number(row.u_regularized),
            number(row.micro_end),
            row.regime_regularized
        );
    }
}

