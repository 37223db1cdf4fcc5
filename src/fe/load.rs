//! Reading FE result files a user names (CLI `compare`, the TUI's `d`): a CalculiX `.dat` with the
//! microslip deck it came from (its header gives the parameters), or a CSV curve from any code.

use std::path::{Path, PathBuf};

use thiserror::Error;

pub use super::face::AnyLoaded;
use super::face::Deck;
use super::header::DeckHeader;
use super::kinematics::Kinematics;
use super::peak_pressure::PeakPressure;
use super::results::CcxRun;
use super::stick_slope::{self, Friction, StickSlopeUsed};
use super::verdict::InterfaceMesh;
use crate::file::{Kinds, Size, read_capped};
use crate::problems::ModelKind;

/// Largest result file read (256 MiB): a `.dat` of a fine deck is a few MB.
pub(crate) const MAX_RESULT_SIZE: Size = Size(256 << 20);

/// A result file that cannot be used, with the file it is about.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{path}: {reason}")]
pub struct LoadError {
    /// The file.
    pub path: String,
    /// What is wrong (with the line when there is one).
    pub reason: String,
}

/// FE points read from one file, with the header of the deck that produced them (CalculiX), or
/// none (CSV: the caller supplies the parameters).
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded<P> {
    /// The deck's header, for `.dat` results.
    pub header: Option<DeckHeader>,
    /// The points.
    pub points: Vec<P>,
    /// The FE mesh along the interface, from the deck (CalculiX results; `None` for CSV, which
    /// does not say).
    pub interface_mesh: Option<InterfaceMesh>,
}

/// What a CalculiX run says about its contact, beside its points ([`ccx_contact`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CcxContact {
    /// The kinematics of the run, from its deck.
    pub kinematics: Kinematics,
    /// The stick slope the run used, from the `.frd` beside its `.dat`, or why it was not read.
    pub stick_slope: Result<StickSlopeUsed, String>,
    /// The largest contact pressure of the same output; `None` where it was not read or holds no
    /// positive pressure.
    pub peak_pressure: Option<PeakPressure>,
}

/// The contact evidence of the `.dat` at `path` whose deck (`deck`, by default beside it with the
/// extension `.inp`) has `header`: the deck's kinematics and the stick slope of the `.frd` beside
/// the `.dat`. Read apart from the points (the TUI, which loads points, does not need it).
///
/// # Errors
/// [`LoadError`] when the deck cannot be read (the points were read from it just before).
pub fn ccx_contact(
    path: &Path,
    deck: Option<&Path>,
    header: &DeckHeader,
) -> Result<CcxContact, LoadError> {
    let deck_text = read(&deck_path(path, deck), "a deck")?;
    let contact = frd_contact(path);
    Ok(CcxContact {
        kinematics: Kinematics::of_deck(&deck_text),
        peak_pressure: contact.as_ref().ok().and_then(|c| PeakPressure::of(c)),
        stick_slope: contact.and_then(|c| ccx_stick_slope(c, header, &deck_text)),
    })
}

fn read(path: &Path, what: &'static str) -> Result<String, LoadError> {
    read_capped(path, MAX_RESULT_SIZE, what, Kinds::RegularOnly)
        .map_err(|e| fail(path, e.to_string()))
}

fn fail(path: &Path, reason: impl Into<String>) -> LoadError {
    LoadError {
        path: path.display().to_string(),
        reason: reason.into(),
    }
}

/// Whether `path` names CalculiX output (by its extension: `.dat`; `.frd` is refused with advice).
fn is_ccx(path: &Path) -> Result<bool, LoadError> {
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("dat") => Ok(true),
        Some(e) if e.eq_ignore_ascii_case("frd") => Err(fail(
            path,
            "give the .dat file of the run: the deck prints what compare reads there",
        )),
        _ => Ok(false),
    }
}

/// The deck of a `.dat`: `deck` when given, else the `.dat`'s path with the extension `.inp`.
fn deck_path(dat: &Path, deck: Option<&Path>) -> PathBuf {
    deck.map_or_else(|| dat.with_extension("inp"), Path::to_path_buf)
}

/// The header and text of the deck of the `.dat` at `path`.
fn read_deck(path: &Path, deck: Option<&Path>) -> Result<(DeckHeader, String), LoadError> {
    // The results first: a mistyped .dat path should say so, not that its deck is missing.
    crate::file::require_regular(path).map_err(|e| fail(path, e.to_string()))?;
    let deck_path = deck_path(path, deck);
    let deck_text = read(&deck_path, "a deck").map_err(|e| LoadError {
        reason: format!(
            "the deck that produced the .dat is needed, by default beside it with the extension \
             .inp: {}",
            e.reason
        ),
        ..e
    })?;
    let header = DeckHeader::parse(&deck_text)
        .map_err(|e| fail(&deck_path, e.to_string()))?
        .ok_or_else(|| {
            fail(
                &deck_path,
                "no '** microslip-deck:' header line: compare reads .dat files of decks written \
                 by `microslip deck ccx`; for other decks write a CSV",
            )
        })?;
    Ok((header, deck_text))
}

/// Refuses a deck of another problem, naming the command that reads it.
fn check_kind(
    header: &DeckHeader,
    path: &Path,
    deck: Option<&Path>,
    wanted: ModelKind,
) -> Result<(), LoadError> {
    let found = header.inputs.kind();
    if found == wanted {
        return Ok(());
    }
    Err(fail(
        &deck_path(path, deck),
        format!(
            "a {} deck; use `microslip compare {}`",
            found.name(),
            found.name()
        ),
    ))
}

