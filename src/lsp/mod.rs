//! `ekb lsp`: the language server (SPEC §9), on standard input and output.
//!
//! Built on `lsp-server`'s message types and `lsp-types`, with one synchronous main loop
//! ([`server`]). It has no logic of its own about knowledge bases: every feature asks the
//! library, through one handler module per kind of request ([`handlers`]).
//!
//! - [`transport`]: reading and writing framed JSON-RPC, answering malformed messages;
//! - [`server`]: the main loop, initialization, cancellation, shutdown;
//! - [`documents`]: the open documents, kept in step by incremental changes, each version
//!   checked once;
//! - [`position`]: LSP positions (UTF-16 by default, UTF-8 or UTF-32 when the client offers)
//!   and byte offsets;
//! - [`lines`]: what the cursor is on, and where each location's lines are;
//! - [`workspace`]: the configuration and `ekb.toml`, found as the command line finds them.

pub mod documents;
pub mod handlers;
pub mod lines;
pub mod position;
pub mod server;
pub mod transport;
pub mod workspace;

use crate::context::Context;
pub use server::Ending;
use transport::Transport;

/// Serves one client over `transport` until it says `exit` or goes away, and waits until
/// every answer is written.
pub fn run(transport: Transport, cli: &Context) -> std::io::Result<Ending> {
    let ending = server::serve(&transport.incoming, &transport.outgoing, cli);
    transport.finish()?;
    Ok(ending)
}
