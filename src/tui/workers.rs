//! Every slow job of the terminal UI on a worker thread: the finite-element and 2-D continuum
//! overlay (`n`, seconds for the lap joint), the plate's continuum of the regime pane, the fit
//! (`f`), a measurement or FE file read with `d` (a million rows take seconds) and the export
//! (`x`). One mechanism serves them all, so that each keeps the promises the event loop needs:
//!
//! - **Signals never wait.** The loop only hands a [`Job`] over ([`Workers::submit`]) and later
//!   picks up its [`Report`] from the channel it also reads the terminal's events from; it never
//!   joins a worker. SIGTERM while a job runs ends the program as fast as when it is idle.
//! - **Newest request wins.** Each [`Lane`] runs at most one job. A request made while one runs
//!   cancels the running one (it stops within one Newton iteration, see
//!   [`crate::numeric::cancel`]) and waits; a newer request replaces the waiting one, which is
//!   never started. A storm of 2 000 keys on K_T thus costs the solve running when it began and
//!   the last one, not 2 000 solves.
//! - **Answers for values no longer shown are dropped.** Every outcome says what it was computed
//!   for (the parameters, the chart, the fit's number), and the app adopts it only if that is
//!   still what it shows; a cancelled job reports nothing at all.
//! - **Esc cancels** ([`Workers::cancel`]) the job of a lane.
//!
//! Exports are the exception: each one runs at once on a thread of its own and runs to its end
//! (two cannot collide: each claims its file names with `create_new`), since every `x` asked for
//! files.

use std::any::Any;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::Sender;

use super::effects::Outcome;
use crate::numeric::cancel::cancellable;

/// A kind of slow job: one runs at a time per lane, except [`Lane::Export`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lane {
    /// The finite-element and 2-D continuum points of the chart shown (`n`).
    Overlay,
    /// The plate's 2-D continuum of the regime pane.
    Continuum,
    /// A fit (`f`).
    Fit,
    /// A file read with `d`.
    Read,
    /// A chart exported with `x`: every request runs, at once.
    Export,
}

impl Lane {
    /// The lanes that run one job at a time, in the order of [`Workers`]' slots.
    const QUEUED: [Lane; 4] = [Lane::Overlay, Lane::Continuum, Lane::Fit, Lane::Read];
}

/// How a running job reports an outcome before its last one (a fit's progress).
pub type Progress<'a> = &'a dyn Fn(Outcome);

/// The work of a job: its outcome (if any), given a way to report progress.
pub type Work = Box<dyn FnOnce(Progress) -> Option<Outcome> + Send>;

/// A slow job.
pub struct Job {
    /// Its lane.
    pub lane: Lane,
    /// Which request it is (a fit's number), for [`Workers::cancel`]; 0 where it does not matter.
    pub tag: u64,
    /// The work.
    pub work: Work,
}

impl Job {
    /// Runs the job on this thread, progress ignored: what tests do instead of a worker.
    pub fn run_here(self) -> Option<Outcome> {
        (self.work)(&|_| {})
    }
}

/// What a worker sends the event loop.
pub enum Report {
    /// An outcome of a job still running (a fit's progress).
    Progress(Outcome),
    /// A job of `lane` ended: its outcome, or none (cancelled, or nothing to say).
    Finished {
        /// The job's lane, free again.
        lane: Lane,
        /// What came of it.
        outcome: Option<Outcome>,
    },
    /// The work panicked (after the panic hook restored the terminal and printed the message):
    /// the loop panics with it too, so that the program ends as it did when the work ran in the
    /// loop.
    Panicked(Box<dyn Any + Send>),
}

/// The job running in a lane and the one waiting for it.
#[derive(Default)]
struct Slot {
    /// The running job's tag and cancel flag.
    running: Option<(u64, Arc<AtomicBool>)>,
    /// The newest request made while it runs.
    waiting: Option<Job>,
}

/// The workers of the event loop, reporting through `reports` (the loop's channel, shared with
/// the terminal's events).
pub struct Workers<M> {
    reports: Sender<M>,
    slots: [Slot; Lane::QUEUED.len()],
}

impl<M: From<Report> + Send + 'static> Workers<M> {
    /// Workers that report through `reports`.
    pub fn new(reports: Sender<M>) -> Workers<M> {
        Workers {
            reports,
            slots: Default::default(),
        }
    }

    /// The slot of a lane that runs one job at a time.
    fn slot(&mut self, lane: Lane) -> Option<&mut Slot> {
        let index = Lane::QUEUED.iter().position(|&l| l == lane)?;
        self.slots.get_mut(index)
    }

    /// Starts `job`, or, if its lane is busy, cancels the running job and lets `job` wait in
    /// place of any older request (which is then never started).
    pub fn submit(&mut self, job: Job) {
        let Some(slot) = self.slot(job.lane) else {
            return self.spawn(job, Arc::new(AtomicBool::new(false)));
        };
        match &slot.running {
            Some((_, cancel)) => {
                cancel.store(true, Ordering::SeqCst);
                slot.waiting = Some(job);
            }
            None => self.start(job),
        }
    }

    /// Esc: cancels the running job of `lane` (only if its tag is `tag`, when given) and drops
    /// the request waiting behind it. A cancelled job reports nothing.
    pub fn cancel(&mut self, lane: Lane, tag: Option<u64>) {
        let Some(slot) = self.slot(lane) else { return };
        if let Some((running, cancel)) = &slot.running
            && tag.is_none_or(|tag| tag == *running)
        {
            cancel.store(true, Ordering::SeqCst);
            slot.waiting = None;
        }
    }

    /// A job of `lane` has ended: the request waiting for it starts.
    pub fn finished(&mut self, lane: Lane) {
        let Some(slot) = self.slot(lane) else { return };
        slot.running = None;
        if let Some(job) = slot.waiting.take() {
            self.start(job);
        }
    }

    /// Starts `job` in its (free) lane.
    fn start(&mut self, job: Job) {
        let cancel = Arc::new(AtomicBool::new(false));
        if let Some(slot) = self.slot(job.lane) {
            slot.running = Some((job.tag, Arc::clone(&cancel)));
        }
        self.spawn(job, cancel);
    }

    /// Runs `job` on a thread of its own, which reports its progress, then its end (or its panic).
    fn spawn(&self, job: Job, cancel: Arc<AtomicBool>) {
        let reports = self.reports.clone();
        std::thread::spawn(move || {
            // The loop has gone (the program is ending): nobody needs the report.
            let send = |report: Report| {
                let _ = reports.send(M::from(report));
            };
            let Job { lane, work, .. } = job;
            // Failures are outcomes (a solver's non-convergence, a full disk); a panic is a bug,
            // and the panic hook has already restored the terminal (on any thread), so the loop
            // ends the program with it rather than drawing on a terminal that is no longer in
            // full-screen mode.
            let progress = |outcome: Outcome| send(Report::Progress(outcome));
            let ran = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                cancellable(&cancel, || work(&progress))
            }));
            send(match ran {
                Ok(outcome) => Report::Finished {
                    lane,
                    outcome: outcome.flatten(),
                },
                Err(payload) => Report::Panicked(payload),
            });
        });
    }
}

