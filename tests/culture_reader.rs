//! The culture knowledge base as the robot's own reader loads it (`CultureKnowledgeBase`
//! in the robot's behaviour controller): what it holds for each key, and the findings
//! that warn of it. Each case in `tests/fixtures/mission/reader/<case>/` holds a types
//! file and a knowledge base; the values asserted here are those the robot's reader,
//! compiled outside ROS, printed for the same files.

use std::path::{Path, PathBuf};

use ekb::mission::check::{check_together, MissionSources};
use ekb::mission::culture::{CultureKnowledgeBase, Held, ValueType, ValueTypes, LINE_BUFFER};
use ekb::rules::selection::RuleSet;
use ekb::source::LineIndex;
use ekb::SourceFile;

const CULTURE: &str = "cultureKnowledgeBaseInput.dat";
const TYPES: &str = "cultureKnowledgeValueTypesInput.dat";

fn case(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/mission/reader")
        .join(name)
}

fn read(name: &str, file: &str) -> String {
    let path = case(name).join(file);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// What the robot holds for `key` in the case `name`: `Text`, `Number`, or the variant.
fn held(name: &str, key: &str) -> String {
    let (types, culture) = (read(name, TYPES), read(name, CULTURE));
    let types = ValueTypes::parse(&types, LINE_BUFFER);
    let culture = CultureKnowledgeBase::parse(&culture, LINE_BUFFER);
    match culture.held(&types, key) {
        Held::Text(text, _) => format!("text {text:?}"),
        Held::Number(number, _) => format!("number {number}"),
        other => format!("{other:?}"),
    }
}

/// The findings of `rule` in the case, as `(file, line, column, message)`.
fn findings(name: &str, rule: &str) -> Vec<(String, u32, u32, String)> {
    let sources =
        [TYPES, CULTURE].map(|file| SourceFile::from_bytes(file, read(name, file).into_bytes()));
    let checked = check_together(
        &MissionSources {
            culture_types: Some(&sources[0]),
            culture_kb: Some(&sources[1]),
            ..MissionSources::default()
        },
        &RuleSet::default(),
    );
    let mut out = Vec::new();
    for file in &checked {
        let text = file.source.text();
        for d in file.diagnostics.iter().filter(|d| d.rule.name == rule) {
            let at = LineIndex::new(text).position(text, d.span.start);
            let name = file.source.name().to_string();
            out.push((name, at.line, at.column, d.message.clone()));
        }
    }
    out
}

fn places(found: &[(String, u32, u32, String)]) -> Vec<(&str, u32, u32)> {
    found
        .iter()
        .map(|(file, line, column, _)| (file.as_str(), *line, *column))
        .collect()
}

#[test]
fn a_types_file_that_starts_with_a_comment_crashes_the_robot() {
    let found = findings("first-line-comment", "culture-unknown-type");
    assert_eq!(places(&found), [(TYPES, 1, 1)]);
    assert!(found[0].3.contains("crashes"), "{}", found[0].3);
    // A comment or a blank line after the first declaration is harmless.
    assert!(findings("comment-after-first-line", "culture-unknown-type").is_empty());
    assert_eq!(
        held("comment-after-first-line", "utilityPhraseEnglish1"),
        "text \"Hello there\""
    );
}

#[test]
fn a_types_file_that_declares_nothing_crashes_the_robot() {
    let found = findings("empty-types", "culture-unknown-type");
    assert_eq!(places(&found), [(TYPES, 1, 1)]);
    assert!(found[0].3.contains("crashes"), "{}", found[0].3);
    assert_eq!(
        ValueTypes::parse("", LINE_BUFFER).crash.map(|s| s.start),
        Some(0)
    );
    assert_eq!(
        ValueTypes::parse("phraseLanguage WORD\n", LINE_BUFFER).crash,
        None
    );
}

#[test]
fn a_types_line_without_a_type_takes_the_type_of_the_line_before() {
    assert_eq!(
        held("type-borrowed", "utilityPhraseEnglish2"),
        "text \"Goodbye for now\""
    );
    let types = ValueTypes::parse("a WORD\nb\nc Phrase\nd\n", LINE_BUFFER);
    assert_eq!(types.type_of("b"), Some(ValueType::Word));
    // An unknown type declares nothing, and a line after it borrows nothing.
    assert_eq!(types.type_of("c"), None);
    assert_eq!(types.type_of("d"), None);
    let found = findings("type-borrowed", "culture-unknown-type");
    assert_eq!(places(&found), [(TYPES, 3, 1)]);
    assert!(found[0].3.contains("declares it PHRASE"), "{}", found[0].3);
}

#[test]
fn a_value_that_does_not_read_keeps_the_one_before_and_a_missing_one_is_borrowed() {
    // `passingDistance five` does not read with %d: the robot keeps 5.
    assert_eq!(held("stale-values", "passingDistance"), "number 5");
    // %d reads a long and cuts it to an int.
    assert_eq!(held("stale-values", "bowExtent"), "number 1");
    assert_eq!(
        held("stale-values", "expressionLoudness"),
        "number 2147483647"
    );
    // `deicticShape` alone reads the value word of the line before.
    assert_eq!(held("stale-values", "deicticShape"), "text \"English\"");
    let found = findings("stale-values", "culture-type-mismatch");
    assert_eq!(
        places(&found),
        [(CULTURE, 2, 17), (CULTURE, 3, 11), (CULTURE, 6, 1)]
    );
    assert!(found[1].3.contains("holds 1"), "{}", found[1].3);
}

#[test]
fn a_phrase_without_a_letter_is_copied_from_the_line_buffer_and_indentation_shifts_it() {
    // `utilityPhraseEnglish2 ...`: the copy runs past the line's end into what the
    // longer line before left in the buffer.
    assert_eq!(
        held("phrase-leftovers", "utilityPhraseEnglish2"),
        "text \"there\""
    );
    // An indented line: the key's length is counted from the line's start.
    assert_eq!(
        held("phrase-leftovers", "utilityPhraseEnglish3"),
        "text \"h3 Goodbye\""
    );
    let found = findings("phrase-leftovers", "culture-type-mismatch");
    assert_eq!(places(&found), [(CULTURE, 2, 1), (CULTURE, 3, 3)]);
    assert!(found[1].3.contains("h3 Goodbye"), "{}", found[1].3);
    // A copy that starts past everything the file wrote is unknown, not empty.
    let types = ValueTypes::parse("utilityPhraseEnglish1 PHRASE\n", LINE_BUFFER);
    let culture = CultureKnowledgeBase::parse("utilityPhraseEnglish1 ...\n", LINE_BUFFER);
    assert!(matches!(
        culture.held(&types, "utilityPhraseEnglish1"),
        Held::Unreadable(_)
    ));
}

#[test]
fn a_last_types_line_that_redeclares_a_key_wins_when_the_first_value_line_is_no_key() {
    // The robot still holds the types file's last declaration; a first line whose key
    // it does not find stores that declaration over the key's.
    assert_eq!(held("redeclared-last", "deicticShape"), "text \"PALM\"");
    assert_eq!(
        held("redeclared-last-first-line-found", "deicticShape"),
        "text \"PALM UPWARDS\""
    );
}
