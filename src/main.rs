//! The `microslip` binary: everything lives in the library; see the library's private `cli`
//! module, reached through `microslip::app`.

fn main() -> std::process::ExitCode {
    microslip::app::main()
}
