//! The TUI's effects: what [`App::update`] asks for and does not do itself (write an exported
//! chart or a preset, read a measurement or FE result file, list presets or a folder, run a fit),
//! and what came of it ([`Outcome`]), which goes back through [`App::receive`].
//!
//! The state stays a pure function of actions and outcomes, so every key can be tested without a
//! disk, and the event loop decides where the work runs: files are quick and are read and written
//! at once, in the loop ([`Runner::perform`], which uses [`perform_blocking`]), between two keys;
//! an export renders a PNG and a PDF (tens of ms) and a fit can take seconds on a long curve, so
//! they run on worker threads, like the slow work of the `television` crate, and report their
//! results (a fit its progress too) as messages the loop picks up with the terminal's events. The
//! loop never waits for them: the screen is redrawn, Esc cancels a fit and signals act as fast as
//! when the program is idle. Tests perform everything in place with
//! [`update_blocking`].

use std::any::Any;
use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::Sender;
use std::time::{Duration, Instant};

use super::action::Action;
use super::app::App;
use crate::TwinBeamsParams;
use crate::fe::load::AnyLoaded;
use crate::fit::{FitError, FitResult, Measurement, Progress};
use crate::preset::{self, Listed, SaveError};
use crate::problems::ModelKind;
use crate::problems::inputs::Inputs;

/// Something [`App::update`] wants done outside the state.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// `x`: write the chart as new files `STEM.svg`, `.png`, `.pdf` and `.csv` in `dir`, or under
    /// the first free name `STEM-2` to `STEM-999`; never replace a file. Rendering the PNG and the
    /// PDF takes longer than a frame, so the loop performs it on a worker.
    ExportChart {
        /// The export directory.
        dir: PathBuf,
        /// The file name without number and extension, e.g. `microslip-w-vs-f`.
        stem: String,
        /// The figure.
        svg: String,
        /// Its points.
        csv: Vec<u8>,
    },
    /// `s`: write a user preset.
    SavePreset {
        /// The user preset directory.
        dir: PathBuf,
        /// The preset name (checked by [`preset::save_atomic`]).
        name: String,
        /// Its description, for the preset the model then comes from.
        description: String,
        /// The parameters saved.
        inputs: Inputs,
        /// The file's text.
        text: String,
        /// True once the user agreed to replace an existing preset.
        overwrite: bool,
    },
    /// `d` with a measurement CSV (`F_N,w_mm`): read and parse it.
    ReadMeasurements {
        /// The file, as typed.
        path: String,
    },
    /// `d` with FE results (a CalculiX `.dat`, a plate CSV): read and parse them.
    ReadFeResults {
        /// The file, as typed.
        path: String,
        /// The model a CSV's points belong to (a `.dat` says it itself).
        kind: ModelKind,
    },
    /// `p`: the bundled presets and those in the user directory.
    ListPresets {
        /// The user preset directory, if any.
        user_dir: Option<PathBuf>,
    },
    /// The plate's 2-D continuum at `params`, for the regime pane (on a worker in the loop: up to
    /// a tenth of a second; a request made while one runs waits, and only the newest waits).
    SolveContinuum {
        /// The plate.
        params: crate::PlateParams,
    },
    /// `:preset NAME`: read the preset `name` (bundled, in `user_dir`, or a path).
    LoadPreset {
        /// The name or path, as typed.
        name: String,
        /// The user preset directory, if any.
        user_dir: Option<PathBuf>,
    },
    /// Tab after `:preset `: complete `prefix`, the end of `text`, among the preset names.
    CompletePreset {
        /// The command line's text.
        text: String,
        /// The part of it being completed.
        prefix: String,
        /// The user preset directory, if any.
        user_dir: Option<PathBuf>,
    },
    /// Tab in a prompt: complete the file name at the end of `text`.
    CompletePath {
        /// The prompt's text.
        text: String,
    },
    /// `f`: fit mu and K_T of the twin beams to the measurements (on a worker in the loop).
    Fit {
        /// Which fit, for its outcomes: those of a cancelled fit are ignored.
        job: u64,
        /// The beams (the start of the fit).
        structure: TwinBeamsParams,
        /// The measurements.
        points: Vec<Measurement>,
    },
    /// Esc while a fit runs: stop it (its outcome is ignored in any case).
    CancelFit {
        /// The fit to stop.
        job: u64,
    },
}

