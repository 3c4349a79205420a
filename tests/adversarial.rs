//! Hostile and broken inputs (issue 5): each gets a clear diagnostic, or a one-line error
//! with exit code 2 — never a panic, a hang, unbounded output, or another exit code.
//! Big inputs are generated in a temporary folder, never committed.

use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use ekb::check::{check, Checked, MAX_SHOWN_PER_RULE};
use ekb::generate::{generate, Spec};
use ekb::model::build::Options;
use ekb::SourceFile;
use predicates::prelude::*;

/// `ekb` run in an empty folder (no configuration is found there), with a time limit so
/// that a hang fails the test instead of blocking it.
fn ekb(dir: &Path) -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
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

/// Runs `ekb check FILE`, expecting exit 2 and one line on standard error with `reason`.
fn refused(dir: &Path, file: &Path, reason: &str) {
    ekb(dir)
        .arg("check")
        .arg(file)
        .assert()
        .code(2)
        .stdout("")
        .stderr(
            predicate::str::contains(reason)
                .and(predicate::function(|err: &str| err.lines().count() == 1)),
        );
}

#[test]
fn a_one_megabyte_line_is_too_long_and_that_is_all() {
    let mut text = b"preGestureMessageEnglish      1 ".to_vec();
    text.extend(std::iter::repeat_n(b"robots ".as_slice(), 150_000).flatten());
    text.push(b'\n');
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
        stdout.contains("error[compat-no-final-newline]"),
        "{stdout}"
    );
    assert!(stdout.len() < 100_000, "{} bytes of output", stdout.len());
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
        assert_eq!(repeated, ekb::check::MAX_KEPT_PER_RULE);
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
    assert!(!stdout
        .chars()
        .any(|c| c != '\n' && ekb::render::escape::is_unsafe(c)));
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
}

#[test]
fn invalid_utf8_in_a_key_an_id_and_a_value() {
    let text = b"robot\xffLocation 1 2.0 3.0 0\n\
                 robotLocationDescription 1\xfe Roomba\n\
                 preGestureMessageEnglish 1 Hello \xc3\x28 there\n"
        .to_vec();
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
