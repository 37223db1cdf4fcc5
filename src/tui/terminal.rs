//! The terminal as a full-screen program uses it: raw mode, the alternate screen and bracketed
//! paste on entry; all three undone on every way out (quit, signal, suspend, error, panic via
//! ratatui's hook); and a check that the terminal is still there at all.

use std::io::{self, stdout};

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{DisableBracketedPaste, EnableBracketedPaste};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{EnterAlternateScreen, enable_raw_mode};
use ratatui::layout::Rect;

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

/// Suspends like other full-screen programs: restores the terminal, stops the process (the default
/// action of SIGTSTP), and once the shell continues it (`fg`), takes the terminal back and clears it
/// so that the next draw repaints everything. `still_wanted` is asked once the terminal is restored,
/// just before stopping: a SIGCONT that arrived meanwhile means the shell has continued the program
/// already, and stopping then would leave it stopped for good.
pub fn suspend(terminal: &mut DefaultTerminal, still_wanted: impl Fn() -> bool) -> io::Result<()> {
    leave();
    #[cfg(unix)]
    if still_wanted() {
        signal_hook::low_level::emulate_default_handler(signal_hook::consts::SIGTSTP)?;
    }
    enable_raw_mode()?;
    execute!(stdout(), EnterAlternateScreen, EnableBracketedPaste)?;
    // `resize` clears the screen and forgets the last frame, so the next draw repaints it all.
    // (`clear` would ask the terminal for the cursor position, an answer that the reader thread,
    // not this one, would receive.)
    let size = terminal.size()?;
    terminal.resize(Rect::new(0, 0, size.width, size.height))
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
