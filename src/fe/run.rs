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
use std::process::{Child, Command, Stdio};
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
    /// `--ccx` names a path that is not a program that can be run.
    #[error("--ccx {path}: {reason}")]
    NotAProgram {
        /// The path as given.
        path: String,
        /// What stands there instead ("a character device, not a program").
        reason: String,
    },
    /// The work folder already holds this job's files.
    #[error("{path} exists: the run would replace it; name an empty or new folder with --workdir")]
    Occupied {
        /// The file found.
        path: String,
    },
    /// The work folder cannot be used: something else stands at its path, or it cannot be made.
    #[error("--workdir {path}: {reason}")]
    Folder {
        /// The folder as given.
        path: String,
        /// What is wrong.
        reason: String,
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
    /// The run was stopped from outside (a signal to microslip); ccx and every process it
    /// started were ended with it.
    #[error(
        "stopped by signal {signal} while ccx ran; ccx was ended too, its files are kept in {folder}"
    )]
    Stopped {
        /// The signal's number.
        signal: i32,
        /// The work folder.
        folder: String,
    },
    /// The folder, the log or the process could not be set up.
    #[error("{0}")]
    Io(#[from] io::Error),
}

impl RunError {
    /// True when the solver itself could not be run or failed (not found, ended with an error,
    /// wrote no results), as opposed to a request refused before it started.
    pub fn is_solver_failure(&self) -> bool {
        matches!(self, RunError::Missing { .. } | RunError::Failed { .. })
    }
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
    /// Increments ccx has started so far (the previous ones are finished).
    pub increments: usize,
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
/// already (the deck, the results or the log), or when something other than a folder stands at
/// its path (a file, `/dev/null`): the message names the path and what is there.
pub fn claim_folder(folder: &Path, job: &str) -> Result<RunFiles, RunError> {
    let refused = |reason: String| RunError::Folder {
        path: folder.display().to_string(),
        reason,
    };
    match fs::metadata(folder) {
        Ok(m) if !m.is_dir() => {
            return Err(refused(format!(
                "{}, not a folder; name a new or empty folder",
                crate::file::kind_of(&m)
            )));
        }
        _ => {}
    }
    fs::create_dir_all(folder).map_err(|e| refused(format!("cannot make the folder: {e}")))?;
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

/// The program `--ccx` names, as it will be run. A bare name (`ccx`) is looked up on the PATH
/// when started; a path (`./fakeccx.sh`, `bin/ccx`) is taken from the current folder, since the
/// solver runs inside the work folder, where a relative path would name another file; and it
/// must be an executable regular file, refused otherwise with what stands there.
pub fn resolve_program(program: &str) -> Result<PathBuf, RunError> {
    if !program.contains('/') {
        return Ok(PathBuf::from(program));
    }
    let refused = |reason: String| RunError::NotAProgram {
        path: program.to_string(),
        reason,
    };
    let path = std::path::absolute(program).map_err(|e| refused(e.to_string()))?;
    let metadata = match fs::metadata(&path) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(refused(format!(
                "no such file ({}, from the current folder)",
                path.display()
            )));
        }
        Err(e) => return Err(refused(e.to_string())),
    };
    if !metadata.is_file() {
        return Err(refused(format!(
            "{}, not a program; name the ccx executable",
            crate::file::kind_of(&metadata)
        )));
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        if metadata.permissions().mode() & 0o111 == 0 {
            return Err(refused(
                "a file without execute permission; make it executable (chmod +x) or name the \
                 ccx executable"
                    .to_string(),
            ));
        }
    }
    Ok(path)
}

