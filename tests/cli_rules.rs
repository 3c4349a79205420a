//! `ekb rules` and `ekb explain`: the rule catalogue from the command line.

use assert_cmd::Command;

/// Every rule name of SPEC §4: the contract.
const SPEC_RULES: &[&str] = &[
    "invalid-utf8",
    "unknown-key",
    "key-case",
    "missing-id",
    "invalid-id",
    "invalid-number",
    "wrong-arity",
    "empty-value",
    "invalid-value",
    "duplicate-key",
    "missing-field",
    "mixed-dialect",
    "legacy-key",
    "control-character",
    "tour-missing",
    "tour-duplicate-spec",
    "tour-count-mismatch",
    "tour-empty",
    "tour-unknown-location",
    "tour-too-long",
    "tour-repeated-stop",
    "unused-location",
    "untranslated-message",
    "repeated-word",
    "trailing-whitespace",
    "theta-out-of-range",
    "gesture-target-sums-to-zero",
    "gesture-behind-robot",
    "compat-line-too-long",
    "compat-leading-symbol",
    "compat-no-final-newline",
    "compat-crlf",
    "compat-bom",
    "compat-too-many-cultural-keys",
];

fn ekb() -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env_remove("NO_COLOR");
    command
}

fn stdout_of(command: &mut Command) -> String {
    let output = command.assert().success().get_output().stdout.clone();
    String::from_utf8(output).unwrap()
}

#[test]
fn rules_lists_every_rule_with_its_severity() {
    let out = stdout_of(ekb().arg("rules"));
    for name in SPEC_RULES {
        assert!(
            out.lines()
                .any(|line| line.split_whitespace().any(|w| w == *name)),
            "{name} missing from\n{out}"
        );
    }
    let key_case = out
        .lines()
        .find(|line| line.contains(" key-case "))
        .unwrap();
    assert!(
        key_case.contains("error") && key_case.contains("yes"),
        "{key_case}"
    );
}

#[test]
fn rules_markdown_has_one_row_per_rule() {
    let out = stdout_of(ekb().args(["rules", "--markdown"]));
    for name in SPEC_RULES {
        assert_eq!(
            out.matches(&format!("| `{name}` |")).count(),
            1,
            "{name} in\n{out}"
        );
    }
    assert!(out.contains("| `key-case` | error | yes | a known key in the wrong case |"));
    assert!(out.contains("| `unused-location` | info |  |"));
}

#[test]
fn explain_prints_the_rule_documentation() {
    let out = stdout_of(ekb().args(["explain", "key-case"]));
    assert!(out.starts_with("# key-case (error, Structure)\n\na known key in the wrong case\n"));
    assert!(out.contains("Fix: `ekb fix` repairs it."));
    for section in ["## What it does", "## Why it matters", "## Example"] {
        assert!(
            out.lines().any(|line| line == section),
            "{section} in\n{out}"
        );
    }
    assert!(
        out.contains("\npostGestureMessageenglish     4 We use it for teaching mobile robotics\n")
    );
    assert!(
        !out.contains("\n ##"),
        "doc comment indentation is stripped"
    );
}

#[test]
fn every_rule_can_be_explained() {
    for name in SPEC_RULES {
        let out = stdout_of(ekb().args(["explain", name]));
        assert!(out.starts_with(&format!("# {name} (")), "{out}");
    }
}

#[test]
fn explain_takes_any_case_and_a_unique_prefix() {
    for query in ["KEY-CASE", "Key-Case", "key-ca"] {
        let out = stdout_of(ekb().args(["explain", query]));
        assert!(
            out.starts_with("# key-case (error, Structure)\n"),
            "{query}: {out}"
        );
    }
    let out = stdout_of(ekb().args(["explain", "untranslated"]));
    assert!(out.starts_with("# untranslated-message (warning, Content)\n"));
    let assert = ekb()
        .args(["explain", "compat-c"])
        .assert()
        .code(2)
        .stdout("");
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert_eq!(
        stderr,
        "ekb: error: `compat-c` starts the names of 2 rules (compat-crlf, \
         compat-cultural-word-split); give more of the name\n"
    );
}

#[test]
fn an_unknown_rule_exits_2_with_a_suggestion() {
    let assert = ekb()
        .args(["explain", "key-cose"])
        .assert()
        .code(2)
        .stdout("");
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert_eq!(
        stderr,
        "ekb: error: no rule named `key-cose`; did you mean `key-case`?\n"
    );
    let assert = ekb().args(["explain", "zzzzzzzzzzzzzz"]).assert().code(2);
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert_eq!(
        stderr,
        "ekb: error: no rule named `zzzzzzzzzzzzzz`; `ekb rules` lists them\n"
    );
}
