//! The twin beams' reports: their K_T table columns, their paper table and their sweep row
//! ([`ReportFace`]).
//!
//! `microslip beam`: the twin beams at one tip force, both laws side by side.

use std::fmt::Write as _;

use serde::{Serialize, Serializer};

use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::numeric::NumericError;
use crate::problems::Problem;
use crate::problems::inputs::Inputs;
use crate::problems::stiffness::mm_to_um;
use crate::report::face::{KtColumn, ReportFace, point_continuum};
use crate::report::point::cycle::{self, AnyCycleFace, CycleFace, CycleKeys, CycleWords};
use crate::report::point::{InputsReport, SideBySide, regime_label, validity_label};
use crate::report::rows::LoopRow;
use crate::report::{number, number_with, sanitize};
use crate::study::curves::{Answer, beam_point};

use super::closed_form::{BeamTheory, TipForce, TwinBeams};
use super::continuum::ContinuumBeams;
use super::params::TwinBeamsParams;
use super::point::BeamPoint;
use super::problem::{BeamsInputs, BeamsModel, TwinBeamsProblem};
use super::validity::CALIBRATED_FRICTION_STRAIN;

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
    const KT_TITLE: &'static str = "twin beams";
    const KT_COLUMNS: &'static [KtColumn] = &[
        KtColumn::Answer {
            title: "F_1 (N)",
            width: 10,
        },
        KtColumn::Answer {
            title: "X (mm)",
            width: 10,
        },
        KtColumn::Answer {
            title: "w(L) (mm)",
            width: 11,
        },
        KtColumn::VsCurrent,
        KtColumn::VsCoulomb,
    ];
    const KT_REGIME_WIDTH: usize = 20;
    type KtAnswer = BeamKtAnswer;
    type PointReport = BeamReport;
    type SweepRow = BeamRow;

    /// The 2-D plane-stress continuum (default mesh) is solved when asked (`--continuum`):
    /// seconds, not microseconds, so never unasked.
    fn point_report(
        preset: &str,
        model: &BeamsModel,
        continuum: bool,
    ) -> Result<BeamReport, NumericError> {
        let solved = point_continuum(continuum, true, || {
            super::solve_beams_continuum(
                model.beams.params(),
                model.force.newtons(),
                super::BeamsContinuumMesh::default(),
            )
        })?;
        let mut report = BeamReport::new(preset, &model.beams, model.force);
        report.continuum = solved
            .as_ref()
            .map(|c| BeamContinuumReport::new(c, &model.beams, model.force));
        Ok(report)
    }

    fn point_text(report: &BeamReport) -> String {
        report.text()
    }

    fn cycle() -> Option<&'static dyn AnyCycleFace> {
        Some(cycle::erased::<Self>())
    }

    fn kt_answer(answer: &Answer) -> Option<BeamKtAnswer> {
        match *answer {
            Answer::Beam(super::stiffness_answer::BeamAnswer {
                first_macroslip_force,
                micro_end,
                tip_deflection,
                regime,
            }) => Some(BeamKtAnswer {
                first_macroslip_force,
                micro_end,
                tip_deflection,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_values(a: &BeamKtAnswer) -> (Vec<f64>, Regime) {
        (
            vec![a.first_macroslip_force, a.micro_end, a.tip_deflection],
            a.regime,
        )
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

/// One row of `microslip sweep beam`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct BeamRow {
    /// Tip force (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// Coulomb tip deflection (mm).
    pub w_coulomb_mm: f64,
    /// Regularized tip deflection (mm).
    pub w_regularized_mm: f64,
    /// End of the microslip zone (mm).
    #[serde(rename = "X_mm")]
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: &'static str,
    /// Regularized regime.
    pub regime_regularized: &'static str,
    /// The deflection's beam theory (`euler-bernoulli` or `timoshenko`). Added after the original
    /// columns, which scripts read by name.
    pub beam_theory: &'static str,
    /// Bound on |w(L) continuum FE / w(L) here - 1| (V2), a fraction; empty where (V2) is not
    /// calibrated (`beam_theory` still names the theory). Deprecated: the same value as
    /// `vs_continuum_within_fraction`, kept one release for scripts that read it.
    pub vs_continuum_within: Option<f64>,
    /// The same bound under the name that says its unit (a fraction: 0.034 is 3.4 %). Added
    /// last, so no column moves. Deprecated: the same value as
    /// `vs_continuum_nlgeom_within_fraction`, which names its kinematics.
    pub vs_continuum_within_fraction: Option<f64>,
    /// The (V2) bound for continuum FE with large rotations (`NLGEOM`), a fraction. Added last.
    pub vs_continuum_nlgeom_within_fraction: Option<f64>,
    /// The (V2L) bound for continuum FE in linear geometry, a fraction. Added last.
    pub vs_continuum_linear_within_fraction: Option<f64>,
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
            vs_continuum_nlgeom_within_fraction: p.validity.expected_error,
            vs_continuum_linear_within_fraction: p.validity.linear_geometry_error,
        }
    }
}

/// What D, U and the secant stiffness of the beams refer to.
pub(crate) const CYCLE_UNITS_NOTE: &str = "D and U are for the pair (both beams' tip forces, the whole \
     interface; U = 1/2 (2 F_a) w_a); the secant stiffness F_a/w_a and the loop w(F) are one beam's \
     (the loop's area is D/2).";

impl CycleFace for TwinBeamsProblem {
    const CYCLE_WORDS: CycleWords = CycleWords {
        peak_key: "w_peak_mm",
        keys: CycleKeys::FORCE,
        heading: ("Twin beams", "tip force"),
        rows: [
            "onset of sliding (N)",
            "peak deflection w_a (mm)",
            "D per cycle, both beams (N mm)",
            "peak energy U, both (N mm)",
            "damping ratio D / (4 pi U) (-)",
            "secant F_a/w_a, 1 beam (N/mm)",
        ],
        note: CYCLE_UNITS_NOTE,
    };

    fn structure_line(beams: &TwinBeams) -> String {
        let p = beams.params();
        format!(
            "L = {} mm, b = {} mm, h = {} mm, E = {} MPa, P = {} MPa, mu = {}, K_T = {} MPa/mm",
            number(p.length),
            number(p.width),
            number(p.half_height),
            number(p.youngs_modulus),
            number(p.pressure),
            number(p.friction),
            number(p.tangential_stiffness)
        )
    }

    type LoopRow = LoopRow;
    type LoadRow = BeamRow;

    fn cycle_inputs(beams: &TwinBeams, amplitude: TipForce) -> Inputs {
        TwinBeamsProblem::to_inputs(BeamsInputs {
            structure: beams.params(),
            force: amplitude.newtons(),
        })
    }
}

/// The twin-beam report at one force.
#[derive(Debug, Clone, Serialize)]
pub struct BeamReport {
    /// Always `beam`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// Tip force of the report (N), also in `inputs`; the text's heading.
    #[serde(skip)]
    pub force: f64,
    /// Coulomb: the whole interface slides above it (N).
    #[serde(rename = "F_thre_N")]
    pub threshold_force: f64,
    /// Regularized: macroslip starts above it (N).
    #[serde(rename = "F_1_N")]
    pub first_macroslip_force: f64,
    /// Where that macroslip starts (mm, the free end).
    #[serde(rename = "first_macroslip_at_mm")]
    pub first_macroslip_position: f64,
    /// mu P / K_T (mm).
    #[serde(rename = "saturation_slip_mm")]
    pub saturation_slip: f64,
    pub coulomb: BeamCoulomb,
    pub regularized: BeamRegularized,
    pub beam_theory: BeamTheoryReport,
    /// The 2-D plane-stress continuum at the same force (docs/theory.md, "The twin beams'
    /// continuum"), when asked for (`--continuum`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<BeamContinuumReport>,
}

/// The twin beams' 2-D plane-stress continuum answer, or why there is none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum BeamContinuumReport {
    Solved(BeamContinuumSolved),
    Failed {
        /// Why the continuum solver gave no answer.
        error: String,
    },
}

/// What the continuum gives where beam theory assumes.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamContinuumSolved {
    /// w(L) (mm): the mean v of both beams' tip nodes at mid-height, as the deck reads it.
    #[serde(rename = "w_mm")]
    pub tip_deflection: f64,
    /// (continuum - Timoshenko) / Timoshenko for w(L), a fraction (0.004 is 0.4 %).
    pub diff_vs_timoshenko_fraction: f64,
    /// Start of the macroslip zone from the clamp, where K_T |s| = mu P (mm; L: none).
    #[serde(rename = "X_mm")]
    pub macroslip_start: f64,
    /// The force at which its first interface pair saturates (N): the continuum's F_1.
    #[serde(rename = "F_1_N")]
    pub elastic_limit: f64,
    /// The least and largest contact pressure along the interface (MPa): P in beam theory.
    #[serde(rename = "contact_pressure_min_MPa")]
    pub pressure_min: f64,
    #[serde(rename = "contact_pressure_max_MPa")]
    pub pressure_max: f64,
    /// Node pairs whose faces would open (held by the tie, without friction).
    pub separated_pairs: usize,
}

