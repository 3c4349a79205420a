//! `ekb fmt` (lay the file out canonically: `Document::parse`, then `write_checked`) and `ekb fix`
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

/// What `ekb fmt` computes: the canonical text, each line checked to read back as it is
/// written (the command writes it to a file as it is made).
fn fmt(source: &SourceFile, _: &Options) -> usize {
    let document = Document::parse(source.text()).expect("a generated file is formattable");
    let mut text = Vec::new();
    document
        .write_checked(&mut text)
        .unwrap_or_else(|_| panic!("the layout reads back"));
    text.len()
}

/// What `ekb fix` computes: the fixed text.
fn run_fix(source: &SourceFile, options: &Options) -> usize {
    fix(source, options).text.len()
}

criterion_group!(benches, bench);
criterion_main!(benches);
