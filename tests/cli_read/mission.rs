//! `ekb mission check|tree|walk` on the robot's set-up copied from the corpus
//! (`tests/fixtures/mission/corpus/`), and `ekb check` on a mission or culture file alone.

use std::path::Path;

use serde_json::Value;

use crate::common::{ekb, run, run_with, Run};

const CONFIG: &str = "tests/fixtures/mission/corpus/config";
const DATA: &str = "tests/fixtures/mission/corpus/data";

/// A copy of the corpus set-up in a temporary folder, with `edit` applied to the file
/// `name` of `data/` (or `config/`).
fn edited_set_up(name: &str, edit: impl Fn(&str) -> String) -> tempfile::TempDir {
    let root = tempfile::tempdir().unwrap();
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    for folder in ["config", "data"] {
        std::fs::create_dir(root.path().join(folder)).unwrap();
        let from = here.join("tests/fixtures/mission/corpus").join(folder);
        for entry in std::fs::read_dir(from).unwrap() {
            let path = entry.unwrap().path();
            let file = path.file_name().unwrap();
            let mut text = std::fs::read_to_string(&path).unwrap();
            if file == name {
                text = edit(&text);
            }
            std::fs::write(root.path().join(folder).join(file), text).unwrap();
        }
    }
    root
}

fn in_language(word: &str) -> tempfile::TempDir {
    edited_set_up("cultureKnowledgeBaseInput.dat", |text| {
        text.replace(
            "phraseLanguage                            English",
            &format!("phraseLanguage {word}"),
        )
    })
}

fn config_of(root: &tempfile::TempDir) -> String {
    root.path().join("config").display().to_string()
}

fn json(run: &Run) -> Value {
    serde_json::from_str(&run.stdout).unwrap_or_else(|e| panic!("{e}: {}", run.stdout))
}

