//! `ekb locations` (not implemented yet).

use super::{CommandError, CommandResult, Context};

#[derive(Debug, clap::Args)]
pub struct Args {}

pub fn run(_args: &Args, _context: &Context) -> CommandResult {
    Err(CommandError(
        "`ekb locations` is not implemented yet".into(),
    ))
}
