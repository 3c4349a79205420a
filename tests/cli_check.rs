//! `ekb check` end to end: exit codes, every output format, standard input, several files,
//! and how the configuration is found and read.

use std::fs;
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use ekb::robot::Reader;
use serde_json::{json, Value};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/check")
}

fn seed_text() -> String {
    fs::read_to_string(fixtures().join("seed.dat")).unwrap()
}

/// `ekb` run in `dir`, with no configuration or colour settings inherited from the caller.
fn ekb_in(dir: &Path) -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env_remove("NO_COLOR");
    command
}

/// `ekb` run in the fixtures folder, so that file names in the output are short.
fn ekb() -> Command {
    ekb_in(&fixtures())
}

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn run(command: &mut Command) -> Run {
    let output = command.output().unwrap();
    Run {
        code: output.status.code().expect("exited"),
        stdout: String::from_utf8(output.stdout).unwrap(),
        stderr: String::from_utf8(output.stderr).unwrap(),
    }
}

/// Asserts exit code 2 with exactly one `ekb: error:` line on standard error containing
/// `reason`, and nothing on standard output.
fn assert_failure(run: &Run, reason: &str) {
    assert_eq!(run.code, 2, "stderr: {}", run.stderr);
    assert_eq!(run.stdout, "");
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(run.stderr.starts_with("ekb: error: "), "{}", run.stderr);
    assert!(run.stderr.contains(reason), "{}", run.stderr);
}

fn placeholder(line: u32, language: &str, phase: &str, location: u32) -> String {
    let column = 33;
    format!(
        "seed.dat:{line}:{column}: warning[untranslated-message] the {language} message {phase} the gesture at location {location} is a placeholder: the robot would say \"No message in {language}\"\n"
    )
}

/// The whole concise report of the seed file.
fn seed_concise() -> String {
    let mut expected = String::from(
        "seed.dat:4:41: warning[repeated-word] \"the\" is repeated: the robot would say it twice\n",
    );
    for (location, first) in [(1, 5), (2, 14), (3, 23), (4, 32), (5, 41)] {
        if location == 4 {
            expected.push_str("seed.dat:28:1: error[missing-field] location 4 has no `postGestureMessageEnglish`: location 4 will say nothing after the gesture in English\n");
        }
        expected.push_str(&placeholder(first, "isiZulu", "before", location));
        expected.push_str(&placeholder(first + 1, "Kinyarwanda", "before", location));
        if location == 4 {
            expected.push_str("seed.dat:34:1: error[key-case] `postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case: the robot's reader ignores this line, so location 4 will say nothing after the gesture in English\n");
        }
        expected.push_str(&placeholder(first + 3, "isiZulu", "after", location));
        expected.push_str(&placeholder(first + 4, "Kinyarwanda", "after", location));
    }
    expected.push_str(
        "Found 2 errors, 21 warnings (1 fixable with ekb fix), checked against reader d5.4.2\n",
    );
    expected
}

// ---------------------------------------------------------------- exit codes and inputs

#[test]
fn clean_files_of_both_dialects_exit_0() {
    for (file, reader) in [
        ("clean-seed.dat", "d5.4.2"),
        ("clean-current.dat", "2025-06"),
    ] {
        let expected = format!("No problems found, checked against reader {reader}\n");
        let run = run(ekb().args(["check", "--format", "concise", file]));
        assert_eq!(run.code, 0, "{file}: {}", run.stdout);
        assert_eq!(run.stdout, expected);
        assert_eq!(run.stderr, "");
        let run = run_human(file);
        assert_eq!(run.code, 0);
        let words = Reader::from_name(reader).unwrap().in_words();
        assert_eq!(
            run.stdout,
            format!("No problems found; as the robot's software {words} reads it ({reader})\n")
        );
    }
}

fn run_human(file: &str) -> Run {
    run(ekb().args(["--color", "never", "check", file]))
}

#[test]
fn the_seed_exits_1_with_every_finding_in_concise_form() {
    let run = run(ekb().args(["check", "--format", "concise", "seed.dat"]));
    assert_eq!(run.code, 1);
    assert_eq!(run.stdout, seed_concise());
    assert_eq!(run.stderr, "");
}

#[test]
fn a_missing_file_exits_2_with_one_line() {
    let run = run(ekb().args(["check", "no-such.dat"]));
    assert_failure(&run, "cannot read no-such.dat: no such file");
}

