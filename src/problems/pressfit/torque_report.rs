//! The twisted fit's reports ([`ReportFace`], [`CycleFace`]): `microslip pressfit-torque` (the
//! fit at one torque, both laws side by side, with Lamé's pressure in plane stress and plane
//! strain), its K_T table's columns, its sweep and loop rows (`T_Nmm`, `theta_..._rad`), its
//! cycle's words.
//!
//! Why apart from the push-out's report: its JSON keys and CSV columns are the torque's (a
//! script reads `theta_rad`, never a `Delta_mm` that holds radians), and its theory has no
//! envelope: no torsional continuum calibrates it (docs/theory.md section 18, (S6)), so every
//! report says "not calibrated" where the push-out's gives its bound.

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::{Law, Regime};
use crate::kernel::validity::Validity;
use crate::numeric::NumericError;
use crate::problems::Problem;
use crate::problems::inputs::Inputs;
use crate::problems::load_driven::MasingCycle;
use crate::problems::stiffness::mm_to_um;
use crate::report::face::{KtColumn, ReportFace};
use crate::report::point::cycle::{self, AnyCycleFace, CycleFace, CycleKeys, CycleWords};
use crate::report::point::{InputsReport, WideLaws, regime_label, threshold_line, validity_label};
use crate::report::{number, number_with, sanitize};
use crate::study::curves::{Answer, LoopPoint};

use super::closed_form::{CarriedLoad, PressFit};
use super::cycle::FitCycle;
use super::params::FitLoad;
use super::point::{FitPoint, fit_point};
use super::registered::problem::{PressFitInputs, PressFitModel, PressFitTorqueProblem};
use super::registered::stiffness_answer::FitAnswer;

/// What a candidate K_T does to the twisted fit at the model's torque (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TorqueKtAnswer {
    /// Torque of first sliding T_1 (N mm).
    #[serde(rename = "T_1_Nmm")]
    pub first_slip_torque: f64,
    /// Sliding zone a from the loaded face x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    /// Sliding zone d from the held face x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// The twist theta (rad).
    #[serde(rename = "theta_rad")]
    pub twist: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

