//! `--format github`: GitHub Actions workflow commands, which show as annotations on a
//! pull request (`::error file=…,line=…::message`).

use std::io::{self, Write};

use super::escape::escape;
use super::FileReport;
use crate::diagnostic::Severity;

pub fn render(reports: &[FileReport<'_>], out: &mut dyn Write) -> io::Result<()> {
    for diagnostic in reports.iter().flat_map(|report| &report.diagnostics) {
        let command = match diagnostic.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "notice",
        };
        let region = diagnostic.region;
        writeln!(
            out,
            "::{command} file={},line={},col={},endLine={},endColumn={},title={}::{}",
            escape_property(diagnostic.file),
            region.line,
            region.column,
            region.end_line,
            region.end_column,
            escape_property(&format!("ekb {}", diagnostic.rule)),
            escape_data(diagnostic.message)
        )?;
    }
    Ok(())
}

/// The Actions toolkit's escaping of a command's message.
/// Other control characters are then made visible, as everywhere else.
fn escape_data(text: &str) -> String {
    let escaped = text
        .replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A");
    escape(&escaped).into_owned()
}

/// The Actions toolkit's escaping of a command's property values.
fn escape_property(text: &str) -> String {
    escape_data(text).replace(':', "%3A").replace(',', "%2C")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toolkit_escaping() {
        assert_eq!(escape_data("50% done\r\nnext"), "50%25 done%0D%0Anext");
        assert_eq!(escape_property("a:b,c%"), "a%3Ab%2Cc%25");
    }
}
