//! Configuration is input too (issue 12, item 4): the robot's INI (`--config`,
//! `EKB_CONFIG`, the default path) and `ekb.toml` are read with the guards of a knowledge
//! base (a regular file, of bounded size, in UTF-8): `--config /dev/zero` grew memory
//! without bound and a FIFO hung. A `knowledgeBase` outside the configuration's project
//! folder is told with `-v`, and `fix` and `fmt` rewrite it only when it is named.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::Duration;

/// Far more than any of these runs needs, even on a loaded machine: past it, `ekb` hangs.
const DEADLINE: Duration = Duration::from_secs(30);

/// A file with something to fix, and what `fix` makes of it.
const UNFIXED: &str = "robotLocationDescription 1 Roomba  \n";
const FIXED: &str = "robotLocationDescription 1 Roomba\n";

fn ekb(dir: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_ekb"));
    command
        .current_dir(dir)
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    command
}

/// Runs `command`, failing the test (and killing it) if it does not end by [`DEADLINE`].
/// Its output is read as it comes (a report of a large file fills a pipe's buffer).
fn run(command: &mut Command) -> Output {
    let child = command.spawn().unwrap();
    let pid = child.id().to_string();
    let (done, finished) = std::sync::mpsc::channel();
    std::thread::spawn(move || done.send(child.wait_with_output().unwrap()));
    finished.recv_timeout(DEADLINE).unwrap_or_else(|_| {
        let _ = Command::new("kill").args(["-9", &pid]).status();
        panic!("ekb hung: {command:?}");
    })
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Asserts exit 2 and one error line on standard error that contains `reason`.
fn assert_refused(output: &Output, reason: &str) {
    let stderr = stderr(output);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("ekb: error: "), "{stderr}");
    assert!(stderr.contains(reason), "{stderr}");
}

fn mkfifo(path: &Path) {
    let made = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(made.success());
}

/// A folder with a knowledge base to check.
fn folder_with_a_file() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let kb = dir.path().join("kb.dat");
    fs::write(&kb, FIXED).unwrap();
    (dir, kb)
}

const NOT_REGULAR: &str =
    "it is not a regular file (a pipe, socket or device); give a regular file";

#[test]
fn config_dev_zero_is_refused_at_once() {
    let (dir, kb) = folder_with_a_file();
    let output = run(ekb(dir.path())
        .args(["--config", "/dev/zero", "check"])
        .arg(&kb));
    assert_refused(
        &output,
        &format!("cannot read configuration /dev/zero: {NOT_REGULAR}"),
    );
    let output = run(ekb(dir.path())
        .env("EKB_CONFIG", "/dev/zero")
        .arg("check")
        .arg(&kb));
    assert_refused(&output, "cannot read configuration /dev/zero");
}

#[test]
fn a_config_fifo_does_not_hang() {
    let (dir, kb) = folder_with_a_file();
    let fifo = dir.path().join("config.ini");
    mkfifo(&fifo);
    let output = run(ekb(dir.path())
        .arg("--config")
        .arg(&fifo)
        .arg("check")
        .arg(&kb));
    assert_refused(&output, NOT_REGULAR);
    let output = run(ekb(dir.path())
        .env("EKB_CONFIG", &fifo)
        .arg("check")
        .arg(&kb));
    assert_refused(&output, NOT_REGULAR);
    // At the default path, it is refused rather than skipped as no configuration.
    fs::create_dir(dir.path().join("config")).unwrap();
    mkfifo(
        &dir.path()
            .join("config/environmentKnowledgeBaseConfiguration.ini"),
    );
    let output = run(ekb(dir.path()).arg("check").arg(&kb));
    assert_refused(&output, NOT_REGULAR);
}

#[test]
fn a_huge_or_wide_config_is_refused() {
    let (dir, kb) = folder_with_a_file();
    let huge = dir.path().join("huge.ini");
    // Sparse: 2 MiB that take no room.
    fs::File::create(&huge).unwrap().set_len(2 << 20).unwrap();
    let output = run(ekb(dir.path())
        .arg("--config")
        .arg(&huge)
        .arg("check")
        .arg(&kb));
    assert_refused(
        &output,
        "it is larger than 1 MiB, the most ekb reads of such a file",
    );
    let wide = dir.path().join("wide.ini");
    let utf16: Vec<u8> = "verboseMode true\n"
        .encode_utf16()
        .flat_map(u16::to_le_bytes)
        .collect();
    fs::write(&wide, utf16).unwrap();
    let output = run(ekb(dir.path())
        .arg("--config")
        .arg(&wide)
        .arg("check")
        .arg(&kb));
    assert_refused(&output, "it is UTF-16LE text");
}