/// What came of an [`Effect`], for [`App::receive`].
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The chart's SVG was written here (and its CSV beside it), or why not.
    Exported(Result<PathBuf, ExportError>),
    /// The preset of [`Effect::SavePreset`] was written here, or why not.
    Saved {
        /// The preset name.
        name: String,
        /// Its description.
        description: String,
        /// The parameters saved.
        inputs: Inputs,
        /// The file written, or why not ([`SaveError::Exists`]: ask before overwriting).
        result: Result<PathBuf, SaveError>,
    },
    /// The measurements of a file, or why it was refused.
    Measurements {
        /// The file, as typed.
        path: String,
        /// The points, or the reason (with the line).
        result: Result<Vec<Measurement>, String>,
    },
    /// FE results, or why they were refused.
    FeResults {
        /// The file, as typed.
        path: String,
        /// The points (and the deck's parameters), or the reason.
        result: Result<AnyLoaded, String>,
    },
    /// The presets to pick from.
    Presets(Vec<Listed>),
    /// What the regime pane shows of the continuum at `params`, or why there is none.
    Continuum {
        /// The plate solved.
        params: crate::PlateParams,
        /// The solution's summary, or the reason.
        result: Result<ContinuumSummary, String>,
    },
    /// The preset of [`Effect::LoadPreset`], or why it cannot be loaded.
    Preset {
        /// The name or path, as typed.
        name: String,
        /// The preset, or the reason.
        result: Result<preset::Preset, String>,
    },
    /// A file name completed.
    Completed {
        /// The text completed (the completion applies only if the prompt still holds it).
        text: String,
        /// The completed text.
        completed: String,
        /// The names that match.
        names: Vec<String>,
    },
    /// How far a running fit got.
    FitProgress {
        /// The fit.
        job: u64,
        /// Its progress.
        progress: Progress,
    },
    /// A fit's result.
    Fitted {
        /// The fit.
        job: u64,
        /// The estimates, or why there are none.
        result: Result<FitResult, FitError>,
    },
}

/// Why `x` wrote nothing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ExportError {
    /// `STEM` and `STEM-2` to `STEM-999` are all taken.
    AllTaken {
        /// The name without number and extension.
        stem: String,
    },
    /// The file system refused.
    Failed {
        /// The SVG that could not be written.
        path: PathBuf,
        /// The file system's reason.
        reason: String,
    },
}

/// Highest number `x` appends to a taken name before giving up.
pub const MAX_EXPORT_NUMBER: u32 = 999;

/// How often a running fit reports its progress, and how long it runs before the first report: a
/// fit that ends sooner (a curve of up to a few thousand rows) changes the screen once, with its
/// result, as when it ran in the loop, and a long one costs a redraw every 100 ms at most.
pub const PROGRESS_EVERY: Duration = Duration::from_millis(100);

