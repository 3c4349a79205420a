//! Translators' commands: `ekb translations`, the PO round trip (`export --format po|pot`,
//! `import --po`) checked with `polib` and the real `msgfmt -c --statistics`, and `ekb set`.

mod author_support;

use std::path::{Path, PathBuf};
use std::process::Command as Process;

use author_support::{ekb, seed, temp_file};
use predicates::prelude::PredicateBooleanExt;
use predicates::str::contains;

fn translations_fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/translations")
        .join(name)
}

fn partly() -> String {
    std::fs::read_to_string(translations_fixture("partly.dat")).unwrap()
}

/// Runs `ekb ARGS`: exit code, standard output, standard error.
fn run(args: &[&str]) -> (i32, String, String) {
    let output = ekb().args(args).output().unwrap();
    (
        output.status.code().unwrap_or(-1),
        String::from_utf8(output.stdout).unwrap(),
        String::from_utf8(output.stderr).unwrap(),
    )
}

/// `msgfmt -c --statistics` of a PO file: its exit code and what it prints. `None` when
/// gettext is not installed (CI installs it, and there its absence fails the test).
fn msgfmt(po: &Path) -> Option<(i32, String)> {
    let output = match Process::new("msgfmt")
        .args(["-c", "--statistics", "-o", "/dev/null"])
        .arg(po)
        .output()
    {
        Ok(output) => output,
        Err(_) if std::env::var_os("CI").is_none() => {
            eprintln!("skipped: msgfmt is not installed (apt-get install gettext)");
            return None;
        }
        Err(error) => panic!("msgfmt: {error}: CI must install gettext"),
    };
    let stderr = String::from_utf8(output.stderr).unwrap();
    Some((output.status.code().unwrap_or(-1), stderr))
}

/// The seed's PO file of `lang`, written by `ekb export -o` into a temporary folder that
/// also holds a copy of the seed; returns the folder, the knowledge base and the PO file.
fn exported(kb: &str, lang: &str) -> (tempfile::TempDir, PathBuf, PathBuf) {
    let (dir, path) = temp_file("kb.dat", kb.as_bytes());
    let po = dir.path().join(format!("{lang}.po"));
    ekb()
        .args(["-q", "export", "--format", "po", "--lang", lang])
        .arg(&path)
        .arg("-o")
        .arg(&po)
        .assert()
        .code(0);
    (dir, path, po)
}

/// Fills the `msgstr` of the entries whose `msgid` is given.
fn translate(po: &Path, translations: &[(&str, &str)]) {
    let mut text = std::fs::read_to_string(po).unwrap();
    for (english, translation) in translations {
        let empty = format!("msgid \"{english}\"\nmsgstr \"\"\n");
        assert!(text.contains(&empty), "no empty entry for {english:?}");
        text = text.replace(
            &empty,
            &format!("msgid \"{english}\"\nmsgstr \"{translation}\"\n"),
        );
    }
    std::fs::write(po, text).unwrap();
}

/// The 1-based numbers of the lines that differ (the files have as many lines).
fn changed_lines(old: &str, new: &str) -> Vec<usize> {
    assert_eq!(
        old.split_inclusive('\n').count(),
        new.split_inclusive('\n').count()
    );
    old.split_inclusive('\n')
        .zip(new.split_inclusive('\n'))
        .enumerate()
        .filter(|(_, (a, b))| a != b)
        .map(|(index, _)| index + 1)
        .collect()
}

/// `ekb import FLAGS --po PO KB`.
fn import_po(flags: &[&str], po: &Path, kb: &Path) -> assert_cmd::assert::Assert {
    ekb()
        .arg("import")
        .args(flags)
        .arg("--po")
        .arg(po)
        .arg(kb)
        .assert()
}

const THREE: [(&str, &str); 3] = [
    (
        "I hope you enjoy the tour",
        "Ngithemba uzokujabulela ukuvakasha",
    ),
    ("This is the Roomba", "Le yiRoomba"),
    ("See you again soon", "Sizobonana futhi maduze"),
];

// ---------------------------------------------------------------------------------------
// ekb translations

