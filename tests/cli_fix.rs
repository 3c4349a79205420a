//! `ekb fix`: the machine-applicable fixes, `--diff`, standard input, dialect migration,
//! refusals and safe writes.

mod author_support;

use author_support::{
    assert_read_only_file_left_intact, culture_knowledge_base, ekb, fixture, read_fixture, seed,
    temp_file,
};
use predicates::prelude::PredicateBooleanExt;
use predicates::str::contains;

const LINE_34_FIXED: &str =
    "postGestureMessageEnglish     4 We use it for teaching mobile robotics";

#[test]
fn fix_on_the_seed_changes_line_34_only_and_leaves_no_error() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains("kb.dat: fixed 1 key-case\n"))
        .stderr(contains("kb.dat: 21 warnings left"));
    let fixed = std::fs::read_to_string(&path).unwrap();
    let original = seed();
    assert_eq!(fixed.len(), original.len());
    let changed: Vec<usize> = original
        .split_inclusive('\n')
        .zip(fixed.split_inclusive('\n'))
        .enumerate()
        .filter(|(_, (old, new))| old != new)
        .map(|(index, _)| index + 1)
        .collect();
    assert_eq!(changed, [34]);
    assert_eq!(fixed.lines().nth(33), Some(LINE_34_FIXED));

    let check = ekb().arg("check").arg(&path).assert().code(0);
    let report = String::from_utf8(check.get_output().stdout.clone()).unwrap();
    assert!(!report.contains("error["), "{report}");
    let words = report.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.ends_with(
            "Found 21 warnings: 20 untranslated-message, 1 repeated-word; as the robot's software \
             of document D5.4.2 reads it (d5.4.2)"
        ),
        "{report}"
    );

    // Idempotent: a second run changes nothing.
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains("kb.dat: nothing to fix"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), fixed);
}

#[test]
fn fix_diff_writes_nothing_and_exits_1_when_something_would_change() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let name = path.display().to_string();
    ekb()
        .args(["fix", "--diff"])
        .arg(&path)
        .assert()
        .code(1)
        .stdout(format!(
            "--- {name}\n+++ {name}\n@@ -31,7 +31,7 @@\n \
             preGestureMessageEnglish      4 This is the Roomba\n \
             preGestureMessageIsiZulu      4 No message in isiZulu\n \
             preGestureMessageKinyarwanda  4 No message in Kinyarwanda\n\
             -postGestureMessageenglish     4 We use it for teaching mobile robotics\n\
             +{LINE_34_FIXED}\n \
             postGestureMessageIsiZulu     4 No message in isiZulu\n \
             postGestureMessageKinyarwanda 4 No message in Kinyarwanda\n \
             robotLocationDescription      5 Pepper's starting location\n"
        ))
        .stderr(contains("would fix 1 key-case"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());

    let (_dir, path) = temp_file("kb.dat", read_fixture("seed-small.dat").as_bytes());
    ekb()
        .args(["fix", "--diff"])
        .arg(&path)
        .assert()
        .code(0)
        .stdout("");
}

#[test]
fn fix_reads_standard_input_and_writes_standard_output() {
    let expected = seed().replace(
        "postGestureMessageenglish    ",
        "postGestureMessageEnglish    ",
    );
    ekb()
        .args(["fix", "-"])
        .write_stdin(seed())
        .assert()
        .code(0)
        .stdout(expected.clone())
        .stderr(contains("<stdin>: fixed 1 key-case"));
    // Nothing to fix: the text comes back unchanged.
    ekb()
        .args(["fix", "-"])
        .write_stdin(expected.clone())
        .assert()
        .code(0)
        .stdout(expected);
}

#[test]
fn fix_changes_only_the_bytes_of_the_fixes() {
    let text = "\u{FEFF}robotLocationDescription 1 Roomba  \r\n\
                RobotLocation 1 5.0 3.9 110\r\n\
                tourSpecification 1 1";
    ekb()
        .args(["fix", "-"])
        .write_stdin(text)
        .assert()
        .code(1)
        .stdout(
            "robotLocationDescription 1 Roomba\n\
             robotLocation 1 5.0 3.9 110\n\
             tourSpecification 1 1\n",
        )
        .stderr(contains(
            "<stdin>: fixed 1 compat-bom, 1 compat-crlf, 1 compat-no-final-newline, 1 key-case, 1 trailing-whitespace",
        ));
}

#[test]
fn fix_converts_only_the_crlf_endings_it_reports() {
    // Issue 12: in `\r\r\n` (a file converted to CRLF twice, or a `\r` typed into a
    // value) the first `\r` is part of the line's text. Converting the ending would make it
    // the next ending, and the next pass would take it away unreported: the line is left,
    // and reported, for a person.
    let text = "robotLocationDescription 1 Roomba\r\r\nrobotLocationDescription 2 Pepper\r\n";
    ekb()
        .args(["fix", "-"])
        .write_stdin(text)
        .assert()
        .code(1)
        .stdout("robotLocationDescription 1 Roomba\r\r\nrobotLocationDescription 2 Pepper\n")
        .stderr(contains("<stdin>: fixed 1 compat-crlf\n"))
        .stderr(contains(
            "<stdin>:1:34: error[compat-crlf] this line ends with CRLF after another `\\r`",
        ));
}