/// Performs `effect` on this thread, the fit included, and returns what came of it (nothing for
/// [`Effect::CancelFit`]: there is nothing to stop here).
pub fn perform_blocking(effect: Effect) -> Option<Outcome> {
    Some(match effect {
        Effect::ExportChart {
            dir,
            stem,
            svg,
            csv,
        } => Outcome::Exported(export(&dir, &stem, &svg, &csv)),
        Effect::SavePreset {
            dir,
            name,
            description,
            inputs,
            text,
            overwrite,
        } => Outcome::Saved {
            result: preset::save_atomic(&dir, &name, &text, overwrite),
            name,
            description,
            inputs,
        },
        Effect::ReadMeasurements { path } => Outcome::Measurements {
            result: crate::measured::read_text(&path, crate::file::Kinds::RegularOnly)
                .map_err(|e| e.to_string())
                .and_then(|text| crate::measured::parse(&text).map_err(|e| e.to_string())),
            path,
        },
        Effect::ReadFeResults { path, kind } => Outcome::FeResults {
            result: crate::fe::load::any_results(std::path::Path::new(&path), None, kind)
                .map_err(|e| e.to_string()),
            path,
        },
        Effect::ListPresets { user_dir } => Outcome::Presets(preset::listing(user_dir.as_deref())),
        Effect::SolveContinuum { params } => solve_continuum(params),
        Effect::LoadPreset { name, user_dir } => Outcome::Preset {
            // As `--preset` takes it: a path, a bundled name, then a user preset of that name.
            result: preset::resolve_in(&name, user_dir.as_deref()).map_err(|e| match e {
                preset::PresetError::NotFound { name } => {
                    format!("no preset named '{name}' (p lists them; a path must end in .toml)")
                }
                other => other.to_string(),
            }),
            name,
        },
        Effect::CompletePreset {
            text,
            prefix,
            user_dir,
        } => {
            let mut names: Vec<String> = preset::listing(user_dir.as_deref())
                .into_iter()
                .filter(|listed| listed.preset.is_ok() && listed.name.starts_with(&prefix))
                .map(|listed| listed.name)
                .collect();
            names.dedup();
            let completed = match super::command::common_prefix(&names) {
                Some(common) => format!("{}{common}", &text[..text.len() - prefix.len()]),
                None => text.clone(),
            };
            Outcome::Completed {
                text,
                completed,
                names,
            }
        }
        Effect::CompletePath { text } => {
            let (completed, names) = super::text_input::complete_path(&text);
            Outcome::Completed {
                text,
                completed,
                names,
            }
        }
        Effect::Fit {
            job,
            structure,
            points,
        } => Outcome::Fitted {
            job,
            result: crate::fit::fit_twin_beams_weighted(
                structure,
                &points,
                None,
                None,
                crate::fit::Weights::default(),
                &mut |_| {},
            ),
        },
        Effect::CancelFit { .. } => return None,
    })
}

/// What the regime pane shows of the plate's continuum solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuumSummary {
    /// u(L), thickness mean (mm).
    pub end_displacement: f64,
    /// Contact pressure over P, mean over the last t_p / 10: the free-end peak at that resolution
    /// (the corner node's own value grows with refinement).
    pub edge_pressure: f64,
}

/// The outcome of [`Effect::SolveContinuum`].
fn solve_continuum(params: crate::PlateParams) -> Outcome {
    let result = crate::problems::plate::solve_plate_continuum(
        params,
        crate::problems::plate::ContinuumMesh::default(),
    )
    .map(|plate| ContinuumSummary {
        end_displacement: plate.end_displacement_mean,
        edge_pressure: plate.edge_pressure_ratio,
    })
    .map_err(|e| e.to_string());
    Outcome::Continuum { params, result }
}

/// Applies `action` and performs every effect it leads to before returning, the fit included:
/// what the event loop does, without threads, for tests.
pub fn update_blocking(app: &mut App, action: Action) {
    let effects = app.update(action);
    drive(app, effects, perform_blocking);
}

/// Performs `effects` with `perform`, feeding each outcome back through [`App::receive`] and
/// performing what that asks for in turn, in order, until nothing is left.
fn drive(app: &mut App, effects: Vec<Effect>, mut perform: impl FnMut(Effect) -> Option<Outcome>) {
    let mut queue = VecDeque::from(effects);
    while let Some(effect) = queue.pop_front() {
        if let Some(outcome) = perform(effect) {
            queue.extend(app.receive(outcome));
        }
    }
}

