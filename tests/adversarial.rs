//! Hostile and broken inputs (issue 5): each gets a clear diagnostic, or a one-line error
//! with exit code 2 — never a panic, a hang, unbounded output, or another exit code. Each
//! goes through `ekb check`, and through `ekb fmt` and `ekb fix`, which rewrite it. Nothing
//! from a file reaches the terminal raw, whichever command prints it.
//! Big inputs are generated in a temporary folder, never committed.

#[path = "support/generate.rs"]
mod generate;

use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use ekb::check::{check, Checked};
use ekb::diagnostic::MAX_SHOWN_PER_RULE;
use ekb::model::build::Options;
use ekb::SourceFile;
use generate::{generate, Spec};
use predicates::prelude::*;

/// `ekb` run in an empty folder (no configuration is found there), with a time limit so
/// that a hang fails the test instead of blocking it.
fn ekb(dir: &Path) -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .timeout(Duration::from_secs(120));
    command
}

fn checked(bytes: Vec<u8>, run: impl FnOnce(&Checked)) {
    let source = SourceFile::from_bytes("adversarial", bytes);
    run(&check(&source, &Options::default()));
}

fn rules(checked: &Checked) -> Vec<&'static str> {
    checked.diagnostics.iter().map(|d| d.rule.name).collect()
}

/// Runs `ekb check FILE` and returns its standard output, asserting the exit code.
fn check_file(dir: &Path, file: &Path, code: i32) -> String {
    let output = ekb(dir)
        .args(["check", "--format", "concise"])
        .arg(file)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(code), "{output:?}");
    String::from_utf8(output.stdout).expect("output is UTF-8")
}

/// Runs `ekb check FILE`, `ekb fmt FILE` and `ekb fix FILE`, expecting of each exit 2 and
/// one line on standard error with `reason`.
fn refused(dir: &Path, file: &Path, reason: &str) {
    for command in ["check", "fmt", "fix"] {
        ekb(dir)
            .arg(command)
            .arg(file)
            .assert()
            .code(2)
            .stdout("")
            .stderr(
                predicate::str::contains(reason)
                    .and(predicate::function(|err: &str| err.lines().count() == 1)),
            );
    }
}

/// Whether `text` holds a character that could change what a terminal shows.
fn has_unsafe(text: &str) -> bool {
    text.chars()
        .any(|c| c != '\n' && ekb::render::escape::is_unsafe(c))
}

/// Runs `ekb fmt FILE` and `ekb fix FILE` on a copy each of a file of `bytes`, and returns
/// their exit codes and standard errors. Neither may panic, exit with another code than 0, 1
/// or 2, or print anything raw from the file; a refusal (2) is one line on standard error.
fn rewrite(bytes: &[u8]) -> [(i32, String); 2] {
    let dir = tempfile::tempdir().unwrap();
    ["fmt", "fix"].map(|command| {
        let file = dir.path().join(format!("{command}.dat"));
        std::fs::write(&file, bytes).unwrap();
        let output = ekb(dir.path()).arg(command).arg(&file).output().unwrap();
        let code = output.status.code().unwrap_or(-1);
        let stderr = String::from_utf8(output.stderr).expect("standard error is UTF-8");
        assert!(
            (0..=2).contains(&code),
            "{command} exited with {code}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{command}: {stderr}");
        assert!(!has_unsafe(&stderr), "{command} printed raw: {stderr}");
        if code == 2 {
            assert_eq!(stderr.lines().count(), 1, "{command}: {stderr}");
            assert!(stderr.starts_with("ekb: error: "), "{command}: {stderr}");
        }
        (code, stderr)
    })
}

/// The exit codes of `ekb fmt` and `ekb fix` on a file of `bytes` (see [`rewrite`]).
fn rewrite_codes(bytes: &[u8]) -> [i32; 2] {
    rewrite(bytes).map(|(code, _)| code)
}

#[test]
fn a_one_megabyte_line_is_too_long_and_that_is_all() {
    let mut text = b"preGestureMessageEnglish      1 ".to_vec();
    text.extend(std::iter::repeat_n(b"robots ".as_slice(), 150_000).flatten());
    text.push(b'\n');
    // fmt only drops the trailing blank; fix too, and leaves the line too long.
    assert_eq!(rewrite_codes(&text), [0, 1]);
    checked(text, |checked| {
        let long = checked
            .diagnostics
            .iter()
            .find(|d| d.rule.name == "compat-line-too-long")
            .expect("compat-line-too-long");
        assert!(
            long.message.contains("1050033 bytes long"),
            "{}",
            long.message
        );
    });
}

