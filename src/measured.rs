//! Reads measured twin-beam deflection curves from CSV text (header naming `F_N` and `w_mm`, and
//! optionally `sigma_mm`, the standard deviation of each w; one measurement per row, forces strictly
//! increasing) and names the file line of every problem.
//!
//! The text is read by the `csv` crate, so spreadsheet output works as is: a UTF-8 byte-order mark,
//! quoted fields, CRLF line ends, blank lines, `#` comment lines (indented or not), spaces
//! around fields and extra columns in any order (ignored).

use std::path::Path;

use thiserror::Error;

use crate::file::{Kinds, ReadError, Size, read_capped};
use crate::fit::{MIN_ROWS, Measured, Measurement};
use crate::kernel::params::{Compact, Domain, Unit};
use crate::problems::{ModelKind, Param};

/// A problem in a data file, with its 1-based line.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("line {line}: {problem}")]
pub struct DataError {
    /// Line number (1-based) in the file.
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

/// Largest measurement file read: 256 MiB. A million rows written with full precision take about
/// 40 MB, so this allows six million or more (a long, finely sampled test) while keeping the text and
/// the parsed points (16 bytes a row) well under a gigabyte; anything bigger is almost certainly not
/// a measured curve, and an endless stream (`/dev/zero`, a FIFO) stops here.
pub(crate) const MAX_DATA_SIZE: Size = Size(256 << 20);

/// Reads the text of a measurement file, refusing one larger than 256 MiB (`MAX_DATA_SIZE`); give the text
/// to [`parse_measured_curve_of`]. `kinds` says whether a stream (a FIFO, `<(...)`) is read ([`Kinds::AnyReadable`],
/// the command line) or refused ([`Kinds::RegularOnly`], the terminal UI, which must not wait).
///
/// # Errors
/// The file cannot be read, is not of an accepted kind, is larger than the cap, or is not UTF-8
/// text.
pub fn read_text(path: impl AsRef<Path>, kinds: Kinds) -> Result<String, ReadError> {
    read_capped(path.as_ref(), MAX_DATA_SIZE, "a measurement file", kinds)
}

/// The comment character: a line that starts with it is skipped.
const COMMENT: u8 = b'#';

fn error(line: usize, problem: impl Into<String>) -> DataError {
    DataError {
        line,
        problem: problem.into(),
    }
}

/// The 1-based line on which the record read from byte `offset` starts.
///
/// The `csv` reader's own position of a record is where the previous record ended, before the blank
/// and comment lines it skips; this skips them the same way (line ends, and whole lines that start
/// with the comment character) and counts the line breaks before the record's first byte. A lone
/// `\r` counts as a line break, as it does for the reader.
///
/// Records come in order, so the count continues from the previous record's start instead of from
/// the top of the file (which made reading a million rows quadratic).
struct LineCounter<'a> {
    bytes: &'a [u8],
    /// Where the previous count stopped.
    at: usize,
    /// Line breaks before `at`.
    breaks: usize,
}

impl<'a> LineCounter<'a> {
    fn new(bytes: &'a [u8]) -> Self {
        LineCounter {
            bytes,
            at: 0,
            breaks: 0,
        }
    }

    fn start_line(&mut self, offset: usize) -> usize {
        let bytes = self.bytes;
        let mut at = offset.min(bytes.len());
        loop {
            match bytes.get(at) {
                Some(b'\r' | b'\n') => at += 1,
                Some(&COMMENT) => {
                    at = bytes[at..]
                        .iter()
                        .position(|&b| b == b'\n')
                        .map_or(bytes.len(), |end| at + end + 1);
                }
                _ => break,
            }
        }
        if at < self.at {
            // Only an error can point back; count from the top then.
            (self.at, self.breaks) = (0, 0);
        }
        // `bytes[at]` is never a line end here, so looking past `at` for the `\n` of a `\r\n` pair
        // gives the same count as stopping at `at`.
        self.breaks += (self.at..at)
            .filter(|&i| {
                bytes[i] == b'\n' || (bytes[i] == b'\r' && bytes.get(i + 1) != Some(&b'\n'))
            })
            .count();
        self.at = at;
        1 + self.breaks
    }
}

/// Rows read between two progress reports of the readers.
const PROGRESS_ROWS: usize = 1 << 16;