#[cfg(test)]
mod tests {
    use std::sync::mpsc::{self, Receiver};
    use std::time::{Duration, Instant};

    use super::*;

    /// A job that reports its number `n` (as a completion's text) once `gate` opens; it waits
    /// on cancellation checkpoints meanwhile, as a solve's Newton iterations do.
    fn job(lane: Lane, n: usize, gate: Arc<AtomicBool>, started: Sender<usize>) -> Job {
        Job {
            lane,
            tag: n as u64,
            work: Box::new(move |_| {
                let _ = started.send(n);
                while !gate.load(Ordering::SeqCst) {
                    crate::numeric::cancel::checkpoint();
                    std::thread::sleep(Duration::from_millis(1));
                }
                Some(Outcome::Completed {
                    text: n.to_string(),
                    completed: String::new(),
                    names: Vec::new(),
                })
            }),
        }
    }

    fn next(reports: &Receiver<Report>) -> Report {
        reports
            .recv_timeout(Duration::from_secs(10))
            .expect("a report within 10 s")
    }

    /// Three requests while one runs: the running one is cancelled (no outcome), the middle one
    /// never starts, the newest runs and reports.
    #[test]
    fn the_newest_request_wins_and_superseded_ones_never_start() {
        let (sender, reports) = mpsc::channel::<Report>();
        let (started_tx, started) = mpsc::channel();
        let mut workers = Workers::new(sender);
        let closed = Arc::new(AtomicBool::new(false));
        workers.submit(job(
            Lane::Overlay,
            1,
            Arc::clone(&closed),
            started_tx.clone(),
        ));
        assert_eq!(started.recv_timeout(Duration::from_secs(10)), Ok(1));
        workers.submit(job(
            Lane::Overlay,
            2,
            Arc::clone(&closed),
            started_tx.clone(),
        ));
        let open = Arc::new(AtomicBool::new(true));
        workers.submit(job(Lane::Overlay, 3, open, started_tx));
        let cancelled = Instant::now();
        let Report::Finished {
            lane: Lane::Overlay,
            outcome: None,
        } = next(&reports)
        else {
            panic!("the running job was not cancelled")
        };
        // At its next checkpoint: milliseconds idle; 5 s holds on a loaded 2-core machine
        // (issue 46, item 10), far below a job that was never cancelled (it runs until `closed`).
        assert!(cancelled.elapsed() < Duration::from_secs(5));
        workers.finished(Lane::Overlay);
        assert_eq!(started.recv_timeout(Duration::from_secs(10)), Ok(3));
        let Report::Finished {
            outcome: Some(Outcome::Completed { text, .. }),
            ..
        } = next(&reports)
        else {
            panic!("the newest job did not report")
        };
        assert_eq!(text, "3");
        workers.finished(Lane::Overlay);
        assert!(started.try_recv().is_err(), "job 2 started");
    }

    /// Esc cancels the running job of a lane (of the tag given) and the one waiting; other lanes
    /// run on.
    #[test]
    fn cancel_stops_a_lane_and_leaves_the_others() {
        let (sender, reports) = mpsc::channel::<Report>();
        let (started_tx, started) = mpsc::channel();
        let mut workers = Workers::new(sender);
        let closed = Arc::new(AtomicBool::new(false));
        workers.submit(job(Lane::Fit, 7, Arc::clone(&closed), started_tx.clone()));
        workers.submit(job(Lane::Read, 8, Arc::clone(&closed), started_tx.clone()));
        let mut seen = [started.recv().unwrap(), started.recv().unwrap()];
        seen.sort_unstable();
        assert_eq!(seen, [7, 8]);
        // Another fit's number: nothing happens.
        workers.cancel(Lane::Fit, Some(6));
        workers.cancel(Lane::Fit, Some(7));
        let Report::Finished {
            lane: Lane::Fit,
            outcome: None,
        } = next(&reports)
        else {
            panic!("the fit was not cancelled")
        };
        assert!(reports.try_recv().is_err(), "the read ended too");
        workers.cancel(Lane::Read, None);
        assert!(matches!(
            next(&reports),
            Report::Finished {
                lane: Lane::Read,
                outcome: None
            }
        ));
    }
}
