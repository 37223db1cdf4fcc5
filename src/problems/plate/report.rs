//! The squeezed plate's reports: its K_T table columns and its paper table ([`ReportFace`]).
//!
//! `microslip plate`: the squeezed plate, both laws, the contact-pressure check, the strip
//! theory's envelope and, when solved, the plane-strain continuum.

use super::point::PlatePoint;
use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::numeric::NumericError;
use crate::problems::Problem;
use crate::problems::stiffness::mm_to_um;
use crate::report::face::{KtColumn, ReportFace, point_continuum};
use crate::report::point::{InputsReport, SideBySide, regime_label, validity_label};
use crate::report::{number, number_with, sanitize};
use crate::study::curves::{Answer, plate_point};

use super::closed_form::{
    FLAT_END_LAYER_SLIP, PRESSURE_DEVIATION_LIMIT, PRESSURE_PEAK_LIMIT, SqueezedPlate,
};
use super::continuum::ContinuumPlate;
use super::params::PlateParams;
use super::problem::SqueezedPlateProblem;
use super::validity as v1;

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
    const KT_TITLE: &'static str = "squeezed plate";
    const KT_COLUMNS: &'static [KtColumn] = &[
        KtColumn::Answer {
            title: "u(L) (mm)",
            width: 12,
        },
        KtColumn::VsCurrent,
        KtColumn::VsCoulomb,
        KtColumn::Answer {
            title: "X_r (mm)",
            width: 10,
        },
    ];
    const KT_REGIME_WIDTH: usize = 20;
    type KtAnswer = PlateKtAnswer;
    type PointReport = PlateReport;
    type SweepRow = PlateRow;

    /// The plane-strain continuum (default mesh) is solved when asked, or when the strip theory
    /// is not expected within 2 %; only the one asked for fails the command.
    fn point_report(
        preset: &str,
        plate: &SqueezedPlate,
        continuum: bool,
    ) -> Result<PlateReport, NumericError> {
        let holds = plate.validity().validity == Validity::Holds;
        let solved = point_continuum(continuum, holds, || {
            super::solve_plate_continuum(plate.params(), super::ContinuumMesh::default())
        })?;
        Ok(PlateReport::new(preset, plate, solved.as_ref()))
    }

    fn point_text(report: &PlateReport) -> String {
        report.text()
    }

    fn kt_answer(answer: &Answer) -> Option<PlateKtAnswer> {
        match *answer {
            Answer::Plate(super::stiffness_answer::PlateAnswer {
                end_displacement,
                micro_end,
                regime,
            }) => Some(PlateKtAnswer {
                end_displacement,
                micro_end,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_values(a: &PlateKtAnswer) -> (Vec<f64>, Regime) {
        (vec![a.end_displacement, a.micro_end], a.regime)
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

/// The squeezed-plate report.
#[derive(Debug, Clone, Serialize)]
pub struct PlateReport {
    /// Always `plate`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// mu P / K_T (mm).
    #[serde(rename = "saturation_slip_mm")]
    pub saturation_slip: f64,
    /// K_T at the onset of macroslip (P11); absent when nothing ever slides (nu = 0).
    #[serde(
        rename = "KT_macroslip_onset_MPa_per_mm",
        skip_serializing_if = "Option::is_none"
    )]
    pub macroslip_onset_stiffness: Option<f64>,
    pub coulomb: PlateCoulomb,
    pub regularized: PlateRegularized,
    pub contact_pressure: ContactPressureReport,
    pub strip_theory: StripTheory,
    /// The plane-strain continuum, when it was solved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumReport>,
}

/// The plain Coulomb law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PlateCoulomb {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// u(L) (mm).
    #[serde(rename = "u_end_mm")]
    pub end_displacement: f64,
    /// End of the stick zone X_s, from the centre (mm).
    #[serde(rename = "Xs_mm")]
    pub stick_end: f64,
}

/// The regularized law's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PlateRegularized {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// u(L) (mm).
    #[serde(rename = "u_end_mm")]
    pub end_displacement: f64,
    /// End of the microslip zone X_r, from the centre (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_end: f64,
}

/// The contact pressure of a flat Timoshenko plate under saturated friction (P7-P9), the paper's
/// check of the constant-pressure assumption. Measured against the plane-strain continuum it is
/// right only for the mean pressure over the last t_p where the strip theory's slip zone is at
/// least t_p long (docs/theory.md, (P12)); its centre and edge values and its flag are kept for
/// compatibility, the flag deprecated.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ContactPressureReport {
    /// Which model these numbers come from.
    pub model: &'static str,
    /// Mean P_r/P over the last t_p before the free end: the one number of this model the
    /// continuum confirms, where `end_layer_ratio_applies`.
    pub end_layer_ratio: f64,
    /// Whether the strip theory's slip zone is at least t_p long, where `end_layer_ratio` was
    /// measured within -30 % to +41 % of the continuum's excess over P.
    pub end_layer_ratio_applies: bool,
    /// P_r/P at the centre.
    pub ratio_centre: f64,
    /// P_r/P at the edge.
    pub ratio_edge: f64,
    #[serde(flatten)]
    pub deviations: PressureDeviations,
    /// Deprecated: the flat model's flag, which does not track a continuum (docs/theory.md (P12));
    /// the continuum's `contact pressure` keys replace it.
    pub constant_pressure_holds: bool,
}

