//! Shared by the tests of what `ekb` prints (`output_safety`, `hostile_sizes`, `standards`,
//! `cli_wrap`): `ekb` run in a folder, with nothing from the environment that would change
//! its output, and a time limit so that a hang fails the test instead of blocking it.

use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;

/// `ekb` run in `dir` (no configuration is found there), without `EKB_CONFIG`,
/// `EKB_READER` or `COLUMNS`.
pub fn ekb(dir: &Path) -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env_remove("COLUMNS")
        .timeout(Duration::from_secs(60));
    command
}