#[test]
fn the_seed_counts_as_its_untranslated_message_findings() {
    let seed_path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("data/environmentKnowledgeBaseInput.dat");
    let seed_path = seed_path.to_str().unwrap();
    let (code, stdout, _) = run(&["translations", seed_path, "--format", "json"]);
    assert_eq!(code, 0);
    let json: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let languages = json["files"][0]["languages"].as_array().unwrap();
    let (_, check, _) = run(&["check", seed_path, "--format", "json"]);
    let check: serde_json::Value = serde_json::from_str(&check).unwrap();
    for (language, name) in [("isiZulu", "isiZulu"), ("Kinyarwanda", "Kinyarwanda")] {
        let status = languages
            .iter()
            .find(|l| l["language"] == language)
            .unwrap();
        assert_eq!(
            (status["total"].as_u64(), status["translated"].as_u64()),
            (Some(10), Some(0))
        );
        let findings = check["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|d| d["rule"] == "untranslated-message")
            .filter(|d| {
                d["message"]
                    .as_str()
                    .unwrap()
                    .contains(&format!("the {name} message"))
            })
            .count();
        assert_eq!(
            status["untranslated"].as_u64(),
            Some(findings as u64),
            "{language}"
        );
        assert_eq!(
            status["code"],
            if language == "isiZulu" { "zu" } else { "rw" }
        );
    }
    let messages = json["files"][0]["messages"].as_array().unwrap();
    assert_eq!(messages.len(), 10);
    // In tour order: 1 4 3 2 5.
    let order: Vec<u64> = messages
        .iter()
        .step_by(2)
        .map(|m| m["location"].as_u64().unwrap())
        .collect();
    assert_eq!(order, [1, 4, 3, 2, 5]);
}

#[test]
fn quiet_prints_one_msgfmt_line_per_language() {
    let (_dir, path) = temp_file("kb.dat", partly().as_bytes());
    ekb()
        .args(["-q", "translations"])
        .arg(&path)
        .assert()
        .code(0)
        .stdout(
            "English: 9 translated messages, 1 untranslated message.\n\
             isiZulu: 2 translated messages, 1 fuzzy translation, 7 untranslated messages.\n\
             Kinyarwanda: 3 translated messages, 7 untranslated messages.\n",
        );
}

#[test]
fn the_grid_and_what_is_left_in_one_language() {
    let (_dir, path) = temp_file("partly.dat", partly().as_bytes());
    let path = path.to_str().unwrap();
    let (code, grid, _) = run(&["translations", path]);
    assert_eq!(code, 0);
    let grid = grid.replace(path, "partly.dat");
    insta::assert_snapshot!("translations_grid", grid);
    let (_, left, _) = run(&["translations", path, "--lang", "Kinyarwanda"]);
    insta::assert_snapshot!(
        "translations_left_kinyarwanda",
        left.replace(path, "partly.dat")
    );
}

#[test]
fn fail_under_exits_1_when_a_language_is_below() {
    let (_dir, path) = temp_file("kb.dat", partly().as_bytes());
    let code = |args: &[&str]| {
        let mut command = ekb();
        command.arg("translations").arg(&path).args(args).arg("-q");
        command.output().unwrap().status.code()
    };
    assert_eq!(code(&["--fail-under", "20"]), Some(0));
    assert_eq!(code(&["--fail-under", "21"]), Some(1));
    assert_eq!(code(&["--fail-under", "25%", "--lang", "rw"]), Some(0));
    assert_eq!(code(&["--fail-under", "101"]), Some(2));
}

#[test]
fn csv_has_a_row_per_language_or_per_message_left() {
    let (_dir, path) = temp_file("kb.dat", partly().as_bytes());
    let path = path.to_str().unwrap();
    let (_, csv, _) = run(&["translations", path, "--format", "csv"]);
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows[0], "file,language,code,total,translated,translated_percent,untranslated,same_as_source,failing_checks,total_words,translated_words");
    assert_eq!(rows[2], format!("{path},isiZulu,zu,10,2,20,7,1,1,66,16"));
    let (_, left, _) = run(&["translations", path, "--format", "csv", "--lang", "zu"]);
    let rows: Vec<&str> = left.lines().collect();
    assert_eq!(rows.len(), 1 + 8);
    assert!(rows.contains(&format!("{path},4,2,The (other) Pepper robot,before,14,same-as-source,same-as-source,This is the Pepper humanoid robot,This is the Pepper humanoid robot").as_str()), "{left}");
    assert!(
        rows.contains(
            &format!("{path},5,5,Pepper's starting location,after,,missing,,,See you again soon")
                .as_str()
        ),
        "{left}"
    );
}

