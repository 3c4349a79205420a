//! Two writers at once (issue 34, item 1): two `ekb` rewriting one file take turns through
//! an advisory lock held from reading the file to replacing it, so a change reported as
//! made is never lost to the other's write.

mod author_support;

use std::path::Path;
use std::process::{Child, Command, Stdio};

use author_support::{fixture, temp_file};

/// Rounds of two concurrent `ekb set`: without the lock, a few in a hundred lost a change.
const ROUNDS: usize = 60;

fn spawn_set(path: &Path, id: &str, text: &str) -> Child {
    Command::new(env!("CARGO_BIN_EXE_ekb"))
        .args(["set", id, "preGestureMessageEnglish", text])
        .arg(path)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("ekb runs")
}

/// Waits for `child`; `true` if it said it made its change.
fn made(child: Child) -> bool {
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    match output.status.code() {
        Some(0) => {
            assert!(stderr.contains(" set"), "{stderr}");
            true
        }
        // A refusal is allowed, if it says so: never a silent loss.
        Some(2) => {
            assert!(stderr.contains("cannot write"), "{stderr}");
            false
        }
        other => panic!("exit {other:?}: {stderr}"),
    }
}

#[test]
fn two_concurrent_sets_on_different_lines_keep_both_changes() {
    let seed = std::fs::read(fixture("current.dat")).unwrap();
    let (_dir, path) = temp_file("kb.dat", &seed);
    let mut both_made = 0;
    for round in 0..ROUNDS {
        let first_text = format!("First writer round {round}");
        let second_text = format!("Second writer round {round}");
        let first = spawn_set(&path, "1", &first_text);
        let second = spawn_set(&path, "2", &second_text);
        let (first_made, second_made) = (made(first), made(second));
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(
            !first_made || text.contains(&first_text),
            "round {round}: the first change was reported as made and lost"
        );
        assert!(
            !second_made || text.contains(&second_text),
            "round {round}: the second change was reported as made and lost"
        );
        both_made += usize::from(first_made && second_made);
    }
    // The second writer waits for the first and reads what it wrote: neither is refused.
    assert_eq!(both_made, ROUNDS);
}
