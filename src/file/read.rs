//! Reading a file a user named, with a size cap, without ever blocking in `open`.
//!
//! Opening a FIFO for reading waits, in the kernel, until some process opens it for writing; no
//! key, Ctrl-C handled by the program, or hang-up gets a look in while it waits. So every file is
//! opened with `O_NONBLOCK` (which returns at once) and only then, for a stream whose writer may
//! still be writing, switched back to blocking reads. Callers that run inside the terminal UI, where
//! even a FIFO whose writer holds it open without writing must not stall the screen, read with
//! [`Kinds::RegularOnly`], which refuses everything but a regular file before opening it.

use std::fs::{File, Metadata};
use std::io::{self, Read};
use std::path::Path;

use super::{ReadError, Size};

/// Which kinds of file a read accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Kinds {
    /// Regular files, and streams (a FIFO, `/dev/stdin`, a process substitution `<(...)`, a
    /// device): these are read to their end or to the cap. Opening never blocks; a FIFO with no
    /// writer reads as empty, and is refused as such.
    AnyReadable,
    /// Regular files only: what the terminal UI and folder listings read, since a stream's writer
    /// could keep them waiting.
    RegularOnly,
}

/// What a file that is not a regular file is, in words ("a FIFO (named pipe)").
#[must_use]
pub(crate) fn kind_of(metadata: &Metadata) -> &'static str {
    let kind = metadata.file_type();
    if kind.is_dir() {
        return "a folder";
    }
    if kind.is_file() {
        return "a regular file";
    }
    if kind.is_symlink() {
        return "a symbolic link";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if kind.is_socket() {
            return "a socket";
        }
        if kind.is_char_device() {
            return "a character device";
        }
        if kind.is_block_device() {
            return "a block device";
        }
    }
    "not a regular file"
}

/// Refuses `path` unless it is a regular file (after following symbolic links); `stat` never
/// blocks, so this is safe to call on anything.
///
/// # Errors
/// [`ReadError::Io`] when `path` cannot be examined, [`ReadError::NotRegular`] otherwise.
pub(crate) fn require_regular(path: &Path) -> Result<Metadata, ReadError> {
    let metadata = std::fs::metadata(path)?;
    if metadata.is_file() {
        Ok(metadata)
    } else {
        Err(ReadError::NotRegular {
            kind: kind_of(&metadata),
        })
    }
}

/// Reads the UTF-8 text of `path`, refusing a file of more than `limit` bytes. `what` names the
/// kind of file for the message ("a preset").
///
/// A regular file whose size is already known to exceed the cap is refused without reading it; any
/// other file (a device, a FIFO, `/proc`, which report no useful size) is read up to one byte past
/// the cap and refused when that byte exists, so an endless stream costs at most `limit` bytes.
///
/// # Errors
/// [`ReadError::Io`] when the file cannot be opened or read, [`ReadError::NotRegular`] for a
/// folder or (with [`Kinds::RegularOnly`]) any file that is not regular, [`ReadError::NoWriter`]
/// for a FIFO nobody wrote to, [`ReadError::TooLarge`] above the cap, [`ReadError::NotText`] when
/// the bytes are not UTF-8.
///
/// # Examples
/// ```
/// use microslip::file::{Kinds, ReadError, Size, read_capped};
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("big.txt");
/// std::fs::write(&path, "x".repeat(2000))?;
/// assert_eq!(read_capped(&path, Size(2000), "a test", Kinds::RegularOnly)?.len(), 2000);
/// let refused = read_capped(&path, Size(1024), "a test", Kinds::RegularOnly).unwrap_err();
/// assert_eq!(refused.to_string(), "file is larger than the 1 KiB limit for a test");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_capped(
    path: &Path,
    limit: Size,
    what: &'static str,
    kinds: Kinds,
) -> Result<String, ReadError> {
    let too_large = || ReadError::TooLarge { limit, what };
    let metadata = std::fs::metadata(path)?;
    if metadata.is_dir() || (kinds == Kinds::RegularOnly && !metadata.is_file()) {
        return Err(ReadError::NotRegular {
            kind: kind_of(&metadata),
        });
    }
    if metadata.is_file() && metadata.len() > limit.0 {
        return Err(too_large());
    }
    let file = open_without_blocking(path)?;
    // What was opened, not what was looked at: the path may have been replaced in between.
    let metadata = file.metadata()?;
    if kinds == Kinds::RegularOnly && !metadata.is_file() {
        return Err(ReadError::NotRegular {
            kind: kind_of(&metadata),
        });
    }
    // A regular file's size is a good first guess (it may still grow while it is read); other
    // files report 0 or nonsense, so they start small and grow as read.
    let expected = if metadata.is_file() {
        metadata.len().min(limit.0)
    } else {
        0
    };
    let mut bytes = Vec::with_capacity(usize::try_from(expected).unwrap_or(0).saturating_add(1));
    if metadata.is_file() {
        file.take(limit.0.saturating_add(1))
            .read_to_end(&mut bytes)?;
    } else {
        read_stream(file, limit.0.saturating_add(1), &mut bytes)?;
    }
    if bytes.len() as u64 > limit.0 {
        return Err(too_large());
    }
    if bytes.is_empty() && is_fifo(&metadata) {
        return Err(ReadError::NoWriter);
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotText {
        offset: e.utf8_error().valid_up_to(),
    })
}

