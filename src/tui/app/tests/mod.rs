//! The app driven by actions and outcomes: editing, steps, undo, charts, pins, paste, quit.

use super::*;
use crate::problems::BeamParam;
use crate::problems::inputs::Model;
use crate::tui::theme::Charset;

mod files;

const L: Param = Param::Beam(BeamParam::Length);
const B: Param = Param::Beam(BeamParam::Width);
const MU: Param = Param::Beam(BeamParam::Friction);
const KT: Param = Param::Beam(BeamParam::Stiffness);
const F: Param = Param::Beam(BeamParam::Force);

fn app_with_dir(dir: Option<PathBuf>) -> App {
    App::new(AppOptions {
        theme: Theme {
            charset: Charset::Unicode,
            color: true,
        },
        preset: preset::resolve("paper-beams").unwrap(),
        user_dir: dir,
        data: None,
        solve_continuum: false,
    })
}

fn app() -> App {
    app_with_dir(None)
}

/// 25 deflections of the paper's beams with mu = 0.35 and K_T = 250 MPa/mm, 12 N to 300 N.
fn measured() -> Vec<Measurement> {
    let beams = crate::TwinBeams::new(crate::TwinBeamsParams {
        friction: 0.35,
        tangential_stiffness: 250.0,
        ..crate::TwinBeamsParams::PAPER
    })
    .unwrap();
    (1..=25)
        .map(|i| {
            let force = 12.0 * f64::from(i);
            let deflection = beams
                .regularized(crate::TipForce::new(force).unwrap())
                .tip_deflection();
            Measurement {
                force,
                response: deflection,
            }
        })
        .collect()
}

/// A key, and what it asks for done at once (files read and written, the fit run).
fn press(app: &mut App, action: Action) {
    crate::tui::effects::update_blocking(app, action);
}

/// Selects the row of `name` with j/k.
fn select(app: &mut App, name: &str) {
    for _ in 0..10 {
        app.update(Action::Previous);
    }
    while app.selected_param().name() != name {
        app.update(Action::Next);
    }
}

fn typed(app: &mut App, text: &str) {
    for c in text.chars() {
        app.update(Action::Input(c));
    }
}

/// The pinned series of the chart shown: (number, name).
fn pinned(app: &App) -> Vec<(u8, String)> {
    app.plot()
        .series
        .iter()
        .filter_map(|s| match s.kind() {
            chart::SeriesKind::Pin(n) => Some((n, s.name.clone())),
            _ => None,
        })
        .collect()
}

fn set_typed(app: &mut App, name: &str, value: &str) {
    select(app, name);
    app.update(Action::StartEdit);
    typed(app, value);
    app.update(Action::Commit);
}

/// A pin kept at F = 100 N, then F raised to 252 N: the force axis grows to 1.25 F = 315 N
/// and the pinned curve runs to its end (it stopped at 240 N, 3 F_thre, before).
#[test]
fn a_pinned_curve_spans_the_whole_force_axis() {
    let mut app = app();
    app.update(Action::Pin);
    set_typed(&mut app, "F", "252");
    let plot = app.plot();
    assert_eq!(plot.x.bounds[1], 315.0);
    let pin = plot
        .series
        .iter()
        .find(|s| s.kind() == chart::SeriesKind::Pin(1));
    let last = pin.and_then(|s| s.points.last()).expect("a pinned curve");
    assert_eq!(last.0, 315.0);
}

#[test]
fn pins_keep_values_follow_the_charts_and_are_named_by_what_differs() {
    let mut app = app();
    app.update(Action::Pin);
    assert_eq!(pinned(&app), [(1, "pin 1: = current".to_string())]);
    set_typed(&mut app, "mu", "0.2");
    assert_eq!(pinned(&app), [(1, "pin 1: mu 0.3->0.2".to_string())]);
    // The same values twice: one pin.
    app.update(Action::Pin);
    app.update(Action::Pin);
    assert_eq!(pinned(&app).len(), 2);
    assert!(app.message().unwrap().text.contains("pin 2 already"));
    // Every chart of the model shows them, the table refuses to pin, the plate has its own.
    for _ in 0..4 {
        app.update(Action::NextChart);
        assert_eq!(pinned(&app).len(), 2, "{}", app.plot().title);
    }
    app.update(Action::NextChart);
    assert!(app.table().is_some());
    app.update(Action::Pin);
    assert!(app.message().unwrap().is_error);
    app.update(Action::NextChart);
    app.update(Action::SwitchModel);
    assert!(pinned(&app).is_empty());
    app.update(Action::SwitchModel);
    assert_eq!(app.kind(), ModelKind::Lap);
    assert!(pinned(&app).is_empty());
    // The problems after it have no pins either; the beams', next, keep theirs.
    for _ in 3..ModelKind::ALL.len() {
        app.update(Action::SwitchModel);
        assert!(pinned(&app).is_empty(), "{}", app.kind());
    }
    app.update(Action::SwitchModel);
    assert_eq!(pinned(&app).len(), 2);
    // A fifth pin replaces the oldest, and its number is free again.
    for mu in ["0.25", "0.35"] {
        set_typed(&mut app, "mu", mu);
        app.update(Action::Pin);
    }
    let numbers: Vec<u8> = pinned(&app).iter().map(|p| p.0).collect();
    assert_eq!(numbers, [1, 2, 3, 4]);
    set_typed(&mut app, "mu", "0.4");
    app.update(Action::Pin);
    assert!(app.message().unwrap().text.contains("replaces pin 1"));
    set_typed(&mut app, "mu", "0.5");
    let names: Vec<String> = pinned(&app).into_iter().map(|p| p.1).collect();
    assert_eq!(
        names,
        [
            "pin 2: mu 0.2->0.5",
            "pin 3: mu 0.25->0.5",
            "pin 4: mu 0.35->0.5",
            "pin 1: mu 0.4->0.5",
        ]
    );
    app.update(Action::ClearPins);
    assert!(pinned(&app).is_empty());
    assert!(app.message().unwrap().text.contains("4 pin(s) cleared"));
}

