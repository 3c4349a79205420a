use crate::common::{assert_terminal_safe, fixture, run, SEED};

/// The `Stop N: location ID` headings, as (N, ID).
fn stops(text: &str) -> Vec<(u32, u32)> {
    text.lines()
        .filter_map(|line| line.strip_prefix("Stop "))
        .map(|rest| {
            let (number, rest) = rest.split_once(": location ").unwrap();
            let id: String = rest.chars().take_while(char::is_ascii_digit).collect();
            (number.parse().unwrap(), id.parse().unwrap())
        })
        .collect()
}

#[test]
fn isizulu_tour_of_the_seed() {
    let out = run(&["tour", "--lang", "isizulu", SEED]);
    assert_eq!(out.code, 0);
    assert_eq!(stops(&out.stdout), [(1, 1), (2, 4), (3, 3), (4, 2), (5, 5)]);
    assert!(out.stdout.contains(
        "Stop 1: location 1, Pepper's starting location  [start: the robot's initial pose and home]\n"
    ));
    assert!(out
        .stdout
        .ends_with("\nisiZulu: 0 of 10 messages translated (10 placeholders)\n"));
    assert!(out.stdout.contains(
        "  says before  UNTRANSLATED: the file has the placeholder \"No message in isiZulu\" (line 5)\n               translate from English: \"Welcome the the robotics lab at Carnegie Mellon University Africa\"\n"
    ));
    insta::assert_snapshot!("tour_seed_isizulu", out.stdout);
}

#[test]
fn languages_by_name_or_code_in_any_case() {
    let reference = run(&["tour", "--lang", "isizulu", SEED]).stdout;
    for spelling in ["isiZulu", "ISIZULU", "zu", "ZU", "zul", "Zulu"] {
        assert_eq!(
            run(&["tour", "--lang", spelling, SEED]).stdout,
            reference,
            "{spelling}"
        );
    }
    for spelling in ["RW", "kin", "Kinyarwanda"] {
        let kinyarwanda = run(&["tour", "--lang", spelling, SEED]).stdout;
        assert!(
            kinyarwanda.ends_with("Kinyarwanda: 0 of 10 messages translated (10 placeholders)\n"),
            "{spelling}"
        );
    }
    assert_eq!(
        run(&["tour", "--lang", "ENG", SEED]).stdout,
        run(&["tour", "--lang", "english", SEED]).stdout
    );
}

#[test]
fn bad_language_lists_the_choices() {
    let out = run(&["tour", "--lang", "french", SEED]);
    assert_eq!(out.code, 2);
    assert!(
        out.stderr
            .contains("invalid value 'french' for '--lang <L>'"),
        "{}",
        out.stderr
    );
    assert!(
        out.stderr
            .contains(
                "[possible values: english, isizulu, kinyarwanda, zulu, ikinyarwanda, en, zu, rw, eng, zul, kin, all]"
            ),
        "{}",
        out.stderr
    );
}

#[test]
fn english_shows_the_missing_message() {
    let out = run(&["tour", "--lang", "en", SEED]);
    assert_eq!(out.code, 0);
    assert!(out.stdout.contains(
        "Stop 2: location 4, Roomba\n  stands at    5.0, 3.9, 110.0°\n  gesture      points at 6.8, 4.8, 0.82\n  says before  \"This is the Roomba\" (line 31)\n  says after   MISSING: no English message, the robot says nothing\n"
    ));
    assert!(out
        .stdout
        .ends_with("English: 9 of 10 messages written (1 missing)\n"));
}

#[test]
fn current_dialect_tour() {
    let out = run(&["tour", "--lang", "zu", &fixture("current.dat")]);
    assert_eq!(out.code, 0);
    assert!(out
        .stdout
        .contains("  gesture      points at 4.4, 7.8, 0.82 with the left arm\n"));
    assert!(out.stdout.contains(
        "  gesture      does not point: the target 1.0, -1.0, 0.0 sums to 0, which the robot's reader takes for \"no gesture\"\n"
    ));
    assert!(out
        .stdout
        .ends_with("isiZulu: 2 of 6 messages translated (4 placeholders)\n"));
    insta::assert_snapshot!("tour_current_isizulu", out.stdout);
}

#[test]
fn json_format() {
    let out = run(&["tour", "--lang", "zu", "--format", "json", SEED]);
    assert_eq!(out.code, 0);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["language"], "isiZulu");
    assert_eq!(json["translated"], 0);
    assert_eq!(json["messages"], 10);
    let ids: Vec<u64> = json["stops"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, [1, 4, 3, 2, 5]);
    let first = &json["stops"][0];
    assert_eq!(first["start"], true);
    assert_eq!(first["points"], false);
    assert_eq!(json["stops"][1]["start"], false);
    assert_eq!(
        first["before"],
        serde_json::json!({
            "status": "placeholder",
            "text": "No message in isiZulu",
            "line": 5,
            "english": "Welcome the the robotics lab at Carnegie Mellon University Africa",
            "robotSays": "No message in isiZulu"
        })
    );
    assert_eq!(json["reader"], "d5.4.2");
    assert!(json.get("robotTour").is_none());
    assert_eq!(
        json["stops"][1]["after"]["english"],
        serde_json::Value::Null
    );
}

