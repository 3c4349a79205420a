//! The promise of `ekb check --reader V`: wherever version V of the robot's reader loads
//! something other than what the file says, the check reports an error (trailing blanks
//! kept in a text excepted: a warning). The reader layer's simulation of each version
//! (`ekb::reader::load`, the view of `export --as-loaded`) is the oracle; the written model
//! is what `ekb` reads from the file.

use ekb::model::build::Options;
use ekb::model::{Key, KnowledgeBase, Language, Phase};
use ekb::reader::line::LoadedValue;
use ekb::reader::{self, Loaded};
use ekb::robot::Reader;
use ekb::source::LineIndex;
use ekb::{Severity, SourceFile};
use proptest::prelude::*;

/// A place where the robot's view and the file differ: what, and the offsets of the lines
/// involved (the line the file's value is on, the line the robot took its value from).
struct Difference {
    what: String,
    at: Vec<u32>,
}

/// Every place where the robot's view and the file differ.
fn differences(kb: &KnowledgeBase<'_>, loaded: &Loaded, text: &str) -> Vec<Difference> {
    let reader = loaded.reader;
    let mut found = Vec::new();
    let differ = |what: String, at: Vec<u32>| Difference { what, at };
    for robot in loaded.locations.values() {
        let written = u32::try_from(robot.id).ok().and_then(|id| kb.location(id));
        if written.is_none() {
            let lines = Key::ALL
                .iter()
                .filter_map(|&key| loaded.field(robot, key))
                .map(|field| field.line.start)
                .collect();
            found.push(differ(
                format!("location {} only in the robot's view", robot.id),
                lines,
            ));
        }
    }
    let loaded_text = |value: &LoadedValue| match value {
        LoadedValue::Text(span) => Some(&text.as_bytes()[span.range()]),
        _ => None,
    };
    for location in kb.locations() {
        let Some(robot) = loaded.locations.get(&(location.id as i32)) else {
            found.push(differ(
                format!("location {} not in the robot's view", location.id),
                vec![location.first_line.start],
            ));
            continue;
        };
        let robot_line = |key: Key| loaded.field(robot, key).map(|field| field.line.start);
        let lines = |written: Option<u32>, key: Key| -> Vec<u32> {
            written.into_iter().chain(robot_line(key)).collect()
        };
        let mut texts: Vec<Key> = Phase::ALL
            .into_iter()
            .flat_map(|phase| Language::ALL.map(|language| Key::for_message(phase, language)))
            .collect();
        texts.push(Key::RobotLocationDescription);
        for key in texts {
            let written = location.text_value(key);
            let held = loaded
                .field(robot, key)
                .map(|field| loaded_text(&field.value).map(String::from_utf8_lossy));
            let same = match (written, &held) {
                (None, None) => true,
                (Some(written), Some(Some(held))) => written.value == held,
                _ => false,
            };
            if !same {
                found.push(differ(
                    format!(
                        "{} of {}: {:?} vs {held:?}",
                        key.name(),
                        location.id,
                        written.map(|v| v.value)
                    ),
                    lines(written.map(|v| v.span.start), key),
                ));
            }
        }
        let numbers = |key: Key| loaded.field(robot, key).map(|field| field.value);
        // The key of the line the pose was read from (a later line of the other pose key
        // may have been rejected).
        let pose_line_key = |at: u32| {
            let line_start = text[..at as usize].rfind('\n').map_or(0, |i| i + 1);
            text[line_start..].split_whitespace().next().unwrap_or("")
        };
        let written_pose = location
            .pose
            .filter(|pose| pose_line_key(pose.span.start) == reader.pose_key().name())
            .map(|pose| {
                (
                    [pose.value.x, pose.value.y, pose.value.theta],
                    pose.span.start,
                )
            });
        let written_target = location.gesture_target.map(|target| {
            (
                [target.value.x, target.value.y, target.value.z],
                target.span.start,
            )
        });
        for (key, written) in [
            (reader.pose_key(), written_pose),
            (Key::GestureTarget, written_target),
        ] {
            let value = written.map(|(numbers, _)| LoadedValue::Numbers(numbers.map(|n| n as f32)));
            if value != numbers(key) {
                let mut at = lines(written.map(|(_, at)| at), key);
                // A pose the robot does not read: the line with the other pose key.
                at.extend(location.pose.map(|pose| pose.span.start));
                found.push(differ(
                    format!(
                        "{} of {}: {value:?} vs {:?}",
                        key.name(),
                        location.id,
                        numbers(key)
                    ),
                    at,
                ));
            }
        }
        if reader.reads(Key::GestureArm) {
            let written = location.gesture_arm;
            let held = loaded
                .field(robot, Key::GestureArm)
                .map(|f| loaded_text(&f.value));
            if held != written.map(|arm| Some(arm.value.name().as_bytes())) {
                found.push(differ(
                    format!("gestureArm of {}: {held:?}", location.id),
                    lines(written.map(|v| v.span.start), Key::GestureArm),
                ));
            }
        }
        if reader.reads(Key::CulturalKnowledge) {
            let written_value = location.cultural_knowledge();
            let written: Option<Vec<&str>> =
                written_value.map(|_| location.cultural_words().collect());
            let held: Option<Vec<&str>> =
                loaded
                    .field(robot, Key::CulturalKnowledge)
                    .map(|field| match &field.value {
                        LoadedValue::Words(words) => {
                            words.iter().map(|span| &text[span.range()]).collect()
                        }
                        _ => vec!["<undefined>"],
                    });
            if written != held {
                found.push(differ(
                    format!(
                        "culturalKnowledge of {}: {written:?} vs {held:?}",
                        location.id
                    ),
                    lines(written_value.map(|v| v.span.start), Key::CulturalKnowledge),
                ));
            }
        }
    }
    let written_tour = kb.tour.as_ref().map(|tour| {
        let stops: Vec<Option<i32>> = tour.stops().map(|stop| Some(stop.value as i32)).collect();
        stops
    });
    let loaded_tour = loaded.tour.as_ref().map(|tour| tour.stops.clone());
    if written_tour != loaded_tour {
        let at = kb
            .tour
            .iter()
            .map(|tour| tour.span.start)
            .chain(loaded.tour.iter().map(|tour| tour.line.start))
            .collect();
        found.push(differ(
            format!("tour {written_tour:?} vs {loaded_tour:?}"),
            at,
        ));
    }
    found
}

