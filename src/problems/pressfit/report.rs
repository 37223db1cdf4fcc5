//! The press fit's reports ([`ReportFace`], [`CycleFace`]): `microslip pressfit` (the fit at one
//! push-out force, both laws side by side, with Lamé's pressure in plane stress and plane strain
//! and the 1-D theory's standing), its K_T table's columns, its sweep and loop rows, its cycle's
//! words.

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::{Law, Regime};
use crate::kernel::validity::Validity;
use crate::numeric::NumericError;
use crate::problems::Problem;
use crate::problems::inputs::Inputs;
use crate::problems::load_driven::MasingCycle;
use crate::problems::stiffness::mm_to_um;
use crate::report::face::{KtColumn, ReportFace, point_continuum};
use crate::report::point::cycle::{self, AnyCycleFace, CycleFace, CycleKeys, CycleWords};
use crate::report::point::{InputsReport, WideLaws, regime_label, threshold_line, validity_label};
use crate::report::{number, number_with, sanitize};
use crate::study::curves::{Answer, LoopPoint};

use super::closed_form::{CarriedLoad, PressFit};
use super::continuum::{ContinuumPressFit, PressFitContinuumMesh, solve_pressfit_continuum};
use super::cycle::FitCycle;
use super::params::FitLoad;
use super::point::{FitPoint, fit_point};
use super::registered::problem::{PressFitInputs, PressFitModel, PressFitProblem};
use super::registered::stiffness_answer::FitAnswer;

/// What a candidate K_T does to the fit at the model's force (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct FitKtAnswer {
    /// Force of first sliding F_1 (N).
    #[serde(rename = "F_1_N")]
    pub first_slip_force: f64,
    /// Sliding zone a from the loaded face x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    /// Sliding zone d from the held face x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// Delta (mm).
    #[serde(rename = "Delta_mm")]
    pub displacement: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

