//! The app's keys that read or write files (presets, data, export, the fit) and the command
//! line, driven through their effects.

use super::*;

#[test]
fn a_refused_preset_name_is_refused_before_the_description_is_asked() {
    let dir = tempfile::tempdir().unwrap();
    for via_command in [true, false] {
        let mut app = app_with_dir(Some(dir.path().to_path_buf()));
        if via_command {
            press(&mut app, Action::CommandLine);
            typed(&mut app, "save ../x");
        } else {
            press(&mut app, Action::SavePreset);
            typed(&mut app, "paper-beams");
        }
        press(&mut app, Action::Commit);
        assert!(
            !matches!(app.mode(), Mode::SaveDescription { .. }),
            "{:?}",
            app.mode()
        );
        let message = app.message().unwrap();
        assert!(message.is_error, "{}", message.text);
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn presets_load_and_save_without_clobbering() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("broken.toml"),
        "model = \"beam\"\nKT = -1\n",
    )
    .unwrap();
    let mut app = app_with_dir(Some(dir.path().to_path_buf()));
    press(&mut app, Action::OpenPresets);
    let Mode::Presets { entries, .. } = app.mode().clone() else {
        panic!("picker not open")
    };
    let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
    // The bundled presets in the registry's order, then the user's.
    let mut expected = crate::preset::bundled_names();
    expected.push("broken");
    assert_eq!(names, expected);
    press(&mut app, Action::Next);
    press(&mut app, Action::Commit);
    assert_eq!(app.preset_name(), "paper-beams-soft");
    assert_eq!(app.inputs().get(KT), Some(120.0));
    // Invalid user file: refused with its problem, picker stays open.
    press(&mut app, Action::OpenPresets);
    // From the current preset (the second) to the last entry, the user's broken one.
    for _ in 0..expected.len() - 2 {
        press(&mut app, Action::Next);
    }
    press(&mut app, Action::Commit);
    assert!(
        app.message()
            .unwrap()
            .text
            .contains("cannot load broken: line 2: invalid KT = -1")
    );
    press(&mut app, Action::Cancel);
    // Save, then save again under the same name: asked first; "no" keeps the file.
    // Save: the name, then the description (prefilled; typing replaces it).
    press(&mut app, Action::SavePreset);
    typed(&mut app, "bench");
    press(&mut app, Action::Commit);
    let Mode::SaveDescription { input, .. } = app.mode() else {
        panic!("{:?}", app.mode())
    };
    assert_eq!(
        input.as_str(),
        "Saved from the microslip TUI (beam model, from paper-beams-soft)"
    );
    typed(&mut app, "soft joint, \"rig 2\"");
    press(&mut app, Action::Commit);
    let path = dir.path().join("bench.toml");
    let saved = std::fs::read_to_string(&path).unwrap();
    assert!(saved.contains("KT = 120.0"));
    let read = crate::preset::store::load(&path).unwrap();
    assert_eq!(read.description, "soft joint, \"rig 2\"");
    assert_eq!(app.state().preset.description, read.description);
    // Saved again under its own name, the description offered is its own.
    press(&mut app, Action::IncreaseCoarse);
    press(&mut app, Action::SavePreset);
    typed(&mut app, "bench");
    press(&mut app, Action::Commit);
    assert!(
        matches!(app.mode(), Mode::SaveDescription { input, .. } if input.as_str() == read.description)
    );
    press(&mut app, Action::Commit);
    assert!(matches!(app.mode(), Mode::ConfirmOverwrite { .. }));
    press(&mut app, Action::Cancel);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), saved);
    press(&mut app, Action::SavePreset);
    typed(&mut app, "bench");
    press(&mut app, Action::Commit);
    press(&mut app, Action::Commit);
    press(&mut app, Action::Yes);
    assert!(
        std::fs::read_to_string(&path)
            .unwrap()
            .contains("L = 250.0")
    );
    assert!(app.message().unwrap().text.starts_with("saved "));
}

