//! `deck` and `bench`: writing an FE deck and running an external solver on it.

use super::*;
use crate::problems::lap::closed_form::{JointForce, LapJoint};
use crate::{TipForce, TwinBeams};

/// The deck `deck` describes for `model`, as text. `command` names the subcommand in errors.
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
    match load(&deck.inputs, model, command)? {
        (_, Model::Beam(crate::problems::twin_beams::problem::BeamsModel { beams, .. })) => {
            let loads = deck_loads(&beams, deck.loads.as_deref(), slope)?;
            let force_step = deck
                .increment
                .map(|f| check_flag("--increment", f, Domain::FORCE_STEP, Unit::Newton))
                .transpose()?;
            let path = deck::LoadPath { force_step };
            crate::problems::twin_beams::deck::beam_deck_on_path(
                &beams, &loads, deck.mesh, slope, path,
            )
        }
        (_, Model::Lap(crate::problems::lap::problem::LapModel { joint, .. })) => {
            let loads = lap_deck_loads(&joint, deck.loads.as_deref(), slope)?;
            let force_step = deck
                .increment
                .map(|f| check_flag("--increment", f, Domain::FORCE_STEP, Unit::Newton))
                .transpose()?;
            crate::problems::lap::deck::lap_deck(
                &joint,
                &loads,
                deck.mesh,
                slope,
                deck::LoadPath { force_step },
            )
        }
        (_, Model::Plate(plate)) => {
            if deck.loads.is_some() {
                return Err(CliError::Usage(
                    "--loads are the tip forces of a beam deck; the plate deck applies its \
                     pressure P in one step (set P with --set P=...)",
                ));
            }
            crate::problems::plate::deck::plate_deck(&plate, deck.mesh, slope)
        }
    }
    .map_err(|e| CliError::Invalid(e.to_string()))
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
    run_compare(
        out,
        model,
        std::slice::from_ref(&files.results),
        Some(&files.deck),
        &deck.inputs,
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

/// The words of [`note_flags_the_deck_overrides`]: only the beams have two beam theories, so
/// only their note says that both are shown.
pub(super) fn deck_overrides_words(given: &[String], model: ModelKind) -> String {
    let theories = match model {
        ModelKind::Beam => " (compare shows both beam theories)",
        ModelKind::Plate | ModelKind::Lap => "",
    };
    format!(
        "{} not used: the deck's header gives the parameters of the run{theories}; to compare FE \
         points at other parameters, give them as CSV",
        report::sanitize(&given.join(" "))
    )
}

/// `command` followed by the model's name, for error messages ("deck ccx beam").
pub(super) fn model_command(model: ModelKind, command: &str) -> String {
    format!("{command} {model}")
}

/// The load steps of a beam deck: `--loads` checked (each a valid force, strictly increasing), or
/// the default multiples of F_thre, which span microslip and macroslip. With a near-Coulomb stick
/// slope the interface is on the edge of sliding everywhere at exactly F_thre, and CalculiX's
/// contact iterations can chatter there until they give up; the default then stops at 0.95 F_thre.
pub(super) fn deck_loads(
    beams: &TwinBeams,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<TipForce>, CliError> {
    let Some(loads) = loads else {
        let thre = beams.threshold_force();
        let at_threshold = match slope {
            StickSlope::Model => 1.0,
            StickSlope::NearCoulomb => 0.95,
        };
        return Ok([0.5, 0.75, at_threshold, 1.25, 1.875, 2.5]
            .map(|m| TipForce::clamped(m * thre))
            .to_vec());
    };
    let mut forces = Vec::with_capacity(loads.len());
    for &f in loads {
        let force = check_flag("--loads", f, Domain::FORCE, Unit::Newton)?;
        if forces
            .last()
            .is_some_and(|last: &TipForce| last.newtons() >= force)
        {
            return Err(CliError::Flag {
                flag: "--loads",
                value: f,
                allowed: "the loads must increase from one step to the next".to_string(),
            });
        }
        forces.push(TipForce::clamped(force));
    }
    Ok(forces)
}

/// The forces of a lap deck's steps: `--loads` (increasing, each at most F_gross), or one in each
/// regime: all microslip (F_1/2), one end sliding, both ends, and 0.9 F_gross (at the deck's
/// stick slope).
pub(super) fn lap_deck_loads(
    joint: &LapJoint,
    loads: Option<&[f64]>,
    slope: StickSlope,
) -> Result<Vec<JointForce>, CliError> {
    let at_slope = joint
        .with_tangential_stiffness(crate::problems::lap::deck::stick_slope_of(slope, joint))
        .unwrap_or(*joint);
    let Some(loads) = loads else {
        let (f1, f2, gross) = (
            at_slope.first_slip_force(),
            at_slope.second_slip_force(),
            at_slope.gross_slip_force(),
        );
        let mut forces: Vec<f64> = vec![0.5 * f1, 0.5 * (f1 + f2), 0.5 * (f2 + gross), 0.9 * gross];
        forces.dedup_by(|a, b| *a <= *b);
        return Ok(forces.into_iter().map(|f| joint.clamped_force(f)).collect());
    };
    let mut forces: Vec<JointForce> = Vec::with_capacity(loads.len());
    for &f in loads {
        let force = joint.force(f).map_err(|e| CliError::Flag {
            flag: "--loads",
            value: f,
            allowed: e.allowed(),
        })?;
        if forces.last().is_some_and(|last| *last >= force) {
            return Err(CliError::Flag {
                flag: "--loads",
                value: f,
                allowed: "the loads must increase from one step to the next".to_string(),
            });
        }
        forces.push(force);
    }
    Ok(forces)
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
