//! The generator of synthetic knowledge bases (`tests/support/generate.rs`, a development
//! tool shared by the tests, the benchmarks and the `ekb-generate` example) writes files
//! that `ekb check` accepts: no error, no warning.

#[path = "support/generate.rs"]
mod generate;

use assert_cmd::Command;
use ekb::check::check;
use ekb::model::build::Options;
use ekb::model::Dialect;
use ekb::robot::Reader;
use ekb::SourceFile;
use generate::{generate, Spec};
use predicates::prelude::*;

#[test]
fn generated_files_pass_ekb_check() {
    // The current dialect's gestureArm is read by reader 2026-03 only.
    for (spec, reader) in [
        (Spec::new(25), "d5.4.2"),
        (
            Spec {
                dialect: Dialect::Current,
                shuffle: true,
                seed: 3,
                ..Spec::new(40)
            },
            "2026-03",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        Command::cargo_bin("ekb")
            .unwrap()
            .current_dir(dir.path())
            .env_remove("EKB_CONFIG")
            .env_remove("EKB_READER")
            .args(["check", "--reader", reader, "--format", "concise", "-"])
            .write_stdin(generate(&spec))
            .assert()
            .code(0)
            .stdout(predicate::str::contains("error").not())
            .stdout(predicate::str::contains("warning").not())
            .stdout(predicate::str::contains("info[unused-location]"));
    }
}

/// The findings on a generated file, checked against the reader that reads all of it
/// (the current dialect's `gestureArm` is read by `2026-03` only).
fn findings(spec: &Spec) -> Vec<&'static str> {
    let source = SourceFile::from_bytes("generated", generate(spec).into_bytes());
    let reader = match spec.dialect {
        Dialect::Seed => Reader::D542,
        Dialect::Current => Reader::V2026_03,
    };
    let options = Options {
        reader: Some(reader),
        ..Options::default()
    };
    let checked = check(&source, &options);
    checked
        .diagnostics
        .iter()
        .map(|d| d.rule.name)
        .filter(|&rule| rule != "unused-location")
        .collect()
}

#[test]
fn generated_files_are_clean_in_both_dialects_and_orders() {
    for dialect in [Dialect::Seed, Dialect::Current] {
        for shuffle in [false, true] {
            for (locations, seed) in [(1, 0), (5, 7), (20, 1), (300, 42)] {
                let spec = Spec {
                    locations,
                    dialect,
                    shuffle,
                    seed,
                };
                assert_eq!(findings(&spec), Vec::<&str>::new(), "{spec:?}");
            }
        }
    }
}

#[test]
fn the_dialect_is_detected_and_every_location_is_complete() {
    for dialect in [Dialect::Seed, Dialect::Current] {
        let spec = Spec {
            dialect,
            shuffle: true,
            ..Spec::new(50)
        };
        let source = SourceFile::from_bytes("generated", generate(&spec).into_bytes());
        let checked = check(&source, &Options::default());
        assert_eq!(checked.kb.dialect, Some(dialect));
        assert_eq!(checked.kb.locations().len(), 50);
        assert_eq!(checked.kb.tour_stops().count(), 20);
    }
}

#[test]
fn deterministic_and_about_600_bytes_per_location() {
    let spec = Spec {
        shuffle: true,
        ..Spec::new(1000)
    };
    let text = generate(&spec);
    assert_eq!(text, generate(&spec));
    assert_ne!(text, generate(&Spec { seed: 2, ..spec }));
    let per_location = text.len() / 1000;
    assert!((520..=680).contains(&per_location), "{per_location}");
}

#[test]
fn no_location_means_an_empty_file() {
    assert_eq!(generate(&Spec::new(0)), "");
}
