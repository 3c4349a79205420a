//! The hunks of a diff, written as the new lines are read once more.

use std::io::{self, BufWriter, Write};
use std::ops::ControlFlow;

use super::align::{Changes, Region};
use super::{old_line, NewLines, Style};
use crate::render::escape::escape;

/// Lines of context around a change.
const CONTEXT: u32 = 3;

/// Writes the headers and every hunk of `changes`.
pub(super) fn print(
    out: &mut impl Write,
    old: &str,
    new: &impl NewLines,
    changes: &Changes,
    style: Style<'_>,
) -> io::Result<()> {
    // A line at a time through a buffer: standard output alone is flushed at every line.
    let mut printer = Printer {
        out: BufWriter::with_capacity(1 << 16, out),
        old,
        at: 0,
        line: 0,
        color: style.color,
        buffer: String::new(),
    };
    printer.write(&format!("--- {}", style.name))?;
    printer.write(&format!("+++ {}", style.name))?;
    let regions = &changes.regions;
    let mut hunks = Hunks {
        changes,
        next: 0,
        last_of_hunk: 0,
    };
    let mut failed = None;
    let mut index = 0u32;
    let _ = new.each_line(&mut |line| {
        let printed = hunks.step(&mut printer, index).and_then(|()| {
            match regions.get(hunks.next.wrapping_sub(1)) {
                Some(region) if region.new.contains(&index) => printer.line('+', line.text),
                _ => Ok(()),
            }
        });
        index += 1;
        match printed {
            Ok(()) if hunks.next < regions.len() || index < regions[regions.len() - 1].new.end => {
                ControlFlow::Continue(())
            }
            Ok(()) => ControlFlow::Break(()),
            Err(error) => {
                failed = Some(error);
                ControlFlow::Break(())
            }
        }
    });
    if let Some(error) = failed {
        return Err(error);
    }
    hunks.step(&mut printer, index)?;
    printer.out.flush()
}

/// Where the printing is in the changes.
struct Hunks<'c> {
    changes: &'c Changes,
    /// The next change to start (the one before it is being printed, or done).
    next: usize,
    /// The last change of the hunk being printed.
    last_of_hunk: usize,
}

impl Hunks<'_> {
    /// What comes before new line `index` (or the end): the end of the change being
    /// printed, and the start of the next one.
    fn step(&mut self, printer: &mut Printer<'_, impl Write>, index: u32) -> io::Result<()> {
        let regions = &self.changes.regions;
        if let Some(region) = self.next.checked_sub(1).map(|at| &regions[at]) {
            if region.new.end == index && !region.new.is_empty() {
                self.finish(printer, self.next - 1)?;
            }
        }
        let Some(region) = regions.get(self.next) else {
            return Ok(());
        };
        if region.new.start != index {
            return Ok(());
        }
        if self.next == 0 || self.next > self.last_of_hunk {
            self.begin_hunk(printer)?;
        }
        printer.old_lines(region.old.start, ' ')?;
        printer.old_lines(region.old.end, '-')?;
        self.next += 1;
        if region.new.is_empty() {
            self.finish(printer, self.next - 1)?;
        }
        Ok(())
    }

    /// The header of the hunk that begins with the next change, and its context before.
    fn begin_hunk(&mut self, printer: &mut Printer<'_, impl Write>) -> io::Result<()> {
        let regions = &self.changes.regions;
        let first = &regions[self.next];
        let mut last = self.next;
        while regions
            .get(last + 1)
            .is_some_and(|next| next.old.start - regions[last].old.end <= 2 * CONTEXT)
        {
            last += 1;
        }
        self.last_of_hunk = last;
        let before = CONTEXT.min(first.old.start);
        let after = CONTEXT.min(self.changes.old_lines - regions[last].old.end);
        let old = range(first.old.start - before, regions[last].old.end + after);
        let new = range(first.new.start - before, regions[last].new.end + after);
        printer.write(&format!("@@ -{old} +{new} @@"))?;
        printer.skip_to(first.old.start - before);
        Ok(())
    }

    /// The context after change `at`: the equal lines up to the next change of its hunk,
    /// or the hunk's last lines.
    fn finish(&mut self, printer: &mut Printer<'_, impl Write>, at: usize) -> io::Result<()> {
        let regions: &[Region] = &self.changes.regions;
        let end = match at == self.last_of_hunk {
            true => (regions[at].old.end + CONTEXT).min(self.changes.old_lines),
            false => regions[at + 1].old.start,
        };
        printer.old_lines(end, ' ')
    }
}

/// A hunk header's range of lines: `start,length` (1-based; an empty range names the line
/// before it), `start` alone for one line, as `diff -u` writes it.
fn range(start: u32, end: u32) -> String {
    match end - start {
        1 => format!("{}", start + 1),
        0 => format!("{start},0"),
        length => format!("{},{length}", start + 1),
    }
}

/// Writes the lines of the diff, and walks the old text.
struct Printer<'o, W: Write> {
    out: BufWriter<W>,
    old: &'o str,
    /// The next old line: its start and number.
    at: usize,
    line: u32,
    color: bool,
    /// The line being printed.
    buffer: String,
}

impl<W: Write> Printer<'_, W> {
    /// Passes over the old lines up to line `to`.
    fn skip_to(&mut self, to: u32) {
        while self.line < to {
            self.at += old_line(self.old, self.at).len();
            self.line += 1;
        }
    }

    /// Prints the old lines up to line `to`, each after `tag`.
    fn old_lines(&mut self, to: u32, tag: char) -> io::Result<()> {
        while self.line < to {
            let text = old_line(self.old, self.at);
            self.line(tag, text)?;
            self.at += text.len();
            self.line += 1;
        }
        Ok(())
    }

    /// Prints `text` (a line with its line ending, if it has one) after `tag`; a line
    /// without one is followed by `\ No newline at end of file`, as `patch` expects.
    fn line(&mut self, tag: char, text: &str) -> io::Result<()> {
        let (content, ended) = match text.strip_suffix('\n') {
            Some(content) => (content, true),
            None => (text, false),
        };
        let mut buffer = std::mem::take(&mut self.buffer);
        buffer.clear();
        buffer.push(tag);
        buffer.push_str(content);
        let written = self.write(&buffer);
        self.buffer = buffer;
        written?;
        match ended {
            true => Ok(()),
            false => self.write("\\ No newline at end of file"),
        }
    }

    /// Writes one line of the diff, escaped as every output of ekb is, on a terminal or
    /// not: a diff is file text, and a CI log shows it too. (A line with something escaped
    /// no longer applies with `patch`; every other line does.)
    fn write(&mut self, line: &str) -> io::Result<()> {
        let colour = match line.as_bytes().first() {
            _ if !self.color => None,
            Some(b'+') => Some("\x1b[32m"),
            Some(b'-') => Some("\x1b[31m"),
            Some(b'@') => Some("\x1b[36m"),
            _ => None,
        };
        let text = escape(line);
        match colour {
            Some(colour) => writeln!(self.out, "{colour}{text}\x1b[0m"),
            None => writeln!(self.out, "{text}"),
        }
    }
}
