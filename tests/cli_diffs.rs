//! The diffs of `ekb fmt --check` and `ekb fix --diff`, written from the layout and the
//! fixes rather than by diffing texts: the real `patch` applies each one to the file and
//! gives exactly what `ekb fmt` or `ekb fix` writes (hunks at the start and the end, several
//! hunks, no final newline, lines moved); a CRLF file's diff is for reading.

mod author_support;

use std::path::Path;
use std::process::{Command, Stdio};

use author_support::{ekb, temp_file};

fn diff_fixture(name: &str) -> Vec<u8> {
    std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/diffs")
            .join(name),
    )
    .unwrap()
}

/// The diff that `ekb <show>` prints for a file holding `text` (exit 1), checked to turn
/// the file into what `ekb <write>` writes, by GNU `patch`. Returns the diff.
fn patch_gives_what_ekb_writes(text: &[u8], show: &[&str], write: &str) -> String {
    let (dir, path) = temp_file("kb.dat", text);
    let output = ekb()
        .current_dir(dir.path())
        .args(show)
        .arg("kb.dat")
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1), "{output:?}");
    let diff = String::from_utf8(output.stdout).unwrap();
    assert!(diff.starts_with("--- kb.dat\n+++ kb.dat\n@@ -"), "{diff}");

    let expected = dir.path().join("expected.dat");
    std::fs::write(&expected, text).unwrap();
    ekb()
        .current_dir(dir.path())
        .args([write, "expected.dat"])
        .output()
        .unwrap();

    let mut patch = Command::new("patch")
        .current_dir(dir.path())
        .args(["--quiet", "--forward", "--no-backup-if-mismatch", "kb.dat"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("GNU patch runs (Debian: apt-get install patch)");
    std::io::Write::write_all(patch.stdin.as_mut().unwrap(), diff.as_bytes()).unwrap();
    let patched = patch.wait_with_output().unwrap();
    assert!(patched.status.success(), "{patched:?}\n{diff}");
    assert_eq!(
        String::from_utf8(std::fs::read(&path).unwrap()).unwrap(),
        std::fs::read_to_string(&expected).unwrap(),
        "{diff}"
    );
    diff
}

/// The hunk headers of `diff`.
fn hunks(diff: &str) -> Vec<&str> {
    diff.lines()
        .filter(|line| line.starts_with("@@ "))
        .collect()
}

#[test]
fn fmt_check_hunks_at_the_start_in_the_middle_and_at_the_end_apply() {
    let diff = patch_gives_what_ekb_writes(
        &diff_fixture("several-hunks.dat"),
        &["fmt", "--check"],
        "fmt",
    );
    assert_eq!(
        hunks(&diff),
        [
            "@@ -1,4 +1,4 @@",
            "@@ -18,7 +18,7 @@",
            "@@ -33,7 +33,7 @@",
            "@@ -48,4 +48,4 @@"
        ],
        "{diff}"
    );
}

#[test]
fn fix_diff_hunks_apply() {
    let diff = patch_gives_what_ekb_writes(
        &diff_fixture("several-hunks.dat"),
        &["fix", "--diff"],
        "fix",
    );
    assert_eq!(
        hunks(&diff),
        ["@@ -1,4 +1,4 @@", "@@ -33,8 +33,8 @@"],
        "{diff}"
    );
}

#[test]
fn a_last_line_without_a_newline_is_marked_and_applies() {
    for (show, write) in [
        (&["fmt", "--check"][..], "fmt"),
        (&["fix", "--diff"][..], "fix"),
    ] {
        let diff = patch_gives_what_ekb_writes(&diff_fixture("no-final-newline.dat"), show, write);
        assert!(
            diff.ends_with(
                " 5 1 4  3 2 5\n\\ No newline at end of file\n+tourSpecification 5 1 4  3 2 5\n"
            ) || diff.ends_with(
                " 5 1 4  3 2 5\n\\ No newline at end of file\n+tourSpecification 5 1 4 3 2 5\n"
            ),
            "{diff}"
        );
    }
}

#[test]
fn lines_moved_by_the_layout_are_taken_out_and_put_in_and_the_rest_stays() {
    let diff =
        patch_gives_what_ekb_writes(&diff_fixture("reorder.dat"), &["fmt", "--check"], "fmt");
    // The lines already in place are context, not taken out and put back.
    for unchanged in [
        " robotLocationDescription      3 Lynxmotion arm\n",
        " robotLocationDescription      1 Reception\n",
        " gestureTarget                 1 0 0 0\n",
        " robotLocationDescription      2 Pepper robot\n",
        " # end\n",
    ] {
        assert!(diff.contains(unchanged), "{unchanged}: {diff}");
    }
    assert!(diff.contains("-tourSpecification 3 1 2 3\n"), "{diff}");
    assert!(
        diff.ends_with("+tourSpecification 3 1 2 3\n+\n # end\n"),
        "{diff}"
    );
}

#[test]
fn the_balanced_order_of_fix_applies() {
    // Ascending ids, as deep a tree as there are locations: `compat-reader-crash`, whose
    // fix writes the blocks in a balanced order.
    let text: String = (1..=6_000)
        .map(|id| format!("robotLocationDescription      {id} Stop {id}\n\n"))
        .collect();
    let diff = patch_gives_what_ekb_writes(text.as_bytes(), &["fix", "--diff"], "fix");
    // What is left is told of the file as it is (the diff writes nothing), less what the
    // order broke.
    let (dir, _path) = temp_file("kb.dat", text.as_bytes());
    let output = ekb()
        .current_dir(dir.path())
        .args(["fix", "--diff", "kb.dat"])
        .output()
        .unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(
        stderr.starts_with("kb.dat: would fix 1 compat-reader-crash\n"),
        "{stderr}"
    );
    assert!(
        stderr.contains("kb.dat:1:1: error[missing-field] location 1 lacks"),
        "{stderr}"
    );
    assert!(!stderr.contains("[compat-"), "{stderr}");
    // The middle id first.
    assert!(
        diff.contains("\n+robotLocationDescription      3001 Stop 3001\n"),
        "{}",
        &diff[..2000]
    );
}

#[test]
fn a_crlf_file_shows_its_carriage_returns_escaped() {
    // Every carriage return is escaped as every output of ekb escapes control characters,
    // so this diff is for reading: `patch` does not apply it.
    let (dir, _path) = temp_file("kb.dat", &diff_fixture("crlf.dat"));
    for command in [["fmt", "--check"], ["fix", "--diff"]] {
        let output = ekb()
            .current_dir(dir.path())
            .args(command)
            .arg("kb.dat")
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(1), "{output:?}");
        let diff = String::from_utf8(output.stdout).unwrap();
        assert!(diff.starts_with("--- kb.dat\n+++ kb.dat\n@@ -1,8 +1,8 @@\n-robotLocationDescription      1 Pepper's starting location\\u{000D}\n"), "{diff}");
        assert!(
            diff.contains("\n+robotLocationDescription      1 Pepper's starting location\n"),
            "{diff}"
        );
        assert!(!diff.contains('\r'), "{diff}");
    }
}