#[test]
fn a_directory_exits_2_with_one_line() {
    let run = run(ekb().args(["check", "."]));
    assert_failure(&run, "is a directory");
}

#[test]
fn an_unknown_format_is_a_usage_error() {
    let run = run(ekb().args(["check", "--format", "xml", "seed.dat"]));
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("xml"), "{}", run.stderr);
}

#[test]
fn warnings_fail_only_with_deny_warnings() {
    let expected = "warning-only.dat:4:44: warning[repeated-word] \"the\" is repeated: the robot would say it twice\nFound 1 warning, checked against reader d5.4.2\n";
    let run_plain = run(ekb().args(["check", "--format", "concise", "warning-only.dat"]));
    assert_eq!(run_plain.code, 0);
    assert_eq!(run_plain.stdout, expected);
    let denied = run(ekb().args([
        "check",
        "--deny-warnings",
        "--format",
        "concise",
        "warning-only.dat",
    ]));
    assert_eq!(denied.code, 1);
    assert_eq!(denied.stdout, expected);
    let clean = run(ekb().args(["check", "--deny-warnings", "clean-current.dat"]));
    assert_eq!(clean.code, 0);
}

#[test]
fn several_files_are_reported_in_file_order_and_counted() {
    // Given out of order: the report is sorted by file name.
    let run = run(ekb().args([
        "check",
        "--format",
        "json",
        "warning-only.dat",
        "seed.dat",
        "clean-seed.dat",
    ]));
    assert_eq!(run.code, 1);
    let report: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(
        report["summary"],
        json!({ "files": 3, "errors": 2, "warnings": 22, "infos": 0 })
    );
    let files: Vec<&str> = report["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["file"].as_str().unwrap())
        .collect();
    assert_eq!(files.len(), 24);
    assert!(files[..23].iter().all(|&file| file == "seed.dat"));
    assert_eq!(files[23], "warning-only.dat");

    let concise = run_concise(&["clean-seed.dat", "warning-only.dat"]);
    assert_eq!(concise.code, 0);
    assert!(concise
        .stdout
        .ends_with("\nFound 1 warning, checked against reader d5.4.2\n"));
}

fn run_concise(files: &[&str]) -> Run {
    run(ekb().args(["check", "--format", "concise"]).args(files))
}

#[test]
fn one_unreadable_file_among_several_is_told_and_the_others_are_checked() {
    // Issue 12: the files before and after the missing one are reported; the exit is 2.
    let run = run(ekb().args([
        "check",
        "--format",
        "concise",
        "clean-seed.dat",
        "no-such.dat",
        "seed.dat",
    ]));
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert_eq!(
        run.stderr,
        "ekb: error: cannot read no-such.dat: no such file\n"
    );
    assert!(run.stdout.starts_with(&seed_concise()), "{}", run.stdout);
    // Only unreadable files: no report at all.
    let none = self::run(ekb().args(["check", "no-such.dat", "nor-this.dat"]));
    assert_eq!(none.code, 2);
    assert_eq!(none.stdout, "");
    assert_eq!(none.stderr.lines().count(), 2, "{}", none.stderr);
}

#[test]
fn a_dash_reads_standard_input() {
    let run = run(ekb()
        .args(["check", "--format", "concise", "-"])
        .write_stdin(seed_text()));
    assert_eq!(run.code, 1);
    assert_eq!(run.stdout, seed_concise().replace("seed.dat:", "<stdin>:"));
}

#[test]
fn standard_input_named_twice_is_refused() {
    // A second read of standard input finds it empty: a phantom file with no tour.
    for command in ["check", "fmt", "fix"] {
        let run = run(ekb()
            .args([command, "-", "clean-seed.dat", "-"])
            .write_stdin(seed_text()));
        assert_failure(&run, "standard input (`-`) is named 2 times");
    }
}

#[test]
fn quiet_leaves_out_the_summary() {
    let concise = run(ekb().args(["-q", "check", "--format", "concise", "seed.dat"]));
    assert_eq!(concise.code, 1);
    assert!(!concise.stdout.contains("Found"));
    assert_eq!(concise.stdout.lines().count(), 23);
    let human = run(ekb().args(["--quiet", "--color", "never", "check", "seed.dat"]));
    assert!(human.stdout.contains("error[key-case]"));
    assert!(!human.stdout.contains("Found"));
    let clean = run(ekb().args(["-q", "check", "clean-seed.dat"]));
    assert_eq!((clean.code, clean.stdout.as_str()), (0, ""));
}

// ---------------------------------------------------------------- formats

#[test]
fn json_has_the_exact_shape_of_the_spec() {
    let run = run(ekb().args(["check", "--format", "json", "seed.dat"]));
    assert_eq!(run.code, 1);
    let report: Value = serde_json::from_str(&run.stdout).unwrap();
    let object = report.as_object().unwrap();
    assert_eq!(
        object.keys().collect::<Vec<_>>(),
        ["diagnostics", "reader", "readers", "summary"]
    );
    assert_eq!(object["reader"], "d5.4.2");
    assert_eq!(object["readers"], json!({ "seed.dat": "d5.4.2" }));
    assert_eq!(
        report["summary"],
        json!({ "files": 1, "errors": 2, "warnings": 21, "infos": 0 })
    );
    let diagnostics = report["diagnostics"].as_array().unwrap();
    assert_eq!(diagnostics.len(), 23);
    for diagnostic in diagnostics {
        let mut keys: Vec<&str> = diagnostic
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        keys.sort_unstable();
        assert_eq!(
            keys,
            [
                "column",
                "end_column",
                "end_line",
                "file",
                "fix",
                "help",
                "line",
                "location_id",
                "message",
                "rule",
                "severity"
            ]
        );
    }
    let positions: Vec<(u64, u64)> = diagnostics
        .iter()
        .map(|d| (d["line"].as_u64().unwrap(), d["column"].as_u64().unwrap()))
        .collect();
    let mut sorted = positions.clone();
    sorted.sort_unstable();
    assert_eq!(positions, sorted);

    let key_case = diagnostics
        .iter()
        .find(|d| d["rule"] == "key-case")
        .unwrap();
    assert_eq!(
        *key_case,
        json!({
            "file": "seed.dat",
            "rule": "key-case",
            "severity": "error",
            "message": "`postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case: the robot's reader ignores this line, so location 4 will say nothing after the gesture in English",
            "line": 34, "column": 1, "end_line": 34, "end_column": 26,
            "location_id": 4,
            "help": "write the key as `postGestureMessageEnglish`",
            "fix": {
                "message": "rename to `postGestureMessageEnglish`",
                "edits": [{
                    "line": 34, "column": 1, "end_line": 34, "end_column": 26,
                    "replacement": "postGestureMessageEnglish"
                }],
                // ekb's addition to SPEC §5, as ruff's: `unsafe` only with --unsafe-fixes.
                "applicability": "safe"
            }
        })
    );
    let repeated = &diagnostics[0];
    assert_eq!(repeated["rule"], "repeated-word");
    assert_eq!(repeated["fix"], Value::Null);
}

#[test]
fn json_of_a_clean_file_is_empty_with_a_summary() {
    let run = run(ekb().args(["check", "--format", "json", "clean-current.dat"]));
    assert_eq!(run.code, 0);
    let report: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(
        report,
        json!({
            "diagnostics": [],
            "reader": "2025-06",
            "readers": { "clean-current.dat": "2025-06" },
            "summary": { "files": 1, "errors": 0, "warnings": 0, "infos": 0 }
        })
    );
}

#[test]
fn github_prints_one_workflow_command_per_finding() {
    let run = run(ekb().args(["check", "--format", "github", "seed.dat"]));
    assert_eq!(run.code, 1);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 23, "no summary line: {}", run.stdout);
    assert!(lines.contains(&"::error file=seed.dat,line=34,col=1,endLine=34,endColumn=26,title=ekb key-case::`postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case: the robot's reader ignores this line, so location 4 will say nothing after the gesture in English"));
    assert_eq!(
        lines[0],
        "::warning file=seed.dat,line=4,col=41,endLine=4,endColumn=48,title=ekb repeated-word::\"the\" is repeated: the robot would say it twice"
    );
    assert_eq!(
        lines.iter().filter(|l| l.starts_with("::error ")).count(),
        2
    );
}

