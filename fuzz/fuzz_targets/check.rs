//! Arbitrary bytes through the whole `ekb check` pipeline: read, build the model, run every
//! rule, render every format. Asserts that nothing panics and that every span a finding
//! carries (its own, its labels', its fix's edits) is in bounds and on character
//! boundaries. TODO after merge: fmt and fix (idempotence), export → import round trip.
#![no_main]

use ekb::check::check;
use ekb::model::build::Options;
use ekb::render::{self, Format, RenderOptions};
use ekb::syntax::Span;
use ekb::SourceFile;
use libfuzzer_sys::fuzz_target;

fn assert_valid(span: Span, text: &str) {
    assert!(span.start <= span.end, "reversed span {span:?}");
    assert!(span.end as usize <= text.len(), "span {span:?} out of bounds");
    assert!(text.is_char_boundary(span.start as usize), "{span:?} splits a character");
    assert!(text.is_char_boundary(span.end as usize), "{span:?} splits a character");
}

fuzz_target!(|data: &[u8]| {
    let source = SourceFile::from_bytes("fuzz", data.to_vec());
    let text = source.text();
    assert_eq!(text.len(), data.len(), "text must keep byte offsets");
    let checked = check(&source, &Options::default());
    for diagnostic in checked.diagnostics.iter().chain(&checked.omitted) {
        assert_valid(diagnostic.span, text);
        for label in &diagnostic.labels {
            assert_valid(label.span, text);
        }
        for edit in diagnostic.fix.iter().flat_map(|fix| &fix.edits) {
            assert_valid(edit.span, text);
        }
    }
    let summary = checked.summary();
    for format in [Format::Concise, Format::Json, Format::Github] {
        let mut out = Vec::new();
        render::render(format, std::slice::from_ref(&checked), &summary, &mut out, &RenderOptions::default())
            .expect("writing to memory cannot fail");
    }
});
