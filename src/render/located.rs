//! Diagnostics with byte spans turned into 1-based lines and columns (end exclusive).

use std::cell::Cell;

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
    /// Locates the findings [`Checked::shown`] lists (at most
    /// [`MAX_SHOWN_PER_RULE`](crate::check::MAX_SHOWN_PER_RULE) of each rule).
    pub fn new(checked: &'a Checked<'a>) -> FileReport<'a> {
        let text = checked.source.text();
        let locator = Locator {
            text,
            index: (!checked.diagnostics.is_empty()).then(|| LineIndex::new(text)),
            cursor: Cell::new(None),
        };
        let diagnostics = checked
            .shown()
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

/// Converts spans to regions. Findings come sorted by position, so it remembers the last
/// position it found and counts columns on from there: locating many findings on one huge
/// line (a million-stop tour) costs the line's length once, not once per finding.
struct Locator<'a> {
    text: &'a str,
    index: Option<LineIndex>,
    cursor: Cell<Option<(u32, Position)>>,
}

impl Locator<'_> {
    fn region(&self, span: Span) -> Region {
        let start = self.position(span.start, self.cursor.get());
        self.cursor.set(Some((span.start, start)));
        let end = self.position(span.end, Some((span.start, start)));
        Region {
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
        }
    }

    /// The position of `offset`, counted on from `from` when that is earlier on the same line.
    fn position(&self, offset: u32, from: Option<(u32, Position)>) -> Position {
        let index = self
            .index
            .as_ref()
            .expect("built when there are diagnostics");
        match from {
            Some((from_offset, from)) if from_offset <= offset => {
                index.position_from(self.text, from_offset, from, offset)
            }
            _ => index.position(self.text, offset),
        }
    }
}
