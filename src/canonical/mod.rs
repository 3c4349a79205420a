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
use std::ops::Range;

use crate::model::Key;
use crate::reader::Reader;
use crate::syntax::Span;

/// Padding never makes a line as long as the smallest reader's line buffer.
const LINE_BUFFER: usize = Reader::SMALLEST_LINE_BUFFER;

/// The column (1-based) where a location line's id starts.
pub const VALUE_COLUMN: usize = 31;

/// U+FEFF: a byte-order mark at the start of a file, text anywhere else.
const BYTE_ORDER_MARK: char = '\u{feff}';

/// The slot of a key that is no known key, even ignoring case: after every known key.
const UNKNOWN_SLOT: u8 = Key::CulturalKnowledge as u8 + 1;

/// The widest padding a key gets (`VALUE_COLUMN - 1` spaces, for a key of one character).
const PADDING: &str = "                              ";

/// `text` in the canonical layout, `None` when it is in it already; or why it cannot be.
pub fn format(text: &str) -> Result<Option<String>, String> {
    let document = Document::parse(text).map_err(|e| e.to_string())?;
    if document.renders_as(text) {
        return Ok(None);
    }
    let formatted = document.render();
    // The layout keeps every line and value: reading the result must give the same document
    // (checked line by line, without reading a second one).
    if !document.reads_back_from(&formatted) {
        return Err(
            "the canonical layout would change its content (a bug in ekb; please report it)".into(),
        );
    }
    Ok(Some(formatted))
}

/// A knowledge base as lines to write, in canonical order (see the module documentation).
///
/// Lean on purpose (`ekb fmt` holds one for a whole file): every key, id, value and comment
/// is a [`Span`] of `text`, and all entries live in one vector in file order; the blocks are
/// ranges of `order`, a permutation of that vector. A span that starts at or after the end of
/// `text` is a span of `rewritten` (positions continuing after `text`), for the few values
/// the layout rewrites.
#[derive(Debug, Clone, Default)]
pub struct Document<'a> {
    /// What the spans are spans of: the file (`parse`) or the values of an export.
    text: Cow<'a, str>,
    /// Values that are not in `text` as written (re-spaced numbers and tour items).
    rewritten: String,
    /// Every comment, in file order: the header's, each entry's, the footer's.
    comments: Vec<Span>,
    /// `comments[..header]`: comments at the top of the file, apart from any entry.
    header: u32,
    /// Every entry, in file order.
    entries: Vec<Entry>,
    /// Entries without a valid id, as written: no block is theirs, so they come first,
    /// where they are seen.
    unplaced: Vec<u32>,
    /// The located entries, block after block (one per location, in order of first
    /// appearance), each block in key order.
    order: Vec<u32>,
    /// Where each block ends in `order`.
    block_ends: Vec<u32>,
    /// The `tourSpecification` lines, in file order (the last wins on the robot).
    tour: Vec<u32>,
}

/// One `key id value` line. The tour and unplaced lines have no id: their key and value are
/// written with one space between.
#[derive(Debug, Clone, Copy)]
struct Entry {
    /// The comments above it are `comments[start..comments_end]`, `start` being the
    /// previous entry's `comments_end` (for the first entry, the end of the header).
    comments_end: u32,
    key: Span,
    id: Option<Span>,
    /// Everything after the id, as it will be written (may be empty).
    value: Span,
}

/// One line of the canonical text, as the layout writes it and as reading it back must
/// see it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Item<'d> {
    Blank,
    Comment(&'d str),
    Entry(Written<'d>),
}

/// An entry as written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Written<'d> {
    key: &'d str,
    id: Option<&'d str>,
    value: &'d str,
    /// A `tourSpecification` line (which has no id either).
    tour: bool,
}

