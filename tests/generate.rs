//! `ekb-generate` writes files that `ekb check` accepts: no error, no warning.

use assert_cmd::Command;
use predicates::prelude::*;

fn generated(args: &[&str]) -> Vec<u8> {
    let output = Command::cargo_bin("ekb-generate")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    output.stdout
}

#[test]
fn generated_files_pass_ekb_check() {
    // The current dialect's gestureArm is read by reader 2026-03 only.
    for (args, reader) in [
        (&["25"][..], "d5.4.2"),
        (
            &["40", "--dialect", "current", "--shuffle", "--seed", "3"],
            "2026-03",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        Command::cargo_bin("ekb")
            .unwrap()
            .current_dir(dir.path())
            .env_remove("EKB_CONFIG")
            .env_remove("EKB_READER")
            .args(["check", "--reader", reader, "--format", "concise", "-"])
            .write_stdin(generated(args))
            .assert()
            .code(0)
            .stdout(predicate::str::contains("error").not())
            .stdout(predicate::str::contains("warning").not())
            .stdout(predicate::str::contains("info[unused-location]"));
    }
}

#[test]
fn the_same_seed_gives_the_same_file() {
    assert_eq!(
        generated(&["30", "--shuffle"]),
        generated(&["30", "--shuffle"])
    );
    assert_ne!(
        generated(&["30", "--shuffle"]),
        generated(&["30", "--shuffle", "--seed", "2"])
    );
}

#[test]
fn bad_arguments_exit_2() {
    Command::cargo_bin("ekb-generate")
        .unwrap()
        .args(["many"])
        .assert()
        .code(2);
}
