//! `ekb-core`: what loading and checking a knowledge base needs, and nothing more. The C
//! ABI and the Python module link this crate alone; the command line, the language server,
//! the drawings and the reports (the `ekb` crate) are faces over it.
//!
//! The layers, from the bytes up (ARCHITECTURE.md's code map numbers them, and a test
//! keeps every import pointing down it):
//! - [`source`]: a file read from disk (always valid UTF-8 text, invalid bytes recorded;
//!   UTF-16 and UTF-32, which [`encoding`] recognises, refused);
//! - [`syntax`]: the lossless line syntax, every byte in a span, and the syntax of
//!   suppression comments;
//! - [`robot`]: the robot's reader as fixed facts: its versions and buffers, the keys it
//!   reads, how its `sscanf` reads a word or a number;
//! - [`model`]: the typed knowledge base, as written; its builder reports what is wrong
//!   with a line as facts, through a trait the rules implement, and names no rule;
//! - [`reader`]: what each version of the robot's reader loads from a file;
//! - [`diagnostic`]: a finding, its rule, and where the rules report them;
//! - [`rules`]: the rule catalogue, one module per rule; [`mod@check`]: the whole check of a
//!   file, the model built and every rule run (or those [`rules::selection`] chooses), less
//!   what the file's suppression comments silence ([`check::suppression`]);
//! - [`config`] (the robot's INI) and [`settings`] (`ekb.toml`): where the file is and how
//!   to check it; [`map`] the lab map and [`mission`] the mission's files, for their rules;
//! - [`render`]: what every face shows of a file the same way: escaped text, clipped
//!   values, findings located by line and column; [`present::language`]: the languages'
//!   names and codes;
//! - [`loader`]: the front door for programs that embed `ekb` (the C ABI, C++ and Python):
//!   a knowledge base loaded as `ekb export` shows it, or refused with `ekb check`'s findings;
//! - [`streams`]: standard output and error, written without a panic.

// Output goes through `streams`, which never panics on a closed stream.
#![deny(clippy::print_stdout, clippy::print_stderr)]

pub mod check;
pub mod config;
pub mod diagnostic;
pub mod encoding;
pub mod loader;
pub mod map;
pub mod mission;
pub mod model;
pub mod open;
pub mod present;
pub mod reader;
pub mod render;
pub mod robot;
pub mod rules;
pub mod settings;
pub mod source;
pub mod streams;
pub mod syntax;
#[doc(hidden)]
pub mod testing;

pub use check::{check, Checked};
pub use diagnostic::{Diagnostic, Severity};
pub use model::KnowledgeBase;
pub use source::SourceFile;
