use std::path::PathBuf;

use crate::common::{assert_terminal_safe, fixture, run, SEED};

/// A copy of the seed file with `from` replaced by `to`, in a temporary folder.
fn seed_with(dir: &tempfile::TempDir, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(SEED))
        .unwrap();
    assert!(text.contains(from), "{from}");
    let path = dir.path().join("new.dat");
    std::fs::write(&path, text.replace(from, to)).unwrap();
    path
}

#[test]
fn layout_comments_and_order_are_not_differences() {
    let out = run(&[
        "diff",
        &fixture("current.dat"),
        &fixture("current-reordered.dat"),
    ]);
    assert_eq!(out.code, 0, "{}", out.stdout);
    assert_eq!(
        out.stdout,
        "No differences: tests/fixtures/read/current.dat and tests/fixtures/read/current-reordered.dat describe the same knowledge base\n"
    );
    let out = run(&["diff", SEED, SEED, "--format", "json"]);
    assert_eq!(out.code, 0);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["equal"], true);
}

#[test]
fn quiet_equal_prints_nothing() {
    let out = run(&["-q", "diff", SEED, SEED]);
    assert_eq!((out.code, out.stdout.as_str()), (0, ""));
}

#[test]
fn locations_and_tour_changes() {
    let out = run(&[
        "diff",
        &fixture("current.dat"),
        &fixture("current-changed.dat"),
    ]);
    assert_eq!(out.code, 1);
    assert!(out.stdout.contains(
        "    robotLocationDescription: \"Pepper robot\" (old line 14) → \"The other Pepper robot\" (new line 14)\n"
    ));
    assert!(out
        .stdout
        .contains("- location 3, Lynxmotion arm (old lines 26–36)\n"));
    assert!(out
        .stdout
        .contains("+ location 4, Roomba (new lines 26–36)\n"));
    insta::assert_snapshot!("diff_current_changed", out.stdout);
}

#[test]
fn json_format() {
    let out = run(&[
        "diff",
        "--format",
        "json",
        &fixture("current.dat"),
        &fixture("current-changed.dat"),
    ]);
    assert_eq!(out.code, 1);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["equal"], false);
    assert_eq!(json["dialect"], serde_json::Value::Null);
    assert_eq!(
        json["added"],
        serde_json::json!([{"id": 4, "description": "Roomba", "lines": [26, 36]}])
    );
    assert_eq!(json["removed"][0]["id"], 3);
    let changed = &json["changed"][0];
    assert_eq!(changed["id"], 2);
    let fields: Vec<&str> = changed["fields"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["field"].as_str().unwrap())
        .collect();
    assert_eq!(
        fields,
        [
            "robotLocationDescription",
            "pose",
            "postGestureMessageIsiZulu"
        ]
    );
    assert_eq!(
        changed["fields"][1],
        serde_json::json!({
            "field": "pose",
            "old": {"x": 3.2, "y": 6.6, "theta": 45.0},
            "new": {"x": 3.4, "y": 6.6, "theta": 60.0},
            "oldLine": 15,
            "newLine": 15
        })
    );
    let tour = &json["tour"];
    assert_eq!(tour["added"], serde_json::json!([4]));
    assert_eq!(tour["removed"], serde_json::json!([3]));
    assert_eq!(tour["reordered"], false);
    assert_eq!(tour["old"]["stops"], serde_json::json!([1, 2, 3]));
    assert_eq!(tour["new"]["line"], 38);
}

#[test]
fn a_dialect_change_is_reported_once() {
    let out = run(&[
        "diff",
        &fixture("seed.dat"),
        &fixture("seed-as-current.dat"),
    ]);
    assert_eq!(out.code, 1);
    assert_eq!(
        out.stdout,
        "--- tests/fixtures/read/seed.dat\n\
         +++ tests/fixtures/read/seed-as-current.dat\n\
         dialect: seed (robotLocation) → current (robotLocationPose)\n\
         Summary: dialect changed\n"
    );
}

#[test]
fn tour_order() {
    let dir = tempfile::tempdir().unwrap();
    let new = seed_with(
        &dir,
        "tourSpecification 5 1 4 3 2 5",
        "tourSpecification 5 1 3 4 2 5",
    );
    let out = run(&["diff", SEED, new.to_str().unwrap()]);
    assert_eq!(out.code, 1);
    assert!(out
        .stdout
        .contains("tour: 1 → 4 → 3 → 2 → 5 (old line 46) → 1 → 3 → 4 → 2 → 5 (new line 46)\n    order changed\n"));
}

#[test]
fn a_removed_field_shows_as_absent() {
    let dir = tempfile::tempdir().unwrap();
    let new = seed_with(&dir, "gestureTarget                 2 3.2 8.4 0.82\n", "");
    let out = run(&["diff", SEED, new.to_str().unwrap()]);
    assert_eq!(out.code, 1);
    assert!(out
        .stdout
        .contains("~ location 2, The (other) Pepper robot\n    gestureTarget: 3.2, 8.4, 0.82 (old line 12) → absent\n"));
}

#[test]
fn errors_exit_2() {
    let out = run(&["diff", SEED, &fixture("no-such-file.dat")]);
    assert_eq!(out.code, 2);
    assert_eq!(
        out.stderr,
        "ekb: error: cannot read tests/fixtures/read/no-such-file.dat: no such file\n"
    );
    assert_eq!(run(&["diff", SEED]).code, 2);
}

#[test]
fn control_characters_are_escaped() {
    let out = run(&["diff", &fixture("seed.dat"), &fixture("control.dat")]);
    assert_eq!(out.code, 1);
    assert_terminal_safe(&out.stdout);
    assert!(out.stdout.contains(
        r#""Red\u{001B}[31m alert\u{202E RIGHT-TO-LEFT OVERRIDE} reversed" (new line 1)"#
    ));
    let out = run(&[
        "diff",
        "--format",
        "json",
        &fixture("seed.dat"),
        &fixture("control.dat"),
    ]);
    assert_terminal_safe(&out.stdout);
}

#[test]
fn standard_input_as_one_side() {
    let seed = std::fs::read(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(SEED)).unwrap();
    let out = crate::common::run_with(
        crate::common::ekb()
            .args(["diff", SEED, "-"])
            .write_stdin(seed),
    );
    assert_eq!(out.code, 0);
    assert!(out
        .stdout
        .ends_with("and <stdin> describe the same knowledge base\n"));
    assert_eq!(run(&["diff", "-", "-"]).code, 2);
}