/// Asserts the promise on `text` for every version of the reader: where the robot's view
/// differs, an error on one of the lines involved (or, for blanks kept at the end of a
/// text, a warning there).
fn assert_differences_are_reported(text: &str) {
    let source = SourceFile::from_bytes("any", text.as_bytes().to_vec());
    let index = LineIndex::new(source.text());
    for version in Reader::ALL {
        let options = Options {
            reader: Some(version),
            ..Options::default()
        };
        let checked = ekb::check(&source, &options);
        let loaded = reader::load(source.text().as_bytes(), version);
        for difference in differences(&checked.kb, &loaded, source.text()) {
            let lines: Vec<u32> = difference.at.iter().map(|&at| index.line(at)).collect();
            let reported = checked.diagnostics.iter().any(|d| {
                let on_a_line = lines.contains(&index.line(d.span.start))
                    || d.labels
                        .iter()
                        .any(|label| lines.contains(&index.line(label.span.start)));
                let counts =
                    d.severity() == Severity::Error || d.rule.name == "trailing-whitespace";
                // Rules that report a file-wide cause once (the first CRLF ending, say).
                let file_wide = matches!(d.rule.name, "compat-crlf" | "compat-line-too-long");
                counts && (on_a_line || file_wide)
            });
            assert!(
                reported,
                "reader {version} loads something else ({}, lines {lines:?}) but check reports no error there in {text:?}:\n{:?}",
                difference.what,
                checked
                    .diagnostics
                    .iter()
                    .map(|d| (d.rule.name, index.line(d.span.start)))
                    .collect::<Vec<_>>()
            );
        }
    }
}

