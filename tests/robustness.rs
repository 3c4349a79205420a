//! The invariants of `tests/invariants/` (the fuzz target's), checked on every `cargo test`
//! with a bounded number of cases: on arbitrary bytes and on random mutations of the seed
//! file, `check` never panics and reports valid spans, every output format renders, `fmt`
//! and `fix` are idempotent, `fmt` keeps the model, and a valid file's export imports to the
//! same model. The inputs the fuzzer once broke on are replayed from `tests/fixtures/fuzz/`.

#[path = "support/generate.rs"]
mod generate;
mod invariants;

use ekb::check::check;
use ekb::model::build::Options;
use ekb::model::Dialect;
use ekb::SourceFile;
use generate::{generate, Spec};
use invariants::survives;
use proptest::prelude::*;

const SEED_FILE: &[u8] = include_bytes!("../data/environmentKnowledgeBaseInput.dat");

/// One edit of a file: what fuzzers and careless pastes do.
#[derive(Debug, Clone)]
enum Mutation {
    Insert(usize, Vec<u8>),
    Delete(usize, usize),
    Replace(usize, u8),
    DuplicateLine(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let interesting = prop_oneof![
        Just(b"\n".to_vec()),
        Just(b"\r\n".to_vec()),
        Just(b"\xef\xbb\xbf".to_vec()),
        Just(b"\xff".to_vec()),
        Just(b"\xc3".to_vec()),
        Just(b"\0".to_vec()),
        Just(" \u{202E}é\t".as_bytes().to_vec()),
        Just(b"-".to_vec()),
        Just(b"99999999999".to_vec()),
        Just(b"nan".to_vec()),
        Just(b"tourSpecification 3 1, 2,,9\n".to_vec()),
        Just(b"#".to_vec()),
        prop::collection::vec(any::<u8>(), 1..8),
    ];
    prop_oneof![
        (any::<usize>(), interesting).prop_map(|(at, bytes)| Mutation::Insert(at, bytes)),
        (any::<usize>(), 1usize..40).prop_map(|(at, len)| Mutation::Delete(at, len)),
        (any::<usize>(), any::<u8>()).prop_map(|(at, byte)| Mutation::Replace(at, byte)),
        any::<usize>().prop_map(Mutation::DuplicateLine),
    ]
}

fn apply(mut bytes: Vec<u8>, mutations: &[Mutation]) -> Vec<u8> {
    for mutation in mutations {
        let len = bytes.len().max(1);
        match mutation {
            Mutation::Insert(at, new) => {
                let at = at % (bytes.len() + 1);
                bytes.splice(at..at, new.iter().copied());
            }
            Mutation::Delete(at, count) => {
                let at = at % len;
                let end = (at + count).min(bytes.len());
                bytes.drain(at.min(end)..end);
            }
            Mutation::Replace(at, byte) => {
                if !bytes.is_empty() {
                    bytes[at % len] = *byte;
                }
            }
            Mutation::DuplicateLine(at) => {
                let at = at % len;
                let start = bytes[..at.min(bytes.len())]
                    .iter()
                    .rposition(|&b| b == b'\n')
                    .map_or(0, |i| i + 1);
                let end = bytes[start..]
                    .iter()
                    .position(|&b| b == b'\n')
                    .map_or(bytes.len(), |i| start + i + 1);
                let line = bytes[start..end].to_vec();
                bytes.splice(end..end, line);
            }
        }
    }
    bytes
}

/// A valid file (no errors) of a few locations in the current dialect, for mutations that
/// keep it valid and so reach the export → import round trip.
fn valid_file() -> Vec<u8> {
    let spec = Spec {
        dialect: Dialect::Current,
        ..Spec::new(4)
    };
    generate(&spec).into_bytes()
}

proptest! {
    // 3 × 64 cases: a few seconds in a debug build (each case checks the input about ten
    // times: fmt twice, fix up to twenty passes, the models).
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes(bytes in prop::collection::vec(any::<u8>(), 0..2048)) {
        survives(&bytes);
    }

    #[test]
    fn mutations_of_the_seed_file(mutations in prop::collection::vec(mutation(), 1..12)) {
        survives(&apply(SEED_FILE.to_vec(), &mutations));
    }

    #[test]
    fn mutations_of_a_valid_file(mutations in prop::collection::vec(mutation(), 1..4)) {
        survives(&apply(valid_file(), &mutations));
    }
}

#[test]
fn the_seed_file_itself() {
    survives(SEED_FILE);
}

#[test]
fn a_valid_file_itself() {
    let file = valid_file();
    let source = SourceFile::from_bytes("valid", file.clone());
    assert!(!check(&source, &Options::default()).has_errors());
    survives(&file);
}

/// Inputs the fuzzer found (`fuzz/`, as BENCHMARKS.md says), kept so they stay fixed.
#[test]
fn fuzz_regressions() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/fuzz");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|ext| ext == "md") {
            continue;
        }
        survives(&std::fs::read(&path).unwrap());
        count += 1;
    }
    assert!(count > 0, "no fixtures in {}", dir.display());
}
