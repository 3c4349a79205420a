//! `--format json`: one JSON object with every finding and a summary (SPEC §5).

use std::collections::BTreeMap;
use std::io::{self, Write};

use serde::Serialize;

use super::{FileReport, LocatedDiagnostic};
use crate::check::Summary;

#[derive(Serialize)]
struct Output<'a> {
    diagnostics: Vec<&'a LocatedDiagnostic<'a>>,
    summary: &'a Summary,
    /// The version of the robot's reader every file was checked against; `null` when they
    /// were checked against different ones (then see `readers`).
    reader: Option<&'static str>,
    /// Each file's reader, by file name.
    readers: BTreeMap<&'a str, &'static str>,
}

pub fn render(
    reports: &[FileReport<'_>],
    summary: &Summary,
    out: &mut dyn Write,
) -> io::Result<()> {
    let readers: BTreeMap<&str, &str> = reports
        .iter()
        .filter(|r| r.read_by_reader())
        .map(|r| (r.checked.source.name(), r.checked.reader.name()))
        .collect();
    let mut names: Vec<&str> = readers.values().copied().collect();
    names.dedup();
    let output = Output {
        diagnostics: reports.iter().flat_map(|r| &r.diagnostics).collect(),
        summary,
        reader: match names.as_slice() {
            [one] => Some(one),
            _ => None,
        },
        readers,
    };
    super::safe_json::write(&output, out)
}