/// Lines for the property test; `#` stands for an id.
const LINES: &[&str] = &[
    "robotLocationDescription # Hall",
    "robotLocationDescription # \"Quoted\"",
    "robotLocationDescription # Ùmuntu",
    "robotLocationDescription # Roomba  ",
    "robotLocation # 1 2 90",
    "robotLocationPose # -1.5 2 -90",
    "robotLocationPose # +1.5 2 90",
    " robotLocationPose # 1.0 2.0 3.0",
    "gestureTarget # 1 1 1",
    "gestureTarget # .5 1 1",
    "gestureTarget # 8,1 2 3",
    "gestureArm # left",
    "gestureArm # right ",
    "culturalKnowledge # DeicticShape Bow",
    "culturalKnowledge # Deictic_Shape",
    "culturalKnowledge # Bow's Deictic-Shape",
    "preGestureMessageEnglish # Hello the lab",
    "\tpreGestureMessageIsiZulu # Sawubona",
    "postGestureMessageKinyarwanda # Murakaza",
    "postGestureMessageenglish # miscased",
    "postGestureMessageEnglish\u{a0}# no-break space",
    "bogus # 1",
    "tourSpecification 2 # 1",
    "tourSpecification 3 #, 1, 2",
    "tourSpecification 3 # 1",
    "  tourSpecification 1 #",
    "# a comment",
    "",
    "\u{c}",
    "robotLocationDescription +# plus id",
    "robotLocationDescription # ",
    "robotLocationDescription #a letters after the id",
    "robotLocationDescription #.5 a point after the id",
    "preGestureMessageEnglish\t#\tTabs between",
    "robotLocationPose # 1e5 2 3",
    "robotLocationPose # 1 2",
    "robotLocationPose # 1 2 3 4",
    "gestureTarget # nan 1 1",
    "gestureTarget #",
    "gestureArm # up",
    "tourSpecification 0",
    "tourSpecification x # 1",
    "tourSpecification 2 # x",
    "tourSpecification -1 #",
    "culturalKnowledge # _Leading Trailing_",
    "culturalKnowledge # A B C",
    "robotLocationDescription 0 zero",
    "robotLocationDescription -# minus id",
    "robotLocationDescription 2147483648 overflow",
    "robotLocationDescription\x0b# vertical tab",
    "robotLocationDescription\t#\tHall\t",
    "preGestureMessageEnglish # Hello\u{0}world",
    "tourSpecification 2 #,1",
    "tourSpecification 2 #x 1",
    "culturalKnowledge # A\tB",
    "culturalKnowledge #",
    "gestureArm # Left",
    "robotLocationPose # 1 2 3x",
    "robotLocationPose # 0x10 2 3",
    "gestureTarget # 1,0 2 3",
    "gestureTarget # 1 1e39 1",
    "robotLocationPose # -1e39 3.4028236e38 1",
    "robotLocationDescription -99999999999999999999 far below",
    "robotLocationDescription #\u{0}Hall",
    "tourSpecification 3 #",
];

/// A message long enough to cross a line buffer (200, 300 or 600 bytes).
fn long_line(id: u32, length: usize) -> String {
    let mut line = format!("preGestureMessageEnglish {id} ");
    while line.len() < length {
        line.push_str("word ");
    }
    line.truncate(length);
    line
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn every_difference_from_the_file_is_an_error(
        lines in prop::collection::vec((0..LINES.len() + 3, 1..4u32, prop::bool::weighted(0.1)), 0..16),
        final_newline in prop::bool::weighted(0.8),
    ) {
        let mut text = String::new();
        for (template, id, crlf) in lines {
            match template.checked_sub(LINES.len()) {
                Some(which) => text.push_str(&long_line(id, [250, 350, 650][which])),
                None => text.push_str(&LINES[template].replace('#', &id.to_string())),
            }
            text.push_str(if crlf { "\r\n" } else { "\n" });
        }
        if !final_newline {
            text.pop();
        }
        assert_differences_are_reported(&text);
    }
}

