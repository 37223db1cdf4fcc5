//! One run's result: what its solver's output says against the closed form, judged by the
//! problem's own comparison (the one `compare` prints), kept as the quantities a ladder
//! extrapolates, the stick slope the solver used and the run's own verdict; written to
//! `result.json` in the run's folder atomically, once the run is complete. A run is done exactly
//! when that file exists and reads back ([`read`]).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::fe;
use crate::fe::ladder::LadderQuantity;
use crate::problems::ModelKind;
use crate::report::compare::CompareFace;
use crate::report::compare::run as compare_run;
use crate::report::face::{Faces, ForProblem, for_problem};

/// The result file's name in a run's folder.
pub const RESULT_FILE: &str = "result.json";

/// The stick slope a run's solver used, against its deck's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunStickSlope {
    /// `agrees`, `does not agree`, `not judged`, `not read`, `not given`.
    pub verdict: String,
    /// The slope used (MPa/mm), where read.
    #[serde(rename = "KT_used_MPa_per_mm")]
    pub used: Option<f64>,
    /// The deck's K_T (MPa/mm).
    #[serde(rename = "KT_deck_MPa_per_mm")]
    pub deck: f64,
    /// (used - deck) / deck.
    pub diff_fraction: Option<f64>,
}

/// A complete run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    /// The run's name (`fine-half-increment`).
    pub run: String,
    /// Its mesh (`coarse`, `fine`, `finest`).
    pub mesh: String,
    /// The increment given to its deck; `None`: the deck's own.
    pub increment: Option<f64>,
    /// Its judged differences from the closed form.
    pub quantities: Vec<LadderQuantity>,
    /// The stick slope its solver used.
    pub stick_slope: Option<RunStickSlope>,
    /// Whether the run alone agrees (the verdict `compare` gives it).
    pub agrees: bool,
    /// That verdict, short.
    pub verdict: String,
    /// Why the run is no judge when its contact locked
    /// ([`crate::fe::peak_pressure`]); `None` otherwise.
    #[serde(default)]
    pub contact_locked: Option<String>,
    /// The solver's wall time (s).
    pub solver_seconds: f64,
}

/// The path of a run's result file.
pub fn path(folder: &Path) -> PathBuf {
    folder.join(RESULT_FILE)
}

/// The result of the run in `folder`, when it is complete: its file exists and reads back.
pub fn read(folder: &Path) -> Option<RunResult> {
    let text = std::fs::read_to_string(path(folder)).ok()?;
    serde_json::from_str(&text).ok()
}

/// The result of the complete run in `folder` (its problem `kind`), judged again from its solver's
/// output by this program: the file keeps what the run did (its name, mesh, increment, solver
/// time), the judgement is today's. A suite resumed after the envelopes, a closed form or the
/// reading of the output changed (the cylinder's bounds were recalibrated in issue 45) must not
/// score its finished runs by the bounds they were first judged with. `None` when the run is not
/// complete, or its output is gone or no longer reads: the run is then run again.
pub fn read_rejudged(kind: ModelKind, folder: &Path) -> Option<RunResult> {
    let stored = read(folder)?;
    let judged = judge(kind, &folder.join(format!("{}.dat", super::JOB))).ok()?;
    Some(RunResult {
        quantities: judged.quantities,
        stick_slope: judged.stick_slope,
        agrees: judged.agrees,
        verdict: judged.verdict,
        contact_locked: judged.contact_locked,
        ..stored
    })
}

/// Writes `result` into `folder` atomically (a temporary file renamed over the name).
///
/// # Errors
/// The file system's.
pub fn write(folder: &Path, result: &RunResult) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(result).map_err(std::io::Error::other)?;
    crate::file::write_atomic(&path(folder), text.as_bytes(), true)
}

/// What a run's output says, judged as the problem of `kind` judges it: the `.dat` at `dat`
/// with its deck beside it.
///
/// # Errors
/// The results cannot be read or do not belong to a deck of `kind`.
pub fn judge(kind: ModelKind, dat: &Path) -> Result<Judged, String> {
    for_problem(kind, Judge { dat })
}

/// A run's judgement, before its name and time are added.
#[derive(Debug, Clone, PartialEq)]
pub struct Judged {
    /// [`RunResult::quantities`].
    pub quantities: Vec<LadderQuantity>,
    /// [`RunResult::stick_slope`].
    pub stick_slope: Option<RunStickSlope>,
    /// [`RunResult::agrees`].
    pub agrees: bool,
    /// [`RunResult::verdict`].
    pub verdict: String,
    /// [`RunResult::contact_locked`].
    pub contact_locked: Option<String>,
}

/// [`judge`]'s body, for [`for_problem`].
struct Judge<'a> {
    dat: &'a Path,
}

impl ForProblem for Judge<'_> {
    type Output = Result<Judged, String>;

    fn run<P: Faces>(self) -> Result<Judged, String> {
        let dat = self.dat;
        let load_error = |e: fe::load::LoadError| format!("{}: {}", e.path, e.reason);
        let loaded = fe::load::results::<P>(dat, None).map_err(load_error)?;
        let header = loaded
            .header
            .as_ref()
            .ok_or_else(|| format!("{}: no deck header", dat.display()))?;
        let model = header
            .model()
            .map_err(|e| e.to_string())?
            .of::<P>()
            .map_err(|other| format!("{}: a deck of the {other}", dat.display()))?;
        let mut compared = P::compare(&model, &loaded.points, loaded.interface_mesh.as_ref());
        let contact = fe::load::ccx_contact(dat, None, header).map_err(load_error)?;
        let run = compare_run::run_evidence(
            dat,
            Some(header),
            &P::interface(&model),
            contact.kinematics,
            Some(contact.stick_slope),
            contact.peak_pressure,
        );
        compare_run::judged_for::<P>(&run, &model, &mut compared);
        let checked = P::checked(compared).map_err(|e| e.to_string())?;
        let source = dat.display().to_string();
        let mut report =
            compare_run::ContactCompared::<P>::new(&source, (checked, Vec::new()), &[run]);
        let slope_run = report.stick_slope.runs.first();
        let contact_locked = slope_run.and_then(|r| r.contact_locked.clone());
        let stick_slope = slope_run.map(|r| RunStickSlope {
            verdict: r.verdict.to_string(),
            used: r.used,
            deck: r.deck,
            diff_fraction: r.diff_fraction,
        });
        let quantities = <P as CompareFace>::ladder_quantities(&report.report);
        let summary = P::summary_mut(&mut report.report);
        Ok(Judged {
            quantities,
            stick_slope,
            agrees: summary.agrees,
            verdict: summary.short.clone(),
            contact_locked,
        })
    }
}
