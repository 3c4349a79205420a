//! Two writers at once (issue 34, item 1): two `ekb` rewriting one file take turns through
//! an advisory lock held from reading the file to replacing it, so a change reported as
//! made is never lost to the other's write. `check --add-ignore` (issue 39, item 5) locks
//! one file at a time, each once whatever it is called.

mod author_support;

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use author_support::{fixture, temp_file};

/// Rounds of two concurrent `ekb set`: without the lock, a few in a hundred lost a change.
const ROUNDS: usize = 60;

/// `ekb ARGS`, its error output kept.
fn spawn_ekb<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_ekb"))
        .args(args)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("ekb runs")
}

fn spawn_set(path: &Path, id: &str, text: &str) -> Child {
    let path = path.as_os_str();
    spawn_ekb(&[
        "set".as_ref(),
        id.as_ref(),
        "preGestureMessageEnglish".as_ref(),
        text.as_ref(),
        path,
    ])
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

/// A file with findings, which `check --add-ignore` gives one suppression comment.
const UNSUPPRESSED: &[u8] = b"robotLocationDescription 1 Roomba  \n";

/// Waits for `child`, killing it if it has not finished in 20 s (a writer waiting for a
/// lock gives up after 30 s; one that waits for its own lock would take that long).
fn finished(mut child: Child) -> Output {
    let deadline = Instant::now() + Duration::from_secs(20);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            child.kill().unwrap();
            panic!(
                "ekb still waits after 20 s: {:?}",
                child.wait_with_output().unwrap()
            );
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    child.wait_with_output().unwrap()
}

fn spawn_add_ignore(files: &[PathBuf]) -> Child {
    let args = ["check", "--add-ignore"].iter().map(std::ffi::OsStr::new);
    let args: Vec<&std::ffi::OsStr> = args.chain(files.iter().map(|f| f.as_os_str())).collect();
    spawn_ekb(&args)
}

fn suppressions_in(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    text.matches("# ekb: ignore[").count()
}

#[test]
fn add_ignore_does_a_file_named_twice_once_without_waiting_on_itself() {
    let (dir, path) = temp_file("a.dat", UNSUPPRESSED);
    let link = dir.path().join("link.dat");
    std::os::unix::fs::symlink(&path, &link).unwrap();
    let again = dir.path().join(".").join("a.dat");
    let output = finished(spawn_add_ignore(&[path.clone(), path.clone(), link, again]));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert_eq!(suppressions_in(&path), 1, "{stderr}");
    assert_eq!(stderr.matches("added").count(), 1, "{stderr}");
    assert!(
        stderr.contains("a.dat: added 1 suppression comment"),
        "{stderr}"
    );
}

#[test]
fn two_add_ignores_given_two_files_in_opposite_orders_both_finish() {
    for round in 0..10 {
        let (dir, a) = temp_file("a.dat", UNSUPPRESSED);
        let b = dir.path().join("b.dat");
        std::fs::write(&b, UNSUPPRESSED).unwrap();
        let forward = spawn_add_ignore(&[a.clone(), b.clone()]);
        let backward = spawn_add_ignore(&[b.clone(), a.clone()]);
        for output in [finished(forward), finished(backward)] {
            let stderr = String::from_utf8_lossy(&output.stderr);
            assert_eq!(output.status.code(), Some(0), "round {round}: {stderr}");
        }
        // The second to lock a file reads what the first wrote and adds nothing.
        assert_eq!(
            (suppressions_in(&a), suppressions_in(&b)),
            (1, 1),
            "round {round}"
        );
    }
}

#[test]
fn add_ignore_over_a_thousand_files_holds_few_descriptors() {
    let dir = tempfile::tempdir().unwrap();
    let files: Vec<PathBuf> = (0..1000)
        .map(|n| {
            let path = dir.path().join(format!("kb{n}.dat"));
            std::fs::write(&path, UNSUPPRESSED).unwrap();
            path
        })
        .collect();
    let child = Command::new("sh")
        .args([
            "-c",
            "ulimit -n 64 && exec \"$0\" check --add-ignore \"$@\"",
        ])
        .arg(env!("CARGO_BIN_EXE_ekb"))
        .args(&files)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let output = finished(child);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(
        output.status.code(),
        Some(0),
        "{}",
        &stderr[..stderr.len().min(2000)]
    );
    for file in &files {
        assert_eq!(suppressions_in(file), 1, "{}", file.display());
    }
}
