//! `ekb fmt` (lay the file out canonically: `Document::parse`, then `render`) and `ekb fix`
//! (check, apply the fixes, check again until nothing is left) on generated knowledge bases
//! of 1k, 10k and 100k locations, in memory. `cargo bench --bench rewrite`.
//!
//! The files are generated with shuffled ids, so that fmt has blocks to regroup and keys to
//! reorder, and fix has nothing to do but check (a valid file: one pass).

use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ekb::canonical::Document;
use ekb::fixing::fix;
use ekb::generate::{generate, Spec};
use ekb::model::build::Options;
use ekb::SourceFile;

const SIZES: [usize; 3] = [1_000, 10_000, 100_000];

fn bench(c: &mut Criterion) {
    let options = Options::default();
    for (name, work) in [
        ("fmt", fmt as fn(&SourceFile, &Options) -> usize),
        ("fix", run_fix),
    ] {
        let mut group = c.benchmark_group(name);
        for locations in SIZES {
            let spec = Spec {
                shuffle: true,
                ..Spec::new(locations)
            };
            let source = SourceFile::from_bytes("bench", generate(&spec).into_bytes());
            group.throughput(Throughput::Bytes(source.text().len() as u64));
            if locations >= 100_000 {
                // A run takes a good fraction of a second: ten of them are enough.
                group
                    .sample_size(10)
                    .measurement_time(Duration::from_secs(10));
            } else {
                group
                    .sample_size(20)
                    .measurement_time(Duration::from_secs(5));
            }
            group.bench_with_input(
                BenchmarkId::from_parameter(locations),
                &source,
                |b, source| b.iter(|| work(source, &options)),
            );
        }
        group.finish();
    }
}

/// What `ekb fmt` computes: the canonical text (and that reading it back gives the same
/// document, which the command checks before writing).
fn fmt(source: &SourceFile, _: &Options) -> usize {
    let document = Document::parse(source.text()).expect("a generated file is formattable");
    let text = document.render();
    assert!(Document::parse(&text).as_ref() == Ok(&document));
    text.len()
}

/// What `ekb fix` computes: the fixed text.
fn run_fix(source: &SourceFile, options: &Options) -> usize {
    fix(source, options).text.len()
}

criterion_group!(benches, bench);
criterion_main!(benches);
