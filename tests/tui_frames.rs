//! Snapshot tests of rendered frames: each snapshot is a claim about what users see. Review changes
//! with `cargo insta review` (or read the `.snap.new` files) before accepting them.

use microslip::app::testing::{Action, App, AppOptions, Charset, Theme};
use microslip::chart::SeriesRole;
use microslip::preset;
use microslip::study::curves::Zone;
use proptest::prelude::*;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use std::collections::HashSet;

fn app_with(preset_name: &str, charset: Charset, color: bool) -> App {
    App::new(AppOptions {
        theme: Theme { charset, color },
        preset: preset::resolve(preset_name).unwrap(),
        user_dir: None,
        data: None,
        solve_continuum: false,
    })
}

fn app() -> App {
    app_with("paper-beams", Charset::Unicode, true)
}

fn render(app: &App, width: u16, height: u16) -> Terminal<TestBackend> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal
        .draw(|frame| microslip::app::testing::draw(frame, app))
        .unwrap();
    terminal
}

fn screen(app: &App, width: u16, height: u16) -> String {
    render(app, width, height).backend().to_string()
}

/// A key, and what it asks for done at once (files read and written, the fit run), as the event
/// loop would before drawing.
fn press(app: &mut App, action: Action) {
    microslip::app::testing::update_blocking(app, action);
}

fn act(app: &mut App, actions: &[Action]) {
    for &action in actions {
        press(app, action);
    }
}

#[test]
fn beam_view_80x24() {
    insta::assert_snapshot!(screen(&app(), 80, 24));
}

#[test]
fn beam_view_120x40() {
    insta::assert_snapshot!(screen(&app(), 120, 40));
}

#[test]
fn beam_charts() {
    let mut app = app();
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("beam_slip_boundary_chart", screen(&app, 100, 30));
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("beam_shear_chart", screen(&app, 100, 30));
}

#[test]
fn plate_views() {
    let mut app = app();
    press(&mut app, Action::SwitchModel);
    insta::assert_snapshot!("plate_view_80x24", screen(&app, 80, 24));
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("plate_slip_boundary_chart", screen(&app, 100, 30));
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("plate_contact_pressure_chart", screen(&app, 100, 30));
}

/// The lap joint, as a newcomer meets it: `m` twice from the beams, at 80x24 in ASCII (regime,
/// both sliding zones, Delta, D and zeta must show), at 120x40 in Unicode, and each of its charts.
#[test]
fn lap_views() {
    let mut ascii = app_with("paper-beams", Charset::Ascii, false);
    press(&mut ascii, Action::SwitchModel);
    press(&mut ascii, Action::SwitchModel);
    let small = screen(&ascii, 80, 24);
    for needed in [
        "macro+micro+macro",
        "a 0.989 d 3.85 mm sliding",
        "Delta regularized 0.0140117 mm",
        "D 2.08 N mm zeta 0.00789",
        "FE within 3.4 %",
    ] {
        assert!(small.contains(needed), "{needed}\n{small}");
    }
    insta::assert_snapshot!("lap_view_80x24_ascii", small);
    let mut app = app();
    press(&mut app, Action::SwitchModel);
    press(&mut app, Action::SwitchModel);
    insta::assert_snapshot!("lap_view_120x40", screen(&app, 120, 40));
    for name in [
        "lap_zones_chart",
        "lap_shear_chart",
        "lap_slip_chart",
        "lap_loop_chart",
        "lap_dissipation_chart",
    ] {
        press(&mut app, Action::NextChart);
        insta::assert_snapshot!(name, screen(&app, 100, 30));
    }
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("lap_kt_table", screen(&app, 80, 24));
}

#[test]
fn help_overlay() {
    let mut app = app();
    press(&mut app, Action::ToggleHelp);
    insta::assert_snapshot!(screen(&app, 80, 24));
}

/// At 80x24 the zone strip is two bare rows: its symbols are explained on the regime pane's lower
/// border, and, with every chart mark, on a page of the help (`j` turns the pages).
#[test]
fn the_zone_symbols_are_explained_at_80x24() {
    let mut app = app_with("paper-beams", Charset::Ascii, false);
    assert!(screen(&app, 80, 24).contains("+ =stick ~microslip #macroslip --+"));
    press(&mut app, Action::ToggleHelp);
    let pages: String = (0..4)
        .map(|_| {
            let page = screen(&app, 80, 24);
            press(&mut app, Action::Next);
            page
        })
        .collect();
    for text in [
        "= stick ~ microslip # macroslip",
        "* Coulomb x K_T o softer + stiffer",
        "- limit # FE @ continuum % measured",
    ] {
        assert!(pages.contains(text), "{text}");
    }
}

#[test]
fn preset_picker() {
    let mut app = app();
    press(&mut app, Action::OpenPresets);
    press(&mut app, Action::Next);
    insta::assert_snapshot!(screen(&app, 80, 24));
}

#[test]
fn input_error_keeps_the_old_value_and_says_why() {
    let mut app = app();
    act(
        &mut app,
        &[
            Action::Next,
            Action::Next,
            Action::Next,
            Action::Next,
            Action::Next,
            Action::Next,
            Action::StartEdit,
            Action::Input('-'),
            Action::Input('3'),
        ],
    );
    insta::assert_snapshot!("typing_a_value", screen(&app, 80, 24));
    press(&mut app, Action::Commit);
    insta::assert_snapshot!("input_error", screen(&app, 80, 24));
}

