//! Measured twin-beam deflection curves: a CSV text with a header naming `F_N` and `w_mm` (other
//! columns are ignored), one measurement per row, forces strictly increasing. Every error names the
//! line, so a user can go straight to it.

use thiserror::Error;

/// One measurement: tip force (N) and tip deflection (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Tip force on each beam (N).
    pub force: f64,
    /// Tip deflection (mm).
    pub deflection: f64,
}

/// A problem in a data file, with its 1-based line.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("line {line}: {problem}")]
pub struct DataError {
    /// Line number (1-based) in the file.
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

/// Fewest rows a fit accepts: two parameters need at least one more point than parameters.
pub const MIN_ROWS: usize = 3;

fn error(line: usize, problem: impl Into<String>) -> DataError {
    DataError {
        line,
        problem: problem.into(),
    }
}

/// Parses the text of a measurement CSV.
pub fn parse(text: &str) -> Result<Vec<Measurement>, DataError> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((header_line, header)) = lines.next() else {
        return Err(error(
            1,
            "empty file: expected a header naming the columns F_N and w_mm",
        ));
    };
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let find = |name: &str| {
        columns.iter().position(|c| *c == name).ok_or_else(|| {
            error(
                header_line,
                format!(
                    "missing column '{name}' in the header (found: {}); F_N and w_mm are required",
                    columns.join(", ")
                ),
            )
        })
    };
    let (force_column, deflection_column) = (find("F_N")?, find("w_mm")?);
    let mut data: Vec<Measurement> = Vec::new();
    let mut last_line = header_line;
    for (line, row) in lines {
        last_line = line;
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        let value = |column: usize, name: &str| -> Result<f64, DataError> {
            let text = fields.get(column).copied().unwrap_or("");
            match text.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ if text.is_empty() => Err(error(line, format!("no value in column {name}"))),
                _ => Err(error(
                    line,
                    format!("'{text}' in column {name} is not a finite number"),
                )),
            }
        };
        let force = value(force_column, "F_N")?;
        let deflection = value(deflection_column, "w_mm")?;
        if force < 0.0 {
            return Err(error(
                line,
                format!("F_N = {force} is negative; forces must be >= 0 N"),
            ));
        }
        if let Some(previous) = data.last()
            && force <= previous.force
        {
            return Err(error(
                line,
                format!(
                    "F_N = {force} is not above the previous {}: forces must increase (one loading branch)",
                    previous.force
                ),
            ));
        }
        data.push(Measurement { force, deflection });
    }
    if data.len() < MIN_ROWS {
        return Err(error(
            last_line,
            format!(
                "only {} data rows; at least {MIN_ROWS} are needed",
                data.len()
            ),
        ));
    }
    Ok(data)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_two_columns_in_any_position_and_ignores_the_rest() {
        let data = parse("# bench 3\nrun,w_mm,F_N\n1,0.01,20\n1,0.02,40\n\n1,0.03,60\n").unwrap();
        assert_eq!(data.len(), 3);
        assert_eq!(
            data[2],
            Measurement {
                force: 60.0,
                deflection: 0.03
            }
        );
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
