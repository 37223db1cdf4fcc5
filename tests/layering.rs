//! The crate's layers, read from its source: every `crate::` path in shipped code (unit-test
//! modules excluded) must point to a lower layer, never up or sideways; a problem's closed forms
//! and its discretized solvers never import each other; and no problem imports another. The
//! layers, lowest first (the crate docs in src/lib.rs say why each sits where it does):
//!
//! ```text
//! kernel, file <- numeric <- problems <- study, fit, verify, preset <- measured <- fe <- chart <- report <- faces <- suite, tui <- cli
//! ```

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Each top-level module and its layer: a module may use only modules of a strictly lower layer.
const LAYERS: &[(&str, u8)] = &[
    ("kernel", 0),
    ("file", 0),
    ("numeric", 1),
    ("problems", 2),
    ("study", 3),
    ("fit", 3),
    ("verify", 3),
    ("preset", 3),
    ("measured", 4),
    // The core's prelude re-exports from every core layer; nothing in either crate uses it.
    ("prelude", 4),
    ("fe", 5),
    ("chart", 6),
    ("report", 7),
    // The application's folder of each problem (`src/problems/<name>/`): its charts, report and
    // deck, written against the traits of `chart`, `report` and `fe`, reached by the TUI and the
    // command line only through them (src/problems/mod.rs says why a problem has two folders).
    ("faces", 8),
    // `microslip suite`'s engine: cases, ladders, the executors and the scorecard, over the
    // problems' faces (`report::face::for_problem`); the command line drives it.
    ("suite", 9),
    ("tui", 9),
    ("cli", 10),
];

/// The files of a problem that hold its closed forms, and those that hold its discretized
/// solvers: neither side may name the other, so that their agreement proves something.
const CLOSED_FORM_SIDE: &[&str] = &["closed_form", "cycle", "validity"];
const DISCRETIZED_SIDE: &[&str] = &["discretized", "continuum"];

/// One source file: its path below `src/` and its code (comments and unit-test modules removed).
struct Source {
    path: String,
    code: String,
}

fn layer_of(module: &str) -> Option<u8> {
    LAYERS
        .iter()
        .find(|(name, _)| *name == module)
        .map(|&(_, layer)| layer)
}

/// The top-level module a file belongs to (`problems/plate/continuum.rs` -> `problems`).
fn top_module(path: &str) -> &str {
    let first = path.split('/').next().unwrap_or(path);
    first.strip_suffix(".rs").unwrap_or(first)
}

/// The code without comments (doc links are not dependencies) and without `#[cfg(test)]`
/// modules (a unit test may build its fixture from any layer).
fn shipped_code(text: &str) -> String {
    let mut code = String::new();
    let mut in_tests = false;
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        if line.trim() == "#[cfg(test)]"
            && lines
                .peek()
                .is_some_and(|next| next.trim_start().starts_with("mod "))
        {
            in_tests = true;
        }
        if in_tests {
            continue;
        }
        let without_comment = match line.find("//") {
            Some(at) => &line[..at],
            None => line,
        };
        code.push_str(without_comment);
        code.push('\n');
    }
    code
}

/// The items `lib.rs` re-exports at the crate root and the top-level module each comes from, so
/// that `use crate::{TwinBeams}` counts as an edge to `problems`.
fn root_reexports(lib: &str) -> BTreeMap<String, String> {
    let mut items = BTreeMap::new();
    let code = shipped_code(lib);
    for statement in code.split(';') {
        let statement = statement.trim();
        let Some(path) = statement.strip_prefix("pub use ") else {
            continue;
        };
        let module = path.split("::").next().unwrap_or_default().to_string();
        // `pub use microslip_core::{kernel, problems}`: the core's modules under their own names.
        if module == "microslip_core" {
            let list = path.trim_start_matches("microslip_core::");
            for name in list.trim_matches(['{', '}']).split(',').map(str::trim) {
                items.insert(name.to_string(), name.to_string());
            }
            continue;
        }
        let names = match (path.find('{'), path.rfind('}')) {
            (Some(open), Some(close)) => path[open + 1..close].to_string(),
            _ => path.rsplit("::").next().unwrap_or_default().to_string(),
        };
        for name in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            items.insert(name.to_string(), module.clone());
        }
    }
    // The registry macro is exported at the core's root (`#[macro_export]`) but defined in
    // `problems`: `crate::with_problems!` is an edge to that layer.
    items.insert("with_problems".to_string(), "problems".to_string());
    items
}

