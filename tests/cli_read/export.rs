use crate::common::{assert_terminal_safe, fixture, run, SEED};

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).expect("valid JSON")
}

#[test]
fn the_seed_has_errors_so_it_is_not_exported() {
    let out = run(&["export", SEED]);
    assert_eq!(out.code, 1);
    assert_eq!(out.stdout, "");
    assert_eq!(
        out.stderr,
        "data/environmentKnowledgeBaseInput.dat:28:1: error[missing-field] location 4 has no `postGestureMessageEnglish`: location 4 will say nothing after the gesture in English\n\
         data/environmentKnowledgeBaseInput.dat:34:1: error[key-case] `postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case: the robot's reader ignores this line, so location 4 will say nothing after the gesture in English\n\
         ekb: not exported: data/environmentKnowledgeBaseInput.dat has 2 errors (fix them, or give --allow-errors to export what the robot would load)\n"
    );
}

#[test]
fn the_shape_of_the_export() {
    let out = run(&["export", "--allow-errors", SEED]);
    assert_eq!(out.code, 0);
    // Numbers as written: 2.6 is 2.6, not 2.5999999046325684.
    assert!(out.stdout.contains("\"x\": 2.6,"));
    let value = json(&out.stdout);
    let keys =
        |v: &serde_json::Value| -> Vec<String> { v.as_object().unwrap().keys().cloned().collect() };
    let mut top = keys(&value);
    top.sort();
    assert_eq!(top, ["dialect", "locations", "tour"]);
    assert_eq!(value["dialect"], "seed");
    assert_eq!(value["tour"], serde_json::json!([1, 4, 3, 2, 5]));
    let locations = value["locations"].as_array().unwrap();
    let ids: Vec<u64> = locations
        .iter()
        .map(|l| l["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, [1, 2, 3, 4, 5]);
    assert_eq!(
        locations[0],
        serde_json::json!({
            "id": 1,
            "description": "Pepper's starting location",
            "pose": { "x": 2.6, "y": 8.1, "theta": -90.0 },
            "gestureTarget": { "x": 0.0, "y": 0.0, "z": 0.0 },
            "gestureArm": null,
            "preGestureMessage": {
                "english": "Welcome the the robotics lab at Carnegie Mellon University Africa",
                "isiZulu": "No message in isiZulu",
                "kinyarwanda": "No message in Kinyarwanda"
            },
            "postGestureMessage": {
                "english": "I hope you enjoy the tour",
                "isiZulu": "No message in isiZulu",
                "kinyarwanda": "No message in Kinyarwanda"
            },
            "culturalKnowledge": []
        })
    );
    // A field absent from the file is null.
    assert_eq!(
        locations[3]["postGestureMessage"]["english"],
        serde_json::Value::Null
    );
}

#[test]
fn current_dialect_with_warnings_exports() {
    let out = run(&["export", &fixture("current.dat")]);
    assert_eq!(out.code, 0);
    assert_eq!(out.stderr, "");
    let value = json(&out.stdout);
    assert_eq!(value["dialect"], "current");
    assert_eq!(value["locations"][0]["gestureArm"], "right");
    assert_eq!(
        value["locations"][0]["culturalKnowledge"],
        serde_json::json!(["SymbolicShapeRespect", "BowExtentRespect"])
    );
    assert_eq!(value["tour"], serde_json::json!([1, 2, 3]));
}

#[test]
fn layout_does_not_change_the_export() {
    let current = run(&["export", &fixture("current.dat")]);
    // Indented lines are misread by the robot (an error), but plain export is as written.
    let reordered = run(&[
        "export",
        "--allow-errors",
        &fixture("current-reordered.dat"),
    ]);
    assert_eq!(current.stdout, reordered.stdout);
}

#[test]
fn output_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.json");
    let out = run(&["export", &fixture("seed.dat"), "-o", path.to_str().unwrap()]);
    assert_eq!(out.code, 0);
    assert_eq!(out.stdout, "");
    let written = std::fs::read_to_string(&path).unwrap();
    assert_eq!(written, run(&["export", &fixture("seed.dat")]).stdout);
}

#[test]
fn schema_is_derived() {
    let out = run(&["export", "--schema"]);
    assert_eq!(out.code, 0);
    let schema = json(&out.stdout);
    assert_eq!(schema["title"], "ExportedKnowledgeBase");
    assert_eq!(schema["required"], serde_json::json!(["locations"]));
    let location = &schema["definitions"]["ExportedLocation"];
    assert_eq!(location["additionalProperties"], false);
    assert_eq!(location["properties"]["id"]["minimum"], 1.0);
}

#[test]
fn control_characters_are_escaped_but_kept() {
    let out = run(&["export", "--allow-errors", &fixture("control.dat")]);
    assert_eq!(out.code, 0);
    assert_terminal_safe(&out.stdout);
    let value = json(&out.stdout);
    assert_eq!(
        value["locations"][0]["description"],
        "Red\u{1b}[31m alert\u{202E} reversed"
    );
}

#[cfg(unix)]
#[test]
fn output_file_keeps_the_permissions_it_replaces() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let fresh = dir.path().join("fresh.json");
    let existing = dir.path().join("existing.json");
    std::fs::write(&existing, "old").unwrap();
    std::fs::set_permissions(&existing, std::fs::Permissions::from_mode(0o640)).unwrap();
    for path in [&fresh, &existing] {
        let out = run(&["export", &fixture("seed.dat"), "-o", path.to_str().unwrap()]);
        assert_eq!(out.code, 0);
    }
    let mode =
        |path: &std::path::Path| std::fs::metadata(path).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&fresh), 0o644);
    assert_eq!(mode(&existing), 0o640);
}