/// The beams' `h` is half of each beam's height: its row says `half` (as the plate's `L` row does)
/// and its prompt says what it is, so nobody types the whole 20 mm height.
#[test]
fn the_beams_half_height_says_half_in_its_row_and_its_prompt() {
    let mut app = app();
    act(&mut app, &[Action::Next, Action::Next]);
    let text = screen(&app, 120, 40);
    let row = text
        .lines()
        .find(|l| l.contains(">  h") || l.contains("> h"))
        .unwrap_or_else(|| panic!("no selected h row:\n{text}"));
    assert!(row.contains("mm half"), "{row}");
    press(&mut app, Action::StartEdit);
    let text = screen(&app, 120, 40);
    assert!(
        text.contains("h (mm, half height (each beam is 2h high))"),
        "{text}"
    );
}

/// The regime title's "FE within 3.02 %" is explained by `i` (its first line) and by `?`.
#[test]
fn the_regime_titles_envelope_is_explained_by_i_and_by_the_help() {
    for preset in ["paper-beams", "lap-aluminium"] {
        let mut app = app_with(preset, Charset::Unicode, true);
        press(&mut app, Action::Explain);
        let text = screen(&app, 100, 30);
        assert!(text.contains("┌ FE within"), "{preset}:\n{text}");
        assert!(text.contains("continuum"), "{preset}:\n{text}");
        assert!(text.contains("line 1/"), "{preset}:\n{text}");
    }
    let mut app = app();
    press(&mut app, Action::ToggleHelp);
    let mut help = String::new();
    for _ in 0..4 {
        help.push_str(&screen(&app, 120, 40));
        press(&mut app, Action::Next);
    }
    assert!(help.contains("Regime title \"FE within 3 %\""), "{help}");
}

/// Issue 36 (20): a refused value shows what was typed, invisible characters escaped and the
/// range given, in the value field and on the `:` line.
#[test]
fn refused_values_show_invisible_characters_and_the_range() {
    let mut app = app();
    press(&mut app, Action::CommandLine);
    type_and_commit(&mut app, "KT=\u{200b}1000");
    let text = screen(&app, 120, 40);
    assert!(
        text.contains(
            "invalid value '\\u{200b}1000' for KT: not a finite number; must be in [1e-6"
        ),
        "{text}"
    );
    let mut app = self::app();
    act(&mut app, &[Action::Next; 7]);
    press(&mut app, Action::StartEdit);
    type_and_commit(&mut app, "1e-400");
    let text = screen(&app, 120, 40);
    assert!(
        text.contains("invalid KT = 1e-400: must be in [1e-6, 1e12] MPa/mm"),
        "{text}"
    );
}

#[test]
fn ascii_charset_draws_only_ascii() {
    let mut app = app_with("paper-beams", Charset::Ascii, true);
    let text = screen(&app, 80, 24);
    assert!(text.is_ascii(), "non-ASCII character in the ASCII screen");
    insta::assert_snapshot!("ascii_beam_view", text);
    for action in [
        Action::NextChart,
        Action::NextChart,
        Action::SwitchModel,
        Action::NextChart,
        Action::NextChart,
        Action::ToggleHelp,
    ] {
        press(&mut app, action);
        assert!(screen(&app, 80, 24).is_ascii(), "after {action:?}");
    }
}

#[test]
fn no_color_marks_selection_and_curves_with_characters() {
    let app = app_with("paper-beams", Charset::Unicode, false);
    let terminal = render(&app, 80, 24);
    let buffer = terminal.backend().buffer();
    assert!(
        buffer
            .content
            .iter()
            .all(|c| c.fg == ratatui::style::Color::Reset && c.bg == ratatui::style::Color::Reset)
    );
    insta::assert_snapshot!("no_color_beam_view", terminal.backend().to_string());
}

#[test]
fn finite_element_points_over_the_curve() {
    let mut app = app_with("paper-beams", Charset::Ascii, false);
    press(&mut app, Action::ToggleNumeric);
    insta::assert_snapshot!(screen(&app, 100, 30));
}

#[test]
fn terminal_too_small() {
    insta::assert_snapshot!(screen(&app(), 60, 16));
}

/// What a user must see at a terminal size.
#[derive(Debug, Clone, Copy)]
enum MustSee {
    /// Too small even for the message: its first characters, in reading order.
    StartOfTooSmall,
    /// Below the minimum, 80x24: the whole message saying so.
    TooSmall,
    /// The main screen: parameter pane, chart and key strip.
    Main,
}

/// The rows of a frame, without the quotes of `TestBackend`'s text.
fn rows(app: &App, width: u16, height: u16) -> Vec<String> {
    screen(app, width, height)
        .lines()
        .map(|l| l.trim_matches('"').to_string())
        .collect()
}