/// The rules of a `--format json` report's findings, with their severities.
fn rules_of(report: &Value, severity: &str) -> Vec<String> {
    report["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|d| d["severity"] == severity)
        .map(|d| d["rule"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn the_corpus_set_up_has_no_error() {
    let checked = run(&[
        "mission",
        "check",
        "--config-dir",
        CONFIG,
        "--format",
        "json",
    ]);
    assert_eq!(checked.code, 0, "{}", checked.stderr);
    let report = json(&checked);
    assert_eq!(report["summary"]["errors"], 0);
    assert_eq!(report["summary"]["files"], 4);
    let warnings = rules_of(&report, "warning");
    let case = warnings
        .iter()
        .filter(|r| *r == "cultural-knowledge-unknown-key")
        .count();
    assert_eq!(case, 6);
    // The reader note names the environment knowledge base's reader only.
    assert_eq!(report["reader"], "2025-06");
    assert_eq!(report["readers"].as_object().unwrap().len(), 1);
}

#[test]
fn an_isizulu_mission_misses_its_phrases_and_its_tour() {
    let root = in_language("IsiZulu");
    let checked = run(&[
        "mission",
        "check",
        "--config-dir",
        &config_of(&root),
        "--format",
        "json",
    ]);
    assert_eq!(checked.code, 1);
    let errors = rules_of(&json(&checked), "error");
    let count = |rule: &str| errors.iter().filter(|r| *r == rule).count();
    assert_eq!(count("mission-missing-phrase"), 7);
    assert_eq!(count("mission-untranslated-tour"), 10);
    assert_eq!(count("mission-language-not-spoken"), 1);
    assert_eq!(errors.len(), 18);
    let wrong_case = in_language("isiZulu");
    let checked = run(&[
        "mission",
        "check",
        "--config-dir",
        &config_of(&wrong_case),
        "--format",
        "concise",
    ]);
    assert_eq!(checked.code, 1);
    assert!(
        checked
            .stdout
            .contains("cultureKnowledgeBaseInput.dat:10:16: error[mission-language-invalid]"),
        "{}",
        checked.stdout
    );
}

#[test]
fn a_mission_in_a_language_the_robot_does_not_speak_is_an_error_unless_ekb_toml_says_it_does() {
    let root = in_language("IsiZulu");
    let check = || {
        run(&[
            "mission",
            "check",
            "--config-dir",
            &config_of(&root),
            "--format",
            "concise",
        ])
    };
    let checked = check();
    assert_eq!(checked.code, 1);
    assert!(
        checked.stdout.contains(
            "cultureKnowledgeBaseInput.dat:10:16: error[mission-language-not-spoken] the \
             mission speaks isiZulu, which the robot's text-to-speech does not speak: every \
             phrase and every talk of the tour is silent"
        ),
        "{}",
        checked.stdout
    );
    std::fs::write(
        root.path().join("ekb.toml"),
        "[robot]\nspeaks = [\"english\", \"isiZulu\", \"kinyarwanda\"]\n",
    )
    .unwrap();
    let checked = check();
    assert!(
        !checked.stdout.contains("mission-language-not-spoken"),
        "{}",
        checked.stdout
    );
    // An English mission is spoken by the default robot.
    let english = run(&[
        "mission",
        "check",
        "--config-dir",
        CONFIG,
        "--format",
        "concise",
    ]);
    assert!(!english.stdout.contains("mission-language-not-spoken"));
    let explained = run(&["explain", "mission-language-not-spoken"]);
    assert_eq!(explained.code, 0, "{}", explained.stderr);
    assert!(
        explained.stdout.contains("no isiZulu engine"),
        "{}",
        explained.stdout
    );
}

#[test]
fn files_can_be_named_one_by_one() {
    let data = |name: &str| format!("{DATA}/{name}");
    let checked = run(&[
        "mission",
        "check",
        "--format",
        "concise",
        "--mission",
        &data("labTour.xml"),
        "--culture-kb",
        &data("cultureKnowledgeBaseInput.dat"),
        "--culture-types",
        &data("cultureKnowledgeValueTypesInput.dat"),
        "--kb",
        &data("environmentKnowledgeBaseInput.dat"),
    ]);
    assert_eq!(checked.code, 0, "{}", checked.stderr);
    assert!(checked
        .stdout
        .contains("warning[cultural-knowledge-unknown-key]"));
    // A flag replaces the file the configuration names.
    let other = run(&[
        "mission",
        "check",
        "--config-dir",
        CONFIG,
        "--format",
        "concise",
        "--mission",
        "tests/fixtures/mission/rules/mission-unknown-node/bad/labTour.xml",
    ]);
    assert_eq!(other.code, 1);
    assert!(
        other.stdout.contains("error[mission-unknown-node]"),
        "{}",
        other.stdout
    );
}

#[test]
fn the_walk_of_the_corpus_in_english() {
    let walked = run(&["mission", "walk", "--config-dir", CONFIG, "--lang", "en"]);
    assert_eq!(walked.code, 0, "{}", walked.stderr);
    insta::assert_snapshot!(walked.stdout);
}

#[test]
fn the_walk_visits_the_tour_in_order_and_ends() {
    let walked = run(&[
        "mission",
        "walk",
        "--config-dir",
        CONFIG,
        "--lang",
        "en",
        "--format",
        "json",
    ]);
    let walk = json(&walked);
    assert_eq!(walk["outcome"]["status"], "completed");
    assert_eq!(walk["language"], "English");
    let steps = walk["steps"].as_array().unwrap();
    let visited: Vec<u64> = steps
        .iter()
        .filter(|s| s["action"] == "go-to")
        .map(|s| s["place"]["location"].as_u64().unwrap())
        .collect();
    assert_eq!(visited, [1, 4, 3, 2, 5]);
    let said: Vec<&str> = steps
        .iter()
        .filter(|s| s["action"] == "say")
        .map(|s| s["text"].as_str().unwrap())
        .collect();
    assert_eq!(
        said.first(),
        Some(&"Hello! Welcome to the Robotics Lab! I'm Pepper, your friendly robot tour guide.")
    );
    assert_eq!(said.last(), Some(&"Goodbye"));
    // Each stop's messages before and after the gesture, between the welcome and goodbye.
    assert_eq!(said.len(), 3 + 5 * 2 + 1);
    // The targets of locations 1 and 5 are 0 0 0: the robot points at the other three.
    assert_eq!(steps.iter().filter(|s| s["action"] == "point").count(), 3);
}

#[test]
fn a_walk_in_isizulu_crashes_at_the_welcome_whose_phrase_is_undefined() {
    // The robot holds a null pointer for an UNDEFINED phrase and makes a string of it:
    // it throws, and the robot stops at the first SayText.
    let walked = run(&["mission", "walk", "--config-dir", CONFIG, "--lang", "zu"]);
    assert_eq!(walked.code, 1);
    assert!(
        walked.stdout.contains(
            "end: the robot crashes at `SayText` (line 55): utilityPhraseIsiZulu4 is typed \
             UNDEFINED"
        ),
        "{}",
        walked.stdout
    );
    assert!(walked.stdout.contains("logic_error"), "{}", walked.stdout);
}

#[test]
fn a_phrase_in_a_language_the_robot_does_not_speak_is_walked_as_silence() {
    // The isiZulu phrases declared and given, so that the robot holds them (it cannot say
    // them; the visitor's isiZulu answer it does not understand either).
    let root = edited_set_up("cultureKnowledgeValueTypesInput.dat", |text| {
        text.lines()
            .map(|line| match line.starts_with("utilityPhraseIsiZulu") {
                true => line.replace("UNDEFINED", "PHRASE"),
                false => line.to_string(),
            })
            .map(|line| line + "\n")
            .collect()
    });
    let culture = root.path().join("data/cultureKnowledgeBaseInput.dat");
    let mut text = std::fs::read_to_string(&culture).unwrap();
    for n in 1..=7 {
        text.push_str(&format!("utilityPhraseIsiZulu{n} Sawubona {n} \n"));
    }
    std::fs::write(&culture, text).unwrap();
    let walk = || {
        run(&[
            "mission",
            "walk",
            "--config-dir",
            &config_of(&root),
            "--lang",
            "zu",
        ])
    };
    let walked = walk();
    assert!(
        walked.stdout.contains(
            "say nothing: the robot does not speak isiZulu (\"Sawubona 4 \" goes unheard)"
        ),
        "{}",
        walked.stdout
    );
    assert!(
        !walked.stdout.contains("say \"Sawubona"),
        "{}",
        walked.stdout
    );
    let as_json = run(&[
        "mission",
        "walk",
        "--config-dir",
        &config_of(&root),
        "--lang",
        "zu",
        "--format",
        "json",
    ]);
    let walk_json = json(&as_json);
    let says: Vec<&Value> = walk_json["steps"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["action"] == "say")
        .collect();
    assert!(!says.is_empty());
    assert!(says
        .iter()
        .all(|s| s["silent"] == "the robot does not speak isiZulu"));
    // Once ekb.toml says the robot speaks isiZulu, it says the phrases.
    std::fs::write(
        root.path().join("ekb.toml"),
        "[robot]\nspeaks = [\"english\", \"isiZulu\", \"kinyarwanda\"]\n",
    )
    .unwrap();
    let walked = walk();
    assert!(
        walked.stdout.contains("say \"Sawubona 4 \""),
        "{}",
        walked.stdout
    );
    assert!(!walked
        .stdout
        .contains("say nothing: the robot does not speak"));
}

#[test]
fn a_mission_with_no_language_the_robot_accepts_hears_no_answer_and_fails() {
    // The robot knows no yes-word of `isiZulu`: it asks three times, says "maybe another
    // time", and the main tree fails.
    let root = in_language("isiZulu");
    let walked = run(&["mission", "walk", "--config-dir", &config_of(&root)]);
    assert_eq!(walked.code, 1);
    assert!(
        walked.stdout.contains("hear no answer"),
        "{}",
        walked.stdout
    );
    assert!(
        walked.stdout.contains("end: the mission fails"),
        "{}",
        walked.stdout
    );
    assert!(
        walked
            .stderr
            .contains("`isiZulu` is not one the robot accepts"),
        "{}",
        walked.stderr
    );
}

#[test]
fn without_speech_recognition_the_tablet_answer_is_not_read_and_the_mission_fails() {
    let root = edited_set_up("behaviorControllerConfiguration.ini", |text| {
        text.replace("asrEnabled true", "asrEnabled false")
    });
    let walked = run(&["mission", "walk", "--config-dir", &config_of(&root)]);
    assert_eq!(walked.code, 1);
    assert!(walked.stdout.contains("ask on the tablet: Yes or No"));
    assert!(walked.stdout.contains("say \"Maybe another time\""));
    assert!(walked.stdout.ends_with(
        "end: the mission fails: its main tree returns FAILURE; the robot asks its operator \
         whether to run the mission again, and shuts down unless they type `y`\n"
    ));
}

#[test]
fn without_start_of_tree_the_robot_runs_the_mission_again_at_once() {
    // StartOfTree is what asks the operator at the robot's console; the robot's loop ticks
    // the tree again whenever it returns.
    let root = edited_set_up("labTour.xml", |text| {
        text.replace(
            "<StartOfTree _description=\"Used for debugging and initializing values\"/>",
            "",
        )
    });
    let walked = run(&["mission", "walk", "--config-dir", &config_of(&root)]);
    assert!(
        walked
            .stdout
            .ends_with("end: the tour is over; the robot runs the mission again at once\n"),
        "{}",
        walked.stdout
    );
    let as_json = run(&[
        "mission",
        "walk",
        "--config-dir",
        &config_of(&root),
        "--format",
        "json",
    ]);
    assert_eq!(json(&as_json)["operatorAsked"], Value::Bool(false));
}

#[test]
fn the_tree_shows_each_nodes_parameter_and_phrase() {
    let tree = run(&["mission", "tree", "--config-dir", CONFIG]);
    assert_eq!(tree.code, 0, "{}", tree.stderr);
    assert!(tree.stdout.starts_with("TourGuide (main tree, line 151)\n  Sequence\n    StartOfTree\n    SubTree ID=\"DetectVisitor\"\n"));
    assert!(
        tree.stdout
            .contains("\n      SayText \"7\" says \"Goodbye\"\n"),
        "{}",
        tree.stdout
    );
    assert!(tree
        .stdout
        .contains("RetryUntilSuccessful num_attempts=\"3\""));
    let zulu = run(&[
        "mission",
        "tree",
        "--config-dir",
        CONFIG,
        "--lang",
        "zu",
        "--format",
        "json",
    ]);
    let trees = json(&zulu);
    let end_tour = &trees["trees"][2];
    assert_eq!(end_tour["id"], "EndTour");
    let say = &end_tour["nodes"][0]["children"][0]["children"][0];
    assert_eq!(say["node"], "SayText");
    assert_eq!(say["says"]["key"], "utilityPhraseIsiZulu7");
    assert_eq!(
        say["says"]["problem"],
        "is typed UNDEFINED in the types file"
    );
}

#[test]
fn check_recognises_a_mission_and_a_culture_file_alone() {
    let mission = run(&["check", &format!("{DATA}/labTour.xml")]);
    assert_eq!(mission.code, 0, "{}", mission.stdout);
    assert_eq!(mission.stdout, "No problems found\n");
    let culture = run(&[
        "check",
        "--format",
        "concise",
        &format!("{DATA}/cultureKnowledgeBaseInput.dat"),
    ]);
    assert_eq!(culture.code, 0);
    assert!(
        culture.stdout.contains("warning[culture-no-final-newline]"),
        "{}",
        culture.stdout
    );
    assert!(!culture.stdout.contains("not-an-environment-knowledge-base"));
    let types = run(&[
        "check",
        &format!("{DATA}/cultureKnowledgeValueTypesInput.dat"),
    ]);
    assert_eq!(types.code, 0, "{}", types.stdout);
    let broken = run(&[
        "check",
        "--format",
        "concise",
        "tests/fixtures/mission/rules/mission-invalid-xml/bad/labTour.xml",
    ]);
    assert_eq!(broken.code, 1);
    assert!(
        broken
            .stdout
            .contains("labTour.xml:6:3: error[mission-invalid-xml]"),
        "{}",
        broken.stdout
    );
}

#[test]
fn what_cannot_be_found_is_said_with_exit_2() {
    let nowhere = run(&[
        "mission",
        "check",
        "--config-dir",
        "tests/fixtures/mission/no-such-folder",
    ]);
    assert_eq!(nowhere.code, 2);
    assert!(
        nowhere.stderr.contains("does not exist"),
        "{}",
        nowhere.stderr
    );
    let nothing = run(&["mission", "check"]);
    assert_eq!(nothing.code, 2);
    assert!(
        nothing.stderr.contains("--config-dir"),
        "{}",
        nothing.stderr
    );
    let no_kb = run(&[
        "mission",
        "walk",
        "--mission",
        &format!("{DATA}/labTour.xml"),
    ]);
    assert_eq!(no_kb.code, 2);
    assert!(no_kb.stderr.contains("--kb"), "{}", no_kb.stderr);
    let unreadable = run(&[
        "mission",
        "tree",
        "--mission",
        "tests/fixtures/mission/rules/mission-invalid-xml/bad/labTour.xml",
    ]);
    assert_eq!(unreadable.code, 2);
    assert!(
        unreadable.stderr.contains("ekb mission check"),
        "{}",
        unreadable.stderr
    );
}

#[test]
fn an_endless_loop_is_reported_not_run_forever() {
    let root = edited_set_up("labTour.xml", |_| {
        "<root BTCPP_format=\"4\" main_tree_to_execute=\"Loop\">\
         <BehaviorTree ID=\"Loop\"><KeepRunningUntilFailure><AlwaysSuccess/>\
         </KeepRunningUntilFailure></BehaviorTree></root>"
            .to_string()
    });
    let walked = run_with(ekb().args(["mission", "walk", "--config-dir", &config_of(&root)]));
    assert_eq!(walked.code, 1);
    assert!(walked.stdout.contains("never ends"), "{}", walked.stdout);
}

#[test]
fn a_phrase_the_types_file_does_not_declare_repeats_the_last_one_said() {
    let walked = run(&[
        "mission",
        "walk",
        "--config-dir",
        CONFIG,
        "--mission",
        "tests/fixtures/mission/rules/mission-missing-phrase/bad/labTour.xml",
    ]);
    assert_eq!(walked.code, 0, "{}", walked.stderr);
    assert_eq!(
        walked.stdout.lines().nth(2),
        Some(
            "3. say \"Please follow me as I move around.\" — utilityPhraseEnglish8 is not \
             declared in the types file: the robot says the phrase it looked up last"
        )
    );
}

#[test]
fn the_configuration_folder_is_read_as_the_robot_reads_it() {
    // The behaviour controller takes the rest of the line as the value: `= labTour`.
    let root = edited_set_up("behaviorControllerConfiguration.ini", |text| {
        text.replace(
            "scenarioSpecification labTour",
            "scenarioSpecification = labTour",
        )
    });
    let checked = run(&["mission", "check", "--config-dir", &config_of(&root)]);
    assert_eq!(checked.code, 2, "{}", checked.stderr);
    assert!(
        checked
            .stderr
            .contains("with the value `= labTour`, not `labTour`"),
        "{}",
        checked.stderr
    );
    assert!(
        checked.stderr.contains("= labTour.xml"),
        "{}",
        checked.stderr
    );
    // The corpus's own files draw no warning.
    let corpus = run(&["mission", "check", "--config-dir", CONFIG]);
    assert!(!corpus.stderr.contains("warning"), "{}", corpus.stderr);
}

#[test]
fn an_isizulu_answer_is_never_understood_and_the_tour_never_starts() {
    // With every isiZulu phrase typed PHRASE, the welcome is said; then the robot listens,
    // knows no isiZulu yes-word, and the visitor never answers.
    let root = edited_set_up("cultureKnowledgeValueTypesInput.dat", |text| {
        text.lines()
            .map(|line| match line.starts_with("utilityPhraseIsiZulu") {
                true => line.replace("UNDEFINED", "PHRASE"),
                false => line.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n")
            + "\n"
    });
    let culture = root.path().join("data/cultureKnowledgeBaseInput.dat");
    let mut text = std::fs::read_to_string(&culture).unwrap();
    for number in 1..=7 {
        text.push_str(&format!("\nutilityPhraseIsiZulu{number} Sawubona {number}"));
    }
    std::fs::write(&culture, text + "\n").unwrap();
    let walked = run(&[
        "mission",
        "walk",
        "--config-dir",
        &config_of(&root),
        "--lang",
        "zu",
    ]);
    assert!(
        walked.stdout.contains("hear no answer"),
        "{}",
        walked.stdout
    );
    assert!(!walked.stdout.contains("go to"), "{}", walked.stdout);
}

#[test]
fn a_delay_and_a_sleep_are_pauses_of_the_walk() {
    let root = edited_set_up("labTour.xml", |text| {
        text.replace(
            "      <Fallback>\n        <SayText name=\"2\"",
            "      <Sleep msec=\"1500\"/>\n      <Fallback>\n        <SayText name=\"2\"",
        )
    });
    let walked = run(&["mission", "walk", "--config-dir", &config_of(&root)]);
    let lines: Vec<&str> = walked.stdout.lines().collect();
    // The Delay of 3,000 ms before the answer is heard, then the Sleep before "follow me".
    let wait_then_listen = lines
        .windows(2)
        .any(|pair| pair[0].ends_with("wait 3 s") && pair[1].contains("listen to the visitor"));
    let sleep_then_follow = lines
        .windows(2)
        .any(|pair| pair[0].ends_with("wait 1.5 s") && pair[1].contains("Please follow me"));
    assert!(wait_then_listen && sleep_then_follow, "{}", walked.stdout);
}

#[test]
fn the_walk_stops_at_a_call_into_an_included_file() {
    let root = edited_set_up("labTour.xml", |text| {
        text.replace(
            "main_tree_to_execute=\"TourGuide\">",
            "main_tree_to_execute=\"TourGuide\">\n  <include path=\"farewell.xml\"/>",
        )
        .replace("<SubTree ID=\"EndTour\"/>", "<SubTree ID=\"Farewell\"/>")
    });
    std::fs::write(
        root.path().join("data/farewell.xml"),
        "<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"Farewell\"><SayText name=\"7\"/></BehaviorTree>\n</root>\n",
    )
    .unwrap();
    let checked = run(&[
        "mission",
        "check",
        "--config-dir",
        &config_of(&root),
        "--format",
        "concise",
    ]);
    assert!(
        !checked.stdout.contains("mission-unknown-tree")
            && !checked.stdout.contains("mission-bad-include"),
        "{}",
        checked.stdout
    );
    let walked = run(&["mission", "walk", "--config-dir", &config_of(&root)]);
    let end = walked.stdout.lines().last().unwrap_or_default();
    assert!(
        end.starts_with("end: the walk stops at `SubTree`")
            && end.contains("it calls `Farewell`, a tree of the included file")
            && end.contains("farewell.xml, which the walk does not follow"),
        "{}",
        walked.stdout
    );
}

#[test]
fn a_navigate_the_map_does_not_join_fails_and_the_walk_goes_on_through_its_fallback() {
    // The lab map of tests/fixtures/map with a square wall round the Roomba (location 4 at
    // 2.3, 5.1).
    let map = crate::lab_map::LabMap::with_obstacles(&crate::lab_map::square_round(2.3, 5.1, 1.0));
    let config = map.config();
    let args = [
        "mission",
        "walk",
        "--config-dir",
        CONFIG,
        "--lang",
        "en",
        "--map-config",
        config.to_str().unwrap(),
    ];
    let walked = run(&args);
    assert_eq!(walked.code, 0, "{}", walked.stderr);
    assert!(
        walked.stdout.contains(
            "12. cannot drive to location 4 \"Roomba\" at (2.3, 5.1), facing 270° (no path joins the two: walls close one off from the other): Navigate fails, and the robot stays where it stands\n13. say \"This is the Roomba\"\n"
        ),
        "{}",
        walked.stdout
    );
    // The next leg starts from location 1, where the robot still stands, and is driven.
    assert!(
        walked.stdout.contains("16. go to location 3"),
        "{}",
        walked.stdout
    );
    let json_args: Vec<&str> = args.iter().copied().chain(["--format", "json"]).collect();
    let walk = json(&run(&json_args));
    let unreachable: Vec<u64> = walk["steps"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["action"] == "go-to" && s["unreachable"].is_string())
        .map(|s| s["place"]["location"].as_u64().unwrap())
        .collect();
    assert_eq!(unreachable, [4]);
    assert_eq!(walk["outcome"]["status"], "completed");
    // On the lab as it is, every Navigate succeeds.
    let lab = [
        "mission",
        "walk",
        "--config-dir",
        CONFIG,
        "--lang",
        "en",
        "--map-config",
        "tests/fixtures/map/mapGenerationConfiguration.ini",
    ];
    assert!(!run(&lab).stdout.contains("cannot drive"));
}