#[test]
fn fifty_megabytes_without_a_newline() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("one-line.dat");
    let words = ["alpha ", "beta ", "gamma ", "delta ", "epsilon "];
    let mut text = b"robotLocationDescription 1 ".to_vec();
    while text.len() < 50_000_000 {
        text.extend_from_slice(words[text.len() % words.len()].as_bytes());
    }
    text.extend_from_slice(b"end");
    std::fs::write(&file, &text).unwrap();
    let stdout = check_file(dir.path(), &file, 1);
    assert!(stdout.contains("error[compat-line-too-long]"), "{stdout}");
    assert!(
        stdout.contains("warning[compat-no-final-newline]"),
        "{stdout}"
    );
    assert!(stdout.len() < 100_000, "{} bytes of output", stdout.len());
    // Both add the final newline; the line stays too long for the robot.
    assert_eq!(rewrite_codes(&text), [0, 1]);
}

#[test]
fn a_line_of_one_word_repeated_keeps_a_bounded_number_of_findings() {
    // A finding every five bytes: 200,000 of them in one megabyte.
    let mut text = b"robotLocationDescription 1 ".to_vec();
    text.extend(std::iter::repeat_n(b"word ".as_slice(), 200_000).flatten());
    text.push(b'\n');
    checked(text, |checked| {
        let repeated = rules(checked)
            .iter()
            .filter(|&&rule| rule == "repeated-word")
            .count();
        assert_eq!(repeated, ekb::diagnostic::MAX_SHOWN_PER_RULE + 1);
    });
}

#[test]
fn a_nul_byte_is_a_control_character_and_is_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("nul.dat");
    std::fs::write(&file, b"preGestureMessageEnglish 1 Hel\0lo\n").unwrap();
    let stdout = check_file(dir.path(), &file, 1);
    assert!(
        stdout.contains("nul.dat:1:31: error[control-character]"),
        "{stdout}"
    );
    assert!(!stdout.contains('\0'));
    let [fmt, fix] = rewrite(b"preGestureMessageEnglish 1 Hel\0lo\n");
    assert_eq!(fmt.0, 0);
    assert_eq!(fix.0, 1);
    assert!(
        fix.1.contains(":1:31: error[control-character]"),
        "{}",
        fix.1
    );
}

/// Deterministic pseudo-random bytes.
fn noise(len: usize, mut state: u64) -> Vec<u8> {
    (0..len)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 24) as u8
        })
        .collect()
}

#[test]
fn random_binary_is_reported_not_fatal() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("random.dat");
    std::fs::write(&file, noise(256 * 1024, 0x5EED)).unwrap();
    let stdout = check_file(dir.path(), &file, 1);
    assert!(stdout.contains("error[invalid-utf8]"), "{stdout}");
    // Nothing raw from the file reaches the terminal.
    assert!(!has_unsafe(&stdout));
    // Rewriting it would lose the bad bytes.
    for (code, stderr) in rewrite(&noise(256 * 1024, 0x5EED)) {
        assert_eq!(code, 2);
        assert!(
            stderr.contains("is not valid UTF-8 (line 1, column "),
            "{stderr}"
        );
    }
}