impl ReportFace for PressFitProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(S8)";
    const KT_TITLE: &'static str = "press fit";
    const FRICTION_STRESS: &'static str = "mu p";
    const KT_COLUMNS: &'static [KtColumn] = &[
        KtColumn::Answer {
            title: "F_1 (N)",
            width: 10,
        },
        KtColumn::Answer {
            title: "a (mm)",
            width: 8,
        },
        KtColumn::Answer {
            title: "d (mm)",
            width: 8,
        },
        KtColumn::Answer {
            title: "Delta (mm)",
            width: 12,
        },
        KtColumn::VsCurrent,
        KtColumn::VsCoulomb,
    ];
    const KT_REGIME_WIDTH: usize = 29;
    type KtAnswer = FitKtAnswer;
    type PointReport = PressFitReport;
    type SweepRow = FitRow;

    /// The axisymmetric continuum (default mesh) is solved when asked, or when the 1-D theory is
    /// not expected within 2 %; only the one asked for fails the command.
    fn point_report(
        preset: &str,
        model: &PressFitModel,
        continuum: bool,
    ) -> Result<PressFitReport, NumericError> {
        let (fit, force) = (model.fit, model.force);
        let holds = fit.validity(force).validity == Validity::Holds;
        let solved = point_continuum(continuum, holds, || {
            solve_pressfit_continuum(
                fit.params(),
                force.value(),
                PressFitContinuumMesh::default(),
            )
        })?;
        Ok(PressFitReport::new(preset, &fit, force, solved.as_ref()))
    }

    fn point_text(report: &PressFitReport) -> String {
        report.text()
    }

    fn cycle() -> Option<&'static dyn AnyCycleFace> {
        Some(cycle::erased::<Self>())
    }

    fn kt_answer(answer: &Answer) -> Option<FitKtAnswer> {
        match *answer {
            Answer::PressFit(FitAnswer {
                first_slip_force,
                zones: (slide_from_loaded_face, slide_from_held_face),
                displacement,
                regime,
            }) => Some(FitKtAnswer {
                first_slip_force,
                slide_from_loaded_face,
                slide_from_held_face,
                displacement,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_values(a: &FitKtAnswer) -> (Vec<f64>, Regime) {
        (
            vec![
                a.first_slip_force,
                a.slide_from_loaded_face,
                a.slide_from_held_face,
                a.displacement,
            ],
            a.regime,
        )
    }
}

/// One row of `microslip sweep pressfit` (and `sweep --vary F`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct FitRow {
    /// Push-out force (N).
    #[serde(rename = "F_N")]
    pub force: f64,
    /// Coulomb Delta (mm).
    #[serde(rename = "Delta_coulomb_mm")]
    pub delta_coulomb: f64,
    /// Regularized Delta (mm).
    #[serde(rename = "Delta_regularized_mm")]
    pub delta_regularized: f64,
    /// Regularized sliding zone from the loaded face x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    /// Regularized sliding zone from the held face x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// Coulomb sliding zone from x = 0 (mm).
    #[serde(rename = "a_coulomb_mm")]
    pub slide_from_loaded_face_coulomb: f64,
    /// Coulomb sliding zone from x = L (mm).
    #[serde(rename = "d_coulomb_mm")]
    pub slide_from_held_face_coulomb: f64,
    /// Coulomb regime.
    pub regime_coulomb: &'static str,
    /// Regularized regime.
    pub regime_regularized: &'static str,
}

impl From<&FitPoint> for FitRow {
    fn from(p: &FitPoint) -> Self {
        FitRow {
            force: p.force,
            delta_coulomb: p.delta_coulomb,
            delta_regularized: p.delta_regularized,
            slide_from_loaded_face: p.zones_regularized.0,
            slide_from_held_face: p.zones_regularized.1,
            slide_from_loaded_face_coulomb: p.zones_coulomb.0,
            slide_from_held_face_coulomb: p.zones_coulomb.1,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
        }
    }
}

/// One point of the fit's `microslip cycle --format csv` (the loop of Delta, both laws).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct FitLoopRow {
    /// `unloading` or `reloading`.
    pub branch: &'static str,
    /// Push-out force (N), negative when the shaft is pulled back.
    #[serde(rename = "F_N")]
    pub force: f64,
    /// Coulomb Delta (mm).
    #[serde(rename = "Delta_coulomb_mm")]
    pub delta_coulomb: f64,
    /// Regularized Delta (mm).
    #[serde(rename = "Delta_regularized_mm")]
    pub delta_regularized: f64,
}

impl From<&LoopPoint> for FitLoopRow {
    fn from(p: &LoopPoint) -> Self {
        FitLoopRow {
            branch: p.branch.label(),
            force: p.force,
            delta_coulomb: p.w_coulomb,
            delta_regularized: p.w_regularized,
        }
    }
}

/// What D, U and the secant stiffness of the fit refer to.
const FIT_CYCLE_NOTE: &str = "the push cycles between +F_a and -F_a on the shaft's end, the hub \
     held; D is the whole interface's; U = 1/2 F_a Delta_a; the secant stiffness is F_a / \
     Delta_a.";

impl CycleFace for PressFitProblem {
    const CYCLE_WORDS: CycleWords = CycleWords {
        peak_key: "Delta_peak_mm",
        keys: CycleKeys::FORCE,
        heading: ("Press fit", "push-out force"),
        rows: [
            "onset of sliding (N)",
            "peak displacement Delta_a (mm)",
            "D per cycle (N mm)",
            "peak energy U (N mm)",
            "damping ratio D / (4 pi U) (-)",
            "secant F_a/Delta_a (N/mm)",
        ],
        note: FIT_CYCLE_NOTE,
    };

    fn structure_line(fit: &PressFit) -> String {
        structure_line(fit)
    }

    type LoopRow = FitLoopRow;
    type LoadRow = FitRow;

    fn force_limit(fit: &PressFit) -> Option<f64> {
        Some(fit.gross_slip_force())
    }

    fn cycle_inputs(fit: &PressFit, amplitude: CarriedLoad) -> Inputs {
        PressFitProblem::to_inputs(PressFitInputs {
            structure: fit.params(),
            force: amplitude.value(),
        })
    }
}

/// The fit in one line (its parameters with units and Lamé's p), under a cycle report's heading:
/// the push-out's and the torque's.
pub(super) fn structure_line(fit: &PressFit) -> String {
    let p = fit.params();
    format!(
        "r = {} mm, ri = {} mm, ro = {} mm, L = {} mm, Es = {} MPa, nus = {}, Eh = {} MPa, \
         nuh = {}, delta = {} mm, mu = {}, K_T = {} MPa/mm; p = {} MPa",
        number(p.fit_radius),
        number(p.bore_radius),
        number(p.outer_radius),
        number(p.length),
        number(p.shaft_modulus),
        number(p.shaft_poisson),
        number(p.hub_modulus),
        number(p.hub_poisson),
        number(p.interference),
        number(p.friction),
        number(p.tangential_stiffness),
        number(fit.contact_pressure())
    )
}

/// What the 1-D theory assumes and where its envelope comes from, said wherever its numbers are
/// shown.
const THEORY_NOTE: &str = "1-D theory (docs/theory.md section 18): Lamé's contact pressure p, \
     uniform over L and untouched by the load; each member's section strained uniformly (shear \
     lag of two bars). Its envelope (S10) bounds Delta's difference from an axisymmetric \
     continuum, measured on 135 steel fits and held out on 24";

/// The press-fit report at one push-out force.
#[derive(Debug, Clone, Serialize)]
pub struct PressFitReport {
    /// Always `pressfit`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// Force of the report (N), also in `inputs`.
    #[serde(skip)]
    pub force: f64,
    /// Lamé's contact pressure in plane stress (MPa): what every number uses.
    #[serde(rename = "p_MPa")]
    pub pressure: f64,
    /// Lamé's contact pressure in plane strain (MPa), beside it.
    #[serde(rename = "p_plane_strain_MPa")]
    pub plane_strain_pressure: f64,
    /// Regularized: sliding starts above it (N).
    #[serde(rename = "F_1_N")]
    pub first_slip_force: f64,
    /// Where: `x=0` (the shaft's loaded face), `x=L` (the hub's held face) or `both`.
    pub first_slip_at: &'static str,
    /// In words, for the text.
    #[serde(skip)]
    pub first_slip_words: &'static str,
    /// Regularized: the other face starts sliding above it (N).
    #[serde(rename = "F_2_N")]
    pub second_slip_force: f64,
    /// Both laws: the whole fit slides at it, mu p 2 pi r L; no more is carried (N).
    #[serde(rename = "F_gross_N")]
    pub gross_slip_force: f64,
    /// mu p / K_T (mm).
    #[serde(rename = "saturation_slip_mm")]
    pub saturation_slip: f64,
    /// 1/lambda, the elastic slip's decay length (mm).
    #[serde(rename = "decay_length_mm")]
    pub decay_length: f64,
    /// The members' axial rigidities Es As and Eh Ah (N).
    #[serde(rename = "shaft_rigidity_N")]
    pub shaft_rigidity: f64,
    #[serde(rename = "hub_rigidity_N")]
    pub hub_rigidity: f64,
    pub coulomb: FitLaw,
    pub regularized: FitLaw,
    pub theory: FitTheoryReport,
    /// The axisymmetric continuum at the same force ((S10)), when it was solved (asked for, or
    /// where the 1-D theory is not expected within 2 %).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<FitContinuumReport>,
}

/// The axisymmetric continuum's answer, or why there is none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum FitContinuumReport {
    Solved(FitContinuumSolved),
    Failed {
        /// Why the continuum solver gave no answer.
        error: String,
    },
}

