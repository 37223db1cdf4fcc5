//! The headless command line: reports, sweeps and presets for scripts and FE benchmarking.
//!
//! A thin layer: presets and `--set` come from [`crate::preset`], numbers from [`crate::study::curves`],
//! formats from [`crate::report`]; this file only parses flags, checks the flags that are not model
//! parameters, and names flags in error messages. Errors are one line on stderr; the exit codes
//! follow one table ([`CliError::exit_code`]): 1 when a command ran and its answer is "no" (`check`,
//! `verify`, a `solve` with no root) or could not be computed, 2 for usage or input problems, 3
//! when the external solver failed, 128 + N after signal N. Nothing goes to stdout before the inputs
//! are known to be valid, so a failed run never leaves half a table behind.

use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Parser, ValueEnum};
use thiserror::Error;

use crate::chart::view::AnyChart;
use crate::chart::{SeriesRole, YMode};
use crate::fe;
use crate::fe::deck::DeckMesh;
use crate::fe::header::StickSlope;
use crate::fe::load::LoadError;
use crate::fit::{self, FitError};
use crate::kernel::params::{Compact, Domain, ParamError, Unit, parse_number};
use crate::numeric::{MeshDensity, NumericError};
use crate::preset::{self, Preset, PresetError, PresetSource};
use crate::problems::inputs::{Inputs, Model};
use crate::problems::problem::Registered;
use crate::problems::{ModelKind, Param, Problem, UnknownParam};
use crate::report::face::{Faces, ForProblem, for_problem};
use crate::report::figure::{self, FigureError};
use crate::report::table::{TableFormat, write_json, write_table, write_table_after};
use crate::report::{self, json, text};
use crate::study::curves::{self, RangeError, Samples, Spacing};
use crate::study::target::{Target, TargetError, solve_for_target};
use crate::tui::theme::Charset;
use crate::verify::{self, Grid};

mod args;
mod compare;
mod cycle;
mod decks;
mod error;
mod figures;
mod fitting;
mod kt;
mod loading;
mod output;
mod plot;
mod point;
mod presets;
mod solve;
mod suite;
mod sweep;
#[cfg(test)]
mod tests;
mod verification;

use args::*;
use compare::*;
use cycle::*;
use decks::*;
use error::*;
use figures::*;
use fitting::*;
use kt::*;
use loading::*;
use output::*;
use plot::*;
use point::*;
use presets::*;
use solve::*;
use sweep::*;
use verification::*;

/// microslip: friction benchmarks under the regularized Coulomb law (Ligier & Bonhote, 2014).
///
/// Units: mm, N, MPa; K_T in MPa/mm. Without a subcommand, opens the terminal UI.
#[derive(Debug, Parser)]
#[command(
    name = "microslip",
    version,
    // The doc comment above, not the crate description: the help speaks to users, Cargo.toml to
    // crates.io.
    long_about = None,
    // A fixed width: help text (and its snapshot) must not depend on the terminal running it.
    term_width = 100,
    after_help = after_help()
)]
pub struct Cli {
    /// What to do (default: the terminal UI).
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Characters the terminal UI may use (ascii: 7-bit only, for any terminal).
    #[arg(long, value_enum, default_value_t = Charset::Unicode)]
    pub charset: Charset,
    /// Preset to open in the terminal UI (bundled or user name, or a .toml path).
    #[arg(long, value_name = "P")]
    pub preset: Option<String>,
    /// Measured load-response curve of the preset's problem to show and fit in the terminal UI:
    /// a CSV with the problem's load and response columns (`microslip fit PROBLEM --help` names
    /// them), an optional sigma_mm.
    #[arg(long, value_name = "DATA.csv")]
    pub data: Option<PathBuf>,
}

/// The closing lines of `--help`: units, and the parameter keys as the model defines them.
fn after_help() -> String {
    let problems: Vec<&str> = ModelKind::ALL.iter().map(|k| k.name()).collect();
    format!(
        "Units: mm, N, MPa; K_T in MPa/mm (1 MPa/um = 1000 MPa/mm).\n\
         Keys for --set and preset files: {}.\n\
         One state of any problem: microslip PROBLEM [--preset P] [--set KEY=VALUE] ({}).\n\
         Without a command, microslip opens the terminal UI (keys: press ? inside).",
        ModelKind::key_docs(),
        problems.join(", ")
    )
}

/// The problem a command that takes any problem opens without --preset (or --model): the
/// registry's first, the paper's twin beams.
const DEFAULT_PROBLEM: ModelKind = ModelKind::ALL[0];

/// Parses the process arguments and runs; the whole binary.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => return report_clap_error(&error),
    };
    if cli.command.is_none() {
        return match crate::tui::run(cli.charset, cli.preset.as_deref(), cli.data.clone()) {
            Ok(exit) => ExitCode::from(exit.code()),
            Err(error) => {
                print_error(&error.to_string());
                ExitCode::from(2)
            }
        };
    }
    let mut out = BufWriter::with_capacity(1 << 16, io::stdout().lock());
    let result = run(&cli, &mut out).and_then(|()| out.flush().map_err(CliError::from));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // `microslip sweep ... | head`: the reader left; that is not an error.
        Err(CliError::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(error) => {
            error.print();
            ExitCode::from(error.exit_code())
        }
    }
}

/// The one error line on stderr. Errors echo what users gave (preset names, paths, values, CSV
/// headers), so the whole line is sanitized here, once, at the edge: a control character in any of
/// them is shown escaped instead of reaching the terminal.
fn print_error(message: &str) {
    // Not `eprintln!`, which panics when stderr is gone (a terminal that hung up).
    let _ = writeln!(io::stderr(), "microslip: {}", report::sanitize(message));
}

