//! The library's front door (`ekb::loader`): one reading with `ekb export` and `ekb check`.

use std::path::Path;

use assert_cmd::Command;
use ekb::loader::{self, LoadError, Options};
use ekb::model::export::ExportedKnowledgeBase;
use ekb::settings::Lookup;
use ekb::Severity;

fn fixture(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
}

fn isolated() -> Options {
    Options {
        settings: Lookup::Isolated,
        ..Options::default()
    }
}

fn ekb_json(args: &[&str]) -> serde_json::Value {
    let output = Command::cargo_bin("ekb")
        .unwrap()
        .arg("--isolated")
        .args(args)
        .output()
        .unwrap();
    serde_json::from_slice(&output.stdout).expect("ekb writes JSON")
}

#[test]
fn a_clean_file_loads_as_ekb_export_shows_it() {
    for name in [
        "check/clean-seed.dat",
        "check/clean-current.dat",
        "check/warning-only.dat",
    ] {
        let path = fixture(name);
        let kb = loader::load_path(&path, &isolated()).unwrap();
        let exported: ExportedKnowledgeBase =
            serde_json::from_value(ekb_json(&["export", path.to_str().unwrap()])).unwrap();
        assert_eq!(kb.export(), exported, "{name}");
        assert_eq!(kb.tour(), exported.tour.as_deref().unwrap(), "{name}");
        for location in &exported.locations {
            let loaded = kb.location(location.id).map(|loaded| loaded.to_export());
            assert_eq!(loaded.as_ref(), Some(location), "{name}");
        }
    }
}

#[test]
fn a_location_is_found_by_id_and_an_unknown_id_is_none() {
    let kb = loader::load_path(&fixture("check/clean-seed.dat"), &isolated()).unwrap();
    let first = kb.tour()[0];
    let location = kb.location(first).expect("the first stop is a location");
    assert_eq!(location.id, first);
    assert!(location.pose.is_some());
    assert!(location.pre_gesture_message.english.is_some());
    assert_eq!(kb.location(0), None);
    assert_eq!(kb.location(2_147_483_647), None);
}

#[test]
fn a_file_with_an_error_is_refused_with_the_findings_of_ekb_check() {
    let path = fixture("check/seed.dat");
    let error = loader::load_path(&path, &isolated()).unwrap_err();
    let LoadError::Refused { findings } = &error else {
        panic!("refused, not {error:?}");
    };
    let checked = ekb_json(&["check", "--format", "json", path.to_str().unwrap()]);
    let expected: Vec<(String, u64, u64)> = checked["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            let rule = d["rule"].as_str().unwrap().to_string();
            (
                rule,
                d["line"].as_u64().unwrap(),
                d["column"].as_u64().unwrap(),
            )
        })
        .collect();
    let got: Vec<(String, u64, u64)> = findings
        .iter()
        .map(|f| (f.rule.to_string(), u64::from(f.line), u64::from(f.column)))
        .collect();
    // The findings of `ekb check`, in reading order: errors first, the key-case error (the
    // cause) before the missing field it causes, then the warnings in the file's order.
    let mut sorted = got.clone();
    sorted.sort_by_key(|(_, line, column)| (*line, *column));
    assert_eq!(sorted, expected);
    assert_eq!(
        got[..3]
            .iter()
            .map(|(rule, line, _)| (rule.as_str(), *line))
            .collect::<Vec<_>>(),
        [
            ("key-case", 34),
            ("missing-field", 28),
            ("repeated-word", 4)
        ]
    );
    let key_case = findings.iter().find(|f| f.rule == "key-case").unwrap();
    assert_eq!((key_case.line, key_case.severity), (34, Severity::Error));
    // The one-line reason names the first error, with its place.
    let first_error = findings
        .iter()
        .find(|f| f.severity == Severity::Error)
        .unwrap();
    assert!(
        error.to_string().starts_with(&first_error.to_string()),
        "{error}"
    );
    assert!(error.to_string().ends_with("(and 1 more error)"), "{error}");
}

