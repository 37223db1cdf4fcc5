//! The signals the TUI acts on, recorded by async-signal-safe handlers and read by the event loop
//! between any two events, so that no signal waits behind queued keys or a long redraw.

use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock};

use signal_hook::consts::{SIGCONT, SIGHUP, SIGINT, SIGTERM, SIGTSTP};

/// SIGCONTs received so far: a suspend asked for before the latest of them is void (the shell
/// already continued the program), so a storm of SIGTSTP/SIGCONT pairs that ends on SIGCONT leaves
/// it running, not stopped.
static CONTINUES: AtomicUsize = AtomicUsize::new(0);
/// The value of [`CONTINUES`] when the pending SIGTSTP arrived.
static STOP_ASKED_AT: AtomicUsize = AtomicUsize::new(0);

/// What a signal asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Restore the terminal and exit with 128 + the signal number.
    Terminate(i32),
    /// Restore the terminal and stop; redraw on continue.
    Suspend,
}

/// The flag of the installed handlers, for [`Signals::exit_if_terminating`].
static INSTALLED: OnceLock<Arc<AtomicUsize>> = OnceLock::new();

/// The last signal received and not yet acted on.
pub struct Signals {
    pending: Arc<AtomicUsize>,
}

impl Signals {
    /// Installs the handlers: SIGTERM, SIGHUP and SIGINT end the program, SIGTSTP suspends it,
    /// SIGCONT voids a suspend not yet acted on. A terminating signal wins over a pending suspend;
    /// a suspend never replaces a pending terminating signal.
    pub fn install() -> io::Result<Signals> {
        let pending = Arc::new(AtomicUsize::new(0));
        for signal in [SIGTERM, SIGHUP, SIGINT] {
            signal_hook::flag::register_usize(signal, Arc::clone(&pending), signal as usize)?;
        }
        let on_stop = Arc::clone(&pending);
        let on_continue = Arc::clone(&pending);
        // SAFETY: both actions only load, store and compare-exchange atomics, which are
        // async-signal-safe; they allocate nothing and take no lock.
        unsafe {
            signal_hook::low_level::register(SIGTSTP, move || {
                STOP_ASKED_AT.store(CONTINUES.load(Ordering::SeqCst), Ordering::SeqCst);
                let _ = on_stop.compare_exchange(
                    0,
                    SIGTSTP as usize,
                    Ordering::SeqCst,
                    Ordering::SeqCst,
                );
            })?;
            signal_hook::low_level::register(SIGCONT, move || {
                CONTINUES.fetch_add(1, Ordering::SeqCst);
                let _ = on_continue.compare_exchange(
                    SIGTSTP as usize,
                    0,
                    Ordering::SeqCst,
                    Ordering::SeqCst,
                );
            })?;
        }
        let _ = INSTALLED.set(Arc::clone(&pending));
        Ok(Signals { pending })
    }

    /// The pending request, if any; taking it clears it.
    pub fn take(&self) -> Option<Request> {
        match self.pending.swap(0, Ordering::SeqCst) {
            0 => None,
            n if n == SIGTSTP as usize => Some(Request::Suspend),
            n => Some(Request::Terminate(n as i32)),
        }
    }

    /// True when a SIGCONT arrived after the SIGTSTP being acted on: stopping now would leave the
    /// program stopped although the shell already continued it.
    pub fn continued_since_stop_request() -> bool {
        CONTINUES.load(Ordering::SeqCst) != STOP_ASKED_AT.load(Ordering::SeqCst)
    }

    /// Ends the process at once if a terminating signal is waiting: for long computations inside
    /// one key's work (a fit of a million measurements), which check in between chunks so that
    /// a signal still acts within milliseconds. Restores the terminal first.
    pub fn exit_if_terminating() {
        let Some(pending) = INSTALLED.get() else {
            return;
        };
        let signal = pending.load(Ordering::SeqCst);
        if signal != 0 && signal != SIGTSTP as usize {
            super::terminal::leave();
            std::process::exit(128 + signal as i32);
        }
        // A terminal that hung up without a SIGHUP (a closed pane) ends a long computation too.
        if super::terminal::hung_up() {
            std::process::exit(129);
        }
    }

    /// True when a signal is waiting (without taking it).
    pub fn waiting(&self) -> bool {
        self.pending.load(Ordering::SeqCst) != 0
    }
}