#[test]
fn sarif_is_what_github_code_scanning_reads() {
    let run = run(ekb().args(["check", "--format", "sarif", "./seed.dat"]));
    assert_eq!(run.code, 1);
    let log: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(
        log["$schema"],
        "https://json.schemastore.org/sarif-2.1.0.json"
    );
    assert_eq!(log["version"], "2.1.0");
    let runs = log["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 1);
    let driver = &runs[0]["tool"]["driver"];
    assert_eq!(driver["name"], "ekb");
    assert_eq!(driver["version"], env!("CARGO_PKG_VERSION"));
    let rules = driver["rules"].as_array().unwrap();
    assert!(rules.len() >= 34);
    for rule in rules {
        for field in ["shortDescription", "fullDescription", "help"] {
            assert!(!rule[field]["text"].as_str().unwrap().is_empty(), "{rule}");
        }
        assert!(rule["help"]["markdown"]
            .as_str()
            .unwrap()
            .contains("## Why it matters"));
        let level = rule["defaultConfiguration"]["level"].as_str().unwrap();
        assert!(["error", "warning", "note"].contains(&level));
    }
    let unused = rules.iter().find(|r| r["id"] == "unused-location").unwrap();
    assert_eq!(unused["defaultConfiguration"]["level"], "note");

    let results = runs[0]["results"].as_array().unwrap();
    assert_eq!(results.len(), 23);
    let key_case = results.iter().find(|r| r["ruleId"] == "key-case").unwrap();
    let index = key_case["ruleIndex"].as_u64().unwrap() as usize;
    assert_eq!(rules[index]["id"], "key-case");
    assert_eq!(rules[index]["defaultConfiguration"]["level"], "error");
    assert_eq!(
        rules[index]["shortDescription"]["text"],
        "a known key in the wrong case"
    );
    assert_eq!(key_case["level"], "error");
    assert!(key_case["message"]["text"]
        .as_str()
        .unwrap()
        .starts_with("`postGestureMessageenglish` is `postGestureMessageEnglish`"));
    assert_eq!(
        key_case["locations"][0]["physicalLocation"],
        json!({
            "artifactLocation": { "uri": "seed.dat" },
            "region": { "startLine": 34, "startColumn": 1, "endLine": 34, "endColumn": 26 }
        })
    );
    let warning = results
        .iter()
        .find(|r| r["ruleId"] == "repeated-word")
        .unwrap();
    assert_eq!(warning["level"], "warning");
}

#[test]
fn sarif_names_standard_input_stdin_as_a_uri_reference() {
    let run = run(ekb()
        .args(["check", "--format", "sarif", "-"])
        .write_stdin(seed_text()));
    let log: Value = serde_json::from_str(&run.stdout).unwrap();
    let uri = &log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]
        ["uri"];
    // `<stdin>` percent-encoded: `<` and `>` may not stand in a URI reference.
    assert_eq!(uri, "%3Cstdin%3E");
}

