//! `ekb --version`: the workspace's version, and for a release build the commit it was built
//! from (build.rs). scripts/test-packages.sh and scripts/release.sh check the commit on the
//! built artifacts; a test build is a debug build, which leaves it out.

use std::process::Command;

#[test]
fn the_version_is_the_workspaces_then_the_commit_of_a_release_build() {
    let output = Command::new(env!("CARGO_BIN_EXE_ekb"))
        .arg("--version")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(0));
    let stdout = String::from_utf8(output.stdout).unwrap();
    let after = stdout
        .strip_prefix(&format!("ekb {}", env!("CARGO_PKG_VERSION")))
        .unwrap_or_else(|| panic!("{stdout:?}"));
    let commit = after
        .strip_prefix(" (")
        .and_then(|rest| rest.strip_suffix(")\n"));
    match commit {
        Some(commit) => assert!(
            commit.len() >= 7 && commit.bytes().all(|byte| byte.is_ascii_hexdigit()),
            "{stdout:?}"
        ),
        None => assert_eq!(after, "\n", "{stdout:?}"),
    }
}
