//! Ctrl-C during a long native call (issue 46, item 7): [`interruptible`] runs the work with the
//! GIL released on a thread of its own, inside the core's cooperative cancellation
//! ([`microslip::numeric::cancel`], the flag the terminal UI's workers use), while the calling
//! thread wakes every [`POLL`] to let Python run its signal handlers (`PyErr_CheckSignals`, which
//! does something only on the main thread). A handler that raises (`KeyboardInterrupt` for
//! SIGINT, or whatever a user's handler raises) sets the flag; the work stops at its next
//! checkpoint (every point of a sweep, every measurement of a fit, every load step of a deck,
//! every Newton iteration of a discretized solve: milliseconds) and the exception is raised. No
//! Python and no signal reaches the core: it sees one `AtomicBool`.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

use microslip::numeric::cancel::cancellable;
use pyo3::exceptions::PyKeyboardInterrupt;
use pyo3::prelude::*;

use crate::errors::guard;

/// How often the calling thread looks at Python's signals while the work runs: well under the
/// half second a user notices, and rare enough that taking the GIL for it costs nothing.
pub const POLL: Duration = Duration::from_millis(50);

/// Runs `work` with the GIL released and the panic guard ([`guard`]), on a worker thread, and
/// stops it when a signal handler raises meanwhile: that exception (`KeyboardInterrupt`) is then
/// the result. `work` gets the cancellation flag, for threads of its own to share
/// ([`microslip::numeric::cancel::cancellable`] each); on its own thread it already runs inside
/// it, so [`microslip::numeric::cancel::checkpoint`] stops it.
pub fn interruptible<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&Arc<AtomicBool>) -> T + Send,
) -> PyResult<T> {
    let cancel = Arc::new(AtomicBool::new(false));
    py.detach(|| {
        std::thread::scope(|scope| {
            let (done, finished) = mpsc::channel::<()>();
            let flag = Arc::clone(&cancel);
            let worker = scope.spawn(move || {
                let ran = guard(|| cancellable(&flag, || work(&flag)));
                // The receiver waits for this (or for the sender to go, should it not be sent).
                let _ = done.send(());
                ran
            });
            let mut raised: Option<PyErr> = None;
            loop {
                match finished.recv_timeout(POLL) {
                    Ok(()) | Err(RecvTimeoutError::Disconnected) => break,
                    Err(RecvTimeoutError::Timeout) if raised.is_none() => {
                        if let Err(e) = Python::attach(|py| py.check_signals()) {
                            cancel.store(true, Ordering::SeqCst);
                            raised = Some(e);
                        }
                    }
                    // Cancelled: waiting for the work to reach its next checkpoint.
                    Err(RecvTimeoutError::Timeout) => {}
                }
            }
            // `guard` caught any panic of the work, so joining cannot fail; were it to, the
            // payload becomes the guard's RuntimeError on this thread.
            let ran = worker
                .join()
                .unwrap_or_else(|payload| std::panic::resume_unwind(payload));
            match (raised, ran) {
                (Some(e), _) => Err(e),
                (None, Ok(Some(value))) => Ok(value),
                // Cancelled with no exception raised here: cannot happen (only this function
                // sets the flag), said as what it would be.
                (None, Ok(None)) => Err(PyKeyboardInterrupt::new_err("interrupted")),
                (None, Err(e)) => Err(e),
            }
        })
    })
}
