//! `ekb rules`: the rule catalogue.

use std::io::Write;

use comfy_table::{presets, ContentArrangement, Table};

use super::{CommandResult, Context, Exit};
use crate::rules::{self, Rule};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Print the catalogue as a Markdown table (as in docs/rules.md)
    #[arg(long)]
    pub markdown: bool,
}

pub fn run(args: &Args, _context: &Context) -> CommandResult {
    let text = if args.markdown {
        markdown_table(rules::ALL)
    } else {
        terminal_table(rules::ALL)
    };
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(text.as_bytes())?;
    Ok(Exit::Clean)
}

/// The catalogue as `docs/rules.md` shows it, one table per category.
pub fn markdown_table(all: &[&Rule]) -> String {
    let mut out = String::new();
    let mut category = None;
    for rule in all {
        if category != Some(rule.category) {
            category = Some(rule.category);
            out.push_str(&format!(
                "\n{}\n\n| rule | severity | fix | when |\n|---|---|---|---|\n",
                rule.category.title()
            ));
        }
        out.push_str(&format!(
            "| `{}` | {} | {} | {} |\n",
            rule.name,
            rule.severity.name(),
            if rule.fixable { "yes" } else { "" },
            rule.summary
        ));
    }
    out
}

fn terminal_table(all: &[&Rule]) -> String {
    let mut table = Table::new();
    table
        .load_preset(presets::UTF8_BORDERS_ONLY)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_header(["rule", "category", "severity", "fix", "when"]);
    for rule in all {
        table.add_row([
            rule.name,
            rule.category.title(),
            rule.severity.name(),
            if rule.fixable { "yes" } else { "" },
            rule.summary,
        ]);
    }
    format!("{table}\n")
}
