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
    assert!(
        out.stderr.contains("1 comment line is not in the JSON"),
        "{}",
        out.stderr
    );
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
    // The same locations, each in the order of its file.
    let by_id = |stdout: &str| {
        let mut value = json(stdout);
        let locations = value["locations"].as_array_mut().unwrap();
        locations.sort_by_key(|location| location["id"].as_u64());
        value
    };
    assert_eq!(by_id(&current.stdout), by_id(&reordered.stdout));
    assert_ne!(current.stdout, reordered.stdout);
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

// ---------------------------------------------------------------- as the robot loads it

#[test]
fn as_loaded_shows_what_each_reader_loads() {
    let seed = json(&run(&["export", "--as-loaded", SEED]).stdout);
    assert_eq!(seed["reader"], "d5.4.2");
    assert_eq!(
        seed["locations"][0]["pose"],
        serde_json::json!({"x": 2.6, "y": 8.1, "theta": -90.0})
    );
    // The miscased key is not read: location 4 says nothing after the gesture.
    assert_eq!(seed["locations"][3]["postGestureMessage"]["english"], "");
    assert_eq!(seed["locations"][0]["gestureArm"], serde_json::Value::Null);
    assert_eq!(
        seed["locations"][0]["culturalKnowledge"],
        serde_json::Value::Null
    );
    // Today's robot ignores `robotLocation`: every pose at the origin.
    let today = run(&["export", "--as-loaded", "--reader", "2025-06", SEED]);
    assert_eq!(today.code, 0, "{}", today.stderr);
    let today = json(&today.stdout);
    for location in today["locations"].as_array().unwrap() {
        assert_eq!(
            location["pose"],
            serde_json::json!({"x": 0.0, "y": 0.0, "theta": 0.0})
        );
    }
    assert_eq!(today["tour"], serde_json::json!([1, 4, 3, 2, 5]));
}

#[test]
fn as_loaded_keeps_what_the_reader_keeps_and_drops_what_it_drops() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.dat");
    std::fs::write(
        &path,
        "robotLocationDescription 1 Roomba  \r\nrobotLocationPose 1 -2.5 1.0 90\r\n\
         gestureArm 1 right \r\nculturalKnowledge 1 Bow's\r\ntourSpecification 2 1\r\n\
         postGestureMessageIsiZulu 1 Sawubona",
    )
    .unwrap();
    let path = path.to_str().unwrap();
    let export = |reader: &str| {
        let out = run(&["export", "--as-loaded", "--reader", reader, path]);
        assert_eq!(out.code, 0, "{}", out.stderr);
        json(&out.stdout)
    };
    let loaded = export("2026-03");
    let location = &loaded["locations"][0];
    assert_eq!(location["description"], "Roomba  \r");
    assert_eq!(location["pose"]["x"], 2.5);
    assert_eq!(location["gestureArm"], "right \r");
    assert_eq!(
        location["culturalKnowledge"],
        serde_json::json!(["Bow's", "s"])
    );
    assert_eq!(location["postGestureMessage"]["isiZulu"], "Sawubon");
    // The second stop is read past the line's end, where the longer line before left the
    // `s` of `Bow's`: `%d` fails there, and the slot keeps the 0 it started with.
    assert_eq!(loaded["tour"], serde_json::json!([1, 0]));
    assert_eq!(
        export("2025-06")["locations"][0]["gestureArm"],
        serde_json::Value::Null
    );
    // Plain export stays as written.
    let written = json(&run(&["export", "--allow-errors", path]).stdout);
    assert_eq!(written["locations"][0]["description"], "Roomba");
    assert_eq!(written["locations"][0]["pose"]["x"], -2.5);
}

#[test]
fn as_loaded_refuses_a_file_the_reader_crashes_on() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("deep.dat");
    // 2026-04 crashes from a depth of 1,932 (the lowest measured over both builds).
    let text: String = (1..=2_000)
        .map(|id| format!("robotLocationDescription {id} Exhibit {id}\n"))
        .collect();
    std::fs::write(&path, text).unwrap();
    let path = path.to_str().unwrap();
    let crash = run(&["export", "--as-loaded", "--reader", "2026-04", path]);
    assert_eq!(crash.code, 1);
    assert_eq!(crash.stdout, "");
    assert!(
        crash.stderr.contains("error[compat-reader-crash]"),
        "{}",
        crash.stderr
    );
    assert!(
        crash.stderr.contains("reader 2026-04 crashes on"),
        "{}",
        crash.stderr
    );
    let deeper = run(&["export", "--as-loaded", "--reader", "2025-06", path]);
    assert_eq!(deeper.code, 0, "{}", deeper.stderr);
    assert_eq!(
        json(&deeper.stdout)["locations"].as_array().unwrap().len(),
        2_000
    );
}

