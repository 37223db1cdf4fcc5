//! The user guide's key and command tables, rendered from the code so that they cannot drift.
//!
//! `docs/guide.md` holds the generated text between marker comments (`<!-- keys:begin -->` ...
//! `<!-- keys:end -->`, `<!-- commands:begin -->` ... `<!-- commands:end -->`). These tests render the
//! tables from the key map (`src/tui/keymap.rs`, the table the `?` overlay prints) and from clap's
//! definition of the command line (`src/cli.rs`) and fail when the guide's text differs. After a
//! change to keys, help texts or flags, regenerate in one command:
//!
//! ```text
//! UPDATE_GUIDE=1 cargo test --test guide_tables
//! ```
//!
//! A new main-screen key also needs its long description in [`KEY_DETAILS`] below (the test says
//! which). The guide's and README's internal links are checked here too.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::Mutex;

use clap::ArgAction;
use microslip::app::testing::guide::{BINDINGS, Context, GLOBAL_KEYS, command, context_title};

/// What each main-screen key does, in the words of the guide (the overlay's one-line text is
/// too short for a newcomer). Keyed by the key's label as the overlay writes it.
const KEY_DETAILS: &[(&str, &str)] = &[
    (
        "j / Down",
        "select the next parameter (stops at the last row)",
    ),
    (
        "k / Up",
        "select the previous parameter (stops at the first row)",
    ),
    (
        "l / Right",
        "increase, fine step (x1.02; F by 1 % of F_thre; nu by 0.005)",
    ),
    (
        "h / Left",
        "decrease, fine step (x1.02; F by 1 % of F_thre; nu by 0.005)",
    ),
    (
        "L / S-Right",
        "increase, coarse step (x1.25; K_T by 10^0.25; F by 10 % of F_thre; nu by 0.05)",
    ),
    (
        "H / S-Left",
        "decrease, coarse step (x1.25; K_T by 10^0.25; F by 10 % of F_thre; nu by 0.05)",
    ),
    (
        "Enter / e",
        "type an exact value: the current one is offered selected (`[600]`: typing replaces it, \
         arrows edit it); Enter accepts, Esc cancels; a refused value keeps the old one and says \
         why; a value far outside the usual range (mu = 4.5) is accepted with a warning",
    ),
    (
        "m / Tab",
        "next problem: twin beams, plate, lap joint (each keeps its own edits)",
    ),
    ("c", "next chart"),
    ("C", "previous chart"),
    (
        "n",
        "finite-element points on/off (on the plate's u(L) chart also the 2-D plane-strain \
         continuum, where the strip theory's assumptions are dropped; on the lap joint's Delta, \
         zone, tau(x) and s(x) charts the 2-D plane-stress continuum, where the shear-lag \
         theory's are). They are solved on a worker thread (seconds for the lap joint's \
         continuum): the legend says `solving...` meanwhile, the newest values win, and Esc (or \
         `q`) stops the solve and turns the points off",
    ),
    (
        "b",
        "twin beams: Euler-Bernoulli (the paper's) or Timoshenko deflection (adds each beam's \
         shear deflection; nu is a beam row, used by Timoshenko only); the pane title says which",
    ),
    (
        "p",
        "preset picker: `j`/`k`, Enter loads, `s` saves, Esc closes",
    ),
    (
        "s",
        "save the parameters as a user preset: its name, then its one-line description (offered: \
         the preset's own when saved under its name, else \"Saved from the microslip TUI \
         (...)\"); asks before overwriting; atomic write",
    ),
    (
        "r",
        "reset to the loaded preset (asks first; `u` undoes it)",
    ),
    (
        "d",
        "load a measured curve for `f` (a CSV: `F_N,w_mm` on the twin beams, `F_N,Delta_mm` on \
         the lap joint, as `microslip fit` takes them; also `--data FILE`) or FE results: a \
         CalculiX `.dat` of a `microslip deck` run (its deck's parameters are adopted; points \
         labelled CalculiX on the w(L), u(L) or Delta chart; the status line gives the comparison \
         of `microslip compare`; plate runs of one deck add up over K_T), or on the plate a CSV \
         `KT_MPa_per_mm,u_mm` of any FE code. The file is read on a worker thread: Esc cancels, \
         other keys do nothing until it is in",
    ),
    (
        "f",
        "fit mu and K_T of the twin beams or the lap joint to their measured curve and adopt the \
         identifiable values (`u` undoes it), as `microslip fit` does. The fit runs \
         on a worker thread: a long one shows its progress on the status line and Esc cancels \
         it, leaving the parameters as they were; other keys do nothing until it ends",
    ),
    (
        "v",
        "chart the response (w(L) of the beams, u(L) of the plate, Delta of the lap joint) \
         against the selected parameter, both laws, cursor at its value (`v` or `c` goes back); \
         the lap joint's chart stays where F <= F_gross",
    ),
    (
        "t",
        "solve the selected parameter for a target, e.g. `ratio=1.01` (offered), `w(L)=0.05`, \
         `X=100`: a single certified root is adopted (`u` undoes it); none or several are said",
    ),
    (
        "i",
        "explain the lines of the regime pane (`j`/`k` move through them)",
    ),
    (
        "a",
        "fit the axes to the data again (the force range of the beams' charts, 3 F_thre, is kept \
         while other parameters change, so that curves can be compared; it is fitted again by \
         itself, and the status line says so, when F_thre leaves it or shrinks below a twelfth of \
         it: a geometry, mu or P changed by a large factor. K_T never moves it)",
    ),
    (
        "y",
        "y axis of the chart: linear, log, relative to Coulomb (each curve / Coulomb - 1 in %), \
         among the modes the chart can show; each chart keeps its own (u(L) vs K_T and D vs F_a \
         open on log)",
    ),
    (
        "g",
        "pin the current parameters (up to 4 per model; a fifth replaces the oldest). A pin keeps \
         its values, so it follows every chart switch: each chart of the model draws the pinned \
         state's regularized curve (K_T, regularized, P_r/P) over the same range and y mode, as \
         Braille in its own colour with its number on the curve, or as its number (`1` to `4`) in \
         the ASCII and `NO_COLOR` modes. The legend names what differs from now, pinned value \
         first (`1 mu 0.2->0.3`); `x` exports pins too",
    ),
    ("G", "clear the pins"),
    (
        ":",
        "command line on the status row: `KT=250 mu=0.2 F=90` sets several values at once, all \
         or none, in `--set` syntax with its refusals (one `u` undoes them); `preset NAME` (or a \
         path), `save NAME`, `export`, `drop`, `help`, `q`. Tab completes keys, command words and \
         preset names",
    ),
    (
        "D",
        "drop the loaded measurements and FE results. They are also dropped when a preset is \
         loaded (they were for other values), and measurements when a CalculiX `.dat`'s deck \
         values are adopted; the status line says what went",
    ),
    (
        "M",
        "show the last status message whole (a message longer than 3 rows, 4 from 30 rows, ends \
         in `... M reads all`; the status takes its rows from the panes above it and never covers \
         the chart)",
    ),
    (
        "x",
        "export the chart shown: `microslip-CHART.svg` (the figure of `microslip plot`) and \
         `.csv` (its points) in the working directory, never replacing a file (`-2`, `-3`, ...); \
         the status line says where",
    ),
    ("u", "undo parameter changes (both models, the last 100)"),
    ("C-r", "redo parameter changes"),
    ("?", "help: every key and every chart mark"),
    (
        "q / Esc",
        "quit; with unsaved edits to a loaded preset it asks first (`y` quits, `n` stays)",
    ),
];