// ---------------------------------------------------------------------------------------
// PO export

#[test]
fn the_seeds_po_file_passes_msgfmt_and_polib() {
    let (_dir, _, po) = exported(&seed(), "zu");
    if let Some((code, stderr)) = msgfmt(&po) {
        assert_eq!(code, 0, "{stderr}");
        assert_eq!(stderr, "0 translated messages, 10 untranslated messages.\n");
    }
    let catalog = polib::po_file::parse(&po).unwrap();
    assert_eq!(catalog.metadata.language, "zu");
    assert_eq!(catalog.metadata.content_type, "text/plain; charset=UTF-8");
    let messages: Vec<_> = catalog.messages().collect();
    assert_eq!(messages.len(), 10);
    let first = messages[0];
    assert_eq!(first.msgctxt(), Some("location 1 preGestureMessage"));
    assert_eq!(
        first.msgid(),
        "Welcome the the robotics lab at Carnegie Mellon University Africa"
    );
    assert_eq!(first.msgstr().unwrap(), "");
    assert!(first.source().ends_with("kb.dat:4"), "{}", first.source());
    assert_eq!(
        first.extracted_comments(),
        "said first at Pepper's starting location, where the robot does not point (location 1, stop 1 of the tour)\n\
         at most 171 bytes: the robot's reader cuts a longer message (a letter with an accent takes 2)"
    );
    // The English line whose key is in the wrong case is still the text to translate.
    let roomba = messages[3];
    assert_eq!(roomba.msgctxt(), Some("location 4 postGestureMessage"));
    assert_eq!(roomba.msgid(), "We use it for teaching mobile robotics");
    assert!(roomba
        .extracted_comments()
        .contains("said after pointing at Roomba"));
}

#[test]
fn a_translation_that_is_its_english_is_exported_fuzzy_and_msgfmt_agrees() {
    let (_dir, path, po) = exported(&partly(), "zu");
    let text = std::fs::read_to_string(&po).unwrap();
    assert!(text.contains("#, fuzzy\nmsgctxt \"location 2 preGestureMessage\"\nmsgid \"This is the Pepper humanoid robot\"\nmsgstr \"This is the Pepper humanoid robot\"\n"), "{text}");
    let (_, quiet, _) = run(&["-q", "translations", "--lang", "zu", path.to_str().unwrap()]);
    if let Some((code, stderr)) = msgfmt(&po) {
        assert_eq!(code, 0, "{stderr}");
        assert_eq!(format!("isiZulu: {stderr}"), quiet);
    }
}

#[test]
fn the_template_has_every_english_message_and_no_language() {
    let (dir, path) = temp_file("kb.dat", seed().as_bytes());
    let pot = dir.path().join("kb.pot");
    ekb()
        .args(["-q", "export", "--format", "pot"])
        .arg(&path)
        .arg("-o")
        .arg(&pot)
        .assert()
        .code(0);
    let catalog = polib::po_file::parse(&pot).unwrap();
    assert_eq!(catalog.metadata.language, "");
    assert_eq!(catalog.messages().count(), 10);
    assert!(catalog.messages().all(|m| m.msgstr().unwrap().is_empty()));
    if let Some((code, stderr)) = msgfmt(&pot) {
        assert_eq!(code, 0, "{stderr}");
        assert!(
            stderr.ends_with("0 translated messages, 10 untranslated messages.\n"),
            "{stderr}"
        );
    }
}

#[test]
fn po_export_names_what_it_needs() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let path = path.to_str().unwrap();
    let (code, _, stderr) = run(&["export", "--format", "po", path]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("--format po needs the language to translate into"),
        "{stderr}"
    );
    let (code, _, stderr) = run(&["export", "--format", "po", "--lang", "eng", path]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("English is the language translations are made from"),
        "{stderr}"
    );
}

// ---------------------------------------------------------------------------------------
// PO import

