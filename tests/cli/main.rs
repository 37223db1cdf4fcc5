//! The real binary, as scripts use it: every subcommand, output contracts, every error case.

use assert_cmd::Command;

mod decks_and_compare;
mod domain_and_files;
mod figures;
mod fit_kt_cycle;
mod generic_fit;
mod generic_sweep;
mod lap_and_words;
mod problem_commands;
mod reports;
mod solve_and_recipes;

/// The keys of the registry's problems that have a load (every one but the plate today), joined
/// by `sep`: what a refusal lists, from the registry, so that a new problem needs no test edit.
fn loaded_problems(sep: &str) -> String {
    microslip::problems::ModelKind::ALL
        .iter()
        .filter(|k| k.description().load.is_some())
        .map(|k| k.name())
        .collect::<Vec<_>>()
        .join(sep)
}

fn microslip() -> Command {
    let mut cmd = Command::cargo_bin("microslip").expect("binary built by cargo");
    // Keep user presets of the machine running the tests out of the way.
    cmd.env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
        .env_remove("HOME");
    cmd
}

fn stdout_of(args: &[&str]) -> String {
    let output = microslip().args(args).output().unwrap();
    assert!(
        output.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(output.stderr.is_empty());
    String::from_utf8(output.stdout).unwrap()
}

/// The report of `compare` (or `bench`): exit 0 when its verdict agrees, 1 when it does not or
/// could not judge, with the short verdict as the one stderr line (issue 46, item 6). The verdict
/// is read from the report itself (the text's closing line, the JSON's `verdict.agrees`) and the
/// exit code checked against it; a CSV has none, its code is only checked to be 0 or 1.
fn compare_report(args: &[&str]) -> String {
    let output = microslip().args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    let stdout = String::from_utf8(output.stdout).unwrap();
    let code = output.status.code();
    assert!(
        matches!(code, Some(0 | 1)),
        "{args:?}: exit {code:?}: {stderr}"
    );
    let agrees = match serde_json::from_str::<serde_json::Value>(&stdout) {
        Ok(json) => json["verdict"]["agrees"].as_bool(),
        Err(_) => stdout
            .lines()
            .rev()
            .find(|l| l.starts_with("Verdict: "))
            .map(|l| l.starts_with("Verdict: agrees")),
    };
    if let Some(agrees) = agrees {
        assert_eq!(
            code == Some(0),
            agrees,
            "{args:?}: exit {code:?} against the verdict"
        );
    }
    if code == Some(1) {
        assert!(
            stderr.starts_with("microslip: verdict: "),
            "{args:?}: {stderr}"
        );
    }
    stdout
}

/// A generic command (`sweep`, `fit`) and its per-problem alias print the same bytes for each
/// of `formats` (given as `--format F` after the words).
fn same_bytes(generic: &[&str], alias: &[&str], formats: &[&str]) {
    for format in formats {
        let with = |words: &[&str]| {
            let mut all = words.to_vec();
            all.extend(["--format", format]);
            stdout_of(&all)
        };
        let (g, a) = (with(generic), with(alias));
        assert!(!a.is_empty(), "{alias:?} printed nothing");
        assert_eq!(g, a, "{generic:?} vs {alias:?} ({format})");
    }
}

/// Runs a command that must fail: one line on stderr, nothing on stdout, exit code `code`.
fn failure(args: &[&str], code: i32) -> String {
    let output = microslip().args(args).output().unwrap();
    assert_eq!(output.status.code(), Some(code), "{args:?}");
    assert!(output.stdout.is_empty(), "{args:?} wrote to stdout");
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    stderr
}

/// Fails when an output shows NaN, an infinity or "n/a" (as a word of text, a CSV field or a JSON
/// null, which is how serde_json writes a non-finite number).
fn assert_finite_output(args: &[&str], output: &str) {
    assert!(!output.contains("n/a"), "{args:?}: n/a in\n{output}");
    for token in output.split(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '.' | '_'))) {
        let word = token.to_ascii_lowercase();
        assert!(
            !matches!(word.as_str(), "nan" | "inf" | "infinity" | "null"),
            "{args:?}: {token} in\n{output}"
        );
    }
}

/// The rows of a CSV table, parsed as numbers where they are numbers.
fn csv_numbers(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').filter_map(|v| v.parse().ok()).collect())
        .collect()
}

/// True when `text` holds a control character other than a line feed, or a bidirectional control.
fn has_raw_control(text: &str) -> bool {
    text.chars()
        .any(|c| (c.is_control() && c != '\n') || ('\u{202a}'..='\u{202e}').contains(&c))
}

