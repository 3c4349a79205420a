//! The canonical layout of a knowledge base, defined once: `ekb fmt` writes it from a parsed
//! file ([`Document::parse`]), `ekb import` from JSON ([`Document::from_export`]).
//!
//! The layout, as the robot's own files are written:
//! - one block per location, in the order the file first mentions each location, separated
//!   by one blank line;
//! - inside a block, the keys in the order of SPEC §1's table ([`Key::order`]); a key in the
//!   wrong case sorts as the key it means; an unknown key goes after the known ones; two lines
//!   with the same slot (duplicates) keep their order;
//! - each line `key id value`, the key padded with spaces so that the id starts at column 31
//!   (a key of 29 characters or more gets one space). If the padding is what would make the
//!   line too long for the robot's 200-byte line buffer, the key gets one space instead;
//! - an entry without a valid id (which location is it?) first, after the header, as written;
//! - the `tourSpecification` line(s) last, after a blank line, the tour's items separated by
//!   single spaces (commas dropped);
//! - a comment moves with the line it precedes. Comments above the first entry that are
//!   separated from it by a blank line are a file header and stay at the top; comments after
//!   the last entry stay at the end;
//! - LF line endings, one final newline, no byte-order mark, no trailing whitespace;
//! - a blank line first if the first line would start with U+FEFF (a line in the middle of
//!   a file can, as text of a key or comment): at the very start of a file it would be read
//!   as a byte-order mark and vanish.
//!
//! Values are copied byte for byte: a text value keeps its inner spacing, a number keeps its
//! spelling. Only the blanks *between* the numbers of a pose or a gesture target, and between
//! the tour's items, become single spaces.

mod balance;
mod from_export;
mod from_source;

pub use from_export::ImportError;
pub use from_source::Unformattable;

use std::borrow::Cow;
use std::io::{self, Write};
use std::ops::ControlFlow;

use crate::model::Key;
use crate::robot::Reader;
use crate::syntax::{self, Body, Line};
use from_source::Place;

/// Padding never makes a line as long as the smallest reader's line buffer.
const LINE_BUFFER: usize = Reader::SMALLEST_LINE_BUFFER;

/// The column (1-based) where a location line's id starts.
pub const VALUE_COLUMN: usize = 31;

/// U+FEFF: a byte-order mark at the start of a file, text anywhere else.
const BYTE_ORDER_MARK: char = '\u{feff}';

/// The slot of a key that is no known key, even ignoring case: after every known key.
const UNKNOWN_SLOT: u8 = Key::CulturalKnowledge as u8 + 1;

/// How many lines [`Document::write_checked`] lays out before it writes them.
const LINES_AT_A_TIME: usize = 1 << 17;

/// The widest padding a key gets (`VALUE_COLUMN - 1` spaces, for a key of one character).
const PADDING: &str = "                              ";

/// How many lines a refusal names before it says "and N more".
pub const NAMED_LINES: usize = 5;

/// `line 4 (`gestureArm`), line 11 (`culturalKnowledge`) and 3 more`: the lines a refusal is
/// about, each with a short description.
pub fn name_lines(lines: &[(u32, String)]) -> String {
    let named: Vec<String> = lines
        .iter()
        .take(NAMED_LINES)
        .map(|(number, what)| format!("line {number} (`{what}`)"))
        .collect();
    match lines.len().saturating_sub(NAMED_LINES) {
        0 => named.join(", "),
        more => format!("{} and {more} more", named.join(", ")),
    }
}

/// `text` in the canonical layout, `None` when it is in it already; or why it cannot be.
/// (`ekb fmt` writing a file streams it with [`Document::write_checked`] instead.)
pub fn format(text: &str) -> Result<Option<String>, String> {
    let document = Document::parse(text).map_err(|e| e.to_string())?;
    if document.renders_as(text) {
        return Ok(None);
    }
    // The layout keeps every line and value: each line written is read back as it is
    // written (without reading a second document).
    let mut formatted = Vec::with_capacity(text.len() + text.len() / 4);
    document
        .write_checked(&mut formatted)
        .map_err(|e| e.to_string())?;
    Ok(Some(
        String::from_utf8(formatted).expect("the layout writes text"),
    ))
}

