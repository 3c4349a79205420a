//! The hunks of a diff, written as the new lines are read once more.

use std::cell::RefCell;
use std::io::{self, BufWriter, Write};
use std::ops::ControlFlow;

use super::align::Start;
use super::follow::Known;
use super::{old_line, NewLines, Style};
use crate::render::escape::{escape, is_plain_line};

/// Lines of context around a change.
pub(super) const CONTEXT: u32 = 3;

/// Writes the headers and every hunk of the changes `known` knows or comes to know, if
/// there are any; returns whether there are.
pub(super) fn print(
    out: &mut impl Write,
    old: &str,
    new: &impl NewLines,
    mut known: Known<'_>,
    style: Style<'_>,
) -> io::Result<bool> {
    if known.region(0).is_none() {
        return Ok(false);
    }
    // A line at a time through a buffer: standard output alone is flushed at every line.
    let mut out = BufWriter::with_capacity(1 << 16, out);
    write_headers(&mut out, style)?;
    let mut printer = Printer::new(&mut out, old, Start::TEXT, 0, style.color);
    print_hunks(&mut printer, new, known, false)?;
    out.flush()?;
    Ok(true)
}

/// Writes the headers of the diff (`---` and `+++`).
pub(super) fn write_headers(out: &mut impl Write, style: Style<'_>) -> io::Result<()> {
    let mut printer = Printer::new(out, "", Start::TEXT, 0, style.color);
    printer.write(&format!("--- {}", style.name))?;
    printer.write(&format!("+++ {}", style.name))
}

/// Writes to `out` the hunks of the changes `known` knows (every one of them), of the new
/// lines `new`, numbered from `start.index` as in the whole new text, whose old lines are
/// read from `start.at`, old line `line`: a part of the diff, printed on its own. If
/// `continued_at` is an old line, the first change goes on with the hunk of the change
/// before it (the part before ended amid its new lines), the old lines printed up to
/// that one.
pub(super) fn print_part(
    out: &mut impl Write,
    old: &str,
    new: &impl NewLines,
    mut known: Known<'_>,
    (start, line): (Start, u32),
    continued_at: Option<u32>,
    color: bool,
) -> io::Result<()> {
    if known.region(0).is_none() {
        return Ok(());
    }
    let mut printer = Printer::new(out, old, start, line, color);
    if let Some(line) = continued_at {
        printer.skip_to(line);
    }
    print_hunks(&mut printer, new, known, continued_at.is_some())
}

/// Writes the hunks of the changes `known` knows or comes to know, of the new lines `new`
/// (the first going on with a hunk begun before if `continued`).
fn print_hunks(
    printer: &mut Printer<'_, impl Write>,
    new: &impl NewLines,
    known: Known<'_>,
    continued: bool,
) -> io::Result<()> {
    let known = RefCell::new(known);
    let mut hunks = Hunks {
        next: 0,
        last_of_hunk: 0,
        continued,
    };
    let mut failed = None;
    // Only the lines of the changes are read again (the context comes from the old text),
    // and the line after each change, where it is finished.
    let mut region_asked = 0;
    // The index after the last line visited: every line, unless the last change ends first.
    let mut after = 0;
    let mut wanted = |index: u32| {
        after = index + 1;
        let mut known = known.borrow_mut();
        known.settle_new(index);
        while known.get(region_asked).is_some_and(|r| r.new.end < index) {
            region_asked += 1;
        }
        known
            .get(region_asked)
            .is_some_and(|region| region.new.start <= index)
    };
    let mut broke_at = None;
    let _ = new.each_wanted_line(&mut wanted, &mut |index, line| {
        let known = &mut *known.borrow_mut();
        let printed = hunks.step(printer, known, index).and_then(|()| {
            match hunks.next.checked_sub(1).and_then(|at| known.get(at)) {
                Some(region) if region.new.contains(&index) => printer.line('+', line.text),
                _ => Ok(()),
            }
        });
        let printed_all = known.is_complete()
            && hunks.next == known.len()
            && known
                .get(known.len() - 1)
                .is_some_and(|last| index + 1 >= last.new.end);
        match printed {
            Ok(()) if !printed_all => ControlFlow::Continue(()),
            Ok(()) => {
                broke_at = Some(index + 1);
                ControlFlow::Break(())
            }
            Err(error) => {
                failed = Some(error);
                ControlFlow::Break(())
            }
        }
    });
    if let Some(error) = failed {
        return Err(error);
    }
    let after = broke_at.unwrap_or(after);
    let finished = hunks.step(printer, &mut known.borrow_mut(), after);
    finished
}

/// Where the printing is in the changes.
struct Hunks {
    /// The next change to start (the one before it is being printed, or done).
    next: usize,
    /// The last change of the hunk being printed.
    last_of_hunk: usize,
    /// Whether the first change goes on with a hunk whose header and first lines were
    /// printed before.
    continued: bool,
}

impl Hunks {
    /// What comes before new line `index` (or the end): the end of the change being
    /// printed, and the start of the next one.
    fn step(
        &mut self,
        printer: &mut Printer<'_, impl Write>,
        known: &mut Known<'_>,
        index: u32,
    ) -> io::Result<()> {
        known.settle_new(index);
        if let Some(at) = self.next.checked_sub(1) {
            let region = known.get(at).expect("a change started");
            if region.new.end == index && !region.new.is_empty() {
                self.finish(printer, known, at)?;
            }
        }
        let Some(region) = known.get(self.next).cloned() else {
            return Ok(());
        };
        if region.new.start != index {
            return Ok(());
        }
        if self.next == 0 || self.next > self.last_of_hunk {
            self.begin_hunk(printer, known)?;
        }
        printer.old_lines(region.old.start, ' ')?;
        printer.old_lines(region.old.end, '-')?;
        self.next += 1;
        if region.new.is_empty() {
            self.finish(printer, known, self.next - 1)?;
        }
        Ok(())
    }