/// Runs `program -i JOB` in the work folder of `files` (whose deck must be written), with its
/// output in the log. Every `every` it calls `progress` and asks `stop` whether the run must end
/// (a signal to microslip: `Some(signal)`); then the solver and everything it started are ended
/// at once.
///
/// The solver runs in a process group of its own, ended as a whole when the run stops for any
/// reason other than the solver's own exit: a stop, an error, a panic (the `Solver` guard's
/// `Drop`). On Linux the kernel also ends it if microslip dies without a chance to (SIGKILL).
/// Its own group also keeps the terminal's Ctrl-C from reaching it directly: microslip decides.
///
/// # Errors
/// [`RunError::Missing`] when the program cannot be found, [`RunError::Failed`] (with the log's
/// tail) when it exits with an error or writes no results, [`RunError::Stopped`] when `stop`
/// asked for it.
pub fn run_ccx(
    program: &Path,
    files: &RunFiles,
    every: Duration,
    progress: &mut dyn FnMut(&Progress),
    stop: &dyn Fn() -> Option<i32>,
) -> Result<(), RunError> {
    let job = files
        .deck
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or_else(|| io::Error::other("the deck has no job name"))?;
    let steps = fs::read_to_string(&files.deck)?
        .lines()
        .filter(|l| l.trim_start().to_ascii_uppercase().starts_with("*STEP"))
        .count();
    let log = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&files.log)?;
    let mut command = Command::new(program);
    command
        .args(["-i", job])
        .current_dir(&files.folder)
        .stdin(Stdio::null())
        .stdout(log.try_clone()?)
        .stderr(log);
    let mut solver = match Solver::spawn(&mut command) {
        Ok(solver) => solver,
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(RunError::Missing {
                program: program.display().to_string(),
            });
        }
        Err(e) => {
            return Err(RunError::NotAProgram {
                path: program.display().to_string(),
                reason: format!("cannot be started: {e}"),
            });
        }
    };
    let started = Instant::now();
    let mut reader = LogReader::open(&files.log)?;
    let status = loop {
        if let Some(status) = solver.try_wait()? {
            break status;
        }
        if let Some(signal) = stop() {
            solver.end();
            return Err(RunError::Stopped {
                signal,
                folder: files.folder.display().to_string(),
            });
        }
        std::thread::sleep(every);
        reader.read_new()?;
        progress(&Progress {
            elapsed: started.elapsed(),
            steps,
            total_time: reader.total_time,
            increments: reader.increments,
        });
    };
    reader.read_to_end()?;
    let has_results = fs::metadata(&files.results).is_ok_and(|m| m.len() > 0);
    // ccx 2.20 exits 0 after some errors ("*ERROR ..." in its output): the log decides too.
    if status.success() && has_results && !reader.reported_error {
        Ok(())
    } else {
        Err(RunError::Failed {
            status: if status.success() {
                "exit 0, but no results or an *ERROR in its log".to_string()
            } else {
                status.to_string()
            },
            log: files.log.display().to_string(),
            tail: reader.tail(),
        })
    }
}

/// A running solver, in a process group of its own, that never outlives its handle: dropping
/// it before the solver exited ends the whole group (the solver and anything it started).
struct Solver {
    child: Child,
    /// Set once the solver's exit was collected: its group is then no longer ours to signal.
    done: bool,
}

impl Solver {
    fn spawn(command: &mut Command) -> io::Result<Solver> {
        #[cfg(unix)]
        {
            use std::os::unix::process::CommandExt;
            command.process_group(0);
            #[cfg(target_os = "linux")]
            // SAFETY: runs in the child between fork and exec; prctl is async-signal-safe and
            // touches no memory of the parent. The solver gets SIGKILL when microslip dies.
            unsafe {
                command.pre_exec(|| {
                    if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL) != 0 {
                        return Err(io::Error::last_os_error());
                    }
                    Ok(())
                });
            }
        }
        Ok(Solver {
            child: command.spawn()?,
            done: false,
        })
    }

    fn try_wait(&mut self) -> io::Result<Option<std::process::ExitStatus>> {
        let status = self.child.try_wait()?;
        self.done = status.is_some();
        Ok(status)
    }

    /// Ends the solver's whole process group: SIGTERM, then SIGKILL for what is left after a
    /// moment, and collects the solver's exit.
    fn end(&mut self) {
        if self.done {
            return;
        }
        #[cfg(unix)]
        {
            let group = -(self.child.id() as i32);
            // SAFETY: kill has no memory effects; the group is the solver's own (process_group(0)
            // made its id the solver's pid, which stays ours until its exit is collected below).
            unsafe { libc::kill(group, libc::SIGTERM) };
            let deadline = Instant::now() + Duration::from_millis(200);
            while Instant::now() < deadline && matches!(self.child.try_wait(), Ok(None)) {
                std::thread::sleep(Duration::from_millis(10));
            }
            // SAFETY: as above; the solver's exit has not been collected with `wait` yet when it
            // is still running, and a zombie keeps its pid and group reserved.
            unsafe { libc::kill(group, libc::SIGKILL) };
        }
        #[cfg(not(unix))]
        let _ = self.child.kill();
        let _ = self.child.wait();
        self.done = true;
    }
}

impl Drop for Solver {
    fn drop(&mut self) {
        self.end();
    }
}

/// Follows a growing log, remembering the total time ccx last printed. (Its `STEP n` lines come
/// from a part of ccx whose output is buffered apart and reach a log file only at the end.)
///
/// Linear in the log: each call reads what was appended, scans it once for whole lines and keeps
/// only the unfinished last line for the next call. (An earlier version drained a `String` from
/// its front once per line, quadratic in the chunk: a solver that wrote 50 MB of log kept it busy
/// for minutes after the solver had ended.)
struct LogReader {
    file: File,
    /// The bytes of the last line, not yet ended by a newline.
    pending: Vec<u8>,
    total_time: Option<f64>,
    /// Increments whose total time was read so far (each ` actual total time=` line).
    increments: usize,
    /// Whether ccx printed an `*ERROR` line (ccx 2.20 exits 0 after some errors).
    reported_error: bool,
    /// The last [`LogReader::TAIL`] lines, for the message when ccx fails: kept as read, so
    /// that a log of hundreds of megabytes is never read whole again.
    last_lines: std::collections::VecDeque<String>,
}

