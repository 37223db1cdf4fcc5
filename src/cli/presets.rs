//! `presets` and `check`: the bundled presets and checking preset files.

use super::*;

pub(super) fn check(out: &mut impl Write, files: &[PathBuf]) -> Result<(), CliError> {
    let mut failed = 0;
    // Paths, descriptions and the values quoted in problems come from users: every line is
    // sanitized before it reaches the terminal.
    let mut say = |line: String| writeln!(out, "{}", report::sanitize(&line));
    for given in files {
        // A name, as --preset takes it: no file of that name here, no folder, no `.toml`.
        let spec = given.to_string_lossy();
        let path = if given.exists() || spec.contains('/') || spec.ends_with(".toml") {
            given.clone()
        } else if preset::is_bundled(&spec) {
            let p = preset::resolve(&spec)?;
            say(format!(
                "{spec}: ok (bundled {} preset: {})",
                p.inputs.kind(),
                p.description
            ))?;
            continue;
        } else {
            match preset::user_preset_dir().map(|dir| dir.join(format!("{spec}.toml"))) {
                Some(file) if file.exists() => file,
                dir => {
                    failed += 1;
                    let folder = dir
                        .and_then(|f| f.parent().map(|d| d.display().to_string()))
                        .unwrap_or_else(|| "none: no configuration folder".to_string());
                    say(format!(
                        "{spec}: no such file, and no preset of that name (bundled: {}; user presets in {folder})",
                        preset::bundled_names().join(" ")
                    ))?;
                    continue;
                }
            }
        };
        let path = &path;
        match preset::store::load(path) {
            Ok(p) => {
                let PresetSource::File(path) = &p.source else {
                    continue;
                };
                let description = if p.description.is_empty() {
                    "no description"
                } else {
                    &p.description
                };
                match p.inputs.validate() {
                    Ok(_) => say(format!(
                        "{}: ok ({} preset: {description})",
                        path.display(),
                        p.inputs.kind()
                    ))?,
                    // A value the file leaves at its default is refused with the others.
                    Err(error) => {
                        failed += 1;
                        say(format!(
                            "{}: {error}; {} is not in the file, so its default was used: give it",
                            path.display(),
                            error.field
                        ))?;
                    }
                }
            }
            Err(problems) => {
                failed += 1;
                for problem in problems {
                    say(format!("{}: {problem}", path.display()))?;
                }
            }
        }
        // A warning, not a problem: the file is fine, only its name loses to a bundled preset.
        if let Some(name) = path.file_stem().and_then(|s| s.to_str())
            && preset::is_bundled(name)
        {
            let warning = PresetError::Shadowed {
                name: name.to_string(),
            };
            say(format!("{}: warning: {warning}", path.display()))?;
        }
    }
    if failed > 0 {
        Err(CliError::CheckFailed(failed))
    } else {
        Ok(())
    }
}
