//! The mission's and the culture knowledge base's rules (SPEC §11), proven rule by rule.
//!
//! The set-up is the robot's, copied from the corpus into `tests/fixtures/mission/corpus/`
//! (`config/` with the three configuration files, `data/` with the mission, the culture
//! knowledge base, its types file and the 2025-06 environment knowledge base). Each rule
//! has a folder `tests/fixtures/mission/rules/<rule>/` whose `bad/` and `good/` hold the
//! files that replace the corpus's: `bad/` must raise the rule at exactly the places
//! listed, `good/` (its near miss) must not raise it.

use std::path::{Path, PathBuf};

use ekb::check::Checked;
use ekb::mission::check::{check_together, MissionSources};
use ekb::model::build::Options;
use ekb::model::Language;
use ekb::robot::speech::RobotProfile;
use ekb::rules::selection::RuleSet;
use ekb::rules::{self, Category};
use ekb::source::LineIndex;
use ekb::{Severity, SourceFile};

const MISSION: &str = "labTour.xml";
const CULTURE: &str = "cultureKnowledgeBaseInput.dat";
const TYPES: &str = "cultureKnowledgeValueTypesInput.dat";
const KB: &str = "environmentKnowledgeBaseInput.dat";

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/mission")
}

/// The four files: the corpus's, each replaced by the one in `dir` if it has it. Read from
/// their paths, so that a mission's `<include>`s are found beside it.
fn set_up(dir: Option<&Path>) -> [SourceFile; 4] {
    [MISSION, CULTURE, TYPES, KB].map(|name| {
        let path = dir
            .map(|dir| dir.join(name))
            .filter(|path| path.is_file())
            .unwrap_or_else(|| fixtures().join("corpus/data").join(name));
        SourceFile::read(&path).unwrap_or_else(|e| panic!("{e}"))
    })
}

/// One finding, located: `(file, line, column)`, and the rest.
#[derive(Debug, Clone)]
struct Finding {
    file: String,
    line: u32,
    column: u32,
    rule: &'static str,
    severity: Severity,
    message: String,
    has_help: bool,
}