/// `x`'s files: `STEM.svg`, `.png`, `.pdf` (the same figure rendered, so whichever a user sends
/// says the same) and `.csv`, or the first free `STEM-N` set; all or none
/// ([`crate::file::write_new_files`]: a disk with room for the SVG only must not keep it). Returns
/// the SVG's path. The terminal's loop performs it on a worker ([`Runner::perform`]).
fn export(
    dir: &std::path::Path,
    stem: &str,
    svg: &str,
    csv: &[u8],
) -> Result<PathBuf, ExportError> {
    use crate::report::figure;
    let rendered = figure::png_from_svg(svg).and_then(|png| Ok((png, figure::pdf_from_svg(svg)?)));
    let (png, pdf) = rendered.map_err(|e| ExportError::Failed {
        path: dir.join(format!("{stem}.png")),
        reason: e.to_string(),
    })?;
    for n in 1..=MAX_EXPORT_NUMBER {
        let name = if n == 1 {
            stem.to_string()
        } else {
            format!("{stem}-{n}")
        };
        let path = |extension: &str| dir.join(format!("{name}.{extension}"));
        let (svg_path, png_path, pdf_path, csv_path) =
            (path("svg"), path("png"), path("pdf"), path("csv"));
        if csv_path.exists() {
            continue;
        }
        let files: [(&std::path::Path, &[u8]); 4] = [
            (&svg_path, svg.as_bytes()),
            (&png_path, &png),
            (&pdf_path, &pdf),
            (&csv_path, csv),
        ];
        match crate::file::write_new_files(&files) {
            Ok(()) => return Ok(svg_path),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => {
                return Err(ExportError::Failed {
                    path: svg_path,
                    reason: e.to_string(),
                });
            }
        }
    }
    Err(ExportError::AllTaken {
        stem: stem.to_string(),
    })
}

/// What a worker sends the event loop.
pub enum Report {
    /// An outcome for [`App::receive`].
    Outcome(Outcome),
    /// The work panicked (after the panic hook restored the terminal and printed the message):
    /// the loop panics with it too, so that the program ends as it did when the work ran in the
    /// loop.
    Panicked(Box<dyn Any + Send>),
}

/// The payload a cancelled fit unwinds with (see [`Runner::perform`]).
struct Cancelled;

/// Performs effects for the event loop: at once in the loop, except the fit, which runs on a
/// worker thread reporting through `reports` (the loop's channel, shared with the terminal's
/// events).
pub struct Runner<M> {
    reports: Sender<M>,
    /// The fit running, if any, and its cancel flag.
    fit: Option<(u64, Arc<AtomicBool>)>,
    /// True while a continuum solve runs; the newest request made meanwhile waits here (older
    /// ones are dropped: a held arrow key asks for many, only the last values matter).
    continuum: (bool, Option<crate::PlateParams>),
}

impl<M: From<Report> + Send + 'static> Runner<M> {
    /// A runner whose workers report through `reports`.
    pub fn new(reports: Sender<M>) -> Runner<M> {
        Runner {
            reports,
            fit: None,
            continuum: (false, None),
        }
    }

    /// Performs what the app asked for before any key (the continuum of a plate it opens on).
    pub fn start(&mut self, app: &mut App) {
        let effects = app.take_asked();
        drive(app, effects, |effect| self.perform(effect));
    }

    /// Applies `action` and performs what it leads to (see [`Runner::perform`]).
    pub fn update(&mut self, app: &mut App, action: Action) {
        let effects = app.update(action);
        drive(app, effects, |effect| self.perform(effect));
    }

    /// Gives a worker's report to the app and performs what that leads to; resumes a worker's
    /// panic.
    pub fn deliver(&mut self, app: &mut App, report: Report) {
        match report {
            Report::Outcome(outcome) => {
                if matches!(outcome, Outcome::Continuum { .. }) {
                    self.continuum.0 = false;
                    if let Some(params) = self.continuum.1.take() {
                        self.start_continuum(params);
                    }
                }
                let effects = app.receive(outcome);
                drive(app, effects, |effect| self.perform(effect));
            }
            Report::Panicked(payload) => std::panic::resume_unwind(payload),
        }
    }

    /// Performs `effect`: a fit starts on a worker thread and reports later (nothing now), a
    /// cancel sets the fit's flag, anything else is done at once ([`perform_blocking`]).
    ///
    /// The fit has no cancel of its own, only its progress callback, called at every grid node
    /// and every 16 384 measurements of a pass: a cancelled fit unwinds out of that callback ([`std::panic::resume_unwind`],
    /// which runs no panic hook, so nothing is printed and the terminal stays as it is) and the
    /// worker catches it, as the `salsa` crate cancels queries. The fit holds no lock and shares
    /// nothing, so unwinding only drops its own data. Built with `panic = "abort"` a cancelled
    /// fit runs to its end instead, and its result is ignored like any cancelled fit's.
    pub fn perform(&mut self, effect: Effect) -> Option<Outcome> {
        match effect {
            Effect::Fit {
                job,
                structure,
                points,
            } => {
                let cancel = Arc::new(AtomicBool::new(false));
                self.fit = Some((job, Arc::clone(&cancel)));
                let reports = self.reports.clone();
                std::thread::spawn(move || {
                    fit_on_worker(job, structure, &points, &cancel, &reports)
                });
                None
            }
            Effect::SolveContinuum { params } => {
                if self.continuum.0 {
                    self.continuum.1 = Some(params);
                } else {
                    self.start_continuum(params);
                }
                None
            }
            Effect::CancelFit { job } => {
                if let Some((_, cancel)) = self.fit.take_if(|(running, _)| *running == job) {
                    cancel.store(true, Ordering::SeqCst);
                }
                None
            }
            // About 40 ms of rendering (release build): more than a frame, so off the loop.
            // Two exports at once cannot collide: each claims its file names with create_new.
            effect @ Effect::ExportChart { .. } => {
                self.on_worker(move || perform_blocking(effect));
                None
            }
            effect => perform_blocking(effect),
        }
    }
}