/// The model behind [`ContactPressureReport`].
pub(crate) const FLAT_PRESSURE_MODEL: &str =
    "flat Timoshenko plate, friction saturated everywhere (P7-P9, paper section 2.2.1)";
/// The model behind the continuum's pressure keys.
pub(crate) const CONTINUUM_PRESSURE_MODEL: &str = "plane-strain continuum FE (contact reactions)";

/// The strip theory's envelope (V1): the verdict on the thickness-mean u(L) and, where a
/// calibration reaches, the bound on each quantity; X_r is not bounded.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StripTheory {
    #[serde(serialize_with = "validity_label")]
    pub validity: Validity,
    /// What the verdict is about.
    pub validity_covers: &'static str,
    /// alpha t_p = t_p / l_s.
    #[serde(rename = "alpha_tp")]
    pub thickness_over_layer: f64,
    /// (L - X_r) / t_p.
    #[serde(rename = "slip_zone_over_tp")]
    pub slip_over_thickness: f64,
    pub calibrated_up_to_alpha_tp: f64,
    pub calibrated_from_slip_zone_over_tp: f64,
    pub calibrated_slip_zone_up_to_alpha_tp: f64,
    #[serde(rename = "X_r_bounded")]
    pub micro_end_bounded: bool,
    #[serde(flatten)]
    pub expected: Option<ExpectedDifferences>,
    /// Where the strip theory is measured wrong (V1c): the least difference of the thickness mean
    /// from the continuum stated for its region.
    /// In JSON under its old name (deprecated, kept one release) and under the name that says
    /// its unit, `measured_difference_at_least_fraction`.
    #[serde(
        rename = "measured_difference_at_least",
        skip_serializing_if = "Option::is_none"
    )]
    pub measured_at_least: Option<f64>,
    #[serde(
        rename = "measured_difference_at_least_fraction",
        skip_serializing_if = "Option::is_none"
    )]
    pub measured_at_least_fraction: Option<f64>,
}

/// Where a calibration reaches: the expected difference from a plane-strain continuum of each
/// quantity, a fraction. Each is written twice in JSON: under its old name (deprecated, kept one
/// release) and under that name with `_fraction`, the unit every ratio's name now carries.
#[derive(Debug, Clone, Copy)]
pub struct ExpectedDifferences {
    pub thickness_mean: f64,
    pub contact_face: f64,
    pub mid_thickness: f64,
}

impl Serialize for ExpectedDifferences {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        crate::report::point::serialize_fractions(
            &[
                ("expected_difference_from_continuum", self.thickness_mean),
                ("expected_difference_contact_face", self.contact_face),
                ("expected_difference_mid_thickness", self.mid_thickness),
            ],
            s,
        )
    }
}