/// The long descriptions of the keys that act everywhere (Ctrl plus the letter).
const GLOBAL_DETAILS: &[(char, &str)] = &[
    ('c', "quit from anywhere, without asking"),
    (
        'z',
        "suspend (the terminal is restored); `fg` resumes and redraws. Without a job-control \
         shell (`ssh host microslip`, `tmux new microslip`) the status line says it cannot \
         suspend",
    ),
];

fn guide_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/guide.md")
}

/// A markdown table cell: pipes escaped, so a description cannot break the table.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// `j / Down` as `` `j` / `Down` ``.
fn keys_cell(label: &str) -> String {
    label
        .split(" / ")
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(" / ")
}

/// The key tables: the main screen with each key's long description, then every other context
/// with the overlay's own words, then the keys that act everywhere.
fn render_keys() -> Result<String, String> {
    let mut out = String::new();
    let mut missing = Vec::new();
    let mut contexts: Vec<Context> = Vec::new();
    for binding in BINDINGS {
        if !contexts.contains(&binding.context) {
            contexts.push(binding.context);
        }
    }
    for context in contexts {
        let main = context == Context::Main;
        let _ = writeln!(out, "**{}**\n", context_title(context));
        if main {
            out.push_str("| keys | does | in detail |\n|---|---|---|\n");
        } else {
            out.push_str("| keys | does |\n|---|---|\n");
        }
        for binding in BINDINGS.iter().filter(|b| b.context == context) {
            let label = binding.label();
            if main {
                let detail = KEY_DETAILS
                    .iter()
                    .find(|(l, _)| *l == label)
                    .map(|(_, d)| *d);
                if detail.is_none() {
                    missing.push(label.clone());
                }
                let _ = writeln!(
                    out,
                    "| {} | {} | {} |",
                    keys_cell(&label),
                    cell(binding.description),
                    cell(detail.unwrap_or(""))
                );
            } else {
                let _ = writeln!(
                    out,
                    "| {} | {} |",
                    keys_cell(&label),
                    cell(binding.description)
                );
            }
        }
        out.push('\n');
    }
    out.push_str("**Everywhere**\n\n| keys | does | in detail |\n|---|---|---|\n");
    for (key, _, what) in GLOBAL_KEYS {
        let detail = GLOBAL_DETAILS
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, d)| *d);
        if detail.is_none() {
            missing.push(format!("C-{key}"));
        }
        let _ = writeln!(
            out,
            "| `C-{key}` | {} | {} |",
            cell(what),
            cell(detail.unwrap_or(""))
        );
    }
    // A stale description would document a key that no longer exists.
    let labels: BTreeSet<String> = BINDINGS
        .iter()
        .filter(|b| b.context == Context::Main)
        .map(|b| b.label())
        .collect();
    let stale: Vec<&str> = KEY_DETAILS
        .iter()
        .map(|(l, _)| *l)
        .filter(|l| !labels.contains(*l))
        .collect();
    if !missing.is_empty() || !stale.is_empty() {
        return Err(format!(
            "tests/guide_tables.rs KEY_DETAILS/GLOBAL_DETAILS: keys without a long description: \
             {missing:?}; descriptions of keys that are not bound: {stale:?}"
        ));
    }
    Ok(out)
}