fn locate(checked: &[Checked<'_>]) -> Vec<Finding> {
    let mut all = Vec::new();
    for file in checked {
        let text = file.source.text();
        let index = LineIndex::new(text);
        for d in &file.diagnostics {
            let at = index.position(text, d.span.start);
            let name = Path::new(file.source.name()).file_name();
            all.push(Finding {
                file: name.map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
                line: at.line,
                column: at.column,
                rule: d.rule.name,
                severity: d.severity(),
                message: d.message.clone(),
                has_help: d.help.is_some(),
            });
        }
    }
    all
}

fn check_set(files: &[SourceFile; 4]) -> Vec<Finding> {
    let options = Options::default();
    let sources = MissionSources {
        mission: Some(&files[0]),
        culture_kb: Some(&files[1]),
        culture_types: Some(&files[2]),
        kb: Some((&files[3], &options)),
        reader: None,
        robot: None,
    };
    locate(&check_together(&sources, &RuleSet::default()))
}

fn show(all: &[Finding]) -> String {
    all.iter()
        .map(|f| {
            format!(
                "  {}:{}:{} {} {}\n",
                f.file, f.line, f.column, f.rule, f.message
            )
        })
        .collect()
}

/// The rule's `bad/` raises it at exactly `expected`, each finding saying what the robot
/// would do and what to do; its `good/` does not raise it.
fn assert_rule(name: &str, expected: &[(&str, u32, u32)]) {
    let rule = rules::by_name(name).unwrap_or_else(|| panic!("no rule `{name}`"));
    let dir = fixtures().join("rules").join(name);
    let bad = check_set(&set_up(Some(&dir.join("bad"))));
    let of_rule: Vec<&Finding> = bad.iter().filter(|f| f.rule == name).collect();
    let found: Vec<(&str, u32, u32)> = of_rule
        .iter()
        .map(|f| (f.file.as_str(), f.line, f.column))
        .collect();
    assert_eq!(
        found,
        expected,
        "`{name}` in bad/; all findings:\n{}",
        show(&bad)
    );
    for finding in of_rule {
        assert_eq!(finding.severity, rule.severity, "{finding:?}");
        assert!(finding.message.contains("robot"), "{}", finding.message);
        assert!(finding.has_help, "{finding:?}");
    }
    let good = check_set(&set_up(Some(&dir.join("good"))));
    let raised: Vec<Finding> = good.into_iter().filter(|f| f.rule == name).collect();
    assert!(raised.is_empty(), "`{name}` in good/:\n{}", show(&raised));
}

macro_rules! rule_tests {
    ($($test:ident: $rule:literal => [$(($file:expr, $line:expr, $column:expr)),* $(,)?];)*) => {
        $(
            #[test]
            fn $test() {
                assert_rule($rule, &[$(($file, $line, $column)),*]);
            }
        )*
        /// Every rule with a test above.
        const TESTED: &[&str] = &[$($rule),*];
    };
}

rule_tests! {
    mission_invalid_xml: "mission-invalid-xml" => [(MISSION, 6, 3)];
    mission_unknown_node: "mission-unknown-node" => [
        (MISSION, 5, 8), (MISSION, 6, 8), (MISSION, 7, 19), (MISSION, 8, 8)
    ];
    mission_bad_children: "mission-bad-children" => [
        (MISSION, 5, 8), (MISSION, 9, 8), (MISSION, 10, 8), (MISSION, 13, 8), (MISSION, 18, 4)
    ];
    mission_unknown_attribute: "mission-unknown-attribute" => [
        (MISSION, 5, 16), (MISSION, 6, 14), (MISSION, 9, 46)
    ];
    mission_bad_port_value: "mission-bad-port-value" => [
        (MISSION, 5, 43), (MISSION, 8, 26), (MISSION, 11, 27), (MISSION, 12, 27), (MISSION, 13, 22)
    ];
    mission_bad_include: "mission-bad-include" => [
        (MISSION, 4, 4), (MISSION, 5, 18), (MISSION, 6, 40), (MISSION, 7, 18), (MISSION, 8, 18),
        (MISSION, 9, 18)
    ];
    mission_unknown_tree: "mission-unknown-tree" => [(MISSION, 2, 46), (MISSION, 5, 20), (MISSION, 6, 8)];
    mission_missing_format: "mission-missing-format" => [(MISSION, 2, 2)];
    mission_unreachable_tree: "mission-unreachable-tree" => [(MISSION, 6, 21)];
    mission_invalid_name: "mission-invalid-name" => [
        (MISSION, 5, 35), (MISSION, 6, 8), (MISSION, 7, 36), (MISSION, 8, 36), (MISSION, 9, 22)
    ];
    mission_language_invalid: "mission-language-invalid" => [(CULTURE, 10, 43)];
    mission_language_not_spoken: "mission-language-not-spoken" => [(CULTURE, 10, 43)];
    mission_missing_phrase: "mission-missing-phrase" => [(MISSION, 5, 22), (MISSION, 7, 22)];
    mission_untranslated_tour: "mission-untranslated-tour" => [(KB, 6, 33), (KB, 11, 1)];
    cultural_knowledge_unknown_key: "cultural-knowledge-unknown-key" => [(KB, 11, 33), (KB, 11, 46)];
    culture_unknown_key: "culture-unknown-key" => [(CULTURE, 2, 1), (CULTURE, 3, 1)];
    culture_type_mismatch: "culture-type-mismatch" => [
        (CULTURE, 2, 15), (CULTURE, 3, 37), (CULTURE, 4, 23), (CULTURE, 5, 1)
    ];
    culture_unknown_type: "culture-unknown-type" => [(TYPES, 2, 23), (TYPES, 3, 1)];
    culture_duplicate_key: "culture-duplicate-key" => [(CULTURE, 3, 1), (TYPES, 3, 1)];
    culture_line_too_long: "culture-line-too-long" => [(CULTURE, 2, 199)];
    culture_no_final_newline: "culture-no-final-newline" => [(CULTURE, 2, 34)];
    culture_crlf: "culture-crlf" => [(CULTURE, 1, 23)];
    culture_word_too_long: "culture-word-too-long" => [(CULTURE, 2, 23), (CULTURE, 3, 1)];
}

#[test]
fn a_culture_line_cut_inside_a_character_is_reported_at_that_character() {
    // `k `, then two-byte characters: the robot cuts at byte 199, inside the 99th.
    let culture = SourceFile::from_bytes(
        "culture.dat",
        format!("k {}\n", "é".repeat(150)).into_bytes(),
    );
    let sources = MissionSources {
        mission: None,
        culture_kb: Some(&culture),
        culture_types: None,
        kb: None,
        reader: None,
        robot: None,
    };
    let found = locate(&check_together(&sources, &RuleSet::default()));
    let cut: Vec<(u32, u32, &str)> = found
        .iter()
        .filter(|f| f.rule == "culture-line-too-long")
        .map(|f| (f.line, f.column, f.message.as_str()))
        .collect();
    assert_eq!(cut.len(), 1, "{}", show(&found));
    assert_eq!((cut[0].0, cut[0].1), (1, 101), "the character cut in two");
    assert!(
        cut[0].2.contains("reads the rest (104 bytes)"),
        "{}",
        cut[0].2
    );
}

#[test]
fn every_mission_and_culture_rule_has_fixtures_and_a_test() {
    for rule in rules::ALL
        .iter()
        .filter(|r| matches!(r.category, Category::Mission | Category::Culture))
    {
        let dir = fixtures().join("rules").join(rule.name);
        for variant in ["bad", "good"] {
            assert!(
                dir.join(variant).is_dir(),
                "rule `{}` has no {}",
                rule.name,
                dir.join(variant).display()
            );
        }
        assert!(
            TESTED.contains(&rule.name),
            "rule `{}` has no test",
            rule.name
        );
    }
}

// ---------------------------------------------------------------------------------------
// The corpus, as the issue says it must come out

fn errors(all: &[Finding]) -> Vec<&Finding> {
    all.iter()
        .filter(|f| f.severity == Severity::Error)
        .collect()
}

/// The corpus's files, with the culture knowledge base's `phraseLanguage` set to `word`.
fn corpus_in(word: &str) -> [SourceFile; 4] {
    let [mission, culture, types, kb] = set_up(None);
    let text = culture.text().replace(
        "phraseLanguage                            English",
        &format!("phraseLanguage {word}"),
    );
    [
        mission,
        SourceFile::from_bytes(CULTURE, text.into_bytes()),
        types,
        kb,
    ]
}

#[test]
fn the_corpus_has_no_error_and_warns_of_the_culture_words_in_the_wrong_case() {
    let all = check_set(&set_up(None));
    assert!(errors(&all).is_empty(), "{}", show(&all));
    let words: Vec<(u32, &str)> = all
        .iter()
        .filter(|f| f.rule == "cultural-knowledge-unknown-key")
        .map(|f| (f.line, f.message.split('`').nth(1).unwrap_or("")))
        .collect();
    assert_eq!(
        words,
        [
            (10, "SymbolicShapeRespect"),
            (10, "BowExtentRespect"),
            (21, "DeicticShape"),
            (32, "DeicticShape"),
            (43, "DeicticShape"),
            (54, "IconicShape"),
        ]
    );
    assert!(all
        .iter()
        .filter(|f| f.rule == "cultural-knowledge-unknown-key")
        .all(|f| f.message.contains("differs only in case")));
    // The upstream file's last phrase loses a letter, but the English mission never says it.
    let lost: Vec<&Finding> = all
        .iter()
        .filter(|f| f.rule == "culture-no-final-newline")
        .collect();
    assert_eq!(lost.len(), 1);
    assert_eq!(lost[0].severity, Severity::Warning);
    assert!(
        lost[0].message.contains("\"Murabeh\""),
        "{}",
        lost[0].message
    );
}

#[test]
fn in_isizulu_every_saytext_misses_its_phrase_and_every_stop_is_untranslated() {
    let all = check_set(&corpus_in("IsiZulu"));
    let rules_of_errors: std::collections::BTreeSet<&str> =
        errors(&all).iter().map(|f| f.rule).collect();
    assert_eq!(
        rules_of_errors.into_iter().collect::<Vec<_>>(),
        [
            "mission-language-not-spoken",
            "mission-missing-phrase",
            "mission-untranslated-tour"
        ]
    );
    let phrases: Vec<u32> = all
        .iter()
        .filter(|f| f.rule == "mission-missing-phrase")
        .map(|f| f.line)
        .collect();
    // Every SayText of labTour.xml, in file order.
    assert_eq!(phrases, [33, 55, 100, 105, 121, 142, 169]);
    assert!(all
        .iter()
        .filter(|f| f.rule == "mission-missing-phrase")
        .all(|f| f.message.contains("UNDEFINED")));
    let stops: Vec<u32> = all
        .iter()
        .filter(|f| f.rule == "mission-untranslated-tour")
        .map(|f| f.line)
        .collect();
    // Each of the five stops, before and after the gesture.
    assert_eq!(stops, [5, 8, 16, 19, 27, 30, 38, 41, 49, 52]);
}

#[test]
fn a_mission_in_a_language_the_robot_does_not_speak_is_silent_unless_the_profile_speaks_it() {
    let files = corpus_in("IsiZulu");
    let not_spoken = |all: &[Finding]| -> Vec<(String, u32, u32, String)> {
        all.iter()
            .filter(|f| f.rule == "mission-language-not-spoken")
            .map(|f| (f.file.clone(), f.line, f.column, f.message.clone()))
            .collect()
    };
    let found = not_spoken(&check_set(&files));
    assert_eq!(
        found,
        [(
            CULTURE.to_string(),
            10,
            16,
            "the mission speaks isiZulu, which the robot's text-to-speech does not speak: every \
             phrase and every talk of the tour is silent"
                .to_string()
        )]
    );
    let options = Options::default();
    let speaks_zulu = RobotProfile {
        speaks: vec![Language::English, Language::IsiZulu, Language::Kinyarwanda],
        ..RobotProfile::default()
    };
    let check_with = |robot: &RobotProfile| {
        let sources = MissionSources {
            mission: Some(&files[0]),
            culture_kb: Some(&files[1]),
            culture_types: Some(&files[2]),
            kb: Some((&files[3], &options)),
            reader: None,
            robot: Some(robot),
        };
        locate(&check_together(&sources, &RuleSet::default()))
    };
    assert!(not_spoken(&check_with(&speaks_zulu)).is_empty());
    // A robot that speaks no Kinyarwanda: a Kinyarwanda mission is silent.
    let english_only = RobotProfile {
        speaks: vec![Language::English],
        ..RobotProfile::default()
    };
    let files = corpus_in("Kinyarwanda");
    let sources = MissionSources {
        mission: Some(&files[0]),
        culture_kb: Some(&files[1]),
        culture_types: Some(&files[2]),
        kb: Some((&files[3], &options)),
        reader: None,
        robot: Some(&english_only),
    };
    let all = locate(&check_together(&sources, &RuleSet::default()));
    let finding = all
        .iter()
        .find(|f| f.rule == "mission-language-not-spoken")
        .expect("a Kinyarwanda mission on a robot that speaks English only");
    assert!(
        finding.message.contains("speaks Kinyarwanda"),
        "{finding:?}"
    );
}

#[test]
fn a_language_in_the_wrong_case_is_invalid() {
    let all = check_set(&corpus_in("isiZulu"));
    let errors: Vec<&str> = errors(&all).iter().map(|f| f.rule).collect();
    assert_eq!(errors, ["mission-language-invalid"]);
    let finding = all
        .iter()
        .find(|f| f.rule == "mission-language-invalid")
        .unwrap();
    assert_eq!((finding.file.as_str(), finding.line), (CULTURE, 10));
}

#[test]
fn a_lost_last_letter_is_an_error_when_the_mission_says_the_phrase() {
    let all = check_set(&corpus_in("Kinyarwanda"));
    let lost: Vec<&Finding> = all
        .iter()
        .filter(|f| f.rule == "culture-no-final-newline")
        .collect();
    assert_eq!(lost.len(), 1);
    assert_eq!(lost[0].severity, Severity::Error);
    assert!(lost[0].message.contains("which the mission says"));
}

// ---------------------------------------------------------------------------------------
// Each kind of tree that BehaviorTree.CPP refuses

/// The findings of a mission file checked alone.
fn check_mission_alone(text: String) -> Vec<Finding> {
    let source = SourceFile::from_bytes("t.xml", text.into_bytes());
    let checked = check_together(
        &MissionSources {
            mission: Some(&source),
            ..MissionSources::default()
        },
        &RuleSet::default(),
    );
    locate(&checked)
}

#[test]
fn each_kind_of_tree_that_behaviortree_cpp_refuses_is_an_error() {
    let cases: &[(&str, &str)] = &[
        ("<root BTCPP_format=\"4\"><BehaviorTree ID=\"A\"><Sequence></BehaviorTree></root>", "mission-invalid-xml"),
        ("<tree BTCPP_format=\"4\"/>", "mission-invalid-xml"),
        ("<BehaviorTree ID=\"A\"><Teleport/></BehaviorTree>", "mission-unknown-node"),
        ("<BehaviorTree ID=\"A\"><Action/></BehaviorTree>", "mission-unknown-node"),
        ("<BehaviorTree ID=\"A\"><Inverter/></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><Inverter><Navigate/><Navigate/></Inverter></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><Sequence/></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><Navigate><Navigate/></Navigate></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><IsVisitorPresent><Navigate/></IsVisitorPresent></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><SubTree ID=\"B\"><Navigate/></SubTree></BehaviorTree><BehaviorTree ID=\"B\"><Navigate/></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><Navigate/><Navigate/></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"></BehaviorTree>", "mission-bad-children"),
        ("<BehaviorTree ID=\"A\"><SubTree/></BehaviorTree>", "mission-unknown-tree"),
        ("<BehaviorTree ID=\"A\"><SubTree ID=\"B\"/></BehaviorTree>", "mission-unknown-tree"),
        ("<BehaviorTree ID=\"A\"><Navigate goal=\"4\"/></BehaviorTree>", "mission-unknown-attribute"),
        ("<BehaviorTree ID=\"A\"><Delay msec=\"4\"><Navigate/></Delay></BehaviorTree>", "mission-unknown-attribute"),
        ("<BehaviorTree ID=\"A\"><RetryUntilSuccessful num_attempts=\"three\"><Navigate/></RetryUntilSuccessful></BehaviorTree>", "mission-bad-port-value"),
    ];
    for (xml, rule) in cases {
        let text = if xml.starts_with("<BehaviorTree") {
            format!("<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">{xml}</root>")
        } else {
            xml.to_string()
        };
        let all = check_mission_alone(text);
        let found: Vec<&str> = errors(&all).iter().map(|f| f.rule).collect();
        assert_eq!(found, [*rule], "{xml}:\n{}", show(&all));
    }
}

/// BehaviorTree.CPP 4.6's loader (`xml_parsing.cpp`, `VerifyXML` and `createNodeFromXML`):
/// what it refuses beyond the cases above, and its near misses, which it loads. Each
/// error is `(rule, line)`.
#[test]
fn behaviortree_cpp_4_refuses_tree_ids_of_nodes_nameless_trees_and_two_models() {
    let cases: &[(&str, &[(&str, u32)])] = &[
        // A tree may not take a node's name, as a <BehaviorTree> or a <SubTree> call.
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"Navigate\">\n\
             <BehaviorTree ID=\"Navigate\"><AlwaysSuccess/></BehaviorTree></root>",
            &[("mission-unknown-tree", 2)],
        ),
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n\
             <BehaviorTree ID=\"A\"><SubTree ID=\"Sequence\"/></BehaviorTree>\n\
             <BehaviorTree ID=\"Sequence\"><AlwaysSuccess/></BehaviorTree></root>",
            &[("mission-unknown-tree", 2), ("mission-unknown-tree", 3)],
        ),
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"Go\">\n\
             <BehaviorTree ID=\"Go\"><Navigate/></BehaviorTree></root>",
            &[],
        ),
        // A tree without an ID beside any other element of <root>.
        (
            "<root BTCPP_format=\"4\">\n<TreeNodesModel/>\n\
             <BehaviorTree><AlwaysSuccess/></BehaviorTree></root>",
            &[("mission-unknown-tree", 3)],
        ),
        (
            "<root BTCPP_format=\"4\">\n<BehaviorTree><AlwaysSuccess/></BehaviorTree></root>",
            &[],
        ),
        // One <TreeNodesModel> at most.
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<TreeNodesModel/>\n\
             <TreeNodesModel/>\n<BehaviorTree ID=\"A\"><AlwaysSuccess/></BehaviorTree></root>",
            &[("mission-bad-children", 3)],
        ),
        // tinyxml2 keeps a `&` that starts no entity as it is.
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\">\n\
             <Navigate _description=\"Fish & Chips &nbsp;\"/></BehaviorTree></root>",
            &[],
        ),
        // Only a name that starts with a letter is checked against the ports.
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\">\n\
             <Navigate _description=\"go\" _skipIf=\"false\" \u{e9}tape=\"1\"/></BehaviorTree></root>",
            &[],
        ),
        (
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\">\n\
             <Navigate etape=\"1\"/></BehaviorTree></root>",
            &[("mission-unknown-attribute", 3)],
        ),
    ];
    for (xml, expected) in cases {
        let all = check_mission_alone(xml.to_string());
        let found: Vec<(&str, u32)> = errors(&all).iter().map(|f| (f.rule, f.line)).collect();
        assert_eq!(found, *expected, "{xml}:\n{}", show(&all));
    }
}

