//! The output contract of the single-point reports (`beam`, `plate`, `lap`, `cycle`, `kt`, `kt
//! --tolerance`, `fit`, `solve`, `compare`): users' scripts read their JSON keys and CSV columns, so
//! the full set of JSON key paths of each case (with each value's JSON type) and each CSV header
//! are pinned here, written out literally from the outputs captured before the reports became
//! types (tests/data/reports/). A renamed, dropped or retyped key fails this test.
//!
//! The captured files also hold the text forms. `outputs_match_the_captured_files` compares every
//! output byte for byte with them; it is ignored by default because its JSON numbers carry all 17
//! digits, which another platform's libm may round differently in the last one. Run it with
//! `cargo test --test report_contract -- --ignored`; `MICROSLIP_CAPTURE=1` rewrites the files.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

/// An output format of a case, and the extension of its captured file.
#[derive(Clone, Copy)]
enum Format {
    Text,
    Json,
    Csv,
}

impl Format {
    fn flag(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Json => "json",
            Format::Csv => "csv",
        }
    }

    fn extension(self) -> &'static str {
        match self {
            Format::Text => "txt",
            Format::Json => "json",
            Format::Csv => "csv",
        }
    }
}

/// One command line, run in each of `formats`; `keys` are the JSON key paths it must give.
struct Case {
    name: &'static str,
    args: &'static [&'static str],
    formats: &'static [Format],
    keys: &'static [&'static [&'static str]],
    /// The CSV header, for cases with a CSV form.
    header: Option<&'static str>,
}

const TEXT_JSON: &[Format] = &[Format::Text, Format::Json];
const ALL: &[Format] = &[Format::Text, Format::Json, Format::Csv];

const BEAM: &[&str] = &[
    "F_1_N: number",
    "F_thre_N: number",
    "beam_theory: object",
    "beam_theory.friction_strain: number",
    "beam_theory.shear_deflection_share: number",
    "beam_theory.shear_deflection_share_fraction: number",
    "beam_theory.theory: string",
    "beam_theory.validity: string",
    "beam_theory.validity_linear_geometry: string",
    "beam_theory.vs_continuum_within: number",
    "beam_theory.vs_continuum_linear_within_fraction: number",
    "beam_theory.vs_continuum_nlgeom_within_fraction: number",
    "beam_theory.vs_continuum_within_fraction: number",
    "coulomb: object",
    "coulomb.regime: string",
    "coulomb.stick_end_mm: number",
    "coulomb.w_tip_mm: number",
    "first_macroslip_at_mm: number",
    "inputs: object",
    "inputs.E_MPa: number",
    "inputs.F_N: number",
    "inputs.KT_MPa_per_mm: number",
    "inputs.L_mm: number",
    "inputs.P_MPa: number",
    "inputs.b_mm: number",
    "inputs.h_mm: number",
    "inputs.mu: number",
    "inputs.nu: number",
    "model: string",
    "preset: string",
    "regularized: object",
    "regularized.X_mm: number",
    "regularized.regime: string",
    "regularized.w_tip_mm: number",
    "saturation_slip_mm: number",
];

const PLATE: &[&str] = &[
    "contact_pressure: object",
    "contact_pressure.constant_pressure_holds: bool",
    "contact_pressure.end_layer_ratio: number",
    "contact_pressure.end_layer_ratio_applies: bool",
    "contact_pressure.mean_deviation: number",
    "contact_pressure.mean_deviation_fraction: number",
    "contact_pressure.mean_deviation_limit: number",
    "contact_pressure.mean_deviation_limit_fraction: number",
    "contact_pressure.model: string",
    "contact_pressure.peak_deviation: number",
    "contact_pressure.peak_deviation_fraction: number",
    "contact_pressure.peak_deviation_limit: number",
    "contact_pressure.peak_deviation_limit_fraction: number",
    "contact_pressure.ratio_centre: number",
    "contact_pressure.ratio_edge: number",
    "coulomb: object",
    "coulomb.Xs_mm: number",
    "coulomb.regime: string",
    "coulomb.u_end_mm: number",
    "inputs: object",
    "inputs.E_MPa: number",
    "inputs.KT_MPa_per_mm: number",
    "inputs.L_mm: number",
    "inputs.P_MPa: number",
    "inputs.mu: number",
    "inputs.nu: number",
    "inputs.tp_mm: number",
    "model: string",
    "preset: string",
    "regularized: object",
    "regularized.Xr_mm: number",
    "regularized.regime: string",
    "regularized.u_end_mm: number",
    "saturation_slip_mm: number",
    "strip_theory: object",
    "strip_theory.X_r_bounded: bool",
    "strip_theory.alpha_tp: number",
    "strip_theory.calibrated_from_slip_zone_over_tp: number",
    "strip_theory.calibrated_slip_zone_up_to_alpha_tp: number",
    "strip_theory.calibrated_up_to_alpha_tp: number",
    "strip_theory.slip_zone_over_tp: number",
    "strip_theory.validity: string",
    "strip_theory.validity_covers: string",
];

/// The plate's K_T at macroslip onset: absent when nothing ever slides (nu = 0).
const PLATE_ONSET: &[&str] = &["KT_macroslip_onset_MPa_per_mm: number"];

/// The strip theory's expected differences: present where a calibration reaches.
const PLATE_EXPECTED: &[&str] = &[
    "strip_theory.expected_difference_contact_face: number",
    "strip_theory.expected_difference_contact_face_fraction: number",
    "strip_theory.expected_difference_from_continuum: number",
    "strip_theory.expected_difference_from_continuum_fraction: number",
    "strip_theory.expected_difference_mid_thickness: number",
    "strip_theory.expected_difference_mid_thickness_fraction: number",
];

/// Where the strip theory is measured wrong (V1c): the least difference stated for its region.
const PLATE_WRONG: &[&str] = &[
    "strip_theory.measured_difference_at_least: number",
    "strip_theory.measured_difference_at_least_fraction: number",
];

