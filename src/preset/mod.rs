//! Presets: named parameter sets in TOML, bundled in the binary or saved by the user.
//!
//! One file per preset, flat keys named as users write them (the keys of
//! [`crate::kernel::params`]), plus `model` and an optional `description`. Missing parameter keys take
//! the paper's value for that model, so a preset can say only what it changes; unknown keys are
//! errors (a typo such as `Kt` must not silently fall back to a default).
//!
//! Four jobs, four files: this one holds the types, the bundled presets and name resolution;
//! [`parse`] reads TOML text (and `--set KEY=VALUE`), [`mod@write`] writes it, [`store`] is the only
//! part that touches the file system.

pub mod parse;
pub mod store;
pub mod write;

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::kernel::params::ParamError;
#[cfg(any(test, feature = "app"))]
use crate::problems::ModelKind;
use crate::problems::UnknownParam;
use crate::problems::choice::{AnyChoice, ChoiceError};
use crate::problems::inputs::Inputs;

pub use parse::apply_assignment;
/// The TUI's value field parses as `--set` and `:` do (the same refusals, the same range).
#[cfg(feature = "app")]
pub(crate) use parse::parse_value;
pub use store::{SaveError, check_name, save_atomic, user_preset_dir, user_presets};
pub use write::to_toml;

/// A parsed preset.
#[derive(Debug, Clone, PartialEq)]
pub struct Preset {
    /// Name (file stem for user files).
    pub name: String,
    /// One-line description.
    pub description: String,
    /// The parameters.
    pub inputs: Inputs,
    /// Where it came from.
    pub source: PresetSource,
}

/// Where a preset lives.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PresetSource {
    /// Embedded in the binary.
    Bundled,
    /// A TOML file.
    File(PathBuf),
}

impl PresetSource {
    /// `bundled` or `user`, as listings show it.
    pub fn origin(&self) -> &'static str {
        match self {
            PresetSource::Bundled => "bundled",
            PresetSource::File(_) => "user",
        }
    }
}

impl fmt::Display for PresetSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PresetSource::Bundled => f.pad("bundled"),
            PresetSource::File(path) => f.pad(&path.display().to_string()),
        }
    }
}

/// What can go wrong with a preset or an assignment. Messages name the key, the value and what is
/// allowed; [`Located`] adds the line inside a file.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PresetError {
    /// A key the model does not have.
    #[error(transparent)]
    UnknownKey(#[from] UnknownParam),
    /// A value that is not a finite number.
    #[error("invalid value '{text}' for {key}: not a finite number; {allowed}")]
    NotANumber {
        /// The key.
        key: String,
        /// The text found.
        text: String,
        /// The allowed range, with the unit (`must be in [1e-6, 1e12] MPa/mm`).
        allowed: String,
    },
    /// A number too small for a double (`1e-400`), which would read as 0, where 0 is refused:
    /// the message quotes the text typed, not the 0 it became.
    #[error("invalid {key} = {text}: {allowed}")]
    Underflow {
        /// The key.
        key: String,
        /// The text found.
        text: String,
        /// The allowed range, with the unit.
        allowed: String,
    },
    /// A value that is not a string where text is expected (`description`).
    #[error("invalid value '{text}' for {key}: must be a string, in double quotes")]
    NotAString {
        /// The key.
        key: String,
        /// The text found.
        text: String,
    },
    /// `--set` text without `=`.
    #[error("invalid assignment '{text}': expected KEY=VALUE, e.g. KT=600")]
    Assignment {
        /// The text found.
        text: String,
    },
    /// A missing or unknown `model`.
    #[error("{0}")]
    Model(String),
    /// A bad value of a problem's setting that is a name (`beam_theory`).
    #[error(transparent)]
    Choice(#[from] ChoiceError),
    /// A problem's setting (`beam_theory`) in a preset of a problem without it.
    #[error("{key} applies to {owner}, not {model}")]
    ChoiceNotApplicable {
        /// The key given (`beam_theory`).
        key: &'static str,
        /// The problem it belongs to ([`AnyChoice::owner`]).
        owner: &'static str,
        /// The problem it was given to, with why it has no such setting where that helps
        /// ([`crate::problems::Problem::REFUSED_AS`]).
        model: &'static str,
    },
    /// A value out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// TOML syntax (the message carries line and column).
    #[error("{0}")]
    Syntax(String),
    /// A problem in the preset `spec` (a name or a path), at `line` of it when it has one.
    #[error(
        "preset '{spec}'{}: {error}",
        line.map_or_else(String::new, |line| format!(", line {line}"))
    )]
    InPreset {
        /// The preset as asked for.
        spec: String,
        /// 1-based line, when the problem has one.
        line: Option<usize>,
        /// The problem.
        error: Box<PresetError>,
    },
    /// The file could not be read.
    #[error("cannot read {path}: {reason}")]
    Io {
        /// The path.
        path: String,
        /// The OS's reason.
        reason: String,
    },
    /// No preset of that name.
    #[error("no preset named '{name}' (see `microslip presets`; a path must end in .toml)")]
    NotFound {
        /// The name asked for.
        name: String,
    },
    /// A user file named like a bundled preset: the bundled one wins everywhere.
    #[error(
        "named like the bundled preset '{name}', which wins (`--preset {name}`, the picker): rename the file to use it by name"
    )]
    Shadowed {
        /// The name both have.
        name: String,
    },
}

