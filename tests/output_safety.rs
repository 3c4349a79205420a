//! Output that cannot forge or inject (issue 12, item 2): whatever a file contains and
//! whatever its name, no line that `ekb` prints — any command, any format, standard output or
//! standard error — begins (after blanks) with `::` or holds `##[` (a GitHub Actions runner
//! obeys both), or holds a raw control, bidirectional or invisible character; only
//! `--format github`'s own commands begin with `::`. Lookalikes are escaped and named.

mod output_support;

use std::ffi::OsString;
use std::path::Path;

use assert_cmd::Command;
use ekb::render::escape::is_hidden;
use proptest::prelude::*;

/// `ekb` run in `dir`, without colour.
fn ekb(dir: &Path) -> Command {
    let mut command = output_support::ekb(dir);
    command.arg("--color=never");
    command
}

/// The lines of `output` that a CI runner would obey or a terminal act on. With
/// `github_commands`, a line that is one of `--format github`'s annotations is allowed.
fn forged_lines(output: &str, github_commands: bool) -> Vec<String> {
    let annotation = |line: &str| {
        ["::error file=", "::warning file=", "::notice file="]
            .iter()
            .any(|command| line.starts_with(command))
    };
    output
        .split('\n')
        .filter(|line| {
            // The runner trims every Unicode blank before looking for `::` and a command
            // of its own, in any case.
            let begins_command = line.trim_start().strip_prefix("::").is_some_and(|rest| {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '-')
                    .collect();
                ekb::render::escape::WORKFLOW_COMMANDS
                    .iter()
                    .any(|command| name.eq_ignore_ascii_case(command))
            });
            (begins_command && !(github_commands && annotation(line)))
                || line.contains("##[")
                || line.chars().any(|ch| ch != '\t' && is_hidden(ch))
        })
        .map(str::to_string)
        .collect()
}

/// Every command that prints something of a file, on `file` (and `other`, for `diff`).
fn commands(file: &Path, other: &Path) -> Vec<Vec<OsString>> {
    let with_file = |args: &[&str]| {
        let mut args: Vec<OsString> = args.iter().map(OsString::from).collect();
        args.push(file.into());
        args
    };
    let mut all: Vec<Vec<OsString>> = [
        &["check"][..],
        &["check", "--format", "concise"],
        &["check", "--format", "json"],
        &["check", "--format", "github"],
        &["check", "--format", "sarif"],
        &["--verbose", "check", "--format", "concise"],
        &["show", "1"],
        &["show", "2"],
        &["show", "99"],
        &["tour"],
        &["tour", "--lang", "zu"],
        &["tour", "--format", "json"],
        &["locations"],
        &["locations", "--format", "classic"],
        &["locations", "--format", "json"],
        &["export", "--allow-errors"],
        &["export", "--as-loaded", "--allow-errors"],
        &["fmt", "--check"],
        &["fix", "--diff"],
    ]
    .iter()
    .map(|args| with_file(args))
    .collect();
    all.push(vec!["diff".into(), file.into(), other.into()]);
    all.push(vec!["diff".into(), other.into(), file.into()]);
    all
}

/// Runs every command on a file named `name` holding `content` (and on a copy of it that
/// `fmt` and `fix` rewrite), and returns what each printed that it must not have.
fn forgeries(name: &OsString, content: &[u8]) -> Vec<String> {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, content).unwrap();
    let other = dir.path().join("other.dat");
    std::fs::write(&other, BASE).unwrap();
    let mut found = Vec::new();
    let mut record = |args: &[OsString], output: std::process::Output| {
        let github = args.iter().any(|arg| arg == "github");
        let code = output.status.code();
        assert!(matches!(code, Some(0..=2)), "{args:?} exited {code:?}");
        for (stream, bytes) in [("stdout", &output.stdout), ("stderr", &output.stderr)] {
            let text = String::from_utf8_lossy(bytes);
            for line in forged_lines(&text, github && stream == "stdout") {
                found.push(format!("{args:?} {stream}: {line:?}"));
            }
        }
    };
    for args in commands(&file, &other) {
        let output = ekb(dir.path()).args(&args).output().unwrap();
        record(&args, output);
    }
    for command in ["fmt", "fix"] {
        let copy = dir.path().join(rewritten_name(name, command));
        std::fs::write(&copy, content).unwrap();
        let args = [OsString::from(command), copy.into()];
        let output = ekb(dir.path()).args(&args).output().unwrap();
        record(&args, output);
    }
    found
}

/// `name` with `command` put before it, for a copy beside the file.
fn rewritten_name(name: &OsString, command: &str) -> OsString {
    let mut copy = OsString::from(format!("{command}-"));
    copy.push(name);
    copy
}