#[test]
fn importing_three_translations_changes_exactly_those_three_lines() {
    let (_dir, path, po) = exported(&seed(), "zu");
    translate(&po, &THREE);
    if let Some((code, stderr)) = msgfmt(&po) {
        assert_eq!(
            (code, stderr.as_str()),
            (0, "3 translated messages, 7 untranslated messages.\n")
        );
    }
    // The seed's key-case error is still there: exit 1, as `ekb fix` with errors left.
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains(
            "imported 3 isiZulu messages (lines 8, 32, 44); 7 untranslated (empty msgstr)",
        ))
        .stderr(contains(
            "kb.dat: written with 2 errors to correct (`ekb check` lists them)",
        ));
    let after = std::fs::read_to_string(&path).unwrap();
    let before = seed();
    assert_eq!(changed_lines(&before, &after), [8, 32, 44]);
    assert_eq!(
        after.lines().nth(31),
        Some("preGestureMessageIsiZulu      4 Le yiRoomba")
    );
    // Every other byte is as it was.
    let strip = |text: &str, lines: &[usize]| -> String {
        text.split_inclusive('\n')
            .enumerate()
            .filter(|(index, _)| !lines.contains(&(index + 1)))
            .map(|(_, line)| line)
            .collect()
    };
    assert_eq!(strip(&before, &[8, 32, 44]), strip(&after, &[8, 32, 44]));
    ekb()
        .args(["-q", "translations", "--lang", "zu"])
        .arg(&path)
        .assert()
        .stdout("isiZulu: 3 translated messages, 7 untranslated messages.\n");
    // Exported again, msgfmt counts the same three; imported again, nothing changes.
    let (_dir2, _, again) = exported(&after, "zu");
    if let Some((_, stderr)) = msgfmt(&again) {
        assert_eq!(stderr, "3 translated messages, 7 untranslated messages.\n");
    }
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains("3 already in the file"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), after);
}

#[test]
fn a_stale_entry_is_named_not_imported_and_exits_1() {
    let (_dir, path, po) = exported(&seed(), "zu");
    translate(&po, &THREE);
    let changed = seed().replace("5 See you again soon\n", "5 See you again soon, goodbye\n");
    std::fs::write(&path, &changed).unwrap();
    let stale_line = std::fs::read_to_string(&po)
        .unwrap()
        .lines()
        .position(|line| line == "msgctxt \"location 5 postGestureMessage\"")
        .unwrap()
        + 1;
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains(format!(
            "zu.po:{stale_line}: stale, not imported: `location 5 postGestureMessage` was translated from \"See you again soon\"; its English is now \"See you again soon, goodbye\""
        )))
        .stderr(contains("imported 2 isiZulu messages (lines 8, 32)"));
    assert_eq!(
        changed_lines(&changed, &std::fs::read_to_string(&path).unwrap()),
        [8, 32]
    );
    import_po(&["--accept-stale"], &po, &path).code(1);
    assert_eq!(
        std::fs::read_to_string(&path).unwrap().lines().nth(43),
        Some("postGestureMessageIsiZulu     5 Sizobonana futhi maduze")
    );
}

/// The seed with its key-case error corrected: a file with no error.
fn seed_without_errors() -> String {
    seed().replace("postGestureMessageenglish ", "postGestureMessageEnglish ")
}

#[test]
fn import_exits_0_into_a_file_left_without_errors_and_its_diff_1_when_it_would_change() {
    let (_dir, path, po) = exported(&seed_without_errors(), "zu");
    translate(&po, &THREE);
    import_po(&["--diff"], &po, &path)
        .code(1)
        .stdout(contains(
            "+postGestureMessageIsiZulu     1 Ngithemba uzokujabulela ukuvakasha",
        ))
        .stderr(contains("would import 3 isiZulu messages"));
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        seed_without_errors()
    );
    import_po(&[], &po, &path)
        .code(0)
        .stderr(contains("imported 3 isiZulu messages"))
        .stderr(contains("written with").not());
    import_po(&["--diff"], &po, &path).code(0).stdout("");
}

