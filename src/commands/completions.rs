//! `ekb completions SHELL`: a shell completion script (the same scripts are kept in
//! `completions/`, and a test fails when they are stale).

use std::io::Write;

use clap_complete::Shell;

use super::{CommandResult, Exit};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The shell to complete for
    #[arg(value_enum)]
    pub shell: Shell,
}

/// Prints the script of `cli`, the whole command line.
pub fn run(args: &Args, cli: clap::Command) -> CommandResult {
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(&script(args.shell, cli))?;
    Ok(Exit::Clean)
}

/// The completion script for `shell`.
pub fn script(shell: Shell, mut cli: clap::Command) -> Vec<u8> {
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut cli, "ekb", &mut out);
    out
}

/// The file name each shell's script is kept under in `completions/`.
pub fn file_name(shell: Shell) -> String {
    match shell {
        Shell::Zsh => "_ekb".to_string(),
        Shell::PowerShell => "_ekb.ps1".to_string(),
        Shell::Elvish => "ekb.elv".to_string(),
        other => format!("ekb.{other}"),
    }
}