/// A small knowledge base with two locations and a tour.
const BASE: &str = "\
robotLocationDescription      1 Entrance
robotLocation                 1 2.6 8.1 -90
gestureTarget                 1 0.0 0.0 0.0
preGestureMessageEnglish      1 Welcome to the lab
preGestureMessageIsiZulu      1 No message in isiZulu
preGestureMessageKinyarwanda  1 Murakaza neza
postGestureMessageEnglish     1 Enjoy the tour
postGestureMessageIsiZulu     1 No message in isiZulu
postGestureMessageKinyarwanda 1 No message in Kinyarwanda
robotLocationDescription      2 Roomba
robotLocation                 2 5.0 3.9 110
gestureTarget                 2 6.8 4.8 0.82
preGestureMessageEnglish      2 This is the Roomba
preGestureMessageIsiZulu      2 Le yi-Roomba
preGestureMessageKinyarwanda  2 Iyi ni Roomba
postGestureMessageEnglish     2 It cleans the floor
postGestureMessageIsiZulu     2 No message in isiZulu
postGestureMessageKinyarwanda 2 No message in Kinyarwanda
tourSpecification 2 1 2
";

/// [`BASE`] with `text` put into its first message, which `check` quotes in a help (its
/// isiZulu is a placeholder: "translate from English: …") and shows under a repeated word,
/// and a copy of the line with a typo in its key, a finding of its own.
fn with_message(text: &str) -> String {
    let line = format!("preGestureMessageEnglish      1 Welcome the the {text}");
    BASE.replace("preGestureMessageEnglish      1 Welcome to the lab", &line)
        + &format!("preGestureMesageEnglish 1 {text}\n")
}

#[test]
fn a_workflow_command_in_a_message_never_begins_a_line_however_it_wraps() {
    // After 0 to 99 letters without a space, wrapping cuts the word at every place once,
    // right before the `::` too; after words, the break comes between words.
    let dir = tempfile::tempdir().unwrap();
    for letters in 0..100 {
        let message = format!(
            "{}::error file=README.md,line=1::pwned",
            "x".repeat(letters)
        );
        std::fs::write(dir.path().join("kb.dat"), with_message(&message)).unwrap();
        let output = ekb(dir.path()).args(["check", "kb.dat"]).output().unwrap();
        let stdout = String::from_utf8(output.stdout).unwrap();
        assert!(
            stdout.contains(":\\u{003A}error file=README.md"),
            "{stdout}"
        );
        let found = forged_lines(&stdout, false);
        assert!(found.is_empty(), "{letters} letters: {found:#?}");
    }
    for message in [
        "        ::error file=README.md,line=1::pwned",
        &format!("{}::error file=README.md,line=1::pwned", "x".repeat(80)),
    ] {
        let found = forgeries(&"kb.dat".into(), with_message(message).as_bytes());
        assert!(found.is_empty(), "{message}: {found:#?}");
    }
}

#[test]
fn hash_bracket_commands_are_broken_up_anywhere_in_a_line() {
    let message = "see ##[warning]forged and ##vso[task.complete result=Failed]";
    let found = forgeries(&"kb.dat".into(), with_message(message).as_bytes());
    assert!(found.is_empty(), "{found:#?}");
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("kb.dat"), with_message(message)).unwrap();
    let output = ekb(dir.path())
        .args(["show", "1", "kb.dat"])
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.contains("##\\u{005B}warning]forged"), "{stdout}");
    assert!(stdout.contains("##vso\\u{005B}task.complete"), "{stdout}");
}

#[test]
fn file_names_with_newlines_and_commands_are_escaped_everywhere() {
    let name = "::error file=a.dat::forged\n::warning x\u{1b}[31m\u{202E}.dat";
    let found = forgeries(&name.into(), BASE.as_bytes());
    assert!(found.is_empty(), "{found:#?}");
    // Named in the error of a missing file, of every command that reads one.
    let dir = tempfile::tempdir().unwrap();
    for command in ["check", "fmt", "fix", "show", "tour", "locations", "export"] {
        let mut args = vec![command];
        if command == "show" {
            args.push("1");
        }
        let output = ekb(dir.path()).args(&args).arg(name).output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{command}");
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert!(
            forged_lines(&stderr, false).is_empty(),
            "{command}: {stderr}"
        );
        assert!(
            stderr
                .starts_with("ekb: error: cannot read :\\u{003A}error file=a.dat::forged\\u{000A}"),
            "{command}: {stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{command}: {stderr}");
    }
}

