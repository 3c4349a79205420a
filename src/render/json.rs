//! `--format json`: one JSON object with every finding and a summary (SPEC §5).

use std::io::{self, Write};

use serde::Serialize;

use super::{FileReport, LocatedDiagnostic};
use crate::diagnostic::Summary;

#[derive(Serialize)]
struct Output<'a> {
    diagnostics: Vec<&'a LocatedDiagnostic<'a>>,
    summary: &'a Summary,
}

pub fn render(
    reports: &[FileReport<'_>],
    summary: &Summary,
    out: &mut dyn Write,
) -> io::Result<()> {
    let output = Output {
        diagnostics: reports.iter().flat_map(|r| &r.diagnostics).collect(),
        summary,
    };
    super::safe_json::write(&output, out)
}
