//! `ekb.toml`, rule selection on the command line, `--level`, `--statistics`, `--exit-zero`,
//! `--output-file`, suppression comments, `--add-ignore` and `ekb settings`, end to end on
//! the seed file (2 errors, 21 warnings: 20 `untranslated-message`, 1 `repeated-word`).

use std::fs;
use std::path::Path;

use assert_cmd::Command;
use serde_json::Value;

fn seed_text() -> String {
    let seed = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/check/seed.dat");
    fs::read_to_string(seed).unwrap()
}

/// A project folder: `data/kb.dat` (the seed file, or `text`) and, if given, `ekb.toml`.
fn project(settings: Option<&str>, text: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir_all(dir.path().join("data")).unwrap();
    fs::write(dir.path().join("data/kb.dat"), text).unwrap();
    if let Some(settings) = settings {
        fs::write(dir.path().join("ekb.toml"), settings).unwrap();
    }
    dir
}

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn ekb(dir: &Path, args: &[&str]) -> Run {
    ekb_with_reader(dir, None, args)
}

/// [`ekb`] with `EKB_READER` set to `reader`, if there is one.
fn ekb_with_reader(dir: &Path, reader: Option<&str>, args: &[&str]) -> Run {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env_remove("NO_COLOR");
    if let Some(reader) = reader {
        command.env("EKB_READER", reader);
    }
    let output = command.args(args).output().unwrap();
    Run {
        code: output.status.code().expect("exited"),
        stdout: String::from_utf8(output.stdout).unwrap(),
        stderr: String::from_utf8(output.stderr).unwrap(),
    }
}

/// `rule@line` of each finding of a concise report.
fn findings(concise: &str) -> Vec<String> {
    concise
        .lines()
        .filter_map(|line| {
            let (place, rest) = line.split_once(": ")?;
            let line_number = place.split(':').nth(1)?;
            let rule = rest.split_once('[')?.1.split_once(']')?.0;
            Some(format!("{rule}@{line_number}"))
        })
        .collect()
}

fn count_of(concise: &str, rule: &str) -> usize {
    findings(concise)
        .iter()
        .filter(|f| f.starts_with(&format!("{rule}@")))
        .count()
}

// ---------------------------------------------------------------------------------------
// The command line

#[test]
fn level_error_shows_only_the_two_errors_and_the_summary() {
    let dir = project(None, &seed_text());
    let run = ekb(
        dir.path(),
        &[
            "check",
            "--level",
            "error",
            "--format",
            "concise",
            "data/kb.dat",
        ],
    );
    assert_eq!(run.code, 1);
    assert_eq!(findings(&run.stdout), ["missing-field@28", "key-case@34"]);
    assert!(run.stdout.ends_with(
        "Found 2 errors, 21 warnings (1 fixable with ekb fix; 21 below --level error not shown), \
         checked against reader d5.4.2\n"
    ));
    let human = ekb(dir.path(), &["check", "--level", "error", "data/kb.dat"]).stdout;
    assert_eq!(human.matches("error[").count(), 2);
    assert!(!human.contains("warning["));
}

#[test]
fn statistics_count_each_rule_the_most_frequent_first() {
    let dir = project(None, &seed_text());
    let run = ekb(dir.path(), &["check", "--statistics", "data/kb.dat"]);
    assert_eq!(run.code, 1);
    assert_eq!(
        run.stdout,
        "untranslated-message 20\n\
         key-case 1 (fixable)\n\
         missing-field 1\n\
         repeated-word 1\n\
         Found 2 errors, 21 warnings (1 fixable with ekb fix)\n"
    );
    let json = ekb(
        dir.path(),
        &["check", "--statistics", "--format", "json", "data/kb.dat"],
    );
    let rules: Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(rules[0]["rule"], "untranslated-message");
    assert_eq!(rules[0]["count"], 20);
    assert_eq!(rules[1]["fixable"], 1);
    let errors = ekb(
        dir.path(),
        &["check", "--statistics", "--level", "error", "data/kb.dat"],
    );
    assert!(errors
        .stdout
        .starts_with("key-case 1 (fixable)\nmissing-field 1\nFound"));
}