#[test]
fn measurements_load_fit_and_set_the_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let mut csv = String::from("F_N,w_mm\n");
    for m in measured() {
        csv.push_str(&format!("{},{}\n", m.force, m.response));
    }
    let path = dir.path().join("m.csv");
    std::fs::write(&path, csv).unwrap();
    let mut app = app();
    press(&mut app, Action::Fit);
    assert!(app.message().unwrap().text.starts_with("no measurements"));
    press(&mut app, Action::LoadData);
    typed(&mut app, path.to_str().unwrap());
    press(&mut app, Action::Commit);
    assert_eq!(app.measurements().unwrap().points.len(), 25);
    assert!(app.plot().series.iter().any(|s| s.name == "measured"));
    press(&mut app, Action::Fit);
    assert!(
        (app.inputs().get(MU).unwrap() / 0.35 - 1.0).abs() < 1e-6,
        "{:?}",
        app.message()
    );
    assert!((app.inputs().get(KT).unwrap() / 250.0 - 1.0).abs() < 1e-6);
    assert!(
        app.message().unwrap().text.starts_with("fit: mu = 0.35"),
        "{:?}",
        app.message()
    );
    // A bad file is refused with its line; the loaded data stay.
    std::fs::write(dir.path().join("bad.csv"), "F_N,w_mm\n1,x\n").unwrap();
    press(&mut app, Action::LoadData);
    for _ in 0..200 {
        press(&mut app, Action::Backspace);
    }
    typed(&mut app, dir.path().join("bad.csv").to_str().unwrap());
    press(&mut app, Action::Commit);
    assert!(
        app.message()
            .unwrap()
            .text
            .contains("line 2: 'x' in column w_mm")
    );
    assert_eq!(app.measurements().unwrap().points.len(), 25);
}

#[test]
fn saving_without_a_directory_is_refused_clearly() {
    let mut app = app();
    app.update(Action::SavePreset);
    typed(&mut app, "x");
    app.update(Action::Commit);
    assert_eq!(
        app.message().unwrap().text,
        "no user preset directory: set XDG_CONFIG_HOME or HOME"
    );
}

/// The exported figure is read without the terminal: a parameter caption, each curve named by
/// its own values with units (not `mu 0.3->0.2`, which reads as a change), and pin 1 not in
/// Coulomb's black dashes.
#[test]
fn x_exports_a_figure_with_a_caption_and_curves_named_by_their_own_values() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = app();
    app.set_export_dir(dir.path().to_path_buf());
    app.update(Action::Pin);
    set_typed(&mut app, "mu", "0.2");
    set_typed(&mut app, "KT", "1000");
    press(&mut app, Action::ExportChart);
    let file = |extension: &str| dir.path().join(format!("microslip-w-vs-f.{extension}"));
    assert!(
        std::fs::read(file("png"))
            .unwrap()
            .starts_with(b"\x89PNG\r\n\x1a\n")
    );
    assert!(std::fs::read(file("pdf")).unwrap().starts_with(b"%PDF-"));
    let svg = std::fs::read_to_string(file("svg")).unwrap();
    for text in [
        "L = 200 mm, b = 20 mm",
        // F is the x axis: not in the caption.
        "P = 1 MPa, mu = 0.2, KT = 1000 MPa/mm\n</text>",
        "K_T (mu = 0.2, KT = 1000 MPa/mm)",
        "pin 1: mu = 0.3, KT = 600 MPa/mm",
    ] {
        assert!(svg.contains(text), "{text}\n{svg}");
    }
    assert!(!svg.contains("-&gt;") && !svg.contains("->"), "{svg}");
    // Coulomb is black with even dashes; pin 1 is neither (purple, dash-dot).
    let curves: Vec<&str> = svg.lines().filter(|l| l.starts_with("<polyline")).collect();
    let with = |dashes: &str| {
        curves
            .iter()
            .find(|l| l.contains(&format!("stroke-dasharray=\"{dashes}\"")))
            .copied()
            .unwrap_or_else(|| panic!("a curve dashed {dashes}\n{svg}"))
    };
    assert!(with("7 4").contains("stroke=\"#000000\""));
    assert!(with("10 4 2 4").contains("stroke=\"#7570B3\""));
    // The CSV keeps its series names.
    let csv = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.csv")).unwrap();
    assert!(csv.contains("\npin 1: mu 0.3->0.2 KT 600->1000,"), "{csv}");
}

