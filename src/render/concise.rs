//! `--format concise`: `file:line:col: severity[rule] message`, one finding per line.

use std::io::{self, Write};

use super::escape::escape;
use super::{FileReport, RenderOptions};
use crate::check::Summary;

pub fn render(
    reports: &[FileReport<'_>],
    summary: &Summary,
    out: &mut dyn Write,
    options: &RenderOptions,
) -> io::Result<()> {
    for diagnostic in reports.iter().flat_map(|report| &report.diagnostics) {
        writeln!(
            out,
            "{}:{}:{}: {}[{}] {}",
            escape(diagnostic.file),
            diagnostic.region.line,
            diagnostic.region.column,
            diagnostic.severity.name(),
            diagnostic.rule,
            escape(diagnostic.message)
        )?;
    }
    if !options.quiet {
        writeln!(
            out,
            "{}{}",
            summary.sentence(),
            super::reader_note(reports, false)
        )?;
    }
    Ok(())
}
