//! Where tables and figures go: stdout or a file that is never clobbered, and the series a chart keeps.

use super::*;

/// A sweep over `param`: its column (named with its unit, `mu`, `L_mm`) first, then the rows.
pub(super) fn write_varied<R: serde::Serialize + Default>(
    out: &mut impl Write,
    format: TableFormat,
    param: Param,
    rows: impl Iterator<Item = (f64, R)>,
) -> io::Result<()> {
    write_table_after(
        out,
        format,
        &json::suffixed(param.name(), param.unit()),
        rows,
    )
}

/// A force range error, named by the flags `--from`, `--to`, `--points`.
pub(super) fn force_range_error(error: RangeError) -> CliError {
    CliError::Range {
        error,
        flags: ["--from", "--to", "--points"],
    }
}

/// Refuses an output file that is one this command reads (`deck ccx lap --preset p.toml -o
/// p.toml` replaced the preset it was reading with the deck): `reads` are the command's input
/// files, `-o` is compared with each as a file ([`crate::file::same_file`]), not as text. Checked
/// before anything is computed or written.
pub(super) fn refuse_overwriting_an_input(
    output: Option<&std::path::Path>,
    reads: &[(&str, PathBuf)],
) -> Result<(), CliError> {
    let Some(output) = output else {
        return Ok(());
    };
    for (flag, read) in reads {
        if crate::file::same_file(output, read) {
            return Err(CliError::Invalid(format!(
                "-o {}: that is the file this command reads ({flag} {}); write to another file",
                output.display(),
                read.display()
            )));
        }
    }
    Ok(())
}

/// Writes `bytes` to `path` ([`crate::file::write_atomic`]: a regular file replaced atomically with
/// its mode kept, a device or FIFO written through, a link followed, a read-only file refused), or
/// to `out` when there is no path or it is `-` or `/dev/stdout` (the program's own standard output,
/// whatever it is redirected to, is written as a stream, never replaced).
pub(super) fn write_output(
    out: &mut impl Write,
    path: Option<&std::path::Path>,
    bytes: &[u8],
) -> Result<(), CliError> {
    let to_stdout = |p: &std::path::Path| {
        p == std::path::Path::new("-") || p == std::path::Path::new("/dev/stdout")
    };
    match path {
        Some(path) if !to_stdout(path) => {
            crate::file::write_atomic(path, bytes, true).map_err(|e| CliError::Data {
                path: path.display().to_string(),
                reason: e.to_string(),
            })
        }
        _ => Ok(out.write_all(bytes)?),
    }
}

/// Resolves the preset (default: the paper's data set of `wanted`), applies `--set`, validates.
/// `command` (as typed after `microslip`) names the command when the preset is of another problem.
/// The roles of `plot --series` (None: not given), without the cursor under `--no-cursor`.
pub(super) fn shown_roles(
    series: Option<&str>,
    no_cursor: bool,
) -> Result<Option<Vec<SeriesRole>>, CliError> {
    let Some(list) = series else {
        return Ok(None);
    };
    let allowed: Vec<&str> = SeriesRole::CHART_ROLES
        .iter()
        .filter_map(|r| r.key())
        .collect();
    let mut roles = Vec::new();
    for key in list.split(',').map(str::trim) {
        let role = SeriesRole::from_key(key).ok_or_else(|| {
            CliError::Invalid(format!(
                "--series {list}: unknown series '{key}' (allowed: {})",
                allowed.join(", ")
            ))
        })?;
        if role == SeriesRole::Cursor && no_cursor {
            return Err(CliError::Invalid(format!(
                "--series {list} and --no-cursor: the one asks for the cursor, the other leaves it out"
            )));
        }
        if !roles.contains(&role) {
            roles.push(role);
        }
    }
    Ok(Some(roles))
}

/// `plot` with only the series of `roles` (and any pins); a role the chart does not have is
/// refused, naming those it has, and so is a selection that leaves nothing but the cursor.
pub(super) fn keep_roles(
    plot: &mut crate::chart::Plot,
    roles: &[SeriesRole],
    chart: &str,
) -> Result<(), CliError> {
    let present: Vec<SeriesRole> = plot.series.iter().map(|s| s.role).collect();
    if let Some(missing) = roles.iter().find(|r| !present.contains(r)) {
        let keys: Vec<&str> = present.iter().filter_map(|r| r.key()).collect();
        let hint = match missing {
            SeriesRole::FiniteElements => " (fe needs --fe)",
            _ => "",
        };
        return Err(CliError::Invalid(format!(
            "--series: chart {chart} has no {} series{hint}; it has: {}",
            missing.key().unwrap_or("?"),
            keys.join(", ")
        )));
    }
    if roles.iter().all(|&r| r == SeriesRole::Cursor) {
        return Err(CliError::Invalid(
            "--series cursor: nothing to draw but the cursor; add a curve (current, coulomb, ...)"
                .to_string(),
        ));
    }
    plot.series.retain(|s| roles.contains(&s.role));
    Ok(())
}

/// A chart's points as CSV (the same rows as the TUI's export).
pub(super) fn chart_csv(plot: &crate::chart::Plot) -> Result<Vec<u8>, CliError> {
    let mut bytes = Vec::new();
    write_table(&mut bytes, TableFormat::Csv, report::rows::chart_rows(plot))?;
    Ok(bytes)
}
