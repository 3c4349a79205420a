//! `ekb`: author and validate the environment knowledge base of a tour-guide robot.
//!
//! The layers, from the bytes up:
//! - [`source`]: a file read from disk (always valid UTF-8 text, invalid bytes recorded);
//! - [`syntax`]: the lossless line syntax, every byte in a span;
//! - [`model`]: the typed knowledge base, as the robot's reader would load it;
//! - [`rules`]: the rule catalogue, one module per rule;
//! - [`render`]: output formats for findings;
//! - [`generate`]: synthetic knowledge bases of any size, for benchmarks and tests;
//! - [`cli`]: the `ekb` command line, one module per command under `commands`.

pub mod check;
pub mod cli;
pub mod commands;
pub mod config;
pub mod diagnostic;
pub mod generate;
pub mod model;
pub mod render;
pub mod rules;
pub mod source;
pub mod syntax;

pub use check::{check, Checked};
pub use diagnostic::{Diagnostic, Severity};
pub use model::KnowledgeBase;
pub use source::SourceFile;
