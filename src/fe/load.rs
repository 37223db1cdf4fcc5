//! Reading FE result files a user names (CLI `compare`, the TUI's `d`): a CalculiX `.dat` with the
//! microslip deck it came from (its header gives the parameters), or a CSV curve from any code.

use std::path::{Path, PathBuf};

use thiserror::Error;

use super::header::DeckHeader;
use super::results::{
    BeamFePoint, CcxRun, LapFePoint, PlateFePoint, ResultsError, beam_points_from_csv,
    lap_points_from_csv, plate_points_from_csv,
};
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
fn ccx_points<P>(
    path: &Path,
    header: DeckHeader,
    deck_text: &str,
    from_run: impl Fn(&CcxRun) -> Result<Vec<P>, ResultsError>,
) -> Result<Loaded<P>, LoadError> {
    let dat = read(path, "an FE result file")?;
    let run = CcxRun {
        header: &header,
        deck: deck_text,
        dat: &dat,
    };
    let points = from_run(&run).map_err(|e| fail(path, e.to_string()))?;
    let interface_mesh = Some(
        run.interface_mesh()
            .map_err(|e| fail(path, e.to_string()))?,
    );
    Ok(Loaded {
        header: Some(header),
        points,
        interface_mesh,
    })
}

fn beam_run(run: &CcxRun) -> Result<Vec<BeamFePoint>, ResultsError> {
    run.beam_points()
}

fn plate_run(run: &CcxRun) -> Result<Vec<PlateFePoint>, ResultsError> {
    run.plate_point().map(|p| vec![p])
}

fn lap_run(run: &CcxRun) -> Result<Vec<LapFePoint>, ResultsError> {
    run.lap_points()
}

/// FE points of any model.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyLoaded {
    /// Twin-beam points.
    Beam(Loaded<BeamFePoint>),
    /// Squeezed-plate points.
    Plate(Loaded<PlateFePoint>),
    /// Double-lap joint points.
    Lap(Loaded<LapFePoint>),
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
        return match header.inputs.kind() {
            ModelKind::Beam => ccx_points(path, header, &deck_text, beam_run).map(AnyLoaded::Beam),
            ModelKind::Plate => {
                ccx_points(path, header, &deck_text, plate_run).map(AnyLoaded::Plate)
            }
            ModelKind::Lap => ccx_points(path, header, &deck_text, lap_run).map(AnyLoaded::Lap),
        };
    }
    match csv_model {
        ModelKind::Beam => beam_results(path, deck).map(AnyLoaded::Beam),
        ModelKind::Plate => plate_results(path, deck).map(AnyLoaded::Plate),
        ModelKind::Lap => lap_results(path, deck).map(AnyLoaded::Lap),
    }
}

/// Beam points from a `.dat` (with its deck) or a CSV `F_N,w_mm`.
///
/// # Errors
/// [`LoadError`] naming the file and, where there is one, the line.
pub fn beam_results(path: &Path, deck: Option<&Path>) -> Result<Loaded<BeamFePoint>, LoadError> {
    results(path, deck, ModelKind::Beam, beam_run, beam_points_from_csv)
}

/// Plate points from a `.dat` (with its deck) or a CSV `KT_MPa_per_mm,u_mm`.
///
/// # Errors
/// [`LoadError`] naming the file and, where there is one, the line.
pub fn plate_results(path: &Path, deck: Option<&Path>) -> Result<Loaded<PlateFePoint>, LoadError> {
    results(
        path,
        deck,
        ModelKind::Plate,
        plate_run,
        plate_points_from_csv,
    )
}

/// Lap-joint points from a `.dat` (with its deck) or a CSV `F_N,Delta_mm`.
///
/// # Errors
/// [`LoadError`] naming the file and, where there is one, the line.
pub fn lap_results(path: &Path, deck: Option<&Path>) -> Result<Loaded<LapFePoint>, LoadError> {
    results(path, deck, ModelKind::Lap, lap_run, lap_points_from_csv)
}

/// The points of `path`: from CalculiX output (with its deck, which must be of `kind`) or a CSV.
fn results<P>(
    path: &Path,
    deck: Option<&Path>,
    kind: ModelKind,
    from_run: impl Fn(&CcxRun) -> Result<Vec<P>, ResultsError>,
    from_csv: impl Fn(&str) -> Result<Vec<P>, ResultsError>,
) -> Result<Loaded<P>, LoadError> {
    if is_ccx(path)? {
        let (header, deck_text) = read_deck(path, deck)?;
        check_kind(&header, path, deck, kind)?;
        ccx_points(path, header, &deck_text, from_run)
    } else {
        let text = read(path, "an FE result file")?;
        let points = from_csv(&text).map_err(|e| fail(path, e.to_string()))?;
        Ok(Loaded {
            header: None,
            points,
            interface_mesh: None,
        })
    }
}
