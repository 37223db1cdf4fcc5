//! `microslip fit beam|lap`: mu and K_T fitted to a measured curve, with a plain verdict on whether
//! the data identify each.

use std::fmt::Write;

use serde::{Serialize, Serializer};

use crate::fit::{Estimate, Evidence, FitResult, Scatter, Status, Structure};
use crate::problems::Param;
use crate::report::{count_of, number, sanitize};

/// The fit report.
#[derive(Debug, Clone, Serialize)]
pub struct FitReport {
    /// The measurement file.
    pub data: String,
    pub preset: String,
    /// The structure the fit held (geometry, moduli, P), for the text.
    #[serde(skip)]
    pub structure: Structure,
    /// How many measurements.
    pub points: usize,
    pub mu: EstimateReport,
    #[serde(rename = "KT_MPa_per_mm")]
    pub kt: EstimateReport,
    /// The residuals, in the response's unit: in JSON `rms_mm` (the twisted fit's `rms_rad`),
    /// `weights` and `scatter` ([`Residuals`]).
    #[serde(flatten)]
    pub residuals: Residuals,
    /// The regime scale, F_1 and the measurements above F_1 at the fitted values, under the
    /// load's name and unit ([`LoadForces`]): in JSON `F_thre_N`, `F_1_N`, `points_above_F_1`
    /// of the beams, `F_gross_N` ... of the lap joint, `Q_gross_N_per_mm`, `Q_1_N_per_mm`,
    /// `points_above_Q_1` of the cylinder (a line load).
    #[serde(flatten, serialize_with = "load_fields")]
    pub forces: LoadForces,
    /// Correlation coefficient of the mu and K_T estimates (null unless both have an error).
    #[serde(rename = "mu_KT_correlation")]
    pub correlation: Option<f64>,
    /// Loaded measurements less fitted parameters; at 0 the scatter and errors are unknown.
    pub degrees_of_freedom: usize,
}

/// The residuals of a fit, in the unit of the response fitted (`mm` for w, Delta, s(a); `rad`
/// for the twisted fit's theta): the RMS and what the standard errors assume.
#[derive(Debug, Clone, Copy)]
pub struct Residuals {
    /// Residual RMS, in `unit`.
    pub rms: f64,
    /// What the standard errors assume: in JSON `weights` ("absolute", "relative" or the sigma
    /// column's name, `sigma_mm`) and `scatter`, sqrt of the weighted fit's reduced chi-square:
    /// the sigma of the response in its unit, its sigma as a fraction of it, or the residuals'
    /// scatter over the given sigmas (about 1 when they are right).
    pub scatter: Scatter,
    /// The response's unit, as its column's header ends (`mm`, `rad`).
    pub unit: &'static str,
}

impl Residuals {
    /// The name of the weights, sqrt of the reduced chi-square (None without a degree of
    /// freedom) and the key that names its unit: `scatter_mm` (absolute weights: the sigma of the
    /// response), `scatter_fraction` (relative: sigma over the response) or `scatter_over_sigma`
    /// (given sigmas: a ratio, about 1 when they are right).
    fn weights_and_scatter(&self) -> (String, Option<f64>, String) {
        match self.scatter {
            Scatter::Absolute { sigma } => {
                ("absolute".into(), sigma, format!("scatter_{}", self.unit))
            }
            Scatter::Relative { fraction } => {
                ("relative".into(), fraction, "scatter_fraction".into())
            }
            Scatter::Known { reduced_chi_square } => (
                format!("sigma_{}", self.unit),
                reduced_chi_square.map(f64::sqrt),
                "scatter_over_sigma".into(),
            ),
        }
    }
}

/// `rms_<unit>`, `weights`, the scatter under its unit's name and, deprecated (kept one
/// release), the same value as `scatter`, whose unit depended on `weights`.
impl Serialize for Residuals {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let (weights, value, key) = self.weights_and_scatter();
        let mut map = s.serialize_map(Some(4))?;
        map.serialize_entry(&format!("rms_{}", self.unit), &self.rms)?;
        map.serialize_entry("scatter", &value)?;
        map.serialize_entry(&key, &value)?;
        map.serialize_entry("weights", &weights)?;
        map.end()
    }
}

