//! What `ekb fmt` and `ekb fix` share once they know a file's new text: show it as a diff,
//! write it in place, or send it to standard output; and the refusals that come before.
//!
//! A command that rewrites a knowledge base (`fix`, `fmt`, and `set` or `import --po` to
//! come) takes its files from [`crate::context::Context::files_to_rewrite`] (which will
//! not rewrite a configured file outside the configuration's project unless it is named),
//! takes [`lock`] before it reads each with [`crate::context::Context::read`] (and holds it
//! until the file is written), calls [`ensure_rewritable`], then
//! [`deliver`], which writes through [`crate::write::rewrite`]: refused if the file changed
//! since it was read, and every other guard of [`crate::write`]. [`for_each_file`] goes
//! on after a file that failed.

use std::hash::{DefaultHasher, Hasher};
use std::io::{self, BufWriter, Write};
use std::path::Path;
use std::time::Duration;

use similar::{Algorithm, DiffOp, TextDiff};

use crate::context::{CommandError, Exit};
use crate::render::escape::escape;
use crate::rules::structure::not_a_knowledge_base;
use crate::source::{LineIndex, SourceFile};
use crate::stderr_line;
use crate::write;

/// What to do with a file's new text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Replace the file (standard input: print the new text).
    Write,
    /// Print a unified diff and write nothing.
    Diff,
}

/// How a diff is printed.
#[derive(Debug, Clone, Copy, Default)]
pub struct DiffStyle {
    pub color: bool,
}

/// Refuses a file that was not valid UTF-8: rewriting it would replace the bad bytes; and a
/// file that is not an environment knowledge base (the culture knowledge base, say), which
/// the layout would reorder and no fix would mend.
pub fn ensure_rewritable(source: &SourceFile) -> Result<(), CommandError> {
    if let Some(first) = source.invalid_utf8().first() {
        let position = LineIndex::new(source.text()).position(source.text(), first.start);
        return Err(CommandError::Failed(format!(
            "{} is not valid UTF-8 (line {}, column {}): ekb does not rewrite it, as that would \
             lose the bad bytes; save it as UTF-8 and run again (if it is Latin-1, \
             `ekb fix --unsafe-fixes` converts it)",
            escape(source.name()),
            position.line,
            position.column
        )));
    }
    match not_a_knowledge_base::check(source.text()) {
        Some(foreign) => Err(CommandError::Failed(format!(
            "{}: {}; ekb does not rewrite it",
            escape(source.name()),
            foreign.message
        ))),
        None => Ok(()),
    }
}

/// The lock a command holds on `path` from reading it to writing it back, if `mode` writes
/// ([`crate::write::lock_to_rewrite`]): two ekb rewriting one file take turns, the second
/// reading what the first wrote.
pub fn lock(path: &Path, mode: Mode) -> Result<Option<write::RewriteLock>, CommandError> {
    match mode {
        Mode::Write => Ok(write::lock_to_rewrite(path)?),
        Mode::Diff => Ok(None),
    }
}

/// Delivers `new`, the new text of `source` read from `path`, as `mode` says. Returns whether
/// it differs from the old text.
pub fn deliver(
    path: &Path,
    source: &SourceFile,
    new: &str,
    mode: Mode,
    style: DiffStyle,
) -> Result<bool, CommandError> {
    let old = source.text();
    let changed = old != new;
    let stdin = path == Path::new("-");
    match mode {
        Mode::Diff if changed => {
            print_diff(source.name(), old, new, style)?;
        }
        Mode::Diff => {}
        Mode::Write if stdin => io::stdout().lock().write_all(new.as_bytes())?,
        Mode::Write if changed => match source.stamp() {
            Some(read_as) => write::rewrite(path, new.as_bytes(), read_as)?,
            None => write::write_atomically(path, new.as_bytes())?,
        },
        Mode::Write => {}
    }
    Ok(changed)
}

/// Writes the new text of `source`, read from `path`, made by `fill` as it is written, in
/// place of the file (standard output for `-`): for a text too large to hold whole. Written
/// through [`crate::write::rewrite_streamed`], so refused as [`deliver`] is if the file
/// changed since it was read. If `fill` fails, the file is left as it was.
pub fn deliver_streamed(
    path: &Path,
    source: &SourceFile,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), CommandError> {
    if path == Path::new("-") {
        let mut stdout = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
        fill(&mut stdout)?;
        stdout.flush()?;
        return Ok(());
    }
    match source.stamp() {
        Some(read_as) => write::rewrite_streamed(path, read_as, fill)?,
        None => write::write_streamed(path, fill)?,
    }
    Ok(())
}