#[test]
fn x_exports_the_chart_as_svg_and_csv_without_replacing_files() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = app();
    app.set_export_dir(dir.path().to_path_buf());
    press(&mut app, Action::ExportChart);
    let message = app.message().unwrap();
    assert!(!message.is_error, "{}", message.text);
    assert!(
        message.text.contains("microslip-w-vs-f.svg"),
        "{}",
        message.text
    );
    let svg = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.svg")).unwrap();
    assert!(svg.contains(&app.plot().title));
    let csv = std::fs::read_to_string(dir.path().join("microslip-w-vs-f.csv")).unwrap();
    assert!(
        csv.starts_with("series,x_axis,x,y_axis,y\nCoulomb,F (N),0"),
        "{csv}"
    );
    // Again: a new name, the first files untouched.
    press(&mut app, Action::ExportChart);
    assert!(dir.path().join("microslip-w-vs-f-2.svg").exists());
    // After v, the file says what is charted; a table is refused with a reason.
    press(&mut app, Action::Vary);
    press(&mut app, Action::ExportChart);
    assert!(dir.path().join("microslip-w-vs-l.csv").exists());
    press(&mut app, Action::Vary);
    press(&mut app, Action::PreviousChart);
    press(&mut app, Action::ExportChart);
    assert!(app.message().unwrap().is_error);
    // Three exports of four files each (SVG, PNG, PDF, CSV).
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 12);
}

#[test]
fn keys_that_need_files_return_effects_and_touch_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // Neither folder exists: the keys alone must not fail, create or read anything.
    let missing = dir.path().join("missing");
    let mut app = app_with_dir(Some(missing.join("presets")));
    app.set_export_dir(missing.join("charts"));
    let effects = app.update(Action::ExportChart);
    let [
        Effect::ExportChart {
            dir,
            stem,
            svg,
            csv,
        },
    ] = effects.as_slice()
    else {
        panic!("{effects:?}")
    };
    assert_eq!(dir, &missing.join("charts"));
    assert_eq!(stem, "microslip-w-vs-f");
    assert!(svg.contains(&app.plot().title));
    assert!(csv.starts_with(b"series,x_axis,x,y_axis,y\n"));
    app.update(Action::SavePreset);
    typed(&mut app, "bench");
    app.update(Action::Commit);
    let effects = app.update(Action::Commit);
    assert!(
        matches!(
            effects.as_slice(),
            [Effect::SavePreset { dir, name, text, overwrite: false, .. }]
                if *dir == missing.join("presets") && name == "bench" && text.contains("KT = 600.0")
        ),
        "{effects:?}"
    );
    assert_eq!(
        app.update(Action::OpenPresets),
        [Effect::ListPresets {
            user_dir: Some(missing.join("presets"))
        }]
    );
    assert_eq!(app.mode(), &Mode::Normal, "the picker opens with the list");
    let path = missing.join("m.csv").display().to_string();
    app.update(Action::LoadData);
    typed(&mut app, &path);
    assert_eq!(
        app.update(Action::Complete),
        [Effect::CompletePath { text: path.clone() }]
    );
    assert_eq!(
        app.update(Action::Commit),
        [Effect::ReadMeasurements {
            path: path.clone(),
            kind: ModelKind::Beam
        }]
    );
    // The app waits for the file, which nobody reads here (Esc would stop the read).
    assert_eq!(app.mode(), &Mode::Loading { path: path.clone() });
    app.mode = Mode::Normal;
    app.update(Action::LoadData);
    typed(&mut app, &format!("{path}.dat"));
    assert_eq!(
        app.update(Action::Commit),
        [Effect::ReadFeResults {
            path: format!("{path}.dat"),
            kind: ModelKind::Beam
        }]
    );
    // Nothing said but that the file is coming; nothing loaded, nothing changed, nothing on the
    // disk.
    assert_eq!(
        app.message().map(|m| m.text.as_str()),
        Some(format!("loading {path}.dat... (Esc cancels)").as_str())
    );
    assert_eq!(app.measurements(), None);
    assert_eq!(app.history(), (0, 0));
    assert!(!missing.exists());
}