impl BeamContinuumReport {
    fn new(
        solved: &Result<ContinuumBeams, NumericError>,
        beams: &TwinBeams,
        force: TipForce,
    ) -> BeamContinuumReport {
        match solved {
            Err(e) => BeamContinuumReport::Failed {
                error: e.to_string(),
            },
            Ok(c) => {
                let timoshenko = beams
                    .with_theory(BeamTheory::EulerBernoulli)
                    .regularized(force)
                    .tip_deflection()
                    + beams.shear_deflection(force);
                let (pressure_min, pressure_max) = c
                    .contact_pressure
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (_, p)| {
                        (lo.min(*p), hi.max(*p))
                    });
                BeamContinuumReport::Solved(BeamContinuumSolved {
                    tip_deflection: c.tip_deflection,
                    diff_vs_timoshenko_fraction: c.tip_deflection / timoshenko - 1.0,
                    macroslip_start: c.macroslip_start,
                    elastic_limit: c.elastic_limit,
                    pressure_min,
                    pressure_max,
                    separated_pairs: c.separated.len(),
                })
            }
        }
    }

    /// Its lines in the text report.
    fn write(&self, out: &mut String) {
        match self {
            BeamContinuumReport::Failed { error } => {
                let _ = writeln!(out, "2-D continuum: FAILED, no answer ({error})");
            }
            BeamContinuumReport::Solved(c) => {
                let _ = writeln!(
                    out,
                    "2-D continuum (plane stress, small strain, docs/theory.md \"The twin beams' continuum\")\n  \
                     w(L) = {} mm ({:+} % vs Timoshenko), X = {} mm, F_1 = {} N\n  \
                     contact pressure {} to {} MPa, {} pairs would open",
                    number(c.tip_deflection),
                    number_with(100.0 * c.diff_vs_timoshenko_fraction, 3),
                    number(c.macroslip_start),
                    number(c.elastic_limit),
                    number(c.pressure_min),
                    number(c.pressure_max),
                    c.separated_pairs
                );
            }
        }
    }
}