/// One argument as a synopsis writes it: `--set KEY=VALUE`, `--format text|json`, `--fe`,
/// `beam|plate|lap`, `RESULT...`; optional ones in brackets.
fn synopsis_piece(arg: &clap::Arg) -> Option<String> {
    let id = arg.get_id().as_str();
    if arg.is_hide_set() || id == "help" || id == "version" {
        return None;
    }
    let values: Vec<String> = arg
        .get_possible_values()
        .iter()
        .filter(|v| !v.is_hide_set())
        .map(|v| v.get_name().to_string())
        .collect();
    let value = if !values.is_empty() && values.len() <= 6 {
        values.join("|")
    } else {
        arg.get_value_names()
            .and_then(|names| names.first())
            .map(|n| n.to_string())
            .unwrap_or_else(|| id.to_uppercase())
    };
    let repeated = matches!(arg.get_action(), ArgAction::Append);
    let piece = if arg.is_positional() {
        let many = arg.get_num_args().is_some_and(|n| n.max_values() > 1);
        format!("{value}{}", if many { "..." } else { "" })
    } else {
        let name = match (arg.get_short(), arg.get_long()) {
            (Some(s), _) => format!("-{s}"),
            (None, Some(l)) => format!("--{l}"),
            (None, None) => return None,
        };
        if matches!(arg.get_action(), ArgAction::SetTrue | ArgAction::Count) {
            name
        } else {
            format!("{name} {value}")
        }
    };
    // A positional's `...` is already in the piece.
    let repeated = repeated && !arg.is_positional();
    Some(if arg.is_required_set() {
        format!("{piece}{}", if repeated { "..." } else { "" })
    } else {
        format!("[{piece}]{}", if repeated { "..." } else { "" })
    })
}

