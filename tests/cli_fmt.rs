//! `ekb fmt`: the canonical layout, `--check`, standard input, refusals and safe writes.

mod author_support;

use author_support::{
    assert_read_only_file_left_intact, culture_knowledge_base, ekb, export_text,
    permissions_are_ignored, read_fixture, seed, temp_file,
};
use ekb::canonical::Document;
use proptest::prelude::*;

/// `ekb fmt -` of `text`: standard output.
fn fmt_stdin(text: &str) -> String {
    let output = ekb().args(["fmt", "-"]).write_stdin(text).output().unwrap();
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    String::from_utf8(output.stdout).unwrap()
}

#[test]
fn fmt_of_the_seed_is_the_committed_canonical_file() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    ekb()
        .arg("fmt")
        .arg(&path)
        .assert()
        .code(0)
        .stderr("1 file reformatted\n");
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("seed.fmt.dat")
    );
    assert_eq!(fmt_stdin(&seed()), read_fixture("seed.fmt.dat"));
}

/// The robot's own current file (from its repository) is already in the canonical layout,
/// long lines included.
#[test]
fn the_robots_own_file_is_already_canonical() {
    let text = read_fixture("upstream-2026-03.dat");
    assert!(text.lines().any(|line| line.len() >= 200));
    ekb()
        .args(["fmt", "--check", "-"])
        .write_stdin(text)
        .assert()
        .code(0)
        .stdout("");
}

#[test]
fn fmt_twice_gives_the_same_bytes() {
    for name in ["messy.dat", "current.dat", "seed-small.dat"] {
        let once = fmt_stdin(&read_fixture(name));
        assert_eq!(fmt_stdin(&once), once, "{name}");
    }
    let (_dir, path) = temp_file("kb.dat", read_fixture("messy.fmt.dat").as_bytes());
    ekb()
        .arg("fmt")
        .arg(&path)
        .assert()
        .code(0)
        .stderr("1 file left unchanged\n");
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        read_fixture("messy.fmt.dat")
    );
}

#[test]
fn fmt_groups_orders_and_keeps_comments_with_the_following_line() {
    // The fixture has comments above a pose line, above a miscased key, a header and a footer;
    // a duplicate key, an unknown key, tabs, trailing blanks and commas in the tour.
    assert_eq!(
        fmt_stdin(&read_fixture("messy.dat")),
        read_fixture("messy.fmt.dat")
    );
    let formatted = read_fixture("messy.fmt.dat");
    assert!(formatted.contains("# The Roomba\nrobotLocation                 4 5.0 3.9 110\n"));
    assert!(formatted.contains(
        "# said last, after the gesture\npostGestureMessageenglish     4 We use it for teaching mobile robotics\n"
    ));
    assert!(formatted.starts_with("# Lab tour, v2 (messy on purpose: ekb fmt tidies it)\n\n"));
    assert!(formatted.ends_with("\ntourSpecification 2 1 4\n\n# end of file\n"));
}

#[test]
fn fmt_never_changes_a_value() {
    for name in ["messy.dat", "current.dat", "seed-small.dat"] {
        let text = read_fixture(name);
        let formatted = fmt_stdin(&text);
        assert_eq!(export_text(&formatted), export_text(&text), "{name}");
        // Text values byte for byte, inner spacing included; numbers keep their spelling.
        for value in [
            "Pepper's  starting location",
            "0.0 0.0 0.0",
            "5.0 3.9 110",
            "-90",
        ] {
            if text.contains(value) {
                assert!(formatted.contains(value), "{name}: {value}");
            }
        }
    }
    let seed = seed();
    assert_eq!(export_text(&fmt_stdin(&seed)), export_text(&seed));
}