/// behaviorController v1.1 (April 2026) registers `…Async` forms of six nodes: a warning
/// (the robots before refuse them), and each does its synchronous node's work.
#[test]
fn the_async_nodes_of_behavior_controller_v1_1_are_a_warning_and_say_their_phrases() {
    let xml = "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\">\n\
               <Sequence>\n<SayTextAsync name=\"4\"/>\n<SayTextAsync name=\"9\"/>\n\
               <NavigateAsync/>\n<PerformIconicGestureAsync name=\"wave\"/>\n</Sequence>\n\
               </BehaviorTree></root>";
    let [_, culture, types, kb] = set_up(None);
    let files = [
        SourceFile::from_bytes(MISSION, xml.as_bytes().to_vec()),
        culture,
        types,
        kb,
    ];
    let all = check_set(&files);
    let mission: Vec<(&str, u32, Severity)> = all
        .iter()
        .filter(|f| f.file == MISSION)
        .map(|f| (f.rule, f.line, f.severity))
        .collect();
    assert_eq!(
        mission,
        [
            ("mission-unknown-node", 4, Severity::Warning),
            ("mission-unknown-node", 5, Severity::Warning),
            ("mission-missing-phrase", 5, Severity::Error),
            ("mission-unknown-node", 6, Severity::Warning),
            ("mission-unknown-node", 7, Severity::Warning),
            ("mission-invalid-name", 7, Severity::Error),
        ],
        "{}",
        show(&all)
    );
}