/// The words of `rows` in reading order, one space apart.
fn words(rows: &[String]) -> String {
    rows.join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Each size shows what it must, so a blank or half-drawn frame fails: below 80x24 the message
/// saying so (as much of it as fits), at and above it the parameter pane, the chart and the key
/// strip, and with the help open its title.
#[test]
fn every_size_and_state_shows_what_the_user_needs() {
    let mut app = app();
    let sizes = [
        (1, 1, MustSee::StartOfTooSmall),
        (10, 3, MustSee::StartOfTooSmall),
        (79, 24, MustSee::TooSmall),
        (80, 23, MustSee::TooSmall),
        (80, 24, MustSee::Main),
        (81, 25, MustSee::Main),
        (200, 60, MustSee::Main),
        (300, 100, MustSee::Main),
    ];
    for (w, h, must_see) in sizes {
        let rows = rows(&app, w, h);
        let shown = words(&rows);
        let message = format!(
            "Terminal too small: {w}x{h}. microslip needs at least 80x24. \
             Enlarge the window, or press q (Ctrl-C) to quit."
        );
        match must_see {
            MustSee::StartOfTooSmall => assert!(
                !shown.is_empty() && message.starts_with(&shown),
                "{w}x{h}: {shown:?}"
            ),
            MustSee::TooSmall => assert_eq!(shown, message, "{w}x{h}"),
            MustSee::Main => assert_main_screen(&rows, w, h),
        }
    }
    press(&mut app, Action::ToggleHelp);
    for (w, h, _) in sizes.into_iter().filter(|s| matches!(s.2, MustSee::Main)) {
        let rows = rows(&app, w, h);
        assert_edges(&rows, w, h);
        assert!(
            rows.iter().any(|r| r.contains("┌ Keys (Esc or ? closes) ")),
            "{w}x{h}: no help title\n{}",
            rows.join("\n")
        );
    }
}

/// The paper's beams on the main screen: its edges, the chart's heading, and the force axis's
/// title on the chart's lower border.
fn assert_main_screen(rows: &[String], w: u16, h: u16) {
    assert_edges(rows, w, h);
    let text = rows.join("\n");
    assert!(
        text.contains("│ w(L) vs F, K_T = 600 MPa/mm"),
        "{w}x{h}:\n{text}"
    );
    assert!(
        rows[rows.len() - 2].ends_with(" F (N) ┘"),
        "{w}x{h}:\n{text}"
    );
}

/// What stays in sight over any overlay: the parameter pane's title top left, the chart pane's
/// title beside it, and the key strip on the last row.
fn assert_edges(rows: &[String], w: u16, h: u16) {
    let text = rows.join("\n");
    assert_eq!(rows.len(), usize::from(h), "{w}x{h}");
    assert!(
        rows[0].starts_with("┌ Twin beams, Euler-Bernoulli ")
            && rows[0].contains("┐┌ w(L) vs F (1/6, c cycles) "),
        "{w}x{h}:\n{text}"
    );
    assert!(
        rows[rows.len() - 1].starts_with(" beam | paper-beams | ? help  q quit"),
        "{w}x{h}:\n{text}"
    );
}

#[test]
fn measured_points_on_the_deflection_chart() {
    // Measurements from the closed form with K_T = 300 MPa/mm, shown over the K_T = 600 curves.
    let beams = microslip::TwinBeams::new(microslip::TwinBeamsParams {
        tangential_stiffness: 300.0,
        ..microslip::TwinBeamsParams::PAPER
    })
    .unwrap();
    let points = (1..=12)
        .map(|i| {
            let force = 20.0 * f64::from(i);
            let deflection = beams
                .regularized(microslip::TipForce::new(force).unwrap())
                .tip_deflection();
            microslip::fit::Measurement {
                force,
                response: deflection,
            }
        })
        .collect();
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Ascii,
            color: false,
        },
        preset: preset::resolve("paper-beams").unwrap(),
        user_dir: None,
        data: Some(microslip::app::testing::Measurements {
            path: "bench.csv".into(),
            points,
        }),
        solve_continuum: false,
    });
    insta::assert_snapshot!("measured_points", screen(&app, 100, 30));
    press(&mut app, Action::Fit);
    insta::assert_snapshot!("after_fit", screen(&app, 100, 30));
}

/// `f` fits the lap joint as it fits the beams (issue 32): its measured Delta(F), drawn from the
/// bundled joint (mu = 0.3, K_T = 1000 MPa/mm) with a gauge's scatter, shows on Delta vs F at
/// K_T = 400, and the fit brings K_T back to about 1000.
#[test]
fn the_lap_joint_is_fitted_with_f() {
    use microslip::problems::inputs::{Inputs, Model};
    let Ok(Model::Lap { joint, .. }) =
        Inputs::paper(microslip::problems::ModelKind::Lap).validate()
    else {
        panic!("the bundled lap joint")
    };
    let points = (1..=14)
        .map(|i| {
            let force = 400.0 * f64::from(i);
            // A gauge's scatter, +-0.4 % alternating: the errors of the fit are not round-off.
            let scatter = if i % 2 == 0 { 1.004 } else { 0.996 };
            let deflection = scatter
                * joint
                    .regularized(joint.force(force).unwrap())
                    .joint_displacement();
            microslip::fit::Measurement {
                force,
                response: deflection,
            }
        })
        .collect();
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Ascii,
            color: false,
        },
        preset: preset::resolve("lap-aluminium").unwrap(),
        user_dir: None,
        data: Some(microslip::app::testing::Measurements {
            path: "joint.csv".into(),
            points,
        }),
        solve_continuum: false,
    });
    press(&mut app, Action::CommandLine);
    act(
        &mut app,
        &"KT=400".chars().map(Action::Input).collect::<Vec<_>>(),
    );
    press(&mut app, Action::Commit);
    insta::assert_snapshot!("lap_measured_points", screen(&app, 100, 30));
    press(&mut app, Action::Fit);
    insta::assert_snapshot!("lap_after_fit", screen(&app, 100, 30));
}