/// The plain Coulomb law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamCoulomb {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// w(L) (mm).
    #[serde(rename = "w_tip_mm")]
    pub tip_deflection: f64,
    /// End of the stick zone, from the clamp (mm).
    #[serde(rename = "stick_end_mm")]
    pub stick_end: f64,
}

/// The regularized law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamRegularized {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// w(L) (mm).
    #[serde(rename = "w_tip_mm")]
    pub tip_deflection: f64,
    /// End of the microslip zone X, from the clamp (mm).
    #[serde(rename = "X_mm")]
    pub micro_end: f64,
}

/// The beam theory and how far its w(L) may be from continuum FE (V2).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BeamTheoryReport {
    /// In JSON its key (`euler-bernoulli`), in text its label.
    #[serde(serialize_with = "theory_key")]
    pub theory: BeamTheory,
    /// Shear deflection over the Euler-Bernoulli w(L), a fraction. Deprecated: the same value
    /// as `shear_deflection_share_fraction`, kept one release.
    pub shear_deflection_share: f64,
    /// The same share under the name that says its unit (0.019 is 1.9 %).
    pub shear_deflection_share_fraction: f64,
    /// Bound on the difference from continuum FE with `NLGEOM`, a fraction; absent where (V2) is
    /// not calibrated. Deprecated: the same value as `vs_continuum_nlgeom_within_fraction`.
    #[serde(
        rename = "vs_continuum_within",
        skip_serializing_if = "Option::is_none"
    )]
    pub expected_error: Option<f64>,
    /// The same bound under the name that says its unit, as `sweep beam`'s column: a fraction
    /// (0.03 is 3 %); absent where (V2) is not calibrated. Deprecated: the same value as
    /// `vs_continuum_nlgeom_within_fraction`, which names its kinematics.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vs_continuum_within_fraction: Option<f64>,
    /// (V2): the bound for continuum FE with large rotations (CalculiX's `NLGEOM`, on which it
    /// was calibrated), a fraction; absent where (V2) is not calibrated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vs_continuum_nlgeom_within_fraction: Option<f64>,
    /// (V2L): the bound for continuum FE in linear geometry, a fraction (wider beyond first
    /// slip); absent where (V2) is not calibrated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vs_continuum_linear_within_fraction: Option<f64>,
    /// The friction strain mu P L / (2 E h) that decides whether (V2) is calibrated.
    pub friction_strain: f64,
    /// The level of the `NLGEOM` bound (V2).
    #[serde(serialize_with = "validity_label")]
    pub validity: Validity,
    /// The level of the linear-geometry bound (V2L).
    #[serde(serialize_with = "validity_label")]
    pub validity_linear_geometry: Validity,
}