#[test]
fn fmt_check_prints_a_diff_and_writes_nothing() {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let output = ekb().args(["fmt", "--check"]).arg(&path).output().unwrap();
    assert_eq!(output.status.code(), Some(1));
    let diff = String::from_utf8(output.stdout).unwrap();
    let name = path.display().to_string();
    assert!(
        diff.starts_with(&format!("--- {name}\n+++ {name}\n@@ -7,6 +7,7 @@\n")),
        "{diff}"
    );
    assert_eq!(
        diff.lines().filter(|line| *line == "+").count(),
        5,
        "{diff}"
    );
    assert_eq!(
        String::from_utf8(output.stderr).unwrap(),
        "1 file would be reformatted\n"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());

    let (_dir, path) = temp_file("kb.dat", read_fixture("seed.fmt.dat").as_bytes());
    ekb()
        .args(["fmt", "--check"])
        .arg(&path)
        .assert()
        .code(0)
        .stdout("")
        .stderr("1 file already formatted\n");
}

#[test]
fn fmt_check_on_standard_input() {
    ekb()
        .args(["fmt", "--check", "-"])
        .write_stdin(read_fixture("seed.fmt.dat"))
        .assert()
        .code(0)
        .stdout("")
        .stderr("");
    ekb()
        .args(["fmt", "--check", "-"])
        .write_stdin(seed())
        .assert()
        .code(1)
        .stdout(predicates::str::starts_with("--- <stdin>\n+++ <stdin>\n"));
}

#[test]
fn fmt_writes_lf_one_final_newline_and_no_bom() {
    let text = "\u{FEFF}gestureTarget 1 1  2\t3  \r\nrobotLocationDescription 1 A\r\n\r\n\r\n";
    assert_eq!(
        fmt_stdin(text),
        "robotLocationDescription      1 A\ngestureTarget                 1 1 2 3\n"
    );
}

#[test]
fn fmt_puts_lines_without_an_id_first_as_written() {
    let text = "robotLocationDescription 1 A\n# which one?\nrobotLocation 4a 1  2 3\ntourSpecification 1 1\n";
    assert_eq!(
        fmt_stdin(text),
        "# which one?\n\
         robotLocation 4a 1  2 3\n\
         \n\
         robotLocationDescription      1 A\n\
         \n\
         tourSpecification 1 1\n"
    );
}

#[test]
fn fmt_refuses_a_stray_carriage_return() {
    let text = "robotLocationDescription 1 A\r\r\ntourSpecification 1 1\n";
    let (_dir, path) = temp_file("kb.dat", text.as_bytes());
    ekb()
        .arg("fmt")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicates::str::contains("cannot format "))
        .stderr(predicates::str::contains(
            "line 1 (`robotLocationDescription 1 A\\u{000D}`) ends in a stray carriage return",
        ));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
}

#[test]
fn fmt_refuses_invalid_utf8() {
    let bytes = b"robotLocationDescription 1 Caf\xe9\n";
    let (_dir, path) = temp_file("kb.dat", bytes);
    ekb()
        .arg("fmt")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicates::str::contains(
            "is not valid UTF-8 (line 1, column 31)",
        ));
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}

#[test]
fn fmt_goes_on_after_a_file_it_cannot_format() {
    let (dir, bad) = temp_file("bad.dat", b"robotLocationDescription 1 Caf\xe9\n");
    let good = dir.path().join("good.dat");
    std::fs::write(&good, seed()).unwrap();
    ekb()
        .arg("fmt")
        .arg(&bad)
        .arg(&good)
        .assert()
        .code(2)
        .stderr(predicates::str::contains("1 file reformatted"));
    assert_eq!(
        std::fs::read_to_string(&good).unwrap(),
        read_fixture("seed.fmt.dat")
    );
}

#[cfg(unix)]
#[test]
fn fmt_keeps_permissions() {
    use std::os::unix::fs::PermissionsExt;
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o640)).unwrap();
    ekb().arg("fmt").arg(&path).assert().code(0);
    let mode = std::fs::metadata(&path).unwrap().permissions().mode();
    assert_eq!(mode & 0o777, 0o640);
}

#[test]
fn fmt_leaves_a_read_only_file_intact() {
    assert_read_only_file_left_intact("fmt");
}

