//! Closed pipes and partial work (issue 12, item 3): whoever reads `ekb`'s output may go
//! away (`ekb fix a b c d 2>&1 | head -1`). `ekb` never panics then, finishes the work that
//! does not need the closed stream, and exits 2: what the stream should have carried is
//! lost. A file that cannot be read among several stops none of the others.

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The line `ekb` ends with when a stream was closed on it.
const CLOSED_STDOUT: &str = "ekb: error: cannot write to standard output: it was closed \
                             before ekb finished (whoever read it stopped reading)\n";

/// A line with trailing blanks: `fix` rewrites it and tells so on standard error.
const UNFIXED: &str = "robotLocationDescription 1 Roomba  \n";
const FIXED: &str = "robotLocationDescription 1 Roomba\n";

fn ekb() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_ekb"));
    command
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env("NO_COLOR", "1");
    command
}

/// The writing end of a pipe nobody reads: a write to it fails (`EPIPE`), as once `head`
/// has exited. Made of a FIFO so that no reader can exist: opened for reading and writing
/// it needs no other end (Linux), then the writing end opens without waiting, then the
/// first goes.
fn pipe_nobody_reads(dir: &Path, name: &str) -> std::fs::File {
    let fifo = dir.join(name);
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let both = OpenOptions::new()
        .read(true)
        .write(true)
        .open(&fifo)
        .unwrap();
    let writer = OpenOptions::new().write(true).open(&fifo).unwrap();
    drop(both);
    writer
}

/// `count` files with something to fix, in `dir`.
fn files_to_fix(dir: &Path, count: usize) -> Vec<PathBuf> {
    (1..=count)
        .map(|n| {
            let path = dir.join(format!("kb{n}.dat"));
            std::fs::write(&path, UNFIXED).unwrap();
            path
        })
        .collect()
}

fn assert_fixed(paths: &[PathBuf]) {
    for path in paths {
        let text = std::fs::read_to_string(path).unwrap();
        assert_eq!(text, FIXED, "{}", path.display());
    }
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn fix_goes_on_with_standard_error_closed() {
    // `ekb fix a b c d 2>&1 | head -1` panicked (exit 101) at the first message, and left c
    // and d unfixed.
    let dir = tempfile::tempdir().unwrap();
    let paths = files_to_fix(dir.path(), 4);
    let status = ekb()
        .arg("fix")
        .args(&paths)
        .stdout(pipe_nobody_reads(dir.path(), "stdout"))
        .stderr(pipe_nobody_reads(dir.path(), "stderr"))
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(2));
    assert_fixed(&paths);
}

#[test]
fn fix_goes_on_with_only_standard_error_closed() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files_to_fix(dir.path(), 3);
    let output = ekb()
        .arg("fix")
        .args(&paths)
        .stderr(pipe_nobody_reads(dir.path(), "stderr"))
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(output.stdout, b"");
    assert_fixed(&paths);
}

#[test]
fn an_export_or_a_report_nobody_receives_is_a_failure() {
    // `export` exited 0, having exported nothing.
    for command in [&["export", "--allow-errors"][..], &["check"]] {
        let dir = tempfile::tempdir().unwrap();
        let kb = dir.path().join("kb.dat");
        std::fs::write(&kb, UNFIXED).unwrap();
        let output = ekb()
            .args(command)
            .arg(&kb)
            .stdout(pipe_nobody_reads(dir.path(), "stdout"))
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2), "{command:?}");
        assert_eq!(stderr(&output), CLOSED_STDOUT, "{command:?}");
    }
}

#[test]
fn fmt_check_with_standard_output_closed_goes_on_and_says_so_once() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files_to_fix(dir.path(), 3);
    // The second cannot be formatted: its error shows that the first did not stop the run.
    std::fs::write(&paths[1], "robotLocationDescription 1 A\r\r\n").unwrap();
    let output = ekb()
        .args(["fmt", "--check"])
        .args(&paths)
        .stdout(pipe_nobody_reads(dir.path(), "stdout"))
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = stderr(&output);
    assert!(
        stderr.starts_with(&format!("ekb: error: cannot format {}", paths[1].display())),
        "{stderr}"
    );
    assert!(stderr.ends_with(&format!("\n{CLOSED_STDOUT}")), "{stderr}");
    assert_eq!(stderr.lines().count(), 2, "{stderr}");
}

#[test]
fn fix_goes_on_after_a_file_it_cannot_read() {
    let dir = tempfile::tempdir().unwrap();
    let paths = files_to_fix(dir.path(), 2);
    let missing = dir.path().join("missing.dat");
    let output = ekb()
        .arg("fix")
        .arg(&paths[0])
        .arg(&missing)
        .arg(&paths[1])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains(&format!(
            "ekb: error: cannot read {}: no such file\n",
            missing.display()
        )),
        "{}",
        stderr(&output)
    );
    assert_fixed(&paths);
}