#[test]
fn f_asks_for_a_fit_that_esc_cancels_leaving_the_parameters_as_they_were() {
    let mut app = app();
    app.measurements = Some(Measurements {
        path: "m.csv".into(),
        points: measured(),
    });
    let before = app.inputs();
    let effects = app.update(Action::Fit);
    let [fit @ Effect::Fit { job, points, .. }] = effects.as_slice() else {
        panic!("{effects:?}")
    };
    let job = *job;
    assert_eq!(points, &measured());
    assert_eq!(app.mode(), &Mode::Fitting { job });
    assert_eq!(app.mode().context(), Context::Working);
    let grid = |done| Outcome::FitProgress {
        job,
        progress: crate::fit::Progress::Bracket {
            done,
            total: 784,
            points: 25,
        },
    };
    app.receive(grid(392));
    assert_eq!(
        app.message().unwrap().text,
        "fitting: grid search for a start on 25 measurements, 50% (Esc cancels)"
    );
    // Meanwhile other keys do nothing: the result is for these parameters.
    for action in [
        Action::Increase,
        Action::SwitchModel,
        Action::Fit,
        Action::RequestQuit,
    ] {
        assert!(app.update(action).is_empty());
    }
    assert_eq!((app.inputs(), app.kind()), (before, ModelKind::Beam));
    assert!(!app.should_quit());
    assert_eq!(app.update(Action::Cancel), [Effect::CancelFit { job }]);
    assert_eq!(app.mode(), &Mode::Normal);
    let cancelled = app.message().cloned();
    assert_eq!(
        cancelled.as_ref().unwrap().text,
        "fit cancelled; the parameters are unchanged"
    );
    // Its progress and result, should they still come, change nothing.
    let late = crate::tui::effects::perform_blocking(fit.clone()).unwrap();
    assert!(matches!(late, Outcome::Fitted { result: Ok(_), .. }));
    app.receive(grid(784));
    assert!(app.receive(late).is_empty());
    assert_eq!(app.inputs(), before);
    assert_eq!(app.message().cloned(), cancelled);
    assert_eq!(app.history(), (0, 0));
    // The next fit is another job; its result is adopted, and u undoes it.
    let effects = app.update(Action::Fit);
    let [next @ Effect::Fit { job: second, .. }] = effects.as_slice() else {
        panic!("{effects:?}")
    };
    assert_ne!(*second, job);
    let result = crate::tui::effects::perform_blocking(next.clone()).unwrap();
    app.receive(result);
    assert!((app.inputs().get(MU).unwrap() / 0.35 - 1.0).abs() < 1e-6);
    assert_eq!(app.mode(), &Mode::Normal);
    app.update(Action::Undo);
    assert_eq!(app.inputs(), before);
}

/// Types `text` on the command line and runs it (files read at once).
fn command(app: &mut App, text: &str) {
    press(app, Action::CommandLine);
    typed(app, text);
    press(app, Action::Commit);
}

#[test]
fn the_command_line_sets_several_values_at_once_and_u_undoes_them_together() {
    let mut app = app();
    command(&mut app, "KT=250 mu=0.2,F=90");
    assert_eq!(
        (
            app.inputs().get(KT),
            app.inputs().get(MU),
            app.inputs().get(F)
        ),
        (Some(250.0), Some(0.2), Some(90.0))
    );
    let said = &app.message().unwrap().text;
    assert!(
        said.contains("KT = 250 MPa/mm") && said.contains("mu = 0.2") && said.contains("F = 90 N"),
        "{said}"
    );
    assert_eq!(app.history(), (1, 0));
    press(&mut app, Action::Undo);
    assert_eq!(app.inputs(), preset::paper(ModelKind::Beam).inputs);
}

