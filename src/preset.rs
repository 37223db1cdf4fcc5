//! Presets: named parameter sets in TOML, bundled in the binary or saved by the user.
//!
//! One file per preset, flat keys named as users write them (`L b h E P mu KT F` for beams,
//! `L tp E nu mu P KT` for the plate), plus `model` and an optional `description`. Missing parameter
//! keys take the paper's value for that model, so a preset can say only what it changes; unknown keys
//! are errors (a typo such as `Kt` must not silently fall back to a default).
//!
//! The same key table drives `--set KEY=VALUE`, so the CLI, the TUI and files accept exactly the same
//! names.

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::model::validate::ParamError;
use crate::{PlateParams, SqueezedPlate, TipForce, TwinBeams, TwinBeamsParams};

/// Which benchmark a parameter set describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelKind {
    /// Twin cantilever beams (paper section 2.1).
    Beam,
    /// Squeezed plate (paper section 2.2).
    Plate,
}

impl ModelKind {
    /// The `model = "..."` value in preset files.
    pub fn name(self) -> &'static str {
        match self {
            ModelKind::Beam => "beam",
            ModelKind::Plate => "plate",
        }
    }

    /// Parameter keys in display order, with their units and meaning.
    pub fn keys(self) -> &'static [ParamKey] {
        match self {
            ModelKind::Beam => BEAM_KEYS,
            ModelKind::Plate => PLATE_KEYS,
        }
    }

    fn key_list(self) -> String {
        self.keys()
            .iter()
            .map(|k| k.name)
            .collect::<Vec<_>>()
            .join(" ")
    }
}

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// A parameter's key, unit and short meaning, as shown to users.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamKey {
    /// Key in preset files and `--set`.
    pub name: &'static str,
    /// Unit, `-` for dimensionless.
    pub unit: &'static str,
    /// What the value means.
    pub meaning: &'static str,
}

const fn key(name: &'static str, unit: &'static str, meaning: &'static str) -> ParamKey {
    ParamKey {
        name,
        unit,
        meaning,
    }
}

const BEAM_KEYS: &[ParamKey] = &[
    key("L", "mm", "beam length"),
    key("b", "mm", "beam width"),
    key("h", "mm", "half height (each beam is 2h high)"),
    key("E", "MPa", "Young's modulus"),
    key("P", "MPa", "interface pressure"),
    key("mu", "-", "friction coefficient"),
    key("KT", "MPa/mm", "tangential contact stiffness"),
    key("F", "N", "tip force on each beam"),
];

const PLATE_KEYS: &[ParamKey] = &[
    key("L", "mm", "half-length of the plate"),
    key("tp", "mm", "plate thickness"),
    key("E", "MPa", "Young's modulus"),
    key("nu", "-", "Poisson ratio"),
    key("mu", "-", "friction coefficient"),
    key("P", "MPa", "applied pressure"),
    key("KT", "MPa/mm", "tangential contact stiffness"),
];

/// Unvalidated inputs of one model, as read from a preset, flags or key presses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Inputs {
    /// Twin beams and the tip force F (N).
    Beam {
        /// Structure and interface.
        structure: TwinBeamsParams,
        /// Tip force on each beam (N).
        force: f64,
    },
    /// Squeezed plate.
    Plate(PlateParams),
}

/// Validated inputs: what the physics core accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Model {
    /// Twin beams at a tip force.
    Beam {
        /// The beams.
        beams: TwinBeams,
        /// The tip force.
        force: TipForce,
    },
    /// Squeezed plate.
    Plate(SqueezedPlate),
}

/// The interface data common to both models: what the K_T comparisons need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceData {
    /// Length L (beam length or plate half-length) (mm).
    pub length: f64,
    /// Friction coefficient (-).
    pub friction: f64,
    /// Contact pressure (MPa).
    pub pressure: f64,
    /// Young's modulus (MPa).
    pub modulus: f64,
    /// Tangential stiffness (MPa/mm).
    pub stiffness: f64,
    /// Poisson ratio, where the model has one.
    pub poisson: Option<f64>,
}