#[test]
fn bytes_load_as_the_file_does() {
    let path = fixture("check/clean-current.dat");
    let bytes = std::fs::read(&path).unwrap();
    let from_bytes = loader::load_bytes("clean-current.dat", &bytes, &isolated()).unwrap();
    let from_path = loader::load_path(&path, &isolated()).unwrap();
    assert_eq!(from_bytes.export(), from_path.export());
    assert_eq!(from_bytes.file(), "clean-current.dat");
}

#[test]
fn check_gives_the_findings_without_refusing() {
    let findings =
        loader::check_bytes("one.dat", b"robotLocationDescription 1 Door\n", &isolated()).unwrap();
    let tour_missing = findings.iter().find(|f| f.rule == "tour-missing").unwrap();
    assert_eq!(tour_missing.severity, Severity::Error);
    let clean = loader::check_path(&fixture("check/clean-seed.dat"), &isolated()).unwrap();
    assert!(clean.iter().all(|f| f.severity != Severity::Error));
}

#[test]
fn a_missing_file_is_unreadable_not_refused() {
    let error = loader::load_path(Path::new("/nonexistent/kb.dat"), &isolated()).unwrap_err();
    assert!(matches!(error, LoadError::Unreadable { .. }), "{error:?}");
    assert!(error.findings().is_empty());
    assert!(
        error.to_string().starts_with("/nonexistent/kb.dat: "),
        "{error}"
    );
}

#[test]
fn the_configuration_names_the_file_and_its_reader() {
    let project = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(project.path().join("config")).unwrap();
    std::fs::create_dir_all(project.path().join("data")).unwrap();
    std::fs::copy(
        fixture("check/clean-current.dat"),
        project.path().join("data/kb.dat"),
    )
    .unwrap();
    let config = project
        .path()
        .join("config/environmentKnowledgeBaseConfiguration.ini");
    std::fs::write(
        &config,
        "knowledgeBase kb.dat\nverboseMode false\nreader 2026-03\n",
    )
    .unwrap();
    let kb = loader::load_configured(Some(&config), &isolated()).unwrap();
    assert_eq!(kb.reader().name(), "2026-03");
    assert!(!kb.is_empty());

    std::fs::write(&config, "knowledgeBase missing.dat\n").unwrap();
    let error = loader::load_configured(Some(&config), &isolated()).unwrap_err();
    assert!(matches!(error, LoadError::Unreadable { .. }), "{error:?}");
}

#[test]
fn the_drop_in_limits_refuse_what_the_documents_types_cannot_hold() {
    // Under 2026-03 (a 600-byte line buffer) with two rules silenced, the file loads: the
    // library has no 200-byte, 20-stop or 2-word limit.
    let path = fixture("loader/fixed-size.dat");
    let options = Options {
        reader: Some(ekb::robot::Reader::V2026_03),
        ..isolated()
    };
    let kb = loader::load_path(&path, &options).unwrap();
    assert_eq!(kb.tour().len(), 21);
    assert_eq!(kb.location(1).unwrap().cultural_knowledge.len(), 3);

    let limited = Options {
        fixed_size_limits: true,
        ..options
    };
    let error = loader::load_path(&path, &limited).unwrap_err();
    let errors: Vec<(&str, u32, u32)> = error
        .findings()
        .iter()
        .filter(|f| f.severity == Severity::Error)
        .map(|f| (f.rule, f.line, f.column))
        .collect();
    // The 200-byte text is refused; the 199-byte one (line 18) fits with its NUL.
    assert_eq!(
        errors,
        [
            ("drop-in-string-length", 5, 33),
            ("drop-in-culture-keys", 11, 33),
            ("drop-in-tour-length", 22, 19),
        ]
    );
    let text = &error.findings()[error
        .findings()
        .iter()
        .position(|f| f.rule == "drop-in-string-length")
        .unwrap()];
    assert!(
        text.message.contains("STRING_LENGTH 200"),
        "{}",
        text.message
    );
    assert_eq!(text.location_id, Some(1));
    // The class it names is written as C++ writes it, not escaped.
    assert_eq!(
        text.help.as_deref(),
        Some("shorten the text, or load the file with ekb::KnowledgeBase, which has no such limit")
    );

    // A file within the limits loads the same with them.
    let clean = fixture("check/clean-current.dat");
    let plain = loader::load_path(&clean, &isolated()).unwrap();
    let within = Options {
        fixed_size_limits: true,
        ..isolated()
    };
    assert_eq!(
        loader::load_path(&clean, &within).unwrap().export(),
        plain.export()
    );
}

