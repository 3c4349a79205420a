//! `ekb-generate N [--dialect seed|current] [--shuffle] [--seed S]`: print a valid knowledge
//! base of N locations (about 600 bytes each) on standard output, for benchmarks:
//! `cargo run --release --example ekb-generate -- 10000 > kb.dat`.

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use ekb::model::Dialect;
use generate::{generate, Spec};

#[path = "../tests/support/generate.rs"]
mod generate;

/// Print a valid synthetic knowledge base of N locations.
#[derive(Debug, Parser)]
#[command(name = "ekb-generate", version)]
struct Args {
    /// Number of locations
    locations: usize,
    /// Dialect of the file
    #[arg(long, value_parser = ekb::commands::named_values::dialect(), default_value = "seed")]
    dialect: Dialect,
    /// Write the locations in random order instead of by ascending id
    #[arg(long)]
    shuffle: bool,
    /// Seed of the pseudo-random choices
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let spec = Spec {
        locations: args.locations,
        dialect: args.dialect,
        shuffle: args.shuffle,
        seed: args.seed,
    };
    let text = generate(&spec);
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("ekb-generate: error: cannot write: {error}");
            ExitCode::from(2)
        }
    }
}
