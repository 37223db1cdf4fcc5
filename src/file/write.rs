//! Writing a file a user named, the way a careful Unix tool does.
//!
//! - A regular file is replaced atomically (a temporary file in the same folder, flushed, renamed
//!   over it): a crash or a full disk never leaves it half written, and its mode and (where the
//!   process may) its owner are kept.
//! - A file the user may not write is refused, not replaced (renaming over a read-only file only
//!   needs the folder to be writable, which is how `-o ro.inp` used to succeed).
//! - A device, a FIFO or a socket is written through, never replaced by a regular file (`-o
//!   /dev/full` used to turn the device node into a file); a FIFO with no reader is refused at once
//!   instead of waiting in `open`.
//! - A symbolic link is followed to the file it names, which is the one written.
//! - Without `overwrite`, nothing that exists at the path is touched, even if it appears between a
//!   check and the write.
//! - No temporary file outlives a call or appears in a message.

use std::fs::{File, Metadata, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Writes `bytes` to `target` (see the module docs for what happens to what stands there): with
/// `overwrite`, an existing regular file is replaced and a device or FIFO written through; without
/// it, the call fails with [`io::ErrorKind::AlreadyExists`] when anything exists at `target`.
///
/// # Errors
/// The file system's error, in words that name no temporary file; `AlreadyExists` without
/// `overwrite`; `PermissionDenied` for a file the user may not write.
pub fn write_atomic(target: &Path, bytes: &[u8], overwrite: bool) -> io::Result<()> {
    if !overwrite {
        return write_new_files(&[(target, bytes)]);
    }
    let target = follow_links(target)?;
    match std::fs::metadata(&target) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => replace(&target, bytes, None),
        Err(e) => Err(e),
        Ok(metadata) if metadata.is_dir() => Err(io::Error::new(
            io::ErrorKind::IsADirectory,
            "a folder, not a file",
        )),
        Ok(metadata) if metadata.is_file() => {
            // Opening for writing (without truncating) asks the kernel the question that matters:
            // may this user write this file? A mode check would be wrong for root and for ACLs.
            OpenOptions::new()
                .write(true)
                .open(&target)
                .map_err(|e| match e.kind() {
                    io::ErrorKind::PermissionDenied => io::Error::new(
                        e.kind(),
                        "the file is read-only for this user (not replaced)",
                    ),
                    _ => e,
                })?;
            replace(&target, bytes, Some(&metadata))
        }
        Ok(_) => write_through(&target, bytes),
    }
}

/// Writes every `(path, bytes)` as a new file, all or none: when one cannot be written (it exists,
/// the disk is full), the ones already written by this call are removed, so a failed export leaves
/// nothing behind. Nothing that exists is ever touched.
///
/// # Errors
/// `AlreadyExists` when a path is taken (also by a dangling symbolic link); else the file system's
/// error.
pub fn write_new_files(files: &[(&Path, &[u8])]) -> io::Result<()> {
    let mut staged: Vec<Temporary> = Vec::with_capacity(files.len());
    for (path, bytes) in files {
        let mut temporary = Temporary::create_beside(path, None)?;
        temporary.write_and_flush(bytes)?;
        staged.push(temporary);
    }
    let mut placed: Vec<&Path> = Vec::with_capacity(files.len());
    for ((path, _), temporary) in files.iter().zip(&mut staged) {
        if let Err(e) = move_without_clobbering(&temporary.path, path) {
            for done in placed {
                let _ = std::fs::remove_file(done);
            }
            return Err(e);
        }
        temporary.placed();
        placed.push(path);
    }
    for (path, _) in files {
        sync_directory(folder_of(path))?;
    }
    Ok(())
}

/// The file `path` names after following symbolic links (at most 40, as the kernel allows); a
/// dangling link gives the path it points to, which is then created.
fn follow_links(path: &Path) -> io::Result<PathBuf> {
    let mut path = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&path) {
            Ok(metadata) if metadata.file_type().is_symlink() => {
                let to = std::fs::read_link(&path)?;
                path = if to.is_absolute() {
                    to
                } else {
                    folder_of(&path).join(to)
                };
            }
            _ => return Ok(path),
        }
    }
    Err(io::Error::new(
        io::ErrorKind::InvalidInput,
        "too many levels of symbolic links",
    ))
}

/// Replaces (or creates) the regular file `target` atomically, keeping `existing`'s mode and owner.
fn replace(target: &Path, bytes: &[u8], existing: Option<&Metadata>) -> io::Result<()> {
    let mut temporary = Temporary::create_beside(target, existing)?;
    temporary.write_and_flush(bytes)?;
    std::fs::rename(&temporary.path, target)?;
    temporary.placed();
    sync_directory(folder_of(target))
}

/// Writes `bytes` into a device, FIFO or socket as it stands, without waiting for a reader.
fn write_through(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = open_for_writing_without_blocking(target)?;
    file.write_all(bytes)?;
    file.flush()
}

