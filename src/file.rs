//! Reading user files with a size cap: the only way the library reads a file a user named (a preset,
//! a measured curve, FE results); and writing one atomically ([`write_atomic`]). A file larger than its cap is refused with the cap in the message instead of
//! being read: `/dev/zero`, a FIFO fed forever or a multi-gigabyte log given by mistake stop at the
//! cap, so memory stays bounded and nothing hangs on an endless stream.

use std::fmt;
use std::io::{self, Read};
use std::path::Path;

use thiserror::Error;

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

/// Reads the UTF-8 text of `path`, refusing a file of more than `limit` bytes. `what` names the
/// kind of file for the message ("a preset").
///
/// A regular file whose size is already known to exceed the cap is refused without reading it; any
/// other file (a device, a FIFO, `/proc`, which report no useful size) is read up to one byte past
/// the cap and refused when that byte exists, so an endless stream costs at most `limit` bytes.
///
/// # Errors
/// [`ReadError::Io`] when the file cannot be opened or read, [`ReadError::TooLarge`] above the cap,
/// [`ReadError::NotText`] when the bytes are not UTF-8.
///
/// # Examples
/// ```
/// use microslip::file::{ReadError, Size, read_capped};
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("big.txt");
/// std::fs::write(&path, "x".repeat(2000))?;
/// assert_eq!(read_capped(&path, Size(2000), "a test")?.len(), 2000);
/// let refused = read_capped(&path, Size(1024), "a test").unwrap_err();
/// assert_eq!(refused.to_string(), "file is larger than the 1 KiB limit for a test");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_capped(path: &Path, limit: Size, what: &'static str) -> Result<String, ReadError> {
    let too_large = || ReadError::TooLarge { limit, what };
    let file = std::fs::File::open(path)?;
    let metadata = file.metadata()?;
    if metadata.is_file() && metadata.len() > limit.0 {
        return Err(too_large());
    }
    // A regular file's size is a good first guess (it may still grow while it is read); other
    // files report 0 or nonsense, so they start small and grow as read.
    let expected = if metadata.is_file() {
        metadata.len().min(limit.0)
    } else {
        0
    };
    let mut bytes = Vec::with_capacity(usize::try_from(expected).unwrap_or(0).saturating_add(1));
    file.take(limit.0.saturating_add(1))
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit.0 {
        return Err(too_large());
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotText {
        offset: e.utf8_error().valid_up_to(),
    })
}

/// Writes `bytes` to `target` so that it is never seen half written and no old content is lost to
/// a failed write: a temporary file in the same directory, flushed, then renamed over `target` (or,
/// without `overwrite`, moved only if `target` does not exist: [`io::ErrorKind::AlreadyExists`]
/// otherwise), then the directory entry flushed so that the rename survives a power cut. The file
/// gets the permissions `File::create` would give (0666 less the umask), not a temporary file's 0600.
///
/// # Errors
/// The file system's error; `AlreadyExists` when `overwrite` is false and `target` exists.
pub fn write_atomic(target: &Path, bytes: &[u8], overwrite: bool) -> io::Result<()> {
    use std::io::Write;
    let dir = match target.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    let name = target
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    // Dropped (and so deleted) on every early return below.
    let mut temporary = builder.tempfile_in(dir)?;
    temporary.write_all(bytes)?;
    temporary.as_file().sync_all()?;
    if overwrite {
        temporary.persist(target).map_err(|e| e.error)?;
    } else {
        temporary.persist_noclobber(target).map_err(|e| e.error)?;
    }
    sync_directory(dir)
}

/// Flushes a directory's entries, so that a rename survives a power cut. Windows has no such call
/// (and does not need it for this); there it does nothing.
fn sync_directory(dir: &Path) -> io::Result<()> {
    #[cfg(unix)]
    {
        std::fs::File::open(dir)?.sync_all()
    }
    #[cfg(not(unix))]
    {
        let _ = dir;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_in_binary_units() {
        assert_eq!(Size(64 * 1024).to_string(), "64 KiB");
        assert_eq!(Size(256 << 20).to_string(), "256 MiB");
        assert_eq!(Size(3 << 30).to_string(), "3 GiB");
        assert_eq!(Size(1000).to_string(), "1000 bytes");
        assert_eq!(Size(1536).to_string(), "1536 bytes");
    }

    #[test]
    fn files_up_to_the_cap_are_read_and_larger_ones_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("f");
        std::fs::write(&path, "abc").unwrap();
        assert_eq!(read_capped(&path, Size(3), "x").unwrap(), "abc");
        assert!(matches!(
            read_capped(&path, Size(2), "x"),
            Err(ReadError::TooLarge { limit: Size(2), .. })
        ));
        std::fs::write(&path, b"ok\xffno").unwrap();
        assert_eq!(
            read_capped(&path, Size(10), "x").unwrap_err().to_string(),
            "not UTF-8 text (invalid byte at offset 2)"
        );
        let missing = read_capped(&dir.path().join("missing"), Size(10), "x").unwrap_err();
        assert!(matches!(missing, ReadError::Io(_)), "{missing}");
    }

    #[cfg(unix)]
    #[test]
    fn an_endless_stream_stops_at_the_cap() {
        let refused = read_capped(Path::new("/dev/zero"), Size(1 << 20), "a test").unwrap_err();
        assert_eq!(
            refused.to_string(),
            "file is larger than the 1 MiB limit for a test"
        );
    }
}