/// The top-level modules a piece of code names through `crate::`.
fn modules_used(code: &str, root: &BTreeMap<String, String>) -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    for (at, _) in code.match_indices("crate::") {
        let rest = &code[at + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            for item in group.split(',').map(str::trim) {
                let head = item.split("::").next().unwrap_or_default();
                match root.get(head) {
                    Some(module) => used.insert(module.clone()),
                    None => used.insert(head.to_string()),
                };
            }
        } else {
            let head: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            match root.get(&head) {
                Some(module) => used.insert(module.clone()),
                None => used.insert(head),
            };
        }
    }
    used.retain(|m| !m.is_empty() && m.chars().next().is_some_and(char::is_lowercase));
    used
}

/// Every breach of the layering in `sources`, one line each.
fn breaches(sources: &[Source], root: &BTreeMap<String, String>) -> Vec<String> {
    let mut found = Vec::new();
    for source in sources {
        let from = top_module(&source.path);
        let Some(from_layer) = layer_of(from) else {
            found.push(format!("{}: module `{from}` has no layer", source.path));
            continue;
        };
        for to in modules_used(&source.code, root) {
            if to == from {
                continue;
            }
            match layer_of(&to) {
                Some(to_layer) if to_layer < from_layer => {}
                Some(_) => found.push(format!(
                    "{}: `{from}` uses `{to}`, which is not below it",
                    source.path
                )),
                None => found.push(format!("{}: uses `{to}`, which has no layer", source.path)),
            }
        }
        found.extend(problem_breaches(source, root));
    }
    found
}

/// Inside `problems/`: a problem names no other problem, and its closed-form side and its
/// discretized side never name each other (directly, through `super::`, or through the root
/// re-exports of the closed forms).
fn problem_breaches(source: &Source, root: &BTreeMap<String, String>) -> Vec<String> {
    let mut found = Vec::new();
    let parts: Vec<&str> = source.path.split('/').collect();
    let [problems, problem, file] = parts[..] else {
        return found;
    };
    if problems != "problems" && problems != "faces" {
        return found;
    }
    let code = &source.code;
    for (other, _) in code.match_indices("crate::problems::") {
        let rest = &code[other + "crate::problems::".len()..];
        // `crate::problems::plate::...` names one module; `crate::problems::{plate, inputs}`
        // names each one in the braces (nested paths inside are that module's own).
        let names: Vec<String> = match rest.strip_prefix('{') {
            Some(list) => {
                let list = &list[..list.find('}').unwrap_or(list.len())];
                list.split(',')
                    .map(|item| {
                        item.trim()
                            .chars()
                            .take_while(|c| c.is_alphanumeric() || *c == '_')
                            .collect()
                    })
                    .collect()
            }
            None => vec![
                rest.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect(),
            ],
        };
        for named in names {
            // Another problem is another folder of src/problems; its files (inputs, quantity,
            // ...) are the shared vocabulary every problem may use.
            let is_folder = !named.is_empty()
                && Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join(CORE)
                    .join("problems")
                    .join(&named)
                    .is_dir();
            if is_folder && named != problem {
                found.push(format!(
                    "{}: problem `{problem}` uses problem `{named}`",
                    source.path
                ));
            }
        }
    }
    let name = file.strip_suffix(".rs").unwrap_or(file);
    let forbidden: &[&str] = if CLOSED_FORM_SIDE.contains(&name) {
        DISCRETIZED_SIDE
    } else if DISCRETIZED_SIDE.contains(&name) {
        CLOSED_FORM_SIDE
    } else {
        &[]
    };
    for other in forbidden {
        let local = format!("super::{other}");
        let absolute = format!("crate::problems::{problem}::{other}");
        if code.contains(&local) || code.contains(&absolute) {
            found.push(format!("{}: `{name}` uses `{other}`", source.path));
        }
    }
    // The closed forms' types are re-exported at the root: naming them is using them.
    if DISCRETIZED_SIDE.contains(&name) {
        let closed_form_items: Vec<&String> = root
            .iter()
            .filter(|(_, module)| module.as_str() == "problems")
            .map(|(item, _)| item)
            .collect();
        for item in closed_form_items {
            if code.contains(&format!("crate::{item}")) || grouped(code, item) {
                found.push(format!(
                    "{}: `{name}` uses the root re-export `{item}`",
                    source.path
                ));
            }
        }
    }
    found
}

