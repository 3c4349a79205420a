//! The fuzz target's invariants, checked on every `cargo test` with a bounded number of
//! cases: on arbitrary bytes and on random mutations of the seed file, `check` never
//! panics, every span it reports is in bounds and on character boundaries, and every
//! output format renders. The inputs the fuzzer once broke on are replayed from
//! `tests/fixtures/fuzz/`. (fmt and fix join these invariants once they exist; see the
//! TODO in BENCHMARKS.md.)

use ekb::check::check;
use ekb::model::build::Options;
use ekb::render::{self, Format, RenderOptions};
use ekb::syntax::Span;
use ekb::SourceFile;
use proptest::prelude::*;

const SEED_FILE: &[u8] = include_bytes!("../data/environmentKnowledgeBaseInput.dat");

fn assert_valid(span: Span, text: &str, what: &str) {
    assert!(span.start <= span.end, "{what}: reversed span {span:?}");
    assert!(
        span.end as usize <= text.len(),
        "{what}: {span:?} out of bounds"
    );
    assert!(
        text.is_char_boundary(span.start as usize) && text.is_char_boundary(span.end as usize),
        "{what}: {span:?} splits a character"
    );
}

/// Everything the fuzz target asserts (fuzz/fuzz_targets/check.rs).
fn survives(bytes: &[u8]) {
    let source = SourceFile::from_bytes("input", bytes.to_vec());
    let text = source.text();
    assert_eq!(text.len(), bytes.len());
    let checked = check(&source, &Options::default());
    for diagnostic in checked.diagnostics.iter().chain(&checked.omitted) {
        let rule = diagnostic.rule.name;
        assert_valid(diagnostic.span, text, rule);
        for label in &diagnostic.labels {
            assert_valid(label.span, text, rule);
        }
        for edit in diagnostic.fix.iter().flat_map(|fix| &fix.edits) {
            assert_valid(edit.span, text, rule);
        }
    }
    let summary = checked.summary();
    for format in [Format::Concise, Format::Json, Format::Github] {
        let mut out = Vec::new();
        render::render(
            format,
            std::slice::from_ref(&checked),
            &summary,
            &mut out,
            &RenderOptions::default(),
        )
        .unwrap();
        assert!(
            String::from_utf8(out).is_ok(),
            "{format:?} wrote invalid UTF-8"
        );
    }
}

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

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes(bytes in prop::collection::vec(any::<u8>(), 0..2048)) {
        survives(&bytes);
    }

    #[test]
    fn mutations_of_the_seed_file(mutations in prop::collection::vec(mutation(), 1..12)) {
        survives(&apply(SEED_FILE.to_vec(), &mutations));
    }
}

#[test]
fn the_seed_file_itself() {
    survives(SEED_FILE);
}

/// Inputs the fuzzer found (see BENCHMARKS.md, "Fuzzing"), kept so they stay fixed.
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