#[test]
fn human_is_the_default_and_says_what_to_change() {
    let checked = run(ekb()
        .env("COLUMNS", "100")
        .args(["--color", "never", "check", "seed.dat"]));
    assert_eq!(checked.code, 1);
    let out = &checked.stdout;
    // The cause first: the key-case error, then what it causes, right under it.
    assert!(out.starts_with("error[key-case]\n"), "{out}");
    for expected in [
        "× `postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case",
        "╭─[seed.dat:34:1]",
        " 34 │ postGestureMessageenglish     4 We use it for teaching mobile robotics",
        "╰── rename to `postGestureMessageEnglish`",
        "help: write the key as `postGestureMessageEnglish`",
        "fix available: rename to `postGestureMessageEnglish` (run `ekb fix`)\n\n\
         error[missing-field]: location 4 has no `postGestureMessageEnglish`: location 4 will say \
         nothing\n  after the gesture in English\n  \
         at seed.dat:28:1, because of the key-case error above\n",
        // One typo, and the two findings agree on its one fix.
        "help: the line of `postGestureMessageEnglish` is there, its key in the wrong case:",
        "warning[repeated-word]",
        // A rule's many warnings: one paragraph, and the command that shows them all.
        "\nwarning[untranslated-message]: 20 findings, on lines 5, 6, 8, 9, 14, 15, 17, 18, 23, 24 \
         and 10 more\n",
        "\n  see all: ekb check --show-all --select untranslated-message seed.dat\n",
    ] {
        assert!(out.contains(expected), "missing {expected:?} in\n{out}");
    }
    assert!(out.rfind("error[") < out.find("warning["), "{out}");
    // In sight: with the command above it and the prompt below, all of it fits a terminal
    // of 100 × 40.
    assert!(
        out.lines().count() <= 38,
        "{} lines:\n{out}",
        out.lines().count()
    );
    // The summary leads with what matters, each severity broken down by rule, and wraps
    // between words.
    let summary = &out[out.rfind("\n\nFound").unwrap() + 2..];
    assert!(
        summary.lines().all(|line| line.chars().count() <= 100),
        "{summary}"
    );
    assert_eq!(
        summary.split_whitespace().collect::<Vec<_>>().join(" "),
        "Found 2 errors: key-case, missing-field · 21 warnings: 20 untranslated-message, \
         1 repeated-word (1 fixable with ekb fix: key-case); as the robot's software of \
         document D5.4.2 reads it (d5.4.2)"
    );
    assert_eq!(checked.stderr, "");

    // Every finding drawn when asked for.
    let all = run(ekb().args(["--color", "never", "check", "--show-all", "seed.dat"]));
    assert_eq!(
        all.stdout
            .matches("warning[untranslated-message]\n")
            .count(),
        20
    );
    assert!(!all.stdout.contains("see all"));
}