/// True when `item` appears in a `crate::{...}` group.
fn grouped(code: &str, item: &str) -> bool {
    code.match_indices("crate::{").any(|(at, _)| {
        let group = &code[at + "crate::{".len()..];
        let group = &group[..group.find('}').unwrap_or(group.len())];
        group.split(',').any(|i| i.trim() == item)
    })
}

fn rust_files(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, found);
        } else if path.extension().is_some_and(|e| e == "rs") {
            found.push(path);
        }
    }
}

/// Where the physics lives: the core crate, whose modules keep their names in the application
/// (`pub use microslip_core::{kernel, ...}`), so that both crates are one layered whole.
const CORE: &str = "crates/microslip-core/src";

/// The sources of both crates (paths below each crate's `src/`) and the root re-exports of both.
fn crate_sources() -> (Vec<Source>, BTreeMap<String, String>) {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sources = Vec::new();
    let mut root = BTreeMap::new();
    for src in [top.join("src"), top.join(CORE)] {
        let mut paths = Vec::new();
        rust_files(&src, &mut paths);
        for path in paths {
            let relative = path
                .strip_prefix(&src)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            // The crate roots list modules and re-exports; the binary is outside the library.
            if relative == "lib.rs" || relative == "main.rs" {
                continue;
            }
            // The application's problem folders are the problems' faces, a layer of their own.
            let relative = match relative.strip_prefix("problems/") {
                Some(face) if src == top.join("src") => format!("faces/{face}"),
                _ => relative,
            };
            let text = std::fs::read_to_string(&path).unwrap();
            sources.push(Source {
                path: relative,
                code: shipped_code(&text),
            });
        }
        let lib = std::fs::read_to_string(src.join("lib.rs")).unwrap();
        root.extend(root_reexports(&lib));
    }
    (sources, root)
}

/// The core crate depends on nothing with a terminal, a file format or a command line in it:
/// its `[dependencies]` are a short, named list (`cargo tree -p microslip-core -e normal` shows
/// the same).
#[test]
fn the_core_crate_depends_on_no_terminal_format_or_command_line() {
    let manifest = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/microslip-core/Cargo.toml"),
    )
    .unwrap();
    let dependencies = manifest
        .split("[dependencies]")
        .nth(1)
        .expect("the core has a [dependencies] table");
    let dependencies = dependencies.split("\n[").next().unwrap_or_default();
    let names: Vec<&str> = dependencies
        .lines()
        .filter_map(|line| line.split('=').next())
        .map(str::trim)
        .filter(|name| !name.is_empty() && !name.starts_with('#'))
        .collect();
    let allowed = ["roots", "serde", "thiserror"];
    for name in &names {
        assert!(allowed.contains(name), "the core depends on `{name}`");
    }
    assert!(names.contains(&"roots"), "read {names:?}");
}

#[test]
fn every_edge_runs_down_and_the_two_sides_of_a_problem_stay_apart() {
    let (sources, root) = crate_sources();
    assert!(sources.len() > 50, "read {} files", sources.len());
    let found = breaches(&sources, &root);
    assert!(found.is_empty(), "layering breached:\n{}", found.join("\n"));
}

#[test]
fn every_top_level_module_has_a_layer() {
    let (sources, _) = crate_sources();
    let modules: BTreeSet<&str> = sources.iter().map(|s| top_module(&s.path)).collect();
    for module in modules {
        assert!(layer_of(module).is_some(), "`{module}` has no layer");
    }
}

/// What the drawing may not name: the physics and what runs it. The TUI's `ui/` draws the
/// read-only view that `recompute` builds (`tui/view.rs`), so that a frame costs no solve and
/// every number on screen was computed once, where the state changed.
const PHYSICS: &[&str] = &["kernel", "numeric", "problems", "study", "fit", "verify"];

