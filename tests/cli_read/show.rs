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