/// A problem located in a preset file.
#[derive(Debug, Clone, PartialEq)]
pub struct Located {
    /// 1-based line, when the problem has one.
    pub line: Option<usize>,
    /// The problem.
    pub error: PresetError,
}

impl fmt::Display for Located {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "line {line}: {}", self.error),
            None => write!(f, "{}", self.error),
        }
    }
}

/// Every problem's bundled presets, (name, TOML text), in the registry's order: each problem's
/// `BUNDLED_PRESETS`, in its face folder (`src/problems/<name>/mod.rs`), gathered from the
/// registry line so that no list of presets lives here.
macro_rules! bundled_presets {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        [$(crate::problems::$folder::BUNDLED_PRESETS),+]
    };
}

/// [`bundled_presets!`] as one list, each preset once: a folder that two registry lines name
/// lists its presets for both.
static BUNDLED: std::sync::LazyLock<Vec<(&'static str, &'static str)>> =
    std::sync::LazyLock::new(|| {
        let mut all: Vec<(&'static str, &'static str)> = Vec::new();
        for &(name, text) in microslip_core::with_problems!(bundled_presets)
            .into_iter()
            .flatten()
        {
            if all.iter().all(|(seen, _)| *seen != name) {
                all.push((name, text));
            }
        }
        all
    });

/// The setting that is a name (not a number) of any problem whose preset key is `key`
/// (`beam_theory`), found through the registry: presets and the command line set it without
/// knowing whose it is.
pub fn choice(key: &str) -> Option<&'static dyn AnyChoice> {
    crate::problems::ModelKind::ALL
        .iter()
        .flat_map(|kind| kind.problem().faces().choices)
        .copied()
        .find(|choice| choice.key() == key)
}

/// The bundled preset that opens a model by default (the paper's data set).
#[cfg(any(test, feature = "app"))]
pub(crate) fn default_name(kind: ModelKind) -> &'static str {
    kind.description().paper_preset
}

/// The bundled presets, parsed.
pub fn bundled() -> Vec<Preset> {
    BUNDLED
        .iter()
        .filter_map(|(name, text)| Preset::parse(text, name, PresetSource::Bundled).ok())
        .collect()
}

/// The paper's preset for `kind`; falls back to the paper's inputs should the bundled file ever
/// fail to parse (a test guards against that).
#[cfg(any(test, feature = "app"))]
pub(crate) fn paper(kind: ModelKind) -> Preset {
    let name = default_name(kind);
    resolve(name).unwrap_or_else(|_| Preset {
        name: name.to_string(),
        description: String::new(),
        inputs: Inputs::paper(kind),
        source: PresetSource::Bundled,
    })
}

