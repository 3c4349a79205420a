//! Parse (build the model) and check generated knowledge bases of 1k, 10k and 100k
//! locations. `cargo bench --bench check`; see BENCHMARKS.md for the figures.
//! (fmt and fix are to be added here once they exist: see the TODO in BENCHMARKS.md.)

use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ekb::check::{check, Diagnostics};
use ekb::generate::{generate, Spec};
use ekb::model::build::{build, Options};
use ekb::SourceFile;

const SIZES: [usize; 3] = [1_000, 10_000, 100_000];

fn bench(c: &mut Criterion) {
    let options = Options::default();
    for (name, work) in [
        ("parse", parse as fn(&SourceFile, &Options) -> usize),
        ("check", run_check),
    ] {
        let mut group = c.benchmark_group(name);
        for locations in SIZES {
            let text = generate(&Spec::new(locations));
            let source = SourceFile::from_bytes("bench", text.into_bytes());
            group.throughput(Throughput::Bytes(source.text().len() as u64));
            if locations >= 100_000 {
                // A run takes a good fraction of a second: ten of them are enough.
                group
                    .sample_size(10)
                    .measurement_time(Duration::from_secs(8));
            } else {
                group
                    .sample_size(30)
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