#[test]
fn stiffness_panels() {
    let mut app = app();
    press(&mut app, Action::PreviousChart);
    insta::assert_snapshot!("beam_stiffness_panel", screen(&app, 80, 24));
    press(&mut app, Action::SwitchModel);
    press(&mut app, Action::PreviousChart);
    insta::assert_snapshot!("plate_stiffness_panel", screen(&app, 80, 24));
}

#[test]
fn cyclic_loading_charts() {
    let mut app = app_with("paper-beams-soft", Charset::Unicode, true);
    for _ in 0..3 {
        press(&mut app, Action::NextChart);
    }
    insta::assert_snapshot!("hysteresis_loop", screen(&app, 100, 30));
    press(&mut app, Action::NextChart);
    insta::assert_snapshot!("dissipation_vs_amplitude", screen(&app, 100, 30));
}

#[test]
fn the_d_key_refuses_a_measurement_file_above_the_cap() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.csv");
    // Sparse: refused by its size, never read.
    std::fs::File::create(&path)
        .unwrap()
        .set_len((256 << 20) + 1)
        .unwrap();
    let mut app = app();
    press(&mut app, Action::LoadData);
    for c in path.to_str().unwrap().chars() {
        press(&mut app, Action::Input(c));
    }
    press(&mut app, Action::Commit);
    let message = app.message().expect("a message");
    assert!(message.is_error);
    assert!(
        message
            .text
            .ends_with("huge.csv: file is larger than the 256 MiB limit for a measurement file"),
        "{}",
        message.text
    );
    assert!(app.measurements().is_none());
}

#[test]
fn the_preset_picker_shows_control_characters_escaped() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("evil\u{1b}[2J.toml"),
        "model = \"beam\"\ndescription = \"bell \\u0007 \\u001b]0;title\\u0007 \\u202e\"\n",
    )
    .unwrap();
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Ascii,
            color: false,
        },
        preset: preset::resolve("paper-beams").unwrap(),
        user_dir: Some(dir.path().to_path_buf()),
        data: None,
        solve_continuum: false,
    });
    press(&mut app, Action::OpenPresets);
    let text = screen(&app, 100, 30);
    assert!(
        text.contains(r"evil\x1b[2J") && text.contains(r"bell \x07 \x1b]0;title\x07 \u{202e}"),
        "{text}"
    );
    assert!(!text.contains('\u{202e}'));
}

#[test]
fn the_picker_never_loads_a_user_file_named_like_a_bundled_preset() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("paper-beams.toml"),
        "model = \"beam\"\nKT = 5\n",
    )
    .unwrap();
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Ascii,
            color: false,
        },
        preset: preset::resolve("paper-beams-soft").unwrap(),
        user_dir: Some(dir.path().to_path_buf()),
        data: None,
        solve_continuum: false,
    });
    press(&mut app, Action::OpenPresets);
    // Bundled: paper-beams, paper-beams-soft (selected), paper-plate, lap-aluminium; then the
    // user's paper-beams.
    press(&mut app, Action::Next);
    press(&mut app, Action::Next);
    press(&mut app, Action::Next);
    let text = screen(&app, 120, 30);
    assert!(
        text.contains("> paper-beams        ?     user    WARNING: shadowed by the bundled one"),
        "{text}"
    );
    press(&mut app, Action::Commit);
    assert_eq!(app.preset_name(), "paper-beams-soft");
    let message = app.message().unwrap();
    assert!(message.is_error);
    assert!(
        message
            .text
            .starts_with("cannot load paper-beams: named like the bundled preset"),
        "{}",
        message.text
    );
    // The picker stays open; picking the bundled one (first row) loads the bundled values.
    for _ in 0..4 {
        press(&mut app, Action::Previous);
    }
    press(&mut app, Action::Commit);
    assert_eq!(app.preset_name(), "paper-beams");
    assert_eq!(
        app.inputs()
            .get(microslip::Param::Beam(microslip::BeamParam::Stiffness)),
        Some(600.0)
    );
}

/// Types `text` into the open prompt and presses Enter.
fn type_and_commit(app: &mut App, text: &str) {
    for c in text.chars() {
        press(app, Action::Input(c));
    }
    press(app, Action::Commit);
}

/// Types `path` into the `d` prompt and loads it.
fn load_data(app: &mut App, path: &str) {
    press(app, Action::LoadData);
    type_and_commit(app, path);
}