#[test]
fn select_ignore_and_extend_select_on_the_command_line() {
    let dir = project(None, &seed_text());
    let concise = |args: &[&str]| {
        let mut all = vec!["check", "--format", "concise"];
        all.extend_from_slice(args);
        all.push("data/kb.dat");
        ekb(dir.path(), &all)
    };
    let run = concise(&["--select", "key-case,repeated-word"]);
    assert_eq!(findings(&run.stdout), ["repeated-word@4", "key-case@34"]);
    let run = concise(&["--select", "content", "--ignore", "untranslated-message"]);
    assert_eq!(findings(&run.stdout), ["repeated-word@4"]);
    assert_eq!(run.code, 0, "no error selected");
    let run = concise(&["--ignore", "structure", "--extend-select", "key-case"]);
    assert_eq!(count_of(&run.stdout, "key-case"), 1);
    assert_eq!(count_of(&run.stdout, "missing-field"), 0);
    let run = concise(&["--ignore", "untranslated-mesage"]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.contains("did you mean `untranslated-message`?"),
        "{}",
        run.stderr
    );
}

#[test]
fn exit_zero_and_output_file() {
    let dir = project(None, &seed_text());
    let run = ekb(dir.path(), &["check", "--exit-zero", "data/kb.dat"]);
    assert_eq!(run.code, 0);
    let run = ekb(
        dir.path(),
        &[
            "check",
            "--format",
            "json",
            "--output-file",
            "report.json",
            "data/kb.dat",
        ],
    );
    assert_eq!((run.code, run.stdout.as_str()), (1, ""));
    let report: Value =
        serde_json::from_str(&fs::read_to_string(dir.path().join("report.json")).unwrap()).unwrap();
    assert_eq!(report["summary"]["errors"], 2);
}

// ---------------------------------------------------------------------------------------
// ekb.toml

const IGNORE_UNTRANSLATED: &str = "[check]\nignore = [\"untranslated-message\"]\n";