/// A knowledge base as lines to write, in canonical order (see the module documentation).
///
/// Lean on purpose (`ekb fmt` holds one for a whole file of any size): it keeps only where
/// each entry line starts, in the order the layout writes them, and the length of those
/// already written so — 6 bytes a line at most. Everything
/// else is read again from the line when it is written: its key, id and value, and the
/// comments above it (the comment lines between it and the entry line before it in the
/// file). Writing reads each line of the file about once more, and holds one line at a time.
#[derive(Debug, Clone, Default)]
pub struct Document<'a> {
    /// What the lines are lines of: the file (`parse`) or the lines written from an export.
    text: Cow<'a, str>,
    /// Where the header ends: the comments before it stay at the top, apart from any entry.
    header_end: u32,
    /// Where the footer starts: the comments after it (after the last entry line) stay at
    /// the end.
    footer_start: u32,
    /// Where each entry line without a valid id starts, as written: no block is theirs, so
    /// they come first, where they are seen.
    unplaced: Vec<u32>,
    /// Where each located entry line starts, block after block (one per location, in order
    /// of first appearance), each block in key order.
    order: Vec<u32>,
    /// The length (line ending included) of each line of `order` that is written as the
    /// layout writes it, with no comment line between it and the entry line before it: the
    /// first reading found it so, as it found its id. Such a line is recorded as it is,
    /// without being read and laid out again, nor its comments looked for, nor its end
    /// (nearly every line of a file that `ekb fmt` wrote). 0 for every other line; empty
    /// when the first reading did not keep where each line goes (a text of very many short
    /// lines, read again to put them in order).
    written: Vec<u16>,
    /// Where each block ends in `order`.
    block_ends: Vec<u32>,
    /// Where each `tourSpecification` line starts, in file order (the last wins on the
    /// robot).
    tour: Vec<u32>,
}

/// The order of a document's location blocks.
#[derive(Debug, Clone, Copy)]
enum BlockOrder {
    /// As the file first mentions each location.
    FirstSeen,
    /// The order that builds a balanced tree in the robot's reader ([`Document::parse_balanced`]).
    Balanced,
}

/// One line of the canonical text, as the layout writes it and as reading it back must
/// see it.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Item<'d> {
    Blank,
    Comment(&'d str),
    Entry(Written<'d>),
}

/// An entry as written.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Written<'d> {
    key: &'d str,
    id: Option<&'d str>,
    value: Cow<'d, str>,
    /// A `tourSpecification` line (which has no id either).
    tour: bool,
}

impl Item<'_> {
    fn starts_with_byte_order_mark(&self) -> bool {
        match self {
            Item::Blank => false,
            Item::Comment(text) => text.starts_with(BYTE_ORDER_MARK),
            Item::Entry(entry) => entry.key.starts_with(BYTE_ORDER_MARK),
        }
    }
}

/// Where a key goes inside its block: SPEC §1's order, a key in the wrong case as the key it
/// means, an unknown key last.
fn slot(known: Option<Key>) -> u8 {
    known.map_or(UNKNOWN_SLOT, |key| key.order() as u8)
}

/// The key `name` means, ignoring case; the exact spelling (almost every line) is looked up
/// first, by a `match`, and a name no key is as long as is no key (a file of a million
/// unknown keys is read several times).
fn known_key(name: &str) -> Option<Key> {
    static LENGTHS: std::sync::OnceLock<std::ops::RangeInclusive<usize>> =
        std::sync::OnceLock::new();
    let lengths = LENGTHS.get_or_init(|| {
        let lengths = Key::ALL.map(|key| key.name().len());
        *lengths.iter().min().unwrap_or(&0)..=*lengths.iter().max().unwrap_or(&0)
    });
    Key::from_name(name).or_else(|| {
        lengths
            .contains(&name.len())
            .then(|| Key::from_name_ignoring_case(name))
            .flatten()
    })
}

/// Why the canonical text was not written: a line would not read back as the line meant (a
/// bug in ekb), or the output failed.
#[derive(Debug)]
pub enum WriteError {
    NotReadBack,
    Io(io::Error),
}