/// The bundled presets' names, as error messages list them.
#[cfg(feature = "app")]
pub(crate) fn bundled_names() -> Vec<&'static str> {
    BUNDLED.iter().map(|(name, _)| *name).collect()
}

/// Whether `name` is a bundled preset's. Bundled names win everywhere: `--preset NAME` and the
/// TUI's picker load the bundled preset, a user file of that name is listed with a warning
/// ([`Listed::shadowed`]) and `check` warns about it; saving under such a name is refused.
pub(crate) fn is_bundled(name: &str) -> bool {
    BUNDLED.iter().any(|(bundled, _)| *bundled == name)
}

/// Resolves `--preset`: a path when it contains a path separator or ends in `.toml`, else a bundled
/// name, else a user preset of that name (bundled names win: see `is_bundled`).
///
/// # Errors
/// [`PresetError::NotFound`] for an unknown name, [`PresetError::Io`] for an unreadable file, and
/// the file's first problem (with its line) for an invalid one.
pub fn resolve(spec: &str) -> Result<Preset, PresetError> {
    resolve_in(spec, user_preset_dir().as_deref())
}

/// [`resolve`] with the user presets in `user_dir` (the TUI's, which tests set).
///
/// # Errors
/// As [`resolve`].
pub fn resolve_in(spec: &str, user_dir: Option<&Path>) -> Result<Preset, PresetError> {
    let first = |mut problems: Vec<Located>| {
        let Located { line, error } = problems.remove(0);
        match (line, error) {
            (None, error @ PresetError::Io { .. }) => error,
            (line, error) => PresetError::InPreset {
                spec: spec.to_string(),
                line,
                error: Box::new(error),
            },
        }
    };
    if spec.contains(std::path::MAIN_SEPARATOR) || spec.contains('/') || spec.ends_with(".toml") {
        return store::load(Path::new(spec)).map_err(first);
    }
    if let Some((name, text)) = BUNDLED.iter().find(|(name, _)| *name == spec) {
        return Preset::parse(text, name, PresetSource::Bundled).map_err(first);
    }
    match user_dir.map(|dir| dir.join(format!("{spec}.toml"))) {
        Some(path) if path.exists() => store::load(&path).map_err(first),
        _ => Err(PresetError::NotFound {
            name: spec.to_string(),
        }),
    }
}

/// One row of a preset listing: bundled presets first, then the user's, with invalid user files
/// kept (and their first problem) so that a listing can show them rather than hide them.
#[derive(Debug, Clone, PartialEq)]
pub struct Listed {
    /// Name (file stem for user files).
    pub name: String,
    /// `bundled` or `user`.
    pub origin: &'static str,
    /// The preset, or the first problem of an invalid file; for a shadowed file, the warning
    /// ([`PresetError::Shadowed`]), so that it cannot be loaded by picking it either.
    pub preset: Result<Preset, Located>,
    /// A user file named like a bundled preset, which wins (`is_bundled`): listed with a
    /// warning rather than as invalid.
    pub shadowed: bool,
}