#[test]
fn a_long_status_message_takes_rows_from_the_panes_and_never_covers_the_chart() {
    let mut app = app();
    let path = "/nonexistent/measurements/from the bench in building 7/campaign 2031-04/\
                specimen 12 of 40, second loading branch after the gauge reset.csv";
    load_data(&mut app, path);
    let text = screen(&app, 80, 24);
    let rows: Vec<&str> = text.lines().collect();
    // Every word of the message is on screen, in order, across the bottom rows.
    let joined: String = rows[21..]
        .iter()
        .map(|l| l.trim_matches('"').trim())
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        joined.contains("specimen 12 of 40, second loading branch after the gauge reset.csv: No such file or directory"),
        "{text}"
    );
    // Above it, the panes end with their borders and the chart with its x axis title.
    assert!(
        rows[20].contains("F (N)") && rows[20].starts_with("\"└"),
        "{text}"
    );
    insta::assert_snapshot!("long_status_message", text);
    // The same at 100x30 after loading CalculiX results (the issue's case): the chart keeps its
    // axis, the message its rows.
    let mut app = app_with("paper-beams-soft", Charset::Ascii, false);
    load(&mut app, "tests/data/calculix/paper-beams.dat");
    let text = screen(&app, 100, 30);
    let rows: Vec<&str> = text.lines().collect();
    let status_rows = rows
        .iter()
        .rev()
        .take_while(|r| !r.contains("F (N)"))
        .count();
    assert!((2..=4).contains(&status_rows), "{text}");
    assert!(
        rows[rows.len() - 1 - status_rows].starts_with("\"+"),
        "{text}"
    );
    // Too long even for three lines: what fits, then how to read it all.
    let mut app = app_with("paper-beams", Charset::Ascii, false);
    load_data(
        &mut app,
        &format!("/nonexistent/{}.csv", "very long name ".repeat(30)),
    );
    let text = screen(&app, 80, 24);
    let rows: Vec<&str> = text.lines().collect();
    assert!(
        rows[23]
            .trim_end_matches('"')
            .trim_end()
            .ends_with("... M reads all"),
        "{text}"
    );
    assert!(rows[20].contains("F (N)"), "{text}");
    assert!(
        rows[21].contains("beam | paper-beams | /nonexistent/very long"),
        "{text}"
    );
    // M shows it whole; Esc closes.
    press(&mut app, Action::ShowMessage);
    let text = screen(&app, 80, 24);
    assert!(
        text.contains("Message") && text.contains("No such file"),
        "{text}"
    );
    press(&mut app, Action::Cancel);
    // A short message again: back to one line.
    press(&mut app, Action::SwitchModel);
    let text = screen(&app, 80, 24);
    assert!(!text.contains("very long"), "{text}");
}

/// The README's capture: the paper's beams compared with two pinned friction coefficients, at
/// 100x30, where the zone strip names X.
fn readme_app() -> App {
    let mut app = app();
    set(&mut app, "mu", "0.2");
    press(&mut app, Action::Pin);
    set(&mut app, "mu", "0.45");
    press(&mut app, Action::Pin);
    set(&mut app, "mu", "0.3");
    for _ in 0..20 {
        press(&mut app, Action::Previous);
    }
    app
}

#[test]
fn the_readme_shows_the_real_main_screen() {
    let readme = include_str!("../README.md");
    let start = readme
        .find("```text\n┌ Twin beams")
        .expect("the screen capture in README.md")
        + "```text\n".len();
    let end = start + readme[start..].find("```").unwrap();
    let captured: Vec<&str> = readme[start..end].lines().map(str::trim_end).collect();
    let real = screen(&readme_app(), 100, 30);
    insta::assert_snapshot!("readme_pins_and_strip_100x30", real);
    let real: Vec<&str> = real
        .lines()
        .map(|l| l.trim_matches('"').trim_end())
        .collect();
    assert_eq!(captured, real);
}

/// Types `path` into the `d` prompt and loads it.
fn load(app: &mut App, path: &str) {
    press(app, Action::LoadData);
    // The prompt starts with the previous path: clear it first.
    for _ in 0..200 {
        press(app, Action::Backspace);
    }
    type_and_commit(app, path);
}

#[test]
fn calculix_points_on_the_deflection_and_displacement_charts() {
    // Real CalculiX 2.20 results (tests/data/calculix); the deck's parameters become the model's.
    let mut app = app_with("paper-beams-soft", Charset::Ascii, false);
    load(&mut app, "tests/data/calculix/paper-beams.dat");
    insta::assert_snapshot!("calculix_beam_points", screen(&app, 120, 40));
    // Two plate runs of the same deck but for K_T make a curve of two points.
    load(&mut app, "tests/data/calculix/plate-kt1e4.dat");
    load(&mut app, "tests/data/calculix/paper-plate.dat");
    insta::assert_snapshot!("calculix_plate_points", screen(&app, 120, 40));
}

/// A screen reached from the paper's beams by a list of actions, and the sizes it is snapshotted
/// at (Unicode, in colour). Each used to have an ASCII twin snapshot as well; the ASCII charset is
/// now covered, over these screens and any size, by
/// `ascii_frames_are_the_unicode_frames_in_ascii_glyphs`, and the snapshots kept their
/// `_unicode` names.
#[derive(Debug, Clone)]
struct Screen {
    name: &'static str,
    actions: Vec<Action>,
    sizes: &'static [(u16, u16)],
}

impl Screen {
    fn new(name: &'static str, actions: Vec<Action>, sizes: &'static [(u16, u16)]) -> Screen {
        Screen {
            name,
            actions,
            sizes,
        }
    }

    /// The paper's beams after the screen's actions.
    fn app(&self, charset: Charset, color: bool) -> App {
        let mut app = app_with("paper-beams", charset, color);
        act(&mut app, &self.actions);
        app
    }

    fn snapshot(&self) {
        let app = self.app(Charset::Unicode, true);
        for &(w, h) in self.sizes {
            insta::assert_snapshot!(format!("{}_{w}x{h}_unicode", self.name), screen(&app, w, h));
        }
    }
}

/// mu is the beams' seventh row (L b h E nu P mu).
const MU_ROW: usize = 6;

/// The actions that select row `row` (counted from the top) and type `value` into it.
fn set_row(row: usize, value: &str) -> Vec<Action> {
    let mut actions = vec![Action::Previous; 20];
    actions.extend(std::iter::repeat_n(Action::Next, row));
    actions.push(Action::StartEdit);
    actions.extend(value.chars().map(Action::Input));
    actions.push(Action::Commit);
    actions
}

