//! The Hertzian cylinder's reports ([`ReportFace`]): `microslip cylinder` (Hertz's contact, both
//! laws side by side at Q), its sweep row and its K_T table's columns.

use std::fmt::Write as _;

use serde::Serialize;

use crate::kernel::regime::Regime;
use crate::kernel::validity::Validity;
use crate::numeric::NumericError;
use crate::problems::Problem;
use crate::problems::inputs::Inputs;
use crate::problems::stiffness::mm_to_um;
use crate::report::face::{KtColumn, ReportFace};
use crate::report::point::cycle::{self, AnyCycleFace, CycleFace, CycleKeys, CycleWords};
use crate::report::point::{InputsReport, regime_label, validity_label};
use crate::report::{number, number_with, sanitize};
use crate::study::curves::Answer;
use crate::study::load::LoopPoint;

use super::closed_form::{Cylinder, TangentialLoad};
use super::point::{CylinderPoint, cylinder_point};
use super::problem::{CylinderInputs, CylinderModel, CylinderProblem};
use super::stiffness_answer::CylinderAnswer;
use super::validity::{CylinderValidity, LEAST_BODY_OVER_HALF_WIDTH};

/// What a candidate K_T does to the cylinder at the model's Q (`microslip kt`'s row).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct CylinderKtAnswer {
    /// K_T a / E* (-).
    #[serde(rename = "KT_a_over_Estar")]
    pub stiffness_group: f64,
    /// Microslip zone half-width c (mm).
    #[serde(rename = "c_mm")]
    pub zone: f64,
    /// Edge slip s(a) (mm).
    #[serde(rename = "sa_mm")]
    pub edge_slip: f64,
    /// Centre slip s(0) (mm).
    #[serde(rename = "s0_mm")]
    pub centre_slip: f64,
    /// Regime.
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
}

/// One row of `microslip sweep --model cylinder`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct CylinderRow {
    /// Tangential line load Q (N/mm).
    #[serde(rename = "Q_N_per_mm")]
    pub load: f64,
    /// Q / (mu P) (-).
    #[serde(rename = "Q_over_muP")]
    pub load_ratio: f64,
    /// Hertz half-width a (mm) and peak pressure p0 (MPa).
    #[serde(rename = "a_mm")]
    pub half_width: f64,
    #[serde(rename = "p0_MPa")]
    pub peak_pressure: f64,
    /// K_T a / E* (-).
    #[serde(rename = "KT_a_over_Estar")]
    pub stiffness_group: f64,
    /// Mindlin's stick zone and the regularized microslip zone, half-widths c (mm).
    #[serde(rename = "c_mindlin_mm")]
    pub zone_coulomb: f64,
    #[serde(rename = "c_mm")]
    pub zone_regularized: f64,
    /// Edge slip s(a) (mm), both laws, and the regularized centre slip s(0).
    #[serde(rename = "sa_mindlin_mm")]
    pub edge_slip_coulomb: f64,
    #[serde(rename = "sa_mm")]
    pub edge_slip_regularized: f64,
    #[serde(rename = "s0_mm")]
    pub centre_slip_regularized: f64,
    /// The largest q / (mu p0), both laws (-).
    pub peak_q_over_mu_p0_mindlin: f64,
    pub peak_q_over_mu_p0: f64,
    /// The regimes.
    pub regime_coulomb: &'static str,
    pub regime_regularized: &'static str,
}

impl From<&CylinderPoint> for CylinderRow {
    fn from(p: &CylinderPoint) -> Self {
        CylinderRow {
            load: p.load,
            load_ratio: p.load_ratio,
            half_width: p.half_width,
            peak_pressure: p.peak_pressure,
            stiffness_group: p.stiffness_group,
            zone_coulomb: p.zone_coulomb,
            zone_regularized: p.zone_regularized,
            edge_slip_coulomb: p.edge_slip_coulomb,
            edge_slip_regularized: p.edge_slip_regularized,
            centre_slip_regularized: p.centre_slip_regularized,
            peak_q_over_mu_p0_mindlin: p.peak_shear_coulomb,
            peak_q_over_mu_p0: p.peak_shear_regularized,
            regime_coulomb: p.regime_coulomb.label(),
            regime_regularized: p.regime_regularized.label(),
        }
    }
}