impl Model {
    /// The model's interface data.
    pub fn interface(&self) -> InterfaceData {
        match self {
            Model::Beam { beams, .. } => {
                let p = beams.params();
                InterfaceData {
                    length: p.length,
                    friction: p.friction,
                    pressure: p.pressure,
                    modulus: p.youngs_modulus,
                    stiffness: p.tangential_stiffness,
                    poisson: None,
                }
            }
            Model::Plate(plate) => {
                let p = plate.params();
                InterfaceData {
                    length: p.half_length,
                    friction: p.friction,
                    pressure: p.pressure,
                    modulus: p.youngs_modulus,
                    stiffness: p.tangential_stiffness,
                    poisson: Some(p.poisson),
                }
            }
        }
    }
}

impl Inputs {
    /// The paper's data set for `kind` (beams at F = 100 N).
    pub fn paper(kind: ModelKind) -> Inputs {
        match kind {
            ModelKind::Beam => Inputs::Beam {
                structure: TwinBeamsParams::PAPER,
                force: 100.0,
            },
            ModelKind::Plate => Inputs::Plate(PlateParams::PAPER),
        }
    }

    /// Which model these inputs are for.
    pub fn kind(&self) -> ModelKind {
        match self {
            Inputs::Beam { .. } => ModelKind::Beam,
            Inputs::Plate(_) => ModelKind::Plate,
        }
    }

    fn slot(&mut self, key: &str) -> Option<&mut f64> {
        Some(match (self, key) {
            (Inputs::Beam { structure: s, .. }, "L") => &mut s.length,
            (Inputs::Beam { structure: s, .. }, "b") => &mut s.width,
            (Inputs::Beam { structure: s, .. }, "h") => &mut s.half_height,
            (Inputs::Beam { structure: s, .. }, "E") => &mut s.youngs_modulus,
            (Inputs::Beam { structure: s, .. }, "P") => &mut s.pressure,
            (Inputs::Beam { structure: s, .. }, "mu") => &mut s.friction,
            (Inputs::Beam { structure: s, .. }, "KT") => &mut s.tangential_stiffness,
            (Inputs::Beam { force, .. }, "F") => force,
            (Inputs::Plate(p), "L") => &mut p.half_length,
            (Inputs::Plate(p), "tp") => &mut p.thickness,
            (Inputs::Plate(p), "E") => &mut p.youngs_modulus,
            (Inputs::Plate(p), "nu") => &mut p.poisson,
            (Inputs::Plate(p), "mu") => &mut p.friction,
            (Inputs::Plate(p), "P") => &mut p.pressure,
            (Inputs::Plate(p), "KT") => &mut p.tangential_stiffness,
            _ => return None,
        })
    }

    /// The value of a parameter key, or `None` for a key this model does not have.
    pub fn get(&self, key: &str) -> Option<f64> {
        let mut copy = *self;
        copy.slot(key).map(|v| *v)
    }

    /// Sets one parameter without validating its range (see [`Inputs::validate`]).
    pub fn set(&mut self, key: &str, value: f64) -> Result<(), PresetError> {
        let kind = self.kind();
        let slot = self.slot(key).ok_or_else(|| PresetError::UnknownKey {
            key: key.to_string(),
            model: kind,
            allowed: kind.key_list(),
        })?;
        *slot = value;
        Ok(())
    }

    /// Applies `KEY=VALUE` as typed on the command line.
    pub fn apply_assignment(&mut self, assignment: &str) -> Result<(), PresetError> {
        let (key, value) = assignment
            .split_once('=')
            .ok_or_else(|| PresetError::Assignment {
                text: assignment.to_string(),
            })?;
        let (key, value) = (key.trim(), value.trim());
        let kind = self.kind();
        if self.get(key).is_none() {
            return Err(PresetError::UnknownKey {
                key: key.to_string(),
                model: kind,
                allowed: kind.key_list(),
            });
        }
        let number = parse_number(value).ok_or_else(|| PresetError::NotANumber {
            key: key.to_string(),
            text: value.to_string(),
        })?;
        self.set(key, number)
    }

