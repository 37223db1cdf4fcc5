//! [`Deck`]: what the FE layer needs of a problem (its deck's header lines, the FE points its
//! runs and CSV curves give, its comparison with the closed forms), as a capability trait each
//! problem's application folder implements (`src/problems/<name>/deck.rs`, with its reader in
//! `fe_points.rs` and its comparison in `compare.rs`), and its erased side
//! ([`AnyDeck`], [`deck_face`], [`AnyLoaded`]) generated from the registry.
//!
//! Why a trait and not a `match` on the problem's kind: the header, the readers and the loader
//! are written once for every problem; what differs (the cited source, the interface node set,
//! the expected closed-form values, the point a run gives) is the problem's own and lives in its
//! folder, so that a new problem with a deck is its folder and its registry line.

use std::fmt::Debug;

use super::deck::{DeckMesh, DeckTooLarge};
use super::header::{DeckHeader, StickSlope};
use super::kinematics::Kinematics;
use super::load::Loaded;
use super::results::{CcxRun, ResultsError};
use super::verdict::InterfaceMesh;
use crate::measured::Curve;
use crate::problems::ModelKind;
use crate::problems::Problem;
use crate::problems::problem::Registered;

/// A problem that CalculiX decks are written for and whose FE results are read and compared.
pub trait Deck: Problem + Registered {
    /// Where the problem comes from, as the deck's first comment line cites it
    /// (`" (Ligier & Bonhote 2014)"`).
    const SOURCE: &'static str;
    /// The node set along the interface whose nodes make the FE mesh an X difference is counted
    /// in ([`CcxRun::interface_mesh`]).
    const INTERFACE_SET: &'static str;
    /// One FE point, from a CalculiX run or a CSV curve.
    type FePoint: Debug + Clone + PartialEq + Send + 'static;
    /// The FE points against the closed forms.
    type Compared: Debug + Clone;

    /// The closed-form values the run of a deck with `header` should reproduce, as comment lines
    /// (`model` is the header's model, validated).
    fn expected(model: &Self::Model, header: &DeckHeader) -> String;

    /// The FE points of a CalculiX run of a deck of this problem, whose header holds `params`.
    ///
    /// # Errors
    /// A malformed `.dat` line, or a result the deck asks for and the `.dat` lacks.
    fn ccx_points(run: &CcxRun, params: &Self::Params) -> Result<Vec<Self::FePoint>, ResultsError>;

    /// The FE mesh along the interface of a CalculiX run of a deck of this problem, which X
    /// differences are counted in: by default the quadratic elements of [`Deck::INTERFACE_SET`]
    /// along x ([`CcxRun::interface_mesh`]); `None` for a deck whose comparison counts none.
    ///
    /// # Errors
    /// As [`CcxRun::interface_mesh`].
    fn interface_mesh(run: &CcxRun) -> Result<Option<InterfaceMesh>, ResultsError> {
        run.interface_mesh().map(Some)
    }

    /// The columns of a CSV curve of FE results, as `compare`'s help lists them (`F_N,w_mm`):
    /// the curve [`Deck::csv_points`] reads.
    const CSV_CURVE: Curve;

    /// The FE points of a CSV curve (its columns are the problem's measurement format).
    ///
    /// # Errors
    /// A malformed row, a value out of its domain, or no row.
    fn csv_points(text: &str) -> Result<Vec<Self::FePoint>, ResultsError>;

    /// The FE `points` against the closed forms of `model` (X differences counted in `mesh`
    /// when it is known).
    ///
    /// # Errors
    /// As the problem's comparison: a fit of K_T that cannot be made is refused with why.
    fn compare(
        model: &Self::Model,
        points: &[Self::FePoint],
        mesh: Option<&InterfaceMesh>,
    ) -> Self::Compared;

    /// The deck of `model` that `request` describes (`deck ccx`, `bench ccx`): its load steps
    /// from the request's forces, checked, or the problem's own defaults.
    ///
    /// # Errors
    /// A request the problem refuses ([`DeckError::Flag`], [`DeckError::Usage`]), or a mesh too
    /// large ([`DeckError::TooLarge`]).
    fn write_deck(model: &Self::Model, request: &DeckRequest) -> Result<String, DeckError>;

    /// The deck's own largest load change per increment (the load's unit) at the model's stick
    /// slope, which `--increment` replaces: a ladder runs it and its half (`microslip suite`).
    /// `None` (the default) for a deck with no increments to halve (a linear single step).
    fn default_increment(_model: &Self::Model) -> Option<f64> {
        None
    }

    /// What the note on flags a deck's header overrides adds for the problem (the beams':
    /// `compare` shows both beam theories); empty for most.
    const OVERRIDES_NOTE: &'static str = "";