/// The plane-strain continuum: with --continuum, or when the strip theory is not within 2 %.
const PLATE_CONTINUUM: &[&str] = &[
    "continuum: object",
    "continuum.Xr_mm: number",
    "continuum.edge_pressure_ratio: number",
    "continuum.end_element_mm: number",
    "continuum.end_layer_pressure_ratio: number",
    "continuum.end_pressure_ratio: number",
    "continuum.interior_pressure_max_ratio: number",
    "continuum.interior_pressure_min_ratio: number",
    "continuum.pressure_model: string",
    "continuum.u_end_contact_face_mm: number",
    "continuum.u_end_mean_mm: number",
    "continuum.u_end_mid_thickness_mm: number",
];

const CYCLE: &[&str] = &[
    "Fa_N: number",
    "coulomb: object",
    "coulomb.D_Nmm: number",
    "coulomb.U_Nmm: number",
    "coulomb.onset_N: number",
    "coulomb.secant_stiffness_N_per_mm: number",
    "coulomb.w_peak_mm: number",
    "coulomb.zeta: number",
    "inputs: object",
    "inputs.E_MPa: number",
    "inputs.F_N: number",
    "inputs.KT_MPa_per_mm: number",
    "inputs.L_mm: number",
    "inputs.P_MPa: number",
    "inputs.b_mm: number",
    "inputs.h_mm: number",
    "inputs.mu: number",
    "inputs.nu: number",
    "model: string",
    "note: string",
    "preset: string",
    "regularized: object",
    "regularized.D_Nmm: number",
    "regularized.U_Nmm: number",
    "regularized.onset_N: number",
    "regularized.secant_stiffness_N_per_mm: number",
    "regularized.w_peak_mm: number",
    "regularized.zeta: number",
];

const KT: &[&str] = &[
    "candidates: array",
    "candidates[]: object",
    "candidates[].KT_MPa_per_mm: null|number",
    "candidates[].basis: string",
    "candidates[].source: string",
    "element_size_mm: number",
    "preset: string",
];

/// A beam candidate's answer.
const KT_BEAM: &[&str] = &[
    "candidates[].F_1_N: number",
    "candidates[].X_mm: number",
    "candidates[].regime: string",
    "candidates[].w_tip_mm: number",
    "candidates[].vs_current_percent: number",
    "candidates[].vs_coulomb_percent: number",
];

const KT_PLATE: &[&str] = &[
    "candidates[].Xr_mm: number",
    "candidates[].regime: string",
    "candidates[].u_end_mm: number",
    "candidates[].vs_current_percent: number",
    "candidates[].vs_coulomb_percent: number",
];

/// A candidate the model refuses (a K_T out of range).
const KT_REFUSED: &[&str] = &["candidates[].not_evaluated: string"];

const TOLERANCE: &[&str] = &[
    "codes: array",
    "current_KT_MPa_per_mm: number",
    "current_deviation: number",
    "note: string",
    "of: string",
    "preset: string",
    "tolerance: number",
];

/// The tolerance of Coulomb (the default reading): no upper end.
const TOLERANCE_OF_COULOMB: &[&str] = &["KT_max_MPa_per_mm: null", "coulomb_vs_current: null"];

/// The tolerance of the current K_T's answer (`--of current`): an interval.
const TOLERANCE_OF_CURRENT: &[&str] = &["KT_max_MPa_per_mm: number", "coulomb_vs_current: number"];

/// A K_T within the tolerance, and each code's setting for it.
const TOLERANCE_FOUND: &[&str] = &[
    "KT_min_MPa_per_mm: number",
    "codes[]: object",
    "codes[].code: string",
    "codes[].default_KT_MPa_per_mm: null|number",
    "codes[].default_enough: bool|null",
    "codes[].element_size_max_mm_with_default: number",
    "codes[].element_size_mm: number",
    "codes[].elastic_slip_max_mm: number",
    "codes[].h_min_max_mm: number",
    "codes[].slip_tolerance_max: number",
    "codes[].stick_slope_min_MPa_per_mm: number",
    "codes[].stiffness_min_MPa_per_mm: number",
];

/// No accepted K_T is within the tolerance: no minimum, and no code settings.
const TOLERANCE_NOWHERE: &[&str] = &["KT_min_MPa_per_mm: null"];

const TOLERANCE_BEAM: &[&str] = &["force_range_N: array", "force_range_N[]: number"];
const TOLERANCE_PLATE: &[&str] = &["force_range_N: null"];

const FIT: &[&str] = &[
    "F_1_N: number",
    "F_thre_N: number",
    "KT_MPa_per_mm: object",
    "KT_MPa_per_mm.note: string",
    "KT_MPa_per_mm.status: string",
    "KT_MPa_per_mm.value: number",
    "data: string",
    "mu: object",
    "mu.note: string",
    "mu.status: string",
    "mu.value: number",
    "points: number",
    "points_above_F_1: number",
    "preset: string",
    "rms_mm: number",
    // Added by issue 36 (15): 0 when the curve passes through every loaded point.
    "degrees_of_freedom: number",
];

/// Added by issue 25 (5): what the errors assume (`weights`, `scatter`).
const FIT_WEIGHTS: &[&str] = &["scatter: number", "weights: string"];

/// Issue 36: the scatter again under a name that says its unit, which the weights decide.
const FIT_SCATTER_MM: &[&str] = &["scatter_mm: number"];
const FIT_SCATTER_FRACTION: &[&str] = &["scatter_fraction: number"];