#[test]
fn human_shows_the_lines_around_the_finding() {
    let out = run_human("seed.dat").stdout;
    let report = out
        .split("\n\n")
        .skip_while(|part| !part.ends_with("error[key-case]"))
        .nth(1)
        .unwrap();
    let numbered: Vec<u32> = report
        .lines()
        .filter_map(|line| line.split_once(" │ ")?.0.trim().parse().ok())
        .collect();
    assert_eq!(numbered, [33, 34, 35], "{report}");
}

#[test]
fn colour_follows_the_color_option_and_no_color() {
    let esc = |run: &Run| run.stdout.contains('\x1b');
    assert!(!esc(&run(
        ekb().args(["--color", "never", "check", "seed.dat"])
    )));
    assert!(esc(&run(
        ekb().args(["--color", "always", "check", "seed.dat"])
    )));
    assert!(!esc(&run(ekb()
        .env("NO_COLOR", "1")
        .args(["check", "seed.dat"]))));
    assert!(
        !esc(&run(ekb().args(["check", "seed.dat"]))),
        "not a terminal"
    );
}

#[test]
fn control_characters_in_the_file_never_reach_the_terminal() {
    let evil = "robotLocationDescription      1 Ro\x1b]0;pwned\x07omba\u{202E}\nrobotlocation 1 \x1b[2J 1 2\n";
    for format in ["human", "concise", "github", "json", "sarif"] {
        let run = run(ekb()
            .args(["--color", "never", "check", "--format", format, "-"])
            .write_stdin(evil));
        assert_eq!(run.code, 1, "{format}");
        assert!(
            !run.stdout.contains(['\x1b', '\x07', '\u{202E}']),
            "{format}: {}",
            run.stdout
        );
    }
    let human = run(ekb()
        .args(["--color", "never", "check", "-"])
        .write_stdin(evil))
    .stdout;
    assert!(
        human.contains(
            " 1 │ robotLocationDescription      1 Ro\\u{001B}]0;pwned\\u{0007}omba\\u{202E RIGHT-TO-LEFT OVERRIDE}"
        ),
        "{human}"
    );
    assert!(human.contains("╭─[<stdin>:1:35]"), "{human}");
}

// ---------------------------------------------------------------- configuration

/// A robot folder: `config/environmentKnowledgeBaseConfiguration.ini` holding `config`, and
/// `data/kb.dat` holding the seed.
fn robot_folder(config: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("config")).unwrap();
    fs::create_dir(dir.path().join("data")).unwrap();
    fs::write(
        dir.path()
            .join("config/environmentKnowledgeBaseConfiguration.ini"),
        config,
    )
    .unwrap();
    fs::write(dir.path().join("data/kb.dat"), seed_text()).unwrap();
    dir
}

fn assert_checked_configured_seed(run: &Run, shown_as: &str) {
    assert_eq!(run.code, 1, "stderr: {}", run.stderr);
    assert!(
        run.stdout.contains(&format!(
            "{shown_as}:34:1: error[key-case] `postGestureMessageenglish`"
        )),
        "{}",
        run.stdout
    );
}

#[test]
fn with_no_file_the_configured_knowledge_base_is_checked() {
    // The robot's own whitespace form, as in its repository.
    let robot =
        robot_folder("knowledgeBase environmentKnowledgeBaseInput.dat\nverboseMode   false\n");
    fs::rename(
        robot.path().join("data/kb.dat"),
        robot.path().join("data/environmentKnowledgeBaseInput.dat"),
    )
    .unwrap();
    let run = run(ekb_in(robot.path()).args(["check", "--format", "concise"]));
    assert_checked_configured_seed(&run, "data/environmentKnowledgeBaseInput.dat");
    assert_eq!(run.stderr, "");
}