#[test]
fn arrows_select_and_step_parameters() {
    let mut app = app();
    assert_eq!(app.selected_param().name(), "L");
    // The selection does not wrap from the first row to the last, nor back.
    app.update(Action::Previous);
    assert_eq!(app.selected_param().name(), "L");
    select(&mut app, "F");
    app.update(Action::Next);
    assert_eq!(app.selected_param().name(), "F");
    app.update(Action::Increase);
    // F steps by 1 % of F_thre = 0.8 N.
    assert!((app.inputs().get(F).unwrap() - 100.8).abs() < 1e-9);
    select(&mut app, "b");
    app.update(Action::IncreaseCoarse);
    assert!((app.inputs().get(B).unwrap() - 25.0).abs() < 1e-9);
    assert!(app.modified());
    assert!(app.is_edited(B) && !app.is_edited(L));
    // Reset asks first; no keeps the edits, yes resets, u undoes the reset.
    app.update(Action::Reset);
    assert_eq!(app.mode(), &Mode::ConfirmReset);
    app.update(Action::Cancel);
    assert!(app.modified());
    app.update(Action::Reset);
    app.update(Action::Yes);
    assert!(!app.modified());
    app.update(Action::Undo);
    assert!((app.inputs().get(B).unwrap() - 25.0).abs() < 1e-9);
}

#[test]
fn steps_stop_at_the_edge_of_the_domain() {
    let mut app = app();
    select(&mut app, "KT");
    let max = BeamParam::Stiffness.spec().domain.max();
    for _ in 0..200 {
        app.update(Action::IncreaseCoarse);
    }
    assert_eq!(app.inputs().get(KT), Some(max));
    // 1e12 MPa/mm is accepted, with a warning: far outside the usual range.
    assert!(
        app.message()
            .unwrap()
            .text
            .contains("far outside the usual range"),
        "{:?}",
        app.message()
    );
}

#[test]
fn force_steps_stop_at_zero() {
    let mut app = app();
    select(&mut app, "F");
    for _ in 0..20 {
        app.update(Action::DecreaseCoarse);
    }
    assert_eq!(app.inputs().get(F), Some(0.0));
    assert!(app.message().is_none());
}

#[test]
fn typed_values_are_validated_and_bad_ones_keep_the_old_value() {
    let mut app = app();
    app.update(Action::StartEdit);
    typed(&mut app, "-5");
    app.update(Action::Commit);
    let message = app.message().unwrap();
    assert!(message.is_error);
    assert_eq!(
        message.text,
        "invalid L = -5: must be > 0 and finite (mm); kept 200"
    );
    assert_eq!(app.inputs().get(L), Some(200.0));
    assert_eq!(app.mode(), &Mode::Normal);
    app.update(Action::StartEdit);
    typed(&mut app, "abc");
    app.update(Action::Commit);
    assert!(
        app.message()
            .unwrap()
            .text
            .starts_with("invalid value 'abc' for L: not a finite number")
    );
    app.update(Action::StartEdit);
    typed(&mut app, "3x");
    app.update(Action::Backspace);
    typed(&mut app, "50");
    app.update(Action::Commit);
    assert_eq!(app.inputs().get(L), Some(350.0));
    app.update(Action::StartEdit);
    typed(&mut app, "1");
    app.update(Action::Cancel);
    assert_eq!(app.inputs().get(L), Some(350.0));
}

