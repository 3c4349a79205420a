//! `ekb man`: the man page, generated from the same CLI definition as `--help`.

use std::io::Write;

use clap::CommandFactory;

use super::{CommandResult, Context, Exit};
use crate::cli::Cli;

#[derive(Debug, clap::Args)]
pub struct Args {}

pub fn run(_args: &Args, _context: &Context) -> CommandResult {
    let mut page = Vec::new();
    clap_mangen::Man::new(Cli::command()).render(&mut page)?;
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(&page)?;
    Ok(Exit::Clean)
}
