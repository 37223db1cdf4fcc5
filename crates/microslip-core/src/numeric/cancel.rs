//! Cooperative cancellation of a long solve, for a caller that runs it on a thread of its own (the
//! terminal UI's workers): [`cancellable`] runs a solve with a flag, and every Newton iteration of
//! every discretized solver ([`checkpoint`], in `newton`) looks at it. A solve whose flag is set
//! stops within one iteration (milliseconds), where the UI would otherwise wait seconds for an
//! answer nobody wants any more (a held arrow key asks for a new one at every step).
//!
//! A cancelled solve unwinds ([`std::panic::resume_unwind`], which runs no panic hook and prints
//! nothing) out of the iteration to [`cancellable`], as the `salsa` crate cancels its queries: the
//! solvers take no lock and share nothing, so unwinding only drops the solve's own data, and no
//! solver signature has to carry a flag it passes down ten levels. Outside [`cancellable`] a
//! checkpoint costs one thread-local read. Built with `panic = "abort"` nothing unwinds: a
//! cancelled solve runs to its end and [`cancellable`] drops its answer.

use std::cell::RefCell;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

thread_local! {
    /// The flag of the [`cancellable`] call running on this thread, if any.
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// The payload a cancelled solve unwinds with.
struct Cancelled;

/// Runs `work` on this thread, stopping it at its next [`checkpoint`] once `cancel` is set.
/// Returns `None` when it was cancelled (set before or during the work), its value otherwise. A
/// panic of `work` that is not a cancellation goes on unwinding.
pub fn cancellable<R>(cancel: &Arc<AtomicBool>, work: impl FnOnce() -> R) -> Option<R> {
    let outer = FLAG.with(|flag| flag.replace(Some(Arc::clone(cancel))));
    let result = catch_unwind(AssertUnwindSafe(work));
    FLAG.with(|flag| flag.replace(outer));
    match result {
        Ok(_) if cancel.load(Ordering::SeqCst) => None,
        Ok(value) => Some(value),
        Err(payload) if payload.is::<Cancelled>() => None,
        Err(payload) => resume_unwind(payload),
    }
}

/// Stops the solve here if the [`cancellable`] call it runs in was cancelled; does nothing
/// otherwise (and always, in a build that aborts on panic). Public for work that is not a
/// discretized solve (a fit's progress callback, a long file parse) to stop at the same points.
pub fn checkpoint() {
    if !cfg!(panic = "unwind") {
        return;
    }
    let cancelled = FLAG.with(|flag| {
        flag.borrow()
            .as_ref()
            .is_some_and(|cancel| cancel.load(Ordering::Relaxed))
    });
    if cancelled {
        resume_unwind(Box::new(Cancelled));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cancelled_solve_stops_at_its_next_checkpoint_and_others_run_to_the_end() {
        let cancel = Arc::new(AtomicBool::new(false));
        let mut iterations = 0;
        let stopped = cancellable(&cancel, || {
            for _ in 0..1000 {
                checkpoint();
                iterations += 1;
                if iterations == 10 {
                    cancel.store(true, Ordering::SeqCst);
                }
            }
            iterations
        });
        assert_eq!(stopped, None);
        assert_eq!(iterations, 10);
        // Outside `cancellable`, and with a fresh flag, a checkpoint does nothing.
        checkpoint();
        let fresh = Arc::new(AtomicBool::new(false));
        assert_eq!(cancellable(&fresh, || 7), Some(7));
    }
}