/// A location whose culturalKnowledge line is `words`, as a file of the current dialect.
fn culture_words_file(dir: &std::path::Path, words: &str) -> String {
    let path = dir.join(format!("{}.dat", words.len()));
    std::fs::write(
        &path,
        format!(
            "robotLocationPose 1 1.0 2.0 90\nculturalKnowledge 1 {words}\ntourSpecification 1 1\n"
        ),
    )
    .unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn culture_words_past_two_crash_the_reader_when_the_location_has_another_line() {
    let dir = tempfile::tempdir().unwrap();
    // Past the buffer's two words (written apart or split by the reader), the location's
    // other line makes the reader update it, and it crashes (measured on the real readers).
    for (words, rule) in [
        ("a b c", "compat-too-many-cultural-keys"),
        ("Deictic_Shape Bow", "compat-cultural-word-split"),
        ("a b c d", "compat-too-many-cultural-keys"),
        ("Deictic_Shape Bow's", "compat-cultural-word-split"),
        ("Deictic_Shape Bow Smile", "compat-too-many-cultural-keys"),
    ] {
        let path = culture_words_file(dir.path(), words);
        let out = run(&["export", "--as-loaded", "--reader", "2025-06", &path]);
        assert_eq!(out.code, 1, "{words}");
        assert!(
            out.stderr.contains(&format!("error[{rule}]"))
                && out.stderr.contains("reader 2025-06 crashes on"),
            "{words}: {}",
            out.stderr
        );
    }
    // Alone on its location, the line loads, its third word over the word count: no crash.
    let alone = dir.path().join("alone.dat");
    std::fs::write(&alone, "culturalKnowledge 1 a b c\ntourSpecification 1 1\n").unwrap();
    let alone = alone.to_str().unwrap();
    let out = run(&["export", "--as-loaded", "--reader", "2025-06", alone]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        json(&out.stdout)["locations"][0]["culturalKnowledge"]
            .as_array()
            .unwrap()
            .len(),
        3
    );
    let check = run(&["check", "--reader", "2025-06", "--format", "concise", alone]);
    assert!(
        check
            .stdout
            .contains(":1:25: error[compat-too-many-cultural-keys]")
            && check
                .stdout
                .contains("writes c past the end of its buffer, the third word's pointer over the location's word count")
            && check.stdout.contains("so it does not crash"),
        "{}",
        check.stdout
    );
    // The document's reader has no culturalKnowledge: it ignores the line whole.
    let path = culture_words_file(dir.path(), "a b c d");
    let seed = run(&["export", "--as-loaded", "--reader", "d5.4.2", &path]);
    assert_eq!(seed.code, 0, "{}", seed.stderr);
    assert_eq!(
        json(&seed.stdout)["locations"][0]["culturalKnowledge"],
        serde_json::Value::Null
    );
    let check = run(&["check", "--reader", "d5.4.2", "--format", "concise", &path]);
    assert!(
        !check.stdout.contains("compat-too-many-cultural-keys"),
        "{}",
        check.stdout
    );
}

#[test]
fn an_indented_culture_line_of_two_words_crashes_the_reader_with_another_line() {
    let dir = tempfile::tempdir().unwrap();
    // Indented, the reader counts the key's length from the line's start and reads the id
    // as a word: `1 Bow Nod`, three words for its buffer of two (measured on the real
    // readers: with the pose line it crashes, alone it loads the three).
    let path = dir.path().join("indented.dat");
    std::fs::write(
        &path,
        "robotLocationPose 1 1.0 2.0 90\n  culturalKnowledge 1 Bow Nod\ntourSpecification 1 1\n",
    )
    .unwrap();
    let path = path.to_str().unwrap();
    let out = run(&["export", "--as-loaded", "--reader", "2025-06", path]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr.contains(":2:1: error[compat-indented-line]")
            && out.stderr.contains("loads the words `1 Bow Nod`")
            && out.stderr.contains("and crashes while the robot starts")
            && out.stderr.contains("reader 2025-06 crashes on"),
        "{}",
        out.stderr
    );
    let alone = dir.path().join("alone.dat");
    std::fs::write(
        &alone,
        "  culturalKnowledge 1 Bow Nod\ntourSpecification 1 1\n",
    )
    .unwrap();
    let alone = alone.to_str().unwrap();
    let out = run(&["export", "--as-loaded", "--reader", "2025-06", alone]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        json(&out.stdout)["locations"][0]["culturalKnowledge"],
        serde_json::json!(["1", "Bow", "Nod"])
    );
    let check = run(&["check", "--reader", "2025-06", "--format", "concise", alone]);
    assert!(
        check.stdout.contains(":1:1: error[compat-indented-line]")
            && check.stdout.contains("it writes past its end")
            && !check.stdout.contains("crashes"),
        "{}",
        check.stdout
    );
    // One word indented loads two, which the buffer holds: no crash.
    let one_word = dir.path().join("one.dat");
    std::fs::write(
        &one_word,
        "robotLocationPose 1 1.0 2.0 90\n  culturalKnowledge 1 Bow\ntourSpecification 1 1\n",
    )
    .unwrap();
    let out = run(&[
        "export",
        "--as-loaded",
        "--reader",
        "2025-06",
        one_word.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
}