/// The workbench of issue 16: w(L) against the selected parameter (`v`), the explanation of a
/// regime line (`i`), the target prompt (`t`) and its answer, and a tall screen whose spare height
/// explains every line.
fn workbench_screens() -> [Screen; 5] {
    let vary = [vec![Action::Next; MU_ROW], vec![Action::Vary]].concat();
    let explain = [
        &vary[..],
        &[Action::Vary, Action::Explain],
        // The title's envelope first, then the pane's lines down to F_1.
        &[Action::Next; 5],
    ]
    .concat();
    let prompt = [
        &explain[..],
        &[Action::Cancel, Action::Next, Action::SolveTarget],
    ]
    .concat();
    let solved = [&prompt[..], &[Action::Commit]].concat();
    [
        Screen::new("main", Vec::new(), &[(200, 60)]),
        Screen::new("vary_mu", vary, &[(80, 24), (200, 60)]),
        Screen::new("explain_f1", explain, &[(80, 24)]),
        Screen::new("target_prompt", prompt, &[(80, 24)]),
        Screen::new("target_solved", solved, &[(80, 24)]),
    ]
}

/// The y-axis modes of `y` (issue 15): w(L) vs F relative to Coulomb, where the K_T family
/// separates, and u(L) vs K_T on its default log axis.
fn y_axis_screens() -> [Screen; 2] {
    let relative = vec![Action::CycleYAxis; 2];
    let log_u = [&relative[..], &[Action::SwitchModel]].concat();
    [
        Screen::new("y_relative_w", relative, &[(80, 24), (120, 40)]),
        Screen::new("y_log_u", log_u, &[(80, 24), (120, 40)]),
    ]
}

/// The paper's beams (mu 0.3) and mu 0.2 pinned, compared with mu 0.45; then X vs F, where the pins
/// follow the chart switch.
fn pin_screens() -> [Screen; 2] {
    let pins = [
        vec![Action::Pin],
        set_row(MU_ROW, "0.2"),
        vec![Action::Pin],
        set_row(MU_ROW, "0.45"),
    ]
    .concat();
    let slip_boundary = [&pins[..], &[Action::NextChart]].concat();
    [
        Screen::new("pins", pins, &[(80, 24), (120, 40)]),
        Screen::new("pins_slip_boundary", slip_boundary, &[(120, 40)]),
    ]
}

#[test]
fn workbench_panes_at_80x24_and_200x60() {
    workbench_screens().iter().for_each(Screen::snapshot);
}

#[test]
fn y_axis_modes_at_80x24_and_120x40() {
    let [relative, log_u] = y_axis_screens();
    relative.snapshot();
    log_u.snapshot();
    let relative_title = |app: &App| app.plot().y.title.contains("Coulomb - 1 (%)");
    assert!(relative_title(&relative.app(Charset::Unicode, true)));
    let mut app = log_u.app(Charset::Unicode, true);
    assert!(app.plot().y.log, "u(L) vs K_T opens on a log axis");
    // Through the lap joint (its own mode, linear) back to the beams: the relative mode of w(L)
    // vs F was kept.
    press(&mut app, Action::SwitchModel);
    assert!(!app.plot().y.log && !relative_title(&app));
    press(&mut app, Action::SwitchModel);
    assert!(relative_title(&app));
}

#[test]
fn pins_and_the_zone_strip_at_80x24_and_120x40() {
    pin_screens().iter().for_each(Screen::snapshot);
}

/// Selects the row of `name` and types `value` into it.
fn set(app: &mut App, name: &str, value: &str) {
    let row = app.kind().params().iter().position(|p| p.name() == name);
    act(app, &set_row(row.expect("a parameter of the model"), value));
}

/// Each Unicode glyph and the ASCII ones that may stand for it: the theme's own pairs (borders,
/// which also give the lines and corner of ratatui's chart axes; curve, zone and cursor symbols),
/// and the sparkline levels of the same height (the charsets have eight and seven steps, so a level
/// meets one or two of the other's).
fn ascii_glyphs() -> HashSet<(&'static str, &'static str)> {
    let [unicode, ascii] = [Charset::Unicode, Charset::Ascii].map(|charset| Theme {
        charset,
        color: false,
    });
    let borders = |theme: &Theme| {
        let s = theme.border_set();
        [
            s.top_left,
            s.top_right,
            s.bottom_left,
            s.bottom_right,
            s.vertical_left,
            s.vertical_right,
            s.horizontal_top,
            s.horizontal_bottom,
        ]
    };
    let zones = |theme: &Theme| {
        [
            Zone::Stick,
            Zone::Microslip,
            Zone::Macroslip,
            Zone::Unloaded,
        ]
        .map(|zone| theme.zone_symbol(zone))
    };
    let mut pairs: HashSet<_> = borders(&unicode).into_iter().zip(borders(&ascii)).collect();
    pairs.extend(zones(&unicode).into_iter().zip(zones(&ascii)));
    let roles = SeriesRole::CHART_ROLES
        .into_iter()
        .chain((1..=4).map(SeriesRole::Pin))
        .chain((1..=6).map(SeriesRole::Family));
    pairs.extend(roles.map(|r| (unicode.series_symbol(r), ascii.series_symbol(r))));
    pairs.insert((unicode.cursor_symbol(), ascii.cursor_symbol()));
    let (u, a) = (unicode.spark_levels(), ascii.spark_levels());
    let (m, n) = ((u.len() - 1) as f64, (a.len() - 1) as f64);
    for (i, &high) in u.iter().enumerate() {
        for (j, &low) in a.iter().enumerate() {
            // Level i stands for ratios within half a step of i / m.
            if (i as f64 / m - j as f64 / n).abs() <= 0.5 / m + 0.5 / n {
                pairs.insert((high, low));
            }
        }
    }
    pairs
}