fn is_fifo(metadata: &Metadata) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        metadata.file_type().is_fifo()
    }
    #[cfg(not(unix))]
    {
        let _ = metadata;
        false
    }
}

/// How long a stream may stay silent while a process holds it open for writing: the read
/// gives up then, instead of waiting for the writer's whole life (`fit lap f.csv` on a FIFO whose
/// writer never wrote used to wait as long as it lived). A process substitution `<(...)` that
/// computes its data for longer than this is refused: writing the data to a file first works.
pub(crate) const STREAM_SILENCE: std::time::Duration = std::time::Duration::from_secs(5);

/// Reads a stream (a FIFO, a device, `/dev/stdin`) opened without blocking, up to `limit`
/// bytes, waiting for data at most [`STREAM_SILENCE`] at a time: no read here ever blocks.
///
/// Why a deadline rather than refusing streams: `fit lap <(script)` is a documented way to fit
/// a curve a program writes; a deadline keeps it, and bounds the wait for a silent writer.
fn read_stream(file: File, limit: u64, bytes: &mut Vec<u8>) -> Result<(), ReadError> {
    let mut file = file.take(limit);
    let mut buffer = [0_u8; 1 << 16];
    loop {
        match file.read(&mut buffer) {
            Ok(0) => return Ok(()),
            Ok(n) => bytes.extend_from_slice(&buffer[..n]),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                if !wait_readable(file.get_ref(), STREAM_SILENCE)? {
                    return Err(ReadError::Silent {
                        seconds: STREAM_SILENCE.as_secs(),
                    });
                }
            }
            Err(e) => return Err(e.into()),
        }
    }
}

/// Waits until `file` has data or its writer closed it, at most `timeout`; false on timeout.
#[cfg(unix)]
fn wait_readable(file: &File, timeout: std::time::Duration) -> io::Result<bool> {
    use std::os::unix::io::AsRawFd;
    let deadline = std::time::Instant::now() + timeout;
    loop {
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        if left.is_zero() {
            return Ok(false);
        }
        let mut poll = libc::pollfd {
            fd: file.as_raw_fd(),
            events: libc::POLLIN,
            revents: 0,
        };
        let millis = libc::c_int::try_from(left.as_millis().max(1)).unwrap_or(libc::c_int::MAX);
        // SAFETY: one valid pollfd for a descriptor `file` owns, for the duration of the call.
        match unsafe { libc::poll(&mut poll, 1, millis) } {
            0 => return Ok(false),
            n if n > 0 => return Ok(true),
            _ => {
                let e = io::Error::last_os_error();
                if e.kind() != io::ErrorKind::Interrupted {
                    return Err(e);
                }
            }
        }
    }
}

#[cfg(not(unix))]
fn wait_readable(_file: &File, _timeout: std::time::Duration) -> io::Result<bool> {
    Ok(true)
}

