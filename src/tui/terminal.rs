//! The terminal as a full-screen program uses it: raw mode, the alternate screen and bracketed
//! paste on entry; all three undone on every way out (quit, signal, suspend, error, panic via
//! ratatui's hook); and a check that the terminal is still there at all.

use std::io::{self, stdout};

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{DisableBracketedPaste, EnableBracketedPaste};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{EnterAlternateScreen, enable_raw_mode};
use ratatui::layout::Rect;

use super::signals;

/// Enters raw mode, the alternate screen and bracketed paste (so that a paste arrives as text, not
/// as keys).
pub fn enter() -> io::Result<DefaultTerminal> {
    let terminal = ratatui::try_init()?;
    execute!(stdout(), EnableBracketedPaste)?;
    Ok(terminal)
}

/// Undoes [`enter`]. Errors are ignored: on a terminal that hung up there is nothing left to
/// restore, and printing about it (as `ratatui::restore` does) could itself fail.
pub fn leave() {
    let _ = execute!(stdout(), DisableBracketedPaste);
    let _ = ratatui::try_restore();
}

/// Suspends like other full-screen programs: restores the terminal, lets the pending SIGTSTP take
/// its default action (the process stops inside `signals::suspend_now`), and once it runs again
/// takes the terminal back and clears it so that the next draw repaints everything. The kernel,
/// not this function, decides whether the stop happens (see the `signals` module): `Ignored` means the
/// process group is orphaned, with no shell that could resume it.
pub fn suspend(terminal: &mut DefaultTerminal) -> io::Result<signals::Suspended> {
    leave();
    let outcome = signals::suspend_now()?;
    enable_raw_mode()?;
    execute!(stdout(), EnterAlternateScreen, EnableBracketedPaste)?;
    // `resize` clears the screen and forgets the last frame, so the next draw repaints it all.
    // (`clear` would ask the terminal for the cursor position, an answer that the reader thread,
    // not this one, would receive.)
    let size = terminal.size()?;
    terminal.resize(Rect::new(0, 0, size.width, size.height))?;
    Ok(outcome)
}

/// True when the terminal on standard input has hung up (its other end closed: a dropped SSH link,
/// a killed tmux pane). Asked directly of the file descriptor, because a terminal reader that only
/// sees end of input can spin without ever reporting it.
#[cfg(unix)]
pub fn hung_up() -> bool {
    let mut fd = libc::pollfd {
        fd: libc::STDIN_FILENO,
        events: 0,
        revents: 0,
    };
    // SAFETY: one valid pollfd, count 1, zero timeout; poll only writes `revents`.
    let ready = unsafe { libc::poll(&mut fd, 1, 0) };
    ready > 0 && fd.revents & (libc::POLLHUP | libc::POLLERR | libc::POLLNVAL) != 0
}

/// No portable hang-up check elsewhere; the reader's errors still end the loop.
#[cfg(not(unix))]
pub fn hung_up() -> bool {
    false
}