/// The physics modules a piece of code names (directly, through a root re-export, or through
/// the core crate's own name).
fn physics_named(code: &str, root: &BTreeMap<String, String>) -> Vec<String> {
    let mut named: Vec<String> = modules_used(code, root)
        .into_iter()
        .filter(|m| PHYSICS.contains(&m.as_str()))
        .collect();
    if code.contains("microslip_core") {
        named.push("microslip_core".to_string());
    }
    named
}

#[test]
fn the_tui_s_drawing_names_no_physics() {
    let (sources, root) = crate_sources();
    let drawing: Vec<&Source> = sources
        .iter()
        .filter(|s| s.path.starts_with("tui/ui/"))
        .collect();
    assert!(drawing.len() >= 4, "read {} files of tui/ui", drawing.len());
    let found: Vec<String> = drawing
        .iter()
        .filter_map(|s| {
            let named = physics_named(&s.code, &root);
            (!named.is_empty()).then(|| format!("{}: names {}", s.path, named.join(", ")))
        })
        .collect();
    assert!(
        found.is_empty(),
        "drawing names physics:\n{}",
        found.join("\n")
    );
}

/// The checker itself can fail: each kind of breach, written into a synthetic source, is
/// reported.
#[test]
fn the_checker_reports_each_kind_of_breach() {
    let lib = "pub use problems::twin_beams::closed_form::{TipForce, TwinBeams};\npub use kernel::regime::Regime;";
    let root = root_reexports(lib);
    assert_eq!(root.get("TwinBeams").map(String::as_str), Some("problems"));
    let source = |path: &str, code: &str| Source {
        path: path.to_string(),
        code: shipped_code(code),
    };
    let cases = [
        // Upward: the kernel naming a report, directly and through a root re-export.
        ("kernel/format.rs", "use crate::report::text;", "not below"),
        ("numeric/mesh.rs", "use crate::{TwinBeams};", "not below"),
        // Sideways: two modules of one layer.
        (
            "fit/mod.rs",
            "let x = crate::study::curves::f();",
            "not below",
        ),
        // A cycle needs an upward edge, which the rule above already refuses.
        ("report/mod.rs", "use crate::tui::app;", "not below"),
        // The two sides of a problem.
        (
            "problems/plate/continuum.rs",
            "use super::closed_form::SqueezedPlate;",
            "uses `closed_form`",
        ),
        (
            "problems/twin_beams/closed_form.rs",
            "use crate::problems::twin_beams::discretized::TwinBeamsFe;",
            "uses `discretized`",
        ),
        (
            "problems/twin_beams/discretized.rs",
            "use crate::{TipForce};",
            "root re-export `TipForce`",
        ),
        // One problem naming another.
        (
            "problems/plate/closed_form.rs",
            "use crate::problems::twin_beams::params::BeamParam;",
            "uses problem `twin_beams`",
        ),
        (
            "problems/plate/closed_form.rs",
            "use crate::problems::{PlateParam, twin_beams::params::BeamParam};",
            "uses problem `twin_beams`",
        ),
        // A module nobody placed.
        ("newthing/mod.rs", "", "has no layer"),
    ];
    for (path, code, expected) in cases {
        let found = breaches(&[source(path, code)], &root);
        assert!(
            found.iter().any(|f| f.contains(expected)),
            "{path}: {code:?} gave {found:?}"
        );
    }
    // Comments and unit tests are not dependencies; a downward edge is fine.
    let fine = "// crate::tui\nuse crate::kernel::format::number;\n#[cfg(test)]\nmod tests {\n    use crate::cli;\n}\n";
    assert!(breaches(&[source("report/text.rs", fine)], &root).is_empty());
    // A problem's shared vocabulary (inputs, quantity, ...) is not another problem.
    let shared = "use crate::problems::{Description, Param, Quantity, QuantityName, Solution};\n";
    assert!(breaches(&[source("problems/plate/mod.rs", shared)], &root).is_empty());
    // Drawing that names physics, directly or through a root re-export; the view it reads is
    // fine.
    assert_eq!(
        physics_named("let z = crate::study::curves::interface_zones(m);", &root),
        ["study"]
    );
    assert_eq!(
        physics_named("use crate::{TwinBeams};", &root),
        ["problems"]
    );
    assert_eq!(
        physics_named("use microslip_core::study::curves::Zone;", &root),
        ["microslip_core"]
    );
    assert!(physics_named("use crate::tui::view::View;", &root).is_empty());
}