impl std::fmt::Display for WriteError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WriteError::NotReadBack => f.write_str(
                "the canonical layout would change its content (a bug in ekb; please report it)",
            ),
            WriteError::Io(error) => error.fmt(f),
        }
    }
}

impl From<io::Error> for WriteError {
    fn from(error: io::Error) -> WriteError {
        WriteError::Io(error)
    }
}

impl<'a> Document<'a> {
    /// The line of `text` that starts at `start`.
    fn line_at(&self, start: u32) -> Line {
        syntax::lines_from(&self.text, start as usize)
            .next()
            .expect("a line starts there")
    }

    /// The entry line that starts at `start`, as the layout writes it.
    fn entry_at(&self, start: u32, tour: bool) -> Written<'_> {
        let text: &str = &self.text;
        let line = self.line_at(start);
        let Body::Entry { key, args } = line.body else {
            unreachable!("an entry line starts there");
        };
        let (id, value) = match from_source::read(text, key, args) {
            Place::Tour(value) => (None, value),
            Place::Unplaced(value) => (None, Cow::Borrowed(value)),
            Place::Located { id_text, value } => (Some(id_text), value),
        };
        Written {
            key: key.text(text),
            id,
            value,
            tour,
        }
    }

    /// The comments of the lines from `from` up to `end` (a line start), in order, each with
    /// where its line starts.
    fn comments_between(&self, from: u32, end: u32) -> impl Iterator<Item = (u32, &str)> + '_ {
        let text: &str = &self.text;
        syntax::lines_from(text, from as usize)
            .take_while(move |line| line.span.start < end)
            .filter_map(move |line| match line.body {
                Body::Comment(comment) => Some((line.span.start, comment.text(text))),
                _ => None,
            })
    }

    /// Where the comments above the entry line at `start` begin: after the entry line before
    /// it in the file, or after the header. Found by reading back over the comment and blank
    /// lines between them, each once.
    fn comments_start(&self, start: u32) -> u32 {
        let bytes = self.text.as_bytes();
        let mut at = start as usize;
        while at > self.header_end as usize {
            let previous = memchr::memrchr(b'\n', &bytes[..at - 1]).map_or(0, |i| i + 1);
            // A line that begins with its key is an entry (nearly every line): no lexing.
            let begins_with_key =
                previous > 0 && !matches!(bytes[previous], b' ' | b'\t' | b'#' | b'\r' | b'\n');
            if begins_with_key || matches!(self.line_at(previous as u32).body, Body::Entry { .. }) {
                break;
            }
            at = previous;
        }
        at.max(self.header_end as usize) as u32
    }

    /// The text whose lines these are.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// [`Document::text`], given back.
    pub fn into_text(self) -> Cow<'a, str> {
        self.text
    }

    /// The canonical text.
    pub fn render(&self) -> String {
        let mut out = String::with_capacity(self.text.len() + self.text.len() / 4);
        let _ = self.walk(|item, _| {
            push_item(&mut out, &item);
            ControlFlow::Continue(())
        });
        out
    }

    /// Writes the canonical text, as [`Document::render`] makes it, to `out`: laid out a
    /// buffer at a time, never held whole.
    pub fn write_to(&self, out: &mut impl Write) -> io::Result<()> {
        const BUFFER: usize = 1 << 16;
        let mut buffer = String::with_capacity(BUFFER + 512);
        let mut failed = None;
        let _ = self.walk(|item, _| {
            push_item(&mut buffer, &item);
            if buffer.len() < BUFFER {
                return ControlFlow::Continue(());
            }
            failed = out.write_all(buffer.as_bytes()).err();
            buffer.clear();
            match failed {
                Some(_) => ControlFlow::Break(()),
                None => ControlFlow::Continue(()),
            }
        });
        match failed {
            Some(error) => Err(error),
            None => out.write_all(buffer.as_bytes()),
        }
    }

    /// Writes the canonical text to `out`, each line read back as it is laid out: one that
    /// would not read as the line meant (the layout must keep every line and value) is
    /// [`WriteError::NotReadBack`], and nothing after it is written. The lines are laid out
    /// [`LINES_AT_A_TIME`] at a time: however large the file, only those are held.
    pub fn write_checked(&self, out: &mut impl Write) -> Result<(), WriteError> {
        let mut lines = Vec::new();
        let mut text = String::new();
        let mut first = true;
        let mut write = |lines: &mut Vec<Unread<'_>>| {
            let read_back = self.lay_out_checked(lines, std::mem::take(&mut first), &mut text);
            lines.clear();
            out.write_all(&text.as_bytes()[1..])?;
            match read_back {
                true => Ok(()),
                false => Err(WriteError::NotReadBack),
            }
        };
        let mut failed = None;
        let _ = self.walk_unread(|line, _| {
            lines.push(line);
            if lines.len() < LINES_AT_A_TIME {
                return ControlFlow::Continue(());
            }
            failed = write(&mut lines).err();
            match failed {
                Some(_) => ControlFlow::Break(()),
                None => ControlFlow::Continue(()),
            }
        });
        match failed {
            Some(error) => Err(error),
            None => write(&mut lines),
        }
    }

    /// Lays out `lines` in `text` after a newline, each read back after the newline before
    /// it, as in the file (where only the first line, if `first`, may begin with a
    /// byte-order mark that reading drops): up to the first that does not read back.
    /// Returns whether all did.
    fn lay_out_checked(&self, lines: &[Unread<'_>], first: bool, text: &mut String) -> bool {
        text.clear();
        text.push('\n');
        for line in lines {
            let start = text.len();
            let item = line.clone().read(self);
            push_item(text, &item);
            let (laid_out, at) = match first && start == 1 {
                true => (&text[1..], 0),
                false => (text.as_str(), start),
            };
            let read_back = syntax::lines_from(laid_out, at).next();
            if !read_back.is_some_and(|read| reads_as(laid_out, &read, &item)) {
                text.truncate(start);
                return false;
            }
        }
        true
    }

    /// Whether `text` is this document's [`render`](Self::render) already (the usual case of
    /// `ekb fmt --check`), found without writing the whole text: each line is written into
    /// one small buffer and compared.
    pub fn renders_as(&self, text: &str) -> bool {
        let mut line = String::new();
        let mut rest = text.as_bytes();
        let walked = self.walk(|item, _| {
            line.clear();
            push_item(&mut line, &item);
            let Some(after) = rest.strip_prefix(line.as_bytes()) else {
                return ControlFlow::Break(());
            };
            rest = after;
            ControlFlow::Continue(())
        });
        walked.is_continue() && rest.is_empty()
    }

    /// Every line of the canonical text, in order, each with where the line of the text it
    /// was made from starts (none for a blank line the layout adds), until `visit` breaks.
    fn walk(
        &self,
        mut visit: impl FnMut(Item<'_>, Option<u32>) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        self.walk_unread(|line, origin| visit(line.read(self), origin))
    }

    /// [`Document::walk`], each entry line given unread: read it only if it is wanted.
    fn walk_unread<'d>(
        &'d self,
        visit: impl FnMut(Unread<'d>, Option<u32>) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let mut walk = Walk {
            document: self,
            sections: 0,
            visit,
        };
        walk.head()?;
        for block in 0..self.block_ends.len() {
            walk.block(block)?;
        }
        walk.tail()
    }
}

