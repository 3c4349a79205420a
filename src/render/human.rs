//! `--format human` (the default): one report per finding, drawn by miette — the rule, what
//! is wrong and what the robot would do, the lines around it with the place underlined, and
//! what to change.
//!
//! miette writes source text as it gets it, and copies nothing it does not need, but it
//! would still need the whole file to count lines. So it never sees the file: each finding
//! gets an [`Excerpt`], escaped copies of just the lines it shows (a handful, even in a
//! 60 MB file), with spans translated into the excerpt and line numbers kept. The lines are
//! cut from the text around each place, and numbered by scanning on from a place already
//! located ([`Locator`], as every format locates findings): no index of the file's lines.

use std::borrow::Cow;
use std::cell::Cell;
use std::fmt;
use std::io::{self, Write};

use miette::{
    GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, MietteSpanContents,
    SourceCode, SourceSpan, SpanContents,
};

use super::escape::{escape, escape_lines};
use super::located::{Locator, Mark};
use super::{compact, FileReport, LocatedDiagnostic, RenderOptions};
use crate::check::Summary;
use crate::diagnostic::{Applicability, Severity};
use crate::source::Position;
use crate::syntax::Span;

/// Lines shown before and after each underlined place.
const CONTEXT_LINES: usize = 1;

/// How many findings are held, drawn, at once.
const FINDINGS_PER_BATCH: usize = 512;

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
    let handlers = Handlers::new(options.color, options.width);
    let in_order: Vec<Vec<&LocatedDiagnostic>> =
        reports.iter().map(FileReport::in_reading_order).collect();
    // A person reads from the top: every file's errors first, then the other findings, in
    // reading order; a rule's many warnings are one line each, after the findings drawn.
    for errors_pass in [true, false] {
        for (report, findings) in reports.iter().zip(&in_order) {
            let part: Vec<&LocatedDiagnostic> = findings
                .iter()
                .copied()
                .filter(|d| (d.severity == Severity::Error) == errors_pass)
                .collect();
            if part.is_empty() {
                continue;
            }
            let groups = match options.show_all {
                true => Vec::new(),
                false => compact::groups(report, &part),
            };
            let drawn: Vec<&LocatedDiagnostic> = part
                .into_iter()
                .filter(|d| !groups.iter().any(|group| group.rule == d.rule))
                .collect();
            let source = Source::new(report.checked.source.name(), report.checked.source.text());
            // A consequence right after its cause is a short paragraph under it.
            let mut run = Vec::new();
            for (index, &finding) in drawn.iter().enumerate() {
                let after_cause = index > 0 && compact::follows(finding, drawn[index - 1]);
                if !after_cause {
                    run.push(finding);
                    continue;
                }
                draw_in_order(&source, run.drain(..), &handlers, out)?;
                writeln!(out, "{}\n", compact::consequence(finding, options.width))?;
            }
            draw_in_order(&source, run.into_iter(), &handlers, out)?;
            for group in &groups {
                writeln!(out, "{}\n", group.paragraph(options.width))?;
            }
        }
    }
    if !options.quiet {
        let summary = format!(
            "{}{}",
            summary.breakdown(),
            super::reader_note(reports, true)
        );
        writeln!(out, "{}", compact::wrapped(&summary, options.width, ""))?;
    }
    Ok(())
}

/// Draws `diagnostics` of `source`, in the order given.
fn draw_in_order<'d, 'r: 'd>(
    source: &Source<'_>,
    diagnostics: impl Iterator<Item = &'d LocatedDiagnostic<'r>>,
    handlers: &Handlers,
    out: &mut dyn Write,
) -> io::Result<()> {
    let mut diagnostics = diagnostics.peekable();
    while diagnostics.peek().is_some() {
        let batch: Vec<&LocatedDiagnostic> =
            diagnostics.by_ref().take(FINDINGS_PER_BATCH).collect();
        // Cut from the file in order (each is located from the one before), a batch at a
        // time, so that only a batch is held.
        let findings: Vec<Finding> = batch.iter().map(|d| source.finding(d)).collect();
        out.write_all(handlers.draw(&findings)?.as_bytes())?;
    }
    Ok(())
}

