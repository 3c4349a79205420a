//! Parse (build the model) and check generated knowledge bases of 1k, 10k and 100k
//! locations, ids ascending. `cargo bench --bench check`; see BENCHMARKS.md for the figures.

mod common;

use criterion::{criterion_group, criterion_main, Criterion};
use ekb::check::check;
use ekb::diagnostic::Diagnostics;
use ekb::model::build::{build, Options};
use ekb::SourceFile;

fn bench(c: &mut Criterion) {
    common::group(c, "parse", parse, false);
    common::group(c, "check", run_check, false);
}

/// Reads the file into the model, with the line rules that run while it is read.
fn parse(source: &SourceFile, options: &Options) -> usize {
    let mut diagnostics = Diagnostics::default();
    let kb = build(source.text(), options, &mut diagnostics);
    kb.locations().len() + diagnostics.len()
}

/// The whole check: the model, every rule, the findings sorted.
fn run_check(source: &SourceFile, options: &Options) -> usize {
    check(source, options).diagnostics.len()
}

criterion_group!(benches, bench);
criterion_main!(benches);
