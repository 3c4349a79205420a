//! How `ekb` fails: one escaped line on standard error, and quiet when its reader goes away.

use std::io::Write;
use std::process::{Command, Stdio};

fn ekb() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ekb"))
}

#[test]
fn error_lines_never_carry_raw_control_characters() {
    let output = ekb()
        .args(["check", "no\x1b[31msuch.dat"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(
        stderr,
        "ekb: error: cannot read no\\u{001B}[31msuch.dat: no such file\n"
    );
}

/// `ekb export big.dat | head -1`: the export stops quietly when `head` exits.
#[test]
fn a_closed_pipe_is_not_an_error() {
    let mut text = String::new();
    for id in 1..=3000 {
        text.push_str(&format!(
            "robotLocationDescription {id} Exhibit number {id} with a longish description\n"
        ));
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("environmentKnowledgeBaseInput.dat");
    std::fs::File::create(&path)
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    let mut child = ekb()
        .args(["export", "--allow-errors"])
        .arg(&path)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // the reader goes away before reading anything
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&output.stderr), "");
}
