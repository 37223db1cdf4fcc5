//! End to end: the real binary in a pseudo-terminal. Keys go in, the screen is read back through a
//! terminal emulator (vt100), and after quitting, `stty` run in the same terminal proves that raw
//! mode was switched off.

use std::io::{Read, Write};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use portable_pty::{CommandBuilder, PtySize, native_pty_system};

struct Session {
    parser: vt100::Parser,
    raw: Vec<u8>,
    output: mpsc::Receiver<Vec<u8>>,
    writer: Box<dyn Write + Send>,
}

impl Session {
    fn pump(&mut self, timeout: Duration) {
        if let Ok(chunk) = self.output.recv_timeout(timeout) {
            self.parser.process(&chunk);
            self.raw.extend_from_slice(&chunk);
        }
    }

    /// Waits until the screen contains `text`; panics with the screen after 10 s.
    fn wait_for(&mut self, text: &str) {
        let start = Instant::now();
        while !self.parser.screen().contents().contains(text) {
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "timed out waiting for {text:?}; screen:\n{}",
                self.parser.screen().contents()
            );
            self.pump(Duration::from_millis(50));
        }
    }

    fn send(&mut self, keys: &str) {
        self.writer.write_all(keys.as_bytes()).unwrap();
        self.writer.flush().unwrap();
    }
}

/// Starts `microslip` in a 100x30 pseudo-terminal under `sh`, which prints the exit code and the
/// terminal modes (`stty -a`) once microslip has exited.
fn start() -> (Session, Box<dyn portable_pty::Child + Send + Sync>) {
    let binary = env!("CARGO_BIN_EXE_microslip");
    let pty = native_pty_system()
        .openpty(PtySize {
            rows: 30,
            cols: 100,
            pixel_width: 0,
            pixel_height: 0,
        })
        .expect("a pseudo-terminal");
    let mut command = CommandBuilder::new("sh");
    command.args(["-c", &format!("'{binary}'; echo; echo EXIT=$?; stty -a")]);
    command.env("TERM", "xterm-256color");
    command.env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"));
    let child = pty.slave.spawn_command(command).unwrap();
    drop(pty.slave);
    let mut reader = pty.master.try_clone_reader().unwrap();
    let (sender, output) = mpsc::channel();
    std::thread::spawn(move || {
        let mut buffer = [0u8; 4096];
        while let Ok(n) = reader.read(&mut buffer) {
            if n == 0 || sender.send(buffer[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    let writer = pty.master.take_writer().unwrap();
    // Keep the master open for the whole session: closing it would hang up the terminal.
    std::mem::forget(pty.master);
    let rows = std::num::NonZero::new(30).unwrap();
    let cols = std::num::NonZero::new(100).unwrap();
    (
        Session {
            parser: vt100::Parser::new(rows, cols, 0),
            raw: Vec::new(),
            output,
            writer,
        },
        child,
    )
}

impl Session {
    /// After microslip exited: the shell's report shows canonical mode and echo back on, and the
    /// alternate screen was left.
    fn assert_restored(&mut self) {
        self.wait_for("EXIT=");
        let start = Instant::now();
        while !self.parser.screen().contents().contains("icanon")
            && start.elapsed() < Duration::from_secs(10)
        {
            self.pump(Duration::from_millis(50));
        }
        let screen = self.parser.screen().contents();
        assert!(
            screen.contains(" icanon") && screen.contains(" echo"),
            "terminal left in raw mode:\n{screen}"
        );
        assert!(!screen.contains("-icanon"), "{screen}");
        let raw = String::from_utf8_lossy(&self.raw);
        assert!(
            raw.contains("\u{1b}[?1049h") && raw.contains("\u{1b}[?1049l"),
            "alternate screen not entered and left"
        );
        assert!(!raw.contains("\u{1b}[?1000h"), "mouse captured");
    }
}

#[test]
fn keys_change_the_screen_and_quit_restores_the_terminal() {
    let (mut session, mut child) = start();
    session.wait_for("Twin beams");
    session.wait_for("100 N");
    // Select F (last row) and raise it by two coarse steps of 10 % of F_thre = 8 N.
    session.send("k");
    session.send("L");
    session.send("L");
    session.wait_for("At F = 116 N");
    // Switch to the plate.
    session.send("m");
    session.wait_for("Squeezed plate");
    session.wait_for("X_r = 9.83832 mm");
    session.send("q");
    session.wait_for("EXIT=0");
    session.assert_restored();
    let _ = child.wait();
}

#[test]
fn sigterm_and_sighup_restore_the_terminal() {
    for signal in ["TERM", "HUP"] {
        let (mut session, mut child) = start();
        session.wait_for("Twin beams");
        // microslip is the shell's only child.
        let shell = child.process_id().expect("shell pid");
        let children =
            std::fs::read_to_string(format!("/proc/{shell}/task/{shell}/children")).unwrap();
        let pid = children
            .split_whitespace()
            .next()
            .expect("microslip pid")
            .to_string();
        let status = std::process::Command::new("kill")
            .args([&format!("-{signal}"), &pid])
            .status()
            .unwrap();
        assert!(status.success());
        session.assert_restored();
        let _ = child.wait();
    }
}

#[test]
fn a_data_file_above_the_cap_is_refused_before_the_screen_changes() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("huge.csv");
    // Sparse: refused by its size, never read.
    std::fs::File::create(&data)
        .unwrap()
        .set_len((256 << 20) + 1)
        .unwrap();
    let binary = env!("CARGO_BIN_EXE_microslip");
    let pty = native_pty_system()
        .openpty(PtySize {
            rows: 30,
            cols: 100,
            pixel_width: 0,
            pixel_height: 0,
        })
        .expect("a pseudo-terminal");
    let mut command = CommandBuilder::new("sh");
    command.args([
        "-c",
        &format!("'{binary}' --data '{}'; echo EXIT=$?", data.display()),
    ]);
    command.env("TERM", "xterm-256color");
    command.env("XDG_CONFIG_HOME", env!("CARGO_TARGET_TMPDIR"));
    let mut child = pty.slave.spawn_command(command).unwrap();
    drop(pty.slave);
    let mut reader = pty.master.try_clone_reader().unwrap();
    let (sender, output) = mpsc::channel();
    std::thread::spawn(move || {
        let mut buffer = [0u8; 4096];
        while let Ok(n) = reader.read(&mut buffer) {
            if n == 0 || sender.send(buffer[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    let mut raw = Vec::new();
    let start = Instant::now();
    while !String::from_utf8_lossy(&raw).contains("EXIT=") {
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "no exit: {}",
            String::from_utf8_lossy(&raw)
        );
        if let Ok(chunk) = output.recv_timeout(Duration::from_millis(50)) {
            raw.extend_from_slice(&chunk);
        }
    }
    let text = String::from_utf8_lossy(&raw);
    assert!(
        text.contains("huge.csv: file is larger than the 256 MiB limit for a measurement file"),
        "{text}"
    );
    assert!(text.contains("EXIT=2"), "{text}");
    assert!(
        !text.contains("\u{1b}[?1049h"),
        "the screen changed: {text}"
    );
    let _ = child.wait();
    drop(pty.master);
}