/// Help and version go to stdout as clap writes them; every other parse error becomes one line.
/// A clap error that is no request for help, as the one line `microslip: ...` says it.
fn clap_error_line(error: &clap::Error) -> String {
    let rendered = error.render().to_string();
    let first_block: Vec<&str> = rendered
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect();
    let line = first_block.join(" ");
    let line = line.strip_prefix("error: ").unwrap_or(&line);
    // `microslip cylindre`, `sweep lapp`: clap's suggestion, on the one line.
    let suggested = [
        clap::error::ContextKind::SuggestedSubcommand,
        clap::error::ContextKind::SuggestedValue,
        clap::error::ContextKind::SuggestedArg,
    ]
    .into_iter()
    .find_map(|kind| match error.get(kind) {
        Some(clap::error::ContextValue::String(s)) => Some(vec![s.clone()]),
        Some(clap::error::ContextValue::Strings(s)) if !s.is_empty() => Some(s.clone()),
        _ => None,
    });
    // `cycle plate`: a problem of the registry that does not take this command.
    let problem = (error.kind() == clap::error::ErrorKind::InvalidSubcommand)
        .then(|| error.get(clap::error::ContextKind::InvalidSubcommand))
        .flatten()
        .map(ToString::to_string)
        .and_then(|name| name.parse::<ModelKind>().ok());
    if let Some(kind) = problem {
        return format!(
            "{line}: the {kind} problem does not take this command (its subcommands are the \
             problems that do: see --help)"
        );
    }
    match suggested {
        Some(names) => format!(
            "{line}; did you mean {}? (see --help)",
            names
                .iter()
                .map(|n| format!("'{n}'"))
                .collect::<Vec<_>>()
                .join(" or ")
        ),
        None => format!("{line} (see --help)"),
    }
}

fn report_clap_error(error: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        error.kind(),
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
    ) {
        // Written like any other output: a full disk or a closed terminal is an error, a reader
        // that left (`microslip --help | head -3`) is not.
        let written = error.print().and_then(|()| io::stdout().flush());
        return match written {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            Err(e) => {
                let error = CliError::Output(e);
                print_error(&error.to_string());
                ExitCode::from(error.exit_code())
            }
        };
    }
    print_error(&clap_error_line(error));
    ExitCode::from(2)
}

/// Runs a parsed command, writing results to `out`.
pub fn run(cli: &Cli, out: &mut impl Write) -> Result<(), CliError> {
    match &cli.command {
        None | Some(Command::Report) => out.write_all(report::paper_report().as_bytes())?,
        // Every problem's subcommand runs the one generic handler for the problem it names.
        Some(Command::Problem(point)) => {
            run_point(out, point.kind, &point.args, point.flag(args::CONTINUUM))?
        }
        Some(Command::Sweep(args)) => run_sweep(out, args)?,
        Some(Command::Solve(args)) => run_solve(out, args)?,
        Some(Command::Fit(command)) => run_fit_command(out, command)?,
        Some(Command::Kt(args)) => match &args.tolerance {
            Some(tolerance) => run_kt_tolerance(
                out,
                &args.inputs,
                args.element_size,
                (tolerance, args.of),
                [args.from, args.to],
                args.format,
            )?,
            None => run_kt(
                out,
                &args.inputs,
                args.element_size,
                args.kn,
                args.nu,
                args.format,
            )?,
        },
        Some(Command::Cycle(args)) => run_cycle_command(out, args)?,
        Some(Command::Presets) => {
            let dir = preset::user_preset_dir();
            let rows = preset::listing(dir.as_deref());
            out.write_all(report::presets::listing(&rows, dir.as_deref()).as_bytes())?
        }
        Some(Command::Check(args)) => check(out, &args.files)?,
        Some(Command::Plot(args)) => run_plot(out, args)?,
        Some(Command::Figures(args)) => {
            let format = FigureFormat::choose(
                Some(args.format),
                None,
                "--format",
                &[FigureFormat::Svg, FigureFormat::Png, FigureFormat::Pdf],
                FigureFormat::Svg,
            )?
            .figure()
            .unwrap_or(figure::Format::Svg);
            run_figures(out, &args.out, !args.no_fe, format, &args.inputs)?
        }
        Some(Command::Compare(args)) => {
            let contact = compare::ContactArgs {
                interface: args.interface.as_deref(),
                kinematics: args.kinematics.map(KinematicsArg::kinematics),
            };
            run_compare(
                out,
                args.model,
                &args.results,
                args.deck.as_deref(),
                &args.inputs,
                contact,
                args.format,
            )?
        }
        Some(Command::Deck(args)) => {
            let FeCode::Ccx = args.code;
            refuse_overwriting_an_input(args.output.as_deref(), &args.deck.inputs.read_files())?;
            let deck = build_deck(
                args.model,
                &args.deck,
                &model_command(args.model, "deck ccx"),
            )?;
            write_output(out, args.output.as_deref(), deck.as_bytes())?
        }
        Some(Command::Bench(args)) => {
            let FeCode::Ccx = args.code;
            run_bench(
                out,
                args.model,
                &args.deck,
                args.workdir.as_deref(),
                &args.ccx,
                args.format,
            )?
        }
        Some(Command::Suite(args)) => suite::run_suite(out, args)?,
        Some(Command::Verify(args)) => {
            let grid = if args.quick { Grid::Quick } else { Grid::Full };
            run_verify(out, grid, args.elements, args.tolerance)?
        }
    }
    Ok(())
}