impl ReportFace for CylinderProblem {
    const MONOTONE_IN_STIFFNESS: &'static str = "(H16)";
    const KT_TITLE: &'static str = "Hertzian cylinder";
    const FRICTION_STRESS: &'static str = "mu p0";
    const KT_COLUMNS: &'static [KtColumn] = &[
        KtColumn::Answer {
            title: "K_T a/E*",
            width: 9,
        },
        KtColumn::Answer {
            title: "c (mm)",
            width: 9,
        },
        KtColumn::Answer {
            title: "s(a) (mm)",
            width: 11,
        },
        KtColumn::VsCurrent,
        KtColumn::VsCoulomb,
    ];
    const KT_REGIME_WIDTH: usize = 20;
    type KtAnswer = CylinderKtAnswer;
    type PointReport = CylinderReport;
    type SweepRow = CylinderRow;

    /// The cylinder has no continuum of its own here: `continuum` is never asked.
    fn point_report(
        preset: &str,
        model: &CylinderModel,
        _continuum: bool,
    ) -> Result<CylinderReport, NumericError> {
        Ok(CylinderReport::new(preset, model))
    }

    fn point_text(report: &CylinderReport) -> String {
        report.text()
    }

    fn cycle() -> Option<&'static dyn AnyCycleFace> {
        Some(cycle::erased::<Self>())
    }

    fn kt_answer(answer: &Answer) -> Option<CylinderKtAnswer> {
        match *answer {
            Answer::Cylinder(CylinderAnswer {
                stiffness_group,
                zone,
                edge_slip,
                centre_slip,
                regime,
            }) => Some(CylinderKtAnswer {
                stiffness_group,
                zone,
                edge_slip,
                centre_slip,
                regime,
            }),
            _ => None,
        }
    }

    fn kt_values(a: &CylinderKtAnswer) -> (Vec<f64>, Regime) {
        (vec![a.stiffness_group, a.zone, a.edge_slip], a.regime)
    }
}

/// One point of the cylinder's `microslip cycle --format csv`: the loop of the edge slip s(a),
/// both laws.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct CylinderLoopRow {
    /// `unloading` or `reloading`.
    pub branch: &'static str,
    /// Tangential line load Q (N/mm).
    #[serde(rename = "Q_N_per_mm")]
    pub load: f64,
    /// Mindlin's and the regularized edge slip s(a) (mm).
    #[serde(rename = "sa_coulomb_mm")]
    pub edge_slip_coulomb: f64,
    #[serde(rename = "sa_regularized_mm")]
    pub edge_slip_regularized: f64,
}

impl From<&LoopPoint> for CylinderLoopRow {
    fn from(p: &LoopPoint) -> Self {
        CylinderLoopRow {
            branch: p.branch.label(),
            load: p.force,
            edge_slip_coulomb: p.w_coulomb,
            edge_slip_regularized: p.w_regularized,
        }
    }
}

impl CycleFace for CylinderProblem {
    const CYCLE_WORDS: CycleWords = CycleWords {
        peak_key: "sa_peak_mm",
        keys: CycleKeys {
            amplitude: "Qa_N_per_mm",
            onset: "onset_N_per_mm",
            dissipation: "D_Nmm_per_mm",
            peak_energy: "U_Nmm_per_mm",
            secant: "secant_stiffness_N_per_mm2",
            dissipations: ["D_coulomb_Nmm_per_mm", "D_regularized_Nmm_per_mm"],
        },
        heading: ("Hertzian cylinder", "tangential line load"),
        rows: [
            "onset of sliding (N/mm)",
            "peak edge slip s(a) (mm)",
            "D per cycle (N mm per mm)",
            "peak energy U (N mm per mm)",
            "damping ratio D / (4 pi U) (-)",
            "secant Q_a/delta_a (N/mm2)",
        ],
        note: "P and Q are line loads (per mm of the cylinder's length): D and U are per mm \
               of it. The loop shown is that of the edge slip s(a); U = Q_a delta_a / 2 and \
               the secant use the bodies' relative shift delta (docs/theory.md, the cylinder's \
               cycle), whose loop's area is D. With a finite K_T the edges slide at any \
               Q > 0 (onset 0).",
    };

    /// The keys the cylinder's cycle wrote before they said its line load's unit (`Fa_N`,
    /// `onset_N`, ...): written beside them for one release.
    const DEPRECATED_KEYS: Option<CycleKeys> = Some(CycleKeys::FORCE);

    fn structure_line(cylinder: &Cylinder) -> String {
        let p = cylinder.params();
        format!(
            "R = {} mm, E = {} MPa, nu = {}, P = {} N/mm, mu = {}, K_T = {} MPa/mm",
            number(p.radius),
            number(p.modulus),
            number(p.poisson),
            number(p.normal_load),
            number(p.friction),
            number(p.tangential_stiffness)
        )
    }

    type LoopRow = CylinderLoopRow;
    type LoadRow = CylinderRow;