/// The cylinder's fit (issue 34, item 4): its load is the line load Q (N/mm), so the forces on
/// the load axis are named by it: the beams' `F_thre_N`, `F_1_N` and `points_above_F_1` are
/// `Q_gross_N_per_mm`, `Q_1_N_per_mm` and `points_above_Q_1`; every other key is the beams'.
const FIT_CYLINDER: &[&str] = &[
    "KT_MPa_per_mm: object",
    "KT_MPa_per_mm.note: string",
    "KT_MPa_per_mm.status: string",
    "KT_MPa_per_mm.value: number",
    "Q_1_N_per_mm: number",
    "Q_gross_N_per_mm: number",
    "data: string",
    "degrees_of_freedom: number",
    "mu: object",
    "mu.note: string",
    "mu.status: string",
    "mu.value: number",
    "points: number",
    "points_above_Q_1: number",
    "preset: string",
    "rms_mm: number",
];

/// (`mu_KT_correlation` added by issue 25 (5).)
const FIT_ERRORS: &[&str] = &[
    "KT_MPa_per_mm.std_error: number",
    "mu.std_error: number",
    "mu_KT_correlation: number",
];

/// K_T held fixed (`--fix KT=...`): it has no standard error, and no correlation with mu.
const FIT_FIXED: &[&str] = &[
    "KT_MPa_per_mm.std_error: null",
    "mu.std_error: number",
    "mu_KT_correlation: null",
];

const SOLVE: &[&str] = &[
    "model: string",
    "param: string",
    "preset: string",
    "quantity: string",
    "range: array",
    "range[]: number",
    "roots: array",
    "roots[]: object",
    "roots[].achieved: number",
    "roots[].bracket: array",
    "roots[].bracket[]: number",
    "roots[].certified: bool",
    "roots[].plateau: bool",
    "roots[].value: number",
    "roots[].within_rounding: bool",
    "target: number",
    "unit: string",
];

const COMPARE_BEAM: &[&str] = &[
    "KT_MPa_per_mm: number",
    "implied: object",
    "model: string",
    "nu: number",
    "results: string",
    "rows: array",
    "rows[]: object",
    "rows[].F_N: number",
    "rows[].X_mm: number",
    "rows[].regime: string",
    "rows[].shear_corrected_within: number",
    "rows[].shear_corrected_within_fraction: number",
    "rows[].w_euler_mm: number",
    "rows[].w_fe_mm: number",
    "rows[].w_shear_corrected_mm: number",
];

/// CalculiX results: a slip profile (the FE regime and X) and defined differences.
const COMPARE_BEAM_FE: &[&str] = &[
    "rows[].X_fe_mm: number",
    "rows[].diff_euler: number",
    "rows[].diff_euler_fraction: number",
    "rows[].diff_shear_corrected: number",
    "rows[].diff_shear_corrected_fraction: number",
    "rows[].regime_fe: string",
];

/// A CSV with F = 0: no slip profile, and the differences undefined (null) at F = 0.
const COMPARE_BEAM_CSV: &[&str] = &[
    "rows[].X_fe_mm: null",
    "rows[].diff_euler: null|number",
    "rows[].diff_euler_fraction: null|number",
    "rows[].diff_shear_corrected: null|number",
    "rows[].diff_shear_corrected_fraction: null|number",
    "rows[].regime_fe: null",
];

/// A CSV of two points, too few for mu and K_T: the reason instead of the implied values.
const COMPARE_BEAM_TWO: &[&str] = &[
    "rows[].X_fe_mm: null",
    "rows[].diff_euler: number",
    "rows[].diff_euler_fraction: number",
    "rows[].diff_shear_corrected: number",
    "rows[].diff_shear_corrected_fraction: number",
    "rows[].regime_fe: null",
    "implied.error: string",
];

const COMPARE_BEAM_IMPLIED: &[&str] = &[
    "implied.KT_MPa_per_mm: number",
    "implied.KT_status: string",
    "implied.mu: number",
    "implied.mu_status: string",
    "implied.rms_mm: number",
    // Added by issue 36 (15).
    "implied.degrees_of_freedom: number",
];

const COMPARE_BEAM_HEADER: &str = "F_N,w_fe_mm,w_euler_mm,diff_euler,w_shear_corrected_mm,\
diff_shear_corrected,shear_corrected_within,regime,regime_fe,X_mm,X_fe_mm,diff_euler_fraction,\
diff_shear_corrected_fraction,shear_corrected_within_fraction";

const COMPARE_PLATE: &[&str] = &[
    "model: string",
    "results: string",
    "rows: array",
    "rows[]: object",
    "rows[].KT_MPa_per_mm: number",
    "rows[].Xr_mm: number",
    "rows[].regime: string",
    "rows[].strip_theory: string",
    "rows[].u_coulomb_mm: number",
    "rows[].u_fe_mm: number",
    "rows[].u_mm: number",
    "rows[].KT_implied_MPa_per_mm: null|number",
    "rows[].diff: number",
    "rows[].diff_fraction: number",
];

/// CalculiX results: through the thickness, and a slip profile.
const COMPARE_PLATE_FE: &[&str] = &[
    "rows[].Xr_fe_mm: number",
    "rows[].diff_contact_face: number",
    "rows[].diff_contact_face_fraction: number",
    "rows[].diff_mid_thickness: number",
    "rows[].diff_mid_thickness_fraction: number",
    "rows[].regime_fe: string",
    "rows[].u_fe_contact_face_mm: number",
    "rows[].u_fe_mid_thickness_mm: number",
];

/// A CSV: u(L) alone.
const COMPARE_PLATE_CSV: &[&str] = &[
    "rows[].Xr_fe_mm: null",
    "rows[].diff_contact_face: null",
    "rows[].diff_contact_face_fraction: null",
    "rows[].diff_mid_thickness: null",
    "rows[].diff_mid_thickness_fraction: null",
    "rows[].regime_fe: null",
    "rows[].u_fe_contact_face_mm: null",
    "rows[].u_fe_mid_thickness_mm: null",
];

/// Added with the verdicts (issue 25, item 1): each row's verdict and the closing one.
const COMPARE_VERDICT: &[&str] = &[
    "rows[].verdict: object",
    "rows[].verdict.envelope: string",
    "rows[].verdict.text: string",
    "verdict: object",
    "verdict.agrees: bool",
    "verdict.summary: string",
];