#[test]
fn each_entry_says_the_bytes_the_reader_reads_and_that_many_import_cleanly() {
    let (_dir, path, po) = exported(&seed_without_errors(), "zu");
    let text = std::fs::read_to_string(&po).unwrap();
    // `postGestureMessageIsiZulu 5 ` and a newline, in the 199 bytes the reader's fgets reads.
    let limit = 199 - "postGestureMessageIsiZulu 5 \n".len();
    assert_eq!(limit, 170);
    assert!(
        text.contains("#. at most 170 bytes: the robot's reader cuts a longer message (a letter with an accent takes 2)\n#: "),
        "{text}"
    );
    // At the limit, with two-byte letters, it imports; one byte more is refused.
    let fits = format!("a{}{}", "\u{e9}".repeat(80), "a".repeat(limit - 161));
    assert_eq!(fits.len(), limit);
    translate(&po, &[("See you again soon", &fits)]);
    import_po(&[], &po, &path).code(0);
    assert!(std::fs::read_to_string(&path)
        .unwrap()
        .contains(&format!("\npostGestureMessageIsiZulu 5 {fits}\n")));
    let (_dir, path, po) = exported(&seed_without_errors(), "zu");
    translate(&po, &[("See you again soon", &format!("{fits}a"))]);
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains("not imported: error[compat-line-too-long]"));
    // A template says the limit in each language.
    let (_, stdout, _) = run(&["export", "--format", "pot", path.to_str().unwrap()]);
    assert!(stdout.contains(
        "#. at most 170 bytes in isiZulu, 166 in Kinyarwanda: the robot's reader cuts a longer message"
    ), "{stdout}");
}

#[test]
fn fuzzy_and_empty_entries_are_not_imported() {
    let (_dir, path, po) = exported(&seed(), "rw");
    translate(
        &po,
        &[
            ("See you again soon", "Tuzongere kubonana ubutaha"),
            ("This is the Roomba", "Iyiyo yitwa rumba"),
        ],
    );
    let text = std::fs::read_to_string(&po).unwrap().replace(
        "msgctxt \"location 4 preGestureMessage\"",
        "#, fuzzy\nmsgctxt \"location 4 preGestureMessage\"",
    );
    std::fs::write(&po, text).unwrap();
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains("imported 1 Kinyarwanda message (line 45); 8 untranslated (empty msgstr); 1 fuzzy, not imported"));
    assert_eq!(
        changed_lines(&seed(), &std::fs::read_to_string(&path).unwrap()),
        [45]
    );
}

#[test]
fn an_unknown_msgctxt_names_its_line_and_nothing_is_imported() {
    let (_dir, path, po) = exported(&seed(), "zu");
    translate(&po, &THREE);
    let text = std::fs::read_to_string(&po).unwrap().replace(
        "location 5 postGestureMessage",
        "location 9 postGestureMessage",
    );
    let line = text.lines().position(|l| l.contains("location 9")).unwrap() + 1;
    std::fs::write(&po, text).unwrap();
    import_po(&[], &po, &path)
        .code(2)
        .stderr(contains(format!("zu.po:{line}: unknown `msgctxt \"location 9 postGestureMessage\"`: the file has no such location")))
        .stderr(contains("(nothing was imported)"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());
    // A malformed PO file: its line, exit 2.
    std::fs::write(&po, "msgid \"a\"\nmsgstr \"b\n").unwrap();
    import_po(&[], &po, &path).code(2).stderr(contains(
        "zu.po:2: msgstr: expected a string in double quotes",
    ));
}

#[test]
fn a_missing_message_gets_a_line_aligned_in_its_location() {
    let (_dir, path, po) = exported(&partly(), "zu");
    translate(&po, &[("See you again soon", "Sizobonana futhi maduze")]);
    import_po(&["-q"], &po, &path).code(1);
    let after = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = after.lines().collect();
    assert_eq!(
        &lines[42..45],
        [
            "postGestureMessageEnglish     5 See you again soon",
            "postGestureMessageIsiZulu     5 Sizobonana futhi maduze",
            "postGestureMessageKinyarwanda 5 No message in Kinyarwanda",
        ]
    );
    assert_eq!(after.len(), partly().len() + lines[43].len() + 1);
}

#[test]
fn a_crlf_file_keeps_its_line_endings() {
    let crlf = seed().replace('\n', "\r\n");
    let (_dir, path, po) = exported(&crlf, "zu");
    translate(&po, &THREE);
    import_po(&["-q"], &po, &path).code(1);
    let after = std::fs::read_to_string(&path).unwrap();
    assert!(
        after.contains("postGestureMessageIsiZulu     1 Ngithemba uzokujabulela ukuvakasha\r\n")
    );
    assert_eq!(after.matches("\r\n").count(), crlf.matches("\r\n").count());
}

#[test]
fn a_translation_the_reader_would_misread_is_refused_unless_forced() {
    let (_dir, path, po) = exported(&seed(), "zu");
    translate(
        &po,
        &[
            ("See you again soon", "\\\"Sizobonana\\\" futhi maduze"),
            ("This is the Roomba", "Le yiRoomba"),
        ],
    );
    import_po(&[], &po, &path)
        .code(1)
        .stderr(contains("not imported: error[compat-leading-symbol]"))
        .stderr(contains("imported 1 isiZulu message (line 32)"));
    import_po(&["-q", "--force"], &po, &path).code(1);
    assert!(std::fs::read_to_string(&path)
        .unwrap()
        .contains("5 \"Sizobonana\" futhi maduze\n"));
}

// ---------------------------------------------------------------------------------------
// ekb set

#[test]
fn set_changes_only_the_value() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    ekb()
        .args([
            "set",
            "1",
            "preGestureMessageIsiZulu",
            "Siyakwamukela elebhu yamarobhothi",
        ])
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains(
            "kb.dat:5: `preGestureMessageIsiZulu` of location 1 set",
        ));
    let after = std::fs::read_to_string(&path).unwrap();
    assert_eq!(changed_lines(&seed(), &after), [5]);
    assert_eq!(
        after.lines().nth(4),
        Some("preGestureMessageIsiZulu      1 Siyakwamukela elebhu yamarobhothi")
    );
}

