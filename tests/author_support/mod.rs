//! Shared by the `fix`, `fmt` and `import` tests: running `ekb`, temporary copies of
//! fixtures, and the export of a model.

#![allow(dead_code)] // each test crate uses a part

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use ekb::model::export::ExportedKnowledgeBase;
use ekb::model::KnowledgeBase;

/// `ekb` with no configuration from the environment.
pub fn ekb() -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .env("NO_COLOR", "1");
    command
}

pub fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/author")
        .join(name)
}

pub fn read_fixture(name: &str) -> String {
    std::fs::read_to_string(fixture(name)).unwrap()
}

/// The culture knowledge base of the robot's repository: a different kind of file.
pub fn culture_knowledge_base() -> Vec<u8> {
    std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/corpus/upstream-2025-06-cultureKnowledgeBaseInput.dat"),
    )
    .unwrap()
}

/// The seed file of the repository.
pub fn seed() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("data/environmentKnowledgeBaseInput.dat"),
    )
    .unwrap()
}

/// A temporary folder holding `name` with `contents`; returns the folder (keep it alive) and
/// the file's path.
pub fn temp_file(name: &str, contents: &[u8]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, contents).unwrap();
    (dir, path)
}

/// Whether this process ignores file permissions (root does): read-only tests are moot then.
pub fn permissions_are_ignored() -> bool {
    let (_dir, path) = temp_file("probe", b"x");
    let mut permissions = std::fs::metadata(&path).unwrap().permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&path, permissions).unwrap();
    std::fs::OpenOptions::new().write(true).open(&path).is_ok()
}

/// The model as export JSON (SPEC §5), as `ekb export` converts it.
pub fn export(kb: &KnowledgeBase<'_>) -> ExportedKnowledgeBase {
    ExportedKnowledgeBase::from(kb)
}

/// The export JSON of a file's text, read as `ekb` reads it, its locations by id: the
/// knowledge base, whatever order `ekb fmt` gives its blocks (the export keeps the file's).
pub fn export_text(text: &str) -> ExportedKnowledgeBase {
    let source = ekb::SourceFile::from_bytes("t", text.as_bytes().to_vec());
    let checked = ekb::check(&source, &Default::default());
    let mut exported = export(&checked.kb);
    exported.locations.sort_by_key(|location| location.id);
    exported
}

/// `ekb SUBCOMMAND kb.dat` on a read-only file: exit 2, a clear message, the file intact,
/// even as root (whom the permission bits do not stop: `ekb` looks at them itself).
pub fn assert_read_only_file_left_intact(subcommand: &str) {
    let (_dir, path) = temp_file("kb.dat", seed().as_bytes());
    let mut permissions = std::fs::metadata(&path).unwrap().permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&path, permissions).unwrap();
    ekb()
        .arg(subcommand)
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicates::str::contains("it is read-only"))
        .stderr(predicates::str::contains("it is left unchanged"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), seed());
}
