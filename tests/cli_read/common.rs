//! Running `ekb` the same way in every test.

use assert_cmd::Command;

/// The document's knowledge base (seed dialect; two errors, 21 warnings).
pub const SEED: &str = "data/environmentKnowledgeBaseInput.dat";

pub fn fixture(name: &str) -> String {
    format!("tests/fixtures/read/{name}")
}

/// `ekb` from the package root, with no configuration, colour or width from the environment.
pub fn ekb() -> Command {
    let mut cmd = assert_cmd::cargo::cargo_bin_cmd!("ekb");
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env_remove("COLUMNS")
        .env_remove("NO_COLOR");
    cmd
}

/// What a run printed and how it exited.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

pub fn run(args: &[&str]) -> Run {
    run_with(ekb().args(args))
}

pub fn run_with(cmd: &mut Command) -> Run {
    let output = cmd.output().expect("ekb runs");
    Run {
        code: output.status.code().expect("ekb exits, not killed"),
        stdout: String::from_utf8(output.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
    }
}

/// No raw control or bidi character in `text` (newlines aside).
pub fn assert_terminal_safe(text: &str) {
    let bad: Vec<char> = text
        .chars()
        .filter(|&c| {
            (c.is_control() && c != '\n')
                || matches!(c, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
        })
        .collect();
    assert!(bad.is_empty(), "raw characters {bad:?} in:\n{text}");
}
