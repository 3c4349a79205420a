//! Diagnostics with byte spans turned into 1-based lines and columns (end exclusive).

use std::cell::Cell;
use std::collections::HashMap;

use serde::Serialize;

use crate::check::Checked;
use crate::diagnostic::{Applicability, Diagnostic, Severity};
use crate::source::{count_chars, LineStart, Position};
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
    /// `safe` (`ekb fix` applies it) or `unsafe` (only with `--unsafe-fixes`).
    pub applicability: Applicability,
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
    /// [`MAX_SHOWN_PER_RULE`](crate::diagnostic::MAX_SHOWN_PER_RULE) of each rule).
    pub fn new(checked: &'a Checked<'a>) -> FileReport<'a> {
        let locator = Locator::new(checked.source.text(), &checked.kb.lines.line_starts);
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
                    applicability: fix.applicability,
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

impl<'a> FileReport<'a> {
    /// The findings in the order a person reads them (the JSON of SPEC §5 keeps the file's
    /// order): errors first, then warnings, then the rest, each in the file's order, except
    /// that a finding that follows from another ([`Diagnostic::follows_from`]) comes right
    /// after the first finding of its cause at its location, when that is no milder. Every
    /// face that lists findings for people lists them so: `ekb check`, the report's table,
    /// the loader's findings (and through it the ROS log and Python's `ekb.check()`).
    pub fn in_reading_order(&self) -> Vec<&LocatedDiagnostic<'a>> {
        let mut first_of: HashMap<(&'static str, Option<u32>), usize> = HashMap::new();
        for (index, finding) in self.diagnostics.iter().enumerate() {
            first_of
                .entry((finding.rule, finding.location_id))
                .or_insert(index);
        }
        let cause_of = |finding: &LocatedDiagnostic| {
            let rule = finding.diagnostic.follows_from?;
            let &cause = first_of.get(&(rule.name, finding.location_id))?;
            (self.diagnostics[cause].severity <= finding.severity).then_some(cause)
        };
        let mut order: Vec<(Severity, usize, bool, usize)> = self
            .diagnostics
            .iter()
            .enumerate()
            .map(|(index, finding)| match cause_of(finding) {
                Some(cause) => (self.diagnostics[cause].severity, cause, true, index),
                None => (finding.severity, index, false, index),
            })
            .collect();
        order.sort_unstable();
        order
            .into_iter()
            .map(|(.., index)| &self.diagnostics[index])
            .collect()
    }

    /// Whether the file was checked against a version of the environment knowledge base's
    /// reader (`--reader`); the mission and the culture knowledge base have their own.
    pub fn read_by_reader(&self) -> bool {
        self.checked.kind == crate::check::FileKind::EnvironmentKnowledgeBase
    }
}

/// A byte offset whose position is known: where a scan can start.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mark {
    pub offset: u32,
    pub position: Position,
}

impl Mark {
    /// The start of the file.
    pub const START: Mark = Mark {
        offset: 0,
        position: Position { line: 1, column: 1 },
    };

    /// How far `offset` is from the mark, in bytes.
    pub fn distance(self, offset: u32) -> u32 {
        self.offset.abs_diff(offset)
    }
}

/// Converts spans to regions by scanning on from the last position found, or from the
/// nearest known line start if that is nearer. Findings come sorted by position, so the scans
/// add up to about one pass over the file (with memchr), and no index of every line is
/// built (on a 100,000-location file that index was 900,000 entries, built to locate a
/// thousand findings). Locating many findings on one huge line (a million-stop tour) costs
/// the line's length once, not once per finding.
pub struct Locator<'a> {
    text: &'a str,
    /// Where the last region started.
    cursor: Cell<Mark>,
    /// Lines whose numbers are known, in file order (those the model noted while reading).
    line_starts: &'a [LineStart],
}