    /// The kinematics of the FE runs the closed form states an envelope for, the narrowest
    /// envelope first: the project's own decks' (linear geometry for most); the beams state one
    /// for `NLGEOM` (their decks') and a wider one for linear geometry (docs/theory.md (V2L)). A
    /// run of other kinematics is not judged against any ([`Deck::without_envelope`]); one that
    /// does not state its kinematics is judged against the last, the widest. A problem with
    /// several swaps in the right one in [`Deck::judge_kinematics`].
    const ENVELOPE_KINEMATICS: &'static [Kinematics] = &[Kinematics::Linear];

    /// `compared` with its envelope taken away (every bound "not calibrated"): for a run whose
    /// kinematics the envelope was not calibrated on.
    fn without_envelope(compared: &mut Self::Compared);

    /// `compared` (of `model`) judged as a run of `kinematics`: where the problem's continuum,
    /// which is small-strain, differs from converged runs of those kinematics by more than its
    /// tolerance, the continuum verdicts get the allowance the problem measured
    /// ([`ContinuumVerdict::with_allowance`](super::continuum_verdict::ContinuumVerdict::with_allowance);
    /// the beams' `NLGEOM`, docs/theory.md (BC4)). Nothing for most.
    fn judge_kinematics(
        _compared: &mut Self::Compared,
        _model: &Self::Model,
        _kinematics: Kinematics,
    ) {
    }

    /// The largest contact pressure a sound run of the problem reaches, as a multiple of the
    /// interface's nominal pressure (its `InterfaceData::pressure`, MPa), and where the contact
    /// locks beyond it: such a run is no judge ([`super::peak_pressure`]). `None` (the default):
    /// not stated, not checked (a press fit's hub edge and a lap joint's cover ends concentrate
    /// the pressure by amounts not measured here).
    const LOCKED_PRESSURE: Option<super::peak_pressure::LockedPressure> = None;

    /// The bundled preset `deck` and `bench` write when no `--preset` is given, and why: a case
    /// where the FE judge is sharp (the closed form within its tightest envelope, K_T resolved
    /// within a few % by the verdict against the continuum). `None`: the paper's preset
    /// ([`crate::problems::Description::paper_preset`]).
    const BENCH_PRESET: Option<(&'static str, &'static str)> = None;

    /// Why the problem has no CalculiX deck, where it has none (the twisted press fit: CAX
    /// elements carry no twist): its [`Deck::write_deck`] refuses with it, and the suite, which
    /// runs decks, leaves the problem out (or refuses it by name with this reason). `None` (the
    /// default): the problem's decks are written.
    const NO_DECK: Option<&'static str> = None;
}

/// What a deck is asked to be: the command line's `--loads`, `--mesh`, stick slope and
/// `--increment`, as the problem's [`Deck::write_deck`] reads them.
#[derive(Debug, Clone, Copy)]
pub struct DeckRequest<'a> {
    /// The forces of the load steps (N), as given, unchecked; `None`: the problem's defaults.
    pub loads: Option<&'a [f64]>,
    /// The mesh density.
    pub mesh: DeckMesh,
    /// The stick slope the deck gives the FE code.
    pub slope: StickSlope,
    /// The largest force change per increment (N), as given, unchecked.
    pub increment: Option<f64>,
}

/// Why a deck was not written, in the command line's words (the CLI maps each variant to its
/// own error of the same text; the Python face prints it as is).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DeckError {
    /// A flag's value refused, or a parameter the deck's geometry cannot hold (the cylinder's
    /// arc wider than its bodies): the flag or key, the value, and what is allowed.
    #[error("invalid {flag} = {}: {allowed}", crate::kernel::params::Compact(*value))]
    Flag {
        /// The flag (`--loads`).
        flag: &'static str,
        /// The value given.
        value: f64,
        /// What the flag accepts.
        allowed: String,
    },
    /// A flag the problem's deck does not take, and why.
    #[error("{0}")]
    Usage(&'static str),
    /// The mesh would be too large.
    #[error(transparent)]
    TooLarge(DeckTooLarge),
    /// The deck as written holds a number that is not finite: refused rather than written, so
    /// that no FE code is ever given one (a problem's deck writer missed a case of its inputs).
    #[error(
        "the deck would hold a non-finite number on its line {line} (`{text}`): not written; \
         its inputs are outside what the deck's geometry takes"
    )]
    NonFinite {
        /// The line (from 1).
        line: usize,
        /// The line's start, sanitized.
        text: String,
    },
}