/// The fit's standard error of K_T, which the K_T verdict uses.
const COMPARE_BEAM_IMPLIED_ERROR: &[&str] = &["implied.KT_std_error_MPa_per_mm: number"];

/// The same key where the fit has no degree of freedom (as many loaded points as parameters):
/// its error is unknown, null (issue 36 (15); it used to be a meaningless 0).
const COMPARE_BEAM_IMPLIED_UNKNOWN_ERROR: &[&str] = &["implied.KT_std_error_MPa_per_mm: null"];

/// CalculiX beams: X in elements of the deck's mesh, and a K_T judged in standard errors.
const COMPARE_BEAM_VERDICT_FE: &[&str] = &[
    "rows[].verdict.X_elements: number",
    "rows[].verdict.X_within_mesh_resolution: bool",
    "rows[].verdict.envelope_bound: number",
    "rows[].verdict.envelope_bound_fraction: number",
    "verdict.KT: string",
    "verdict.KT_z: number",
];

/// A CSV with F = 0: no mesh, no envelope where the difference is undefined, no z.
const COMPARE_BEAM_VERDICT_CSV: &[&str] = &[
    "rows[].verdict.X_elements: null",
    "rows[].verdict.X_within_mesh_resolution: null",
    "rows[].verdict.envelope_bound: null|number",
    "rows[].verdict.envelope_bound_fraction: null|number",
    "verdict.KT: string",
    "verdict.KT_z: null",
];

/// Two CSV points: no mesh, no K_T implied.
const COMPARE_BEAM_VERDICT_TWO: &[&str] = &[
    "rows[].verdict.X_elements: null",
    "rows[].verdict.X_within_mesh_resolution: null",
    "rows[].verdict.envelope_bound: number",
    "rows[].verdict.envelope_bound_fraction: number",
    "verdict.KT: string",
    "verdict.KT_z: null",
];

/// The plate: (V1) is not calibrated at every K_T, so the bound may be null.
const COMPARE_PLATE_VERDICT: &[&str] = &[
    "rows[].verdict.envelope_bound: null|number",
    "rows[].verdict.envelope_bound_fraction: null|number",
];

const COMPARE_PLATE_VERDICT_FE: &[&str] = &[
    "rows[].verdict.Xr_elements: number",
    "rows[].verdict.Xr_within_mesh_resolution: bool",
];

const COMPARE_PLATE_VERDICT_CSV: &[&str] = &[
    "rows[].verdict.Xr_elements: null",
    "rows[].verdict.Xr_within_mesh_resolution: null",
];

const COMPARE_PLATE_HEADER: &str = "KT_MPa_per_mm,u_fe_mm,u_fe_contact_face_mm,\
u_fe_mid_thickness_mm,u_mm,diff,diff_contact_face,diff_mid_thickness,u_coulomb_mm,regime,\
regime_fe,Xr_mm,Xr_fe_mm,KT_implied_MPa_per_mm,strip_theory,diff_fraction,diff_contact_face_fraction,\
diff_mid_thickness_fraction";

/// `compare lap` (issue 24) of CalculiX results: pinned when it was first published.
/// Issue 33: the FE response against the continuum at the deck's parameters, all rows together
/// (`compare plate`, `compare lap`).
const COMPARE_CONTINUUM: &[&str] = &[
    "continuum: object",
    "continuum.KT_deck_MPa_per_mm: number",
    "continuum.KT_implied_MPa_per_mm: number",
    "continuum.KT_implied_high_MPa_per_mm: number",
    "continuum.KT_implied_low_MPa_per_mm: number",
    "continuum.agrees: bool",
    "continuum.resolution_fraction: number",
    "continuum.text: string",
    "continuum.tolerance_fraction: number",
    "rows[].continuum: object",
    "rows[].continuum.agrees: bool",
    "rows[].continuum.diff_fraction: number",
    "rows[].continuum.resolution_fraction: number",
    "rows[].continuum.response_mm: number",
    "rows[].continuum.sensitivity: number",
    "rows[].continuum.solved: bool",
    "rows[].continuum.text: string",
    "rows[].continuum.tolerance_fraction: number",
    "rows[].continuum.allowance_fraction: number",
];

/// Each row's implied K_T through the continuum: a number where one is implied.
const COMPARE_CONTINUUM_IMPLIED: &[&str] = &[
    "rows[].continuum.KT_implied_MPa_per_mm: number",
    "rows[].continuum.KT_implied_diff_fraction: number",
    "rows[].continuum.KT_implied_high_MPa_per_mm: number",
    "rows[].continuum.KT_implied_low_MPa_per_mm: number",
];

/// ... or null where a row's value no K_T gives (the CSV's made-up points).
const COMPARE_CONTINUUM_IMPLIED_OR_NOT: &[&str] = &[
    "rows[].continuum.KT_implied_MPa_per_mm: null|number",
    "rows[].continuum.KT_implied_diff_fraction: null|number",
    "rows[].continuum.KT_implied_high_MPa_per_mm: null|number",
    "rows[].continuum.KT_implied_low_MPa_per_mm: null|number",
];

/// `compare beam` against the beams' continuum (issue 33): the summary, as the plate's and lap's.
const COMPARE_BEAM_CONTINUUM: &[&str] = &[
    "continuum: object",
    "continuum.KT_deck_MPa_per_mm: number",
    "continuum.KT_implied_MPa_per_mm: number",
    "continuum.KT_implied_high_MPa_per_mm: number",
    "continuum.KT_implied_low_MPa_per_mm: number",
    "continuum.agrees: bool",
    "continuum.resolution_fraction: number",
    "continuum.text: string",
    "continuum.tolerance_fraction: number",
    "rows[].continuum: object",
    "rows[].continuum.agrees: bool",
    "rows[].continuum.response_mm: number",
    "rows[].continuum.solved: bool",
    "rows[].continuum.text: string",
    "rows[].continuum.tolerance_fraction: number",
    "rows[].continuum.allowance_fraction: number",
];