/// A walk through the lines of the canonical text, or some of them: each line given to
/// `visit` unread, with where the line of the text it was made from starts, the blank line
/// between two sections put in.
struct Walk<'d, 'a, V> {
    document: &'d Document<'a>,
    /// How many sections came before (the header, the lines without a valid id, each
    /// block, the tour and the footer are each one, if they have lines).
    sections: usize,
    visit: V,
}

impl<'d, V: FnMut(Unread<'d>, Option<u32>) -> ControlFlow<()>> Walk<'d, '_, V> {
    /// The lines before the blocks: the header's comments, the entries without a valid id.
    fn head(&mut self) -> ControlFlow<()> {
        let document = self.document;
        for (n, (start, comment)) in document
            .comments_between(0, document.header_end)
            .enumerate()
        {
            self.line(Unread::Item(Item::Comment(comment)), start, n == 0)?;
        }
        for (n, &start) in document.unplaced.iter().enumerate() {
            self.entry(start, n == 0, false, None)?;
        }
        ControlFlow::Continue(())
    }

    /// The lines of block `block` (by number).
    fn block(&mut self, block: usize) -> ControlFlow<()> {
        let document = self.document;
        let start = block
            .checked_sub(1)
            .map_or(0, |before| document.block_ends[before]);
        let lines = start as usize..document.block_ends[block] as usize;
        let written = document.written.get(lines.clone());
        for (n, &start) in document.order[lines].iter().enumerate() {
            let written = written.map_or(0, |written| written[n]);
            self.entry(start, n == 0, false, (written > 0).then_some(written))?;
        }
        ControlFlow::Continue(())
    }

