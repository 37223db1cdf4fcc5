//! The `microslip` binary: everything lives in the library; see `microslip::cli`.

fn main() -> std::process::ExitCode {
    microslip::cli::main()
}
