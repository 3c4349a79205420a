//! What the benches share: one criterion group per piece of work, over generated knowledge
//! bases of 1k, 10k and 100k locations.

use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput};
use generate::{generate, Spec};

#[path = "../../tests/support/generate.rs"]
mod generate;
use ekb::model::build::Options;
use ekb::SourceFile;

const SIZES: [usize; 3] = [1_000, 10_000, 100_000];

/// The work measured: it returns a number so that the optimiser cannot drop it.
pub type Work = fn(&SourceFile, &Options) -> usize;

/// A group `name` measuring `work` at every size, on files with ids `shuffle`d or ascending.
pub fn group(c: &mut Criterion, name: &str, work: Work, shuffle: bool) {
    let options = Options::default();
    let mut group = c.benchmark_group(name);
    for locations in SIZES {
        let spec = Spec {
            shuffle,
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
