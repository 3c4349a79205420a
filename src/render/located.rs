//! Diagnostics with byte spans turned into 1-based lines and columns (end exclusive).

use serde::Serialize;

use crate::check::Checked;
use crate::diagnostic::{Diagnostic, Severity};
use crate::source::{LineIndex, Position};
use crate::syntax::Span;

/// A region of a file: 1-based, columns in Unicode scalar values, end exclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Region {
    pub line: u32,
    pub column: u32,
    pub end_line: u32,
    pub end_column: u32,
}

/// A fix's edit, located.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LocatedEdit {
    #[serde(flatten)]
    pub region: Region,
    pub replacement: String,
}

/// A fix, located.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LocatedFix {
    pub message: String,
    pub edits: Vec<LocatedEdit>,
}

/// A diagnostic as every output format sees it (and exactly the JSON shape of SPEC §5).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LocatedDiagnostic<'a> {
    pub file: &'a str,
    pub rule: &'static str,
    pub severity: Severity,
    pub message: &'a str,
    #[serde(flatten)]
    pub region: Region,
    pub location_id: Option<u32>,
    pub help: Option<&'a str>,
    pub fix: Option<LocatedFix>,
    #[serde(skip)]
    pub diagnostic: &'a Diagnostic,
}

/// One checked file, ready to render.
#[derive(Debug)]
pub struct FileReport<'a> {
    pub checked: &'a Checked<'a>,
    pub diagnostics: Vec<LocatedDiagnostic<'a>>,
}

impl<'a> FileReport<'a> {
    pub fn new(checked: &'a Checked<'a>) -> FileReport<'a> {
        let text = checked.source.text();
        let locator = Locator {
            text,
            index: (!checked.diagnostics.is_empty()).then(|| LineIndex::new(text)),
        };
        let diagnostics = checked
            .diagnostics
            .iter()
            .map(|diagnostic| LocatedDiagnostic {
                file: checked.source.name(),
                rule: diagnostic.rule.name,
                severity: diagnostic.severity(),
                message: &diagnostic.message,
                region: locator.region(diagnostic.span),
                location_id: diagnostic.location_id,
                help: diagnostic.help.as_deref(),
                fix: diagnostic.fix.as_ref().map(|fix| LocatedFix {
                    message: fix.message.clone(),
                    edits: fix
                        .edits
                        .iter()
                        .map(|edit| LocatedEdit {
                            region: locator.region(edit.span),
                            replacement: edit.replacement.clone(),
                        })
                        .collect(),
                }),
                diagnostic,
            })
            .collect();
        FileReport {
            checked,
            diagnostics,
        }
    }
}

struct Locator<'a> {
    text: &'a str,
    index: Option<LineIndex>,
}

impl Locator<'_> {
    fn region(&self, span: Span) -> Region {
        let index = self
            .index
            .as_ref()
            .expect("built when there are diagnostics");
        let Position { line, column } = index.position(self.text, span.start);
        let end = index.position(self.text, span.end);
        Region {
            line,
            column,
            end_line: end.line,
            end_column: end.column,
        }
    }
}