/// ... each row's numbers where every row implies a K_T (`compare-beam-two`, the CSV; a row at
/// F = 0 has no `continuum`: the continuum's w(L) is 0, a relative difference undefined).
const COMPARE_BEAM_CONTINUUM_EVERY_ROW: &[&str] = &[
    "rows[].continuum.diff_fraction: number",
    "rows[].continuum.resolution_fraction: number",
    "rows[].continuum.sensitivity: number",
];

/// ... or null where beyond the macroslip a row's w(L) barely moves with K_T (no resolution, no
/// K_T implied: the paper's deck above F_1).
const COMPARE_BEAM_CONTINUUM_SOME_ROWS: &[&str] = &[
    "rows[].continuum.diff_fraction: number",
    "rows[].continuum.resolution_fraction: null|number",
    "rows[].continuum.sensitivity: number",
];

const COMPARE_LAP: &[&str] = &[
    "model: string",
    "results: string",
    "rows: array",
    "rows[]: object",
    "rows[].F_N: number",
    "rows[].Delta_fe_mm: number",
    "rows[].Delta_mm: number",
    "rows[].diff: number",
    "rows[].diff_fraction: number",
    "rows[].shear_lag_within: number",
    "rows[].shear_lag_within_fraction: number",
    "rows[].Delta_coulomb_mm: number",
    "rows[].regime: string",
    "rows[].regime_fe: string",
    "rows[].a_mm: number",
    "rows[].a_fe_mm: number",
    "rows[].d_mm: number",
    "rows[].d_fe_mm: number",
    "rows[].KT_implied_MPa_per_mm: null",
    "rows[].shear_lag: string",
    "rows[].verdict.envelope_bound: number",
    "rows[].verdict.envelope_bound_fraction: number",
    "rows[].verdict.a_elements: number",
    "rows[].verdict.d_elements: number",
];

const COMPARE_LAP_HEADER: &str = "F_N,Delta_fe_mm,Delta_mm,diff,shear_lag_within,\
Delta_coulomb_mm,regime,regime_fe,a_mm,a_fe_mm,d_mm,d_fe_mm,KT_implied_MPa_per_mm,shear_lag,\
diff_fraction,shear_lag_within_fraction";

/// The lap joint's report (issue 24): pinned when it was first published.
const LAP: &[&str] = &[
    "F_1_N: number",
    "F_2_N: number",
    "F_gross_N: number",
    "coulomb: object",
    "coulomb.Delta_mm: number",
    "coulomb.a_mm: number",
    // Issue 36: D and zeta of a cycle between +F and -F, as the TUI shows them.
    "coulomb.D_Nmm: number",
    "coulomb.d_mm: number",
    "coulomb.regime: string",
    "coulomb.zeta: number",
    "covers_stiffness_N_per_mm: number",
    "decay_length_mm: number",
    "first_slip_at: string",
    "inner_stiffness_N_per_mm: number",
    "inputs: object",
    "inputs.E1_MPa: number",
    "inputs.E2_MPa: number",
    "inputs.F_N: number",
    "inputs.KT_MPa_per_mm: number",
    "inputs.L_mm: number",
    "inputs.P_MPa: number",
    "inputs.b_mm: number",
    "inputs.mu: number",
    "inputs.t1_mm: number",
    "inputs.t2_mm: number",
    "model: string",
    "preset: string",
    "regularized: object",
    "regularized.Delta_mm: number",
    "regularized.a_mm: number",
    "regularized.D_Nmm: number",
    "regularized.d_mm: number",
    "regularized.regime: string",
    "regularized.zeta: number",
    "saturation_slip_mm: number",
    "shear_lag: object",
    "shear_lag.decay_length_over_thickness: number",
    "shear_lag.note: string",
    "shear_lag.validity: string",
    // The envelope (L14) and, where the theory is not expected within 2 %, the continuum.
    "shear_lag.clamping_prestress: number",
    "shear_lag.cover_bending: number",
    "shear_lag.expected_error: number",
    // Issue 36: the bound under its one name in every output (sweep lap, compare lap).
    "shear_lag.shear_lag_within_fraction: number",
    "shear_lag.outside_calibration: null",
    // Issue 33: every calibrated range the joint leaves (empty here).
    "shear_lag.outside_calibration_all: array",
    "shear_lag.shear_compliance: number",
    "continuum: object",
    "continuum.Delta_mm: number",
    "continuum.a_mm: number",
    "continuum.contact_pressure_max_MPa: number",
    "continuum.contact_pressure_min_MPa: number",
    "continuum.d_mm: number",
    "continuum.diff_vs_shear_lag: number",
    "continuum.diff_vs_shear_lag_fraction: number",
    "continuum.separated_pairs: number",
];

/// The lap joint's cycle report (issue 24).
const LAP_CYCLE: &[&str] = &[
    "Fa_N: number",
    "coulomb: object",
    "coulomb.D_Nmm: number",
    "coulomb.Delta_peak_mm: number",
    "coulomb.U_Nmm: number",
    "coulomb.onset_N: number",
    "coulomb.secant_stiffness_N_per_mm: number",
    "coulomb.zeta: number",
    "inputs: object",
    "inputs.E1_MPa: number",
    "inputs.E2_MPa: number",
    "inputs.F_N: number",
    "inputs.KT_MPa_per_mm: number",
    "inputs.L_mm: number",
    "inputs.P_MPa: number",
    "inputs.b_mm: number",
    "inputs.mu: number",
    "inputs.t1_mm: number",
    "inputs.t2_mm: number",
    "model: string",
    "note: string",
    "preset: string",
    "regularized: object",
    "regularized.D_Nmm: number",
    "regularized.Delta_peak_mm: number",
    "regularized.U_Nmm: number",
    "regularized.onset_N: number",
    "regularized.secant_stiffness_N_per_mm: number",
    "regularized.zeta: number",
];

