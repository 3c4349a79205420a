//! Standards (issue 12, item 6): SARIF's artifact URIs are URI references as the 2.1.0
//! schema requires, for standard input and for names that are not UTF-8 too; `import`
//! refuses an unknown field anywhere, naming its JSON path; and export → import → export
//! keeps the dialect even when no location has a pose to tell it.

mod output_support;

use std::path::Path;

use output_support::ekb;
use serde_json::Value;

/// A file with findings (a repeated word, a placeholder), in the seed dialect.
const FILE: &str = "\
robotLocationDescription      1 Entrance
robotLocation                 1 2.6 8.1 -90
gestureTarget                 1 0.0 0.0 0.0
preGestureMessageEnglish      1 Welcome the the lab
preGestureMessageIsiZulu      1 No message in isiZulu
preGestureMessageKinyarwanda  1 Murakaza neza
postGestureMessageEnglish     1 Enjoy the tour
postGestureMessageIsiZulu     1 Sawubona
postGestureMessageKinyarwanda 1 Murakoze
tourSpecification 1 1
";

/// Whether `uri` is a URI reference of RFC 3986 (the JSON Schema format `uri-reference`
/// that SARIF 2.1.0 gives `artifactLocation.uri`): only its characters, every `%` starting
/// an escape, and no `:` in the first segment of a relative reference.
fn is_uri_reference(uri: &str) -> bool {
    let allowed = |ch: char| ch.is_ascii_alphanumeric() || "-._~!$&'()*+,;=:@/?#[]%".contains(ch);
    let escapes_complete = uri.match_indices('%').all(|(at, _)| {
        uri.as_bytes()
            .get(at + 1..at + 3)
            .is_some_and(|hex| hex.iter().all(u8::is_ascii_hexdigit))
    });
    let scheme = uri.split_once(':').is_some_and(|(scheme, _)| {
        scheme.starts_with(|c: char| c.is_ascii_alphabetic())
            && scheme
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c))
    });
    let first_segment = uri.split(['/', '?', '#']).next().unwrap_or("");
    !uri.is_empty()
        && uri.chars().all(allowed)
        && escapes_complete
        && (scheme || !first_segment.contains(':'))
}

/// The `uri` of every result's location in SARIF `output`.
fn result_uris(output: &[u8]) -> Vec<String> {
    let sarif: Value = serde_json::from_slice(output).unwrap();
    let results = sarif["runs"][0]["results"].as_array().unwrap();
    assert!(!results.is_empty());
    results
        .iter()
        .map(|result| {
            let location = &result["locations"][0]["physicalLocation"]["artifactLocation"];
            location["uri"].as_str().unwrap().to_string()
        })
        .collect()
}

#[test]
fn uri_references_are_told_from_other_text() {
    for valid in [
        "data/kb.dat",
        "%3Cstdin%3E",
        "file:///srv/kb.dat",
        "k%FFb.dat",
    ] {
        assert!(is_uri_reference(valid), "{valid}");
    }
    for invalid in [
        "<stdin>",
        "my kb.dat",
        "a%zz.dat",
        "1:kb.dat",
        "Ùmuntu.dat",
        "",
    ] {
        assert!(!is_uri_reference(invalid), "{invalid}");
    }
}

#[test]
fn sarif_of_standard_input_has_a_uri_reference() {
    let dir = tempfile::tempdir().unwrap();
    let output = ekb(dir.path())
        .args(["check", "--format", "sarif", "-"])
        .write_stdin(FILE)
        .output()
        .unwrap();
    for uri in result_uris(&output.stdout) {
        assert_eq!(uri, "%3Cstdin%3E");
        assert!(is_uri_reference(&uri));
    }
}

#[test]
fn sarif_uris_of_odd_names_are_uri_references() {
    let dir = tempfile::tempdir().unwrap();
    for (name, expected) in [
        ("my kb #1?.dat", "my%20kb%20%231%3F.dat"),
        ("a:b[1]%.dat", "a%3Ab%5B1%5D%25.dat"),
        ("Ùmuntu.dat", "%C3%99muntu.dat"),
    ] {
        std::fs::write(dir.path().join(name), FILE).unwrap();
        let output = ekb(dir.path())
            .args(["check", "--format", "sarif", name])
            .output()
            .unwrap();
        for uri in result_uris(&output.stdout) {
            assert_eq!(uri, expected);
            assert!(is_uri_reference(&uri), "{uri}");
        }
    }
}

