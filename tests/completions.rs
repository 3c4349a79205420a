//! The completion scripts kept in `completions/` must match what `ekb completions` prints.
//! Regenerate them with `scripts/update-completions.sh` after changing the CLI.

use std::path::Path;

use clap::ValueEnum;
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
            kept == script(shell),
            "{} is stale or missing: run scripts/update-completions.sh",
            path.display()
        );
    }
}

#[test]
fn completions_name_every_subcommand() {
    let bash = String::from_utf8(script(Shell::Bash)).unwrap();
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
fn man_page_describes_the_tool() {
    let output = assert_cmd::Command::cargo_bin("ekb")
        .unwrap()
        .arg("man")
        .output()
        .unwrap();
    assert!(output.status.success());
    let page = String::from_utf8(output.stdout).unwrap();
    assert!(
        page.starts_with(".ie") || page.contains(".TH ekb"),
        "{}",
        &page[..page.len().min(200)]
    );
    assert!(page.contains("check"));
}