impl ReportFace for PressFitTorqueProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(S8)";
    const KT_TITLE: &'static str = "twisted press fit";
    const FRICTION_STRESS: &'static str = "mu p";
    const KT_COLUMNS: &'static [KtColumn] = &[
        KtColumn::Answer {
            title: "T_1 (N mm)",
            width: 12,
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
            title: "theta (rad)",
            width: 12,
        },
        KtColumn::VsCurrent,
        KtColumn::VsCoulomb,
    ];
    const KT_REGIME_WIDTH: usize = 29;
    type KtAnswer = TorqueKtAnswer;
    type PointReport = TorqueReport;
    type SweepRow = TorqueRow;

    /// No continuum: none is solved, asked or not (the command line refuses `--continuum` for a
    /// problem without one).
    fn point_report(
        preset: &str,
        model: &PressFitModel,
        _continuum: bool,
    ) -> Result<TorqueReport, NumericError> {
        Ok(TorqueReport::new(preset, &model.fit, model.force))
    }

    fn point_text(report: &TorqueReport) -> String {
        report.text()
    }

    fn cycle() -> Option<&'static dyn AnyCycleFace> {
        Some(cycle::erased::<Self>())
    }

    fn kt_answer(answer: &Answer) -> Option<TorqueKtAnswer> {
        match *answer {
            Answer::PressFitTorque(FitAnswer {
                first_slip_force,
                zones: (slide_from_loaded_face, slide_from_held_face),
                displacement,
                regime,
            }) => Some(TorqueKtAnswer {
                first_slip_torque: first_slip_force,
                slide_from_loaded_face,
                slide_from_held_face,
                twist: displacement,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_values(a: &TorqueKtAnswer) -> (Vec<f64>, Regime) {
        (
            vec![
                a.first_slip_torque,
                a.slide_from_loaded_face,
                a.slide_from_held_face,
                a.twist,
            ],
            a.regime,
        )
    }
}

/// One row of `microslip sweep pressfit-torque` (and `sweep --vary T`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct TorqueRow {
    /// Torque (N mm).
    #[serde(rename = "T_Nmm")]
    pub torque: f64,
    /// Coulomb twist (rad).
    #[serde(rename = "theta_coulomb_rad")]
    pub twist_coulomb: f64,
    /// Regularized twist (rad).
    #[serde(rename = "theta_regularized_rad")]
    pub twist_regularized: f64,
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

impl From<&FitPoint> for TorqueRow {
    fn from(p: &FitPoint) -> Self {
        TorqueRow {
            torque: p.force,
            twist_coulomb: p.delta_coulomb,
            twist_regularized: p.delta_regularized,
            slide_from_loaded_face: p.zones_regularized.0,
            slide_from_held_face: p.zones_regularized.1,
            slide_from_loaded_face_coulomb: p.zones_coulomb.0,
            slide_from_held_face_coulomb: p.zones_coulomb.1,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
        }
    }
}

/// One point of the twisted fit's `microslip cycle --format csv` (the loop of theta, both laws).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct TorqueLoopRow {
    /// `unloading` or `reloading`.
    pub branch: &'static str,
    /// Torque (N mm), negative when the shaft is twisted back.
    #[serde(rename = "T_Nmm")]
    pub torque: f64,
    /// Coulomb twist (rad).
    #[serde(rename = "theta_coulomb_rad")]
    pub twist_coulomb: f64,
    /// Regularized twist (rad).
    #[serde(rename = "theta_regularized_rad")]
    pub twist_regularized: f64,
}

impl From<&LoopPoint> for TorqueLoopRow {
    fn from(p: &LoopPoint) -> Self {
        TorqueLoopRow {
            branch: p.branch.label(),
            torque: p.force,
            twist_coulomb: p.w_coulomb,
            twist_regularized: p.w_regularized,
        }
    }
}

/// The cycle's keys of a torque: T dtheta is N mm, as F dDelta; the secant is N mm per rad.
const TORQUE_KEYS: CycleKeys = CycleKeys {
    amplitude: "Ta_Nmm",
    onset: "onset_Nmm",
    dissipation: "D_Nmm",
    peak_energy: "U_Nmm",
    secant: "secant_stiffness_Nmm_per_rad",
    dissipations: ["D_coulomb_Nmm", "D_regularized_Nmm"],
};

impl CycleFace for PressFitTorqueProblem {
    const CYCLE_WORDS: CycleWords = CycleWords {
        peak_key: "theta_peak_rad",
        keys: TORQUE_KEYS,
        heading: ("Twisted press fit", "torque"),
        rows: [
            "onset of sliding (N mm)",
            "peak twist theta_a (rad)",
            "D per cycle (N mm)",
            "peak energy U (N mm)",
            "damping ratio D / (4 pi U) (-)",
            "secant T_a/theta_a (N mm/rad)",
        ],
        note: "the torque cycles between +T_a and -T_a on the shaft's end, the hub held; D is \
               the whole interface's; U = 1/2 T_a theta_a; the secant stiffness is T_a / \
               theta_a.",
    };

    fn structure_line(fit: &PressFit) -> String {
        super::report::structure_line(fit)
    }

    type LoopRow = TorqueLoopRow;
    type LoadRow = TorqueRow;

    fn force_limit(fit: &PressFit) -> Option<f64> {
        Some(fit.torsion().gross_load())
    }

    fn cycle_inputs(fit: &PressFit, amplitude: CarriedLoad) -> Inputs {
        PressFitTorqueProblem::to_inputs(PressFitInputs {
            structure: fit.params(),
            force: amplitude.value(),
        })
    }
}

/// What the 1-D theory assumes, said wherever its numbers are shown.
const THEORY_NOTE: &str = "1-D theory (docs/theory.md section 18, (S6)): Lamé's contact \
     pressure p, uniform over L and untouched by the torque; each member twisted as a \
     Saint-Venant shaft or tube whose section turns rigidly (shear lag of two tubes). No \
     torsional continuum calibrates it: how far a continuum's theta is is not measured";

/// The twisted-fit report at one torque.
#[derive(Debug, Clone, Serialize)]
pub struct TorqueReport {
    /// Always `pressfit-torque`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// Torque of the report (N mm), also in `inputs`.
    #[serde(skip)]
    pub torque: f64,
    /// Lamé's contact pressure in plane stress (MPa): what every number uses.
    #[serde(rename = "p_MPa")]
    pub pressure: f64,
    /// Lamé's contact pressure in plane strain (MPa), beside it.
    #[serde(rename = "p_plane_strain_MPa")]
    pub plane_strain_pressure: f64,
    /// Regularized: sliding starts above it (N mm).
    #[serde(rename = "T_1_Nmm")]
    pub first_slip_torque: f64,
    /// Where: `x=0` (the shaft's loaded face), `x=L` (the hub's held face) or `both`.
    pub first_slip_at: &'static str,
    /// In words, for the text.
    #[serde(skip)]
    pub first_slip_words: &'static str,
    /// Regularized: the other face starts sliding above it (N mm).
    #[serde(rename = "T_2_Nmm")]
    pub second_slip_torque: f64,
    /// Both laws: the whole fit slides at it, mu p 2 pi r^2 L (N mm).
    #[serde(rename = "T_gross_Nmm")]
    pub gross_slip_torque: f64,
    /// mu p / K_T (mm): the circumferential slip at which the interface slides.
    #[serde(rename = "saturation_slip_mm")]
    pub saturation_slip: f64,
    /// 1/lambda, the elastic slip's decay length (mm).
    #[serde(rename = "decay_length_mm")]
    pub decay_length: f64,
    /// The members' torsional rigidities Gs Js and Gh Jh (N mm^2).
    #[serde(rename = "shaft_torsional_rigidity_Nmm2")]
    pub shaft_rigidity: f64,
    #[serde(rename = "hub_torsional_rigidity_Nmm2")]
    pub hub_rigidity: f64,
    pub coulomb: TorqueLaw,
    pub regularized: TorqueLaw,
    pub theory: TorqueTheoryReport,
}

/// One law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TorqueLaw {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// theta: the shaft's loaded end's rotation relative to the hub's held face (rad).
    #[serde(rename = "theta_rad")]
    pub twist: f64,
    /// Sliding zone from the loaded face x = 0 (mm).
    #[serde(rename = "a_mm")]
    pub slide_from_loaded_face: f64,
    /// Sliding zone from the held face x = L (mm).
    #[serde(rename = "d_mm")]
    pub slide_from_held_face: f64,
    /// Energy dissipated per cycle of the torque between +T and -T (N mm); `cycle`'s key.
    #[serde(rename = "D_Nmm")]
    pub dissipation: f64,
    /// The equivalent damping ratio D / (4 pi U), U = T theta / 2 (dimensionless).
    #[serde(rename = "zeta")]
    pub damping_ratio: f64,
}

/// The 1-D theory's standing: not calibrated.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TorqueTheoryReport {
    #[serde(serialize_with = "validity_label")]
    pub validity: Validity,
    /// Always null: no continuum measured the torque's 1-D theory.
    pub theory_within_fraction: Option<f64>,
    pub note: &'static str,
}

