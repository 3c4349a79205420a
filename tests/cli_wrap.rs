//! Human output wraps at the terminal's width, at `COLUMNS` when it is set, and at 100
//! columns when standard output is no terminal (issue 13, item 4).

mod output_support;

use output_support::ekb;
use std::process::Command as Process;

/// A location whose isiZulu and Kinyarwanda messages are placeholders: each finding's help
/// quotes the long English message, which has to wrap.
const FILE: &str = "\
robotLocationDescription      1 Entrance
robotLocation                 1 2.6 8.1 -90
gestureTarget                 1 0.0 0.0 0.0
preGestureMessageEnglish      1 Welcome to the robotics lab, where you will meet the robots we build and the people who teach them to guide visitors
preGestureMessageIsiZulu      1 No message in isiZulu
preGestureMessageKinyarwanda  1 No message in Kinyarwanda
postGestureMessageEnglish     1 I hope you enjoy the tour of the lab and that you come back to see what the robots have learned by then
postGestureMessageIsiZulu     1 No message in isiZulu
postGestureMessageKinyarwanda 1 No message in Kinyarwanda
tourSpecification 1 1
";

/// The lines of a human report that wrap: messages and helps (a snippet's lines are the
/// file's, never wrapped).
fn wrapping_lines(report: &str) -> Vec<&str> {
    let starts = ["  help:", "        ", "  ⚠", "  ×", "  │", "  ☞"];
    report
        .lines()
        .filter(|line| starts.iter().any(|start| line.starts_with(start)))
        .collect()
}

/// The width of the widest of `lines`, in characters.
fn widest(lines: &[&str]) -> usize {
    lines.iter().map(|line| line.chars().count()).max().unwrap()
}

fn setup() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), FILE).unwrap();
    dir
}

#[test]
fn wraps_at_100_columns_when_not_a_terminal() {
    let dir = setup();
    let output = ekb(dir.path())
        .args(["check", "--show-all", "kb.dat"])
        .output()
        .unwrap();
    let report = String::from_utf8(output.stdout).unwrap();
    let lines = wrapping_lines(&report);
    assert!(lines.len() > 8, "{report}");
    assert!((90..=100).contains(&widest(&lines)), "{report}");
}

#[test]
fn wraps_at_columns_when_set() {
    let dir = setup();
    let output = ekb(dir.path())
        .env("COLUMNS", "60")
        .args(["check", "--show-all", "kb.dat"])
        .output()
        .unwrap();
    let report = String::from_utf8(output.stdout).unwrap();
    let lines = wrapping_lines(&report);
    assert!((50..=60).contains(&widest(&lines)), "{report}");
}

#[test]
fn a_grouped_rule_and_the_summary_wrap_between_words() {
    let dir = setup();
    let output = ekb(dir.path())
        .env("COLUMNS", "60")
        .args(["check", "kb.dat"])
        .output()
        .unwrap();
    let report = String::from_utf8(output.stdout).unwrap();
    // Four placeholders, one paragraph; nothing of the file drawn, so every line wraps.
    assert!(report.starts_with("warning[untranslated-message]: 4 findings, on lines"));
    let lines: Vec<&str> = report.lines().collect();
    assert!((50..=60).contains(&widest(&lines)), "{report}");
    let summary = &report[report.find("\nFound").unwrap() + 1..];
    assert_eq!(
        summary.split_whitespace().collect::<Vec<_>>().join(" "),
        "Found 4 warnings: 4 untranslated-message; as the robot's software of document D5.4.2 \
         reads it (d5.4.2)"
    );
    // Between words: each line but the first starts with the indent, then a word.
    assert!(
        summary
            .lines()
            .skip(1)
            .all(|line| line.starts_with("  ") && !line[2..].starts_with(' ')),
        "{summary}"
    );
}

#[test]
fn wraps_at_the_terminals_width() {
    // `script` (util-linux) runs ekb on a pseudo-terminal of 70 columns.
    if Process::new("script").arg("--version").output().is_err() {
        eprintln!("skipped: no `script` to make a terminal");
        return;
    }
    let dir = setup();
    let ekb = assert_cmd::cargo::cargo_bin("ekb");
    let shell = format!(
        "stty rows 40 cols 70; {} --color never check --show-all kb.dat",
        ekb.display()
    );
    let output = Process::new("script")
        .args(["-qec", &shell, "/dev/null"])
        .current_dir(dir.path())
        .env_remove("COLUMNS")
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .output()
        .unwrap();
    let report = String::from_utf8(output.stdout).unwrap().replace('\r', "");
    let lines = wrapping_lines(&report);
    assert!(lines.len() > 8, "{report}");
    assert!((60..=70).contains(&widest(&lines)), "{report}");
}

#[test]
fn locations_never_part_a_language_from_its_mark() {
    let dir = setup();
    for columns in ["60", "80", "100"] {
        let output = ekb(dir.path())
            .env("COLUMNS", columns)
            .args(["locations", "kb.dat"])
            .output()
            .unwrap();
        let table = String::from_utf8(output.stdout).unwrap();
        for line in table.lines() {
            let cells: Vec<&str> = line.split(['│', '┆']).map(str::trim).collect();
            assert!(
                !cells.iter().any(|cell| ["EN", "ZU", "RW"]
                    .iter()
                    .any(|code| cell.ends_with(&format!(" {code}")) || cell == code)),
                "a code parted from its mark at {columns} columns:\n{table}"
            );
        }
    }
}

#[test]
fn show_wraps_its_title_and_findings_at_columns() {
    let dir = setup();
    let long = FILE.replace("Entrance", &"Entrance hall ".repeat(12));
    std::fs::write(dir.path().join("kb.dat"), long).unwrap();
    let output = ekb(dir.path())
        .env("COLUMNS", "60")
        .args(["show", "1", "kb.dat"])
        .output()
        .unwrap();
    let shown = String::from_utf8(output.stdout).unwrap();
    assert!(shown.contains("\nFindings at this location"), "{shown}");
    assert!(
        shown.lines().all(|line| line.chars().count() <= 60),
        "a line past 60 columns:\n{shown}"
    );
}