/// How far the flat model's P_r/P strays from 1, and the limits of "constant pressure", as
/// fractions: in JSON under their old keys and with `_fraction` (`serialize_fractions`).
#[derive(Debug, Clone, Copy)]
pub struct PressureDeviations {
    /// Mean |P_r/P - 1|.
    pub mean: f64,
    /// Peak |P_r/P - 1|.
    pub peak: f64,
    pub mean_limit: f64,
    pub peak_limit: f64,
}

impl Serialize for PressureDeviations {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        crate::report::point::serialize_fractions(
            &[
                ("mean_deviation", self.mean),
                ("peak_deviation", self.peak),
                ("mean_deviation_limit", self.mean_limit),
                ("peak_deviation_limit", self.peak_limit),
            ],
            s,
        )
    }
}

/// The plane-strain continuum: its answer, or why it has none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum ContinuumReport {
    Solved(ContinuumSolved),
    Failed { error: String },
}

/// The continuum's answer.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ContinuumSolved {
    /// u(L), thickness mean (mm).
    #[serde(rename = "u_end_mean_mm")]
    pub mean: f64,
    /// u(L) at the contact face (mm).
    #[serde(rename = "u_end_contact_face_mm")]
    pub contact_face: f64,
    /// u(L) at mid-thickness (mm).
    #[serde(rename = "u_end_mid_thickness_mm")]
    pub mid_thickness: f64,
    /// X_r (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_end: f64,
    /// Contact pressure at the free end over P: the end node's value, which grows as the mesh is
    /// refined (the corner is singular); at the resolution `end_element_mm`.
    pub end_pressure_ratio: f64,
    /// The length of the last element along the face (mm): the resolution of `end_pressure_ratio`.
    #[serde(rename = "end_element_mm")]
    pub end_element: f64,
    /// Which model the pressure keys come from.
    pub pressure_model: &'static str,
    /// Mean contact pressure over the last t_p, over P (converged with the mesh).
    pub end_layer_pressure_ratio: f64,
    /// Mean contact pressure over the last t_p / 10, over P: the free-end peak at that
    /// resolution (converged).
    pub edge_pressure_ratio: f64,
    /// Smallest and largest P_r/P at least t_p from the free end.
    pub interior_pressure_min_ratio: f64,
    pub interior_pressure_max_ratio: f64,
    /// (continuum - strip) / strip for the thickness mean; `None` where the strip's u(L) is 0.
    #[serde(skip)]
    pub from_strip: Option<f64>,
}

impl StripTheory {
    pub fn new(plate: &SqueezedPlate) -> StripTheory {
        let v = plate.validity();
        StripTheory {
            validity: v.validity,
            validity_covers: "u(L) thickness mean",
            thickness_over_layer: v.thickness_over_layer,
            slip_over_thickness: v.slip_over_thickness,
            calibrated_up_to_alpha_tp: v1::CALIBRATED_RATIO,
            calibrated_from_slip_zone_over_tp: v1::CALIBRATED_SLIP,
            calibrated_slip_zone_up_to_alpha_tp: v1::CALIBRATED_RATIO_SLIP,
            micro_end_bounded: false,
            expected: v.expected.map(|e| ExpectedDifferences {
                thickness_mean: e[0],
                contact_face: e[1],
                mid_thickness: e[2],
            }),
            measured_at_least: v.measured_at_least,
            measured_at_least_fraction: v.measured_at_least,
        }
    }

