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