/// What the continuum gives where the 1-D theory assumes.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct FitContinuumSolved {
    /// Delta (mm): the shaft's loaded face's mean axial displacement, from the fitted state.
    #[serde(rename = "Delta_mm")]
    pub displacement: f64,
    /// (continuum - 1-D) / 1-D for Delta, a fraction (0.011 is 1.1 %).
    pub diff_vs_theory_fraction: Option<f64>,
    /// The sliding zones where K_T |s| >= mu p (the 1-D theory's reading) (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// The least and largest contact pressure over the fit (MPa): Lamé's p in the theory.
    #[serde(rename = "contact_pressure_min_MPa")]
    pub pressure_min: f64,
    #[serde(rename = "contact_pressure_max_MPa")]
    pub pressure_max: f64,
    /// mu times the total contact force (N): the continuum's own F_gross.
    #[serde(rename = "capacity_N")]
    pub capacity: f64,
    /// Node pairs whose faces would open (held by the tie, without friction).
    pub separated_pairs: usize,
}

impl FitContinuumReport {
    fn new(solved: &Result<ContinuumPressFit, NumericError>, theory: f64) -> FitContinuumReport {
        match solved {
            Err(e) => FitContinuumReport::Failed {
                error: e.to_string(),
            },
            Ok(c) => {
                let (pressure_min, pressure_max) = c
                    .pressure
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(_, p)| {
                        (lo.min(p), hi.max(p))
                    });
                FitContinuumReport::Solved(FitContinuumSolved {
                    displacement: c.delta,
                    diff_vs_theory_fraction: (theory != 0.0).then(|| c.delta / theory - 1.0),
                    slide_from_loaded_face: c.nominal_zones.from_loaded_face,
                    slide_from_held_face: c.nominal_zones.from_held_face,
                    pressure_min,
                    pressure_max,
                    capacity: c.capacity,
                    separated_pairs: c.separated.len(),
                })
            }
        }
    }
}

