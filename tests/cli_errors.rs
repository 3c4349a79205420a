//! How `ekb` fails: one escaped line on standard error. (When its reader goes away:
//! `closed_streams.rs`.)

use std::process::Command;

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