#[test]
fn standard_ini_form_works_too() {
    let robot =
        robot_folder("; ekb settings\n[robot]\nknowledgeBase = kb.dat\nverboseMode = false\n");
    let run = run(ekb_in(robot.path()).args(["check", "--format", "concise"]));
    assert_checked_configured_seed(&run, "data/kb.dat");
}

#[test]
fn comments_after_values_are_dropped_and_unknown_keys_warned_about() {
    let robot = robot_folder("knowledgeBase = kb.dat ; the lab's file\nverbosemode true\n");
    let run = run(ekb_in(robot.path()).args(["check", "--format", "concise"]));
    assert_checked_configured_seed(&run, "data/kb.dat");
    assert_eq!(
        run.stderr,
        "ekb: warning: configuration config/environmentKnowledgeBaseConfiguration.ini: \
         unknown key `verbosemode` (ignored); did you mean `verboseMode`?\n"
    );
}

#[test]
fn a_file_argument_wins_over_the_configured_one() {
    let robot = robot_folder("knowledgeBase kb.dat\n");
    fs::write(
        robot.path().join("clean.dat"),
        fs::read(fixtures().join("clean-seed.dat")).unwrap(),
    )
    .unwrap();
    let run = run(ekb_in(robot.path()).args(["check", "clean.dat"]));
    assert_eq!(run.code, 0, "{}", run.stdout);
}

#[test]
fn config_option_and_environment_variable_are_found_in_that_order() {
    let robot = robot_folder("knowledgeBase kb.dat\n");
    let other = robot_folder("knowledgeBase clean.dat\n");
    fs::write(
        other.path().join("data/clean.dat"),
        fs::read(fixtures().join("clean-current.dat")).unwrap(),
    )
    .unwrap();
    let robot_config = robot
        .path()
        .join("config/environmentKnowledgeBaseConfiguration.ini");
    let other_config = other
        .path()
        .join("config/environmentKnowledgeBaseConfiguration.ini");
    let elsewhere = tempfile::tempdir().unwrap();

    // --config: knowledgeBase is resolved in the data/ folder beside the config/ folder.
    let run_option = run(ekb_in(elsewhere.path())
        .arg("--config")
        .arg(&robot_config)
        .args(["check", "--format", "concise"]));
    let expected_path = robot.path().join("data/kb.dat");
    assert_checked_configured_seed(&run_option, &expected_path.display().to_string());

    // EKB_CONFIG when there is no --config.
    let run_env = run(ekb_in(elsewhere.path())
        .env("EKB_CONFIG", &other_config)
        .args(["check"]));
    assert_eq!(run_env.code, 0, "{}", run_env.stdout);

    // --config before EKB_CONFIG.
    let run_both = run(ekb_in(elsewhere.path())
        .env("EKB_CONFIG", &other_config)
        .arg("--config")
        .arg(&robot_config)
        .args(["check"]));
    assert_eq!(run_both.code, 1);

    // EKB_CONFIG before the default path under the current folder.
    let run_env_over_default = run(ekb_in(robot.path())
        .env("EKB_CONFIG", &other_config)
        .args(["check"]));
    assert_eq!(run_env_over_default.code, 0);
}

#[test]
fn a_missing_knowledge_base_exits_2_with_one_line() {
    let robot = robot_folder("knowledgeBase missing.dat\n");
    let run = run(ekb_in(robot.path()).arg("check"));
    assert_failure(&run, "data/missing.dat");
}

#[test]
fn an_unreadable_or_bad_configuration_exits_2_with_one_line() {
    let fixtures = fixtures();
    let missing = run(ekb().args(["--config", "no-such.ini", "check", "seed.dat"]));
    assert_failure(
        &missing,
        "cannot read configuration no-such.ini: no such file",
    );
    let missing_env = run(ekb()
        .env("EKB_CONFIG", "no-such.ini")
        .args(["check", "seed.dat"]));
    assert_failure(&missing_env, "no-such.ini");
    let directory = run(ekb()
        .arg("--config")
        .arg(&fixtures)
        .args(["check", "seed.dat"]));
    assert_failure(&directory, "cannot read configuration");
    let bad = robot_folder("knowledgeBase kb.dat\nverboseMode perhaps\n");
    let run_bad = run(ekb_in(bad.path()).arg("check"));
    assert_failure(&run_bad, "verboseMode must be true or false, not `perhaps`");
    let bad_dialect = robot_folder("knowledgeBase = kb.dat\ndialect = klingon\n");
    let run_bad_dialect = run(ekb_in(bad_dialect.path()).arg("check"));
    assert_failure(&run_bad_dialect, "dialect must be seed, current or auto");
}