#[cfg(unix)]
#[test]
fn sarif_percent_encodes_the_bytes_of_a_name_that_is_not_utf8() {
    use std::os::unix::ffi::OsStrExt;
    let dir = tempfile::tempdir().unwrap();
    let name = std::ffi::OsStr::from_bytes(b"k\xffb.dat");
    std::fs::write(dir.path().join(name), FILE).unwrap();
    let output = ekb(dir.path())
        .args(["check", "--format", "sarif"])
        .arg(name)
        .output()
        .unwrap();
    for uri in result_uris(&output.stdout) {
        assert_eq!(uri, "k%FFb.dat");
    }
}

/// An export of one location; `pose` and `target` are the JSON of those fields.
fn export(dialect: &str, pose: &str, target: &str) -> String {
    format!(
        r#"{{"dialect": {dialect}, "locations": [{{"id": 1, "description": "Entrance",
        "pose": {pose}, "gestureTarget": {target}, "gestureArm": null,
        "preGestureMessage": {{"english": "Welcome", "isiZulu": null, "kinyarwanda": null}},
        "postGestureMessage": {{"english": null, "isiZulu": null, "kinyarwanda": null}},
        "culturalKnowledge": []}}], "tour": [1]}}"#
    )
}

#[test]
fn import_refuses_unknown_fields_inside_pose_and_gesture_target() {
    let dir = tempfile::tempdir().unwrap();
    let point = r#"{"x": 1.0, "y": 2.0, "z": 0.5}"#;
    for (json, path, field) in [
        (
            export(
                r#""current""#,
                r#"{"x": 1.0, "y": 2.0, "theta": 90, "z": 0}"#,
                point,
            ),
            "locations[0].pose.z",
            "`z`",
        ),
        (
            export(
                r#""current""#,
                "null",
                r#"{"x": 1.0, "y": 2.0, "z": 0.5, "arm": "left"}"#,
            ),
            "locations[0].gestureTarget.arm",
            "`arm`",
        ),
    ] {
        let output = ekb(dir.path())
            .args(["import", "-"])
            .write_stdin(json)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2));
        assert!(output.stdout.is_empty());
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(
            stderr.starts_with(&format!("ekb: error: <stdin>: {path} (line ")),
            "{stderr}"
        );
        assert!(
            stderr.contains(&format!("unknown field {field}")),
            "{stderr}"
        );
    }
}

/// The dialect of `ekb export` of the file `ekb import` makes of `json`.
fn dialect_after_import(dir: &Path, json: &str) -> Value {
    let imported = ekb(dir)
        .args(["import", "-"])
        .write_stdin(json)
        .output()
        .unwrap();
    let exported = ekb(dir)
        .args(["export", "--allow-errors", "-"])
        .write_stdin(imported.stdout)
        .output()
        .unwrap();
    let export: Value = serde_json::from_slice(&exported.stdout).unwrap();
    export["dialect"].clone()
}

#[test]
fn export_import_export_keeps_the_dialect_without_poses() {
    let dir = tempfile::tempdir().unwrap();
    let target = r#"{"x": 0.0, "y": 0.0, "z": 0.0}"#;
    for dialect in ["seed", "current"] {
        let json = export(&format!("\"{dialect}\""), "null", target);
        assert_eq!(dialect_after_import(dir.path(), &json), dialect);
    }
    // No dialect stays none; a pose tells it without a declaration.
    assert_eq!(
        dialect_after_import(dir.path(), &export("null", "null", target)),
        Value::Null
    );
    let pose = r#"{"x": 1.0, "y": 2.0, "theta": 90}"#;
    let json = export(r#""seed""#, pose, target);
    let imported = ekb(dir.path())
        .args(["import", "-"])
        .write_stdin(json.clone())
        .output()
        .unwrap();
    assert!(!String::from_utf8(imported.stdout)
        .unwrap()
        .contains("# ekb: dialect"));
    assert_eq!(dialect_after_import(dir.path(), &json), "seed");
}

#[test]
fn the_declared_dialect_chooses_the_reader_and_fmt_keeps_it() {
    let dir = tempfile::tempdir().unwrap();
    let json = export(r#""seed""#, "null", r#"{"x": 0.0, "y": 0.0, "z": 0.0}"#);
    let imported = ekb(dir.path())
        .args(["import", "-"])
        .write_stdin(json)
        .output()
        .unwrap();
    let text = String::from_utf8(imported.stdout).unwrap();
    assert!(text.starts_with("# ekb: dialect seed\n\n"), "{text}");
    std::fs::write(dir.path().join("kb.dat"), &text).unwrap();
    ekb(dir.path())
        .args(["fmt", "--check", "kb.dat"])
        .assert()
        .code(0);
    let output = ekb(dir.path())
        .args(["check", "--format", "concise", "kb.dat"])
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.contains("checked against reader d5.4.2"), "{stdout}");
}