fn theory_key<S: Serializer>(theory: &BeamTheory, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(theory.key())
}

impl BeamReport {
    pub fn new(preset: &str, beams: &TwinBeams, force: TipForce) -> BeamReport {
        let row = beam_point(beams, force);
        BeamReport {
            model: "beam",
            preset: preset.to_string(),
            inputs: InputsReport(TwinBeamsProblem::to_inputs(BeamsInputs {
                structure: beams.params(),
                force: force.newtons(),
            })),
            force: row.force,
            threshold_force: beams.threshold_force(),
            first_macroslip_force: beams.first_macroslip_force(),
            first_macroslip_position: beams.first_macroslip_position(),
            saturation_slip: beams.saturation_slip(),
            coulomb: BeamCoulomb {
                regime: row.regime_coulomb,
                tip_deflection: row.w_coulomb,
                stick_end: row.stick_end,
            },
            regularized: BeamRegularized {
                regime: row.regime_regularized,
                tip_deflection: row.w_regularized,
                micro_end: row.micro_end,
            },
            beam_theory: BeamTheoryReport {
                theory: row.validity.theory,
                shear_deflection_share: row.validity.shear_share,
                shear_deflection_share_fraction: row.validity.shear_share,
                expected_error: row.validity.expected_error,
                vs_continuum_within_fraction: row.validity.expected_error,
                vs_continuum_nlgeom_within_fraction: row.validity.expected_error,
                vs_continuum_linear_within_fraction: row.validity.linear_geometry_error,
                friction_strain: row.validity.friction_strain,
                validity: row.validity.validity,
                validity_linear_geometry: row
                    .validity
                    .linear_geometry_error
                    .map_or(Validity::NotCalibrated, Validity::of_error),
            },
            continuum: None,
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Twin cantilever beams (Ligier & Bonhote 2014, section 2.1) - preset {}",
            sanitize(&self.preset)
        );
        self.inputs.write(&mut out);
        let _ = writeln!(out, "Thresholds");
        let _ = writeln!(
            out,
            "  F_thre     = {:<14} Coulomb: the whole interface slides above it",
            format!("{} N", number(self.threshold_force))
        );
        let _ = writeln!(
            out,
            "  F_1        = {:<14} regularized: macroslip starts above it, at x = {} mm (free end)",
            format!("{} N", number(self.first_macroslip_force)),
            number(self.first_macroslip_position)
        );
        let _ = writeln!(
            out,
            "  mu P / K_T = {:<14} saturation slip",
            format!("{} um", number(mm_to_um(self.saturation_slip)))
        );
        let _ = writeln!(
            out,
            "{:<24}{:<22}regularized",
            format!("At F = {} N", number(self.force)),
            "Coulomb"
        );
        let (c, r) = (&self.coulomb, &self.regularized);
        SideBySide {
            response: "w(L) (mm)",
            ratio: "w_reg / w_Coulomb",
            values: (c.tip_deflection, r.tip_deflection),
            regimes: (c.regime, r.regime),
            zone_ends: (
                format!("{} (stick end)", number(c.stick_end)),
                format!("{} (microslip end X)", number(r.micro_end)),
            ),
        }
        .write(&mut out);
        let v = &self.beam_theory;
        let left_out = match v.theory {
            BeamTheory::EulerBernoulli => format!(
                "; it leaves out the shear deflection, {} % of w(L) (--beam-theory timoshenko adds it)",
                number_with(100.0 * v.shear_deflection_share, 3)
            ),
            BeamTheory::Timoshenko => String::new(),
        };
        let envelope = match (v.expected_error, v.vs_continuum_linear_within_fraction) {
            (Some(bound), Some(linear))
                if number_with(100.0 * linear, 2) != number_with(100.0 * bound, 2) =>
            {
                format!(
                    "regularized w(L) within {} % of continuum FE with NLGEOM (large rotations; \
                     {}), within {} % of one in linear geometry ({}) (docs/theory.md (V2), \
                     (V2L)){left_out}",
                    number_with(100.0 * bound, 2),
                    v.validity.label(),
                    number_with(100.0 * linear, 2),
                    Validity::of_error(linear).label()
                )
            }
            (Some(bound), _) => format!(
                "regularized w(L) within {} % of continuum FE, with NLGEOM or in linear geometry \
                 (docs/theory.md (V2)): {}{left_out}",
                number_with(100.0 * bound, 2),
                v.validity.label()
            ),
            (None, _) => format!(
                "regularized w(L) against continuum FE: {} (docs/theory.md (V2)){left_out}\n  \
                 the friction strain mu P L / (2 E h) = {} is beyond the {} up to which (V2) was \
                 measured to hold: check with a continuum model",
                v.validity.label(),
                number_with(v.friction_strain, 3),
                number_with(CALIBRATED_FRICTION_STRAIN, 2)
            ),
        };
        let _ = writeln!(
            out,
            "Beam theory: {}{}\n  {envelope}",
            v.theory.label(),
            match v.theory {
                BeamTheory::EulerBernoulli => " (the paper's)",
                BeamTheory::Timoshenko => " (Euler-Bernoulli plus each beam's shear deflection)",
            },
        );
        if let Some(continuum) = &self.continuum {
            continuum.write(&mut out);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::csv::test_support::header;

    /// The header users' scripts read: a change here breaks them, so it must be deliberate.
    #[test]
    fn the_sweep_header_is_the_published_contract() {
        assert_eq!(
            header::<BeamRow>(),
            "F_N,w_coulomb_mm,w_regularized_mm,X_mm,regime_coulomb,regime_regularized,beam_theory,\
             vs_continuum_within,vs_continuum_within_fraction,vs_continuum_nlgeom_within_fraction,\
             vs_continuum_linear_within_fraction"
        );
    }

    #[test]
    fn beam_report_shows_units_thresholds_and_both_laws() {
        let beams = TwinBeams::new(TwinBeamsParams::PAPER).unwrap();
        let text = BeamReport::new("paper-beams", &beams, TipForce::new(100.0).unwrap()).text();
        for needle in [
            "KT  = 600 MPa/mm",
            "(0.6 MPa/um)",
            "F_thre     = 80 N",
            "F_1        = 80.1857 N",
            "0.5 um",
            "17.3095 (microslip end X)",
            "microslip+macroslip",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
    }
}