impl TorqueReport {
    /// The report of `fit` at `torque`.
    pub fn new(preset: &str, fit: &PressFit, torque: CarriedLoad) -> TorqueReport {
        let axis = fit.torsion();
        let row = fit_point(axis, torque);
        let p = fit.params();
        let law = |law, regime, twist, (a, d): (f64, f64)| {
            let cycle = FitCycle::new(axis, law, torque);
            TorqueLaw {
                regime,
                twist,
                slide_from_loaded_face: a,
                slide_from_held_face: d,
                dissipation: cycle.dissipation(),
                damping_ratio: cycle.damping_ratio(),
            }
        };
        // G J / r^2 times r^2: the rigidities the shear lag reads, back in N mm^2.
        let [shaft, hub] = p
            .rigidities(FitLoad::Torque)
            .map(|k| k * p.fit_radius.powi(2));
        TorqueReport {
            model: PressFitTorqueProblem::INFO.key,
            preset: preset.to_string(),
            inputs: InputsReport(PressFitTorqueProblem::to_inputs(PressFitInputs {
                structure: p,
                force: torque.value(),
            })),
            torque: row.force,
            pressure: fit.contact_pressure(),
            plane_strain_pressure: fit.plane_strain_pressure(),
            first_slip_torque: axis.first_slip_load(),
            first_slip_at: axis.first_slip_face().key(),
            first_slip_words: axis.first_slip_face().label(),
            second_slip_torque: axis.second_slip_load(),
            gross_slip_torque: axis.gross_load(),
            saturation_slip: p.friction * fit.contact_pressure() / p.tangential_stiffness,
            decay_length: 1.0 / axis.decay_rate(),
            shaft_rigidity: shaft,
            hub_rigidity: hub,
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
            theory: TorqueTheoryReport {
                validity: Validity::NotCalibrated,
                theory_within_fraction: None,
                note: THEORY_NOTE,
            },
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Press fit twisted (shear lag, docs/theory.md section 18, (S6)) - preset {}",
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
            "Members: shaft Gs Js = {} N mm^2, hub Gh Jh = {} N mm^2",
            number(self.shaft_rigidity),
            number(self.hub_rigidity)
        );
        let _ = writeln!(out, "Thresholds");
        threshold_line(
            &mut out,
            "T_1",
            format!("{} N mm", number(self.first_slip_torque)),
            &format!(
                "regularized: sliding starts above it, at {}",
                self.first_slip_words
            ),
        );
        threshold_line(
            &mut out,
            "T_2",
            format!("{} N mm", number(self.second_slip_torque)),
            "regularized: both faces slide above it",
        );
        threshold_line(
            &mut out,
            "T_gross",
            format!("{} N mm", number(self.gross_slip_torque)),
            "both laws: the whole fit turns (mu p 2 pi r^2 L); no more is carried",
        );
        threshold_line(
            &mut out,
            "mu p / K_T",
            format!("{} um", number(mm_to_um(self.saturation_slip))),
            &format!(
                "saturation slip (circumferential); 1/lambda = {} mm, the elastic slip's decay \
                 length",
                number(self.decay_length)
            ),
        );
        let (c, r) = (&self.coulomb, &self.regularized);
        let mut table = WideLaws(&mut out);
        table.heading(format!("At T = {} N mm", number(self.torque)));
        table.row("regime", c.regime.to_string(), r.regime.to_string());
        table.row("theta (rad)", number(c.twist), number(r.twist));
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
            "D per cycle +-T (N mm)",
            number_with(c.dissipation, 4),
            number_with(r.dissipation, 4),
        );
        if c.twist > 0.0 {
            table.both("theta_reg / theta_Coulomb", number(r.twist / c.twist));
        }
        let _ = writeln!(
            out,
            "  (a: sliding zone from x = 0, the shaft's loaded face; d: from x = L, the hub's held \
             face; theta = the shaft's loaded end's rotation relative to the hub's held face)"
        );
        let _ = writeln!(
            out,
            "Theory: {}\n  here: not calibrated (no torsional continuum)",
            self.theory.note
        );
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::csv::test_support::header;

