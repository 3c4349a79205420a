//! `ekb`: author and validate the environment knowledge base of a tour-guide robot.
//!
//! The layers up to the loader's front door are the core's (`ekb-core`, which the C ABI and
//! the Python module link alone), re-exported here at the same paths; the renderers, the
//! rewriting commands, the language server and the command line are this crate's.
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
//! - [`render`]: output formats for findings;
//! - [`present`]: how `locations`, `show`, `tour` and `diff` show a knowledge base;
//! - [`diff`]: the semantic difference of two knowledge bases;
//! - [`canonical`]: the canonical layout that `fmt` and `import` write; [`fixing`]: `fix`;
//!   [`commands::rewrite`] and [`mod@write`]: how both show and safely write their result;
//! - [`config`] (the robot's INI) and [`settings`] (`ekb.toml`): where the file is and how
//!   to check it;
//! - [`loader`]: the front door for programs that embed `ekb` (the C ABI, C++ and Python):
//!   a knowledge base loaded as `ekb export` shows it, or refused with `ekb check`'s findings;
//! - [`context`]: what the command line and the language server share; [`lsp`]: `ekb lsp`,
//!   the language server, whose handlers ask the layers below; [`commands`]: one module per
//!   command; [`cli`]: the `ekb` command line; [`streams`]: standard output and error,
//!   written without a panic.

// Output goes through `streams`, which never panics on a closed stream.
#![deny(clippy::print_stdout, clippy::print_stderr)]

pub mod canonical;
pub mod cli;
pub mod commands;
pub mod context;
pub mod diff;
pub mod draw;
pub mod edit;
pub mod fixing;
pub mod lsp;
pub mod present;
pub mod render;
pub mod report;
pub mod serve;
pub mod translations;
pub mod write;

// The core's layers, at the paths they have always had here.
pub use ekb_core::{
    check, config, diagnostic, encoding, loader, map, mission, model, open, reader, robot, rules,
    settings, source, stderr_line, streams, syntax,
};
pub use ekb_core::{Checked, Diagnostic, KnowledgeBase, Severity, SourceFile};
