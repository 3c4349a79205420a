//! `ekb fmt` (lay the file out canonically: `Document::parse`, then `render`) and `ekb fix`
//! (check, apply the fixes, check again until nothing is left) on generated knowledge bases
//! of 1k, 10k and 100k locations, in memory. `cargo bench --bench rewrite`.
//!
//! The files are generated with shuffled ids, so that fmt has blocks to regroup and keys to
//! reorder, and fix has nothing to do but check (a valid file: one pass).

mod common;

use criterion::{criterion_group, criterion_main, Criterion};
use ekb::canonical::Document;
use ekb::fixing::fix;
use ekb::model::build::Options;
use ekb::SourceFile;

fn bench(c: &mut Criterion) {
    common::group(c, "fmt", fmt, true);
    common::group(c, "fix", run_fix, true);
}

/// What `ekb fmt` computes: the canonical text (and that reading it back gives the same
/// document, which the command checks before writing).
fn fmt(source: &SourceFile, _: &Options) -> usize {
    let document = Document::parse(source.text()).expect("a generated file is formattable");
    let text = document.render();
    assert!(document.reads_back_from(&text));
    text.len()
}

/// What `ekb fix` computes: the fixed text.
fn run_fix(source: &SourceFile, options: &Options) -> usize {
    fix(source, options).text.len()
}

criterion_group!(benches, bench);
criterion_main!(benches);