/// The names that are a problem's own: its folder's name as a path (`twin_beams::`), its
/// registry variant as the generic enums spell it (`ModelKind::Beam`, `Param::Beam`, ...) and
/// every type its core folder declares (`TwinBeams`, `TipForce`, `BeamParam`, ...).
fn problem_names() -> Vec<(String, Vec<String>)> {
    let core = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(CORE)
        .join("problems");
    let registry = std::fs::read_to_string(core.join("mod.rs")).unwrap();
    let mut problems = Vec::new();
    for entry in std::fs::read_dir(&core).unwrap() {
        let folder = entry.unwrap().path();
        if !folder.is_dir() {
            continue;
        }
        let name = folder.file_name().unwrap().to_string_lossy().to_string();
        let mut names = vec![format!("{name}::")];
        // The registry line `Beam => twin_beams::TwinBeamsProblem,`. A folder the registry
        // does not list yet (a problem being built, declared by `pub mod` alone) has no variants
        // to be named by; its folder and its types are checked all the same.
        let line = registry
            .lines()
            .find(|l| l.contains(&format!("=> {name}::")));
        if let Some(line) = line {
            let variant = line.split("=>").next().unwrap().trim().to_string();
            for generic in ["ModelKind", "Param", "Inputs", "Model"] {
                names.push(format!("{generic}::{variant}"));
            }
        } else {
            assert!(
                registry.contains(&format!("pub mod {name};")),
                "no registry line and no module for `{name}`"
            );
        }
        let mut files = Vec::new();
        rust_files(&folder, &mut files);
        for file in files {
            let code = shipped_code(&std::fs::read_to_string(file).unwrap());
            for word in ["pub struct ", "pub enum ", "pub trait ", "pub type "] {
                for (at, _) in code.match_indices(word) {
                    let ident: String = code[at + word.len()..]
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    if !ident.is_empty() && !names.contains(&ident) {
                        names.push(ident);
                    }
                }
            }
        }
        problems.push((name, names));
    }
    problems
}

/// True when `code` holds `name` as a whole word (a `BeamParam` inside `BeamParams` counts for
/// `BeamParams` only).
fn names_word(code: &str, name: &str) -> bool {
    let word = |c: char| c.is_alphanumeric() || c == '_';
    code.match_indices(name).any(|(at, _)| {
        let before = code[..at].chars().next_back();
        let after = code[at + name.len()..].chars().next();
        !before.is_some_and(word) && (name.ends_with("::") || !after.is_some_and(word))
    })
}

/// No file outside every problem's two folders names a problem (issue 32's measure: what a new
/// problem would touch besides its folders and its registry line).
#[test]
fn only_a_problem_s_folders_and_the_registry_name_it() {
    let (sources, _) = crate_sources();
    let problems = problem_names();
    assert!(problems.len() >= 3, "read {} problems", problems.len());
    let mut naming = Vec::new();
    for source in &sources {
        let own_folder = |name: &str| {
            source.path.starts_with(&format!("problems/{name}/"))
                || source.path.starts_with(&format!("faces/{name}/"))
        };
        // The registry (the core's problems/mod.rs) is where the problems are listed.
        if source.path == "problems/mod.rs" {
            continue;
        }
        // Unit tests build their fixtures from named problems, as `tests/` does.
        if source.path.contains("/tests/") || source.path.ends_with("/tests.rs") {
            continue;
        }
        let named: Vec<String> = problems
            .iter()
            .filter(|(name, _)| !own_folder(name))
            .flat_map(|(_, names)| names.iter().filter(|n| names_word(&source.code, n)))
            .cloned()
            .collect();
        if !named.is_empty() {
            naming.push((source.path.clone(), named));
        }
    }
    let named: Vec<String> = naming
        .iter()
        .map(|(p, n)| format!("{p}: {}", n.join(", ")))
        .collect();
    assert!(
        named.is_empty(),
        "{} files name a problem outside its folders (move what names it into the problem's \
         folder, or say it through the registry):\n{}",
        named.len(),
        named.join("\n")
    );
}

