//! `ekb lsp` end to end: the real binary, spoken to in JSON-RPC over its standard input and
//! output, as an editor speaks to it.

mod client;
mod features;
#[path = "../support/generate.rs"]
mod generate;
mod robustness;