const CASES: &[Case] = &[
    Case {
        name: "beam-F120",
        args: &["beam", "--set", "F=120"],
        formats: TEXT_JSON,
        keys: &[BEAM],
        header: None,
    },
    Case {
        name: "beam-timoshenko",
        args: &["beam", "--beam-theory", "timoshenko"],
        formats: TEXT_JSON,
        keys: &[BEAM],
        header: None,
    },
    Case {
        name: "plate-KT1e4",
        args: &["plate", "--set", "KT=1e4"],
        formats: TEXT_JSON,
        keys: &[PLATE, PLATE_ONSET, PLATE_EXPECTED],
        header: None,
    },
    Case {
        name: "plate-KT1e4-continuum",
        args: &["plate", "--set", "KT=1e4", "--continuum"],
        formats: TEXT_JSON,
        keys: &[PLATE, PLATE_ONSET, PLATE_EXPECTED, PLATE_CONTINUUM],
        header: None,
    },
    // The paper's plate: the strip theory is measured wrong there (V1c), so the continuum is
    // solved.
    Case {
        name: "plate-paper",
        args: &["plate"],
        formats: TEXT_JSON,
        keys: &[PLATE, PLATE_ONSET, PLATE_WRONG, PLATE_CONTINUUM],
        header: None,
    },
    Case {
        name: "plate-nu0",
        args: &["plate", "--set", "nu=0"],
        formats: TEXT_JSON,
        keys: &[PLATE, PLATE_EXPECTED],
        header: None,
    },
    Case {
        name: "cycle",
        args: &["cycle", "--amplitude", "150"],
        formats: TEXT_JSON,
        keys: &[CYCLE],
        header: None,
    },
    Case {
        name: "lap",
        args: &["lap"],
        formats: TEXT_JSON,
        keys: &[LAP],
        header: None,
    },
    Case {
        name: "lap-cycle",
        args: &["cycle", "--preset", "lap-aluminium", "--amplitude", "4000"],
        formats: TEXT_JSON,
        keys: &[LAP_CYCLE],
        header: None,
    },
    Case {
        name: "kt-beam",
        args: &["kt"],
        formats: TEXT_JSON,
        keys: &[KT, KT_BEAM],
        header: None,
    },
    Case {
        name: "kt-beam-kn",
        args: &["kt", "--element-size", "1", "--kn", "1000"],
        formats: TEXT_JSON,
        keys: &[KT, KT_BEAM],
        header: None,
    },
    Case {
        name: "kt-beam-refused",
        args: &["kt", "--kn", "1e-6"],
        formats: TEXT_JSON,
        keys: &[KT, KT_BEAM, KT_REFUSED],
        header: None,
    },
    Case {
        name: "kt-plate",
        args: &["kt", "--preset", "paper-plate", "--kn", "1e6"],
        formats: TEXT_JSON,
        keys: &[KT, KT_PLATE],
        header: None,
    },
    Case {
        name: "kt-tolerance-beam",
        args: &["kt", "--tolerance", "1%", "--from", "0", "--to", "300"],
        formats: TEXT_JSON,
        keys: &[
            TOLERANCE,
            TOLERANCE_OF_COULOMB,
            TOLERANCE_FOUND,
            TOLERANCE_BEAM,
        ],
        header: None,
    },
    Case {
        name: "kt-tolerance-everywhere",
        args: &["kt", "--tolerance", "1000%"],
        formats: TEXT_JSON,
        keys: &[
            TOLERANCE,
            TOLERANCE_OF_COULOMB,
            TOLERANCE_FOUND,
            TOLERANCE_BEAM,
        ],
        header: None,
    },
    Case {
        name: "kt-tolerance-plate",
        args: &["kt", "--tolerance", "1%", "--preset", "paper-plate"],
        formats: TEXT_JSON,
        keys: &[
            TOLERANCE,
            TOLERANCE_OF_COULOMB,
            TOLERANCE_FOUND,
            TOLERANCE_PLATE,
        ],
        header: None,
    },
    // The other reading: within 5 % of the current K_T's answer, an interval.
    Case {
        name: "kt-tolerance-current",
        args: &[
            "kt",
            "--tolerance",
            "5%",
            "--of",
            "current",
            "--preset",
            "paper-plate",
        ],
        formats: TEXT_JSON,
        keys: &[
            TOLERANCE,
            TOLERANCE_OF_CURRENT,
            TOLERANCE_FOUND,
            TOLERANCE_PLATE,
        ],
        header: None,
    },
    // No accepted K_T is within: KT_min is null.
    Case {
        name: "kt-tolerance-nowhere",
        args: &["kt", "--tolerance", "1e-7", "--preset", "paper-plate"],
        formats: TEXT_JSON,
        keys: &[
            TOLERANCE,
            TOLERANCE_OF_COULOMB,
            TOLERANCE_NOWHERE,
            TOLERANCE_PLATE,
        ],
        header: None,
    },
    // Captured with equal weights, the default before issue 25 (5): `--weights absolute` keeps
    // their numbers.
    Case {
        name: "fit",
        args: &[
            "fit",
            "beam",
            "tests/data/reports/inputs/fit-beam.csv",
            "--weights",
            "absolute",
        ],
        formats: TEXT_JSON,
        keys: &[FIT, FIT_ERRORS, FIT_WEIGHTS, FIT_SCATTER_MM],
        header: None,
    },
    Case {
        name: "fit-fixed",
        args: &[
            "fit",
            "beam",
            "tests/data/reports/inputs/fit-beam.csv",
            "--fix",
            "KT=200",
            "--weights",
            "absolute",
        ],
        formats: TEXT_JSON,
        keys: &[FIT, FIT_FIXED, FIT_WEIGHTS, FIT_SCATTER_MM],
        header: None,
    },
    // The default weights (relative), issue 25 (5).
    Case {
        name: "fit-relative",
        args: &["fit", "beam", "tests/data/reports/inputs/fit-beam.csv"],
        formats: TEXT_JSON,
        keys: &[FIT, FIT_ERRORS, FIT_WEIGHTS, FIT_SCATTER_FRACTION],
        header: None,
    },
    // The cylinder's bundled curve (issue 34, item 4), default weights.
    Case {
        name: "fit-cylinder",
        args: &[
            "fit",
            "cylinder",
            "tests/data/reports/inputs/fit-cylinder.csv",
        ],
        formats: TEXT_JSON,
        keys: &[FIT_CYLINDER, FIT_ERRORS, FIT_WEIGHTS, FIT_SCATTER_FRACTION],
        header: None,
    },
    Case {
        name: "solve-beam",
        args: &["solve", "beam", "--vary", "KT", "--target", "ratio=1.01"],
        formats: TEXT_JSON,
        keys: &[SOLVE],
        header: None,
    },
    Case {
        name: "solve-beam-plateau",
        args: &["solve", "beam", "--vary", "F", "--target", "X=200"],
        formats: TEXT_JSON,
        keys: &[SOLVE],
        header: None,
    },
    Case {
        name: "solve-beam-limit",
        args: &[
            "solve",
            "beam",
            "--vary",
            "KT",
            "--target",
            "ratio=1.0000000000001",
        ],
        formats: TEXT_JSON,
        keys: &[SOLVE],
        header: None,
    },
    Case {
        name: "solve-plate",
        args: &["solve", "plate", "--vary", "KT", "--target", "ratio=1.01"],
        formats: TEXT_JSON,
        keys: &[SOLVE],
        header: None,
    },
    Case {
        name: "compare-beam-calculix",
        args: &["compare", "beam", "tests/data/calculix/paper-beams.dat"],
        formats: ALL,
        keys: &[
            COMPARE_BEAM,
            COMPARE_BEAM_FE,
            COMPARE_BEAM_IMPLIED,
            COMPARE_VERDICT,
            COMPARE_BEAM_IMPLIED_ERROR,
            COMPARE_BEAM_VERDICT_FE,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_READ,
            COMPARE_BEAM_CONTINUUM,
            COMPARE_BEAM_CONTINUUM_SOME_ROWS,
            COMPARE_CONTINUUM_IMPLIED_OR_NOT,
        ],
        header: Some(COMPARE_BEAM_HEADER),
    },
    // A CSV from another code, with F = 0: no FE slip profile, undefined differences, and two
    // loaded points for two parameters: a K_T implied, its uncertainty unknown.
    Case {
        name: "compare-beam-csv",
        args: &[
            "compare",
            "beam",
            "tests/data/reports/inputs/compare-beam.csv",
        ],
        formats: ALL,
        keys: &[
            COMPARE_BEAM,
            COMPARE_BEAM_CSV,
            COMPARE_BEAM_IMPLIED,
            COMPARE_VERDICT,
            COMPARE_BEAM_IMPLIED_UNKNOWN_ERROR,
            COMPARE_BEAM_VERDICT_CSV,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_GIVEN,
            COMPARE_BEAM_CONTINUUM,
            COMPARE_BEAM_CONTINUUM_EVERY_ROW,
            COMPARE_CONTINUUM_IMPLIED,
        ],
        header: Some(COMPARE_BEAM_HEADER),
    },
    Case {
        name: "compare-beam-two",
        args: &[
            "compare",
            "beam",
            "tests/data/reports/inputs/compare-beam-two.csv",
            "--set",
            "KT=120",
        ],
        formats: ALL,
        keys: &[
            COMPARE_BEAM,
            COMPARE_BEAM_TWO,
            COMPARE_VERDICT,
            COMPARE_BEAM_VERDICT_TWO,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_GIVEN,
            COMPARE_BEAM_CONTINUUM,
            COMPARE_BEAM_CONTINUUM_EVERY_ROW,
            COMPARE_CONTINUUM_IMPLIED,
        ],
        header: Some(COMPARE_BEAM_HEADER),
    },
    Case {
        name: "compare-plate-calculix",
        args: &[
            "compare",
            "plate",
            "tests/data/calculix/plate-kt1e4.dat",
            "tests/data/calculix/paper-plate.dat",
        ],
        formats: ALL,
        keys: &[
            COMPARE_PLATE,
            COMPARE_PLATE_FE,
            COMPARE_VERDICT,
            COMPARE_PLATE_VERDICT,
            COMPARE_PLATE_VERDICT_FE,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_READ,
            COMPARE_CONTINUUM,
            COMPARE_CONTINUUM_IMPLIED,
        ],
        header: Some(COMPARE_PLATE_HEADER),
    },
    Case {
        name: "compare-lap-calculix",
        args: &["compare", "lap", "tests/data/calculix/lap-aluminium.dat"],
        formats: ALL,
        keys: &[
            COMPARE_LAP,
            COMPARE_VERDICT,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_READ,
            COMPARE_CONTINUUM,
            COMPARE_CONTINUUM_IMPLIED,
        ],
        header: Some(COMPARE_LAP_HEADER),
    },
    Case {
        name: "compare-plate-csv",
        args: &[
            "compare",
            "plate",
            "tests/data/reports/inputs/compare-plate.csv",
        ],
        formats: ALL,
        keys: &[
            COMPARE_PLATE,
            COMPARE_PLATE_CSV,
            COMPARE_VERDICT,
            COMPARE_PLATE_VERDICT,
            COMPARE_PLATE_VERDICT_CSV,
            COMPARE_CONTACT,
            COMPARE_CONTACT_NOT_GIVEN,
            COMPARE_CONTINUUM,
            COMPARE_CONTINUUM_IMPLIED_OR_NOT,
        ],
        header: Some(COMPARE_PLATE_HEADER),
    },
];