#[test]
fn the_command_line_refuses_as_set_does_and_changes_nothing() {
    let mut app = app();
    let before = app.inputs();
    for (typed_line, said) in [
        ("KT=250 mu=abc", "mu=abc"),
        ("KT=250 mu=-1", "mu"),
        ("KT=250 tp=1", "unknown key 'tp' for the beam model"),
        ("KT=250 mu", "'mu' is not KEY=VALUE"),
        ("frobnicate", "unknown command 'frobnicate'"),
    ] {
        command(&mut app, typed_line);
        let message = app.message().unwrap();
        assert!(message.is_error, "{typed_line}: {message:?}");
        assert!(
            message.text.contains(said),
            "{typed_line}: {}",
            message.text
        );
        assert_eq!(app.inputs(), before, "{typed_line}");
        assert_eq!(app.mode(), &Mode::Normal);
    }
    assert_eq!(app.history(), (0, 0));
}

#[test]
fn the_command_line_loads_presets_by_name_and_completes_keys_and_names() {
    let mut app = app();
    press(&mut app, Action::CommandLine);
    typed(&mut app, "K");
    press(&mut app, Action::Complete);
    assert!(matches!(app.mode(), Mode::Command { input } if input.as_str() == "KT="));
    press(&mut app, Action::Cancel);
    press(&mut app, Action::CommandLine);
    typed(&mut app, "preset paper-p");
    press(&mut app, Action::Complete);
    assert!(
        matches!(app.mode(), Mode::Command { input } if input.as_str() == "preset paper-plate")
    );
    press(&mut app, Action::Commit);
    assert_eq!(app.kind(), ModelKind::Plate);
    assert_eq!(app.preset_name(), "paper-plate");
    command(&mut app, "preset no-such");
    let message = app.message().unwrap();
    assert!(message.is_error && message.text.contains("no preset named 'no-such'"));
    assert!(message.text.contains("p lists them"), "{}", message.text);
    command(&mut app, "help");
    assert_eq!(app.mode(), &Mode::Help);
}

#[test]
fn loaded_data_go_with_d_and_with_another_preset() {
    let mut app = app();
    press(&mut app, Action::DropData);
    assert!(app.message().unwrap().text.starts_with("no loaded data"));
    let data = Measurements {
        path: "m.csv".into(),
        points: measured(),
    };
    app.measurements = Some(data.clone());
    press(&mut app, Action::DropData);
    assert_eq!(app.measurements(), None);
    assert!(
        app.message()
            .unwrap()
            .text
            .contains("dropped 25 measurements (m.csv)"),
        "{:?}",
        app.message()
    );
    // Another preset: the data belonged to the previous bench.
    app.measurements = Some(data);
    command(&mut app, "preset paper-beams-soft");
    assert_eq!(app.measurements(), None);
    assert!(
        app.message()
            .unwrap()
            .text
            .contains("dropped 25 measurements")
    );
}

#[test]
fn a_deck_s_values_adopted_drop_the_measurements_taken_at_other_values() {
    let mut app = app();
    app.measurements = Some(Measurements {
        path: "m.csv".into(),
        points: measured(),
    });
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/calculix/paper-beams.dat"
    );
    press(&mut app, Action::LoadData);
    typed(&mut app, path);
    press(&mut app, Action::Commit);
    assert_eq!(app.measurements(), None);
    let said = &app.message().unwrap().text;
    assert!(
        said.contains("deck parameters adopted") && said.contains("dropped 25"),
        "{said}"
    );
}