#[test]
fn no_file_and_no_configuration_exits_2_with_one_line() {
    let empty = tempfile::tempdir().unwrap();
    let run = run(ekb_in(empty.path()).arg("check"));
    assert_failure(&run, "no FILE given and no configuration found");
}

#[test]
fn verbose_mode_prints_what_is_read_on_standard_error() {
    let quiet = robot_folder("knowledgeBase kb.dat\nverboseMode false\n");
    let verbose = robot_folder("knowledgeBase kb.dat\nverboseMode   true\n");
    let expected = [
        "ekb: reading data/kb.dat",
        "ekb: read robotLocation 1 2.6 8.1 -90",
        "ekb: read tourSpecification 5 1 4 3 2 5",
    ];
    let from_config = run(ekb_in(verbose.path()).args(["check", "--format", "concise"]));
    let from_option = run(ekb_in(quiet.path()).args(["-v", "check", "--format", "concise"]));
    for run in [&from_config, &from_option] {
        assert_eq!(run.code, 1);
        for line in expected {
            assert!(run.stderr.lines().any(|l| l == line), "{}", run.stderr);
        }
        assert!(run.stdout.contains("error[key-case]"));
    }
    let silent = run(ekb_in(quiet.path()).args(["check", "--format", "concise"]));
    assert_eq!(silent.stderr, "");
}

#[test]
fn the_dialect_key_pins_a_dialect() {
    let pinned = robot_folder("knowledgeBase = kb.dat\ndialect = current\n");
    let run_pinned = run(ekb_in(pinned.path()).args(["check", "--format", "concise"]));
    assert_eq!(run_pinned.code, 1);
    assert_eq!(run_pinned.stdout.matches("error[legacy-key]").count(), 5);
    assert!(run_pinned.stdout.contains(
        "data/kb.dat:2:1: error[legacy-key] reader 2025-06 reads poses from `robotLocationPose`, not `robotLocation`"
    ));
    for dialect in ["seed", "auto"] {
        let robot = robot_folder(&format!("knowledgeBase = kb.dat\ndialect = {dialect}\n"));
        let run = run(ekb_in(robot.path()).args(["check", "--format", "concise"]));
        assert!(!run.stdout.contains("legacy-key"), "{dialect}");
    }
}

// ---------------------------------------------------------------- the robot's reader

#[test]
fn the_reader_comes_from_the_option_the_environment_ekb_toml_or_the_configuration() {
    let robot = robot_folder("knowledgeBase = kb.dat\n");
    let legacy = |run: &Run| run.stdout.matches("error[legacy-key]").count();
    let check = || {
        let mut command = ekb_in(robot.path());
        command.args(["check", "--format", "concise"]);
        command
    };
    // By default, the document's reader for the document's dialect.
    let default = run(&mut check());
    assert_eq!(legacy(&default), 0, "{}", default.stdout);
    assert!(default.stdout.ends_with("checked against reader d5.4.2\n"));
    // ekb.toml beside the file, or in a folder above it.
    fs::write(robot.path().join("ekb.toml"), "reader = \"2025-06\"\n").unwrap();
    let settings = run(&mut check());
    assert_eq!(legacy(&settings), 5, "{}", settings.stdout);
    assert!(settings
        .stdout
        .ends_with("checked against reader 2025-06\n"));
    // EKB_READER overrides it, and --reader overrides both.
    let env = run(check().env("EKB_READER", "d5.4.2"));
    assert_eq!(legacy(&env), 0);
    let option = run(check()
        .env("EKB_READER", "d5.4.2")
        .args(["--reader", "2026-02"]));
    assert_eq!(legacy(&option), 5);
    assert!(option.stdout.ends_with("checked against reader 2026-02\n"));
    // The robot's configuration may name one too, below ekb.toml.
    fs::remove_file(robot.path().join("ekb.toml")).unwrap();
    fs::write(
        robot
            .path()
            .join("config/environmentKnowledgeBaseConfiguration.ini"),
        "knowledgeBase = kb.dat\nreader = 2026-04\n",
    )
    .unwrap();
    let config = run(&mut check());
    assert!(
        config.stdout.ends_with("checked against reader 2026-04\n"),
        "{}",
        config.stdout
    );
}