/// Runs `each` on every path, going on after a failure (reported on standard error; a
/// closed standard output is told once, at the end), and returns the worst exit.
pub fn for_each_file(
    paths: &[std::path::PathBuf],
    mut each: impl FnMut(&Path) -> Result<Exit, CommandError>,
) -> Exit {
    let mut worst = Exit::Clean;
    for path in paths {
        let exit = each(path).unwrap_or_else(|error| {
            error.report();
            Exit::Failure
        });
        if exit as u8 > worst as u8 {
            worst = exit;
        }
    }
    worst
}

/// Past this many bytes (the old text and the new together) a diff is not printed: the
/// lines that would change are told instead ([`tell_changed_lines`]). A real knowledge base
/// is a few kilobytes; a diff of hundreds of megabytes is read by no one.
pub const LARGEST_DIFF: usize = 16 << 20;

/// How long a diff may take to be minimal: past it, a coarser diff is printed (still one
/// that applies). A real file's diff takes a millisecond; the balanced order of 10,000
/// locations in id order (`compat-reader-crash`) moves every block and took 2 s.
const DIFF_TIMEOUT: Duration = Duration::from_millis(250);

/// Lines of context around a change.
const CONTEXT: usize = 3;

/// Prints the unified diff of `old` and `new` on standard output (nothing if they are
/// equal); past [`LARGEST_DIFF`], the lines that would change on standard error. Returns
/// whether they differ.
pub fn print_diff(name: &str, old: &str, new: &str, style: DiffStyle) -> io::Result<bool> {
    if old == new {
        return Ok(false);
    }
    if old.len() + new.len() > LARGEST_DIFF {
        if let Some(stretch) = changed_lines(old, new) {
            tell_changed_lines(name, old, stretch);
        }
        return Ok(true);
    }
    // A line at a time through a buffer: standard output alone is flushed at every line.
    let mut out = BufWriter::with_capacity(1 << 16, io::stdout().lock());
    write_diff(&mut out, name, old, new, style)?;
    out.flush()?;
    Ok(true)
}

/// [`print_diff`] of `old` and the text that `write` writes. Past [`LARGEST_DIFF`] of `old`,
/// where only the lines that change are told, that text is compared with `old` as it is
/// written and never held whole (a formatted or balanced file can be larger than the
/// original).
pub fn print_diff_streamed<E: From<io::Error>>(
    name: &str,
    old: &str,
    style: DiffStyle,
    write: impl FnOnce(&mut dyn Write) -> Result<(), E>,
) -> Result<bool, E> {
    if old.len() <= LARGEST_DIFF {
        let mut new = Vec::with_capacity(old.len() + old.len() / 4);
        write(&mut new)?;
        let new = String::from_utf8(new).map_err(io::Error::other)?;
        return Ok(print_diff(name, old, &new, style)?);
    }
    let mut compared = ChangedStretch::new(old);
    write(&mut compared)?;
    Ok(match compared.finish() {
        Some(stretch) => {
            tell_changed_lines(name, old, stretch);
            true
        }
        None => false,
    })
}

/// Tells on standard error which lines of `old` would change (`stretch`: from the first to
/// the last that differs), for a text too large to show as a diff.
fn tell_changed_lines(name: &str, old: &str, (first, last): (usize, usize)) {
    stderr_line!(
        "{}: would change lines {first} to {last} of {}; the diff of a file over {} MiB is not \
         shown (write the result to another file with `ekb fmt - < FILE > OTHER` or \
         `ekb fix`, and compare)",
        escape(name),
        old.lines().count(),
        LARGEST_DIFF >> 20
    );
}

/// The first and the last line (1-based) of `old` that `new` does not have in the same place
/// counted from the start or from the end: the stretch of `old` that changes. For an
/// insertion between two lines, the line after it. `None` if they are equal.
fn changed_lines(old: &str, new: &str) -> Option<(usize, usize)> {
    let mut compared = ChangedStretch::new(old);
    compared
        .write_all(new.as_bytes())
        .expect("comparing never fails");
    compared.finish()
}

/// The stretch of `old` that a new text changes ([`changed_lines`]), found as the new text
/// is written: its lines (each with its newline) are compared with `old`'s from the start as
/// they come, and kept only as hashes, to be compared from the end once all are written.
struct ChangedStretch<'o> {
    old: &'o str,
    /// `old`'s lines not yet compared from the start.
    old_lines: std::str::SplitInclusive<'o, char>,
    /// How many lines at the start the two texts share; whether one has differed since.
    same_start: usize,
    differed: bool,
    /// The new text's last line, while its newline has not come.
    partial: Vec<u8>,
    new_lines: Vec<u64>,
}