#[test]
fn the_plate_s_continuum_u_is_solved_for_the_values_shown_and_a_late_answer_is_ignored() {
    use crate::tui::summary::ContinuumState;
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: Charset::Unicode,
            color: true,
        },
        preset: preset::resolve("paper-plate").unwrap(),
        user_dir: None,
        data: None,
        solve_continuum: true,
    });
    let asked = app.take_asked();
    let [Effect::SolveContinuum { inputs }] = asked.as_slice() else {
        panic!("{asked:?}")
    };
    assert_eq!(*inputs, Inputs::Plate(crate::PlateParams::PAPER));
    assert_eq!(app.continuum(), ContinuumState::Solving);
    // A value changes before the answer comes: the answer is for values no longer shown.
    let stale = crate::tui::effects::perform_blocking(asked[0].clone()).unwrap();
    select(&mut app, "mu");
    let effects = app.update(Action::IncreaseCoarse);
    assert!(matches!(
        effects.as_slice(),
        [Effect::SolveContinuum { .. }]
    ));
    app.receive(stale);
    assert_eq!(app.continuum(), ContinuumState::Solving);
    for effect in effects {
        let outcome = crate::tui::effects::perform_blocking(effect).unwrap();
        app.receive(outcome);
    }
    let Some(Model::Plate(plate)) = app.model() else {
        panic!()
    };
    let expected = crate::problems::plate::solve_plate_continuum(
        plate.params(),
        crate::problems::plate::ContinuumMesh::default(),
    )
    .unwrap();
    assert_eq!(
        app.continuum(),
        ContinuumState::Solved(crate::tui::effects::ContinuumSummary {
            end_displacement: expected.end_displacement_mean,
            edge_pressure: expected.edge_pressure_ratio,
        })
    );
    assert!(
        app.summary_lines()
            .iter()
            .any(|l| l.text.starts_with("contact P 2-D: ") && l.text.ends_with(" P at end")),
        "the continuum's edge pressure replaces the flat model's line"
    );
    let line = app
        .summary_lines()
        .into_iter()
        .find(|l| l.text.starts_with("u(L) 2-D FE"))
        .unwrap();
    assert!(line.text.contains(" mm ("), "{}", line.text);
    // The beams have none.
    press(&mut app, Action::SwitchModel);
    assert_eq!(app.continuum(), ContinuumState::Off);
}

#[test]
fn the_force_axis_follows_f_thre_when_it_leaves_the_axis_and_says_so() {
    let mut app = app();
    let right = |app: &App| app.plot().x.bounds[1];
    assert!(
        (right(&app) - 240.0).abs() < 1e-9,
        "3 F_thre of the paper's beams"
    );
    // K_T does not move F_thre: the axis stays while it is dragged.
    select(&mut app, "KT");
    for _ in 0..5 {
        press(&mut app, Action::DecreaseCoarse);
    }
    assert!((right(&app) - 240.0).abs() < 1e-9);
    // P x 8: F_thre = 640 N, beyond the axis: fitted again, and said.
    command(&mut app, "P=8");
    let threshold = match app.model() {
        Some(Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. })) => {
            beams.threshold_force()
        }
        _ => panic!(),
    };
    assert!((threshold - 640.0).abs() < 1e-9);
    assert!(
        (right(&app) - 3.0 * threshold).abs() < 1e-9,
        "{}",
        right(&app)
    );
    let said = &app.message().unwrap().text;
    assert!(
        said.contains("set P = 8 MPa") && said.contains("F axis rescaled to 0-1920 N"),
        "{said}"
    );
    // Down by 40: F_thre = 16 N, squeezed into the start of 0-1920 N (F lowered too: the
    // axis always reaches 1.25 F to show the current force).
    command(&mut app, "P=0.2 F=10");
    assert!((right(&app) - 48.0).abs() < 1e-9, "{}", right(&app));
    assert!(app.message().unwrap().text.contains("squeezed"));
    // A factor inside the band keeps the axis (and says nothing of it).
    command(&mut app, "P=0.3");
    assert!((right(&app) - 48.0).abs() < 1e-9);
    assert!(!app.message().unwrap().text.contains("rescaled"));
}