/// Every preset a user can load: the bundled ones, then those in `user_dir` (sorted by name).
pub fn listing(user_dir: Option<&Path>) -> Vec<Listed> {
    let bundled = bundled().into_iter().map(|p| Listed {
        name: p.name.clone(),
        origin: PresetSource::Bundled.origin(),
        preset: Ok(p),
        shadowed: false,
    });
    let user = user_dir
        .map(user_presets)
        .unwrap_or_default()
        .into_iter()
        .map(|(path, loaded)| {
            let name = path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            let shadowed = is_bundled(&name);
            let preset = if shadowed {
                Err(Located {
                    line: None,
                    error: PresetError::Shadowed { name: name.clone() },
                })
            } else {
                loaded.map_err(|mut problems| problems.swap_remove(0))
            };
            Listed {
                name,
                origin: PresetSource::File(path).origin(),
                preset,
                shadowed,
            }
        });
    bundled.chain(user).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_problem_opens_on_a_bundled_preset_of_its_own() {
        for kind in ModelKind::ALL {
            let preset = resolve(default_name(kind)).unwrap();
            assert_eq!(preset.inputs.kind(), kind, "{}", default_name(kind));
        }
    }
    use crate::problems::{BeamParam, Param};

    #[test]
    fn bundled_presets_parse_and_validate() {
        let presets = bundled();
        assert_eq!(presets.len(), BUNDLED.len());
        for preset in presets {
            assert!(preset.inputs.validate().is_ok(), "{}", preset.name);
            assert!(!preset.description.is_empty());
        }
        let soft = resolve("paper-beams-soft").unwrap();
        assert_eq!(
            soft.inputs.get(Param::Beam(BeamParam::Stiffness)),
            Some(120.0)
        );
        for kind in ModelKind::ALL {
            assert_eq!(paper(kind).inputs, Inputs::paper(kind));
        }
    }

    /// Every file of `presets/` is bundled, once, by the problem its `model` names: a preset
    /// file a problem's folder forgets (or another problem's folder bundles) fails here.
    #[test]
    fn every_preset_file_is_bundled_by_its_own_problem() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/presets");
        let mut files: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter_map(|f| f.strip_suffix(".toml").map(str::to_string))
            .collect();
        files.sort();
        let mut bundled_names: Vec<String> = BUNDLED.iter().map(|(n, _)| n.to_string()).collect();
        bundled_names.sort();
        assert_eq!(files, bundled_names);
        macro_rules! owners {
            ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
                [$((ModelKind::$variant, crate::problems::$folder::BUNDLED_PRESETS)),+]
            };
        }
        // Each preset is one of the problems whose folder lists it (a folder that two lines name
        // lists its presets for both).
        let owners = microslip_core::with_problems!(owners);
        for (name, _) in BUNDLED.iter() {
            let kind = resolve(name).unwrap().inputs.kind();
            assert!(
                owners.iter().any(|(owner, presets)| *owner == kind
                    && presets.iter().any(|(listed, _)| listed == name)),
                "{name}"
            );
        }
    }

    #[test]
    fn listing_keeps_invalid_user_files_with_their_problem() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("b.toml"), "model = \"beam\"\nKT = -1\n").unwrap();
        std::fs::write(dir.path().join("a.toml"), "model = \"plate\"\n").unwrap();
        std::fs::write(dir.path().join("notes.txt"), "not a preset").unwrap();
        let rows = listing(Some(dir.path()));
        let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
        // The bundled presets in the registry's order, then the user's, by name.
        let mut expected: Vec<&str> = BUNDLED.iter().map(|(name, _)| *name).collect();
        expected.extend(["a", "b"]);
        assert_eq!(names, expected);
        assert!(rows[BUNDLED.len() + 1].preset.as_ref().unwrap_err().line == Some(2));
        assert_eq!(listing(None).len(), BUNDLED.len());
    }

    #[test]
    fn a_user_file_named_like_a_bundled_preset_is_listed_shadowed_and_never_loaded() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("paper-beams.toml"),
            "model = \"beam\"\nKT = 1\n",
        )
        .unwrap();
        let rows = listing(Some(dir.path()));
        let user: Vec<&Listed> = rows.iter().filter(|r| r.origin == "user").collect();
        assert_eq!(user.len(), 1);
        assert!(user[0].shadowed);
        assert_eq!(
            user[0].preset.as_ref().map_err(ToString::to_string),
            Err(
                "named like the bundled preset 'paper-beams', which wins (`--preset paper-beams`, \
                 the picker): rename the file to use it by name"
                    .to_string()
            )
        );
        assert!(
            rows.iter()
                .filter(|r| r.origin == "bundled")
                .all(|r| !r.shadowed)
        );
        // The one rule: by name, the bundled preset.
        assert_eq!(
            resolve("paper-beams")
                .unwrap()
                .inputs
                .get(Param::Beam(BeamParam::Stiffness)),
            Some(600.0)
        );
    }
}