#[test]
fn the_async_nodes_are_known_to_2026_04_and_an_error_for_an_earlier_reader() {
    use ekb::robot::Reader;
    let xml = "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\">\n\
               <NavigateAsync/>\n</BehaviorTree></root>";
    let source = SourceFile::from_bytes(MISSION, xml.as_bytes().to_vec());
    let unknown = |reader: Option<Reader>| {
        let sources = MissionSources {
            mission: Some(&source),
            reader,
            ..MissionSources::default()
        };
        locate(&check_together(&sources, &RuleSet::default()))
            .into_iter()
            .filter(|f| f.rule == "mission-unknown-node")
            .map(|f| (f.line, f.severity))
            .collect::<Vec<_>>()
    };
    assert_eq!(unknown(None), [(3, Severity::Warning)]);
    assert_eq!(unknown(Some(Reader::V2026_04)), []);
    assert_eq!(unknown(Some(Reader::V2025_06)), [(3, Severity::Error)]);
    assert_eq!(unknown(Some(Reader::V2026_03)), [(3, Severity::Error)]);
}

// ---------------------------------------------------------------------------------------
// Any input: a finding, never a panic or a hang

mod any_input {
    use super::*;
    use ekb::mission::culture::PhraseBook;
    use ekb::mission::{outline, walk};
    use proptest::prelude::*;

