//! The signals the TUI acts on, recorded by async-signal-safe handlers and read by the event loop
//! between any two events, so that no signal waits behind queued keys or a long redraw.
//!
//! SIGTSTP has no handler: it keeps its default action (stop) and stays *blocked* in every
//! thread, so that it waits, pending, in the kernel until the loop has restored the terminal and
//! unblocks it (see [`crate::tui::terminal::suspend`]). The kernel then decides, atomically, what a
//! program without a handler would get: a SIGCONT sent after the SIGTSTP discards it (a storm of
//! stops and continues that ends on a continue leaves the program running, whatever the timing),
//! and in an orphaned process group (no job-control shell: `ssh host microslip`, `sh -c`) a stop
//! is ignored, because nothing could resume it. An earlier version recorded SIGTSTP in a handler
//! and stopped itself later with SIGSTOP: a SIGCONT arriving between its check and the SIGSTOP
//! was lost and the program stayed stopped (seen once on CI), and Ctrl-Z under `ssh host
//! microslip` froze the session for good.

use std::io;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

use signal_hook::consts::{SIGCONT, SIGHUP, SIGINT, SIGTERM, SIGTSTP};

/// SIGCONTs received so far: a suspend that returns with the count unchanged was not a stop.
static CONTINUES: AtomicUsize = AtomicUsize::new(0);

/// What a signal asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Restore the terminal and exit with 128 + the signal number.
    Terminate(i32),
    /// Restore the terminal and let a pending SIGTSTP act; redraw on continue.
    Suspend,
}

/// The last terminating signal received and not yet acted on, and the pending SIGTSTP.
pub struct Signals {
    pending: Arc<AtomicUsize>,
}

impl Signals {
    /// Installs the handlers: SIGTERM, SIGHUP and SIGINT end the program; SIGCONT is counted.
    /// Blocks SIGTSTP and SIGCONT in the calling thread, a mask every thread spawned afterwards
    /// inherits: call it before any thread is started.
    pub fn install() -> io::Result<Signals> {
        let pending = Arc::new(AtomicUsize::new(0));
        for signal in [SIGTERM, SIGHUP, SIGINT] {
            signal_hook::flag::register_usize(signal, Arc::clone(&pending), signal as usize)?;
        }
        // SAFETY: the action only increments an atomic, which is async-signal-safe; it
        // allocates nothing and takes no lock.
        unsafe {
            signal_hook::low_level::register(SIGCONT, || {
                CONTINUES.fetch_add(1, Ordering::SeqCst);
            })?;
        }
        stop_signal_mask(libc::SIG_BLOCK)?;
        Ok(Signals { pending })
    }

    /// The pending request, if any; a terminating signal wins over a suspend. Taking a
    /// terminating signal clears it; a SIGTSTP stays pending until [`suspend_now`] lets it act.
    pub fn take(&self) -> Option<Request> {
        match self.pending.swap(0, Ordering::SeqCst) {
            0 if stop_pending() => Some(Request::Suspend),
            0 => None,
            n => Some(Request::Terminate(n as i32)),
        }
    }

    /// True when a signal is waiting (without taking it).
    pub fn waiting(&self) -> bool {
        self.pending.load(Ordering::SeqCst) != 0 || stop_pending()
    }
}

/// Asks for a suspend the way the terminal does for Ctrl-Z when it is not in raw mode: SIGTSTP to
/// the whole process group. It waits, blocked, until the loop acts on it.
pub fn request_suspend() {
    // SAFETY: kill with pid 0 (our process group) and a valid signal number has no memory effects.
    unsafe {
        libc::kill(0, SIGTSTP);
    }
}

/// How a suspend ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Suspended {
    /// The process was stopped and has been continued (or a SIGCONT voided the stop).
    Continued,
    /// The kernel discarded the stop: the process group is orphaned, so no shell could resume it.
    Ignored,
}

/// Lets a pending SIGTSTP take its default action now: the process stops here, inside this call,
/// unless a SIGCONT sent after the SIGTSTP has discarded it or the process group is orphaned.
/// Returns once the process runs again, with SIGTSTP blocked as before.
pub fn suspend_now() -> io::Result<Suspended> {
    let continues = CONTINUES.load(Ordering::SeqCst);
    stop_signal_mask(libc::SIG_UNBLOCK)?;
    stop_signal_mask(libc::SIG_BLOCK)?;
    Ok(if CONTINUES.load(Ordering::SeqCst) == continues {
        Suspended::Ignored
    } else {
        Suspended::Continued
    })
}

/// Blocks or unblocks SIGTSTP and SIGCONT in the calling thread. Both are blocked from
/// [`Signals::install`] on, in every thread, and unblocked only inside [`suspend_now`]: the
/// SIGCONT that continues the process then runs its handler in this thread, within that call,
/// never later in another one, so the count [`suspend_now`] reads is complete.
fn stop_signal_mask(how: libc::c_int) -> io::Result<()> {
    // SAFETY: the set is initialised by sigemptyset before use; pthread_sigmask only reads it.
    unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        libc::sigaddset(&mut set, SIGTSTP);
        libc::sigaddset(&mut set, SIGCONT);
        match libc::pthread_sigmask(how, &set, std::ptr::null_mut()) {
            0 => Ok(()),
            error => Err(io::Error::from_raw_os_error(error)),
        }
    }
}

/// True when a SIGTSTP is pending for this process (sent to it and not yet discarded by a
/// SIGCONT).
fn stop_pending() -> bool {
    // SAFETY: the set is written by sigpending before it is read.
    unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        libc::sigpending(&mut set) == 0 && libc::sigismember(&set, SIGTSTP) == 1
    }
}