#[test]
fn a_vertical_tab_or_form_feed_after_a_key_is_a_space_to_the_reader() {
    // Found by the property test above: `sscanf`'s `%s` ends a key at a vertical tab, so
    // the reader loads these lines, which are no `key value` lines to ekb.
    assert_differences_are_reported(
        "robotLocationDescription\u{B}2 vertical tab\r\nrobotLocationDescription\u{B}2 vertical tab\npostGestureMessageEnglish\u{A0}2 no-break space\n",
    );
    assert_differences_are_reported(
        "robotLocationPose 2 1 2 3\nrobotLocationDescription\u{C}2 form feed\ntourSpecification 1 2\n",
    );
}

#[test]
fn the_seed_and_the_corpus() {
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    for file in [
        "corpus/environmentKnowledgeBaseInput.dat",
        "corpus/upstream-2025-06-environmentKnowledgeBaseInput.dat",
        "corpus/upstream-2026-02-environmentKnowledgeBaseInput.dat",
        "corpus/upstream-2026-03-gesture-arm-environmentKnowledgeBaseInput.dat",
    ] {
        let text = std::fs::read_to_string(fixtures.join(file)).unwrap();
        assert_differences_are_reported(&text);
    }
    // The robot's repository's knowledge bases over time.
    let history = std::fs::read_dir(fixtures.join("corpus/history")).unwrap();
    let files: Vec<_> = history
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|ext| ext == "dat"))
        .collect();
    assert_eq!(files.len(), 6);
    for path in files {
        assert_differences_are_reported(&std::fs::read_to_string(path).unwrap());
    }
}

/// What `reader` loads from the fixture `name` (under `tests/fixtures/reader/`), as
/// `export --as-loaded` prints it, and the check's findings as (rule, line, severity).
fn loaded_fixture(
    name: &str,
    version: Reader,
) -> (serde_json::Value, Vec<(String, u32, Severity)>) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/reader")
        .join(name);
    let source = SourceFile::from_bytes(name, std::fs::read(path).unwrap());
    let loaded = reader::load(source.text().as_bytes(), version);
    let export = serde_json::to_value(reader::export::LoadedExport::new(&loaded)).unwrap();
    let options = Options {
        reader: Some(version),
        ..Options::default()
    };
    let index = LineIndex::new(source.text());
    let findings = ekb::check(&source, &options)
        .diagnostics
        .iter()
        .map(|d| {
            (
                d.rule.name.to_string(),
                index.line(d.span.start),
                d.severity(),
            )
        })
        .collect();
    (export, findings)
}

fn has(findings: &[(String, u32, Severity)], rule: &str, line: u32, severity: Severity) -> bool {
    findings
        .iter()
        .any(|(name, at, level)| name == rule && *at == line && *level == severity)
}

/// Found against the real readers: glibc's `scanf("%f")` reads on past an exponent without
/// digits (`1e+` is 1, and the next number follows), and reads hexadecimal floats (`0x1p3`
/// is 8). `ekb` took both lines as unreadable, so it showed their locations' old values.
#[test]
fn numbers_as_the_real_reader_scans_them() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("scanf-numbers.dat", version);
        let location = |id: usize| &loaded["locations"][id - 1];
        assert_eq!(
            location(1)["gestureTarget"],
            serde_json::json!({ "x": 1.5, "y": 1.0, "z": 0.5 }),
            "{version}"
        );
        assert_eq!(
            location(2)["gestureTarget"],
            serde_json::json!({ "x": 1.0, "y": 2.0, "z": 3.0 }),
            "{version}"
        );
        if version != Reader::D542 {
            assert_eq!(
                location(2)["pose"],
                serde_json::json!({ "x": 8.0, "y": 1.0, "theta": 16.0 }),
                "{version}"
            );
        }
        for line in [3, 5, 6] {
            assert!(
                has(&findings, "invalid-number", line, Severity::Error),
                "{version} line {line}: {findings:?}"
            );
        }
    }
}