/// The fit's forces on the load axis, named by the problem's load (F in N; the cylinder's Q, a
/// line load in N/mm).
#[derive(Debug, Clone, Copy)]
pub struct LoadForces {
    /// The load parameter (F, Q): its name and unit.
    pub load: Param,
    /// The regime scale's name ([`Description::regime_scale_name`](crate::problems::Description):
    /// `F_thre`, `F_gross`, `Q_gross`) and its value at the fitted values.
    pub regime_scale: (&'static str, f64),
    /// F_1 at the fitted values: where the interface first slides (0 where it slides somewhere
    /// at every load: the cylinder's edges).
    pub first_macroslip_force: f64,
    /// Measurements above F_1, the only ones that depend on mu.
    pub beyond_first_macroslip: usize,
}

impl LoadForces {
    /// F_1's name: the load's, with index 1 (`F_1`, `Q_1`).
    fn first_name(&self) -> String {
        format!("{}_1", self.load.name())
    }
}

/// `{scale}_{unit}`, `{load}_1_{unit}` and `points_above_{load}_1` ([`FitReport::forces`]), the
/// unit spelled as a key ([`crate::kernel::params::Unit::key`]: `N`, `N_per_mm`, `Nmm`).
fn load_fields<S: Serializer>(forces: &LoadForces, s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let unit = forces.load.unit().key();
    let (scale, value) = forces.regime_scale;
    let first = forces.first_name();
    let mut map = s.serialize_map(Some(3))?;
    map.serialize_entry(&format!("{scale}_{unit}"), &value)?;
    map.serialize_entry(&format!("{first}_{unit}"), &forces.first_macroslip_force)?;
    map.serialize_entry(
        &format!("points_above_{first}"),
        &forces.beyond_first_macroslip,
    )?;
    map.end()
}

/// What the errors assume, in words, with the scatter the residuals show (or that they cannot
/// show it: `points` loaded measurements through as many parameters).
fn assumption(
    residuals: &Residuals,
    response: &str,
    (points, parameters): (usize, usize),
) -> String {
    let unit = residuals.unit;
    let unknown = || {
        format!(
            "the residuals cannot show the scatter: uncertainty unknown, {} = {} (the curve \
             passes through every loaded point)",
            count_of(points, "loaded point"),
            count_of(parameters, "parameter")
        )
    };
    match residuals.scatter {
        Scatter::Absolute { sigma } => format!(
            "the same scatter at every point (--weights absolute); {}",
            sigma.map_or_else(unknown, |s| format!(
                "the residuals show {} {unit}",
                number(s)
            ))
        ),
        Scatter::Relative { fraction } => format!(
            "scatter proportional to {response} (--weights relative); {}",
            fraction.map_or_else(unknown, |f| format!(
                "the residuals show {} % of {response}",
                number(100.0 * f)
            ))
        ),
        Scatter::Known { reduced_chi_square } => format!(
            "the sigma_{unit} column, taken as known; {}",
            reduced_chi_square.map_or_else(
                || "chi^2/dof undefined (no degree of freedom left)".to_string(),
                |c| format!("chi^2/dof = {} (about 1 when it is right)", number(c))
            )
        ),
    }
}

/// One fitted (or fixed) parameter.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct EstimateReport {
    pub value: f64,
    /// Absent (null) where it could not be computed, or the value was held fixed.
    pub std_error: Option<f64>,
    #[serde(serialize_with = "status_label")]
    pub status: Status,
    /// In JSON the reason in words ([`evidence`]).
    #[serde(rename = "note", serialize_with = "evidence_words")]
    pub evidence: Evidence,
}

fn status_label<S: Serializer>(status: &Status, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(status.label())
}

fn evidence_words<S: Serializer>(e: &Evidence, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&evidence(e))
}

/// The reason behind a fit verdict, in plain words (the text and JSON fit reports' note).
pub fn evidence(evidence: &Evidence) -> String {
    match *evidence {
        Evidence::HeldFixed => "held fixed".to_string(),
        Evidence::StandardError { relative } => {
            format!("relative standard error {:.2} %", 100.0 * relative)
        }
        Evidence::AtSearchBound => "the best fit sits at the edge of the search range".to_string(),
        Evidence::NoDependence => "the data do not depend on it".to_string(),
        Evidence::NoDegreesOfFreedom { points, parameters } => format!(
            "{} = {}: the fit passes through every one, so its residuals (0 by construction) \
             cannot show an error",
            count_of(points, "loaded point"),
            count_of(parameters, "parameter")
        ),
        Evidence::NoDataAboveFirstMacroslip {
            first_macroslip_force,
            mu_at_least,
        } => format!(
            "no measurement above F_1 = {} N: below F_1 the deflection does not depend on mu; the data only show mu >= {}",
            number(first_macroslip_force),
            number(mu_at_least)
        ),
        Evidence::FewPointsAboveFirstMacroslip { relative, points } => format!(
            "relative standard error {:.2} %; only {points} {} above F_1",
            100.0 * relative,
            if points == 1 {
                "measurement"
            } else {
                "measurements"
            }
        ),
    }
}