    /// The envelope in words.
    fn write(&self, out: &mut String) {
        let verdict = match self.validity {
            Validity::Holds => "holds (within 2 %)",
            Validity::Approximate => "approximate (within 10 %)",
            Validity::Outside => "OUTSIDE its envelope: use the continuum values below",
            Validity::NotCalibrated => {
                "NOT CALIBRATED here (no bound reaches this plate): use the continuum values below"
            }
            Validity::MeasuredWrong => "MEASURED WRONG here (V1c): use the continuum values below",
        };
        let _ = writeln!(
            out,
            "Validity of the strip theory (u uniform through t_p; docs/theory.md (V1))\n  \
             alpha t_p = t_p / l_s = {}; slip zone L - X_r = {} t_p\n  \
             u(L) as the thickness mean: {verdict}",
            number_with(self.thickness_over_layer, 3),
            number_with(self.slip_over_thickness, 3),
        );
        match self.expected {
            Some(e) => {
                let _ = writeln!(
                    out,
                    "  expected difference from a plane-strain continuum: thickness mean {} %, \
                     contact face {} %, mid-thickness {} %; X_r is not bounded (the strip's slip \
                     zone is too long where the thickness matters)",
                    number_with(100.0 * e.thickness_mean, 2),
                    number_with(100.0 * e.contact_face, 2),
                    number_with(100.0 * e.mid_thickness, 2)
                );
            }
            None if self.measured_at_least.is_some() => {
                let least = self.measured_at_least.unwrap_or(0.0);
                let (from, below, _) = v1::MEASURED_WRONG
                    .into_iter()
                    .find(|r| r.2 == least)
                    .unwrap_or(v1::MEASURED_WRONG[0]);
                let _ = writeln!(
                    out,
                    "  measured: every calibration plate with alpha t_p >= {from} and a slip zone \
                     under {below} t_p was off by more than {} % on the thickness mean (V1c)",
                    number_with(100.0 * least, 2)
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "  calibrated for alpha t_p <= {} or a slip zone of at least {} t_p (alpha t_p <= \
                     {}); measured differences beyond range from under 1 % to 540 %",
                    self.calibrated_up_to_alpha_tp,
                    self.calibrated_from_slip_zone_over_tp,
                    self.calibrated_slip_zone_up_to_alpha_tp
                );
            }
        }
    }
}

impl ContinuumReport {
    fn new(solved: &Result<ContinuumPlate, NumericError>, strip: f64) -> ContinuumReport {
        match solved {
            Ok(c) => ContinuumReport::Solved(ContinuumSolved {
                mean: c.end_displacement_mean,
                contact_face: c.end_displacement_face,
                mid_thickness: c.end_displacement_mid,
                micro_end: c.micro_zone_end,
                end_pressure_ratio: c.end_pressure_ratio,
                end_element: c.contact_pressure.iter().rev().nth(2).map_or(0.0, |q| {
                    c.contact_pressure[c.contact_pressure.len() - 1].0 - q.0
                }),
                pressure_model: CONTINUUM_PRESSURE_MODEL,
                end_layer_pressure_ratio: c.end_layer_pressure_ratio,
                edge_pressure_ratio: c.edge_pressure_ratio,
                interior_pressure_min_ratio: c.interior_pressure_range.0,
                interior_pressure_max_ratio: c.interior_pressure_range.1,
                from_strip: crate::fe::compare::relative_difference(c.end_displacement_mean, strip),
            }),
            Err(e) => ContinuumReport::Failed {
                error: e.to_string(),
            },
        }
    }

    fn write(&self, out: &mut String) {
        match self {
            ContinuumReport::Solved(c) => {
                let from_strip = c.from_strip.map_or_else(
                    || "as the strip theory: nu = 0, nothing squeezes the plate sideways".into(),
                    |d| format!("{:+.1} % from the strip theory", 100.0 * d),
                );
                let _ = writeln!(
                    out,
                    "Plane-strain continuum (2-D finite elements, contact pressure from the solution)\n  \
                     u(L) = {} mm thickness mean ({from_strip}), {} mm at the contact \
                     face, {} mm at mid-thickness\n  X_r = {} mm",
                    number(c.mean),
                    number(c.contact_face),
                    number(c.mid_thickness),
                    number(c.micro_end),
                );
                let _ = writeln!(
                    out,
                    "  contact pressure (continuum FE): {} to {} P beyond t_p from the free end; \
                     mean {} P over the last t_p, {} P over the last t_p/10; {} P at the free-end \
                     node (element {} mm: the corner is singular, this value grows as the mesh is \
                     refined)",
                    number_with(c.interior_pressure_min_ratio, 3),
                    number_with(c.interior_pressure_max_ratio, 3),
                    number_with(c.end_layer_pressure_ratio, 3),
                    number_with(c.edge_pressure_ratio, 3),
                    number_with(c.end_pressure_ratio, 3),
                    number(c.end_element)
                );
            }
            ContinuumReport::Failed { error } => {
                let _ = writeln!(out, "Plane-strain continuum: not solved ({error})");
            }
        }
    }
}

