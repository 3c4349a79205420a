//! `ekb tour` (not implemented yet).

use super::{CommandError, CommandResult, Context};

#[derive(Debug, clap::Args)]
pub struct Args {}

pub fn run(_args: &Args, _context: &Context) -> CommandResult {
    Err(CommandError("`ekb tour` is not implemented yet".into()))
}