impl From<&Estimate> for EstimateReport {
    fn from(e: &Estimate) -> Self {
        EstimateReport {
            value: e.value,
            std_error: e.std_error,
            status: e.status,
            evidence: e.evidence,
        }
    }
}

impl FitReport {
    pub fn new(data: &str, preset: &str, structure: &Structure, result: &FitResult) -> FitReport {
        let forces = LoadForces {
            load: structure.load(),
            regime_scale: (
                structure.kind().description().regime_scale_name,
                result.threshold_force,
            ),
            first_macroslip_force: result.first_macroslip_force,
            beyond_first_macroslip: result.beyond_first_macroslip,
        };
        FitReport {
            data: data.to_string(),
            preset: preset.to_string(),
            structure: *structure,
            points: result.points,
            mu: EstimateReport::from(&result.mu),
            kt: EstimateReport::from(&result.kt),
            residuals: Residuals {
                rms: result.rms,
                scatter: result.scatter,
                unit: crate::measured::column_unit(structure.response_column()),
            },
            forces,
            correlation: result.correlation,
            degrees_of_freedom: result.degrees_of_freedom,
        }
    }

    /// (loaded points, parameters fitted through them) when no degree of freedom is left, as
    /// the estimates' evidence says; else the parameters not held by `--fix`, twice.
    fn no_freedom(&self) -> (usize, usize) {
        [&self.mu, &self.kt]
            .iter()
            .find_map(|e| match e.evidence {
                Evidence::NoDegreesOfFreedom { points, parameters } => Some((points, parameters)),
                _ => None,
            })
            .unwrap_or_else(|| {
                let free = [&self.mu, &self.kt]
                    .iter()
                    .filter(|e| e.status != Status::Fixed)
                    .count();
                (free, free)
            })
    }

    /// The readable report: estimates with standard errors and the verdicts.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let what = self.structure.fitted();
        let _ = writeln!(
            out,
            "Fit of mu and K_T to {} ({}), {what} of preset {}",
            sanitize(&self.data),
            count_of(self.points, "measurement"),
            sanitize(&self.preset)
        );
        let held: Vec<String> = self
            .structure
            .held()
            .into_iter()
            .map(|(param, value)| {
                format!(
                    "{} = {}{}",
                    param.name(),
                    number(value),
                    param.unit_suffix()
                )
            })
            .collect();
        let _ = writeln!(out, "  structure: {}", held.join(", "));
        for (name, unit, estimate) in [("mu ", "", &self.mu), ("K_T", " MPa/mm", &self.kt)] {
            let error = estimate
                .std_error
                .map_or(String::new(), |e| format!(" +- {}", number(e)));
            // "fixed (held fixed)" said it twice: a held value needs no reason.
            let reason = match estimate.evidence {
                Evidence::HeldFixed => String::new(),
                ref other => format!(" ({})", evidence(other)),
            };
            let _ = writeln!(
                out,
                "  {name} = {}{error}{unit}: {}{reason}",
                number(estimate.value),
                estimate.status.label(),
            );
        }
        if let Some(rho) = self.correlation {
            let _ = writeln!(out, "  correlation of mu and K_T = {}", number(rho));
        }
        let response = crate::problems::Quantity::Response.name(self.structure.kind());
        let _ = writeln!(
            out,
            "  errors assume {}",
            assumption(&self.residuals, response, self.no_freedom())
        );
        let exact = if self.degrees_of_freedom == 0 {
            " (0 by construction: no degree of freedom left)"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "  residual RMS = {} {}{exact}",
            number(self.residuals.rms),
            self.residuals.unit
        );
        let forces = &self.forces;
        let (name, all_slide) = forces.regime_scale;
        let (first, unit) = (forces.first_name(), forces.load.unit_suffix());
        let first_slip = if forces.first_macroslip_force == 0.0 {
            // The cylinder's edges (p -> 0 there): no load below which mu is absent.
            format!(
                "{first} = 0{unit}: the interface slides somewhere at every load, so every \
                 loaded measurement depends on mu, though at small loads barely (mu's standard \
                 error says how much)"
            )
        } else {
            format!(
                "{first} = {}{unit}; {} of {} measurements above {first}",
                number(forces.first_macroslip_force),
                forces.beyond_first_macroslip,
                self.points
            )
        };
        let _ = writeln!(
            out,
            "  at the fitted values: {name} = {}{unit}, {first_slip}",
            number(all_slide),
        );
        out
    }
}
