//! The only way the library reads or writes a file a user named (a preset, a measured curve, FE
//! results, a deck, a figure).
//!
//! - [`read_capped`] reads with a size cap and never blocks in `open`: a file larger than its cap
//!   is refused with the cap in the message instead of being read (`/dev/zero`, a FIFO fed forever
//!   or a multi-gigabyte log given by mistake stop at the cap), and a FIFO with no writer is refused
//!   at once instead of waiting for one.
//! - [`write_atomic`] and [`write_new_files`] write like a careful Unix tool: atomic replacement of
//!   regular files with their mode kept, devices and FIFOs written through, symbolic links followed,
//!   read-only files refused, nothing left behind by a failed write.

use std::fmt;
use std::io;

use thiserror::Error;

mod read;
mod write;

pub use read::{Kinds, read_capped};
pub(crate) use read::{kind_of, require_regular};
pub use write::{write_atomic, write_new_files};

/// True when `a` and `b` name one existing file, however written (`p.toml`, `./p.toml`, an
/// absolute path, a symbolic or hard link): the same device and inode where the platform has
/// them, else the same canonical path. False when either does not exist: a file not there yet
/// cannot be one that is read.
pub fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (std::fs::metadata(a), std::fs::metadata(b)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
            (Ok(a), Ok(b)) => a == b,
            _ => false,
        }
    }
}

/// Why a capped read failed.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The operating system's error (missing file, no permission, a directory...), shown as is.
    #[error("{0}")]
    Io(#[from] io::Error),
    /// More bytes than the cap (the rest was not read).
    #[error("file is larger than the {limit} limit for {what}")]
    TooLarge {
        /// The cap.
        limit: Size,
        /// What kind of file was expected, e.g. "a preset".
        what: &'static str,
    },
    /// Not a file that can be read here: a folder, or (where only regular files are read) a FIFO,
    /// a device or a socket.
    #[error("{kind}, not a regular file")]
    NotRegular {
        /// What it is, in words ("a FIFO (named pipe)").
        kind: &'static str,
    },
    /// A stream whose writer holds it open and sent nothing for this long.
    #[error(
        "nothing came through for {seconds} s while a process holds it open for writing: write \
         the data to a regular file, or let its writer finish sooner"
    )]
    Silent {
        /// The silence waited for (s).
        seconds: u64,
    },
    /// A FIFO that no process writes to: nothing to read.
    #[error("nothing to read: a FIFO (named pipe) that no process writes to")]
    NoWriter,
    /// The bytes are not UTF-8 text.
    #[error("not UTF-8 text (invalid byte at offset {offset})")]
    NotText {
        /// Offset of the first invalid byte.
        offset: usize,
    },
}

/// A number of bytes, shown in binary units when it is a whole number of them ("64 KiB").
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct Size(pub u64);

impl fmt::Display for Size {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const UNITS: [(u64, &str); 3] = [(1 << 30, "GiB"), (1 << 20, "MiB"), (1 << 10, "KiB")];
        for (unit, name) in UNITS {
            if self.0 >= unit && self.0.is_multiple_of(unit) {
                return write!(f, "{} {name}", self.0 / unit);
            }
        }
        write!(f, "{} bytes", self.0)
    }
}

/// Clears `O_NONBLOCK` on `fd`: files are opened without blocking (a FIFO's `open` waits for its
/// other end), then read and written as usual.
#[cfg(unix)]
fn set_blocking(fd: std::os::unix::io::RawFd) -> io::Result<()> {
    // SAFETY: fcntl on a descriptor the caller owns, reading then setting its status flags.
    let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
    if flags < 0 {
        return Err(io::Error::last_os_error());
    }
    // SAFETY: as above.
    if unsafe { libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) } < 0 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Makes a FIFO at `path` (for the tests that show nothing waits on one).
    #[cfg(unix)]
    pub(crate) fn mkfifo(path: &std::path::Path) {
        let name = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
        // SAFETY: a valid NUL-terminated path; mkfifo only creates the node.
        assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
    }

    #[test]
    fn sizes_read_in_binary_units() {
        assert_eq!(Size(64 * 1024).to_string(), "64 KiB");
        assert_eq!(Size(256 << 20).to_string(), "256 MiB");
        assert_eq!(Size(3 << 30).to_string(), "3 GiB");
        assert_eq!(Size(1000).to_string(), "1000 bytes");
        assert_eq!(Size(1536).to_string(), "1536 bytes");
    }
}