fn open_for_writing_without_blocking(target: &Path) -> io::Result<File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        use std::os::unix::io::AsRawFd;
        let file = OpenOptions::new()
            .write(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(target)
            .map_err(|e| {
                if e.raw_os_error() == Some(libc::ENXIO) {
                    io::Error::new(
                        io::ErrorKind::WouldBlock,
                        "no process is reading this FIFO (start the reader first, or write to \
                         standard output with `-o -` and a pipe)",
                    )
                } else {
                    e
                }
            })?;
        // Writes wait for a slow reader as they would to a pipe; only the open must not wait.
        super::set_blocking(file.as_raw_fd())?;
        Ok(file)
    }
    #[cfg(not(unix))]
    {
        OpenOptions::new().write(true).open(target)
    }
}

/// Moves `from` to `to` unless something exists at `to` (checked by the kernel in the same step).
fn move_without_clobbering(from: &Path, to: &Path) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::ffi::OsStrExt;
        let c = |p: &Path| {
            std::ffi::CString::new(p.as_os_str().as_bytes())
                .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "a NUL byte in the path"))
        };
        let (from_c, to_c) = (c(from)?, c(to)?);
        // SAFETY: two valid NUL-terminated paths; renameat2 reads them and nothing else.
        let done = unsafe {
            libc::renameat2(
                libc::AT_FDCWD,
                from_c.as_ptr(),
                libc::AT_FDCWD,
                to_c.as_ptr(),
                libc::RENAME_NOREPLACE,
            )
        };
        if done == 0 {
            return Ok(());
        }
        let error = io::Error::last_os_error();
        // File systems without RENAME_NOREPLACE say EINVAL; a hard link is the portable way.
        if error.raw_os_error() != Some(libc::EINVAL) {
            return Err(error);
        }
    }
    std::fs::hard_link(from, to)?;
    std::fs::remove_file(from)
}

/// A temporary file beside its target, removed when dropped unless it was moved into place.
struct Temporary {
    path: PathBuf,
    file: Option<File>,
}

impl Temporary {
    /// Creates `.<name>.<pid>-<n>.tmp` in `target`'s folder with `existing`'s mode (else the mode
    /// `File::create` gives: 0666 less the umask) and, where the process may, its owner.
    fn create_beside(target: &Path, existing: Option<&Metadata>) -> io::Result<Self> {
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let folder = folder_of(target);
        let name = target
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let mut options = OpenOptions::new();
        options.write(true).create_new(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o666);
        let mut last_error = None;
        for _ in 0..100 {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let path = folder.join(format!(".{name}.{}-{n}.tmp", std::process::id()));
            match options.open(&path) {
                Ok(file) => {
                    let temporary = Self {
                        path,
                        file: Some(file),
                    };
                    if let Some(existing) = existing {
                        temporary.take_over(existing)?;
                    }
                    return Ok(temporary);
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last_error = Some(e),
                Err(e) if e.kind() == io::ErrorKind::PermissionDenied => {
                    return Err(io::Error::new(
                        e.kind(),
                        format!(
                            "the folder {} does not let this user create a file (microslip \
                             writes a new file and moves it into place, so that a failed write \
                             never leaves a half-written one)",
                            folder.display()
                        ),
                    ));
                }
                Err(e) => return Err(e),
            }
        }
        Err(last_error.unwrap_or_else(|| io::Error::other("no free temporary name")))
    }

    /// Gives the temporary file the mode and owner of the file it replaces.
    fn take_over(&self, existing: &Metadata) -> io::Result<()> {
        let Some(file) = &self.file else {
            return Ok(());
        };
        file.set_permissions(existing.permissions())?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let mine = file.metadata()?;
            if (mine.uid(), mine.gid()) != (existing.uid(), existing.gid()) {
                // Only root may give a file away; anyone else keeps the new file as their own,
                // as `cp` and editors do. The mode is set again: chown may clear set-id bits.
                if std::os::unix::fs::fchown(file, Some(existing.uid()), Some(existing.gid()))
                    .is_ok()
                {
                    file.set_permissions(existing.permissions())?;
                }
            }
        }
        Ok(())
    }

    fn write_and_flush(&mut self, bytes: &[u8]) -> io::Result<()> {
        let Some(file) = self.file.as_mut() else {
            return Ok(());
        };
        file.write_all(bytes)?;
        file.sync_all()
    }

