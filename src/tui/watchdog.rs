//! The last resort behind "signals never wait": if the event loop has not ended [`GRACE`] after
//! SIGTERM, SIGINT, SIGHUP or Ctrl-C, a thread of its own restores the terminal and ends the
//! process, whatever the loop is busy with.
//!
//! The loop looks at signals and Ctrl-C between any two events, so it normally acts within a few
//! milliseconds; but one event or one frame can take longer than that (a chart rebuilt by a debug
//! build on a machine loaded to 4 runnable threads a core took 0.5 s, and 1.4 to 1.8 s on the lap
//! joint with its overlay on), and a signal then waited for it. The watchdog does not: it sleeps
//! on a pipe that the signal handlers and the terminal's reader write to, and [`GRACE`] after a
//! byte comes, it takes over unless the loop has ended meanwhile ([`Watchdog::disarm`]). Only one
//! of the two restores the terminal: whichever moves the shared state out of "running" first.
//!
//! Taking over, it writes the sequences that leave the alternate screen, bracketed paste and the
//! hidden cursor straight to the terminal's file descriptor (not through the standard output's
//! lock, which a stuck draw may hold; each sequence starts with ESC, which ends any sequence a
//! draw left half written), leaves raw mode and exits with the code the loop would have used
//! (128 + the signal; 0 for Ctrl-C, which quits without asking). Nothing else needs ending: the
//! workers are threads of this process, and the TUI starts no child process.

use std::io::{self, Read, Write};
use std::os::unix::net::UnixStream;
use std::sync::Arc;
use std::sync::atomic::{AtomicU8, AtomicUsize, Ordering};
use std::time::Duration;

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};

/// How long the loop has to end by itself after a signal or Ctrl-C.
pub const GRACE: Duration = Duration::from_millis(100);

/// The loop runs; a wake-up may take over.
const RUNNING: u8 = 0;
/// The loop has ended and restores the terminal itself.
const ENDING: u8 = 1;
/// The watchdog has taken over.
const TAKEN: u8 = 2;

/// The watchdog's end of the loop: arms it for Ctrl-C, disarms it when the loop ends.
#[derive(Clone)]
pub struct Watchdog {
    state: Arc<AtomicU8>,
    wake: Arc<UnixStream>,
}

impl Watchdog {
    /// Starts the watchdog thread and has SIGTERM, SIGINT and SIGHUP wake it (besides the
    /// handlers of [`super::signals`], which the loop reads).
    pub fn start() -> io::Result<Watchdog> {
        let (mut sleeper, wake) = UnixStream::pair()?;
        wake.set_nonblocking(true)?;
        let signal = Arc::new(AtomicUsize::new(0));
        for number in [SIGTERM, SIGINT, SIGHUP] {
            signal_hook::flag::register_usize(number, Arc::clone(&signal), number as usize)?;
            signal_hook::low_level::pipe::register(number, wake.try_clone()?)?;
        }
        let state = Arc::new(AtomicU8::new(RUNNING));
        let watched = Arc::clone(&state);
        std::thread::spawn(move || {
            let mut byte = [0u8; 1];
            // A wake-up (or the end of the pipe, which ends the thread).
            while sleeper.read(&mut byte).is_ok_and(|n| n == 1) {
                std::thread::sleep(GRACE);
                if watched.load(Ordering::SeqCst) != RUNNING {
                    return;
                }
                let code = match signal.load(Ordering::SeqCst) {
                    0 => 0,
                    n => 128 + i32::try_from(n).unwrap_or(127),
                };
                if watched
                    .compare_exchange(RUNNING, TAKEN, Ordering::SeqCst, Ordering::SeqCst)
                    .is_ok()
                {
                    take_over(code);
                }
            }
        });
        Ok(Watchdog {
            state,
            wake: Arc::new(wake),
        })
    }

    /// Ctrl-C was pressed: the loop has [`GRACE`] to quit.
    pub fn arm_quit(&self) {
        // Never blocks (the stream is non-blocking): a full pipe already holds a wake-up.
        let _ = (&*self.wake).write(b"c");
    }

    /// The loop has ended: true when the caller restores the terminal; false when the watchdog
    /// already does (the caller must then leave the terminal alone and wait to be ended).
    pub fn disarm(&self) -> bool {
        self.state
            .compare_exchange(RUNNING, ENDING, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
    }
}

/// Restores the terminal and ends the process with `code`, without waiting for the loop.
fn take_over(code: i32) -> ! {
    // Bracketed paste off, the main screen back, the cursor shown.
    const LEAVE: &[u8] = b"\x1b[?2004l\x1b[?1049l\x1b[?25h";
    // SAFETY: a write of a valid buffer to a file descriptor; errors (a terminal gone) are
    // ignored, as there is nothing left to restore then.
    unsafe {
        libc::write(libc::STDOUT_FILENO, LEAVE.as_ptr().cast(), LEAVE.len());
    }
    let _ = ratatui::crossterm::terminal::disable_raw_mode();
    // SAFETY: _exit ends the process at once, running no destructors or atexit handlers, which
    // could wait for locks the stuck loop holds (the standard output's).
    unsafe { libc::_exit(code) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whoever leaves "running" first restores the terminal; the other one does not.
    #[test]
    fn only_one_of_loop_and_watchdog_restores() {
        let (_sleeper, wake) = UnixStream::pair().unwrap();
        wake.set_nonblocking(true).unwrap();
        let watchdog = Watchdog {
            state: Arc::new(AtomicU8::new(RUNNING)),
            wake: Arc::new(wake),
        };
        assert!(watchdog.disarm());
        assert!(!watchdog.disarm());
        watchdog.state.store(TAKEN, Ordering::SeqCst);
        assert!(!watchdog.disarm());
        // Arming never blocks, even once the pipe is full.
        for _ in 0..100_000 {
            watchdog.arm_quit();
        }
    }
}
