//! `--format human` (the default): one report per finding, drawn by miette — the rule, what
//! is wrong and what the robot would do, the lines around it with the place underlined, and
//! what to change.
//!
//! miette writes source text as it gets it, and copies nothing it does not need, but it
//! would still need the whole file to count lines. So it never sees the file: each finding
//! gets an [`Excerpt`], escaped copies of just the lines it shows (a handful, even in a
//! 60 MB file), with spans translated into the excerpt and line numbers kept.

use std::collections::BTreeSet;
use std::fmt;
use std::io::{self, Write};

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents,
    SourceCode, SourceSpan, SpanContents,
};

use super::escape::escape;
use super::{FileReport, LocatedDiagnostic, RenderOptions};
use crate::diagnostic::{Severity, Summary};
use crate::source::LineIndex;
use crate::syntax::Span;

/// Lines shown before and after each underlined place.
const CONTEXT_LINES: usize = 1;

/// Where messages and help wrap.
const WIDTH: usize = 100;

/// Lines longer than this (bytes) are not drawn: the layout of a snippet grows with its
/// line's length, and a pasted paragraph of megabytes would take minutes. The finding is
/// still reported, with its position, but without its snippet.
const MAX_DRAWN_LINE: usize = 4096;

pub fn render(
    reports: &[FileReport<'_>],
    summary: &Summary,
    out: &mut dyn Write,
    options: &RenderOptions,
) -> io::Result<()> {
    let theme = if options.color {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme)
        .with_width(WIDTH)
        .with_urls(false)
        .with_context_lines(CONTEXT_LINES)
        .without_syntax_highlighting();
    for report in reports.iter().filter(|r| !r.diagnostics.is_empty()) {
        let lines = Lines::new(report.checked.source.text());
        for diagnostic in &report.diagnostics {
            let finding = Finding::new(diagnostic, &lines);
            let mut text = String::new();
            handler
                .render_report(&mut text, &finding)
                .map_err(|_| io::Error::other("cannot lay out a finding"))?;
            writeln!(out, "{text}")?;
        }
    }
    if !options.quiet {
        writeln!(out, "{}", summary.sentence())?;
    }
    Ok(())
}

/// One finding as miette sees it: every text already escaped.
#[derive(Debug)]
struct Finding<'a> {
    /// `error[key-case]`
    code: String,
    message: String,
    severity: Severity,
    help: Option<String>,
    labels: Vec<LabeledSpan>,
    /// `None` when a line to underline is too long to draw ([`MAX_DRAWN_LINE`]).
    excerpt: Option<Excerpt<'a>>,
}

impl<'a> Finding<'a> {
    fn new(diagnostic: &LocatedDiagnostic<'_>, lines: &Lines<'a>) -> Finding<'a> {
        let source = diagnostic.diagnostic;
        let spans = || std::iter::once(source.span).chain(source.labels.iter().map(|l| l.span));
        let drawable = spans().all(|span| lines.drawable(lines.number(span.start)));
        let mut finding = Finding::without_snippet(diagnostic);
        if !drawable {
            // Without a snippet miette shows no position: say it in the message.
            let region = diagnostic.region;
            finding.message = format!(
                "{}:{}:{}: {}",
                escape(diagnostic.file),
                region.line,
                region.column,
                finding.message
            );
            return finding;
        }
        let excerpt = Excerpt::new(escape(diagnostic.file).into_owned(), lines, spans());
        // The message above says what is wrong, the help below what to do: the label only
        // marks the place, or names the fix when there is one.
        let label = match &source.fix {
            Some(fix) => escape(&fix.message).into_owned(),
            None => "here".to_string(),
        };
        let primary = LabeledSpan::new_primary_with_span(
            Some(label),
            excerpt.source_span(lines, source.span),
        );
        let secondary = source.labels.iter().map(|label| {
            LabeledSpan::new_with_span(
                Some(escape(&label.message).into_owned()),
                excerpt.source_span(lines, label.span),
            )
        });
        finding.labels = std::iter::once(primary).chain(secondary).collect();
        finding.excerpt = Some(excerpt);
        finding
    }

    /// The finding's words, with no place drawn yet.
    fn without_snippet(diagnostic: &LocatedDiagnostic<'_>) -> Finding<'a> {
        let fix = diagnostic
            .fix
            .as_ref()
            .map(|fix| format!("fix available: {} (run `ekb fix`)", fix.message));
        let help = match (diagnostic.help, fix) {
            (Some(help), Some(fix)) => Some(format!("{help}\n{fix}")),
            (help, fix) => help.map(str::to_string).or(fix),
        };
        Finding {
            code: format!("{}[{}]", diagnostic.severity.name(), diagnostic.rule),
            message: escape(diagnostic.message).into_owned(),
            severity: diagnostic.severity,
            help: help.map(|help| escape(&help).into_owned()),
            labels: Vec::new(),
            excerpt: None,
        }
    }
}

impl fmt::Display for Finding<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Finding<'_> {}