/// Every screen that had an ASCII twin snapshot.
fn twinned_screens() -> Vec<Screen> {
    let mut screens = workbench_screens().to_vec();
    screens.extend(y_axis_screens());
    screens.extend(pin_screens());
    screens
}

/// Steps a user may take from any of the screens: a key, or 0.4 typed into the seventh row (mu on
/// the beams). Not the finite-element points (`n`): solving them makes a case ten times slower in
/// a debug build, and `finite_element_points_over_the_curve` shows them in ASCII.
fn step() -> impl Strategy<Value = Vec<Action>> {
    let keys = [
        Action::Next,
        Action::Previous,
        Action::NextChart,
        Action::PreviousChart,
        Action::SwitchModel,
        Action::CycleYAxis,
        Action::Pin,
        Action::Vary,
        Action::Explain,
        Action::ToggleHelp,
        Action::ToggleBeamTheory,
        Action::Cancel,
    ];
    let mut steps: Vec<Vec<Action>> = keys.into_iter().map(|key| vec![key]).collect();
    steps.push(vec![Action::SolveTarget, Action::Commit]);
    steps.push(set_row(MU_ROW, "0.4"));
    prop::sample::select(steps)
}

/// Cases of the charset property: two frames of up to 220x70 each, after up to a dozen actions
/// (about 40 ms a case in a debug build).
const CASES: u32 = 64;

proptest! {
    #![proptest_config(ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::with_cases(CASES)
    })]

    /// The ASCII charset draws only 7-bit characters, and its frame is the Unicode one with each
    /// glyph replaced by an ASCII counterpart: same text in the same cells. The Unicode frame is
    /// the one without colour, where both charsets tell curves apart by symbols (a Braille line
    /// has no counterpart); the ASCII frame must match it in colour too, and without colour
    /// style for style as well.
    #[test]
    fn ascii_frames_are_the_unicode_frames_in_ascii_glyphs(
        start in prop::sample::select(twinned_screens()),
        steps in prop::collection::vec(step(), 0..6),
        width in 60u16..=220,
        height in 16u16..=70,
        color: bool,
    ) {
        let actions: Vec<Action> = steps.concat();
        let frame = |charset, color| {
            let mut app = start.app(charset, color);
            act(&mut app, &actions);
            render(&app, width, height).backend().buffer().clone()
        };
        let (unicode, ascii) = (frame(Charset::Unicode, false), frame(Charset::Ascii, color));
        let glyphs = ascii_glyphs();
        for (i, (u, a)) in unicode.content.iter().zip(&ascii.content).enumerate() {
            let (x, y) = (i % usize::from(width), i / usize::from(width));
            let (high, low) = (u.symbol(), a.symbol());
            prop_assert!(low.is_ascii(), "({x}, {y}): {low:?}");
            prop_assert!(
                high == low || glyphs.contains(&(high, low)),
                "({x}, {y}): {high:?} drawn as {low:?}"
            );
            if !color {
                prop_assert_eq!(u.style(), a.style(), "({}, {})", x, y);
            }
        }
    }
}

#[test]
fn pins_in_relative_mode_and_on_the_plate() {
    let mut app = app();
    press(&mut app, Action::Pin);
    set(&mut app, "KT", "2000");
    press(&mut app, Action::CycleYAxis);
    press(&mut app, Action::CycleYAxis);
    assert_eq!(app.y_mode(), microslip::chart::YMode::Relative);
    insta::assert_snapshot!("pins_relative_120x40", screen(&app, 120, 40));
    // Without colour, on the plate: the pin is told apart by its number.
    let mut app = app_with("paper-plate", Charset::Unicode, false);
    press(&mut app, Action::Pin);
    set(&mut app, "tp", "0.5");
    insta::assert_snapshot!("pins_plate_80x24_no_color", screen(&app, 80, 24));
}

/// The chart pane's plotting cells of an 80x24 frame (the SSH case): the rows between the legend
/// and the x axis, right of the y axis, inside the pane's border.
fn chart_body(text: &str) -> Vec<String> {
    let rows: Vec<&str> = text.lines().map(|l| l.trim_matches('"')).collect();
    // The x axis: the pane's row whose chart part is a `+` then dashes.
    let axis_row = rows
        .iter()
        .position(|r| r.chars().skip(34).collect::<String>().contains("+---"))
        .expect("an x axis");
    let axis_column = rows[axis_row][34..].find('+').expect("the axis corner") + 34;
    rows[3..axis_row]
        .iter()
        .map(|r| {
            r.chars()
                .skip(axis_column + 1)
                .take(79 - axis_column - 1)
                .collect()
        })
        .collect()
}