#[test]
fn a_million_bad_lines_give_bounded_output() {
    // 50 MB of binary lines: every one an unknown key, most with invalid UTF-8.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("binary.dat");
    let mut bytes = noise(50_000_000, 42);
    for line in bytes.chunks_mut(50) {
        line.iter_mut().for_each(|b| {
            if matches!(*b, b'\n' | b' ' | b'\t' | b'#') {
                *b = b'x'
            }
        });
        line[0] = b'k';
        line[49] = b'\n';
    }
    std::fs::write(&file, &bytes).unwrap();
    let stdout = check_file(dir.path(), &file, 1);
    let unknown = stdout.matches("error[unknown-key]").count();
    assert_eq!(unknown, MAX_SHOWN_PER_RULE + 1, "the first ones and a note");
    assert!(stdout.contains("… and 999000 more `unknown-key` findings"));
    assert!(stdout.len() < 2_000_000, "{} bytes of output", stdout.len());
    // The summary counts every finding, shown or not.
    let summary = stdout.lines().last().unwrap();
    let errors: usize = summary
        .strip_prefix("Found ")
        .and_then(|rest| rest.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{summary}"));
    assert!(errors > 1_000_000, "{summary}");
    assert_eq!(rewrite_codes(&bytes), [2, 2], "not valid UTF-8");
}

#[test]
fn invalid_utf8_in_a_key_an_id_and_a_value() {
    let text = b"robot\xffLocation 1 2.0 3.0 0\n\
                 robotLocationDescription 1\xfe Roomba\n\
                 preGestureMessageEnglish 1 Hello \xc3\x28 there\n"
        .to_vec();
    for (code, stderr) in rewrite(&text) {
        assert_eq!(code, 2);
        assert!(
            stderr.contains("is not valid UTF-8 (line 1, column 6)"),
            "{stderr}"
        );
    }
    checked(text, |checked| {
        let utf8: Vec<u32> = checked
            .diagnostics
            .iter()
            .filter(|d| d.rule.name == "invalid-utf8")
            .map(|d| d.span.start)
            .collect();
        assert_eq!(utf8, [5, 53, 95]);
        let rules = rules(checked);
        assert!(rules.contains(&"unknown-key"), "{rules:?}");
        assert!(rules.contains(&"invalid-id"), "{rules:?}");
    });
}

#[test]
fn a_directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    refused(dir.path(), dir.path(), "is a directory");
}

#[test]
fn a_missing_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    refused(dir.path(), &dir.path().join("nope.dat"), "no such file");
}

#[cfg(unix)]
#[test]
fn an_unreadable_file_is_refused() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("secret.dat");
    std::fs::write(&file, "tourSpecification 1 1\n").unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o000)).unwrap();
    if std::fs::read(&file).is_ok() {
        return; // running as root: permissions do not apply
    }
    refused(dir.path(), &file, "permission denied");
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_waiting_for_a_writer() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.dat");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|status| status.success()) {
        return; // no mkfifo here
    }
    refused(dir.path(), &fifo, "not a regular file");
}

#[cfg(unix)]
#[test]
fn dev_zero_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    refused(dir.path(), Path::new("/dev/zero"), "not a regular file");
}

#[test]
fn an_id_of_forty_digits_is_invalid() {
    let id = "1".repeat(40);
    let text = format!("robotLocationDescription {id} Roomba\n");
    // fmt keeps the line as written, fix cannot guess the id.
    assert_eq!(rewrite_codes(text.as_bytes()), [0, 1]);
    checked(text.into_bytes(), |checked| {
        let invalid = checked
            .diagnostics
            .iter()
            .find(|d| d.rule.name == "invalid-id")
            .expect("invalid-id");
        assert_eq!(invalid.span.len(), 40);
    });
}

#[test]
fn a_float_of_four_hundred_digits_is_invalid() {
    let huge = format!("1{}", "0".repeat(399));
    let text = format!("robotLocation 1 {huge} 1.0 0\n");
    assert_eq!(rewrite_codes(text.as_bytes()), [0, 1]);
    checked(text.into_bytes(), |checked| {
        let invalid = checked
            .diagnostics
            .iter()
            .find(|d| d.rule.name == "invalid-number")
            .expect("invalid-number");
        assert_eq!(invalid.span.len(), 400);
    });
    // A long but finite number is fine.
    let long = format!("0.{}1", "0".repeat(398));
    let text = format!("robotLocation 1 {long} 1.0 0\n");
    checked(text.into_bytes(), |checked| {
        assert!(!rules(checked).contains(&"invalid-number"));
    });
}

