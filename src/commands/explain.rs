//! `ekb explain RULE`: one rule's documentation.

use std::io::Write;

use super::{CommandError, CommandResult, Context, Exit};
use crate::rules;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The rule's name in any case, or the start of it, e.g. `key-case`, `untranslated` (see `ekb rules`)
    #[arg(value_name = "RULE")]
    pub rule: String,
}

pub fn run(args: &Args, _context: &Context) -> CommandResult {
    let rule = rules::lookup(&args.rule).map_err(CommandError::Failed)?;
    let fix = if rule.fixable {
        "Fix: `ekb fix` repairs it."
    } else if rule.doc.contains("## Fix (unsafe)") {
        "Fix: only a guess, applied by `ekb fix --unsafe-fixes` (see below)."
    } else {
        "Fix: none automatic; edit the file."
    };
    let mut stdout = std::io::stdout().lock();
    writeln!(
        stdout,
        "# {} ({}, {})\n\n{}\n\n{}\n",
        rule.name,
        rule.severity.name(),
        rule.category.title(),
        rule.summary,
        fix
    )?;
    stdout.write_all(rule.markdown().as_bytes())?;
    Ok(Exit::Clean)
}
