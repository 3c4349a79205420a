//! A real editor end to end: headless Neovim opens the seed file with `ekb lsp` attached
//! (`tests/fixtures/lsp/neovim-e2e.lua`) and reads back the diagnostics and a hover.
//!
//! Skipped, saying so, where Neovim is not installed; on CI (`CI` set) its absence is a
//! failure: `.ci/run` installs it.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[test]
fn neovim_shows_the_findings_of_the_seed_file() {
    let found = Command::new("nvim")
        .arg("--version")
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|status| status.success());
    if !found {
        assert!(
            std::env::var_os("CI").is_none(),
            "nvim is not installed: CI must install it (see .ci/run)"
        );
        eprintln!("SKIPPED neovim_shows_the_findings_of_the_seed_file: nvim is not installed (apt-get install neovim)");
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("environmentKnowledgeBaseInput.dat");
    std::fs::copy(root.join("tests/fixtures/check/seed.dat"), &file).unwrap();
    let out = folder.path().join("seen.txt");
    let mut nvim = Command::new("nvim")
        .args(["--headless", "--clean", "-n", "-i", "NONE", "-c"])
        .arg(format!(
            "luafile {}",
            root.join("tests/fixtures/lsp/neovim-e2e.lua").display()
        ))
        .current_dir(folder.path())
        .env("EKB_BIN", env!("CARGO_BIN_EXE_ekb"))
        .env("EKB_FILE", &file)
        .env("EKB_OUT", &out)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(120);
    while nvim.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            nvim.kill().unwrap();
            panic!("nvim did not finish in two minutes");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let seen = std::fs::read_to_string(&out).expect("nvim wrote what it saw");
    let mut lines: Vec<&str> = seen.lines().collect();
    lines.sort();
    let errors: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|line| line.contains("key-case") || line.contains("missing-field"))
        .collect();
    assert_eq!(
        errors,
        [
            "diagnostic 27:0 missing-field location 4 has no `postGestureMessageEnglish`: location 4 will say nothing after the gesture in English",
            "diagnostic 33:0 key-case `postGestureMessageenglish` is `postGestureMessageEnglish` in the wrong case: the robot's reader ignores this line, so location 4 will say nothing after the gesture in English",
        ],
        "{seen}"
    );
    let diagnostics = lines
        .iter()
        .filter(|l| l.starts_with("diagnostic "))
        .count();
    assert_eq!(diagnostics, 23, "{seen}");
    assert!(
        lines.contains(&"hover **Location 4: Roomba** · stop 2 of 5"),
        "{seen}"
    );
}