/// Every view the `c` key cycles through, on both models, at 80x24 in ASCII without colour (an SSH
/// session): a snapshot each, the title whole, and every series' own marker drawn in the chart
/// (not only in the legend), so that each series can be told apart; the finite-element and
/// continuum points (`n`) with marks of their own.
#[test]
fn every_chart_at_80x24_in_ascii_shows_each_series_by_its_own_marker() {
    use microslip::chart::SeriesKind;
    for (preset, name) in [("paper-beams", "beam"), ("paper-plate", "plate")] {
        let mut app = app_with(preset, Charset::Ascii, false);
        let theme = Theme {
            charset: Charset::Ascii,
            color: false,
        };
        let (_, _, count) = app.views().describe(app.kind());
        for position in 1..=count {
            let text = screen(&app, 80, 24);
            insta::assert_snapshot!(format!("ascii_80x24_{name}_{position}"), text);
            let plot = app.plot().clone();
            if app.table().is_none() {
                assert!(text.contains(&plot.title), "title cut: {}", plot.title);
                let body = chart_body(&text).concat();
                for series in &plot.series {
                    let mark = match series.kind() {
                        SeriesKind::Cursor => theme.cursor_symbol(),
                        _ => theme.series_symbol(series.role),
                    };
                    assert!(
                        body.contains(mark),
                        "{name} {position} ({}): no {mark} for {}\n{text}",
                        plot.title,
                        series.name
                    );
                }
            }
            press(&mut app, Action::NextChart);
        }
    }
    // u(L) vs K_T with the project's finite-element points and the 2-D continuum: two marks.
    let mut app = app_with("paper-plate", Charset::Ascii, false);
    press(&mut app, Action::ToggleNumeric);
    let text = screen(&app, 80, 24);
    insta::assert_snapshot!("ascii_80x24_plate_fe_and_continuum", text);
    let body = chart_body(&text).concat();
    assert!(body.contains('#') && body.contains('@'), "{text}");
}

#[test]
fn a_deflection_far_beyond_the_measured_range_claims_no_envelope() {
    let mut app = app();
    press(&mut app, Action::CommandLine);
    for c in "F=1e12".chars() {
        press(&mut app, Action::Input(c));
    }
    press(&mut app, Action::Commit);
    let text = screen(&app, 80, 24);
    assert!(
        text.contains("Regime (i), FE: w/L too big") && !text.contains("FE within"),
        "{text}"
    );
    // The paper's force keeps its number.
    let text = screen(&self::app(), 80, 24);
    assert!(text.contains("Regime (i), FE within 3 %"), "{text}");
}

#[test]
fn a_friction_strain_beyond_the_calibration_claims_no_envelope() {
    // mu P = 10 MPa on the paper's beams: mu P L / (2 E h) = 4.8e-4, beyond the 1.2e-4 of (V2).
    let mut app = app();
    press(&mut app, Action::CommandLine);
    for c in "mu=1 P=10".chars() {
        press(&mut app, Action::Input(c));
    }
    press(&mut app, Action::Commit);
    let text = screen(&app, 80, 24);
    assert!(
        text.contains("Regime (i), FE: not calibrated") && !text.contains("FE within"),
        "{text}"
    );
}

/// The x tick labels between the ends on the chart drawn at `width` x `height`, each as (the
/// column of its centre, in cells from the graph's left edge, and its value), and the graph's width
/// in cells. The graph is found by the axes' corner `└` and the x axis drawn from
/// it; the labels are on the row under the axis.
fn x_tick_labels(app: &App, width: u16, height: u16) -> (Vec<(f64, f64)>, usize) {
    let rows = rows(app, width, height);
    let (axis_row, corner) = rows
        .iter()
        .enumerate()
        .rev()
        .find_map(|(r, row)| {
            // The axes' corner has the y labels' blanks on its left; a pane's has a border.
            let row: Vec<char> = row.chars().collect();
            (1..row.len())
                .find(|&c| row[c] == '└' && row[c - 1] == ' ')
                .map(|c| (r, c))
        })
        .expect("the chart's axes");
    let axis: Vec<char> = rows[axis_row].chars().collect();
    let graph = axis[corner + 1..].iter().take_while(|&&c| c == '─').count();
    let labels: Vec<char> = rows[axis_row + 1].chars().collect();
    let mut found = Vec::new();
    let mut column = corner + 1;
    while column < corner + 1 + graph {
        if labels[column] == ' ' {
            column += 1;
            continue;
        }
        let start = column;
        while column < corner + 1 + graph && labels[column] != ' ' {
            column += 1;
        }
        let text: String = labels[start..column].iter().collect();
        let centre = (start - corner - 1) as f64 + (column - start) as f64 / 2.0;
        found.push((centre, text.parse::<f64>().expect(&text)));
    }
    // The first and last labels are aligned to the axis ends, not centred on their values.
    found.pop();
    if found.first().is_some_and(|&(centre, _)| centre < 4.0) {
        found.remove(0);
    }
    (found, graph)
}

#[test]
fn x_tick_labels_sit_at_their_values_at_every_width() {
    let beams = app();
    let mut lap = app();
    press(&mut lap, Action::SwitchModel);
    press(&mut lap, Action::SwitchModel);
    for (name, app) in [("beams", &beams), ("lap joint", &lap)] {
        let [lo, hi] = app.plot().x.bounds;
        for width in [80, 120, 200, 300] {
            let height = if width == 80 { 24 } else { 60 };
            let (labels, graph) = x_tick_labels(app, width, height);
            assert!(!labels.is_empty(), "{name} at {width}: no middle labels");
            for (centre, value) in labels {
                // The value's place on the axis, in cells: [c, c + 1) holds column c's values.
                let at = (value - lo) / (hi - lo) * graph as f64;
                assert!(
                    (centre - at).abs() <= 0.5,
                    "{name} at {width}x{height}: label {value} centred at cell {centre}, its \
                     value is at {at:.2} (graph {graph} cells, x from {lo} to {hi})"
                );
            }
        }
    }
}