/// `microslip NAME ...` wrapped at 100 columns, continuation lines indented.
fn synopsis(path: &str, cmd: &clap::Command) -> String {
    let pieces: Vec<String> = cmd.get_arguments().filter_map(synopsis_piece).collect();
    let mut lines = vec![path.to_string()];
    for piece in pieces {
        let last = lines.last_mut().expect("one line at least");
        if last.len() + 1 + piece.len() > 100 && last.trim().len() > path.len() {
            lines.push(format!("{}{piece}", " ".repeat(path.len() + 1)));
        } else {
            last.push(' ');
            last.push_str(&piece);
        }
    }
    lines.join("\n")
}

/// The first paragraph of a command's help, on one line.
fn about(cmd: &clap::Command) -> String {
    cmd.get_about()
        .map(|a| a.to_string())
        .unwrap_or_default()
        .split("\n\n")
        .next()
        .unwrap_or_default()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Every command (and group: `sweep`, `fit`), depth first in clap's order.
fn walk<'a>(prefix: &str, cmd: &'a clap::Command, out: &mut Vec<(String, &'a clap::Command)>) {
    for sub in cmd.get_subcommands() {
        if sub.get_name() == "help" || sub.is_hide_set() {
            continue;
        }
        let path = format!("{prefix} {}", sub.get_name());
        out.push((path.clone(), sub));
        walk(&path, sub, out);
    }
}

/// The command table (each command with its one-line about) and every leaf command's synopsis.
fn render_commands() -> String {
    let root = command();
    let mut commands = Vec::new();
    walk("microslip", &root, &mut commands);
    let mut out = String::from("| command | what it does |\n|---|---|\n");
    let _ = writeln!(
        out,
        "| `microslip` | the terminal UI (no command; keys: `?` inside) |"
    );
    for (path, cmd) in &commands {
        let _ = writeln!(out, "| `{path}` | {} |", cell(&about(cmd)));
    }
    out.push_str("\nEvery flag (`microslip COMMAND --help` says what each does):\n\n```text\n");
    let _ = writeln!(out, "{}", synopsis("microslip", &root));
    for (path, cmd) in &commands {
        // A group is listed when it takes flags of its own (`sweep`, the generic sweep).
        if cmd.has_subcommands() && cmd.get_arguments().all(|a| synopsis_piece(a).is_none()) {
            continue;
        }
        let _ = writeln!(out, "{}", synopsis(path, cmd));
    }
    out.push_str("```\n");
    out
}

/// Compares the guide's text between `<!-- NAME:begin -->` and `<!-- NAME:end -->` with
/// `rendered`; with `UPDATE_GUIDE=1`, writes `rendered` there instead.
fn check_section(name: &str, rendered: &str) {
    // Tests run in parallel: two sections regenerated at once must not lose one another's update.
    static GUIDE: Mutex<()> = Mutex::new(());
    let _lock = GUIDE
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let path = guide_path();
    let guide = std::fs::read_to_string(&path).expect("docs/guide.md is readable");
    let begin = format!("<!-- {name}:begin -->\n");
    let end = format!("<!-- {name}:end -->");
    let start = guide
        .find(&begin)
        .unwrap_or_else(|| panic!("docs/guide.md has no `{}` marker", begin.trim()))
        + begin.len();
    let stop = start
        + guide[start..]
            .find(&end)
            .unwrap_or_else(|| panic!("docs/guide.md has no `{end}` marker"));
    let current = &guide[start..stop];
    if current == rendered {
        return;
    }
    if std::env::var_os("UPDATE_GUIDE").is_some_and(|v| v == "1") {
        let updated = format!("{}{rendered}{}", &guide[..start], &guide[stop..]);
        // Written beside it and renamed over it, so that the link tests never read half a guide.
        let temporary = path.with_extension("md.tmp");
        std::fs::write(&temporary, updated).expect("docs/ is writable");
        std::fs::rename(&temporary, &path).expect("docs/guide.md is replaceable");
        eprintln!("docs/guide.md: the {name} section was regenerated");
        return;
    }
    let first_difference = current
        .lines()
        .zip(rendered.lines())
        .find(|(a, b)| a != b)
        .map(|(a, b)| format!("guide:     {a}\ngenerated: {b}"))
        .unwrap_or_else(|| "(one is a prefix of the other)".to_string());
    panic!(
        "docs/guide.md's {name} table differs from the code; regenerate it with\n    \
         UPDATE_GUIDE=1 cargo test --test guide_tables\nfirst difference:\n{first_difference}"
    );
}

#[test]
fn the_guides_key_tables_are_the_key_maps() {
    let rendered = render_keys().unwrap_or_else(|e| panic!("{e}"));
    check_section("keys", &rendered);
}

#[test]
fn the_guides_command_table_is_the_command_line() {
    check_section("commands", &render_commands());
}

#[test]
fn the_command_table_names_every_command_and_flag() {
    // The renderer itself: a command or flag it skipped would silently leave the guide.
    let text = render_commands();
    for needle in [
        "`microslip sweep beam`",
        "`microslip fit lap`",
        "`microslip bench`",
        "microslip plot ",
        "[--set KEY=VALUE]...",
        "[--format text|json]",
        "[-o FILE]",
        "--amplitude FA",
        "RESULT...",
        "[--fe]",
    ] {
        assert!(text.contains(needle), "{needle} missing from\n{text}");
    }
}

/// GitHub's anchor of a heading: lower case, punctuation but `-` and `_` dropped, spaces to `-`.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a markdown text's headings (outside fenced code).
fn anchors(text: &str) -> BTreeSet<String> {
    let mut fenced = false;
    let mut out = BTreeSet::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.insert(slug(line.trim_start_matches('#')));
        }
    }
    out
}