/// The plate's K_T at macroslip onset in words (docs/theory.md, (P11)).
pub(crate) fn onset_words(stiffness: Option<f64>) -> String {
    match stiffness {
        Some(kt) => format!(
            "K_T at macroslip onset = {} MPa/mm: below it all microslip, above it macroslip at the free end",
            number(kt)
        ),
        None => "no macroslip at any K_T (nu = 0: the plate does not expand)".to_string(),
    }
}

impl PlateReport {
    /// The report of `plate`, with the continuum's solution when one was asked for.
    pub fn new(
        preset: &str,
        plate: &SqueezedPlate,
        continuum: Option<&Result<ContinuumPlate, NumericError>>,
    ) -> PlateReport {
        let row = plate_point(plate);
        let pressure = plate.contact_pressure();
        PlateReport {
            model: "plate",
            preset: preset.to_string(),
            inputs: InputsReport(SqueezedPlateProblem::to_inputs(plate.params())),
            saturation_slip: plate.saturation_slip(),
            macroslip_onset_stiffness: plate.macroslip_onset_stiffness(),
            coulomb: PlateCoulomb {
                regime: row.regime_coulomb,
                end_displacement: row.u_coulomb,
                stick_end: row.stick_end,
            },
            regularized: PlateRegularized {
                regime: row.regime_regularized,
                end_displacement: row.u_regularized,
                micro_end: row.micro_end,
            },
            contact_pressure: ContactPressureReport {
                model: FLAT_PRESSURE_MODEL,
                end_layer_ratio: pressure.mean_ratio_over(
                    plate.params().half_length - plate.params().thickness,
                    plate.params().half_length,
                ),
                end_layer_ratio_applies: plate.end_layer_pressure().is_some(),
                ratio_centre: pressure.ratio(0.0),
                ratio_edge: pressure.ratio(plate.params().half_length),
                deviations: PressureDeviations {
                    mean: pressure.mean_deviation(),
                    peak: pressure.peak_deviation(),
                    mean_limit: PRESSURE_DEVIATION_LIMIT,
                    peak_limit: PRESSURE_PEAK_LIMIT,
                },
                constant_pressure_holds: pressure.constant_pressure_holds(),
            },
            strip_theory: StripTheory::new(plate),
            continuum: continuum.map(|solved| ContinuumReport::new(solved, row.u_regularized)),
        }
    }

