//! `ekb explain RULE`: one rule's documentation.

use std::io::Write;

use super::{CommandError, CommandResult, Context, Exit};
use crate::rules;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The rule's name, e.g. `key-case` (see `ekb rules`)
    #[arg(value_name = "RULE")]
    pub rule: String,
}

pub fn run(args: &Args, _context: &Context) -> CommandResult {
    let Some(rule) = rules::by_name(&args.rule) else {
        let nearest = rules::ALL
            .iter()
            .map(|rule| (strsim::levenshtein(rule.name, &args.rule), rule.name))
            .min()
            .filter(|&(distance, _)| distance <= 4)
            .map(|(_, name)| format!("; did you mean `{name}`?"))
            .unwrap_or_else(|| "; `ekb rules` lists them".to_string());
        return Err(CommandError::Failed(format!(
            "no rule named `{}`{nearest}",
            args.rule
        )));
    };
    let fix = if rule.fixable {
        "Fix: `ekb fix` repairs it."
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