    fn force_limit(cylinder: &Cylinder) -> Option<f64> {
        Some(cylinder.gross_slip_load())
    }

    fn cycle_inputs(cylinder: &Cylinder, amplitude: TangentialLoad) -> Inputs {
        CylinderProblem::to_inputs(CylinderInputs {
            structure: cylinder.params(),
            load: amplitude.newtons_per_mm(),
        })
    }
}

/// What the report's numbers assume.
const SOLUTION_NOTE: &str = "two elastic half-planes of one material (Hertz's pressure, unchanged \
     by the shear); Mindlin's closed form under Coulomb, the semi-analytic regularized solution \
     (docs/theory.md, the Hertzian cylinder)";

/// One law's answer at Q.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct CylinderLaw {
    #[serde(serialize_with = "regime_label")]
    pub regime: Regime,
    /// Half-width c of the zone where |q| < mu p (mm): Mindlin's stick zone, the regularized
    /// law's microslip zone.
    #[serde(rename = "c_mm")]
    pub zone: f64,
    /// c / a (-).
    pub c_over_a: f64,
    /// Edge slip s(a), the fretting slip amplitude (mm).
    #[serde(rename = "sa_mm")]
    pub edge_slip: f64,
    /// Centre slip s(0) (mm).
    #[serde(rename = "s0_mm")]
    pub centre_slip: f64,
    /// The largest q / (mu p0) (-).
    pub peak_q_over_mu_p0: f64,
}

/// The cylinder's report at one tangential load.
#[derive(Debug, Clone, Serialize)]
pub struct CylinderReport {
    /// Always `cylinder`.
    pub model: &'static str,
    pub preset: String,
    pub inputs: InputsReport,
    /// Q (N/mm), also in `inputs`.
    #[serde(rename = "Q_N_per_mm")]
    pub load: f64,
    /// Hertz: contact half-width a (mm), peak pressure p0 (MPa), contact modulus E* (MPa).
    #[serde(rename = "a_mm")]
    pub half_width: f64,
    #[serde(rename = "p0_MPa")]
    pub peak_pressure: f64,
    #[serde(rename = "Estar_MPa")]
    pub contact_modulus: f64,
    /// K_T a / E* (-): how compliant the interface is beside the bodies.
    #[serde(rename = "KT_a_over_Estar")]
    pub stiffness_group: f64,
    /// The gross-slip load mu P (N/mm): no larger Q is carried.
    #[serde(rename = "Q_gross_N_per_mm")]
    pub gross_slip_load: f64,
    /// mu p0 / K_T (mm): the slip at which the law saturates at the centre.
    #[serde(rename = "saturation_slip_centre_mm")]
    pub saturation_slip: f64,
    pub coulomb: CylinderLaw,
    pub regularized: CylinderLaw,
    /// What the solution assumes.
    pub note: &'static str,
    /// How far the half-plane answer holds for this cylinder (docs/theory.md, "The Hertzian
    /// cylinder in CI and how far the half-plane answer holds").
    pub half_plane_validity: HalfPlaneValidity,
}

/// The half-plane answer's envelope in the report ([`CylinderValidity`]).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct HalfPlaneValidity {
    /// `holds`, `approximate` (s(a) expected within 2 %, 10 % of a finite-body FE answer) or
    /// `not calibrated` (outside the measured envelope).
    #[serde(serialize_with = "validity_label")]
    pub validity: Validity,
    /// |c_FE - c| / a expected at most this (-); null outside the envelope.
    pub c_within_fraction_of_a: Option<f64>,
    /// |s(a)_FE / s(a) - 1| expected at most this (-); null outside the envelope.
    pub sa_within_fraction: Option<f64>,
    /// a / R (-).
    #[serde(rename = "a_over_R")]
    pub half_width_over_radius: f64,
    /// The least body half-width and depth, in a, the envelope was measured for.
    #[serde(rename = "bodies_at_least_a")]
    pub least_body: f64,
    /// Why the envelope does not reach this cylinder; null inside it.
    pub outside_because: Option<&'static str>,
}

impl From<CylinderValidity> for HalfPlaneValidity {
    fn from(v: CylinderValidity) -> Self {
        HalfPlaneValidity {
            validity: v.validity,
            c_within_fraction_of_a: v.zone_within,
            sa_within_fraction: v.edge_slip_within,
            half_width_over_radius: v.half_width_over_radius,
            least_body: LEAST_BODY_OVER_HALF_WIDTH,
            outside_because: v.outside_because,
        }
    }
}