    /// Pieces of missions and culture files, mixed with noise.
    fn piece() -> impl Strategy<Value = String> {
        prop_oneof![
            Just("<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">".to_string()),
            Just("<BehaviorTree ID=\"A\">".to_string()),
            Just("</BehaviorTree>".to_string()),
            Just("<Sequence>".to_string()),
            Just("</Sequence>".to_string()),
            Just("<KeepRunningUntilFailure>".to_string()),
            Just("<SubTree ID=\"A\"/>".to_string()),
            Just("<SayText name=\"4\"/>".to_string()),
            Just("<SelectExhibit/>".to_string()),
            Just("</root>".to_string()),
            Just("phraseLanguage English\n".to_string()),
            Just("utilityPhraseEnglish4 PHRASE\n".to_string()),
            Just("utilityPhraseEnglish4 \"Hello\"\r\n".to_string()),
            "[ -~\\t\\r\\n\u{e9}\u{feff}]{0,30}",
        ]
    }

    fn file() -> impl Strategy<Value = String> {
        prop::collection::vec(piece(), 0..12).prop_map(|pieces| pieces.concat())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]
        #[test]
        fn checking_showing_and_walking_never_panic(
            mission in file(), culture in file(), types in file()
        ) {
            let files = [
                SourceFile::from_bytes(MISSION, mission.into_bytes()),
                SourceFile::from_bytes(CULTURE, culture.into_bytes()),
                SourceFile::from_bytes(TYPES, types.into_bytes()),
                set_up(None)[3].clone(),
            ];
            check_set(&files);
            for source in &files[..3] {
                ekb::mission::check::check_file(source, &Options::default(), &RuleSet::default(), None);
            }
            let Ok(mission) = ekb::mission::check::read_mission(&files[0]) else {
                return Ok(());
            };
            let kb = ekb::check(&files[3], &Options::default());
            let culture = ekb::mission::culture::CultureKnowledgeBase::parse(files[1].text(), ekb::mission::culture::LINE_BUFFER);
            let types = ekb::mission::culture::ValueTypes::parse(files[2].text(), ekb::mission::culture::LINE_BUFFER);
            let phrases = PhraseBook {
                culture: Some((&culture, &types)),
                language: Some(ekb::model::Language::English),
            };
            outline::outline(&mission, files[0].text(), &phrases);
            let robot = ekb::robot::speech::RobotProfile::default();
            let world = walk::World { kb: &kb.kb, phrases, asr_enabled: true, robot: &robot, map: None };
            let walked = walk::walk(&mission, files[0].text(), &world);
            prop_assert!(walked.ticks <= walk::MAX_TICKS + 1);
        }
    }
}