impl miette::Diagnostic for Finding<'_> {
    fn code<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        Some(Box::new(&self.code))
    }

    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
            Severity::Info => miette::Severity::Advice,
        })
    }

    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.help
            .as_ref()
            .map(|help| Box::new(help) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        self.excerpt
            .as_ref()
            .map(|excerpt| excerpt as &dyn SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let labels = self.excerpt.is_some().then(|| self.labels.iter().cloned());
        labels.map(|labels| Box::new(labels) as Box<dyn Iterator<Item = LabeledSpan>>)
    }
}

/// A file's text and where its lines are, to cut excerpts from.
struct Lines<'a> {
    text: &'a str,
    index: LineIndex,
    /// The last line with any content or line ending (0 for an empty file).
    last: u32,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Lines<'a> {
        let index = LineIndex::new(text);
        let end = index.position(text, text.len() as u32).line;
        // After a final newline the "line" at the very end is empty: not worth showing.
        let last = if text.is_empty() || text.ends_with('\n') {
            end - 1
        } else {
            end
        };
        Lines { text, index, last }
    }

    /// The 1-based line of a byte offset.
    fn number(&self, offset: u32) -> u32 {
        self.index.line(offset)
    }

    /// Where line `number` starts, and its text without the line ending.
    fn line(&self, number: u32) -> (u32, &'a str) {
        let start = self.index.line_start(number);
        let end = self
            .index
            .next_line_start(number)
            .map_or(self.text.len(), |next| next as usize - 1);
        let line = &self.text[start as usize..end.max(start as usize)];
        (start, line.strip_suffix('\r').unwrap_or(line))
    }

    /// Whether line `number` is short enough to draw.
    fn drawable(&self, number: u32) -> bool {
        self.line(number).1.len() <= MAX_DRAWN_LINE
    }
}

/// The lines one finding shows, escaped, joined into one text with its own offsets. Lines
/// not consecutive in the file are kept apart: a span never crosses from one to the next.
#[derive(Debug)]
struct Excerpt<'a> {
    /// The file's name, escaped.
    name: String,
    /// The escaped lines, each followed by `\n`.
    text: String,
    lines: Vec<ExcerptLine<'a>>,
}

#[derive(Debug)]
struct ExcerptLine<'a> {
    /// 1-based, in the file.
    number: u32,
    /// Where the line starts in the file.
    file_start: u32,
    /// The line in the file, without its ending.
    original: &'a str,
    /// Where its escaped copy starts in [`Excerpt::text`].
    start: usize,
    /// Where its `\n` is in [`Excerpt::text`].
    end: usize,
}