/// Opens `path` for reading with `O_NONBLOCK`, so that a FIFO without a writer does not wait in
/// `open`, and keeps the flag: a stream is read by [`read_stream`], which waits for data with a
/// deadline. A FIFO with no writer at all reads as empty.
fn open_without_blocking(path: &Path) -> io::Result<File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(path)
    }
    #[cfg(not(unix))]
    {
        File::open(path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(path: &Path, limit: u64, kinds: Kinds) -> Result<String, ReadError> {
        read_capped(path, Size(limit), "a test", kinds)
    }

    #[test]
    fn files_up_to_the_cap_are_read_and_larger_ones_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("f");
        std::fs::write(&path, "abc").unwrap();
        assert_eq!(read(&path, 3, Kinds::RegularOnly).unwrap(), "abc");
        assert!(matches!(
            read(&path, 2, Kinds::AnyReadable),
            Err(ReadError::TooLarge { limit: Size(2), .. })
        ));
        std::fs::write(&path, b"ok\xffno").unwrap();
        assert_eq!(
            read(&path, 10, Kinds::AnyReadable).unwrap_err().to_string(),
            "not UTF-8 text (invalid byte at offset 2)"
        );
        let missing = read(&dir.path().join("missing"), 10, Kinds::AnyReadable).unwrap_err();
        assert!(matches!(missing, ReadError::Io(_)), "{missing}");
        let folder = read(dir.path(), 10, Kinds::AnyReadable).unwrap_err();
        assert_eq!(folder.to_string(), "a folder, not a regular file");
    }

    #[cfg(unix)]
    #[test]
    fn an_endless_stream_stops_at_the_cap_and_is_refused_where_only_files_are_read() {
        let zero = Path::new("/dev/zero");
        let refused = read(zero, 1 << 20, Kinds::AnyReadable).unwrap_err();
        assert_eq!(
            refused.to_string(),
            "file is larger than the 1 MiB limit for a test"
        );
        let refused = read(zero, 1 << 20, Kinds::RegularOnly).unwrap_err();
        assert_eq!(
            refused.to_string(),
            "a character device, not a regular file"
        );
    }

    /// A FIFO nobody writes to: `open` used to wait forever. The read runs on a thread so that a
    /// regression fails the test (by timeout) instead of hanging the suite.
    #[cfg(unix)]
    #[test]
    fn a_fifo_without_a_writer_never_blocks() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("x.toml");
        super::super::tests::mkfifo(&fifo);
        let (send, receive) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let any = read(&path, 100, Kinds::AnyReadable).map_err(|e| e.to_string());
            let regular = read(&path, 100, Kinds::RegularOnly).map_err(|e| e.to_string());
            let _ = send.send((any, regular));
        });
        let (any, regular) = receive
            .recv_timeout(std::time::Duration::from_secs(10))
            .expect("reading a FIFO without a writer blocked");
        assert_eq!(
            any.unwrap_err(),
            "nothing to read: a FIFO (named pipe) that no process writes to"
        );
        assert_eq!(
            regular.unwrap_err(),
            "a FIFO (named pipe), not a regular file"
        );
    }

    /// A FIFO that a writer fills is read to its end (`<(...)`, `mkfifo` with a writer).
    #[cfg(unix)]
    #[test]
    fn a_fifo_with_a_writer_is_read_to_its_end() {
        use std::io::Write;
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("data.csv");
        super::super::tests::mkfifo(&fifo);
        // The writer opens first (a read-write open of a FIFO never blocks on Linux), so that the
        // reader finds one, then writes slowly and closes.
        let mut writer = std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .open(&fifo)
            .unwrap();
        let handle = std::thread::spawn(move || {
            writer.write_all(b"F_N,w_mm\n").unwrap();
            std::thread::sleep(std::time::Duration::from_millis(50));
            writer.write_all(b"1,2\n").unwrap();
        });
        // The reader sees the writer's end close only after the thread drops it.
        let text = read(&fifo, 100, Kinds::AnyReadable).unwrap();
        handle.join().unwrap();
        assert_eq!(text, "F_N,w_mm\n1,2\n");
    }
}