#[test]
fn undo_and_redo_walk_a_bounded_history_of_both_models() {
    let mut app = app();
    app.update(Action::Undo);
    assert_eq!(app.message().unwrap().text, "nothing to undo");
    app.update(Action::IncreaseCoarse); // L 250
    app.update(Action::SwitchModel);
    app.update(Action::IncreaseCoarse); // plate L 12.5
    // Round the registry's other problems, unchanged, back to the beams.
    for _ in 1..ModelKind::ALL.len() {
        app.update(Action::SwitchModel);
    }
    app.update(Action::IncreaseCoarse); // L 312.5
    assert_eq!(app.history(), (3, 0));
    app.update(Action::Undo);
    assert_eq!(app.inputs().get(L), Some(250.0));
    // Undoing the plate's change shows the plate.
    app.update(Action::Undo);
    assert_eq!(app.kind(), ModelKind::Plate);
    assert_eq!(
        app.inputs()
            .get(Param::Plate(crate::PlateParam::HalfLength)),
        Some(10.0)
    );
    app.update(Action::Undo);
    assert_eq!(app.kind(), ModelKind::Beam);
    assert_eq!(app.inputs().get(L), Some(200.0));
    app.update(Action::Redo);
    app.update(Action::Redo);
    assert_eq!(app.kind(), ModelKind::Beam);
    assert_eq!(app.inputs().get(L), Some(250.0));
    // A new change forgets what could be redone.
    app.update(Action::Increase);
    assert_eq!(app.history(), (3, 0));
    for _ in 0..2 * HISTORY {
        app.update(Action::Increase);
    }
    assert_eq!(app.history().0, HISTORY);
}

#[test]
fn typing_replaces_the_prefilled_value_and_unusual_values_warn() {
    let mut app = app();
    select(&mut app, "mu");
    app.update(Action::StartEdit);
    let Mode::Editing { input } = app.mode() else {
        panic!()
    };
    assert_eq!(input.shown(), "[0.3]");
    typed(&mut app, "4.5");
    app.update(Action::Commit);
    assert_eq!(app.inputs().get(MU), Some(4.5));
    let message = app.message().unwrap();
    assert!(message.is_error && message.text.contains("mu = 4.5 is far outside"));
    // Outside the domain: refused, as before.
    app.update(Action::StartEdit);
    typed(&mut app, "450");
    app.update(Action::Commit);
    assert_eq!(app.inputs().get(MU), Some(4.5));
    app.update(Action::Undo);
    assert_eq!(app.inputs().get(MU), Some(0.3));
}

#[test]
fn v_charts_the_response_against_the_selected_row_and_t_solves_it() {
    let mut app = app();
    select(&mut app, "mu");
    app.update(Action::Vary);
    assert_eq!(app.varied(), Some(MU));
    assert!(app.plot().title.starts_with("w(L) vs mu"));
    app.update(Action::NextChart);
    assert_eq!(app.varied(), None);
    assert_eq!(
        app.views().of(ModelKind::Beam).position(ModelKind::Beam).0,
        1
    );
    // t on K_T with the offered target ratio=1.01: the smallest K_T within 1 % of Coulomb.
    select(&mut app, "KT");
    app.update(Action::SolveTarget);
    app.update(Action::Commit);
    let kt = app.inputs().get(KT).unwrap();
    assert!((kt - 423.12).abs() < 0.01, "{kt} {:?}", app.message());
    assert!(app.message().unwrap().text.contains("certified root"));
    app.update(Action::Undo);
    assert_eq!(app.inputs().get(KT), Some(600.0));
    // No root: said, nothing changed.
    app.update(Action::SolveTarget);
    typed(&mut app, "ratio=0.5");
    app.update(Action::Commit);
    assert!(app.message().unwrap().is_error);
    assert_eq!(app.inputs().get(KT), Some(600.0));
}

#[test]
fn the_force_axis_stays_when_mu_changes_until_a_fits_it() {
    let mut app = app();
    let before = app.plot().x.bounds;
    select(&mut app, "mu");
    app.update(Action::DecreaseCoarse);
    assert_eq!(app.plot().x.bounds, before, "the x range jumped");
    app.update(Action::FitAxes);
    // 3 F_thre of mu = 0.3 / 1.25: 192 N instead of 240 N.
    assert!(
        (app.plot().x.bounds[1] - 192.0).abs() < 1e-9,
        "{:?}",
        app.plot().x
    );
}

#[test]
fn i_walks_through_the_lines_of_the_regime_pane() {
    let mut app = app();
    app.update(Action::Explain);
    assert_eq!(app.mode(), &Mode::Explain { line: 0 });
    for _ in 0..50 {
        app.update(Action::Next);
    }
    let count = app.explained_lines().len();
    assert_eq!(app.summary_lines().len() + 1, count, "the title first");
    assert_eq!(app.mode(), &Mode::Explain { line: count - 1 });
    app.update(Action::Cancel);
    assert_eq!(app.mode(), &Mode::Normal);
}