/// miette's report handler, twice: one wraps the message and help at `width`, the other
/// does not. Wrapping (textwrap, finding where Unicode lets a line break) was a third of the
/// cost of a report, and most messages fit on a line anyway: those are drawn by the handler
/// that does not wrap, to the same bytes ([`unwrapped`]).
struct Handlers {
    wrapping: GraphicalReportHandler,
    plain: GraphicalReportHandler,
    width: usize,
}

/// The columns before a message's lines (`  × `) and a help's (`  help: `).
const MESSAGE_INDENT: usize = 4;
const HELP_INDENT: usize = 8;

impl Handlers {
    fn new(color: bool, width: usize) -> Handlers {
        let theme = if color {
            GraphicalTheme::unicode()
        } else {
            GraphicalTheme::unicode_nocolor()
        };
        let wrapping = GraphicalReportHandler::new_themed(theme)
            .with_width(width)
            .with_urls(false)
            .with_context_lines(CONTEXT_LINES)
            .without_syntax_highlighting();
        let plain = wrapping.clone().with_wrap_lines(false);
        Handlers {
            wrapping,
            plain,
            width,
        }
    }

    /// The findings, drawn one after the other, each followed by a blank line.
    fn draw(&self, findings: &[Finding<'_>]) -> io::Result<String> {
        let mut drawn = String::new();
        for finding in findings {
            self.for_finding(finding)
                .render_report(&mut drawn, finding)
                .map_err(|_| io::Error::other("cannot lay out a finding"))?;
            drawn.push('\n');
        }
        Ok(drawn)
    }

    fn for_finding(&self, finding: &Finding<'_>) -> &GraphicalReportHandler {
        let help = finding.help.as_deref();
        if unwrapped(&finding.message, MESSAGE_INDENT, self.width)
            && help.is_none_or(|help| unwrapped(help, HELP_INDENT, self.width))
        {
            &self.plain
        } else {
            &self.wrapping
        }
    }
}

/// Whether miette's wrapping leaves `text`, drawn after `indent` columns, as it is. It does
/// when each line fits in `width` (less miette's margin of 2) and holds only
/// printable ASCII (one column a byte), neither blank nor beginning or ending with a space
/// (wrapping drops trailing spaces, and indents blank lines differently).
fn unwrapped(text: &str, indent: usize, width: usize) -> bool {
    text.split('\n').all(|line| {
        let bytes = line.as_bytes();
        line.len() + indent <= width.saturating_sub(2)
            && bytes.first().is_some_and(u8::is_ascii_graphic)
            && bytes.last().is_some_and(u8::is_ascii_graphic)
            && bytes
                .iter()
                .fold(true, |ok, &b| ok & matches!(b, b' '..=b'~'))
    })
}

/// One finding as miette sees it: every text already escaped.
#[derive(Debug)]
struct Finding<'a> {
    severity: Severity,
    rule: &'static str,
    message: Cow<'a, str>,
    help: Option<Cow<'a, str>>,
    labels: Vec<LabeledSpan>,
    /// `None` when a line to underline is too long to draw ([`MAX_DRAWN_LINE`]).
    excerpt: Option<Excerpt<'a>>,
}

/// `error[key-case]`, what miette calls the code.
struct Code {
    severity: Severity,
    rule: &'static str,
}

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}[{}]", self.severity.name(), self.rule)
    }
}

/// A checked file, to draw its findings.
struct Source<'a> {
    text: &'a str,
    /// The file's name, escaped once for all its findings.
    name: Cow<'a, str>,
    locator: Locator<'a>,
    /// Where the last secondary label was. Labels point back (at a first definition, an
    /// earlier tour), often many findings at the same place, so each is located from the
    /// nearer of its finding and the last label: never a scan back over the file per finding.
    last_label: Cell<Mark>,
}

/// A line of the file: its number, and where it is.
#[derive(Debug, Clone, Copy)]
struct FileLine {
    /// 1-based.
    number: u32,
    start: usize,
    /// Where its `\n` is, or the end of the text.
    end: usize,
}

