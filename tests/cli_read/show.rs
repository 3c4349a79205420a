use crate::common::{assert_terminal_safe, fixture, run, SEED};

#[test]
fn one_location_with_line_numbers_and_findings() {
    let out = run(&["show", "4", SEED]);
    assert_eq!(out.code, 0);
    let stdout = &out.stdout;
    assert!(stdout.starts_with(
        "Location 4: Roomba\ndata/environmentKnowledgeBaseInput.dat, lines 28–36; stop 2 of 5 on the tour\n"
    ));
    assert!(stdout.contains("│ 29   ┆ robotLocation                 ┆ 5.0, 3.9, 110.0°"));
    assert!(stdout.contains("│ –    ┆ postGestureMessageEnglish     ┆ MISSING"));
    assert!(stdout.contains("  line 34: error[key-case] `postGestureMessageenglish`"));
    insta::assert_snapshot!("show_seed_4", out.stdout);
}

#[test]
fn the_first_stop_is_the_home_pose() {
    let out = run(&["show", "1", SEED]);
    assert!(out
        .stdout
        .contains("stop 1 of 5 on the tour (the start and home pose)"));
    // seed.dat's tour is 1 2 1.
    let out = run(&["show", "1", &fixture("seed.dat")]);
    assert!(out
        .stdout
        .contains("; stops 1 and 3 of 3 on the tour (the start and home pose)\n"));
    let out = run(&["show", "2", &fixture("no-tour.dat")]);
    assert!(out.stdout.contains("; not on the tour\n"));
}

#[test]
fn current_dialect_fields() {
    let out = run(&["show", "2", &fixture("current.dat")]);
    assert_eq!(out.code, 0);
    assert!(out
        .stdout
        .contains("│ 15   ┆ robotLocationPose             ┆ 3.2, 6.6, 45.0°"));
    assert!(out
        .stdout
        .contains("│ 17   ┆ gestureArm                    ┆ left"));
    assert!(out
        .stdout
        .contains("│ 24   ┆ culturalKnowledge             ┆ DeicticShape"));
    insta::assert_snapshot!("show_current_2", out.stdout);
}

#[test]
fn unknown_id_is_a_usage_error_that_lists_the_nearest() {
    let out = run(&["show", "7", SEED]);
    assert_eq!(out.code, 2);
    assert_eq!(out.stdout, "");
    assert_eq!(
        out.stderr,
        "ekb: error: no location 7 in data/environmentKnowledgeBaseInput.dat; the nearest ids are 5, 4 and 3 (`ekb locations` lists them all)\n"
    );
}

#[test]
fn bad_id_text_is_a_usage_error() {
    for bad in ["abc", "0", "-1", "2147483648"] {
        let out = run(&["show", bad, SEED]);
        assert_eq!(out.code, 2, "{bad}");
        assert!(
            out.stderr
                .contains("a location id is a whole number from 1 to 2147483647"),
            "{}",
            out.stderr
        );
    }
}

#[test]
fn control_characters_are_escaped() {
    let out = run(&["show", "1", &fixture("control.dat")]);
    assert_eq!(out.code, 0);
    assert_terminal_safe(&out.stdout);
    assert!(out.stdout.contains(r"Bell\u{0007} rings"));
}

#[test]
fn values_the_robot_loads_otherwise_are_marked_with_what_the_file_says() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.dat");
    let long = "word ".repeat(50);
    std::fs::write(
        &path,
        format!(
            "robotLocationDescription 1 Roomba  \nrobotLocationPose 1 -3.5 1.0 90\n\
             preGestureMessageEnglish 1 {long}\ntourSpecification 1 1\n\
             postGestureMessageIsiZulu 1 Sawubona"
        ),
    )
    .unwrap();
    let out = run(&["show", "1", path.to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let stdout = &out.stdout;
    assert!(stdout.contains("As reader 2025-06 loads it."), "{stdout}");
    assert!(
        stdout.contains("3.5, 1.0, 90.0° (the file says -3.5, 1.0, 90.0°)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("\"Roomba  \" (the file says Roomba)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("\"Sawubon\" (the file says Sawubona)"),
        "{stdout}"
    );
    // Findings on the location's own lines are listed with it, whatever their rule.
    for line in [
        "line 1: warning[trailing-whitespace]",
        "line 3: error[compat-line-too-long]",
        "line 5: error[compat-no-final-newline]",
    ] {
        assert!(stdout.contains(line), "missing {line:?} in {stdout}");
    }
    // The document's reader ignores robotLocationPose: the robot stands at the origin.
    let seed = run(&["show", "1", "--reader", "d5.4.2", path.to_str().unwrap()]);
    assert!(
        seed.stdout
            .contains("0.0, 0.0, 0.0° (the file says -3.5, 1.0, 90.0°)"),
        "{}",
        seed.stdout
    );
}

#[test]
fn a_message_in_a_language_the_robot_does_not_speak_is_marked_not_spoken() {
    let out = run(&["show", "4", SEED]);
    assert!(
        out.stdout.contains(
            "│ 32   ┆ preGestureMessageIsiZulu      ┆ No message in isiZulu (placeholder, \
             untranslated) (not spoken)"
        ),
        "{}",
        out.stdout
    );
    assert!(!out
        .stdout
        .contains("Kinyarwanda (placeholder, untranslated) (not spoken)"));
    let joined = out.stdout.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        joined.contains(
            "the robot does not speak isiZulu: it says nothing at these stops (its \
             text-to-speech has no isiZulu engine; `[robot] speaks` in ekb.toml says otherwise \
             if yours does)"
        ),
        "{}",
        out.stdout
    );
    assert_eq!(out.stdout.matches("does not speak").count(), 1);
    // Once ekb.toml says the robot speaks isiZulu, nothing is said.
    let (_dir, file) = crate::tour::seed_on_a_robot_that_speaks_isizulu();
    let out = run(&["show", "4", &file]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(!out.stdout.contains("not spoken"), "{}", out.stdout);
    assert!(!out.stdout.contains("does not speak"), "{}", out.stdout);
}