#[cfg(unix)]
#[test]
fn fmt_leaves_a_file_in_a_read_only_folder_intact() {
    use std::os::unix::fs::PermissionsExt;
    if permissions_are_ignored() {
        eprintln!("skipped: this user ignores file permissions (root)");
        return;
    }
    let (dir, path) = temp_file("kb.dat", seed().as_bytes());
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o555)).unwrap();
    let assert = ekb().arg("fmt").arg(&path).assert();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    assert
        .code(2)
        .stderr(predicates::str::contains("cannot create a file in folder"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());
}

/// A line of a knowledge base, well placed or not, in any layout.
fn any_line() -> impl Strategy<Value = String> {
    let keys = prop::sample::select(vec![
        "robotLocationDescription",
        "robotLocation",
        "robotLocationPose",
        "gestureTarget",
        "gestureArm",
        "preGestureMessageEnglish",
        "postGestureMessageenglish",
        "PreGestureMessageIsizulu",
        "culturalKnowledge",
        "unknownKey",
    ]);
    let blank = prop::sample::select(vec![" ", "\t", "   ", " \t "]);
    let id = prop::sample::select(vec!["1", "2", "03", "17", "4a", "0", ""]);
    let value = "[A-Za-z0-9.,'!?é-]{1,8}( {1,2}[A-Za-z0-9.,'!?é-]{1,8}){0,3}";
    let entry = (
        keys,
        blank.clone(),
        id,
        blank.clone(),
        value,
        prop::option::of(blank),
    )
        .prop_map(|(key, gap, id, gap2, value, trailing)| {
            format!("{key}{gap}{id}{gap2}{value}{}", trailing.unwrap_or(""))
        });
    prop_oneof![
        6 => entry,
        1 => "# [a-z ]{0,10}".prop_map(String::from),
        1 => Just(String::new()),
        1 => "tourSpecification( [1-9]){0,4}".prop_map(String::from),
    ]
}

fn any_file() -> impl Strategy<Value = String> {
    (
        prop::collection::vec(any_line(), 0..24),
        prop::sample::select(vec!["\n", "\r\n"]),
        any::<bool>(),
    )
        .prop_map(|(lines, ending, final_newline)| {
            let mut text = lines.join(ending);
            if final_newline && !text.is_empty() {
                text.push_str(ending);
            }
            text
        })
}

/// Every entry as `(key, id, value)`, with the blanks inside values collapsed.
fn entries(text: &str) -> Vec<(String, String)> {
    let mut entries: Vec<(String, String)> = text
        .lines()
        .map(str::trim)
        .filter(|line| !line.is_empty() && !line.starts_with('#'))
        .map(|line| {
            let mut words = line.split_whitespace();
            let key = words.next().unwrap().to_string();
            (key, words.collect::<Vec<_>>().join(" "))
        })
        .collect();
    entries.sort();
    entries
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn fmt_is_idempotent_and_keeps_every_entry(text in any_file()) {
        let document = Document::parse(&text).unwrap();
        let once = document.render();
        prop_assert_eq!(Document::parse(&once).unwrap().render(), once.clone());
        prop_assert_eq!(entries(&once), entries(&text));
        prop_assert_eq!(export_text(&once), export_text(&text));
    }
}

#[test]
fn fmt_refuses_a_file_that_is_not_an_environment_knowledge_base() {
    // Reordering the culture knowledge base's lines would be a change, and a wrong one.
    let bytes = culture_knowledge_base();
    let (_dir, path) = temp_file("cultureKnowledgeBaseInput.dat", &bytes);
    ekb()
        .arg("fmt")
        .arg(&path)
        .assert()
        .code(2)
        .stdout("")
        .stderr(predicates::str::contains(
            "cultureKnowledgeBaseInput.dat: this is not an environment knowledge base: none of \
             its 78 `key value` lines has one of its keys (the first is `passingDistance`)",
        ));
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}
