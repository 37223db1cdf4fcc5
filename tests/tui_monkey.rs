//! A monkey at the keyboard: random keys, pastes and resizes (20x5 to 250x80) through the real
//! `update` and `draw` path on a `TestBackend`. Nothing may panic, and every frame (recompute
//! included) must be drawn within [`FRAME_BOUND`], whatever values were accepted on the way: the
//! property the event loop relies on to act on signals promptly.

use std::time::{Duration, Instant};

use microslip::app::testing::{Action, App, AppOptions, Charset, Theme};
use microslip::preset;
use ratatui::Terminal;
use ratatui::backend::TestBackend;

/// Bound on one update plus one frame, in a debug build on a loaded 2-core CI machine (release
/// frames take about 1 ms, see BENCHMARKS.md).
const FRAME_BOUND: Duration = Duration::from_millis(1500);

/// xorshift64*: reproducible randomness without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Every action a key can produce (typed characters come from `TYPED`); `Quit` is left out so
/// that a run goes on, and `RequestQuit` is answered by the monkey like any question.
const ACTIONS: &[Action] = &[
    Action::Next,
    Action::Previous,
    Action::Increase,
    Action::Decrease,
    Action::IncreaseCoarse,
    Action::DecreaseCoarse,
    Action::StartEdit,
    Action::Backspace,
    Action::Commit,
    Action::Commit,
    Action::Cancel,
    Action::Yes,
    Action::SwitchModel,
    Action::NextChart,
    Action::PreviousChart,
    Action::CycleYAxis,
    Action::ToggleHelp,
    Action::OpenPresets,
    Action::Reset,
    Action::RequestQuit,
    Action::Suspend,
];

/// Values a hostile user types or pastes: extremes, non-numbers, overlong text.
const TYPED: &[&str] = &[
    "0",
    "1e-320",
    "1e-9",
    "0.4999999",
    "0.5",
    "1e6",
    "1e12",
    "1e100",
    "1e307",
    "1e308",
    "-1e308",
    "nan",
    "inf",
    "1.0000000000000000000000000000000e3",
    "abc",
    "",
    "\u{1b}[31m",
];

/// A key, and what it asks for (the preset list of `p`) done at once, as the event loop would.
fn press(app: &mut App, action: Action) {
    microslip::app::testing::update_blocking(app, action);
}

const PRESETS: [&str; 3] = ["paper-beams", "paper-beams-soft", "paper-plate"];

fn run(seed: u64, steps: usize) {
    let mut rng = Rng(seed);
    let mut app = App::new(AppOptions {
        theme: Theme {
            charset: *rng.pick(&[Charset::Unicode, Charset::Ascii]),
            color: rng.below(2) == 0,
        },
        preset: preset::resolve(PRESETS[rng.below(PRESETS.len())]).unwrap(),
        user_dir: None,
        data: None,
        solve_continuum: false,
    });
    let (mut width, mut height) = (100u16, 30u16);
    for step in 0..steps {
        let started = Instant::now();
        match rng.below(10) {
            0 => {
                width = 20 + rng.below(231) as u16;
                height = 5 + rng.below(76) as u16;
            }
            3 | 4 => {
                // A whole edit: some row, Enter, a hostile value, Enter.
                for _ in 0..rng.below(9) {
                    press(&mut app, Action::Next);
                }
                press(&mut app, Action::StartEdit);
                rng.pick(TYPED)
                    .chars()
                    .for_each(|c| press(&mut app, Action::Input(c)));
                press(&mut app, Action::Commit);
            }
            1 | 2 => {
                let text = rng.pick(TYPED);
                if rng.below(2) == 0 {
                    app.paste(&format!("{text}\nq\n"));
                } else {
                    text.chars().for_each(|c| press(&mut app, Action::Input(c)));
                }
            }
            _ => press(&mut app, *rng.pick(ACTIONS)),
        }
        if app.should_quit() {
            return;
        }
        let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
        terminal
            .draw(|frame| microslip::app::testing::draw(frame, &app))
            .unwrap();
        let took = started.elapsed();
        assert!(
            took < FRAME_BOUND,
            "seed {seed}, step {step}: {took:?} for one action and one {width}x{height} frame"
        );
        let screen = terminal.backend().to_string();
        assert!(
            !screen.contains("NaN") && !screen.contains("inf "),
            "seed {seed}, step {step}: a non-number on screen:\n{screen}"
        );
    }
}

#[test]
fn random_keys_pastes_and_resizes_never_panic_or_stall() {
    for seed in 1..=4 {
        run(0x9e37_79b9_7f4a_7c15 ^ seed, 400);
    }
}