/// The targets of `](target)` links in a markdown text.
fn links(text: &str) -> Vec<String> {
    text.split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .map(str::to_string)
        .collect()
}

#[test]
fn the_guides_and_readmes_links_land_on_headings() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let guide = std::fs::read_to_string(guide_path()).expect("docs/guide.md");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let guide_anchors = anchors(&guide);
    let mut broken = Vec::new();
    for target in links(&guide) {
        if let Some(anchor) = target.strip_prefix('#') {
            if !guide_anchors.contains(anchor) {
                broken.push(format!("docs/guide.md -> {target}"));
            }
        } else if !target.contains("://") {
            let file = target.split('#').next().unwrap_or_default();
            if !root.join("docs").join(file).exists() {
                broken.push(format!("docs/guide.md -> {target}"));
            }
        }
    }
    for target in links(&readme) {
        if target.contains("://") {
            continue;
        }
        let (file, anchor) = target.split_once('#').unwrap_or((&target, ""));
        let missing_file = !root.join(file).exists();
        let missing_anchor =
            file == "docs/guide.md" && !anchor.is_empty() && !guide_anchors.contains(anchor);
        if missing_file || missing_anchor {
            broken.push(format!("README.md -> {target}"));
        }
    }
    assert!(broken.is_empty(), "links to nowhere: {broken:?}");
}

#[test]
fn every_section_of_the_guide_is_in_its_contents_list() {
    let guide = std::fs::read_to_string(guide_path()).expect("docs/guide.md");
    let listed: BTreeSet<String> = links(&guide)
        .into_iter()
        .filter_map(|t| t.strip_prefix('#').map(str::to_string))
        .collect();
    let mut fenced = false;
    let orphans: Vec<&str> = guide
        .lines()
        .filter(|line| {
            if line.starts_with("```") {
                fenced = !fenced;
            }
            !fenced && line.starts_with("## ")
        })
        .map(|line| line.trim_start_matches("## "))
        .filter(|heading| *heading != "Contents" && !listed.contains(&slug(heading)))
        .collect();
    assert!(
        orphans.is_empty(),
        "sections not in the contents: {orphans:?}"
    );
}

#[test]
fn the_slug_follows_github() {
    assert_eq!(
        slug(" Script it headless: point, sweep, solve, cycle"),
        "script-it-headless-point-sweep-solve-cycle"
    );
    assert_eq!(
        slug(" Choose K_T for your FE code (kt)"),
        "choose-k_t-for-your-fe-code-kt"
    );
}