/// The deck of `model` that `request` describes ([`Deck::write_deck`]), refused rather than
/// returned if any number in it is not finite: the one door both faces (the CLI's `deck` and
/// `bench`, Python's `deck()`) write decks through.
///
/// # Errors
/// As [`Deck::write_deck`], and [`DeckError::NonFinite`].
pub fn written_deck<P: Deck>(model: &P::Model, request: &DeckRequest) -> Result<String, DeckError> {
    let text = P::write_deck(model, request)?;
    match first_non_finite_line(&text) {
        Some((line, content)) => Err(DeckError::NonFinite {
            line,
            text: content
                .chars()
                .take(60)
                .flat_map(char::escape_debug)
                .collect(),
        }),
        None => Ok(text),
    }
}

/// The first line (from 1) of `deck` holding a field that reads as a non-finite number (`NaN`,
/// `inf`, `-inf`, as Rust writes them), with its text; comment lines (`**`) are prose and not
/// looked at.
fn first_non_finite_line(deck: &str) -> Option<(usize, &str)> {
    deck.lines().enumerate().find_map(|(i, line)| {
        if line.starts_with("**") {
            return None;
        }
        line.split(|c: char| c == ',' || c == '=' || c.is_whitespace())
            .map(|field| field.trim_start_matches(['+', '-']).to_ascii_lowercase())
            .any(|field| matches!(field.as_str(), "nan" | "inf" | "infinity"))
            .then_some((i + 1, line))
    })
}

#[cfg(test)]
mod finite_tests {
    use super::first_non_finite_line;

    /// Every way Rust writes a non-finite f64 in a data line is caught, with its line; words in
    /// comment lines and keywords are not numbers.
    #[test]
    fn a_non_finite_field_is_found_on_its_line() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for text in [format!("{bad}"), format!("{bad:e}"), format!("{bad:.10e}")] {
                let deck = format!("** infinite loads, NaN\n*NODE\n1, 0.0, {text}, 0.0\n");
                assert_eq!(
                    first_non_finite_line(&deck),
                    Some((3, format!("1, 0.0, {text}, 0.0").as_str())),
                    "{text}"
                );
            }
        }
        let fine =
            "** a NaN in prose\n*SURFACE INTERACTION, NAME=SI\n*NODE\n1, 1.0e0, -2.5e-3, 0\n";
        assert_eq!(first_non_finite_line(fine), None);
    }
}

impl DeckError {
    /// `value` of `flag` checked against `domain`, refused in the words of the domain.
    ///
    /// # Errors
    /// [`DeckError::Flag`] when `value` is outside `domain`.
    pub fn check(
        flag: &'static str,
        value: f64,
        domain: crate::kernel::params::Domain,
        unit: crate::kernel::params::Unit,
    ) -> Result<f64, DeckError> {
        domain
            .check(flag, value, unit)
            .map_err(|_| DeckError::Flag {
                flag,
                value,
                allowed: domain.refusal(value, unit),
            })
    }
}

impl DeckError {
    /// The loads of `--loads`, each made a load by `accept` (refused in the words of its range)
    /// and each above the one before: every problem's deck steps.
    ///
    /// # Errors
    /// [`DeckError::Flag`] naming the first load refused, or the first that does not increase.
    pub fn increasing_loads<L>(
        loads: &[f64],
        accept: impl Fn(f64) -> Result<L, crate::kernel::params::ParamError>,
    ) -> Result<Vec<L>, DeckError> {
        let mut out = Vec::with_capacity(loads.len());
        let mut last: Option<f64> = None;
        for &value in loads {
            let load = accept(value).map_err(|e| DeckError::Flag {
                flag: "--loads",
                value,
                allowed: e.allowed(),
            })?;
            if last.is_some_and(|l| l >= value) {
                return Err(DeckError::Flag {
                    flag: "--loads",
                    value,
                    allowed: "the loads must increase from one step to the next".to_string(),
                });
            }
            last = Some(value);
            out.push(load);
        }
        Ok(out)
    }
}

impl From<DeckTooLarge> for DeckError {
    fn from(e: DeckTooLarge) -> Self {
        DeckError::TooLarge(e)
    }
}

/// A [`Deck`] with its types erased: what a header and a run reader hold for any problem.
pub trait AnyDeck: Send + Sync {
    /// [`Deck::SOURCE`].
    fn source(&self) -> &'static str;
    /// [`Deck::INTERFACE_SET`].
    fn interface_set(&self) -> &'static str;
    /// The header of [`Deck::CSV_CURVE`]: `x,y`.
    fn csv_columns(&self) -> String;
    /// [`Deck::NO_DECK`].
    fn no_deck(&self) -> Option<&'static str>;
    /// [`Deck::expected`] for the header's model; `None` where the header's inputs do not
    /// validate (a header edited by hand) or are of another problem.
    fn expected(&self, header: &DeckHeader) -> Option<String>;
}