#[test]
fn fix_of_carriage_returns_and_blanks_is_idempotent() {
    // Inputs the fuzzer found: `\r`s and blanks mixed before an ending, a last line without
    // one. One run gives what a second leaves alone.
    let text = "robotLocationDescription 1 Roomba\r\r\n\
                robotLocationDescription 2 Pepper\r\r\t\r\r\r \r\r\t\r\r\r\r\r\r\r\r\r\r\r\r";
    let fix = |input: &str| {
        let output = ekb()
            .args(["fix", "-"])
            .write_stdin(input)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(1), "{output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let once = fix(text);
    assert_eq!(fix(&once), once);
    assert!(once.ends_with('\n'), "{once:?}");
}

#[test]
fn fix_lists_the_errors_left_for_a_person() {
    let text = read_fixture("seed-small.dat")
        .replace("tourSpecification 2 1 2", "tourSpecification 2 1 9");
    let text = text.replace(
        "preGestureMessageEnglish      2",
        "preGestureMessageenglish      2",
    );
    ekb()
        .args(["fix", "-"])
        .write_stdin(text)
        .assert()
        .code(1)
        .stderr(contains("<stdin>: fixed 1 key-case\n"))
        .stderr(contains("<stdin>:21:23: error[tour-unknown-location]"))
        .stderr(contains("<stdin>: 1 error left to correct by hand\n"));
}

#[test]
fn fix_dialect_current_renames_the_pose_key_only() {
    let (_dir, path) = temp_file("kb.dat", read_fixture("seed-small.dat").as_bytes());
    ekb()
        .args(["fix", "--dialect", "current"])
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains("fixed 2 legacy-key"));
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("seed-small.current.dat")
    );
    // And back.
    ekb()
        .args(["fix", "--dialect", "seed"])
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains("fixed 2 legacy-key"));
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("seed-small.dat")
    );
}

#[test]
fn fix_dialect_current_keeps_a_formatted_file_formatted() {
    let formatted = ekb()
        .args(["fmt", "-"])
        .write_stdin(seed())
        .output()
        .unwrap();
    assert_eq!(formatted.status.code(), Some(0));
    let (_dir, path) = temp_file("kb.dat", &formatted.stdout);
    ekb()
        .args(["fix", "--dialect", "current"])
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains("5 legacy-key"));
    ekb().args(["fmt", "--check"]).arg(&path).assert().code(0);
}

#[test]
fn fix_dialect_seed_refuses_lines_the_seed_dialect_cannot_hold() {
    let (_dir, path) = temp_file("kb.dat", read_fixture("current.dat").as_bytes());
    ekb()
        .args(["fix", "--dialect", "seed"])
        .arg(&path)
        .assert()
        .code(2)
        .stderr(contains(
            "to the seed dialect: line 4 (`gestureArm`), line 11 (`culturalKnowledge`), \
             line 16 (`gestureArm`), line 23 (`culturalKnowledge`) have no equivalent in it",
        ));
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("current.dat")
    );
}

#[test]
fn a_pinned_dialect_makes_legacy_keys_fixable() {
    let (dir, path) = temp_file("kb.dat", read_fixture("seed-small.dat").as_bytes());
    let config = dir.path().join("ekb.ini");
    std::fs::write(&config, "dialect = current\n").unwrap();
    ekb()
        .arg("--config")
        .arg(&config)
        .arg("fix")
        .arg(&path)
        .assert()
        .code(0);
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("seed-small.current.dat")
    );
}

#[test]
fn fix_refuses_invalid_utf8() {
    let bytes = b"postGestureMessageenglish 1 Caf\xe9\n";
    let (_dir, path) = temp_file("kb.dat", bytes);
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(contains("is not valid UTF-8"));
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}

#[test]
fn fix_leaves_a_read_only_file_intact() {
    assert_read_only_file_left_intact("fix");
}

#[test]
fn fix_of_a_missing_file_is_exit_2() {
    ekb()
        .arg("fix")
        .arg(fixture("no-such-file.dat"))
        .assert()
        .code(2)
        .stderr(contains("no such file"));
}

#[test]
fn fix_refuses_a_file_that_is_not_an_environment_knowledge_base() {
    // Reordering the culture knowledge base's lines would be a change, and a wrong one.
    let bytes = culture_knowledge_base();
    let (_dir, path) = temp_file("cultureKnowledgeBaseInput.dat", &bytes);
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(2)
        .stdout("")
        .stderr(contains(
            "cultureKnowledgeBaseInput.dat: this is not an environment knowledge base: none of \
             its 78 `key value` lines has one of its keys (the first is `passingDistance`)",
        ));
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}

