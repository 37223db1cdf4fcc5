//! The `microslip` binary. Until the TUI and the CLI land, it prints the report of the paper's two
//! data sets; nothing else lives here.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        None => {
            print!("{}", microslip::report::paper_report());
            ExitCode::SUCCESS
        }
        Some("--version" | "-V") => {
            println!("microslip {}", env!("CARGO_PKG_VERSION"));
            ExitCode::SUCCESS
        }
        Some("--help" | "-h") => {
            println!(
                "microslip: friction benchmarks under the regularized Coulomb law\n\nUsage: microslip    print the report of the paper's two data sets (mm, N, MPa)"
            );
            ExitCode::SUCCESS
        }
        Some(other) => {
            eprintln!(
                "microslip: unexpected argument '{other}': this version takes no arguments (try --help)"
            );
            ExitCode::from(2)
        }
    }
}
