//! The Slurm executor: the runs as one job array (`sbatch --array=0-N%J`, at most J tasks at
//! once), followed with `squeue` until the array has left the queue, each task writing its run's
//! result file as the local pool does (`microslip suite --run-one FOLDER`). A task that left no
//! result file failed: its case says which run and where its output is.
//!
//! Why the tasks run microslip itself and not ccx alone: the result file is written only once
//! the run's output is judged, on the node that holds the output, so a lost node loses its run
//! only (a resumed suite runs it again) and the submitting process needs nothing but the result
//! files. Followed with `squeue` rather than `sacct`: a single-node Slurm without accounting
//! storage has no `sacct` (`shared/notes/slurm-single-node.md`).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use super::pool::{self, Prepared};

/// The folder of the array's script, task list and task outputs: `<workdir>/slurm`.
pub fn folder(workdir: &Path) -> PathBuf {
    workdir.join("slurm")
}

/// Why the array could not be submitted or followed.
#[derive(Debug, thiserror::Error)]
pub enum SlurmError {
    /// A Slurm command could not be run or refused.
    #[error("{command}: {reason}")]
    Command {
        /// The command.
        command: String,
        /// What it said.
        reason: String,
    },
    /// A file of the array could not be written.
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

fn run(command: &mut Command) -> Result<String, SlurmError> {
    let shown = format!("{command:?}").replace('"', "");
    let output = command.output().map_err(|e| SlurmError::Command {
        command: shown.clone(),
        reason: format!("{e} (is Slurm installed and on the PATH?)"),
    })?;
    if !output.status.success() {
        return Err(SlurmError::Command {
            command: shown,
            reason: String::from_utf8_lossy(&output.stderr).trim().to_string(),
        });
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

/// Prepares every run's folder, writes the array's task list and script, and submits it with
/// at most `jobs` tasks at once; `microslip` is this program, `ccx` the solver each task runs.
/// Returns the array's job id.
///
/// # Errors
/// A folder that cannot be written, `sbatch` missing or refusing.
pub fn submit(
    runs: &[Prepared],
    jobs: usize,
    workdir: &Path,
    microslip: &Path,
    ccx: &Path,
) -> Result<String, SlurmError> {
    let dir = folder(workdir);
    std::fs::create_dir_all(&dir)?;
    let mut tasks = String::new();
    for run in runs {
        pool::prepare(run).map_err(|e| std::io::Error::other(e.to_string()))?;
        let folder = std::path::absolute(&run.folder)?;
        tasks.push_str(&folder.display().to_string());
        tasks.push('\n');
    }
    let list = std::path::absolute(dir.join("tasks.txt"))?;
    crate::file::write_atomic(&list, tasks.as_bytes(), true)?;
    let script = dir.join("array.sh");
    let quote = |p: &Path| format!("'{}'", p.display().to_string().replace('\'', "'\\''"));
    let body = format!(
        "#!/bin/sh\n# microslip suite: one run per array task (the folders in tasks.txt)\n\
         folder=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" {list})\n\
         exec {microslip} suite --run-one \"$folder\" --ccx {ccx}\n",
        list = quote(&list),
        microslip = quote(microslip),
        ccx = quote(ccx),
    );
    crate::file::write_atomic(&script, body.as_bytes(), true)?;
    let out = run(Command::new("sbatch")
        .arg("--parsable")
        .arg(format!(
            "--array=0-{}%{}",
            runs.len().saturating_sub(1),
            jobs.max(1)
        ))
        .arg("--job-name=microslip-suite")
        .arg("--ntasks=1")
        .arg("--cpus-per-task=1")
        .arg(format!(
            "--output={}",
            std::path::absolute(dir.join("task-%a.out"))?.display()
        ))
        .arg(&script))?;
    // `--parsable`: "JOBID" or "JOBID;CLUSTER".
    let id = out.trim().split(';').next().unwrap_or_default().to_string();
    if id.is_empty() || !id.chars().all(|c| c.is_ascii_digit()) {
        return Err(SlurmError::Command {
            command: "sbatch".to_string(),
            reason: format!("no job id in its answer '{}'", out.trim()),
        });
    }
    Ok(id)
}

/// Waits until the array `job` has left the queue, calling `progress` with the number of
/// tasks still queued or running each time it changes; on a stop (`stop` says a signal), the
/// array is cancelled (`scancel`) and the signal returned.
///
/// # Errors
/// `squeue` missing or failing.
pub fn wait(
    job: &str,
    stop: &dyn Fn() -> Option<i32>,
    progress: &mut dyn FnMut(usize),
) -> Result<Option<i32>, SlurmError> {
    let mut last = None;
    loop {
        if let Some(signal) = stop() {
            let _ = run(Command::new("scancel").arg(job));
            return Ok(Some(signal));
        }
        let out = run(Command::new("squeue").args(["-h", "-r", "-j", job, "-o", "%i %T"]));
        let left = match out {
            Ok(text) => text.lines().filter(|l| !l.trim().is_empty()).count(),
            // A job that has left the controller's memory is an invalid id: done.
            Err(SlurmError::Command { reason, .. }) if reason.contains("Invalid job id") => 0,
            Err(e) => return Err(e),
        };
        if last != Some(left) {
            progress(left);
            last = Some(left);
        }
        if left == 0 {
            return Ok(None);
        }
        std::thread::sleep(Duration::from_millis(500));
    }
}