impl HalfPlaneValidity {
    /// The envelope in one sentence.
    pub fn text(&self) -> String {
        match (self.c_within_fraction_of_a, self.sa_within_fraction) {
            (Some(c), Some(sa)) => format!(
                "{}: a finite-body FE answer (bodies at least {} a wide and deep) expected within \
                 {} % of a in c and {} % in s(a)",
                self.validity.label(),
                number(self.least_body),
                number(100.0 * c),
                number(100.0 * sa)
            ),
            _ => format!(
                "{}: {}",
                self.validity.label(),
                self.outside_because
                    .unwrap_or("outside the measured envelope")
            ),
        }
    }
}

impl CylinderReport {
    /// The report of `model`.
    pub fn new(preset: &str, model: &CylinderModel) -> CylinderReport {
        let row = cylinder_point(&model.cylinder, model.load);
        let cylinder = &model.cylinder;
        let a = row.half_width;
        let p = cylinder.params();
        let coulomb = cylinder.coulomb(model.load);
        CylinderReport {
            model: "cylinder",
            preset: preset.to_string(),
            inputs: InputsReport(CylinderProblem::to_inputs(CylinderInputs {
                structure: p,
                load: row.load,
            })),
            load: row.load,
            half_width: a,
            peak_pressure: row.peak_pressure,
            contact_modulus: cylinder.contact_modulus(),
            stiffness_group: row.stiffness_group,
            gross_slip_load: cylinder.gross_slip_load(),
            saturation_slip: p.friction * row.peak_pressure / p.tangential_stiffness,
            coulomb: CylinderLaw {
                regime: row.regime_coulomb,
                zone: row.zone_coulomb,
                c_over_a: row.zone_coulomb / a,
                edge_slip: row.edge_slip_coulomb,
                centre_slip: coulomb.centre_slip(),
                peak_q_over_mu_p0: row.peak_shear_coulomb,
            },
            regularized: CylinderLaw {
                regime: row.regime_regularized,
                zone: row.zone_regularized,
                c_over_a: row.zone_regularized / a,
                edge_slip: row.edge_slip_regularized,
                centre_slip: row.centre_slip_regularized,
                peak_q_over_mu_p0: row.peak_shear_regularized,
            },
            note: SOLUTION_NOTE,
            half_plane_validity: cylinder.validity().into(),
        }
    }

    /// The readable report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Hertzian cylinder on a flat (plane strain; P and Q are line loads, N per mm of the \
             cylinder's length) - preset {}",
            sanitize(&self.preset)
        );
        self.inputs.write(&mut out);
        let _ = writeln!(
            out,
            "Hertz: a = {} mm, p0 = {} MPa (E* = {} MPa); K_T a / E* = {}",
            number(self.half_width),
            number(self.peak_pressure),
            number(self.contact_modulus),
            number_with(self.stiffness_group, 4)
        );
        let _ = writeln!(
            out,
            "  Q_gross = mu P = {} N/mm (gross slip); mu p0 / K_T = {} um (saturation slip at the centre)",
            number(self.gross_slip_load),
            number(mm_to_um(self.saturation_slip))
        );
        let (c, r) = (&self.coulomb, &self.regularized);
        let _ = writeln!(
            out,
            "{:<32}{:<22}regularized",
            format!("At Q = {} N/mm", number(self.load)),
            "Mindlin (Coulomb)"
        );
        let row = |out: &mut String, label: &str, a: String, b: String| {
            let _ = writeln!(out, "  {label:<30}{a:<22}{b}");
        };
        row(
            &mut out,
            "regime",
            c.regime.to_string(),
            r.regime.to_string(),
        );
        row(
            &mut out,
            "c (mm), |q| < mu p inside",
            number(c.zone),
            number(r.zone),
        );
        row(&mut out, "c / a", number(c.c_over_a), number(r.c_over_a));
        row(
            &mut out,
            "s(a) edge slip (mm)",
            number(c.edge_slip),
            number(r.edge_slip),
        );
        row(
            &mut out,
            "s(0) centre slip (mm)",
            number(c.centre_slip),
            number(r.centre_slip),
        );
        row(
            &mut out,
            "peak q / (mu p0)",
            number(c.peak_q_over_mu_p0),
            number(r.peak_q_over_mu_p0),
        );
        let _ = writeln!(
            out,
            "  (with a finite K_T the edges slide for any Q > 0, where p -> 0: over a - c = {} mm \
             at each edge)",
            number(self.half_width - r.zone)
        );
        let _ = writeln!(out, "Solution: {}", self.note);
        let _ = writeln!(
            out,
            "Half-plane answer against CalculiX: {}",
            self.half_plane_validity.text()
        );
        out
    }
}