/// The lap joint's F stops at F_gross and its mu where F_gross falls to F, and says why.
#[test]
fn lap_steps_stop_where_the_joint_would_slide_through() {
    let mut app = app();
    app.update(Action::SwitchModel);
    app.update(Action::SwitchModel);
    assert_eq!(app.kind(), ModelKind::Lap);
    let force = Param::Lap(crate::problems::LapParam::Force);
    let mu = Param::Lap(crate::problems::LapParam::Friction);
    while app.selected_param() != force {
        app.update(Action::Next);
    }
    for _ in 0..20 {
        app.update(Action::IncreaseCoarse);
    }
    assert_eq!(app.inputs().get(force), Some(6000.0));
    assert!(app.message().unwrap().text.starts_with("F stops at 6000 N"));
    while app.selected_param() != mu {
        app.update(Action::Previous);
    }
    for _ in 0..20 {
        app.update(Action::DecreaseCoarse);
    }
    let lowest = app.inputs().get(mu).unwrap();
    assert!((lowest - 0.3).abs() < 1e-12, "{lowest}");
    assert!(app.message().unwrap().text.starts_with("mu stops at 0.3"));
    assert!(app.model().is_some());
}

#[test]
fn switching_model_keeps_each_models_edits() {
    let mut app = app();
    app.update(Action::IncreaseCoarse);
    app.update(Action::SwitchModel);
    assert_eq!(app.kind(), ModelKind::Plate);
    assert_eq!(app.preset_name(), "paper-plate");
    assert_eq!(app.selected_param().name(), "L");
    app.update(Action::SwitchModel);
    assert_eq!(app.kind(), ModelKind::Lap);
    assert_eq!(app.preset_name(), "lap-aluminium");
    // Round the registry's other problems back to the beams.
    for _ in 2..ModelKind::ALL.len() {
        app.update(Action::SwitchModel);
    }
    assert_eq!(app.inputs().get(L), Some(250.0));
}

#[test]
fn charts_cycle_both_ways() {
    let mut app = app();
    app.update(Action::PreviousChart);
    let (position, count) = app.views().of(ModelKind::Beam).position(ModelKind::Beam);
    assert_eq!(position, count);
    assert!(count > 1);
    app.update(Action::NextChart);
    assert_eq!(
        app.views().of(ModelKind::Beam).position(ModelKind::Beam).0,
        1
    );
}

#[test]
fn a_paste_longer_than_an_input_takes_is_refused_whole() {
    let mut app = app();
    select(&mut app, "F");
    app.update(Action::StartEdit);
    assert!(app.paste("12"));
    assert!(app.paste(&"9".repeat(5000)));
    let message = app.message().unwrap().text.clone();
    assert!(
        message.starts_with("paste refused: 5000 characters"),
        "{message}"
    );
    app.update(Action::Commit);
    assert_eq!(
        app.inputs().get(F),
        Some(12.0),
        "the earlier text, untouched"
    );
}

#[test]
fn pastes_are_text_up_to_the_first_line_break_and_never_keys() {
    let mut app = app();
    select(&mut app, "F");
    app.update(Action::StartEdit);
    assert!(app.paste("150\nq\n"));
    assert!(!app.should_quit());
    app.update(Action::Commit);
    assert_eq!(app.inputs().get(F), Some(150.0));
    assert!(app.paste("q"));
    assert!(!app.should_quit());
    assert!(app.message().unwrap().text.starts_with("paste ignored"));
}

#[test]
fn quitting_with_unsaved_edits_asks_first() {
    let mut app = app();
    app.update(Action::RequestQuit);
    assert!(app.should_quit(), "nothing edited: quits at once");
    let mut app = app_with_dir(None);
    app.update(Action::Increase);
    app.update(Action::SwitchModel);
    app.update(Action::RequestQuit);
    let Mode::ConfirmQuit { unsaved } = app.mode().clone() else {
        panic!("no question: {:?}", app.mode())
    };
    assert_eq!(unsaved, "beam (paper-beams)");
    app.update(Action::Cancel);
    assert!(!app.should_quit());
    app.update(Action::RequestQuit);
    app.update(Action::Yes);
    assert!(app.should_quit());
    // Ctrl-C never asks.
    let mut app = app_with_dir(None);
    app.update(Action::Increase);
    app.update(Action::Quit);
    assert!(app.should_quit());
}

#[test]
fn help_and_quit() {
    let mut app = app();
    app.update(Action::ToggleHelp);
    assert_eq!(app.mode(), &Mode::Help);
    app.update(Action::Next);
    assert_eq!(app.mode(), &Mode::Help);
    app.update(Action::ToggleHelp);
    assert_eq!(app.mode(), &Mode::Normal);
    app.update(Action::Quit);
    assert!(app.should_quit());
}