#[test]
fn a_million_stop_tour() {
    let mut text = generate(&Spec::new(3));
    text.truncate(text.rfind("tourSpecification").unwrap());
    text.push_str("tourSpecification 1000000");
    for i in 0..1_000_000 {
        text.push_str([" 1", " 2", " 3", " 4"][i % 4]);
    }
    text.push('\n');
    assert_eq!(rewrite_codes(text.as_bytes()), [0, 1]);
    checked(text.into_bytes(), |checked| {
        let count = |rule| rules(checked).iter().filter(|&&r| r == rule).count();
        assert_eq!(count("tour-too-long"), 1);
        assert_eq!(count("tour-count-mismatch"), 0);
        // Location 4 does not exist: 250,000 findings, of which some are kept and the
        // first are shown, with a note for the rest.
        assert!(count("tour-unknown-location") >= MAX_SHOWN_PER_RULE);
        let shown = checked
            .shown()
            .filter(|d| d.rule.name == "tour-unknown-location")
            .count();
        assert_eq!(shown, MAX_SHOWN_PER_RULE + 1);
        let other_errors = checked
            .diagnostics
            .iter()
            .filter(|d| d.severity() == ekb::Severity::Error)
            .filter(|d| d.rule.name != "tour-unknown-location")
            .count();
        assert_eq!(checked.summary().errors, 250_000 + other_errors);
    });
}

fn with_tour(stops: usize) -> Vec<u8> {
    let mut text = generate(&Spec::new(stops));
    text.truncate(text.rfind("tourSpecification").unwrap());
    text.push_str(&format!("tourSpecification {stops}"));
    for id in 1..=stops {
        text.push_str(&format!(" {id}"));
    }
    text.push('\n');
    text.into_bytes()
}

#[test]
fn a_tour_of_twenty_stops_is_fine_and_of_twenty_one_is_not() {
    assert_eq!(rewrite_codes(&with_tour(20)), [0, 0]);
    assert_eq!(rewrite_codes(&with_tour(21)), [0, 1]);
    checked(with_tour(20), |checked| {
        assert_eq!(rules(checked), Vec::<&str>::new());
    });
    checked(with_tour(21), |checked| {
        assert_eq!(rules(checked), ["tour-too-long"]);
        assert!(checked.has_errors());
    });
}

#[test]
fn control_and_bidi_characters_never_reach_the_terminal_raw() {
    let dir = tempfile::tempdir().unwrap();
    // A file name, keys and values with an escape sequence, a bidi override and isolate,
    // a carriage return and a bell.
    let file = dir.path().join("evil\u{202E}.dat");
    std::fs::write(
        &file,
        "pre\u{1b}[31mGesture 1 x\n\
         preGestureMessageEnglish 1 Hi \u{202E}there\u{2066} \u{7} the the end\r\n\
         robotLocationDescription 1 \u{1b}]0;pwned\u{7}\n",
    )
    .unwrap();
    for format in ["human", "concise", "json", "github", "sarif"] {
        let output = ekb(dir.path())
            .args(["check", "--format", format])
            .arg(&file)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(1), "{format}");
        let stdout = String::from_utf8(output.stdout).unwrap();
        let raw: Vec<char> = stdout
            .chars()
            .filter(|&c| c != '\n' && ekb::render::escape::is_unsafe(c))
            .collect();
        assert!(raw.is_empty(), "{format} printed {raw:?}");
        assert!(stdout.contains("error"), "{format}: {stdout}");
    }
    // The verbose trace on standard error quotes the file too.
    let output = ekb(dir.path())
        .args(["-v", "check"])
        .arg(&file)
        .output()
        .unwrap();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(
        stderr.contains("ekb: read preGestureMessageEnglish"),
        "{stderr}"
    );
    assert!(
        !stderr
            .chars()
            .any(|c| c != '\n' && ekb::render::escape::is_unsafe(c)),
        "{stderr}"
    );
}

/// A knowledge base whose description, messages, cultural knowledge and name hold escape
/// sequences, C1 controls and bidi overrides, and a second version of it for `diff`.
fn evil_files(dir: &Path) -> (std::path::PathBuf, std::path::PathBuf) {
    let old = "robotLocationDescription 1 Evil\u{1b}[31m room\u{202E}\n\
               robotLocation 1 1.0 2.0 0\n\
               gestureTarget 1 0.0 0.0 0.0\n\
               preGestureMessageEnglish 1 Hi \u{202E}there\u{2066} \u{7} end\n\
               postGestureMessageEnglish 1 \u{1b}]0;pwned\u{7}\n\
               culturalKnowledge 1 a\u{9b}b  \n\
               robotLocationDescription 2 Lab\u{200F}\n\
               tourSpecification 2 1 2\n";
    let new = old
        .replace("pwned", "owned\u{1b}[2J")
        .replace("Lab", "L\u{1b}[1mab");
    // Trailing blanks on line 6, for fix to remove.
    let (old_file, new_file) = (dir.join("evil\u{202E}.dat"), dir.join("new\u{1b}.dat"));
    std::fs::write(&old_file, old).unwrap();
    std::fs::write(&new_file, new).unwrap();
    (old_file, new_file)
}

