//! `deck` and `bench`: writing an FE deck and running an external solver on it.

use super::*;
use crate::fe::face::{DeckError, DeckRequest};

/// The deck `deck` describes for `model`, as text. `command` names the subcommand in errors.
/// What the flags mean for the deck (which loads, which increments) is the problem's own
/// ([`Deck::write_deck`](crate::fe::face::Deck::write_deck)).
pub(super) fn build_deck(
    model: ModelKind,
    deck: &DeckArgs,
    command: &str,
) -> Result<String, CliError> {
    let slope = if deck.near_coulomb {
        StickSlope::NearCoulomb
    } else {
        StickSlope::Model
    };
    let (inputs, note) = with_bench_preset(&deck.inputs, model);
    let (_, loaded) = load(&inputs, model, command)?;
    let request = DeckRequest {
        loads: deck.loads.as_deref(),
        mesh: deck.mesh,
        slope,
        increment: deck.increment,
    };
    let written = crate::suite::run::write_deck(model, &loaded, &request)
        .ok_or_else(|| wrong_model(&deck.inputs, loaded.kind(), model, command))?;
    let written = written.map(|deck| match &note {
        Some(note) => with_case_note(&deck, note),
        None => deck,
    });
    written.map_err(|e| match e {
        DeckError::Flag {
            flag,
            value,
            allowed,
        } => CliError::Flag {
            flag,
            value,
            allowed,
        },
        DeckError::Usage(why) => CliError::Usage(why),
        DeckError::TooLarge(e) => CliError::Invalid(e.to_string()),
        e @ DeckError::NonFinite { .. } => CliError::Invalid(e.to_string()),
    })
}

/// `inputs`, or where they name no preset, the problem's benchmark preset ([`Deck::BENCH_PRESET`])
/// with the note that says which and why (for stderr once the deck is written): `deck` and
/// `bench` default to a case where the judge is sharp.
///
/// [`Deck::BENCH_PRESET`]: crate::fe::face::Deck::BENCH_PRESET
fn with_bench_preset(inputs: &InputArgs, model: ModelKind) -> (InputArgs, Option<String>) {
    let mut inputs = inputs.clone();
    if inputs.preset.is_some() {
        return (inputs, None);
    }
    let (name, why) = for_problem(model, BenchPreset).unwrap_or((
        model.description().paper_preset,
        "the problem's default bundled preset",
    ));
    let note = format!(
        "Case: the preset {name}, the default of deck and bench for the {}: {why}; --preset \
         names another",
        model.name()
    );
    inputs.preset = Some(name.to_string());
    (inputs, Some(note))
}

/// `deck` with `note` as comment lines (of at most 100 characters: CalculiX reads 132) before
/// its `*HEADING`, below the header comments `compare` reads.
fn with_case_note(deck: &str, note: &str) -> String {
    let mut lines = vec![String::from("**")];
    for word in note.split(' ') {
        let last = lines.last_mut().expect("one line at least");
        if last.len() + word.len() + 1 > 100 {
            lines.push(format!("** {word}"));
        } else {
            last.push(' ');
            last.push_str(word);
        }
    }
    let comment = lines.join("\n") + "\n";
    match deck.find("*HEADING") {
        Some(at) => format!("{}{comment}{}", &deck[..at], &deck[at..]),
        None => comment + deck,
    }
}

/// The problem's [`Deck::BENCH_PRESET`](crate::fe::face::Deck::BENCH_PRESET), for
/// [`for_problem`].
struct BenchPreset;

impl ForProblem for BenchPreset {
    type Output = Option<(&'static str, &'static str)>;

    fn run<P: Faces>(self) -> Self::Output {
        P::BENCH_PRESET
    }
}

