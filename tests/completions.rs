//! The completion scripts kept in `completions/` must match what `ekb completions` prints.
//! Regenerate them with `scripts/update-completions.sh` after changing the CLI.

use std::path::Path;

use clap::{CommandFactory, ValueEnum};
use clap_complete::Shell;
use ekb::commands::completions::{file_name, script};

#[test]
fn kept_completion_scripts_are_current() {
    for &shell in Shell::value_variants() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("completions")
            .join(file_name(shell));
        let kept = std::fs::read(&path).unwrap_or_default();
        assert!(
            kept == script(shell, ekb::cli::Cli::command()),
            "{} is stale or missing: run scripts/update-completions.sh",
            path.display()
        );
    }
}

#[test]
fn completions_name_every_subcommand() {
    let bash = String::from_utf8(script(Shell::Bash, ekb::cli::Cli::command())).unwrap();
    for command in [
        "check",
        "locations",
        "show",
        "tour",
        "diff",
        "export",
        "import",
        "fmt",
        "fix",
        "rules",
        "explain",
    ] {
        assert!(bash.contains(command), "bash completion lacks {command}");
    }
}

#[test]
fn man_page_documents_every_command_and_names_no_other_page() {
    let output = assert_cmd::Command::cargo_bin("ekb")
        .unwrap()
        .arg("man")
        .output()
        .unwrap();
    assert!(output.status.success());
    let page = String::from_utf8(output.stdout).unwrap();
    assert!(
        page.contains(".TH ekb 1"),
        "{}",
        &page[..page.len().min(200)]
    );
    // roff writes a hyphen as `\-`.
    let roff = |text: &str| text.replace('-', "\\-");
    for command in ekb::cli::Cli::command().get_subcommands() {
        let name = command.get_name();
        assert!(page.contains(&format!(".SS \"ekb {name}\"\n")), "{name}");
        for arg in command.get_arguments() {
            let shown = match (arg.get_long(), arg.get_value_names()) {
                (Some(long), _) => roff(&format!("--{long}")),
                (None, Some(names)) => names.join(" "),
                (None, None) => panic!("{name}: an argument with no name"),
            };
            assert!(page.contains(&shown), "{name} {shown}");
        }
        for missing_page in [format!("ekb-{name}("), roff(&format!("ekb-{name}("))] {
            assert!(!page.contains(&missing_page), "{missing_page}");
        }
    }
    for section in [
        ".SH OPTIONS",
        ".SH \"EXIT STATUS\"",
        ".SH ENVIRONMENT",
        ".B EKB_CONFIG",
        ".B NO_COLOR",
        ".SH FILES",
    ] {
        assert!(page.contains(section), "{section}");
    }
}

/// The commands of the man page's EXAMPLES: each `.B ekb …` line and each `\fBekb …\fR` in
/// the text below it, as a shell would split them.
fn examples(page: &str) -> Vec<Vec<String>> {
    let section = page
        .split(".SH EXAMPLES\n")
        .nth(1)
        .and_then(|rest| rest.split("\n.SH ").next())
        .expect("an EXAMPLES section");
    let unroff = |text: &str| text.replace("\\-", "-").replace("\\(dq", "\"");
    let mut commands = Vec::new();
    for line in section.lines() {
        if let Some(command) = line.strip_prefix(".B ") {
            commands.push(unroff(command));
        }
        for piece in line.split("\\fB").skip(1) {
            let command = piece.split("\\fR").next().unwrap();
            if command.contains(' ') {
                commands.push(unroff(command));
            }
        }
    }
    commands
        .iter()
        .map(|command| {
            // Words, with a double-quoted one kept whole.
            let mut words = Vec::new();
            for (index, part) in command.split('"').enumerate() {
                match index % 2 {
                    1 => words.push(part.to_string()),
                    _ => words.extend(part.split_whitespace().map(str::to_string)),
                }
            }
            words
        })
        .collect()
}

#[test]
fn every_example_of_the_man_page_runs() {
    let page = ekb::commands::man::page(ekb::cli::Cli::command()).unwrap();
    let examples = examples(&page);
    assert!(examples.len() >= 10, "{examples:?}");
    // The robot's folders: config/ naming the files in data/.
    let dir = tempfile::tempdir().unwrap();
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/mission/corpus");
    for folder in ["config", "data"] {
        std::fs::create_dir(dir.path().join(folder)).unwrap();
        for entry in std::fs::read_dir(corpus.join(folder)).unwrap() {
            let entry = entry.unwrap();
            std::fs::copy(
                entry.path(),
                dir.path().join(folder).join(entry.file_name()),
            )
            .unwrap();
        }
    }
    for words in examples {
        assert_eq!(words[0], "ekb", "{words:?}");
        let args: Vec<&str> = words[1..]
            .iter()
            .map(|word| match word.as_str() {
                "FILE" => "data/environmentKnowledgeBaseInput.dat",
                word => word,
            })
            .collect();
        let output = assert_cmd::Command::cargo_bin("ekb")
            .unwrap()
            .current_dir(dir.path())
            .env_remove("EKB_CONFIG")
            .args(&args)
            .output()
            .unwrap();
        // 1 is a finding (or a diff): the example did its job.
        assert!(
            matches!(output.status.code(), Some(0 | 1)),
            "ekb {}: {}",
            args.join(" "),
            String::from_utf8_lossy(&output.stderr)
        );
    }
}