#[test]
fn what_a_finding_quotes_of_the_file_is_escaped() {
    let text = b"robotLocationDescription 1\0Hall\ntourSpecification 1 1\n";
    let findings = loader::check_bytes("nul.dat", text, &isolated()).unwrap();
    let quoting = findings.iter().find(|f| f.rule == "invalid-id").unwrap();
    assert!(quoting.message.contains("\\u{0000}"), "{}", quoting.message);
    for finding in &findings {
        let all = format!("{finding} {:?}", finding.help);
        assert!(!all.contains('\0'), "{all}");
    }
}

#[test]
fn the_drop_in_string_length_is_the_programs() {
    // A 335-byte message, under the 2026-04 reader (a 600-byte line buffer): a program
    // built with the document's STRING_LENGTH 200 is refused it, naming the limit; one
    // built with the 2026-04 header's 600 loads it whole.
    let message = "x".repeat(335);
    let text = std::fs::read_to_string(fixture("check/clean-current.dat"))
        .unwrap()
        .replace(
            "preGestureMessageEnglish      1 Welcome to the robotics lab",
            &format!("preGestureMessageEnglish      1 {message}"),
        );
    assert!(text.contains(&message));
    let options = |string_length| Options {
        reader: Some(ekb::robot::Reader::V2026_04),
        fixed_size_limits: true,
        string_length,
        ..isolated()
    };

    let error = loader::load_bytes("long.dat", text.as_bytes(), &options(200)).unwrap_err();
    let refused: Vec<&loader::Finding> = error
        .findings()
        .iter()
        .filter(|f| f.severity == Severity::Error)
        .collect();
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].rule, "drop-in-string-length");
    assert_eq!((refused[0].line, refused[0].location_id), (4, Some(1)));
    assert!(
        refused[0].message.contains("335 bytes")
            && refused[0].message.contains("at most 199")
            && refused[0].message.contains("STRING_LENGTH 200"),
        "{}",
        refused[0].message
    );
    assert_eq!(
        Options::default().string_length,
        loader::STRING_LENGTH,
        "the document's size is the default"
    );

    let kb = loader::load_bytes("long.dat", text.as_bytes(), &options(600)).unwrap();
    assert_eq!(
        kb.location(1).unwrap().pre_gesture_message.english,
        Some(message.as_str())
    );
    // 335 bytes and the NUL need a STRING_LENGTH of 336.
    let error = loader::load_bytes("long.dat", text.as_bytes(), &options(335)).unwrap_err();
    assert!(error.findings()[0].message.contains("STRING_LENGTH 335"));
    assert!(loader::load_bytes("long.dat", text.as_bytes(), &options(336)).is_ok());

    // A size no program has is a clear error, not a check.
    for absurd in [0, 1, usize::MAX] {
        let error = loader::load_bytes("long.dat", text.as_bytes(), &options(absurd)).unwrap_err();
        assert!(
            matches!(&error, LoadError::Unreadable { reason, .. } if reason.contains(&format!("STRING_LENGTH {absurd} is not a size"))),
            "{error:?}"
        );
    }
}

/// A folder holding `ekb.toml` with `settings` and, in its folder `lab/`, a clean file and one
/// whose tour stops at a location that does not exist: the folder, the clean and the bad.
fn under_settings(settings: &str) -> (tempfile::TempDir, std::path::PathBuf, std::path::PathBuf) {
    let root = tempfile::tempdir().unwrap();
    std::fs::write(root.path().join("ekb.toml"), settings).unwrap();
    let lab = root.path().join("lab");
    std::fs::create_dir(&lab).unwrap();
    let text = std::fs::read_to_string(fixture("check/clean-current.dat")).unwrap();
    let clean = lab.join("clean.dat");
    std::fs::write(&clean, &text).unwrap();
    let bad = lab.join("bad-tour.dat");
    std::fs::write(
        &bad,
        text.replace("tourSpecification 2 1 2", "tourSpecification 2 1 9"),
    )
    .unwrap();
    (root, clean, bad)
}

