//! Files a user names, through the real binary: `-o` never clobbers what it should not (devices,
//! FIFOs, links, read-only files, modes), and no file a user names or a folder holds can make the
//! program wait (FIFOs). Every command runs under a timeout, so a regression fails instead of
//! hanging the suite.

#![cfg(unix)]

use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;

/// Far above any of these commands' run time; reached only when something blocks.
const TIMEOUT: Duration = Duration::from_secs(20);

fn microslip(config: &Path) -> Command {
    let mut cmd = Command::cargo_bin("microslip").expect("binary built by cargo");
    cmd.env("XDG_CONFIG_HOME", config)
        .env_remove("HOME")
        .timeout(TIMEOUT);
    cmd
}

fn mkfifo(path: &Path) {
    let made = std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .unwrap();
    assert!(made.success());
}

/// Runs `args`; returns (exit code, stdout, stderr). A timeout shows as code `None` and fails.
fn run(config: &Path, args: &[&str]) -> (i32, String, String) {
    let output = microslip(config).args(args).output().unwrap();
    let code = output
        .status
        .code()
        .unwrap_or_else(|| panic!("{args:?} did not exit by itself (blocked?)"));
    (
        code,
        String::from_utf8(output.stdout).unwrap(),
        String::from_utf8(output.stderr).unwrap(),
    )
}

#[test]
fn output_to_a_device_writes_through_and_never_replaces_it() {
    let dir = tempfile::tempdir().unwrap();
    let (code, _, stderr) = run(dir.path(), &["deck", "ccx", "beam", "-o", "/dev/full"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("/dev/full") && stderr.contains("space"),
        "{stderr}"
    );
    assert!(
        std::fs::metadata("/dev/full")
            .unwrap()
            .file_type()
            .is_char_device()
    );
    let (code, _, stderr) = run(dir.path(), &["deck", "ccx", "beam", "-o", "/dev/null"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        std::fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device()
    );
}

#[test]
fn output_dash_and_dev_stdout_go_to_standard_output() {
    let dir = tempfile::tempdir().unwrap();
    let (_, plain, _) = run(dir.path(), &["deck", "ccx", "plate"]);
    for target in ["-", "/dev/stdout"] {
        let (code, out, stderr) = run(dir.path(), &["deck", "ccx", "plate", "-o", target]);
        assert_eq!(code, 0, "{stderr}");
        assert_eq!(out, plain, "-o {target}");
    }
    assert!(!dir.path().join("-").exists());
}

#[test]
fn output_to_a_fifo_without_a_reader_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("deck.inp");
    mkfifo(&fifo);
    let (code, _, stderr) = run(
        dir.path(),
        &["deck", "ccx", "plate", "-o", fifo.to_str().unwrap()],
    );
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("no process is reading this FIFO"),
        "{stderr}"
    );
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
}

#[test]
fn output_through_a_symbolic_link_lands_in_the_file_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.inp");
    std::fs::write(&real, "old").unwrap();
    let link = dir.path().join("link.inp");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let (code, _, stderr) = run(
        dir.path(),
        &["deck", "ccx", "plate", "-o", link.to_str().unwrap()],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
    assert!(std::fs::read_to_string(&real).unwrap().starts_with("**"));
}

#[test]
fn a_replaced_file_keeps_its_mode_and_nothing_else_is_left() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("chart.svg");
    std::fs::write(&out, "old").unwrap();
    std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o600)).unwrap();
    let (code, _, stderr) = run(dir.path(), &["plot", "w-vs-f", "-o", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let mode = std::fs::metadata(&out).unwrap().permissions().mode() & 0o7777;
    assert_eq!(mode, 0o600);
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["chart.svg"]);
}

/// A read-only file is refused, not replaced, for a user who may not write it (as `nobody` when
/// the tests run as root, since root may write anything).
#[test]
fn a_read_only_file_is_refused_for_a_user_who_may_not_write_it() {
    let dir = tempfile::tempdir().unwrap();
    // The folder is writable by all, so that only the file's own mode protects it (renaming over a
    // read-only file needs nothing more, which is how it used to be replaced).
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o777)).unwrap();
    let protected = dir.path().join("ro.inp");
    std::fs::write(&protected, "keep me").unwrap();
    std::fs::set_permissions(&protected, std::fs::Permissions::from_mode(0o444)).unwrap();
    // SAFETY: geteuid has no preconditions.
    let root = unsafe { libc::geteuid() } == 0;
    let binary = env!("CARGO_BIN_EXE_microslip");
    let mut command = if root {
        let mut c = std::process::Command::new("setpriv");
        c.args(["--reuid=65534", "--regid=65534", "--clear-groups", binary]);
        c
    } else {
        std::process::Command::new(binary)
    };
    let output = command
        .args(["deck", "ccx", "plate", "-o"])
        .arg(&protected)
        .env("XDG_CONFIG_HOME", dir.path())
        .env_remove("HOME")
        .output()
        .unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("read-only"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&protected).unwrap(), "keep me");
}

/// A FIFO in the preset folder, given as a preset, or as FE results never makes the program wait:
/// each is refused as not a regular file.
#[test]
fn fifos_where_files_are_expected_are_refused_without_waiting() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("microslip/presets");
    std::fs::create_dir_all(&presets).unwrap();
    let fifo = presets.join("x.toml");
    mkfifo(&fifo);
    let (code, out, stderr) = run(dir.path(), &["presets"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        out.contains("a FIFO (named pipe), not a regular file"),
        "{out}"
    );
    let fifo = fifo.to_str().unwrap();
    let (code, out, _) = run(dir.path(), &["check", fifo]);
    assert_eq!(code, 1);
    assert!(
        out.contains("a FIFO (named pipe), not a regular file"),
        "{out}"
    );
    let (code, _, stderr) = run(dir.path(), &["beam", "--preset", fifo]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("a FIFO (named pipe), not a regular file"),
        "{stderr}"
    );
    let dat = dir.path().join("beam.dat");
    mkfifo(&dat);
    std::fs::write(dir.path().join("beam.inp"), "** a deck\n").unwrap();
    let (code, _, stderr) = run(dir.path(), &["compare", "beam", dat.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("beam.dat: a FIFO (named pipe), not a regular file"),
        "{stderr}"
    );
    // The deck beside a regular .dat.
    let dat = dir.path().join("plate.dat");
    std::fs::write(&dat, "").unwrap();
    mkfifo(&dir.path().join("plate.inp"));
    let (code, _, stderr) = run(dir.path(), &["compare", "plate", dat.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("a FIFO (named pipe), not a regular file"),
        "{stderr}"
    );
}

/// A measured curve may come from a pipe (`fit beam <(...)`): read to its end when a writer is
/// there, refused at once when none is.
#[test]
fn a_measured_curve_from_a_fifo_without_a_writer_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("w.csv");
    mkfifo(&fifo);
    let (code, _, stderr) = run(dir.path(), &["fit", "beam", fifo.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("no process writes to"), "{stderr}");
}