/// `microslip bench ccx MODEL`: the deck into a work folder, ccx on it with progress on stderr,
/// then the comparison as `compare` prints it. The folder is kept and named on stderr.
pub(super) fn run_bench(
    out: &mut impl Write,
    model: ModelKind,
    deck: &DeckArgs,
    workdir: Option<&std::path::Path>,
    ccx: &str,
    format: CompareFormat,
) -> Result<(), CliError> {
    let text = build_deck(model, deck, &model_command(model, "bench ccx"))?;
    // Before the folder is made: a refused --ccx leaves nothing behind.
    let program = fe::run::resolve_program(ccx)?;
    let job = model.name();
    let files = match workdir {
        Some(folder) => fe::run::claim_folder(folder, job)?,
        None => {
            let folder = fe::run::fresh_folder(&std::env::temp_dir(), job)?;
            fe::run::RunFiles::new(&folder, job)
        }
    };
    crate::file::write_new_files(&[(files.deck.as_path(), text.as_bytes())])?;
    let stop = StopSignals::install()?;
    let stderr = io::stderr();
    let terminal = stderr.is_terminal();
    let mut progress = ProgressLine::new(stderr.lock(), terminal);
    let shown = files.folder.display().to_string();
    let started = Instant::now();
    let mut announced = false;
    let mut increments_said = 0;
    let result = fe::run::run_ccx(
        &program,
        &files,
        Duration::from_millis(50),
        &mut |p| {
            // Said once ccx runs: a missing ccx is then one line of error, not two.
            if !announced {
                eprintln!("microslip: running {ccx} on {}", files.deck.display());
                announced = true;
            }
            if terminal {
                progress.update(Instant::now(), || text::ccx_progress(p));
            } else if p.increments > increments_said {
                // A log or a CI job sees a line per increment, not minutes of silence.
                increments_said = p.increments;
                eprintln!(
                    "microslip: {}, increment {}",
                    text::ccx_progress(p),
                    p.increments
                );
            }
        },
        &|| stop.received(),
    );
    drop(progress);
    result?;
    if let Some(signal) = stop.received() {
        return Err(fe::run::RunError::Stopped {
            signal,
            folder: shown,
        }
        .into());
    }
    eprintln!(
        "microslip: ccx took {:.0} s; its files and log ({}) are kept in {shown}",
        started.elapsed().as_secs_f64(),
        files.log.display()
    );
    // Which case ran, once it ran (an error before stays one line).
    if let (_, Some(note)) = with_bench_preset(&deck.inputs, model) {
        eprintln!("microslip: {note}");
    }
    run_compare(
        out,
        model,
        std::slice::from_ref(&files.results),
        Some(&files.deck),
        &deck.inputs,
        super::compare::ContactArgs::default(),
        format,
    )
}

/// SIGTERM, SIGINT and SIGHUP while `bench` runs the solver: recorded instead of ending
/// microslip at once, so that the solver (in a process group of its own, out of the terminal's
/// reach) is ended first; microslip then exits with 128 + the signal, as the default action
/// would have.
pub(super) struct StopSignals {
    pub(super) received: std::sync::Arc<std::sync::atomic::AtomicUsize>,
}

impl StopSignals {
    pub(super) fn install() -> io::Result<StopSignals> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let received = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
        for signal in [SIGTERM, SIGINT, SIGHUP] {
            signal_hook::flag::register_usize(
                signal,
                std::sync::Arc::clone(&received),
                signal as usize,
            )?;
        }
        Ok(StopSignals { received })
    }

    /// The last signal received, if any.
    pub(super) fn received(&self) -> Option<i32> {
        match self.received.load(std::sync::atomic::Ordering::SeqCst) {
            0 => None,
            n => i32::try_from(n).ok(),
        }
    }
}

/// `microslip compare`: reads every result file, builds the closed forms from its deck's header (or
/// from `--preset`/`--set` for CSV) and prints the comparison.
/// Says on stderr which parameter flags a CalculiX run's deck overrides: its header gives the
/// parameters the run was made with, and comparing at others would mean nothing (they used to be
/// ignored without a word).
pub(super) fn note_flags_the_deck_overrides(inputs: &InputArgs, model: ModelKind) {
    let given = inputs.flags();
    if given.is_empty() {
        return;
    }
    eprintln!("microslip: note: {}", deck_overrides_words(&given, model));
}

/// The words of [`note_flags_the_deck_overrides`]: what a problem adds is its own
/// ([`Deck::OVERRIDES_NOTE`](crate::fe::face::Deck::OVERRIDES_NOTE): only the beams have two beam
/// theories, so only their note says that both are shown).
pub(super) fn deck_overrides_words(given: &[String], model: ModelKind) -> String {
    let theories = for_problem(model, OverridesNote);
    format!(
        "{} not used: the deck's header gives the parameters of the run{theories}; to compare FE \
         points at other parameters, give them as CSV",
        report::sanitize(&given.join(" "))
    )
}

/// [`Deck::OVERRIDES_NOTE`](crate::fe::face::Deck::OVERRIDES_NOTE) of a problem, for
/// [`for_problem`].
struct OverridesNote;

impl ForProblem for OverridesNote {
    type Output = &'static str;

    fn run<P: Faces>(self) -> &'static str {
        P::OVERRIDES_NOTE
    }
}

/// `command` followed by the model's name, for error messages ("deck ccx beam").
pub(super) fn model_command(model: ModelKind, command: &str) -> String {
    format!("{command} {model}")
}

/// A count as users write numbers, the README's notation included: `101`, `1e8`. Anything but a
/// whole number of at most 1e15 (a negative, a fraction, a word) is refused with what is expected;
/// the range of each count is checked where it is used.
pub(super) fn parse_count(text: &str) -> Result<u64, String> {
    let refuse = || format!("must be a whole number such as 101 or 1e8 (got '{text}')");
    let value = parse_number(text.trim()).ok_or_else(refuse)?;
    if value < 0.0 || value.fract() != 0.0 || value > 1e15 {
        return Err(refuse());
    }
    Ok(value as u64)
}