#[test]
fn the_culture_reader_of_2026_02_holds_lines_of_up_to_299_bytes() {
    // 250 bytes: cut by `2025-06`'s reader (200), whole in `2026-02`'s copy (300).
    let culture = SourceFile::from_bytes(
        "culture.dat",
        format!(
            "phraseLanguage English\nutilityPhraseEnglish1 {}\nutilityPhraseEnglish2 Hi\n",
            "a".repeat(227)
        )
        .into_bytes(),
    );
    let too_long = |reader: Option<ekb::robot::Reader>| {
        let options = Options {
            reader,
            ..Options::default()
        };
        let checked =
            ekb::mission::check::check_file(&culture, &options, &RuleSet::default(), None);
        locate(&[checked])
            .into_iter()
            .filter(|f| f.rule == "culture-line-too-long")
            .map(|f| (f.line, f.column))
            .collect::<Vec<_>>()
    };
    assert_eq!(too_long(None), [(2, 200)]);
    assert_eq!(too_long(Some(ekb::robot::Reader::V2025_06)), [(2, 200)]);
    assert_eq!(too_long(Some(ekb::robot::Reader::V2026_02)), []);
}

#[test]
fn an_untranslated_stop_is_named_by_its_location_and_its_place_on_the_tour() {
    // The tour is `2 2 1` (two stops): location 1 is its second stop.
    let bad = fixtures().join("rules/mission-untranslated-tour/bad");
    let all = check_set(&set_up(Some(&bad)));
    let first = all
        .iter()
        .find(|f| f.rule == "mission-untranslated-tour")
        .expect("a finding");
    assert_eq!((first.file.as_str(), first.line), (KB, 6));
    assert!(
        first
            .message
            .contains("the message of location 1 (stop 2 of the tour) before the gesture"),
        "{}",
        first.message
    );
}