    /// Validates through the model's checked constructors.
    pub fn validate(&self) -> Result<Model, ParamError> {
        Ok(match *self {
            Inputs::Beam { structure, force } => Model::Beam {
                beams: TwinBeams::new(structure)?,
                force: TipForce::new(force)?,
            },
            Inputs::Plate(params) => Model::Plate(SqueezedPlate::new(params)?),
        })
    }

    /// Every out-of-range parameter, not only the first: each key is checked on its own against the
    /// paper's otherwise valid data set, so one bad value cannot hide another.
    pub fn all_param_errors(&self) -> Vec<ParamError> {
        let kind = self.kind();
        kind.keys()
            .iter()
            .filter_map(|k| {
                let mut probe = Inputs::paper(kind);
                probe.set(k.name, self.get(k.name)?).ok()?;
                probe.validate().err()
            })
            .collect()
    }
}

/// Parses a number as users type it: `1e6`, `600`, `0.3`; rejects NaN and infinities spelled out.
pub fn parse_number(text: &str) -> Option<f64> {
    let value: f64 = text.parse().ok()?;
    // "nan" and "inf" parse in Rust; they are never what a user means. Range checks catch the rest.
    if value.is_nan() || text.to_ascii_lowercase().contains("inf") {
        None
    } else {
        Some(value)
    }
}

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

impl fmt::Display for PresetSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PresetSource::Bundled => f.pad("bundled"),
            PresetSource::File(path) => f.pad(&path.display().to_string()),
        }
    }
}