fn calculix_fixture(name: &str) -> String {
    format!("{}/tests/data/calculix/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// Pixels of `png` (RGBA) darker than mid-grey within the rows `rows` (PNG pixels).
fn dark_pixels(png: &resvg::tiny_skia::Pixmap, rows: std::ops::Range<u32>) -> usize {
    png.pixels()
        .chunks(png.width() as usize)
        .skip(rows.start as usize)
        .take((rows.end - rows.start) as usize)
        .flatten()
        .filter(|p| u32::from(p.red()) + u32::from(p.green()) + u32::from(p.blue()) < 3 * 100)
        .count()
}

/// The smallest K_T (MPa/mm) at which the paper's beams' regularized w(L) is within `tolerance` of
/// Coulomb's at every force of 0 < F <= 300 N, from the closed forms of docs/theory.md.
///
/// The worst forces are those in stick, F <= F_thre = 4 mu b h P / 3 = 80 N < F_1, where both
/// deflections are linear in F ((T2); tests/kt_tolerance.rs checks it by brute force over 1000
/// forces). There (B6) gives tau = tau_b (1 - cosh k(L - x) / cosh kL), and (B11)
/// w(L) = F L^3 / (2 E b h^3) - 3 / (2 E h^2) int_0^L tau(x) (L x - x^2 / 2) dx. With y = L - x,
/// L x - x^2 / 2 = (L^2 - y^2) / 2, int_0^L cosh(ky) dy = sinh(kL) / k and
/// int_0^L y^2 cosh(ky) dy = L^2 sinh(kL) / k - 2 L cosh(kL) / k^2 + 2 sinh(kL) / k^3:
///
///     int_0^L (1 - cosh k(L - x) / cosh kL)(L x - x^2 / 2) dx = L^3/3 - L/k^2 + tanh(kL)/k^3,
///
/// so, with tau_b = 3 F / (4 b h), w(L) = F (L^3 + 9 L / k^2 - 9 tanh(kL) / k^3) / (8 E b h^3).
/// Coulomb's stick is w(L) = F L^3 / (8 E b h^3) (B3), hence
///
///     w / w_Coulomb - 1 = 9 / (kL)^2 (1 - tanh(kL) / (kL))
///
/// (9 / (kL)^2 for large kL, the limit of section 1), which falls as kL grows: bisected on kL,
/// then K_T = (kL)^2 E h / (4 L^2) from k = 2 sqrt(K_T / (E h)) (B5).
fn paper_beams_stiffness_within(tolerance: f64) -> f64 {
    // The paper's beams (preset paper-beams): L (mm), h half the height (mm), E (MPa).
    let (length, half_height, youngs) = (200.0, 10.0, 210_000.0);
    let deviation = |kl: f64| 9.0 / (kl * kl) * (1.0 - kl.tanh() / kl);
    let (mut low, mut high) = (1.0, 1e4);
    assert!(deviation(low) > tolerance && deviation(high) < tolerance);
    for _ in 0..100 {
        let mid = 0.5 * (low + high);
        if deviation(mid) > tolerance {
            low = mid;
        } else {
            high = mid;
        }
    }
    high * high * youngs * half_height / (4.0 * length * length)
}

/// The smallest K_T (MPa/mm) at which the paper's plate's regularized u(L) is within `tolerance`
/// of Coulomb's, from the closed forms of docs/theory.md.
///
/// Far into macroslip, where coth(alpha X_r) = 1 to double precision, (P6) gives
/// L - X_r = l - 1 / alpha, and (P2) from u(X_r) = mu P / K_T gives
///
///     u(L) = mu P / K_T + kappa (l (l - 1 / alpha) - (l - 1 / alpha)^2 / 2)
///          = mu P / K_T + kappa l^2 / 2 - kappa / (2 alpha^2) = u_Coulomb + mu P / (2 K_T),
///
/// since kappa / alpha^2 = mu P / K_T ((P2), (P4)) and u_Coulomb = kappa l^2 / 2 (P3); the limit
/// K_T -> infinity of section 2. So u / u_Coulomb - 1 = mu P / (2 K_T u_Coulomb), and the K_T
/// sought is mu P / (2 tolerance u_Coulomb), with
/// u_Coulomb = (1 + nu) nu^2 t_p P / (2 (1 - nu) mu E) (7.9591836735e-6 mm, the header of
/// tests/data/plate-paper-fd.csv). At 1 % that K_T is 1.88e7 MPa/mm: alpha = 35 /mm,
/// X_r = 9.74 mm, alpha X_r = 341, where coth is 1 to 1e-290.
fn paper_plate_stiffness_within(tolerance: f64) -> f64 {
    // The paper's plate (preset paper-plate): mu, P (MPa), E (MPa), nu, t_p (mm).
    let (mu, pressure, youngs, poisson, thickness) = (0.3, 10.0, 70_000.0, 0.3, 0.2);
    let coulomb = (1.0 + poisson) * poisson * poisson * thickness * pressure
        / (2.0 * (1.0 - poisson) * mu * youngs);
    mu * pressure / (2.0 * tolerance * coulomb)
}

/// The series of a chart CSV: each name with its number of points and its largest x.
fn csv_series(data: &str) -> Vec<(String, usize, f64)> {
    let mut series: Vec<(String, usize, f64)> = Vec::new();
    for line in data.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let (name, x) = (cells[0].to_string(), cells[2].parse::<f64>().unwrap());
        match series.iter_mut().find(|s| s.0 == name) {
            Some(s) => {
                s.1 += 1;
                s.2 = s.2.max(x);
            }
            None => series.push((name, 1, x)),
        }
    }
    series
}

/// The names of the series `plot` writes as CSV with `args`.
fn plotted_names(args: &[&str]) -> Vec<String> {
    let data = stdout_of(&[&["plot"], args, &["--format", "csv"]].concat());
    csv_series(&data).into_iter().map(|s| s.0).collect()
}
