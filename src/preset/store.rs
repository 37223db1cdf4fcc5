//! The preset file store: the only part of the library that reads or writes preset files. Saving is
//! atomic and never clobbers: a crash, a full disk or a file that appeared meanwhile never leaves a
//! half-written, lost or overwritten preset, nor a stray temporary file.

use std::path::{Path, PathBuf};

use thiserror::Error;

use super::{Located, Preset, PresetError, PresetSource};
use crate::file::{Kinds, Size, read_capped};

/// Why a preset could not be saved.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SaveError {
    /// The name would not make a safe file name.
    #[error("invalid preset name '{0}': use 1 to 64 letters, digits, '-' or '_'")]
    BadName(String),
    /// The name belongs to a bundled preset.
    #[error("'{0}' is a bundled preset; choose another name")]
    Bundled(String),
    /// A file of that name exists and overwriting was not confirmed.
    #[error("preset '{0}' exists")]
    Exists(String),
    /// No user preset directory (no configuration directory is known for this user).
    #[error("no user preset directory: set XDG_CONFIG_HOME or HOME")]
    NoDirectory,
    /// The file system refused.
    #[error("cannot save {path}: {reason}")]
    Io {
        /// The path.
        path: String,
        /// The OS's reason.
        reason: String,
    },
}

/// Largest preset file read: 64 KiB. A preset is a dozen lines (under 1 KiB); the cap leaves room
/// for long comments and refuses a wrong file (a log, a device such as `/dev/zero`) at once instead of
/// reading it into memory.
pub(crate) const MAX_PRESET_SIZE: Size = Size(64 * 1024);

/// Reads and parses a preset file; the name is the file stem.
///
/// # Errors
/// [`PresetError::Io`] when the file cannot be read or is larger than 64 KiB (`MAX_PRESET_SIZE`), else
/// every problem of its text (see [`Preset::parse`]).
pub fn load(path: &Path) -> Result<Preset, Vec<Located>> {
    let text = read_capped(path, MAX_PRESET_SIZE, "a preset", Kinds::RegularOnly).map_err(|e| {
        vec![Located {
            line: None,
            error: PresetError::Io {
                path: path.display().to_string(),
                reason: e.to_string(),
            },
        }]
    })?;
    let name = path
        .file_stem()
        .map_or_else(|| "preset".into(), |s| s.to_string_lossy().into_owned());
    Preset::parse(&text, &name, PresetSource::File(path.to_path_buf()))
}

/// Checks a user preset's name before anything is asked or written: the TUI checks it before it
/// asks for the description, which a refused name would otherwise throw away.
///
/// # Errors
/// [`SaveError::BadName`] unless 1 to 64 ASCII letters, digits, `-` or `_` (no path: `../x` is
/// refused); [`SaveError::Bundled`] for a bundled preset's name.
pub fn check_name(name: &str) -> Result<(), SaveError> {
    let valid = !name.is_empty()
        && name.len() <= 64
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
    if !valid {
        return Err(SaveError::BadName(name.to_string()));
    }
    if super::is_bundled(name) {
        return Err(SaveError::Bundled(name.to_string()));
    }
    Ok(())
}

/// Saves `text` as `<dir>/<name>.toml` atomically: written to a temporary file in the same
/// directory, flushed to disk, then moved into place, and the directory entry flushed too, so a
/// crash never leaves a half-written or lost preset.
///
/// Without `overwrite`, the move fails if the target exists at that instant (not only when it was
/// checked), so a file that appeared meanwhile is never clobbered. The temporary file is removed on
/// every error.
///
/// # Errors
/// [`SaveError::BadName`], [`SaveError::Bundled`], [`SaveError::Exists`] (nothing written), or
/// [`SaveError::Io`] when the file system refuses.
pub fn save_atomic(
    dir: &Path,
    name: &str,
    text: &str,
    overwrite: bool,
) -> Result<PathBuf, SaveError> {
    check_name(name)?;
    let target = dir.join(format!("{name}.toml"));
    if !overwrite && target.exists() {
        return Err(SaveError::Exists(name.to_string()));
    }
    let io_error = |path: &Path, e: std::io::Error| SaveError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    std::fs::create_dir_all(dir).map_err(|e| io_error(dir, e))?;
    // A FIFO or device under a preset's name would swallow the preset: refused, not written through.
    if let Ok(metadata) = std::fs::metadata(&target)
        && !metadata.is_file()
    {
        return Err(SaveError::Io {
            path: target.display().to_string(),
            reason: format!("{}, not a regular file", crate::file::kind_of(&metadata)),
        });
    }
    match crate::file::write_atomic(&target, text.as_bytes(), overwrite) {
        Ok(()) => Ok(target),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            Err(SaveError::Exists(name.to_string()))
        }
        Err(e) => Err(io_error(&target, e)),
    }
}

/// The user preset folder: `microslip/presets` in the platform's configuration directory
/// (`$XDG_CONFIG_HOME` or `~/.config` on Linux, `~/Library/Application Support` on macOS,
/// `%APPDATA%` on Windows). `None` when the platform knows no such directory for this user.
pub fn user_preset_dir() -> Option<PathBuf> {
    dirs::config_dir().map(|config| config.join("microslip").join("presets"))
}