/// Issue 33: the stick slope the FE code used and the run's kinematics, beside every comparison's
/// own keys (here without an interface output: no .frd beside the fixtures' .dat, no --interface).
const COMPARE_CONTACT: &[&str] = &[
    "kinematics.envelope_applies: bool",
    "kinematics.envelope_calibrated_on: string",
    "kinematics.envelopes_calibrated_on: array",
    "kinematics.envelopes_calibrated_on[]: string",
    "kinematics.kinematics: string",
    "kinematics.text: string",
    "kinematics: object",
    "stick_slope.runs: array",
    "stick_slope.runs[].KT_deck_MPa_per_mm: number",
    "stick_slope.runs[].KT_friction_card_MPa_per_mm: null",
    "stick_slope.runs[].KT_used_MPa_per_mm: null",
    "stick_slope.runs[].contact_locked: null",
    "stick_slope.runs[].diff_fraction: null",
    "stick_slope.runs[].peak_pressure_MPa: null",
    "stick_slope.runs[].results: string",
    "stick_slope.runs[].spread_fraction: null",
    "stick_slope.runs[].step: null",
    "stick_slope.runs[].steps: array",
    "stick_slope.runs[].sticking_nodes: null",
    "stick_slope.runs[].text: string",
    "stick_slope.runs[].verdict: string",
    "stick_slope.runs[]: object",
    "stick_slope.tolerance_fraction: number",
    "stick_slope.verdict: string",
    "stick_slope: object",
];