/// The points of the `.dat` at `path`, read with its already read deck.
fn ccx_points<P: Deck>(
    path: &Path,
    header: DeckHeader,
    deck_text: &str,
) -> Result<Loaded<P::FePoint>, LoadError> {
    let dat = read(path, "an FE result file")?;
    let run = CcxRun {
        header: &header,
        deck: deck_text,
        dat: &dat,
        dat_path: path,
    };
    let points = run.points::<P>().map_err(|e| fail(path, e.to_string()))?;
    let interface_mesh = P::interface_mesh(&run).map_err(|e| fail(path, e.to_string()))?;
    Ok(Loaded {
        header: Some(header),
        points,
        interface_mesh,
    })
}

/// The interface at the end of each step of the CalculiX run whose `.dat` is `dat`, from the
/// `CONTACT` blocks of the `.frd` beside it (the decks ask for them: `*CONTACT FILE`, `CDIS, CSTR`).
///
/// # Errors
/// The `.frd` missing, unreadable, malformed or without a `CONTACT` block, in words naming it.
pub fn frd_contact(dat: &Path) -> Result<Vec<stick_slope::ContactStep>, String> {
    use std::io::Read as _;
    let frd = dat.with_extension("frd");
    let file = std::fs::File::open(&frd).map_err(|e| {
        format!(
            "{}: {e} (the run's .frd, beside its .dat, holds the interface output)",
            frd.display()
        )
    })?;
    let reader = std::io::BufReader::new(file.take(stick_slope::MAX_FRD_BYTES));
    let contact =
        stick_slope::read_frd_contact(reader).map_err(|e| format!("{}: {e}", frd.display()))?;
    if contact.is_empty() {
        return Err(format!(
            "{}: no CONTACT block (the deck's *CONTACT FILE with CDIS, CSTR writes them)",
            frd.display()
        ));
    }
    Ok(contact)
}

/// The stick slope a CalculiX run used, from its `contact` output (the `CONTACT` blocks of the
/// `.frd` beside its `.dat`: [`frd_contact`]), against the deck header's K_T; the friction
/// coefficient is the one the run was given (the deck's `*FRICTION` card).
fn ccx_stick_slope(
    contact: Vec<stick_slope::ContactStep>,
    header: &DeckHeader,
    deck_text: &str,
) -> Result<StickSlopeUsed, String> {
    let contact = if stick_slope::first_step_changes_friction(deck_text) {
        stick_slope::slips_from_first_step(contact)
    } else {
        contact
    };
    let interface = header.model().map_err(|e| e.to_string())?.interface();
    let card = stick_slope::friction_card(deck_text);
    let friction = Friction {
        coefficient: card.map_or(interface.friction, |(mu, _)| mu),
        nominal_pressure: interface.pressure,
    };
    let mut used = StickSlopeUsed::measure(&contact, friction, interface.stiffness);
    used.friction_card = card
        .map(|(_, slope)| slope)
        .filter(|slope| (slope / interface.stiffness - 1.0).abs() > 1e-9);
    Ok(used)
}

/// Where FE points are read from: a `.dat` with its deck (header and text already read), or a
/// CSV. Which problem's points it holds is the reader's type parameter ([`Source::points`]).
pub(crate) enum Source<'a> {
    /// CalculiX output at `path`, of the deck whose header and text are given.
    Ccx {
        /// The `.dat`.
        path: &'a Path,
        /// The deck's header.
        header: DeckHeader,
        /// The deck's text.
        deck_text: String,
    },
    /// A CSV curve at `path`.
    Csv(&'a Path),
}

impl Source<'_> {
    /// The points of the source, as problem `P`'s.
    pub(crate) fn points<P: Deck>(self) -> Result<Loaded<P::FePoint>, LoadError> {
        match self {
            Source::Ccx {
                path,
                header,
                deck_text,
            } => ccx_points::<P>(path, header, &deck_text),
            Source::Csv(path) => {
                let text = read(path, "an FE result file")?;
                let points = P::csv_points(&text).map_err(|e| fail(path, e.to_string()))?;
                Ok(Loaded {
                    header: None,
                    points,
                    interface_mesh: None,
                })
            }
        }
    }
}

/// The points of `path`, of whichever model its deck is (CalculiX), or of `csv_model` (CSV: the
/// columns do not say).
///
/// # Errors
/// [`LoadError`] naming the file and, where there is one, the line.
pub fn any_results(
    path: &Path,
    deck: Option<&Path>,
    csv_model: ModelKind,
) -> Result<AnyLoaded, LoadError> {
    if is_ccx(path)? {
        // The deck says which model; it is read once.
        let (header, deck_text) = read_deck(path, deck)?;
        let kind = header.inputs.kind();
        let source = Source::Ccx {
            path,
            header,
            deck_text,
        };
        return AnyLoaded::read(kind, source);
    }
    AnyLoaded::read(csv_model, Source::Csv(path))
}

/// Problem `P`'s points from a `.dat` (with its deck, which must be of `P`) or a CSV in `P`'s
/// measurement format (`F_N,w_mm` for the beams, `KT_MPa_per_mm,u_mm` for the plate,
/// `F_N,Delta_mm` for the lap joint).
///
/// # Errors
/// [`LoadError`] naming the file and, where there is one, the line.
pub fn results<P: Deck>(path: &Path, deck: Option<&Path>) -> Result<Loaded<P::FePoint>, LoadError> {
    if is_ccx(path)? {
        let (header, deck_text) = read_deck(path, deck)?;
        check_kind(&header, path, deck, P::KIND)?;
        Source::Ccx {
            path,
            header,
            deck_text,
        }
        .points::<P>()
    } else {
        Source::Csv(path).points::<P>()
    }
}