impl<M: From<Report> + Send + 'static> Runner<M> {
    /// Solves the continuum on a worker thread, which reports its outcome (or its panic).
    fn start_continuum(&mut self, params: crate::PlateParams) {
        self.continuum.0 = true;
        self.on_worker(move || Some(solve_continuum(params)));
    }

    /// Runs `work` on a worker thread, which reports its outcome (if any) or its panic.
    fn on_worker(&self, work: impl FnOnce() -> Option<Outcome> + Send + 'static) {
        let reports = self.reports.clone();
        std::thread::spawn(move || {
            // Failures are outcomes (a solver's non-convergence, a full disk); a panic is a bug,
            // and the panic hook has already restored the terminal (on any thread), so the loop
            // ends the program with it as it does for the fit's, rather than drawing on a
            // terminal that is no longer in full-screen mode.
            let report = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)) {
                Ok(Some(outcome)) => Report::Outcome(outcome),
                Ok(None) => return,
                Err(payload) => Report::Panicked(payload),
            };
            // The loop has gone (the program is ending): nobody needs the report.
            let _ = reports.send(M::from(report));
        });
    }
}

/// A worker's fit: progress every [`PROGRESS_EVERY`], then the result, unless cancelled.
fn fit_on_worker<M: From<Report>>(
    job: u64,
    structure: TwinBeamsParams,
    points: &[Measurement],
    cancel: &AtomicBool,
    reports: &Sender<M>,
) {
    let send = |report: Report| {
        // The loop has gone (the program is ending): nobody needs the report.
        let _ = reports.send(M::from(report));
    };
    let mut reported = Instant::now();
    let fitted = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        // The command line's default weights (a sigma_mm column is not kept by the terminal UI).
        crate::fit::fit_twin_beams_weighted(
            structure,
            points,
            None,
            None,
            crate::fit::Weights::default(),
            &mut |progress| {
                if cfg!(panic = "unwind") && cancel.load(Ordering::SeqCst) {
                    std::panic::resume_unwind(Box::new(Cancelled));
                }
                if reported.elapsed() >= PROGRESS_EVERY {
                    reported = Instant::now();
                    send(Report::Outcome(Outcome::FitProgress { job, progress }));
                }
            },
        )
    }));
    match fitted {
        Ok(result) => send(Report::Outcome(Outcome::Fitted { job, result })),
        Err(payload) if payload.is::<Cancelled>() => {}
        Err(payload) => send(Report::Panicked(payload)),
    }
}

#[cfg(test)]
mod tests {
    use std::sync::mpsc::{self, RecvTimeoutError};

    use super::*;
    use crate::tui::app::{AppOptions, Measurements, Mode};
    use crate::tui::theme::{Charset, Theme};

    /// The app on the paper's beams with `count` measurements of a straight w(F) line: a fit
    /// that takes seconds on a million.
    fn app_with_points(count: u32) -> App {
        let points = (1..=count)
            .map(|i| {
                let force = 300.0 * f64::from(i) / f64::from(count);
                Measurement {
                    force,
                    response: 4e-4 * force,
                }
            })
            .collect();
        App::new(AppOptions {
            theme: Theme {
                charset: Charset::Ascii,
                color: false,
            },
            preset: preset::resolve("paper-beams").unwrap(),
            user_dir: None,
            data: Some(Measurements {
                path: "line.csv".into(),
                points,
            }),
            solve_continuum: false,
        })
    }