/// Why the stick slope was not read (a .dat without its .frd).
const COMPARE_CONTACT_NOT_READ: &[&str] = &["stick_slope.runs[].reason: string"];

/// A CSV without --interface: nothing to read, no reason.
const COMPARE_CONTACT_NOT_GIVEN: &[&str] = &["stick_slope.runs[].reason: null"];

/// Every key path of `value` with its JSON type, `a.b: number`; an array's elements are merged
/// under `a[]`, so the set says what each element may hold, and a key whose type varies between
/// elements shows the types joined, `null|number`.
fn key_paths(value: &Value) -> BTreeSet<String> {
    let mut types = std::collections::BTreeMap::<String, BTreeSet<&'static str>>::new();
    fn walk(
        value: &Value,
        path: String,
        types: &mut std::collections::BTreeMap<String, BTreeSet<&'static str>>,
    ) {
        let kind = match value {
            Value::Null => "null",
            Value::Bool(_) => "bool",
            Value::Number(_) => "number",
            Value::String(_) => "string",
            Value::Array(_) => "array",
            Value::Object(_) => "object",
        };
        if !path.is_empty() {
            types.entry(path.clone()).or_default().insert(kind);
        }
        match value {
            Value::Object(map) => {
                for (key, item) in map {
                    let child = if path.is_empty() {
                        key.clone()
                    } else {
                        format!("{path}.{key}")
                    };
                    walk(item, child, types);
                }
            }
            Value::Array(items) => {
                for item in items {
                    walk(item, format!("{path}[]"), types);
                }
            }
            _ => {}
        }
    }
    walk(value, String::new(), &mut types);
    types
        .into_iter()
        .map(|(path, kinds)| format!("{path}: {}", Vec::from_iter(kinds).join("|")))
        .collect()
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The output of `args` in `format`, run from the crate's root (the fixtures' paths are relative,
/// so they read the same in every output).
fn output(args: &[&str], format: Format) -> Vec<u8> {
    let mut cmd = Command::cargo_bin("microslip").expect("binary built by cargo");
    cmd.current_dir(root())
        .env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
        .env_remove("HOME")
        .args(args);
    if !matches!(format, Format::Text) {
        cmd.args(["--format", format.flag()]);
    }
    let output = cmd.output().unwrap();
    // `compare` exits 1 on a verdict that does not agree (or cannot judge), its report printed
    // all the same; every other command, and any other code, is a failure here.
    let verdict = args.first() == Some(&"compare") && output.status.code() == Some(1);
    assert!(
        output.status.success() || verdict,
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output.stdout
}

fn captured(case: &Case, format: Format) -> PathBuf {
    root()
        .join("tests/data/reports")
        .join(format!("{}.{}", case.name, format.extension()))
}

#[test]
fn json_keys_are_the_pinned_ones() {
    let mut failures = Vec::new();
    for case in CASES {
        let json: Value = serde_json::from_slice(&output(case.args, Format::Json)).unwrap();
        let got = key_paths(&json);
        let pinned: BTreeSet<String> = case
            .keys
            .iter()
            .flat_map(|block| block.iter().map(|k| k.to_string()))
            .collect();
        if got != pinned {
            failures.push(format!(
                "{} ({:?}):\n  missing: {:?}\n  extra: {:?}",
                case.name,
                case.args,
                pinned.difference(&got).collect::<Vec<_>>(),
                got.difference(&pinned).collect::<Vec<_>>()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn csv_headers_are_the_pinned_ones() {
    for case in CASES {
        let Some(header) = case.header else { continue };
        let csv = String::from_utf8(output(case.args, Format::Csv)).unwrap();
        assert_eq!(csv.lines().next(), Some(header), "{}", case.name);
    }
}

#[test]
#[ignore = "byte-exact numbers may differ in the last digit on another platform's libm"]
fn outputs_match_the_captured_files() {
    let capture = std::env::var_os("MICROSLIP_CAPTURE").is_some();
    let mut differ = Vec::new();
    for case in CASES {
        for &format in case.formats {
            let (path, got) = (captured(case, format), output(case.args, format));
            if capture {
                std::fs::write(&path, &got).unwrap();
            } else if std::fs::read(&path).unwrap() != got {
                differ.push(path.display().to_string());
            }
        }
    }
    assert!(differ.is_empty(), "differ from the capture: {differ:?}");
}