/// What can go wrong with a preset or an assignment. Messages name the key, the value and what is
/// allowed; `origin` and `line` locate problems inside files.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PresetError {
    /// A key the model does not have.
    #[error("unknown key '{key}' for the {model} model (allowed: {allowed})")]
    UnknownKey {
        /// The key as written.
        key: String,
        /// The model.
        model: ModelKind,
        /// Space-separated allowed keys.
        allowed: String,
    },
    /// A value that is not a finite number.
    #[error("invalid value '{text}' for {key}: not a finite number")]
    NotANumber {
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
    /// A value out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// TOML syntax (the message carries line and column).
    #[error("{0}")]
    Syntax(String),
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

/// 1-based line on which `key` is assigned at the top level of `text`, if found.
fn line_of_key(text: &str, key: &str) -> Option<usize> {
    text.lines()
        .position(|line| {
            let line = line.trim_start();
            let rest = line
                .strip_prefix(key)
                .or_else(|| line.strip_prefix(&format!("\"{key}\"")));
            rest.is_some_and(|rest| rest.trim_start().starts_with('='))
        })
        .map(|i| i + 1)
}

impl Preset {
    /// Parses preset text, collecting every problem (for `microslip check`); the first one is enough
    /// for callers that only need to refuse.
    pub fn parse(text: &str, name: &str, source: PresetSource) -> Result<Preset, Vec<Located>> {
        let table: toml::Table = toml::from_str(text).map_err(|e| {
            let message = e.to_string();
            // toml's message starts with "TOML parse error at line L, column C" followed by an excerpt;
            // keep it on one line.
            let one_line = message
                .lines()
                .filter(|l| !l.trim().is_empty())
                .collect::<Vec<_>>();
            let summary = match (one_line.first(), one_line.last()) {
                (Some(first), Some(last)) if first != last => format!("{first}: {}", last.trim()),
                (Some(first), _) => first.to_string(),
                _ => "invalid TOML".to_string(),
            };
            vec![Located {
                line: None,
                error: PresetError::Syntax(summary),
            }]
        })?;
        let mut problems = Vec::new();
        let at = |key: &str| line_of_key(text, key);
        let kind = match table.get("model").map(|v| v.as_str()) {
            Some(Some("beam")) => ModelKind::Beam,
            Some(Some("plate")) => ModelKind::Plate,
            Some(other) => {
                let found =
                    other.map_or_else(|| "a non-string value".to_string(), |s| format!("'{s}'"));
                return Err(vec![Located {
                    line: at("model"),
                    error: PresetError::Model(format!(
                        "invalid model = {found}: must be \"beam\" or \"plate\""
                    )),
                }]);
            }
            None => {
                return Err(vec![Located {
                    line: None,
                    error: PresetError::Model(
                        "missing key 'model': must be \"beam\" or \"plate\"".to_string(),
                    ),
                }]);
            }
        };
        let mut inputs = Inputs::paper(kind);
        let mut description = String::new();
        for (key, value) in &table {
            match key.as_str() {
                "model" => {}
                "description" => match value.as_str() {
                    Some(text) => description = text.to_string(),
                    None => problems.push(Located {
                        line: at(key),
                        error: PresetError::NotANumber {
                            key: key.clone(),
                            text: value.to_string(),
                        },
                    }),
                },
                _ => {
                    let number = value
                        .as_float()
                        .or_else(|| value.as_integer().map(|i| i as f64));
                    let result = match number {
                        Some(n) if !n.is_nan() => inputs.set(key, n),
                        _ if inputs.get(key).is_none() => inputs.set(key, 0.0),
                        _ => Err(PresetError::NotANumber {
                            key: key.clone(),
                            text: value.to_string(),
                        }),
                    };
                    if let Err(error) = result {
                        problems.push(Located {
                            line: at(key),
                            error,
                        });
                    }
                }
            }
        }
        for error in inputs.all_param_errors() {
            problems.push(Located {
                line: at(error.field),
                error: PresetError::Param(error),
            });
        }
        if problems.is_empty() {
            Ok(Preset {
                name: name.to_string(),
                description,
                inputs,
                source,
            })
        } else {
            problems.sort_by_key(|p| p.line.unwrap_or(0));
            Err(problems)
        }
    }

    /// Reads and parses a preset file; the name is the file stem.
    pub fn load(path: &Path) -> Result<Preset, Vec<Located>> {
        let text = std::fs::read_to_string(path).map_err(|e| {
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
}

/// A preset file's text for `inputs` (what the TUI saves): every key, with units in comments.
pub fn to_toml(inputs: &Inputs, description: &str) -> String {
    let mut text = String::from("# microslip preset. Units: mm, N, MPa; KT in MPa/mm.\n");
    text.push_str(&format!(
        "description = {}\n",
        toml::Value::from(description)
    ));
    text.push_str(&format!("model = \"{}\"\n", inputs.kind().name()));
    for key in inputs.kind().keys() {
        let value = inputs.get(key.name).unwrap_or(f64::NAN);
        text.push_str(&format!(
            "{} = {value:?}  # {} ({})\n",
            key.name, key.meaning, key.unit
        ));
    }
    text
}

/// Why a preset could not be saved.
#[derive(Debug, Clone, PartialEq, Error)]
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
    /// No user preset directory (neither XDG_CONFIG_HOME nor HOME is set).
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

/// Saves `text` as `<dir>/<name>.toml` atomically: written to a temporary file in the same directory,
/// flushed, then renamed over the target, so a crash never leaves a half-written or lost preset. An
/// existing file is replaced only when `overwrite` is true.
pub fn save_atomic(
    dir: &Path,
    name: &str,
    text: &str,
    overwrite: bool,
) -> Result<PathBuf, SaveError> {
    let valid = !name.is_empty()
        && name.len() <= 64
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
    if !valid {
        return Err(SaveError::BadName(name.to_string()));
    }
    if BUNDLED.iter().any(|(bundled, _)| *bundled == name) {
        return Err(SaveError::Bundled(name.to_string()));
    }
    let target = dir.join(format!("{name}.toml"));
    if target.exists() && !overwrite {
        return Err(SaveError::Exists(name.to_string()));
    }
    let io_error = |path: &Path, e: std::io::Error| SaveError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    std::fs::create_dir_all(dir).map_err(|e| io_error(dir, e))?;
    let temporary = dir.join(format!(".{name}.toml.tmp-{}", std::process::id()));
    let written = (|| {
        use std::io::Write;
        let mut file = std::fs::File::create(&temporary)?;
        file.write_all(text.as_bytes())?;
        file.sync_all()
    })();
    if let Err(e) = written.and_then(|()| std::fs::rename(&temporary, &target)) {
        let _ = std::fs::remove_file(&temporary);
        return Err(io_error(&target, e));
    }
    Ok(target)
}

/// Presets embedded in the binary: (name, TOML text).
pub const BUNDLED: &[(&str, &str)] = &[
    ("paper-beams", include_str!("../presets/paper-beams.toml")),
    (
        "paper-beams-soft",
        include_str!("../presets/paper-beams-soft.toml"),
    ),
    ("paper-plate", include_str!("../presets/paper-plate.toml")),
];

/// The bundled presets, parsed.
pub fn bundled() -> Vec<Preset> {
    BUNDLED
        .iter()
        .filter_map(|(name, text)| Preset::parse(text, name, PresetSource::Bundled).ok())
        .collect()
}

/// `$XDG_CONFIG_HOME/microslip/presets`, else `$HOME/.config/microslip/presets`.
pub fn user_preset_dir() -> Option<PathBuf> {
    let config = std::env::var_os("XDG_CONFIG_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| {
            std::env::var_os("HOME")
                .filter(|v| !v.is_empty())
                .map(|home| PathBuf::from(home).join(".config"))
        })?;
    Some(config.join("microslip").join("presets"))
}

/// User presets (`*.toml` in [`user_preset_dir`]), sorted by name; unreadable files are returned as
/// errors so that a listing can show them rather than hide them.
pub fn user_presets() -> Vec<(PathBuf, Result<Preset, Vec<Located>>)> {
    let Some(dir) = user_preset_dir() else {
        return Vec::new();
    };
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|p| (p.clone(), Preset::load(&p)))
        .collect()
}

/// Resolves `--preset`: a path when it contains a path separator or ends in `.toml`, else a bundled
/// name, else a user preset of that name.
pub fn resolve(spec: &str) -> Result<Preset, PresetError> {
    let first = |mut problems: Vec<Located>| {
        let problem = problems.remove(0);
        match problem.line {
            Some(line) => {
                PresetError::Syntax(format!("preset '{spec}', line {line}: {}", problem.error))
            }
            None => match problem.error {
                PresetError::Io { .. } => problem.error,
                other => PresetError::Syntax(format!("preset '{spec}': {other}")),
            },
        }
    };
    if spec.contains(std::path::MAIN_SEPARATOR) || spec.contains('/') || spec.ends_with(".toml") {
        return Preset::load(Path::new(spec)).map_err(first);
    }
    if let Some((name, text)) = BUNDLED.iter().find(|(name, _)| *name == spec) {
        return Preset::parse(text, name, PresetSource::Bundled).map_err(first);
    }
    match user_preset_dir().map(|dir| dir.join(format!("{spec}.toml"))) {
        Some(path) if path.exists() => Preset::load(&path).map_err(first),
        _ => Err(PresetError::NotFound {
            name: spec.to_string(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundled_presets_parse_and_validate() {
        let presets = bundled();
        assert_eq!(presets.len(), BUNDLED.len());
        for preset in presets {
            assert!(preset.inputs.validate().is_ok(), "{}", preset.name);
            assert!(!preset.description.is_empty());
        }
        let soft = resolve("paper-beams-soft").unwrap();
        assert_eq!(soft.inputs.get("KT"), Some(120.0));
    }

    #[test]
    fn every_problem_is_reported_with_its_line() {
        let text = "model = \"beam\"\nKt = 5\nL = -1\nmu = \"high\"\nE = 0\n";
        let problems = Preset::parse(text, "x", PresetSource::Bundled).unwrap_err();
        let shown: Vec<String> = problems.iter().map(ToString::to_string).collect();
        assert_eq!(shown.len(), 4, "{shown:?}");
        assert!(shown[0].starts_with(
            "line 2: unknown key 'Kt' for the beam model (allowed: L b h E P mu KT F)"
        ));
        assert!(
            shown[1].starts_with("line 3: invalid L = -1: must be > 0"),
            "{shown:?}"
        );
        assert!(
            shown[2].starts_with("line 4: invalid value '\"high\"' for mu"),
            "{shown:?}"
        );
        assert!(shown[3].starts_with("line 5: invalid E = 0"), "{shown:?}");
    }

    #[test]
    fn syntax_errors_carry_line_and_column() {
        let problems =
            Preset::parse("model = \"beam\"\nL = = 3\n", "x", PresetSource::Bundled).unwrap_err();
        let message = problems[0].to_string();
        assert!(message.contains("line 2, column"), "{message}");
        assert!(!message.contains('\n'));
    }

    #[test]
    fn model_must_be_named() {
        let problems = Preset::parse("L = 3\n", "x", PresetSource::Bundled).unwrap_err();
        assert!(problems[0].to_string().contains("missing key 'model'"));
        let problems =
            Preset::parse("model = \"shell\"\n", "x", PresetSource::Bundled).unwrap_err();
        assert_eq!(
            problems[0].to_string(),
            "line 1: invalid model = 'shell': must be \"beam\" or \"plate\""
        );
    }

    #[test]
    fn assignments_check_key_and_number() {
        let mut inputs = Inputs::paper(ModelKind::Plate);
        inputs.apply_assignment("nu=0.25").unwrap();
        assert_eq!(inputs.get("nu"), Some(0.25));
        inputs.apply_assignment(" KT = 1e3 ").unwrap();
        assert_eq!(inputs.get("KT"), Some(1e3));
        let err = inputs.apply_assignment("F=3").unwrap_err().to_string();
        assert_eq!(
            err,
            "unknown key 'F' for the plate model (allowed: L tp E nu mu P KT)"
        );
        let err = inputs.apply_assignment("E=abc").unwrap_err().to_string();
        assert_eq!(err, "invalid value 'abc' for E: not a finite number");
        assert!(inputs.apply_assignment("E=NaN").is_err());
        assert!(inputs.apply_assignment("E=inf").is_err());
        assert!(inputs.apply_assignment("E").is_err());
    }

    #[test]
    fn saved_presets_round_trip_and_are_never_clobbered_silently() {
        let dir = tempfile::tempdir().unwrap();
        let mut inputs = Inputs::paper(ModelKind::Beam);
        inputs.set("KT", 123.456).unwrap();
        let text = to_toml(&inputs, "bench \"A\"");
        let path = save_atomic(dir.path(), "bench-a", &text, false).unwrap();
        let loaded = Preset::load(&path).unwrap();
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
        assert_eq!(Preset::load(&path).unwrap().inputs.get("KT"), Some(600.0));
        assert!(matches!(
            save_atomic(dir.path(), "../evil", "x", false),
            Err(SaveError::BadName(_))
        ));
        assert!(matches!(
            save_atomic(dir.path(), "paper-beams", "x", false),
            Err(SaveError::Bundled(_))
        ));
        let leftovers: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .filter_map(Result::ok)
            .filter(|e| e.file_name().to_string_lossy().contains(".tmp-"))
            .collect();
        assert!(leftovers.is_empty());
    }

    #[test]
    fn missing_keys_fall_back_to_the_paper_values() {
        let preset =
            Preset::parse("model = \"plate\"\nKT = 10\n", "x", PresetSource::Bundled).unwrap();
        assert_eq!(preset.inputs.get("tp"), Some(0.2));
        assert_eq!(preset.inputs.get("KT"), Some(10.0));
    }
}
