//! Size on hostile files (issue 12, item 5): a value of megabytes shows as a few hundred
//! characters and how many more; a tour of many thousand stops shows its first stops, as
//! `check` shows the first findings of a rule. Output stays small whatever the file, which is
//! what keeps every command linear (the times are in BENCHMARKS.md, never in tests).

mod output_support;

use std::path::Path;

use ekb::render::clip::SHOWN_CHARS;
use output_support::ekb;

/// Two locations, location 1's English message before the gesture and its description
/// `long` and `description`, and a tour of `tour` stops alternating between them.
fn file(message: &str, description: &str, stops: usize) -> String {
    let mut text = String::new();
    for id in 1..=2 {
        let (message, description) = match id {
            1 => (message, description),
            _ => ("Hello", "Roomba"),
        };
        text.push_str(&format!(
            "robotLocationDescription      {id} {description}\n\
             robotLocation                 {id} 1.0 2.0 90\n\
             gestureTarget                 {id} 0.0 0.0 0.0\n\
             preGestureMessageEnglish      {id} {message}\n\
             preGestureMessageIsiZulu      {id} No message in isiZulu\n\
             preGestureMessageKinyarwanda  {id} Muraho\n\
             postGestureMessageEnglish     {id} Bye\n\
             postGestureMessageIsiZulu     {id} Sala kahle\n\
             postGestureMessageKinyarwanda {id} Murabeho\n"
        ));
    }
    let ids: Vec<String> = (0..stops).map(|i| (1 + i % 2).to_string()).collect();
    text.push_str(&format!("tourSpecification {stops} {}\n", ids.join(" ")));
    text
}

/// A megabyte of words, none repeated twice in a row: 999,999 characters.
fn megabyte() -> String {
    "the robot greets every visitor ".repeat(32_259)[..999_999].to_string()
}

fn run(dir: &Path, args: &[&str]) -> String {
    let output = ekb(dir).args(args).output().unwrap();
    assert!(output.status.code().is_some_and(|c| c <= 1), "{args:?}");
    String::from_utf8(output.stdout).unwrap()
}

/// Whether `output` shows [`megabyte`] cut: its first [`SHOWN_CHARS`] characters and `…`,
/// then (in quotes or not) how many more there are.
fn shows_megabyte_cut(output: &str) -> bool {
    let head = format!("{}…", &megabyte()[..SHOWN_CHARS]);
    let note = format!(" ({} more characters)", 999_999 - SHOWN_CHARS);
    output.contains(&format!("{head}{note}")) || output.contains(&format!("{head}\"{note}"))
}

#[test]
fn a_megabyte_message_shows_a_few_hundred_characters_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), file(&megabyte(), "Entrance", 2)).unwrap();
    for args in [
        &["show", "1", "kb.dat"][..],
        &["tour", "kb.dat"],
        &["tour", "--lang", "zu", "kb.dat"],
        &["check", "kb.dat"],
        &["check", "--format", "concise", "kb.dat"],
    ] {
        let stdout = run(dir.path(), args);
        assert!(stdout.len() < 20_000, "{args:?}: {} bytes", stdout.len());
        // `check` wraps the quote over several lines; the others show it on one.
        if args[0] != "check" {
            assert!(shows_megabyte_cut(&stdout), "{args:?}: {stdout}");
        }
    }
    // The help of the placeholder quotes the English message to translate.
    let json = run(dir.path(), &["check", "--format", "json", "kb.dat"]);
    let json: serde_json::Value = serde_json::from_str(&json).unwrap();
    let helps: Vec<&str> = json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|d| d["help"].as_str())
        .collect();
    assert!(
        helps.iter().any(|help| shows_megabyte_cut(help)),
        "{helps:#?}"
    );
}

#[test]
fn a_megabyte_description_is_cut_in_the_tables() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), file("Hello", &megabyte(), 2)).unwrap();
    for args in [&["locations", "kb.dat"][..], &["show", "1", "kb.dat"]] {
        let stdout = run(dir.path(), args);
        assert!(stdout.len() < 20_000, "{args:?}: {} bytes", stdout.len());
        assert!(shows_megabyte_cut(&stdout), "{args:?}: {stdout}");
    }
}

#[test]
fn a_long_tour_shows_its_first_stops_and_counts_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), file("Hello", "Entrance", 5000)).unwrap();
    let tour = run(dir.path(), &["tour", "kb.dat"]);
    let stops = tour
        .lines()
        .filter(|line| line.starts_with("Stop "))
        .count();
    assert_eq!(stops, 1000);
    assert!(tour.contains(
        "\n… and 4000 more stops, not shown (ekb shows the first 1000; `ekb tour --format json` lists them all)\n"
    ));
    let header = tour.lines().next().unwrap();
    assert!(header.starts_with("Tour of kb.dat in English: 5000 stops (1 → 2 → 1 → 2"));
    assert!(
        header.ends_with("2 … and 4900 more), as reader d5.4.2 loads it"),
        "{header}"
    );
    // The counts are of every stop, shown or not.
    assert!(
        tour.ends_with("English: 10000 of 10000 messages written\n"),
        "{tour}"
    );
    let json = run(dir.path(), &["tour", "--format", "json", "kb.dat"]);
    let json: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(json["stops"].as_array().unwrap().len(), 5000);
    assert_eq!(json["messages"], 10000);
}

#[test]
fn positions_on_a_long_tour_are_cut_in_locations_and_show() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), file("Hello", "Entrance", 5000)).unwrap();
    let table = run(dir.path(), &["locations", "kb.dat"]);
    assert!(table.contains("1 (start), 3, 5, 7"), "{table}");
    assert!(table.contains("199 … and 2400 more"), "{table}");
    let show = run(dir.path(), &["show", "2", "kb.dat"]);
    // Its heading is wrapped at the width: read as one text.
    let show = show.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(show.contains("stops 2, 4, 6, "), "{show}");
    assert!(
        show.contains("200 … and 2400 more of 5000 on the tour"),
        "{show}"
    );
}
