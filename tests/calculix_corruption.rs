//! Real CalculiX result files (`tests/data/calculix/`), cut short and corrupted at random: the
//! readers either refuse with a message, or give exactly the points of the intact file. Never a
//! number computed from part of a node set or part of the load steps (issue: a plate `.dat` cut
//! inside its `UEND` block gave a thickness mean 40 % low and an implied K_T 70 times too stiff,
//! exit 0).
//!
//! The comparison with the closed forms is a pure function of the points and the deck's header,
//! so equal points mean an equal comparison; the points are what is checked.

mod common;

use std::path::PathBuf;

use microslip::fe::header::DeckHeader;
use microslip::fe::results::CcxRun;
use microslip::problems::plate::SqueezedPlateProblem;
use microslip::problems::plate::fe_points::PlateFePoint;
use microslip::problems::twin_beams::TwinBeamsProblem;
use microslip::problems::twin_beams::fe_points::BeamFePoint;
use proptest::prelude::*;

fn fixture(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/calculix")
        .join(name);
    std::fs::read_to_string(path).unwrap()
}

/// A run's deck and `.dat` texts, and the header of the deck.
struct Run {
    deck: String,
    dat: String,
    header: DeckHeader,
}

impl Run {
    fn load(stem: &str) -> Run {
        let deck = fixture(&format!("{stem}.inp"));
        let header = DeckHeader::parse(&deck).unwrap().unwrap();
        Run {
            dat: fixture(&format!("{stem}.dat")),
            deck,
            header,
        }
    }

    fn beam_points(&self, dat: &str) -> Result<Vec<BeamFePoint>, String> {
        self.run(dat)
            .points::<TwinBeamsProblem>()
            .map_err(|e| e.to_string())
    }

    fn plate_point(&self, dat: &str) -> Result<PlateFePoint, String> {
        self.run(dat)
            .points::<SqueezedPlateProblem>()
            .map(|mut points| points.remove(0))
            .map_err(|e| e.to_string())
    }

    fn run<'a>(&'a self, dat: &'a str) -> CcxRun<'a> {
        CcxRun {
            header: &self.header,
            deck: &self.deck,
            dat,
            dat_path: std::path::Path::new("no-such-run.dat"),
        }
    }
}

/// Characters that are not part of any number, name or separator CalculiX writes: a corruption
/// made of them cannot turn into another valid number. (A digit for a digit could, and no reader
/// can see that; a space for a minus sign too. Those are out of any reader's reach.)
const JUNK: &[char] = &['x', '#', '@', ',', ';', '?'];

/// One corruption of `text`, chosen by the numbers given.
fn corrupt(text: &str, kind: u8, at: usize, junk: usize) -> String {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let line = at % lines.len().max(1);
    let junk = JUNK[junk % JUNK.len()];
    match kind % 5 {
        // Cut at a byte (on a character boundary).
        0 => {
            let mut cut = at % (text.len() + 1);
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            text[..cut].to_string()
        }
        // A line lost.
        1 => lines
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != line)
            .map(|(_, l)| *l)
            .collect(),
        // A line written twice.
        2 => lines
            .iter()
            .enumerate()
            .flat_map(|(i, l)| std::iter::repeat_n(*l, if i == line { 2 } else { 1 }))
            .collect(),
        // A character replaced by junk.
        3 | 4 => {
            let chars: Vec<char> = text.chars().collect();
            if chars.is_empty() {
                return String::new();
            }
            let position = at % chars.len();
            let mut out: String = chars[..position].iter().collect();
            out.push(junk);
            // 3 replaces the character, 4 inserts before it.
            let rest = if kind % 5 == 3 {
                position + 1
            } else {
                position
            };
            out.extend(&chars[rest..]);
            out
        }
        _ => unreachable!("kind % 5"),
    }
}

/// Cases per fixture: each reads a whole `.dat` (up to 1 800 lines).
const CASES: u32 = 96;

proptest! {
    #![proptest_config(common::fixed_seed(CASES))]

    #[test]
    fn a_damaged_beam_dat_is_refused_or_read_as_the_intact_one(
        kind in 0u8..5,
        at in 0usize..1_000_000,
        junk in 0usize..16,
    ) {
        let run = Run::load("paper-beams");
        let intact = run.beam_points(&run.dat).unwrap();
        let damaged = corrupt(&run.dat, kind, at, junk);
        match run.beam_points(&damaged) {
            Ok(points) => prop_assert_eq!(points, intact, "kind {} at {}", kind, at),
            Err(message) => prop_assert!(!message.is_empty()),
        }
    }

    #[test]
    fn a_damaged_plate_dat_is_refused_or_read_as_the_intact_one(
        kind in 0u8..5,
        at in 0usize..1_000_000,
        junk in 0usize..16,
        stem in prop::sample::select(vec!["paper-plate", "plate-kt1e4"]),
    ) {
        let run = Run::load(stem);
        let intact = run.plate_point(&run.dat).unwrap();
        let damaged = corrupt(&run.dat, kind, at, junk);
        match run.plate_point(&damaged) {
            Ok(point) => prop_assert_eq!(point, intact, "{} kind {} at {}", stem, kind, at),
            Err(message) => prop_assert!(!message.is_empty()),
        }
    }
}

/// The two cases of the issue, exactly: a plate `.dat` cut inside `UEND` (`head -n 6`), and a beam
/// `.dat` holding 6 of its deck's 9 steps.
#[test]
fn the_reported_truncations_are_refused_and_say_what_is_missing() {
    let plate = Run::load("paper-plate");
    let head: String = plate.dat.split_inclusive('\n').take(6).collect();
    let refused = plate.plate_point(&head).unwrap_err();
    assert!(
        refused.contains("set UEND has 3 rows for the deck's 9 nodes (6 missing)"),
        "{refused}"
    );
    let beams = Run::load("paper-beams");
    let steps = beams.header.loads.len();
    // Keep the blocks of the pressure step and of the first loads: cut before the block of the
    // fourth load (time 5).
    let cut = beams
        .dat
        .find("and time  0.5000000E+01")
        .and_then(|at| beams.dat[..at].rfind('\n'))
        .unwrap();
    let refused = beams.beam_points(&beams.dat[..=cut]).unwrap_err();
    assert!(
        refused.contains(&format!("load step 4 of {steps}"))
            && refused.contains(&format!(
                "the .dat holds 3 of the deck's {steps} load steps"
            )),
        "{refused}"
    );
}