    /// The file was moved into place: nothing to remove.
    fn placed(&mut self) {
        self.file = None;
        self.path = PathBuf::new();
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.path.as_os_str().is_empty() {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(folder) if !folder.as_os_str().is_empty() => folder,
        _ => Path::new("."),
    }
}

/// Flushes a folder's entries, so that a rename survives a power cut. Windows has no such call
/// (and does not need it for this); there it does nothing.
fn sync_directory(folder: &Path) -> io::Result<()> {
    #[cfg(unix)]
    {
        File::open(folder)?.sync_all()
    }
    #[cfg(not(unix))]
    {
        let _ = folder;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every name in `dir`, to show that no temporary file is left behind.
    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[cfg(unix)]
    use super::super::tests::mkfifo;

    #[test]
    fn a_new_file_is_created_and_an_existing_one_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("deck.inp");
        write_atomic(&path, b"one", true).unwrap();
        write_atomic(&path, b"two", true).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        let taken = write_atomic(&path, b"three", false).unwrap_err();
        assert_eq!(taken.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        assert_eq!(names(dir.path()), ["deck.inp"]);
    }

    #[cfg(unix)]
    #[test]
    fn a_replaced_file_keeps_its_mode() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("private.inp");
        std::fs::write(&path, "old").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
        write_atomic(&path, b"new", true).unwrap();
        let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o7777;
        assert_eq!(mode, 0o600);
        assert_eq!(std::fs::read(&path).unwrap(), b"new");
    }

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_is_followed_to_the_file_it_names() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.svg");
        let link = dir.path().join("link.svg");
        std::fs::write(&real, "old").unwrap();
        std::os::unix::fs::symlink("real.svg", &link).unwrap();
        write_atomic(&link, b"new", true).unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        // A dangling link: the file it names is created.
        let dangling = dir.path().join("dangling.svg");
        std::os::unix::fs::symlink("made.svg", &dangling).unwrap();
        write_atomic(&dangling, b"made", true).unwrap();
        assert_eq!(std::fs::read(dir.path().join("made.svg")).unwrap(), b"made");
        assert!(std::fs::symlink_metadata(&dangling).unwrap().is_symlink());
        // A loop is refused in words.
        let a = dir.path().join("a");
        std::os::unix::fs::symlink("b", &a).unwrap();
        std::os::unix::fs::symlink("a", dir.path().join("b")).unwrap();
        let looped = write_atomic(&a, b"x", true).unwrap_err();
        assert_eq!(looped.to_string(), "too many levels of symbolic links");
    }

    #[cfg(unix)]
    #[test]
    fn devices_are_written_through_never_replaced() {
        use std::os::unix::fs::FileTypeExt;
        write_atomic(Path::new("/dev/null"), b"gone", true).unwrap();
        assert!(
            std::fs::metadata("/dev/null")
                .unwrap()
                .file_type()
                .is_char_device()
        );
        let full = write_atomic(Path::new("/dev/full"), &[b'x'; 200_000], true).unwrap_err();
        assert_eq!(full.kind(), io::ErrorKind::StorageFull, "{full}");
        assert!(
            std::fs::metadata("/dev/full")
                .unwrap()
                .file_type()
                .is_char_device()
        );
    }

    /// A FIFO without a reader is refused at once (it used to be replaced by a regular file); with
    /// a reader it is written through. Both on a thread, so that a regression times out.
    #[cfg(unix)]
    #[test]
    fn a_fifo_is_written_through_or_refused_without_waiting() {
        use std::io::Read;
        use std::os::unix::fs::FileTypeExt;
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("out.inp");
        mkfifo(&fifo);
        let (send, receive) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let _ = send.send(write_atomic(&path, b"deck", true).map_err(|e| e.to_string()));
        });
        let refused = receive
            .recv_timeout(std::time::Duration::from_secs(10))
            .expect("writing to a FIFO without a reader blocked")
            .unwrap_err();
        assert!(
            refused.starts_with("no process is reading this FIFO"),
            "{refused}"
        );
        assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
        // With a reader (opened read-write so that opening does not wait for us).
        let mut reader = OpenOptions::new()
            .read(true)
            .write(true)
            .open(&fifo)
            .unwrap();
        write_atomic(&fifo, b"deck", true).unwrap();
        let mut got = [0u8; 4];
        reader.read_exact(&mut got).unwrap();
        assert_eq!(&got, b"deck");
        assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
        assert_eq!(names(dir.path()), ["out.inp"]);
    }

    #[test]
    fn a_folder_is_not_a_file() {
        let dir = tempfile::tempdir().unwrap();
        let refused = write_atomic(dir.path(), b"x", true).unwrap_err();
        assert_eq!(refused.to_string(), "a folder, not a file");
    }

    /// An export of two files where the second cannot be written leaves neither (it used to leave
    /// the first, one more per retry).
    #[test]
    fn new_files_are_written_all_or_none() {
        let dir = tempfile::tempdir().unwrap();
        let (svg, csv) = (dir.path().join("c.svg"), dir.path().join("c.csv"));
        std::fs::write(&csv, "theirs").unwrap();
        let taken = write_new_files(&[(&svg, b"svg"), (&csv, b"csv")]).unwrap_err();
        assert_eq!(taken.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(names(dir.path()), ["c.csv"]);
        assert_eq!(std::fs::read(&csv).unwrap(), b"theirs");
        std::fs::remove_file(&csv).unwrap();
        write_new_files(&[(&svg, b"svg"), (&csv, b"csv")]).unwrap();
        assert_eq!(names(dir.path()), ["c.csv", "c.svg"]);
    }

    /// Messages never name the temporary file: a folder the user may not write, or a missing one.
    #[test]
    fn messages_name_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no/such/folder/f.svg");
        let refused = write_atomic(&missing, b"x", true).unwrap_err();
        assert!(!refused.to_string().contains(".tmp"), "{refused}");
        let refused = write_new_files(&[(&missing, b"x")]).unwrap_err();
        assert!(!refused.to_string().contains(".tmp"), "{refused}");
    }
}