/// The presets in `dir` (`*.toml`), sorted by path; unreadable or invalid files are returned as
/// errors so that a listing can show them rather than hide them. A missing folder has none.
pub fn user_presets(dir: &Path) -> Vec<(PathBuf, Result<Preset, Vec<Located>>)> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths.into_iter().map(|p| (p.clone(), load(&p))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::to_toml;
    use crate::problems::inputs::Inputs;
    use crate::problems::{BeamParam, ModelKind, Param};
    use std::io::Write;

    const KT: Param = Param::Beam(BeamParam::Stiffness);

    fn leftovers(dir: &Path) -> Vec<String> {
        std::fs::read_dir(dir)
            .unwrap()
            .filter_map(Result::ok)
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".tmp"))
            .collect()
    }

    #[test]
    fn saved_presets_round_trip_and_are_never_clobbered_silently() {
        let dir = tempfile::tempdir().unwrap();
        let mut inputs = Inputs::paper(ModelKind::Beam);
        inputs.set(KT, 123.456).unwrap();
        let text = to_toml(&inputs, "bench \"A\"");
        let path = save_atomic(dir.path(), "bench-a", &text, false).unwrap();
        let loaded = load(&path).unwrap();
        assert_eq!(loaded.inputs, inputs);
        assert_eq!(loaded.description, "bench \"A\"");
        assert_eq!(
            save_atomic(dir.path(), "bench-a", "x", false),
            Err(SaveError::Exists("bench-a".into()))
        );
        assert_eq!(
            std::fs::read_to_string(&path).unwrap(),
            text,
            "refused save must leave the file intact"
        );
        save_atomic(
            dir.path(),
            "bench-a",
            &to_toml(&Inputs::paper(ModelKind::Beam), ""),
            true,
        )
        .unwrap();
        assert_eq!(load(&path).unwrap().inputs.get(KT), Some(600.0));
        assert!(matches!(
            save_atomic(dir.path(), "../evil", "x", false),
            Err(SaveError::BadName(_))
        ));
        assert!(matches!(
            save_atomic(dir.path(), "paper-beams", "x", false),
            Err(SaveError::Bundled(_))
        ));
        assert!(leftovers(dir.path()).is_empty());
    }

    #[cfg(unix)]
    #[test]
    fn saved_presets_get_ordinary_file_permissions() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let saved = save_atomic(dir.path(), "p", "model = \"beam\"\n", false).unwrap();
        let reference = dir.path().join("reference");
        std::fs::File::create(&reference).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&saved), mode(&reference));
    }

    #[test]
    fn a_file_that_appears_during_the_save_is_not_clobbered() {
        // The race itself cannot be timed from a test; what can be checked is the mechanism: the
        // final move refuses an existing target, even when the early check did not see it.
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("late.toml");
        let mut temporary = tempfile::Builder::new()
            .suffix(".tmp")
            .tempfile_in(dir.path())
            .unwrap();
        temporary.write_all(b"new").unwrap();
        std::fs::write(&target, "theirs").unwrap();
        let refused = temporary.persist_noclobber(&target).unwrap_err();
        assert_eq!(refused.error.kind(), std::io::ErrorKind::AlreadyExists);
        drop(refused);
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "theirs");
        assert!(leftovers(dir.path()).is_empty());
    }

    #[test]
    fn a_failed_move_leaves_no_temporary_file() {
        // A directory where the preset should go: the final move fails (even for root) after the
        // temporary file was written and flushed.
        let dir = tempfile::tempdir().unwrap();
        let blocker = dir.path().join("x.toml");
        std::fs::create_dir(&blocker).unwrap();
        std::fs::write(blocker.join("inside"), "").unwrap();
        let result = save_atomic(dir.path(), "x", "model = \"beam\"\n", true);
        assert!(matches!(result, Err(SaveError::Io { .. })), "{result:?}");
        assert!(leftovers(dir.path()).is_empty());
        assert!(blocker.join("inside").exists());
    }

    #[test]
    fn a_file_larger_than_the_cap_is_refused_with_the_limit() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("huge.toml");
        let mut text = String::from("model = \"beam\"\n");
        while text.len() <= MAX_PRESET_SIZE.0 as usize {
            text.push_str("# a long comment line, repeated until the file is past the cap\n");
        }
        std::fs::write(&path, &text).unwrap();
        let problems = load(&path).unwrap_err();
        assert_eq!(
            problems[0].to_string(),
            format!(
                "cannot read {}: file is larger than the 64 KiB limit for a preset",
                path.display()
            )
        );
        // At the cap exactly, it is read.
        text.truncate(MAX_PRESET_SIZE.0 as usize);
        let end = text.rfind('\n').unwrap() + 1;
        text.truncate(end);
        std::fs::write(&path, &text).unwrap();
        assert!(load(&path).is_ok());
    }

    #[test]
    fn user_presets_lists_only_toml_files_sorted() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("z.toml"), "model = \"beam\"\n").unwrap();
        std::fs::write(dir.path().join("a.toml"), "oops = \n").unwrap();
        std::fs::write(dir.path().join("readme.md"), "").unwrap();
        let found = user_presets(dir.path());
        assert_eq!(found.len(), 2);
        assert!(found[0].1.is_err() && found[1].1.is_ok());
        assert!(user_presets(&dir.path().join("missing")).is_empty());
    }
}
