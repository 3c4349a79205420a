use crate::common::{assert_terminal_safe, ekb, fixture, run, run_with, SEED};

#[test]
fn table_of_the_seed() {
    let out = run(&["locations", SEED]);
    assert_eq!(out.code, 0);
    assert_eq!(
        out.stderr,
        "ekb: note: data/environmentKnowledgeBaseInput.dat has 2 errors; `ekb check` lists them\n"
    );
    // Location 4's English message after the gesture is missing (its key is miscased).
    assert!(out.stdout.contains("after  EN ✗ ZU ~ RW ~"));
    // The seed dialect has no gesture arms: no column for them.
    assert!(!out.stdout.contains(" arm "));
    insta::assert_snapshot!("locations_seed_table", out.stdout);
}

#[test]
fn table_of_the_current_dialect_has_the_arm_column() {
    let out = run(&["locations", &fixture("current.dat")]);
    assert_eq!(out.code, 0);
    assert_eq!(out.stderr, "");
    insta::assert_snapshot!("locations_current_table", out.stdout);
}

#[test]
fn table_fits_the_width() {
    let out = run_with(ekb().env("COLUMNS", "70").args(["locations", SEED]));
    assert_eq!(out.code, 0);
    for line in out
        .stdout
        .lines()
        .filter(|line| line.starts_with(['┌', '│', '╞', '└']))
    {
        assert!(line.chars().count() <= 70, "too wide: {line}");
    }
}

#[test]
fn json_has_status_and_tour_positions() {
    let out = run(&["locations", "--format", "json", SEED]);
    assert_eq!(out.code, 0);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let ids: Vec<u64> = json["locations"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, [1, 2, 3, 4, 5]);
    let roomba = &json["locations"][3];
    assert_eq!(roomba["description"], "Roomba");
    assert_eq!(roomba["tourPositions"], serde_json::json!([2]));
    assert_eq!(roomba["lines"], serde_json::json!([28, 36]));
    assert_eq!(
        roomba["messageStatus"]["postGestureMessage"],
        serde_json::json!({"english": "missing", "isiZulu": "placeholder", "kinyarwanda": "placeholder"})
    );
    assert_eq!(
        roomba["postGestureMessage"]["english"],
        serde_json::Value::Null
    );
    assert_eq!(json["tour"], serde_json::json!([1, 4, 3, 2, 5]));
}

#[test]
fn classic_is_the_robots_printout() {
    let out = run(&["locations", "--format", "classic", SEED]);
    assert_eq!(out.code, 0);
    let first_block: Vec<&str> = out.stdout.split("\n\n").next().unwrap().lines().collect();
    assert_eq!(
        first_block,
        [
            "Key                              1    ",
            "Location Description             Pepper's starting location ",
            "Robot Location                   (2.6, 8.1 -90.0)",
            "Gesture Target                   (0.0, 0.0 0.0) ",
            "Pre-Gesture Message English      Welcome the the robotics lab at Carnegie Mellon University Africa ",
            "Pre-Gesture Message isiZulu      No message in isiZulu ",
            "Pre-Gesture Message Kinyarwanda  No message in Kinyarwanda ",
            "Post-Gesture Message English     I hope you enjoy the tour ",
            "Post-Gesture Message isiZulu     No message in isiZulu ",
            "Post-Gesture Message Kinyarwanda No message in Kinyarwanda ",
        ]
    );
    // As on the robot: one decimal of a 32-bit float, and nothing for a missing message.
    assert!(out
        .stdout
        .contains("Gesture Target                   (3.2, 8.4 0.8) \n"));
    assert!(out.stdout.contains("Post-Gesture Message English      \n"));
    insta::assert_snapshot!("locations_seed_classic", out.stdout);
}

#[test]
fn control_characters_are_escaped_in_every_format() {
    for format in ["table", "json", "classic"] {
        let out = run(&["locations", "--format", format, &fixture("control.dat")]);
        assert_eq!(out.code, 0, "{format}");
        assert_terminal_safe(&out.stdout);
        assert_terminal_safe(&out.stderr);
    }
    let table = run(&["locations", &fixture("control.dat")]).stdout;
    assert!(table.contains(r"Red\u{001B}[31m alert\u{202E RIGHT-TO-LEFT OVERRIDE} reversed"));
    let json = run(&["locations", "--format", "json", &fixture("control.dat")]).stdout;
    assert!(json.contains(r#""description": "Red\u001b[31m alert\u202e reversed""#));
}

#[test]
fn bad_format_and_missing_file_exit_2() {
    assert_eq!(run(&["locations", "--format", "xml", SEED]).code, 2);
    let out = run(&["locations", &fixture("no-such-file.dat")]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("no such file"), "{}", out.stderr);
}

#[test]
fn without_a_file_the_configured_knowledge_base_is_read() {
    // config/environmentKnowledgeBaseConfiguration.ini names data/environmentKnowledgeBaseInput.dat.
    let configured = run(&["locations", "--format", "json"]);
    assert_eq!(configured.code, 0);
    assert_eq!(
        configured.stdout,
        run(&["locations", "--format", "json", SEED]).stdout
    );
}

#[test]
fn values_as_the_chosen_reader_loads_them() {
    let out = run(&["locations", "--reader", "2025-06", SEED]);
    assert_eq!(out.code, 0);
    assert!(
        out.stdout
            .contains("0.0, 0.0, 0.0° (the file says 2.6, 8.1, -90.0°)"),
        "{}",
        out.stdout
    );
    assert!(out
        .stdout
        .contains("5 locations, as reader 2025-06 loads them."));
    // The robot's own printout prints what it holds.
    let classic = run(&[
        "locations",
        "--format",
        "classic",
        "--reader",
        "2025-06",
        SEED,
    ]);
    assert!(
        classic
            .stdout
            .contains("Robot Location                   (0.0, 0.0 0.0)\n"),
        "{}",
        classic.stdout
    );
    assert!(!classic.stdout.contains("(2.6, 8.1 -90.0)"));
    let json = run(&["locations", "--format", "json", "--reader", "2026-02", SEED]);
    let json: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(json["reader"], "2026-02");
}
