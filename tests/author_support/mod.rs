//! Shared by the `fix`, `fmt` and `import` tests: running `ekb`, temporary copies of
//! fixtures, and a model → export conversion of their own.
//!
//! The conversion stands in for `impl From<&KnowledgeBase> for ExportedKnowledgeBase`
//! (written on another branch for `ekb export`); once that lands, these tests can use it.

#![allow(dead_code)] // each test crate uses a part

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use ekb::model::export::{ExportedKnowledgeBase, ExportedLocation, ExportedMessages};
use ekb::model::{KnowledgeBase, Language, Location, Phase};

/// `ekb` with no configuration from the environment.
pub fn ekb() -> Command {
    let mut command = Command::cargo_bin("ekb").unwrap();
    command.env_remove("EKB_CONFIG").env("NO_COLOR", "1");
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

/// The model as export JSON (SPEC §5).
pub fn export(kb: &KnowledgeBase<'_>) -> ExportedKnowledgeBase {
    ExportedKnowledgeBase {
        dialect: kb.dialect,
        locations: kb.locations().iter().map(location).collect(),
        tour: kb
            .tour
            .as_ref()
            .map(|tour| tour.stops.iter().map(|stop| stop.value).collect()),
    }
}

fn location(location: &Location<'_>) -> ExportedLocation {
    let messages = |phase| {
        let text = |language| {
            location
                .message(phase, language)
                .map(|v| v.value.to_string())
        };
        ExportedMessages {
            english: text(Language::English),
            isi_zulu: text(Language::IsiZulu),
            kinyarwanda: text(Language::Kinyarwanda),
        }
    };
    ExportedLocation {
        id: location.id,
        description: location.description.map(|v| v.value.to_string()),
        pose: location.pose.map(|v| v.value),
        gesture_target: location.gesture_target.map(|v| v.value),
        gesture_arm: location.gesture_arm.map(|v| v.value),
        pre_gesture_message: messages(Phase::Pre),
        post_gesture_message: messages(Phase::Post),
        cultural_knowledge: location.cultural_words().map(String::from).collect(),
    }
}

/// The export JSON of a file's text, read as `ekb` reads it.
pub fn export_text(text: &str) -> ExportedKnowledgeBase {
    let source = ekb::SourceFile::from_bytes("t", text.as_bytes().to_vec());
    let checked = ekb::check(&source, &Default::default());
    export(&checked.kb)
}
