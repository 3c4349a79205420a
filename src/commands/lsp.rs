//! `ekb lsp`: the language server, on standard input and output (see [`crate::lsp`]).

use super::{CommandResult, Context, Exit};
use crate::lsp::{self, transport::Transport, Ending};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Talk over standard input and output: what the server always does (editors' clients
    /// pass this flag)
    #[arg(long)]
    pub stdio: bool,
}

/// Exits 0 after `shutdown` and `exit`, 1 when the client exits or goes away without
/// `shutdown` (as the protocol asks).
pub fn run(_args: &Args, context: &Context) -> CommandResult {
    match lsp::run(Transport::stdio(), context)? {
        Ending::Clean => Ok(Exit::Clean),
        Ending::Abrupt => Ok(Exit::Findings),
    }
}