    /// The header users' scripts read: the torque's own columns, no `_mm` column holding
    /// radians.
    #[test]
    fn the_torque_headers_are_the_torque_s() {
        assert_eq!(
            header::<TorqueRow>(),
            "T_Nmm,theta_coulomb_rad,theta_regularized_rad,a_mm,d_mm,a_coulomb_mm,d_coulomb_mm,\
             regime_coulomb,regime_regularized"
        );
        assert_eq!(
            header::<TorqueLoopRow>(),
            "branch,T_Nmm,theta_coulomb_rad,theta_regularized_rad"
        );
    }

    /// The #98 fit twisted at half its gross torque: T_gross = mu p 2 pi r^2 L with Lamé's p by
    /// hand, the rigidities G J by hand, theta regularized above Coulomb's, and the theory not
    /// calibrated.
    #[test]
    fn the_report_has_the_torque_s_keys_and_numbers() {
        let model = PressFitTorqueProblem::model(&PressFitTorqueProblem::paper()).unwrap();
        let report = TorqueReport::new("pressfit-ccx98-torque", &model.fit, model.force);
        let json = serde_json::to_value(&report).unwrap();
        let (r, ri, ro, e, nu, delta) = (20.0_f64, 10.0_f64, 30.0_f64, 210_000.0, 0.3, 0.0025);
        let p = e * delta / r * (r * r - ri * ri) * (ro * ro - r * r)
            / (2.0 * r * r * (ro * ro - ri * ri));
        let gross = 0.1 * p * 2.0 * std::f64::consts::PI * r * r * 17.7332;
        assert!((json["T_gross_Nmm"].as_f64().unwrap() - gross).abs() < 1e-9 * gross);
        let g = e / (2.0 * (1.0 + nu));
        let j_shaft = std::f64::consts::PI / 2.0 * (r.powi(4) - ri.powi(4));
        let shaft = json["shaft_torsional_rigidity_Nmm2"].as_f64().unwrap();
        assert!((shaft / (g * j_shaft) - 1.0).abs() < 1e-12, "{shaft}");
        for law in ["coulomb", "regularized"] {
            for key in ["theta_rad", "a_mm", "d_mm", "regime", "D_Nmm"] {
                assert!(!json[law][key].is_null(), "{law}.{key}");
            }
            assert!(json[law]["Delta_mm"].is_null(), "{law}");
        }
        assert!(
            json["regularized"]["theta_rad"].as_f64().unwrap()
                > json["coulomb"]["theta_rad"].as_f64().unwrap()
        );
        assert_eq!(json["theory"]["validity"], "not calibrated");
        let text = report.text();
        assert!(text.contains("T_gross") && text.contains("N mm"), "{text}");
        assert!(
            !text.contains("F_gross") && !text.contains("Delta"),
            "{text}"
        );
    }
}
