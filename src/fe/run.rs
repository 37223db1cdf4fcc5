//! Running CalculiX on a deck: the one external program the project drives. `microslip bench`
//! writes a deck into a work folder, runs `ccx -i JOB` there with its output kept in `JOB.log`,
//! reports progress from that log while it runs, and hands back the `.dat` for the comparison.
//!
//! Why a folder of its own: ccx writes a dozen files named after the job (`.dat`, `.frd`, `.sta`,
//! `.cvg`, `spooles.out`...). A fresh folder (or one the user names, refused if it already holds
//! the job's files) means no run ever clobbers a user's file, and the log stays for reading when
//! ccx fails.

use std::fs::{self, File, OpenOptions};
use std::io::{self, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The files of one run, all in its work folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunFiles {
    /// The folder.
    pub folder: PathBuf,
    /// The deck, `JOB.inp`.
    pub deck: PathBuf,
    /// ccx's results, `JOB.dat`.
    pub results: PathBuf,
    /// ccx's standard output and error, `JOB.log`.
    pub log: PathBuf,
}

impl RunFiles {
    /// The files of job `job` in `folder`.
    pub fn new(folder: &Path, job: &str) -> RunFiles {
        RunFiles {
            folder: folder.to_path_buf(),
            deck: folder.join(format!("{job}.inp")),
            results: folder.join(format!("{job}.dat")),
            log: folder.join(format!("{job}.log")),
        }
    }
}

/// Why a run gave no results.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The program is not on the PATH (or not where `--ccx` says).
    #[error(
        "CalculiX's solver `{program}` was not found: install it (Debian, Ubuntu: `apt-get install calculix-ccx`) or name it with --ccx PATH; without it, run `microslip deck ccx ... -o JOB.inp`, `ccx -i JOB` and `microslip compare ... JOB.dat` by hand"
    )]
    Missing {
        /// The program as given.
        program: String,
    },
    /// The work folder already holds this job's files.
    #[error("{path} exists: the run would replace it; name an empty or new folder with --workdir")]
    Occupied {
        /// The file found.
        path: String,
    },
    /// ccx ended with an error, or without writing results.
    #[error("ccx failed ({status}); the last lines of its log, {log}:\n{tail}")]
    Failed {
        /// How it ended.
        status: String,
        /// The log's path.
        log: String,
        /// The log's last lines.
        tail: String,
    },
    /// The folder, the log or the process could not be set up.
    #[error("{0}")]
    Io(#[from] io::Error),
}

/// What the progress callback is told while ccx runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Progress {
    /// Time since ccx started.
    pub elapsed: Duration,
    /// The deck's load steps (`*STEP` cards).
    pub steps: usize,
    /// The total (pseudo-)time ccx last reported as converged: every step of microslip's decks
    /// lasts 1, so this counts the load steps done, fractions included.
    pub total_time: Option<f64>,
}

/// A fresh work folder for job `job` under `parent`: `microslip-ccx-JOB-N`, the first N that
/// does not exist yet (created, never reused).
pub fn fresh_folder(parent: &Path, job: &str) -> io::Result<PathBuf> {
    for n in 1..10_000 {
        let folder = parent.join(format!("microslip-ccx-{job}-{n}"));
        match fs::create_dir(&folder) {
            Ok(()) => return Ok(folder),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(io::Error::other(format!(
        "no free name microslip-ccx-{job}-N in {}",
        parent.display()
    )))
}

/// Makes `folder` (and its parents) if missing, and refuses it when it holds a file of `job`
/// already (the deck, the results or the log).
pub fn claim_folder(folder: &Path, job: &str) -> Result<RunFiles, RunError> {
    fs::create_dir_all(folder)?;
    let files = RunFiles::new(folder, job);
    for path in [&files.deck, &files.results, &files.log] {
        if fs::symlink_metadata(path).is_ok() {
            return Err(RunError::Occupied {
                path: path.display().to_string(),
            });
        }
    }
    Ok(files)
}

/// Runs `program -i JOB` in the work folder of `files` (whose deck must be written), with its
/// output in the log, calling `progress` about every `every` while it runs.
///
/// # Errors
/// [`RunError::Missing`] when the program cannot be found, [`RunError::Failed`] (with the log's
/// tail) when it exits with an error or writes no results.
pub fn run_ccx(
    program: &str,
    files: &RunFiles,
    every: Duration,
    progress: &mut dyn FnMut(&Progress),
) -> Result<(), RunError> {
    let job = files
        .deck
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or_else(|| io::Error::other("the deck has no job name"))?;
    let log = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&files.log)?;
    let mut child = match Command::new(program)
        .args(["-i", job])
        .current_dir(&files.folder)
        .stdin(Stdio::null())
        .stdout(log.try_clone()?)
        .stderr(log)
        .spawn()
    {
        Ok(child) => child,
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(RunError::Missing {
                program: program.to_string(),
            });
        }
        Err(e) => return Err(e.into()),
    };
    let started = Instant::now();
    let steps = fs::read_to_string(&files.deck)?
        .lines()
        .filter(|l| l.trim_start().to_ascii_uppercase().starts_with("*STEP"))
        .count();
    let mut reader = LogReader::open(&files.log)?;
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break status;
        }
        std::thread::sleep(every);
        reader.read_new()?;
        progress(&Progress {
            elapsed: started.elapsed(),
            steps,
            total_time: reader.total_time,
        });
    };
    let has_results = fs::metadata(&files.results).is_ok_and(|m| m.len() > 0);
    // ccx 2.20 exits 0 after some errors ("*ERROR ..." in its output): the log decides too.
    let log_text = fs::read_to_string(&files.log).unwrap_or_default();
    let reported_error = log_text
        .lines()
        .any(|l| l.trim_start().starts_with("*ERROR"));
    if status.success() && has_results && !reported_error {
        Ok(())
    } else {
        Err(RunError::Failed {
            status: if status.success() {
                "exit 0, but no results or an *ERROR in its log".to_string()
            } else {
                status.to_string()
            },
            log: files.log.display().to_string(),
            tail: tail(&log_text, 12),
        })
    }
}