impl<'a> Locator<'a> {
    pub fn new(text: &'a str, line_starts: &'a [LineStart]) -> Locator<'a> {
        Locator {
            text,
            cursor: Cell::new(Mark::START),
            line_starts,
        }
    }

    fn region(&self, span: Span) -> Region {
        let start = self.position(self.nearest_mark(span.start), span.start);
        let mark = Mark {
            offset: span.start,
            position: start,
        };
        self.cursor.set(mark);
        let end = self.position(mark, span.end);
        Region {
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
        }
    }

    /// The nearer to `offset` of the last region's start and the last known line start
    /// before `offset`.
    fn nearest_mark(&self, offset: u32) -> Mark {
        let cursor = self.cursor.get();
        let before = self
            .line_starts
            .partition_point(|start| start.offset <= offset);
        match before.checked_sub(1).map(|last| self.line_starts[last]) {
            Some(start) if start.offset.abs_diff(offset) < cursor.distance(offset) => Mark {
                offset: start.offset,
                position: Position {
                    line: start.line,
                    column: 1,
                },
            },
            _ => cursor,
        }
    }

    /// The position of `offset`, counted from `from`: the cost is the distance between them
    /// (and, backwards, the length of the line of `offset`).
    pub fn position(&self, from: Mark, offset: u32) -> Position {
        let bytes = self.text.as_bytes();
        let offset = (offset as usize).min(bytes.len());
        let from_offset = (from.offset as usize).min(bytes.len());
        let from = from.position;
        let newlines = |range: &[u8]| memchr::memchr_iter(b'\n', range).count() as u32;
        if offset >= from_offset {
            let skipped = &bytes[from_offset..offset];
            match memchr::memrchr(b'\n', skipped) {
                None => Position {
                    line: from.line,
                    column: from.column + count_chars(skipped) as u32,
                },
                Some(last) => Position {
                    line: from.line + newlines(skipped),
                    column: count_chars(&skipped[last + 1..]) as u32 + 1,
                },
            }
        } else {
            let line_start = memchr::memrchr(b'\n', &bytes[..offset]).map_or(0, |i| i + 1);
            Position {
                line: from.line - newlines(&bytes[offset..from_offset]),
                column: count_chars(&bytes[line_start..offset]) as u32 + 1,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::LineIndex;

    #[test]
    fn known_line_starts_give_the_same_regions() {
        let text = "ab\nÙmuntu x\n\nlast é line\nmore\n";
        let index = LineIndex::new(text);
        let line_starts = [3, 13, 27].map(|offset| LineStart {
            offset,
            line: index.position(text, offset).line,
        });
        let spans: [(u32, u32); 7] = [
            (0, 2),
            (14, 20),
            (4, 12),
            (28, 31),
            (1, 30),
            (31, 32),
            (12, 13),
        ];
        let with_starts = Locator::new(text, &line_starts);
        let from_cursor = Locator::new(text, &[]);
        for (start, end) in spans {
            let span = Span::new(start as usize, end as usize);
            let expected = Region {
                line: index.position(text, start).line,
                column: index.position(text, start).column,
                end_line: index.position(text, end).line,
                end_column: index.position(text, end).column,
            };
            assert_eq!(with_starts.region(span), expected, "{span:?}");
            assert_eq!(from_cursor.region(span), expected, "{span:?}");
        }
    }

    #[test]
    fn scanning_on_agrees_with_the_line_index() {
        let text = "ab\nÙmuntu x\n\nlast é line";
        let index = LineIndex::new(text);
        let locator = Locator::new(text, &[]);
        let offsets = [0, 1, 5, 12, 13, 14, 2, 3, 20, 4, text.len() as u32, 0];
        for from in offsets {
            let known = Mark {
                offset: from,
                position: index.position(text, from),
            };
            for offset in offsets {
                assert_eq!(
                    locator.position(known, offset),
                    index.position(text, offset),
                    "from {from} to {offset}"
                );
            }
        }
    }
}