/// The [`AnyDeck`] of a [`Deck`] problem `P`.
struct DeckOf<P>(std::marker::PhantomData<P>);

impl<P: Deck> AnyDeck for DeckOf<P> {
    fn source(&self) -> &'static str {
        P::SOURCE
    }

    fn interface_set(&self) -> &'static str {
        P::INTERFACE_SET
    }

    fn csv_columns(&self) -> String {
        format!("{},{}", P::CSV_CURVE.x, P::CSV_CURVE.y)
    }

    fn no_deck(&self) -> Option<&'static str> {
        P::NO_DECK
    }

    fn expected(&self, header: &DeckHeader) -> Option<String> {
        let model = P::model(&P::from_inputs(&header.inputs)?).ok()?;
        Some(P::expected(&model, header))
    }
}

/// The bridge between a problem and its variant of [`AnyLoaded`]: written by the registry for
/// every problem ([`deck_face`]'s expansion), never by hand, as the core's `enum_bridges!` writes
/// a problem's bridges to `Inputs` and `Model`; what lets an erased face written once over `P`
/// (the screen's, `chart::panes`) read the points of any problem's run.
pub trait LoadedVariant: Deck {
    /// The points of `loaded`; `None` for another problem's.
    fn loaded(loaded: &AnyLoaded) -> Option<&Loaded<Self::FePoint>>;
}

/// Writes [`deck_face`], [`AnyLoaded`] and each problem's [`LoadedVariant`] from the registry: one
/// arm per problem, none by hand.
macro_rules! deck_faces {
    ($($(#[$doc:meta])* $variant:ident => $folder:ident :: $problem:ident),+ $(,)?) => {
        /// The [`Deck`] of the problem `kind`, erased.
        pub fn deck_face(kind: ModelKind) -> &'static dyn AnyDeck {
            match kind {
                $(ModelKind::$variant => &DeckOf::<crate::problems::$folder::$problem>(
                    std::marker::PhantomData,
                )),+
            }
        }

        /// FE points of any problem, read from one file: one variant per problem of the
        /// registry, holding that problem's [`Deck::FePoint`]s.
        #[derive(Debug, Clone, PartialEq)]
        pub enum AnyLoaded {
            $($(#[$doc])* $variant(Loaded<<crate::problems::$folder::$problem as Deck>::FePoint>)),+
        }

        impl AnyLoaded {
            /// The problem the points are of.
            pub fn kind(&self) -> ModelKind {
                match self {
                    $(AnyLoaded::$variant(_) => ModelKind::$variant),+
                }
            }

            /// The deck's header of `.dat` results; `None` for a CSV curve.
            pub fn header(&self) -> Option<&DeckHeader> {
                match self {
                    $(AnyLoaded::$variant(l) => l.header.as_ref()),+
                }
            }

            /// The points of `source`, read as the problem `kind`'s.
            pub(crate) fn read(
                kind: ModelKind,
                source: super::load::Source<'_>,
            ) -> Result<AnyLoaded, super::load::LoadError> {
                match kind {
                    $(ModelKind::$variant => source
                        .points::<crate::problems::$folder::$problem>()
                        .map(AnyLoaded::$variant)),+
                }
            }
        }

        $(impl LoadedVariant for crate::problems::$folder::$problem {
            fn loaded(loaded: &AnyLoaded) -> Option<&Loaded<Self::FePoint>> {
                match loaded {
                    AnyLoaded::$variant(points) => Some(points),
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }
        })+
    };
}

microslip_core::with_problems!(deck_faces);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::deck::DeckMesh;
    use crate::fe::header::StickSlope;

    /// Every problem of the registry has a deck face: a cited source, an interface set, and the
    /// expected values of its paper data set; a header of another problem's inputs has none.
    #[test]
    fn every_problem_has_a_deck_face() {
        for kind in ModelKind::ALL {
            let face = deck_face(kind);
            assert!(face.source().starts_with(" ("), "{kind}");
            assert!(!face.interface_set().is_empty(), "{kind}");
            let header = DeckHeader {
                inputs: kind.problem().paper_inputs(),
                loads: vec![1.0],
                mesh: DeckMesh::Coarse,
                stick_slope: StickSlope::Model,
                poisson: 0.3,
            };
            let expected = face.expected(&header).unwrap_or_default();
            assert!(expected.starts_with("** Expected"), "{kind}: {expected}");
            for other in ModelKind::ALL.into_iter().filter(|&k| k != kind) {
                assert_eq!(deck_face(other).expected(&header), None, "{kind} {other}");
            }
        }
    }
}