/// Found against the real readers: a tour line with fewer ids than its count does not
/// stop at its end; the reader reads on into the bytes its buffer held before (SPEC §2.17):
/// the `1` that the longer tour line before left, then the `Lab` of the description
/// before that, where `%d` fails and the last slot keeps what it held (the earlier tour's
/// `1`). A letter stops it too: the stops after it keep what they held, which is 0 where
/// no line set them (the tour is zero-filled when loading starts).
#[test]
fn tour_stops_past_the_end_of_the_line_come_from_the_buffer() {
    let cases = [
        (
            "tour-past-the-line.dat",
            "tour-count-mismatch",
            4,
            serde_json::json!([2, 1, 1]),
        ),
        (
            "tour-stops-at-a-letter.dat",
            "invalid-id",
            2,
            serde_json::json!([2, 0, 0]),
        ),
    ];
    for version in Reader::ALL {
        for (fixture, rule, line, tour) in &cases {
            let (loaded, findings) = loaded_fixture(fixture, version);
            assert_eq!(&loaded["tour"], tour, "{fixture} {version}");
            let reported = has(&findings, rule, *line, Severity::Error);
            assert!(reported, "{fixture} {version}: {findings:?}");
        }
    }
}

/// Found against the real readers: `tourSpecification 2147483647 1` keeps every version
/// busy for about four minutes (it tries to read an id for each declared stop); the check
/// says so, besides the errors about the count.
#[test]
fn a_huge_tour_count_is_a_slow_load() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("tour-huge-count.dat", version);
        assert_eq!(loaded["tour"][0], 1, "{version}");
        assert!(
            has(&findings, "compat-slow-load", 2, Severity::Warning),
            "{findings:?}"
        );
        assert!(
            has(&findings, "tour-too-long", 2, Severity::Error),
            "{findings:?}"
        );
    }
    let (_, findings) = loaded_fixture("tour-past-the-line.dat", Reader::V2025_06);
    assert!(!findings.iter().any(|(rule, ..)| rule == "compat-slow-load"));
}

/// Found against the real readers: `culturalKnowledge` with no word after its id loads no
/// word (the reader's loop runs only within the line), where `ekb` showed it undefined.
#[test]
fn cultural_knowledge_without_words_loads_none() {
    for version in &Reader::ALL[1..] {
        let name = "cultural-knowledge-without-words.dat";
        let (loaded, findings) = loaded_fixture(name, *version);
        let words = &loaded["locations"][0]["culturalKnowledge"];
        assert_eq!(*words, serde_json::json!([]), "{version}");
        let reported = has(&findings, "empty-value", 3, Severity::Error);
        assert!(reported, "{version}: {findings:?}");
    }
}

/// Found against the real readers: a culturalKnowledge line of three words that a later
/// line of its location overwrites still crashes the reader, which reads it first; the check
/// reported only `duplicate-key`, a warning.
#[test]
fn an_overwritten_cultural_knowledge_line_still_crashes_the_reader() {
    let name = "cultural-knowledge-overwritten.dat";
    for version in &Reader::ALL[1..] {
        let (_, findings) = loaded_fixture(name, *version);
        let rule = "compat-too-many-cultural-keys";
        assert!(
            has(&findings, rule, 2, Severity::Error),
            "{version}: {findings:?}"
        );
        assert!(
            !has(&findings, rule, 4, Severity::Error),
            "{version}: {findings:?}"
        );
    }
    let (_, findings) = loaded_fixture(name, Reader::D542);
    assert!(!findings
        .iter()
        .any(|(rule, ..)| rule == "compat-too-many-cultural-keys"));
}