#[test]
fn unsafe_fixes_wait_for_the_flag_and_the_safe_ones_do_not() {
    let text = seed()
        .replace(
            "robotLocationDescription      1",
            "robotLocationDescription\u{A0}     1",
        )
        .replace(" 8.1 -90", " 8,1 -90")
        .replace(
            "robotLocation                 3 2.0 6.3 -45",
            "robotLocation                 3 2.0 6.3 \u{2212}45",
        );
    let (_dir, path) = temp_file("kb.dat", text.as_bytes());
    let check = ekb().arg("check").arg(&path).output().unwrap();
    let report = String::from_utf8(check.stdout).unwrap();
    assert!(
        report.contains("(unsafe fix available: write `-45`;"),
        "{report}"
    );
    // Locations 1 and 5 have the decimal comma.
    assert!(
        report.contains("3 with ekb fix --unsafe-fixes: invalid-number)"),
        "{report}"
    );
    let json = ekb()
        .args(["check", "--format", "json"])
        .arg(&path)
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let applicability: Vec<(&str, &str)> = json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|d| !d["fix"].is_null())
        .map(|d| {
            (
                d["rule"].as_str().unwrap(),
                d["fix"]["applicability"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        applicability,
        [
            ("unicode-space", "safe"),
            ("invalid-number", "unsafe"),
            ("invalid-number", "unsafe"),
            ("key-case", "safe"),
            ("invalid-number", "unsafe")
        ]
    );
    // The three guesses are not "by hand": the flag that makes them is named.
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(1)
        .stderr(contains(
            "kb.dat: 3 errors left that `ekb fix --unsafe-fixes` fixes by a guess \
             (`ekb fix --unsafe-fixes --diff` shows it first)\n",
        ))
        .stderr(contains("by hand").not());
    let safe = std::fs::read_to_string(&path).unwrap();
    assert!(
        safe.contains("robotLocationDescription      1"),
        "the no-break space is gone"
    );
    assert!(
        safe.contains("\u{2212}45") && safe.contains("8,1 -90"),
        "the guesses wait"
    );
    ekb()
        .args(["fix", "--unsafe-fixes"])
        .arg(&path)
        .assert()
        .stderr(contains("fixed 3 invalid-number"));
    let fixed = std::fs::read_to_string(&path).unwrap();
    assert!(
        fixed.contains(" 6.3 -45\n") && fixed.contains(" 8.1 -90\n"),
        "{fixed}"
    );
}

#[test]
fn a_misspelled_key_is_reported_where_the_fix_is_and_renamed_by_an_unsafe_fix() {
    let text = seed().replace(
        "preGestureMessageEnglish      3 ",
        "preGestureMesageEnglish       3 ",
    );
    let (_dir, path) = temp_file("kb.dat", text.as_bytes());
    let json = ekb()
        .args(["check", "--format", "json"])
        .arg(&path)
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let of_location_3: Vec<&serde_json::Value> = json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|d| d["rule"] == "missing-field" || d["rule"] == "unknown-key")
        .filter(|d| d["message"].as_str().unwrap().contains("location 3"))
        .collect();
    assert_eq!(of_location_3.len(), 2, "{of_location_3:?}");
    let help = of_location_3[0]["help"].as_str().unwrap();
    assert_eq!(of_location_3[0]["rule"], "missing-field");
    assert!(
        !help.contains("add a line"),
        "a second line would be a duplicate: {help}"
    );
    assert!(
        help.contains("with the key misspelled: correct the key there"),
        "{help}"
    );
    let typo = of_location_3[1];
    assert_eq!(typo["rule"], "unknown-key");
    assert_eq!(typo["fix"]["applicability"], "unsafe");
    ekb()
        .args(["fix", "--unsafe-fixes"])
        .arg(&path)
        .assert()
        .stderr(contains("1 unknown-key"));
    // Line 34's key in the wrong case is fixed too.
    let fixed = seed().replace("postGestureMessageenglish", "postGestureMessageEnglish");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), fixed);
}

#[test]
fn unsafe_fixes_read_a_latin1_file_as_latin1() {
    let latin1 = seed()
        .replace("Roomba", "Caf\u{E9}")
        .replace("Welcome the the", "\u{2018}Welcome\u{2019} the the");
    // Windows-1252: é is 0xE9, ‘ and ’ are 0x91 and 0x92.
    let bytes: Vec<u8> = latin1
        .chars()
        .map(|c| match c {
            '\u{2018}' => 0x91,
            '\u{2019}' => 0x92,
            c => u8::try_from(u32::from(c)).unwrap(),
        })
        .collect();
    let (_dir, path) = temp_file("kb.dat", &bytes);
    ekb()
        .arg("fix")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(contains("`ekb fix --unsafe-fixes` converts it"));
    ekb()
        .args(["fix", "--unsafe-fixes"])
        .arg(&path)
        .assert()
        .stderr(contains("fixed 3 invalid-utf8, 1 key-case"));
    let fixed = latin1.replace("postGestureMessageenglish", "postGestureMessageEnglish");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), fixed);
}