impl<'a> Excerpt<'a> {
    /// The lines of `spans`' starts, with [`CONTEXT_LINES`] around each.
    fn new(name: String, lines: &Lines<'a>, spans: impl Iterator<Item = Span>) -> Excerpt<'a> {
        let context = CONTEXT_LINES as u32;
        let mut numbers = BTreeSet::new();
        for span in spans {
            let number = lines.number(span.start);
            numbers.insert(number);
            let around = number.saturating_sub(context).max(1)..=number.saturating_add(context);
            numbers.extend(around.filter(|&n| n <= lines.last && lines.drawable(n)));
        }
        let mut text = String::new();
        let lines = numbers
            .into_iter()
            .map(|number| {
                let (file_start, original) = lines.line(number);
                let start = text.len();
                text.push_str(&escape(original));
                let end = text.len();
                text.push('\n');
                ExcerptLine {
                    number,
                    file_start,
                    original,
                    start,
                    end,
                }
            })
            .collect();
        Excerpt { name, text, lines }
    }

    /// `span` of the file, in the excerpt's offsets; cut at the end of its first line so
    /// that every label is drawn on one line.
    fn source_span(&self, lines: &Lines<'_>, span: Span) -> SourceSpan {
        let number = lines.number(span.start);
        let Some(line) = self.lines.iter().find(|line| line.number == number) else {
            return SourceSpan::from(0..0);
        };
        let relative = |offset: u32| offset.saturating_sub(line.file_start) as usize;
        let start = line.offset(relative(span.start), Round::Down);
        let end = line.offset(relative(span.end), Round::Up).max(start);
        SourceSpan::from(start..end)
    }

    /// The index of the line that holds excerpt offset `offset`.
    fn line_at(&self, offset: usize) -> usize {
        self.lines
            .partition_point(|line| line.start <= offset)
            .saturating_sub(1)
    }

    /// Whether lines `first..=last` follow one another in the file.
    fn consecutive(&self, first: usize, last: usize) -> bool {
        self.lines[first..=last]
            .windows(2)
            .all(|pair| pair[1].number == pair[0].number + 1)
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Round {
    Down,
    Up,
}

impl ExcerptLine<'_> {
    /// The excerpt offset of byte `relative` of the line in the file. Inside a character it
    /// moves to that character's start (`Down`) or end (`Up`); inside the line ending it
    /// means the shown `\n`.
    fn offset(&self, relative: usize, round: Round) -> usize {
        if relative > self.original.len() {
            return match round {
                Round::Down => self.end,
                Round::Up => self.end + 1,
            };
        }
        let mut relative = relative;
        while !self.original.is_char_boundary(relative) {
            match round {
                Round::Down => relative -= 1,
                Round::Up => relative += 1,
            }
        }
        self.start + escape(&self.original[..relative]).len()
    }

    /// The 0-based column in the file (in characters) of an excerpt offset in this line.
    fn column(&self, offset: usize) -> usize {
        let mut shown = self.start;
        let mut column = 0;
        let mut buffer = [0; 4];
        for ch in self.original.chars() {
            if shown >= offset {
                break;
            }
            shown += escape(ch.encode_utf8(&mut buffer)).len();
            column += 1;
        }
        column
    }
}

impl SourceCode for Excerpt<'_> {
    fn read_span<'b>(
        &'b self,
        span: &SourceSpan,
        context_lines_before: usize,
        context_lines_after: usize,
    ) -> Result<Box<dyn SpanContents<'b> + 'b>, MietteError> {
        let start = span.offset();
        let end = start + span.len();
        if self.lines.is_empty() || end > self.text.len() {
            return Err(MietteError::OutOfBounds);
        }
        let first = self.line_at(start);
        let last = self.line_at(end.saturating_sub(1).max(start));
        if !self.consecutive(first, last) {
            return Err(MietteError::OutOfBounds);
        }
        let mut from = first;
        while from > 0 && first - from < context_lines_before && self.consecutive(from - 1, from) {
            from -= 1;
        }
        let mut to = last;
        while to + 1 < self.lines.len()
            && to - last < context_lines_after
            && self.consecutive(to, to + 1)
        {
            to += 1;
        }
        let data_start = self.lines[from].start;
        let data_end = self.lines[to].end + 1;
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            &self.text.as_bytes()[data_start..data_end],
            SourceSpan::from(data_start..data_end),
            self.lines[from].number as usize - 1,
            self.lines[first].column(start),
            to - from + 1,
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::check;
    use crate::model::build::Options;
    use crate::render::located::FileReport;
    use crate::source::SourceFile;

    fn human(name: &str, text: &str) -> String {
        let source = SourceFile::from_bytes(name, text.as_bytes().to_vec());
        let checked = check(&source, &Options::default());
        let report = FileReport::new(&checked);
        let mut out = Vec::new();
        render(
            &[report],
            &checked.summary(),
            &mut out,
            &RenderOptions::default(),
        )
        .unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn control_characters_in_the_file_are_shown_escaped() {
        let out = human(
            "evil\x1b]0;x\x07.dat",
            "robotLocationDescription 1 Ro\x1b[2Jomba\u{202E}x\r\n",
        );
        assert!(!out.chars().any(super::super::escape::is_unsafe), "{out}");
        assert!(out.contains("Ro\\u{001B}[2Jomba\\u{202E}x"), "{out}");
        assert!(out.contains("evil\\u{001B}]0;x\\u{0007}.dat"), "{out}");
    }

    #[test]
    fn line_numbers_and_columns_are_those_of_the_file() {
        let text = "# ä\x01\nrobotLocationDescription 1 \x01Roomba\nrobotlocation 1 1 2 3\n";
        let out = human("kb.dat", text);
        // control-character: column 28 counts characters of the file, not of the escapes.
        assert!(out.contains("[kb.dat:2:28]"), "{out}");
        assert!(out.contains("[kb.dat:3:1]"), "{out}");
        assert!(out.contains(" 3 │ robotlocation 1 1 2 3"), "{out}");
    }

    #[test]
    fn every_span_of_a_tricky_file_renders() {
        let text = "a\u{e4}\x01b\r\n\n\u{1F600}x\ty\nlast";
        let lines = Lines::new(text);
        let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor());
        for start in 0..=text.len() {
            for end in start..=text.len() {
                let span = Span::new(start, end);
                let excerpt = Excerpt::new("t".into(), &lines, std::iter::once(span));
                let finding = Finding {
                    code: "error[test]".into(),
                    message: "m".into(),
                    severity: Severity::Error,
                    help: None,
                    labels: vec![LabeledSpan::new_primary_with_span(
                        Some("here".into()),
                        excerpt.source_span(&lines, span),
                    )],
                    excerpt: Some(excerpt),
                };
                let mut out = String::new();
                handler
                    .render_report(&mut out, &finding)
                    .unwrap_or_else(|_| panic!("span {start}..{end}"));
                assert!(!out.chars().any(super::super::escape::is_unsafe), "{out}");
            }
        }
    }

    #[test]
    fn a_huge_line_is_reported_without_its_snippet() {
        // 1.5 MB of repeated words on one line: miette would take minutes (or panic).
        let text = format!("robotLocationDescription 1 {}\n", "word ".repeat(300_000));
        let out = human("big.dat", &text);
        assert!(
            out.contains("big.dat:1:28: \"word\" is repeated"),
            "{}",
            &out[..out.len().min(2000)]
        );
        assert!(!out.contains("╭─["), "a snippet was drawn");
        assert!(out.len() < 1_000_000);
    }
}