/// SPEC §2.15: `%f` into a `float` loads a finite decimal too large for one as an
/// infinity, on every version; `export --as-loaded` shows it as `"inf"` or `"-inf"`.
#[test]
fn a_number_too_large_for_a_float_loads_as_an_infinity() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("float-overflow.dat", version);
        let location = &loaded["locations"][0];
        assert_eq!(
            location["gestureTarget"],
            serde_json::json!({ "x": 3.0, "y": "inf", "z": 0.82 }),
            "{version}"
        );
        if version != Reader::D542 {
            assert_eq!(
                location["pose"],
                serde_json::json!({ "x": 1.0, "y": "-inf", "theta": "inf" }),
                "{version}"
            );
        }
        for line in [3, 4] {
            assert!(
                has(&findings, "compat-float-overflow", line, Severity::Error),
                "{version} line {line}: {findings:?}"
            );
        }
        let overflows = findings
            .iter()
            .filter(|(rule, ..)| rule == "compat-float-overflow")
            .count();
        assert_eq!(overflows, 3, "{version}: {findings:?}");
    }
}

/// SPEC §2.15: an id past a C `long` saturates (`LONG_MIN`, `LONG_MAX`), and `%d` keeps its
/// low 32 bits: `-99999999999999999999` lands on id 0, `99999999999999999999` on -1.
#[test]
fn an_id_past_a_long_lands_on_the_low_bits_of_its_limit() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("id-past-long.dat", version);
        let ids: Vec<(i64, &str)> = loaded["locations"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| {
                (
                    l["id"].as_i64().unwrap(),
                    l["description"].as_str().unwrap(),
                )
            })
            .collect();
        assert_eq!(ids, [(-1, "Yard"), (0, "Lab"), (1, "Hall")], "{version}");
        for line in [2, 3] {
            assert!(
                has(&findings, "invalid-id", line, Severity::Error),
                "{version} line {line}: {findings:?}"
            );
        }
    }
}

/// SPEC §2.17: a buffer an earlier line filled is reused, so a short line whose value the
/// reader looks for past its end loads what the longer line before it left there.
#[test]
fn a_short_line_loads_what_a_longer_one_left_in_the_buffer() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("leftovers.dat", version);
        assert_eq!(
            loaded["locations"][1]["description"], "long description of the hall",
            "{version}"
        );
        assert!(
            has(&findings, "empty-value", 2, Severity::Error),
            "{version}: {findings:?}"
        );
    }
}

/// SPEC §2.17: the reader's loops that skip to a value do not stop at a NUL byte: the text
/// after it is loaded.
#[test]
fn the_text_after_a_nul_byte_is_loaded() {
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("after-a-nul.dat", version);
        let location = &loaded["locations"][0];
        assert_eq!(location["description"], "Hall", "{version}");
        assert_eq!(
            location["preGestureMessage"]["english"], "Welcome",
            "{version}"
        );
        for line in [1, 2] {
            assert!(
                has(&findings, "control-character", line, Severity::Error),
                "{version} line {line}: {findings:?}"
            );
        }
    }
}

