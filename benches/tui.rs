//! Speed of the terminal UI: `cargo bench --bench tui`. Results and machine: BENCHMARKS.md.
//!
//! Besides timings, prints the bytes a real crossterm backend writes for one parameter change at
//! 120x40 against a full repaint (the cost that matters over SSH).

use std::io::{self, Write};
use std::sync::atomic::{AtomicUsize, Ordering};

use divan::{Bencher, black_box};
use microslip::app::testing::{Action, App, AppOptions, Charset, Theme};
use microslip::preset;
use ratatui::backend::{CrosstermBackend, TestBackend};
use ratatui::layout::Rect;
use ratatui::{Terminal, TerminalOptions, Viewport};

fn main() {
    report_bytes_per_change();
    divan::main();
}

fn app(preset_name: &str) -> App {
    App::new(AppOptions {
        theme: Theme {
            charset: Charset::Unicode,
            color: true,
        },
        preset: preset::resolve(preset_name).unwrap(),
        user_dir: None,
        data: None,
        solve_continuum: false,
    })
}

static WRITTEN: AtomicUsize = AtomicUsize::new(0);

/// A writer that only counts.
struct Counter;

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        WRITTEN.fetch_add(buf.len(), Ordering::Relaxed);
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

fn report_bytes_per_change() {
    let options = TerminalOptions {
        viewport: Viewport::Fixed(Rect::new(0, 0, 120, 40)),
    };
    let mut terminal = Terminal::with_options(CrosstermBackend::new(Counter), options).unwrap();
    let mut app = app("paper-beams");
    terminal
        .draw(|f| microslip::app::testing::draw(f, &app))
        .unwrap();
    let full = WRITTEN.swap(0, Ordering::Relaxed);
    select_last_row(&mut app); // F
    terminal
        .draw(|f| microslip::app::testing::draw(f, &app))
        .unwrap();
    let select = WRITTEN.swap(0, Ordering::Relaxed);
    app.update(Action::Increase); // F + 1 % of F_thre: summary, cursor and curves move
    terminal
        .draw(|f| microslip::app::testing::draw(f, &app))
        .unwrap();
    let change = WRITTEN.swap(0, Ordering::Relaxed);
    eprintln!(
        "bytes at 120x40: full repaint {full}, select a row {select}, one parameter change {change}"
    );
}

/// Nudges the last parameter (F or K_T) up and down on chart `chart` of `preset`: everything the view
/// recomputes after a parameter change (chart data), at the view's sampling density (200 points per
/// curve, whatever the terminal size).
fn recompute(bencher: Bencher, preset_name: &str, chart: usize) {
    let mut app = app(preset_name);
    for _ in 0..chart {
        app.update(Action::NextChart);
    }
    select_last_row(&mut app);
    nudge_last_row(bencher, app);
}

/// Selects the last row (F of the beams, K_T of the plate): the selection does not wrap, so this
/// takes j presses, not one k.
fn select_last_row(app: &mut App) {
    for _ in 0..app.kind().params().len() {
        app.update(Action::Next);
    }
}

/// Steps the selected row up and down, one step per iteration.
fn nudge_last_row(bencher: Bencher, mut app: App) {
    let mut up = true;
    bencher.bench_local(|| {
        app.update(if up {
            Action::Increase
        } else {
            Action::Decrease
        });
        up = !up;
        black_box(app.plot().series.len())
    });
}

/// Charts 0-2, and 5: the K_T table with its two tolerance solves (`microslip kt --tolerance`).
#[divan::bench(args = [0, 1, 2, 5])]
fn recompute_beam_view(bencher: Bencher, chart: usize) {
    recompute(bencher, "paper-beams", chart);
}

/// Charts 0-2 (0 on its default log axis), and 3: the K_T table with its tolerance solve.
#[divan::bench(args = [0, 1, 2, 3])]
fn recompute_plate_view(bencher: Bencher, chart: usize) {
    recompute(bencher, "paper-plate", chart);
}

/// The lap joint's charts 0-5, and 6: the K_T table with its two tolerance solves.
#[divan::bench(args = [0, 1, 2, 3, 4, 5, 6])]
fn recompute_lap_view(bencher: Bencher, chart: usize) {
    recompute(bencher, "lap-aluminium", chart);
}

/// Drawing one frame (all panes, chart included) into a 200x60 TestBackend.
#[divan::bench(args = ["unicode", "ascii"])]
fn render_200x60(bencher: Bencher, charset: &str) {
    draw_200x60(bencher, &beams_in(charset));
}

/// The paper's beams in colour, in `charset` (`ascii` or `unicode`).
fn beams_in(charset: &str) -> App {
    let charset = if charset == "ascii" {
        Charset::Ascii
    } else {
        Charset::Unicode
    };
    App::new(AppOptions {
        theme: Theme {
            charset,
            color: true,
        },
        preset: preset::resolve("paper-beams").unwrap(),
        user_dir: None,
        data: None,
        solve_continuum: false,
    })
}

fn draw_200x60(bencher: Bencher, app: &App) {
    let mut terminal = Terminal::new(TestBackend::new(200, 60)).unwrap();
    bencher.bench_local(|| {
        terminal
            .draw(|f| microslip::app::testing::draw(f, app))
            .unwrap();
    });
}

/// `app` with four pins (mu 0.2, 0.25, 0.35, 0.4) and mu back at 0.3, the selection on the last row.
fn with_four_pins(mut app: App) -> App {
    let rows = app.kind().params().len();
    for _ in 0..rows {
        app.update(Action::Previous);
    }
    while app.selected_param().name() != "mu" {
        app.update(Action::Next);
    }
    for mu in ["0.2", "0.25", "0.35", "0.4", "0.3"] {
        app.update(Action::StartEdit);
        for c in mu.chars() {
            app.update(Action::Input(c));
        }
        app.update(Action::Commit);
        if mu != "0.3" {
            app.update(Action::Pin);
        }
    }
    select_last_row(&mut app);
    app
}

/// As `recompute_beam_view` and `recompute_plate_view` on their first chart, with four pins: each
/// pin rebuilds the chart at its own parameters.
#[divan::bench(args = ["paper-beams", "paper-plate"])]
fn recompute_with_4_pins(bencher: Bencher, preset_name: &str) {
    nudge_last_row(bencher, with_four_pins(app(preset_name)));
}

/// `render_200x60` with four pins on the beams' w(L) chart.
#[divan::bench(args = ["unicode", "ascii"])]
fn render_200x60_with_4_pins(bencher: Bencher, charset: &str) {
    draw_200x60(bencher, &with_four_pins(beams_in(charset)));
}
