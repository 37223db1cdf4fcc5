//! Which cases a suite runs: `--cases NAME,...` (a problem's key means that problem's bundled
//! presets, from the registry; any other name is a preset's) or `--cases FILE.toml`, a user's list
//! of cases:
//!
//! ```toml
//! [[case]]
//! name = "pad-stiff"              # the folder and scorecard name (letters, digits, - _ .)
//! preset = "cylinder-steel-pad"   # a bundled or user preset, or a path
//! set = ["KT=1e6"]                # optional: assignments as --set takes them
//! meshes = ["coarse", "fine"]     # optional: the rungs (default: the suite's ladder)
//! loads = [150, 300]              # optional: the load steps, as deck --loads takes them
//! converged_within = 0.003        # optional: the largest uncertainty accepted, a fraction
//! ```

use std::path::Path;

use serde::Deserialize;

use super::{Case, Ladder};
use crate::fe::deck::DeckMesh;
use crate::fe::face::deck_face;
use crate::preset;
use crate::problems::ModelKind;

/// The largest case file read (it is a short list).
const MAX_CASES_FILE: crate::file::Size = crate::file::Size(1 << 20);

/// Why a list of cases was refused: the name, the value, what is allowed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("--cases: {0}")]
pub struct CasesError(pub String);

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseFile {
    case: Vec<CaseEntry>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseEntry {
    name: String,
    preset: String,
    #[serde(default)]
    set: Vec<String>,
    meshes: Option<Vec<String>>,
    loads: Option<Vec<f64>>,
    converged_within: Option<f64>,
}

/// The cases `spec` names on `ladder`; `None`: every problem's bundled presets.
///
/// # Errors
/// An unknown name, an unreadable or malformed file, a bad case name or mesh, a name twice.
pub fn resolve(spec: Option<&str>, ladder: Ladder) -> Result<Vec<Case>, CasesError> {
    let cases = match spec {
        Some(file) if file.ends_with(".toml") => from_file(Path::new(file), ladder)?,
        Some(names) => {
            let mut cases = Vec::new();
            for name in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
                cases.extend(named(name, ladder)?);
            }
            cases
        }
        // Every problem whose decks are written: a problem without one has nothing to run.
        None => ModelKind::ALL
            .iter()
            .filter(|kind| deck_face(**kind).no_deck().is_none())
            .flat_map(|kind| bundled_cases(*kind, ladder))
            .collect(),
    };
    if cases.is_empty() {
        return Err(CasesError("no case given".to_string()));
    }
    if let Some((case, why)) = cases
        .iter()
        .find_map(|c| deck_face(c.kind).no_deck().map(|why| (c, why)))
    {
        return Err(CasesError(format!(
            "the case '{}' cannot be run: {why}",
            crate::report::sanitize(&case.name)
        )));
    }
    for (n, case) in cases.iter().enumerate() {
        if cases[..n].iter().any(|c| c.name == case.name) {
            return Err(CasesError(format!(
                "the case '{}' is named twice; each case's runs have a folder of its name",
                crate::report::sanitize(&case.name)
            )));
        }
    }
    Ok(cases)
}

/// The bundled presets of `kind`, one case each.
fn bundled_cases(kind: ModelKind, ladder: Ladder) -> Vec<Case> {
    preset::bundled()
        .into_iter()
        .filter(|p| p.inputs.kind() == kind)
        .map(|p| Case {
            name: p.name.clone(),
            kind,
            preset: p.name,
            assignments: Vec::new(),
            meshes: ladder.meshes().to_vec(),
            loads: None,
            converged_within: None,
        })
        .collect()
}

/// A name of `--cases`: a problem's key (its bundled presets) or a preset's name.
fn named(name: &str, ladder: Ladder) -> Result<Vec<Case>, CasesError> {
    if let Ok(kind) = name.parse::<ModelKind>() {
        return Ok(bundled_cases(kind, ladder));
    }
    let found = preset::resolve(name).map_err(|e| {
        let keys: Vec<&str> = ModelKind::ALL.iter().map(|k| k.name()).collect();
        CasesError(format!(
            "'{}' is neither a problem ({}) nor a preset: {e}",
            crate::report::sanitize(name),
            keys.join(", ")
        ))
    })?;
    checked_name(name)?;
    Ok(vec![Case {
        name: name.to_string(),
        kind: found.inputs.kind(),
        preset: name.to_string(),
        assignments: Vec::new(),
        meshes: ladder.meshes().to_vec(),
        loads: None,
        converged_within: None,
    }])
}

/// The cases of a TOML file.
fn from_file(path: &Path, ladder: Ladder) -> Result<Vec<Case>, CasesError> {
    let shown = path.display().to_string();
    let text = crate::file::read_capped(
        path,
        MAX_CASES_FILE,
        "a list of cases",
        crate::file::Kinds::RegularOnly,
    )
    .map_err(|e| CasesError(format!("{shown}: {e}")))?;
    let file: CaseFile =
        toml::from_str(&text).map_err(|e| CasesError(format!("{shown}: {}", e.message())))?;
    file.case
        .into_iter()
        .map(|entry| {
            checked_name(&entry.name)?;
            let found = preset::resolve(&entry.preset)
                .map_err(|e| CasesError(format!("{shown}, case {}: {e}", entry.name)))?;
            let meshes = match entry.meshes {
                None => ladder.meshes().to_vec(),
                Some(names) => mesh_rungs(&names)
                    .map_err(|why| CasesError(format!("{shown}, case {}: {why}", entry.name)))?,
            };
            if let Some(within) = entry.converged_within
                && !(within > 0.0 && within < 1.0)
            {
                return Err(CasesError(format!(
                    "{shown}, case {}: converged_within = {within}: expected a fraction between 0 \
                     and 1 (0.003 is 0.3 %)",
                    entry.name
                )));
            }
            Ok(Case {
                name: entry.name,
                kind: found.inputs.kind(),
                preset: entry.preset,
                assignments: entry.set,
                meshes,
                loads: entry.loads,
                converged_within: entry.converged_within,
            })
        })
        .collect()
}