#[test]
fn an_empty_include_path_is_said_to_be_empty() {
    let bad = fixtures().join("rules/mission-bad-include/bad");
    let all = check_set(&set_up(Some(&bad)));
    let empty: Vec<&Finding> = all.iter().filter(|f| f.line == 9).collect();
    assert_eq!(empty.len(), 1, "{}", show(&all));
    assert!(
        empty[0]
            .message
            .starts_with("an <include> whose path is empty: BehaviorTree.CPP stops loading"),
        "{}",
        empty[0].message
    );
}

#[test]
fn trees_of_included_files_may_be_called_and_the_walk_says_it_does_not_follow_them() {
    let good = fixtures().join("rules/mission-bad-include/good");
    let files = set_up(Some(&good));
    let all = check_set(&files);
    let mission_errors: Vec<&Finding> = errors(&all)
        .into_iter()
        .filter(|f| f.file == MISSION)
        .collect();
    assert!(mission_errors.is_empty(), "{}", show(&all));
    // The same calls without the includes: both trees unknown.
    let text = files[0]
        .text()
        .replace("<include", "<!-- include")
        .replace("xml\"/>", "xml\"/ -->");
    let alone = check_mission_alone(text);
    let unknown: Vec<u32> = alone
        .iter()
        .filter(|f| f.rule == "mission-unknown-tree")
        .map(|f| f.line)
        .collect();
    assert_eq!(unknown, [7, 8], "{}", show(&alone));

    let mission = ekb::mission::check::read_mission(&files[0]).unwrap();
    assert!(mission
        .included_tree("Farewell")
        .is_some_and(|file| file.ends_with("trees/farewell.xml")));
}