#[test]
fn a_bad_reader_is_a_usage_error() {
    let robot = robot_folder("knowledgeBase = kb.dat\n");
    fs::write(robot.path().join("ekb.toml"), "\nreader = \"2027-01\"\n").unwrap();
    let bad = run(ekb_in(robot.path()).arg("check"));
    assert_eq!(bad.code, 2);
    assert!(bad.stderr.contains("ekb.toml:2:10: `reader` must be one of d5.4.2, 2025-06, 2026-02, 2026-03, 2026-04, not `2027-01`"), "{}", bad.stderr);
    let option = run(ekb_in(robot.path()).args(["check", "--reader", "2027-01"]));
    assert_eq!(option.code, 2);
    assert!(
        option.stderr.contains("possible values: d5.4.2, 2025-06"),
        "{}",
        option.stderr
    );
}

#[test]
fn each_format_says_which_reader_it_checked_against() {
    let sarif = run(ekb().args([
        "check", "--format", "sarif", "--reader", "2026-03", "seed.dat",
    ]));
    let sarif: Value = serde_json::from_str(&sarif.stdout).unwrap();
    assert_eq!(
        sarif["runs"][0]["properties"]["readers"],
        json!({ "seed.dat": "2026-03" })
    );
    let two = run(ekb().args(["check", "--format", "json", "seed.dat", "clean-current.dat"]));
    let two: Value = serde_json::from_str(&two.stdout).unwrap();
    assert_eq!(two["reader"], Value::Null);
    assert_eq!(
        two["readers"],
        json!({ "clean-current.dat": "2025-06", "seed.dat": "d5.4.2" })
    );
    let human = run(ekb().args(["check", "seed.dat", "clean-current.dat"]));
    // Wrapped between words.
    let words = human
        .stdout
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        words.ends_with(
            "; as the robot's software reads it: 2025-06 for clean-current.dat, d5.4.2 for seed.dat"
        ),
        "{}",
        human.stdout
    );
}

#[test]
fn the_human_report_shows_errors_before_warnings_each_in_line_order() {
    // A warning (repeated word) on line 2, before the error (a key in the wrong case) on 3.
    let dir = tempfile::tempdir().unwrap();
    let kb = dir.path().join("kb.dat");
    fs::write(
        &kb,
        seed_text().replacen(" This is the Roomba", " This is the the Roomba", 1),
    )
    .unwrap();
    let out = run(ekb_in(dir.path()).args(["check", "--color", "never", "kb.dat"]));
    assert_eq!(out.code, 1, "{}", out.stderr);
    let headings: Vec<&str> = out
        .stdout
        .lines()
        .filter(|line| line.starts_with("error[") || line.starts_with("warning["))
        .collect();
    let first_warning = headings
        .iter()
        .position(|h| h.starts_with("warning["))
        .expect("warnings");
    assert!(first_warning > 0, "{headings:?}");
    assert!(
        headings[first_warning..]
            .iter()
            .all(|h| h.starts_with("warning[")),
        "{headings:?}"
    );
}

#[test]
fn a_unicode_minus_is_explained_by_its_consequence_in_check_show_and_tour() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("kb.dat"),
        seed_text().replace(" 2.0 6.3 -45", " 2.0 6.3 \u{2212}45"),
    )
    .unwrap();
    let said = |args: &[&str]| run(ekb_in(dir.path()).env_remove("COLUMNS").args(args)).stdout;
    let check = said(&["check", "--format", "concise", "kb.dat"]);
    assert!(
        check.contains(
            "is not a finite decimal number: the robot's reader loses the line's whole value, \
             so the robot will stand at (0, 0) facing 0° at location 3"
        ),
        "{check}"
    );
    let show = said(&["show", "3", "kb.dat"]);
    assert!(
        show.contains(
            "0.0, 0.0, 0.0° (the line's value is invalid, so the robot's reader holds this"
        ),
        "{show}"
    );
    let tour = said(&["tour", "kb.dat"]);
    assert!(
        tour.contains("stands at    0, 0, 0°: the pose line's numbers are invalid"),
        "{tour}"
    );
}