#[test]
fn tables_tours_diffs_and_rewrites_never_print_raw_control_characters() {
    let dir = tempfile::tempdir().unwrap();
    let (old, new) = evil_files(dir.path());
    let runs: [(&[&str], &[&Path], i32, &str); 10] = [
        (
            &["locations"],
            &[&old],
            0,
            "Evil\\u{001B}[31m room\\u{202E RIGHT-TO-LEFT OVERRIDE}",
        ),
        (&["show", "1"], &[&old], 0, "\\u{001B}]0;pwned\\u{0007}"),
        (
            &["show", "2"],
            &[&old],
            0,
            "Lab\\u{200F RIGHT-TO-LEFT MARK}",
        ),
        (
            &["tour", "--lang", "en"],
            &[&old],
            0,
            "Hi \\u{202E RIGHT-TO-LEFT OVERRIDE}there",
        ),
        (&["translations"], &[&old], 0, "Evil\\u{001B}[31m room"),
        (
            &["translations", "--lang", "zu", "--format", "csv"],
            &[&old],
            0,
            "Hi \\u{202E RIGHT-TO-LEFT OVERRIDE}there",
        ),
        (
            &["diff"],
            &[&old, &new],
            1,
            "L\\u{001B}[1mab\\u{200F RIGHT-TO-LEFT MARK}",
        ),
        (&["export", "--allow-errors"], &[&old], 0, "a\\u009bb"),
        // The diffs of fmt and fix, coloured as on a terminal.
        (
            &["--color", "always", "fmt", "--check"],
            &[&old],
            1,
            "\\u{001B}]0",
        ),
        (
            &["--color", "always", "fix", "--diff"],
            &[&old],
            1,
            "a\\u{009B}b",
        ),
    ];
    for (args, files, code, expected) in runs {
        let output = ekb(dir.path()).args(args).args(files).output().unwrap();
        let (stdout, stderr) = (
            String::from_utf8(output.stdout).unwrap(),
            String::from_utf8(output.stderr).unwrap(),
        );
        assert_eq!(output.status.code(), Some(code), "{args:?}: {stderr}");
        // Colour is the one escape sequence ekb writes itself.
        let stdout = stdout.replace("\u{1b}[0m", "");
        let stdout = ["\u{1b}[31m", "\u{1b}[32m", "\u{1b}[36m"]
            .iter()
            .fold(stdout, |out, colour| out.replace(colour, ""));
        assert!(!has_unsafe(&stdout), "{args:?} printed raw: {stdout:?}");
        assert!(!has_unsafe(&stderr), "{args:?} printed raw: {stderr:?}");
        assert!(stdout.contains(expected), "{args:?}: {stdout}");
    }
}

#[test]
fn fmt_refuses_a_stray_carriage_return_in_one_line() {
    let [(fmt, stderr), (fix, _)] = rewrite(b"robotLocationDescription 1 A\r\n# note\r\r\n");
    assert_eq!(fmt, 2);
    assert!(
        stderr.contains("line 2 (`# note\\u{000D}`) ends in a stray carriage return"),
        "{stderr}"
    );
    assert!((0..=1).contains(&fix));
}

#[test]
fn one_fix_run_fixes_more_findings_of_a_rule_than_check_keeps() {
    // 20,000 lines with trailing blanks: twice the findings a check keeps of one rule.
    let lines = 2 * ekb::source::MAX_KEPT_PER_RULE;
    let text: String = (1..=lines)
        .map(|id| format!("robotLocationDescription {id} Room {id}  \n"))
        .collect();
    let [_, (code, stderr)] = rewrite(text.as_bytes());
    assert_eq!(code, 1, "missing fields are left: {stderr}");
    assert!(
        // And, 20,000 ascending ids being a tree too deep for the reader, their order.
        stderr.contains(&format!(
            "fixed 1 compat-reader-crash, {lines} trailing-whitespace"
        )),
        "{stderr}"
    );
    assert!(!stderr.contains("trailing-whitespace]"), "{stderr}");
}