    /// The contact pressure in words: the flat model for what it predicts, then the continuum's
    /// where it was solved.
    fn write_pressure(&self, out: &mut String) {
        let p = &self.contact_pressure;
        let _ = writeln!(
            out,
            "Contact pressure\n  {}: P_r/P = {} at the centre, {} at the edge (|P_r/P - 1| mean \
             {} %, peak {} %)",
            p.model,
            number(p.ratio_centre),
            number(p.ratio_edge),
            number(100.0 * p.deviations.mean),
            number(100.0 * p.deviations.peak)
        );
        let applies = if p.end_layer_ratio_applies {
            format!(
                "here {} P (slip zone {} t_p)",
                number_with(p.end_layer_ratio, 3),
                number_with(self.strip_theory.slip_over_thickness, 3)
            )
        } else {
            format!(
                "not here (slip zone {} t_p)",
                number_with(self.strip_theory.slip_over_thickness, 3)
            )
        };
        let _ = writeln!(
            out,
            "  against the plane-strain continuum this model is right only for the mean pressure \
             over the last t_p where the slip zone is at least {FLAT_END_LAYER_SLIP} t_p long: \
             {applies}; its centre and edge values and its constant-pressure flag are not the \
             plate's (docs/theory.md (P12))"
        );
        if !matches!(self.continuum, Some(ContinuumReport::Solved(_))) {
            let _ = writeln!(
                out,
                "  the plate's own contact pressure: plane-strain continuum (--continuum)"
            );
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Squeezed plate on a rigid plane (Ligier & Bonhote 2014, section 2.2) - preset {}",
            sanitize(&self.preset)
        );
        self.inputs.write(&mut out);
        let _ = writeln!(
            out,
            "  saturation slip mu P / K_T = {} um",
            number(mm_to_um(self.saturation_slip))
        );
        let _ = writeln!(out, "  {}", onset_words(self.macroslip_onset_stiffness));
        let _ = writeln!(out, "{:<24}{:<22}regularized", "Solution", "Coulomb");
        let (c, r) = (&self.coulomb, &self.regularized);
        SideBySide {
            response: "u(L) (mm)",
            ratio: "u_reg / u_Coulomb",
            values: (c.end_displacement, r.end_displacement),
            regimes: (c.regime, r.regime),
            zone_ends: (
                format!("X_s = {}", number(c.stick_end)),
                format!("X_r = {}", number(r.micro_end)),
            ),
        }
        .write(&mut out);
        self.write_pressure(&mut out);
        self.strip_theory.write(&mut out);
        if let Some(continuum) = &self.continuum {
            continuum.write(&mut out);
        }
        out
    }
}

/// A sweep row of the plate (`sweep plate`), from one point of it.
/// One row of `microslip sweep plate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PlateRow {
    /// Tangential stiffness (MPa/mm).
    #[serde(rename = "KT_MPa_per_mm")]
    pub kt: f64,
    /// Coulomb end displacement (mm).
    pub u_coulomb_mm: f64,
    /// Regularized end displacement (mm).
    pub u_regularized_mm: f64,
    /// End of the Coulomb stick zone (mm).
    #[serde(rename = "Xs_mm")]
    pub stick_end: f64,
    /// End of the microslip zone (mm).
    #[serde(rename = "Xr_mm")]
    pub micro_end: f64,
    /// Coulomb regime.
    pub regime_coulomb: &'static str,
    /// Regularized regime.
    pub regime_regularized: &'static str,
    /// The strip theory against a plane-strain continuum (V1): holds (within 2 %), approximate
    /// (10 %) or outside. Added after the original columns, which scripts read by name.
    pub strip_theory: &'static str,
}

impl From<&PlatePoint> for PlateRow {
    fn from(p: &PlatePoint) -> Self {
        PlateRow {
            kt: p.kt,
            u_coulomb_mm: p.u_coulomb,
            u_regularized_mm: p.u_regularized,
            stick_end: p.stick_end,
            micro_end: p.micro_end,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
            strip_theory: p.strip_validity.label(),
        }
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
            header::<PlateRow>(),
            "KT_MPa_per_mm,u_coulomb_mm,u_regularized_mm,Xs_mm,Xr_mm,regime_coulomb,regime_regularized,\
             strip_theory"
        );
    }

    #[test]
    fn plate_report_shows_both_zone_ends_and_names_the_pressure_model() {
        let plate_model = SqueezedPlate::new(PlateParams::PAPER).unwrap();
        let text = PlateReport::new("paper-plate", &plate_model, None).text();
        for needle in [
            "nu  = 0.3",
            "X_s = 9.71429",
            "X_r = 9.83832",
            "flat Timoshenko plate, friction saturated everywhere (P7-P9",
            // (L - X_r) / t_p = (10 - 9.83832) / 0.2: under one t_p, where the flat model's
            // end-layer mean was not measured right.
            "not here (slip zone 0.808 t_p)",
            "plane-strain continuum (--continuum)",
            "MEASURED WRONG here (V1c)",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
    }
}