/// A case's mesh rungs: known names, coarsest first, each once.
fn mesh_rungs(names: &[String]) -> Result<Vec<DeckMesh>, String> {
    let meshes = names
        .iter()
        .map(|n| {
            DeckMesh::from_name(n).ok_or_else(|| {
                format!(
                    "meshes = '{}': expected coarse, fine or finest",
                    crate::report::sanitize(n)
                )
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    if meshes.is_empty()
        || meshes
            .windows(2)
            .any(|w| w[0].refinement() >= w[1].refinement())
    {
        return Err(format!(
            "meshes = [{}]: give at least one, coarsest first, each once",
            names.join(", ")
        ));
    }
    Ok(meshes)
}

/// A case's name must be a plain folder name.
fn checked_name(name: &str) -> Result<(), CasesError> {
    let plain = !name.is_empty()
        && name.len() <= 64
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
    if plain {
        Ok(())
    } else {
        Err(CasesError(format!(
            "case name '{}': use 1 to 64 letters, digits, '-', '_' or '.', not starting with '.' \
             (it names the case's folder)",
            crate::report::sanitize(name)
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A problem's key means its bundled presets; every problem with a deck is in the default
    /// suite, and a problem without one (the twisted press fit) is left out of it and refused by
    /// name, with why.
    #[test]
    fn a_problem_s_key_means_its_bundled_presets() {
        let decked = |kind: &ModelKind| deck_face(*kind).no_deck().is_none();
        for kind in ModelKind::ALL.into_iter().filter(|k| !decked(k)) {
            let refused = resolve(Some(kind.name()), Ladder::Quick).unwrap_err().0;
            assert!(refused.contains("cannot be run") && refused.contains("no CalculiX deck"));
        }
        for kind in ModelKind::ALL.into_iter().filter(decked) {
            let cases = resolve(Some(kind.name()), Ladder::Quick).unwrap();
            let bundled: Vec<String> = preset::bundled()
                .into_iter()
                .filter(|p| p.inputs.kind() == kind)
                .map(|p| p.name)
                .collect();
            let names: Vec<String> = cases.iter().map(|c| c.name.clone()).collect();
            assert_eq!(names, bundled, "{kind}");
            assert!(cases.iter().all(|c| c.kind == kind && c.meshes.len() == 2));
        }
        let all = resolve(None, Ladder::Full).unwrap();
        let runnable = preset::bundled()
            .into_iter()
            .filter(|p| decked(&p.inputs.kind()))
            .count();
        assert_eq!(all.len(), runnable);
        assert!(all.iter().all(|c| decked(&c.kind)));
    }

    #[test]
    fn a_case_file_names_presets_assignments_and_rungs() {
        let dir = tempfile::tempdir().unwrap();
        let bundled = preset::bundled().remove(0);
        let path = dir.path().join("cases.toml");
        std::fs::write(
            &path,
            format!(
                "[[case]]\nname = \"a\"\npreset = \"{}\"\nset = [\"mu=0.2\"]\n\
                 meshes = [\"fine\", \"finest\"]\nloads = [1, 2.5]\nconverged_within = 0.003\n",
                bundled.name
            ),
        )
        .unwrap();
        let cases = resolve(path.to_str(), Ladder::Full).unwrap();
        assert_eq!(cases.len(), 1);
        assert_eq!(cases[0].meshes, [DeckMesh::Fine, DeckMesh::Finest]);
        assert_eq!(cases[0].assignments, ["mu=0.2"]);
        assert_eq!(cases[0].loads, Some(vec![1.0, 2.5]));
        assert_eq!(cases[0].converged_within, Some(0.003));
        assert_eq!(cases[0].kind, bundled.inputs.kind());
        for (bad, says) in [
            ("name = \"../x\"", "case name"),
            (
                "name = \"a\"\nmeshes = [\"fine\", \"coarse\"]",
                "coarsest first",
            ),
            ("name = \"a\"\nmeshes = [\"huge\"]", "expected coarse"),
            (
                "name = \"a\"\nconverged_within = 0.0",
                "converged_within = 0: expected a fraction between 0 and 1",
            ),
            (
                "name = \"a\"\nconverged_within = 3.0",
                "converged_within = 3: expected a fraction",
            ),
            (
                "name = \"a\"\nconverged_within = nan",
                "converged_within = NaN: expected a fraction",
            ),
        ] {
            std::fs::write(
                &path,
                format!("[[case]]\n{bad}\npreset = \"{}\"\n", bundled.name),
            )
            .unwrap();
            let e = resolve(path.to_str(), Ladder::Full).unwrap_err();
            assert!(e.0.contains(says), "{bad}: {e}");
        }
        let e = resolve(Some("no-such-thing"), Ladder::Full).unwrap_err();
        assert!(e.0.contains("neither a problem"), "{e}");
        let twice = format!("{0},{0}", bundled.name);
        assert!(
            resolve(Some(&twice), Ladder::Full)
                .unwrap_err()
                .0
                .contains("twice")
        );
    }
}
