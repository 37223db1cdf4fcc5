//! What can go wrong on the command line, and the exit code each failure gets.

use super::*;

/// Why a command failed.
#[derive(Debug, Error)]
pub enum CliError {
    /// A preset or `--set` problem.
    #[error(transparent)]
    Preset(#[from] PresetError),
    /// A parameter out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// A sweep range problem, with the command's flags for the start, end and number of points.
    #[error("{}", error.message(*flags))]
    Range {
        /// The problem.
        error: RangeError,
        /// The flags naming the start, the end and the number of points.
        flags: [&'static str; 3],
    },
    /// A flag that is not a model parameter, out of its range.
    #[error("invalid {flag} = {}: {allowed}", Compact(*value))]
    Flag {
        /// The flag.
        flag: &'static str,
        /// The value given.
        value: f64,
        /// What is allowed.
        allowed: String,
    },
    /// A preset of another problem.
    #[error("preset '{preset}' is a {found} preset; `microslip {command}` needs a {wanted} preset")]
    WrongModel {
        /// The preset.
        preset: String,
        /// Its model.
        found: ModelKind,
        /// The model the command needs.
        wanted: ModelKind,
        /// The command, as typed after `microslip` (e.g. `fit beam`).
        command: String,
    },
    /// A parameter name the model does not have.
    #[error("invalid --vary: {0}")]
    Vary(#[from] UnknownParam),
    /// A target that cannot be solved (boxed: its "no root" case carries the whole scan).
    #[error(transparent)]
    Target(Box<TargetError>),
    /// Missing flags.
    #[error("{0}")]
    Usage(&'static str),
    /// The cross-check found errors above tolerance (already reported on stdout).
    #[error("{0} of the quantities checked {verb} the tolerance", verb = if *.0 == 1 { "exceeds" } else { "exceed" })]
    VerifyFailed(usize),
    /// `compare` or `bench`: the verdict (already reported on stdout) is not "agrees": the FE
    /// results do not agree, or could not be judged. The short verdict, for the one stderr line.
    #[error("verdict: {0} (exit code 1: the report says why)")]
    Disagrees(String),
    /// Unreadable or malformed measurements.
    #[error("{path}: {reason}")]
    Data {
        /// The file.
        path: String,
        /// What is wrong (with the line number when there is one).
        reason: String,
    },
    /// A bad `--beam-theory`.
    #[error("{0}")]
    Theory(String),
    /// Another flag the command cannot use as given (the message names it).
    #[error("{0}")]
    Invalid(String),
    /// A bad `--fix`.
    #[error("invalid --fix '{0}': expected mu=VALUE or KT=VALUE with a finite number")]
    Fix(String),
    /// The fit could not run.
    #[error(transparent)]
    Fit(#[from] FitError),
    /// A numerical solve failed, or refused its inputs.
    #[error("numerical solver: {0}")]
    Numeric(#[from] NumericError),
    /// A figure that cannot be drawn.
    #[error(transparent)]
    Figure(#[from] FigureError),
    /// Files with problems (already reported on stdout).
    #[error("{0} of the files checked {verb} problems", verb = if *.0 == 1 { "has" } else { "have" })]
    CheckFailed(usize),
    /// Writing the output failed.
    #[error("cannot write output: {0}")]
    Output(#[from] io::Error),
    /// `bench`: the solver could not be run, failed, or was stopped by a signal; or its work
    /// folder or program was refused.
    #[error(transparent)]
    Solver(#[from] fe::run::RunError),
}

impl From<TargetError> for CliError {
    fn from(e: TargetError) -> Self {
        CliError::Target(Box::new(e))
    }
}

impl CliError {
    /// The exit code, by the one table users read (README, "Exit codes"): 1 when the command ran
    /// and its answer is "no" or could not be computed, 2 when the input was refused before
    /// anything ran, 3 when the external solver failed, 128 + N when signal N stopped it.
    pub(super) fn exit_code(&self) -> u8 {
        use fe::run::RunError;
        match self {
            CliError::Target(e)
                if matches!(
                    **e,
                    TargetError::NoRoot { .. } | TargetError::Undefined { .. }
                ) =>
            {
                1
            }
            // Inputs the built-in solvers do not take (a K_T too stiff for double precision):
            // refused with the largest value that works, before any solve.
            CliError::Numeric(NumericError::OutOfRange(_) | NumericError::BadLoad(_)) => 2,
            CliError::CheckFailed(_)
            | CliError::VerifyFailed(_)
            | CliError::Disagrees(_)
            | CliError::Output(_)
            | CliError::Numeric(_) => 1,
            CliError::Solver(RunError::Stopped { signal, .. }) => {
                u8::try_from(128 + signal).unwrap_or(u8::MAX)
            }
            CliError::Solver(e) if e.is_solver_failure() => 3,
            _ => 2,
        }
    }

    /// Writes the error on stderr: one line, but for a failed solver the lines of its log
    /// follow, each as a line of its own (each sanitized, as every line shown is).
    pub(super) fn print(&self) {
        if let CliError::Solver(fe::run::RunError::Failed { status, log, tail }) = self {
            print_error(&format!(
                "ccx failed ({status}); the last lines of its log, {log}:"
            ));
            let mut stderr = io::stderr().lock();
            for line in tail.lines() {
                let _ = writeln!(stderr, "  {}", report::sanitize(line));
            }
        } else {
            print_error(&self.to_string());
        }
    }
}