    /// The header of the hunk that begins with the next change, and its context before.
    fn begin_hunk(
        &mut self,
        printer: &mut Printer<'_, impl Write>,
        known: &mut Known<'_>,
    ) -> io::Result<()> {
        let first = known.get(self.next).cloned().expect("a change to start");
        let (mut last, mut last_region) = (self.next, first.clone());
        loop {
            // Every change that starts close enough to be in this hunk is known.
            known.settle_old(last_region.old.end + 2 * CONTEXT + 1);
            match known.get(last + 1) {
                Some(next) if next.old.start - last_region.old.end <= 2 * CONTEXT => {
                    (last, last_region) = (last + 1, next.clone());
                }
                _ => break,
            }
        }
        self.last_of_hunk = last;
        if std::mem::take(&mut self.continued) {
            return Ok(());
        }
        let before = CONTEXT.min(first.old.start);
        let after = known.old_lines_after(last_region.old.end, CONTEXT);
        let old = (first.old.start - before, last_region.old.end + after);
        let new = (first.new.start - before, last_region.new.end + after);
        printer.header(old, new)?;
        printer.skip_to(first.old.start - before);
        Ok(())
    }

    /// The context after change `at`: the equal lines up to the next change of its hunk,
    /// or the hunk's last lines.
    fn finish(
        &mut self,
        printer: &mut Printer<'_, impl Write>,
        known: &mut Known<'_>,
        at: usize,
    ) -> io::Result<()> {
        let end = match at == self.last_of_hunk {
            true => {
                let end = known.get(at).expect("a change").old.end;
                end + known.old_lines_after(end, CONTEXT)
            }
            false => known.get(at + 1).expect("a change of the hunk").old.start,
        };
        printer.old_lines(end, ' ')
    }
}

/// Writes a hunk header's range of lines, `start,end` (0-based, end excluded), as `diff -u`
/// does: `start,length` (1-based; an empty range names the line before it), `start` alone
/// for one line.
fn write_range(out: &mut impl Write, (start, end): (u32, u32)) -> io::Result<()> {
    match end - start {
        1 => write!(out, "{}", start + 1),
        0 => write!(out, "{start},0"),
        length => write!(out, "{},{length}", start + 1),
    }
}

/// Writes the lines of the diff, and walks the old text.
struct Printer<'o, W: Write> {
    out: W,
    old: &'o str,
    /// The next old line: its start and number.
    at: usize,
    line: u32,
    color: bool,
    /// The line being printed.
    buffer: String,
}

impl<'o, W: Write> Printer<'o, W> {
    /// A printer of lines to `out`, at the old line `line` that starts at `start.at`.
    fn new(out: W, old: &'o str, start: Start, line: u32, color: bool) -> Printer<'o, W> {
        Printer {
            out,
            old,
            at: start.at,
            line,
            color,
            buffer: String::new(),
        }
    }

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
        if is_plain_line(content) {
            // Then so is the line with its tag (a space, `+` or `-`): written as it is.
            let colour = self.colour(tag as u8);
            self.out.write_all(colour.as_bytes())?;
            self.out.write_all(&[tag as u8])?;
            self.out.write_all(content.as_bytes())?;
            self.end_line(colour)?;
        } else {
            let mut buffer = std::mem::take(&mut self.buffer);
            buffer.clear();
            buffer.push(tag);
            buffer.push_str(content);
            let written = self.write(&buffer);
            self.buffer = buffer;
            written?;
        }
        match ended {
            true => Ok(()),
            false => self.write("\\ No newline at end of file"),
        }
    }

    /// The header of a hunk of the old lines `old` and the new lines `new` (digits only:
    /// nothing to escape).
    fn header(&mut self, old: (u32, u32), new: (u32, u32)) -> io::Result<()> {
        let colour = self.colour(b'@');
        self.out.write_all(colour.as_bytes())?;
        self.out.write_all(b"@@ -")?;
        write_range(&mut self.out, old)?;
        self.out.write_all(b" +")?;
        write_range(&mut self.out, new)?;
        self.out.write_all(b" @@")?;
        self.end_line(colour)
    }

    /// Writes one line of the diff, escaped as every output of ekb is, on a terminal or
    /// not: a diff is file text, and a CI log shows it too. (A line with something escaped
    /// no longer applies with `patch`; every other line does.)
    fn write(&mut self, line: &str) -> io::Result<()> {
        let colour = self.colour(line.as_bytes().first().copied().unwrap_or(b' '));
        self.out.write_all(colour.as_bytes())?;
        self.out.write_all(escape(line).as_bytes())?;
        self.end_line(colour)
    }

    /// The colour of a line that starts with `tag`, if any.
    fn colour(&self, tag: u8) -> &'static str {
        match tag {
            _ if !self.color => "",
            b'+' => "\x1b[32m",
            b'-' => "\x1b[31m",
            b'@' => "\x1b[36m",
            _ => "",
        }
    }

    /// Ends a line written in `colour`.
    fn end_line(&mut self, colour: &str) -> io::Result<()> {
        match colour.is_empty() {
            true => self.out.write_all(b"\n"),
            false => self.out.write_all(b"\x1b[0m\n"),
        }
    }
}