const SILENCING: &str = "[check]\nignore = [\"tour\"]\n";

#[test]
fn an_ekb_toml_above_the_file_is_not_read_unless_named() {
    let (root, _, bad) = under_settings(SILENCING);
    // `ekb check` finds it, and silences the tour rules: the bad tour passes the check.
    Command::cargo_bin("ekb")
        .unwrap()
        .args(["check", bad.to_str().unwrap()])
        .assert()
        .code(0);
    // The loader reads no settings it was not asked for: refused for the stop at 9.
    let error = loader::load_path(&bad, &Options::default()).unwrap_err();
    let unknown = error
        .findings()
        .iter()
        .find(|f| f.rule == "tour-unknown-location")
        .unwrap_or_else(|| panic!("{error:?}"));
    assert_eq!((unknown.severity, unknown.line), (Severity::Error, 21));
    // Named by path, the same settings are obeyed.
    let named = Options {
        settings: Lookup::Explicit(root.path().join("ekb.toml")),
        ..Options::default()
    };
    let kb = loader::load_path(&bad, &named).unwrap();
    assert_eq!(kb.tour(), [1, 9]);
}

#[test]
fn a_fifo_or_a_folder_where_ekb_toml_would_be_stops_no_load() {
    let (root, clean, _) = under_settings("");
    let settings = root.path().join("ekb.toml");
    std::fs::remove_file(&settings).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(&settings)
        .status()
        .unwrap();
    assert!(made.success());
    let kb = loader::load_path(&clean, &Options::default()).unwrap();
    assert_eq!(kb.tour(), [1, 2]);
    assert!(loader::check_path(&clean, &Options::default()).is_ok());
    std::fs::remove_file(&settings).unwrap();
    std::fs::create_dir(&settings).unwrap();
    assert!(loader::load_path(&clean, &Options::default()).is_ok());
    // Asked for by path, settings that cannot be read make the file unreadable.
    let named = Options {
        settings: Lookup::Explicit(settings),
        ..Options::default()
    };
    let error = loader::load_path(&clean, &named).unwrap_err();
    assert!(matches!(error, LoadError::Unreadable { .. }), "{error:?}");
}

#[test]
fn an_unreadable_file_is_named_escaped_and_short() {
    let hostile = format!("/nonexistent/\u{1b}]0;pwned\u{7}{}", "a".repeat(900 * 1024));
    let error = loader::load_path(Path::new(&hostile), &Options::default()).unwrap_err();
    let LoadError::Unreadable { file, reason } = &error else {
        panic!("{error:?}");
    };
    let message = error.to_string();
    for text in [file, reason, &message] {
        assert!(!text.chars().any(|c| c.is_control()), "{text:.200}");
        assert!(text.len() < 2_000, "{} bytes", text.len());
    }
    assert!(
        file.starts_with("/nonexistent/\\u{001B}]0;pwned\\u{0007}aaa"),
        "{file:.100}"
    );
    let more = hostile.chars().count() - 300;
    assert!(
        file.ends_with(&format!("… ({more} more characters)")),
        "{file}"
    );
}

#[test]
fn a_configurations_value_is_escaped_and_short() {
    let folder = tempfile::tempdir().unwrap();
    let config = folder
        .path()
        .join("environmentKnowledgeBaseConfiguration.ini");
    let value = format!("\u{1b}]0;pwned\u{7}{}", "b".repeat(900 * 1024));
    std::fs::write(&config, format!("knowledgeBase {value}\n")).unwrap();
    let error = loader::load_configured(Some(&config), &Options::default()).unwrap_err();
    let message = error.to_string();
    assert!(!message.chars().any(|c| c.is_control()), "{message:.300}");
    assert!(
        message.len() < 2_000,
        "{} bytes: {message:.300}",
        message.len()
    );
    assert!(
        message.contains("\\u{001B}]0;pwned\\u{0007}"),
        "{message:.300}"
    );
}