#[test]
fn fmt_check_past_16_mib_names_the_one_line_that_would_change() {
    // A canonical file below 17 MB of comments, with one line of it out of the layout.
    let seed = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/check/clean-seed.dat");
    let (dir, path) = temp_file("kb.dat", &std::fs::read(seed).unwrap());
    let formatted = ekb()
        .current_dir(dir.path())
        .args(["--isolated", "fmt", "kb.dat"])
        .output()
        .unwrap();
    assert!(formatted.status.success(), "{formatted:?}");
    let canonical = std::fs::read_to_string(&path).unwrap();
    let mut lines: Vec<&str> = canonical.split_inclusive('\n').collect();
    assert_eq!(lines[1], "robotLocation                 1 2.6 8.1 0\n");
    lines[1] = "robotLocation 1 2.6 8.1 0\n";
    let padding = "# padding\n".repeat(1_700_000);
    std::fs::write(&path, padding + &lines.concat()).unwrap();
    let output = ekb()
        .current_dir(dir.path())
        .args(["--isolated", "fmt", "--check", "kb.dat"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1), "{output:?}");
    assert!(output.stdout.is_empty(), "no diff past 16 MiB");
    let stderr = String::from_utf8(output.stderr).unwrap();
    let total = 1_700_000 + lines.len();
    assert!(
        stderr.starts_with(&format!(
            "kb.dat: would change lines 1700002 to 1700002 of {total}; the diff of a file over 16 MiB is not shown"
        )),
        "{stderr}"
    );
}