#[test]
fn a_stop_with_no_location() {
    let out = run(&["tour", &fixture("tour-unknown-stop.dat")]);
    assert_eq!(out.code, 0);
    assert!(out.stdout.contains(
        "Stop 2: location 9 — NOT IN THE FILE: the robot has nothing to do or say here\n"
    ));
    assert!(out
        .stdout
        .ends_with("English: 4 of 6 messages written (2 missing)\n"));
}

#[test]
fn no_tour() {
    let out = run(&["tour", &fixture("no-tour.dat")]);
    assert_eq!(out.code, 1);
    assert_eq!(out.stdout, "");
    assert!(out.stderr.contains(
        "ekb: tests/fixtures/read/no-tour.dat has no tour: add a `tourSpecification` line"
    ));
}

#[test]
fn control_characters_are_escaped() {
    for format in ["text", "json"] {
        let out = run(&["tour", "--format", format, &fixture("control.dat")]);
        assert_eq!(out.code, 0);
        assert_terminal_safe(&out.stdout);
    }
}

#[test]
fn the_tour_as_the_chosen_reader_loads_it() {
    // Today's robot ignores `robotLocation`: it stands at the origin at every stop.
    let out = run(&["tour", "--reader", "2025-06", SEED]);
    assert_eq!(out.code, 0);
    assert!(out.stdout.starts_with("Tour of data/environmentKnowledgeBaseInput.dat in English: 5 stops (1 → 4 → 3 → 2 → 5), as reader 2025-06 loads it\n"), "{}", out.stdout);
    assert!(
        out.stdout
            .contains("stands at    0.0, 0.0, 0.0° (the file says 2.6, 8.1, -90.0°)"),
        "{}",
        out.stdout
    );
    // A last message without a newline loses its last letter; an indented tour is no tour.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("kb.dat");
    let text = std::fs::read_to_string(fixture("current.dat")).unwrap();
    let text = text.replace("tourSpecification", " tourSpecification");
    std::fs::write(&path, text.trim_end()).unwrap();
    let out = run(&[
        "tour",
        "--lang",
        "rw",
        "--format",
        "json",
        path.to_str().unwrap(),
    ]);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(json["robotTour"], serde_json::json!([]));
    let text = run(&["tour", "--lang", "rw", path.to_str().unwrap()]).stdout;
    assert!(
        text.contains("The robot's reader loads another tour: no tour at all"),
        "{text}"
    );
}

/// The seed file in a temporary folder, with an `ekb.toml` that says the robot speaks
/// isiZulu too; the file's path.
pub fn seed_on_a_robot_that_speaks_isizulu() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let file = dir.path().join("kb.dat");
    std::fs::copy(here.join(SEED), &file).unwrap();
    std::fs::write(
        dir.path().join("ekb.toml"),
        "[robot]\nspeaks = [\"english\", \"isiZulu\", \"kinyarwanda\"]\n",
    )
    .unwrap();
    (dir, file.display().to_string())
}

#[test]
fn a_tour_in_a_language_the_robot_does_not_speak_says_so_first() {
    let notice = "the robot does not speak isiZulu: it says nothing at these stops (its \
                  text-to-speech has no isiZulu engine; `[robot] speaks` in ekb.toml says \
                  otherwise if yours does)\n";
    let out = run(&["tour", "--lang", "zu", SEED]);
    assert!(out.stdout.starts_with(notice), "{}", out.stdout);
    assert_eq!(out.stdout.matches("does not speak").count(), 1);
    let json = run(&["tour", "--lang", "zu", "--format", "json", SEED]);
    let json: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(json["spoken"], false);
    // Languages it speaks: no notice.
    for lang in ["en", "rw"] {
        let out = run(&["tour", "--lang", lang, SEED]);
        assert!(out.stdout.starts_with("Tour of "), "{}", out.stdout);
        let json = run(&["tour", "--lang", lang, "--format", "json", SEED]);
        let json: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
        assert_eq!(json["spoken"], true);
    }
    // Once ekb.toml says the robot speaks isiZulu, nothing is said.
    let (_dir, file) = seed_on_a_robot_that_speaks_isizulu();
    let out = run(&["tour", "--lang", "zu", &file]);
    assert!(out.stdout.starts_with("Tour of "), "{}", out.stdout);
    assert!(!out.stdout.contains("does not speak"));
    let json = run(&["tour", "--lang", "zu", "--format", "json", &file]);
    let json: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(json["spoken"], true);
}