/// The last `lines` lines of `text`.
fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}

/// Follows a growing log, remembering the total time ccx last printed. (Its `STEP n` lines come
/// from a part of ccx whose output is buffered apart and reach a log file only at the end.)
struct LogReader {
    file: File,
    pending: String,
    total_time: Option<f64>,
}

impl LogReader {
    fn open(path: &Path) -> io::Result<LogReader> {
        Ok(LogReader {
            file: File::open(path)?,
            pending: String::new(),
            total_time: None,
        })
    }

    /// Reads what was appended since the last call and updates the total time.
    fn read_new(&mut self) -> io::Result<()> {
        let mut bytes = Vec::new();
        self.file.read_to_end(&mut bytes)?;
        self.pending.push_str(&String::from_utf8_lossy(&bytes));
        while let Some(end) = self.pending.find('\n') {
            let line: String = self.pending.drain(..=end).collect();
            self.read_line(&line);
        }
        Ok(())
    }

    /// ccx 2.20 prints ` actual total time=2.5e+00` at each increment it starts.
    fn read_line(&mut self, line: &str) {
        let time = line.trim().strip_prefix("actual total time=");
        if let Some(time) = time.and_then(|t| t.trim().parse::<f64>().ok()) {
            self.total_time = Some(time);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_log_reader_follows_the_total_time_as_ccx_prints_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("job.log");
        // As ccx 2.20 writes it (from a real log).
        fs::write(
            &path,
            " increment 1 attempt 1 \n actual step time=1.000000e+00\n actual total time=1.000000e+00\n",
        )
        .unwrap();
        let mut reader = LogReader::open(&path).unwrap();
        reader.read_new().unwrap();
        assert_eq!(reader.total_time, Some(1.0));
        // A line arrives in two pieces: nothing is read from the half line.
        let mut file = OpenOptions::new().append(true).open(&path).unwrap();
        io::Write::write_all(&mut file, b" actual total time=2.5").unwrap();
        reader.read_new().unwrap();
        assert_eq!(reader.total_time, Some(1.0));
        io::Write::write_all(&mut file, b"05802e+00\n").unwrap();
        reader.read_new().unwrap();
        assert_eq!(reader.total_time, Some(2.505802));
    }

    #[test]
    fn a_missing_program_is_named_with_how_to_get_it() {
        let dir = tempfile::tempdir().unwrap();
        let files = claim_folder(dir.path(), "beam").unwrap();
        fs::write(&files.deck, "*HEADING\n").unwrap();
        let error = run_ccx(
            "microslip-no-such-ccx",
            &files,
            Duration::from_millis(10),
            &mut |_| {},
        )
        .unwrap_err();
        assert!(matches!(error, RunError::Missing { .. }), "{error}");
        assert!(error.to_string().contains("apt-get install calculix-ccx"));
    }

    #[test]
    fn a_failing_program_gives_the_tail_of_its_log() {
        let dir = tempfile::tempdir().unwrap();
        let files = claim_folder(dir.path(), "beam").unwrap();
        fs::write(&files.deck, "*HEADING\n").unwrap();
        // `false` stands for a ccx that fails: it exits 1 and writes no results.
        let error = run_ccx("false", &files, Duration::from_millis(10), &mut |_| {}).unwrap_err();
        assert!(matches!(error, RunError::Failed { .. }), "{error}");
        assert!(error.to_string().contains("beam.log"), "{error}");
    }

    #[test]
    fn a_folder_holding_the_jobs_files_is_refused_and_fresh_folders_never_repeat() {
        let dir = tempfile::tempdir().unwrap();
        let files = claim_folder(dir.path(), "beam").unwrap();
        fs::write(&files.results, "old results").unwrap();
        let error = claim_folder(dir.path(), "beam").unwrap_err();
        assert!(matches!(error, RunError::Occupied { .. }), "{error}");
        assert_eq!(fs::read_to_string(&files.results).unwrap(), "old results");
        let first = fresh_folder(dir.path(), "beam").unwrap();
        let second = fresh_folder(dir.path(), "beam").unwrap();
        assert_ne!(first, second);
        assert!(first.is_dir() && second.is_dir());
    }
}