/// One law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct FitLaw {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// Delta: the shaft's loaded end relative to the hub's held face (mm).
    #[serde(rename = "Delta_mm")]
    pub displacement: f64,
    /// Sliding zone from the loaded face x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    /// Sliding zone from the held face x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// Energy dissipated per cycle of the push between +F and -F (N mm); `cycle`'s key.
    #[serde(rename = "D_Nmm")]
    pub dissipation: f64,
    /// The equivalent damping ratio D / (4 pi U), U = F Delta / 2 (dimensionless).
    #[serde(rename = "zeta")]
    pub damping_ratio: f64,
}

/// The 1-D theory's standing: its envelope against the axisymmetric continuum (S10) and the
/// sizes of what it leaves out (S9).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct FitTheoryReport {
    #[serde(serialize_with = "validity_label")]
    pub validity: Validity,
    /// The envelope's bound on Delta's difference from the continuum, a fraction (0.034 is
    /// 3.4 %); null where the calibration does not reach.
    pub theory_within_fraction: Option<f64>,
    /// Which calibrated range the fit leaves (null inside them).
    pub outside_calibration: Option<&'static str>,
    /// The end effect at the faces and the walls' shear compliance: the envelope's terms.
    pub end_effect: f64,
    pub wall_shear: f64,
    /// The load's Poisson change of the interference over delta: its third term.
    pub poisson_coupling: f64,
    /// (ro - r) / L.
    pub end_zone_over_length: f64,
    /// (1/lambda) over the thicker wall: small is where uniform strain is doubtful.
    pub decay_over_wall: f64,
    /// delta / r.
    pub interference_strain: f64,
    pub note: &'static str,
}