/// The generic layers: folders (from the repository's root) whose items may not be named after a
/// problem. A problem's own types, functions and constants live in its two folders; a generic
/// layer that declares `BeamRow` or `lap_points` is a problem's code under a generic roof, which
/// the next problem copies. More folders join this list as they are cleaned.
const GENERIC_LAYERS: &[&str] = &[
    "src/fe",
    "src/report",
    "src/cli",
    "src/chart",
    "src/tui",
    "python/src",
];

/// Each problem's name prefixes, from the registry itself: its variant (`Beam`), its type less
/// `Problem` (`TwinBeams`), its folder as a type (`TwinBeams`) and its key and folder as the
/// start of a function, module or constant (`beam_`, `twin_beams_`, `BEAM_`, `TWIN_BEAMS_`).
fn problem_prefixes() -> Vec<String> {
    macro_rules! names {
        ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
            vec![$((
                stringify!($variant),
                stringify!($problem),
                stringify!($folder),
                <microslip_core::problems::$folder::$problem as
                    microslip_core::problems::Problem>::INFO.key,
            )),+]
        };
    }
    let camel = |snake: &str| -> String {
        snake
            .split('_')
            .map(|w| {
                let mut c = w.chars();
                c.next()
                    .map(|f| f.to_uppercase().chain(c).collect::<String>())
                    .unwrap_or_default()
            })
            .collect()
    };
    let mut prefixes = Vec::new();
    for (variant, problem, folder, key) in microslip_core::with_problems!(names) {
        for name in [
            variant.to_string(),
            problem
                .strip_suffix("Problem")
                .unwrap_or(problem)
                .to_string(),
            camel(folder),
            camel(key),
            format!("{key}_"),
            format!("{folder}_"),
            format!("{}_", key.to_uppercase()),
            format!("{}_", folder.to_uppercase()),
        ] {
            if !prefixes.contains(&name) {
                prefixes.push(name);
            }
        }
    }
    prefixes
}

/// The items `code` declares whose name starts with one of `prefixes` as a word (`Beam` in
/// `BeamRow` or `Beam`, not in `Beamish`; `beam_` in `beam_points`), each as `kind name`.
fn problem_named_items(code: &str, prefixes: &[String]) -> Vec<String> {
    const KINDS: &[&str] = &[
        "struct", "enum", "fn", "type", "const", "static", "trait", "mod", "union",
    ];
    let mut found = Vec::new();
    for line in code.lines() {
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || "(<:{;=,".contains(c))
            .filter(|w| !w.is_empty())
            .collect();
        for pair in words.windows(2) {
            let [kind, name] = [pair[0], pair[1]];
            if !KINDS.contains(&kind) {
                continue;
            }
            let named = prefixes.iter().any(|prefix| {
                name.strip_prefix(prefix.as_str()).is_some_and(|rest| {
                    prefix.ends_with('_')
                        || rest.is_empty()
                        || rest.starts_with(|c: char| c.is_uppercase() || c.is_ascii_digit())
                })
            });
            if named {
                found.push(format!("{kind} {name}"));
            }
            break;
        }
    }
    found
}

/// The shipped code of every file of the generic layers, `(path from the root, code)`, in
/// path order: unit-test files (`tests.rs`, a `tests/` folder) and modules left out.
fn generic_layer_sources() -> Vec<(String, String)> {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sources = Vec::new();
    for layer in GENERIC_LAYERS {
        let mut paths = Vec::new();
        rust_files(&top.join(layer), &mut paths);
        paths.sort();
        for path in paths {
            let relative = path
                .strip_prefix(top)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            if relative.ends_with("/tests.rs") || relative.contains("/tests/") {
                continue;
            }
            let code = shipped_code(&std::fs::read_to_string(&path).unwrap());
            sources.push((relative, code));
        }
    }
    sources
}

/// Every item of the generic layers named after a problem, `path: kind name`.
fn problem_named_items_of_generic_layers() -> Vec<String> {
    let prefixes = problem_prefixes();
    generic_layer_sources()
        .into_iter()
        .flat_map(|(path, code)| {
            problem_named_items(&code, &prefixes)
                .into_iter()
                .map(move |item| format!("{path}: {item}"))
        })
        .collect()
}

