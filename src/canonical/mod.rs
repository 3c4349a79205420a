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

mod from_export;
mod from_source;

pub use from_export::ImportError;
pub use from_source::Unformattable;

use std::borrow::Cow;

use crate::model::Key;
use crate::rules::compat::compat_line_too_long::LINE_BUFFER;

/// The column (1-based) where a location line's id starts.
pub const VALUE_COLUMN: usize = 31;

/// U+FEFF: a byte-order mark at the start of a file, text anywhere else.
const BYTE_ORDER_MARK: char = '\u{feff}';

/// The slot of a key that is no known key, even ignoring case: after every known key.
const UNKNOWN_SLOT: usize = Key::CulturalKnowledge as usize + 1;

/// A knowledge base as lines to write, in canonical order (see the module documentation).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Document<'a> {
    /// Comments at the top of the file, apart from any entry.
    pub header: Vec<Cow<'a, str>>,
    /// Entries without a valid id, as written: no block is theirs, so they come first, where
    /// they are seen.
    pub unplaced: Vec<Entry<'a>>,
    /// One per location, in order of first appearance.
    pub blocks: Vec<Block<'a>>,
    /// The `tourSpecification` lines, in file order (the last wins on the robot).
    pub tour: Vec<Entry<'a>>,
    /// Comments after the last entry.
    pub footer: Vec<Cow<'a, str>>,
}

/// The lines of one location.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Block<'a> {
    pub entries: Vec<Entry<'a>>,
}

/// One `key id value` line, with the comments above it. The tour and unplaced lines have no
/// id: their key and value are written with one space between.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry<'a> {
    pub comments: Vec<Cow<'a, str>>,
    pub key: Cow<'a, str>,
    pub id: Option<Cow<'a, str>>,
    /// Everything after the id, as it will be written (may be empty).
    pub value: Cow<'a, str>,
}

impl Entry<'_> {
    /// Where the line goes inside its block.
    fn slot(&self) -> usize {
        Key::from_name_ignoring_case(&self.key).map_or(UNKNOWN_SLOT, Key::order)
    }
}

impl Block<'_> {
    /// Puts the entries in canonical key order, keeping the order of equal keys. Each slot
    /// is found once (a key lookup ignoring case): a block is usually sorted already, and
    /// `sort_by_key` would look up both keys of every comparison.
    fn sort(&mut self) {
        self.entries.sort_by_cached_key(Entry::slot);
    }
}

impl Document<'_> {
    /// The canonical text.
    pub fn render(&self) -> String {
        let mut out = String::new();
        let mut sections = 0;
        let mut section = |out: &mut String| {
            if sections > 0 {
                out.push('\n');
            }
            sections += 1;
        };
        if !self.header.is_empty() {
            section(&mut out);
            push_comments(&mut out, &self.header);
        }
        if !self.unplaced.is_empty() {
            section(&mut out);
            self.unplaced
                .iter()
                .for_each(|entry| push_entry(&mut out, entry));
        }
        for block in &self.blocks {
            section(&mut out);
            block
                .entries
                .iter()
                .for_each(|entry| push_entry(&mut out, entry));
        }
        if !self.tour.is_empty() {
            section(&mut out);
            self.tour
                .iter()
                .for_each(|entry| push_entry(&mut out, entry));
        }
        if !self.footer.is_empty() {
            section(&mut out);
            push_comments(&mut out, &self.footer);
        }
        if out.starts_with(BYTE_ORDER_MARK) {
            out.insert(0, '\n');
        }
        out
    }
}

fn push_comments(out: &mut String, comments: &[Cow<'_, str>]) {
    for comment in comments {
        out.push_str(comment);
        out.push('\n');
    }
}

fn push_entry(out: &mut String, entry: &Entry<'_>) {
    push_comments(out, &entry.comments);
    out.push_str(&entry.key);
    if let Some(id) = &entry.id {
        let key_width = entry.key.chars().count();
        let padded = (VALUE_COLUMN - 1).max(key_width + 1) - key_width;
        let value = if entry.value.is_empty() {
            0
        } else {
            1 + entry.value.len()
        };
        let unpadded_length = entry.key.len() + 1 + id.len() + value + "\n".len();
        // Pad unless the padding is what would make the robot cut the line.
        let spaces = if unpadded_length + padded - 1 < LINE_BUFFER || unpadded_length >= LINE_BUFFER
        {
            padded
        } else {
            1
        };
        out.extend(std::iter::repeat_n(' ', spaces));
        out.push_str(id);
    }
    if !entry.value.is_empty() {
        out.push(' ');
        out.push_str(&entry.value);
    }
    out.push('\n');
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry<'a>(key: &'a str, id: Option<&'a str>, value: &'a str) -> Entry<'a> {
        Entry {
            comments: Vec::new(),
            key: key.into(),
            id: id.map(Cow::from),
            value: value.into(),
        }
    }

    #[test]
    fn ids_start_at_column_31() {
        let mut out = String::new();
        push_entry(&mut out, &entry("gestureTarget", Some("1"), "0.0 0.0 0.0"));
        push_entry(
            &mut out,
            &entry("postGestureMessageKinyarwanda", Some("12"), "x"),
        );
        push_entry(
            &mut out,
            &entry("aVeryLongUnknownKeyOfThirtyOneCh", Some("3"), ""),
        );
        push_entry(&mut out, &entry("tourSpecification", None, "2 1 3"));
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
    fn padding_never_makes_a_line_too_long_for_the_robot() {
        // 13 + 1 + 1 + 1 + 182 + newline = 199 bytes with one space; padding would add 16.
        let value = "x".repeat(182);
        let mut out = String::new();
        push_entry(&mut out, &entry("gestureTarget", Some("1"), &value));
        assert_eq!(out.len(), LINE_BUFFER - 1);
        assert!(out.starts_with("gestureTarget 1 x"));
        // A line too long anyway is padded as usual.
        let value = "x".repeat(190);
        let mut out = String::new();
        push_entry(&mut out, &entry("gestureTarget", Some("1"), &value));
        assert!(out.starts_with("gestureTarget                 1 x"));
    }
}