impl PressFitReport {
    /// The report of `fit` at `force`.
    pub fn new(
        preset: &str,
        fit: &PressFit,
        force: CarriedLoad,
        continuum: Option<&Result<ContinuumPressFit, NumericError>>,
    ) -> PressFitReport {
        let row = fit_point(fit.axial(), force);
        let p = fit.params();
        let law = |law, regime, delta, (a, d): (f64, f64)| {
            let cycle = FitCycle::new(fit.axial(), law, force);
            FitLaw {
                regime,
                displacement: delta,
                slide_from_loaded_face: a,
                slide_from_held_face: d,
                dissipation: cycle.dissipation(),
                damping_ratio: cycle.damping_ratio(),
            }
        };
        let [shaft_rigidity, hub_rigidity] = p.rigidities(FitLoad::Axial);
        let v = fit.validity(force);
        PressFitReport {
            model: "pressfit",
            preset: preset.to_string(),
            inputs: InputsReport(PressFitProblem::to_inputs(PressFitInputs {
                structure: p,
                force: force.value(),
            })),
            force: row.force,
            pressure: fit.contact_pressure(),
            plane_strain_pressure: fit.plane_strain_pressure(),
            first_slip_force: fit.first_slip_force(),
            first_slip_at: fit.first_slip_face().key(),
            first_slip_words: fit.first_slip_face().label(),
            second_slip_force: fit.second_slip_force(),
            gross_slip_force: fit.gross_slip_force(),
            saturation_slip: p.friction * fit.contact_pressure() / p.tangential_stiffness,
            decay_length: 1.0 / fit.axial().decay_rate(),
            shaft_rigidity,
            hub_rigidity,
            coulomb: law(
                Law::Coulomb,
                row.regime_coulomb,
                row.delta_coulomb,
                row.zones_coulomb,
            ),
            regularized: law(
                Law::Regularized,
                row.regime_regularized,
                row.delta_regularized,
                row.zones_regularized,
            ),
            theory: FitTheoryReport {
                validity: v.validity,
                theory_within_fraction: v.expected_error,
                outside_calibration: v.outside_calibration,
                end_effect: v.end_effect,
                wall_shear: v.wall_shear,
                poisson_coupling: v.poisson_coupling,
                end_zone_over_length: v.end_zone_over_length,
                decay_over_wall: v.decay_over_wall,
                interference_strain: v.interference_strain,
                note: THEORY_NOTE,
            },
            continuum: continuum.map(|c| FitContinuumReport::new(c, row.delta_regularized)),
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Press fit pushed out (shear lag, docs/theory.md section 18) - preset {}",
            sanitize(&self.preset)
        );
        self.inputs.write(&mut out);
        let _ = writeln!(
            out,
            "Contact pressure (Lamé): p = {} MPa in plane stress (used throughout), {} MPa in plane strain",
            number(self.pressure),
            number(self.plane_strain_pressure)
        );
        let _ = writeln!(
            out,
            "Members: shaft Es As = {} N, hub Eh Ah = {} N",
            number(self.shaft_rigidity),
            number(self.hub_rigidity)
        );
        let _ = writeln!(out, "Thresholds");
        threshold_line(
            &mut out,
            "F_1",
            format!("{} N", number(self.first_slip_force)),
            &format!(
                "regularized: sliding starts above it, at {}",
                self.first_slip_words
            ),
        );
        threshold_line(
            &mut out,
            "F_2",
            format!("{} N", number(self.second_slip_force)),
            "regularized: both faces slide above it",
        );
        threshold_line(
            &mut out,
            "F_gross",
            format!("{} N", number(self.gross_slip_force)),
            "both laws: the whole fit slides (mu p 2 pi r L); no more is carried",
        );
        threshold_line(
            &mut out,
            "mu p / K_T",
            format!("{} um", number(mm_to_um(self.saturation_slip))),
            &format!(
                "saturation slip; 1/lambda = {} mm, the elastic slip's decay length",
                number(self.decay_length)
            ),
        );
        let (c, r) = (&self.coulomb, &self.regularized);
        let mut table = WideLaws(&mut out);
        table.heading(format!("At F = {} N", number(self.force)));
        table.row("regime", c.regime.to_string(), r.regime.to_string());
        table.row("Delta (mm)", number(c.displacement), number(r.displacement));
        table.row(
            "a, from x = 0 (mm)",
            number(c.slide_from_loaded_face),
            number(r.slide_from_loaded_face),
        );
        table.row(
            "d, from x = L (mm)",
            number(c.slide_from_held_face),
            number(r.slide_from_held_face),
        );
        table.row(
            "D per cycle +-F (N mm)",
            number_with(c.dissipation, 4),
            number_with(r.dissipation, 4),
        );
        if c.displacement > 0.0 {
            table.both(
                "Delta_reg / Delta_Coulomb",
                number(r.displacement / c.displacement),
            );
        }
        let _ = writeln!(
            out,
            "  (a: sliding zone from x = 0, the shaft's loaded face; d: from x = L, the hub's held \
             face; Delta = the shaft's loaded end relative to the hub's held face)"
        );
        let v = &self.theory;
        // Where the continuum was solved, its measured difference is the answer, in place of the
        // envelope's bound.
        let measured = match &self.continuum {
            Some(FitContinuumReport::Solved(c)) => c.diff_vs_theory_fraction,
            _ => None,
        };
        let verdict = match (measured, v.theory_within_fraction, v.outside_calibration) {
            (Some(d), _, _) => format!(
                "Delta {} from the axisymmetric continuum solved below ({}; measured, in place \
                 of the envelope)",
                crate::report::compare::percent(d),
                Validity::of_error(d.abs()).label()
            ),
            (None, Some(e), _) => format!(
                "Delta within {} % of a continuum ({})",
                number_with(100.0 * e, 2),
                v.validity.label()
            ),
            (None, None, Some(why)) => {
                format!("not calibrated here ({why}): use the continuum")
            }
            (None, None, None) => "not calibrated here: use the continuum".to_string(),
        };
        let _ = writeln!(
            out,
            "Theory: {}\n  here: {verdict}; terms: end effect {}, walls' shear {}, Poisson \
             change of the interference {} %",
            v.note,
            number_with(v.end_effect, 3),
            number_with(v.wall_shear, 3),
            number_with(100.0 * v.poisson_coupling, 3),
        );
        match &self.continuum {
            None => {}
            Some(FitContinuumReport::Failed { error }) => {
                let _ = writeln!(
                    out,
                    "Axisymmetric continuum (S10): FAILED, no answer (the 1-D numbers above are \
                     unchecked): {}",
                    sanitize(error)
                );
            }
            Some(FitContinuumReport::Solved(c)) => {
                let _ = writeln!(
                    out,
                    "Axisymmetric continuum (docs/theory.md (S10): shaft and hub as ring bodies, \
                     the interference resolved without friction)\n  \
                     Delta = {} mm ({} vs the 1-D theory); a = {} mm, d = {} mm (K_T |s| >= mu p)\n  \
                     contact pressure {} to {} MPa over the fit (Lamé's p: {} MPa); capacity mu \
                     x contact force {} N (F_gross: {} N)",
                    number(c.displacement),
                    c.diff_vs_theory_fraction
                        .map_or_else(|| "n/a".to_string(), crate::report::compare::percent),
                    number(c.slide_from_loaded_face),
                    number(c.slide_from_held_face),
                    number_with(c.pressure_min, 4),
                    number_with(c.pressure_max, 4),
                    number(self.pressure),
                    number(c.capacity),
                    number(self.gross_slip_force),
                );
                if c.separated_pairs > 0 {
                    let _ = writeln!(
                        out,
                        "  {} interface node pairs would open: held by the tie, without friction",
                        c.separated_pairs
                    );
                }
            }
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
            header::<FitRow>(),
            "F_N,Delta_coulomb_mm,Delta_regularized_mm,a_mm,d_mm,a_coulomb_mm,d_coulomb_mm,\
             regime_coulomb,regime_regularized"
        );
        assert_eq!(
            header::<FitLoopRow>(),
            "branch,F_N,Delta_coulomb_mm,Delta_regularized_mm"
        );
    }

