//! The real binary as the integration tests run it: user presets of the machine running the
//! tests kept out of the way, and (exit code, stdout, stderr) of a command.
#![allow(dead_code)]

use assert_cmd::Command;

/// `microslip`, with a configuration folder of its own.
pub fn microslip() -> Command {
    let mut cmd = Command::cargo_bin("microslip").expect("binary built by cargo");
    cmd.env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"))
        .env_remove("HOME");
    cmd
}

/// (exit code, stdout, stderr) of `args`.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let output = microslip().args(args).output().unwrap();
    (
        output.status.code().unwrap(),
        String::from_utf8(output.stdout).unwrap(),
        String::from_utf8(output.stderr).unwrap(),
    )
}