impl Item<'_> {
    fn starts_with_byte_order_mark(self) -> bool {
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
/// first, by a `match`.
fn known_key(name: &str) -> Option<Key> {
    Key::from_name(name).or_else(|| Key::from_name_ignoring_case(name))
}

impl<'a> Document<'a> {
    /// The text of a span of this document.
    fn str(&self, span: Span) -> &str {
        let base = self.text.len();
        if span.end as usize <= base {
            span.text(&self.text)
        } else {
            &self.rewritten[span.start as usize - base..span.end as usize - base]
        }
    }

    /// The span of `value`, kept as a slice of `text` when it is one.
    fn span_of(&mut self, value: Cow<'_, str>) -> Span {
        match value {
            Cow::Borrowed(slice) if is_within(slice, &self.text) => Span::of(slice, &self.text),
            value => {
                let start = self.text.len() + self.rewritten.len();
                self.rewritten.push_str(&value);
                Span::new(start, start + value.len())
            }
        }
    }

    /// The comments above `entries[index]`.
    fn comments_of(&self, index: usize) -> Range<usize> {
        let start = match index {
            0 => self.header,
            _ => self.entries[index - 1].comments_end,
        };
        start as usize..self.entries[index].comments_end as usize
    }

    /// Where the footer starts in `comments`: after the last entry's comments.
    fn footer(&self) -> usize {
        self.entries
            .last()
            .map_or(0, |entry| entry.comments_end as usize)
    }

    /// The canonical text.
    pub fn render(&self) -> String {
        let mut out = String::with_capacity(self.text.len() + self.text.len() / 4);
        self.walk(|item| push_item(&mut out, item));
        out
    }

    /// Whether `text` is this document's [`render`](Self::render) already (the usual case of
    /// `ekb fmt --check`), found without writing the whole text: each line is written into
    /// one small buffer and compared.
    pub fn renders_as(&self, text: &str) -> bool {
        let mut line = String::new();
        let mut rest = text.as_bytes();
        let mut same = true;
        self.walk(|item| {
            line.clear();
            push_item(&mut line, item);
            same = same && rest.starts_with(line.as_bytes());
            rest = rest.get(line.len()..).unwrap_or_default();
        });
        same && rest.is_empty()
    }

    /// Whether reading `formatted` (this document's [`render`](Self::render)) back would
    /// give this document again: every line reads as exactly the line that was written there.
    /// That is what [`parse`](Self::parse) would compare, line by line, without a second
    /// document: the blocks, their order and the header and footer follow from the lines.
    pub fn reads_back_from(&self, formatted: &str) -> bool {
        let mut lines = crate::syntax::lines(formatted);
        let mut same = true;
        self.walk(|item| {
            same = same
                && lines
                    .next()
                    .is_some_and(|line| reads_as(formatted, &line, item));
        });
        same && lines.next().is_none()
    }

    /// Every line of the canonical text, in order.
    fn walk(&self, mut visit: impl FnMut(Item<'_>)) {
        let mut sections = 0;
        let mut visit = |item: Item<'_>, new_section: bool| {
            if new_section {
                // Sections are apart; and a first line starting with U+FEFF would be read as a
                // byte-order mark.
                if sections > 0 || item.starts_with_byte_order_mark() {
                    visit(Item::Blank);
                }
                sections += 1;
            }
            visit(item);
        };
        let comments = |range: Range<usize>| self.comments[range].iter().map(|&c| self.str(c));
        for (n, comment) in comments(0..self.header as usize).enumerate() {
            visit(Item::Comment(comment), n == 0);
        }
        let mut entry = |index: u32, new_section: bool, tour: bool| {
            let index = index as usize;
            let mut first = new_section;
            for comment in comments(self.comments_of(index)) {
                visit(Item::Comment(comment), std::mem::take(&mut first));
            }
            let entry = &self.entries[index];
            let written = Written {
                key: self.str(entry.key),
                id: entry.id.map(|id| self.str(id)),
                value: self.str(entry.value),
                tour,
            };
            visit(Item::Entry(written), first);
        };
        for (n, &index) in self.unplaced.iter().enumerate() {
            entry(index, n == 0, false);
        }
        let mut start = 0;
        for &end in &self.block_ends {
            for (n, &index) in self.order[start as usize..end as usize].iter().enumerate() {
                entry(index, n == 0, false);
            }
            start = end;
        }
        for (n, &index) in self.tour.iter().enumerate() {
            entry(index, n == 0, true);
        }
        for (n, comment) in comments(self.footer()..self.comments.len()).enumerate() {
            visit(Item::Comment(comment), n == 0);
        }
    }
}

/// Whether `part` is a slice of `whole`'s memory.
fn is_within(part: &str, whole: &str) -> bool {
    let (start, end) = (part.as_ptr() as usize, whole.as_ptr() as usize);
    start >= end && start + part.len() <= end + whole.len()
}

fn push_item(out: &mut String, item: Item<'_>) {
    match item {
        Item::Blank => {}
        Item::Comment(text) => out.push_str(text),
        Item::Entry(entry) => push_entry(out, entry.key, entry.id, entry.value),
    }
    out.push('\n');
}

/// `key id value`, the id at [`VALUE_COLUMN`] (without the line ending).
fn push_entry(out: &mut String, key: &str, id: Option<&str>, value: &str) {
    out.push_str(key);
    if let Some(id) = id {
        let key_width = key.chars().count();
        let padded = (VALUE_COLUMN - 1).max(key_width + 1) - key_width;
        let value_length = if value.is_empty() { 0 } else { 1 + value.len() };
        let unpadded_length = key.len() + 1 + id.len() + value_length + "\n".len();
        // Pad unless the padding is what would make the robot cut the line.
        let spaces = if unpadded_length + padded - 1 < LINE_BUFFER || unpadded_length >= LINE_BUFFER
        {
            padded
        } else {
            1
        };
        out.push_str(&PADDING[..spaces]);
        out.push_str(id);
    }
    if !value.is_empty() {
        out.push(' ');
        out.push_str(value);
    }
}

/// Whether `line` of `text` reads as `item`: the same comment, or the same entry (key, id,
/// value and where it goes), and no stray carriage return.
fn reads_as(text: &str, line: &crate::syntax::Line, item: Item<'_>) -> bool {
    use crate::syntax::Body;
    if from_source::ends_in_stray_return(text, line) {
        return false;
    }
    match (line.body, item) {
        (Body::Blank, Item::Blank) => true,
        (Body::Comment(comment), Item::Comment(expected)) => comment.text(text) == expected,
        (Body::Entry { key, args }, Item::Entry(expected)) => {
            key.text(text) == expected.key && from_source::read(text, key, args).is(expected)
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry<'a>(key: &'a str, id: Option<&'a str>, value: &'a str) -> Written<'a> {
        Written {
            key,
            id,
            value,
            tour: false,
        }
    }

    /// The line of an entry, with its line ending.
    fn push_line(out: &mut String, entry: Written<'_>) {
        push_item(out, Item::Entry(entry));
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
        assert!(document.reads_back_from(&formatted));
        assert!(document.renders_as(&formatted));
        assert!(!document.reads_back_from(text));
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
            assert!(!document.reads_back_from(&changed), "{changed:?}");
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