impl<'o> ChangedStretch<'o> {
    fn new(old: &'o str) -> ChangedStretch<'o> {
        ChangedStretch {
            old,
            old_lines: old.split_inclusive('\n'),
            same_start: 0,
            differed: false,
            partial: Vec::new(),
            new_lines: Vec::new(),
        }
    }

    fn line(&mut self, line: &[u8]) {
        if !self.differed {
            match self.old_lines.next() {
                Some(old) if old.as_bytes() == line => self.same_start += 1,
                _ => self.differed = true,
            }
        }
        self.new_lines.push(line_hash(line));
    }

    /// The stretch of `old` that changes; `None` if the new text is `old`.
    fn finish(mut self) -> Option<(usize, usize)> {
        if !self.partial.is_empty() {
            let last = std::mem::take(&mut self.partial);
            self.line(&last);
        }
        let old_count = self.old.split_inclusive('\n').count();
        if !self.differed && self.new_lines.len() == old_count {
            return None;
        }
        let same_end = self
            .old
            .split_inclusive('\n')
            .rev()
            .zip(self.new_lines.iter().rev())
            .take_while(|(old, &new)| line_hash(old.as_bytes()) == new)
            .count()
            .min(old_count - self.same_start);
        let first = self.same_start + 1;
        Some((first, (old_count - same_end).max(first)))
    }
}

impl Write for ChangedStretch<'_> {
    fn write(&mut self, mut bytes: &[u8]) -> io::Result<usize> {
        let written = bytes.len();
        while let Some(newline) = memchr::memchr(b'\n', bytes) {
            let (line, rest) = bytes.split_at(newline + 1);
            if self.partial.is_empty() {
                self.line(line);
            } else {
                let mut whole = std::mem::take(&mut self.partial);
                whole.extend_from_slice(line);
                self.line(&whole);
                whole.clear();
                self.partial = whole;
            }
            bytes = rest;
        }
        self.partial.extend_from_slice(bytes);
        Ok(written)
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// A line's hash, to compare it with another without holding it (a different line with the
/// same hash, one chance in 2^64, would only narrow the stretch told).
fn line_hash(line: &[u8]) -> u64 {
    let mut hasher = DefaultHasher::new();
    hasher.write(line);
    hasher.finish()
}

/// Writes the unified diff of `old` and `new` (which differ) to `out`, with three lines of
/// context, each printed line escaped as every output of ekb is, on a terminal or not: a
/// diff is file text, and a CI log shows it too. (A line with something escaped no longer
/// applies with `patch`; every other line does.)
fn write_diff(
    out: &mut impl Write,
    name: &str,
    old: &str,
    new: &str,
    style: DiffStyle,
) -> io::Result<()> {
    // Patience anchors on unique lines, so a formatted file (a blank line between every
    // block) diffs in about linear time; the deadline bounds the rest.
    let diff = TextDiff::configure()
        .algorithm(Algorithm::Patience)
        .timeout(DIFF_TIMEOUT)
        .diff_lines(old, new);
    let write_line = |out: &mut dyn Write, line: &str| {
        let colour = match line.as_bytes().first() {
            _ if !style.color => "",
            Some(b'+') => "\x1b[32m",
            Some(b'-') => "\x1b[31m",
            Some(b'@') => "\x1b[36m",
            _ => "",
        };
        let reset = if colour.is_empty() { "" } else { "\x1b[0m" };
        writeln!(out, "{colour}{}{reset}", escape(line))
    };
    write_line(out, &format!("--- {name}"))?;
    write_line(out, &format!("+++ {name}"))?;
    let (old_lines, new_lines) = (diff.old_slices(), diff.new_slices());
    for group in diff.grouped_ops(CONTEXT) {
        let (first, last) = (group[0], group[group.len() - 1]);
        let header = format!(
            "@@ -{} +{} @@",
            hunk_range(first.old_range().start, last.old_range().end),
            hunk_range(first.new_range().start, last.new_range().end)
        );
        write_line(out, &header)?;
        for op in &group {
            let (equal, taken, put) = match *op {
                DiffOp::Equal { old_index, len, .. } => (old_index..old_index + len, 0..0, 0..0),
                DiffOp::Delete {
                    old_index, old_len, ..
                } => (0..0, old_index..old_index + old_len, 0..0),
                DiffOp::Insert {
                    new_index, new_len, ..
                } => (0..0, 0..0, new_index..new_index + new_len),
                DiffOp::Replace {
                    old_index,
                    old_len,
                    new_index,
                    new_len,
                } => (
                    0..0,
                    old_index..old_index + old_len,
                    new_index..new_index + new_len,
                ),
            };
            let lines = (equal.map(|i| (' ', old_lines[i])))
                .chain(taken.map(|i| ('-', old_lines[i])))
                .chain(put.map(|i| ('+', new_lines[i])));
            for (tag, line) in lines {
                match line.strip_suffix('\n') {
                    Some(content) => write_line(out, &format!("{tag}{content}"))?,
                    None => {
                        write_line(out, &format!("{tag}{line}"))?;
                        write_line(out, "\\ No newline at end of file")?;
                    }
                }
            }
        }
    }
    Ok(())
}

/// A hunk header's range of lines `start..end` (0-based), as `diff -u` writes it:
/// `start,length` (1-based; an empty range names the line before it), `start` alone for
/// one line.
fn hunk_range(start: usize, end: usize) -> String {
    match end - start {
        1 => format!("{}", start + 1),
        0 => format!("{start},0"),
        length => format!("{},{length}", start + 1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn diff(old: &str, new: &str) -> String {
        let mut out = Vec::new();
        write_diff(&mut out, "kb.dat", old, new, DiffStyle::default()).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn a_line_changed_in_place() {
        assert_eq!(
            diff("a\nb\n", "a\nc\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -1,2 +1,2 @@\n a\n-b\n+c\n"
        );
    }

    #[test]
    fn a_text_without_a_final_newline_says_so() {
        assert_eq!(
            diff("a\nb", "a\nb\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+b\n"
        );
    }

    #[test]
    fn an_empty_side_names_the_line_before() {
        assert_eq!(
            diff("", "x\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -0,0 +1 @@\n+x\n"
        );
        assert_eq!(
            diff("x\n", ""),
            "--- kb.dat\n+++ kb.dat\n@@ -1 +0,0 @@\n-x\n"
        );
    }

    #[test]
    fn changes_six_lines_apart_share_a_hunk_and_seven_do_not() {
        let old: String = (0..20).map(|n| format!("{n}\n")).collect();
        let six = old.replace("\n3\n", "\n3x\n").replace("\n10\n", "\n10x\n");
        assert_eq!(diff(&old, &six).matches("@@ -").count(), 1);
        assert!(diff(&old, &six).contains("@@ -1,14 +1,14 @@"));
        let seven = old.replace("\n3\n", "\n3x\n").replace("\n11\n", "\n11x\n");
        let seven = diff(&old, &seven);
        assert!(seven.contains("@@ -1,7 +1,7 @@") && seven.contains("@@ -9,7 +9,7 @@"));
    }

    #[test]
    fn lines_are_escaped_and_coloured() {
        let mut out = Vec::new();
        let style = DiffStyle { color: true };
        write_diff(&mut out, "k\u{1b}.dat", "a\n", "b\u{7}\n", style).unwrap();
        let out = String::from_utf8(out).unwrap();
        // The headers too, coloured by their first character.
        assert!(
            out.starts_with("\x1b[31m--- k\\u{001B}.dat\x1b[0m\n"),
            "{out}"
        );
        assert!(
            out.contains("\x1b[31m-a\x1b[0m\n\x1b[32m+b\\u{0007}\x1b[0m\n"),
            "{out}"
        );
        assert!(out.contains("\x1b[36m@@ -1 +1 @@\x1b[0m\n"), "{out}");
    }

    #[test]
    fn a_text_too_large_for_a_diff_names_the_lines_that_change() {
        let changed = |old, new| changed_lines(old, new).expect("they differ");
        assert_eq!(changed("a\nb\nc\nd\n", "a\nB\nC\nd\n"), (2, 3));
        assert_eq!(changed("a\nb\n", "x\nb\n"), (1, 1));
        assert_eq!(changed("a\nb\n", "a\nb\nc\n"), (3, 3));
        assert_eq!(changed("a\nb\n", "a\n"), (2, 2));
        // An insertion between two equal lines: the line after it.
        assert_eq!(changed("a\na\n", "a\nx\na\n"), (2, 2));
        // A last line without its newline is not the same line with it.
        assert_eq!(changed("a\nb", "a\nb\n"), (2, 2));
        assert_eq!(changed_lines("a\nb", "a\nb"), None);
        assert_eq!(changed_lines("", ""), None);
    }

    #[test]
    fn the_stretch_is_the_same_whatever_pieces_the_text_comes_in() {
        let old = "one\ntwo\nthree\nfour\nfive\n";
        let new = "one\ntwo\nTHREE\nfour\nfive\n";
        for piece in [1, 2, 3, 7, 100] {
            let mut compared = ChangedStretch::new(old);
            for chunk in new.as_bytes().chunks(piece) {
                compared.write_all(chunk).unwrap();
            }
            assert_eq!(compared.finish(), Some((3, 3)), "pieces of {piece}");
        }
        let mut same = ChangedStretch::new(old);
        for chunk in old.as_bytes().chunks(4) {
            same.write_all(chunk).unwrap();
        }
        assert_eq!(same.finish(), None);
    }
}