    /// The lines after the blocks: the tour, the footer's comments.
    fn tail(&mut self) -> ControlFlow<()> {
        let document = self.document;
        for (n, &start) in document.tour.iter().enumerate() {
            self.entry(start, n == 0, true, None)?;
        }
        let end = document.text.len() as u32;
        for (n, (start, comment)) in document
            .comments_between(document.footer_start, end)
            .enumerate()
        {
            self.line(Unread::Item(Item::Comment(comment)), start, n == 0)?;
        }
        ControlFlow::Continue(())
    }

    /// The entry line at `start`, after the comments above it; `written`: its length if it
    /// is written as the layout writes it ([`Document::written`]).
    fn entry(
        &mut self,
        start: u32,
        new_section: bool,
        tour: bool,
        written: Option<u16>,
    ) -> ControlFlow<()> {
        let document = self.document;
        let mut first = new_section;
        let comments = match written {
            Some(_) => start,
            None => document.comments_start(start),
        };
        debug_assert!(
            written.is_none()
                || (document.comments_between(document.comments_start(start), start))
                    .next()
                    .is_none()
        );
        // (Without comments above it, the line is not lexed once more to find none.)
        if comments < start {
            for (line, comment) in document.comments_between(comments, start) {
                let comment = Unread::Item(Item::Comment(comment));
                self.line(comment, line, std::mem::take(&mut first))?;
            }
        }
        let entry = Unread::Entry { start, tour };
        self.line(entry, start, first)
    }

    /// A line made from the line of the text at `origin`, the first of a section if
    /// `new_section`.
    fn line(&mut self, line: Unread<'d>, origin: u32, new_section: bool) -> ControlFlow<()> {
        if new_section {
            // Sections are apart; and a first line starting with U+FEFF would be read as a
            // byte-order mark.
            if self.sections > 0
                || line
                    .clone()
                    .read(self.document)
                    .starts_with_byte_order_mark()
            {
                (self.visit)(Unread::Item(Item::Blank), None)?;
            }
            self.sections += 1;
        }
        (self.visit)(line, Some(origin))
    }
}

/// A line of the canonical text before it is written: an entry line is read from the text
/// (its key, id and value) only when it is wanted.
#[derive(Clone)]
enum Unread<'d> {
    Item(Item<'d>),
    Entry { start: u32, tour: bool },
}

impl<'d> Unread<'d> {
    fn read(self, document: &'d Document<'_>) -> Item<'d> {
        match self {
            Unread::Item(item) => item,
            Unread::Entry { start, tour } => Item::Entry(document.entry_at(start, tour)),
        }
    }
}

fn push_item(out: &mut String, item: &Item<'_>) {
    match item {
        Item::Blank => {}
        Item::Comment(text) => out.push_str(text),
        Item::Entry(entry) => push_entry(out, entry.key, entry.id, &entry.value),
    }
    out.push('\n');
}

/// `key id value`, the id at [`VALUE_COLUMN`] (without the line ending).
fn push_entry(out: &mut String, key: &str, id: Option<&str>, value: &str) {
    out.push_str(key);
    if let Some(id) = id {
        out.push_str(&PADDING[..padding(key, id, value)]);
        out.push_str(id);
    }
    if !value.is_empty() {
        out.push(' ');
        out.push_str(value);
    }
}