impl<'a> Source<'a> {
    fn new(name: &'a str, text: &'a str) -> Source<'a> {
        Source {
            text,
            name: escape(name),
            locator: Locator::new(text, &[]),
            last_label: Cell::new(Mark::START),
        }
    }

    fn finding<'d>(&'d self, diagnostic: &'d LocatedDiagnostic<'_>) -> Finding<'d> {
        let fix = diagnostic.fix.as_ref().map(|fix| &fix.message);
        let fix_help = diagnostic.fix.as_ref().map(|fix| match fix.applicability {
            Applicability::Safe => format!("fix available: {} (run `ekb fix`)", fix.message),
            Applicability::Unsafe => format!(
                "(unsafe fix available: {}; run `ekb fix --unsafe-fixes` if that is what was meant)",
                fix.message
            ),
        });
        let help = match (diagnostic.help, fix_help) {
            (help, None) => help.map(Cow::Borrowed),
            (None, Some(fix)) => Some(Cow::Owned(fix)),
            (Some(help), Some(fix)) => Some(Cow::Owned(format!("{help}\n{fix}"))),
        };
        let mut finding = Finding {
            severity: diagnostic.severity,
            rule: diagnostic.rule,
            message: escape(diagnostic.message),
            help: help.map(escaped),
            labels: Vec::new(),
            excerpt: None,
        };
        let source = diagnostic.diagnostic;
        let region = diagnostic.region;
        let primary = Mark {
            offset: source.span.start,
            position: Position {
                line: region.line,
                column: region.column,
            },
        };
        let places = self.line(primary).and_then(|line| {
            let labels = source.labels.iter().map(|label| {
                let line = self.label_line(label.span.start, primary)?;
                Some((label, line))
            });
            Some((line, labels.collect::<Option<Vec<_>>>()?))
        });
        let Some((line, labels)) = places else {
            // Without a snippet miette shows no position: say it in the message.
            finding.message = Cow::Owned(format!(
                "{}:{}:{}: {}",
                self.name, region.line, region.column, finding.message
            ));
            return finding;
        };
        let lines = std::iter::once(line).chain(labels.iter().map(|(_, line)| *line));
        let excerpt = Excerpt::new(&self.name, self.text, self.with_context(lines));
        // The message above says what is wrong, the help below what to do: the label only
        // marks the place, or names the fix when there is one.
        let label = match fix {
            Some(fix) => escape(fix).into_owned(),
            None => "here".to_string(),
        };
        let primary =
            LabeledSpan::new_primary_with_span(Some(label), excerpt.source_span(line, source.span));
        let secondary = labels.iter().map(|(label, line)| {
            LabeledSpan::new_with_span(
                Some(escape(&label.message).into_owned()),
                excerpt.source_span(*line, label.span),
            )
        });
        finding.labels = std::iter::once(primary).chain(secondary).collect();
        finding.excerpt = Some(excerpt);
        finding
    }

    /// The line of `mark`, if it is short enough to draw.
    fn line(&self, mark: Mark) -> Option<FileLine> {
        let (start, end) = self.bounds(mark.offset as usize)?;
        Some(FileLine {
            number: mark.position.line,
            start,
            end,
        })
    }

    /// The line of a secondary label's `offset`, if it is short enough to draw, numbered from
    /// the nearer of `primary` (its finding) and the last label.
    fn label_line(&self, offset: u32, primary: Mark) -> Option<FileLine> {
        let (start, end) = self.bounds(offset as usize)?;
        let last = self.last_label.get();
        let from = if primary.distance(offset) <= last.distance(offset) {
            primary
        } else {
            last
        };
        let position = self.locator.position(from, offset);
        self.last_label.set(Mark { offset, position });
        Some(FileLine {
            number: position.line,
            start,
            end,
        })
    }

    /// Where the line holding `offset` starts and ends, if it is short enough to draw: the
    /// search stops [`MAX_DRAWN_LINE`] bytes away, so a huge line costs no more than a short
    /// one however many findings it has.
    fn bounds(&self, offset: usize) -> Option<(usize, usize)> {
        let bytes = self.text.as_bytes();
        let offset = offset.min(bytes.len());
        // A drawable line has at most MAX_DRAWN_LINE bytes and a `\r`: the newlines around
        // any offset in it are at most `reach` bytes away from its start.
        let reach = MAX_DRAWN_LINE + 2;
        let back = offset.saturating_sub(reach);
        let start = match memchr::memrchr(b'\n', &bytes[back..offset]) {
            Some(newline) => back + newline + 1,
            None if back == 0 => 0,
            None => return None,
        };
        let ahead = (start + reach).min(bytes.len());
        let end = match memchr::memchr(b'\n', &bytes[offset..ahead]) {
            Some(newline) => offset + newline,
            None if ahead == bytes.len() => ahead,
            None => return None,
        };
        (line_text(self.text, start, end).len() <= MAX_DRAWN_LINE).then_some((start, end))
    }

    /// `lines`, with [`CONTEXT_LINES`] around each (those short enough to draw), in order.
    fn with_context(&self, lines: impl Iterator<Item = FileLine>) -> Vec<FileLine> {
        let mut all = Vec::new();
        for line in lines {
            all.push(line);
            let mut before = line;
            for _ in 0..CONTEXT_LINES {
                let Some(previous) = before.start.checked_sub(1).and_then(|end| {
                    let (start, end) = self.bounds(end)?;
                    Some(FileLine {
                        number: before.number - 1,
                        start,
                        end,
                    })
                }) else {
                    break;
                };
                all.push(previous);
                before = previous;
            }
            let mut after = line;
            for _ in 0..CONTEXT_LINES {
                // After a final newline the "line" at the very end is empty: not worth showing.
                let next_start = after.end + 1;
                if next_start >= self.text.len() {
                    break;
                }
                let Some((start, end)) = self.bounds(next_start) else {
                    break;
                };
                after = FileLine {
                    number: after.number + 1,
                    start,
                    end,
                };
                all.push(after);
            }
        }
        all.sort_unstable_by_key(|line| line.number);
        all.dedup_by_key(|line| line.number);
        all
    }
}

