//! Snapshot tests of rendered frames: each snapshot is a claim about what users see. Review changes
//! with `cargo insta review` (or read the `.snap.new` files) before accepting them.

use microslip::preset;
use microslip::tui::action::Action;
use microslip::tui::app::{App, AppOptions};
use microslip::tui::effects;
use microslip::tui::theme::{Charset, Theme};
use microslip::tui::ui;
use ratatui::Terminal;
use ratatui::backend::TestBackend;

fn app_with(preset_name: &str, charset: Charset, color: bool) -> App {
    App::new(AppOptions {
        theme: Theme { charset, color },
        preset: preset::resolve(preset_name).unwrap(),
        user_dir: None,
        data: None,
    })
}

fn app() -> App {
    app_with("paper-beams", Charset::Unicode, true)
}

fn render(app: &App, width: u16, height: u16) -> Terminal<TestBackend> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|frame| ui::draw(frame, app)).unwrap();
    terminal
}

fn screen(app: &App, width: u16, height: u16) -> String {
    render(app, width, height).backend().to_string()
}

/// A key, and what it asks for done at once (files read and written, the fit run), as the event
/// loop would before drawing.
fn press(app: &mut App, action: Action) {
    effects::update_blocking(app, action);
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

#[test]
fn help_overlay() {
    let mut app = app();
    press(&mut app, Action::ToggleHelp);
    insta::assert_snapshot!(screen(&app, 80, 24));
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

#[test]
fn every_size_and_state_renders_without_panic() {
    let mut app = app();
    for (w, h) in [
        (1, 1),
        (10, 3),
        (79, 24),
        (80, 23),
        (80, 24),
        (81, 25),
        (200, 60),
        (300, 100),
    ] {
        let _ = screen(&app, w, h);
    }
    act(&mut app, &[Action::ToggleHelp]);
    let _ = screen(&app, 80, 24);
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
            microslip::fit::Measurement { force, deflection }
        })
        .collect();
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Ascii,
            color: false,
        },
        preset: preset::resolve("paper-beams").unwrap(),
        user_dir: None,
        data: Some(microslip::tui::app::Measurements {
            path: "bench.csv".into(),
            points,
        }),
    });
    insta::assert_snapshot!("measured_points", screen(&app, 100, 30));
    press(&mut app, Action::Fit);
    insta::assert_snapshot!("after_fit", screen(&app, 100, 30));
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
    });
    press(&mut app, Action::OpenPresets);
    // Bundled: paper-beams, paper-beams-soft (selected), paper-plate; then the user's paper-beams.
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
    for _ in 0..3 {
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
fn a_long_status_message_wraps_upwards_instead_of_being_cut() {
    let mut app = app();
    let path = "/nonexistent/measurements/from the bench in building 7/campaign 2031-04/\
                specimen 12 of 40, second loading branch after the gauge reset.csv";
    load_data(&mut app, path);
    let text = screen(&app, 80, 24);
    // Every word of the message is on screen, in order, across the bottom rows.
    let bottom: Vec<&str> = text.lines().rev().take(4).collect();
    let joined: String = bottom
        .iter()
        .rev()
        .map(|l| l.trim_matches('"').trim())
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        joined.contains("specimen 12 of 40, second loading branch after the gauge reset.csv: No such file or directory"),
        "{text}"
    );
    insta::assert_snapshot!("long_status_message", text);
    // Too long even for four lines: what fits, then `...`.
    let mut app = app_with("paper-beams", Charset::Ascii, false);
    load_data(
        &mut app,
        &format!("/nonexistent/{}.csv", "very long name ".repeat(30)),
    );
    let text = screen(&app, 80, 24);
    let rows: Vec<&str> = text.lines().collect();
    assert!(
        rows[23].trim_end_matches('"').trim_end().ends_with("..."),
        "{text}"
    );
    assert!(!rows[19].contains("very long"), "{text}");
    assert!(
        rows[20].contains("beam | paper-beams | /nonexistent/very long"),
        "{text}"
    );
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

/// The workbench of issue 16 at the smallest and a large size, in both charsets: w(L) against the
/// selected parameter (`v`), the explanation of a regime line (`i`), the target prompt (`t`), and
/// a tall screen whose spare height explains every line.
#[test]
fn workbench_panes_at_80x24_and_200x60_in_both_charsets() {
    for (charset, tag) in [(Charset::Unicode, "unicode"), (Charset::Ascii, "ascii")] {
        let mut app = app_with("paper-beams", charset, true);
        let shot = |name: &str, app: &App, width: u16, height: u16| {
            let text = screen(app, width, height);
            if charset == Charset::Ascii {
                assert!(text.is_ascii(), "{name}");
            }
            insta::assert_snapshot!(format!("{name}_{width}x{height}_{tag}"), text);
        };
        shot("main", &app, 200, 60);
        // mu is the seventh row (L b h E nu P mu).
        act(&mut app, &[Action::Next; 6]);
        press(&mut app, Action::Vary);
        shot("vary_mu", &app, 80, 24);
        shot("vary_mu", &app, 200, 60);
        press(&mut app, Action::Vary);
        act(
            &mut app,
            &[
                Action::Explain,
                Action::Next,
                Action::Next,
                Action::Next,
                Action::Next,
            ],
        );
        shot("explain_f1", &app, 80, 24);
        press(&mut app, Action::Cancel);
        act(&mut app, &[Action::Next, Action::SolveTarget]);
        shot("target_prompt", &app, 80, 24);
        press(&mut app, Action::Commit);
        shot("target_solved", &app, 80, 24);
    }
}

/// The y-axis modes of `y` (issue 15): w(L) vs F relative to Coulomb, where the K_T family
/// separates, and u(L) vs K_T on its default log axis, at 80x24 and 120x40 in both charsets (the
/// ASCII one without colour: curves told apart by their symbols).
#[test]
fn y_axis_modes_at_80x24_and_120x40_in_both_charsets() {
    for (charset, tag) in [(Charset::Unicode, "unicode"), (Charset::Ascii, "ascii")] {
        let mut app = app_with("paper-beams", charset, charset == Charset::Unicode);
        let shot = |name: &str, app: &App, width: u16, height: u16| {
            let text = screen(app, width, height);
            if charset == Charset::Ascii {
                assert!(text.is_ascii(), "{name}");
            }
            insta::assert_snapshot!(format!("{name}_{width}x{height}_{tag}"), text);
        };
        // w(L) vs F: linear, then log, then relative.
        act(&mut app, &[Action::CycleYAxis, Action::CycleYAxis]);
        assert!(app.plot().y.title.contains("Coulomb - 1 (%)"));
        shot("y_relative_w", &app, 80, 24);
        shot("y_relative_w", &app, 120, 40);
        press(&mut app, Action::SwitchModel);
        assert!(app.plot().y.log, "u(L) vs K_T opens on a log axis");
        shot("y_log_u", &app, 80, 24);
        shot("y_log_u", &app, 120, 40);
        // Back to the beams: the relative mode of w(L) vs F was kept.
        press(&mut app, Action::SwitchModel);
        assert!(app.plot().y.title.contains("Coulomb - 1 (%)"));
    }
}

/// Selects the row of `name` and types `value` into it.
fn set(app: &mut App, name: &str, value: &str) {
    for _ in 0..20 {
        press(app, Action::Previous);
    }
    while app.selected_param().name() != name {
        press(app, Action::Next);
    }
    press(app, Action::StartEdit);
    type_and_commit(app, value);
}

#[test]
fn pins_and_the_zone_strip_at_80x24_and_120x40_in_both_charsets() {
    for (charset, name) in [(Charset::Unicode, "unicode"), (Charset::Ascii, "ascii")] {
        // Pin the paper's beams (mu 0.3), then mu 0.2; compare both with mu 0.45.
        let mut app = app_with("paper-beams", charset, true);
        press(&mut app, Action::Pin);
        set(&mut app, "mu", "0.2");
        press(&mut app, Action::Pin);
        set(&mut app, "mu", "0.45");
        for (w, h) in [(80, 24), (120, 40)] {
            insta::assert_snapshot!(format!("pins_{w}x{h}_{name}"), screen(&app, w, h));
        }
        // The pins follow the chart switch: X vs F at the same three friction coefficients.
        press(&mut app, Action::NextChart);
        insta::assert_snapshot!(
            format!("pins_slip_boundary_120x40_{name}"),
            screen(&app, 120, 40)
        );
    }
}

#[test]
fn pins_in_relative_mode_and_on_the_plate() {
    let mut app = app();
    press(&mut app, Action::Pin);
    set(&mut app, "KT", "2000");
    press(&mut app, Action::CycleYAxis);
    press(&mut app, Action::CycleYAxis);
    assert_eq!(app.y_mode(), microslip::report::chart::YMode::Relative);
    insta::assert_snapshot!("pins_relative_120x40", screen(&app, 120, 40));
    // Without colour, on the plate: the pin is told apart by its number.
    let mut app = app_with("paper-plate", Charset::Unicode, false);
    press(&mut app, Action::Pin);
    set(&mut app, "tp", "0.5");
    insta::assert_snapshot!("pins_plate_80x24_no_color", screen(&app, 80, 24));
}