impl LogReader {
    fn open(path: &Path) -> io::Result<LogReader> {
        Ok(LogReader {
            file: File::open(path)?,
            pending: Vec::new(),
            total_time: None,
            increments: 0,
            reported_error: false,
            last_lines: std::collections::VecDeque::with_capacity(Self::TAIL),
        })
    }

    /// Lines of the log a failure shows.
    const TAIL: usize = 12;

    /// Reads the rest of the log once the solver ended: its last line may lack a newline.
    fn read_to_end(&mut self) -> io::Result<()> {
        self.read_new()?;
        if !self.pending.is_empty() {
            let last = std::mem::take(&mut self.pending);
            self.read_line(&last);
        }
        Ok(())
    }

    /// The last lines read, one per line.
    fn tail(&self) -> String {
        let lines: Vec<&str> = self.last_lines.iter().map(String::as_str).collect();
        lines.join("\n")
    }

    /// Reads what was appended since the last call and updates the total time. Lines are split
    /// on bytes, before any decoding, so a character cut between two reads is never mangled.
    fn read_new(&mut self) -> io::Result<()> {
        self.file.read_to_end(&mut self.pending)?;
        let Some(last_newline) = self.pending.iter().rposition(|&b| b == b'\n') else {
            return Ok(());
        };
        let rest = self.pending.split_off(last_newline + 1);
        let whole = std::mem::replace(&mut self.pending, rest);
        // The chunk ends with a newline: the empty piece after it is no line.
        for line in whole[..whole.len() - 1].split(|&b| b == b'\n') {
            self.read_line(line);
        }
        Ok(())
    }

    /// ccx 2.20 prints ` actual total time=2.5e+00` at each increment it starts.
    fn read_line(&mut self, line: &[u8]) {
        let trimmed = line.trim_ascii();
        self.reported_error |= trimmed.starts_with(b"*ERROR");
        if self.last_lines.len() == Self::TAIL {
            self.last_lines.pop_front();
        }
        let text = String::from_utf8_lossy(line);
        self.last_lines
            .push_back(text.strip_suffix('\r').unwrap_or(&text).to_string());
        let Some(time) = trimmed.strip_prefix(b"actual total time=") else {
            return;
        };
        let time = std::str::from_utf8(time).ok();
        if let Some(time) = time.and_then(|t| t.trim().parse::<f64>().ok()) {
            self.total_time = Some(time);
            self.increments += 1;
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
            Path::new("microslip-no-such-ccx"),
            &files,
            Duration::from_millis(10),
            &mut |_| {},
            &|| None,
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
        let error = run_ccx(
            Path::new("false"),
            &files,
            Duration::from_millis(10),
            &mut |_| {},
            &|| None,
        )
        .unwrap_err();
        assert!(matches!(error, RunError::Failed { .. }), "{error}");
        assert!(error.to_string().contains("beam.log"), "{error}");
    }

    /// A solver handle dropped while the solver runs (an error or a panic between spawn and
    /// exit) ends it and the processes it started: none outlives the handle.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_dropped_solver_handle_ends_its_whole_process_group() {
        let dir = tempfile::tempdir().unwrap();
        let pids = dir.path().join("pids");
        let mut command = Command::new("sh");
        command
            .arg("-c")
            .arg("sleep 60 & echo $$ $! > \"$0.tmp\"; mv \"$0.tmp\" \"$0\"; wait")
            .arg(&pids);
        let solver = Solver::spawn(&mut command).unwrap();
        let started = Instant::now();
        while !pids.exists() {
            assert!(started.elapsed() < Duration::from_secs(10));
            std::thread::sleep(Duration::from_millis(10));
        }
        let pids: Vec<u32> = fs::read_to_string(&pids)
            .unwrap()
            .split_whitespace()
            .map(|p| p.parse().unwrap())
            .collect();
        drop(solver);
        // The solver was reaped by the drop; its orphaned child may linger as a zombie until
        // init collects it, which is ended all the same.
        let running = |pid: u32| {
            fs::read_to_string(format!("/proc/{pid}/stat")).is_ok_and(|stat| {
                stat.rsplit_once(')')
                    .is_some_and(|(_, rest)| !rest.trim_start().starts_with('Z'))
            })
        };
        let deadline = Instant::now() + Duration::from_secs(1);
        while pids.iter().any(|&p| running(p)) && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(10));
        }
        assert!(!pids.iter().any(|&p| running(p)), "{pids:?}");
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