/// The text of the line from `start` to `end`, without its line ending.
fn line_text(text: &str, start: usize, end: usize) -> &str {
    let line = &text[start..end];
    line.strip_suffix('\r').unwrap_or(line)
}

/// `text` (a help: a line of advice, and the fix's), escaped, still owned if it was.
fn escaped(text: Cow<'_, str>) -> Cow<'_, str> {
    match escape_lines(&text) {
        Cow::Borrowed(_) => text,
        Cow::Owned(escaped) => Cow::Owned(escaped),
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
        Some(Box::new(Code {
            severity: self.severity,
            rule: self.rule,
        }))
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

/// The lines one finding shows, escaped, joined into one text with its own offsets. Lines
/// not consecutive in the file are kept apart: a span never crosses from one to the next.
#[derive(Debug)]
struct Excerpt<'a> {
    /// The file's name, escaped.
    name: &'a str,
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
    /// The excerpt of `lines` (in order, each once) of the file `text`.
    fn new(name: &'a str, text: &'a str, lines: Vec<FileLine>) -> Excerpt<'a> {
        let mut shown = String::new();
        let lines = lines
            .into_iter()
            .map(|line| {
                let original = line_text(text, line.start, line.end);
                let start = shown.len();
                shown.push_str(&escape(original));
                let end = shown.len();
                shown.push('\n');
                ExcerptLine {
                    number: line.number,
                    file_start: line.start as u32,
                    original,
                    start,
                    end,
                }
            })
            .collect();
        Excerpt {
            name,
            text: shown,
            lines,
        }
    }

    /// `span` of the file, which starts on `line`, in the excerpt's offsets; cut at the end
    /// of its first line so that every label is drawn on one line.
    fn source_span(&self, line: FileLine, span: Span) -> SourceSpan {
        let Some(line) = self.lines.iter().find(|shown| shown.number == line.number) else {
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
            self.name.to_string(),
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

    /// The width the tests draw at: that of output that is not a terminal.
    const WIDTH: usize = crate::render::DEFAULT_WIDTH;

    /// The findings of `text`, every one drawn (`--show-all`): the tests of drawing.
    fn human(name: &str, text: &str) -> String {
        let every_one = RenderOptions {
            show_all: true,
            ..RenderOptions::default()
        };
        human_with(name, text, &every_one)
    }

    fn human_with(name: &str, text: &str, options: &RenderOptions) -> String {
        let source = SourceFile::from_bytes(name, text.as_bytes().to_vec());
        let checked = check(&source, &Options::default());
        let report = FileReport::new(&checked);
        let mut out = Vec::new();
        render(&[report], &checked.summary(), &mut out, options).unwrap();
        String::from_utf8(out).unwrap()
    }

    /// Four placeholders in isiZulu at location `id`, and its other fields.
    fn untranslated_location(id: u32) -> String {
        let mut text = format!(
            "robotLocationDescription {id} Roomba\nrobotLocation {id} 1.0 2.0 90\n\
             gestureTarget {id} 1.0 2.0 0.5\n"
        );
        for phase in ["pre", "post"] {
            text.push_str(&format!("{phase}GestureMessageEnglish {id} Hello there\n"));
            text.push_str(&format!(
                "{phase}GestureMessageIsiZulu {id} No message in isiZulu\n"
            ));
            text.push_str(&format!(
                "{phase}GestureMessageKinyarwanda {id} Muraho neza\n"
            ));
        }
        text
    }

    /// Two locations of [`untranslated_location`] on a tour: four placeholders.
    fn two_untranslated_locations() -> String {
        let (first, second) = (untranslated_location(1), untranslated_location(2));
        format!("{first}{second}tourSpecification 2 1 2\n")
    }

    #[test]
    fn a_rules_many_warnings_are_one_paragraph_unless_all_are_asked_for() {
        // Two locations: four placeholders, grouped; one: two, each drawn.
        let text = two_untranslated_locations();
        let grouped = human_with("kb.dat", &text, &RenderOptions::default());
        assert_eq!(
            grouped.matches("warning[untranslated-message]").count(),
            1,
            "{grouped}"
        );
        assert!(
            grouped.starts_with(
                "warning[untranslated-message]: 4 findings, on lines 5, 8, 14, 17\n  the first: "
            ),
            "{grouped}"
        );
        assert!(
            grouped.contains(
                "\n  see all: ekb check --show-all --select untranslated-message kb.dat\n"
            ),
            "{grouped}"
        );
        assert!(!grouped.contains("╭─["), "{grouped}");
        let every_one = human("kb.dat", &text);
        assert_eq!(
            every_one.matches("warning[untranslated-message]").count(),
            4
        );

        let near_miss = format!("{}tourSpecification 1 1\n", untranslated_location(1));
        let drawn = human_with("kb.dat", &near_miss, &RenderOptions::default());
        assert_eq!(
            drawn.matches("warning[untranslated-message]\n").count(),
            2,
            "{drawn}"
        );
        assert!(!drawn.contains("see all"), "{drawn}");
    }

    #[test]
    fn a_grouped_rule_names_a_file_the_shell_reads_as_one_word() {
        let text = two_untranslated_locations();
        let out = human_with("lab 2/it's.dat", &text, &RenderOptions::default());
        assert!(
            out.contains("--select untranslated-message 'lab 2/it'\\''s.dat'\n"),
            "{out}"
        );
    }

    #[test]
    fn findings_drawn_in_batches_come_out_in_order() {
        // 1,200 findings: batches of 512, and a last short batch.
        let text: String = (1..=1_200)
            .map(|id| format!("robotLocationDescription {id} exhibit {id}\n"))
            .collect();
        let out = human("kb.dat", &text);
        let source = SourceFile::from_bytes("kb.dat", text.into_bytes());
        let checked = check(&source, &Options::default());
        let report = FileReport::new(&checked);
        let handlers = Handlers::new(false, WIDTH);
        let one_by_one = Source::new("kb.dat", source.text());
        let findings: Vec<Finding> = report
            .diagnostics
            .iter()
            .map(|d| one_by_one.finding(d))
            .collect();
        let drawn = handlers.draw(&findings);
        assert!(findings.len() > FINDINGS_PER_BATCH);
        assert!(out.starts_with(&drawn.unwrap()), "{out}");
    }

    #[test]
    fn control_characters_in_the_file_are_shown_escaped() {
        let out = human(
            "evil\x1b]0;x\x07.dat",
            "robotLocationDescription 1 Ro\x1b[2Jomba\u{202E}x\r\n",
        );
        assert!(
            !out.chars()
                .any(|c| c != '\n' && super::super::escape::is_unsafe(c)),
            "{out}"
        );
        assert!(
            out.contains("Ro\\u{001B}[2Jomba\\u{202E RIGHT-TO-LEFT OVERRIDE}x"),
            "{out}"
        );
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
        let source = Source::new("t", text);
        let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor());
        for start in 0..=text.len() {
            let mark = Mark {
                offset: start as u32,
                position: source.locator.position(Mark::START, start as u32),
            };
            let line = source.line(mark).unwrap();
            for end in start..=text.len() {
                let span = Span::new(start, end);
                let lines = source.with_context(std::iter::once(line));
                let excerpt = Excerpt::new("t", text, lines);
                let finding = Finding {
                    severity: Severity::Error,
                    rule: "test",
                    message: "m".into(),
                    help: None,
                    labels: vec![LabeledSpan::new_primary_with_span(
                        Some("here".into()),
                        excerpt.source_span(line, span),
                    )],
                    excerpt: Some(excerpt),
                };
                let mut out = String::new();
                handler
                    .render_report(&mut out, &finding)
                    .unwrap_or_else(|_| panic!("span {start}..{end}"));
                assert!(
                    !out.chars()
                        .any(|c| c != '\n' && super::super::escape::is_unsafe(c)),
                    "{out}"
                );
            }
        }
    }

    /// `message` and `help` drawn by both handlers, without a snippet.
    fn drawn_by_both(message: &str, help: Option<&str>) -> (String, String) {
        let handlers = Handlers::new(false, WIDTH);
        let finding = Finding {
            severity: Severity::Warning,
            rule: "test",
            message: message.into(),
            help: help.map(Cow::Borrowed),
            labels: Vec::new(),
            excerpt: None,
        };
        let draw = |handler: &GraphicalReportHandler| {
            let mut out = String::new();
            handler.render_report(&mut out, &finding).unwrap();
            out
        };
        (draw(&handlers.wrapping), draw(&handlers.plain))
    }

    #[test]
    fn text_is_left_unwrapped_exactly_when_wrapping_would_not_change_it() {
        // `len` bytes of words, the last ending with a letter.
        let words = |len: usize| format!("{}x", &"word ".repeat(len)[..len - 1]);
        let fits = 98 - MESSAGE_INDENT;
        for (message, help) in [
            (words(fits), None),
            ("m".into(), Some(words(98 - HELP_INDENT))),
            ("m".into(), Some(format!("{}\n{}", words(20), words(90)))),
        ] {
            assert!(unwrapped(&message, MESSAGE_INDENT, WIDTH));
            assert!(help
                .as_deref()
                .is_none_or(|h| unwrapped(h, HELP_INDENT, WIDTH)));
            let (wrapped, plain) = drawn_by_both(&message, help.as_deref());
            assert_eq!(wrapped, plain);
        }
        // One column more, a trailing space, a blank line, a character wider than a byte:
        // wrapping changes each, so none is taken as unwrapped.
        for (message, help) in [
            (words(fits + 1), None),
            ("m".into(), Some(words(98 - HELP_INDENT + 1))),
            ("m ".into(), None),
            ("m".into(), Some("a\n\nb".into())),
            (format!("{}中", words(fits - 1)), None),
        ] {
            let unwrapped = unwrapped(&message, MESSAGE_INDENT, WIDTH)
                && help
                    .as_deref()
                    .is_none_or(|h| unwrapped(h, HELP_INDENT, WIDTH));
            assert!(!unwrapped, "{message:?} {help:?}");
            let (wrapped, plain) = drawn_by_both(&message, help.as_deref());
            assert_ne!(wrapped, plain, "{message:?} {help:?}");
        }
    }

    proptest::proptest! {
        #[test]
        fn unwrapped_text_is_drawn_as_wrapping_would(
            message in "[ -~]{1,100}(\n[ -~]{0,100}){0,2}",
            help in proptest::option::of("[ -~]{1,100}(\n[ -~]{0,100}){0,2}"),
        ) {
            let help = help.as_deref();
            if unwrapped(&message, MESSAGE_INDENT, WIDTH) && help.is_none_or(|h| unwrapped(h, HELP_INDENT, WIDTH)) {
                let (wrapped, plain) = drawn_by_both(&message, help);
                proptest::prop_assert_eq!(wrapped, plain);
            }
        }
    }

    /// A description of location `id`, of exactly `len` bytes before `ending`, with "word"
    /// repeated.
    fn repeated_word_line(id: u32, len: usize, ending: &str) -> String {
        let line = format!(
            "robotLocationDescription {id} word word {}",
            "x".repeat(len)
        );
        format!("{}{ending}", &line[..len])
    }

    /// The gutter of each line `report` draws (its line number or nothing).
    fn gutters(report: &str) -> Vec<&str> {
        let gutters = report.lines().filter_map(|line| line.split_once(" │ "));
        gutters.map(|(gutter, _)| gutter.trim()).collect()
    }

    #[test]
    fn lines_up_to_the_limit_are_drawn_with_their_neighbours() {
        for ending in ["\n", "\r\n"] {
            let drawn = |id| repeated_word_line(id, MAX_DRAWN_LINE, ending);
            let too_long = repeated_word_line(2, MAX_DRAWN_LINE + 1, ending);
            let (first, fourth) = (drawn(1), drawn(4));
            let text = format!("# 1\n{first}{too_long}# 4\n{}{fourth}# 7{ending}", drawn(3));
            let out = human("kb.dat", &text);
            let repeated = |line| {
                let start = format!("╭─[kb.dat:{line}:28]");
                let mut reports = out.split("\n\n");
                reports.find(|report| report.contains(&start)).unwrap()
            };
            // Line 3, too long, is neither drawn nor shown as a neighbour.
            assert_eq!(gutters(repeated(2)), ["1", "2"], "{ending:?}");
            assert!(
                out.contains("kb.dat:3:28: \"word\" is repeated"),
                "{ending:?}"
            );
            assert_eq!(gutters(repeated(5)), ["4", "5", "6"], "{ending:?}");
            assert_eq!(gutters(repeated(6)), ["5", "6", "7"], "{ending:?}");
            let tour_missing = out.split("\n\n").nth(1).unwrap();
            assert!(tour_missing.contains("no `tourSpecification`"));
            assert_eq!(gutters(tour_missing), ["1", "2"], "{ending:?}");
        }
    }

    #[test]
    fn labels_far_back_are_numbered_right() {
        // Location 1's description twice, 5000 lines apart, for many locations.
        let mut text = String::new();
        for id in 1..=3 {
            text.push_str(&format!("robotLocationDescription {id} first\n"));
        }
        text.push_str(&"# filler\n".repeat(5000));
        for id in 1..=3 {
            text.push_str(&format!("robotLocationDescription {id} second\n"));
        }
        let out = human("kb.dat", &text);
        for id in 1..=3 {
            let report = out
                .split("\n\n")
                .find(|report| report.contains(&format!("location {id} has")))
                .unwrap();
            let numbered = gutters(report);
            let (first, second) = (id, 5003 + id);
            assert!(numbered.contains(&first.to_string().as_str()), "{report}");
            assert!(numbered.contains(&second.to_string().as_str()), "{report}");
            assert!(report.contains("first given here"), "{report}");
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
