//! The preset listing of `microslip presets`: bundled then user presets, invalid files shown with
//! their first problem, and where user presets live.

use std::fmt::Write;
use std::path::Path;

use super::sanitize;
use crate::preset::Listed;

/// The listing as text; `user_dir` is where user presets are looked for (`None`: no such folder).
pub fn listing(rows: &[Listed], user_dir: Option<&Path>) -> String {
    let mut out = String::new();
    // The model column as wide as the longest problem key (and its heading); the name column as
    // the longest name, 20 at least, so that every row's columns line up.
    let width = crate::problems::ModelKind::key_width().max("model".len());
    let names = rows
        .iter()
        .map(|row| sanitize(&row.name).chars().count())
        .max()
        .unwrap_or(0)
        .max(20);
    let _ = writeln!(
        out,
        "{:<names$} {:<width$} {:<8} description",
        "name", "model", "source"
    );
    for row in rows {
        // Names come from file names and descriptions from the files: either may hold anything.
        let name = sanitize(&row.name);
        let _ = match &row.preset {
            Ok(p) => writeln!(
                out,
                "{:<names$} {:<width$} {:<8} {}",
                name,
                p.inputs.kind().name(),
                row.origin,
                sanitize(&p.description)
            ),
            Err(warning) if row.shadowed => writeln!(
                out,
                "{:<names$} {:<width$} {:<8} WARNING: {}",
                name,
                "?",
                row.origin,
                sanitize(&warning.to_string()),
            ),
            Err(problem) => {
                let file = user_dir.map_or_else(
                    || format!("{}.toml", row.name),
                    |dir| dir.join(format!("{}.toml", row.name)).display().to_string(),
                );
                writeln!(
                    out,
                    "{:<names$} {:<width$} {:<8} INVALID: {} (run `microslip check {}`)",
                    name,
                    "?",
                    row.origin,
                    sanitize(&problem.to_string()),
                    sanitize(&file),
                )
            }
        };
    }
    let _ = match user_dir {
        Some(dir) => writeln!(
            out,
            "\nuser presets: {}",
            sanitize(&dir.display().to_string())
        ),
        None => writeln!(
            out,
            "\nuser presets: none (no configuration directory is known for this user)"
        ),
    };
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset;

    #[test]
    fn invalid_files_are_listed_with_their_problem_and_how_to_check_them() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("bad.toml"), "model = \"beam\"\nKT = -3\n").unwrap();
        let text = listing(&preset::listing(Some(dir.path())), Some(dir.path()));
        assert!(text.starts_with("name "));
        // The source column lines up on every row, whatever the longest problem key.
        let column = |line: &str| line.find(" bundled ").or_else(|| line.find(" user "));
        let header = text.lines().next().unwrap().find(" source ").unwrap();
        for line in text.lines().skip(1).filter(|l| column(l).is_some()) {
            assert_eq!(column(line), Some(header), "{line}");
        }
        let beams = text
            .lines()
            .find(|l| l.starts_with("paper-beams "))
            .unwrap();
        assert_eq!(
            beams.split_whitespace().take(3).collect::<Vec<_>>(),
            ["paper-beams", "beam", "bundled"],
            "{text}"
        );
        // The longest bundled name (`pressfit-ccx98-torque`, 21 characters) still leaves a
        // space before its model: no column runs into the next.
        let torque = text
            .lines()
            .find(|l| l.starts_with("pressfit-ccx98-torque "))
            .unwrap();
        assert_eq!(column(torque), Some(header), "{torque}");
        let bad = text.lines().find(|l| l.starts_with("bad ")).unwrap();
        assert!(bad.contains("INVALID: line 2: invalid KT = -3"), "{bad}");
        assert!(bad.contains("microslip check "), "{bad}");
        assert!(text.ends_with(&format!("user presets: {}\n", dir.path().display())));
    }

    #[test]
    fn a_user_file_named_like_a_bundled_preset_gets_a_warning_not_invalid() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("paper-plate.toml"), "model = \"beam\"\n").unwrap();
        let text = listing(&preset::listing(Some(dir.path())), Some(dir.path()));
        let shadowed: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with("paper-plate ") && l.contains(" user "))
            .collect();
        assert_eq!(shadowed.len(), 1, "{text}");
        assert!(
            shadowed[0]
                .contains("WARNING: named like the bundled preset 'paper-plate', which wins"),
            "{text}"
        );
        assert!(!text.contains("INVALID"), "{text}");
    }

    #[test]
    fn control_characters_in_names_and_descriptions_are_shown_escaped() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("evil\u{1b}[2J.toml"),
            "model = \"beam\"\ndescription = \"ring \\u0007 clear \\u001b[2J\\nfake line\"\n",
        )
        .unwrap();
        std::fs::write(
            dir.path().join("bad\u{9b}.toml"),
            "model = \"beam\"\nKT = -3\n",
        )
        .unwrap();
        let text = listing(&preset::listing(Some(dir.path())), Some(dir.path()));
        assert!(
            !text.chars().any(|c| c.is_control() && c != '\n'),
            "{text:?}"
        );
        assert!(
            text.contains("evil\\x1b[2J") && text.contains("ring \\x07 clear \\x1b[2J\\nfake line"),
            "{text}"
        );
        assert!(text.contains("bad\\u{9b}"), "{text}");
        // One line per preset, the header and the folder: the newline did not split a row.
        assert_eq!(text.lines().count(), 1 + preset::bundled().len() + 2 + 2);
    }
}
