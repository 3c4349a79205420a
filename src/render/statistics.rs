//! `ekb check --statistics`: instead of the findings, one line per rule with its count and
//! whether `ekb fix` can fix it, the most frequent first (as `ruff check --statistics`):
//!
//! ```text
//! untranslated-message 20
//! key-case 1 (fixable)
//! ```
//!
//! `--format json` gives the same as a JSON array of `{rule, severity, count, fixable, unsafe_fixable}`.

use std::io::{self, Write};

use serde::Serialize;

use super::{Format, RenderOptions};
use crate::check::Summary;
use crate::diagnostic::Severity;

/// One rule's line.
#[derive(Debug, Serialize)]
struct RuleStatistics {
    rule: &'static str,
    /// The gravest severity among its findings.
    severity: Severity,
    count: usize,
    /// How many `ekb fix` can fix.
    fixable: usize,
    /// How many only `ekb fix --unsafe-fixes` can fix.
    unsafe_fixable: usize,
}

/// Writes the statistics of the rules with findings at or above `level`.
pub fn render(
    format: Format,
    summary: &Summary,
    level: Severity,
    out: &mut dyn Write,
    options: &RenderOptions,
) -> io::Result<()> {
    let mut rules: Vec<RuleStatistics> = Vec::new();
    for count in summary.by_rule.iter().filter(|c| c.severity <= level) {
        match rules.iter_mut().find(|r| r.rule == count.rule.name) {
            Some(known) => {
                known.count += count.count;
                known.fixable += count.fixable;
                known.unsafe_fixable += count.unsafe_fixable;
                known.severity = known.severity.min(count.severity);
            }
            None => rules.push(RuleStatistics {
                rule: count.rule.name,
                severity: count.severity,
                count: count.count,
                fixable: count.fixable,
                unsafe_fixable: count.unsafe_fixable,
            }),
        }
    }
    rules.sort_by(|a, b| b.count.cmp(&a.count).then(a.rule.cmp(b.rule)));
    if format == Format::Json {
        return super::safe_json::write(&rules, out);
    }
    for rule in &rules {
        let fixable = match (rule.fixable, rule.unsafe_fixable) {
            (0, 0) => "",
            (n, 0) if n == rule.count => " (fixable)",
            (0, n) if n == rule.count => " (unsafe fix available)",
            _ => " (some fixable)",
        };
        writeln!(out, "{} {}{fixable}", rule.rule, rule.count)?;
    }
    if !options.quiet {
        writeln!(out, "{}", summary.sentence())?;
    }
    Ok(())
}