/// The measured load-response curve of `kind` (what `d` and `--data` read and `f` fits), read
/// with its [`Fittable`](crate::problems::fittable::Fittable) columns (`F_N,w_mm` for the beams,
/// `F_N,Delta_mm` for the lap joint, `Q_N_per_mm,sa_mm` for the cylinder), telling `progress`
/// (bytes read, bytes in all) every few ten thousand rows and keeping the `sigma_mm` column when
/// there is one. Every problem is read the same way, from its own columns: there is no default
/// reader a problem could forget to replace and so read another's columns silently (issue 43).
///
/// # Errors
/// As [`parse_measured_columns_with_progress`]; for a problem with no measured curve to fit (no
/// load: the plate), an error that says so.
pub fn parse_measured_curve_of(
    kind: ModelKind,
    text: &str,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Measured, DataError> {
    let Some(fittable) = kind.problem().faces().fittable else {
        return Err(error(
            1,
            format!(
                "the {} has no measured load-response curve to fit",
                kind.description().title
            ),
        ));
    };
    parse_measured_columns_with_progress(
        text,
        (fittable.load_column(), fittable.load()),
        fittable.response_column(),
        progress,
    )
}

/// [`parse_measured_curve_of`] for any fittable problem: its load column (`F_N`, the
/// cylinder's `Q_N_per_mm`: [`crate::fit::Structure::load_column`]) and its `response` column
/// (`w_mm`, `Delta_mm`, `sa_mm`: [`crate::fit::Structure::response_column`]), with an optional
/// `sigma_mm`, so that a fit reads its problem's curve without naming the problem.
///
/// # Errors
/// As [`parse_measured_columns_with_progress`], with the problem's column names, the load's unit and
/// its domain.
pub fn parse_measured_response_with_progress(
    text: &str,
    structure: &crate::fit::Structure,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Measured, DataError> {
    parse_measured_columns_with_progress(
        text,
        (structure.load_column(), structure.load()),
        structure.response_column(),
        progress,
    )
}

/// The measured curve of the columns `load` (its header and the load parameter,
/// whose unit and domain its values are checked against) and `response`: what a problem's pane
/// reads a measured curve with when its columns are not the beams' (the cylinder's
/// `Q_N_per_mm,sa_mm`).
///
/// # Errors
/// As [`parse_curve`], with these columns, the load's unit and domain; and a sigma that is
/// missing, not a finite number or not > 0.
pub fn parse_measured_columns_with_progress(
    text: &str,
    (load_column, load): (&'static str, Param),
    response: &'static str,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Measured, DataError> {
    let spec = load.spec();
    let curve = Curve {
        x: load_column,
        y: response,
        // A line load (N/mm) is not a force: messages say which they range over.
        x_what: if spec.unit == Unit::Newton {
            "forces"
        } else {
            "loads"
        },
        x_domain: spec.domain,
        x_unit: spec.unit,
        min_rows: MIN_ROWS,
    };
    parse_measured_curve(text, &curve, progress)
}

fn parse_measured_curve(
    text: &str,
    curve: &Curve,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Measured, DataError> {
    let sigma_column = curve.sigma_column();
    let (points, sigma) = read_rows(text, curve, Some(&sigma_column), progress)?;
    Ok(Measured {
        points: points
            .into_iter()
            .map(|(force, deflection)| Measurement {
                force,
                response: deflection,
            })
            .collect(),
        sigma,
    })
}

/// The two columns of a curve file and what the first may hold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curve {
    /// Header of the abscissa column, e.g. `F_N`.
    pub x: &'static str,
    /// Header of the ordinate column, e.g. `w_mm`.
    pub y: &'static str,
    /// What the abscissae are, plural, for messages ("forces").
    pub x_what: &'static str,
    /// The values the abscissa may take, and their unit.
    pub x_domain: Domain,
    /// Unit of the abscissa.
    pub x_unit: Unit,
    /// Fewest rows accepted.
    pub min_rows: usize,
}

impl Curve {
    /// The header of its optional column of per-point standard deviations ([`sigma_column`]).
    pub(crate) fn sigma_column(&self) -> String {
        sigma_column(self.y)
    }
}

/// The header of the optional column of per-point standard deviations of the response column
/// `response`, in the response's unit: `sigma_` and the unit its header ends with (`sigma_mm`
/// for `w_mm`, the twisted fit's `sigma_rad` for `theta_rad`).
pub(crate) fn sigma_column(response: &str) -> String {
    format!("sigma_{}", column_unit(response))
}

/// The unit a response column's header ends with (`mm` of `w_mm`, `rad` of `theta_rad`).
pub(crate) fn column_unit(header: &str) -> &str {
    header.rsplit_once('_').map_or("mm", |(_, unit)| unit)
}

/// A measured twin-beam curve for the fit: `F_N,w_mm`, at least [`MIN_ROWS`] rows.
pub(crate) const MEASURED_DEFLECTION: Curve = Curve {
    x: "F_N",
    y: "w_mm",
    x_what: "forces",
    x_domain: Domain::FORCE,
    x_unit: Unit::Newton,
    min_rows: MIN_ROWS,
};

/// A measured lap-joint curve for the fit: `F_N,Delta_mm` (the force through the joint, the
/// joint displacement), at least [`MIN_ROWS`] rows.
pub(crate) const MEASURED_JOINT_DISPLACEMENT: Curve = Curve {
    y: "Delta_mm",
    ..MEASURED_DEFLECTION
};

/// The pairs of any [`Curve`] read from a CSV: (abscissa, ordinate) pairs, abscissae strictly increasing.
///
/// # Errors
/// A [`DataError`] with the 1-based line of the file: no header, a missing column, a value that
/// is missing or not a finite number, an abscissa outside its domain or not above the previous
/// one, or fewer rows than the curve needs.
pub fn parse_curve(text: &str, curve: &Curve) -> Result<Vec<(f64, f64)>, DataError> {
    parse_curve_with_progress(text, curve, &mut |_, _| {})
}

fn parse_curve_with_progress(
    text: &str,
    curve: &Curve,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<(f64, f64)>, DataError> {
    Ok(read_rows(text, curve, None, progress)?.0)
}

/// The (abscissa, ordinate) pairs of a curve file, and the values of an optional column.
type Rows = (Vec<(f64, f64)>, Option<Vec<f64>>);

/// The (abscissa, ordinate) pairs of a curve file and, when the header names the optional column
/// `spread` (a standard deviation of the ordinate), its values.
fn read_rows(
    text: &str,
    curve: &Curve,
    spread: Option<&str>,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Rows, DataError> {
    // The reader would skip the mark as well; removing it here keeps byte offsets and lines aligned.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let bytes = text.as_bytes();
    let mut lines = LineCounter::new(bytes);
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(COMMENT))
        .trim(csv::Trim::All)
        .from_reader(bytes);
    // (line, record) of every non-blank record; a line of spaces is a record of one empty field.
    let mut records = std::iter::from_fn(move || {
        let mut record = csv::StringRecord::new();
        match reader.read_record(&mut record) {
            Ok(true) => {
                let offset = record.position().map_or(0, |p| p.byte());
                Some(Ok((lines.start_line(offset as usize), record)))
            }
            Ok(false) => None,
            Err(e) => {
                let offset = e.position().map_or(0, |p| p.byte());
                Some(Err(error(lines.start_line(offset as usize), e.to_string())))
            }
        }
    })
    // Also skipped: comment lines indented with spaces, which the reader's own comment rule (a `#`
    // in the first column) does not catch.
    .filter(|r| {
        !matches!(r, Ok((_, record))
            if (record.len() == 1 && record[0].is_empty())
                || record.get(0).is_some_and(|first| first.starts_with('#')))
    });
    let Some((header_line, header)) = records.next().transpose()? else {
        return Err(error(
            1,
            format!(
                "empty file: expected a header naming the columns {} and {}",
                curve.x, curve.y
            ),
        ));
    };
    let columns: Vec<&str> = header.iter().collect();
    let find = |name: &str| {
        columns.iter().position(|c| *c == name).ok_or_else(|| {
            error(
                header_line,
                format!(
                    "missing column '{name}' in the header (found: {}); {} and {} are required",
                    columns.join(", "),
                    curve.x,
                    curve.y
                ),
            )
        })
    };
    // A sweep table of microslip itself (`sweep beam`, `sweep plate`) names the regularized
    // response `w_regularized_mm` / `u_regularized_mm` (the twisted fit's `theta_regularized_rad`):
    // read as the measured column when there is no `w_mm` / `u_mm`, so a sweep loads without
    // renaming columns.
    let sweep_column = match curve.y.rsplit_once('_') {
        Some((name, unit)) => format!("{name}_regularized_{unit}"),
        None => format!("{}_regularized", curve.y),
    };
    let deflection_column = match columns.iter().position(|c| *c == sweep_column.as_str()) {
        Some(i) if !columns.contains(&curve.y) => i,
        _ => find(curve.y)?,
    };
    let force_column = find(curve.x)?;
    let spread_column =
        spread.and_then(|name| Some((columns.iter().position(|c| *c == name)?, name)));
    // A column named twice: which one is meant cannot be known (it used to take the first).
    for name in [curve.x, curve.y, sweep_column.as_str()]
        .into_iter()
        .chain(spread)
    {
        if columns.iter().filter(|c| **c == name).count() > 1 {
            return Err(error(
                header_line,
                format!("column '{name}' appears more than once in the header; keep one"),
            ));
        }
    }
    let mut data: Vec<(f64, f64)> = Vec::new();
    let mut spreads = spread_column.map(|_| Vec::new());
    let mut last_line = header_line;
    for (row, record) in records.enumerate() {
        let (line, fields) = record?;
        last_line = line;
        if row % PROGRESS_ROWS == 0 {
            let at = fields.position().map_or(0, |p| p.byte() as usize);
            progress(at, text.len());
        }
        let value = |column: usize, name: &str| -> Result<f64, DataError> {
            let text = fields.get(column).unwrap_or("");
            match text.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ if text.is_empty() => Err(error(line, format!("no value in column {name}"))),
                _ => Err(error(
                    line,
                    format!("'{text}' in column {name} is not a finite number"),
                )),
            }
        };
        let force = value(force_column, curve.x)?;
        let deflection = value(deflection_column, curve.y)?;
        if !curve.x_domain.contains(force) {
            let problem = if force < 0.0 {
                "is negative"
            } else if force < curve.x_domain.min() {
                "is too small"
            } else {
                "is too large"
            };
            return Err(error(
                line,
                format!(
                    "{} = {} {problem}; {} {}",
                    curve.x,
                    Compact(force),
                    curve.x_what,
                    curve.x_domain.describe(curve.x_unit)
                ),
            ));
        }
        if let Some(&(previous, _)) = data.last()
            && force <= previous
        {
            return Err(error(
                line,
                format!(
                    "{} = {} is not above the previous {}: {} must increase (one loading branch)",
                    curve.x,
                    Compact(force),
                    Compact(previous),
                    curve.x_what
                ),
            ));
        }
        if !Domain::DISPLACEMENT.contains(deflection) {
            return Err(error(
                line,
                format!(
                    "{} = {} is not a displacement: {}",
                    curve.y,
                    Compact(deflection),
                    Domain::DISPLACEMENT.describe(Unit::Millimetre)
                ),
            ));
        }
        if let (Some((column, name)), Some(spreads)) = (spread_column, spreads.as_mut()) {
            let sigma = value(column, name)?;
            if sigma <= 0.0 {
                return Err(error(
                    line,
                    format!(
                        "{name} = {} is not a standard deviation: must be > 0",
                        Compact(sigma)
                    ),
                ));
            }
            spreads.push(sigma);
        }
        data.push((force, deflection));
    }
    if data.iter().any(|p| p.1 != 0.0) && data.iter().all(|p| p.1 <= 0.0) {
        return Err(error(
            header_line,
            format!(
                "every {} is negative or zero: microslip counts displacements positive in the \
                 direction of the load (F pushes the tip, P squeezes the plate outward, F pulls \
                 the lap joint's inner plate out); many FE \
                 codes report them along -y: flip the sign of the column",
                curve.y
            ),
        ));
    }
    if data.len() < curve.min_rows {
        return Err(error(
            last_line,
            format!(
                "only {} data rows; at least {} are needed",
                data.len(),
                curve.min_rows
            ),
        ));
    }
    Ok((data, spreads))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The beams' columns (`F_N,w_mm`) read whole: the reader every case below exercises.
    fn parse(text: &str) -> Result<Vec<Measurement>, DataError> {
        parse_with_progress(text, &mut |_, _| {})
    }

    fn parse_with_progress(
        text: &str,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Vec<Measurement>, DataError> {
        Ok(parse_measured_with_progress(text, progress)?.points)
    }

    /// The beams' curve with its sigma column.
    fn parse_measured_with_progress(
        text: &str,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Measured, DataError> {
        parse_measured_curve(text, &MEASURED_DEFLECTION, progress)
    }

    /// The lap joint's curve with its sigma column.
    fn parse_measured_joint_with_progress(
        text: &str,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Measured, DataError> {
        parse_measured_curve(text, &MEASURED_JOINT_DISPLACEMENT, progress)
    }

    /// Read by its problem's columns, a fittable problem's curve is what its own reader gives;
    /// every fittable problem reads a file headed with its own load and response columns and
    /// refuses another's, naming the column it expected.
    #[test]
    fn a_curve_read_by_its_problem_s_columns_is_its_problem_s() {
        use crate::fit::Structure;
        use crate::problems::ModelKind;
        use crate::problems::inputs::Inputs;
        let structure = |kind: ModelKind| Structure::of(&Inputs::paper(kind).validate().unwrap());
        let beam = "F_N,w_mm,sigma_mm\n10,0.1,0.01\n20,0.2,0.01\n30,0.3,0.01\n";
        let joint = "F_N,Delta_regularized_mm\n10,0.1\n20,0.2\n30,0.3\n";
        let by = |text, kind| {
            parse_measured_response_with_progress(text, &structure(kind).unwrap(), &mut |_, _| {})
        };
        assert_eq!(
            by(beam, ModelKind::Beam),
            parse_measured_with_progress(beam, &mut |_, _| {})
        );
        assert_eq!(
            by(joint, ModelKind::Lap),
            parse_measured_joint_with_progress(joint, &mut |_, _| {})
        );
        // What `d` and `--data` read is the same curve, for every problem; the plate has none.
        for kind in ModelKind::ALL {
            let read = parse_measured_curve_of(kind, beam, &mut |_, _| {});
            match structure(kind) {
                Some(s) => assert_eq!(
                    read,
                    parse_measured_response_with_progress(beam, &s, &mut |_, _| {}),
                    "{kind}"
                ),
                None => assert!(
                    read.unwrap_err()
                        .to_string()
                        .contains("has no measured load-response curve"),
                    "{kind}"
                ),
            }
        }
        let fittable = ModelKind::ALL.into_iter().filter_map(structure);
        for mine in fittable.clone() {
            let (load, response) = (mine.load_column(), mine.response_column());
            let text = format!("{load},{response}\n10,0.1\n20,0.2\n30,0.3\n");
            let read = parse_measured_response_with_progress(&text, &mine, &mut |_, _| {});
            assert_eq!(read.unwrap().points.len(), 3, "{text}");
            // Another problem's columns, where they differ (the lap joint and the press fit
            // both read Delta against F: either reads the other's curve).
            let others = fittable.clone().filter(|s| {
                s.kind() != mine.kind()
                    && (s.load_column(), s.response_column()) != (load, response)
            });
            for theirs in others {
                let message = parse_measured_response_with_progress(&text, &theirs, &mut |_, _| {})
                    .unwrap_err()
                    .to_string();
                let (load, response) = (theirs.load_column(), theirs.response_column());
                assert!(
                    message.starts_with("line 1: missing column '")
                        && message.ends_with(&format!("{load} and {response} are required")),
                    "{message}"
                );
            }
        }
    }

    #[test]
    fn a_sweep_table_of_microslip_loads_as_measurements() {
        let text = "F_N,w_coulomb_mm,w_regularized_mm,X_mm,regime_coulomb,regime_regularized\n\
                    0.0,0.0,0.0,200.0,unloaded,unloaded\n\
                    50.0,0.01,0.012,200.0,stick,microslip\n\
                    100.0,0.038,0.0383,17.3,macroslip,microslip+macroslip\n";
        let data = parse(text).unwrap();
        assert_eq!(data.len(), 3);
        assert_eq!((data[1].force, data[1].response), (50.0, 0.012));
        // A measured column wins over the sweep's.
        let both = "F_N,w_regularized_mm,w_mm\n1,9,0.1\n2,9,0.2\n3,9,0.3\n";
        assert_eq!(parse(both).unwrap()[0].response, 0.1);
    }

    /// A response in another unit than mm (the twisted fit's theta in rad): its sweep column
    /// `theta_regularized_rad` is read as `theta_rad`, and its sigma column is `sigma_rad`.
    #[test]
    fn a_sweep_column_and_a_sigma_column_keep_the_response_s_unit() {
        let curve = Curve {
            x: "T_Nmm",
            y: "theta_rad",
            x_what: "torques",
            x_domain: Domain::FORCE,
            x_unit: Unit::NewtonMillimetre,
            min_rows: 1,
        };
        assert_eq!(curve.sigma_column(), "sigma_rad");
        let sweep = "T_Nmm,theta_coulomb_rad,theta_regularized_rad\n100,1e-6,2e-6\n";
        let read = parse_curve(sweep, &curve).unwrap();
        assert_eq!(read, [(100.0, 2e-6)]);
    }

    #[test]
    fn a_sigma_column_is_read_and_checked_like_the_others() {
        let text = "sigma_mm,F_N,w_mm\n0.001,10,0.1\n0.002,20,0.2\n0.003,30,0.3\n";
        let measured = parse_measured_with_progress(text, &mut |_, _| {}).unwrap();
        assert_eq!(measured.points, EXPECTED);
        assert_eq!(measured.sigma, Some(vec![0.001, 0.002, 0.003]));
        assert_eq!(parse(text).unwrap(), EXPECTED);
        let without =
            parse_measured_with_progress("F_N,w_mm\n10,0.1\n20,0.2\n30,0.3\n", &mut |_, _| {});
        assert_eq!(without.unwrap().sigma, None);
        for (text, expected) in [
            (
                "F_N,w_mm,sigma_mm\n10,0.1,0.001\n20,0.2,0\n30,0.3,1\n",
                "line 3: sigma_mm = 0 is not a standard deviation: must be > 0",
            ),
            (
                "F_N,w_mm,sigma_mm\n10,0.1,-2e-3\n",
                "line 2: sigma_mm = -0.002 is not a standard deviation: must be > 0",
            ),
            (
                "F_N,w_mm,sigma_mm\n10,0.1,inf\n",
                "line 2: 'inf' in column sigma_mm is not a finite number",
            ),
            (
                "F_N,w_mm,sigma_mm\n10,0.1\n",
                "line 2: no value in column sigma_mm",
            ),
            (
                "F_N,w_mm,sigma_mm,sigma_mm\n10,0.1,1,1\n",
                "line 1: column 'sigma_mm' appears more than once in the header; keep one",
            ),
        ] {
            // The plain reader checks the column too: a file means the same to every reader.
            assert_eq!(parse(text).unwrap_err().to_string(), expected);
        }
    }

    #[test]
    fn reads_the_two_columns_in_any_position_and_ignores_the_rest() {
        let data = parse("# bench 3\nrun,w_mm,F_N\n1,0.01,20\n1,0.02,40\n\n1,0.03,60\n").unwrap();
        assert_eq!(data.len(), 3);
        assert_eq!(
            data[2],
            Measurement {
                force: 60.0,
                response: 0.03
            }
        );
    }

    /// The three measurements most tests below expect, whatever the file's dressing.
    const EXPECTED: [Measurement; 3] = [
        Measurement {
            force: 10.0,
            response: 0.1,
        },
        Measurement {
            force: 20.0,
            response: 0.2,
        },
        Measurement {
            force: 30.0,
            response: 0.3,
        },
    ];

    #[test]
    fn a_byte_order_mark_is_not_part_of_the_first_column_name() {
        let text = "\u{feff}F_N,w_mm\n10,0.1\n20,0.2\n30,0.3\n";
        assert_eq!(parse(text).unwrap(), EXPECTED);
        // Nor does it shift the lines: the bad value is on the fourth line.
        let message = parse("\u{feff}F_N,w_mm\n10,0.1\n20,0.2\n30,x\n")
            .unwrap_err()
            .to_string();
        assert_eq!(message, "line 4: 'x' in column w_mm is not a finite number");
        let message = parse("\u{feff}# exported\nF_N,w_mm\n10,x\n")
            .unwrap_err()
            .to_string();
        assert_eq!(message, "line 3: 'x' in column w_mm is not a finite number");
    }

    #[test]
    fn quoted_headers_and_values_are_unquoted() {
        let text = "\"run\",\"F_N\",\"w_mm\"\n\"a, b\",10,0.1\n\"c\",\"20\",\"0.2\"\nd,30,0.3\n";
        assert_eq!(parse(text).unwrap(), EXPECTED);
        let message = parse("\"F_N\",\"deflection\"\n1,2\n")
            .unwrap_err()
            .to_string();
        assert!(
            message.starts_with(
                "line 1: missing column 'w_mm' in the header (found: F_N, deflection)"
            ),
            "{message}"
        );
    }

    #[test]
    fn comment_and_blank_lines_anywhere_keep_the_line_numbers() {
        let text = "# bench 3\n\nF_N,w_mm\n10,0.1\n# gauge reset\n\n20,0.2\n   \n30,0.3\n# end\n";
        assert_eq!(parse(text).unwrap(), EXPECTED);
        // Lines: 1 comment, 2 blank, 3 header, 4 data, 5 comment, 6 blank, 7 data, 8 comment, 9 bad.
        let text = "# bench 3\n\nF_N,w_mm\n10,0.1\n# gauge reset\n\n20,0.2\n# x\n30,abc\n";
        assert_eq!(
            parse(text).unwrap_err().to_string(),
            "line 9: 'abc' in column w_mm is not a finite number"
        );
        // A missing column is reported on the header's own line, after the comments.
        let text = "# a\n# b\n\nF_N,w\n";
        assert!(
            parse(text)
                .unwrap_err()
                .to_string()
                .starts_with("line 4: missing column 'w_mm'")
        );
        // Too few rows: the line of the last row read.
        let text = "F_N,w_mm\n10,0.1\n# c\n20,0.2\n\n# d\n";
        assert_eq!(
            parse(text).unwrap_err().to_string(),
            "line 4: only 2 data rows; at least 3 are needed"
        );
        // Indented comments are comments too (as before the csv crate), lines still counted.
        let text = "  # bench 3\nF_N,w_mm\n10,0.1\n\t# reset, again\n20,0.2\n  # x\n30,abc\n";
        assert_eq!(
            parse(text).unwrap_err().to_string(),
            "line 7: 'abc' in column w_mm is not a finite number"
        );
        // Only comments and blank lines: no header.
        assert!(
            parse("# nothing\n\n# here\n")
                .unwrap_err()
                .to_string()
                .starts_with("line 1: empty file")
        );
    }

    #[test]
    fn spaces_around_fields_and_names_are_ignored() {
        let text = " F_N , w_mm \n 10 , 0.1 \n20,   0.2\t\n  30,0.3   \n";
        assert_eq!(parse(text).unwrap(), EXPECTED);
        let message = parse("F_N , w_mm\n10 , 0.1\n20 ,  \n")
            .unwrap_err()
            .to_string();
        assert_eq!(message, "line 3: no value in column w_mm");
    }

    #[test]
    fn crlf_files_read_like_lf_files_and_count_lines_the_same() {
        let text = "F_N,w_mm\r\n10,0.1\r\n20,0.2\r\n30,0.3\r\n";
        assert_eq!(parse(text).unwrap(), EXPECTED);
        let text = "# c\r\nF_N,w_mm\r\n10,0.1\r\n\r\n20,0.2\r\n30,abc\r\n";
        assert_eq!(
            parse(text).unwrap_err().to_string(),
            "line 6: 'abc' in column w_mm is not a finite number"
        );
        // Old Mac line ends (a lone CR) are line breaks too.
        assert_eq!(
            parse("F_N,w_mm\r10,0.1\r20,x\r").unwrap_err().to_string(),
            "line 3: 'x' in column w_mm is not a finite number"
        );
    }

    #[test]
    fn long_files_report_progress_in_bytes() {
        let mut text = String::from("F_N,w_mm\n");
        for i in 1..=200_000 {
            text.push_str(&format!("{i},0.1\n"));
        }
        let mut reports = Vec::new();
        let data =
            parse_with_progress(&text, &mut |done, total| reports.push((done, total))).unwrap();
        assert_eq!(data.len(), 200_000);
        // Rows 0, 65 536, 131 072 and 196 608.
        assert_eq!(reports.len(), 4, "{reports:?}");
        assert!(
            reports
                .iter()
                .all(|&(done, total)| done < total && total == text.len())
        );
        assert!(reports.windows(2).all(|w| w[0].0 < w[1].0), "{reports:?}");
    }

    #[test]
    fn line_numbers_stay_right_deep_into_a_long_file() {
        // 60 000 rows with comments and CRLF line ends: counting from the top of the file for
        // every record (as before) took minutes here; counting on from the last record, a moment.
        let mut text = String::from("# long\r\nF_N,w_mm\r\n");
        for i in 1..=60_000 {
            text.push_str(&format!("{i},0.1\r\n"));
            if i % 1000 == 0 {
                text.push_str("# block\r\n\r\n");
            }
        }
        assert_eq!(parse(&text).unwrap().len(), 60_000);
        // 2 header lines + 60 000 rows + 2 lines per 1000 rows = line 60 122; the next is bad.
        text.push_str("60001,x\r\n");
        assert_eq!(
            parse(&text).unwrap_err().to_string(),
            "line 60123: 'x' in column w_mm is not a finite number"
        );
    }

    #[test]
    fn measurement_files_above_the_cap_are_refused_without_reading_them() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("huge.csv");
        // Sparse: no disk space used, and the size alone refuses it.
        let file = std::fs::File::create(&path).unwrap();
        file.set_len(MAX_DATA_SIZE.0 + 1).unwrap();
        assert_eq!(
            read_text(&path, Kinds::AnyReadable)
                .unwrap_err()
                .to_string(),
            "file is larger than the 256 MiB limit for a measurement file"
        );
        std::fs::write(&path, "F_N,w_mm\n1,2\n").unwrap();
        assert_eq!(
            read_text(&path, Kinds::AnyReadable).unwrap(),
            "F_N,w_mm\n1,2\n"
        );
    }

    #[test]
    fn a_column_named_twice_and_an_all_negative_curve_are_refused_with_a_reason() {
        assert_eq!(
            parse("F_N,w_mm,w_mm\n1,1,2\n2,2,3\n3,3,4\n")
                .unwrap_err()
                .to_string(),
            "line 1: column 'w_mm' appears more than once in the header; keep one"
        );
        let negative = parse("F_N,w_mm\n0,0\n1,-1\n2,-2\n3,-3\n")
            .unwrap_err()
            .to_string();
        assert!(
            negative.contains("flip the sign of the column"),
            "{negative}"
        );
        // One negative point among positive ones is data, not a sign convention.
        assert!(parse("F_N,w_mm\n0,-1e-9\n1,1\n2,2\n").is_ok());
    }

    /// 1e200 in a result gave a 200-digit percentage, 1.7e308 "inf": refused with the range.
    #[test]
    fn a_displacement_beyond_any_structure_is_refused_with_its_line_and_range() {
        let text = "F_N,w_mm\n1,0.5\n2,1e200\n3,1\n";
        assert_eq!(
            parse(text).unwrap_err().to_string(),
            "line 3: w_mm = 1e200 is not a displacement: must be in [-1e6, 1e6] mm"
        );
        assert!(parse("F_N,w_mm\n1,-2\n2,-1e6\n3,1e6\n").is_ok());
    }

    #[test]
    fn every_malformation_names_its_line() {
        let cases = [
            (
                "F_N,deflection\n1,2\n",
                "line 1: missing column 'w_mm' in the header (found: F_N, deflection)",
            ),
            (
                "F_N,w_mm\n10,0.1\n20,abc\n",
                "line 3: 'abc' in column w_mm is not a finite number",
            ),
            ("F_N,w_mm\n10,0.1\n20\n", "line 3: no value in column w_mm"),
            (
                "F_N,w_mm\n10,0.1\n30,0.2\n20,0.3\n",
                "line 4: F_N = 20 is not above the previous 30",
            ),
            (
                "F_N,w_mm\n10,0.1\n20,0.2\n",
                "line 3: only 2 data rows; at least 3 are needed",
            ),
            ("F_N,w_mm\n-1,0.1\n", "line 2: F_N = -1 is negative"),
            (
                "F_N,w_mm\n10,0.1\n2e12,0.2\n",
                "line 3: F_N = 2e12 is too large; forces must be in [0, 1e12] N",
            ),
            (
                "F_N,w_mm\n10,NaN\n",
                "line 2: 'NaN' in column w_mm is not a finite number",
            ),
            ("", "line 1: empty file"),
        ];
        for (text, expected) in cases {
            let message = parse(text).unwrap_err().to_string();
            assert!(
                message.starts_with(expected),
                "{message:?} should start with {expected:?}"
            );
        }
    }
}