#[test]
fn set_adds_a_missing_line_after_the_key_before_it() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    ekb()
        .args([
            "set",
            "4",
            "POSTGESTUREMESSAGEENGLISH",
            "We use it for teaching mobile robotics",
        ])
        .arg(&path)
        .assert()
        .code(0)
        .stderr(contains(
            "kb.dat:35: `postGestureMessageEnglish` of location 4 set",
        ));
    let after = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        after.lines().nth(34),
        Some("postGestureMessageEnglish     4 We use it for teaching mobile robotics")
    );
    assert_eq!(
        after.replace(
            "postGestureMessageEnglish     4 We use it for teaching mobile robotics\n",
            ""
        ),
        seed()
    );
}

#[test]
fn set_refuses_what_the_reader_would_misread_unless_forced() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let path_text = path.to_str().unwrap();
    let (code, _, stderr) = run(&[
        "set",
        "2",
        "preGestureMessageKinyarwanda",
        "\"Iyi\" ni robo",
        path_text,
    ]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("kb.dat:15: error[compat-leading-symbol]"),
        "{stderr}"
    );
    assert!(
        stderr.contains("give --force to write it anyway"),
        "{stderr}"
    );
    let long = "Iyi ni robo ".repeat(20);
    let (code, _, stderr) = run(&["set", "2", "preGestureMessageKinyarwanda", &long, path_text]);
    assert_eq!(code, 1);
    assert!(stderr.contains("error[compat-line-too-long]"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());
    let (code, _, _) = run(&[
        "set",
        "--force",
        "2",
        "preGestureMessageKinyarwanda",
        "\"Iyi\" ni robo",
        path_text,
    ]);
    assert_eq!(code, 0);
    assert!(std::fs::read_to_string(&path)
        .unwrap()
        .contains("preGestureMessageKinyarwanda  2 \"Iyi\" ni robo\n"));
}

#[test]
fn set_says_what_it_cannot_do() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let path = path.to_str().unwrap();
    for (args, expected) in [
        (
            ["set", "1", "preGestureMesageIsiZulu", "x"],
            "is no key; did you mean `preGestureMessageIsiZulu`?",
        ),
        (
            ["set", "9", "preGestureMessageIsiZulu", "x"],
            "the file has no location 9",
        ),
        (
            ["set", "0", "preGestureMessageIsiZulu", "x"],
            "`0` is no location id",
        ),
        (
            ["set", "1", "tourSpecification", "x"],
            "`tourSpecification` belongs to no location",
        ),
        (
            ["set", "1", "preGestureMessageIsiZulu", "a\nb"],
            "a value is one line",
        ),
    ] {
        let mut all = args.to_vec();
        all.push(path);
        let (code, _, stderr) = run(&all);
        assert_eq!(code, 2, "{args:?}");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
    }
    assert_eq!(std::fs::read_to_string(path).unwrap(), seed());
}

#[test]
fn set_on_standard_input_prints_the_new_file() {
    ekb()
        .args(["set", "3", "gestureTarget", "0.7 4.8 0.82", "-"])
        .write_stdin(seed())
        .assert()
        .code(0)
        .stdout(seed().replace(
            "gestureTarget                 3 0.6 4.8 0.82",
            "gestureTarget                 3 0.7 4.8 0.82",
        ));
}