/// How many spaces the layout writes between `key` and `id` (before `value`).
pub(crate) fn padding(key: &str, id: &str, value: &str) -> usize {
    let key_width = match key.is_ascii() {
        true => key.len(),
        false => key.chars().count(),
    };
    let padded = (VALUE_COLUMN - 1).max(key_width + 1) - key_width;
    let value_length = if value.is_empty() { 0 } else { 1 + value.len() };
    let unpadded_length = key.len() + 1 + id.len() + value_length + "\n".len();
    // Pad unless the padding is what would make the robot cut the line.
    if unpadded_length + padded - 1 < LINE_BUFFER || unpadded_length >= LINE_BUFFER {
        padded
    } else {
        1
    }
}

/// Whether `line` of `text` reads as `item`: the same comment, or the same entry (key, id,
/// value and where it goes), and no stray carriage return.
fn reads_as(text: &str, line: &Line, item: &Item<'_>) -> bool {
    if from_source::ends_in_stray_return(text, line) {
        return false;
    }
    match (line.body, item) {
        (Body::Blank, Item::Blank) => true,
        (Body::Comment(comment), Item::Comment(expected)) => comment.text(text) == *expected,
        (Body::Entry { key, args }, Item::Entry(expected)) => {
            key.text(text) == expected.key && from_source::read(text, key, args).is(expected)
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_a_few_lines() {
        let lines: Vec<(u32, String)> = (1..=7).map(|n| (n, format!("k{n}"))).collect();
        assert_eq!(name_lines(&lines[..1]), "line 1 (`k1`)");
        assert_eq!(
            name_lines(&lines),
            "line 1 (`k1`), line 2 (`k2`), line 3 (`k3`), line 4 (`k4`), line 5 (`k5`) and 2 more"
        );
    }

    fn entry<'a>(key: &'a str, id: Option<&'a str>, value: &'a str) -> Written<'a> {
        Written {
            key,
            id,
            value: value.into(),
            tour: false,
        }
    }

    /// The line of an entry, with its line ending.
    fn push_line(out: &mut String, entry: Written<'_>) {
        push_item(out, &Item::Entry(entry));
    }

    /// Whether reading `formatted` gives `document` again, line by line (what
    /// [`Document::write_checked`] checks of each line as it writes it).
    fn reads_back_from(document: &Document<'_>, formatted: &str) -> bool {
        let mut lines = syntax::lines(formatted);
        let walked = document.walk(|item, _| {
            let line = lines.next();
            match line.is_some_and(|line| reads_as(formatted, &line, &item)) {
                true => ControlFlow::Continue(()),
                false => ControlFlow::Break(()),
            }
        });
        walked.is_continue() && lines.next().is_none()
    }

    #[test]
    fn what_is_written_checked_is_what_is_rendered() {
        let text = "# header\n\nzzz 1 x\n# c\nrobotLocation 1 1  2 3\nhello\n\
                    tourSpecification 2 1,2\n\u{feff}k v\n# end\n";
        let document = Document::parse(text).unwrap();
        let mut written = Vec::new();
        document.write_checked(&mut written).unwrap();
        assert_eq!(String::from_utf8(written).unwrap(), document.render());
    }

    #[test]
    fn a_large_file_is_laid_out_in_batches_as_in_one() {
        // Lines shorter than a placed line's 8 bytes are read again to be put in place; and
        // written in several batches.
        let lines = 300_000;
        let text = format!("# head\n\n{}", "a 1 x\nb 2 y\n".repeat(lines));
        assert!(lines > LINES_AT_A_TIME);
        let document = Document::parse(&text).unwrap();
        let block = |line: &str| line.repeat(lines);
        let expected = format!(
            "# head\n\n{}\n{}",
            block("a                             1 x\n"),
            block("b                             2 y\n")
        );
        assert_eq!(document.render(), expected);
        let mut written = Vec::new();
        document.write_checked(&mut written).unwrap();
        assert!(written == expected.as_bytes());
        // A stray carriage return in the second part is named by its line.
        let text = format!("{text}a 1 x\r\r\n");
        let error = Document::parse(&text).unwrap_err();
        assert_eq!((error.count, error.lines[0].0), (1, 2 * lines as u32 + 3));
    }

    #[test]
    fn lines_as_written_are_marked_with_their_lengths() {
        // Each line as the layout writes it, each block's keys out of order: the lengths
        // the first reading found move with their lines as blocks are sorted and balanced.
        let line = |key: &str, id: usize, value: &str| {
            let mut line = String::new();
            push_entry(&mut line, key, Some(&id.to_string()), value);
            line + "\n"
        };
        let text: String = (1..=40)
            .map(|id| {
                line("robotLocation", id, "1 2 3")
                    + &line("robotLocationDescription", id, &"x".repeat(20 + id))
                    + "\n"
            })
            .collect();
        let document = Document::parse_balanced(&text).unwrap();
        // (All but the file's first line, above which comments are looked for.)
        let marked = document.written.iter().filter(|&&length| length > 0);
        assert_eq!((document.order.len(), marked.count()), (80, 79));
        assert_ne!(document.render(), text);
    }

    #[test]
    fn the_padding_is_as_wide_as_the_column_says() {
        assert_eq!(PADDING.len(), VALUE_COLUMN - 1);
        assert!(PADDING.bytes().all(|byte| byte == b' '));
    }

    #[test]
    fn ids_start_at_column_31() {
        let mut out = String::new();
        push_line(&mut out, entry("gestureTarget", Some("1"), "0.0 0.0 0.0"));
        push_line(
            &mut out,
            entry("postGestureMessageKinyarwanda", Some("12"), "x"),
        );
        push_line(
            &mut out,
            entry("aVeryLongUnknownKeyOfThirtyOneCh", Some("3"), ""),
        );
        push_line(&mut out, entry("tourSpecification", None, "2 1 3"));
        assert_eq!(
            out,
            "gestureTarget                 1 0.0 0.0 0.0\n\
             postGestureMessageKinyarwanda 12 x\n\
             aVeryLongUnknownKeyOfThirtyOneCh 3\n\
             tourSpecification 2 1 3\n"
        );
    }

    #[test]
    fn a_line_starting_with_u_feff_is_not_made_the_first_line_of_the_file() {
        // Found by the fuzzer: the line had no id, so it moved to the top, where the next
        // reading took its U+FEFF for a byte-order mark.
        let text = "robotLocationDescription 1 A\n\u{feff}x y\n";
        let once = Document::parse(text).unwrap().render();
        assert_eq!(once, "\n\u{feff}x y\n\nrobotLocationDescription      1 A\n");
        assert_eq!(Document::parse(&once).unwrap().render(), once);
    }

    #[test]
    fn the_canonical_text_reads_back_and_any_other_does_not() {
        let text = "# header\n\nzzz 1 x\n# c\nrobotLocation 1 1  2 3\nhello\n\
                    tourSpecification 2 1,2\n\u{feff}k v\n# end\n";
        let document = Document::parse(text).unwrap();
        let formatted = document.render();
        assert!(reads_back_from(&document, &formatted));
        assert!(document.renders_as(&formatted));
        assert!(!reads_back_from(&document, text));
        assert!(!document.renders_as(text));
        for changed in [
            formatted.replace("1 2 3", "1 2 4"),
            formatted.replace("# c", "# d"),
            formatted.replace("tourSpecification 2", "tourspecification 2"),
            formatted.replace("hello", "hello 7"),
            formatted.replace("\n\n", "\n"),
            format!("{formatted}\n"),
            formatted.replace(
                "zzz                           1",
                "zzz                           01",
            ),
            formatted.replace("# end\n", "# end\r\r\n"),
        ] {
            assert!(!reads_back_from(&document, &changed), "{changed:?}");
            assert!(!document.renders_as(&changed), "{changed:?}");
        }
    }

    #[test]
    fn padding_never_makes_a_line_too_long_for_the_robot() {
        // 13 + 1 + 1 + 1 + 182 + newline = 199 bytes with one space; padding would add 16.
        let value = "x".repeat(182);
        let mut out = String::new();
        push_line(&mut out, entry("gestureTarget", Some("1"), &value));
        assert_eq!(out.len(), LINE_BUFFER - 1);
        assert!(out.starts_with("gestureTarget 1 x"));
        // A line too long anyway is padded as usual.
        let value = "x".repeat(190);
        let mut out = String::new();
        push_line(&mut out, entry("gestureTarget", Some("1"), &value));
        assert!(out.starts_with("gestureTarget                 1 x"));
    }
}