#[test]
fn an_ignored_rule_is_gone_from_every_format_and_from_the_exit_code() {
    // The seed file with its key corrected: warnings only.
    let warnings_only =
        seed_text().replace("postGestureMessageenglish", "postGestureMessageEnglish");
    let dir = project(Some(IGNORE_UNTRANSLATED), &warnings_only);
    for format in ["human", "concise", "json", "github", "sarif"] {
        let run = ekb(
            dir.path(),
            &[
                "check",
                "--deny-warnings",
                "--format",
                format,
                "data/kb.dat",
            ],
        );
        assert_eq!(
            run.code, 1,
            "{format}: the repeated word is still a warning"
        );
        let results = match format {
            // SARIF's rule descriptors list every rule: count the results only.
            "sarif" => {
                let sarif: Value = serde_json::from_str(&run.stdout).unwrap();
                sarif["runs"][0]["results"].to_string()
            }
            _ => run.stdout.clone(),
        };
        assert!(
            !results.contains("untranslated-message"),
            "{format}: {results}"
        );
        assert!(results.contains("repeated-word"), "{format}");
    }
    // Ignore the repeated word too, on the command line: nothing left to deny.
    let run = ekb(
        dir.path(),
        &[
            "check",
            "--deny-warnings",
            "--ignore",
            "repeated-word",
            "data/kb.dat",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stdout);
    assert!(run.stdout.ends_with(
        "No problems found; as the robot's software of document D5.4.2 reads it (d5.4.2)\n"
    ));
    // --isolated brings them back.
    let run = ekb(
        dir.path(),
        &["check", "--isolated", "--format", "concise", "data/kb.dat"],
    );
    assert_eq!(count_of(&run.stdout, "untranslated-message"), 20);
}

#[test]
fn a_misspelt_rule_in_the_settings_exits_2_naming_the_line() {
    let dir = project(
        Some("reader = \"d5.4.2\"\n[check]\nignore = [\"untranslated-mesage\"]\n"),
        &seed_text(),
    );
    let run = ekb(dir.path(), &["check", "data/kb.dat"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stdout, "");
    let toml = dir.path().join("ekb.toml");
    assert_eq!(
        run.stderr,
        "ekb: error: settings ekb.toml:3:11: `untranslated-mesage` is no rule or category; did \
         you mean `untranslated-message`? (in `ignore`)\n"
    );
    let run = ekb(dir.path(), &["check", "--isolated", "data/kb.dat"]);
    assert_eq!(run.code, 1, "--isolated reads no settings");
    fs::write(&toml, "[check]\nextend-selct = []\n").unwrap();
    let run = ekb(dir.path(), &["check", "data/kb.dat"]);
    assert!(
        run.stderr
            .contains("2:1: unknown key `extend-selct` in [check]; did you mean `extend-select`?"),
        "{}",
        run.stderr
    );
}

#[test]
fn settings_path_severity_and_per_file_ignores() {
    let dir = project(None, &seed_text());
    fs::create_dir_all(dir.path().join("data/drafts")).unwrap();
    fs::write(dir.path().join("data/drafts/kb.dat"), seed_text()).unwrap();
    let settings = "[check]\n\
                    severity = { untranslated-message = \"info\" }\n\
                    per-file-ignores = { \"data/drafts/*.dat\" = [\"content\"] }\n";
    fs::write(dir.path().join("team.toml"), settings).unwrap();
    let run = ekb(
        dir.path(),
        &[
            "check",
            "--settings",
            "team.toml",
            "--format",
            "concise",
            "data/kb.dat",
            "data/drafts/kb.dat",
        ],
    );
    let (main, drafts): (Vec<&str>, Vec<&str>) = run
        .stdout
        .lines()
        .filter(|line| line.starts_with("data/"))
        .partition(|line| line.starts_with("data/kb.dat"));
    assert_eq!(
        main.iter()
            .filter(|l| l.contains(": info[untranslated-message]"))
            .count(),
        20
    );
    assert!(drafts
        .iter()
        .all(|line| !line.contains("untranslated") && !line.contains("repeated")));
    assert_eq!(drafts.len(), 2, "the errors only: {drafts:?}");
    assert!(run.stdout.contains("Found 4 errors, 1 warning, 20 info"));
}

#[test]
fn settings_shows_each_value_and_where_it_comes_from() {
    let dir = project(
        Some("reader = \"2025-06\"\n[check]\nignore = [\"untranslated-message\"]\n[mission]\nconfig-dir = \"../bc/config\"\n"),
        &seed_text(),
    );
    let run = ekb(dir.path(), &["settings", "--ignore", "tour", "data/kb.dat"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let toml = "ekb.toml";
    for expected in [
        format!("reader = \"2025-06\"  # {toml}:1"),
        "select = [\"structure\", \"tour\", \"content\", \"compat\", \"map\", \"mission\", \"culture\", \"translation\"]  # default: every rule".into(),
        format!("ignore = [\"untranslated-message\", \"tour\"]  # {toml}:3, then the command line"),
        format!(
            "config-dir = \"{}\"  # {toml}:5",
            dir.path().join("../bc/config").display()
        ),
        "# config is not set".into(),
    ] {
        assert!(
            run.stdout.contains(&expected),
            "no {expected:?} in\n{}",
            run.stdout
        );
    }
    assert!(run
        .stdout
        .contains("rules run on this file; not: tour-missing,"));
    let run = ekb(
        dir.path(),
        &[
            "--reader",
            "2026-03",
            "--isolated",
            "settings",
            "data/kb.dat",
        ],
    );
    assert!(run.stdout.contains("# no settings file: --isolated"));
    assert!(run.stdout.contains("reader = \"2026-03\"  # --reader"));
    // The same reader from the environment is told as coming from there.
    let run = ekb_with_reader(
        dir.path(),
        Some("2026-03"),
        &["--isolated", "settings", "data/kb.dat"],
    );
    assert!(
        run.stdout.contains("reader = \"2026-03\"  # EKB_READER"),
        "{}",
        run.stdout
    );
}

#[test]
fn settings_shows_the_robot_profile_and_where_each_value_comes_from() {
    let dir = project(
        Some("[robot]\nspeaks = [\"english\", \"isiZulu\"]\n\nturn-speed = 1.2\n"),
        &seed_text(),
    );
    let run = ekb(dir.path(), &["settings", "data/kb.dat"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    for expected in [
        "[robot]\nspeaks = [\"English\", \"isiZulu\"]  # ekb.toml:2\n",
        "speed = 0.27  # default\n",
        "turn-speed = 1.2  # ekb.toml:4\n",
        "syllables-per-second = 5.0  # default\n",
    ] {
        assert!(
            run.stdout.contains(expected),
            "no {expected:?} in\n{}",
            run.stdout
        );
    }
    let run = ekb(dir.path(), &["--isolated", "settings", "data/kb.dat"]);
    assert!(
        run.stdout
            .contains("speaks = [\"English\", \"Kinyarwanda\"]  # default\n"),
        "{}",
        run.stdout
    );
    // A bad value stops every command, naming its line and column.
    fs::write(dir.path().join("ekb.toml"), "[robot]\nspeed = -1\n").unwrap();
    let run = ekb(dir.path(), &["check", "data/kb.dat"]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr
            .contains("ekb.toml:2:9: `speed` must be a number above 0 (m/s, e.g. 0.27), not -1"),
        "{}",
        run.stderr
    );
}

// ---------------------------------------------------------------------------------------
// Suppression comments

fn with_line_before(text: &str, number: usize, inserted: &str) -> String {
    let mut lines: Vec<&str> = text.split_inclusive('\n').collect();
    let line = format!("{inserted}\n");
    lines.insert(number - 1, &line);
    lines.concat()
}

#[test]
fn an_ignore_comment_silences_that_finding_only_and_is_reported_once_unused() {
    // Above line 4, the repeated word: it becomes line 5.
    let text = with_line_before(&seed_text(), 4, "# ekb: ignore[repeated-word]");
    let dir = project(None, &text);
    let run = ekb(dir.path(), &["check", "--format", "concise", "data/kb.dat"]);
    assert_eq!(count_of(&run.stdout, "repeated-word"), 0);
    assert_eq!(count_of(&run.stdout, "untranslated-message"), 20);
    assert!(run.stdout.contains("Found 2 errors, 20 warnings"));
    // Moved elsewhere (above line 3), it is unused; `ekb fix` removes it.
    let moved = with_line_before(&seed_text(), 3, "# ekb: ignore[repeated-word]");
    fs::write(dir.path().join("data/kb.dat"), &moved).unwrap();
    let run = ekb(dir.path(), &["check", "--format", "concise", "data/kb.dat"]);
    assert_eq!(count_of(&run.stdout, "repeated-word"), 1);
    assert!(findings(&run.stdout).contains(&"unused-suppression@3".to_string()));
    let run = ekb(dir.path(), &["fix", "data/kb.dat"]);
    assert!(
        run.stderr.contains("1 unused-suppression"),
        "{}",
        run.stderr
    );
    let fixed = fs::read_to_string(dir.path().join("data/kb.dat")).unwrap();
    assert!(!fixed.contains("ekb: ignore"));
}

#[test]
fn add_ignore_makes_the_file_check_clean_and_a_second_run_adds_nothing() {
    let dir = project(None, &seed_text());
    let run = ekb(dir.path(), &["check", "--add-ignore", "data/kb.dat"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stderr, "data/kb.dat: added 23 suppression comments\n");
    let once = fs::read_to_string(dir.path().join("data/kb.dat")).unwrap();
    assert!(once
        .contains("# ekb: ignore[repeated-word]\npreGestureMessageEnglish      1 Welcome the the"));
    assert!(once.contains("# ekb: ignore[missing-field]\nrobotLocationDescription      4 Roomba"));
    let run = ekb(dir.path(), &["check", "--deny-warnings", "data/kb.dat"]);
    assert_eq!(run.code, 0, "{}", run.stdout);
    let run = ekb(dir.path(), &["check", "--add-ignore", "data/kb.dat"]);
    assert_eq!(run.stderr, "data/kb.dat: added 0 suppression comments\n");
    assert_eq!(
        fs::read_to_string(dir.path().join("data/kb.dat")).unwrap(),
        once
    );
    // fmt keeps each comment with its line, and the file stays clean.
    ekb(dir.path(), &["fmt", "data/kb.dat"]);
    let run = ekb(dir.path(), &["check", "--deny-warnings", "data/kb.dat"]);
    assert_eq!(run.code, 0, "{}", run.stdout);
}

#[test]
fn a_file_wide_ignore_silences_a_rule_everywhere() {
    let text = format!(
        "# ekb: ignore-file[untranslated-message, tour]\n{}",
        seed_text()
    );
    let dir = project(None, &text);
    let run = ekb(dir.path(), &["check", "--format", "concise", "data/kb.dat"]);
    assert_eq!(count_of(&run.stdout, "untranslated-message"), 0);
    assert_eq!(
        findings(&run.stdout),
        [
            "unused-suppression@1",
            "repeated-word@5",
            "missing-field@29",
            "key-case@35"
        ]
    );
    assert!(run
        .stdout
        .contains("unused-suppression] this suppression of `tour` silences nothing"));
}