#[test]
fn ekb_toml_gets_the_same_guards() {
    let (dir, kb) = folder_with_a_file();
    let settings = dir.path().join("ekb.toml");
    mkfifo(&settings);
    let output = run(ekb(dir.path()).arg("check").arg(&kb));
    assert_refused(
        &output,
        // Named relative to the current folder, where it is.
        &format!("cannot read settings ekb.toml: {NOT_REGULAR}"),
    );
    fs::remove_file(&settings).unwrap();
    std::os::unix::fs::symlink("/dev/zero", &settings).unwrap();
    let output = run(ekb(dir.path()).arg("check").arg(&kb));
    assert_refused(&output, NOT_REGULAR);
    fs::remove_file(&settings).unwrap();
    fs::File::create(&settings)
        .unwrap()
        .set_len(2 << 20)
        .unwrap();
    let output = run(ekb(dir.path()).arg("check").arg(&kb));
    assert_refused(&output, "it is larger than 1 MiB");
}

/// A project `robot/` with `config/kb.ini` naming `knowledge_base`, beside a folder
/// `outside/` with a file to fix; returns the temporary root, the configuration and the
/// outside file.
fn project(knowledge_base: &str) -> (tempfile::TempDir, PathBuf, PathBuf) {
    let root = tempfile::tempdir().unwrap();
    let robot = root.path().join("robot");
    fs::create_dir_all(robot.join("config")).unwrap();
    fs::create_dir_all(robot.join("data")).unwrap();
    fs::create_dir_all(root.path().join("outside")).unwrap();
    fs::write(robot.join("data/kb.dat"), UNFIXED).unwrap();
    let outside = root.path().join("outside/kb.dat");
    fs::write(&outside, UNFIXED).unwrap();
    let config = robot.join("config/kb.ini");
    fs::write(&config, format!("knowledgeBase {knowledge_base}\n")).unwrap();
    (root, config, outside)
}

#[test]
fn verbose_says_where_the_knowledge_base_is() {
    let (root, config, outside) = project("../../outside/kb.dat");
    let real_root = fs::canonicalize(root.path()).unwrap();
    let output = run(ekb(root.path())
        .arg("--config")
        .arg(&config)
        .args(["-v", "check"]));
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let expected = format!(
        "ekb: the knowledgeBase of configuration {} is {}, outside its project folder {}\n",
        config.display(),
        real_root.join("outside/kb.dat").display(),
        real_root.join("robot").display()
    );
    assert!(
        stderr(&output).starts_with(&expected),
        "{}",
        stderr(&output)
    );
    assert_eq!(fs::read_to_string(&outside).unwrap(), UNFIXED);

    // Inside: where it is, no more.
    let (root, config, _) = project("kb.dat");
    let real_root = fs::canonicalize(root.path()).unwrap();
    let output = run(ekb(root.path())
        .arg("--config")
        .arg(&config)
        .args(["-v", "check"]));
    let expected = format!(
        "ekb: the knowledgeBase of configuration {} is {}\n",
        config.display(),
        real_root.join("robot/data/kb.dat").display()
    );
    assert!(
        stderr(&output).starts_with(&expected),
        "{}",
        stderr(&output)
    );

    // Into /proc: told, with where the `..` lead.
    let (root, config, _) = project("../../../../../../../../../../proc/self/environ");
    let output = run(ekb(root.path())
        .arg("--config")
        .arg(&config)
        .args(["-v", "check"]));
    let first = stderr(&output)
        .lines()
        .next()
        .unwrap_or_default()
        .to_string();
    assert!(first.contains(" is /proc/"), "{first}");
    assert!(
        first.contains("/environ, outside its project folder "),
        "{first}"
    );
}

#[test]
fn fix_and_fmt_rewrite_a_configured_file_outside_the_project_only_when_named() {
    for command in ["fix", "fmt"] {
        let (root, config, outside) = project("../../outside/kb.dat");
        let output = run(ekb(root.path()).arg("--config").arg(&config).arg(command));
        assert_refused(&output, "outside the configuration's project folder");
        assert!(stderr(&output).contains("only when you name it on the command line"));
        assert_eq!(fs::read_to_string(&outside).unwrap(), UNFIXED, "{command}");
        // Named: the user means it.
        let output = run(ekb(root.path())
            .arg("--config")
            .arg(&config)
            .arg(command)
            .arg(&outside));
        assert!(output.status.code() != Some(2), "{}", stderr(&output));
        assert_ne!(fs::read_to_string(&outside).unwrap(), UNFIXED, "{command}");
    }
    // Inside the project, the configured file is rewritten without being named.
    let (root, config, _) = project("kb.dat");
    let output = run(ekb(root.path()).arg("--config").arg(&config).arg("fix"));
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let inside = root.path().join("robot/data/kb.dat");
    assert_eq!(fs::read_to_string(inside).unwrap(), FIXED);
}