    /// The issue's JSON keys are there, with the #98 fit's numbers: p from Lamé by hand, F_gross
    /// = mu p 2 pi r L, and the two laws' Delta.
    #[test]
    fn the_report_has_the_keys_the_issue_names() {
        let inputs = PressFitProblem::paper();
        let model = PressFitProblem::model(&inputs).unwrap();
        let report = PressFitReport::new("pressfit-ccx98", &model.fit, model.force, None);
        let json = serde_json::to_value(&report).unwrap();
        // Lamé, plane stress, equal moduli E: p = E delta / r * (r^2 - ri^2)(ro^2 - r^2) /
        // (2 r^2 (ro^2 - ri^2)) for equal Poisson ratios.
        let (r, ri, ro, e, delta) = (20.0_f64, 10.0_f64, 30.0_f64, 210_000.0, 0.0025);
        let p = e * delta / r * (r * r - ri * ri) * (ro * ro - r * r)
            / (2.0 * r * r * (ro * ro - ri * ri));
        assert!((json["p_MPa"].as_f64().unwrap() - p).abs() < 1e-9 * p);
        let gross = 0.1 * p * 2.0 * std::f64::consts::PI * r * 17.7332;
        assert!((json["F_gross_N"].as_f64().unwrap() - gross).abs() < 1e-9 * gross);
        for law in ["coulomb", "regularized"] {
            for key in ["Delta_mm", "a_mm", "d_mm", "regime"] {
                assert!(!json[law][key].is_null(), "{law}.{key}");
            }
        }
        assert!(
            json["regularized"]["Delta_mm"].as_f64().unwrap()
                > json["coulomb"]["Delta_mm"].as_f64().unwrap()
        );
        assert!(json["F_1_N"].as_f64().unwrap() < json["F_gross_N"].as_f64().unwrap());
        let text = report.text();
        assert!(text.contains("plane strain"), "{text}");
        assert!(text.contains("not calibrated"), "{text}");
    }
}