    #[test]
    fn a_fit_runs_on_a_worker_shows_progress_and_esc_stops_it_at_once() {
        let (sender, reports) = mpsc::channel::<Report>();
        let mut runner = Runner::new(sender);
        let mut app = app_with_points(1_000_000);
        let before = app.inputs();
        let started = Instant::now();
        runner.update(&mut app, Action::Fit);
        assert!(
            started.elapsed() < Duration::from_millis(500),
            "f waited for the fit: {:?}",
            started.elapsed()
        );
        assert!(matches!(app.mode(), Mode::Fitting { .. }));
        let Ok(Report::Outcome(progress @ Outcome::FitProgress { .. })) =
            reports.recv_timeout(Duration::from_secs(10))
        else {
            panic!("no progress report")
        };
        runner.deliver(&mut app, Report::Outcome(progress));
        let text = &app.message().unwrap().text;
        assert!(
            text.starts_with("fitting: ") && text.ends_with(" (Esc cancels)"),
            "{text}"
        );
        let cancelled = Instant::now();
        runner.update(&mut app, Action::Cancel);
        assert_eq!(app.mode(), &Mode::Normal);
        assert_eq!(app.inputs(), before);
        // The worker stops: its end closes the channel (the runner's copy is dropped), and no
        // result ever comes.
        drop(runner);
        loop {
            match reports.recv_timeout(Duration::from_secs(10)) {
                Ok(Report::Outcome(Outcome::FitProgress { .. })) => {}
                Ok(Report::Outcome(other)) => panic!("after Esc: {other:?}"),
                Ok(Report::Panicked(_)) => panic!("the worker panicked"),
                Err(RecvTimeoutError::Timeout) => panic!("the fit still runs 10 s after Esc"),
                Err(RecvTimeoutError::Disconnected) => break,
            }
        }
        let took = cancelled.elapsed();
        eprintln!("fit stopped {took:?} after Esc");
        assert!(
            took < Duration::from_secs(1),
            "the fit stopped {took:?} after Esc"
        );
        assert_eq!(app.inputs(), before);
    }

    #[test]
    fn a_fit_on_a_worker_reports_its_result_and_the_loop_adopts_it() {
        let (sender, reports) = mpsc::channel::<Report>();
        let mut runner = Runner::new(sender);
        let mut app = app_with_points(50);
        runner.update(&mut app, Action::Fit);
        // Progress first if the machine is slow, then the result.
        while matches!(app.mode(), Mode::Fitting { .. }) {
            let Ok(report) = reports.recv_timeout(Duration::from_secs(10)) else {
                panic!("no result")
            };
            runner.deliver(&mut app, report);
        }
        assert!(app.message().unwrap().text.starts_with("fit: mu = "));
        assert_eq!(app.history(), (1, 0));
    }

    /// `x` renders a PNG and a PDF, longer than a frame: the loop hands it to a worker and goes
    /// on (nothing written, nothing said yet); the worker's report then says where it went.
    #[test]
    fn an_export_runs_on_a_worker_and_reports_its_files() {
        let (sender, reports) = mpsc::channel::<Report>();
        let mut runner = Runner::new(sender);
        let dir = tempfile::tempdir().unwrap();
        let mut app = app_with_points(2);
        app.set_export_dir(dir.path().to_path_buf());
        let before = app.message().map(|m| m.text.clone());
        runner.update(&mut app, Action::ExportChart);
        assert_eq!(app.message().map(|m| m.text.clone()), before);
        let Ok(report) = reports.recv_timeout(Duration::from_secs(30)) else {
            panic!("the export did not report")
        };
        runner.deliver(&mut app, report);
        let message = app.message().unwrap();
        assert!(!message.is_error, "{}", message.text);
        for extension in ["svg", "png", "pdf", "csv"] {
            let file = dir.path().join(format!("microslip-w-vs-f.{extension}"));
            assert!(file.exists(), "{}: {}", file.display(), message.text);
        }
    }
}