/// Issue 43: no item of a generic layer (`src/fe`, `src/report`: shipped code, unit-test
/// modules left out, as for the layers) is named after a problem; a problem's points,
/// comparisons, rows and verdicts live in its folder.
#[test]
fn no_item_of_a_generic_layer_is_named_after_a_problem() {
    let found = problem_named_items_of_generic_layers();
    assert!(
        found.is_empty(),
        "{} items of {GENERIC_LAYERS:?} are named after a problem (move them to the problem's \
         folder; 36 were when this check was written, none since):\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The check itself can fail: each kind of item, named after a problem by its variant, type,
/// key or folder, is found; a generic name, or a problem's name inside a word, is not.
#[test]
fn the_problem_name_check_finds_each_kind_of_item() {
    let prefixes = problem_prefixes();
    for expected in [
        "Beam",
        "TwinBeams",
        "beam_",
        "twin_beams_",
        "Plate",
        "Lap",
        "Cylinder",
    ] {
        assert!(prefixes.iter().any(|p| p == expected), "{prefixes:?}");
    }
    let code = "pub struct BeamRow {\n\
                pub(crate) enum PlateCompared<'a> {\n\
                fn lap_points(run: &CcxRun) {\n\
                pub const BEAM_CURVE: Curve = x;\n\
                pub type CylinderReport = Table<X>;\n\
                pub trait TwinBeamsFace {\n\
                pub mod twin_beams_faces;\n\
                pub fn label(row: &BeamRow) -> String {\n\
                struct Lapse;\n\
                let beam_row = 1;\n";
    assert_eq!(
        problem_named_items(code, &prefixes),
        [
            "struct BeamRow",
            "enum PlateCompared",
            "fn lap_points",
            "const BEAM_CURVE",
            "type CylinderReport",
            "trait TwinBeamsFace",
            "mod twin_beams_faces",
        ]
    );
}

/// What a generic layer's text may not say of one problem: its key (and the key's plural) as a
/// word, its title, and its load's bound formula, all from the registry (`beam`, `beams`,
/// `twin cantilever beams`, `2 b mu P L`), lower case.
fn problem_words() -> Vec<(String, bool)> {
    macro_rules! infos {
        ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
            vec![$(<microslip_core::problems::$folder::$problem as
                microslip_core::problems::Problem>::INFO),+]
        };
    }
    let mut words = Vec::new();
    for info in microslip_core::with_problems!(infos) {
        // (text, as a whole word)
        words.push((info.key.to_lowercase(), true));
        words.push((format!("{}s", info.key.to_lowercase()), true));
        words.push((info.title.to_lowercase(), false));
        if let Some(bound) = &info.load_bound {
            // A formula of one factor (`mu P`) is the friction stress of any problem.
            if bound.formula.split_whitespace().count() > 2 {
                words.push((bound.formula.to_lowercase(), false));
            }
        }
    }
    words
}

/// The string literals of `code` (`"..."`, escapes kept), in order.
fn string_literals(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut chars = code.chars().peekable();
    let mut previous = ' ';
    while let Some(c) = chars.next() {
        // A char literal `'"'` is not the start of a string.
        if c == '"' && previous != '\'' {
            let mut literal = String::new();
            while let Some(d) = chars.next() {
                match d {
                    '\\' => {
                        literal.push(d);
                        if let Some(e) = chars.next() {
                            literal.push(e);
                        }
                    }
                    '"' => break,
                    _ => literal.push(d),
                }
            }
            found.push(literal);
            previous = '"';
        } else {
            previous = c;
        }
    }
    found
}

/// The literals of `code` that name a problem in `words`, each as its first 40 characters.
fn literals_naming_a_problem(code: &str, words: &[(String, bool)]) -> Vec<String> {
    let is_word_char = |c: char| c.is_alphanumeric() || c == '_' || c == '-';
    string_literals(code)
        .into_iter()
        .filter(|literal| {
            let lower = literal.to_lowercase();
            words.iter().any(|(word, whole)| {
                lower.match_indices(word.as_str()).any(|(at, _)| {
                    !whole
                        || (!lower[..at].ends_with(is_word_char)
                            && !lower[at + word.len()..].starts_with(is_word_char))
                })
            })
        })
        .map(|literal| literal.chars().take(40).collect())
        .collect()
}

/// Issue 43: the generic layers' messages, help texts, prompts and captions say a problem's name,
/// title or formula only through its `Description`, or the literal lives in the problem's folder
/// (23 named one when this check was written, none since).
#[test]
fn no_literal_of_a_generic_layer_names_a_problem() {
    let words = problem_words();
    let found: Vec<String> = generic_layer_sources()
        .into_iter()
        .flat_map(|(path, code)| {
            literals_naming_a_problem(&code, &words)
                .into_iter()
                .map(move |literal| format!("{path}: {literal}"))
        })
        .collect();
    assert!(
        found.is_empty(),
        "{} literals of {GENERIC_LAYERS:?} name a problem (say it through the problem's \
         Description, or move the text into the problem's folder):\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The doc comments of `src/cli/args` that clap shows as help (on a command, a flag, a value or
/// the struct of one; not those of a helper function, trait, impl or module), one text per
/// block, with the line it starts on.
fn help_texts(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let mut block: Option<(usize, String)> = None;
    for (number, line) in text.lines().enumerate() {
        let line = line.trim_start();
        if line.trim() == "#[cfg(test)]" {
            break;
        }
        if let Some(doc) = line.strip_prefix("///") {
            let (_, text) = block.get_or_insert_with(|| (number + 1, String::new()));
            text.push_str(doc);
            continue;
        }
        if line.starts_with("#[") || line.is_empty() {
            continue;
        }
        if let Some(help) = block.take() {
            let item = line
                .trim_start_matches("pub(in crate::cli) ")
                .trim_start_matches("pub(crate) ")
                .trim_start_matches("pub(super) ")
                .trim_start_matches("pub ");
            let developer = [
                "fn ",
                "trait ",
                "impl",
                "macro_rules!",
                "mod ",
                "type ",
                "const ",
            ]
            .iter()
            .any(|start| item.starts_with(start));
            if !developer {
                found.push(help);
            }
        }
    }
    found
}

/// Issue 43: the command line's help, written as doc comments in `src/cli/args`, is a message
/// like any other: it says a problem's words through the registry (`per_problem_help`, the
/// problem's own subcommand), never by naming one.
#[test]
fn no_help_text_of_the_command_line_names_a_problem() {
    let words = problem_words();
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut paths = Vec::new();
    rust_files(&top.join("src/cli/args"), &mut paths);
    paths.sort();
    let mut found = Vec::new();
    for path in paths {
        let text = std::fs::read_to_string(&path).unwrap();
        for (line, help) in help_texts(&text) {
            let quoted = format!("\"{}\"", help.replace('"', "'"));
            if !literals_naming_a_problem(&quoted, &words).is_empty() {
                let name = path.file_name().unwrap().to_string_lossy().to_string();
                found.push(format!("src/cli/args/{name}:{line}: {}", help.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "{} help texts of the command line name a problem (generate them from the registry):\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The help check can fail: a flag's doc comment naming a problem is found, a helper
/// function's is not.
#[test]
fn the_help_check_finds_a_flag_s_words() {
    let words = problem_words();
    let code = "/// The lap joint's load.\n#[arg(long)]\npub load: f64,\n\
                /// Lists beam: L b h.\npub(in crate::cli) fn lists() {}\n";
    let texts = help_texts(code);
    assert_eq!(texts.len(), 1, "{texts:?}");
    let quoted = format!("\"{}\"", texts[0].1);
    assert_eq!(literals_naming_a_problem(&quoted, &words).len(), 1);
}

/// The literal check can fail: a key as a word, a title and a formula are found; a key inside
/// a word or in a comment is not.
#[test]
fn the_literal_check_finds_a_problem_s_words() {
    let words = problem_words();
    let code = shipped_code(
        "fn a() { x(\"the lap joint slides\"); y(\"Twin cantilever beams\"); \
         z(\"F <= 2 b mu P L\"); w(\"overlapping\"); v('\"'); }\n// \"a beam\"\n",
    );
    assert_eq!(
        literals_naming_a_problem(&code, &words),
        [
            "the lap joint slides",
            "Twin cantilever beams",
            "F <= 2 b mu P L"
        ]
    );
}