/// Found against the real readers: a lone `\r` that is the last byte a version's line
/// buffer holds of its line (byte 199, 299 or 599 of it) ends that line: the reader drops
/// it, as it takes the last byte of a text for its newline, and reads what follows as a
/// line of its own. It changes nothing loaded, so it is no `compat-line-too-long`, and the
/// robot never says it, so it is no `control-character`; `ekb` reported both. A version
/// whose buffer holds the line on past the `\r` keeps it in the text (and the check says
/// so); a `\r` a byte before the cut is one on every version.
#[test]
fn a_lone_carriage_return_where_the_buffer_cuts_the_line_ends_it() {
    let description = |loaded: &serde_json::Value, at: usize| {
        loaded["locations"][at]["description"]
            .as_str()
            .unwrap()
            .to_string()
    };
    for buffer in [200, 300, 600] {
        let name = format!("lone-cr-at-the-cut-{buffer}.dat");
        for version in Reader::ALL {
            let (loaded, findings) = loaded_fixture(&name, version);
            let on_the_line = |rule: &str| has(&findings, rule, 4, Severity::Error);
            if version.line_buffer() == buffer {
                let first = description(&loaded, 0);
                assert_eq!(first.len(), buffer - 2 - 27, "{version} {name}");
                // The fixture's text ends in an `s` before its `\r`.
                assert!(first.ends_with('s'), "{version} {name}: {first:?}");
                assert_eq!(description(&loaded, 1), "Lab", "{version} {name}");
                assert!(
                    !on_the_line("compat-line-too-long") && !on_the_line("control-character"),
                    "{version} {name}: {findings:?}"
                );
            } else {
                assert!(
                    description(&loaded, 0).contains('\r') || version.line_buffer() < buffer,
                    "{version} {name}"
                );
                assert!(
                    on_the_line("control-character"),
                    "{version} {name}: {findings:?}"
                );
                let cut = version.line_buffer() < buffer;
                assert_eq!(
                    on_the_line("compat-line-too-long"),
                    cut,
                    "{version} {name}: {findings:?}"
                );
            }
        }
    }
    for version in Reader::ALL {
        let (loaded, findings) = loaded_fixture("lone-cr-before-the-cut.dat", version);
        assert!(
            has(&findings, "control-character", 4, Severity::Error),
            "{version}: {findings:?}"
        );
        let cut = version.line_buffer() == 200;
        assert_eq!(
            has(&findings, "compat-line-too-long", 4, Severity::Error),
            cut,
            "{version}: {findings:?}"
        );
        assert!(description(&loaded, 0).contains('\r'), "{version}");
    }
}

/// Found against the real readers: three `culturalKnowledge` words on an id that has no
/// location yet make one, with the pointer to the third word written over its word count,
/// and no crash; the reader crashes only where another line of the location that it reads
/// makes it update the location (the description of location 6 here, or on `2026-03` the
/// `gestureArm` of location 5). `ekb` said it crashed on a line the version ignores too.
#[test]
fn three_cultural_words_on_a_new_id_overwrite_its_word_count_without_a_crash() {
    let rule = "compat-too-many-cultural-keys";
    for version in &Reader::ALL[1..] {
        let source = SourceFile::from_bytes(
            "three-words",
            std::fs::read(
                std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("tests/fixtures/reader/cultural-knowledge-three-words.dat"),
            )
            .unwrap(),
        );
        let options = Options {
            reader: Some(*version),
            ..Options::default()
        };
        let index = LineIndex::new(source.text());
        let checked = ekb::check(&source, &options);
        let message = |line: u32| {
            checked
                .diagnostics
                .iter()
                .find(|d| d.rule.name == rule && index.line(d.span.start) == line)
                .map(|d| (d.severity(), d.message.clone()))
                .unwrap_or_else(|| panic!("{version}: no {rule} at line {line}"))
        };
        let (severity, new_id) = message(1);
        assert_eq!(severity, Severity::Error, "{version}");
        match *version {
            Reader::V2026_03 => assert!(new_id.ends_with("crashes while the robot starts")),
            _ => assert!(
                new_id.contains("third word's pointer over the location's word count")
                    && new_id.contains("does not crash"),
                "{version}: {new_id}"
            ),
        }
        let (_, existing) = message(4);
        assert!(
            existing.ends_with("crashes while the robot starts"),
            "{version}: {existing}"
        );
    }
    let (_, findings) = loaded_fixture("cultural-knowledge-three-words.dat", Reader::D542);
    assert!(!findings.iter().any(|(name, ..)| name == rule));
}