#[cfg(unix)]
#[test]
fn a_file_name_that_is_not_utf8_is_shown_replaced() {
    use std::os::unix::ffi::OsStringExt;
    let name = OsString::from_vec(b"::kb\xff\n.dat".to_vec());
    let found = forgeries(&name, BASE.as_bytes());
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn diffs_escape_file_text_when_not_on_a_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("kb.dat");
    let text = BASE.replace(
        "Entrance",
        "Entrance\u{1b}]0;pwned\u{7} a\u{9b}b \u{202E}x  ",
    );
    std::fs::write(&file, &text).unwrap();
    for command in ["fmt --check", "fix --diff"] {
        let output = ekb(dir.path())
            .args(command.split(' '))
            .arg(&file)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(1), "{command}");
        let stdout = String::from_utf8(output.stdout).unwrap();
        assert!(
            forged_lines(&stdout, false).is_empty(),
            "{command}: {stdout}"
        );
        assert!(
            stdout.contains(
                "Entrance\\u{001B}]0;pwned\\u{0007} a\\u{009B}b \\u{202E RIGHT-TO-LEFT OVERRIDE}x"
            ),
            "{command}: {stdout}"
        );
    }
}

#[test]
fn lookalikes_and_invisible_spaces_are_escaped_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let text = BASE
        .replace(
            "robotLocationDescription      2",
            "robotLocationD\u{435}scription 2",
        )
        .replace("This is the Roomba", "This\u{A0}is the\u{3000}Roomba")
        .replace("Enjoy the tour", "Enjoy\u{2003}the tour")
        + "gestureArm 1 \u{212A}eft\n";
    std::fs::write(dir.path().join("kb.dat"), &text).unwrap();
    let output = ekb(dir.path())
        .args(["check", "--format", "concise", "kb.dat"])
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    for expected in [
        "kb.dat:10:1: error[unknown-key] `robotLocationD\\u{0435 CYRILLIC SMALL LETTER IE}scription` is not a key",
        "the value starts with `\\u{212A KELVIN SIGN}`",
    ] {
        assert!(stdout.contains(expected), "{expected}\n{stdout}");
    }
    let output = ekb(dir.path())
        .args(["show", "2", "kb.dat"])
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("This\\u{00A0 NO-BREAK SPACE}is the\\u{3000 IDEOGRAPHIC SPACE}Roomba"),
        "{stdout}"
    );
    let output = ekb(dir.path()).args(["tour", "kb.dat"]).output().unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("\"Enjoy\\u{2003 EM SPACE}the tour\""),
        "{stdout}"
    );
}

/// Text that CI runners and terminals act on, and the characters around it that move it
/// about: words (wrapping), blanks, colons, brackets, newlines (in names), lookalikes.
fn hostile_text(max: usize) -> impl Strategy<Value = String> {
    let pieces = prop::sample::select(vec![
        "::",
        ":",
        "##[",
        "##",
        "[",
        "##vso[",
        "::error file=x::y",
        " ",
        "        ",
        "\t",
        "word ",
        "words and more words ",
        "\u{1b}[31m",
        "\u{1b}]0;t\u{7}",
        "\u{9b}",
        "\r",
        "\u{202E}",
        "\u{2066}",
        "\u{200B}",
        "\u{FEFF}",
        "\u{A0}",
        "\u{3000}",
        "\u{435}",
        "\u{212A}",
        "\u{2212}1",
        "\u{FF1A}\u{FF1A}",
        "#",
        "é",
        "-",
    ]);
    prop::collection::vec(pieces, 0..max).prop_map(|pieces| pieces.concat())
}

/// A knowledge base with hostile text in keys, values, comments and the tour, some lines
/// broken on purpose.
fn hostile_file() -> impl Strategy<Value = String> {
    let line = prop_oneof![
        hostile_text(24).prop_map(|t| format!("preGestureMessageEnglish 1 the the {t}")),
        hostile_text(24).prop_map(|t| format!("robotLocationDescription 2 {t}")),
        hostile_text(6).prop_map(|t| format!("{t}robotLocation{t} 1 2 3 4")),
        hostile_text(6).prop_map(|t| format!("gestureArm 2 {t}")),
        hostile_text(6).prop_map(|t| format!("# {t}")),
        hostile_text(6).prop_map(|t| format!("tourSpecification 2 1 {t}2")),
        hostile_text(8),
    ];
    prop::collection::vec(line, 1..6).prop_map(|lines| format!("{BASE}{}\n", lines.join("\n")))
}

/// A file name with what a runner or a terminal acts on (no `/`, no NUL).
fn hostile_name() -> impl Strategy<Value = OsString> {
    let pieces = prop::sample::select(vec![
        "::",
        ":",
        "##[",
        "\n",
        "\r",
        " ",
        "\u{1b}[2J",
        "\u{202E}",
        "\u{A0}",
        "\u{435}",
        "kb",
        ".dat",
        "#",
        ",",
        "%",
    ]);
    prop::collection::vec(pieces, 1..8).prop_map(|pieces| OsString::from(pieces.concat() + ".dat"))
}

proptest! {
    // Each case runs every command (about twenty processes): a few cases keep it fast.
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn nothing_a_file_holds_or_is_named_forges_a_ci_command(
        name in hostile_name(),
        content in hostile_file(),
    ) {
        let found = forgeries(&name, content.as_bytes());
        prop_assert!(found.is_empty(), "{:#?}", found);
    }
}
